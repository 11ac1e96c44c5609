/** @file
 * trk/term_page.h - Page (CUSUM) track termination for a target with
 * fluctuating SNR (Blanding et al. 2007 eqs 5-10; Willett II.C eqs 58-64;
 * docs/conventions.md "Track confirmation and termination", Page).
 *
 * Per look (one scan of one sensor, in arrival order):
 *   s   = ln f0 - ln f1      (eq 5; f1 the HMM predictive likelihood of
 *                             trk/hmm_detect.h, f0 = P_FA or 1 - P_FA of the gate)
 *   c_t = max(c_{t-1} + s, 0), c_0 = 0                         (eq 6)
 *   terminate when c_t > h (strict).
 * hmm.events selects f1's event model (trk/hmm_detect.h): under
 * TRK_EVENTS_COMPLETE, the default, a miss gives s = -ln(miss mixture) > 0
 * however large the gate, so a coasting track is terminated; under
 * TRK_EVENTS_PAPER (Blanding eq 8 as printed) s = ln(1 - P_FA) - ln(miss
 * mixture) turns negative as the gate grows and it may never be.
 * Multisensor: every sensor's looks update the one statistic; each sensor
 * keeps its own Markov state (one transition per look of that sensor).
 * The decision (TRK_DECISION_TERMINATE, enum trk_decision in types.h) is
 * sticky (the first firing holds); the statistic keeps running after it (no
 * reset), as the vectors expect.
 *
 * struct trk_page_model (threshold and the HMM of every sensor; built once,
 * shared by every track) and struct trk_page (one track: c_t, the per-sensor
 * HMM posteriors and look counts, decision). */
#ifndef TRK_TERM_PAGE_H
#define TRK_TERM_PAGE_H

#include "trk/hmm_detect.h"
#include "trk/types.h"

/** Parameters of Page's test. */
struct trk_page_params {
    struct trk_hmm_params hmm; /**< detection model of a present target and
                                  its event model (hmm.events) */
    trk_real h;                /**< threshold on c, > 0 */
};

/** Shared, read-only after init. */
struct trk_page_model {
    struct trk_hmm_model hmm;  /**< detection model (from the parameters) */
    trk_real h;  /**< threshold on c (from the parameters) */
};

/** Per track. */
struct trk_page {
    struct trk_hmm_state hmm;  /**< HMM posteriors */
    trk_real stat;   /**< c_t (0 before the first look) */
    trk_real s;      /**< increment of the latest look */
    uint32_t t;      /**< looks so far */
    int fire;        /**< c_t > h at the latest look */
    enum trk_decision decision; /**< sticky: CONTINUE or TERMINATE */
};

/** TRK_E_ARG NULL or unknown hmm.events, TRK_E_NAN non-finite parameter,
 * TRK_E_RANGE h <= 0 or a model probability out of range, TRK_E_CAPACITY
 * too many sensors. *m untouched on error. */
TRK_NODISCARD trk_status trk_page_model_init(struct trk_page_model *m,
                                             const struct trk_page_params *p);

/** Start state of a new track: c = 0, no look, no decision. Does nothing when
 * m or s is NULL. */
void trk_page_reset(const struct trk_page_model *m, struct trk_page *s);

/** One look of `sensor`: detected 1 when the gate held a detection, 0 when
 * not; pfa the gate's false-alarm probability (Blanding eq 4). Writes the
 * (sticky) decision to *decision. TRK_E_ARG NULL m, s or decision,
 * TRK_E_RANGE detected not 0 or 1, TRK_E_NAN / TRK_E_RANGE pfa not in
 * (0, 1), TRK_E_SENSOR unknown sensor; *s and *decision untouched on error. */
TRK_NODISCARD trk_status trk_page_step(const struct trk_page_model *m, struct trk_page *s,
                                       unsigned sensor, int detected, trk_real pfa,
                                       enum trk_decision *decision);

/** One step with a given increment s = ln f0 - ln f1 (e.g. a likelihood ratio
 * that also uses amplitude); the HMM state is not touched. TRK_E_ARG NULL,
 * TRK_E_NAN s not finite; *s and *decision untouched on error. */
TRK_NODISCARD trk_status trk_page_step_llr(const struct trk_page_model *m, struct trk_page *s,
                                           trk_real s_inc, enum trk_decision *decision);

#endif
