# mk/q2tables.mk - the default q2 tables (`make tables`, with mk/tables.mk's
# amplitude tables) and the thread-count reproducibility check of
# `trk-tablegen q2` (a step of `make test`).
#
#   make tables   also writes into $(BUILD)/tables/:
#     q2_pdaf_pg099.tbl       PDAF, nz 2, P_G 0.99
#     q2_pdaf_g6.tbl          PDAF, nz 2, gate g = 6 (gamma 36, Brekke Table I)
#     q2_pdafai_rayleigh_g6.tbl, q2_pdafai_k1_g6.tbl, q2_pdafai_k8_g6.tbl
#                             PDAFAI, nz 2, gamma 36: Rayleigh, K nu = 1, K nu = 8
#   each on the tool's default grid (trk-tablegen q2 --help) at se <= 1e-3
#   per cell, then checked with `trk-tablegen info` (the library's loader).
#   Q2_TABLE_FLAGS adds options to every run (e.g. --threads 2 --quiet).
Q2_TABLE_FLAGS ?=
# (mk/tables.mk, read after this file, sets the same two)
TABLES_DIR ?= $(BUILD)/tables
TABLEGEN ?= $(BUILD)/bin/trk-tablegen
Q2_TABLES := $(TABLES_DIR)/q2_pdaf_pg099.tbl $(TABLES_DIR)/q2_pdaf_g6.tbl \
  $(TABLES_DIR)/q2_pdafai_rayleigh_g6.tbl $(TABLES_DIR)/q2_pdafai_k1_g6.tbl $(TABLES_DIR)/q2_pdafai_k8_g6.tbl

# $(1) file stem, $(2) options
define Q2_TABLE_rule
$(TABLES_DIR)/$(1).tbl: $(TABLEGEN)
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)
	@$(TABLEGEN) q2 $(2) $(Q2_TABLE_FLAGS) --out $$@ || { rm -f $$@; exit 1; }
	@$(TABLEGEN) info $$@ > /dev/null || { echo "$$@: rejected by trk-tablegen info"; rm -f $$@; exit 1; }
endef
$(eval $(call Q2_TABLE_rule,q2_pdaf_pg099,--detector pdaf --gate-prob 0.99))
$(eval $(call Q2_TABLE_rule,q2_pdaf_g6,--detector pdaf --gate-gamma 36))
$(eval $(call Q2_TABLE_rule,q2_pdafai_rayleigh_g6,--detector pdafai --clutter-model rayleigh --gate-gamma 36))
$(eval $(call Q2_TABLE_rule,q2_pdafai_k1_g6,--detector pdafai --clutter-model k --k-shape 1 --gate-gamma 36))
$(eval $(call Q2_TABLE_rule,q2_pdafai_k8_g6,--detector pdafai --clutter-model k --k-shape 8 --gate-gamma 36))

.PHONY: q2-tables q2-repro
tables: q2-tables
q2-tables: $(Q2_TABLES)
	@echo "tables: $(words $(Q2_TABLES)) q2 tables in $(TABLES_DIR)"

# The same q2 table from 1 and 2 threads must be byte-identical (counter-based
# random numbers keyed by (seed, stratum, sample); work merged in a fixed order).
TEST_EXTRA += q2-repro
TEST_EXTRA_DEPS_q2-repro := $(TABLEGEN)
q2-repro: $(TEST_EXTRA_DEPS_q2-repro)
	@d=$$(mktemp -d) || exit 1; st=0; \
	for t in 1 2; do \
	  $(TABLEGEN) q2 --detector pdaf --pd 0.5:1:0.1 --lambda-vg 0.01:20:6 --samples 20000 --target-se 2e-3 \
	    --seed 3 --threads $$t --quiet --out $$d/pdaf$$t.tbl > /dev/null || st=1; \
	  $(TABLEGEN) q2 --detector pdafai --clutter-model k --k-shape 2 --gate-gamma 36 --snr-db 10,15 --pfa 1e-3:0.1:3 \
	    --lambda-vg 0.01:20:6 --samples 20000 --target-se 2e-3 --seed 3 --threads $$t --quiet \
	    --out $$d/ai$$t.tbl > /dev/null || st=1; \
	done; \
	if [ $$st = 0 ]; then cmp $$d/pdaf1.tbl $$d/pdaf2.tbl && cmp $$d/ai1.tbl $$d/ai2.tbl || st=1; fi; \
	rm -rf $$d; \
	if [ $$st = 0 ]; then echo "q2-repro: trk-tablegen q2 tables identical with 1 and 2 threads"; \
	else echo "q2-repro: FAILED (trk-tablegen q2 output depends on the thread count, or a run failed)"; exit 1; fi
