/* trk-bench - benchmarks of libtrk; prints "bench <name> <value> <unit>".
 *   trk-bench [PREFIX...]   run every benchmark, or those whose name starts
 *                           with one of the PREFIXes. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "trk/types.h"

#define TRK_BENCH_ENTRY(bname) TRK_BENCH(bname);
#include "bench_cases.inc"
#undef TRK_BENCH_ENTRY

static const struct {
    const char *name;
    void (*fn)(void);
} cases[] = {
#define TRK_BENCH_ENTRY(bname) {#bname, trk_bench_##bname},
#include "bench_cases.inc"
#undef TRK_BENCH_ENTRY
    {NULL, NULL}};

static volatile double sink_;

void bench_sink(double v) { sink_ += v; }

void bench_print(const char *name, double value, const char *unit)
{
    printf("bench %s %.6g %s\n", name, value, unit);
    fflush(stdout);
}

double bench_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

double bench_time_ns(void (*fn)(void *), void *arg, int reps)
{
    long n = 1;
    for (;;) { /* calibrate a batch of >= 20 ms */
        double t0 = bench_now_ns();
        for (long i = 0; i < n; i++) fn(arg);
        double dt = bench_now_ns() - t0;
        if (dt >= 2e7 || n >= (1L << 40)) break;
        n = dt > 0 ? (long)(n * 2.2e7 / dt) + 1 : n * 10;
    }
    double best = 1e300;
    for (int r = 0; r < reps; r++) {
        double t0 = bench_now_ns();
        for (long i = 0; i < n; i++) fn(arg);
        double per = (bench_now_ns() - t0) / (double)n;
        if (per < best) best = per;
    }
    return best;
}

int main(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-bench: libtrk was built with other capacities or real type\n");
        return 2;
    }
    printf("# trk-bench (%s build)\n", TRK_REAL_IS_FLOAT ? "float" : "double");
    int ran = 0;
    for (int i = 0; cases[i].name; i++) {
        int want = argc < 2;
        for (int a = 1; a < argc; a++)
            if (strncmp(cases[i].name, argv[a], strlen(argv[a])) == 0) want = 1;
        if (!want) continue;
        cases[i].fn();
        ran++;
    }
    if (ran == 0) {
        fprintf(stderr, "trk-bench: no benchmark matches\n");
        return 2;
    }
    return 0;
}
