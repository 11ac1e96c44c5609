# mk/docs-run.mk - `make docs-run`: the documentation's runnable blocks
# (README.md and docs/*.md, fences marked ```sh run or ```python run) run by
# tools/scripts/docs_run.py, each in a fresh temporary directory mirroring
# the repository root; a failing block fails the step with its FILE:LINE
# (tests/docs_run_selftest.sh checks that first, on a page of its own).
# Blocks marked `long` or `display` are skipped (DOCS_RUN_FLAGS=--long runs
# the long ones). A step of `make test` (docs/development.md "Docs that run").
# The documented commands name build/: the step runs in the default build.
DOCS_RUN_FLAGS ?=
TEST_EXTRA += docs-run
# what the runnable blocks use: the tools, libtrk.a (a program built against
# it), libtrk.so (the Python tracker example) and the demo's amplitude table
TEST_EXTRA_DEPS_docs-run := $(BUILD)/bin/trk-sim $(BUILD)/bin/trk-tablegen $(BUILD)/bin/trk-sonar-sim \
  $(BUILD)/bin/trk-lcm-bridge $(LIB) $(BUILD)/libtrk.so $(DEMO_TABLES)
.PHONY: docs-run
docs-run: $(TEST_EXTRA_DEPS_docs-run)
	@[ '$(BUILD)' = build ] || { echo "docs-run: the documented commands use build/: run it without BUILD=$(BUILD)"; exit 1; }
	@# the runner itself: a failing block fails at its FILE:LINE, skipped ones do not run
	@sh tests/docs_run_selftest.sh
	@# what the Python examples read: the amplitude demo's CSV files
	@# (build/demo-amplitude) and the LCM demo's track log (build/demo-lcm)
	@$(MAKE) --no-print-directory demo-amplitude demo-lcm > /dev/null
	@python3 tools/scripts/docs_run.py $(DOCS_RUN_FLAGS) README.md docs/*.md
