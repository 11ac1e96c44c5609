# qemu.mk - the reference vectors on the target ISA: make qemu-test
#
#   build/qemu/<target>/fw.elf: a bare-metal image for QEMU's mps2 boards
#   (tests/qemu/: startup.c, mps2.ld, main.c) holding
#     - libtrk exactly as make cross builds it (build/cross/<target>/libtrk.a)
#     - the host's vector parser, checker and kinds (tools/vec/*.c), compiled
#       for the target, with every kind_*.c picked up automatically
#     - tools/common/*.c that build for the target (helpers of the kinds; a
#       file that does not build is left out with a message - if a kind needs
#       it, the link fails and says so)
#     - every $(VECTORS_DIR)/*.vec file as C data (tests/qemu/vec2c.sh)
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
#   make qemu-test-cortex-m4f
#   make qemu-build          the images only
#
# Kinds left out of the image (their cases are counted as "skipped on target"):
#   q2_pdaf q2_pdafai  importance-sampling Monte Carlo estimators of q2
#                      (tools/common/q2_is.c, 3e6-8e6 scenes per case, ~5 s per
#                      file natively at -O3 with doubles): hours under emulation
#                      on a float-only FPU; they are tool-side numerics, not
#                      firmware code. mre_steady and crlb_irf (same file) run.
# Memory: the parser's case buffers are lowered to VEC_POOL = 65536 values and
# VEC_MAX_ENTRIES = 512 (tools/vec/vec.h; 2^18 on the host): ~1.3 MB, ~2 MB of
# .bss in all, of the board's 4 MiB RAM (stack: the top 256 KiB). The largest
# public case needs 11249 values; a larger one fails loudly ("case too large").
# Code space (4 MiB): ~0.7 MB of vector text, 0.7 MB (float) / 1.3 MB (double)
# of tables.

QEMU ?= qemu-system-arm
QEMU_TIMEOUT ?= 900
QEMU_TARGETS ?= cortex-m4f cortex-m7d
QEMU_MACHINE_cortex-m4f := mps2-an386
QEMU_MACHINE_cortex-m7d := mps2-an500
FW_SKIP_KINDS ?= q2_pdaf q2_pdafai
FW_VEC_DEFS := -DVEC_POOL='(1u << 16)' -DVEC_MAX_ENTRIES=512
FW_WARN := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes \
  -Wno-format-truncation
FW_VEC_FILES = $(sort $(wildcard $(VECTORS_DIR)/*.vec))
FW_KIND_SRC = $(sort $(wildcard tools/vec/kind_*.c))
FW_RANDOM123 ?= /usr/include/Random123
FW_TABLEGEN = $(BUILD)/bin/trk-tablegen
# newlib-nano + semihosting. Neither nano nor Debian's full newlib printf
# knows C99 %zu (messages of some kinds print "zu" and a shifted argument on
# target: cosmetic, the counts and comparisons are unaffected).
FW_SPECS ?= --specs=nano.specs --specs=rdimon.specs

define QEMU_template
FW_DIR_$(1) := build/qemu/$(1)
FW_CFLAGS_$(1) = $$(FW_WARN) $$(TARGET_$(1)_CFLAGS) $$(FW_VEC_DEFS) -ffunction-sections -fdata-sections -g \
  -Iinclude -Itools/vec -Itools/common -I$$(FW_DIR_$(1))/gen -isystem $$(FW_DIR_$(1))/inc \
  -DFW_TARGET='"$(1) on $$(QEMU_MACHINE_$(1))"' -DFW_SKIP_KINDS='"$$(FW_SKIP_KINDS)"' \
  -DFW_AMP_K_DIRECT=$$(if $$(TARGET_$(1)_FLOAT),0,1)
FW_HARNESS_SRC_$(1) = tools/vec/vec.c tools/vec/registry.c $$(FW_KIND_SRC) tests/qemu/startup.c tests/qemu/main.c
FW_HARNESS_OBJ_$(1) = $$(patsubst %.c,$$(FW_DIR_$(1))/obj/%.o,$$(FW_HARNESS_SRC_$(1))) $$(FW_DIR_$(1))/obj/vec_data.o \
  $$(FW_DIR_$(1))/obj/amp_tables.o

$$(FW_DIR_$(1))/inc/.stamp:
	@mkdir -p $$(@D)
	@if [ -d $$(FW_RANDOM123) ]; then ln -sfn $$(FW_RANDOM123) $$(@D)/Random123; fi
	@touch $$@
$$(FW_DIR_$(1))/gen/vec_kinds.inc: $$(FW_KIND_SRC) mk/qemu.mk
	@mkdir -p $$(@D)
	sed -n 's/^TRK_VEC_KIND(\([^)]*\)).*/TRK_VEC_KIND_ENTRY(\1)/p' $$(FW_KIND_SRC) | \
	  awk -v skip="$$(FW_SKIP_KINDS)" 'BEGIN { n = split(skip, s, " "); for (i = 1; i <= n; i++) k[s[i]] = 1 } \
	    { name = $$$$0; sub(/^TRK_VEC_KIND_ENTRY\(/, "", name); sub(/,.*/, "", name); if (!(name in k)) print }' > $$@.tmp
	mv $$@.tmp $$@
$$(FW_DIR_$(1))/vec_data.c: $$(FW_VEC_FILES) tests/qemu/vec2c.sh
	@mkdir -p $$(@D)
	sh tests/qemu/vec2c.sh $$(FW_VEC_FILES) > $$@.tmp && mv $$@.tmp $$@
$$(FW_DIR_$(1))/tables/amp_tables.c: $$(FW_VEC_FILES) tests/qemu/amp_tables.sh $$(FW_TABLEGEN)
	@mkdir -p $$(@D)
	sh tests/qemu/amp_tables.sh $$(FW_TABLEGEN) $$(if $$(TARGET_$(1)_FLOAT),float,double) $$(@D) $$(FW_VEC_FILES) > $$@.tmp
	mv $$@.tmp $$@
$$(FW_DIR_$(1))/obj/amp_tables.o: $$(FW_DIR_$(1))/tables/amp_tables.c
	@mkdir -p $$(@D)
	$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -c $$< -o $$@
$$(FW_DIR_$(1))/obj/vec_data.o: $$(FW_DIR_$(1))/vec_data.c
	@mkdir -p $$(@D)
	$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -Wno-overlength-strings -c $$< -o $$@
$$(FW_DIR_$(1))/obj/%.o: %.c $$(FW_DIR_$(1))/gen/vec_kinds.inc $$(FW_DIR_$(1))/inc/.stamp \
  $$(wildcard include/trk/*.h tools/vec/*.h tools/common/*.h) mk/qemu.mk
	@mkdir -p $$(@D)
	$$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -c $$< -o $$@
# helpers of the kinds: best effort (see the top of this file)
$$(FW_DIR_$(1))/libfwcommon.a: $$(wildcard tools/common/*.c tools/common/*.h) $$(FW_DIR_$(1))/inc/.stamp mk/qemu.mk
	@mkdir -p $$(FW_DIR_$(1))/common
	@rm -f $$@; ok=""; for f in $$(wildcard tools/common/*.c); do \
	  o=$$(FW_DIR_$(1))/common/$$$$(basename $$$$f .c).o; \
	  if $$(TARGET_$(1)_CC) $$(FW_CFLAGS_$(1)) -c $$$$f -o $$$$o 2>$$$$o.err; then ok="$$$$ok $$$$o"; \
	  else echo "   qemu-$(1): $$$$f does not build for the target, left out: $$$$(grep -m1 error $$$$o.err)"; fi; \
	done; $$(call cross_tool,$(1),ar) rcs $$@ $$$$ok
$$(FW_DIR_$(1))/fw.elf: $$(FW_HARNESS_OBJ_$(1)) $$(FW_DIR_$(1))/libfwcommon.a build/cross/$(1)/libtrk.a tests/qemu/mps2.ld
	$$(TARGET_$(1)_CC) $$(TARGET_$(1)_CFLAGS) -nostartfiles $$(FW_SPECS) \
	  -u _printf_float -T tests/qemu/mps2.ld -Wl,--gc-sections -Wl,-Map=$$@.map \
	  $$(FW_HARNESS_OBJ_$(1)) $$(FW_DIR_$(1))/libfwcommon.a build/cross/$(1)/libtrk.a -lm -o $$@
	@$$(call cross_tool,$(1),size) $$@
qemu-build-$(1): $$(FW_DIR_$(1))/fw.elf
qemu-test-$(1): $$(FW_DIR_$(1))/fw.elf size-files-$(1)
	@command -v $$(QEMU) >/dev/null || { echo "qemu-test: $$(QEMU) not found (apt-get install qemu-system-arm)"; exit 1; }
	@echo "== qemu-test $(1) ($$(QEMU_MACHINE_$(1))): $$<"
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

# make test runs both images (about 45 s from scratch, ~5 s of it emulation)
# The Makefile expands test-extra's prerequisites before mk/*.mk is read,
# so TEST_EXTRA += alone would not register the step: name it directly too.
TEST_EXTRA += qemu-test
test-extra: qemu-test
