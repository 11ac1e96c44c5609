# trk - target tracking library for active sonar. See README.md.
#
#   make                 libtrk (build/libtrk.a), libtrk_host.a, tools (build/bin/)
#   make test            the whole test matrix (gcc + clang, ASan+UBSan, float,
#                        small capacities, vectors, heap check, cross build)
#   make check           tests + vectors of ONE configuration (BUILD, CC, REAL, SAN)
#   make bench           trk-bench in double and float
#   make demo            trk's main job (see README)
#   make cross           libtrk for Cortex-M (build/cross/<target>/libtrk.a)
#   make check-heap      fail if libtrk references a heap/stdio/abort symbol
#   make install PREFIX=/usr/local [DESTDIR=]
#
# Configuration variables (one build directory per configuration):
#   BUILD=build  CC=gcc|clang  REAL=double|float  SAN=0|1 (ASan+UBSan)  OPT=-O2
#   CONFIG_DEFS='-DTRK_MAX_TRACKS=8 ...'  (capacities, see include/trk/config.h)
#
# Layout rules (nothing to edit when adding files):
#   src/*.c           -> libtrk.a (firmware library: no heap, no stdio)
#   src/host/*.c      -> libtrk_host.a (file helpers for host programs)
#   tools/common/*.c, tools/vec/*.c -> libtrk_tools.a (shared by tools and tests)
#   tools/trk-NAME/*.c -> bin/trk-NAME; tools/trk-NAME/tool.mk may set
#                        TOOL_CFLAGS_trk-NAME, TOOL_LDLIBS_trk-NAME, TOOL_DEPS_trk-NAME
#   tests/test_*.c    -> one cmocka test program each; tests/*.mk may add rules
#   examples/*.c      -> bin/example-NAME
#   mk/*.mk           -> extra targets (cross, fuzz, size report, ...)

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

WARN := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes
LIBWARN := -Wmissing-prototypes -Wdouble-promotion
# The library's kernels loop over constant dimensions (4 states, 2
# measurements); gcc -O2 does not unroll them all, -funroll-loops does
# (trk-bench pda_update_m10: 303 -> 256 ns with gcc 12). Firmware builds
# (mk/cross.mk) choose their own flags.
LIBOPT ?= -funroll-loops
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
CFLAGS_ALL := $(WARN) $(OPT) -g $(DEFS) $(SANFLAGS) -Iinclude -MMD -MP
LDFLAGS_ALL := $(SANFLAGS)

CMOCKA_CFLAGS := $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS := $(or $(shell pkg-config --libs cmocka 2>/dev/null),-lcmocka)

LIB_SRC := $(wildcard src/*.c)
HOST_SRC := $(wildcard src/host/*.c)
TOOLLIB_SRC := $(wildcard tools/common/*.c tools/vec/*.c)
TOOL_DIRS := $(patsubst tools/%/,%,$(wildcard tools/trk-*/))
TEST_SRC := $(wildcard tests/test_*.c)
EXAMPLE_SRC := $(wildcard examples/*.c)

LIB := $(BUILD)/libtrk.a
HOSTLIB := $(BUILD)/libtrk_host.a
TOOLLIB := $(BUILD)/libtrk_tools.a
GEN := $(BUILD)/gen
obj = $(patsubst %.c,$(BUILD)/obj/%.o,$(1))

TOOLS := $(addprefix $(BUILD)/bin/,$(TOOL_DIRS))
TESTS := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
EXAMPLES := $(patsubst examples/%.c,$(BUILD)/bin/example-%,$(EXAMPLE_SRC))

.PHONY: all lib tools tests examples check test bench demo install check-heap clean help
.DEFAULT_GOAL := all

all: lib tools examples
lib: $(LIB) $(HOSTLIB)
tools: $(TOOLS)
tests: $(TESTS)
examples: $(EXAMPLES)

-include $(wildcard tools/*/tool.mk)
-include $(wildcard tests/*.mk)

# --- library objects: stricter warnings
$(BUILD)/obj/src/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) $(LIBOPT) $(LIBWARN) -Isrc -c $< -o $@

$(BUILD)/obj/tools/%.o: tools/%.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) -Itools/vec -Itools/common -I$(GEN) $(TOOL_CFLAGS_$(firstword $(subst /, ,$*))) -c $< -o $@

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itools/vec -Itools/common -Itests -I$(GEN) -c $< -o $@

$(LIB): $(call obj,$(LIB_SRC))
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

$(HOSTLIB): $(call obj,$(HOST_SRC)) | $(LIB)
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $(filter %.o,$^)

$(TOOLLIB): $(call obj,$(TOOLLIB_SRC))
	@mkdir -p $(@D)
	rm -f $@ && $(AR) rcs $@ $^

# --- registries collected from marker lines (no shared file to edit)
$(GEN)/vec_kinds.inc: $(wildcard tools/vec/kind_*.c) Makefile
	@mkdir -p $(@D)
	sed -n 's/^TRK_VEC_KIND(\([^)]*\)).*/TRK_VEC_KIND_ENTRY(\1)/p' $(sort $(wildcard tools/vec/kind_*.c)) > $@.tmp && mv $@.tmp $@
$(GEN)/bench_cases.inc: $(wildcard tools/trk-bench/bench_*.c) Makefile
	@mkdir -p $(@D)
	sed -n 's/^TRK_BENCH(\([a-z0-9_]*\)).*/TRK_BENCH_ENTRY(\1)/p' $(sort $(wildcard tools/trk-bench/bench_*.c)) > $@.tmp && mv $@.tmp $@
$(BUILD)/obj/tools/vec/registry.o: $(GEN)/vec_kinds.inc
$(BUILD)/obj/tools/trk-bench/main.o: $(GEN)/bench_cases.inc

# --- tools: bin/trk-NAME from tools/trk-NAME/*.c
define TOOL_template
$(BUILD)/bin/$(1): $$(call obj,$$(wildcard tools/$(1)/*.c)) $$(TOOL_DEPS_$(1)) $(TOOLLIB) $(HOSTLIB) $(LIB)
	@mkdir -p $$(@D)
	$$(CC) $$(LDFLAGS_ALL) $$(TOOL_LDFLAGS_$(1)) $$(filter %.o,$$^) $(TOOLLIB) $(HOSTLIB) $(LIB) $$(TOOL_LDLIBS_$(1)) -lm -o $$@
endef
$(foreach t,$(TOOL_DIRS),$(eval $(call TOOL_template,$(t))))

# --- tests and examples
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TOOLLIB) $(HOSTLIB) $(LIB)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS_ALL) $< $(TEST_EXTRA_OBJS_$*) $(TOOLLIB) $(HOSTLIB) $(LIB) $(CMOCKA_LIBS) $(TEST_LDLIBS_$*) -lm -o $@

$(BUILD)/bin/example-%: $(BUILD)/obj/examples/%.o $(HOSTLIB) $(LIB)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS_ALL) $< $(HOSTLIB) $(LIB) -lm -o $@

# --- one configuration: tests + reference vectors + heap check
# ../shared/vectors when the checkout sits next to it, else the copy in tests/vectors
VECTORS_DIR ?= $(if $(wildcard ../shared/vectors/*.vec),../shared/vectors,tests/vectors)
# The Monte Carlo kinds take ~25 s CPU under sanitizers; those builds skip them
# (the non-sanitizer configurations of `make test` run every kind).
comma := ,
VECTORS_SKIP := $(if $(filter 1,$(SAN)),q2_pdaf$(comma)q2_pdafai,)
check: all $(TESTS)
	@set -e; for t in $(TESTS); do echo "== $$t"; TRK_VECTORS_DIR=$(VECTORS_DIR) TRK_BUILD=$(BUILD) \
	  $(if $(VECTORS_SKIP),TRK_VECTORS_SKIP=$(VECTORS_SKIP)) $$t; done
	@if [ -d $(VECTORS_DIR) ]; then echo "== trk-vectors ($(REAL))"; \
	  $(BUILD)/bin/trk-vectors --quiet $(if $(VECTORS_SKIP),--skip $(VECTORS_SKIP)) $(VECTORS_DIR)/*.vec; \
	 else echo "== trk-vectors: $(VECTORS_DIR) not found, skipped"; fi
	@$(MAKE) --no-print-directory BUILD=$(BUILD) check-heap

HEAP_SYMS := malloc|calloc|realloc|free|alloca|__builtin_alloca|printf|fprintf|sprintf|snprintf|vsnprintf|puts|putchar|fputs|fopen|fwrite|fread|abort|exit|_exit|__assert_fail|__stack_chk_fail_local|stdout|stderr
check-heap: $(LIB)
	@if nm -u $(LIB) | grep -E '^ *U ($(HEAP_SYMS))$$'; then \
	  echo "check-heap: libtrk references the symbols above (heap/stdio/abort)"; exit 1; fi
	@echo "check-heap: $(LIB) references no heap, stdio or abort symbol"

# --- the whole matrix (README's test command)
TEST_CONFIGS := test-gcc test-clang test-gcc-float test-small
test:
	$(MAKE) --no-print-directory BUILD=build/test-gcc CC=gcc SAN=1 OPT=-O1 check
	$(MAKE) --no-print-directory BUILD=build/test-clang CC=clang SAN=1 OPT=-O1 check
	$(MAKE) --no-print-directory BUILD=build/test-gcc-float CC=gcc SAN=1 OPT=-O1 REAL=float check
	$(MAKE) --no-print-directory BUILD=build/test-small CC=gcc OPT=-O2 \
	  CONFIG_DEFS='-DTRK_MAX_TRACKS=8 -DTRK_MAX_DETECTIONS=32 -DTRK_MAX_SENSORS=2' check
	$(MAKE) --no-print-directory all
	$(MAKE) --no-print-directory check-bad-config
	$(MAKE) --no-print-directory test-extra
	$(MAKE) --no-print-directory cross
	@echo "make test: all configurations passed"

# A deliberately impossible configuration must not compile.
check-bad-config:
	@if echo '#include "trk/trk.h"' | $(CC) -std=c99 -Iinclude -DTRK_MAX_MEAS=4 -x c -fsyntax-only - 2>/dev/null; then \
	  echo "check-bad-config: TRK_MAX_MEAS=4 compiled but must fail"; exit 1; fi
	@echo "check-bad-config: an impossible configuration fails to compile, as it must"

# Extra test steps registered by mk/*.mk and tests/*.mk with TEST_EXTRA +=
# (fuzz corpus replay, valgrind, QEMU, ...); the rule is at the end of this
# file, after those files are read.
TEST_EXTRA ?=

bench:
	$(MAKE) --no-print-directory BUILD=build OPT=-O2 tools
	$(MAKE) --no-print-directory BUILD=build/float OPT=-O2 REAL=float tools
	@echo "== double"; build/bin/trk-bench
	@echo "== float";  build/float/bin/trk-bench

demo: all
	$(BUILD)/bin/example-firmware_loop

install: all
	install -d $(DESTDIR)$(PREFIX)/include/trk $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 644 include/trk/*.h $(DESTDIR)$(PREFIX)/include/trk/
	install -m 644 $(LIB) $(HOSTLIB) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(TOOLS) $(DESTDIR)$(PREFIX)/bin/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@CFLAGS@|$(strip $(DEFS))|' trk.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/trk.pc
	$(INSTALL_EXTRA)

clean:
	rm -rf build

help:
	@sed -n '1,30p' Makefile

-include $(wildcard mk/*.mk)
test-extra: $(TEST_EXTRA)
-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
