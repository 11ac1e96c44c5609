# mk/tables.mk - amplitude tables made by trk-tablegen.
#
#   make tables   the default amplitude tables into $(BUILD)/tables/:
#                 K clutter nu = 1 and nu = 8 (Brekke's setting) and Rayleigh,
#                 SNR 15 dB, P_FA 1e-4, 1e-3, 1e-2, 1e-1, each checked with
#                 `trk-tablegen info` (the library's loader) after writing
#   $(GEN)/amp_table_data.h  the C-array table of examples/amp_table_firmware.c,
#                 generated in the build's own real width (float builds get a
#                 float table)
TABLES_DIR := $(BUILD)/tables
TABLE_SNR_DB := 15
TABLE_PFAS := 1e-4 1e-3 1e-2 1e-1
TABLEGEN := $(BUILD)/bin/trk-tablegen

# $(1) file stem, $(2) model options, $(3) pfa
define AMP_TABLE_rule
$(TABLES_DIR)/amp_$(1)_snr$(TABLE_SNR_DB)_pfa$(3).tbl: $(TABLEGEN)
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)
	@$(TABLEGEN) amp $(2) --snr-db $(TABLE_SNR_DB) --pfa $(3) --out $$@ $$(if $$(filter 1,$$(V)),,> /dev/null) || { rm -f $$@; exit 1; }
	@$(TABLEGEN) info $$@ > /dev/null || { echo "$$@: rejected by trk-tablegen info"; rm -f $$@; exit 1; }
AMP_TABLES += $(TABLES_DIR)/amp_$(1)_snr$(TABLE_SNR_DB)_pfa$(3).tbl
endef
AMP_TABLES :=
$(foreach p,$(TABLE_PFAS),$(eval $(call AMP_TABLE_rule,k1,--clutter-model k --k-shape 1,$(p))))
$(foreach p,$(TABLE_PFAS),$(eval $(call AMP_TABLE_rule,k8,--clutter-model k --k-shape 8,$(p))))
$(foreach p,$(TABLE_PFAS),$(eval $(call AMP_TABLE_rule,rayleigh,--clutter-model rayleigh,$(p))))

.PHONY: tables
tables: $(AMP_TABLES)
	@echo "tables: $(words $(AMP_TABLES)) amplitude tables in $(TABLES_DIR)"

# (rewritten only when its content changes: a relinked trk-tablegen does not
# recompile the example)
$(GEN)/amp_table_data.h: $(TABLEGEN)
	@mkdir -p $(@D)
	$(Q)$(TABLEGEN) amp --clutter-model k --k-shape 1 --snr-db 15 --pfa 1e-3 --format c --name amp_table --out $@.tmp > /dev/null
	$(Q)if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; \
	  $(if $(filter 1,$(V)),:,printf '%-14s %-4s %s\n' '$(CFG)' GEN '$@'); fi
$(BUILD)/obj/examples/amp_table_firmware.o: $(GEN)/amp_table_data.h
