# tools/trk-bench/tool.mk - the q2 benchmarks (bench_q2.c) time the q2 sampler
# on 1 and 2 threads (libtrk_gen.a holds its OpenMP build, mk/q2.mk); the LCM
# bridge benchmarks (bench_lcm.c) run the bridge core of libtrk_lcm.a over
# liblcm.
TOOL_LDLIBS_trk-bench += $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)
# The baseline loops (baseline_*.c) are compiled with the library's
# own optimisation flags, so a ratio compares code, not flags.
$(BUILD)/obj/tools/trk-bench/baseline_pda.o: CFLAGS_ALL += $(LIBOPT)
# ... and once more at -O2 -funroll-loops (the library's flags before it
# moved to -O3, which slows gcc 12's float loop): the _vs_baseline_o2
# lines
$(BUILD)/obj/tools/trk-bench/baseline_pda_o2.o: CFLAGS_ALL += -funroll-loops
$(BUILD)/obj/tools/trk-bench/baseline_pda_o2.o: tools/trk-bench/baseline_pda.c
# make bench-instr: callgrind's instrumentation around the measured scans
# (bench.h BENCH_INSTR_*), when valgrind's header is installed (.ci/run's
# valgrind package has it).
ifneq ($(wildcard /usr/include/valgrind/callgrind.h),)
TOOL_CFLAGS_trk-bench += -DTRK_BENCH_CALLGRIND
endif
