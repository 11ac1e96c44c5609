/* pda_impl.h (private) - stages of the PDA update shared by pda.c (one track,
 * public API) and tracker.c (a whole scan). See trk/pda.h for the formulas. */
#ifndef TRK_PDA_IMPL_H
#define TRK_PDA_IMPL_H

#include "kalman_impl.h"
#include "trk/pda.h"

/* ln e_i = ln P_D - (nz/2) ln 2pi - (1/2) ln det S - d2/2 + ln l^a */
TRK_INLINE trk_real trk_i_pda_log_e(const struct trk_pda *pda, trk_real log_det_s, trk_real d2,
                                       trk_real log_lr)
{
    return pda->log_pd_norm - TRK_REAL_C(0.5) * (log_det_s + d2) + log_lr;
}

/* V_G = c_nz gamma^(nz/2) sqrt(det S) */
TRK_INLINE trk_real trk_i_pda_gate_volume(const struct trk_pda *pda, const struct trk_innovation *inn)
{
    return inn->sqrt_det_s <= TRK_REAL_MAX ? pda->gate_const * inn->sqrt_det_s
                                           : pda->gate_const * trk_exp(TRK_REAL_C(0.5) * inn->log_det_s);
}

/* ln e_0 = ln lambda + ln(1 - P_D P_G); precomputed for parametric clutter */
TRK_INLINE trk_real trk_i_pda_log_e0(const struct trk_pda *pda, trk_real lambda)
{
    return pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->log_e0_param
                                                        : trk_log(lambda) + pda->log_miss;
}

/* Normalise in the log domain: log_e0 and log_w[0..n) (in) -> beta0 and
 * w[0..n) = beta_i (out, in place). When every weight is zero (e.g. no
 * detection and lambda = 0) beta0 = 1. If log_sum_meas is not NULL it gets
 * ln sum_i e_i over the detections (-inf when there are none). */
TRK_INLINE trk_real trk_i_pda_normalise(trk_real log_e0, size_t n, trk_real *w, trk_real *log_sum_meas)
{
    trk_real mx = log_e0;
    for (size_t i = 0; i < n; i++)
        if (w[i] > mx) mx = w[i];
    if (!(mx > -TRK_REAL_MAX)) { /* all -inf */
        for (size_t i = 0; i < n; i++) w[i] = 0;
        if (log_sum_meas) *log_sum_meas = -(trk_real)INFINITY;
        return 1;
    }
    trk_real e0 = trk_exp(log_e0 - mx), sum_meas = 0;
    for (size_t i = 0; i < n; i++) {
        w[i] = trk_exp(w[i] - mx);
        sum_meas += w[i];
    }
    if (log_sum_meas) *log_sum_meas = sum_meas > 0 ? mx + trk_log(sum_meas) : -(trk_real)INFINITY;
    trk_real inv = 1 / (e0 + sum_meas);
    for (size_t i = 0; i < n; i++) w[i] *= inv;
    return e0 * inv;
}

/* u = P- H' L^-T (nx x nz), so that K = u L^-1 and K nu = u y with the
 * whitened innovation y = L^-1 nu (S = L L'). */
TRK_INLINE void trk_i_pda_u(int nx, int nz, const trk_real *pht, const trk_real *l_inv, trk_real *u)
{
    for (int a = 0; a < nx; a++)
        for (int j = 0; j < nz; j++) {
            trk_real s = 0;
            for (int t = 0; t <= j; t++) s += pht[a * nz + t] * l_inv[j * nz + t];
            u[a * nz + j] = s;
        }
}

/* y = L^-1 (z - z_pred) */
TRK_INLINE void trk_i_pda_whiten(int nz, const trk_real *l_inv, const trk_real *z,
                                 const trk_real *z_pred, trk_real *y)
{
    trk_real nu[TRK_MAX_MEAS];
    for (int t = 0; t < nz; t++) nu[t] = z[t] - z_pred[t];
    trk_i_tril_mul(nz, l_inv, nu, y);
}

/* acc (upper triangle, nx x nx) += w d d' */
TRK_INLINE void trk_i_pda_rank1(int nx, trk_real *acc, trk_real w, const trk_real *d)
{
    for (int a = 0; a < nx; a++) {
        trk_real wd = w * d[a];
        for (int b = a; b < nx; b++) acc[a * nx + b] += wd * d[b];
    }
}

/* The PDA state and covariance update (CONVENTIONS "PDA") as the moment
 * match of a Gaussian mixture, written so that every term is positive
 * semi-definite. Hypothesis i (beta_i, innovation nu_i = z_i - z_pred) moves
 * the state by dx_i = K_i nu_i = u_i y_i; hypothesis 0 (beta0) by 0:
 *   x = x- + dxbar,  dxbar = sum_i beta_i dx_i
 *   P = beta0 P- + pc_sum + sum_i beta_i (dx_i - dxbar)(dx_i - dxbar)' + beta0 dxbar dxbar'
 * pc_sum = sum_i beta_i P_c,i is supplied by the caller.
 * Detections that share one S (the sensor's covariance) form one group G
 * with u = P- H' L^-T; its part of the sum is split by the law of total
 * variance into u W u' + B (u ybar - dxbar)(u ybar - dxbar)', with
 * B = sum_G beta_i, ybar = sum_G beta_i y_i / B, W = sum_G beta_i (y_i - ybar)(y_i - ybar)',
 * so each shared detection costs only nz-dimensional work. With that group
 * alone this is exactly the standard form
 *   P = beta0 P- + (1 - beta0) P_c + K (sum beta_i nu_i nu_i' - nubar nubar') K'.
 * Detections with their own covariance R_j (own S_j = L_j L_j') enter one by
 * one with their own u_j.
 *   shared group: n rows of z at z_stride, beta[n], its l_inv = L^-1
 *   own: n1 rows of z1 (stride nz), beta1[n1], l_inv1 at stride nz*nz
 * Entries with beta = 0 are skipped. x_out/p_out may alias x_pred/p_pred. */
TRK_INLINE void trk_i_pda_combine(int nx, int nz, const trk_real *x_pred, const trk_real *p_pred,
                                  const trk_real *pht, const trk_real *z_pred, trk_real beta0,
                                  size_t n, const trk_real *z, size_t z_stride,
                                  const trk_real *beta, const trk_real *l_inv, size_t n1,
                                  const trk_real *z1, const trk_real *beta1,
                                  const trk_real *l_inv1, const trk_real *pc_sum, trk_real *x_out,
                                  trk_real *p_out)
{
    trk_real u[TRK_MAX_STATE * TRK_MAX_MEAS], uj[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_real sy[TRK_MAX_MEAS] = {0}, y[TRK_MAX_MEAS], d[TRK_MAX_STATE];
    trk_real dxbar[TRK_MAX_STATE], acc[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_real bsum = 0;
    /* pass 1: group sums and the mean move */
    trk_i_pda_u(nx, nz, pht, l_inv, u);
    for (size_t i = 0; i < n; i++) {
        if (beta[i] == 0) continue;
        trk_i_pda_whiten(nz, l_inv, z + i * z_stride, z_pred, y);
        bsum += beta[i];
        for (int t = 0; t < nz; t++) sy[t] += beta[i] * y[t];
    }
    trk_i_mat_mul(nx, nz, 1, u, sy, dxbar);
    for (size_t j = 0; j < n1; j++) {
        if (beta1[j] == 0) continue;
        trk_i_pda_u(nx, nz, pht, l_inv1 + j * (size_t)(nz * nz), uj);
        trk_i_pda_whiten(nz, l_inv1 + j * (size_t)(nz * nz), z1 + j * (size_t)nz, z_pred, y);
        trk_i_mat_mul(nx, nz, 1, uj, y, d);
        for (int a = 0; a < nx; a++) dxbar[a] += beta1[j] * d[a];
    }
    for (int a = 0; a < nx; a++)
        for (int b = a; b < nx; b++)
            acc[a * nx + b] = beta0 * (p_pred[a * nx + b] + dxbar[a] * dxbar[b]) + pc_sum[a * nx + b];
    /* pass 2: spreads */
    if (bsum > 0) {
        trk_real ybar[TRK_MAX_MEAS], w[TRK_MAX_MEAS * TRK_MAX_MEAS] = {0};
        trk_real uw[TRK_MAX_STATE * TRK_MAX_MEAS];
        for (int t = 0; t < nz; t++) ybar[t] = sy[t] / bsum;
        for (size_t i = 0; i < n; i++) {
            if (beta[i] == 0) continue;
            trk_i_pda_whiten(nz, l_inv, z + i * z_stride, z_pred, y);
            for (int t = 0; t < nz; t++) y[t] -= ybar[t];
            for (int s = 0; s < nz; s++)
                for (int t = s; t < nz; t++) w[s * nz + t] += beta[i] * y[s] * y[t];
        }
        for (int s = 0; s < nz; s++)
            for (int t = s + 1; t < nz; t++) w[t * nz + s] = w[s * nz + t];
        trk_i_mat_mul(nx, nz, nz, u, w, uw);
        for (int a = 0; a < nx; a++)
            for (int b = a; b < nx; b++) {
                trk_real s = 0;
                for (int t = 0; t < nz; t++) s += uw[a * nz + t] * u[b * nz + t];
                acc[a * nx + b] += s;
            }
        trk_i_mat_mul(nx, nz, 1, u, ybar, d);
        for (int a = 0; a < nx; a++) d[a] -= dxbar[a];
        trk_i_pda_rank1(nx, acc, bsum, d);
    }
    for (size_t j = 0; j < n1; j++) {
        if (beta1[j] == 0) continue;
        trk_i_pda_u(nx, nz, pht, l_inv1 + j * (size_t)(nz * nz), uj);
        trk_i_pda_whiten(nz, l_inv1 + j * (size_t)(nz * nz), z1 + j * (size_t)nz, z_pred, y);
        trk_i_mat_mul(nx, nz, 1, uj, y, d);
        for (int a = 0; a < nx; a++) d[a] -= dxbar[a];
        trk_i_pda_rank1(nx, acc, beta1[j], d);
    }
    for (int a = 0; a < nx; a++) {
        x_out[a] = x_pred[a] + dxbar[a];
        for (int b = a; b < nx; b++) p_out[a * nx + b] = p_out[b * nx + a] = acc[a * nx + b];
    }
}

#endif
