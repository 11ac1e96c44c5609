# fuzz.mk - libFuzzer targets (clang) and the corpus replay (any compiler).
#
# Every tests/fuzz/fuzz_NAME.c defines LLVMFuzzerTestOneInput and has a seed
# corpus in tests/fuzz/corpus/NAME/ (committed). Extra link inputs of a target
# may be set in tests/fuzz/NAME.mk (FUZZ_OBJS_NAME: objects of $(BUILD),
# FUZZ_CFLAGS_NAME: include paths) - nothing else to edit to add a target.
#
#   make fuzz [FUZZ_SECONDS=60] [FUZZ_TARGETS='vec table']
#        builds build/fuzz/bin/fuzz-NAME with clang -fsanitize=fuzzer,address,
#        undefined (library and tool code instrumented too) and runs each target
#        for FUZZ_SECONDS, one after the other (1 job: the machine is shared),
#        new inputs into build/fuzz/corpus/NAME/, crashes into
#        build/fuzz/artifacts/; the executions of every run are added to
#        build/fuzz/NAME.execs and the totals printed. FUZZ_FLAGS adds libFuzzer
#        options, e.g. FUZZ_FLAGS='-fork=1 -ignore_crashes=1' to go on after a
#        finding (executions are then read from the last "#N: cov:" line)
#   make fuzz-merge     adds the coverage-increasing inputs of build/fuzz/corpus/
#                       to the committed tests/fuzz/corpus/ (libFuzzer -merge=1)
#   make fuzz-replay    replays tests/fuzz/corpus/NAME/ with the plain-C main
#                       tests/fuzz/replay.c in the current BUILD/CC/SAN; a step
#                       of the ASan+UBSan configurations of make test (gcc and
#                       clang: CHECK_EXTRA=fuzz-replay)

FUZZ_SECONDS ?= 60
FUZZ_DIR := build/fuzz
FUZZ_ALL := $(patsubst tests/fuzz/fuzz_%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_TARGETS ?= $(FUZZ_ALL)
FUZZ_SAN := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_FLAGS ?=

-include $(wildcard tests/fuzz/*.mk)

# --- replay: $(BUILD)/fuzz-replay/replay-NAME (generic object rule of the Makefile)
define FUZZ_REPLAY_template
$(BUILD)/fuzz-replay/replay-$(1): $(BUILD)/obj/tests/fuzz/replay.o $(BUILD)/obj/tests/fuzz/fuzz_$(1).o \
  $$(FUZZ_OBJS_$(1)) $(TOOL_LIBS)
	@mkdir -p $$(@D)
	$$(Q)$(CC) $(LDFLAGS_ALL) $$(filter %.o,$$^) $(TOOL_LIBS) $$(FUZZ_LDLIBS_$(1)) -lm -o $$@
$(BUILD)/obj/tests/fuzz/fuzz_$(1).o: CFLAGS_ALL += $$(FUZZ_CFLAGS_$(1))
endef
$(foreach t,$(FUZZ_ALL),$(eval $(call FUZZ_REPLAY_template,$(t))))

.PHONY: fuzz fuzz-build fuzz-merge fuzz-replay
TEST_EXTRA_DEPS_fuzz-replay := $(addprefix $(BUILD)/fuzz-replay/replay-,$(FUZZ_ALL))
fuzz-replay: $(TEST_EXTRA_DEPS_fuzz-replay)
	@set -e; for t in $(FUZZ_ALL); do \
	  if [ -d tests/fuzz/corpus/$$t ]; then $(BUILD)/fuzz-replay/replay-$$t tests/fuzz/corpus/$$t; \
	  else echo "fuzz-replay: tests/fuzz/corpus/$$t missing"; exit 1; fi; done

# --- libFuzzer binaries: the whole build of build/fuzz is clang + coverage + ASan/UBSan
FUZZ_MAKE = $(MAKE) --no-print-directory BUILD=$(FUZZ_DIR) CC=clang OPT=-O1 \
  SANFLAGS='$(FUZZ_SAN)'

fuzz-build:
	@command -v clang >/dev/null || { echo "fuzz: clang not found"; exit 1; }
	+$(FUZZ_MAKE) $(addprefix $(FUZZ_DIR)/bin/fuzz-,$(FUZZ_TARGETS))

ifeq ($(BUILD),$(FUZZ_DIR))
# No comparison tracing in the fixed-size arithmetic loops: LCM's generated
# array codecs and the small dense kernels (linalg, kalman, the MRE/CRLB
# recursions). Their loop compares fed __sanitizer_cov_trace_cmp* with 60 %
# of all samples (perf, lcm_copy 564 and vec_kinds 706 executions/s) and
# carry no input-dependent branch worth solving; edge coverage, ASan and
# UBSan stay on in them. The parsers and validators keep trace-cmp.
FUZZ_NO_CMP_OBJS := $(FUZZ_DIR)/obj/src/linalg.o $(FUZZ_DIR)/obj/src/kalman.o \
  $(patsubst src/perf/%.c,$(FUZZ_DIR)/obj/src/perf/%.o,$(wildcard src/perf/*.c)) \
  $(FUZZ_DIR)/obj/lcmgen/%.o
$(FUZZ_NO_CMP_OBJS): CFLAGS_ALL += -fno-sanitize-coverage=trace-cmp
define FUZZ_BIN_template
$(FUZZ_DIR)/bin/fuzz-$(1): $(FUZZ_DIR)/obj/tests/fuzz/fuzz_$(1).o $$(FUZZ_OBJS_$(1)) $(TOOL_LIBS)
	@mkdir -p $$(@D)
	$(CC) -fsanitize=fuzzer,address,undefined -fopenmp $$(filter %.o,$$^) $(TOOL_LIBS) $$(FUZZ_LDLIBS_$(1)) -lm -o $$@
endef
$(foreach t,$(FUZZ_ALL),$(eval $(call FUZZ_BIN_template,$(t))))
endif

# One target after the other; -print_final_stats gives the executions.
fuzz: fuzz-build
	@mkdir -p $(FUZZ_DIR)/artifacts
	@set -e; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_DIR)/corpus/$$t; \
	  dict=""; [ -f tests/fuzz/$$t.dict ] && dict="-dict=tests/fuzz/$$t.dict"; \
	  echo "== fuzz-$$t: $(FUZZ_SECONDS) s"; \
	  before=$$(ls $(FUZZ_DIR)/artifacts | grep -c "^$$t-" || true); \
	  rc=0; $(FUZZ_DIR)/bin/fuzz-$$t -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 $$dict \
	    -artifact_prefix=$(FUZZ_DIR)/artifacts/$$t- $(FUZZ_FLAGS) $(FUZZ_DIR)/corpus/$$t tests/fuzz/corpus/$$t \
	    > $(FUZZ_DIR)/$$t.log 2>&1 || rc=$$?; \
	  n=$$(awk '/stat::number_of_executed_units:/ { s = $$2 } /^#[0-9]+: cov:/ { f = substr($$1, 2) + 0 } \
	    END { print (s + 0 > f + 0 ? s + 0 : f + 0) }' $(FUZZ_DIR)/$$t.log); \
	  prev=$$(cat $(FUZZ_DIR)/$$t.execs 2>/dev/null || echo 0); \
	  echo $$((prev + $${n:-0})) > $(FUZZ_DIR)/$$t.execs; \
	  grep -E '^(#[0-9]+ +DONE|stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb))' $(FUZZ_DIR)/$$t.log || true; \
	  echo "   fuzz-$$t: rc $$rc, $${n:-0} executions this run, $$(cat $(FUZZ_DIR)/$$t.execs) in total (build/fuzz/$$t.execs)"; \
	  after=$$(ls $(FUZZ_DIR)/artifacts | grep -c "^$$t-" || true); \
	  if [ $$rc -ne 0 ] || [ $$after -ne $$before ]; then grep -E 'ERROR|SUMMARY|Test unit written' $(FUZZ_DIR)/$$t.log; \
	    echo "   fuzz-$$t: $$((after - before)) new file(s) in $(FUZZ_DIR)/artifacts/ - a finding"; exit 1; fi; \
	done

fuzz-merge: fuzz-build
	@set -e; for t in $(FUZZ_TARGETS); do mkdir -p tests/fuzz/corpus/$$t $(FUZZ_DIR)/corpus/$$t; \
	  $(FUZZ_DIR)/bin/fuzz-$$t -merge=1 tests/fuzz/corpus/$$t $(FUZZ_DIR)/corpus/$$t 2>&1 | grep -E 'MERGE-OUTER: [0-9]+ new files' || true; done

# --- seeds of fuzz_table (written by hand when the table format changes)
.PHONY: fuzz-table-seeds
fuzz-table-seeds: $(BUILD)/obj/tests/fuzz/table_seeds.o $(TOOL_LIBS)
	@mkdir -p $(BUILD)/fuzz-replay tests/fuzz/corpus/table
	$(CC) $(LDFLAGS_ALL) $< $(TOOL_LIBS) -lm -o $(BUILD)/fuzz-replay/table_seeds
	$(BUILD)/fuzz-replay/table_seeds tests/fuzz/corpus/table
	@ls -l tests/fuzz/corpus/table

# --- open findings (tests/fuzz/findings/<target>/, see its README.md): never fails
.PHONY: fuzz-findings
fuzz-findings: $(addprefix $(BUILD)/fuzz-replay/replay-,$(FUZZ_ALL))
	@for d in tests/fuzz/findings/*/; do t=$$(basename $$d); \
	  [ -x $(BUILD)/fuzz-replay/replay-$$t ] || continue; \
	  for f in $$d*; do case $$f in *.md) continue;; esac; \
	    if $(BUILD)/fuzz-replay/replay-$$t $$f >/dev/null 2>&1; then echo "FIXED $$f"; else echo "OPEN  $$f"; fi; done; done
