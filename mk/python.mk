# mk/python.mk - the Python tools for analysts (tools/python: the lcm-gen -p
# types of trk's messages, a pure-Python LCM log reader, trk-sim CSV readers,
# a track-log plotting example; docs/analysis.md "Python").
#
#   make test-python   a step of `make test` (tests/python_tools.sh): the reader
#                      and types against trk-lcm-bridge --summarize and the
#                      bridge's counts on a log made by trk-sonar-sim, the CSV
#                      readers against trk-sim demo-amplitude's files, the example with
#                      each plotter present, the committed types against lcm-gen
#   make python-types  regenerate the type modules of tools/python/trk from
#                      tools/lcm/types (the package itself: mk/python-binding.mk)
.PHONY: test-python python-types
TEST_EXTRA += test-python
TEST_EXTRA_DEPS_test-python := $(BUILD)/bin/trk-sonar-sim $(BUILD)/bin/trk-lcm-bridge $(BUILD)/bin/trk-sim \
  $(BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl
test-python: $(TEST_EXTRA_DEPS_test-python)
	@sh tests/python_tools.sh $(BUILD)
# (the package's __init__.py is its own, with the binding: lcm-gen's type
# modules are replaced, its __init__.py's imports must be in ours)
python-types: $(LCM_FILES)
	rm -rf $(BUILD)/python-types && mkdir -p $(BUILD)/python-types
	lcm-gen -p --ppath $(BUILD)/python-types $(LCM_FILES)
	@test -s $(BUILD)/python-types/trk/__init__.py || { echo "lcm-gen did not write $(BUILD)/python-types/trk"; exit 1; }
	rm -f tools/python/trk/*_t.py
	cp $(BUILD)/python-types/trk/*_t.py tools/python/trk/
	@grep '^from \.' $(BUILD)/python-types/trk/__init__.py | while IFS= read -r l; do \
	  grep -qxF "$$l" tools/python/trk/__init__.py || echo "python-types: add to tools/python/trk/__init__.py: $$l"; done

# --- install: the types, the readers and the example into
# $(PREFIX)/share/trk/python (PYTHONPATH=$(PREFIX)/share/trk/python)
PY_SHARE = $(DESTDIR)$(PREFIX)/share/trk/python
.PHONY: install-python
install: install-python
install-python:
	install -d $(PY_SHARE)/trk
	install -m 644 tools/python/lcmlog.py tools/python/trklog.py tools/python/trkcsv.py tools/python/needs.py $(PY_SHARE)/
	install -m 755 tools/python/plot_track_log.py $(PY_SHARE)/
	install -m 644 tools/python/trk/*.py $(PY_SHARE)/trk/
