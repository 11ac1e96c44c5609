# tools/trk-tablegen/tool.mk - subcommand registry.
# Subcommands are collected from `TABLEGEN_CMD(name, "summary")` lines of
# tools/trk-tablegen/*.c (see tablegen.h). The amplitude table generator and
# the q2 sampler it drives are OpenMP builds in libtrk_tools.a (mk/q2.mk);
# every table node / stratum is computed by one thread and merged in a fixed
# order, so the tables are bit-identical whatever the thread count.
$(GEN)/tablegen_cmds.inc: $(wildcard tools/trk-tablegen/*.c) tools/trk-tablegen/tool.mk
	@mkdir -p $(@D)
	$(Q)sed -n 's/^TABLEGEN_CMD(\([a-z0-9_]*\),.*/TABLEGEN_CMD_ENTRY(\1)/p' $(sort $(wildcard tools/trk-tablegen/*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/trk-tablegen/main.o: $(GEN)/tablegen_cmds.inc
