# trk-sim: OpenMP, and the experiment registry collected from
# `SIM_EXPERIMENT(id, "name", "description")` lines of tools/trk-sim/exp_*.c.
TOOL_CFLAGS_trk-sim := -fopenmp
TOOL_LDFLAGS_trk-sim := -fopenmp

$(GEN)/sim_experiments.inc: $(wildcard tools/trk-sim/exp_*.c) tools/trk-sim/tool.mk
	@mkdir -p $(@D)
	sed -n 's/^SIM_EXPERIMENT(\(.*\))[ {]*$$/SIM_ENTRY(\1)/p' $(sort $(wildcard tools/trk-sim/exp_*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/trk-sim/main.o: $(GEN)/sim_experiments.inc

# The q2 sampler behind toc.h (brekke-toc, toc, demo) on all cores: the OpenMP
# build of tools/common/q2_is.c (rule in mk/q2.mk) ahead of libtrk_tools.a.
TOOL_DEPS_trk-sim += $(BUILD)/obj/omp/tools/common/q2_is.o
