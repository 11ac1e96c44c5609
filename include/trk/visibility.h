/** @file
 * trk/visibility.h - target visibility (IPDA-style existence) of one track,
 * for confirmation and deletion (Kennedy 2008 eqs 1-2 and 21-32;
 * docs/conventions.md "Track confirmation and termination" -> Visibility).
 *
 * Per scan, with the previous posterior pv:
 *   pv_pred = Delta pv + Delta_bar (1 - pv)                         (eq 1)
 *   Lam     = (1 - pd pg) + pd sum_i (g_D,i / rho) l_i               (eqs 21-24, 29-31)
 *   pv      = pv_pred Lam / ((1 - pv_pred) + pv_pred Lam)  (= 1 - beta_-1)
 *   pcv     = (1 - omega_c) pv + omega_c pcv                         (eq 2)
 * g_D,i = N(nu_i; 0, S) is the spatial likelihood of gated detection i, rho
 * the clutter density (same units), l_i its amplitude likelihood ratio
 * (Brekke's l^a, or Kennedy's g_A/f_A; 1 without amplitude). With ln l^a the
 * tracker already has ln e_i = ln(pd g_D,i l_i) of the PDA weights, so the
 * update takes log terms: Lam is formed by log-sum-exp and pv by the
 * logistic of ln(pv_pred/(1 - pv_pred)) + ln Lam, never overflowing however
 * large l_i. (Eqs 29-31 divide by pv pd, singular at pv = 0: not used.)
 *
 * Decision (enum trk_decision, types.h; pv and pcv keep running after it):
 *   TRK_DECISION_CONFIRM    the first scan with pcv >= p_con (Kennedy:
 *                           tentative -> confirmed)
 *   TRK_DECISION_TERMINATE  the first scan with pcv < p_term (deletion, or
 *                           rejection of a tentative track; p_term = 0 never
 *                           fires)
 * Sticky as every test's decision, with the one change types.h allows: this
 * test serves a track in both roles with one state (the tracker's
 * trk_track.vis runs from initiation to the end), so a confirmed track later
 * terminates: CONTINUE -> CONFIRM -> TERMINATE, or CONTINUE -> TERMINATE.
 * CONFIRM never returns to CONTINUE, and TERMINATE is final (a terminated
 * track is never confirmed however high pcv climbs).
 * As for the other per-track tests, the validated parameters form a model
 * shared by all tracks and each track owns only the small state.
 */
#ifndef TRK_VISIBILITY_H
#define TRK_VISIBILITY_H

#include "trk/types.h"

/** Parameters of the visibility test (confirmation and termination by the visibility confidence p_cv). */
struct trk_visibility_params {
    trk_real pv0;           /**< p_v(1|1), visibility at the initiation scan, (0, 1) */
    trk_real pcv0;          /**< p_cv(1), confidence at the initiation scan, [0, 1] */
    trk_real delta_stay;    /**< Delta: P(visible -> visible) per scan, [0, 1] */
    trk_real delta_become;  /**< Delta_bar: P(invisible -> visible) per scan, [0, 1] */
    trk_real omega_c;       /**< smoothing weight of the confidence, [0, 1) */
    trk_real p_con;         /**< confirm when pcv >= p_con, (0, 1] */
    trk_real p_term;        /**< terminate when pcv < p_term, [0, p_con) (0: never) */
};

/** Validated parameters, shared by every track. */
struct trk_visibility_model {
    struct trk_visibility_params params;  /**< as given to trk_visibility_model_init */
};

/** Per-track state. */
struct trk_visibility {
    trk_real pv_pred;       /**< p_v(k|k-1) of the last scan (pv0 before the first) */
    trk_real pv;            /**< p_v(k|k) */
    trk_real pcv;           /**< smoothed confidence p_cv(k) */
    enum trk_decision decision; /**< CONTINUE, CONFIRM (pcv reached p_con) or
                                   TERMINATE (pcv fell below p_term); see above */
    int scans;              /**< updates since init */
};

/** TRK_E_ARG NULL pointer, TRK_E_NAN non-finite parameter, TRK_E_RANGE a
 * parameter outside its range. *m untouched on error. */
TRK_NODISCARD trk_status trk_visibility_model_init(struct trk_visibility_model *m,
                                                   const struct trk_visibility_params *p);

/** Start state of a new track: pv = pv0, pcv = pcv0, no decision
 * (CONTINUE). Does nothing when m or v is NULL. */
void trk_visibility_reset(const struct trk_visibility_model *m, struct trk_visibility *v);

/** Start state of a new track with a given existence pv0 in [0, 1] (the
 * tracker's initial existence, trk/tracker.h): pv = pv_pred = pcv = pv0.
 * Does nothing when m or v is NULL. */
void trk_visibility_reset_to(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pv0);

/** One scan: the visibility test's step. log_sum is the log of the detection
 * sum,
 *   log_sum = ln sum_i (g_D,i / rho) l_i  (-INFINITY: no gated detection;
 *             +INFINITY: a detection where clutter is impossible, rho = 0:
 *             pv = 1; trk_visibility_log_sum forms it from the gated set),
 * pd in (0, 1] the detection probability and pg in (0, 1] the gate
 * probability. Updates pv_pred, pv, pcv and the decision and writes the
 * decision to *decision. TRK_E_ARG NULL m, v or decision, TRK_E_NAN NaN
 * log_sum or non-finite pd/pg, TRK_E_RANGE pd or pg outside (0, 1]; *v and
 * *decision untouched on error. */
TRK_NODISCARD trk_status trk_visibility_step(const struct trk_visibility_model *m,
                                             struct trk_visibility *v, trk_real pd, trk_real pg,
                                             trk_real log_sum, enum trk_decision *decision);

/** trk_visibility_step without the decision output (the decision is still
 * updated in v->decision): the tracker's per-scan update of trk_track.vis.
 * Same statuses except that there is no decision pointer to check. */
TRK_NODISCARD trk_status trk_visibility_update_log(const struct trk_visibility_model *m,
                                                   struct trk_visibility *v, trk_real pd,
                                                   trk_real pg, trk_real log_sum);

/** Eq 1: the predicted visibility pv_pred = Delta pv + Delta_bar (1 - pv) of
 * the coming scan (m and v not NULL): the existence psi a joint association
 * weighs the track's events with (trk/jpda.h). */
trk_real trk_visibility_predict(const struct trk_visibility_model *m, const struct trk_visibility *v);

/** One scan whose posterior pv_post in [0, 1] was formed elsewhere (the
 * JIPDA existence of trk_jpda_existence, from pv_pred = trk_visibility_predict):
 * pv_pred, pv, pcv (eq 2) and the decision as trk_visibility_update_log.
 * With the track alone in its cluster, JIPDA's posterior is the pv of
 * trk_visibility_update_log (docs/conventions.md). TRK_E_ARG NULL m or v, TRK_E_NAN
 * non-finite pv_post, TRK_E_RANGE outside [0, 1]; *v untouched on error. */
TRK_NODISCARD trk_status trk_visibility_update_posterior(const struct trk_visibility_model *m,
                                                         struct trk_visibility *v, trk_real pv_post);

/** The step's log_sum from the n gated detections: spatial likelihoods
 * gd[i] >= 0 and the clutter density rho > 0 (same units), and
 * log_la[i] = ln l_i (NULL: no amplitude, l_i = 1), by log-sum-exp
 * (-INFINITY for n = 0). n <= TRK_MAX_DETECTIONS. TRK_E_ARG NULL log_sum (or
 * gd with n > 0), TRK_E_CAPACITY n above TRK_MAX_DETECTIONS, TRK_E_NAN a
 * non-finite gd, rho or log_la, TRK_E_RANGE gd[i] < 0 or rho <= 0; *log_sum
 * untouched on error. */
TRK_NODISCARD trk_status trk_visibility_log_sum(size_t n, const trk_real *gd, trk_real rho,
                                                const trk_real *log_la, trk_real *log_sum);

#endif
