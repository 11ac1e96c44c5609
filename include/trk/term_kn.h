/** @file
 * trk/term_kn.h - K-of-N track termination (docs/conventions.md "K/N termination";
 * Blanding sec. 1, Willett II.A).
 *
 * count = detections in the last min(t, N) scans; terminate iff t >= N and
 * count <= K ("K or fewer in the last N"; no decision before N scans).
 * K = 0 is "N consecutive misses". The decision (TRK_DECISION_TERMINATE,
 * enum trk_decision in types.h) is sticky; the count keeps running.
 *
 * struct trk_kn_model (K, N; validated once, shared by every track) and
 * struct trk_kn (one track's window and count). */
#ifndef TRK_TERM_KN_H
#define TRK_TERM_KN_H

#include "trk/types.h"

/** Longest K/N window, in scans. */
#define TRK_KN_MAX_N 64

/** Parameters of the K/N test: terminate with K or fewer detections in the last N scans. */
struct trk_kn_params {
    int k; /**< 0..n-1 */
    int n; /**< 1..TRK_KN_MAX_N */
};

/** Shared, read-only after init. */
struct trk_kn_model {
    /** @{ K and N (from the parameters) */
    int k, n;
    /** @} */
};

/** Per track. */
struct trk_kn {
    uint64_t history; /**< bit 0 = latest scan */
    uint32_t t;  /**< scans so far */
    int count;  /**< detections in the last min(t, N) scans */
    int fire;     /**< raw comparison of the latest step: t >= N and count <= K */
    enum trk_decision decision; /**< sticky: CONTINUE or TERMINATE */
};

/** TRK_E_ARG NULL, TRK_E_RANGE n out of range or k outside 0..n-1. *m
 * untouched on error. */
TRK_NODISCARD trk_status trk_kn_model_init(struct trk_kn_model *m, const struct trk_kn_params *p);

/** Start state of a new track. Does nothing when m or s is NULL. */
void trk_kn_reset(const struct trk_kn_model *m, struct trk_kn *s);

/** One scan of a track reset with m: detected 1 when the gate held a
 * detection, 0 when not. Writes the (sticky) decision to *decision.
 * TRK_E_ARG NULL m, s or decision, TRK_E_RANGE detected not 0 or 1; *s and
 * *decision untouched on error. */
TRK_NODISCARD trk_status trk_kn_step(const struct trk_kn_model *m, struct trk_kn *s, int detected,
                                     enum trk_decision *decision);

#endif
