/* q2_table.c - q2 tables by importance sampling (q2_table.h). */
#include "q2_table.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "par.h"
#include "q2_amp.h"
#include "progress.h"
#include "q2_is.h"
#include "table_writer.h"
#include "trk/amplitude.h"
#include "trk/gate.h"
#include "trk/q2.h"
#include "trk/special.h"

#ifdef _OPENMP
#include <omp.h>
#endif


/* ---- grid syntax ---- */

static int real_ok(const char *s, double *v)
{
    char *end;
    errno = 0;
    if (!s || !*s) return 0;
    *v = strtod(s, &end);
    return errno != ERANGE && !*end && isfinite(*v);
}

static int parse_count(const char *s, unsigned long *n)
{
    char *end;
    errno = 0;
    if (!s || !*s || *s == '-') return -1;
    *n = strtoul(s, &end, 10);
    return errno || *end || *n > Q2_TABLE_MAX_NODES ? -1 : 0;
}



/* LIST: values and ranges A:B:STEP, comma-separated, strictly increasing.
 * Returns the count or -1. */
int q2_table_parse_list(const char *s, double *v, int max)
{
    int n = 0;
    char buf[256];
    const char *p = s;
    while (*p) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == 0 || len >= sizeof buf) return -1;
        memcpy(buf, p, len);
        buf[len] = 0;
        char *c1 = strchr(buf, ':');
        if (!c1) {
            if (n >= max || !real_ok(buf, &v[n])) return -1;
            n++;
        } else {
            *c1 = 0;
            char *c2 = strchr(c1 + 1, ':');
            if (!c2) return -1;
            *c2 = 0;
            double a, b, st;
            if (!real_ok(buf, &a) || !real_ok(c1 + 1, &b) || !real_ok(c2 + 1, &st) || !(st > 0) || !(b >= a))
                return -1;
            const double cnt = floor((b - a) / st + 1e-9);
            if (cnt > max) return -1;
            for (long k = 0; k <= (long)cnt; k++) {
                if (n >= max) return -1;
                double x = a + st * (double)k;
                if (fabs(x - b) < 1e-9 * st) x = b;
                if (fabs(x) < 1e-12 * st) x = 0;
                v[n++] = x;
            }
        }
        p = e ? e + 1 : p + len;
        if (e && !*p) return -1;
    }
    for (int i = 1; i < n; i++)
        if (!(v[i] > v[i - 1])) return -1;
    return n;
}

/* LOG: A:B:N. */
int q2_table_parse_log(const char *s, struct q2_table_axis *a)
{
    char buf[256];
    if (strlen(s) >= sizeof buf) return -1;
    strcpy(buf, s);
    char *c1 = strchr(buf, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    if (!c1 || !c2) return -1;
    *c1 = *c2 = 0;
    unsigned long n = 0;
    if (!real_ok(buf, &a->lo) || !real_ok(c1 + 1, &a->hi) || parse_count(c2 + 1, &n) || n < 2)
        return -1;
    if (!(a->lo > 0) || !(a->hi > a->lo)) return -1;
    a->n = n;
    a->nodes = NULL;
    return 0;
}

/* A LIST axis: uniform lists become computed (linear) axes, others explicit. */
void q2_table_list_axis(const double *v, int n, struct q2_table_axis *a)
{
    a->n = (size_t)n;
    a->lo = v[0];
    a->hi = v[n - 1];
    a->nodes = NULL;
    if (n < 3) return;
    a->nodes = v;
    const double h = (v[n - 1] - v[0]) / (n - 1);
    for (int i = 0; i < n; i++)
        if (fabs(v[i] - (v[0] + h * i)) > 1e-12 * (fabs(v[0]) + fabs(v[n - 1]))) return;
    a->nodes = NULL;
}

double q2_table_node(const struct q2_table_axis *a, int log_axis, size_t i)
{
    if (a->nodes) return a->nodes[i];
    if (a->n == 1) return a->lo;
    if (i == a->n - 1) return a->hi;
    const double f = (double)i / (double)(a->n - 1);
    return log_axis ? a->lo * exp(f * log(a->hi / a->lo)) : a->lo + f * (a->hi - a->lo);
}

int q2_gate_gamma(int nz, double pg, double *gamma)
{
    if (nz < 1 || nz > 3 || !(pg > 0 && pg < 1)) return -1;
    if (nz == 2) {
        *gamma = -2 * log1p(-pg);
        return 0;
    }
    trk_real g;
    if (trk_gate_gamma(nz, (trk_real)pg, &g) != TRK_OK) return -1;
    *gamma = (double)g;
    return 0;
}

double q2_gate_prob(int nz, double gamma)
{
    if (nz == 2) return -expm1(-0.5 * gamma);
    return (double)trk_chi2_cdf(nz, (trk_real)gamma);
}

/* An axis: count, finite, strictly increasing nodes inside [min, max]
 * (min excluded when open_lo, max excluded when open_hi). */
static int check_axis(const struct q2_table_axis *a, const char *name, int log_axis, double min, double max,
                      int open_lo, int open_hi, size_t min_n, char *err, size_t n)
{
    if (a->n < min_n || a->n > Q2_TABLE_MAX_NODES) {
        snprintf(err, n, "%s axis: %zu nodes, must be %zu .. %u", name, a->n, min_n, Q2_TABLE_MAX_NODES);
        return -1;
    }
    if (!a->nodes) {
        if (!isfinite(a->lo) || !isfinite(a->hi)) return errmsg_fail(err, n, "%s axis: range is not finite", name);
        if (a->n > 1 && !(a->hi > a->lo)) return errmsg_fail(err, n, "%s axis: the range must increase", name);
        if (a->n == 1 && a->hi != a->lo) return errmsg_fail(err, n, "%s axis: one node needs lo = hi", name);
        if (log_axis && !(a->lo > 0)) return errmsg_fail(err, n, "%s axis: a log axis needs lo > 0", name);
    }
    double prev = 0;
    for (size_t i = 0; i < a->n; i++) {
        const double v = q2_table_node(a, log_axis, i);
        if (!isfinite(v)) return errmsg_fail(err, n, "%s axis: node not finite", name);
        if ((open_lo ? !(v > min) : !(v >= min)) || (open_hi ? !(v < max) : !(v <= max))) {
            snprintf(err, n, "%s axis: node %.10g outside %s%g, %g%s", name, v, open_lo ? "(" : "[", min, max,
                     open_hi ? ")" : "]");
            return -1;
        }
        if (i > 0 && !(v > prev)) return errmsg_fail(err, n, "%s axis: nodes must increase strictly", name);
        prev = v;
    }
    return 0;
}

struct tw_axes {
    struct tablew_axis ax[3];
    double *vals[3];
};

static int table_axis(const struct q2_table_axis *a, int log_axis, uint32_t var, struct tablew_axis *t)
{
    t->count = (uint32_t)a->n;
    t->variable = var;
    t->ratio = 0;
    t->lo = q2_table_node(a, log_axis, 0);
    t->hi = q2_table_node(a, log_axis, a->n - 1);
    t->values = NULL;
    if (log_axis) {
        if (a->nodes) return -1; /* log axes are computed, uniform in ln x */
        t->spacing = TRK_TABLE_SPACING_LOG;
    } else {
        t->spacing = a->nodes ? TRK_TABLE_SPACING_EXPLICIT : TRK_TABLE_SPACING_LINEAR;
        t->values = a->nodes;
    }
    return 0;
}

static int serialise(const struct q2_table_spec *s, const struct q2_table_run *r, const struct q2_table_result *res,
                     const double *data, unsigned char **bytes, size_t *len, char *err, size_t errlen)
{
    const int ai = s->detector == TRK_Q2_PDAFAI;
    const uint32_t kind = ai ? TRK_TABLE_KIND_Q2_PDAFAI : TRK_TABLE_KIND_Q2_PDAF;
    const uint32_t rs = s->real_size ? s->real_size : (uint32_t)sizeof(trk_real);
    struct tablew_axis ax[3];
    uint32_t naxes;
    int bad;
    if (ai) {
        naxes = 3;
        bad = table_axis(&s->snr_db, 0, TRK_TABLE_VAR_SNR_DB, &ax[0]) ||
              table_axis(&s->pfa, 1, TRK_TABLE_VAR_PFA, &ax[1]) ||
              table_axis(&s->lambda_vg, 1, TRK_TABLE_VAR_LAMBDA_VG, &ax[2]);
    } else {
        naxes = 2;
        bad = table_axis(&s->pd, 0, TRK_TABLE_VAR_PD, &ax[0]) ||
              table_axis(&s->lambda_vg, 1, TRK_TABLE_VAR_LAMBDA_VG, &ax[1]);
    }
    if (bad) return errmsg_fail(err, errlen, "pfa and lambda_vg axes must be log-spaced ranges");
    struct tablew *w = tablew_new(kind, TRK_Q2_TABLE_VERSION, rs);
    if (!w) return errmsg_fail(err, errlen, "out of memory");
    bad = tablew_param_int(w, "detector", s->detector) || tablew_param_int(w, "nz", s->nz) ||
          tablew_param_real(w, "gate_gamma", s->gate_gamma) ||
          tablew_param_real(w, "gate_prob", q2_gate_prob(s->nz, s->gate_gamma)) ||
          (ai && (tablew_param_int(w, "model", s->amp_model) ||
                  tablew_param_real(w, "nu", s->amp_model == TRK_AMP_K ? s->nu : 0) ||
                  (s->amp_model == TRK_AMP_K &&
                   tablew_param_int(w, "amp_size", s->amp_size ? s->amp_size : Q2_AMP_TABLE_SIZE)) ||
                  (res->amp_measured && (tablew_param_real(w, "amp_err_log_lr", res->amp_err_log_lr) ||
                                         tablew_param_real(w, "amp_err_inv_sf", res->amp_err_inv_sf))))) ||
          tablew_param_real(w, "max_se", res->max_se) || tablew_param_real(w, "mean_se", res->mean_se) ||
          tablew_param_int(w, "samples", (int64_t)r->samples) || tablew_param_real(w, "target_se", r->target_se) ||
          tablew_param_int(w, "seed", (int64_t)r->seed) ||
          tablew_param_real(w, "tail_mass", r->tail_mass > 0 ? r->tail_mass : 1e-12) ||
          tablew_param_int(w, "generator_version", Q2_TABLE_GENERATOR_VERSION) ||
          (res->interp_measured && (tablew_param_real(w, "interp_err_max", res->interp_max) ||
                                    tablew_param_real(w, "interp_err_rms", res->interp_rms))) ||
          tablew_section(w, TRK_Q2_SECTION_VALUES, naxes, ax, 2,
                         s->cubic ? TRK_TABLE_INTERP_CUBIC : TRK_TABLE_INTERP_LINEAR, data) ||
          tablew_finish(w, bytes, len);
    if (bad) snprintf(err, errlen, "table: %s", tablew_error(w));
    tablew_free(w);
    return bad ? -1 : 0;
}

/* A lookup over the values (trk_real copy in *vals, caller frees). */
static int make_lookup(const struct q2_table_spec *s, const double *data, size_t ncells, trk_real **vals,
                       trk_real **nodes, struct trk_q2_lookup *lk)
{
    const int ai = s->detector == TRK_Q2_PDAFAI;
    *vals = malloc(ncells * sizeof **vals);
    *nodes = malloc((s->pd.n + s->snr_db.n + 1) * sizeof **nodes);
    if (!*vals || !*nodes) return -1;
    for (size_t c = 0; c < ncells; c++) (*vals)[c] = (trk_real)data[2 * c];
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    g.detector = s->detector;
    g.values = *vals;
    const struct q2_table_axis *lin = ai ? &s->snr_db : &s->pd;
    struct trk_q2_axis *a0 = &g.axis[0];
    a0->count = lin->n;
    a0->interp = s->cubic ? TRK_Q2_CUBIC : TRK_Q2_LINEAR;
    if (lin->nodes) {
        for (size_t i = 0; i < lin->n; i++) (*nodes)[i] = (trk_real)lin->nodes[i];
        a0->nodes = *nodes;
    }
    a0->u_first = (trk_real)q2_table_node(lin, 0, 0);
    a0->u_last = (trk_real)q2_table_node(lin, 0, lin->n - 1);
    int k = 1;
    if (ai) {
        g.axis[1] = (struct trk_q2_axis){s->pfa.n, NULL, (trk_real)log(s->pfa.lo), (trk_real)log(s->pfa.hi), 1,
                                         a0->interp};
        k = 2;
    }
    g.axis[k] = (struct trk_q2_axis){s->lambda_vg.n, NULL, (trk_real)log(s->lambda_vg.lo),
                                     (trk_real)log(s->lambda_vg.hi), 1, a0->interp};
    return trk_q2_lookup_init(lk, &g) == TRK_OK ? 0 : -1;
}

/* The PDAFAI lines' amplitude models (nodes, then the test midpoints: snr
 * mid, pfa geometric mid) as work units of tools/par (on the threads, or
 * the ranks of an MPI job: r->par), one model per unit. A unit's result:
 * its status, its message, the packed model (q2_amp_pack) of at most cap
 * table bytes; every rank unpacks every model. */
#define AMP_SLOT_HEAD 264 /* int32 status, pad, char msg[256] */

struct amp_job {
    const struct q2_table_spec *s;
    size_t n0, n1, m1;
    size_t cap; /* table bytes of a model (that of model 0) */
};

static void amp_params(const struct amp_job *j, size_t k, double *snr, double *pfa)
{
    const struct q2_table_spec *s = j->s;
    if (k < j->n0 * j->n1) {
        *snr = q2_table_node(&s->snr_db, 0, k / j->n1);
        *pfa = q2_table_node(&s->pfa, 1, k % j->n1);
    } else {
        const size_t t = k - j->n0 * j->n1, i = t / j->m1, jj = t % j->m1;
        *snr = 0.5 * (q2_table_node(&s->snr_db, 0, i) + q2_table_node(&s->snr_db, 0, i + 1));
        *pfa = sqrt(q2_table_node(&s->pfa, 1, jj) * q2_table_node(&s->pfa, 1, jj + 1));
    }
}

static size_t amp_slot(const struct amp_job *j) { return AMP_SLOT_HEAD + q2_amp_packed_size(j->cap); }

static int amp_unit(void *ctx, size_t k, void *res, void **ws)
{
    const struct amp_job *j = ctx;
    const struct q2_table_spec *s = j->s;
    (void)ws;
    unsigned char *slot = res;
    char *msg = (char *)slot + 8;
    int32_t st = 0;
    double snr, pfa;
    amp_params(j, k, &snr, &pfa);
    struct q2_amp a;
    memset(slot, 0, AMP_SLOT_HEAD);
    if (q2_amp_init(&a, s->amp_model, s->nu, snr, pfa, s->amp_size, s->amp_measure, msg, 256) != 0) {
        st = 1;
    } else {
        if (q2_amp_table_len(&a) > j->cap) {
            snprintf(msg, 256, "amplitude model %zu: a table of %zu bytes, %zu expected", k, q2_amp_table_len(&a),
                     j->cap);
            st = 1;
        } else {
            q2_amp_pack(&a, slot + AMP_SLOT_HEAD);
        }
        q2_amp_free(&a);
    }
    memcpy(slot, &st, sizeof st);
    return 0; /* a refused model is the caller's message, in model order */
}

/* The message of model k's slot that says refused (status st != 0): its
 * reason as amp_unit wrote it, or, when the slot cannot be amp_unit's (a
 * status other than 1, no text, no NUL or a byte that is not printable
 * text: a slot resumed from a forged or damaged checkpoint), that. */
static void amp_slot_refusal(const unsigned char *slot, size_t k, int32_t st, char *err, size_t errlen)
{
    const char *msg = (const char *)slot + 8;
    const char *end = memchr(msg, 0, 256);
    int text = st == 1 && end && end > msg;
    for (const char *c = msg; text && c < end; c++) text = *c >= 0x20 && *c < 0x7f;
    if (text) snprintf(err, errlen, "%s", msg);
    else
        snprintf(err, errlen,
                 "amplitude model %zu: its result is damaged (refused, status %ld, without a reason: a forged or "
                 "damaged checkpoint?)",
                 k, (long)st);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int q2_table_build(const struct q2_table_spec *s, const struct q2_table_run *r, struct q2_table_result *res,
                   char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    if (err && errlen) err[0] = 0;
    if (!s || !r) return errmsg_fail(err, errlen, "no spec");
    const int ai = s->detector == TRK_Q2_PDAFAI;
    if (s->detector != TRK_Q2_PDAF && !ai) return errmsg_fail(err, errlen, "detector must be pdaf or pdafai");
    if (s->nz < 1 || s->nz > 3) return errmsg_fail(err, errlen, "nz must be 1, 2 or 3 (got %d)", s->nz);
    if (!(s->gate_gamma > 0 && s->gate_gamma <= 1000))
        return errmsg_fail(err, errlen, "gate gamma must be in (0, 1000] (got %g)", s->gate_gamma);
    const uint32_t rs = s->real_size ? s->real_size : (uint32_t)sizeof(trk_real);
    if (rs != 4 && rs != 8) return errmsg_fail(err, errlen, "real width must be 4 or 8 bytes");
    if (r->samples < 2 || r->samples > 0xffffffffu)
        return errmsg_fail(err, errlen, "samples must be in [2, 4294967295]");
    if (!(r->target_se >= 0 && r->target_se < 1))
        return errmsg_fail(err, errlen, "target se must be in [0, 1) (got %g)", r->target_se);
    /* axes: the container needs >= 2 nodes on every axis of a table */
    if (check_axis(&s->lambda_vg, "lambda_vg", 1, 0, Q2_IS_MAX_LAMBDA_VG, 1, 0, 2, err, errlen)) return -1;
    if (s->lambda_vg.nodes) return errmsg_fail(err, errlen, "the lambda_vg axis is a log-spaced range");
    if (ai) {
        if (s->amp_model != TRK_AMP_RAYLEIGH && s->amp_model != TRK_AMP_K)
            return errmsg_fail(err, errlen, "amplitude model must be rayleigh or k");
        if (s->amp_model == TRK_AMP_K && !(s->nu > 0 && s->nu <= 1e6))
            return errmsg_fail(err, errlen, "K shape nu must be in (0, 1e6] (got %g)", s->nu);
        if (check_axis(&s->snr_db, "snr_db", 0, -30, 60, 0, 0, 1, err, errlen) ||
            check_axis(&s->pfa, "pfa", 1, 0, 1, 1, 1, 2, err, errlen))
            return -1;
        if (s->pfa.nodes) return errmsg_fail(err, errlen, "the pfa axis is a log-spaced range");
    } else if (check_axis(&s->pd, "pd", 0, 0, 1, 1, 0, 2, err, errlen)) {
        return -1;
    }
    const int meas = s->measure_interp;
    const size_t nlv = s->lambda_vg.n;
    const size_t n0 = ai ? s->snr_db.n : s->pd.n, n1 = ai ? s->pfa.n : 1;
    const size_t ncells = n0 * n1 * nlv;
    /* test grid: centres of the grid cells */
    const size_t m0 = meas ? n0 - 1 : 0, m1 = ai ? (meas ? n1 - 1 : 0) : 1, mlv = meas ? nlv - 1 : 0;
    const size_t ntest = meas ? m0 * m1 * mlv : 0;
    if (meas && (n0 < 2)) return errmsg_fail(err, errlen, "the interpolation error needs >= 2 nodes per axis");

    int rc = -1;
    double *lv = malloc(nlv * sizeof *lv), *lvm = malloc((nlv ? nlv : 1) * sizeof *lvm);
    double *q = calloc(ncells + ntest + 1, sizeof *q), *se = calloc(ncells + ntest + 1, sizeof *se);
    double *data = malloc(2 * ncells * sizeof *data);
    double *cpd = NULL, *clv = NULL;
    const size_t nmodels = ai ? n0 * n1 + m0 * m1 : 0;
    struct q2_amp *amp = calloc(nmodels + 1, sizeof *amp);
    struct q2_amp_sampler *smp = calloc(nmodels + 1, sizeof *smp);
    const size_t nlines = ai ? nmodels : 1;
    struct q2_is_line *lines = calloc(nlines, sizeof *lines);
    trk_real *lkv = NULL, *lkn = NULL;
    double *errs = NULL, *tse = NULL;
    char *amp_built = calloc(nmodels + 1, 1);
    if (!lv || !lvm || !q || !se || !data || !amp || !smp || !lines || !amp_built) {
        errmsg_fail(err, errlen, "out of memory");
        goto out;
    }
    for (size_t j = 0; j < nlv; j++) lv[j] = q2_table_node(&s->lambda_vg, 1, j);
    for (size_t j = 0; j < mlv; j++) lvm[j] = sqrt(lv[j] * lv[j + 1]);

    struct q2_is_options opt;
    memset(&opt, 0, sizeof opt);
    opt.seed = r->seed;
    opt.samples = r->samples;
    opt.target_se = r->target_se;
    opt.tail_mass = r->tail_mass;
    opt.threads = r->threads;
    opt.progress = r->progress;
    opt.progress_ctx = r->progress_ctx;
    opt.par = r->par;

    double t0 = progress_now_s();
    if (!ai) {
        cpd = malloc((ncells + ntest) * sizeof *cpd);
        clv = malloc((ncells + ntest) * sizeof *clv);
        if (!cpd || !clv) {
            errmsg_fail(err, errlen, "out of memory");
            goto out;
        }
        size_t k = 0;
        for (size_t i = 0; i < n0; i++)
            for (size_t j = 0; j < nlv; j++, k++) cpd[k] = q2_table_node(&s->pd, 0, i), clv[k] = lv[j];
        for (size_t i = 0; i < m0; i++)
            for (size_t j = 0; j < mlv; j++, k++) {
                cpd[k] = 0.5 * (q2_table_node(&s->pd, 0, i) + q2_table_node(&s->pd, 0, i + 1));
                clv[k] = lvm[j];
            }
        lines[0] = (struct q2_is_line){.nz = s->nz, .gamma = s->gate_gamma, .stream = 0,
                                       .n_cells = ncells + ntest, .pd = cpd, .lambda_vg = clv, .q2 = q, .se = se};
    } else {
        /* amplitude models: work units; model 0 built here first gives the
         * size of a table */
        struct amp_job job = {s, n0, n1, m1, 0};
        double snr0, pfa0;
        amp_params(&job, 0, &snr0, &pfa0);
        if (q2_amp_init(&amp[0], s->amp_model, s->nu, snr0, pfa0, s->amp_size, s->amp_measure, err, errlen) != 0)
            goto out;
        job.cap = q2_amp_table_len(&amp[0]);
        q2_amp_free(&amp[0]);
        const size_t slot = amp_slot(&job);
        unsigned char *slots = malloc(nmodels * slot);
        if (!slots) {
            errmsg_fail(err, errlen, "out of memory");
            goto out;
        }
        struct par_batch pb;
        par_batch_init(&pb, nmodels, slot, 1, amp_unit, &job);
        pb.threads = r->threads;
        char e2[256];
        if (par_run(r->par, &pb, slots, e2, sizeof e2) != PAR_OK) {
            errmsg_fail(err, errlen, "amplitude models: %s", e2);
            free(slots);
            goto out;
        }
        int bad = 0;
        for (size_t k = 0; k < nmodels && !bad; k++) { /* the first failure, in model order */
            const unsigned char *sl = slots + k * slot;
            int32_t st;
            memcpy(&st, sl, sizeof st);
            if (st) {
                amp_slot_refusal(sl, k, st, err, errlen);
                bad = 1;
            } else if (q2_amp_unpack(&amp[k], sl + AMP_SLOT_HEAD, slot - AMP_SLOT_HEAD, err, errlen) != 0) {
                bad = 1;
            } else {
                amp_built[k] = 1;
            }
        }
        free(slots);
        for (size_t k = 0; k < nmodels && !bad; k++) {
            if (amp[k].measured) {
                res->amp_measured = 1;
                if (amp[k].err_log_lr > res->amp_err_log_lr) res->amp_err_log_lr = amp[k].err_log_lr;
                if (amp[k].err_inv_sf > res->amp_err_inv_sf) res->amp_err_inv_sf = amp[k].err_inv_sf;
            }
            smp[k] = q2_amp_sampler_of(&amp[k]);
            const int test = k >= n0 * n1;
            lines[k] = (struct q2_is_line){.nz = s->nz, .gamma = s->gate_gamma, .amp = &smp[k], .stream = 1,
                                           .n_cells = test ? mlv : nlv, .lambda_vg = test ? lvm : lv,
                                           .q2 = test ? q + ncells + (k - n0 * n1) * mlv : q + k * nlv,
                                           .se = test ? se + ncells + (k - n0 * n1) * mlv : se + k * nlv};
        }
        if (bad) goto out;
    }
    res->setup_s = progress_now_s() - t0;
    t0 = progress_now_s();
    char e3[300];
    if (q2_is_run(lines, nlines, &opt, e3, sizeof e3)) {
        snprintf(err, errlen, "sampler: %s", e3);
        goto out;
    }
    res->sample_s = progress_now_s() - t0;
    for (size_t l = 0; l < nlines; l++) res->scenes += lines[l].scenes, res->points += lines[l].points;
    double sum_se = 0;
    for (size_t c = 0; c < ncells; c++) {
        if (!(q[c] >= 0 && q[c] <= 1) || !(se[c] >= 0)) {
            errmsg_fail(err, errlen, "sampler returned q2 %g outside [0, 1]", q[c]);
            goto out;
        }
        data[2 * c] = q[c];
        data[2 * c + 1] = se[c];
        if (se[c] > res->max_se) res->max_se = se[c];
        sum_se += se[c];
    }
    res->mean_se = sum_se / (double)ncells;
    res->n_cells = ncells;
    res->n_lines = ai ? n0 * n1 : 1;

    if (meas) {
        struct trk_q2_lookup lk;
        if (make_lookup(s, data, ncells, &lkv, &lkn, &lk)) {
            errmsg_fail(err, errlen, "the q2 grid is refused by the library lookup");
            goto out;
        }
        errs = malloc(ntest * sizeof *errs);
        tse = malloc(ntest * sizeof *tse);
        if (!errs || !tse) {
            errmsg_fail(err, errlen, "out of memory");
            goto out;
        }
        double e2 = 0;
        for (size_t t = 0; t < ntest; t++) {
            trk_real x[3], v;
            double xs[3];
            if (!ai) {
                xs[0] = cpd[ncells + t];
                xs[1] = clv[ncells + t];
                xs[2] = 0;
            } else {
                const size_t line = t / mlv, i = line / m1, j = line % m1;
                xs[0] = 0.5 * (q2_table_node(&s->snr_db, 0, i) + q2_table_node(&s->snr_db, 0, i + 1));
                xs[1] = sqrt(q2_table_node(&s->pfa, 1, j) * q2_table_node(&s->pfa, 1, j + 1));
                xs[2] = lvm[t % mlv];
            }
            for (int d = 0; d < 3; d++) x[d] = (trk_real)xs[d];
            if (trk_q2_lookup_eval(&lk, x, &v) != TRK_OK) {
                errmsg_fail(err, errlen, "lookup at a test point failed");
                goto out;
            }
            const double e = fabs((double)v - q[ncells + t]);
            errs[t] = e;
            tse[t] = se[ncells + t];
            e2 += e * e;
            if (tse[t] <= Q2_TABLE_QUIET_SE) {
                res->interp_n_quiet++;
                if (e > res->interp_max_quiet) res->interp_max_quiet = e;
            }
            if (e > res->interp_max) {
                res->interp_max = e;
                for (int d = 0; d < 3; d++) res->interp_max_at[d] = xs[d];
            }
        }
        res->interp_measured = 1;
        res->interp_n = ntest;
        res->interp_rms = sqrt(e2 / (double)ntest);
        qsort(tse, ntest, sizeof *tse, cmp_double);
        res->interp_se_median = tse[ntest / 2];
    }
    /* a table needs >= 2 nodes per axis (the container); else values only */
    if (n0 >= 2 && serialise(s, r, res, data, &res->bytes, &res->len, err, errlen)) goto out;
    res->values = data;
    data = NULL;
    rc = 0;
out:
    for (size_t k = 0; k < nmodels && amp_built; k++)
        if (amp_built[k]) q2_amp_free(&amp[k]);
    free(amp_built);
    free(amp), free(smp), free(lines), free(lv), free(lvm), free(q), free(se), free(data);
    free(cpd), free(clv), free(lkv), free(lkn), free(errs), free(tse);
    return rc;
}

void q2_table_result_free(struct q2_table_result *res)
{
    free(res->bytes);
    free(res->values);
    res->bytes = NULL;
    res->values = NULL;
}
