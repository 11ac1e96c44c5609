/* bench.h - trk-bench plumbing.
 *
 * A benchmark family lives in tools/trk-bench/bench_<family>.c and defines
 *     TRK_BENCH(name) { ... bench_print("name_x", value, "ns"); ... }
 * The build collects every TRK_BENCH line into the registry. `trk-bench`
 * runs all, `trk-bench NAME...` only those whose name starts with NAME,
 * `trk-bench --help` lists them (tools/cli's option parser).
 * Output lines: "bench <name> <value> <unit>". */
#ifndef TRK_BENCH_H
#define TRK_BENCH_H

#include <stddef.h>

#define TRK_BENCH(bname) void trk_bench_##bname(void)

/* Print one result line: "bench <name> <value> <unit>". */
void bench_print(const char *name, double value, const char *unit);

/* Monotonic wall time in nanoseconds. */
double bench_now_ns(void);

/* Time fn(arg) per call: runs it in batches until each batch takes >= 20 ms,
 * repeats `reps` batches and returns the minimum time per call in ns. */
double bench_time_ns(void (*fn)(void *), void *arg, int reps);

/* Keep a value alive so the optimiser cannot drop the work producing it. */
void bench_sink(double v);

/* Callgrind's instrumentation on and off around a measured region (make
 * bench-instr); no-ops unless built with valgrind's header
 * (TRK_BENCH_CALLGRIND, set by tool.mk when it is installed). */
#ifdef TRK_BENCH_CALLGRIND
#include <valgrind/callgrind.h>
#define BENCH_INSTR_START() CALLGRIND_START_INSTRUMENTATION
#define BENCH_INSTR_STOP() CALLGRIND_STOP_INSTRUMENTATION
#else
#define BENCH_INSTR_START() ((void)0)
#define BENCH_INSTR_STOP() ((void)0)
#endif

#endif
