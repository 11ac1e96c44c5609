# mk/tools-faults.mk - `make fault-tools`: the tools' faults of an adversarial pass
# (checkpoint leftovers, an unwritable or full checkpoint path, replay of an
# empty file or a directory) and their messages (program name, exit status,
# "did you mean", statuses in plain words), a step of `make test`
# (tests/fault_tools.sh; a few seconds).
TEST_EXTRA += fault-tools
# (after mk/mpi.mk, which sets MPI)
TEST_EXTRA_DEPS_fault-tools := $(addprefix $(BUILD)/bin/,trk-lcm-bridge trk-tablegen trk-sim trk-vectors) \
	$(if $(filter 1,$(MPI)),$(MPI_BINS))
.PHONY: fault-tools
fault-tools: $(TEST_EXTRA_DEPS_fault-tools)
	@sh tests/fault_tools.sh $(BUILD)/bin
