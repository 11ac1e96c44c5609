/** @file
 * trk/irf.h - the PDAF's information-reduction factor by deterministic
 * quadrature: q2 as a function of lambda_vg, and its parts conditioned on the
 * number of gated measurements (the conditional factors HYCA needs).
 *
 * Definition (docs/conventions.md "q2, MRE and CRLB"; Brekke 2011 eqs 28-30,
 * 38): with the target detected and gated, n clutter points uniform in the
 * gate, L_i = exp(-rho_i^2 / 2) the Gaussian kernel of point i and
 * b = (2 pi)^(nz/2) lambda_vg (1 - pd pg) / (pd c_nz gamma^(nz/2)),
 *   beta_1 = L_1 / (b + L_1 + sum_{j=2}^{n+1} L_j),
 *   q2     = pd F_{nz+2}(gamma) sum_{n>=0} Poisson(n; lambda_vg) E_n[beta_1],
 * rho_1^2 ~ chi2(nz+2) truncated to [0, gamma], rho_j = sqrt(gamma) U^(1/nz).
 *
 * Method. 1/x = int_0^inf exp(-t x) dt and the independence of the points
 * turn the (n+1)-dimensional expectation into one integral:
 *   E_n[beta_1] = int_0^inf exp(-t b) psi(t) phi(t)^n dt,
 *   phi(t) = E[exp(-t L_clutter)],   psi(t) = E[L_1 exp(-t L_1)],
 * and the Poisson sum into
 *   q2 = pd F int_0^inf exp(-t b) psi(t) exp(-lambda_vg (1 - phi(t))) dt.
 * phi and psi are radial integrals (composite 8-point Gauss-Legendre in rho,
 * panels TRK_IRF_PANEL_RHO wide); the t integral is the trapezoid rule in
 * s = ln t, step TRK_IRF_STEP_S, over [-40, gamma/2 + 4]: the integrand is
 * analytic in the strip |Im s| < pi/2, so the rule's error is about
 * exp(-pi^2 / step) (1e-21 at 0.2), and the ends cut less than 1e-17.
 * phi and psi depend on (nz, gamma) only: trk_irf_init tabulates them once,
 * and each evaluation is one pass over the nodes (no random numbers: the
 * result is a smooth, deterministic function of pd and lambda_vg).
 * Checked against the importance-sampling reference values (tests/test_irf.c).
 *
 * The amplitude-aided factor (PDAFAI) is not covered here: use q2 tables.
 * No heap, no global state.
 */
#ifndef TRK_IRF_H
#define TRK_IRF_H

#include "trk/types.h"

#define TRK_IRF_MAX_NODES 640          /**< nodes in s = ln t */
#define TRK_IRF_STEP_S TRK_REAL_C(0.2) /**< trapezoid step in s */
#define TRK_IRF_PANEL_RHO TRK_REAL_C(0.125) /**< radial panel width */
#define TRK_IRF_MAX_GAMMA TRK_REAL_C(150.0) /**< largest gate threshold (node budget) */

/** Tabulated phi and psi for one (nz, gamma); read-only after init. */
struct trk_irf {
    int nz;                         /**< 1..3 */
    trk_real gamma;                 /**< gate threshold on d2 */
    trk_real pg;                    /**< P(chi2(nz) <= gamma) */
    trk_real f_target;              /**< F_{nz+2}(gamma) = P(chi2(nz+2) <= gamma) */
    trk_real b_per_lambda_vg;       /**< (2 pi)^(nz/2) / (c_nz gamma^(nz/2)) */
    int n;                          /**< nodes used */
    trk_real t[TRK_IRF_MAX_NODES];  /**< t_k = exp(s_k) */
    trk_real w[TRK_IRF_MAX_NODES];  /**< step t_k psi(t_k) (the rule's weight) */
    trk_real phi[TRK_IRF_MAX_NODES];        /**< phi(t_k) */
    trk_real one_m_phi[TRK_IRF_MAX_NODES];  /**< 1 - phi(t_k), computed directly */
};

/** Tabulate phi and psi for nz in 1..3 and gate threshold gamma in
 * (0, TRK_IRF_MAX_GAMMA]. TRK_E_ARG NULL or bad nz, TRK_E_NAN non-finite
 * gamma, TRK_E_RANGE gamma out of range. *irf untouched on error. */
TRK_NODISCARD trk_status trk_irf_init(struct trk_irf *irf, int nz, trk_real gamma);

/** The PDA constant b at detection probability pd in (0, 1] and lambda_vg >= 0
 * (NaN on bad input). */
trk_real trk_irf_b(const struct trk_irf *irf, trk_real pd, trk_real lambda_vg);

/** e[n] = E_n[beta_1] for n = 0..n_max at PDA constant b >= 0.
 * TRK_E_ARG NULL or n_max < 0, TRK_E_NAN / TRK_E_RANGE bad b. */
TRK_NODISCARD trk_status trk_irf_beta1(const struct trk_irf *irf, trk_real b, int n_max, trk_real *e);

/** q2 of the PDAF at (pd, lambda_vg), pd in (0, 1], lambda_vg >= 0.
 * TRK_E_ARG NULL, TRK_E_NAN non-finite input, TRK_E_RANGE out of range. */
TRK_NODISCARD trk_status trk_irf_q2(const struct trk_irf *irf, trk_real pd, trk_real lambda_vg,
                                    trk_real *q2);

/** q2 at one pd as a function of lambda_vg: a trk_q2_fn (trk/q2.h) whose ctx is
 * a struct trk_irf_line, e.g. the MRE's q2_fn without a table. */
struct trk_irf_line {
    const struct trk_irf *irf;  /**< the integrals (trk_irf_init) */
    trk_real pd;  /**< detection probability, (0, 1] */
};
/** Evaluate q2 at lambda_vg for the struct trk_irf_line ctx (trk_irf_q2). */
TRK_NODISCARD trk_status trk_irf_line_eval(const void *ctx, trk_real lambda_vg, trk_real *q2);

#endif /* TRK_IRF_H */
