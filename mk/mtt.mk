# mk/mtt.mk - `make mtt`: the multi-target evaluation (trk-sim mtt) with the
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
#                   make mtt MTT_ARGS="--family fixed"   (the 8 fixed targets, the
#                                                         scenario the peer was measured on)
# The default run (10 seeds x 200 scans x 7 clutter levels x 4 configurations per build:
# new, pda, old and the known-association oracle)
# takes seconds per build on 2 cores; compiling the large build dominates.
#   make mtt-smoke  the `make test` step: a short run, its CSV checked (tests/mtt_smoke.sh)
#   make mtt-sonar-smoke  the `make test` step for --family sonar: a short run, its CSV
#                   checked (tests/mtt_sonar_smoke.sh)
#   make mtt-sonar-goals  the `make test` step of the sonar family's goals at the defaults:
#                   120 seeds at 20 and 100 per ping against the oracle
#                   (tests/mtt_sonar_goals.sh)
#   make mtt-imm    manoeuvring targets, CV-only (new) against IMM (imm).
#                   Builds trk-sim in $(MTT_IMM_BUILD) (CONFIG_DEFS=$(MTT_IMM_DEFS): IMM tracks),
#                   then `trk-sim mtt --config new,imm $(MTT_IMM_ARGS)` (10 seeds, the default
#                   clutter levels) once per turn rate R of $(MTT_IMM_RATES) deg/s, each turn
#                   30 scans of 4 s long (--turn-rate R --turn-deg 120R; each seed's rate is
#                   R x [0.8, 1.2], so 25-37 scans), and once with the straight target
#                   accelerating (--accel $(MTT_IMM_ACCEL) --accel-s $(MTT_IMM_ACCEL_S), the
#                   default 90 deg turn at 3 deg/s):
#                     $(MTT_RESULTS)/mtt_imm_turnR.csv, mtt_imm_accel.csv   the rows
#                     $(MTT_RESULTS)/mtt_imm_*_manoeuvre.png (turn and acceleration coverage
#                                    against clutter) and the other plots of trk-sim mtt
#                   The table "-- manoeuvres" of each run: coverage, RMSE and track loss of
#                   the turning (accelerating) target during the manoeuvre and after it.
#                   About 25 s of runs on 2 cores (10 seeds), ~1.5 min to compile the build.
#                   The imm configuration's models: trk-sim mtt --imm-rate, --imm-stay,
#                   --imm-turn-q (defaults in tools/trk-sim/exp_mtt.c, MTT_IMM_*), e.g.
#                   make mtt-imm MTT_IMM_ARGS="--seeds 20 --imm-stay 0.9"
MTT_ARGS ?=
MTT_LARGE_TRACKS ?= 1024
MTT_LARGE_BUILD ?= build/large
MTT_RESULTS ?= build/results
MTT_IMM_BUILD ?= build/imm
MTT_IMM_DEFS ?= -DTRK_WITH_IMM=1 -DTRK_MAX_MODELS=3
MTT_IMM_ARGS ?=
MTT_IMM_RATES ?= 1 2 3
MTT_IMM_ACCEL ?= 0.1
MTT_IMM_ACCEL_S ?= 60

.PHONY: mtt mtt-smoke mtt-sonar-smoke mtt-sonar-goals mtt-imm tuning
# `make tuning`: one setting at a time (assumed P_D and clutter density, P_G,
# the existence thresholds, clutter beyond capacity) against GOSPA, false
# tracks and time to confirm (tools/scripts/tuning_sweep.sh; docs/tuning.md)
TUNING_SEEDS ?= 20
TUNING_SCANS ?= 200
tuning: $(BUILD)/bin/trk-sim
	sh tools/scripts/tuning_sweep.sh $(BUILD)/bin/trk-sim $(MTT_RESULTS)/tuning $(TUNING_SEEDS) $(TUNING_SCANS)
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

TEST_EXTRA += mtt-sonar-smoke
TEST_EXTRA_DEPS_mtt-sonar-smoke := $(BUILD)/bin/trk-sim
mtt-sonar-smoke: $(TEST_EXTRA_DEPS_mtt-sonar-smoke)
	@sh tests/mtt_sonar_smoke.sh $(BUILD)/bin/trk-sim

# the sonar family's goals at the defaults (120 seeds, about 10 s on 2 cores)
TEST_EXTRA += mtt-sonar-goals
TEST_EXTRA_DEPS_mtt-sonar-goals := $(BUILD)/bin/trk-sim
mtt-sonar-goals: $(TEST_EXTRA_DEPS_mtt-sonar-goals)
	@sh tests/mtt_sonar_goals.sh $(BUILD)/bin/trk-sim

mtt-imm:
	+@$(MAKE) --no-print-directory BUILD=$(MTT_IMM_BUILD) CONFIG_DEFS='$(MTT_IMM_DEFS)' $(MTT_IMM_BUILD)/bin/trk-sim
	@mkdir -p $(MTT_RESULTS)
	@set -e; for r in $(MTT_IMM_RATES); do \
	  deg=$$(awk "BEGIN { print 120 * $$r }"); \
	  echo "$(MTT_IMM_BUILD)/bin/trk-sim mtt --config new,imm --turn-rate $$r --turn-deg $$deg $(MTT_IMM_ARGS) --out $(MTT_RESULTS)/mtt_imm_turn$$r"; \
	  $(MTT_IMM_BUILD)/bin/trk-sim mtt --config new,imm --turn-rate $$r --turn-deg $$deg $(MTT_IMM_ARGS) \
	    --out $(MTT_RESULTS)/mtt_imm_turn$$r; \
	done
	$(MTT_IMM_BUILD)/bin/trk-sim mtt --config new,imm --accel $(MTT_IMM_ACCEL) --accel-s $(MTT_IMM_ACCEL_S) \
	  $(MTT_IMM_ARGS) --out $(MTT_RESULTS)/mtt_imm_accel
