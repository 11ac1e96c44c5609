/** @file
 * trk/kalman.h - linear-Gaussian prediction and update, and the 2-D
 * constant-velocity model (docs/conventions.md "State and covariance layout").
 *
 * State order of the CV model: [x, vx, y, vy]; measurement [x, y].
 * All matrices row-major. nx in 1..TRK_MAX_STATE, nz in 1..TRK_MAX_MEAS.
 */
#ifndef TRK_KALMAN_H
#define TRK_KALMAN_H

#include "trk/types.h"

/** State dimension of the 2-D constant-velocity (CV) model. */
#define TRK_CV2_NX 4
/** Measurement dimension of the CV model (position x, y). */
#define TRK_CV2_NZ 2

/** @{ */
/** Named components of the CV state [x, vx, y, vy] (m, m/s) ... */
#define TRK_CV2_X 0
#define TRK_CV2_VX 1
#define TRK_CV2_Y 2
#define TRK_CV2_VY 3
/** @} */
/** @{ */
/** ... and of its measurement [x, y] (m). */
#define TRK_CV2_ZX 0
#define TRK_CV2_ZY 1
/** @} */

/** @{ */
/** Row-major index of element (i, j) of a CV state covariance P (4 x 4) and
 * of a measurement-space matrix S or R (2 x 2), e.g. the position variance
 * p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)]. */
#define TRK_CV2_P(i, j) ((i) * TRK_CV2_NX + (j))
#define TRK_CV2_S(i, j) ((i) * TRK_CV2_NZ + (j))
/** @} */

/** F = blkdiag([[1, T], [0, 1]] x 2). */
void trk_cv2_transition(trk_real dt_s, trk_real f[TRK_CV2_NX * TRK_CV2_NX]);

/** Q = blkdiag(q [[T^3/3, T^2/2], [T^2/2, T]] x 2), q the power spectral density
 * of continuous white-noise acceleration (m^2/s^3). */
void trk_cv2_process_noise(trk_real dt_s, trk_real q_m2_per_s3, trk_real q[TRK_CV2_NX * TRK_CV2_NX]);

/** CV prediction in place: x = F x, P = F P F' + Q with F and Q of dt_s and
 * q as above, evaluated with F's block structure (~40 flops instead of the
 * ~130 of the general product; equal to trk_kalman_predict with
 * trk_cv2_transition/trk_cv2_process_noise to rounding). P stays exactly
 * symmetric. TRK_E_NAN for a non-finite dt_s or q (x, P untouched). */
TRK_NODISCARD trk_status trk_cv2_predict(trk_real dt_s, trk_real q_m2_per_s3, trk_real x[TRK_CV2_NX],
                                         trk_real p[TRK_CV2_NX * TRK_CV2_NX]);

/** F and Q (row-major, 2 n_axes square) of the CV model with n_axes = 1
 * (state [x, vx]) or 2 ([x, vx, y, vy]); the same blocks as above.
 * TRK_E_ARG for another n_axes or a NULL pointer. */
TRK_NODISCARD trk_status trk_cv_model(int n_axes, trk_real dt_s, trk_real q_m2_per_s3, trk_real *f,
                                      trk_real *q);

/** The steady state of the CV Kalman filter on one axis, and the
 * constant-gain (alpha-beta) filter it defines (seed survey ch. 3.1.3,
 * 3.3.1-3.3.2; docs/conventions.md "Constant-gain filter"): position
 * measurements of variance r_m2 every dt_s seconds, the continuous
 * white-noise acceleration model of trk_cv2_predict (spectral density q).
 * With the tracking index lambda^2 = q dt^3 / r the gains satisfy
 * beta^2 / (1 - alpha) = lambda^2 and alpha^2 + alpha beta - 2 beta +
 * beta^2 / 6 = 0 (the survey's Kalata relation 3.5 for this model, whose
 * last term is beta^2 / 4 for piecewise-constant acceleration); in closed
 * form u = (lambda + sqrt(16 + lambda^2 / 3)) / 2, s = sqrt(1 - alpha) =
 * 2 / (u + sqrt(u^2 - 4)), alpha = 1 - s^2, beta = lambda s. */
struct trk_cv_steady {
    trk_real alpha;         /**< position gain */
    trk_real beta;          /**< velocity gain times dt (dimensionless) */
    trk_real k_vel_per_s;   /**< velocity gain beta / dt (1/s) */
    trk_real pred[3];       /**< predicted covariance [pp, pv, vv] (m^2, m^2/s, m^2/s^2) */
    trk_real post[3];       /**< updated covariance [pp, pv, vv] */
};

/** The steady state above into *ss. TRK_E_ARG NULL ss, dt_s, q or r_m2
 * not finite and > 0; TRK_E_RANGE a steady state the real type cannot
 * hold (lambda above 1e15, or so small that alpha rounds to 0, or a
 * covariance term beyond TRK_REAL_MAX); *ss is then not written. */
TRK_NODISCARD trk_status trk_cv_steady_state(trk_real dt_s, trk_real q_m2_per_s3, trk_real r_m2,
                                             struct trk_cv_steady *ss);

/** Two-point differencing (Bar-Shalom, Willett & Tian, "Tracking and Data
 * Fusion" 2011): the CV state from a position z0 (covariance r0, 2 x 2
 * row-major) and a position z1 (r1) dt_s later: x = z1, v = (z1 - z0) / dt,
 * P_pp = R1, P_pv = P_vp = R1 / dt, P_vv = (R0 + R1) / dt^2 (per axis pair,
 * with the xy terms). x and p are outputs only. TRK_E_ARG NULL pointer or
 * dt_s not > 0, TRK_E_NAN a non-finite x, TRK_E_NOT_SPD P not positive
 * definite in this arithmetic (R0 tiny against R1: its Schur complement is
 * R0 / dt^2); x and p are then not usable. */
TRK_NODISCARD trk_status trk_cv2_two_point(const trk_real z0[TRK_CV2_NZ], const trk_real r0[TRK_CV2_NZ * TRK_CV2_NZ],
                                           const trk_real z1[TRK_CV2_NZ], const trk_real r1[TRK_CV2_NZ * TRK_CV2_NZ],
                                           trk_real dt_s, trk_real x[TRK_CV2_NX],
                                           trk_real p[TRK_CV2_NX * TRK_CV2_NX]);

/** H = [[1,0,0,0],[0,0,1,0]]. */
extern const trk_real trk_cv2_h[TRK_CV2_NZ * TRK_CV2_NX];

/** x = F x, P = F P F' + Q (symmetrised). In place.
 * TRK_E_ARG bad dimension/pointer, TRK_E_NAN non-finite result (x, P untouched). */
TRK_NODISCARD trk_status trk_kalman_predict(int nx, const trk_real *f, const trk_real *q,
                                            trk_real *x, trk_real *p);

/** Predicted measurement and its innovation covariance S = H P H' + R with the
 * Cholesky factor of S, which gating and the PDA reuse. */
struct trk_innovation {
    int nz;  /**< measurement dimension */
    trk_real z_pred[TRK_MAX_MEAS];  /**< predicted measurement H x */
    trk_real s[TRK_MAX_MEAS * TRK_MAX_MEAS];       /**< S */
    trk_real s_chol[TRK_MAX_MEAS * TRK_MAX_MEAS];  /**< lower L, S = L L' */
    trk_real s_chol_inv[TRK_MAX_MEAS * TRK_MAX_MEAS]; /**< L^-1 (lower): d2 = |L^-1 nu|^2 */
    trk_real log_det_s;                            /**< ln det S */
    trk_real sqrt_det_s;                           /**< sqrt(det S) (may overflow in float: use log_det_s) */
};

/** Fill *inn from (x, P) and the measurement model (H, R).
 * TRK_E_NOT_SPD when S is not positive definite (inn is then not usable). */
TRK_NODISCARD trk_status trk_kalman_innovation(int nx, int nz, const trk_real *h, const trk_real *r,
                                               const trk_real *x, const trk_real *p,
                                               struct trk_innovation *inn);

/** Gain K = P H' S^-1 (nx x nz) from the innovation's Cholesky factor. */
void trk_kalman_gain(int nx, int nz, const trk_real *h, const trk_real *p,
                     const struct trk_innovation *inn, trk_real *k);

/** Joseph-form covariance P_c = (I - K H) P (I - K H)' + K R K' (symmetric
 * positive definite whenever P and R are). pc may not alias p. */
void trk_kalman_joseph(int nx, int nz, const trk_real *h, const trk_real *r, const trk_real *k,
                       const trk_real *p, trk_real *pc);

/** Standard Kalman update with measurement z, in place (Joseph form).
 * TRK_E_NOT_SPD when S is not positive definite, TRK_E_NAN for a non-finite
 * z; x and P are untouched on error. */
TRK_NODISCARD trk_status trk_kalman_update(int nx, int nz, const trk_real *h, const trk_real *r,
                                           const trk_real *z, trk_real *x, trk_real *p);

#endif /* TRK_KALMAN_H */
