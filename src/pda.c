/* pda.c - one-track PDA update (trk/pda.h; docs/conventions.md "PDA", Brekke eqs 21-25).
 * The update itself is trk_i_pda_update_set (pda_impl.h), shared with the
 * tracker; this file gates the caller's detections into a gated set. */
#include "trk/pda.h"

#include <stdint.h>

#include "pda_impl.h"

static trk_status refuse(const char **field, const char *name, trk_status st)
{
    if (field) *field = name;
    return st;
}

/* trk_pda_check_params, with gamma for trk_pda_init. */
static trk_status check(const struct trk_pda_params *pr, const char **field, trk_real *gamma)
{
    if (field) *field = NULL;
    if (!pr) return refuse(field, "params", TRK_E_ARG);
    if (pr->nz < 1 || pr->nz > TRK_MAX_MEAS) return refuse(field, "nz", TRK_E_ARG);
    if (pr->clutter != TRK_CLUTTER_PARAMETRIC && pr->clutter != TRK_CLUTTER_NONPARAMETRIC)
        return refuse(field, "clutter", TRK_E_ARG);
    if (pr->gating != 0 && pr->gating != 1) return refuse(field, "gating", TRK_E_ARG);
    if (!isfinite(pr->pd)) return refuse(field, "pd", TRK_E_NAN);
    if (!isfinite(pr->gate_prob)) return refuse(field, "gate_prob", TRK_E_NAN);
    if (!isfinite(pr->clutter_density)) return refuse(field, "clutter_density", TRK_E_NAN);
    if (!(pr->pd > 0 && pr->pd <= 1)) return refuse(field, "pd", TRK_E_RANGE);
    if (pr->clutter == TRK_CLUTTER_PARAMETRIC && !(pr->clutter_density >= 0))
        return refuse(field, "clutter_density", TRK_E_RANGE);
    trk_status st = trk_gate_gamma(pr->nz, pr->gate_prob, gamma);
    return st == TRK_OK ? TRK_OK : refuse(field, "gate_prob", st);
}

trk_status trk_pda_check_params(const struct trk_pda_params *pr, const char **field)
{
    trk_real gamma;
    return check(pr, field, &gamma);
}

trk_status trk_pda_init(struct trk_pda *pda, const struct trk_pda_params *pr)
{
    trk_real gamma;
    if (!pda) return TRK_E_ARG;
    trk_status st = check(pr, NULL, &gamma);
    if (st != TRK_OK) return st;
    pda->params = *pr;
    pda->gamma = gamma;
    pda->log_pd_norm = trk_log(pr->pd) - TRK_REAL_C(0.5) * (trk_real)pr->nz * TRK_LN_2PI;
    pda->log_miss = trk_log1p(-pr->pd * pr->gate_prob);
    pda->log_e0_param = trk_log(pr->clutter_density) + pda->log_miss;
    return TRK_OK;
}

trk_status trk_i_pda_update_set_rt(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                   struct trk_i_pda_set *s, struct trk_i_pda_out *o)
{
    return trk_i_pda_update_set(pda, pr, s, o);
}

trk_status trk_i_pda_update_beta_rt(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                    trk_real beta0)
{
    return trk_i_pda_update_beta(pr, s, beta0);
}

/* Gate the set's detections (s->n of them at z): d2 (into d2 when not
 * NULL) and w = ln e_i, -inf outside (with log_lr when not NULL); *finite
 * cleared for a detection or log_lr that is not finite. The detections in
 * the gate, returned. */
TRK_INLINE size_t gate(const struct trk_pda *pda, const int nz, const struct trk_innovation *inn, const trk_real *z,
                       const trk_real *log_lr, trk_real *d2, struct trk_i_pda_set *s, int *finite)
{
    size_t n_gated = 0;
    int ok = 1;
    for (size_t i = 0; i < s->n; i++) {
        trk_real nu[TRK_MAX_MEAS];
        for (int t = 0; t < nz; t++) nu[t] = z[i * nz + t] - inn->z_pred[t];
        if (log_lr) ok &= isfinite(log_lr[i]) != 0;
        const trk_real di = trk_i_mahalanobis2(nz, inn->s_chol_inv, nu);
        /* a finite d2 needs finite nu, so finite z: the components are
         * checked only for d2 = inf or NaN (rare) */
        if (!(di <= TRK_REAL_MAX))
            for (int t = 0; t < nz; t++) ok &= isfinite(z[i * nz + t]) != 0;
        const int in = trk_gate_inside(di, pda->gamma);
        if (d2) d2[i] = di;
        n_gated += (size_t)in;
        trk_i_pda_set_w(s, i, (in || !pda->params.gating) ? trk_i_pda_log_e(pda, inn->log_det_s, di, log_lr ? log_lr[i] : 0)
                                                         : -(trk_real)INFINITY);
    }
    *finite = ok;
    return n_gated;
}

/* The update for given dimensions; called with constants for the 2-D CV
 * model so the compiler unrolls it, and with run-time dimensions otherwise.
 * inn_in: the caller's innovation, or NULL to compute it here. */
TRK_INLINE trk_status pda_update(const struct trk_pda *pda, const int nx, const int nz,
                                 const trk_real *h, const trk_real *r, trk_real *x, trk_real *p,
                                 const struct trk_innovation *inn_in, size_t m, const trk_real *z,
                                 const trk_real *log_lr, trk_real *beta, trk_real *d2,
                                 struct trk_pda_report *rep)
{
    struct trk_innovation inn_own;
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    int sel_idx[TRK_MAX_MEAS];
    /* the library's CV H (the usual caller) needs no scan */
    const int *sel = (h == trk_cv2_h && nx == TRK_CV2_NX && nz == TRK_CV2_NZ) ? trk_i_cv2_sel()
                     : trk_i_h_select(nx, nz, h, sel_idx)                 ? sel_idx
                                                                          : NULL;
    const struct trk_innovation *inn = inn_in;
    if (inn) {
        trk_i_mul_ht(nx, nx, nz, p, h, sel, pht);
    } else {
        trk_status st = trk_i_innovation_sel(nx, nz, h, sel, r, x, p, pht, &inn_own);
        if (st != TRK_OK) return st;
        inn = &inn_own;
    }
    /* gate: d2, and the unnormalised log weights (beta[] holds ln e_i, -inf
     * outside); the detections' finiteness checked on the way. The usual
     * call (no amplitudes, no d2 wanted) gets a copy of its own (not in a
     * size build) */
    int finite = 1;
    struct trk_i_pda_set set = {m, m, 0, z, beta, NULL, -(trk_real)INFINITY, 0};
    const size_t n_gated = (TRK_SIZE_OPT || log_lr || d2) ? gate(pda, nz, inn, z, log_lr, d2, &set, &finite)
                                                          : gate(pda, nz, inn, z, NULL, NULL, &set, &finite);
    if (!finite) return TRK_E_NAN;
    const struct trk_i_pda_pred pred = {nx, nz, h, sel, r, x, p, pht, inn};
    set.m_gated = pda->params.gating ? n_gated : m;
    struct trk_i_pda_out out;
    /* x, P: the posterior. The CV copy inlines the update (speed); other
     * dimensions share the one out-of-line copy (and so does every caller in
     * a TRK_SIZE_OPT build) */
    const trk_status st = (nx == TRK_CV2_NX && nz == TRK_CV2_NZ) ? trk_i_pda_run(pda, &pred, &set, &out)
                                                                 : trk_i_pda_update_set_rt(pda, &pred, &set, &out);
    if (st != TRK_OK) return st;
    if (rep) {
        rep->beta0 = out.beta0;
        rep->n_gated = (int)n_gated;
        rep->gate_volume = out.gate_volume;
        rep->lambda = out.lambda;
    }
    return TRK_OK;
}

TRK_INLINE trk_status check_args(const struct trk_pda *pda, int nx, const trk_real *h, const trk_real *r,
                             const trk_real *x, const trk_real *p, size_t m, const trk_real *z,
                             const trk_real *beta)
{
    if (!pda || !h || !r || !x || !p || (m > 0 && (!z || !beta))) return TRK_E_ARG;
    const int nz = pda->params.nz;
    if (nx < nz || nx > TRK_MAX_STATE) return TRK_E_ARG;
    if (m > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    return TRK_OK; /* z and log_lr: finite, checked by the gate (pda_update) */
}

/* Both public entry points; inn NULL: computed here. */
TRK_INLINE trk_status update(const struct trk_pda *pda, int nx, const trk_real *h, const trk_real *r,
                         trk_real *x, trk_real *p, const struct trk_innovation *inn, size_t m,
                         const trk_real *z, const trk_real *log_lr, trk_real *beta, trk_real *d2,
                         struct trk_pda_report *rep)
{
    trk_status st = check_args(pda, nx, h, r, x, p, m, z, beta);
    if (st != TRK_OK) return st;
    const int nz = pda->params.nz;
#if !TRK_SIZE_OPT /* a copy unrolled for the CV model (speed); size builds keep one */
    if (nx == TRK_CV2_NX && nz == TRK_CV2_NZ)
        return pda_update(pda, TRK_CV2_NX, TRK_CV2_NZ, h, r, x, p, inn, m, z, log_lr, beta, d2, rep);
#endif
    return pda_update(pda, nx, nz, h, r, x, p, inn, m, z, log_lr, beta, d2, rep);
}

trk_status trk_pda_update(const struct trk_pda *pda, int nx, const trk_real *h, const trk_real *r,
                          trk_real *x, trk_real *p, size_t m, const trk_real *z,
                          const trk_real *log_lr, trk_real *beta, trk_real *d2,
                          struct trk_pda_report *rep)
{
    return update(pda, nx, h, r, x, p, NULL, m, z, log_lr, beta, d2, rep);
}

trk_status trk_pda_update_inn(const struct trk_pda *pda, int nx, const trk_real *h, const trk_real *r,
                              trk_real *x, trk_real *p, const struct trk_innovation *inn, size_t m,
                              const trk_real *z, const trk_real *log_lr, trk_real *beta, trk_real *d2,
                              struct trk_pda_report *rep)
{
    if (!inn || !pda || inn->nz != pda->params.nz) return TRK_E_ARG;
    return update(pda, nx, h, r, x, p, inn, m, z, log_lr, beta, d2, rep);
}

trk_status trk_pda_update_weights(int nx, const trk_real *h, const trk_real *r, trk_real *x, trk_real *p,
                                  const struct trk_innovation *inn, size_t m, const trk_real *z,
                                  const trk_real *beta)
{
    if (!h || !r || !x || !p || !inn || !beta || (m > 0 && !z)) return TRK_E_ARG;
    const int nz = inn->nz;
    if (nz < 1 || nz > TRK_MAX_MEAS || nx < nz || nx > TRK_MAX_STATE) return TRK_E_ARG;
    if (m > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    trk_real sum = 0;
    for (size_t i = 0; i <= m; i++) {
        if (!isfinite(beta[i])) return TRK_E_NAN;
        if (!(beta[i] >= 0 && beta[i] <= 1)) return TRK_E_RANGE;
        sum += beta[i];
    }
    if (!(trk_fabs(sum - 1) <= TRK_REAL_C(1e-3))) return TRK_E_RANGE;
    for (size_t i = 0; i < m * (size_t)nz; i++)
        if (!isfinite(z[i])) return TRK_E_NAN;
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    int sel_idx[TRK_MAX_MEAS];
    const int *sel = trk_i_h_select(nx, nz, h, sel_idx) ? sel_idx : NULL;
    trk_i_mul_ht(nx, nx, nz, p, h, sel, pht);
    const struct trk_i_pda_pred pred = {nx, nz, h, sel, r, x, p, pht, inn};
    /* the combination only reads the weights (s->w is not const for the
     * update that normalises them in place) */
    const struct trk_i_pda_set set = {m, m, m, z, (trk_real *)(uintptr_t)(beta + 1), NULL, 0, 0};
    return trk_i_pda_update_beta_rt(&pred, &set, beta[0]);
}
