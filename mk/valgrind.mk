# valgrind.mk - the vector runner under valgrind (part of make test):
#
#   make valgrind-vectors    valgrind --error-exitcode=1 $(BUILD)/bin/trk-vectors
#                            over every $(VECTORS_DIR)/*.vec (uninstrumented
#                            -O2 build: memcheck sees uninitialised reads and
#                            leaks that ASan does not)
#
# One OpenMP thread (OMP_NUM_THREADS=1): valgrind runs threads one at a time
# anyway, and libgomp's thread stacks would be reported as possibly lost.
# Cases of VALGRIND_SAMPLE_KINDS are thinned to the first case of each kind:
# the q2 importance-sampling kinds run 3e6-8e6 Monte Carlo scenes per case
# (~0.2 s each natively, ~10 s each under valgrind). The filtered copies are
# written to $(BUILD)/valgrind/ (file-level tol lines kept).

VALGRIND ?= valgrind
VALGRIND_FLAGS ?= -q --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect
VALGRIND_SAMPLE_KINDS ?= q2_pdaf q2_pdafai

.PHONY: valgrind-vectors
TEST_EXTRA += valgrind-vectors
TEST_EXTRA_DEPS_valgrind-vectors := $(BUILD)/bin/trk-vectors
valgrind-vectors: $(TEST_EXTRA_DEPS_valgrind-vectors)
	@command -v $(VALGRIND) >/dev/null || { echo "valgrind-vectors: $(VALGRIND) not found (apt-get install valgrind)"; exit 1; }
	@if [ ! -d $(VECTORS_DIR) ]; then echo "valgrind-vectors: $(VECTORS_DIR) not found, skipped"; exit 0; fi
	@mkdir -p $(BUILD)/valgrind
	@for f in $(VECTORS_DIR)/*.vec; do \
	  awk -v kinds="$(VALGRIND_SAMPLE_KINDS)" ' \
	    BEGIN { n = split(kinds, k, " "); for (i = 1; i <= n; i++) thin[k[i]] = 1 } \
	    BEGIN { keep = 1 } \
	    /^case / { incase = 1; keep = !($$2 in thin) || !($$2 in seen); seen[$$2] = 1; if (!keep) dropped++ } \
	    keep || !incase { print } \
	    /^end/ { incase = 0; keep = 1 } \
	    END { if (dropped) printf "   %s: %d cases of [%s] left out (first of each kept)\n", FILENAME, dropped, kinds > "/dev/stderr" }' \
	    $$f > $(BUILD)/valgrind/$$(basename $$f); done
	@echo "== valgrind $(BUILD)/bin/trk-vectors $(VECTORS_DIR)/*.vec"
	OMP_NUM_THREADS=1 $(VALGRIND) $(VALGRIND_FLAGS) $(BUILD)/bin/trk-vectors --quiet $(BUILD)/valgrind/*.vec
