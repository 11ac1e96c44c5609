/** @file
 * trk/crlb.h - Cramer-Rao lower bound for tracking in clutter with the
 * information-reduction factor q2 (Willett eqs 28-37, Proposition 2).
 *
 * Information recursion (Willett eq 37), constant-velocity model of
 * docs/conventions.md "State and covariance layout" with nz position
 * coordinates, R = r I:
 *   J+ = Q^-1 + q2 H' R^-1 H - Q^-1 F (J + F' Q^-1 F)^-1 F' Q^-1
 * Evaluated in the algebraically equal form (matrix inversion lemma)
 *   J+ = (Q + F J^-1 F')^-1 + q2 H' R^-1 H,
 * because the printed form subtracts two matrices of size ~Q^-1 to leave one
 * of size ~J: with q~ = 1.6e-4 (Brekke's Table I) that cancels ~4 digits,
 * all of them in float. Its steady state equals the Kalman steady state with
 * R / q2 (q2 = 1: the information filter). The bound on the position error
 * is sqrt(Jinv11 + Jinv22) (nz = 2) as for the MRE (trk/mre.h).
 * It is not the MRE with the same q2 (the MRE is 2-4x larger).
 */
#ifndef TRK_CRLB_H
#define TRK_CRLB_H

#include "trk/types.h"

/** Largest state dimension of the bound (2 nz). */
#define TRK_CRLB_MAX_NX 4

/** The model of the bound: constant velocity in nz coordinates, information reduced by q2. */
struct trk_crlb_params {
    int nz;                /**< 1 or 2 position coordinates */
    trk_real dt_s;         /**< T > 0 */
    trk_real q_m2_per_s3;  /**< process noise PSD q~ > 0 */
    trk_real r_m2;         /**< measurement noise variance r > 0 (R = r I) */
    trk_real q2;           /**< information-reduction factor in (0, 1] */
    int max_iter;          /**< steady-state iteration cap; 0: 100000 */
    trk_real rel_tol;      /**< convergence: estimated distance of J^-1 to the fixed
                              point <= rel_tol max|J^-1| (as trk_mre_params); 0: 64 eps */
};

/** Validated parameters and the model's matrices (init once). */
struct trk_crlb {
    struct trk_crlb_params params;  /**< as given to trk_crlb_init */
    int nx;                                         /**< 2 nz */
    trk_real f[TRK_CRLB_MAX_NX * TRK_CRLB_MAX_NX];  /**< transition matrix F (nx x nx) */
    trk_real q[TRK_CRLB_MAX_NX * TRK_CRLB_MAX_NX];  /**< process noise covariance Q (nx x nx) */
    trk_real hrh[TRK_CRLB_MAX_NX * TRK_CRLB_MAX_NX]; /**< q2 H' R^-1 H */
};

/** TRK_E_ARG NULL / nz not 1 or 2 / negative max_iter, TRK_E_NAN non-finite,
 * TRK_E_RANGE dt, q, r not > 0, q2 outside (0, 1], rel_tol < 0.
 * *c untouched on error. */
TRK_NODISCARD trk_status trk_crlb_init(struct trk_crlb *c, const struct trk_crlb_params *params);

/** Initial information J0 = P0^-1 (nx x nx) from an initial covariance p0
 * (NULL: two-point differencing, per coordinate [[r, r/T], [r/T, 2r/T^2]]).
 * TRK_E_NAN non-finite p0, TRK_E_NOT_SPD p0 not positive definite. */
TRK_NODISCARD trk_status trk_crlb_initial_info(const struct trk_crlb *c, const trk_real *p0,
                                               trk_real *j0);

/** One step of eq 37 in place: j (nx x nx) holds J_k on entry and J_{k+1}
 * on return; j_inv (may be NULL) receives the bound J_{k+1}^-1.
 * TRK_E_ARG NULL, TRK_E_NOT_SPD J not positive definite, TRK_E_NAN
 * non-finite result. j untouched on error. */
TRK_NODISCARD trk_status trk_crlb_step(const struct trk_crlb *c, trk_real *j, trk_real *j_inv);

/** The steady-state bound (trk_crlb_steady_state). */
struct trk_crlb_result {
    int nx;  /**< state dimension 2 nz */
    trk_real j[TRK_CRLB_MAX_NX * TRK_CRLB_MAX_NX];      /**< steady-state information */
    trk_real j_inv[TRK_CRLB_MAX_NX * TRK_CRLB_MAX_NX];  /**< the bound J^-1 */
    trk_real pos_rmse_m;                                /**< sqrt(Jinv11 + Jinv22) */
    int iterations;  /**< steps to convergence */
};

/** Iterate eq 37 to its steady state from j0 (NULL: the two-point-differencing
 * information). TRK_E_DIVERGED when max_iter steps do not converge or a
 * value becomes non-finite; the statuses of trk_crlb_step otherwise. */
TRK_NODISCARD trk_status trk_crlb_steady_state(const struct trk_crlb *c, const trk_real *j0,
                                               struct trk_crlb_result *res);

#endif /* TRK_CRLB_H */
