# mk/sim-assumptions.mk - the assumptions that change trk-sim's results as
# options (--start, --gate-cap, --mre-start), a step of
# `make test` (tests/sim_assumptions.sh, ~20 s): the defaults keep the numbers
# of before (tests/sim_assumptions/*.rows), the options act in the expected
# direction, the CSV headers and plot titles name them.
.PHONY: sim-assumptions
TEST_EXTRA += sim-assumptions
TEST_EXTRA_DEPS_sim-assumptions := $(BUILD)/bin/trk-sim
sim-assumptions: $(TEST_EXTRA_DEPS_sim-assumptions)
	@sh tests/sim_assumptions.sh $(BUILD)/bin/trk-sim
