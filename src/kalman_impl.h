/* kalman_impl.h (private) - inline kernels of kalman.c, reused by pda.c and
 * tracker.c with constant dimensions. */
#ifndef TRK_KALMAN_IMPL_H
#define TRK_KALMAN_IMPL_H

#include "linalg_impl.h"
#include "trk/kalman.h"

/* P = F P F' + Q, x = F x. */
static inline void trk_i_predict(int nx, const trk_real *f, const trk_real *q, trk_real *x,
                                 trk_real *p)
{
    trk_real fp[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_real xn[TRK_MAX_STATE];
    trk_i_mat_mul(nx, nx, 1, f, x, xn);
    trk_i_mat_mul(nx, nx, nx, f, p, fp);
    trk_i_mat_mul_abt(nx, nx, nx, fp, f, p);
    for (int i = 0; i < nx * nx; i++) p[i] += q[i];
    trk_i_symmetrize(nx, p);
    for (int i = 0; i < nx; i++) x[i] = xn[i];
}

/* PH' (nx x nz), S = H P H' + R, its Cholesky factor and log-determinant. */
static inline trk_status trk_i_innovation(int nx, int nz, const trk_real *h, const trk_real *r,
                                          const trk_real *x, const trk_real *p, trk_real *pht,
                                          struct trk_innovation *inn)
{
    trk_i_mat_mul_abt(nx, nx, nz, p, h, pht);
    trk_i_mat_mul(nz, nx, 1, h, x, inn->z_pred);
    trk_i_mat_mul(nz, nx, nz, h, pht, inn->s);
    for (int i = 0; i < nz * nz; i++) inn->s[i] += r[i];
    trk_i_symmetrize(nz, inn->s);
    inn->nz = nz;
    trk_status st = trk_i_chol(nz, inn->s, inn->s_chol);
    if (st != TRK_OK) return st;
    inn->log_det_s = trk_i_chol_logdet(nz, inn->s_chol);
    return TRK_OK;
}

/* K = P H' S^-1: row i of K solves S k_i' = (PH')_i' (S symmetric). */
static inline void trk_i_gain(int nx, int nz, const trk_real *pht, const trk_real *s_chol,
                              trk_real *k)
{
    for (int i = 0; i < nx; i++) {
        trk_real y[TRK_MAX_MEAS];
        trk_i_chol_forward(nz, s_chol, pht + i * nz, y);
        trk_i_chol_backward(nz, s_chol, y, k + i * nz);
    }
}

/* Pc = (I - K H) P (I - K H)' + K R K'. */
static inline void trk_i_joseph(int nx, int nz, const trk_real *h, const trk_real *r,
                                const trk_real *k, const trk_real *p, trk_real *pc)
{
    trk_real a[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_real ap[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_real kr[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_i_mat_mul(nx, nz, nx, k, h, a);
    for (int i = 0; i < nx * nx; i++) a[i] = -a[i];
    for (int i = 0; i < nx; i++) a[i * nx + i] += 1;
    trk_i_mat_mul(nx, nx, nx, a, p, ap);
    trk_i_mat_mul_abt(nx, nx, nx, ap, a, pc);
    trk_i_mat_mul(nx, nz, nz, k, r, kr);
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < nx; j++) {
            trk_real s = 0;
            for (int t = 0; t < nz; t++) s += kr[i * nz + t] * k[j * nz + t];
            pc[i * nx + j] += s;
        }
    trk_i_symmetrize(nx, pc);
}

/* d2 = nu' S^-1 nu = |L^-1 nu|^2. */
static inline trk_real trk_i_mahalanobis2(int nz, const trk_real *s_chol, const trk_real *nu)
{
    trk_real y[TRK_MAX_MEAS];
    trk_real d2 = 0;
    trk_i_chol_forward(nz, s_chol, nu, y);
    for (int i = 0; i < nz; i++) d2 += y[i] * y[i];
    return d2;
}

#endif
