# mk/demo.mk - `make demo`, trk's main job end to end (README: the first command).
#
#   make demo       builds everything (the Makefile's `demo: all`), makes the amplitude
#                   table of the scenario with trk-tablegen (K nu 1, SNR 15 dB, P_FA 1e-2,
#                   one of `make tables`' defaults; under a second; the q2 tables of `make
#                   tables` take minutes and are not needed: the demo samples the q2 of its
#                   MRE prediction itself), then `trk-sim demo`: a simulated sonar with
#                   heavy-tailed (K, nu = 1) clutter through the track table (PDAFAI, confirmation by amplitude-
#                   aided visibility, Shiryaev termination), a readable summary (tracks
#                   confirmed, lost, false; position RMSE against the MRE prediction),
#                   CSV files and PNG plots in $(BUILD)/demo/ (without gnuplot: the CSV
#                   files and the .gp scripts, and a note). Then the LCM pipeline
#                   (mk/lcm.mk, demo-lcm) and the firmware-style example.
#   make demo-main  the sonar scenario alone
#   DEMO_FLAGS      extra trk-sim demo options / tracker settings, e.g.
#                   make demo DEMO_FLAGS='--seed 7 --set term=page'
# The whole `make demo` takes well under a minute on 2 cores once built.
DEMO_DIR = $(BUILD)/demo
DEMO_FLAGS ?=
# the table the scenario uses (rule in mk/tables.mk, read after this file:
# name it by path, $(TABLES_DIR) is not defined yet)
DEMO_TABLES := $(BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl

.PHONY: demo-main
demo: demo-main
demo-main: $(BUILD)/bin/trk-sim $(DEMO_TABLES)
	@echo "== trk demo: amplitude table by trk-tablegen ($(BUILD)/tables), sonar scenario -> $(DEMO_DIR)"
	@$(BUILD)/bin/trk-sim demo --tables $(BUILD)/tables --out $(DEMO_DIR) $(DEMO_FLAGS)

# Under `make -j demo` the LCM demo waits for the sonar scenario (readable output).
ifneq ($(filter demo,$(MAKECMDGOALS)),)
demo-lcm: | demo-main
endif

# the firmware-style example as a `make test` step: it exits non-zero unless
# every target has a confirmed track and no confirmed track is false
TEST_EXTRA += example-firmware-loop
TEST_EXTRA_DEPS_example-firmware-loop := $(BUILD)/bin/example-firmware_loop
example-firmware-loop: $(TEST_EXTRA_DEPS_example-firmware-loop)
	@out=$$($(BUILD)/bin/example-firmware_loop) || { echo "$$out"; echo "example-firmware-loop: FAILED"; exit 1; }; \
	  echo "$$out" | tail -1
