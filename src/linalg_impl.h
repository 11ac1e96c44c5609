/* linalg_impl.h (private) - inline bodies of the small-matrix kernels.
 *
 * The public functions of linalg.c wrap these. Hot paths (tracker, pda) call
 * them directly with constant dimensions so the compiler unrolls the loops;
 * one implementation serves both. */
#ifndef TRK_LINALG_IMPL_H
#define TRK_LINALG_IMPL_H

#include "internal.h"
#include "trk/types.h"

TRK_INLINE void trk_i_mat_mul(int n, int k, int m, const trk_real *a, const trk_real *b,
                                 trk_real *c)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            trk_real s = 0;
            for (int t = 0; t < k; t++) s += a[i * k + t] * b[t * m + j];
            c[i * m + j] = s;
        }
}

TRK_INLINE void trk_i_mat_mul_abt(int n, int k, int m, const trk_real *a, const trk_real *b,
                                     trk_real *c)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            trk_real s = 0;
            for (int t = 0; t < k; t++) s += a[i * k + t] * b[j * k + t];
            c[i * m + j] = s;
        }
}

TRK_INLINE void trk_i_symmetrize(int n, trk_real *a)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            trk_real s = TRK_REAL_C(0.5) * (a[i * n + j] + a[j * n + i]);
            a[i * n + j] = s;
            a[j * n + i] = s;
        }
}

/* Cholesky-Banachiewicz. Rejects a pivot that is not > 0 or not finite
 * (a NaN pivot fails the comparison). */
TRK_INLINE trk_status trk_i_chol(int n, const trk_real *a, trk_real *l)
{
    for (int i = 0; i < n; i++) {
        for (int j = 0; j <= i; j++) {
            trk_real s = a[i * n + j];
            for (int t = 0; t < j; t++) s -= l[i * n + t] * l[j * n + t];
            if (i == j) {
                if (!(s > 0) || !(s <= TRK_REAL_MAX)) return TRK_E_NOT_SPD;
                l[i * n + i] = trk_sqrt(s);
            } else {
                l[i * n + j] = s / l[j * n + j];
            }
        }
        for (int j = i + 1; j < n; j++) l[i * n + j] = 0;
    }
    return TRK_OK;
}

/* Is the symmetric A (n x n, its lower triangle read) positive definite?
 * TRK_OK or TRK_E_NOT_SPD, by an LDL' factorisation without square roots:
 * every pivot d_i > 0 and finite (the test trk_mat_check_spd runs after its
 * symmetry and finiteness scans), for the tracker's and the PDA's posterior
 * checks. One division per pivot; a pivot whose reciprocal overflows (a
 * subnormal one) goes to trk_i_spd_div, which divides instead. trk_i_spd
 * is the out-of-line copy (linalg.c: its workspace stays off the callers'
 * frames; trk_mat_check_spd's test), so every check decides alike; the
 * inline one unrolls at a caller's constant n (the CV kernels). */
trk_status trk_i_spd(int n, const trk_real *a);
trk_status trk_i_spd_div(int n, const trk_real *a);
TRK_INLINE trk_status trk_i_spd_inline(int n, const trk_real *a)
{
    trk_real ld[TRK_MAX_STATE * TRK_MAX_STATE], inv_d[TRK_MAX_STATE]; /* ld[i][k] = L_ik d_k (i > k) */
    for (int j = 0; j < n; j++) {
        trk_real dj = a[j * n + j];
        for (int k = 0; k < j; k++) dj -= ld[j * n + k] * ld[j * n + k] * inv_d[k];
        if (!(dj > 0) || !(dj <= TRK_REAL_MAX)) return TRK_E_NOT_SPD;
        inv_d[j] = 1 / dj;
        if (!(inv_d[j] <= TRK_REAL_MAX)) return trk_i_spd_div(n, a); /* a subnormal pivot: divide */
        for (int i = j + 1; i < n; i++) {
            trk_real v = a[i * n + j];
            for (int k = 0; k < j; k++) v -= ld[i * n + k] * ld[j * n + k] * inv_d[k];
            ld[i * n + j] = v;
        }
    }
    return TRK_OK;
}

TRK_INLINE void trk_i_chol_forward(int n, const trk_real *l, const trk_real *b, trk_real *y)
{
    for (int i = 0; i < n; i++) {
        trk_real s = b[i];
        for (int t = 0; t < i; t++) s -= l[i * n + t] * y[t];
        y[i] = s / l[i * n + i];
    }
}

TRK_INLINE void trk_i_chol_backward(int n, const trk_real *l, const trk_real *y, trk_real *x)
{
    for (int i = n - 1; i >= 0; i--) {
        trk_real s = y[i];
        for (int t = i + 1; t < n; t++) s -= l[t * n + i] * x[t];
        x[i] = s / l[i * n + i];
    }
}

/* Inverse of a lower-triangular L (non-zero diagonal): M = L^-1, lower. */
TRK_INLINE void trk_i_tril_inverse(int n, const trk_real *l, trk_real *m)
{
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < j; i++) m[i * n + j] = 0;
        m[j * n + j] = 1 / l[j * n + j];
        for (int i = j + 1; i < n; i++) {
            trk_real s = 0;
            for (int t = j; t < i; t++) s += l[i * n + t] * m[t * n + j];
            m[i * n + j] = -s / l[i * n + i];
        }
    }
}

/* y = M v for a lower-triangular M. */
TRK_INLINE void trk_i_tril_mul(int n, const trk_real *m, const trk_real *v, trk_real *y)
{
    for (int i = n - 1; i >= 0; i--) {
        trk_real s = 0;
        for (int t = 0; t <= i; t++) s += m[i * n + t] * v[t];
        y[i] = s;
    }
}

/* y = M' v for a lower-triangular M. */
TRK_INLINE void trk_i_tril_mul_t(int n, const trk_real *m, const trk_real *v, trk_real *y)
{
    for (int i = 0; i < n; i++) {
        trk_real s = 0;
        for (int t = i; t < n; t++) s += m[t * n + i] * v[t];
        y[i] = s;
    }
}

TRK_INLINE trk_real trk_i_chol_logdet(int n, const trk_real *l)
{
    trk_real s = 0;
    for (int i = 0; i < n; i++) s += trk_log(l[i * n + i]);
    return 2 * s;
}

#endif
