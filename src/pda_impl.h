/* pda_impl.h (private) - stages of the PDA update shared by pda.c (one track,
 * public API) and tracker.c (a whole scan). See trk/pda.h for the formulas. */
#ifndef TRK_PDA_IMPL_H
#define TRK_PDA_IMPL_H

#include "kalman_impl.h"
#include "trk/pda.h"

/* ln e_i = ln P_D - (nz/2) ln 2pi - (1/2) ln det S - d2/2 + ln l^a */
static inline trk_real trk_i_pda_log_e(const struct trk_pda *pda, trk_real log_det_s, trk_real d2,
                                       trk_real log_lr)
{
    return pda->log_pd_norm - TRK_REAL_C(0.5) * (log_det_s + d2) + log_lr;
}

/* Normalise in the log domain: log_e0 and log_w[0..n) (in) -> beta0 and
 * w[0..n) = beta_i (out, in place). When every weight is zero (e.g. no
 * detection and lambda = 0) beta0 = 1. */
static inline trk_real trk_i_pda_normalise(trk_real log_e0, size_t n, trk_real *w)
{
    trk_real mx = log_e0;
    for (size_t i = 0; i < n; i++)
        if (w[i] > mx) mx = w[i];
    if (!(mx > -TRK_REAL_MAX)) { /* all -inf */
        for (size_t i = 0; i < n; i++) w[i] = 0;
        return 1;
    }
    trk_real e0 = trk_exp(log_e0 - mx), sum = e0;
    for (size_t i = 0; i < n; i++) {
        w[i] = trk_exp(w[i] - mx);
        sum += w[i];
    }
    trk_real inv = 1 / sum;
    for (size_t i = 0; i < n; i++) w[i] *= inv;
    return e0 * inv;
}

/* dx = K_i nu = P H' S_i^-1 nu (nx): the gain applied without forming K_i. */
static inline void trk_i_pda_dx(int nx, int nz, const trk_real *pht, const trk_real *s_chol,
                                const trk_real *nu, trk_real *dx)
{
    trk_real w[TRK_MAX_MEAS];
    trk_i_chol_forward(nz, s_chol, nu, w);
    trk_i_chol_backward(nz, s_chol, w, w);
    trk_i_mat_mul(nx, nz, 1, pht, w, dx);
}

/* Mixture combination (the PDA state and covariance update, CONVENTIONS
 * "PDA", written so that every term is positive semi-definite):
 *   dx_i = K_i nu_i = P- H' S_i^-1 nu_i, nu_i = z_i - z_pred, dxbar = sum beta_i dx_i
 *   x = x- + dxbar
 *   P = beta0 P- + pc_sum + sum_i beta_i (dx_i - dxbar)(dx_i - dxbar)' + beta0 dxbar dxbar'
 * pc_sum = sum_i beta_i P_c,i (= (1 - beta0) P_c when all share one S).
 * With one S for every detection this is exactly the standard PDA covariance
 * (the spread term equals K (sum beta_i nu_i nu_i' - nubar nubar') K'); a
 * detection with its own covariance R_i brings its own S_i (moment-matched
 * Gaussian mixture, the same formula).
 * z: n rows at z_stride; s_chol: Cholesky factors of S_i at s_stride reals
 * (0: one S). Entries with beta_i = 0 are skipped. x_out/p_out may alias
 * x_pred/p_pred. */
static inline void trk_i_pda_combine(int nx, int nz, const trk_real *x_pred, const trk_real *p_pred,
                                     const trk_real *pht, const trk_real *z_pred, trk_real beta0,
                                     size_t n, const trk_real *z, size_t z_stride,
                                     const trk_real *beta, const trk_real *s_chol, size_t s_stride,
                                     const trk_real *pc_sum, trk_real *x_out, trk_real *p_out)
{
    trk_real dxbar[TRK_MAX_STATE] = {0};
    trk_real acc[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_real nu[TRK_MAX_MEAS], d[TRK_MAX_STATE];
    for (size_t i = 0; i < n; i++) {
        if (beta[i] == 0) continue;
        for (int t = 0; t < nz; t++) nu[t] = z[i * z_stride + t] - z_pred[t];
        trk_i_pda_dx(nx, nz, pht, s_chol + i * s_stride, nu, d);
        for (int a = 0; a < nx; a++) dxbar[a] += beta[i] * d[a];
    }
    for (int a = 0; a < nx; a++)
        for (int b = a; b < nx; b++)
            acc[a * nx + b] = beta0 * (p_pred[a * nx + b] + dxbar[a] * dxbar[b]) + pc_sum[a * nx + b];
    for (size_t i = 0; i < n; i++) {
        if (beta[i] == 0) continue;
        for (int t = 0; t < nz; t++) nu[t] = z[i * z_stride + t] - z_pred[t];
        trk_i_pda_dx(nx, nz, pht, s_chol + i * s_stride, nu, d);
        for (int a = 0; a < nx; a++) d[a] -= dxbar[a];
        for (int a = 0; a < nx; a++) {
            trk_real bd = beta[i] * d[a];
            for (int b = a; b < nx; b++) acc[a * nx + b] += bd * d[b];
        }
    }
    for (int a = 0; a < nx; a++) {
        x_out[a] = x_pred[a] + dxbar[a];
        for (int b = a; b < nx; b++) p_out[a * nx + b] = p_out[b * nx + a] = acc[a * nx + b];
    }
}

#endif
