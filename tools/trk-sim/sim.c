/* sim.c - trk-sim plumbing: declarative options, progress, output (sim.h). */
#include "errmsg.h"
#include "sim.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "fileio.h"
#include "par.h"
#include "plot.h"
#include "single_target.h"
#include "toc_curve.h"
#include "trk/table_file.h"

/* ---------------------------------------------------------------- directories */

int sim_mkdir_p(const char *path)
{
    char buf[1024];
    const size_t n = strlen(path);
    if (n == 0 || n >= sizeof buf) return -1;
    memcpy(buf, path, n + 1);
    for (size_t i = 1; i <= n; i++)
        if (buf[i] == '/' || buf[i] == 0) {
            const char c = buf[i];
            buf[i] = 0;
            struct stat st;
            if (mkdir(buf, 0777) != 0 && (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode))) return -1;
            buf[i] = c;
        }
    return 0;
}

/* ---------------------------------------------------------------- options */

static int parse_seed(const char *s, void *dst)
{
    char *end;
    if (!*s || strpbrk(s, " \t\n\r\v\f")) return -1; /* no blanks, as every number */
    errno = 0;
    unsigned long long v = strtoull(s, &end, 0);
    if (errno || end == s || *end) return -1;
    *(uint64_t *)dst = (uint64_t)v;
    return 0;
}

#ifdef TRK_TOOL_MPI
enum { C_SEED, C_RUNS, C_OUT, C_THREADS, C_QUIET, C_NO_PLOT, C_CKPT, C_CKPT_S, C_N };
#else
enum { C_SEED, C_RUNS, C_OUT, C_THREADS, C_QUIET, C_NO_PLOT, C_N };
#endif

/* The common options over *com (and *threads: --threads is parsed as a long). */
static void common_table(struct cli_opt t[C_N + 1], struct sim_common *com, long *threads, const char *def_out,
                         const char *out_arg)
{
    const struct cli_opt c[C_N + 1] = {
        CLI_OPT_CUSTOM("--seed", &com->seed, parse_seed, "N", "1",
                       "random seed; run i draws from the stream (seed, i)"),
        CLI_OPT_LONG("--runs", &com->runs, "N", NULL, CLI_GE, 1, 0, "Monte Carlo runs"),
        CLI_OPT_STRING("--out", &com->out, out_arg ? out_arg : "PREFIX", def_out,
                       out_arg && strcmp(out_arg, "DIR") == 0 ? "directory of the output files"
                                                              : "prefix of the output files"),
        CLI_OPT_LONG("--threads", threads, "N", NULL, CLI_IN, 1, 1024,
                     "OpenMP threads (default: all cores; the results do not depend on it)"),
        CLI_OPT_FLAG("--quiet", &com->quiet, "no progress on stderr"),
        CLI_OPT_FLAG("--no-plot", &com->no_plot, "CSV only: no gnuplot script or PNG"),
#ifdef TRK_TOOL_MPI
        CLI_OPT_STRING("--checkpoint", &com->checkpoint, "FILE", NULL,
                       "trk-sim-mpi: write the finished runs to FILE as they finish; a run\n"
                       "with the same arguments resumes from it (the same bytes); removed\n"
                       "once the output is written"),
        CLI_OPT_DOUBLE("--checkpoint-interval", &com->checkpoint_s, "S", "5", CLI_GE, 0, 1e6,
                       PAR_CHECKPOINT_INTERVAL_HELP),
#endif
        CLI_OPT_END};
    memcpy(t, c, sizeof c);
}

void sim_common_usage(FILE *f)
{
    struct sim_common com;
    long threads;
    struct cli_opt t[C_N + 1];
    common_table(t, &com, &threads, NULL, NULL);
    cli_print_options(f, t, NULL);
}

/* sim_cli's operand (0: taken) as a cli operand hook (1: one argument taken). */
struct operand_adapter {
    const struct sim_cli *cli;
};

static int take_operand(void *ctx, const char *arg, const char *next, char *err, size_t errlen)
{
    const struct operand_adapter *ad = ctx;
    (void)next, (void)err, (void)errlen;
    return ad->cli->operand(arg, ad->cli->operand_ctx) == 0 ? 1 : 0;
}

int sim_parse_more(const struct sim_cli *cli, void (*more_help)(FILE *f), struct sim_common *com, int argc,
                   char **argv)
{
    long threads = 0;
    struct cli_opt common[C_N + 1];
    char prog[128], usage[256];
    memset(com, 0, sizeof *com);
    common_table(common, com, &threads, cli->out, cli->out_arg);
    if (cli->unused & SIM_UNUSED_RUNS) common[C_RUNS].flags |= CLI_HIDDEN;
    if (cli->unused & SIM_UNUSED_THREADS) common[C_THREADS].flags |= CLI_HIDDEN;
    snprintf(prog, sizeof prog, "trk-sim %s", cli->name);
    snprintf(usage, sizeof usage, "%s", cli->usage ? cli->usage : "[options]");
    struct operand_adapter ad = {cli};
    struct cli c;
    memset(&c, 0, sizeof c);
    c.prog = prog;
    c.usage = usage;
    c.about = cli->about;
    c.opts = cli->opts;
    c.common = common;
    c.after = cli->files;
    c.more_help = more_help;
    c.operand = cli->operand ? take_operand : NULL;
    c.ctx = &ad;
    const int rc = cli_parse(&c, argc, argv);
    com->threads = (int)threads;
    com->par = sim_par();
    if (!par_is_root(com->par)) com->quiet = 1; /* rank 0 reports for every rank */
    if (rc != CLI_RUN || !com->checkpoint || !com->par) return rc;
    const int crc = par_checkpoint_cli(com->par, prog, com->checkpoint, com->checkpoint_s, argc, argv);
    return crc ? crc : rc;
}

int sim_parse(const struct sim_cli *cli, struct sim_common *com, int argc, char **argv)
{
    return sim_parse_more(cli, NULL, com, argc, argv);
}

/* ---------------------------------------------------------------- runs */

static void units_done(void *ctx, size_t first, size_t count)
{
    (void)first;
    sim_progress_add(ctx, (long)count);
}

int sim_run_units(const struct sim_common *c, const char *label, size_t n, size_t size, size_t chunk,
                  int (*run)(void *ctx, size_t i, void *res, void **ws), void (*ws_free)(void *ctx, void *ws),
                  void *ctx, void *out, double *wall, size_t *failed_unit)
{
    struct sim_progress pr;
    sim_progress_start(&pr, c, label, (long)n);
    struct par_batch b;
    par_batch_init(&b, n, size, chunk, run, ctx);
    b.threads = c->threads;
    b.ws_free = ws_free;
    b.done = units_done;
    b.done_ctx = &pr;
    char err[1600];
    const int rc = par_run(c->par, &b, out, err, sizeof err);
    *wall = sim_progress_end(&pr);
    if (rc == PAR_OK) return 0;
    if (rc == PAR_E_UNIT) {
        if (failed_unit) *failed_unit = b.failed_unit;
        return 1;
    }
    fprintf(stderr, "trk-sim %s: %s\n", label, err);
    return -1;
}

int sim_threads(const struct sim_common *c)
{
#ifdef _OPENMP
    if (c->threads > 0) omp_set_num_threads(c->threads);
    return omp_get_max_threads();
#else
    (void)c;
    return 1;
#endif
}

void sim_progress_start(struct sim_progress *p, const struct sim_common *c, const char *label, long total)
{
    progress_start(&p->bar, label, total, !c->quiet);
    p->t0 = progress_now_s();
}

void sim_progress_add(struct sim_progress *p, long n)
{
#pragma omp critical(sim_progress)
    progress_add(&p->bar, n);
}

double sim_progress_end(struct sim_progress *p)
{
    progress_end(&p->bar);
    return progress_now_s() - p->t0;
}

/* ---------------------------------------------------------------- single-target runs */

int sim_amp_k_grid(const char *exp, struct st_amp *amp, const double *nu, int n_nu, const double *snr_db,
                   int n_snr, const double *pfa, int n_pfa, int grid, unsigned size)
{
    const int n = n_nu * n_snr * n_pfa;
    int first_bad = n;
    char msg[256] = "";
#pragma omp parallel for schedule(dynamic, 1)
    for (int i = 0; i < n; i++) {
        const int a = i / (n_snr * n_pfa), b = (i / n_pfa) % n_snr, c = i % n_pfa;
        char e[256];
        if (st_amp_init(&amp[i], TRK_AMP_K, nu[a], snr_db[b], pfa[c], grid, size, e, sizeof e)) {
#pragma omp critical(sim_amp_err)
            if (i < first_bad) {
                first_bad = i;
                snprintf(msg, sizeof msg, "%s", e);
            }
        }
    }
    if (first_bad < n) {
        fprintf(stderr, "trk-sim %s: %s\n", exp, msg);
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- assumptions */

#define SIM_STR_(x) #x
#define SIM_STR(x) SIM_STR_(x)
const char sim_gate_cap_default[] = "truncate:" SIM_STR(TRK_MAX_DETECTIONS);
const int sim_mre_start_values[3] = {TOC_START_TWOPOINT, TOC_START_ZERO, TOC_START_STEADY};
const int sim_texture_values[2] = {ST_TEXTURE_CELL, ST_TEXTURE_SCAN};

int sim_parse_start(const char *v, void *dst)
{
    /* "twopoint": the spelling of --init, accepted */
    if (strcmp(v, "two-point") == 0 || strcmp(v, "twopoint") == 0) *(int *)dst = ST_INIT_TWOPOINT;
    else if (strcmp(v, "steady") == 0) *(int *)dst = ST_INIT_STEADY;
    else return -1;
    return 0;
}

int sim_parse_gate_cap(const char *v, void *dst)
{
    struct st_gate_cap *g = dst;
    if (strncmp(v, "truncate:", 9) == 0) {
        long n;
        if (cli_parse_long(v + 9, &n) != 0 || n < 1 || n > TRK_MAX_DETECTIONS) return -1;
        *g = (struct st_gate_cap){ST_GATE_TRUNCATE, n, 0};
        return 0;
    }
    if (strncmp(v, "count:", 6) == 0) {
        long n;
        if (cli_parse_long(v + 6, &n) != 0 || n < 1 || n > TRK_MAX_DETECTIONS) return -1;
        *g = (struct st_gate_cap){ST_GATE_COUNT, n, 0};
        return 0;
    }
    if (strncmp(v, "lost:", 5) == 0) {
        double l;
        if (cli_parse_double(v + 5, &l) != 0 || !(l > 0 && l < INFINITY)) return -1;
        *g = (struct st_gate_cap){ST_GATE_LOST, 0, l};
        return 0;
    }
    return -1;
}

const char *sim_start_name(int init) { return init == ST_INIT_STEADY ? "steady" : "two-point"; }

char *sim_gate_cap_name(const struct st_gate_cap *g, char *buf, size_t n)
{
    if (g->mode == ST_GATE_LOST) snprintf(buf, n, "lost:%g", g->lambda_vg);
    else if (g->mode == ST_GATE_COUNT) snprintf(buf, n, "count:%ld", g->n);
    else snprintf(buf, n, "truncate:%ld", g->n > 0 ? g->n : (long)TRK_MAX_DETECTIONS);
    return buf;
}

void sim_assumptions_csv(FILE *f, int init, const struct st_gate_cap *g, int mre_start)
{
    char gc[64];
    fprintf(f, "# assumptions: start %s (--start: initial covariance %s), gate cap %s (--gate-cap: %s)",
            sim_start_name(init),
            init == ST_INIT_STEADY ? "the clutter-free Kalman steady state" : "by two-point differencing",
            sim_gate_cap_name(g, gc, sizeof gc),
            g->mode == ST_GATE_LOST    ? "the track is lost when lambda V_G exceeds the cap"
            : g->mode == ST_GATE_COUNT ? "the track is lost when its gate holds that many detections"
                                       : "a gate holding more passes its nearest by d2");
    if (mre_start >= 0) fprintf(f, ", MRE start %s (--mre-start)", toc_start_name(mre_start));
    fprintf(f, "\n");
}

char *sim_assumptions_title(char *buf, size_t n, int init, const struct st_gate_cap *g, int mre_start)
{
    char gc[64];
    const int k = snprintf(buf, n, "start %s, gate cap %s", sim_start_name(init), sim_gate_cap_name(g, gc, sizeof gc));
    if (mre_start >= 0 && k >= 0 && (size_t)k < n)
        snprintf(buf + k, n - (size_t)k, ", MRE start %s", toc_start_name(mre_start));
    return buf;
}

int sim_brekke_model(const char *exp, struct st_model *m, const struct st_amp *amp, double cell_m2, long scans,
                     int init, int texture, const struct st_gate_cap *gate_cap, uint64_t seed)
{
    struct st_params sp;
    st_params_brekke(&sp);
    sp.n_scans = scans;
    sp.init = init;
    sp.texture = texture;
    if (gate_cap) sp.gate_cap = *gate_cap;
    sp.amp = &amp->m;
    sp.lambda_per_m2 = amp->pfa / cell_m2;
    sp.seed = seed;
    char e[256];
    if (st_model_init(m, &sp, e, sizeof e)) {
        fprintf(stderr, "trk-sim %s: %s\n", exp, e);
        return -1;
    }
    return 0;
}

struct toc *sim_brekke_toc(const char *exp, const struct sim_common *c, double nu, double snr_db, double cell_m2,
                           double pfa_min, double pfa_max, int mre_start, const char *tables, long q2_samples,
                           void *bufs[2])
{
    struct toc_scenario ts;
    toc_scenario_brekke(&ts, TRK_AMP_K, nu, snr_db, cell_m2);
    ts.mre_start = mre_start;
    ts.pfa_min = fmin(ts.pfa_min, pfa_min);
    ts.pfa_max = fmax(ts.pfa_max, pfa_max);
    struct toc_q2_source src;
    memset(&src, 0, sizeof src);
    struct trk_table tb[2];
    bufs[0] = bufs[1] = NULL;
    if (tables) {
        char name[64];
        snprintf(name, sizeof name, "q2_pdafai_k%g_g6.tbl", nu);
        if (sim_load_table(exp, tables, "q2_pdaf_g6.tbl", &tb[0], &bufs[0]) ||
            sim_load_table(exp, tables, name, &tb[1], &bufs[1]))
            return NULL;
        src.pdaf = &tb[0];
        src.pdafai = &tb[1];
    }
    src.samples = (uint64_t)q2_samples;
    src.seed = c->seed;
    src.threads = c->threads;
    src.quiet = c->quiet;
    src.par = c->par;
    char err[512];
    struct toc *t = toc_new(&ts, &src, err, sizeof err);
    if (!t) fprintf(stderr, "trk-sim %s: MRE (nu %g): %s\n", exp, nu, err);
    return t;
}

struct st_units {
    const struct st_model *mod;
    long runs, from;
    int n_filters;
    void (*keep)(void *slot, int ai, const struct st_result *res);
    /* or, with the errors of every scan (sim_st_runs_err) */
    void (*keep_err)(void *ctx, void *slot, long model, int ai, const struct st_result *res,
                     const double *err_by_scan);
    void *ctx;
};

/* a thread's workspace: st_run's, and the per-scan errors for keep_err */
struct st_unit_ws {
    struct st_ws w;
    double *err;
    size_t err_cap;
};

/* unit it: model it / runs, run it % runs, every filter */
static int st_unit(void *ctx, size_t it, void *slot, void **ws)
{
    const struct st_units *u = ctx;
    struct st_unit_ws *w = *ws;
    if (!w) {
        if (!(w = malloc(sizeof *w))) return 1;
        *w = (struct st_unit_ws){{NULL, 0, NULL, 0}, NULL, 0};
        *ws = w;
    }
    const long k = (long)it / u->runs, run = (long)it % u->runs;
    const size_t n_scans = (size_t)u->mod[k].p.n_scans;
    if (u->keep_err && w->err_cap < n_scans) {
        double *e = realloc(w->err, n_scans * sizeof *e);
        if (!e) return 1;
        w->err = e;
        w->err_cap = n_scans;
    }
    int bad = 0;
    for (int ai = 0; ai < u->n_filters; ai++) {
        struct st_result res;
        if (st_run(&u->mod[k], &w->w, (uint32_t)run, ai, u->from, u->keep_err ? w->err : NULL, &res) != 0)
            bad = 1;
        else if (u->keep_err)
            u->keep_err(u->ctx, slot, k, ai, &res, w->err);
        else
            u->keep(slot, ai, &res);
    }
    return bad;
}

static void st_ws_release(void *ctx, void *ws)
{
    (void)ctx;
    struct st_unit_ws *w = ws;
    if (!w) return;
    st_ws_free(&w->w);
    free(w->err);
    free(w);
}

static double st_runs(const struct sim_common *c, const char *label, const struct st_units *u, long n_models,
                      void *out, size_t slot_size, int *failed)
{
    double wall = 0;
    *failed = sim_run_units(c, label, (size_t)(n_models * u->runs), slot_size, 8, st_unit, st_ws_release,
                            (void *)u, out, &wall, NULL) != 0;
    return wall;
}

double sim_st_runs(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                   long runs, int n_filters, long from,
                   void (*keep)(void *slot, int ai, const struct st_result *res), void *out, size_t slot_size,
                   int *failed)
{
    const struct st_units u = {mod, runs, from, n_filters, keep, NULL, NULL};
    return st_runs(c, label, &u, n_models, out, slot_size, failed);
}

double sim_st_runs_err(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                       long runs, int n_filters, long from,
                       void (*keep)(void *ctx, void *slot, long model, int ai, const struct st_result *res,
                                    const double *err_by_scan),
                       void *ctx, void *out, size_t slot_size, int *failed)
{
    const struct st_units u = {mod, runs, from, n_filters, NULL, keep, ctx};
    return st_runs(c, label, &u, n_models, out, slot_size, failed);
}

int sim_load_table(const char *exp, const char *dir, const char *file, struct trk_table *t, void **buf)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    size_t n;
    trk_status st = trk_table_file_size(path, &n);
    if (st == TRK_OK) {
        *buf = malloc(n + 8);
        if (!*buf) return -1;
        st = trk_table_load_file(path, *buf, n + 8, t, NULL);
    }
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim %s: %s: %s\n", exp, path, ERRMSG_STATUS(st));
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- output */

FILE *sim_csv_open(const struct sim_common *c, struct fileio_out *o, const char *suffix, char *path,
                   size_t pathlen, const char *header)
{
    char buf[1024];
    if (!path) path = buf, pathlen = sizeof buf;
    if (snprintf(path, pathlen, "%s%s", c->out, suffix) >= (int)pathlen) {
        fprintf(stderr, "trk-sim: %s%s: path too long\n", c->out, suffix);
        return NULL;
    }
    /* rank 0 writes the files (the other ranks' output is the same) */
    FILE *f = fileio_create(o, par_is_root(c->par) ? path : "/dev/null", 0);
    if (!f) {
        fprintf(stderr, "trk-sim: cannot write %s: %s\n", path, strerror(errno));
        return NULL;
    }
    if (header) fprintf(f, "%s\n", header);
    return f;
}

int sim_csv_close(struct fileio_out *o)
{
    if (fileio_commit(o) == 0) return 0;
    fprintf(stderr, "trk-sim: %s: write error: %s\n", o->path, strerror(errno));
    return -1;
}

void sim_csv_discard(struct fileio_out *o) { fileio_discard(o); }

static void text_vadd(struct sim_text *t, const char *fmt, va_list ap)
{
    va_list aq;
    va_copy(aq, ap);
    const int n = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    if (n < 0 || t->failed) {
        t->failed = 1;
        return;
    }
    if (t->len + (size_t)n + 1 > t->cap) {
        size_t cap = t->cap ? t->cap : 4096;
        while (cap < t->len + (size_t)n + 1) cap *= 2;
        char *s = realloc(t->s, cap);
        if (!s) {
            t->failed = 1;
            return;
        }
        t->s = s;
        t->cap = cap;
    }
    vsnprintf(t->s + t->len, t->cap - t->len, fmt, ap);
    t->len += (size_t)n;
}

void sim_text_add(struct sim_text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    text_vadd(t, fmt, ap);
    va_end(ap);
}

void sim_text_free(struct sim_text *t)
{
    free(t->s);
    memset(t, 0, sizeof *t);
}

int sim_plot(const struct sim_common *c, const char *suffix, const char *body)
{
    if (c->no_plot || !par_is_root(c->par)) return 0;
    if (!body) return -1;
    char base[1024];
    snprintf(base, sizeof base, "%s%s", c->out, suffix);
    return plot_gnuplot("trk-sim", base, body);
}

int sim_plotf(const struct sim_common *c, const char *suffix, const char *fmt, ...)
{
    if (c->no_plot || !par_is_root(c->par)) return 0;
    struct sim_text t = {NULL, 0, 0, 0};
    va_list ap;
    va_start(ap, fmt);
    text_vadd(&t, fmt, ap);
    va_end(ap);
    const int rc = t.failed ? -1 : sim_plot(c, suffix, t.s);
    sim_text_free(&t);
    return rc;
}
