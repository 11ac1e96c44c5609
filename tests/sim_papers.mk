# tests/sim_papers.mk - reproducibility of trk-sim's paper experiments and demo
# (a step of `make test`): the same seed must give byte-identical
# CSV files with 1 and 2 OpenMP threads (counter-based random streams keyed by
# (seed, run); per-run results reduced in run order; the q2 sampler of the
# MRE predictions merges its work in a fixed order). Small sizes: seconds.
.PHONY: sim-papers-repro
TEST_EXTRA += sim-papers-repro
TEST_EXTRA_DEPS_sim-papers-repro := $(BUILD)/bin/trk-sim $(BUILD)/tables/amp_k1_snr15_pfa1e-2.tbl
sim-papers-repro: $(TEST_EXTRA_DEPS_sim-papers-repro)
	@d=$$(mktemp -d) || exit 1; st=0; s=$(BUILD)/bin/trk-sim; \
	for t in 1 2; do \
	  $$s brekke-trackloss --runs 40 --scans 60 --cell-m2 0.25 --k-shape 1 --snr-db 10 --pfa 1e-2,1e-1 \
	    --seed 3 --threads $$t --quiet --no-plot --out $$d/tl$$t > /dev/null || st=1; \
	  $$s brekke-toc --runs 30 --scans 60 --from 31 --k-shape 1 --pfa 1e-3,1e-1 --q2-samples 20000 \
	    --seed 3 --threads $$t --quiet --no-plot --out $$d/toc$$t > /dev/null || st=1; \
	  $$s willett-crlb --runs 200 --scans 40 --from 11 --points 0.9:0.001,0.8:0.0001 --q2-samples 20000 \
	    --seed 3 --threads $$t --quiet --no-plot --out $$d/wc$$t > /dev/null || st=1; \
	  $$s kennedy-null --runs 100 --max-scans 8 --seed 3 --threads $$t --quiet --no-plot --out $$d/kn$$t > /dev/null || st=1; \
	  $$s brekke-errpdf --runs 30 --scans 60 --from 31 --pfa 1e-3,1e-1 --q2-samples 20000 \
	    --seed 3 --threads $$t --quiet --no-plot --out $$d/ep$$t > /dev/null || st=1; \
	  $$s demo-amplitude --tables $(BUILD)/tables --scans 60 --mre-samples 20000 --seed 3 --threads $$t --quiet --no-plot \
	    --out $$d/demo$$t > /dev/null || st=1; \
	done; \
	if [ $$st = 0 ]; then \
	  cmp $$d/tl1.csv $$d/tl2.csv && cmp $$d/tl1_loss.csv $$d/tl2_loss.csv && cmp $$d/ep1.csv $$d/ep2.csv && \
	  cmp $$d/ep1_fig3.csv $$d/ep2_fig3.csv && cmp $$d/ep1_fig4.csv $$d/ep2_fig4.csv && cmp $$d/toc1.csv $$d/toc2.csv && cmp $$d/toc1_mre.csv $$d/toc2_mre.csv && \
	  cmp $$d/wc1.csv $$d/wc2.csv && cmp $$d/kn1.csv $$d/kn2.csv && \
	  cmp $$d/demo1/tracks.csv $$d/demo2/tracks.csv && cmp $$d/demo1/summary.csv $$d/demo2/summary.csv || st=1; \
	fi; \
	rm -rf $$d; \
	if [ $$st = 0 ]; then echo "sim-papers-repro: trk-sim paper experiments and demo: CSV identical with 1 and 2 threads"; \
	else echo "sim-papers-repro: FAILED (trk-sim output depends on the thread count, or a run failed)"; exit 1; fi
