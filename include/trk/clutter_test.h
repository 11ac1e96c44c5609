/** @file
 * trk/clutter_test.h - Kennedy's clutter-based confirmation tests (Kennedy
 * 2008 sec. 1.2-1.4; docs/conventions.md "Track confirmation and termination",
 * clutter density / clutter amplitude).
 *
 * H0: the tentative track is on clutter. H0 rejected -> confirm the track.
 * Both tests use a window of the last K = min(t, kmax) updates (t = 1 is the
 * first update after initiation): it grows to kmax, then slides (sec. 1.4).
 *
 * Density test (eqs 3-10): per update rho_vg = rho V_g, the clutter density
 * times the clutter-free gate volume enclosed by the nearest peak
 * (V_g = V_c D^m sqrt|S|, eq 5). Under H0 Z_D = 2 sum_window rho V_g ~
 * chi2(2K) (eq 9). p_value = P(chi2(2K) <= Z_D) (eq 10, the LOWER tail: a
 * target's nearest peak is closer than clutter's; the paper's "exceeds" is a
 * typo). Reject H0 when p_value <= alpha (<=> Z_D <= lower alpha-quantile).
 *
 * Amplitude test (eqs 11-16): per update the SNR (dB) of the associated
 * (nearest) peak and of the N_k other peaks of the scan, all >= a_min (the
 * detection threshold, dB). With Sa = sum_window (a_assoc - a_min), So =
 * sum_window sum_others (a - a_min), dof1 = 2K, dof2 = 2 sum_window N_k:
 * Z_A = (Sa / dof1) / (So / dof2) ~ F(dof1, dof2) under H0 (eq 15; N_k may
 * vary per scan). p_value = P(F >= Z_A) (UPPER tail; eq 16 is 1 - p_value).
 * Reject H0 when p_value <= alpha. While the window holds no other peak
 * (dof2 = 0) there is no test: stat 0, p_value 1. With So = 0 < Sa the
 * statistic is infinite: stat = TRK_REAL_MAX, p_value 0.
 *
 * Decisions are sticky (enum trk_decision, types.h): TRK_DECISION_CONFIRM at
 * the first update that rejects H0; these tests never reject a tentative
 * track (never TERMINATE: pair them with a maximum tentative life).
 * Statistics keep running after a decision.
 *
 * Each test is split in two: a model (validated parameters and, for the
 * density test, the threshold table for K = 1..kmax, which costs a few
 * microseconds per entry) built once by *_model_init and shared by every
 * track, and a per-track state (the window ring and the statistics) started
 * by the cheap *_reset and advanced by *_step, which take both. */
#ifndef TRK_CLUTTER_TEST_H
#define TRK_CLUTTER_TEST_H

#include "trk/types.h"

/* The largest window, TRK_CLUTTER_KMAX (default 32), is a knob of
 * trk/config.h: per-track storage grows with it. */

/* ---------------------------------------------------------------- density */

/** Parameters of the clutter-density (chi-square) confirmation test. */
struct trk_clutter_chi2_params {
    trk_real alpha;  /**< size of the test, (0, 1) (K08 uses 0.01) */
    unsigned kmax;   /**< window length, 1 .. TRK_CLUTTER_KMAX (K08: 25) */
};

/** Shared, read-only after init. */
struct trk_clutter_chi2_model {
    trk_real alpha;  /**< size of the test (from the parameters) */
    unsigned kmax;  /**< window length (from the parameters) */
    trk_real threshold_tab[TRK_CLUTTER_KMAX]; /**< lower alpha-quantile of chi2(2K),
                                                 K = 1..kmax (0 beyond) */
};

/** Per track. */
struct trk_clutter_chi2 {
    trk_real win[TRK_CLUTTER_KMAX]; /**< rho V_g of the window (ring) */
    unsigned head;         /**< next slot of the ring */
    unsigned k;            /**< window length K */
    uint32_t t;            /**< updates so far */
    int dof;               /**< 2K */
    trk_real stat;         /**< Z_D */
    trk_real p_value;      /**< P(chi2(2K) <= Z_D); 1 before the first update */
    trk_real threshold;    /**< model threshold_tab[K-1]: reject <=> stat <= threshold */
    int reject;            /**< p_value <= alpha at the latest update */
    enum trk_decision decision; /**< sticky: CONTINUE or CONFIRM */
};

/** Validate and compute the threshold table. TRK_E_ARG NULL, TRK_E_NAN alpha
 * not finite, TRK_E_RANGE alpha outside (0, 1) or kmax = 0, TRK_E_CAPACITY
 * kmax > TRK_CLUTTER_KMAX. *m untouched on error. */
TRK_NODISCARD trk_status trk_clutter_chi2_model_init(struct trk_clutter_chi2_model *m,
                                                     const struct trk_clutter_chi2_params *p);

/** Start state of a new track (empty window, p_value 1). Does nothing when m
 * or s is NULL. */
void trk_clutter_chi2_reset(const struct trk_clutter_chi2_model *m, struct trk_clutter_chi2 *s);

/** One update with rho_vg = rho V_g of the nearest peak (>= 0). Writes the
 * (sticky) decision to *decision. TRK_E_ARG NULL m, s or decision, TRK_E_NAN
 * rho_vg not finite, TRK_E_RANGE negative; *s and *decision untouched on
 * error. */
TRK_NODISCARD trk_status trk_clutter_chi2_step(const struct trk_clutter_chi2_model *m,
                                               struct trk_clutter_chi2 *s, trk_real rho_vg,
                                               enum trk_decision *decision);

/* ---------------------------------------------------------------- amplitude */

/** Parameters of the amplitude (F) confirmation test. */
struct trk_clutter_amp_params {
    trk_real a_min_db; /**< detection threshold (SNR, dB), finite */
    trk_real alpha;    /**< size of the test, (0, 1) */
    unsigned kmax;     /**< window length, 1 .. TRK_CLUTTER_KMAX */
};

/** Shared, read-only after init. */
struct trk_clutter_amp_model {
    trk_real a_min_db;  /**< detection threshold, SNR dB (from the parameters) */
    trk_real alpha;  /**< size of the test (from the parameters) */
    unsigned kmax;  /**< window length (from the parameters) */
};

/** Per track. */
struct trk_clutter_amp {
    trk_real sa[TRK_CLUTTER_KMAX];       /**< a_assoc - a_min per update (ring) */
    trk_real so[TRK_CLUTTER_KMAX];       /**< sum over others of (a - a_min) */
    uint16_t n_others[TRK_CLUTTER_KMAX]; /**< N_k (<= TRK_MAX_DETECTIONS <= 65535) */
    /** @{ next slot of the ring and window length K */
    unsigned head, k;
    /** @} */
    uint32_t t;  /**< updates so far */
    /** @{ */
    int dof1, dof2;        /**< 2K, 2 sum_window N_k */
    /** @} */
    trk_real stat;         /**< Z_A */
    trk_real p_value;      /**< P(F(dof1, dof2) >= Z_A); 1 before any test */
    int reject;            /**< p_value <= alpha at the latest update */
    enum trk_decision decision; /**< sticky: CONTINUE or CONFIRM */
};

/** TRK_E_ARG NULL, TRK_E_NAN non-finite, TRK_E_RANGE alpha outside (0, 1) or
 * kmax = 0, TRK_E_CAPACITY kmax > TRK_CLUTTER_KMAX. *m untouched on error. */
TRK_NODISCARD trk_status trk_clutter_amp_model_init(struct trk_clutter_amp_model *m,
                                                    const struct trk_clutter_amp_params *p);

/** Start state of a new track. Does nothing when m or s is NULL. */
void trk_clutter_amp_reset(const struct trk_clutter_amp_model *m, struct trk_clutter_amp *s);

/** One update: a_assoc_db the associated peak's SNR, a_others_db[n_others]
 * the other peaks of the scan (may be NULL when n_others = 0), all dB.
 * Writes the (sticky) decision to *decision. TRK_E_ARG NULL m, s, decision
 * (or a_others_db with n_others > 0), TRK_E_CAPACITY n_others >
 * TRK_MAX_DETECTIONS, TRK_E_NAN non-finite amplitude, TRK_E_RANGE an
 * amplitude below a_min_db; *s and *decision untouched on error. */
TRK_NODISCARD trk_status trk_clutter_amp_step(const struct trk_clutter_amp_model *m,
                                              struct trk_clutter_amp *s, trk_real a_assoc_db,
                                              size_t n_others, const trk_real *a_others_db,
                                              enum trk_decision *decision);

/** Upper alpha-quantile of F(dof1, dof2) of the current window (reject <=>
 * stat >= threshold), solved on demand (tens of microseconds; the decision
 * does not need it). TRK_E_ARG NULL, TRK_E_RANGE no test yet (dof2 = 0). */
TRK_NODISCARD trk_status trk_clutter_amp_threshold(const struct trk_clutter_amp_model *m,
                                                   const struct trk_clutter_amp *s,
                                                   trk_real *threshold);

#endif
