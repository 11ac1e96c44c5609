# mk/docs.mk - `make docs`: the API reference of libtrk from its public
# headers (include/trk, docs/Doxyfile, start page docs/api-main.md) by
# Doxygen, in $(BUILD)/docs/html/index.html (the headers' indented layout
# kept by the input filter tools/scripts/doxygen_filter.awk). Every public
# function, type, member and macro must carry a Doxygen comment: any Doxygen
# warning (an undocumented declaration, a broken reference or command) fails
# it, with the warnings printed as file:line, and so does a header without a
# @file comment. A step of `make test`.
DOXYGEN ?= doxygen
DOCS_DIR := $(BUILD)/docs
TEST_EXTRA += docs
TEST_EXTRA_DEPS_docs :=
.PHONY: docs
docs:
	@command -v $(DOXYGEN) > /dev/null || { echo "docs: $(DOXYGEN) not found (Debian: apt-get install doxygen)"; exit 1; }
	@# Doxygen checks a header's functions only when the header itself is
	@# documented: one without a @file comment fails here
	@nofile=$$(grep -L '@file' include/trk/*.h); if [ -n "$$nofile" ]; then \
	  echo "docs: FAILED: no /** @file ... */ comment (its functions would go unchecked):" $$nofile; exit 1; fi
	@rm -rf $(DOCS_DIR) && mkdir -p $(DOCS_DIR)
	@{ cat docs/Doxyfile; echo 'OUTPUT_DIRECTORY = $(DOCS_DIR)'; } | $(DOXYGEN) - > $(DOCS_DIR)/doxygen.log 2>&1; \
	  rc=$$?; n=$$(grep -c ': \(warning\|error\):' $(DOCS_DIR)/doxygen.log); \
	  if [ $$rc -ne 0 ] || [ $$n -ne 0 ]; then cat $(DOCS_DIR)/doxygen.log; \
	    echo "docs: FAILED: $$n Doxygen warnings (exit status $$rc); document what they name (docs/development.md \"API reference\")"; exit 1; fi
	@echo "docs: API reference of $(words $(wildcard include/trk/*.h)) headers in $(DOCS_DIR)/html/index.html, 0 Doxygen warnings"
