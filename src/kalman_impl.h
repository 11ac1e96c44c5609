/* kalman_impl.h (private) - inline kernels of kalman.c, reused by pda.c and
 * tracker.c with constant dimensions. */
#ifndef TRK_KALMAN_IMPL_H
#define TRK_KALMAN_IMPL_H

#include "linalg_impl.h"
#include "trk/kalman.h"

/* The kernels marked TRK_I_KALMAN_KERNEL (gain, joseph_upper) are inline
 * everywhere except in size builds (TRK_SIZE_OPT), where kalman.c defines
 * the one external copy (TRK_I_KALMAN_DEFINE) that pda.c calls, as
 * linalg_impl.h does for the loop kernels (measured on the Cortex-M4F
 * library: 0.4 KB). trk_i_innovation_sel stays inline: its callers pass a
 * constant selection that the inlined copies fold, and as one external copy
 * it made the typical firmware image 308 B larger. */
#if !TRK_SIZE_OPT
#define TRK_I_KALMAN_KERNEL TRK_INLINE
#else
#ifdef TRK_I_KALMAN_DEFINE
#define TRK_I_KALMAN_KERNEL
#endif
void trk_i_gain(int nx, int nz, const trk_real *pht, const trk_real *s_chol_inv, trk_real *k);
void trk_i_joseph_upper(int nx, int nz, const trk_real *h, const int *sel, const trk_real *r, const trk_real *k,
                        const trk_real *p, const trk_real *pht, trk_real c, trk_real *pc);
#endif

/* P = F P F' + Q, x = F x. */
TRK_INLINE void trk_i_predict(int nx, const trk_real *f, const trk_real *q, trk_real *x,
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

/* CV model: F = blkdiag(F1, F1), F1 = [[1, T], [0, 1]]. Each 2x2 block B of P
 * maps to F1 B F1' = [[b00 + T (b01 + b10) + T^2 b11, b01 + T b11],
 *                     [b10 + T b11,                   b11]]
 * and Q adds q [[T^3/3, T^2/2], [T^2/2, T]] to the diagonal blocks. */
TRK_INLINE void trk_i_cv2_predict(trk_real t, trk_real q, trk_real *x, trk_real *p)
{
    const trk_real t2 = t * t;
    const trk_real qa = q * t2 * t / 3, qb = q * t2 / 2, qc = q * t;
    x[0] += t * x[1];
    x[2] += t * x[3];
    for (int bi = 0; bi < 4; bi += 2)
        for (int bj = 0; bj < 4; bj += 2) {
            trk_real *r0 = p + bi * 4 + bj, *r1 = r0 + 4;
            const trk_real b00 = r0[0], b01 = r0[1], b10 = r1[0], b11 = r1[1];
            r0[0] = b00 + t * (b01 + b10) + t2 * b11;
            r0[1] = b01 + t * b11;
            r1[0] = b10 + t * b11;
            if (bi == bj) {
                r0[0] += qa;
                r0[1] += qb;
                r1[0] += qb;
                r1[1] += qc;
            }
        }
    trk_i_symmetrize(4, p);
}

/* The components the 2-D CV model's H selects (x, y), as a constant the
 * inlined kernels fold into their indexing. */
TRK_INLINE const int *trk_i_cv2_sel(void)
{
    static const int sel[TRK_CV2_NZ] = {TRK_CV2_X, TRK_CV2_Y};
    return sel;
}

/* Does H (nz x nx) only select state components (each row one 1, the rest
 * 0)? Then idx[j] is the component row j selects and the products with H
 * below become copies (the 2-D CV model's H picks x and y). */
TRK_INLINE int trk_i_h_select(int nx, int nz, const trk_real *h, int *idx)
{
    for (int j = 0; j < nz; j++) {
        int one = -1;
        for (int i = 0; i < nx; i++) {
            const trk_real v = h[j * nx + i];
            if (v == 1 && one < 0) one = i;
            else if (v != 0) return 0;
        }
        if (one < 0) return 0;
        idx[j] = one;
    }
    return 1;
}

/* Y (n x nz) = A (n x nx) H' with H general, or picking columns idx of A. */
TRK_INLINE void trk_i_mul_ht(int n, int nx, int nz, const trk_real *a, const trk_real *h, const int *sel,
                             trk_real *y)
{
    if (sel) {
        for (int i = 0; i < n; i++)
            for (int j = 0; j < nz; j++) y[i * nz + j] = a[i * nx + sel[j]];
    } else {
        trk_i_mat_mul_abt(n, nx, nz, a, h, y);
    }
}

/* PH' (nx x nz), S = H P H' + R, its Cholesky factor and log-determinant. */
TRK_INLINE trk_status trk_i_innovation_sel(int nx, int nz, const trk_real *h, const int *sel,
                                          const trk_real *r, const trk_real *x, const trk_real *p,
                                          trk_real *pht, struct trk_innovation *inn)
{
    trk_i_mul_ht(nx, nx, nz, p, h, sel, pht);
    if (sel) {
        for (int j = 0; j < nz; j++) inn->z_pred[j] = x[sel[j]];
        for (int j = 0; j < nz; j++)
            for (int k = 0; k < nz; k++) inn->s[j * nz + k] = pht[sel[j] * nz + k] + r[j * nz + k];
    } else {
        trk_i_mat_mul(nz, nx, 1, h, x, inn->z_pred);
        trk_i_mat_mul(nz, nx, nz, h, pht, inn->s);
        for (int i = 0; i < nz * nz; i++) inn->s[i] += r[i];
    }
    trk_i_symmetrize(nz, inn->s);
    inn->nz = nz;
    trk_real sqrt_det = 1;
    /* 2 x 2: in closed form (speed; size builds keep the loop alone) */
    if (TRK_SIZE_OPT || nz != 2 || !trk_i_chol2(inn->s, inn->s_chol, inn->s_chol_inv, &sqrt_det)) {
        trk_status st = trk_i_chol(nz, inn->s, inn->s_chol);
        if (st != TRK_OK) return st;
        trk_i_tril_inverse(nz, inn->s_chol, inn->s_chol_inv);
        sqrt_det = 1;
        for (int i = 0; i < nz; i++) sqrt_det *= inn->s_chol[i * nz + i]; /* = prod L_ii */
    }
    /* one log instead of nz; the product of nz <= 3 square roots of finite
     * pivots overflows only in float for |S| above ~1e25 */
    inn->log_det_s = (sqrt_det > 0 && sqrt_det <= TRK_REAL_MAX) ? 2 * trk_log(sqrt_det)
                                                                : trk_i_chol_logdet(nz, inn->s_chol);
    inn->sqrt_det_s = sqrt_det;
    return TRK_OK;
}

/* The same with H general (no selection shortcut). */
TRK_INLINE trk_status trk_i_innovation(int nx, int nz, const trk_real *h, const trk_real *r,
                                      const trk_real *x, const trk_real *p, trk_real *pht,
                                      struct trk_innovation *inn)
{
    return trk_i_innovation_sel(nx, nz, h, NULL, r, x, p, pht, inn);
}

#ifdef TRK_I_KALMAN_KERNEL
/* K = P H' S^-1 = P H' L^-T L^-1 (row i of K: L^-T L^-1 (PH')_i'). */
TRK_I_KALMAN_KERNEL void trk_i_gain(int nx, int nz, const trk_real *pht, const trk_real *s_chol_inv, trk_real *k)
{
    for (int i = 0; i < nx; i++) {
        trk_real y[TRK_MAX_MEAS];
        trk_i_tril_mul(nz, s_chol_inv, pht + i * nz, y);
        trk_i_tril_mul_t(nz, s_chol_inv, y, k + i * nz);
    }
}

/* Joseph form Pc = (I - K H) P (I - K H)' + K R K', evaluated as
 *   A = (I - K H) P = P - K (P H')',   Pc = A - (A H' - K R) K'.
 * A H' - K R vanishes in exact arithmetic (K S = P H'); forming it keeps the
 * Joseph form's first-order insensitivity to errors in K at about half the
 * cost of the three explicit products. pht = P H' (given); sel as for
 * trk_i_innovation_sel. The upper triangle of Pc (a <= b) only, scaled by
 * c: pc[a][b] = c Pc_ab (the PDA's B P_c); the lower is left as it was. */
TRK_I_KALMAN_KERNEL void trk_i_joseph_upper(int nx, int nz, const trk_real *h, const int *sel, const trk_real *r,
                                            const trk_real *k, const trk_real *p, const trk_real *pht, trk_real c,
                                            trk_real *pc)
{
    /* A H' = P H' - K (H P H') (H P H' = H pht, nz x nz), so A itself is
     * formed only where Pc needs it, entry by entry (no nx x nx array) */
    trk_real hph[TRK_MAX_MEAS * TRK_MAX_MEAS], e[TRK_MAX_STATE * TRK_MAX_MEAS];
    if (sel) {
        for (int j = 0; j < nz; j++)
            for (int t = 0; t < nz; t++) hph[j * nz + t] = pht[sel[j] * nz + t];
    } else {
        trk_i_mat_mul(nz, nx, nz, h, pht, hph);
    }
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < nz; j++) {
            trk_real s = pht[i * nz + j];
            for (int t = 0; t < nz; t++) s -= k[i * nz + t] * (hph[j * nz + t] + r[t * nz + j]);
            e[i * nz + j] = s; /* A H' - K R */
        }
    for (int i = 0; i < nx; i++)
        for (int j = i; j < nx; j++) {
            trk_real s = p[i * nx + j];
            for (int t = 0; t < nz; t++) s -= k[i * nz + t] * pht[j * nz + t] + e[i * nz + t] * k[j * nz + t];
            pc[i * nx + j] = c * s; /* A - E K' is symmetric in exact arithmetic */
        }
}
#endif

/* The whole Pc (symmetric). */
TRK_INLINE void trk_i_joseph_sel(int nx, int nz, const trk_real *h, const int *sel, const trk_real *r,
                                 const trk_real *k, const trk_real *p, const trk_real *pht, trk_real *pc)
{
    trk_i_joseph_upper(nx, nz, h, sel, r, k, p, pht, 1, pc);
    for (int i = 0; i < nx; i++)
        for (int j = i + 1; j < nx; j++) pc[j * nx + i] = pc[i * nx + j];
}

/* The same with H general; P H' computed here. */
TRK_INLINE void trk_i_joseph(int nx, int nz, const trk_real *h, const trk_real *r, const trk_real *k,
                             const trk_real *p, trk_real *pc)
{
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_i_mat_mul_abt(nx, nx, nz, p, h, pht);
    trk_i_joseph_sel(nx, nz, h, NULL, r, k, p, pht, pc);
}

/* d2 = nu' S^-1 nu = |L^-1 nu|^2 (a sum of squares: never negative). */
TRK_INLINE trk_real trk_i_mahalanobis2(int nz, const trk_real *s_chol_inv, const trk_real *nu)
{
    trk_real y[TRK_MAX_MEAS];
    trk_real d2 = 0;
    trk_i_tril_mul(nz, s_chol_inv, nu, y);
    for (int i = 0; i < nz; i++) d2 += y[i] * y[i];
    return d2;
}

#endif
