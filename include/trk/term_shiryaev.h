/** @file
 * trk/term_shiryaev.h - Shiryaev (Bayesian quickest detection) track
 * termination with the fluctuating-SNR detection model (Blanding et al. 2007
 * eqs 11-14; Willett II.C eqs 65-68; docs/conventions.md "Track confirmation and
 * termination", Shiryaev).
 *
 * Prior on the change time k_c (eq 11): P(k_c = 0) = beta0, then geometric
 * with per-look probability rho. The statistic is the posterior log-odds of
 * a change (eqs 13-14), carried in the log domain:
 *   g_0 = ln(beta0 / (1 - beta0))
 *   g_t = logaddexp(ln rho, g_{t-1}) - ln(1 - rho) + s_t,  s = ln f0 - ln f1
 *   (rho = 0: g_t = g_{t-1} + s_t)
 *   terminate when g_t > h (strict); h = ln(b / (1 - b)) for a posterior
 *   probability threshold b, so any finite h is valid.
 * exp(g) is never formed: g passes +709 and -745 on long runs. The decision
 * (TRK_DECISION_TERMINATE, enum trk_decision in types.h) is sticky; the
 * statistic keeps running after it. Multisensor as Page; hmm.events selects
 * the event model of f1 as for Page (trk/term_page.h, trk/hmm_detect.h).
 *
 * struct trk_shiryaev_model (threshold, g_0, ln rho, ln(1 - rho) and the HMM
 * of every sensor; built once, shared by every track) and struct
 * trk_shiryaev (one track: g_t, the per-sensor HMM posteriors and look
 * counts, decision). */
#ifndef TRK_TERM_SHIRYAEV_H
#define TRK_TERM_SHIRYAEV_H

#include "trk/hmm_detect.h"
#include "trk/types.h"

/** Parameters of the Shiryaev test. */
struct trk_shiryaev_params {
    struct trk_hmm_params hmm; /**< detection model of a present target and
                                  its event model (hmm.events) */
    trk_real beta0;            /**< P(change before the first look), (0, 1) */
    trk_real rho;              /**< per-look change probability, [0, 1) */
    trk_real h;                /**< threshold on the log-odds g, finite */
};

/** Shared, read-only after init. */
struct trk_shiryaev_model {
    struct trk_hmm_model hmm;  /**< detection model (from the parameters) */
    trk_real h;  /**< threshold on g (from the parameters) */
    trk_real g0;          /**< ln(beta0 / (1 - beta0)) (eq 13 at k = 0) */
    trk_real log_rho;     /**< ln rho (unused when rho = 0) */
    trk_real log1m_rho;   /**< ln(1 - rho) */
    int rho_zero;  /**< 1 when rho = 0 */
};

/** Per track. */
struct trk_shiryaev {
    struct trk_hmm_state hmm;  /**< HMM posteriors */
    trk_real stat;        /**< g_t (g_0 before the first look) */
    trk_real s;           /**< increment of the latest look */
    uint32_t t;  /**< looks so far */
    int fire;             /**< g_t > h at the latest look */
    enum trk_decision decision; /**< sticky: CONTINUE or TERMINATE */
};

/** TRK_E_ARG NULL or unknown hmm.events, TRK_E_NAN non-finite parameter,
 * TRK_E_RANGE beta0 or rho or a model probability out of range,
 * TRK_E_CAPACITY too many sensors. *m untouched on error. */
TRK_NODISCARD trk_status trk_shiryaev_model_init(struct trk_shiryaev_model *m,
                                                 const struct trk_shiryaev_params *p);

/** Start state of a new track: g = g_0, no look, no decision. Does nothing
 * when m or s is NULL. */
void trk_shiryaev_reset(const struct trk_shiryaev_model *m, struct trk_shiryaev *s);

/** One look of `sensor` (see trk_page_step). Same statuses; *s and
 * *decision untouched on error. */
TRK_NODISCARD trk_status trk_shiryaev_step(const struct trk_shiryaev_model *m,
                                           struct trk_shiryaev *s, unsigned sensor,
                                           int detected, trk_real pfa,
                                           enum trk_decision *decision);

/** One step with a given increment s = ln f0 - ln f1 (HMM state untouched).
 * TRK_E_ARG NULL, TRK_E_NAN s not finite; *s and *decision untouched on
 * error. */
TRK_NODISCARD trk_status trk_shiryaev_step_llr(const struct trk_shiryaev_model *m,
                                               struct trk_shiryaev *s, trk_real s_inc,
                                               enum trk_decision *decision);

#endif
