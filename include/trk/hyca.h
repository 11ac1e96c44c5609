/** @file
 * trk/hyca.h - track-life prediction by hybrid conditional averaging (HYCA;
 * Willett 2010 section I.D.2, eqs 43-48 and Figs 7-8, after Li and
 * Bar-Shalom 1991; docs/conventions.md "HYCA").
 *
 * Constant-velocity model of trk/mre.h (nz position coordinates, R = r I,
 * Q from T and q~). Both forms are Markov chains whose state is the
 * detection event of the last scan, each state carrying the covariance
 * conditioned on it; the hybrid conditional average of a state is the
 * average over its predecessors, weighted by how likely each led to it.
 *
 * 1. Missed detections only (Fig. 7): states 1 (detection, R) and 2 (miss,
 *    R = infinity, eq 44), mu = (pd, 1 - pd) every scan (eq 47, identical
 *    rows). Eq 46 is applied literally,
 *      P_j(k+1) = sum_i mu_i f_j(P_i(k)),
 *    f_1 the prediction then the Kalman update, f_2 the prediction alone: the
 *    update acts on each P_i before the average (not f_1(sum_i mu_i P_i),
 *    which differs by 2-4 % at pd 0.5). The answer is the fixed point and its
 *    average P = pd P_1 + (1 - pd) P_2 (eq 48). At pd = 1 it is the
 *    algebraic Riccati equation's solution; below, HYCA lies above the Monte
 *    Carlo mean of the random Riccati recursion (2-4 % at pd 0.5, 0.2-0.4 %
 *    at 0.9): it is an approximation.
 *
 * 2. With clutter (Fig. 8): the state is m, the number of gated
 *    measurements of the last scan, m = 0 .. m_lost - 1, and m >= m_lost is
 *    an absorbing "lost" state (a gate that holds that many has run away).
 *    The choices (the notes leave them open):
 *    - Gate. From state i the prediction P-_i = F P_i F' + Q gives
 *      S_i = H P-_i H' + R and the gate volume V_i = c_nz gamma^(nz/2)
 *      sqrt(det S_i): the gate follows each state's covariance.
 *    - Count. m' = (target detected and gated) + (Poisson clutter in the
 *      gate), the two independent:
 *        P{m' = j | i} = (1 - pd pg) Pois(j; lambda V_i) + pd pg Pois(j - 1; lambda V_i).
 *    - Covariance. Given m' = j the PDAF's expected update is
 *        f_j(P_i) = P-_i - eta_j K S_i K',
 *      with eta_j the information-reduction factor conditioned on j gated
 *      measurements, split from q2 = sum_j eta_j P{m' = j} (Brekke eqs
 *      28-30): P{m' = j} eta_j = pd F_{nz+2}(gamma) Pois(j - 1; lambda V_i)
 *      E_{j-1}[beta_1], evaluated by trk/irf.h (eta_0 = 0: a scan with no
 *      gated measurement is a prediction). q2 of the MRE is its average.
 *    - Average. P_j(k+1) = sum_i mu_i P{j | i} f_j(P_i(k)) / mu'_j with
 *      mu'_j = sum_i mu_i P{j | i}; with lambda = 0 and pg -> 1 this is form 1.
 *    - Start. A track starts held, m = 1 (its initiating detection), with the
 *      two-point-differencing covariance (or the caller's P_0).
 *    - Life. S(k) = P{held after k scans}; the life L (scans until the
 *      track is lost) has E[L] = sum_{k>=0} S(k) and median the first k with
 *      S(k) <= 1/2. The chain normalised over the held states converges to a
 *      quasi-stationary state with a constant loss probability p per scan;
 *      from there S falls geometrically and the sums are closed in form.
 *    The PDAF is modelled (no amplitude information; a PDAFAI holds tracks
 *    longer, docs/analysis.md shows by how much).
 *
 * No heap, no global state. struct trk_hyca holds the quadrature tables of
 * trk/irf.h (about 20 KB in double): not a stack object for small threads.
 */
#ifndef TRK_HYCA_H
#define TRK_HYCA_H

#include "trk/irf.h"
#include "trk/types.h"

/** Largest state dimension (2 nz). */
#define TRK_HYCA_MAX_NX 4
#define TRK_HYCA_MAX_STATES 64   /**< largest m_lost */

/* ---- 1. missed detections only ---- */

/** The model of the missed-detections-only recursion (trk_hyca_md). */
struct trk_hyca_md_params {
    int nz;                  /**< 1 or 2 position coordinates */
    trk_real dt_s;           /**< T > 0 */
    trk_real q_m2_per_s3;    /**< process noise PSD q~ > 0 */
    trk_real r_m2;           /**< measurement noise variance r > 0 */
    trk_real pd;             /**< detection probability in (0, 1] */
    int max_iter;            /**< iteration cap; 0: 1000000 */
    trk_real rel_tol;        /**< convergence rule of trk/mre.h; 0: 64 eps */
};

/** The fixed point of trk_hyca_md. */
struct trk_hyca_md_result {
    int nx;                                          /**< 2 nz */
    trk_real p_det[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX];  /**< P_1: given a detection */
    trk_real p_miss[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX]; /**< P_2: given a miss */
    trk_real p[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX];      /**< pd P_1 + (1 - pd) P_2 (eq 48) */
    trk_real rmse_m;         /**< sqrt of the position variances of p */
    int iterations;          /**< steps to the fixed point */
    trk_real last_change;    /**< max |change| of P_1, P_2 in the last step */
    trk_real rel_tol;        /**< the tolerance the convergence test used */
};

/** Iterate eq 46 from P_1 = P_2 = 0 to its fixed point.
 * TRK_E_ARG NULL / nz not 1 or 2 / max_iter < 0, TRK_E_NAN non-finite
 * parameter, TRK_E_RANGE a parameter outside its range, TRK_E_DIVERGED no
 * convergence within max_iter (res holds the last iterate). */
TRK_NODISCARD trk_status trk_hyca_md(const struct trk_hyca_md_params *params,
                                     struct trk_hyca_md_result *res);

/* ---- 2. with clutter: the chain over the number of gated measurements ---- */

/** The model of the chain with clutter (trk_hyca_init). */
struct trk_hyca_params {
    int nz;                  /**< 1 or 2 */
    /** @{ */
    trk_real dt_s, q_m2_per_s3, r_m2;  /**< as above */
    /** @} */
    trk_real pd;             /**< detection probability in (0, 1] */
    trk_real gate_prob;      /**< P_G in (0, 1) (gamma from it unless gate_gamma > 0) */
    trk_real gate_gamma;     /**< > 0: the gate threshold on d2 itself; 0: from gate_prob */
    trk_real clutter_density;  /**< lambda >= 0 per m^nz */
    int m_lost;              /**< gated count that counts as lost, 2..TRK_HYCA_MAX_STATES;
                                0: 10 (Willett, Fig. 8) */
    int max_scans;           /**< iteration cap; 0: 100000 */
    int horizon_scans;       /**< > 0: also the figures of a run cut at this many scans
                                (a simulation's length); 0: none */
    trk_real rel_tol;        /**< quasi-stationary convergence (rule of trk/mre.h) on the
                                covariances, the state probabilities and the loss rate;
                                0: 1e-10 in double, 1e-5 in float */
};

/** Validated model and the quadrature tables (init once, then read-only). */
struct trk_hyca {
    struct trk_hyca_params params;  /**< as given to trk_hyca_init */
    int nx;  /**< state dimension 2 nz */
    trk_real gamma;          /**< gate threshold on d2 */
    trk_real f[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX];  /**< transition matrix F (nx x nx) */
    trk_real q[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX];  /**< process noise covariance Q (nx x nx) */
    struct trk_irf irf;      /**< E_n[beta_1] at the chain's gate (trk/irf.h) */
};

/** TRK_E_ARG NULL / nz / m_lost / max_scans, TRK_E_NAN non-finite parameter,
 * TRK_E_RANGE a parameter outside its range (gamma above
 * TRK_IRF_MAX_GAMMA too). *h untouched on error. */
TRK_NODISCARD trk_status trk_hyca_init(struct trk_hyca *h, const struct trk_hyca_params *params);

/** The quasi-stationary figures of the chain (trk_hyca_run). */
struct trk_hyca_result {
    /** @{ state dimension 2 nz and the lost state's gated count (from the parameters) */
    int nx, m_lost;
    /** @} */
    trk_real p_held[TRK_HYCA_MAX_NX * TRK_HYCA_MAX_NX]; /**< E[P | held], quasi-stationary */
    trk_real rmse_m;              /**< sqrt of its position variances */
    trk_real mu[TRK_HYCA_MAX_STATES]; /**< P{m = j | held}, quasi-stationary */
    trk_real mean_gated;          /**< sum_j j mu_j */
    trk_real loss_per_scan;       /**< P{lost at the next scan | held}, quasi-stationary */
    trk_real mean_life_scans;     /**< E[L]; +inf when the loss probability is 0 */
    trk_real median_life_scans;   /**< first k with S(k) <= 1/2; +inf likewise */
    trk_real lost_by_horizon;     /**< 1 - S(horizon_scans) (0 without a horizon) */
    trk_real mean_life_horizon;   /**< E[min(L, horizon_scans)] (0 without a horizon) */
    int iterations;               /**< scans iterated */
    int converged;                /**< 1: quasi-stationary reached (geometric tail);
                                     0: S(k) fell below 1e-15 first (the sums are
                                     then complete, the quasi-stationary figures are
                                     those of the last scan) */
};

/** Run the chain from a new track (m = 1, covariance p0: nx x nx SPD, or NULL
 * for the two-point-differencing covariance). TRK_OK with *res filled;
 * TRK_E_DIVERGED when max_scans pass without convergence (res holds the
 * last scan's figures); TRK_E_NOT_SPD / TRK_E_NAN a bad p0 or a non-finite
 * result; TRK_E_ARG NULL. */
TRK_NODISCARD trk_status trk_hyca_run(const struct trk_hyca *h, const trk_real *p0,
                                      struct trk_hyca_result *res);

#endif /* TRK_HYCA_H */
