/* trk-bench - benchmarks of libtrk; prints "bench <name> <value> <unit>".
 *   trk-bench [PREFIX...]   run every benchmark, or those whose name starts
 *                           with one of the PREFIXes.
 *   trk-bench --help        the benchmarks (also --list); exit status 0. */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "cli.h"
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

double bench_urand(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

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

/* PREFIX operands. */
struct prefixes {
    const char **p;
    int n;
};

static int take_prefix(void *ctx, const char *arg, const char *next, char *err, size_t errlen)
{
    struct prefixes *pr = ctx;
    (void)next, (void)err, (void)errlen;
    if (arg[0] == '-') return 0; /* an unknown option */
    pr->p[pr->n++] = arg;
    return 1;
}

static void list_benchmarks(FILE *f)
{
    fprintf(f, "benchmarks (each prints one or more lines \"bench <name> <value> <unit>\"):\n");
    for (int i = 0; cases[i].name; i++) fprintf(f, "  %s\n", cases[i].name);
}

int main(int argc, char **argv)
{
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-bench: libtrk was built with other capacities or real type\n");
        return 2;
    }
    int list = 0;
    struct prefixes pr = {NULL, 0};
    pr.p = malloc((size_t)argc * sizeof *pr.p);
    if (!pr.p) {
        fprintf(stderr, "trk-bench: out of memory\n");
        return 1;
    }
    const struct cli_opt opts[] = {
        CLI_OPT_FLAG("--list", &list, "list the benchmarks and exit (as --help does)"),
        CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-bench",
        .usage = "[PREFIX...]",
        .about = "Benchmarks of libtrk: runs every benchmark, or those whose name starts with one of\n"
                 "the PREFIXes (exit status 2 when none matches).",
        .opts = opts,
        .more_help = list_benchmarks,
        .operand = take_prefix,
        .ctx = &pr};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN || list) {
        if (list) list_benchmarks(stdout);
        free(pr.p);
        return list ? 0 : parsed;
    }
    printf("# trk-bench (%s build)\n", TRK_REAL_IS_FLOAT ? "float" : "double");
    int ran = 0;
    for (int i = 0; cases[i].name; i++) {
        int want = pr.n == 0;
        for (int a = 0; a < pr.n; a++)
            if (strncmp(cases[i].name, pr.p[a], strlen(pr.p[a])) == 0) want = 1;
        if (!want) continue;
        cases[i].fn();
        ran++;
    }
    free(pr.p);
    if (ran == 0) {
        fprintf(stderr, "trk-bench: no benchmark matches (see --help)\n");
        return 2;
    }
    return 0;
}
