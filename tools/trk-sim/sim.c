/* sim.c - trk-sim plumbing: declarative options, progress, output (sim.h). */
#include "sim.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "cli.h"
#include "plot.h"
#include "single_target.h"
#include "trk/table_file.h"

/* ---------------------------------------------------------------- value parsers */

int sim_parse_long(const char *s, long *v)
{
    char *end;
    errno = 0;
    double d = strtod(s, &end); /* accepts 1e6 */
    /* (the range test keeps the conversion to long defined) */
    if (errno || end == s || *end || !(d >= -9.2e18 && d <= 9.2e18) || d != (double)(long)d) return -1;
    *v = (long)d;
    return 0;
}

int sim_parse_double(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return errno || end == s || *end ? -1 : 0;
}

int sim_parse_list(const char *s, double *v, int max)
{
    double a, b, st;
    char tail;
    if (sscanf(s, "%lf:%lf:%lf%c", &a, &b, &st, &tail) == 3) {
        if (!(st > 0) || b < a) return -1;
        int n = 0;
        for (double x = a; x <= b + 1e-9 * st; x = a + st * n) {
            if (n == max) return -1; /* more values than the list holds: refuse, never drop */
            v[n++] = x;
        }
        return n;
    }
    int n = 0;
    const char *p = s;
    while (*p) {
        char *end;
        if (n == max) return -1; /* more values than the list holds */
        v[n] = strtod(p, &end);
        if (end == p) return -1;
        n++;
        if (*end == ',') end++;
        else if (*end) return -1;
        p = end;
    }
    return n > 0 ? n : -1;
}

static int parse_seed(const char *s, void *dst)
{
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 0);
    if (errno || end == s || *end) return -1;
    *(uint64_t *)dst = (uint64_t)v;
    return 0;
}

/* ---------------------------------------------------------------- option table */

static int in_range(const struct sim_opt *o, double v)
{
    return (!(o->range & SIM_GE) || v >= o->lo) && (!(o->range & SIM_GT) || v > o->lo) &&
           (!(o->range & SIM_LE) || v <= o->hi) && (!(o->range & SIM_LT) || v < o->hi);
}

/* "in [lo, hi]", ">= lo", ... ("" without a range). */
static void range_text(const struct sim_opt *o, char *buf, size_t n)
{
    const unsigned lo = o->range & (SIM_GE | SIM_GT), hi = o->range & (SIM_LE | SIM_LT);
    if (lo && hi)
        snprintf(buf, n, " in %c%.15g, %.15g%c", lo == SIM_GE ? '[' : '(', o->lo, o->hi, hi == SIM_LE ? ']' : ')');
    else if (lo)
        snprintf(buf, n, " %s %.15g", lo == SIM_GE ? ">=" : ">", o->lo);
    else if (hi)
        snprintf(buf, n, " %s %.15g", hi == SIM_LE ? "<=" : "<", o->hi);
    else
        buf[0] = 0;
}

/* The k-th word of "a|b|c" matching s? */
static int choice_index(const char *words, const char *s)
{
    const size_t len = strlen(s);
    for (int k = 0; *words; k++) {
        const size_t w = strcspn(words, "|");
        if (w == len && strncmp(words, s, len) == 0) return k;
        words += w;
        if (*words == '|') words++;
    }
    return -1;
}

/* The value into o->dst: 0, or -1 (nothing stored for a scalar). */
static int set_value(const struct sim_opt *o, const char *v)
{
    switch (o->type) {
    case SIM_LONG: {
        long l;
        if (sim_parse_long(v, &l) || !in_range(o, (double)l)) return -1;
        *(long *)o->dst = l;
        return 0;
    }
    case SIM_DOUBLE: {
        double d;
        if (sim_parse_double(v, &d) || !in_range(o, d)) return -1;
        *(double *)o->dst = d;
        return 0;
    }
    case SIM_LIST: {
        double *x = o->dst;
        const int n = sim_parse_list(v, x, o->max);
        if (n < 1) return -1;
        for (int k = 0; k < n; k++)
            if (!in_range(o, x[k])) return -1;
        *o->n = n;
        return 0;
    }
    case SIM_CHOICE: {
        const int k = choice_index(o->arg, v);
        if (k < 0) return -1;
        *(int *)o->dst = o->values ? o->values[k] : k;
        return 0;
    }
    case SIM_STRING: *(const char **)o->dst = v; return 0;
    case SIM_CUSTOM: return o->parse(v, o->dst);
    case SIM_FLAG: break;
    }
    return -1;
}

static void bad_value(const char *exp, const struct sim_opt *o, const char *v)
{
    char what[160] = "see --help", r[96];
    range_text(o, r, sizeof r);
    switch (o->type) {
    case SIM_LONG: snprintf(what, sizeof what, "an integer%s", r); break;
    case SIM_DOUBLE: snprintf(what, sizeof what, "a number%s", r); break;
    case SIM_LIST:
        snprintf(what, sizeof what, "a list a,b,c or from:to:step%s%s",
                 r[0] ? ", each" : "", r);
        break;
    case SIM_CHOICE: snprintf(what, sizeof what, "one of %s", o->arg); break;
    default: break;
    }
    fprintf(stderr, "%s: bad value for %s: '%s' (%s)\n", exp, o->name, v, what);
}

/* One option's lines of --help: name and value, the help text, the default
 * (on a line of its own when the last one is long). */
static void help_line(FILE *f, const struct sim_opt *o, const char *out_arg)
{
    char left[96];
    const char *arg = o->type == SIM_FLAG ? NULL : o->arg;
    if (strcmp(o->name, "--out") == 0) arg = out_arg;
    snprintf(left, sizeof left, "%s%s%s", o->name, arg ? " " : "", arg ? arg : "");
    int col = strlen(left) < 20 ? fprintf(f, "  %-19s ", left) : fprintf(f, "  %s  ", left);
    for (const char *h = o->help ? o->help : "";;) {
        const size_t len = strcspn(h, "\n");
        col += fprintf(f, "%.*s", (int)len, h);
        h += len;
        if (!*h) break;
        col = fprintf(f, "\n  %-19s ", "") - 1;
        h++;
    }
    if (o->def) {
        if (col + 11 + (int)strlen(o->def) > 100) fprintf(f, "\n  %-19s (default %s)\n", "", o->def);
        else fprintf(f, " (default %s)\n", o->def);
    } else {
        fputc('\n', f);
    }
}

static const struct sim_opt *find(const struct sim_opt *t, const char *name)
{
    for (; t && t->name; t++)
        if (strcmp(t->name, name) == 0) return t;
    return NULL;
}

enum { C_SEED, C_RUNS, C_OUT, C_THREADS, C_QUIET, C_NO_PLOT, C_N };

/* The common options over *com (and *threads: --threads is parsed as a long). */
static void common_table(struct sim_opt t[C_N + 1], struct sim_common *com, long *threads, const char *def_out)
{
    const struct sim_opt c[C_N + 1] = {
        SIM_OPT_CUSTOM("--seed", &com->seed, parse_seed, "N", "1",
                       "random seed; run i draws from the stream (seed, i)"),
        SIM_OPT_LONG("--runs", &com->runs, "N", NULL, SIM_GE, 1, 0, "Monte Carlo runs"),
        SIM_OPT_STRING("--out", &com->out, "PREFIX", def_out, "prefix of the output files"),
        SIM_OPT_LONG("--threads", threads, "N", NULL, SIM_IN, 1, 1024,
                     "OpenMP threads (default: all cores; the results do not depend on it)"),
        SIM_OPT_FLAG("--quiet", &com->quiet, "no progress on stderr"),
        SIM_OPT_FLAG("--no-plot", &com->no_plot, "CSV only: no gnuplot script or PNG"),
        SIM_OPT_END};
    memcpy(t, c, sizeof c);
}

void sim_common_usage(FILE *f)
{
    struct sim_common com;
    long threads;
    struct sim_opt t[C_N + 1];
    common_table(t, &com, &threads, NULL);
    for (int k = 0; k < C_N; k++) help_line(f, &t[k], "PREFIX");
}

static void usage(const struct sim_cli *cli, const struct sim_opt *common)
{
    printf("usage: trk-sim %s %s\n", cli->name, cli->usage ? cli->usage : "[options]");
    if (cli->about) printf("%s\n", cli->about);
    printf("options:\n");
    int lists = 0;
    for (const struct sim_opt *o = cli->opts; o && o->name; o++) {
        help_line(stdout, o, NULL);
        lists |= o->type == SIM_LIST;
    }
    if (lists) printf("  (LIST: values a,b,c or a range from:to:step)\n");
    printf("common options:\n");
    for (int k = 0; k < C_N; k++) {
        if ((k == C_RUNS && (cli->unused & SIM_UNUSED_RUNS)) ||
            (k == C_THREADS && (cli->unused & SIM_UNUSED_THREADS)) || find(cli->opts, common[k].name))
            continue;
        help_line(stdout, &common[k], cli->out_arg ? cli->out_arg : "PREFIX");
    }
    if (cli->files) printf("%s\n", cli->files);
}

int sim_parse(const struct sim_cli *cli, struct sim_common *com, int argc, char **argv)
{
    long threads = 0;
    struct sim_opt common[C_N + 1];
    memset(com, 0, sizeof *com);
    common_table(common, com, &threads, cli->out);
    const struct sim_opt *tables[2] = {cli->opts, common};
    for (int t = 0; t < 2; t++)
        for (const struct sim_opt *o = tables[t]; o && o->name; o++)
            if (o->def && set_value(o, o->def) != 0) {
                fprintf(stderr, "%s: internal error: bad default '%s' of %s\n", cli->name, o->def, o->name);
                return 1;
            }
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(cli, common);
            return 0;
        }
        const struct sim_opt *hit = NULL;
        const char *v = NULL;
        for (int t = 0; t < 2 && !hit; t++)
            for (const struct sim_opt *o = tables[t]; o && o->name && !hit; o++) {
                if (o->type == SIM_FLAG) {
                    if (strcmp(a, o->name) == 0) hit = o;
                    continue;
                }
                const int r = cli_opt(argc, argv, &i, o->name, &v, cli->name);
                if (r < 0) return 2;
                if (r > 0) hit = o;
            }
        if (!hit) {
            if (cli->operand && cli->operand(a, cli->operand_ctx) == 0) continue;
            fprintf(stderr, "%s: unknown option %s (see --help)\n", cli->name, a);
            return 2;
        }
        if (hit->type == SIM_FLAG) {
            *(int *)hit->dst = 1;
        } else if (set_value(hit, v) != 0) {
            bad_value(cli->name, hit, v);
            return 2;
        }
    }
    com->threads = (int)threads;
    return SIM_RUN;
}

/* ---------------------------------------------------------------- runs */

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

void sim_progress_step(struct sim_progress *p, long *pending)
{
    if (++*pending == 64) {
        sim_progress_add(p, *pending);
        *pending = 0;
    }
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
        fprintf(stderr, "%s: %s\n", exp, msg);
        return -1;
    }
    return 0;
}

int sim_brekke_model(const char *exp, struct st_model *m, const struct st_amp *amp, double cell_m2, long scans,
                     int init, int texture, uint64_t seed)
{
    struct st_params sp;
    st_params_brekke(&sp);
    sp.n_scans = scans;
    sp.init = init;
    sp.texture = texture;
    sp.amp = &amp->m;
    sp.lambda_per_m2 = amp->pfa / cell_m2;
    sp.seed = seed;
    char e[256];
    if (st_model_init(m, &sp, e, sizeof e)) {
        fprintf(stderr, "%s: %s\n", exp, e);
        return -1;
    }
    return 0;
}

double sim_st_runs(const struct sim_common *c, const char *label, const struct st_model *mod, long n_models,
                   long runs, int n_filters, long from,
                   void (*keep)(void *ctx, long it, int ai, const struct st_result *res), void *ctx, int *failed)
{
    struct sim_progress pr;
    int bad = 0;
    sim_progress_start(&pr, c, label, n_models * runs);
#pragma omp parallel
    {
        struct st_ws ws = {NULL, 0, NULL, 0};
        long pending = 0;
#pragma omp for schedule(dynamic, 8)
        for (long it = 0; it < n_models * runs; it++) {
            const long k = it / runs, run = it % runs;
            for (int ai = 0; ai < n_filters; ai++) {
                struct st_result res;
                if (st_run(&mod[k], &ws, (uint32_t)run, ai, from, NULL, &res) != 0) {
#pragma omp atomic write
                    bad = 1;
                } else {
                    keep(ctx, it, ai, &res);
                }
            }
            sim_progress_step(&pr, &pending);
        }
        sim_progress_add(&pr, pending);
        st_ws_free(&ws);
    }
    *failed = bad;
    return sim_progress_end(&pr);
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
        fprintf(stderr, "%s: %s: %s\n", exp, path, trk_status_str(st));
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- output */

FILE *sim_csv_open(const struct sim_common *c, const char *suffix, char *path, size_t pathlen,
                   const char *header)
{
    char buf[1024];
    if (!path) path = buf, pathlen = sizeof buf;
    snprintf(path, pathlen, "%s%s", c->out, suffix);
    return plot_csv_open(path, header);
}

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
    if (c->no_plot) return 0;
    if (!body) return -1;
    char base[1024];
    snprintf(base, sizeof base, "%s%s", c->out, suffix);
    return plot_gnuplot(base, body);
}

int sim_plotf(const struct sim_common *c, const char *suffix, const char *fmt, ...)
{
    if (c->no_plot) return 0;
    struct sim_text t = {NULL, 0, 0, 0};
    va_list ap;
    va_start(ap, fmt);
    text_vadd(&t, fmt, ap);
    va_end(ap);
    const int rc = t.failed ? -1 : sim_plot(c, suffix, t.s);
    sim_text_free(&t);
    return rc;
}
