/** @file
 * trk/confirm_mn.h - M-of-N track confirmation (docs/conventions.md "M/N
 * confirmation"; 'Tracking Radar' 2.2.4, Willett II.A item 1).
 *
 * Per scan t = 1, 2, ... the caller passes whether the tentative track had a
 * detection in its gate.
 *   fixed:   count = detections in scans 1..min(t, N); TRK_DECISION_CONFIRM
 *            at the first t with count >= M, TRK_DECISION_TERMINATE (reject)
 *            at the first t with count + (N - t) < M (the outcome is certain).
 *   sliding: count = detections in the last min(t, N) scans; CONFIRM at the
 *            first t with count >= M; never TERMINATE (pair it with a maximum
 *            tentative life).
 * Decisions are sticky (enum trk_decision, types.h): the first one holds,
 * later steps repeat it; the count keeps running.
 *
 * struct trk_mn_model (M, N, mode; validated once, shared by every track)
 * and struct trk_mn (one track's window and count). */
#ifndef TRK_CONFIRM_MN_H
#define TRK_CONFIRM_MN_H

#include "trk/types.h"

/** Longest M/N window, in scans. */
#define TRK_MN_MAX_N 64

/** The window of the M/N test: TRK_MN_FIXED, scans 1..N (confirms or rejects); TRK_MN_SLIDING, the latest N scans (confirms only). See the file description. */
enum trk_mn_mode { TRK_MN_FIXED = 0, TRK_MN_SLIDING = 1 };

/** Parameters of the M/N test. */
struct trk_mn_params {
    int m;                 /**< detections needed, 1..n */
    int n;                 /**< window length in scans, 1..TRK_MN_MAX_N */
    enum trk_mn_mode mode;  /**< fixed or sliding window */
};

/** Shared, read-only after init. */
struct trk_mn_model {
    /** @{ M detections needed in a window of N scans (from the parameters) */
    int m, n;
    /** @} */
    enum trk_mn_mode mode;  /**< fixed or sliding window (from the parameters) */
};

/** Per track. */
struct trk_mn {
    uint64_t history;      /**< bit 0 = latest scan */
    uint32_t t;            /**< scans seen */
    int count;             /**< current count (see above) */
    enum trk_decision decision; /**< sticky: CONTINUE, CONFIRM or TERMINATE (rejected) */
};

/** TRK_E_ARG NULL or bad mode, TRK_E_RANGE m or n out of range. *m untouched
 * on error. */
TRK_NODISCARD trk_status trk_mn_model_init(struct trk_mn_model *m, const struct trk_mn_params *p);

/** Start state of a new track: no scan, count 0, pending. Does nothing when
 * m or s is NULL. */
void trk_mn_reset(const struct trk_mn_model *m, struct trk_mn *s);

/** One scan of a track reset with m: detected 1 when the gate held a
 * detection, 0 when not. Writes the (sticky) decision to *decision.
 * TRK_E_ARG NULL m, s or decision, TRK_E_RANGE detected not 0 or 1; *s and
 * *decision untouched on error. */
TRK_NODISCARD trk_status trk_mn_step(const struct trk_mn_model *m, struct trk_mn *s, int detected,
                                     enum trk_decision *decision);

#endif
