# cross.mk - libtrk for firmware targets: make cross
#
#   build/cross/<target>/libtrk.a, built from src/*.c only (no host helpers),
#   and build/cross/<target>/libtrk_perf.a from src/perf/*.c (design-time
#   analysis: q2 lookup, MRE, TOC, CRLB; firmware does not link it), with the
#   target's compiler and flags, then checked (both archives):
#     - no heap/stdio/abort symbol referenced (HEAP_SYMS from the Makefile)
#     - float targets: no soft-double helper and no double libm function
#       referenced (a float build that promotes to double runs soft-float
#       double code on a Cortex-M4F: slow and large)
#   Each object also leaves <obj>.su (-fstack-usage) and <obj>.ci
#   (-fcallgraph-info=su) next to it for the stack analysis of mk/size.mk.
#
# Targets (TARGET_<name>_CC / _CFLAGS / _FLOAT):
#   cortex-m4f      Cortex-M4 + FPv4-SP (single precision FPU), trk_real = float, -Os
#   cortex-m4f-O2   same, -O2
#   cortex-m7d      Cortex-M7 + FPv5-D16 (double precision FPU), trk_real = double, -Os
#   cortex-m7d-O2   same, -O2
#   riscv           RV32IMAFC, ilp32f ABI, trk_real = float, -Os, -ffreestanding;
#                   only when riscv64-unknown-elf-gcc is installed (Debian package
#                   gcc-riscv64-unknown-elf). That compiler ships no C library: the
#                   library is compiled against newlib's target-independent headers
#                   (/usr/include/newlib, package libnewlib-dev, which
#                   libnewlib-arm-none-eabi depends on); libm, memcpy and memset are
#                   left for the firmware's own C library to provide at link time.
#
#   make cross                     all targets available on this machine
#   make cross CROSS_TARGETS=riscv one target
#   make cross CROSS_EXTRA_CFLAGS=-DTRK_SIZE_OPT   pass extra flags (e.g. a size knob)
#   make cross-sizeopt             the M4F -Os library with TRK_SIZE_OPT forced off and on
#                                  (build/cross/cortex-m4f-inline, cortex-m4f-sizeopt) and
#                                  the two sizes

ARM_CC ?= arm-none-eabi-gcc
RISCV_CC ?= riscv64-unknown-elf-gcc
NEWLIB_INC ?= /usr/include/newlib
HAVE_RISCV := $(if $(shell command -v $(RISCV_CC) 2>/dev/null),$(if $(wildcard $(NEWLIB_INC)/math.h),1))

CROSS_TARGETS_ARM := cortex-m4f cortex-m4f-O2 cortex-m7d cortex-m7d-O2
CROSS_TARGETS ?= $(CROSS_TARGETS_ARM) $(if $(HAVE_RISCV),riscv)
CROSS_EXTRA_CFLAGS ?=
CROSS_COMMON := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes \
  -Wmissing-prototypes -Wdouble-promotion -ffunction-sections -fdata-sections \
  -fstack-usage -fcallgraph-info=su -g -Iinclude -Isrc

M4F_FLAGS := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard
M7D_FLAGS := -mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard

TARGET_cortex-m4f_CC := $(ARM_CC)
TARGET_cortex-m4f_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os
TARGET_cortex-m4f_FLOAT := 1
TARGET_cortex-m4f-O2_CC := $(ARM_CC)
TARGET_cortex-m4f-O2_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -O2
TARGET_cortex-m4f-O2_FLOAT := 1
TARGET_cortex-m7d_CC := $(ARM_CC)
TARGET_cortex-m7d_CFLAGS := $(M7D_FLAGS) -Os
TARGET_cortex-m7d-O2_CC := $(ARM_CC)
TARGET_cortex-m7d-O2_CFLAGS := $(M7D_FLAGS) -O2
TARGET_riscv_CC := $(RISCV_CC)
TARGET_riscv_CFLAGS := -march=rv32imafc -mabi=ilp32f -mcmodel=medlow -ffreestanding \
  -isystem $(NEWLIB_INC) -DTRK_REAL_FLOAT -Os
TARGET_riscv_FLOAT := 1
# size-knob comparison (cross-sizeopt), not in the default list
TARGET_cortex-m4f-inline_CC := $(ARM_CC)
TARGET_cortex-m4f-inline_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os -DTRK_SIZE_OPT=0
TARGET_cortex-m4f-inline_FLOAT := 1
TARGET_cortex-m4f-sizeopt_CC := $(ARM_CC)
TARGET_cortex-m4f-sizeopt_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os -DTRK_SIZE_OPT=1
TARGET_cortex-m4f-sizeopt_FLOAT := 1
# the M4F library without joint association in the tracker (size-check's
# typical image of a firmware that leaves it out), not in the default list
TARGET_cortex-m4f-nojoint_CC := $(ARM_CC)
TARGET_cortex-m4f-nojoint_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os -DTRK_WITH_JOINT=0
TARGET_cortex-m4f-nojoint_FLOAT := 1
# the M4F library with IMM tracks in the table (TRK_WITH_IMM=1, three models:
# their size budgets in size-check), not in the default list
TARGET_cortex-m4f-imm_CC := $(ARM_CC)
TARGET_cortex-m4f-imm_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os -DTRK_WITH_IMM=1 -DTRK_MAX_MODELS=3
TARGET_cortex-m4f-imm_FLOAT := 1
# the M4F library with the alpha-beta track filter compiled in
# (TRK_WITH_ALPHA_BETA=1: its image and stack in size-check), not in the default list
TARGET_cortex-m4f-ab_CC := $(ARM_CC)
TARGET_cortex-m4f-ab_CFLAGS := $(M4F_FLAGS) -DTRK_REAL_FLOAT -Os -DTRK_WITH_ALPHA_BETA=1
TARGET_cortex-m4f-ab_FLOAT := 1
CROSS_TARGETS_KNOWN := $(CROSS_TARGETS_ARM) riscv cortex-m4f-inline cortex-m4f-sizeopt cortex-m4f-nojoint \
  cortex-m4f-imm cortex-m4f-ab

# binutils of a target: arm-none-eabi-gcc -> arm-none-eabi-nm
cross_tool = $(patsubst %gcc,%$(2),$(TARGET_$(1)_CC))

# Soft-double helpers (ARM EABI __aeabi_dadd, __aeabi_f2d, __aeabi_i2d, ...;
# libgcc __adddf3, __extendsfdf2, ...) and double libm functions: none may be
# referenced by a float build.
SOFT_DOUBLE_RE := __aeabi_(c?d[a-z0-9]+|[a-z0-9]*2d)|__[a-z]*df[0-9a-z]*
# float -> 64-bit integer conversions: libgcc's Arm __aeabi_f2lz/__aeabi_f2ulz
# (_fixsfdi/_fixunssfdi) compute through soft double (__aeabi_dmul, ...):
# ~2.2 KB of double code in a Cortex-M4F image. Reported as a warning;
# CROSS_F2LZ_FATAL=1 makes it an error (to be the default once the library
# has no such conversion: see docs/firmware.md).
# (RISC-V rv32 libgcc: __fixsfdi -> __fixunssfdi -> __muldf3, ...: the same.)
INDIRECT_SOFT_DOUBLE_RE := __aeabi_f2u?lz|__fixu?n?s?sfdi
CROSS_F2LZ_FATAL ?= 0
DOUBLE_LIBM_RE := sqrt|exp|exp2|expm1|log|log1p|log2|log10|pow|floor|ceil|round|trunc|fmod|fabs|sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|erf|erfc|lgamma|tgamma|hypot|cbrt|ldexp|frexp|modf|scalbn|nextafter|fmin|fmax|copysign

# build/cross/<target>/flags.txt holds the target's compiler and flags and is
# rewritten only when they change (CROSS_EXTRA_CFLAGS given or dropped): the
# objects then rebuild, so an archive never mixes -D knobs, and what
# install-cross writes into a target's .pc file is what its archive was built
# with.
define CROSS_template
CROSS_OBJ_$(1) := $$(patsubst src/%.c,build/cross/$(1)/obj/%.o,$$(LIB_SRC))
CROSS_PERF_OBJ_$(1) := $$(patsubst src/%.c,build/cross/$(1)/obj/%.o,$$(PERF_SRC))
build/cross/$(1)/flags.txt: FORCE
	@mkdir -p $$(@D)
	@echo '$$(TARGET_$(1)_CC) $$(CROSS_COMMON) $$(TARGET_$(1)_CFLAGS) $$(CROSS_EXTRA_CFLAGS)' > $$@.tmp; \
	  if cmp -s $$@.tmp $$@; then rm -f $$@.tmp; else mv $$@.tmp $$@; fi
build/cross/$(1)/obj/%.o: src/%.c $$(wildcard include/trk/*.h src/*.h src/perf/*.h) mk/cross.mk build/cross/$(1)/flags.txt
	@mkdir -p $$(@D)
	$$(call say,CC,$$< ($(1)))
	$$(Q)$$(TARGET_$(1)_CC) $$(CROSS_COMMON) $$(TARGET_$(1)_CFLAGS) $$(CROSS_EXTRA_CFLAGS) -c $$< -o $$@
build/cross/$(1)/libtrk.a: $$(CROSS_OBJ_$(1))
	$$(call say,AR,$$@)
	$$(Q)rm -f $$@ && $$(call cross_tool,$(1),ar) rcs $$@ $$^
build/cross/$(1)/libtrk_perf.a: $$(CROSS_PERF_OBJ_$(1))
	$$(call say,AR,$$@)
	$$(Q)rm -f $$@ && $$(call cross_tool,$(1),ar) rcs $$@ $$^
cross-$(1): build/cross/$(1)/libtrk.a build/cross/$(1)/libtrk_perf.a
	@echo "== $(1): $$^"
	@$$(call cross_tool,$(1),size) -t $$< | tail -1 | awk '{printf "   libtrk.a       text %s  data %s  bss %s  (bytes, whole library)\n", $$$$1, $$$$2, $$$$3}'
	@$$(call cross_tool,$(1),size) -t build/cross/$(1)/libtrk_perf.a | tail -1 | awk '{printf "   libtrk_perf.a  text %s  data %s  bss %s  (bytes, analysis modules)\n", $$$$1, $$$$2, $$$$3}'
	@if $$(call cross_tool,$(1),nm) -u $$^ | grep -E '^ *U ($$(HEAP_SYMS))$$$$'; then \
	  echo "cross-$(1): libtrk or libtrk_perf references heap/stdio/abort symbols"; exit 1; fi
	@if [ "$$(TARGET_$(1)_FLOAT)" = 1 ] && $$(call cross_tool,$(1),nm) -u $$^ | \
	    grep -E '^ *U (($$(SOFT_DOUBLE_RE))|($$(DOUBLE_LIBM_RE)))$$$$' >/dev/null; then \
	  echo "cross-$(1): float build pulls in soft-double helpers or double libm functions:"; \
	  $$(call cross_tool,$(1),nm) -A -u $$^ | grep -E ' U (($$(SOFT_DOUBLE_RE))|($$(DOUBLE_LIBM_RE)))$$$$'; exit 1; fi
	@if [ "$$(TARGET_$(1)_FLOAT)" = 1 ] && $$(call cross_tool,$(1),nm) -A -u $$^ | grep -E ' U ($$(INDIRECT_SOFT_DOUBLE_RE))$$$$'; then \
	  echo "   WARNING cross-$(1): float -> int64 conversion above pulls libgcc's soft-double code into a firmware image"; \
	  [ "$$(CROSS_F2LZ_FATAL)" != 1 ] || exit 1; fi
	@echo "   nm: no heap/stdio/abort symbol$$(if $$(TARGET_$(1)_FLOAT),$$(comma) no soft-double or double libm)"
endef
comma := ,
$(foreach t,$(CROSS_TARGETS_KNOWN),$(eval $(call CROSS_template,$(t))))

.PHONY: cross cross-sizeopt $(addprefix cross-,$(CROSS_TARGETS_KNOWN))
cross: $(addprefix cross-,$(CROSS_TARGETS))
	@$(if $(HAVE_RISCV),,echo "== riscv: skipped ($(RISCV_CC) or $(NEWLIB_INC)/math.h not found; apt-get install gcc-riscv64-unknown-elf)")

cross-sizeopt: cross-cortex-m4f-inline cross-cortex-m4f-sizeopt

# each cross target's library and symbol checks: a step of `make test`
TEST_EXTRA += $(addprefix cross-,$(CROSS_TARGETS))
$(foreach t,$(CROSS_TARGETS),$(eval TEST_EXTRA_DEPS_cross-$(t) := build/cross/$(t)/libtrk.a build/cross/$(t)/libtrk_perf.a))
