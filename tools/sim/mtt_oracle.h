/* mtt_oracle.h - the known-association bound of `trk-sim mtt` (the "oracle"):
 * per target one constant-velocity Kalman filter fed only with that target's
 * own detections (the scan generator's origin of each detection), with the
 * sensor's R and the process noise q the trackers get. What any tracker with
 * this sensor and motion model could at best do: no clutter, no other target
 * and no initiation logic in its way. (Where a target manoeuvres beyond q
 * the filter lags it and, unlike a tracker, never starts again: no bound
 * there.)
 *
 * Per target:
 *   first detection   kept (no track yet)
 *   second detection  the track starts, from the two by two-point
 *                     differencing (trk_cv2_two_point, as trk's initiation):
 *                     from this scan on the track is reported (confirmed)
 *   every later scan  predicted to the scan time (trk_cv2_predict), then
 *                     updated with its detection if it has one
 *                     (trk_kalman_update, Joseph form); a missed detection
 *                     leaves the prediction
 *   the target gone   mtt_oracle_end: the track ends and does not restart
 * A detection's covariance is its own (has_cov) or else the sensor's R. Two
 * detections of one target in a scan update it one after the other. The
 * Kalman formulas are the library's (trk/kalman.h); nothing of the filter
 * is computed here. Host code (tools/sim): the per-target state is on the
 * heap. */
#ifndef TRK_SIM_MTT_ORACLE_H
#define TRK_SIM_MTT_ORACLE_H

#include <stddef.h>

#include "trk/kalman.h"
#include "trk/tracker.h"

enum mtt_oracle_state {
    MTT_ORACLE_NONE = 0, /* no detection of the target yet */
    MTT_ORACLE_ONE,      /* its first detection held */
    MTT_ORACLE_TRACK,    /* the filter runs: reported */
    MTT_ORACLE_ENDED     /* the target has gone */
};

struct mtt_oracle_track {
    int state;                  /* enum mtt_oracle_state */
    double t0_s;                /* ONE: the first detection's time ... */
    trk_real z0_m[TRK_CV2_NZ];  /* ... position ... */
    trk_real r0_m2[TRK_CV2_NZ * TRK_CV2_NZ]; /* ... and covariance */
    double t_s;                 /* TRACK: the time of x and p */
    long start_scan;            /* TRACK: the scan index the track started at */
    trk_real x[TRK_CV2_NX];     /* [x, vx, y, vy] */
    trk_real p[TRK_CV2_NX * TRK_CV2_NX];
};

struct mtt_oracle {
    trk_real r_m2[TRK_CV2_NZ * TRK_CV2_NZ]; /* the sensor's R (2 x 2) */
    trk_real q_m2_per_s3;       /* CV process noise */
    long scans;                 /* scans processed */
    size_t n_targets;
    struct mtt_oracle_track *tr; /* per target index */
};

/* What one scan did. */
struct mtt_oracle_report {
    size_t n_target_det;        /* detections of a target (origin >= 0) */
    size_t n_updated;           /* tracks updated with a detection */
    size_t n_started;           /* tracks started (second detections) */
};

/* Targets 0 .. n_targets-1, the sensor's R as [xx, xy, yy] (TRK_COV2_*),
 * q >= 0. 0, or -1 (bad argument: R not SPD, q negative or not finite; no
 * memory). */
int mtt_oracle_init(struct mtt_oracle *o, size_t n_targets, const trk_real cov_m2[3], trk_real q_m2_per_s3);
void mtt_oracle_free(struct mtt_oracle *o);

/* One scan: the running tracks predicted to its time, then each detection
 * whose origin (one per detection, the target index or -1 for clutter) is a
 * target not ended given to that target's filter. rep may be NULL. 0, or -1
 * for a scan back in time, an origin beyond the targets, or a refused
 * filter step (a non-finite detection, S not positive definite). */
int mtt_oracle_scan(struct mtt_oracle *o, const struct trk_scan *scan, const long *origin,
                    struct mtt_oracle_report *rep);

/* Target i has gone: its track ends (1 when it had one, else 0). */
int mtt_oracle_end(struct mtt_oracle *o, size_t i);

/* Target i's track (x, p at the last scan's time), or NULL when it has none
 * (not yet two detections, or ended). */
const struct mtt_oracle_track *mtt_oracle_track(const struct mtt_oracle *o, size_t i);

#endif
