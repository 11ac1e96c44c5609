/* linalg.c - public wrappers of the small-matrix kernels (linalg_impl.h). */
#include "trk/linalg.h"

#define TRK_I_LINALG_DEFINE /* the external copies of the loop kernels in size builds */
#include "linalg_impl.h"

#define DIM_OK(n) ((n) >= 1 && (n) <= TRK_MAX_STATE)

void trk_mat_mul(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c)
{
    trk_i_mat_mul(n, k, m, a, b, c);
}

void trk_mat_mul_abt(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c)
{
    trk_i_mat_mul_abt(n, k, m, a, b, c);
}

void trk_mat_symmetrize(int n, trk_real *a) { trk_i_symmetrize(n, a); }

trk_status trk_chol(int n, const trk_real *a, trk_real *l)
{
    if (!DIM_OK(n) || !a || !l) return TRK_E_ARG;
    return trk_i_chol(n, a, l);
}

void trk_chol_forward(int n, const trk_real *l, const trk_real *b, trk_real *y)
{
    trk_i_chol_forward(n, l, b, y);
}

void trk_chol_solve(int n, const trk_real *l, const trk_real *b, trk_real *x)
{
    trk_real y[TRK_MAX_STATE];
    trk_i_chol_forward(n, l, b, y);
    trk_i_chol_backward(n, l, y, x);
}

trk_real trk_chol_logdet(int n, const trk_real *l) { return trk_i_chol_logdet(n, l); }

trk_status trk_i_spd(int n, const trk_real *a) { return trk_i_spd_inline(n, a); }

/* With a division per entry (no reciprocal of a pivot, which overflows for
 * a subnormal one): trk_i_spd_inline's fallback. */
trk_status trk_i_spd_div(int n, const trk_real *a)
{
    trk_real l[TRK_MAX_STATE * TRK_MAX_STATE], d[TRK_MAX_STATE]; /* unit lower L, D */
    for (int j = 0; j < n; j++) {
        trk_real dj = a[j * n + j];
        for (int k = 0; k < j; k++) dj -= l[j * n + k] * l[j * n + k] * d[k];
        if (!(dj > 0) || !(dj <= TRK_REAL_MAX)) return TRK_E_NOT_SPD;
        d[j] = dj;
        for (int i = j + 1; i < n; i++) {
            trk_real v = a[i * n + j];
            for (int k = 0; k < j; k++) v -= l[i * n + k] * l[j * n + k] * d[k];
            l[i * n + j] = v / dj;
        }
    }
    return TRK_OK;
}

trk_status trk_mat_check_spd(int n, const trk_real *a, trk_real rel_tol)
{
    if (!DIM_OK(n) || !a || !(rel_tol >= 0)) return TRK_E_ARG;
    for (int i = 0; i < n * n; i++)
        if (!isfinite(a[i])) return TRK_E_NAN;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            trk_real scale = trk_fabs(a[i * n + i]) > trk_fabs(a[j * n + j]) ? trk_fabs(a[i * n + i])
                                                                              : trk_fabs(a[j * n + j]);
            if (trk_fabs(a[i * n + j] - a[j * n + i]) > rel_tol * scale) return TRK_E_NOT_SPD;
        }
    return trk_i_spd(n, a);
}
