/* irf.c - the PDAF's information-reduction factor by quadrature (trk/irf.h;
 * Brekke 2011 eqs 28-30, 38; docs/conventions.md "q2, MRE and CRLB"). */
#include "trk/irf.h"

#include "internal.h"
#include "trk/gate.h"
#include "trk/special.h"

/* 8-point Gauss-Legendre on [-1, 1]: nodes +-x[i], weights w[i] */
static const trk_real gl_x[4] = {TRK_REAL_C(0.1834346424956498), TRK_REAL_C(0.5255324099163290),
                                 TRK_REAL_C(0.7966664774136267), TRK_REAL_C(0.9602898564975363)};
static const trk_real gl_w[4] = {TRK_REAL_C(0.3626837833783620), TRK_REAL_C(0.3137066458778873),
                                 TRK_REAL_C(0.2223810344533745), TRK_REAL_C(0.1012285362903763)};

#define S_LO TRK_REAL_C(-40.0) /* exp(-40) = 4e-18: the cut-off low end */
#define S_HI_MARGIN TRK_REAL_C(4.0) /* exp(-t L_min) = exp(-e^4) = 2e-24 at the high end */

static trk_real ipow(trk_real x, int k)
{
    trk_real y = 1;
    while (k-- > 0) y *= x;
    return y;
}

/* Add one radial node (rho, weight of its quadrature) to the clutter and
 * target sums at every t node: phi += wc exp(-t L), psi += wt L exp(-t L). */
static void add_radial_node(struct trk_irf *irf, trk_real rho, trk_real wq, trk_real *psi,
                            trk_real *norm_c, trk_real *norm_t)
{
    const int nz = irf->nz;
    const trk_real r2 = rho * rho, l = trk_exp(-r2 / 2);
    const trk_real wc = wq * ipow(rho, nz - 1);     /* clutter: density ~ rho^(nz-1) */
    const trk_real wt = wq * ipow(rho, nz + 1) * l; /* target: chi(nz+2) ~ rho^(nz+1) e^(-rho^2/2) */
    *norm_c += wc;
    *norm_t += wt;
    for (int k = 0; k < irf->n; k++) {
        const trk_real tl = irf->t[k] * l, e = trk_exp(-tl);
        irf->phi[k] += wc * e;
        irf->one_m_phi[k] += wc * -trk_expm1(-tl);
        psi[k] += wt * l * e;
    }
}

trk_status trk_irf_init(struct trk_irf *irf, int nz, trk_real gamma)
{
    if (!irf || nz < 1 || nz > 3) return TRK_E_ARG;
    if (!isfinite(gamma)) return TRK_E_NAN;
    if (!(gamma > 0 && gamma <= TRK_IRF_MAX_GAMMA)) return TRK_E_RANGE;
    struct trk_irf m;
    m.nz = nz;
    m.gamma = gamma;
    m.pg = trk_chi2_cdf(nz, gamma);
    m.f_target = trk_chi2_cdf(nz + 2, gamma);
    m.b_per_lambda_vg = trk_pow(2 * TRK_PI, (trk_real)nz / 2) /
                        (trk_gate_unit_volume(nz) * trk_pow(gamma, (trk_real)nz / 2));
    const trk_real s_hi = gamma / 2 + S_HI_MARGIN;
    m.n = (int)trk_floor((s_hi - S_LO) / TRK_IRF_STEP_S) + 2;
    trk_real psi[TRK_IRF_MAX_NODES];
    for (int k = 0; k < m.n; k++) {
        m.t[k] = trk_exp(S_LO + (trk_real)k * TRK_IRF_STEP_S);
        m.phi[k] = m.one_m_phi[k] = psi[k] = 0;
    }
    /* radial integrals over rho in [0, sqrt(gamma)], composite Gauss-Legendre */
    const trk_real rho_max = trk_sqrt(gamma);
    const int panels = (int)trk_floor(rho_max / TRK_IRF_PANEL_RHO) + 1;
    const trk_real half = rho_max / (trk_real)(2 * panels);
    trk_real norm_c = 0, norm_t = 0;
    for (int p = 0; p < panels; p++) {
        const trk_real mid = (trk_real)(2 * p + 1) * half;
        for (int i = 0; i < 4; i++) {
            add_radial_node(&m, mid - half * gl_x[i], half * gl_w[i], psi, &norm_c, &norm_t);
            add_radial_node(&m, mid + half * gl_x[i], half * gl_w[i], psi, &norm_c, &norm_t);
        }
    }
    /* normalise the densities by their own quadrature (E[1] = 1 exactly);
     * the trapezoid weight in s is step * t (dt = t ds) */
    for (int k = 0; k < m.n; k++) {
        m.phi[k] /= norm_c;
        m.one_m_phi[k] /= norm_c;
        m.w[k] = TRK_IRF_STEP_S * m.t[k] * psi[k] / norm_t;
    }
    *irf = m;
    return TRK_OK;
}

trk_real trk_irf_b(const struct trk_irf *irf, trk_real pd, trk_real lambda_vg)
{
    if (!irf || !(pd > 0 && pd <= 1) || !(lambda_vg >= 0)) return (trk_real)NAN;
    return irf->b_per_lambda_vg * lambda_vg * (1 - pd * irf->pg) / pd;
}

trk_status trk_irf_beta1(const struct trk_irf *irf, trk_real b, int n_max, trk_real *e)
{
    if (!irf || !e || n_max < 0) return TRK_E_ARG;
    if (isnan(b)) return TRK_E_NAN;
    if (!(b >= 0) || !isfinite(b)) return TRK_E_RANGE;
    for (int j = 0; j <= n_max; j++) e[j] = 0;
    for (int k = 0; k < irf->n; k++) {
        trk_real v = irf->w[k] * trk_exp(-b * irf->t[k]);
        for (int j = 0; j <= n_max && v != 0; j++) {
            e[j] += v;
            v *= irf->phi[k];
        }
    }
    return TRK_OK;
}

trk_status trk_irf_q2(const struct trk_irf *irf, trk_real pd, trk_real lambda_vg, trk_real *q2)
{
    if (!irf || !q2) return TRK_E_ARG;
    if (!isfinite(pd) || !isfinite(lambda_vg)) return TRK_E_NAN;
    if (!(pd > 0 && pd <= 1) || !(lambda_vg >= 0)) return TRK_E_RANGE;
    const trk_real b = trk_irf_b(irf, pd, lambda_vg);
    trk_real sum = 0;
    for (int k = 0; k < irf->n; k++)
        sum += irf->w[k] * trk_exp(-b * irf->t[k] - lambda_vg * irf->one_m_phi[k]);
    *q2 = pd * irf->f_target * sum;
    return TRK_OK;
}

trk_status trk_irf_line_eval(const void *ctx, trk_real lambda_vg, trk_real *q2)
{
    const struct trk_irf_line *l = ctx;
    if (!l) return TRK_E_ARG;
    return trk_irf_q2(l->irf, l->pd, lambda_vg, q2);
}
