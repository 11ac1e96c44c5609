# qemu.mk - the reference vectors on the target ISA: make qemu-test
#
#   build/qemu/<target>/fw.elf: a bare-metal image for QEMU's mps2 boards
#   (tests/qemu/: startup.c, mps2.ld, main.c) holding
#     - libtrk and libtrk_perf exactly as make cross builds them
#       (build/cross/<target>/libtrk.a, libtrk_perf.a)
#     - the host's vector parser, checker and kinds (tools/vec/*.c), compiled
#       for the target, with every kind_*.c picked up automatically
#     - the firmware-capable helpers of the kinds (FW_COMMON_SRC below)
#     - every $(VECTORS_DIR)/*.vec file as C data (tests/qemu/vec2c.sh), the
#       cases of kinds the image does not run reduced to their case/end lines
#     - an amplitude lookup table per K-clutter parameter set of those files,
#       made by the host's trk-tablegen in the target's real width and linked
#       as a const array (tests/qemu/amp_tables.sh): model-k amplitude cases
#       are checked by table lookup ("<kind>/table" lines); on float-only
#       targets only so (the kinds' direct K evaluation is tool-side
#       double-precision quadrature: minutes of soft-double under emulation)
#   run with semihosting; QEMU's exit status is the image's.
#
#   make qemu-test           cortex-m4f on mps2-an386 (Cortex-M4F, float), then
#                            cortex-m7d on mps2-an500 (Cortex-M7, double FPU, double)
#   make qemu-test-cortex-m4f  one of them (each is a step of `make test`)
#   make qemu-build          the images only
#
# Kinds in the image: every kind of tools/vec/kind_*.c but those registered
# VEC_SLOW (the importance-sampling Monte Carlo estimators of q2, q2_pdaf and
# q2_pdafai: 3e6-8e6 scenes per case, hours under emulation on a float-only
# FPU; tool-side numerics, not firmware code; mre_steady and crlb_irf run).
# Only the cases of those kinds are embedded whole; a case of any other kind
# (slow, or not implemented yet) is embedded as its `case` and `end` lines
# alone, so the image reports it - slow ones as "skipped on target",
# unknown ones as "unimplemented" - whatever its size (tests/qemu/vec2c.sh
# --keep). The image's size thus depends on the implemented kinds' cases only.
# Memory (tests/qemu/mps2.ld, as QEMU 7.2 models both boards: `info mtree`):
# 4 MiB SSRAM1 at 0 for code and the load image of .data, 4 MiB SSRAM2/3 at
# 0x20000000 for .data, .bss, heap and stack (top 256 KiB); the link fails with
# a message when either does not fit. The parser's case buffers are lowered
# to VEC_POOL = 65536 values and VEC_MAX_ENTRIES = 512 (tools/vec/vec.h; 2^18
# on the host): ~1.3 MB of .bss. The largest public case needs 11249 values; a
# larger one fails loudly ("case too large").
# The firmware-capable layers: src (libtrk), src/perf (libtrk_perf), tools/vec
# (the kinds) and, from tools/gen, the model files the kinds call,
# named in FW_COMMON_SRC (K-distribution quadrature, the in-memory amplitude
# table, the q2 amplitude law, the table writer); the rest of those layers
# uses the host's clock, files or threads.
# The image is rebuilt when VECTORS_DIR or its file list changes
# ($(FW_DIR)/vectors.list holds both).

QEMU ?= qemu-system-arm
QEMU_TIMEOUT ?= 900
QEMU_TARGETS ?= cortex-m4f cortex-m7d
QEMU_MACHINE_cortex-m4f := mps2-an386
QEMU_MACHINE_cortex-m7d := mps2-an500
FW_VEC_DEFS := -DVEC_POOL='(1u << 16)' -DVEC_MAX_ENTRIES=512
FW_WARN := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes \
  -Wno-format-truncation
FW_VEC_FILES = $(sort $(wildcard $(VECTORS_DIR)/*.vec))
FW_KIND_SRC = $(sort $(wildcard tools/vec/kind_*.c))
# the kinds registered VEC_SLOW: not in the image's registry
FW_SKIP_KINDS := $(shell sed -n 's/^TRK_VEC_KIND(\([a-z0-9_]*\),.*VEC_SLOW).*/\1/p' $(sort $(wildcard tools/vec/kind_*.c)))
FW_COMMON_SRC := tools/gen/amp_table.c tools/gen/kdist.c tools/gen/q2_amp.c tools/gen/table_writer.c tools/cli/number.c
FW_RANDOM123 ?= /usr/include/Random123
FW_TABLEGEN = $(BUILD)/bin/trk-tablegen
# newlib-nano + semihosting. Neither nano nor Debian's full newlib printf
# knows C99 %zu (messages of some kinds print "zu" and a shifted argument on
# target: cosmetic, the counts and comparisons are unaffected).
FW_SPECS ?= --specs=nano.specs --specs=rdimon.specs

define QEMU_template
FW_DIR_$(1) := build/qemu/$(1)
FW_CFLAGS_$(1) = $$(FW_WARN) $$(TARGET_$(1)_CFLAGS) $$(FW_VEC_DEFS) -ffunction-sections -fdata-sections -g \
  -Iinclude -Itools/vec -Itools/gen -Itools/cli -I$$(FW_DIR_$(1))/gen -isystem $$(FW_DIR_$(1))/inc \
  -DFW_TARGET='"$(1) on $$(QEMU_MACHINE_$(1))"' -DFW_SKIP_KINDS='"$$(strip $$(FW_SKIP_KINDS))"' \
  -DFW_AMP_K_DIRECT=$$(if $$(TARGET_$(1)_FLOAT),0,1)
FW_HARNESS_SRC_$(1) = tools/vec/vec.c tools/vec/registry.c $$(FW_KIND_SRC) $$(FW_COMMON_SRC) tests/qemu/startup.c \
  tests/qemu/main.c
FW_HARNESS_OBJ_$(1) = $$(patsubst %.c,$$(FW_DIR_$(1))/obj/%.o,$$(FW_HARNESS_SRC_$(1))) $$(FW_DIR_$(1))/obj/vec_data.o \
  $$(FW_DIR_$(1))/obj/amp_tables.o

$$(FW_DIR_$(1))/inc/.stamp:
	@mkdir -p $$(@D)
	@if [ -d $$(FW_RANDOM123) ]; then ln -sfn $$(FW_RANDOM123) $$(@D)/Random123; fi
	@touch $$@
# the image's kind registry: every kind but the slow ones
$$(FW_DIR_$(1))/gen/vec_kinds.inc: $$(FW_KIND_SRC) mk/qemu.mk
	@mkdir -p $$(@D)
	$$(Q)sed -n '/VEC_SLOW)/d; s/^TRK_VEC_KIND(\([^)]*\)).*/TRK_VEC_KIND_ENTRY(\1)/p' $$(FW_KIND_SRC) > $$@.tmp
	$$(Q)mv $$@.tmp $$@
# VECTORS_DIR and its files, rewritten only when they change
$$(FW_DIR_$(1))/vectors.list: FORCE
	@mkdir -p $$(@D)
	@echo '$$(VECTORS_DIR): $$(FW_VEC_FILES)' > $$@.tmp; if cmp -s $$@.tmp $$@; then rm -f $$@.tmp; else mv $$@.tmp $$@; fi
$$(FW_DIR_$(1))/vec_data.c: $$(FW_VEC_FILES) $$(FW_DIR_$(1))/vectors.list $$(FW_DIR_$(1))/gen/vec_kinds.inc tests/qemu/vec2c.sh
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)
	$$(Q)sh tests/qemu/vec2c.sh --keep "$$$$(sed 's/^TRK_VEC_KIND_ENTRY(\([a-z0-9_]*\),.*/\1/' $$(FW_DIR_$(1))/gen/vec_kinds.inc)" \
	  $$(FW_VEC_FILES) > $$@.tmp && mv $$@.tmp $$@
$$(FW_DIR_$(1))/tables/amp_tables.c: $$(FW_VEC_FILES) $$(FW_DIR_$(1))/vectors.list tests/qemu/amp_tables.sh $$(FW_TABLEGEN)
	@mkdir -p $$(@D)
	$$(call say,GEN,$$@)
	$$(Q)sh tests/qemu/amp_tables.sh $$(FW_TABLEGEN) $$(if $$(TARGET_$(1)_FLOAT),float,double) $$(@D) $$(FW_VEC_FILES) > $$@.tmp
	$$(Q)mv $$@.tmp $$@
$$(FW_DIR_$(1))/obj/amp_tables.o: $$(FW_DIR_$(1))/tables/amp_tables.c
	@mkdir -p $$(@D)
	$$(call say,CC,$$< ($(1)))
	$$(Q)$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -c $$< -o $$@
$$(FW_DIR_$(1))/obj/vec_data.o: $$(FW_DIR_$(1))/vec_data.c
	@mkdir -p $$(@D)
	$$(call say,CC,$$< ($(1)))
	$$(Q)$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -Wno-overlength-strings -c $$< -o $$@
$$(FW_DIR_$(1))/obj/%.o: %.c $$(FW_DIR_$(1))/gen/vec_kinds.inc $$(FW_DIR_$(1))/inc/.stamp \
  $$(wildcard include/trk/*.h tools/vec/*.h tools/gen/*.h tools/cli/number.h) mk/qemu.mk
	@mkdir -p $$(@D)
	$$(call say,CC,$$< ($(1)))
	$$(Q)$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -c $$< -o $$@
$$(FW_DIR_$(1))/fw.elf: $$(FW_HARNESS_OBJ_$(1)) build/cross/$(1)/libtrk_perf.a build/cross/$(1)/libtrk.a tests/qemu/mps2.ld
	$$(call say,LD,$$@)
	$$(Q)$$(TARGET_$(1)_CC) $$(TARGET_$(1)_CFLAGS) -nostartfiles $$(FW_SPECS) \
	  -u _printf_float -T tests/qemu/mps2.ld -Wl,--gc-sections -Wl,-Map=$$@.map \
	  $$(FW_HARNESS_OBJ_$(1)) build/cross/$(1)/libtrk_perf.a build/cross/$(1)/libtrk.a -lm -o $$@
	$$(Q)$$(call cross_tool,$(1),size) $$@ > $$@.size
qemu-build-$(1): $$(FW_DIR_$(1))/fw.elf
TEST_EXTRA += qemu-test-$(1)
TEST_EXTRA_DEPS_qemu-test-$(1) := $$(FW_DIR_$(1))/fw.elf size-files-$(1)
qemu-test-$(1): $$(TEST_EXTRA_DEPS_qemu-test-$(1))
	@command -v $$(QEMU) >/dev/null || { echo "qemu-test: $$(QEMU) not found (apt-get install qemu-system-arm)"; exit 1; }
	@echo "== qemu-test $(1) ($$(QEMU_MACHINE_$(1))): $$<"; cat $$<.size
	@start=$$$$(date +%s); \
	timeout $$(QEMU_TIMEOUT) $$(QEMU) -M $$(QEMU_MACHINE_$(1)) -nographic -semihosting -kernel $$< </dev/null \
	  > $$(FW_DIR_$(1))/run.log 2>&1; rc=$$$$?; end=$$$$(date +%s); \
	grep -v '^NOT-APPLICABLE' $$(FW_DIR_$(1))/run.log; \
	echo "   (not-applicable cases: $$$$(grep -c '^NOT-APPLICABLE' $$(FW_DIR_$(1))/run.log); full log $$(FW_DIR_$(1))/run.log)"; \
	echo "   qemu-test $(1): exit status $$$$rc, $$$$((end - start)) s wall"; \
	if [ $$$$rc -eq 124 ]; then echo "qemu-test $(1): timed out after $$(QEMU_TIMEOUT) s"; fi; \
	[ $$$$rc -eq 0 ] || exit 1
	@awk -F '\t' 'FILENAME ~ /stack.txt$$$$/ { bound[$$$$1] = $$$$2; next } \
	  /^stack: / { m["trk_tracker_process_scan"] = $$$$3; m["trk_pda_update"] = $$$$6 } \
	  END { bad = 0; for (f in m) { \
	    printf "   stack %s: measured %d B <= static bound %d B: %s\n", f, m[f], bound[f], (m[f] + 0 <= bound[f] + 0 ? "yes" : "NO"); \
	    if (m[f] + 0 > bound[f] + 0) bad = 1 } exit bad }' \
	  build/cross/$(1)/stack.txt FS=' ' $$(FW_DIR_$(1))/run.log
endef
$(foreach t,$(QEMU_TARGETS),$(eval $(call QEMU_template,$(t))))

.PHONY: qemu-test qemu-build $(addprefix qemu-test-,$(QEMU_TARGETS)) $(addprefix qemu-build-,$(QEMU_TARGETS))
qemu-build: $(addprefix qemu-build-,$(QEMU_TARGETS))
# everything is built by this make (no race with size-check under -j), then
# each image runs on its own, one after the other
qemu-test: qemu-build $(addprefix size-files-,$(QEMU_TARGETS))
	@set -e; for t in $(QEMU_TARGETS); do $(MAKE) --no-print-directory qemu-test-$$t; done

# --- float accuracy: every kind's largest error in the double build, the
# float build on the host and the float build on the Cortex-M4F (QEMU),
# against the reference values, next to the kind's float tolerance (justified
# in tools/vec/kind_*.c). trk-vectors --report-error prints each host column.
.PHONY: float-error-report
float-error-report:
	@$(MAKE) --no-print-directory BUILD=build tools >/dev/null
	@$(MAKE) --no-print-directory BUILD=build/float REAL=float tools >/dev/null
	@$(MAKE) --no-print-directory qemu-test-cortex-m4f >/dev/null
	@build/bin/trk-vectors --report-error --quiet $(FW_VEC_FILES) > build/qemu/report-double.txt || true
	@build/float/bin/trk-vectors --report-error --quiet $(FW_VEC_FILES) > build/qemu/report-float.txt || true
	@echo "== largest error against the reference values per kind (abs / rel / fraction of the tolerance used)"
	@awk 'FILENAME ~ /double/ && NF == 5 && $$2 ~ /^[0-9]+$$/ { d[$$1] = sprintf("%9.2g %9.2g", $$4, $$5); k[$$1] = 1 } \
	  FILENAME ~ /float/ && NF == 5 && $$2 ~ /^[0-9]+$$/ { f[$$1] = sprintf("%9.2g %9.2g %6.3f", $$3, $$4, $$5); k[$$1] = 1 } \
	  FILENAME ~ /run.log/ && NF == 9 && $$2 ~ /^[0-9]+$$/ { q[$$1] = sprintf("%9.2g %9.2g %6.3f", $$5, $$6, $$7); \
	    t[$$1] = sprintf("%8.2g %8.2g", $$8, $$9); k[$$1] = 1 } \
	  END { printf "%-20s | %19s | %26s | %26s | %17s\n", "kind", "double: rel  used", "host float: abs rel used", \
	          "M4F (QEMU): abs rel used", "float tol abs rel"; \
	    n = 0; for (x in k) K[++n] = x; \
	    for (i = 2; i <= n; i++) { v = K[i]; for (j = i - 1; j >= 1 && K[j] > v; j--) K[j + 1] = K[j]; K[j + 1] = v } \
	    for (i = 1; i <= n; i++) { x = K[i]; printf "%-20s | %19s | %26s | %26s | %17s\n", x, \
	      (x in d) ? d[x] : "-", (x in f) ? f[x] : "-", (x in q) ? q[x] : "(not on target)", (x in t) ? t[x] : "-" } }' \
	  build/qemu/report-double.txt build/qemu/report-float.txt build/qemu/cortex-m4f/run.log

# make test runs both images, each as a step of its own (qemu-test-<target>)
