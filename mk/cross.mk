# cross.mk - libtrk for firmware targets: make cross
#   build/cross/<target>/libtrk.a, built with the target's compiler and flags
#   from src/*.c only (no host helpers), then its size is printed.
# Targets (TARGET_<name>_CC / _CFLAGS):
#   cortex-m4f  arm-none-eabi-gcc, Cortex-M4 with single-precision FPU, trk_real = float, -Os

CROSS_TARGETS ?= cortex-m4f
CROSS_COMMON := -std=c99 -Wall -Wextra -Wpedantic -Werror -Wvla -Wshadow -Wstrict-prototypes \
  -Wmissing-prototypes -Wdouble-promotion -ffunction-sections -fdata-sections -fstack-usage -Iinclude -Isrc

TARGET_cortex-m4f_CC := arm-none-eabi-gcc
TARGET_cortex-m4f_CFLAGS := -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -DTRK_REAL_FLOAT -Os

define CROSS_template
CROSS_OBJ_$(1) := $$(patsubst src/%.c,build/cross/$(1)/obj/%.o,$$(LIB_SRC))
build/cross/$(1)/obj/%.o: src/%.c
	@mkdir -p $$(@D)
	$$(TARGET_$(1)_CC) $$(CROSS_COMMON) $$(TARGET_$(1)_CFLAGS) -c $$< -o $$@
build/cross/$(1)/libtrk.a: $$(CROSS_OBJ_$(1))
	rm -f $$@ && $$(TARGET_$(1)_CC:gcc=ar) rcs $$@ $$^
cross-$(1): build/cross/$(1)/libtrk.a
	@echo "== $(1): $$<"
	@$$(TARGET_$(1)_CC:gcc=size) -t $$< | tail -1 | awk '{printf "   text %s  data %s  bss %s  (bytes, whole library)\n", $$$$1, $$$$2, $$$$3}'
	@if $$(TARGET_$(1)_CC:gcc=nm) -u $$< | grep -E '^ *U ($$(HEAP_SYMS))$$$$'; then \
	  echo "cross-$(1): libtrk references heap/stdio/abort symbols"; exit 1; fi
	@if $$(TARGET_$(1)_CC:gcc=nm) -u $$< | grep -E '__aeabi_(d|f2d|dadd|dmul|ddiv)' >/dev/null && [ "$(1)" = cortex-m4f ]; then \
	  echo "cross-$(1): float build pulls in soft-double helpers:"; $$(TARGET_$(1)_CC:gcc=nm) -A -u $$< | grep -E '__aeabi_(d|f2d)'; exit 1; fi
endef
$(foreach t,$(CROSS_TARGETS),$(eval $(call CROSS_template,$(t))))

.PHONY: cross $(addprefix cross-,$(CROSS_TARGETS))
cross: $(addprefix cross-,$(CROSS_TARGETS))
