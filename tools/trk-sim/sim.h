/* sim.h - trk-sim plumbing: experiment registry and shared option parsing.
 *
 * An experiment lives in tools/trk-sim/exp_<name>.c and is declared by one
 * line starting at column 0:
 *     SIM_EXPERIMENT(c_identifier, "cli-name", "one-line description")
 *     { ... return exit status ... }
 * The build collects these lines into build/gen/sim_experiments.inc (see
 * tool.mk); nothing else to edit. The function receives argc/argv with
 * argv[0] = the experiment name.
 *
 * Common options (sim_common_arg): --seed N, --runs N, --out PREFIX,
 * --threads N, --quiet, --no-plot. Results must not depend on the thread
 * count: key each run's random stream by (seed, run) (tools/common/rng.h)
 * and reduce per-run results in run order after the parallel loop. */
#ifndef TRK_SIM_H
#define TRK_SIM_H

#include <stdint.h>

#define SIM_EXPERIMENT(id, name, desc) int sim_exp_##id(int argc, char **argv)

struct sim_common {
    uint64_t seed;
    long runs;          /* 0 = the experiment's default */
    const char *out;    /* output prefix (CSV, .gp, .png) */
    int threads;        /* 0 = OpenMP default */
    int quiet;          /* no progress bar */
    int no_plot;        /* CSV only */
};

/* Defaults: seed 1, runs 0, out = def_out, threads 0. */
void sim_common_defaults(struct sim_common *c, const char *def_out);

/* Try to consume argv[*i] (and its value) as a common option.
 * 1 consumed (*i advanced past the value), 0 not a common option, -1 bad
 * value (message printed). Forms: `--name value` and `--name=value`. */
int sim_common_arg(int argc, char **argv, int *i, struct sim_common *c);

/* `--name value` / `--name=value` matcher for experiment options: 1 and *val
 * set (and *i advanced) when argv[*i] is that option, -1 when its value is
 * missing, 0 otherwise. */
int sim_arg(int argc, char **argv, int *i, const char *name, const char **val);
int sim_parse_long(const char *s, long *v);
int sim_parse_double(const char *s, double *v);
/* Comma-separated list of doubles ("1,2,3" or "a:b:step"); returns the count
 * (<= max) or -1. */
int sim_parse_list(const char *s, double *v, int max);

/* Apply c->threads (omp_set_num_threads) and return the thread count used. */
int sim_threads(const struct sim_common *c);

#endif
