# mk/hostile.mk - `make hostile-tools`: hostile input to the tools
# (hangs and unbounded reads, write errors and destroyed outputs, parsing),
# a step of `make test` (tests/hostile_tools.sh; a few seconds).
TEST_EXTRA += hostile-tools
TEST_EXTRA_DEPS_hostile-tools := $(addprefix $(BUILD)/bin/,trk-tablegen trk-sim trk-sonar-sim trk-vectors)
.PHONY: hostile-tools
hostile-tools: $(TEST_EXTRA_DEPS_hostile-tools)
	@sh tests/hostile_tools.sh $(BUILD)/bin
