/* trk/confirm_mn.h - M-of-N track confirmation (CONVENTIONS "M/N
 * confirmation"; 'Tracking Radar' 2.2.4, Willett II.A item 1).
 *
 * Per scan t = 1, 2, ... the caller passes whether the tentative track had a
 * detection in its gate.
 *   fixed:   count = detections in scans 1..min(t, N); decision +1 (confirm)
 *            at the first t with count >= M, -1 (reject) at the first t with
 *            count + (N - t) < M (the outcome is certain).
 *   sliding: count = detections in the last min(t, N) scans; +1 at the first
 *            t with count >= M; never -1 (pair it with a maximum tentative life).
 * Decisions are sticky: the first one holds, later steps repeat it.
 *
 * struct trk_mn_model (M, N, mode; validated once, shared by every track)
 * and struct trk_mn (one track's window and count). */
#ifndef TRK_CONFIRM_MN_H
#define TRK_CONFIRM_MN_H

#include "trk/types.h"

#define TRK_MN_MAX_N 64

enum trk_mn_mode { TRK_MN_FIXED = 0, TRK_MN_SLIDING = 1 };

struct trk_mn_params {
    int m;                 /* detections needed, 1..n */
    int n;                 /* window length in scans, 1..TRK_MN_MAX_N */
    enum trk_mn_mode mode;
};

/* Shared, read-only after init. */
struct trk_mn_model {
    int m, n;
    enum trk_mn_mode mode;
};

/* Per track. */
struct trk_mn {
    uint64_t history;      /* bit 0 = latest scan */
    uint32_t t;            /* scans seen */
    int count;             /* current count (see above) */
    int decision;          /* +1 confirmed, -1 rejected, 0 pending */
};

/* TRK_E_ARG NULL or bad mode, TRK_E_RANGE m or n out of range. *m untouched
 * on error. */
TRK_NODISCARD trk_status trk_mn_model_init(struct trk_mn_model *m, const struct trk_mn_params *p);

/* Start state of a new track: no scan, count 0, pending. Does nothing when
 * m or s is NULL. */
void trk_mn_reset(const struct trk_mn_model *m, struct trk_mn *s);

/* One scan of a track reset with m; returns the (sticky) decision. */
int trk_mn_step(const struct trk_mn_model *m, struct trk_mn *s, int detected);

#endif
