# mk/sim.mk - trk-sim reproducibility check (a step of `make test`):
# the same seed must give byte-identical CSV files with 1 and 2 OpenMP threads
# (counter-based random streams keyed by (seed, run); reductions in run order).
.PHONY: sim-repro
TEST_EXTRA += sim-repro
TEST_EXTRA_DEPS_sim-repro := $(BUILD)/bin/trk-sim
sim-repro: $(TEST_EXTRA_DEPS_sim-repro)
	@d=$$(mktemp -d) || exit 1; st=0; \
	for t in 1 2; do \
	  $(BUILD)/bin/trk-sim blanding-add-arl --runs 150 --max-scans 4000 --seed 5 --threads $$t \
	    --quiet --no-plot --out $$d/bl$$t > /dev/null || st=1; \
	  $(BUILD)/bin/trk-sim clutter-null --runs 3000 --scans 30 --seed 5 --threads $$t \
	    --quiet --no-plot --out $$d/cn$$t > /dev/null || st=1; \
	done; \
	if [ $$st = 0 ]; then cmp $$d/bl1.csv $$d/bl2.csv && cmp $$d/bl1_front.csv $$d/bl2_front.csv && \
	  cmp $$d/cn1.csv $$d/cn2.csv || st=1; fi; \
	rm -rf $$d; \
	if [ $$st = 0 ]; then echo "sim-repro: trk-sim CSV identical with 1 and 2 threads"; \
	else echo "sim-repro: FAILED (trk-sim output depends on the thread count, or a run failed)"; exit 1; fi
