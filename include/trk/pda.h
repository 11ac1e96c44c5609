/** @file
 * trk/pda.h - probabilistic data association update (PDAF, and PDAFAI when
 * each detection carries an amplitude log-likelihood ratio).
 *
 * docs/conventions.md "PDA" (Bar-Shalom's standard form; Brekke eqs 21-25):
 *   e_0 = lambda (1 - P_D P_G)                       missed detection
 *   e_i = P_D N(nu_i; 0, S) l^a(a_i)                 detection i in the gate
 *   beta_i = e_i / (e_0 + sum_j e_j)                 (log domain: never underflows)
 *   x = x- + K nubar,  nubar = sum beta_i nu_i
 *   P = beta_0 P- + (1 - beta_0) P_c + K (sum beta_i nu_i nu_i' - nubar nubar') K'
 * P_c is the Kalman (Joseph-form) covariance. The spread term is accumulated
 * as sum_i beta_i (dx_i - dxbar)(dx_i - dxbar)' + beta_0 dxbar dxbar' with
 * dx_i = K nu_i: a sum of positive semi-definite terms, so P stays SPD.
 *
 * Clutter: parametric (lambda = clutter_density, per m^nz) or nonparametric
 * (lambda = m_G / V_G, m_G the number of gated detections; m_G = 0 gives
 * beta_0 = 1). Gating off ("include all"): every detection gets its e_i and
 * e_0 still uses the configured P_G.
 *
 * Amplitude (PDAFAI): log_lr[i] = ln l^a(a_i) multiplies e_i; e_0 unchanged;
 * P_D is the detection probability at the amplitude threshold. NULL = PDAF.
 */
#ifndef TRK_PDA_H
#define TRK_PDA_H

#include "trk/kalman.h"
#include "trk/types.h"

/** How the clutter density lambda of an update is found. */
enum trk_clutter_mode {
    TRK_CLUTTER_PARAMETRIC = 0,    /**< lambda given */
    TRK_CLUTTER_NONPARAMETRIC = 1  /**< lambda = m_G / V_G */
};

/** Parameters of a PDA update. */
struct trk_pda_params {
    int nz;                         /**< measurement dimension, 1..TRK_MAX_MEAS */
    trk_real pd;                    /**< detection probability, (0, 1] */
    trk_real gate_prob;             /**< P_G, (0, 1) */
    enum trk_clutter_mode clutter;  /**< parametric (clutter_density) or nonparametric (m_G / V_G) */
    trk_real clutter_density;       /**< lambda per m^nz, >= 0 (parametric only) */
    int gating;                     /**< 1: only d2 <= gamma; 0: include all */
};

/** Validated parameters and the constants derived from them (init once). */
struct trk_pda {
    struct trk_pda_params params;  /**< as given to trk_pda_init */
    trk_real gamma;        /**< gate threshold on d2 */
    trk_real log_pd_norm;  /**< ln P_D - (nz/2) ln 2 pi */
    trk_real log_miss;     /**< ln(1 - P_D P_G) (-inf when P_D P_G = 1) */
    trk_real log_e0_param; /**< ln lambda + log_miss for parametric clutter */
};

/** Check params as trk_pda_init does, without building anything. On a
 * refusal *field (if field is not NULL) names the refused member: "nz",
 * "clutter", "gating", "pd", "gate_prob" or "clutter_density" ("params" for
 * a NULL params); NULL on success. Statuses as trk_pda_init. */
TRK_NODISCARD trk_status trk_pda_check_params(const struct trk_pda_params *params, const char **field);

/** TRK_E_ARG bad pointer/nz/enum, TRK_E_NAN non-finite, TRK_E_RANGE a
 * probability or density outside its range. *pda untouched on error. */
TRK_NODISCARD trk_status trk_pda_init(struct trk_pda *pda, const struct trk_pda_params *params);

/** What one PDA update found (optional output of trk_pda_update). */
struct trk_pda_report {
    trk_real beta0;        /**< probability that no detection is the target's */
    int n_gated;           /**< detections with d2 <= gamma */
    trk_real gate_volume;  /**< V_G of this update */
    trk_real lambda;       /**< clutter density used */
};

/** One PDA update of (x, P), given the predicted state and covariance (in;
 * P symmetric, as every covariance: trk_cv2_predict and trk_kalman_predict
 * keep it exactly so) and m detections z (m x nz, row-major). Writes the
 * posterior into x and P.
 *   h, r       measurement matrix (nz x nx) and noise covariance (nz x nz)
 *   log_lr     m amplitude log-likelihood ratios, or NULL (PDAF)
 *   beta       m outputs: association probabilities (0 outside the gate);
 *              required, also the workspace
 *   d2         m outputs (squared Mahalanobis distances), or NULL
 *   rep        beta_0 and counts, or NULL
 * TRK_E_ARG bad pointer/dimension, TRK_E_CAPACITY m > TRK_MAX_DETECTIONS,
 * TRK_E_NAN non-finite z or log_lr or a non-finite result, TRK_E_NOT_SPD S
 * not positive definite or a posterior variance not > 0. On error x and P
 * are untouched.
 *
 * This is the one per-track PDA of the library: the tracker runs the same
 * code for each track (with detections that carry their own covariance in
 * the same gated set), and the simulators call it.
 *
 * The 2-D CV model's path: nx = 4, nz = 2 and an H that selects
 * x and y of the state [x, vx, y, vy] (trk_cv2_h, recognised by its address
 * without a scan, or an equal array), with no detection of its own
 * covariance, run a copy written over the model's fixed indices, within
 * 1.2-1.3x of a hand-written loop of the same arithmetic (docs/results.md
 * "Benchmarks"). There is no separate entry point to choose: every other
 * model takes the general code. Builds with TRK_SIZE_OPT (the -Os default)
 * keep the general code alone. */
TRK_NODISCARD trk_status trk_pda_update(const struct trk_pda *pda, int nx, const trk_real *h,
                                        const trk_real *r, trk_real *x, trk_real *p, size_t m,
                                        const trk_real *z, const trk_real *log_lr, trk_real *beta,
                                        trk_real *d2, struct trk_pda_report *rep);

/** The same with the innovation of the prediction already computed (by
 * trk_kalman_innovation from this x, P, h and r, e.g. for gating or to draw
 * clutter in the gate first): *inn is used as given, not recomputed.
 * TRK_E_ARG also for inn NULL or inn->nz other than the PDA's nz. */
TRK_NODISCARD trk_status trk_pda_update_inn(const struct trk_pda *pda, int nx, const trk_real *h,
                                            const trk_real *r, trk_real *x, trk_real *p,
                                            const struct trk_innovation *inn, size_t m,
                                            const trk_real *z, const trk_real *log_lr, trk_real *beta,
                                            trk_real *d2, struct trk_pda_report *rep);

/** The state update of the PDA with association weights given by the caller
 * (e.g. the conditional weights of joint association, trk/jpda.h):
 * beta[0] = beta_0 (no detection is the target's), beta[1..m] for the m
 * detections z (m x nz), summing to 1 (within 1e-3); inn the innovation of
 * (x, P) under (h, r) from trk_kalman_innovation. The combination is the
 * one of trk_pda_update (docs/conventions.md "PDA"), so a detection with weight 0
 * does not enter. TRK_E_ARG, TRK_E_CAPACITY m > TRK_MAX_DETECTIONS,
 * TRK_E_NAN / TRK_E_RANGE bad weights or z, TRK_E_NOT_SPD a posterior
 * that is not positive definite; x and P untouched on error. */
TRK_NODISCARD trk_status trk_pda_update_weights(int nx, const trk_real *h, const trk_real *r, trk_real *x,
                                                trk_real *p, const struct trk_innovation *inn, size_t m,
                                                const trk_real *z, const trk_real *beta);

#endif
