# install-cross.mk - the firmware kit: make install-cross PREFIX=/opt/trk [DESTDIR=]
#
# For each cross target this machine builds (CROSS_TARGETS of mk/cross.mk:
# cortex-m4f, cortex-m4f-O2, cortex-m7d, cortex-m7d-O2, and riscv when its
# compiler is installed):
#   $(PREFIX)/lib/trk/<target>/libtrk.a, libtrk_perf.a
#                         the archives exactly as `make cross` builds them
#   $(PREFIX)/lib/pkgconfig/trk-<target>.pc
#                         Cflags: -I$(PREFIX)/include and the flags of the
#                         archive's compilation a caller must match: its -m
#                         (CPU, FPU, float ABI) and -D (scalar type,
#                         capacities) flags, taken from TARGET_<target>_CFLAGS
#                         and CROSS_EXTRA_CFLAGS (mk/cross.mk), not a copy;
#                         Libs: -L$(PREFIX)/lib/trk/<target> -ltrk -lm;
#                         variables cc (the target's compiler) and real
# and once:
#   $(PREFIX)/include/trk/*.h   the headers (the same files `make install` writes)
#   $(PREFIX)/bin/trk-tablegen  the host table generator (`--real float` for
#                         the float targets' ROM tables; also `make install`'s)
# The pkg-config files sit beside the host's trk.pc: one PKG_CONFIG_PATH
# serves both. docs/firmware.md "Building your own image with the kit";
# examples/cortex-m4f/ builds a bare-metal image from such a prefix alone.
INSTALL_CROSS_TARGETS ?= $(CROSS_TARGETS)
# the flags of a target's archive that a caller's compilation must match
cross_abi_flags = $(strip $(filter -m% -D% -U%,$(TARGET_$(1)_CFLAGS) $(CROSS_EXTRA_CFLAGS)))
cross_real = $(if $(filter -DTRK_REAL_FLOAT,$(call cross_abi_flags,$(1))),float,double)

define INSTALL_CROSS_template
install-cross-$(1): build/cross/$(1)/libtrk.a build/cross/$(1)/libtrk_perf.a install-cross-common
	install -d $$(DESTDIR)$$(PREFIX)/lib/trk/$(1)
	install -m 644 build/cross/$(1)/libtrk.a build/cross/$(1)/libtrk_perf.a $$(DESTDIR)$$(PREFIX)/lib/trk/$(1)/
	sed -e 's|@PREFIX@|$$(PREFIX)|' -e 's|@TARGET@|$(1)|g' -e 's|@CC@|$$(TARGET_$(1)_CC)|' \
	  -e 's|@REAL@|$$(call cross_real,$(1))|g' -e 's|@VERSION@|$$(TRK_VERSION)|' \
	  -e 's|@CFLAGS@|$$(call cross_abi_flags,$(1))|' trk-cross.pc.in > $$(DESTDIR)$$(PREFIX)/lib/pkgconfig/trk-$(1).pc
endef
$(foreach t,$(CROSS_TARGETS_KNOWN),$(eval $(call INSTALL_CROSS_template,$(t))))

.PHONY: install-cross install-cross-common $(addprefix install-cross-,$(CROSS_TARGETS_KNOWN))
install-cross-common: $(BUILD)/bin/trk-tablegen
	@case '$(CROSS_EXTRA_CFLAGS)' in *TRK_CONFIG_FILE*) echo "install-cross: a TRK_CONFIG_FILE build is not installable (its header is not installed): give its knobs as -D flags in CROSS_EXTRA_CFLAGS"; exit 1;; esac
	install -d $(DESTDIR)$(PREFIX)/include/trk $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 644 include/trk/*.h $(DESTDIR)$(PREFIX)/include/trk/
	install -m 755 $(BUILD)/bin/trk-tablegen $(DESTDIR)$(PREFIX)/bin/
install-cross: $(addprefix install-cross-,$(INSTALL_CROSS_TARGETS))
	@echo "install-cross: $(INSTALL_CROSS_TARGETS) in $(DESTDIR)$(PREFIX)/lib/trk/ (pkg-config: $(addprefix trk-,$(INSTALL_CROSS_TARGETS)))"

# `make fw-kit`, a step of `make test`: the kit installed into a scratch
# prefix, the bare-metal example built from that prefix alone and run under
# QEMU (tests/fw_kit.sh asserts its line and exit status).
FW_KIT_DIR := $(BUILD)/fw-kit
.PHONY: fw-kit
TEST_EXTRA_DEPS_fw-kit := $(BUILD)/bin/trk-tablegen
TEST_EXTRA += fw-kit
fw-kit: $(TEST_EXTRA_DEPS_fw-kit)
	@sh tests/fw_kit.sh '$(MAKE)' $(abspath $(FW_KIT_DIR))
