# tools/trk-tablegen/tool.mk - subcommand registry and OpenMP.
# Subcommands are collected from `TABLEGEN_CMD(name, "summary")` lines of
# tools/trk-tablegen/*.c (see tablegen.h). The amplitude table generator
# (tools/common/amp_table.c) is compiled a second time with -fopenmp for this
# tool; every table node is computed by one thread, so the tables are
# bit-identical whatever the thread count.
$(GEN)/tablegen_cmds.inc: $(wildcard tools/trk-tablegen/*.c) tools/trk-tablegen/tool.mk
	@mkdir -p $(@D)
	sed -n 's/^TABLEGEN_CMD(\([a-z0-9_]*\),.*/TABLEGEN_CMD_ENTRY(\1)/p' $(sort $(wildcard tools/trk-tablegen/*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/trk-tablegen/main.o: $(GEN)/tablegen_cmds.inc

AMP_TABLE_OMP_OBJ := $(BUILD)/obj/omp/tools/common/amp_table.o
$(AMP_TABLE_OMP_OBJ): tools/common/amp_table.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) -fopenmp -Itools/common -c $< -o $@
TOOL_DEPS_trk-tablegen += $(AMP_TABLE_OMP_OBJ)
TOOL_LDLIBS_trk-tablegen += -fopenmp

# trk-tablegen q2 runs the q2 sampler on all cores: the OpenMP build of
# tools/common/q2_is.c (rule in mk/q2.mk) ahead of libtrk_tools.a.
TOOL_DEPS_trk-tablegen += $(BUILD)/obj/omp/tools/common/q2_is.o
