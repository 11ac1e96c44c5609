/* pda.c - one-track PDA update (trk/pda.h; CONVENTIONS "PDA", Brekke eqs 21-25). */
#include "trk/pda.h"

#include "pda_impl.h"
#include "trk/gate.h"

trk_status trk_pda_init(struct trk_pda *pda, const struct trk_pda_params *pr)
{
    if (!pda || !pr) return TRK_E_ARG;
    if (pr->nz < 1 || pr->nz > TRK_MAX_MEAS) return TRK_E_ARG;
    if (pr->clutter != TRK_CLUTTER_PARAMETRIC && pr->clutter != TRK_CLUTTER_NONPARAMETRIC)
        return TRK_E_ARG;
    if (pr->gating != 0 && pr->gating != 1) return TRK_E_ARG;
    if (!isfinite(pr->pd) || !isfinite(pr->gate_prob) || !isfinite(pr->clutter_density))
        return TRK_E_NAN;
    if (!(pr->pd > 0 && pr->pd <= 1)) return TRK_E_RANGE;
    if (pr->clutter == TRK_CLUTTER_PARAMETRIC && !(pr->clutter_density >= 0)) return TRK_E_RANGE;
    trk_real gamma;
    trk_status st = trk_gate_gamma(pr->nz, pr->gate_prob, &gamma);
    if (st != TRK_OK) return st;
    pda->params = *pr;
    pda->gamma = gamma;
    pda->log_pd_norm = trk_log(pr->pd) - TRK_REAL_C(0.5) * (trk_real)pr->nz * TRK_LN_2PI;
    pda->log_miss = trk_log1p(-pr->pd * pr->gate_prob);
    pda->log_e0_param = trk_log(pr->clutter_density) + pda->log_miss;
    pda->gate_const = trk_gate_unit_volume(pr->nz) * trk_pow(gamma, (trk_real)pr->nz / 2);
    return TRK_OK;
}

/* The update for given dimensions; called with constants for the 2-D CV
 * model so the compiler unrolls it, and with run-time dimensions otherwise. */
TRK_INLINE trk_status pda_update(const struct trk_pda *pda, const int nx, const int nz,
                                    const trk_real *h, const trk_real *r, trk_real *x, trk_real *p,
                                    size_t m, const trk_real *z, const trk_real *log_lr,
                                    trk_real *beta, trk_real *d2, struct trk_pda_report *rep)
{
    struct trk_innovation inn;
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_real xn[TRK_MAX_STATE], pn[TRK_MAX_STATE * TRK_MAX_STATE];

    int sel_idx[TRK_MAX_MEAS];
    const int *sel = trk_i_h_select(nx, nz, h, sel_idx) ? sel_idx : NULL;
    trk_status st = trk_i_innovation_sel(nx, nz, h, sel, r, x, p, pht, &inn);
    if (st != TRK_OK) return st;
    const trk_real vg = trk_i_pda_gate_volume(pda, &inn);

    /* d2, gate, unnormalised log weights (beta[] holds ln e_i, -inf outside) */
    int n_gated = 0;
    for (size_t i = 0; i < m; i++) {
        trk_real nu[TRK_MAX_MEAS];
        for (int t = 0; t < nz; t++) nu[t] = z[i * nz + t] - inn.z_pred[t];
        trk_real di = trk_i_mahalanobis2(nz, inn.s_chol_inv, nu);
        if (d2) d2[i] = di;
        int in = trk_gate_inside(di, pda->gamma);
        n_gated += in;
        beta[i] = (in || !pda->params.gating)
                      ? trk_i_pda_log_e(pda, inn.log_det_s, di, log_lr ? log_lr[i] : 0)
                      : -(trk_real)INFINITY;
    }
    const int n_hyp = pda->params.gating ? n_gated : (int)m;
    trk_real lambda = pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->params.clutter_density
                                                                   : (trk_real)n_hyp / vg;
    trk_real beta0 = 1;
    if (n_hyp > 0) {
        trk_real k[TRK_MAX_STATE * TRK_MAX_MEAS], pc[TRK_MAX_STATE * TRK_MAX_STATE];
        beta0 = trk_i_pda_normalise(trk_i_pda_log_e0(pda, lambda), m, beta, NULL);
        trk_i_gain(nx, nz, pht, inn.s_chol_inv, k);
        trk_i_joseph_sel(nx, nz, h, sel, r, k, p, pht, pc);
        for (int i = 0; i < nx * nx; i++) pc[i] *= 1 - beta0;
        trk_i_pda_combine(nx, nz, x, p, pht, inn.z_pred, beta0, m, z, (size_t)nz, beta,
                          inn.s_chol_inv, 0, NULL, NULL, NULL, pc, xn, pn);
        for (int i = 0; i < nx; i++)
            if (!isfinite(xn[i])) return TRK_E_NAN;
        for (int i = 0; i < nx * nx; i++)
            if (!isfinite(pn[i])) return TRK_E_NAN;
        for (int i = 0; i < nx; i++) x[i] = xn[i];
        for (int i = 0; i < nx * nx; i++) p[i] = pn[i];
    } else { /* nothing to associate (also nonparametric m_G = 0): x, P = prediction */
        for (size_t i = 0; i < m; i++) beta[i] = 0;
    }
    if (rep) {
        rep->beta0 = beta0;
        rep->n_gated = n_gated;
        rep->gate_volume = vg;
        rep->lambda = lambda;
    }
    return TRK_OK;
}

trk_status trk_pda_update(const struct trk_pda *pda, int nx, const trk_real *h, const trk_real *r,
                          trk_real *x, trk_real *p, size_t m, const trk_real *z,
                          const trk_real *log_lr, trk_real *beta, trk_real *d2,
                          struct trk_pda_report *rep)
{
    if (!pda || !h || !r || !x || !p || (m > 0 && (!z || !beta))) return TRK_E_ARG;
    const int nz = pda->params.nz;
    if (nx < nz || nx > TRK_MAX_STATE) return TRK_E_ARG;
    if (m > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    for (size_t i = 0; i < m * (size_t)nz; i++)
        if (!isfinite(z[i])) return TRK_E_NAN;
    if (log_lr)
        for (size_t i = 0; i < m; i++)
            if (!isfinite(log_lr[i])) return TRK_E_NAN;
#if !TRK_SIZE_OPT /* a copy unrolled for the CV model (speed); size builds keep one */
    if (nx == TRK_CV2_NX && nz == TRK_CV2_NZ)
        return pda_update(pda, TRK_CV2_NX, TRK_CV2_NZ, h, r, x, p, m, z, log_lr, beta, d2, rep);
#endif
    return pda_update(pda, nx, nz, h, r, x, p, m, z, log_lr, beta, d2, rep);
}
