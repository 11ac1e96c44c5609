# mk/mtt.mk - `make mtt`: issue 14's multi-target evaluation (trk-sim mtt) with the
# default track table and a large-capacity build, and their comparison.
#
#   make mtt        builds trk-sim in build/ (TRK_MAX_TRACKS of include/trk/config.h, 64)
#                   and in $(MTT_LARGE_BUILD) (CONFIG_DEFS=-DTRK_MAX_TRACKS=$(MTT_LARGE_TRACKS)),
#                   runs `trk-sim mtt $(MTT_ARGS)` with each (the same scenarios: the results
#                   differ only by the table's capacity), then `trk-sim mtt-compare`:
#                     $(MTT_RESULTS)/mtt_default.csv, mtt_large.csv   each build's rows (and plots)
#                     $(MTT_RESULTS)/mtt.csv, mtt_ratio.csv, mtt_*.png  merged: one table, one set
#                                    of plots, per metric the ratio default / large and
#                                    whether the default's mean is in the large build's
#                                    95 % interval
#   MTT_ARGS        trk-sim mtt options for both runs, e.g.
#                   make mtt MTT_ARGS="--scans 60 --seeds 3 --set term=page"
#                   make mtt MTT_ARGS="--speed-max 20"   (targets faster than the 15 m/s
#                                                         two-point velocity gate)
#                   make mtt MTT_ARGS="--family fixed"   (b9ce836's 8 fixed targets, the
#                                                         scenario the peer was measured on)
# The default run (10 seeds x 200 scans x 7 clutter levels x 2 configurations per build)
# takes seconds per build on 2 cores; compiling the large build dominates.
#   make mtt-smoke  the `make test` step: a short run, its CSV checked (tests/mtt_smoke.sh)
MTT_ARGS ?=
MTT_LARGE_TRACKS ?= 1024
MTT_LARGE_BUILD ?= build/large
MTT_RESULTS ?= build/results

.PHONY: mtt mtt-smoke
mtt:
	+@$(MAKE) --no-print-directory BUILD=build CONFIG_DEFS= build/bin/trk-sim
	+@$(MAKE) --no-print-directory BUILD=$(MTT_LARGE_BUILD) CONFIG_DEFS=-DTRK_MAX_TRACKS=$(MTT_LARGE_TRACKS) \
	  $(MTT_LARGE_BUILD)/bin/trk-sim
	@mkdir -p $(MTT_RESULTS)
	build/bin/trk-sim mtt $(MTT_ARGS) --out $(MTT_RESULTS)/mtt_default
	$(MTT_LARGE_BUILD)/bin/trk-sim mtt $(MTT_ARGS) --out $(MTT_RESULTS)/mtt_large
	build/bin/trk-sim mtt-compare $(MTT_RESULTS)/mtt_default.csv $(MTT_RESULTS)/mtt_large.csv \
	  --out $(MTT_RESULTS)/mtt

TEST_EXTRA += mtt-smoke
TEST_EXTRA_DEPS_mtt-smoke := $(BUILD)/bin/trk-sim
mtt-smoke: $(TEST_EXTRA_DEPS_mtt-smoke)
	@sh tests/mtt_smoke.sh $(BUILD)/bin/trk-sim
