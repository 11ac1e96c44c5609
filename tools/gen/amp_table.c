/* amp_table.c - amplitude table generation and the direct evaluation it is
 * checked against (amp_table.h). */
#include "amp_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "table_writer.h"
#include "trk/table.h"

/* ------------------------------------------------------------------ direct */

int amp_direct_init(struct amp_direct *d, int model, double nu, double clutter_power, double snr_db, double pfa)
{
    memset(d, 0, sizeof *d);
    if (!(clutter_power > 0) || !isfinite(clutter_power) || !(pfa > 0 && pfa < 1)) return -1;
    d->model = model;
    d->clutter_power = clutter_power;
    d->sqrt_p = sqrt(clutter_power);
    d->pfa = pfa;
    d->snr_db = snr_db;
    d->nu = nu;
    if (model == TRK_AMP_RAYLEIGH) {
        if (trk_amplitude_init_rayleigh(&d->ray, (trk_real)clutter_power, (trk_real)snr_db, (trk_real)pfa) != TRK_OK)
            return -1;
        d->t = (double)trk_amplitude_threshold(&d->ray);
        d->pd = (double)trk_amplitude_pd(&d->ray);
        return 0;
    }
    if (model != TRK_AMP_K) return -1;
    double tn;
    if (kdist_init(&d->k, nu, snr_db) != 0 || kdist_threshold(&d->k, pfa, &tn) != 0) return -1;
    d->t = tn * d->sqrt_p;
    d->pd = exp(kdist_log_sf(&d->k, 1, tn));
    return 0;
}

int amp_direct_log_lr(const struct amp_direct *d, double a, double *log_lr)
{
    if (d->model == TRK_AMP_RAYLEIGH) {
        trk_real v;
        if (trk_amplitude_log_lr(&d->ray, (trk_real)a, &v) != TRK_OK) return -1;
        *log_lr = (double)v;
        return 0;
    }
    if (!(a >= d->t) || !isfinite(a)) return -1;
    *log_lr = kdist_log_lr(&d->k, d->pfa, d->pd, a / d->sqrt_p, NULL);
    return isfinite(*log_lr) ? 0 : -1;
}

int amp_direct_inv_sf(const struct amp_direct *d, int source, double x, double *a)
{
    if (d->model == TRK_AMP_RAYLEIGH) {
        trk_real v;
        if (trk_amplitude_inv_sf(&d->ray, source, (trk_real)x, &v) != TRK_OK) return -1;
        *a = (double)v;
        return 0;
    }
    double an;
    if (kdist_inv_sf(&d->k, source, d->t / d->sqrt_p, x, &an, NULL) != 0) return -1;
    *a = an * d->sqrt_p;
    return 0;
}

/* ---------------------------------------------------------------- nodes
 * Everything below is in normalised units u = a/sqrt(P). */

struct gen {
    const struct amp_table_opts *o;
    struct amp_direct d;
    double ut;       /* normalised threshold */
    double snr;      /* linear */
};

/* u^2(x) and du^2/dx of one curve. */
static int inv_node(const struct gen *g, int source, double x, double *u2, double *du2)
{
    if (g->d.model == TRK_AMP_RAYLEIGH) {
        double a;
        if (amp_direct_inv_sf(&g->d, source, x, &a) != 0) return -1;
        *u2 = a * a / g->d.clutter_power;
        *du2 = source ? 1 + g->snr : 1; /* d(t^2 + Q x)/dx / P */
        return 0;
    }
    double u, dudx;
    if (kdist_inv_sf(&g->d.k, source, g->ut, x, &u, &dudx) != 0) return -1;
    *u2 = u * u;
    *du2 = 2 * u * dudx;
    return 0;
}

/* ln l^a and d ln l^a / ds at s = ln u. */
static int llr_node(const struct gen *g, double s, double *L, double *dLds)
{
    const double u = exp(s);
    if (g->d.model == TRK_AMP_RAYLEIGH) {
        if (amp_direct_log_lr(&g->d, fmax(u * g->d.sqrt_p, g->d.t), L) != 0) return -1;
        *dLds = 2 * u * u * g->snr / (1 + g->snr); /* L = lr0 + (u^2) SNR/(1+SNR) */
        return 0;
    }
    double dLdA;
    *L = kdist_log_lr(&g->d.k, g->d.pfa, g->d.pd, fmax(u, g->ut), &dLdA);
    *dLds = 2 * u * u * dLdA;
    return isfinite(*L) && isfinite(*dLds) ? 0 : -1;
}

/* u at x (exact), for the geometric grid and the error measurement. */
static int inv_u(const struct gen *g, int source, double x, double *u)
{
    double a;
    if (amp_direct_inv_sf(&g->d, source, x, &a) != 0) return -1;
    *u = a / g->d.sqrt_p;
    return 0;
}

/* x = ln S(t) - ln S(a) for the geometric grid (normalised u). */
static double x_of_u(const struct gen *g, int source, double u)
{
    if (g->d.model == TRK_AMP_RAYLEIGH) return (u * u - g->ut * g->ut) / (source ? 1 + g->snr : 1);
    return kdist_log_sf(&g->d.k, source, g->ut) - kdist_log_sf(&g->d.k, source, u);
}

/* B of Brekke eq 44: u_last = u_t + A (B^n - 1)/(B - 1), n steps. */
static double geom_ratio(double span, double step, uint32_t n)
{
    const double want = span / step; /* sum_{p<n} B^p */
    if (fabs(want - n) < 1e-12 * n) return 1;
    double lo = want > n ? 1 : 0, hi = want > n ? 2 : 1;
    if (want > n)
        while ((pow(hi, n) - 1) / (hi - 1) < want) hi *= 2;
    for (int it = 0; it < 200; it++) {
        const double mid = 0.5 * (lo + hi);
        const double sum = fabs(mid - 1) < 1e-15 ? n : (pow(mid, n) - 1) / (mid - 1);
        if (sum < want) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* ------------------------------------------------------------ measurement */

static int measure(const struct gen *g, const unsigned char *bytes, size_t len, int pts, double x_max,
                   double s_lo, double s_hi, uint32_t nllr, uint32_t ninv, struct amp_table_result *r)
{
    struct trk_table t;
    struct trk_amplitude m;
    if (trk_table_parse(&t, bytes, len) != TRK_OK || trk_amplitude_init_table(&m, &t) != TRK_OK) return -1;
    double e_llr = 0, e_inv = 0;
    const double hs = (s_hi - s_lo) / (nllr - 1);
    for (uint32_t i = 0; i + 1 < nllr; i++)
        for (int k = 1; k <= pts; k++) {
            const double s = s_lo + hs * (i + (double)k / (pts + 1));
            const double a = fmax(exp(s) * g->d.sqrt_p, g->d.t);
            double want;
            trk_real got;
            if (amp_direct_log_lr(&g->d, a, &want) != 0 || trk_amplitude_log_lr(&m, (trk_real)a, &got) != TRK_OK)
                return -1;
            e_llr = fmax(e_llr, fabs((double)got - want));
        }
    /* a(x): uniform grid at points between the nodes; geometric grid on a
     * uniform x sample of [0, x_max] (its nodes are far apart in x) */
    const uint32_t nx = g->o->grid == TRK_AMP_GRID_GEOMETRIC ? 1024 : ninv;
    const double hx = x_max / (nx - 1);
    for (int src = 0; src < 2; src++)
        for (uint32_t i = 0; i + 1 < nx; i++)
            for (int k = 1; k <= pts; k++) {
                const double x = hx * (i + (double)k / (pts + 1));
                double want;
                trk_real got;
                if (amp_direct_inv_sf(&g->d, src, x, &want) != 0 ||
                    trk_amplitude_inv_sf(&m, src, (trk_real)x, &got) != TRK_OK)
                    return -1;
                e_inv = fmax(e_inv, fabs((double)got - want) / want);
            }
    r->err_log_lr = e_llr;
    r->err_inv_sf = e_inv;
    r->measured = 1;
    return 0;
}

/* ------------------------------------------------------------------ build */

static int serialise(const struct gen *g, const struct amp_table_opts *o, uint32_t rs, double x_max,
                     double a_max_u, double limit, double geom_b, const struct amp_table_result *errs,
                     const struct tablew_axis *llr_ax, const double *llr, const struct tablew_axis inv_ax[2],
                     double *const inv[2], unsigned char **bytes, size_t *len, char *err, size_t errlen)
{
    struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, TRK_AMP_TABLE_VERSION, rs);
    if (!w) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    const int geo = o->grid == TRK_AMP_GRID_GEOMETRIC;
    const uint32_t inv_ncomp = geo ? 1 : 2, inv_interp = geo ? TRK_TABLE_INTERP_LINEAR : TRK_TABLE_INTERP_HERMITE;
    int bad = tablew_param_int(w, "model", g->d.model) || tablew_param_real(w, "nu", g->d.model == TRK_AMP_K ? g->d.nu : 0) ||
              tablew_param_real(w, "snr_db", g->d.snr_db) || tablew_param_real(w, "pfa", g->d.pfa) ||
              tablew_param_real(w, "clutter_power", g->d.clutter_power) ||
              tablew_param_real(w, "threshold", g->d.t) || tablew_param_real(w, "pd", g->d.pd) ||
              (g->d.model == TRK_AMP_K && tablew_param_real(w, "log_lr_limit", limit)) ||
              tablew_param_real(w, "x_max", x_max) || tablew_param_real(w, "a_max", a_max_u * g->d.sqrt_p) ||
              tablew_param_int(w, "grid", geo ? TRK_AMP_GRID_GEOMETRIC : TRK_AMP_GRID_UNIFORM) ||
              tablew_param_int(w, "generator_version", AMP_TABLE_GENERATOR_VERSION) ||
              (geo && (tablew_param_real(w, "geom_step", AMP_TABLE_GEOM_STEP) ||
                       tablew_param_real(w, "geom_last", AMP_TABLE_GEOM_LAST) ||
                       tablew_param_real(w, "geom_ratio", geom_b))) ||
              (errs && errs->measured &&
               (tablew_param_real(w, "err_log_lr", errs->err_log_lr) ||
                tablew_param_real(w, "err_inv_sf", errs->err_inv_sf))) ||
              tablew_section(w, TRK_AMP_SECTION_LOG_LR, 1, llr_ax, 2, TRK_TABLE_INTERP_HERMITE, llr) ||
              tablew_section(w, TRK_AMP_SECTION_INV_SF_CLUTTER, 1, &inv_ax[0], inv_ncomp, inv_interp, inv[0]) ||
              tablew_section(w, TRK_AMP_SECTION_INV_SF_TARGET, 1, &inv_ax[1], inv_ncomp, inv_interp, inv[1]) ||
              tablew_finish(w, bytes, len);
    if (bad) snprintf(err, errlen, "%s", tablew_error(w));
    tablew_free(w);
    return bad ? -1 : 0;
}

/* The node loops as work units (one node's values into its slot), run by
 * o->exec or by this file's OpenMP loops. */
struct node_job {
    const struct gen *g;
    double s_lo, s_hi, x_max;
    uint32_t nllr, ninv;
    const double *inv_u;   /* geometric: the grids' amplitudes, curve src at 2 ninv src */
};

/* ln l^a node i: res = {L, dL/ds} */
static int llr_unit(void *ctx, size_t i, void *res)
{
    const struct node_job *j = ctx;
    double *v = res;
    const double s = i == j->nllr - 1 ? j->s_hi : j->s_lo + (j->s_hi - j->s_lo) * (double)i / (j->nllr - 1);
    return llr_node(j->g, s, &v[0], &v[1]) != 0;
}

/* inverse-survival node k of the uniform grid (curve k / ninv): res = {u^2, du^2/dx} */
static int inv_unit(void *ctx, size_t k, void *res)
{
    const struct node_job *j = ctx;
    double *v = res;
    const int src = (int)(k / j->ninv);
    const size_t i = k % j->ninv;
    const double x = j->x_max * (double)i / (j->ninv - 1);
    return inv_node(j->g, src, i == 0 ? 0 : x, &v[0], &v[1]) != 0;
}

/* x of node k of the geometric grid: res = {x} */
static int geo_unit(void *ctx, size_t k, void *res)
{
    const struct node_job *j = ctx;
    const int src = (int)(k / j->ninv);
    const size_t p = k % j->ninv;
    *(double *)res = p == 0 ? 0 : x_of_u(j->g, src, j->inv_u[(size_t)src * 2 * j->ninv + p]);
    return 0;
}

/* fn over [0, n), slots of `size` bytes: o->exec, else OpenMP here. 0, or
 * -1 when a node failed. */
static int nodes(const struct amp_table_opts *o, size_t n, size_t size, int (*fn)(void *, size_t, void *),
                 struct node_job *j, void *out)
{
    if (o->exec) return o->exec->run(o->exec->ctx, n, size, fn, j, out) ? -1 : 0;
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 8) reduction(| : bad)
#endif
    for (long i = 0; i < (long)n; i++) bad |= fn(j, (size_t)i, (unsigned char *)out + (size_t)i * size) != 0;
    return bad ? -1 : 0;
}

int amp_table_build(const struct amp_table_opts *o, struct amp_table_result *r, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    struct gen g;
    memset(&g, 0, sizeof g);
    g.o = o;
    const double power = o->clutter_power > 0 ? o->clutter_power : 1;
    const uint32_t rs = o->real_size ? o->real_size : (uint32_t)sizeof(trk_real);
    const int geo = o->grid == TRK_AMP_GRID_GEOMETRIC;
    const uint32_t ninv = o->size ? o->size : geo ? AMP_TABLE_DEFAULT_GEOM_SIZE : AMP_TABLE_DEFAULT_SIZE;
    const uint32_t nllr = o->llr_size ? o->llr_size : AMP_TABLE_DEFAULT_LLR_SIZE;
    const double x_max = o->x_max > 0 ? o->x_max : AMP_TABLE_X_MAX;
    if (o->grid != 0 && o->grid != TRK_AMP_GRID_UNIFORM && !geo) {
        snprintf(err, errlen, "grid must be uniform or geometric");
        return -1;
    }
    if (rs != 4 && rs != 8) {
        snprintf(err, errlen, "real width must be 4 or 8 bytes");
        return -1;
    }
    if (ninv < 4 || nllr < 4 || ninv > 1u << 20 || nllr > 1u << 20) {
        snprintf(err, errlen, "table sizes must be in 4 .. 1048576");
        return -1;
    }
    if (!(x_max > 0 && x_max <= 700)) {
        snprintf(err, errlen, "x_max must be in (0, 700]");
        return -1;
    }
    if (amp_direct_init(&g.d, o->model, o->nu, power, o->snr_db, o->pfa) != 0) {
        snprintf(err, errlen, "bad model parameters (model %d, nu %g, snr_db %g, pfa %g, clutter power %g)", o->model,
                 o->nu, o->snr_db, o->pfa, power);
        return -1;
    }
    g.ut = g.d.t / g.d.sqrt_p;
    g.snr = pow(10.0, o->snr_db / 10);
    r->threshold = g.d.t;
    r->pd = g.d.pd;

    /* a_max: the larger amplitude at x = x_max */
    double a_max_u = 0;
    for (int src = 0; src < 2; src++) {
        double u;
        if (inv_u(&g, src, x_max, &u) != 0) {
            snprintf(err, errlen, "inverse survival at x = %g did not converge", x_max);
            return -1;
        }
        a_max_u = fmax(a_max_u, u);
    }
    r->a_max = a_max_u * g.d.sqrt_p;

    /* log l^a nodes, uniform in s = ln u over [ln u_t, ln u_max] */
    const double s_lo = log(g.ut), s_hi = log(a_max_u);
    double *llr = malloc(2 * nllr * sizeof(double));
    /* each array one block, curve 1 after curve 0: node k's slot is k */
    double *inv_b = malloc(2 * 2 * ninv * sizeof(double)), *xs_b = malloc(2 * ninv * sizeof(double));
    double *inv[2] = {inv_b, inv_b ? inv_b + 2 * ninv : NULL};
    double *xs[2] = {xs_b, xs_b ? xs_b + ninv : NULL};
    int rc = -1;
    if (!llr || !inv_b || !xs_b) {
        snprintf(err, errlen, "out of memory");
        goto out;
    }
    struct node_job job = {&g, s_lo, s_hi, x_max, nllr, ninv, inv_b};
    if (nodes(o, nllr, 2 * sizeof(double), llr_unit, &job, llr) != 0) {
        snprintf(err, errlen, "log l^a node evaluation failed");
        goto out;
    }
    struct tablew_axis llr_ax = {nllr, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_LN_AMP, s_lo, s_hi, 0, NULL};

    /* inverse survival nodes */
    struct tablew_axis inv_ax[2];
    double geom_b = 0;
    int bad = 0;
    if (!geo) {
        bad = nodes(o, 2 * (size_t)ninv, 2 * sizeof(double), inv_unit, &job, inv_b) != 0;
        for (int src = 0; src < 2; src++) {
            inv[src][0] = g.ut * g.ut; /* exact at x = 0 */
            inv_ax[src] = (struct tablew_axis){ninv, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, 0, x_max, 0, NULL};
        }
    } else {
        /* Brekke eqs 43-45: u_p = u_t + A (B^p - 1)/(B - 1), u_last = 100 */
        const double span = AMP_TABLE_GEOM_LAST - g.ut;
        if (!(span > AMP_TABLE_GEOM_STEP)) {
            snprintf(err, errlen, "threshold %g is above the geometric grid's last amplitude", g.ut);
            goto out;
        }
        geom_b = geom_ratio(span, AMP_TABLE_GEOM_STEP, ninv - 1);
        for (int src = 0; src < 2; src++) {
            double sum = 0, step = AMP_TABLE_GEOM_STEP;
            for (uint32_t p = 0; p < ninv; p++) {
                const double u = p == ninv - 1 ? AMP_TABLE_GEOM_LAST : g.ut + sum;
                inv[src][p] = u;
                sum += step;
                step *= geom_b;
            }
        }
        if (nodes(o, 2 * (size_t)ninv, sizeof(double), geo_unit, &job, xs_b) != 0) bad = 1;
        for (int src = 0; src < 2; src++) {
            for (uint32_t p = 1; p < ninv; p++)
                if (!(xs[src][p] > xs[src][p - 1]) || !isfinite(xs[src][p])) bad = 1;
            inv_ax[src] = (struct tablew_axis){ninv, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_X, 0,
                                               xs[src][ninv - 1], 0, xs[src]};
        }
    }
    if (bad) {
        snprintf(err, errlen, "inverse survival node evaluation failed");
        goto out;
    }
    const double limit = g.d.model == TRK_AMP_K ? kdist_log_lr_inf(&g.d.k, g.d.pfa, g.d.pd) : 0;
    if (serialise(&g, o, rs, x_max, a_max_u, limit, geom_b, NULL, &llr_ax, llr, inv_ax, inv, &r->bytes, &r->len,
                  err, errlen))
        goto out;
    /* Rayleigh tables are evaluated by the library's closed forms: nothing to measure */
    if (o->measure && rs == sizeof(trk_real) && g.d.model == TRK_AMP_K) {
        const int pts = o->measure_points > 0 ? o->measure_points : 3;
        if (measure(&g, r->bytes, r->len, pts, x_max, s_lo, s_hi, nllr, ninv, r) != 0) {
            snprintf(err, errlen, "the generated table does not load or evaluate through the library");
            free(r->bytes);
            r->bytes = NULL;
            goto out;
        }
        /* again, with the measured errors as parameters */
        free(r->bytes);
        r->bytes = NULL;
        if (serialise(&g, o, rs, x_max, a_max_u, limit, geom_b, r, &llr_ax, llr, inv_ax, inv, &r->bytes, &r->len,
                      err, errlen))
            goto out;
    }
    /* the library must accept what is written (a clutter power of 1e31 gave a
     * table trk_amplitude_init_table refuses); tables of the other real width cannot be loaded here */
    if (rs == sizeof(trk_real)) {
        struct trk_table t;
        struct trk_amplitude m;
        trk_status st = trk_table_parse(&t, r->bytes, r->len);
        if (st == TRK_OK) st = trk_amplitude_init_table(&m, &t);
        if (st != TRK_OK) {
            snprintf(err, errlen, "the library refuses the generated table (clutter power %g, threshold %g): %s",
                     power, g.d.t, ERRMSG_STATUS(st));
            free(r->bytes);
            r->bytes = NULL;
            goto out;
        }
    }
    rc = 0;
out:
    free(llr);
    free(inv_b);
    free(xs_b);
    return rc;
}

void amp_table_opts_init(struct amp_table_opts *o, int model, double nu, double snr_db, double pfa)
{
    memset(o, 0, sizeof *o);
    o->model = model;
    o->nu = nu;
    o->snr_db = snr_db;
    o->pfa = pfa;
}

int amp_table_model(const struct amp_table_opts *o, struct trk_amplitude *m, struct amp_table_result *r,
                    char *err, size_t errlen)
{
    const char *name = o->model == TRK_AMP_K ? "K" : "Rayleigh";
    char e2[256];
    if (amp_table_build(o, r, e2, sizeof e2) != 0) {
        snprintf(err, errlen, "%s amplitude table (nu %g, snr %g dB, pfa %g): %s", name, o->nu, o->snr_db, o->pfa,
                 e2);
        return -1;
    }
    struct trk_table t;
    trk_status st = trk_table_parse(&t, r->bytes, r->len);
    if (st == TRK_OK) st = trk_amplitude_init_table(m, &t);
    if (st != TRK_OK) {
        snprintf(err, errlen, "%s amplitude table (nu %g, snr %g dB, pfa %g) refused by the library: %s", name,
                 o->nu, o->snr_db, o->pfa, ERRMSG_STATUS(st));
        free(r->bytes);
        r->bytes = NULL;
        return -1;
    }
    return 0;
}
