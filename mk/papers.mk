# mk/papers.mk - one command that reproduces the papers.
#   make papers        the papers' experiments at their paper sizes into
#                      build/papers/ (CSV, PNG with gnuplot) and
#                      build/papers/summary.{md,csv}: per printed value the
#                      paper's, trk's with its 95 % interval, and whether they
#                      agree (tools/scripts/papers.sh). Long (docs/analysis.md: trk-sim);
#                      not part of make test.
#   make papers PAPERS_SIZE=tiny   the same at 40 runs each (seconds): the
#                      whole chain and the summary's format, not the papers' precision.
#   papers-summary     the `make test` step: the same script at a tiny size
#                      (seconds), the summary's format checked.
.PHONY: papers papers-summary
PAPERS_SIZE ?= paper
papers: $(BUILD)/bin/trk-sim
	sh tools/scripts/papers.sh $(BUILD)/bin/trk-sim $(BUILD)/papers $(PAPERS_SIZE)
TEST_EXTRA += papers-summary
TEST_EXTRA_DEPS_papers-summary := $(BUILD)/bin/trk-sim
papers-summary: $(TEST_EXTRA_DEPS_papers-summary)
	@sh tests/papers_summary.sh $(BUILD)/bin/trk-sim
