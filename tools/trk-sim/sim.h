/* sim.h - trk-sim plumbing: experiment registry, declarative options and the
 * shared run/output steps.
 *
 * An experiment lives in tools/trk-sim/exp_<name>.c and is declared by one
 * line starting at column 0:
 *     SIM_EXPERIMENT(c_identifier, "cli-name", "one-line description")
 *     { ... return exit status ... }
 * The build collects these lines into build/gen/sim_experiments.inc (see
 * tool.mk); nothing else to edit. The function receives argc/argv with
 * argv[0] = the experiment name.
 *
 * Options: the experiment describes each of its options once, in a table of
 * struct sim_opt (name, type, destination, default, accepted range, help),
 * and sim_parse does the rest: defaults, --help (printed from the table),
 * the common options (--seed N, --runs N, --out PREFIX, --threads N,
 * --quiet, --no-plot), value checks and the error messages. Exit status 2
 * for bad usage, as everywhere in trk-sim:
 *     long scans;
 *     const struct sim_opt opts[] = {
 *         SIM_OPT_LONG("--scans", &scans, "N", "300", SIM_IN, 1, 1000000, "scans per run"),
 *         SIM_OPT_END};
 *     const struct sim_cli cli = {"my-exp", NULL, "What it does.", opts, "my_exp", NULL, 0,
 *                                 "Writes PREFIX.csv.", NULL, NULL};
 *     struct sim_common com;
 *     const int parsed = sim_parse(&cli, &com, argc, argv);
 *     if (parsed != SIM_RUN) return parsed;
 *
 * Results must not depend on the thread count: key each run's random stream
 * by (seed, run) (tools/sim/rng.h) and reduce per-run results in run
 * order after the parallel loop. */
#ifndef TRK_SIM_H
#define TRK_SIM_H

#include <stdint.h>
#include <stdio.h>

#include "progress.h"

#define SIM_EXPERIMENT(id, name, desc) int sim_exp_##id(int argc, char **argv)

struct sim_common {
    uint64_t seed;      /* --seed (default 1) */
    long runs;          /* --runs when the experiment has no --runs of its own (0: not given) */
    const char *out;    /* --out: output prefix (CSV, .gp, .png) */
    int threads;        /* --threads; 0 = OpenMP default */
    int quiet;          /* --quiet: no progress bar */
    int no_plot;        /* --no-plot: CSV only */
};

/* ---------------------------------------------------------------- options */

enum sim_opt_type {
    SIM_LONG,   /* long *dst; an integer ("1e6" accepted) within the range */
    SIM_DOUBLE, /* double *dst; a number within the range */
    SIM_LIST,   /* double dst[max], *n = count: "a,b,c" or "from:to:step", each within the range */
    SIM_CHOICE, /* int *dst = values[k] for the k-th word of words ("cell|scan") */
    SIM_FLAG,   /* int *dst = 1; takes no value */
    SIM_STRING, /* const char **dst = the value */
    SIM_CUSTOM  /* parse(value, dst) == 0 */
};

/* Accepted range of SIM_LONG, SIM_DOUBLE and SIM_LIST values: a bit set
 * (0: any value strtod accepts). */
enum {
    SIM_GE = 1, /* lo <= v */
    SIM_GT = 2, /* lo < v */
    SIM_LE = 4, /* v <= hi */
    SIM_LT = 8, /* v < hi */
    SIM_IN = SIM_GE | SIM_LE,
    SIM_OPEN = SIM_GT | SIM_LT
};

struct sim_opt {
    const char *name;       /* "--scans"; NULL ends the table */
    enum sim_opt_type type;
    void *dst;
    const char *arg;        /* the value in --help ("N", "LIST"); CHOICE: the words */
    const char *def;        /* the default as text: parsed into dst before the command
                             * line and shown by --help; NULL: dst keeps its value and
                             * the help text says what the default is */
    const char *help;       /* one line; '\n' continues it on the next line */
    unsigned range;         /* SIM_GE | ... */
    double lo, hi;
    int max, *n;            /* SIM_LIST: capacity of dst, count */
    const int *values;      /* SIM_CHOICE: one per word (NULL: the word's index) */
    int (*parse)(const char *value, void *dst); /* SIM_CUSTOM: 0 or -1 */
};

#define SIM_OPT_LONG(name, dst, arg, def, range, lo, hi, help) \
    {name, SIM_LONG, dst, arg, def, help, range, lo, hi, 0, NULL, NULL, NULL}
#define SIM_OPT_DOUBLE(name, dst, arg, def, range, lo, hi, help) \
    {name, SIM_DOUBLE, dst, arg, def, help, range, lo, hi, 0, NULL, NULL, NULL}
#define SIM_OPT_LIST(name, dst, n, max, def, range, lo, hi, help) \
    {name, SIM_LIST, dst, "LIST", def, help, range, lo, hi, max, n, NULL, NULL}
#define SIM_OPT_CHOICE(name, dst, words, values, def, help) \
    {name, SIM_CHOICE, dst, words, def, help, 0, 0, 0, 0, NULL, values, NULL}
#define SIM_OPT_FLAG(name, dst, help) {name, SIM_FLAG, dst, NULL, NULL, help, 0, 0, 0, 0, NULL, NULL, NULL}
#define SIM_OPT_STRING(name, dst, arg, def, help) \
    {name, SIM_STRING, dst, arg, def, help, 0, 0, 0, 0, NULL, NULL, NULL}
#define SIM_OPT_CUSTOM(name, dst, parse, arg, def, help) \
    {name, SIM_CUSTOM, dst, arg, def, help, 0, 0, 0, 0, NULL, NULL, parse}
#define SIM_OPT_END {NULL, SIM_FLAG, NULL, NULL, NULL, NULL, 0, 0, 0, 0, NULL, NULL, NULL}

/* Common options an experiment accepts but does not use (not listed by --help). */
enum { SIM_UNUSED_RUNS = 1, SIM_UNUSED_THREADS = 2 };

struct sim_cli {
    const char *name;       /* the experiment ("clutter-null"): messages and --help */
    const char *usage;      /* after "trk-sim NAME"; NULL: "[options]" */
    const char *about;      /* what it does (lines of --help before the options) */
    const struct sim_opt *opts;
    const char *out;        /* default --out */
    const char *out_arg;    /* --out's value in --help; NULL: "PREFIX" */
    unsigned unused;        /* SIM_UNUSED_* */
    const char *files;      /* what it writes (lines of --help after the options) */
    /* a non-option argument: 0 taken, else an unknown option (NULL: none taken) */
    int (*operand)(const char *arg, void *ctx);
    void *operand_ctx;
};

#define SIM_RUN (-1)
/* Defaults, then the command line into the options and *com (--help
 * anywhere: the help, exit status 0). SIM_RUN when the experiment should run,
 * else its exit status (2 after a message on a bad option or value). */
int sim_parse(const struct sim_cli *cli, struct sim_common *com, int argc, char **argv);

/* The common options' help lines (trk-sim --help). */
void sim_common_usage(FILE *f);

/* Value parsers (the ones of the option table). 0, or -1. */
int sim_parse_long(const char *s, long *v);
int sim_parse_double(const char *s, double *v);
/* Comma-separated list of doubles ("1,2,3" or "a:b:step"); returns the count
 * (<= max), or -1 for a malformed list or one with more than max values
 * (refused, never cut short). */
int sim_parse_list(const char *s, double *v, int max);

/* ---------------------------------------------------------------- runs */

/* Apply c->threads (omp_set_num_threads) and return the thread count used. */
int sim_threads(const struct sim_common *c);

/* A progress bar over the runs of a parallel loop (none under --quiet), and
 * its wall time. */
struct sim_progress {
    struct progress bar;
    double t0;
};
void sim_progress_start(struct sim_progress *p, const struct sim_common *c, const char *label, long total);
/* n more runs done; from any thread (serialised inside). */
void sim_progress_add(struct sim_progress *p, long n);
/* One more run done by this thread: counted in *pending, passed on every 64
 * (call sim_progress_add(p, *pending) after the thread's last run). */
void sim_progress_step(struct sim_progress *p, long *pending);
/* The final line; returns the wall time in seconds since the start. */
double sim_progress_end(struct sim_progress *p);

/* ---------------------------------------------------------------- single-target runs (single_target.h) */

struct st_amp;
struct st_model;
struct st_result;

/* The K amplitude models (st_amp_init, grid and size as there) of every
 * (nu, snr_db, pfa) of the three lists, built in parallel, in the order
 * amp[(a * n_snr + b) * n_pfa + c] = (nu[a], snr_db[b], pfa[c]). 0, or -1
 * with a message "EXP: ..." on stderr (free the models with st_amp_free). */
int sim_amp_k_grid(const char *exp, struct st_amp *amp, const double *nu, int n_nu, const double *snr_db,
                   int n_snr, const double *pfa, int n_pfa, int grid, unsigned size);

/* *m = Brekke's Table I model (st_params_brekke) on the amplitude model
 * *amp, lambda = amp->pfa / cell_m2, with scans per run, initial track and
 * texture (st_params) and the seed. 0, or -1 with a message on stderr. */
int sim_brekke_model(const char *exp, struct st_model *m, const struct st_amp *amp, double cell_m2, long scans,
                     int init, int texture, uint64_t seed);

/* Every run (model k < n_models, run < runs) in parallel: st_run with each
 * filter ai < n_filters (0 PDAF, 1 PDAFAI), errors summed over scans >=
 * from; keep(ctx, k * runs + run, ai, result) stores what the experiment
 * needs (called from any thread: write to that run's own slot). Progress bar
 * `label` unless --quiet. Returns the wall time; *failed = 1 when st_run
 * refused a call (that run is not kept). */
double sim_st_runs(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                   long runs, int n_filters, long from,
                   void (*keep)(void *ctx, long it, int ai, const struct st_result *res), void *ctx, int *failed);

/* A table file dir/file (`make tables`) loaded through the library into *t,
 * which views *buf (malloc'd: free it after the last use of *t). 0, or -1
 * with a message "EXP: path: status" on stderr. */
struct trk_table;
int sim_load_table(const char *exp, const char *dir, const char *file, struct trk_table *t, void **buf);

/* ---------------------------------------------------------------- output */

/* Opens c->out + suffix (e.g. ".csv", "_front.csv") for writing with its
 * header line (plot.h plot_csv_open); the name goes to path[pathlen] when
 * path is not NULL. NULL (and a message) on failure. */
FILE *sim_csv_open(const struct sim_common *c, const char *suffix, char *path, size_t pathlen,
                   const char *header);

/* A growing text (gnuplot script bodies): sim_text_add appends printf-style.
 * On out of memory the text is left as it was and t->failed set. */
struct sim_text {
    char *s;
    size_t len, cap;
    int failed;
};
void sim_text_add(struct sim_text *t, const char *fmt, ...);
void sim_text_free(struct sim_text *t);

/* Unless --no-plot: the gnuplot script c->out + suffix + ".gp" with `body`
 * (plot.h plot_gnuplot), and the PNG when gnuplot is there. Returns
 * plot_gnuplot's value (0 without plotting; -1 on an I/O error). */
int sim_plot(const struct sim_common *c, const char *suffix, const char *body);
/* The same with the body formatted printf-style. */
int sim_plotf(const struct sim_common *c, const char *suffix, const char *fmt, ...);

#endif
