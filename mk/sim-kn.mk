# mk/sim-kn.mk - blanding-add-arl's K range of the K/N rules, a
# step of `make test`: --kn-k full (K = 0..N-1) holds every rule of the
# default trimmed range (K = N/16..N/3) with the same values (common random
# numbers: a rule's first passage does not depend on the others), holds N
# rules per window N, and both CSV files and the gnuplot script name the range;
# the plot marks the points with censored runs (lower bounds).
.PHONY: sim-kn-range
TEST_EXTRA += sim-kn-range
TEST_EXTRA_DEPS_sim-kn-range := $(BUILD)/bin/trk-sim
sim-kn-range: $(TEST_EXTRA_DEPS_sim-kn-range)
	@d=$$(mktemp -d) || exit 1; st=0; \
	for m in trimmed full; do \
	  $(BUILD)/bin/trk-sim blanding-add-arl --runs 40 --max-scans 1000 --seed 5 --kn-n 4:16:4 --kn-k $$m \
	    --quiet --out $$d/$$m > /dev/null 2>&1 || st=1; \
	  grep -v '^#' $$d/$$m.csv | sort > $$d/$$m.rows; \
	done; \
	t=$$(grep -c '^kn,' $$d/trimmed.csv); f=$$(grep -c '^kn,' $$d/full.csv); \
	[ $$st = 0 ] && [ "$$f" = 40 ] && [ "$$(comm -23 $$d/trimmed.rows $$d/full.rows | wc -l)" = 0 ] && \
	  grep -q '^# K/N rules: K = N/16..N/3 (--kn-k trimmed)' $$d/trimmed.csv && \
	  grep -q '^# K/N rules: K = 0..N-1 (--kn-k full)' $$d/full.csv && \
	  grep -q "set title .*K/N: K = 0..N-1" $$d/full.gp && grep -q "title 'K/N (K = N/16..N/3)'" $$d/trimmed.gp && \
	  grep -q "title 'censored runs: ADD/ARL a lower bound'" $$d/full.gp || st=1; \
	rm -rf $$d; \
	if [ $$st = 0 ]; then echo "sim-kn-range: --kn-k full: $$f K/N rules for N = 4, 8, 12, 16 (0..N-1), the $$t trimmed ones among them unchanged; the CSV and the plot name the range"; \
	else echo "sim-kn-range: FAILED (rules $$t trimmed / $$f full, or a CSV/plot without the K range)"; exit 1; fi
