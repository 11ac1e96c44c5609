# mk/python-binding.mk - the shared library for hosts and the Python package
# trk that drives it (docs/python.md).
#
#   make shared        $(BUILD)/libtrk.so (double; a REAL=float build:
#                      libtrk_f.so): libtrk's sources, the host table reader
#                      (src/host) and the library's self-description
#                      (src/shared: version, ABI check, struct layouts),
#                      compiled -fPIC into $(BUILD)/pic (the static archives
#                      and their objects are untouched)
#   make install       also installs the shared library (lib/, soname
#                      libtrk.so.0) and the package (share/trk/python/trk,
#                      with mk/python.mk's tools)
#   make test-python-binding   a step of `make test`
#                      (tests/python_binding.sh): the layout table, the
#                      parameters, same tracks as the C program bit for bit
#                      (double and float), the live receiver against the
#                      bridge over multicast, the GOSPA example against
#                      trk-sim's C GOSPA, `pip install .` into a venv
#   make bench-python  the cost of a scan through Python against the C call
#                      (64 tracks x 256 detections; tools/python/bench_scan.py)
SHARED_SUFFIX := $(if $(filter float,$(REAL)),_f)
SHARED_NAME := libtrk$(SHARED_SUFFIX).so
SHARED_LIB := $(BUILD)/$(SHARED_NAME)
SHARED_SRC := $(LIB_SRC) $(HOST_SRC) $(wildcard src/shared/*.c)
SHARED_OBJS := $(patsubst %.c,$(BUILD)/pic/obj/%.o,$(SHARED_SRC))
# the version the library reports (trk_shared_version) is the Makefile's
SHARED_VERSION_DEF := -DTRK_VERSION_STRING='"$(TRK_VERSION)"'

.PHONY: shared bench-python test-python-binding
shared: $(SHARED_LIB)
# `make` builds it beside the static archives; not in a sanitizer build
# (SAN=1): clang links no sanitizer runtime into a shared object (the link
# with --no-undefined fails), and a sanitized library cannot be loaded by an
# unsanitized Python anyway
ifneq ($(SAN),1)
all: shared
endif

$(BUILD)/pic/obj/src/%.o: src/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$< (PIC))
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBOPT) $(LIBWARN) -fPIC $(SHARED_VERSION_DEF) -Isrc -c $< -o $@
$(BUILD)/obj/src/shared/%.o: CFLAGS_ALL += $(SHARED_VERSION_DEF)

$(SHARED_LIB): $(SHARED_OBJS)
	$(call say,LD,$@)
	$(Q)$(CC) -shared $(SANFLAGS) -Wl,-soname,$(SHARED_NAME).0 -Wl,--no-undefined $^ -lm -o $@

# --- install: lib/libtrk.so.VERSION with its soname link, and no development
# link lib/libtrk.so: `-ltrk` (pkg-config trk) must keep linking the static
# libtrk.a, the firmware's own code; the package loads the soname. The
# package beside mk/python.mk's tools
install: install-shared
.PHONY: install-shared
install-shared: $(SHARED_LIB)
	install -d $(DESTDIR)$(PREFIX)/lib
	install -m 755 $(SHARED_LIB) $(DESTDIR)$(PREFIX)/lib/$(SHARED_NAME).$(TRK_VERSION)
	ln -sf $(SHARED_NAME).$(TRK_VERSION) $(DESTDIR)$(PREFIX)/lib/$(SHARED_NAME).0
	rm -f $(DESTDIR)$(PREFIX)/lib/$(SHARED_NAME)

# --- the float library of this configuration (its own build directory,
# the one `make bench` uses), with its C replay and its float table
SHARED_FLOAT_BUILD := $(BUILD)/float
.PHONY: shared-float
shared-float:
	+@$(MAKE) --no-print-directory BUILD=$(SHARED_FLOAT_BUILD) REAL=float CONFIG_DEFS='$(CONFIG_DEFS)' \
	  shared $(SHARED_FLOAT_BUILD)/bin/py-replay-csv $(SHARED_FLOAT_BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl

# the C side of the identity test and of the GOSPA comparison
$(BUILD)/bin/py-replay-csv: $(BUILD)/obj/tests/python/replay_csv.o $(HOSTLIB) $(LIB)
	@mkdir -p $(@D)
	$(call say,LD,$@)
	$(Q)$(CC) $(LDFLAGS_ALL) $< $(HOSTLIB) $(LIB) -lm -o $@
$(BUILD)/bin/py-gospa: $(BUILD)/obj/tests/python/gospa_csv.o $(TOOL_LIBS)
	@mkdir -p $(@D)
	$(call say,LD,$@)
	$(Q)$(CC) $(LDFLAGS_ALL) $< $(TOOL_LIBS) -lm -o $@

TEST_EXTRA += test-python-binding
TEST_EXTRA_DEPS_test-python-binding := $(SHARED_LIB) $(if $(filter double,$(REAL)),shared-float) \
  $(BUILD)/bin/py-replay-csv $(BUILD)/bin/py-gospa $(BUILD)/bin/py-lcm-big $(BUILD)/bin/trk-sim $(BUILD)/bin/trk-sonar-sim \
  $(BUILD)/bin/trk-lcm-bridge $(BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl
test-python-binding: $(TEST_EXTRA_DEPS_test-python-binding)
	@sh tests/python_binding.sh $(BUILD)

bench-python: $(SHARED_LIB) $(BUILD)/bin/py-replay-csv
	@sh -c '. tests/step_lib.sh; find_python || { echo "bench-python: no python3 with numpy"; exit 1; }; \
	  TRK_LIBRARY=$(abspath $(SHARED_LIB)) PYTHONPATH=tools/python $$PY tools/python/bench_scan.py --c-replay $(BUILD)/bin/py-replay-csv'
$(BUILD)/bin/py-lcm-big: $(BUILD)/obj/tests/python/lcm_big_publish.o
	@mkdir -p $(@D)
	$(call say,LD,$@)
	$(Q)$(CC) $(LDFLAGS_ALL) $< $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm) -o $@

# the examples beside mk/python.mk's tools in share/trk/python
install: install-python-examples
.PHONY: install-python-examples
install-python-examples: install-python
	install -m 755 tools/python/gospa_grid.py tools/python/bench_scan.py $(PY_SHARE)/
