/** @file
 * trk/linalg.h - small dense matrices of fixed maximum size (no heap, no VLAs).
 *
 * Matrices are row-major arrays of trk_real; a[i*cols + j] is row i, column j.
 * Dimensions are passed explicitly and must be 1..TRK_MAX_STATE. Output may not
 * alias input unless a function says so.
 */
#ifndef TRK_LINALG_H
#define TRK_LINALG_H

#include "trk/types.h"

/** C (n x m) = A (n x k) * B (k x m). */
void trk_mat_mul(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c);

/** C (n x m) = A (n x k) * B' with B (m x k). */
void trk_mat_mul_abt(int n, int k, int m, const trk_real *a, const trk_real *b, trk_real *c);

/** A (n x n) = (A + A') / 2, in place. */
void trk_mat_symmetrize(int n, trk_real *a);

/** Cholesky factor L (lower, n x n; upper part set to 0) of a symmetric A.
 * Only the lower triangle of A is read. L may alias A.
 * Returns TRK_E_NOT_SPD when a pivot is not positive and finite (L then holds
 * garbage), TRK_E_ARG for a bad dimension. */
TRK_NODISCARD trk_status trk_chol(int n, const trk_real *a, trk_real *l);

/** Solve L y = b (forward substitution) for a lower-triangular L with
 * non-zero diagonal. y may alias b. */
void trk_chol_forward(int n, const trk_real *l, const trk_real *b, trk_real *y);

/** Solve A x = b with A = L L' (both substitutions). x may alias b. */
void trk_chol_solve(int n, const trk_real *l, const trk_real *b, trk_real *x);

/** ln det A = 2 sum ln L_ii. */
trk_real trk_chol_logdet(int n, const trk_real *l);

/** TRK_OK when A is symmetric (relative tolerance rel_tol on each pair, against
 * the larger diagonal) and positive definite (every pivot of its LDL'
 * factorisation positive; the tracker and the PDA check their posteriors
 * with the same factorisation); TRK_E_NAN for a non-finite entry. */
TRK_NODISCARD trk_status trk_mat_check_spd(int n, const trk_real *a, trk_real rel_tol);

#endif /* TRK_LINALG_H */
