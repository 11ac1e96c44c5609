/* toc.c - the tracking operating characteristic (Brekke sec. 5, Fig. 2):
 * steady-state RMSE of the MRE (mre.c) as a function of the detector's
 * false-alarm probability, and its minimum. Declared in trk/toc.h. */
#include "trk/toc.h"

#include <math.h>

#include "internal.h"

struct pfa_bind {
    trk_q2_pfa_fn fn;
    const void *ctx;
    trk_real pfa;
};

static trk_status q2_at_pfa(const void *ctx, trk_real lambda_vg, trk_real *q2)
{
    const struct pfa_bind *b = ctx;
    return b->fn(b->ctx, b->pfa, lambda_vg, q2);
}

static trk_status q2_unused(const void *ctx, trk_real lambda_vg, trk_real *q2)
{
    (void)ctx, (void)lambda_vg, (void)q2;
    return TRK_E_ARG;
}

static trk_status toc_check(const struct trk_toc_params *p)
{
    if (!p || !p->q2_fn) return TRK_E_ARG;
    /* the model's own parameters: refused here, not counted as divergence */
    struct trk_mre m;
    struct trk_mre_params mp = p->mre;
    mp.clutter_density = 0;
    mp.q2_fn = q2_unused;
    trk_status st = trk_mre_init(&m, &mp);
    if (st != TRK_OK) return st;
    if (!isfinite(p->cells_per_m) || !isfinite(p->pfa_min) || !isfinite(p->pfa_max) ||
        !isfinite(p->ln_pfa_tol))
        return TRK_E_NAN;
    if (!(p->cells_per_m > 0)) return TRK_E_RANGE;
    if (!(p->pfa_min > 0 && p->pfa_min < p->pfa_max && p->pfa_max < 1)) return TRK_E_RANGE;
    if (p->n_grid != 0 && (p->n_grid < 3 || p->n_grid > 100000)) return TRK_E_RANGE;
    if (!(p->ln_pfa_tol >= 0)) return TRK_E_RANGE;
    return TRK_OK;
}

trk_status trk_toc_rmse(const struct trk_toc_params *p, trk_real pfa, trk_real *rmse_m,
                        struct trk_mre_result *res)
{
    struct trk_mre m;
    struct trk_mre_result local;
    if (!rmse_m) return TRK_E_ARG;
    trk_status st = toc_check(p);
    if (st != TRK_OK) return st;
    if (!isfinite(pfa)) return TRK_E_NAN;
    if (!(pfa > 0 && pfa < 1)) return TRK_E_RANGE;
    struct pfa_bind bind = {p->q2_fn, p->q2_ctx, pfa};
    struct trk_mre_params mp = p->mre;
    mp.clutter_density = pfa * p->cells_per_m;
    mp.q2 = 1;
    mp.q2_fn = q2_at_pfa;
    mp.q2_ctx = &bind;
    st = trk_mre_init(&m, &mp);
    if (st != TRK_OK) return st;
    if (!res) res = &local;
    st = trk_mre_steady_state(&m, p->p0, res);
    *rmse_m = st == TRK_OK ? res->rmse_m : (trk_real)INFINITY;
    return st;
}

/* e(pfa) with "no steady state" (diverged, or off the q2 grid) as +inf. */
struct toc_eval {
    const struct trk_toc_params *p;
    struct trk_toc_result *best;
    trk_status hard;  /* first status that is neither OK, DIVERGED nor RANGE */
};

static trk_real toc_eval_at(struct toc_eval *ev, trk_real ln_pfa)
{
    struct trk_mre_result r;
    trk_real e;
    const trk_real pfa = trk_exp(ln_pfa);
    trk_status st = trk_toc_rmse(ev->p, pfa, &e, &r);
    ev->best->n_evals++;
    if (st == TRK_E_DIVERGED || st == TRK_E_RANGE) {
        ev->best->n_diverged++;
        return (trk_real)INFINITY;
    }
    if (st != TRK_OK) {
        if (ev->hard == TRK_OK) ev->hard = st;
        return (trk_real)INFINITY;
    }
    if (e < ev->best->rmse_m) {
        ev->best->rmse_m = e;
        ev->best->pfa = pfa;
        ev->best->lambda_vg = r.lambda_vg;
        ev->best->q2 = r.q2;
    }
    return e;
}

trk_status trk_toc_optimise(const struct trk_toc_params *p, struct trk_toc_result *res)
{
    if (!res) return TRK_E_ARG;
    trk_status st = toc_check(p);
    if (st != TRK_OK) return st;
    const int n = p->n_grid ? p->n_grid : 41;
    const trk_real tol = p->ln_pfa_tol > 0 ? p->ln_pfa_tol : TRK_REAL_C(1e-3);
    const trk_real lo = trk_log(p->pfa_min), hi = trk_log(p->pfa_max);
    struct trk_toc_result r = {0, (trk_real)INFINITY, 0, 0, 0, 0};
    struct toc_eval ev = {p, &r, TRK_OK};

    /* coarse grid in ln pfa */
    int best_i = -1;
    trk_real best_e = (trk_real)INFINITY;
    for (int i = 0; i < n; i++) {
        trk_real x = lo + (hi - lo) * ((trk_real)i / (trk_real)(n - 1));
        trk_real e = toc_eval_at(&ev, x);
        if (ev.hard != TRK_OK) return ev.hard;
        if (e < best_e) {
            best_e = e;
            best_i = i;
        }
    }
    if (best_i < 0) {
        *res = r;
        return TRK_E_DIVERGED;
    }
    /* golden-section refinement on [x_{i-1}, x_{i+1}] */
    const trk_real step = (hi - lo) / (trk_real)(n - 1);
    trk_real a = lo + step * (trk_real)(best_i > 0 ? best_i - 1 : 0);
    trk_real b = lo + step * (trk_real)(best_i < n - 1 ? best_i + 1 : n - 1);
    const trk_real g = TRK_REAL_C(0.61803398874989484820);
    trk_real c = b - g * (b - a), d = a + g * (b - a);
    trk_real fc = toc_eval_at(&ev, c), fd = toc_eval_at(&ev, d);
    for (int it = 0; it < 200 && b - a > tol && ev.hard == TRK_OK; it++) {
        if (fc <= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = toc_eval_at(&ev, c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = toc_eval_at(&ev, d);
        }
    }
    if (ev.hard != TRK_OK) return ev.hard;
    *res = r;
    return TRK_OK;
}
