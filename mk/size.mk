# size.mk - footprint report of the cross builds: make size-report
#
#   make size-report    builds the cross targets (mk/cross.mk) and prints
#                       - .text/.rodata/.data/.bss per module and target
#                       - sizeof(struct trk_tracker) at the default and a small
#                         configuration (TRK_MAX_TRACKS=8, TRK_MAX_DETECTIONS=32,
#                         TRK_MAX_SENSORS=2), per target
#                       - worst-case stack depth of every public function
#                       - what a typical firmware image links (tools/scripts/
#                         fw_footprint.c: tracker + amplitude from a ROM table,
#                         --gc-sections), per library (libtrk, libm, libc, libgcc)
#                       - the footprint goals (M4F .text <= 32 KB, RAM for 64
#                         tracks x 256 detections <= 64 KB, stack <= 2 KB)
#   make size-check     (part of make test) fails when, on cortex-m4f:
#                       - libtrk has static data (.data/.bss: no global state)
#                       - the worst stack of trk_tracker_process_scan exceeds
#                         STACK_LIMIT (2048; STACK_LIMIT_FILTERS, 2176, in the
#                         builds with IMM or the alpha-beta filter)
#                       - sizeof(struct trk_tracker) + a scan of
#                         TRK_MAX_DETECTIONS detections + that stack exceed
#                         RAM_LIMIT (73744: 64 KB + the clutter maps, below) at the default capacities
#                       - the libtrk code a typical firmware image links
#                         (fw_footprint.c) exceeds TEXT_LIMIT_JOINT (55296) with
#                         the defaults (joint association: +7.1 KB), or
#                         TEXT_LIMIT (48000) in a build without
#                         joint association (TRK_WITH_JOINT=0, target
#                         cortex-m4f-nojoint)
#                       The whole libtrk.a's .text is reported, not gated: a
#                         firmware pays only for what it links (every module
#                         is in the archive, the alpha-beta steady state and
#                         the estimators a firmware links only when it calls
#                         them included), so the budgets are the images'. The
#                         design-time analysis code (q2 lookup, MRE, TOC, ROC,
#                         CRLB) is in libtrk_perf.a, reported apart.
#
# Stack method (tools/scripts/stack_ci.awk, stack_elf.awk):
#   1. every cross object is compiled with -fstack-usage -fcallgraph-info=su:
#      gcc writes each function's own frame (.su) and the calls that survived
#      optimisation (.ci);
#   2. ARM targets: the whole libtrk.a is linked with newlib-nano and libm
#      (tools/scripts/probe_main.c, probe.elf, never run); stack_elf.awk reads
#      its disassembly (push/vpush/sub sp per function, bl/tail-call edges)
#      and gives the worst depth of each libm/libc/libgcc function libtrk calls;
#   3. stack_ci.awk sums own frame + deepest callee over the library's call
#      graph, with the numbers of step 2 for external callees.
#   Limits: recursion and calls through function pointers are flagged, not
#   bounded; a preempting interrupt's own stack and exception frame are not
#   included; the riscv build has no C library to link, so its figures are
#   libtrk's own frames only. stack_elf.awk applied to libtrk's own functions
#   gives the same numbers as step 3 (a cross-check, see docs/firmware.md).

SIZE_SMALL_DEFS := -DTRK_MAX_TRACKS=8 -DTRK_MAX_DETECTIONS=32 -DTRK_MAX_SENSORS=2
STACK_LIMIT ?= 2048
# The builds with an optional track filter (TRK_WITH_IMM, TRK_WITH_ALPHA_BETA)
# had the default's 2 KB until each track's prediction carried its own R,
# P_D, lambda and covariance bound (polar sensors and the profiles over
# range): 2168 B with IMM and 2136 B with alpha-beta (2026-12-07, with the
# clutter map's edge rule), on the size build's general own-covariance PDA
# path (its Joseph form per detection); the default build is at 2032 B.
STACK_LIMIT_FILTERS ?= 2176
# The image limits were 32 KB (no joint association) and 36 KB until scans
# beyond capacity were thinned instead of refused (+3.4 KB in every image:
# the gate boxes, the bounded heap, the amplitude models' survival
# functions for the raised threshold) and detections outside the
# surveillance bound were counted (max_coord_m); both run in every scan.
# 34 KB and 40 KB until a new target in a nearly full table started with
# the three points' existence (+0.7 KB: the continuation's gate and
# likelihood, run whenever a pair was refused for want of a slot) and the
# covariance bound was applied to the prediction before gating (+0.1 KB).
# 35 KB and 41 KB until polar sensors and where a sensor sees (+4.5 KB in
# every image, run in every scan: the view of the pose and coverage, each
# track's P_D, lambda and R at its prediction with its own PDA constants,
# the conversion of polar detections, the parameters' check of the
# profiles, coverage and pose) and the velocity prior of two-point
# initiation (trk_kalman_update, +0.6 KB).
# 40 KB and 46 KB until the clutter map (+1.6 KB in every image: the cell
# of a position, a cell's ratio with its expected count, the scan's count
# of the detections no confirmed track gated, the parameters' check).
# 42 KB and 48 KB until amplitudes on a sonar (+2.1 KB with joint association,
# +1.4 KB without: the Rayleigh ratio at a P_D profile's SNR, persistent
# returns in the amplitude likelihood and at a raised threshold, two-point
# initiation's strongest-pairs-first order and its sort, the checks).
# 50 KB with joint association until its two-track clusters were solved in
# closed form (+0.35 KB: O(detections) in place of the subset programme,
# the worst-case scan's two tracks sharing a full gate; docs/firmware.md).
# 50.5 KB with joint association until a pair's second point took the
# density of its displacement under the new track's velocity prior (+0.3 KB:
# the Gaussian in the pair's odds and in the choice of partner; its gain on
# the sonar family in docs/tracker.md "Initial existence").
# 44.25 KB and 51 KB until a weak pair waited for its third point
# (init.min_existence, +0.2 KB: the threshold, the test of a first point
# evicted for room, the parameter's check; docs/tracker.md "A weak pair
# waits for a third point") and the merge kept the more probable of two
# tentative tracks.
# 44.5 KB and 51.25 KB until existence confirmation's gate-count check
# (confirm.existence.count_alpha, +0.4 KB: the chi-square cdf it takes the
# Poisson tail from, the counts per look; docs/tracker.md "The gate-count
# check").
# 51.5 KB with joint association until a cluster whose every joint event
# underflowed was solved again with floored weights (+0.3 KB: the check of
# its marginals and the floor; before, its tracks ended as numerical;
# jpda.h trk_jpda_report n_floored).
# 44.75 KB and 51.75 KB until the clutter map pooled a window of cells
# about a position, its guard counting one detection per scan less, the
# window wrapping in bearing on a map all round (+0.4 KB, +0.3 KB without
# joint association: the window's loop and its parameters' defaults and
# checks; docs/tracker.md "Clutter map").
# 45 KB and 52.25 KB until the clutter map's edge rule (+0.45 KB, +0.3 KB
# without joint association: the window's four quadrants summed in its
# loop, the Chernoff bounds of their Poisson tails, the parameter's
# default and check; docs/tracker.md "Clutter map").
# 45.5 KB and 52.75 KB until the gate-count check counted the gate's ring
# and the whole gate against a target of three highlights (+0.35 KB: a d2
# per gated detection of a tentative track, two more sums) and an
# adversarial pass's findings were mended (+0.2 KB: an unseen track's
# innovation with the sensor's R, the conversion's covariance at the pose,
# the checks of sigmas whose squares underflow, of the clutter map's floor
# and of the density's bound; docs/tracker.md "The gate-count check",
# "Polar sensors, P_D over range, coverage").
# 46 KB and 53.25 KB until a start's odds weighed each of its points
# alone (+0.2 KB in both images: each point's single-point odds and their
# log-sum; docs/tracker.md "Initial existence").
# 46.25 KB and 53.5 KB until a tentative track's echoes were weighed
# against a persistent scatterer's (+0.5 KB in both images: the look's
# ratio over its gated echoes, its bounded sum, the motion test's bar;
# docs/tracker.md "Echoes weighed against a scatterer's").
# 46.75 KB without joint association until every live track was updated once
# a scan (+0.1 KB there: the per-slot mark ws.done, which joint association
# already kept as in_joint, its clearing and tests in the per-track loops; a
# confirmed track that went back to held was updated a second time).
TEXT_LIMIT ?= 48000
TEXT_LIMIT_JOINT ?= 55296
# RAM: 64 KB for the table, the workspace and a full scan at the default
# capacities (64 tracks, 256 detections, 4 sensors) and the stack, plus each
# sensor's clutter map as its own line: TRK_MAX_SENSORS x
# (TRK_CLUTTER_MAP_CELLS + 1) float (4 x 513 x 4 B = 8208 B; a firmware
# with one sensor, TRK_MAX_SENSORS=1, pays 2052 B, TRK_CLUTTER_MAP_CELLS=256
# half, and TRK_CLUTTER_MAP_CELLS=0 none). 69648 until the map's default
# went from 16 x 16 cells to 16 x 32 (docs/tracker.md "Clutter map": the
# finer bearing cells with the guard cell keep positions-only false tracks
# down).
RAM_LIMIT ?= 73744
SIZE_PROBE_FLAGS := -std=c99 -Wall -Wextra -Wpedantic -Werror -fdata-sections -Iinclude
TARGET_cortex-m4f_ARCH := arm
TARGET_cortex-m4f-O2_ARCH := arm
TARGET_cortex-m7d_ARCH := arm
TARGET_cortex-m7d-O2_ARCH := arm
TARGET_cortex-m4f-inline_ARCH := arm
TARGET_cortex-m4f-sizeopt_ARCH := arm
TARGET_cortex-m4f-nojoint_ARCH := arm
TARGET_cortex-m4f-imm_ARCH := arm
TARGET_cortex-m4f-ab_ARCH := arm
TARGET_riscv_ARCH := riscv

define SIZE_template
build/cross/$(1)/size-A.txt: build/cross/$(1)/libtrk.a
	$$(Q)$$(call cross_tool,$(1),size) -A $$< > $$@.tmp && mv $$@.tmp $$@
build/cross/$(1)/sizeof-default.txt: tools/scripts/sizeof_probe.c $$(wildcard include/trk/*.h) mk/size.mk
	@mkdir -p $$(@D)
	$$(Q)$$(TARGET_$(1)_CC) $$(SIZE_PROBE_FLAGS) $$(TARGET_$(1)_CFLAGS) -c $$< -o $$(@:.txt=.o)
	$$(Q)$$(call cross_tool,$(1),nm) -S $$(@:.txt=.o) > $$@
build/cross/$(1)/sizeof-small.txt: tools/scripts/sizeof_probe.c $$(wildcard include/trk/*.h) mk/size.mk
	@mkdir -p $$(@D)
	$$(Q)$$(TARGET_$(1)_CC) $$(SIZE_PROBE_FLAGS) $$(TARGET_$(1)_CFLAGS) $$(SIZE_SMALL_DEFS) -c $$< -o $$(@:.txt=.o)
	$$(Q)$$(call cross_tool,$(1),nm) -S $$(@:.txt=.o) > $$@
ifeq ($$(TARGET_$(1)_ARCH),arm)
build/cross/$(1)/probe.elf: build/cross/$(1)/libtrk.a build/cross/$(1)/libtrk_perf.a tools/scripts/probe_main.c
	$$(Q)$$(TARGET_$(1)_CC) $$(TARGET_$(1)_CFLAGS) --specs=nano.specs --specs=nosys.specs tools/scripts/probe_main.c \
	  -Wl,--whole-archive build/cross/$(1)/libtrk_perf.a build/cross/$(1)/libtrk.a -Wl,--no-whole-archive -lm -o $$@
build/cross/$(1)/fw-footprint.txt: build/cross/$(1)/libtrk.a tools/scripts/fw_footprint.c tools/scripts/map_sum.awk
	$$(Q)$$(TARGET_$(1)_CC) $$(SIZE_PROBE_FLAGS) $$(TARGET_$(1)_CFLAGS) -ffunction-sections --specs=nano.specs --specs=nosys.specs \
	  -Wl,--gc-sections -Wl,-Map=build/cross/$(1)/fw-footprint.map tools/scripts/fw_footprint.c $$< -lm \
	  -o build/cross/$(1)/fw-footprint.elf
	$$(Q)awk -f tools/scripts/map_sum.awk build/cross/$(1)/fw-footprint.map > $$@
build/cross/$(1)/stack-extern.txt: build/cross/$(1)/probe.elf tools/scripts/stack_elf.awk
	$$(Q)$$(call cross_tool,$(1),objdump) -d --no-show-raw-insn $$< | awk -f tools/scripts/stack_elf.awk > $$@.tmp && mv $$@.tmp $$@
else
build/cross/$(1)/stack-extern.txt: build/cross/$(1)/libtrk.a
	: > $$@
build/cross/$(1)/fw-footprint.txt: build/cross/$(1)/libtrk.a
	: > $$@
endif
build/cross/$(1)/stack.txt: build/cross/$(1)/libtrk.a build/cross/$(1)/libtrk_perf.a build/cross/$(1)/stack-extern.txt \
  tools/scripts/stack_ci.awk
	$$(Q)awk -v EXTERN=build/cross/$(1)/stack-extern.txt -v ROOTS=public -f tools/scripts/stack_ci.awk \
	  $$(patsubst %.o,%.ci,$$(CROSS_OBJ_$(1)) $$(CROSS_PERF_OBJ_$(1))) | sort > $$@.tmp && mv $$@.tmp $$@
size-files-$(1): build/cross/$(1)/size-A.txt build/cross/$(1)/sizeof-default.txt \
  build/cross/$(1)/sizeof-small.txt build/cross/$(1)/stack.txt build/cross/$(1)/fw-footprint.txt
endef
$(foreach t,$(CROSS_TARGETS_KNOWN),$(eval $(call SIZE_template,$(t))))

.PHONY: size-report size-check $(addprefix size-files-,$(CROSS_TARGETS_KNOWN))
size-report: cross
	@$(MAKE) --no-print-directory $(addprefix size-files-,$(CROSS_TARGETS)) build/cross/cortex-m4f-nojoint/fw-footprint.txt >/dev/null
	@sh tools/scripts/size_report.sh build/cross $(CROSS_TARGETS)

TEST_EXTRA += size-check
TEST_EXTRA_DEPS_size-check := build/cross/cortex-m4f/libtrk.a size-files-cortex-m4f \
  build/cross/cortex-m4f-nojoint/fw-footprint.txt build/cross/cortex-m4f-imm/stack.txt \
  build/cross/cortex-m4f-imm/sizeof-default.txt build/cross/cortex-m4f-imm/fw-footprint.txt \
  build/cross/cortex-m4f-ab/stack.txt build/cross/cortex-m4f-ab/fw-footprint.txt
size-check: cross-cortex-m4f $(TEST_EXTRA_DEPS_size-check)
	@awk '/^\.s?(data|bss)/ && $$2 > 0 { print "size-check: static data in libtrk: " $$0; bad = 1 } END { exit bad }' \
	  build/cross/cortex-m4f/size-A.txt
	@awk -v slim=$(STACK_LIMIT) -v flim=$(STACK_LIMIT_FILTERS) -v rlim=$(RAM_LIMIT) -v tlim=$(TEXT_LIMIT) -v tjlim=$(TEXT_LIMIT_JOINT) \
	  ' \
	  function hex(s,   i, v) { v = 0; s = tolower(s); for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1; return v } \
	  FILENAME ~ /-ab\/stack.txt$$/ { split($$0, f, "\t"); if (f[1] == "trk_tracker_process_scan") { sta = f[2] + 0; patha = f[5] } next } \
	  FILENAME ~ /-ab\/fw-footprint/ && $$1 == "libtrk" { fwa = $$2 + 0; next } \
	  FILENAME ~ /imm\/stack.txt$$/ { split($$0, f, "\t"); if (f[1] == "trk_tracker_process_scan") { sti = f[2] + 0; pathi = f[5] } next } \
	  FILENAME ~ /stack.txt$$/ { split($$0, f, "\t"); if (f[1] == "trk_tracker_process_scan") { st = f[2] + 0; path = f[5] } next } \
	  FILENAME ~ /imm\/sizeof-default/ && NF == 4 { szi[$$4] = hex($$2); next } \
	  FILENAME ~ /imm\/fw-footprint/ && $$1 == "libtrk" { fwi = $$2 + 0; next } \
	  FILENAME ~ /sizeof-default/ && NF == 4 { sz[$$4] = hex($$2); next } \
	  FILENAME ~ /nojoint\/fw-footprint/ && $$1 == "libtrk" { fwn = $$2 + 0; next } \
	  FILENAME ~ /fw-footprint/ && $$1 == "libtrk" { fw = $$2 + 0; next } \
	  FILENAME ~ /size-A/ && $$1 ~ /^\.text/ { lib += $$2; next } \
	  END { bad = 0; \
	    if (st == "") { print "size-check: no stack figure for trk_tracker_process_scan"; exit 1 } \
	    ram = sz["trk_sizeof_tracker"] + sz["trk_sizeof_scan_detections"] + st; \
	    printf "size-check cortex-m4f: stack of trk_tracker_process_scan %d B (limit %d)\n", st, slim; \
	    printf "size-check cortex-m4f: RAM for the default capacities %d B = tracker %d + scan %d + stack %d (limit %d)\n", \
	      ram, sz["trk_sizeof_tracker"], sz["trk_sizeof_scan_detections"], st, rlim; \
	    printf "size-check cortex-m4f: libtrk .text in a typical firmware image %d B (limit %d); no .data/.bss\n", fw, tjlim; \
	    printf "size-check cortex-m4f: the same without joint association (TRK_WITH_JOINT=0) %d B (limit %d)\n", fwn, tlim; \
	    printf "size-check cortex-m4f: the whole libtrk.a .text %d B (reported, not gated: an image links what it calls; analysis modules in libtrk_perf.a)\n", lib; \
	    printf "size-check cortex-m4f-imm (TRK_WITH_IMM=1, 3 models): stack of trk_tracker_process_scan %d B (limit %d); tracker %d B (%d without IMM; track %d B, %d without); libtrk .text in a typical image %d B\n", \
	      sti, flim, szi["trk_sizeof_tracker"], sz["trk_sizeof_tracker"], szi["trk_sizeof_track"], sz["trk_sizeof_track"], fwi; \
	    printf "size-check cortex-m4f-ab (TRK_WITH_ALPHA_BETA=1): stack of trk_tracker_process_scan %d B (limit %d); libtrk .text in a typical image %d B\n", \
	      sta, flim, fwa; \
	    if (sti == "" || sti > flim) { print "size-check: FAILED stack with IMM, worst path: " pathi; bad = 1 } \
	    if (sta == "" || sta > flim) { print "size-check: FAILED stack with alpha-beta, worst path: " patha; bad = 1 } \
	    if (st > slim) { print "size-check: FAILED stack, worst path: " path; bad = 1 } \
	    if (ram > rlim) { print "size-check: FAILED RAM"; bad = 1 } \
	    if (fw > tjlim) { print "size-check: FAILED .text"; bad = 1 } \
	    if (fwn > tlim) { print "size-check: FAILED .text without joint association"; bad = 1 } \
	    exit bad }' build/cross/cortex-m4f/stack.txt build/cross/cortex-m4f/sizeof-default.txt \
	  build/cross/cortex-m4f/fw-footprint.txt build/cross/cortex-m4f-nojoint/fw-footprint.txt \
	  build/cross/cortex-m4f-imm/stack.txt build/cross/cortex-m4f-imm/sizeof-default.txt \
	  build/cross/cortex-m4f-imm/fw-footprint.txt build/cross/cortex-m4f-ab/stack.txt \
	  build/cross/cortex-m4f-ab/fw-footprint.txt build/cross/cortex-m4f/size-A.txt
