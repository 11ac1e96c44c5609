# mk/lcm.mk - the LCM bridge's message types and extra targets.
#
#   tools/lcm/types/*.lcm  -> $(BUILD)/gen/lcm/trk_<type>.{c,h}
#       lcm-gen -c --c-no-pubsub (no liblcm needed by the generated code);
#       compiled into libtrk_tools.a (with tools/lcm/lcm_copy.c, the
#       validated message <-> struct copy). Programs that talk LCM
#       (trk-lcm-bridge, trk-sonar-sim, test_lcm_*, trk-bench) link -llcm.
#   make demo-lcm       simulated sonar -> bridge -> track log, and a summary
#                       (also run by `make demo`)
#   make test-lcm-udpm  UDP multicast through a private network namespace
#                       (part of `make test`; skips with a reason when the
#                       machine cannot create one)
#   fuzzing: tests/fuzz/fuzz_lcm_copy.c (the message -> struct copy and the
#                       tracker behind it) and tests/fuzz/fuzz_lcm_log.c (the
#                       log reader) with their corpora tests/fuzz/corpus/
#                       lcm_copy and lcm_log, run by mk/fuzz.mk (make fuzz
#                       FUZZ_TARGETS='lcm_copy lcm_log'; replayed by make test)
#   make test-lcm-walkthrough  the walk-through of docs/lcm.md, run literally
#   make install        also installs the .lcm files to $(PREFIX)/share/trk/lcm
#                       and the generated C (include/trk/lcm, libtrk_lcmtypes.a,
#                       trk-lcm.pc) and C++ (include/trk/lcm-cpp) types

LCM_DIR := tools/lcm/types
LCM_FILES := $(sort $(wildcard $(LCM_DIR)/*.lcm))
LCM_GEN_DIR := $(GEN)/lcm
LCM_TYPES := $(patsubst $(LCM_DIR)/%.lcm,trk_%,$(LCM_FILES))
LCM_GEN_C := $(patsubst %,$(LCM_GEN_DIR)/%.c,$(LCM_TYPES))
LCM_GEN_H := $(patsubst %,$(LCM_GEN_DIR)/%.h,$(LCM_TYPES))
LCM_GEN_STAMP := $(LCM_GEN_DIR)/.stamp
LCM_GEN_OBJS := $(patsubst %,$(BUILD)/obj/lcmgen/%.o,$(LCM_TYPES))
LCM_LIBS := $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)

# lcm-gen exits 0 when it cannot write: create the directory first and check
# that every file appeared.
$(LCM_GEN_STAMP): $(LCM_FILES) mk/lcm.mk
	@command -v lcm-gen >/dev/null 2>&1 || { echo "lcm-gen not found: apt-get install liblcm-dev liblcm-bin"; exit 1; }
	@rm -rf $(LCM_GEN_DIR) && mkdir -p $(LCM_GEN_DIR)
	$(call say,GEN,$(LCM_GEN_DIR) (lcm-gen))
	$(Q)lcm-gen -c --c-no-pubsub --c-cpath $(LCM_GEN_DIR) --c-hpath $(LCM_GEN_DIR) $(LCM_FILES) > /dev/null
	@for f in $(LCM_GEN_C) $(LCM_GEN_H); do \
	  test -s $$f || { echo "lcm-gen did not write $$f"; rm -f $@; exit 1; }; done
	@touch $@
$(LCM_GEN_C) $(LCM_GEN_H): $(LCM_GEN_STAMP) ;

# Generated code is not ours to fix: no -Werror, no pedantic (it compares
# function and object pointers), no unused-parameter warnings. Sanitizer
# builds compile it at -O0: gcc takes 17 s for trk_bridge_status_t.c at -O1
# with ASan+UBSan (0.3 s at -O0), and it is instrumented all the same.
$(BUILD)/obj/lcmgen/%.o: $(LCM_GEN_DIR)/%.c $(LCM_GEN_STAMP) $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(filter-out -Werror -Wpedantic,$(CFLAGS_ALL)) $(if $(filter 1,$(SAN)),-O0) -Wno-unused-parameter -I$(LCM_GEN_DIR) -c $< -o $@

# into libtrk_lcm.a (its recipe archives every object prerequisite)
$(call LAYERLIB,lcm): $(LCM_GEN_OBJS)

# everything that includes a generated header waits for lcm-gen
LCM_USERS := $(wildcard tools/lcm/*.c tools/trk-lcm-bridge/*.c tools/trk-sonar-sim/*.c \
  tools/trk-bench/bench_lcm.c tests/test_lcm_*.c)
$(call obj,$(LCM_USERS)): $(LCM_GEN_STAMP)

# --- install: the message definitions (for lcm-gen in other languages), and
# the generated types for C (with LCM's publish/subscribe functions: headers
# in include/trk/lcm/, code in libtrk_lcmtypes.a, pkg-config trk-lcm) and C++
# (header-only, include/trk/lcm-cpp/trk/*.hpp). The types do not depend on
# REAL: the double and the float install write the same files. (Python:
# mk/python.mk; Java: mk/lcm_java.mk.)
LCM_SHARE = $(DESTDIR)$(PREFIX)/share/trk/lcm
LCM_INST_DIR := $(BUILD)/lcm-install
LCM_INST_STAMP := $(LCM_INST_DIR)/.stamp
LCM_TYPES_LIB := $(LCM_INST_DIR)/libtrk_lcmtypes.a
LCM_INST_OBJS := $(patsubst %,$(LCM_INST_DIR)/obj/%.o,$(LCM_TYPES))
$(LCM_INST_STAMP): $(LCM_FILES) mk/lcm.mk
	@command -v lcm-gen >/dev/null 2>&1 || { echo "lcm-gen not found: apt-get install liblcm-dev liblcm-bin"; exit 1; }
	@rm -rf $(LCM_INST_DIR) && mkdir -p $(LCM_INST_DIR)/include/trk/lcm $(LCM_INST_DIR)/src $(LCM_INST_DIR)/cpp $(LCM_INST_DIR)/obj
	$(call say,GEN,$(LCM_INST_DIR) (lcm-gen -c, -x))
	$(Q)lcm-gen -c --c-cpath $(LCM_INST_DIR)/src --c-hpath $(LCM_INST_DIR)/include/trk/lcm --cinclude trk/lcm $(LCM_FILES) > /dev/null
	$(Q)lcm-gen -x --cpp-hpath $(LCM_INST_DIR)/cpp $(LCM_FILES) > /dev/null
	@for t in $(LCM_TYPES); do test -s $(LCM_INST_DIR)/src/$$t.c && test -s $(LCM_INST_DIR)/include/trk/lcm/$$t.h && \
	  test -s $(LCM_INST_DIR)/cpp/trk/$${t#trk_}.hpp || { echo "lcm-gen did not write $$t"; exit 1; }; done
	@touch $@
$(LCM_INST_OBJS): $(LCM_INST_DIR)/obj/%.o: $(LCM_INST_STAMP)
	$(call say,CC,$(LCM_INST_DIR)/src/$*.c)
	$(Q)$(CC) -std=c99 $(OPT) -fPIC -I$(LCM_INST_DIR)/include $(shell pkg-config --cflags lcm 2>/dev/null) \
	  -c $(LCM_INST_DIR)/src/$*.c -o $@
$(LCM_TYPES_LIB): $(LCM_INST_OBJS)
	$(archive)
.PHONY: install-lcm-types
install: install-lcm-types
install-lcm-types: $(LCM_TYPES_LIB)
	install -d $(LCM_SHARE) $(DESTDIR)$(PREFIX)/include/trk/lcm $(DESTDIR)$(PREFIX)/include/trk/lcm-cpp/trk \
	  $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 $(LCM_FILES) $(LCM_SHARE)/
	install -m 644 $(LCM_INST_DIR)/include/trk/lcm/*.h $(DESTDIR)$(PREFIX)/include/trk/lcm/
	install -m 644 $(LCM_INST_DIR)/cpp/trk/*.hpp $(DESTDIR)$(PREFIX)/include/trk/lcm-cpp/trk/
	install -m 644 $(LCM_TYPES_LIB) $(DESTDIR)$(PREFIX)/lib/
	printf '%s\n' 'prefix=$(PREFIX)' 'includedir=$${prefix}/include' 'libdir=$${prefix}/lib' \
	  'cppincludedir=$${includedir}/trk/lcm-cpp' 'lcmdir=$${prefix}/share/trk/lcm' '' \
	  'Name: trk-lcm' 'Description: trk LCM message types (lcm-gen C code with publish/subscribe; C++: -I$${cppincludedir})' \
	  'Version: $(TRK_VERSION)' 'Requires: lcm' 'Cflags: -I$${includedir}' 'Libs: -L$${libdir} -ltrk_lcmtypes' \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/trk-lcm.pc

# --- demo: simulated sonar -> LCM log -> bridge (replay) -> track log -> summary
DEMO_LCM_DIR = $(BUILD)/demo-lcm
.PHONY: demo-lcm test-lcm-udpm
DEMO_LCM_SONAR = --targets 4 --seed 7 --clutter-model k --k-shape 2 --snr-db 16 --pfa 1e-3 --clutter-density 2.5e-6
demo-lcm: $(BUILD)/bin/trk-sonar-sim $(BUILD)/bin/trk-lcm-bridge $(BUILD)/bin/trk-tablegen
	@mkdir -p $(DEMO_LCM_DIR)
	@echo "== LCM demo 1/4: simulated sonar -> $(DEMO_LCM_DIR)/detections.lcmlog"
	@echo "   (4 targets, K-distributed clutter nu 2, 16 dB, 10 clutter detections per scan, a malformed message every 25th scan)"
	$(BUILD)/bin/trk-sonar-sim --out $(DEMO_LCM_DIR)/detections.lcmlog --scans 150 $(DEMO_LCM_SONAR) --bad-every 25
	@echo "== LCM demo 2/4: the bridge's settings for this sonar (amplitude model included) and its K table"
	$(BUILD)/bin/trk-sonar-sim $(DEMO_LCM_SONAR) --print-bridge-config --bridge-amp-table $(DEMO_LCM_DIR)/sonar.amp \
	  > $(DEMO_LCM_DIR)/bridge.conf
	$(BUILD)/bin/trk-tablegen amp --clutter-model k --k-shape 2 --snr-db 16 --pfa 1e-3 --out $(DEMO_LCM_DIR)/sonar.amp \
	  > /dev/null
	@echo "== LCM demo 3/4: trk-lcm-bridge --replay -> $(DEMO_LCM_DIR)/tracks.lcmlog"
	$(BUILD)/bin/trk-lcm-bridge --config $(DEMO_LCM_DIR)/bridge.conf --replay $(DEMO_LCM_DIR)/detections.lcmlog \
	  --out $(DEMO_LCM_DIR)/tracks.lcmlog --keep-input
	@echo "== LCM demo 4/4: what the track log holds"
	$(BUILD)/bin/trk-lcm-bridge --summarize $(DEMO_LCM_DIR)/tracks.lcmlog
demo: demo-lcm

# --- UDP multicast in a private network namespace (no real network touched)
TEST_EXTRA += test-lcm-udpm
TEST_EXTRA_DEPS_test-lcm-udpm := $(BUILD)/bin/trk-sonar-sim $(BUILD)/bin/trk-lcm-bridge
test-lcm-udpm: $(TEST_EXTRA_DEPS_test-lcm-udpm)
	@sh tests/lcm_udpm_netns.sh $(BUILD)

# --- the LCM walk-through of docs/lcm.md, run literally (offline and live over
# udpm in a network namespace): as many confirmed tracks as targets
.PHONY: test-lcm-walkthrough
TEST_EXTRA += test-lcm-walkthrough
TEST_EXTRA_DEPS_test-lcm-walkthrough := $(BUILD)/bin/trk-sonar-sim $(BUILD)/bin/trk-lcm-bridge $(BUILD)/bin/trk-tablegen
test-lcm-walkthrough: $(TEST_EXTRA_DEPS_test-lcm-walkthrough)
	@$(if $(filter build,$(BUILD)),sh tests/lcm_walkthrough.sh docs/lcm.md,echo "test-lcm-walkthrough: the commands of docs/lcm.md name build/bin: run with BUILD=build")
