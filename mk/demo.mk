# mk/demo.mk - `make demo`, trk's main job end to end (README: the first command).
#
#   make demo       builds everything (the Makefile's `demo: all`), then `trk-sim demo`:
#                   the sonar's own problem, one run of the sonar family of trk-sim mtt
#                   (a polar sensor on a platform moving at 3 m/s, P_D falling with
#                   range, reverberation patches, persistent scatterers, eight targets;
#                   50 clutter detections per ping) through the track table with the
#                   library's defaults and the sensor's description, next to the
#                   known-association oracle: a summary (coverage per target and beyond
#                   5 km, false tracks, RMSE by range band against the oracle), CSV files
#                   and PNG plots in $(BUILD)/demo/ (the sector with detections, truth,
#                   tracks and the oracle; the error against range; without gnuplot the
#                   .gp scripts and a note). Then the amplitude demo (demo-amplitude), the
#                   LCM pipeline (mk/lcm.mk, demo-lcm) and the firmware-style example.
#   make demo-main  the sonar alone
#   make demo-amplitude  amplitude-aided tracking (PDAFAI) in heavy-tailed K clutter:
#                   makes the scenario's amplitude table with trk-tablegen (K nu 1, SNR
#                   15 dB, P_FA 1e-2, one of `make tables`' defaults; under a second),
#                   then `trk-sim demo-amplitude` (2 km x 2 km, 250 pings, four targets,
#                   150 clutter per ping; position RMSE against the MRE prediction) into
#                   $(BUILD)/demo-amplitude/ (what the Python examples of docs/ read)
#   DEMO_FLAGS      extra trk-sim demo options / tracker settings, e.g.
#                   make demo DEMO_FLAGS='--seed 7 --clutter-count 100 --set stationary_d2=0'
# The whole `make demo` takes well under a minute on 2 cores once built.
DEMO_DIR = $(BUILD)/demo
DEMO_AMP_DIR = $(BUILD)/demo-amplitude
DEMO_FLAGS ?=
# the table the amplitude demo uses (rule in mk/tables.mk, read after this
# file: name it by path, $(TABLES_DIR) is not defined yet)
DEMO_TABLES := $(BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl

.PHONY: demo-main demo-amplitude
demo: demo-main demo-amplitude
demo-main: $(BUILD)/bin/trk-sim
	@echo "== trk demo: the sonar's own problem -> $(DEMO_DIR)"
	@$(BUILD)/bin/trk-sim demo --out $(DEMO_DIR) $(DEMO_FLAGS)
demo-amplitude: $(BUILD)/bin/trk-sim $(DEMO_TABLES)
	@echo "== trk demo-amplitude: amplitude table by trk-tablegen ($(BUILD)/tables), K clutter -> $(DEMO_AMP_DIR)"
	@$(BUILD)/bin/trk-sim demo-amplitude --tables $(BUILD)/tables --out $(DEMO_AMP_DIR)

# Under `make -j demo` the demos run one after the other (readable output).
ifneq ($(filter demo,$(MAKECMDGOALS)),)
demo-amplitude: | demo-main
demo-lcm: | demo-amplitude
endif

# the sonar demo as a `make test` step: what it must show, its files
# against its summary (tests/demo_sonar.sh)
TEST_EXTRA += demo-sonar-check
TEST_EXTRA_DEPS_demo-sonar-check := $(BUILD)/bin/trk-sim
demo-sonar-check: $(TEST_EXTRA_DEPS_demo-sonar-check)
	@sh tests/demo_sonar.sh $(BUILD)/bin/trk-sim

# the firmware-style example as a `make test` step: it exits non-zero unless
# every target has a confirmed track and no confirmed track is false
TEST_EXTRA += example-firmware-loop
TEST_EXTRA_DEPS_example-firmware-loop := $(BUILD)/bin/example-firmware_loop
example-firmware-loop: $(TEST_EXTRA_DEPS_example-firmware-loop)
	@out=$$($(BUILD)/bin/example-firmware_loop) || { echo "$$out"; echo "example-firmware-loop: FAILED"; exit 1; }; \
	  echo "$$out" | tail -1
