/** @file
 * trk/confirm_sprt.h - Wald sequential probability ratio test for track
 * confirmation on binary detections (Willett II.B eqs 49-57 in sequential
 * form; docs/conventions.md "Track confirmation and termination", SPRT).
 *
 * H1 target present, H0 track on clutter. Per look:
 *   llr_t = llr_{t-1} + ln f1 - ln f0,  llr_0 = 0,  f0 = P_FA or 1 - P_FA
 *   fixed P_D, event model hmm.events (trk/hmm_detect.h; docs/conventions.md
 *   "Complete detection-event model"):
 *     TRK_EVENTS_COMPLETE (default): ln f1 = ln(1 - (1-P_D)(1-P_FA)) for a
 *       hit, ln(1 - P_D) + ln(1 - P_FA) for a miss (the gate of a present
 *       target may hold clutter too), so a miss adds ln(1 - P_D) < 0
 *       whatever the gate's size;
 *     TRK_EVENTS_PAPER: hit ln(P_D / P_FA), miss ln(1 - P_D) - ln(1 - P_FA)
 *       (the reference vectors' form);
 *   HMM:        f1 the predictive likelihood of trk/hmm_detect.h (per sensor
 *               Markov state, same event models), so llr_t is the log of
 *               Willett's eq 49 ratio (eqs 53 / 55) computed recursively,
 *               O(1) per look.
 *   ln A = ln((1 - beta) / alpha): TRK_DECISION_CONFIRM when llr >= ln A
 *   ln B = ln(beta / (1 - alpha)): TRK_DECISION_TERMINATE (reject) when llr <= ln B
 * alpha = P(confirm | false track), beta = P(reject | true track) (Wald's
 * approximate thresholds). The initiating detection counts only if the
 * caller passes it as the first look (Willett conditions on it, eq 50).
 * The decision (enum trk_decision, types.h) is sticky; llr keeps
 * accumulating after it.
 *
 * struct trk_sprt_model (Wald thresholds, P_D, ln P_D / ln(1 - P_D) or the HMM of
 * every sensor; built once, shared by every track) and struct trk_sprt (one
 * track: llr_t, the per-sensor HMM posteriors and look counts, decision). */
#ifndef TRK_CONFIRM_SPRT_H
#define TRK_CONFIRM_SPRT_H

#include "trk/hmm_detect.h"
#include "trk/types.h"

/** Detection model of a present target (the type of trk_sprt_params.model). */
enum trk_sprt_pd_model {
    TRK_SPRT_FIXED_PD = 0, /**< one P_D for every look */
    TRK_SPRT_HMM = 1       /**< per-sensor two-state Markov model (hmm) */
};

/** Parameters of the SPRT: error probabilities and the detection model of a present target. */
struct trk_sprt_params {
    trk_real alpha;             /**< (0, 1), alpha + beta < 1 */
    trk_real beta;              /**< (0, 1) */
    enum trk_sprt_pd_model model;  /**< fixed P_D or the HMM */
    trk_real pd;                /**< TRK_SPRT_FIXED_PD: P_D in (0, 1) */
    struct trk_hmm_params hmm;  /**< TRK_SPRT_HMM: the model. hmm.events applies to
                                   both models; the rest of hmm is ignored with
                                   fixed P_D */
};

/** Shared, read-only after init. */
struct trk_sprt_model {
    enum trk_sprt_pd_model pd_model;  /**< fixed P_D or the HMM (from the parameters) */
    /** @{ */
    trk_real ln_a, ln_b;        /**< Wald thresholds */
    /** @} */
    enum trk_event_model events; /**< hmm.events, both models */
    /** @{ */
    trk_real pd, miss;          /**< fixed P_D: P_D, 1 - P_D (HMM: 0, 1) */
    /** @} */
    /** @{ */
    trk_real log_pd, log_miss;  /**< fixed P_D: ln P_D, ln(1 - P_D) */
    /** @} */
    struct trk_hmm_model hmm;   /**< HMM (fixed P_D: a valid one-sensor model
                                   carrying the event model) */
};

/** Per track. */
struct trk_sprt {
    struct trk_hmm_state hmm;   /**< HMM posteriors (unused with fixed P_D) */
    trk_real stat;              /**< llr_t */
    trk_real inc;               /**< increment of the latest look */
    uint32_t t;  /**< looks so far */
    enum trk_decision fire;     /**< the latest look alone: CONFIRM llr >= ln A,
                                   TERMINATE llr <= ln B, CONTINUE between */
    enum trk_decision decision; /**< sticky: the first fire that is not CONTINUE */
};

/** TRK_E_ARG NULL, bad model or unknown hmm.events, TRK_E_NAN non-finite
 * parameter, TRK_E_RANGE alpha, beta (or alpha + beta >= 1), pd or a model
 * probability out of range, TRK_E_CAPACITY too many sensors. *m untouched on
 * error. */
TRK_NODISCARD trk_status trk_sprt_model_init(struct trk_sprt_model *m,
                                             const struct trk_sprt_params *p);

/** Start state of a new track: llr = 0, no look, no decision. Does nothing
 * when m or s is NULL. */
void trk_sprt_reset(const struct trk_sprt_model *m, struct trk_sprt *s);

/** One look: detected 1 for a detection in the gate (0 for none), pfa the
 * gate's P_FA (both event models). `sensor` selects the Markov state (HMM model; ignored for
 * fixed P_D). Writes the (sticky) decision to *decision. TRK_E_ARG NULL m, s
 * or decision, TRK_E_RANGE detected not 0 or 1, TRK_E_NAN / TRK_E_RANGE pfa
 * not in (0, 1), TRK_E_SENSOR unknown sensor (HMM); *s and *decision
 * untouched on error. */
TRK_NODISCARD trk_status trk_sprt_step(const struct trk_sprt_model *m, struct trk_sprt *s,
                                       unsigned sensor, int detected, trk_real pfa,
                                       enum trk_decision *decision);

/** One step with a given log-likelihood-ratio increment ln f1 - ln f0 (e.g.
 * with kinematic or amplitude terms). TRK_E_ARG NULL, TRK_E_NAN not finite;
 * *s and *decision untouched on error. */
TRK_NODISCARD trk_status trk_sprt_step_llr(const struct trk_sprt_model *m, struct trk_sprt *s,
                                           trk_real inc, enum trk_decision *decision);

#endif
