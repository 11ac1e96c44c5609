# trk - target tracking library for active sonar. See README.md.
#
#   make                 libtrk (build/libtrk.a), libtrk_host.a, tools (build/bin/)
#   make check           the developer loop: build, then the tests and the reference
#                        vectors of ONE configuration (BUILD, CC, REAL, SAN), slow
#                        Monte Carlo vector kinds left out (counted and named)
#     make check T=tracker            one test program (T=test_tracker too; T=vectors,
#                                     T=heap: those steps; a list works)
#     make check T=tracker CASE='test_merge*'   one cmocka case (pattern, * and ?)
#     make check VEC_SLOW=1           the slow vector kinds too
#   make test            the whole matrix, configurations overlapped on 2 jobs
#                        (gcc + clang ASan+UBSan, float, small capacities, the
#                        default build's extra steps: QEMU, valgrind, fuzz replay,
#                        cross builds, ...); one line per step, a summary line
#                        per configuration and a final "test: N passed, N failed"
#   make bench           trk-bench in double and float
#   make bench-instr     instructions per scan_64x256 (callgrind), double and float
#   make bench-grid      the scan over a grid of tracks x detections
#   make demo            trk's main job (see README)
#   make docs            the API reference of include/trk (Doxygen), build/docs/html
#   make docs-run        the runnable blocks of README.md and docs/*.md
#   make cross           libtrk for Cortex-M (build/cross/<target>/libtrk.a)
#   make check-heap      fail if libtrk references a heap/stdio/abort symbol
#   make install PREFIX=/usr/local [DESTDIR=]   (float beside it: make install
#                        REAL=float BUILD=build/float PREFIX=...; docs/firmware.md "Install")
#   MPI=1|0              the MPI builds bin/trk-tablegen-mpi, bin/trk-sim-mpi
#                        (default: when mpicc is found; mk/mpi.mk, docs/analysis.md "MPI")
#
# Configuration variables (one build directory per configuration):
#   BUILD=build  CC=gcc|clang  REAL=double|float  SAN=0|1 (ASan+UBSan)  OPT=-O2
#   CONFIG_DEFS='-DTRK_MAX_TRACKS=8 ...'  (capacities, see include/trk/config.h)
#   V=1                  print the commands (default: one line per file and step)
#   DEBUG=-g             debug-information flags
#
# Layers: each a folder and an archive; a layer calls only layers below it
# (nothing to edit when adding a file to a layer):
#   tools/trk-NAME/*.c -> bin/trk-NAME: mains and subcommands only, no tool links
#                        another tool's objects; tools/trk-NAME/tool.mk may set
#                        TOOL_CFLAGS_trk-NAME, TOOL_LDLIBS_trk-NAME, TOOL_DEPS_trk-NAME
#   tools/lcm/*.c     -> libtrk_lcm.a   LCM message types (tools/lcm/types), copy,
#                                       log files, the bridge core          (uses cli)
#   tools/vec/*.c     -> libtrk_vec.a   reference-vector parser, checker, kinds (gen)
#   tools/sim/*.c     -> libtrk_sim.a   scenarios, amplitude draws, single-target
#                                       Monte Carlo, TOC curves, rng, stats
#                                       (gen, par, cli)
#   tools/gen/*.c     -> libtrk_gen.a   table generation, K quadrature, the q2
#                                       importance sampler (OpenMP)     (par, cli)
#   tools/par/*.c     -> libtrk_par.a   work distribution: batches of work units
#                                       on threads or MPI ranks, checkpoint (cli);
#                                       tools/par/mpi/ -> libtrk_par_mpi.a, the
#                                       MPI layer of the -mpi builds (mk/mpi.mk)
#   tools/cli/*.c     -> libtrk_cli.a   option parser, key=value files, tracker
#                                       configuration, progress, plots, errors, files
#   src/host/*.c      -> libtrk_host.a  the table file reader (host, stdio)
#   src/perf/*.c      -> libtrk_perf.a  design-time analysis: q2 lookup, MRE, TOC,
#                                       ROC, CRLB (not in the firmware archive)
#   src/*.c           -> libtrk.a       the firmware library: no heap, no stdio
#   tests/test_*.c    -> one cmocka test program each; tests/*.mk may add rules
#   examples/*.c      -> bin/example-NAME
#   mk/*.mk           -> extra targets (cross, fuzz, size report, ...); a file
#                        registers a step of `make test` with
#                          TEST_EXTRA += NAME
#                          TEST_EXTRA_DEPS_NAME := what NAME needs built
#                          NAME: $(TEST_EXTRA_DEPS_NAME) ; recipe
#                        (the deps are built first, visibly and in parallel;
#                        the step then runs with its output in a log)

BUILD ?= build
ifeq ($(origin CC),default)
CC := gcc
endif
REAL ?= double
SAN ?= 0
OPT ?= -O2
CONFIG_DEFS ?=
PREFIX ?= /usr/local
AR ?= ar
V ?= 0
# the label of this configuration in the output
CFG ?= $(if $(filter build,$(BUILD)),default,$(notdir $(BUILD)))

# --- output: one line per compiled or linked file (V=1: the commands)
ifeq ($(V),1)
Q :=
say =
else
Q := @
say = @printf '%-14s %-4s %s\n' '$(CFG)' '$(1)' '$(2)'
endif

WARN := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes
LIBWARN := -Wmissing-prototypes -Wdouble-promotion
# The library's kernels loop over constant dimensions (4 states, 2
# measurements); gcc -O2 does not unroll them all, -funroll-loops does
# (trk-bench pda_update_m10: 303 -> 256 ns with gcc 12), and -O3 vectorises
# the 4 x 4 covariance rows that -O2's cheap cost model leaves scalar
# (pda_update_m10 / its baseline 1.25 -> 1.18 double, 1.46 ->
# 1.33 float, gcc 12, same run). An -O2 build (the default, the benchmarks)
# compiles the library at -O3; other levels (the sanitizer builds' -O1, -O0)
# are left as given. Firmware builds (mk/cross.mk) choose their own flags.
LIBOPT ?= $(if $(filter -O2,$(OPT)),-O3 )-funroll-loops
DEFS := $(CONFIG_DEFS)
ifeq ($(REAL),float)
DEFS += -DTRK_REAL_FLOAT
else ifneq ($(REAL),double)
$(error REAL must be double or float)
endif
SANFLAGS :=
ifeq ($(SAN),1)
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
endif
# debug information: -g; `make test`'s sanitizer builds use -g1 (file:line in
# sanitizer reports, ~20 % less compile time)
DEBUG ?= -g
# extra flags of the test programs' own objects (tests/, examples/):
# `make test`'s sanitizer builds compile them at -O0 (half the compile time;
# the code under test keeps OPT)
TEST_OPT ?=
CFLAGS_ALL := $(WARN) $(OPT) $(DEBUG) $(DEFS) $(SANFLAGS) -Iinclude -MMD -MP
# Host programs link OpenMP: the table generators and the q2 sampler of
# libtrk_tools.a are compiled once, with -fopenmp (mk/q2.mk).
LDFLAGS_ALL := $(SANFLAGS) -fopenmp

CMOCKA_CFLAGS := $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS := $(or $(shell pkg-config --libs cmocka 2>/dev/null),-lcmocka)

LIB_SRC := $(wildcard src/*.c)
PERF_SRC := $(wildcard src/perf/*.c)
HOST_SRC := $(wildcard src/host/*.c)
TOOL_LAYERS := lcm vec sim gen par cli
TOOL_DIRS := $(patsubst tools/%/,%,$(wildcard tools/trk-*/))
TEST_SRC := $(wildcard tests/test_*.c)
EXAMPLE_SRC := $(wildcard examples/*.c)

LIB := $(BUILD)/libtrk.a
PERFLIB := $(BUILD)/libtrk_perf.a
HOSTLIB := $(BUILD)/libtrk_host.a
LAYERLIB = $(BUILD)/libtrk_$(1).a
# every layer below the tools, in link order
TOOL_LIBS := $(foreach l,$(TOOL_LAYERS),$(call LAYERLIB,$(l))) $(HOSTLIB) $(PERFLIB) $(LIB)
TOOL_INC := $(addprefix -Itools/,$(TOOL_LAYERS))
GEN := $(BUILD)/gen
RESULTS := $(BUILD)/results
obj = $(patsubst %.c,$(BUILD)/obj/%.o,$(1))

TOOLS := $(addprefix $(BUILD)/bin/,$(TOOL_DIRS))
TEST_NAMES := $(patsubst tests/%.c,%,$(TEST_SRC))
TESTS := $(addprefix $(BUILD)/tests/,$(TEST_NAMES))
EXAMPLES := $(patsubst examples/%.c,$(BUILD)/bin/example-%,$(EXAMPLE_SRC))

.PHONY: all lib tools tests examples check check-run test test-extra bench demo install check-heap \
  clean help FORCE
.DEFAULT_GOAL := all
# Objects are never deleted as intermediates (a test program does not relink
# after every build because its object vanished). Not `.SECONDARY:` without
# prerequisites: that makes every target intermediate, and a missing object
# of a new source file would then not be built into an up-to-date archive.
.PRECIOUS: $(BUILD)/obj/%.o
FORCE:

all: lib tools examples
	@:
lib: $(LIB) $(PERFLIB) $(HOSTLIB)
tools: $(TOOLS)
tests: $(TESTS)
examples: $(EXAMPLES)

-include $(wildcard tools/*/tool.mk)
-include $(wildcard tests/*.mk)

# --- the configuration of this build directory: every object depends on a
# file holding the compiler and its flags, rewritten only when they change,
# so reusing a BUILD directory with other CONFIG_DEFS, REAL, SAN or CC
# rebuilds everything instead of mixing struct layouts.
BUILD_CONFIG := $(BUILD)/config.txt
$(BUILD_CONFIG): FORCE
	@mkdir -p $(@D)
	@echo '$(CC) $(CFLAGS_ALL) $(LIBOPT) $(TEST_OPT) $(LDFLAGS_ALL)' > $@.tmp; \
	  if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv $@.tmp $@; fi

# --- library objects: stricter warnings
$(BUILD)/obj/src/%.o: src/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBOPT) $(LIBWARN) -Isrc -c $< -o $@

$(BUILD)/obj/tools/%.o: tools/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(TOOL_INC) -I$(GEN) $(TOOL_CFLAGS_$(firstword $(subst /, ,$*))) -c $< -o $@

$(BUILD)/obj/%.o: %.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(TEST_OPT) $(CMOCKA_CFLAGS) $(TOOL_INC) -Itests -I$(GEN) -c $< -o $@

# archive(name): the recipe of a static library from its object prerequisites
define archive
	@mkdir -p $(@D)
	$(call say,AR,$@)
	$(Q)rm -f $@ && $(AR) rcs $@ $(filter %.o,$^)
endef
$(LIB): $(call obj,$(LIB_SRC))
	$(archive)
$(PERFLIB): $(call obj,$(PERF_SRC))
	$(archive)
$(HOSTLIB): $(call obj,$(HOST_SRC))
	$(archive)
define LAYER_template
$(call LAYERLIB,$(1)): $$(call obj,$$(wildcard tools/$(1)/*.c))
	$$(archive)
endef
$(foreach l,$(TOOL_LAYERS),$(eval $(call LAYER_template,$(l))))

# --- registries collected from marker lines (no shared file to edit)
$(GEN)/vec_kinds.inc: $(wildcard tools/vec/kind_*.c) Makefile
	@mkdir -p $(@D)
	$(Q)sed -n 's/^TRK_VEC_KIND(\([^)]*\)).*/TRK_VEC_KIND_ENTRY(\1)/p' $(sort $(wildcard tools/vec/kind_*.c)) > $@.tmp && mv $@.tmp $@
$(GEN)/bench_cases.inc: $(wildcard tools/trk-bench/bench_*.c) Makefile
	@mkdir -p $(@D)
	$(Q)sed -n 's/^TRK_BENCH(\([a-z0-9_]*\)).*/TRK_BENCH_ENTRY(\1)/p' $(sort $(wildcard tools/trk-bench/bench_*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/vec/registry.o: $(GEN)/vec_kinds.inc
$(BUILD)/obj/tools/trk-bench/main.o: $(GEN)/bench_cases.inc

# --- tools: bin/trk-NAME from tools/trk-NAME/*.c
define TOOL_template
$(BUILD)/bin/$(1): $$(call obj,$$(wildcard tools/$(1)/*.c)) $$(TOOL_DEPS_$(1)) $(TOOL_LIBS)
	@mkdir -p $$(@D)
	$$(call say,LD,$$@)
	$$(Q)$$(CC) $$(LDFLAGS_ALL) $$(TOOL_LDFLAGS_$(1)) $$(filter %.o,$$^) $(TOOL_LIBS) $$(TOOL_LDLIBS_$(1)) -lm -o $$@
endef
$(foreach t,$(TOOL_DIRS),$(eval $(call TOOL_template,$(t))))

# --- tests and examples
# (no line of their own: each test program's step line names it)
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TOOL_LIBS)
	@mkdir -p $(@D)
	$(Q)$(CC) $(LDFLAGS_ALL) $< $(TEST_EXTRA_OBJS_$*) $(TOOL_LIBS) $(CMOCKA_LIBS) $(TEST_LDLIBS_$*) -lm -o $@

# examples are firmware-style programs: the libraries a product links
$(BUILD)/bin/example-%: $(BUILD)/obj/examples/%.o $(HOSTLIB) $(LIB)
	@mkdir -p $(@D)
	$(call say,LD,$@)
	$(Q)$(CC) $(LDFLAGS_ALL) $< $(HOSTLIB) $(LIB) -lm -o $@

# --- steps: every test program, the vectors, each extra check is a step.
# tests/run_step.sh runs it with its output in $(RESULTS)/NAME.log, prints one
# line (PASS/FAIL, what it counted, seconds; the whole log only on failure)
# and records the result in $(RESULTS)/NAME.res; tests/summary.sh then prints
# "CFG: N passed, N failed" and fails when any step failed. A failing step
# does not stop the others.
STEP = CFG='$(CFG)' sh tests/run_step.sh $(RESULTS)
SUMMARY = sh tests/summary.sh

# the reference vectors (every kind; format in tests/vectors/FORMAT.md)
VECTORS_DIR ?= tests/vectors
# The kinds registered VEC_SLOW (Monte Carlo q2 estimators, ~20 s in all)
# run only where VEC_SLOW=1: `make test` sets it in one configuration.
VEC_SLOW ?= 0
VECTORS_FLAGS := --quiet $(if $(filter 1,$(VEC_SLOW)),,--skip-slow)

# T selects steps (test_NAME, NAME, vectors, heap); CASE a cmocka case pattern.
T ?=
CASE ?=
CHECK_EXTRA ?=
ALL_CHECK_STEPS := $(TEST_NAMES) vectors heap $(CHECK_EXTRA)
CHECK_STEPS := $(if $(T),$(filter $(T) $(addprefix test_,$(T)),$(ALL_CHECK_STEPS)),$(ALL_CHECK_STEPS))
ifneq ($(T),)
ifeq ($(CHECK_STEPS),)
$(error T=$(T) names no step; steps: $(ALL_CHECK_STEPS))
endif
endif
ifneq ($(CASE),)
ifeq ($(T),)
$(error CASE=$(CASE) needs T=<test program>, e.g. make check T=tracker CASE='$(CASE)')
endif
endif
res = $(patsubst %,$(RESULTS)/%.res,$(1))

$(RESULTS)/test_%.res: $(BUILD)/tests/test_% FORCE
	@TRK_TEST_CASE='$(CASE)' $(STEP) test_$* $<
$(RESULTS)/vectors.res: $(BUILD)/bin/trk-vectors FORCE
	@if [ -d $(VECTORS_DIR) ]; then DETAIL_LINES=4 $(STEP) vectors $< $(VECTORS_FLAGS) $(VECTORS_DIR)/*.vec; \
	 else echo "$(CFG) vectors: $(VECTORS_DIR) not found, skipped"; fi
$(RESULTS)/heap.res: $(LIB) $(PERFLIB) FORCE
	@$(STEP) heap $(MAKE) --no-print-directory check-heap

# check: everything of this configuration and its steps (the developer loop),
# on CHECK_JOBS jobs unless make was given -j
CHECK_JOBS ?= $(shell nproc 2>/dev/null || echo 2)
.PHONY: check-steps
check:
	+@$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(CHECK_JOBS)) all check-steps
	@$(SUMMARY) '$(CFG)' $(call res,$(CHECK_STEPS))
# check-run: only what the steps need (what `make test` runs per configuration)
check-run: check-steps
	@$(SUMMARY) '$(CFG)' $(call res,$(CHECK_STEPS))
check-steps: $(call res,$(CHECK_STEPS))
	@:

HEAP_SYMS := malloc|calloc|realloc|free|alloca|__builtin_alloca|printf|fprintf|sprintf|snprintf|vsnprintf|puts|putchar|fputs|fopen|fwrite|fread|abort|exit|_exit|__assert_fail|__stack_chk_fail_local|stdout|stderr
check-heap: $(LIB) $(PERFLIB)
	@if nm -u $(LIB) $(PERFLIB) | grep -E '^ *U ($(HEAP_SYMS))$$'; then \
	  echo "check-heap: libtrk or libtrk_perf references the symbols above (heap/stdio/abort)"; exit 1; fi
	@echo "check-heap: $(LIB) and $(PERFLIB) reference no heap, stdio or abort symbol"

# --- the whole matrix (README's test command). The configurations are
# independent sub-makes (own build directories) run on TEST_JOBS jobs; each
# prints its steps and its summary line, then the total.
TEST_JOBS ?= 2
# (the default configuration first: its steps are the longest chain)
TEST_CONFIGS := test-default test-gcc test-clang test-gcc-float test-small
SAN_CHECK := SAN=1 OPT=-O1 DEBUG=-g1 TEST_OPT=-O0
# The gcc sanitizer builds take the firmware's code path (TRK_SIZE_OPT=1, as
# every -Os build: the kernels out of line with run-time dimensions); clang's
# takes the host's (the kernels inlined and unrolled for the CV model). Both
# paths are sanitized, and gcc does not spend 20 s on the unrolled pda.c
# under UBSan (2 s this way).
SAN_SIZE_OPT := CONFIG_DEFS=-DTRK_SIZE_OPT=1
.PHONY: $(TEST_CONFIGS) test-configs
TEST_RESULT_DIRS := $(addsuffix /results,$(addprefix build/,$(filter-out test-default,$(TEST_CONFIGS))) build)
test:
	@rm -rf $(TEST_RESULT_DIRS)
	+@rc=0; $(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(TEST_JOBS)) -k test-configs || rc=$$?; \
	  $(SUMMARY) --make-status $$rc test $(addsuffix /*.res,$(TEST_RESULT_DIRS))
test-configs: $(TEST_CONFIGS)
test-gcc:
	+@$(MAKE) --no-print-directory BUILD=build/test-gcc CC=gcc $(SAN_CHECK) $(SAN_SIZE_OPT) CHECK_EXTRA=fuzz-replay check-run
test-clang:
	+@$(MAKE) --no-print-directory BUILD=build/test-clang CC=clang $(SAN_CHECK) CHECK_EXTRA=fuzz-replay check-run
test-gcc-float:
	+@$(MAKE) --no-print-directory BUILD=build/test-gcc-float CC=gcc $(SAN_CHECK) $(SAN_SIZE_OPT) REAL=float check-run
test-small:
	+@$(MAKE) --no-print-directory BUILD=build/test-small CC=gcc OPT=-O1 DEBUG=-g1 VEC_SLOW=1 \
	  CONFIG_DEFS='-DTRK_MAX_TRACKS=8 -DTRK_MAX_DETECTIONS=32 -DTRK_MAX_SENSORS=2 -DTRK_WITH_IMM=1' check-run
test-default:
	+@$(MAKE) --no-print-directory BUILD=build test-extra

# A deliberately impossible configuration must not compile.
TEST_EXTRA += check-bad-config
check-bad-config:
	@if echo '#include "trk/trk.h"' | $(CC) -std=c99 -Iinclude -DTRK_MAX_MEAS=4 -x c -fsyntax-only - 2>/dev/null; then \
	  echo "check-bad-config: TRK_MAX_MEAS=4 compiled but must fail"; exit 1; fi
	@echo "check-bad-config: an impossible configuration fails to compile, as it must"

# (the IMM build: the per-track cost of three models against CV, and
# the default build's scans against the IMM build's CV scans: IMM compiled in
# but off)
BENCH_IMM_DEFS := -DTRK_WITH_IMM=1 -DTRK_MAX_MODELS=3
bench:
	$(MAKE) --no-print-directory BUILD=build OPT=-O2 tools
	$(MAKE) --no-print-directory BUILD=build/float OPT=-O2 REAL=float tools
	$(MAKE) --no-print-directory BUILD=build/imm-float OPT=-O2 REAL=float CONFIG_DEFS='$(BENCH_IMM_DEFS)' \
	  build/imm-float/bin/trk-bench
	@echo "== double"; build/bin/trk-bench
	@echo "== float";  build/float/bin/trk-bench
	@echo "== float, TRK_WITH_IMM=1 (3 models)"; build/imm-float/bin/trk-bench scan_64x256 sizeof_tracker
	@echo "== the size grid (TRK_MAX_TRACKS 256, TRK_MAX_DETECTIONS 4096)"; $(MAKE) --no-print-directory bench-grid
	@echo "== instructions"; $(MAKE) --no-print-directory bench-instr

# The size grid: the scan at tracks 64 / 256 and detections 256 /
# 1024 / 4096 at a fixed density in a build of 256 tracks and 4096
# detections, and the growth over four times the area with the table's
# slack kept (64 targets in the default 64-slot build against 256 targets in
# the 256-slot build; the big build's 64-target scans also start clutter
# tracks in its 192 free slots). Three rounds alternating the two builds,
# the fastest of each figure.
BENCH_BIG_DEFS := -DTRK_MAX_TRACKS=256 -DTRK_MAX_DETECTIONS=4096
bench-grid:
	$(MAKE) --no-print-directory BUILD=build OPT=-O2 build/bin/trk-bench
	$(MAKE) --no-print-directory BUILD=build/big OPT=-O2 CONFIG_DEFS='$(BENCH_BIG_DEFS)' build/big/bin/trk-bench
	@rm -f build/big/scan_grid_small.txt build/big/scan_grid.txt; \
	for r in 1 2 3; do \
	  build/bin/trk-bench scan_grid >> build/big/scan_grid_small.txt; \
	  build/big/bin/trk-bench scan_grid >> build/big/scan_grid.txt; \
	done; \
	awk '$$1 == "bench" && $$3 + 0 > 0 { if (!($$2 in m) || $$3 < m[$$2]) m[$$2] = $$3; u[$$2] = $$4; o[++n] = $$2 } \
	     END { for (i = 1; i <= n; i++) if (!(o[i] in done)) { done[o[i]] = 1; print "bench", o[i], m[o[i]], u[o[i]] } }' \
	  build/big/scan_grid.txt | grep -v '_growth_'; \
	small=$$(awk '$$2 == "scan_grid_T64_D256" && (s == "" || $$3 < s) { s = $$3 } END { print s }' build/big/scan_grid_small.txt); \
	big=$$(awk '$$2 == "scan_grid_T256_D1024" && (s == "" || $$3 < s) { s = $$3 } END { print s }' build/big/scan_grid.txt); \
	echo "bench scan_grid_T64_D256_default_build $$small ns"; \
	awk -v a=$$small -v b=$$big 'BEGIN { printf "bench scan_grid_growth_4x_area_same_slack %.3g x\n", b / a }'

# The instruction count of one scan_64x256: machine-independent,
# unlike the times. trk-bench scan_64x256_instr under callgrind with the
# instrumentation on for the timed scans only; Ir / scans.
bench-instr:
	$(MAKE) --no-print-directory BUILD=build OPT=-O2 build/bin/trk-bench
	$(MAKE) --no-print-directory BUILD=build/float OPT=-O2 REAL=float build/float/bin/trk-bench
	@for b in build build/float; do \
	  out=$$(valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=$$b/bench-instr.callgrind \
	    $$b/bin/trk-bench scan_64x256_instr 2>/dev/null | awk '$$2 == "scan_64x256_instr_scans" { print $$3 }'); \
	  ir=$$(awk '/^totals:/ { print $$2; exit }' $$b/bench-instr.callgrind); \
	  test -n "$$out" && test -n "$$ir" || { echo "bench-instr: no count from $$b"; exit 1; }; \
	  echo "bench scan_64x256_instructions_$$(test $$b = build && echo double || echo float) $$(awk -v i=$$ir -v n=$$out 'BEGIN { printf "%.0f", i / n }') instructions"; \
	done

demo: all
	$(BUILD)/bin/example-firmware_loop

# --- install (docs/firmware.md "Install"): headers, libraries, pkg-config files, tools,
# the LCM types (mk/lcm.mk, mk/lcm_java.mk, mk/python.mk add theirs as
# prerequisites install-lcm-types, install-java, install-python; commands
# in INSTALL_EXTRA run last). A double build (the default) installs libtrk.a,
# libtrk_perf.a, libtrk_host.a, trk.pc and the tools (bin/; trk-bench, a
# benchmark of the build, in libexec/trk/); a float build (REAL=float, in a
# build directory of its own, e.g. BUILD=build/float) installs libtrk_f.a,
# libtrk_perf_f.a, libtrk_host_f.a and trk-float.pc beside them, and no
# tools (they are host programs: the double ones serve). The headers are the
# same for both; the .pc file's Cflags carry the build's -D knobs, so a
# program compiled with `pkg-config --cflags trk-float` sees the float
# layout, and trk_config_check() refuses a mix at run time (TRK_E_ABI).
TRK_VERSION := 0.1.0
INSTALL_SUFFIX := $(if $(filter float,$(REAL)),_f)
INSTALL_PC := $(if $(filter float,$(REAL)),trk-float,trk)
INSTALL_TOOLS := $(if $(filter float,$(REAL)),,$(filter-out $(BUILD)/bin/trk-bench,$(TOOLS)))
INSTALL_LIBEXEC := $(if $(filter float,$(REAL)),,$(filter $(BUILD)/bin/trk-bench,$(TOOLS)))
install: lib $(INSTALL_TOOLS) $(INSTALL_LIBEXEC)
	@case '$(DEFS)' in *TRK_CONFIG_FILE*) echo "install: a TRK_CONFIG_FILE build is not installable (its header is not installed): give its knobs as -D flags in CONFIG_DEFS"; exit 1;; esac
	install -d $(DESTDIR)$(PREFIX)/include/trk $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/trk/*.h $(DESTDIR)$(PREFIX)/include/trk/
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/libtrk$(INSTALL_SUFFIX).a
	install -m 644 $(PERFLIB) $(DESTDIR)$(PREFIX)/lib/libtrk_perf$(INSTALL_SUFFIX).a
	install -m 644 $(HOSTLIB) $(DESTDIR)$(PREFIX)/lib/libtrk_host$(INSTALL_SUFFIX).a
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@NAME@|$(INSTALL_PC)|' -e 's|@REAL@|$(REAL)|' \
	  -e 's|@VERSION@|$(TRK_VERSION)|' -e 's|@SUFFIX@|$(INSTALL_SUFFIX)|g' -e 's|@CFLAGS@|$(strip $(DEFS))|' \
	  trk.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/$(INSTALL_PC).pc
	$(if $(INSTALL_TOOLS),install -d $(DESTDIR)$(PREFIX)/bin && install -m 755 $(INSTALL_TOOLS) $(DESTDIR)$(PREFIX)/bin/)
	$(if $(INSTALL_LIBEXEC),install -d $(DESTDIR)$(PREFIX)/libexec/trk && \
	  install -m 755 $(INSTALL_LIBEXEC) $(DESTDIR)$(PREFIX)/libexec/trk/)
	$(INSTALL_EXTRA)

clean:
	rm -rf build

help:
	@sed -n '1,45p' Makefile

-include $(wildcard mk/*.mk)

# --- the extra steps of the default configuration (registered above and in
# mk/*.mk, tests/*.mk): each one's deps are built by this make, then the step
# runs as `make NAME` with its output in its log.
define EXTRA_STEP_template
$(RESULTS)/$(1).res: $$(TEST_EXTRA_DEPS_$(1)) FORCE
	@$$(STEP) $(1) $$(MAKE) --no-print-directory $(1)
endef
$(foreach s,$(sort $(TEST_EXTRA) $(CHECK_EXTRA)),$(eval $(call EXTRA_STEP_template,$(s))))
test-extra: $(call res,$(TEST_EXTRA))
	@$(SUMMARY) '$(CFG)' $^

-include $(shell find $(BUILD)/obj $(BUILD)/pic/obj -name '*.d' 2>/dev/null)
