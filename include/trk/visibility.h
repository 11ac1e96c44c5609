/* trk/visibility.h - target visibility (IPDA-style existence) of one track,
 * for confirmation and deletion (Kennedy 2008 eqs 1-2 and 21-32;
 * CONVENTIONS "Track confirmation and termination" -> Visibility).
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
 * Decisions (sticky: the first firing holds; the statistics keep running):
 *   confirmed  pcv >= p_con                (Kennedy: tentative -> confirmed)
 *   terminated pcv <  p_term               (deletion; p_term = 0 never fires)
 * As for the other per-track tests, the validated parameters form a model
 * shared by all tracks and each track owns only the small state.
 */
#ifndef TRK_VISIBILITY_H
#define TRK_VISIBILITY_H

#include "trk/types.h"

struct trk_visibility_params {
    trk_real pv0;           /* p_v(1|1), visibility at the initiation scan, (0, 1) */
    trk_real pcv0;          /* p_cv(1), confidence at the initiation scan, [0, 1] */
    trk_real delta_stay;    /* Delta: P(visible -> visible) per scan, [0, 1] */
    trk_real delta_become;  /* Delta_bar: P(invisible -> visible) per scan, [0, 1] */
    trk_real omega_c;       /* smoothing weight of the confidence, [0, 1) */
    trk_real p_con;         /* confirm when pcv >= p_con, (0, 1] */
    trk_real p_term;        /* terminate when pcv < p_term, [0, p_con) (0: never) */
};

/* Validated parameters, shared by every track. */
struct trk_visibility_model {
    struct trk_visibility_params params;
};

/* Per-track state. */
struct trk_visibility {
    trk_real pv_pred;       /* p_v(k|k-1) of the last scan (pv0 before the first) */
    trk_real pv;            /* p_v(k|k) */
    trk_real pcv;           /* smoothed confidence p_cv(k) */
    int confirmed;          /* sticky: pcv reached p_con */
    int terminated;         /* sticky: pcv fell below p_term */
    int scans;              /* updates since init */
};

/* TRK_E_ARG NULL pointer, TRK_E_NAN non-finite parameter, TRK_E_RANGE a
 * parameter outside its range. *v untouched on error. */
TRK_NODISCARD trk_status trk_visibility_model_init(struct trk_visibility_model *m,
                                                   const struct trk_visibility_params *p);

/* Start state of a new track: pv = pv0, pcv = pcv0, no decision. */
void trk_visibility_reset(const struct trk_visibility_model *m, struct trk_visibility *v);

/* One scan from the log of the detection sum,
 *   log_sum = ln sum_i (g_D,i / rho) l_i  (-INFINITY: no gated detection),
 * with detection probability pd in (0, 1] and gate probability pg in (0, 1].
 * (+INFINITY: a detection where clutter is impossible, rho = 0: pv = 1).
 * TRK_E_ARG NULL m or v, TRK_E_NAN NaN log_sum or non-finite pd/pg,
 * TRK_E_RANGE pd or pg outside (0, 1]. v untouched on error. */
TRK_NODISCARD trk_status trk_visibility_update_log(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pd, trk_real pg,
                                                   trk_real log_sum);

/* One scan from the n gated detections: spatial likelihoods gd[i] >= 0 and
 * the clutter density rho > 0 (same units), and log_la[i] = ln l_i (NULL:
 * no amplitude, l_i = 1). n <= TRK_MAX_DETECTIONS. TRK_E_CAPACITY above it;
 * otherwise as trk_visibility_update_log, TRK_E_RANGE for gd[i] < 0 or
 * rho <= 0, TRK_E_NAN for a non-finite gd, rho or log_la. */
TRK_NODISCARD trk_status trk_visibility_update(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pd, trk_real pg, size_t n,
                                               const trk_real *gd, trk_real rho, const trk_real *log_la);

#endif
