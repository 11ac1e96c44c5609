/* linalg_impl.h (private) - inline bodies of the small-matrix kernels.
 *
 * The public functions of linalg.c wrap these. Hot paths (tracker, pda) call
 * them directly with constant dimensions so the compiler unrolls the loops;
 * one implementation serves both. */
#ifndef TRK_LINALG_IMPL_H
#define TRK_LINALG_IMPL_H

#include "internal.h"
#include "trk/types.h"

/* The loop kernels marked TRK_I_LOOP_KERNEL (mat_mul, mat_mul_abt,
 * symmetrize, chol, tril_inverse, tril_mul, chol_logdet) are inline
 * everywhere, except in size builds (TRK_SIZE_OPT): there the compiler kept
 * one static copy per file that calls them (tracker.c, pda.c, kalman.c), so
 * linalg.c defines the one external copy (TRK_I_LINALG_DEFINE) and the
 * others see prototypes (measured on the Cortex-M4F library: 0.9 KB for the
 * first four, 0.6 KB for mat_mul, mat_mul_abt and chol_logdet). */
#if !TRK_SIZE_OPT
#define TRK_I_LOOP_KERNEL TRK_INLINE
#else
#ifdef TRK_I_LINALG_DEFINE
#define TRK_I_LOOP_KERNEL
#endif
void trk_i_symmetrize(int n, trk_real *a);
trk_status trk_i_chol(int n, const trk_real *a, trk_real *l);
void trk_i_tril_inverse(int n, const trk_real *l, trk_real *m);
void trk_i_tril_mul(int n, const trk_real *m, const trk_real *v, trk_real *y);
void trk_i_mat_mul(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c);
void trk_i_mat_mul_abt(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c);
trk_real trk_i_chol_logdet(int n, const trk_real *l);
#endif

#ifdef TRK_I_LOOP_KERNEL
TRK_I_LOOP_KERNEL void trk_i_mat_mul(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            trk_real s = 0;
            for (int t = 0; t < k; t++) s += a[i * k + t] * b[t * m + j];
            c[i * m + j] = s;
        }
}

TRK_I_LOOP_KERNEL void trk_i_mat_mul_abt(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            trk_real s = 0;
            for (int t = 0; t < k; t++) s += a[i * k + t] * b[j * k + t];
            c[i * m + j] = s;
        }
}

TRK_I_LOOP_KERNEL void trk_i_symmetrize(int n, trk_real *a)
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
TRK_I_LOOP_KERNEL trk_status trk_i_chol(int n, const trk_real *a, trk_real *l)
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
#endif

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

/* A (2x2, symmetric) = L L' in closed form: L, L^-1 (both lower, row-major)
 * and sqrt det A = l00 l11, from det A = a00 a11 - a01^2 with the two square
 * roots and the two divisions independent (trk_i_chol's square root,
 * division, square root, division is one chain of four). 0 when a00 or
 * det A is not a positive finite normal number: the caller then factors by
 * trk_i_chol, which decides. */
TRK_INLINE int trk_i_chol2(const trk_real *a, trk_real *l, trk_real *m, trk_real *sqrt_det)
{
    const trk_real det = a[0] * a[3] - a[2] * a[2];
    if (!(a[0] >= TRK_REAL_MIN && a[0] <= TRK_REAL_MAX && det >= TRK_REAL_MIN && det <= TRK_REAL_MAX)) return 0;
    const trk_real l00 = trk_sqrt(a[0]), sd = trk_sqrt(det);
    const trk_real m00 = 1 / l00, r = 1 / sd; /* 1 / l00, 1 / (l00 l11) */
    l[0] = l00;
    l[1] = 0;
    l[2] = a[2] * m00;
    l[3] = sd * m00;
    m[0] = m00;
    m[1] = 0;
    m[2] = -a[2] * m00 * r;
    m[3] = l00 * r;
    *sqrt_det = sd;
    return 1;
}

/* Is the symmetric 4x4 A positive definite beyond doubt? 1 when it is, by
 * the blocks A = [P B; B' C] (2x2 each, P on indices 0-1): P > 0 and its
 * Schur complement C - B' P^-1 B > 0, both tested by determinants scaled by
 * det P (division-free: a chain of multiplications where LDL' has four
 * divisions in a row), every pivot at least SPD4_MARGIN of its scale so that
 * rounding (relative eps / SPD4_MARGIN at most) cannot decide it. 0 when it
 * is not, or nearly not, or a product left the finite normal range: the
 * caller then decides by trk_i_spd_inline. */
#define TRK_I_SPD4_MARGIN (TRK_REAL_C(1.0) / 256)
TRK_INLINE int trk_i_spd4_sure(const trk_real *a)
{
    const trk_real p00 = a[0], p01 = a[1], p11 = a[5];
    const trk_real b00 = a[2], b01 = a[3], b10 = a[6], b11 = a[7];
    const trk_real det_p = p00 * p11 - p01 * p01;
    /* G = adj(P) B, H = B' G = det P B' P^-1 B, M = det P C - H */
    const trk_real g00 = p11 * b00 - p01 * b10, g01 = p11 * b01 - p01 * b11;
    const trk_real g10 = p00 * b10 - p01 * b00, g11 = p00 * b11 - p01 * b01;
    const trk_real m00 = det_p * a[10] - (b00 * g00 + b10 * g10);
    const trk_real m01 = det_p * a[11] - (b00 * g01 + b10 * g11);
    const trk_real m11 = det_p * a[15] - (b01 * g01 + b11 * g11);
    const trk_real det_m = m00 * m11 - m01 * m01;
    /* every test evaluated (no branch per test: a NaN fails each) */
    return (p00 >= TRK_REAL_MIN) & (det_p > TRK_I_SPD4_MARGIN * (p00 * p11)) & (det_p >= TRK_REAL_MIN) &
           (m00 > TRK_I_SPD4_MARGIN * (det_p * a[10])) & (m11 > TRK_I_SPD4_MARGIN * (det_p * a[15])) &
           (det_m > TRK_I_SPD4_MARGIN * (m00 * m11)) & (det_m >= TRK_REAL_MIN) & (det_m <= TRK_REAL_MAX);
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

#ifdef TRK_I_LOOP_KERNEL
/* Inverse of a lower-triangular L (non-zero diagonal): M = L^-1, lower. */
TRK_I_LOOP_KERNEL void trk_i_tril_inverse(int n, const trk_real *l, trk_real *m)
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
TRK_I_LOOP_KERNEL void trk_i_tril_mul(int n, const trk_real *m, const trk_real *v, trk_real *y)
{
    for (int i = n - 1; i >= 0; i--) {
        trk_real s = 0;
        for (int t = 0; t <= i; t++) s += m[i * n + t] * v[t];
        y[i] = s;
    }
}
#endif

/* y = M' v for a lower-triangular M. */
TRK_INLINE void trk_i_tril_mul_t(int n, const trk_real *m, const trk_real *v, trk_real *y)
{
    for (int i = 0; i < n; i++) {
        trk_real s = 0;
        for (int t = i; t < n; t++) s += m[t * n + i] * v[t];
        y[i] = s;
    }
}

#ifdef TRK_I_LOOP_KERNEL
TRK_I_LOOP_KERNEL trk_real trk_i_chol_logdet(int n, const trk_real *l)
{
    trk_real s = 0;
    for (int i = 0; i < n; i++) s += trk_log(l[i * n + i]);
    return 2 * s;
}
#endif

#endif
