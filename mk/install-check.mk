# install-check.mk - `make install` into a scratch prefix, then build a
# program against the installed headers and library through pkg-config.
INSTALL_CHECK_DIR := build/install-check
.PHONY: install-check
TEST_EXTRA_DEPS_install-check := all
TEST_EXTRA += install-check
install-check: $(TEST_EXTRA_DEPS_install-check)
	rm -rf $(INSTALL_CHECK_DIR)
	$(MAKE) --no-print-directory install PREFIX=$(abspath $(INSTALL_CHECK_DIR))
	PKG_CONFIG_PATH=$(abspath $(INSTALL_CHECK_DIR))/lib/pkgconfig sh -c \
	  '$(CC) -std=c99 -Wall -Werror examples/firmware_loop.c $$(pkg-config --cflags --libs trk) -o $(INSTALL_CHECK_DIR)/example'
	$(INSTALL_CHECK_DIR)/example > /dev/null
	@echo "install-check: installed headers, library and trk.pc build and run a program"
