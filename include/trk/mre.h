/** @file
 * trk/mre.h - modified Riccati equation (MRE) of the PDAF / PDAFAI, its
 * steady state, the steady-state position RMSE, and the tracking operating
 * characteristic (TOC): the RMSE along a ROC and the false-alarm probability
 * that minimises it.
 *
 * MRE (Brekke eq 27; docs/conventions.md "q2, MRE and CRLB"), the
 * constant-velocity model of docs/conventions.md "State and covariance
 * layout" with nz position coordinates (nz = 1: state [x, vx]; nz = 2:
 * [x, vx, y, vy]), R = r I:
 *   P-  = F P F' + Q
 *   S   = H P- H' + R
 *   K   = P- H' S^-1
 *   P   = P- - q2 K S K'  = (1 - q2) P- + q2 Pc     (Pc the Kalman update,
 *                                                     Joseph form: P stays SPD)
 * with q2 either constant or looked up each step at
 *   lambda_vg = lambda V_G,  V_G = c_nz gamma^(nz/2) sqrt(det S).
 * Steady-state position RMSE (Brekke eq 35): e = sqrt(P11 + P22), the sum of
 * the position variances (nz = 2: P[0][0] + P[2][2]; nz = 1: P[0][0]).
 *
 * TOC (Brekke Sec. V-C, Fig. 2): at false-alarm probability pfa the clutter
 * density is lambda = pfa * cells_per_m (one false alarm per resolution cell
 * with probability pfa: cells_per_m = 1 / cell size in m^nz), q2 comes from
 * the detector's q2 along its ROC (trk_q2_pfa_fn, trk/q2.h), and e(pfa) is
 * the MRE's steady-state RMSE. The optimum is searched on a grid in ln pfa,
 * then refined by golden-section search around the best grid point.
 *
 * No heap, no global state; everything lives in the caller's structs.
 */
#ifndef TRK_MRE_H
#define TRK_MRE_H

#include "trk/q2.h"
#include "trk/types.h"

/** Largest state dimension (2 nz). */
#define TRK_MRE_MAX_NX 4

/** The model of the modified Riccati equation: constant velocity in nz coordinates, PDA gate and clutter, q2 from a function. */
struct trk_mre_params {
    int nz;                    /**< 1 or 2 position coordinates */
    trk_real dt_s;             /**< scan interval T > 0 */
    trk_real q_m2_per_s3;      /**< process noise PSD q~ > 0 (m^2/s^3, docs/conventions.md) */
    trk_real r_m2;             /**< measurement noise variance r > 0 (R = r I) */
    trk_real gate_prob;        /**< P_G in (0, 1): gamma and V_G (unless gate_gamma > 0) */
    trk_real gate_gamma;       /**< > 0: the gate threshold on d2 itself (Brekke's g^2,
                                  e.g. 36; a P_G of 1 - 1.5e-8 is 1.0f in float);
                                  0: gamma from gate_prob */
    trk_real clutter_density;  /**< lambda >= 0 per m^nz (only enters lambda_vg) */
    trk_real q2;               /**< constant q2 in (0, 1], used when q2_fn == NULL */
    trk_q2_fn q2_fn;           /**< or: q2 looked up at lambda_vg each step */
    const void *q2_ctx;        /**< ctx of q2_fn (e.g. struct trk_q2_line) */
    int max_iter;              /**< steady-state iteration cap; 0: 100000 */
    trk_real rel_tol;          /**< convergence: estimated distance to the fixed point
                                  (last change x max(1, r/(1-r)), r the contraction
                                  rate) <= rel_tol max|P|; 0: 64 eps */
    trk_real max_pos_var_m2;   /**< divergence: position variance above this while its
                                  growth accelerates (20 steps); 0: 1e4 times the
                                  largest of nz r, nz q T^3/3 and the initial one */
};

/** Validated model and derived constants (init once, then read-only). */
struct trk_mre {
    struct trk_mre_params params;  /**< as given to trk_mre_init */
    int nx;                                     /**< 2 nz */
    trk_real f[TRK_MRE_MAX_NX * TRK_MRE_MAX_NX];  /**< transition matrix F (nx x nx) */
    trk_real q[TRK_MRE_MAX_NX * TRK_MRE_MAX_NX];  /**< process noise covariance Q (nx x nx) */
    trk_real gamma;                             /**< gate threshold on d2 */
};

/** TRK_E_ARG NULL / nz not 1 or 2 / negative max_iter / q2 not given,
 * TRK_E_NAN non-finite parameter, TRK_E_RANGE a parameter outside its range.
 * *m untouched on error. */
TRK_NODISCARD trk_status trk_mre_init(struct trk_mre *m, const struct trk_mre_params *params);

/** Two-point-differencing initial covariance (per coordinate
 * [[r, r/T], [r/T, 2r/T^2]]), the default start of the iteration. */
void trk_mre_initial_cov(const struct trk_mre *m, trk_real *p);

/** What one step used. */
struct trk_mre_step_info {
    trk_real s[4];        /**< S (nz x nz) of this step */
    trk_real lambda_vg;   /**< lambda V_G at this S */
    trk_real q2;          /**< q2 used */
};

/** One MRE step in place: p (nx x nx) holds P_{k-1} on entry and P_k on
 * return. info may be NULL. TRK_E_ARG NULL, TRK_E_NOT_SPD S not positive
 * definite, TRK_E_NAN non-finite result, TRK_E_RANGE a q2_fn value outside
 * [0, 1] (0: the scan carries no information), or any status of q2_fn (e.g.
 * TRK_E_RANGE for lambda_vg outside its grid). p untouched on error. */
TRK_NODISCARD trk_status trk_mre_step(const struct trk_mre *m, trk_real *p,
                                      struct trk_mre_step_info *info);

/** The steady state of the modified Riccati equation (trk_mre_steady_state). */
struct trk_mre_result {
    int nx;                                        /**< 2 nz */
    trk_real p[TRK_MRE_MAX_NX * TRK_MRE_MAX_NX];   /**< steady-state E[P_k|k] */
    trk_real s[4];                                 /**< steady-state S (nz x nz) */
    trk_real lambda_vg;                            /**< lambda V_G at that S */
    trk_real q2;                                   /**< q2 at that S */
    trk_real rmse_m;                               /**< sqrt(P11 + P22) (eq 35) */
    int iterations;  /**< steps to convergence */
};

/** Iterate the MRE to its steady state from p0 (nx x nx, SPD, or all zero:
 * P_0 = 0, the first prediction is Q; NULL: the two-point-differencing
 * covariance). TRK_OK with *res filled; TRK_E_DIVERGED
 * when the position variance exceeds max_pos_var_m2 with accelerating growth
 * (an RMSE 100 times every noise scale of the model: the track is lost for
 * any practical purpose), exceeds 1e8 times that, a value becomes non-finite,
 * or max_iter steps do not converge (res then holds the last iterate,
 * res->rmse_m = +inf); otherwise the first failing step's status
 * (e.g. TRK_E_RANGE when lambda_vg leaves the q2 grid; res holds the last
 * good iterate). */
TRK_NODISCARD trk_status trk_mre_steady_state(const struct trk_mre *m, const trk_real *p0,
                                              struct trk_mre_result *res);

/** Position RMSE sqrt(P11 + P22) (Brekke eq 35) of a CV covariance with nz
 * position coordinates (indices 0 and 2 of [x, vx, y, vy]); NaN for bad nz. */
trk_real trk_mre_rmse(int nz, const trk_real *p);

#endif /* TRK_MRE_H */
