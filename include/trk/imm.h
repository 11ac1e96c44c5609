/** @file
 * trk/imm.h - the interacting multiple model estimator (IMM; Blom &
 * Bar-Shalom 1988) for the 2-D state [x, vx, y, vy], alone or with PDA
 * (IMM-PDA), following docs/conventions.md "Multiple models (IMM)":
 *
 *   models     j = 1..n: a coordinated turn at the known rate omega_j
 *              (omega_j = 0: constant velocity), F_ct below, Q the CV Q
 *              (trk_cv2_process_noise) with the model's own q_j
 *   switching  p_ij = P(model j at t | model i at t-T), rows sum to 1
 *   mixing     c_j = sum_i p_ij mu_i,  mu_i|j = p_ij mu_i / c_j,
 *              x0_j = sum_i mu_i|j x_i,
 *              P0_j = sum_i mu_i|j (P_i + (x_i - x0_j)(x_i - x0_j)')
 *   predict    each model predicts (x0_j, P0_j) with its F_j, Q_j
 *   update     one measurement: a Kalman update per model, mode likelihood
 *              Lambda_j = N(z; H x_j-, S_j). With clutter (IMM-PDA): the
 *              validated detections are those inside at least one model's
 *              gate (d2_j <= gamma); each model runs the PDA (trk/pda.h)
 *              over all of them with its own S_j, a validated detection
 *              outside model j's own gate keeping its weight there, and
 *              Lambda_j = lambda (1 - P_D P_G) + P_D sum_i N(nu_ij; 0, S_j) l^a_i
 *   mode       mu_j' ~ Lambda_j c_j (log domain)
 *   combine    x = sum_j mu_j' x_j,  P = sum_j mu_j' (P_j + (x_j - x)(x_j - x)')
 * With one model the IMM is the Kalman filter and the IMM-PDA the PDA.
 *
 *   F_ct = [[1, s/w,      0, -(1-c)/w],
 *           [0, c,        0, -s      ],
 *           [0, (1-c)/w,  1, s/w     ],
 *           [0, s,        0, c       ]],   s = sin wT, c = cos wT
 *
 * Memory: a track's IMM state is n models x (4 + 16) reals and n mode
 * probabilities; nothing else persists. Covariances stay symmetric positive
 * definite: the mixing and combination add positive semi-definite spread
 * terms to convex combinations of SPD matrices, the Kalman and PDA updates
 * are the library's (Joseph form). */
#ifndef TRK_IMM_H
#define TRK_IMM_H

#include "trk/config.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "trk/types.h"

/** TRK_MAX_MODELS: trk/config.h (default 3). */
#define TRK_IMM_NX 4
/** Measurement dimension of the IMM (position x, y). */
#define TRK_IMM_NZ 2

/** The models of an IMM track: constant velocity or coordinated turn each, and the switching matrix. */
struct trk_imm_params {
    int n_models;                                   /**< 1 .. TRK_MAX_MODELS */
    trk_real omega_rad_s[TRK_MAX_MODELS];           /**< turn rate; 0 = CV; |omega| <= 1 rad/s */
    trk_real q_m2_per_s3[TRK_MAX_MODELS];           /**< CV process noise density, >= 0 */
    trk_real p_switch[TRK_MAX_MODELS * TRK_MAX_MODELS]; /**< row i: P(i -> j), n x n packed */
};

/** The mode-conditioned estimates of one track. */
struct trk_imm_state {
    trk_real mu[TRK_MAX_MODELS];  /**< mode probabilities mu_i */
    trk_real x[TRK_MAX_MODELS][TRK_IMM_NX];  /**< mode-conditioned states x_i */
    trk_real p[TRK_MAX_MODELS][TRK_IMM_NX * TRK_IMM_NX];  /**< mode-conditioned covariances P_i (row-major) */
};

/** TRK_E_ARG NULL or n_models outside 1..TRK_MAX_MODELS, TRK_E_NAN non-finite,
 * TRK_E_RANGE a negative q, |omega| > 1 rad/s, a switching probability
 * outside [0, 1] or a row not summing to 1 (within 1e-6). */
TRK_NODISCARD trk_status trk_imm_check_params(const struct trk_imm_params *m);

/** F of a coordinated turn at omega (above); omega = 0 gives the CV F. */
void trk_ct_transition(trk_real dt_s, trk_real omega_rad_s, trk_real f[TRK_IMM_NX * TRK_IMM_NX]);

/** Mixing: mu_pred[j] = c_j, and the mixed initial conditions of every model
 * in place in s (s->mu is left as it was: the update replaces it).
 * TRK_E_ARG NULL, TRK_E_RANGE mode probabilities not a distribution,
 * TRK_E_NAN non-finite result. */
TRK_NODISCARD trk_status trk_imm_mix(const struct trk_imm_params *m, struct trk_imm_state *s,
                                     trk_real mu_pred[TRK_MAX_MODELS]);

/** Predict each model over dt_s > 0 (in place). TRK_E_RANGE dt_s <= 0,
 * TRK_E_NAN non-finite result. */
TRK_NODISCARD trk_status trk_imm_predict(const struct trk_imm_params *m, trk_real dt_s, struct trk_imm_state *s);

/** One measurement z with noise covariance r (2 x 2): a Kalman update per
 * model, log_lik[j] = ln N(z; H x_j-, S_j) (may be NULL), s->mu = the
 * posterior mode probabilities from mu_pred. TRK_E_NOT_SPD, TRK_E_NAN; s
 * untouched on error. */
TRK_NODISCARD trk_status trk_imm_update(const struct trk_imm_params *m, const trk_real r[TRK_IMM_NZ * TRK_IMM_NZ],
                                        const trk_real z[TRK_IMM_NZ], const trk_real mu_pred[TRK_MAX_MODELS],
                                        struct trk_imm_state *s, trk_real *log_lik);

/** Scratch of trk_imm_pda_update (caller-owned; nothing persists). */
struct trk_imm_work {
    trk_real z[2 * TRK_MAX_DETECTIONS];  /**< the gated detections, 2 per row */
    trk_real log_lr[TRK_MAX_DETECTIONS];  /**< their amplitude log-likelihood ratios */
    trk_real beta[TRK_MAX_DETECTIONS];  /**< association probabilities */
};

/** IMM-PDA on a scan of n_det detections z (n_det x 2) with amplitude
 * log-likelihood ratios log_lr (NULL: none). pda: the PDA parameters
 * (parametric clutter; its gating flag is ignored: the validated set is the
 * union of the models' gates). validated (n_det outputs, 1/0, may be NULL);
 * log_lik[j] = ln Lambda_j (may be NULL); s->mu = the posterior mode
 * probabilities. TRK_E_ARG, TRK_E_CAPACITY n_det > TRK_MAX_DETECTIONS,
 * TRK_E_UNSUPPORTED nonparametric clutter, TRK_E_NOT_SPD, TRK_E_NAN; s
 * untouched on error. */
TRK_NODISCARD trk_status trk_imm_pda_update(const struct trk_imm_params *m, const struct trk_pda *pda,
                                            const trk_real r[TRK_IMM_NZ * TRK_IMM_NZ], size_t n_det,
                                            const trk_real *z, const trk_real *log_lr,
                                            const trk_real mu_pred[TRK_MAX_MODELS], struct trk_imm_state *s,
                                            struct trk_imm_work *w, unsigned char *validated, trk_real *log_lik);

/** The combined estimate (moment matching). */
void trk_imm_combine(const struct trk_imm_params *m, const struct trk_imm_state *s, trk_real x[TRK_IMM_NX],
                     trk_real p[TRK_IMM_NX * TRK_IMM_NX]);

#endif /* TRK_IMM_H */
