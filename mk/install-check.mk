# install-check.mk - `make install` of the double and the float build into
# one scratch prefix, then external programs built through pkg-config alone
# (tests/install_check.sh): both scalar types, the refused mix, the LCM types
# (C, C++, Python, Java), the installed tools.
INSTALL_CHECK_DIR := $(BUILD)/install-check
# the float build's directory (the one `make bench` uses: same flags)
INSTALL_CHECK_FLOAT := $(BUILD)/float
.PHONY: install-check
# (the jar of the double install built by this make: test-lcm-spy uses it too)
TEST_EXTRA_DEPS_install-check = all $(if $(HAVE_JAVA),$(LCM_JAR))
TEST_EXTRA += install-check
install-check: $(TEST_EXTRA_DEPS_install-check)
	rm -rf $(INSTALL_CHECK_DIR)
	$(MAKE) --no-print-directory install PREFIX=$(abspath $(INSTALL_CHECK_DIR)/prefix)
	cp $(INSTALL_CHECK_DIR)/prefix/lib/pkgconfig/trk.pc $(INSTALL_CHECK_DIR)/trk.pc.double
	$(MAKE) --no-print-directory install REAL=float BUILD=$(INSTALL_CHECK_FLOAT) CONFIG_DEFS='$(CONFIG_DEFS)' \
	  PREFIX=$(abspath $(INSTALL_CHECK_DIR)/prefix)
	@CC='$(CC)' sh tests/install_check.sh $(BUILD) $(abspath $(INSTALL_CHECK_DIR))
