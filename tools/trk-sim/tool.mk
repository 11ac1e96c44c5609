# trk-sim: OpenMP (compile; every host program links it), and the experiment registry collected from
# `SIM_EXPERIMENT(id, "name", "description")` lines of tools/trk-sim/exp_*.c.
TOOL_CFLAGS_trk-sim := -fopenmp

$(GEN)/sim_experiments.inc: $(wildcard tools/trk-sim/exp_*.c) tools/trk-sim/tool.mk
	@mkdir -p $(@D)
	$(Q)sed -n 's/^SIM_EXPERIMENT(\(.*\))[ {]*$$/SIM_ENTRY(\1)/p' $(sort $(wildcard tools/trk-sim/exp_*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/trk-sim/main.o: $(GEN)/sim_experiments.inc

# The q2 sampler behind toc_curve.h (brekke-toc, toc, demo) runs on all cores: its
# OpenMP build is in libtrk_tools.a (mk/q2.mk).
