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
 * struct sim_opt (= struct cli_opt, tools/cli/cli.h: name, type,
 * destination, default, accepted range, help; SIM_OPT_ALIAS for an old
 * spelling), and sim_parse (cli_parse) does the rest: defaults, --help
 * (printed from the table), the common options (--seed N, --runs N,
 * --out PREFIX, --threads N, --quiet, --no-plot), value checks and the
 * error messages. Exit status 2 for bad usage, as everywhere in trk-sim:
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
 * by (seed, run) (tools/sim/rng.h), let each run write its result into its
 * own slot (sim_run_units: work units of tools/par, on this process's
 * threads or, in trk-sim-mpi, over the ranks of an MPI job) and reduce the
 * slots in run order afterwards. Output files go through sim_csv_open and
 * sim_plot, which write on rank 0 only. */
#ifndef TRK_SIM_H
#define TRK_SIM_H

#include <stdint.h>
#include <stdio.h>

#include "cli.h"
#include "fileio.h"
#include "progress.h"

#define SIM_EXPERIMENT(id, name, desc) int sim_exp_##id(int argc, char **argv)

struct par;

struct sim_common {
    uint64_t seed;      /* --seed (default 1) */
    long runs;          /* --runs when the experiment has no --runs of its own (0: not given) */
    const char *out;    /* --out: output prefix (CSV, .gp, .png) */
    int threads;        /* --threads; 0 = OpenMP default */
    int quiet;          /* --quiet: no progress bar (and on every rank but 0) */
    int no_plot;        /* --no-plot: CSV only */
    struct par *par;    /* the work distribution (tools/par/par.h): the MPI
                           rank in trk-sim-mpi, NULL (this process) in trk-sim */
    const char *checkpoint;  /* trk-sim-mpi --checkpoint FILE (NULL: none) */
    double checkpoint_s;     /* --checkpoint-interval */
};

/* This process's work distribution (main.c): see sim_common.par. */
struct par *sim_par(void);

/* ---------------------------------------------------------------- options */

/* The options are tools/cli's (cli.h): struct sim_opt is struct cli_opt, the
 * SIM_ names are its CLI_ names. */
#define sim_opt cli_opt
#define SIM_LONG CLI_LONG
#define SIM_DOUBLE CLI_DOUBLE
#define SIM_LIST CLI_LIST
#define SIM_CHOICE CLI_CHOICE
#define SIM_FLAG CLI_FLAG
#define SIM_STRING CLI_STRING
#define SIM_STRINGS CLI_STRINGS
#define SIM_CUSTOM CLI_CUSTOM
#define SIM_GE CLI_GE
#define SIM_GT CLI_GT
#define SIM_LE CLI_LE
#define SIM_LT CLI_LT
#define SIM_IN CLI_IN
#define SIM_OPEN CLI_OPEN

#define SIM_OPT_LONG CLI_OPT_LONG
#define SIM_OPT_DOUBLE CLI_OPT_DOUBLE
#define SIM_OPT_LIST CLI_OPT_LIST
#define SIM_OPT_CHOICE CLI_OPT_CHOICE
#define SIM_OPT_FLAG CLI_OPT_FLAG
#define SIM_OPT_STRING CLI_OPT_STRING
#define SIM_OPT_STRINGS CLI_OPT_STRINGS
#define SIM_OPT_CUSTOM CLI_OPT_CUSTOM
#define SIM_OPT_ALIAS CLI_OPT_ALIAS /* an old spelling, with a deprecation note */
#define SIM_OPT_END CLI_OPT_END

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

#define SIM_RUN CLI_RUN
/* Defaults, then the command line into the options and *com (cli_parse:
 * --help anywhere: the help, exit status 0). SIM_RUN when the experiment
 * should run, else its exit status (2 after a one-line message on a bad
 * option or value). Messages start "trk-sim NAME: ". */
int sim_parse(const struct sim_cli *cli, struct sim_common *com, int argc, char **argv);
/* The same, with more_help(f) printed at the end of --help (e.g. tcfg_help). */
int sim_parse_more(const struct sim_cli *cli, void (*more_help)(FILE *f), struct sim_common *com, int argc,
                   char **argv);

/* The common options' help lines (trk-sim --help). */
void sim_common_usage(FILE *f);

/* Value parsers (the ones of the option table, cli.h cli_parse_*). 0, or -1. */
#define sim_parse_long cli_parse_long
#define sim_parse_double cli_parse_double
/* Comma-separated list of doubles ("1,2,3" or "a:b:step"); returns the count
 * (<= max), or -1 for a malformed list or one with more than max values
 * (refused, never cut short). */
#define sim_parse_list cli_parse_list

/* ---------------------------------------------------------------- runs */

/* Apply c->threads (omp_set_num_threads) and return the thread count used. */
int sim_threads(const struct sim_common *c);

/* Work units [0, n) through tools/par (par.h) on c->par: run(ctx, i, res,
 * &ws) writes unit i's result (size bytes) at res = out + i * size; ws is
 * the thread's workspace (NULL at first, freed by ws_free). chunk: units
 * per chunk (consecutive). A progress bar `label` over the units on rank 0
 * (none under --quiet); *wall the wall time. Every slot is filled on every
 * rank when it returns 0; 1: a unit failed (its index in *failed_unit when
 * not NULL; the caller says what failed); -1 after a message "LABEL: ..."
 * (the distribution or the checkpoint failed). */
int sim_run_units(const struct sim_common *c, const char *label, size_t n, size_t size, size_t chunk,
                  int (*run)(void *ctx, size_t i, void *res, void **ws), void (*ws_free)(void *ctx, void *ws),
                  void *ctx, void *out, double *wall, size_t *failed_unit);

/* A progress bar over the runs of a parallel loop (none under --quiet), and
 * its wall time. */
struct sim_progress {
    struct progress bar;
    double t0;
};
void sim_progress_start(struct sim_progress *p, const struct sim_common *c, const char *label, long total);
/* n more runs done; from any thread (serialised inside). */
void sim_progress_add(struct sim_progress *p, long n);
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
 * *amp, lambda = amp->pfa / cell_m2, with scans per run, initial track,
 * texture and runaway-gate rule (st_params; gate_cap NULL: the default) and
 * the seed. 0, or -1 with a message on stderr. */
struct st_gate_cap;
int sim_brekke_model(const char *exp, struct st_model *m, const struct st_amp *amp, double cell_m2, long scans,
                     int init, int texture, const struct st_gate_cap *gate_cap, uint64_t seed);

/* The assumptions that change the results, one option
 * each, the same name and meaning in every experiment, named in every CSV
 * header and plot title:
 *   --start two-point|steady   the single-target runs' initial track
 *                              covariance (enum st_init; --init twopoint,
 *                              the old spelling, is accepted)
 *   --gate-cap truncate:N|lost:L|count:M  the runaway-gate rule (struct st_gate_cap)
 *   --mre-start two-point|zero|steady  the MRE's start (enum toc_start) */
#define SIM_START_HELP                                                                      \
    "initial track covariance P0 (the estimate drawn from N(truth, P0)):\n"                 \
    "two-point differencing, or the clutter-free Kalman steady state"
#define SIM_OPT_START(dst_) \
    SIM_OPT_CUSTOM("--start", dst_, sim_parse_start, "two-point|steady", "two-point", SIM_START_HELP)
#define SIM_GATE_CAP_HELP                                                                   \
    "runaway gate: truncate:N passes the N nearest (d2) of a gate holding\n"                \
    "more (N <= TRK_MAX_DETECTIONS); lost:L declares the track lost when\n"                 \
    "lambda V_G exceeds L; count:M declares it lost when its gate holds M\n"                \
    "or more detections (HYCA's lost state)"
#define SIM_OPT_GATE_CAP(dst_) \
    SIM_OPT_CUSTOM("--gate-cap", dst_, sim_parse_gate_cap, "truncate:N|lost:L|count:M", sim_gate_cap_default, \
                   SIM_GATE_CAP_HELP)
#define SIM_MRE_START_HELP                                                                  \
    "the MRE's start at every P_FA: two-point differencing (a new track),\n"                \
    "P = 0, or the clutter-free Kalman steady state"
#define SIM_OPT_MRE_START(dst_) \
    SIM_OPT_CHOICE("--mre-start", dst_, "two-point|zero|steady", sim_mre_start_values, "two-point", SIM_MRE_START_HELP)
extern const char sim_gate_cap_default[];  /* "truncate:<TRK_MAX_DETECTIONS>" */
extern const int sim_mre_start_values[3];
int sim_parse_start(const char *v, void *dst);     /* int *: enum st_init */
int sim_parse_gate_cap(const char *v, void *dst);  /* struct st_gate_cap * */
const char *sim_start_name(int init);              /* "two-point", "steady" */
/* "truncate:256", "lost:50" or "count:10" into buf[n]; returns buf. */
char *sim_gate_cap_name(const struct st_gate_cap *g, char *buf, size_t n);
/* The CSV header line "# assumptions: start S (--start), gate cap G
 * (--gate-cap: ...)[, MRE start M (--mre-start)]" (mre_start < 0: none). */
void sim_assumptions_csv(FILE *f, int init, const struct st_gate_cap *g, int mre_start);
/* The same for a plot title: "start S, gate cap G[, MRE start M]". */
char *sim_assumptions_title(char *buf, size_t n, int init, const struct st_gate_cap *g, int mre_start);

/* Every run (model k < n_models, run < runs) as a work unit
 * (sim_run_units): st_run with each filter ai < n_filters (0 PDAF, 1
 * PDAFAI), errors summed over scans >= from; keep(slot, ai, result) stores
 * what the experiment needs in the run's own slot, slot = out + (k * runs +
 * run) * slot_size. Progress bar `label` unless --quiet. Returns the wall
 * time; *failed = 1 when st_run refused a call or the distribution failed
 * (with a message). */
double sim_st_runs(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                   long runs, int n_filters, long from,
                   void (*keep)(void *slot, int ai, const struct st_result *res), void *out, size_t slot_size,
                   int *failed);

/* The same with the position error of every scan: keep(ctx, slot, model,
 * ai, result, err_by_scan), model the run's model index, err_by_scan[k - 1]
 * the error at scan k = 1 .. n_scans of the model (NAN after the run
 * stopped; st_run). */
double sim_st_runs_err(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                       long runs, int n_filters, long from,
                       void (*keep)(void *ctx, void *slot, long model, int ai, const struct st_result *res,
                                    const double *err_by_scan),
                       void *ctx, void *out, size_t slot_size, int *failed);

/* The MRE's TOC (tools/sim/toc_curve.h) of Brekke's Table I model in K clutter of
 * shape nu at snr_db and cell_m2 (toc_scenario_brekke), its P_FA range
 * widened to [pfa_min, pfa_max], the MRE start mre_start (enum toc_start);
 * q2 from the tables DIR/q2_pdaf_g6.tbl and DIR/q2_pdafai_k<nu>_g6.tbl of
 * `make tables` (tables not NULL; their bytes in bufs[0], bufs[1]: free
 * them after toc_free) or sampled here (q2_samples per stratum, 0: toc_curve.h's
 * default; c's seed, threads and work distribution). brekke-toc's and
 * brekke-errpdf's one MRE set-up. NULL after a message "EXP: ..." on
 * failure. */
struct toc;
struct toc *sim_brekke_toc(const char *exp, const struct sim_common *c, double nu, double snr_db, double cell_m2,
                           double pfa_min, double pfa_max, int mre_start, const char *tables, long q2_samples,
                           void *bufs[2]);

/* The K texture option of the Brekke experiments (enum st_texture). */
extern const int sim_texture_values[2];
#define SIM_TEXTURE_HELP                                                                    \
    "K texture drawn per detection (i.i.d. K amplitudes) or once\n"                         \
    "per scan (bursty clutter, see tools/sim/single_target.h)"
#define SIM_OPT_TEXTURE(dst_) \
    SIM_OPT_CHOICE("--texture", dst_, "cell|scan", sim_texture_values, "cell", SIM_TEXTURE_HELP)
/* The MRE's q2 source options of brekke-toc and brekke-errpdf (sim_brekke_toc). */
#define SIM_OPT_Q2_SAMPLES(dst_)                                                            \
    SIM_OPT_LONG("--q2-samples", dst_, "N", NULL, SIM_GE, 1000, 0,                          \
                 "importance samples per stratum of the MRE's q2 grids (default toc.h's)")
#define SIM_OPT_TABLES(dst_)                                                                \
    SIM_OPT_STRING("--tables", dst_, "DIR", NULL,                                           \
                   "the MRE's q2 from the tables of `make tables` (q2_pdaf_g6.tbl,\n"       \
                   "q2_pdafai_k<nu>_g6.tbl) instead of sampling them here")

/* A table file dir/file (`make tables`) loaded through the library into *t,
 * which views *buf (malloc'd: free it after the last use of *t). 0, or -1
 * with a message "EXP: path: status" on stderr. */
struct trk_table;
int sim_load_table(const char *exp, const char *dir, const char *file, struct trk_table *t, void **buf);

/* ---------------------------------------------------------------- output */

/* mkdir -p: path and every directory above it (those there already kept).
 * 0, or -1 (a part that is not a directory, a path too long). */
int sim_mkdir_p(const char *path);

/* Opens c->out + suffix (e.g. ".csv", "_front.csv") for writing with its
 * header line, through o (fileio.h: a temporary file renamed into place by
 * sim_csv_close, so a failed run never leaves a cut file); the name goes to
 * path[pathlen] when path is not NULL. NULL (and a message) on failure.
 * On an MPI rank other than 0 the writes go to /dev/null. */
FILE *sim_csv_open(const struct sim_common *c, struct fileio_out *o, const char *suffix, char *path,
                   size_t pathlen, const char *header);
/* Every write of o checked, flushed, closed and renamed into place: 0, or -1
 * with a message "trk-sim: PATH: write error: ..." on stderr (a full disk
 * must not leave cut CSVs and exit status 0). */
int sim_csv_close(struct fileio_out *o);
/* An error elsewhere: o's temporary file removed, its PATH untouched. */
void sim_csv_discard(struct fileio_out *o);

/* A growing text (gnuplot script bodies): sim_text_add appends printf-style.
 * On out of memory the text is left as it was and t->failed set. */
struct sim_text {
    char *s;
    size_t len, cap;
    int failed;
};
void sim_text_add(struct sim_text *t, const char *fmt, ...);
void sim_text_free(struct sim_text *t);

/* Unless --no-plot (or on an MPI rank other than 0): the gnuplot script
 * c->out + suffix + ".gp" with `body` (plot.h plot_gnuplot), and the PNG
 * when gnuplot is there. Returns plot_gnuplot's value (0 without plotting;
 * -1 on an I/O error). */
int sim_plot(const struct sim_common *c, const char *suffix, const char *body);
/* The same with the body formatted printf-style. */
int sim_plotf(const struct sim_common *c, const char *suffix, const char *fmt, ...);

#endif
