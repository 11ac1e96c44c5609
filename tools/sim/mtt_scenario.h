/* mtt_scenario.h - the multi-target scenario family of `trk-sim mtt` (issue
 * 14 item 7): eight targets in a square region, seeded, deterministic.
 *
 * Region [0, S]^2 (S = region_m, 3 km), a scan every T s (4 s), scans
 * 0 .. n_scans-1 at t_k = k T. The targets, by role (enum mtt_role):
 *   CROSS_A, CROSS_B  an X: both pass the crossing point (the centre + up to
 *                     +-150 m per axis) at the same time, scan n/2 +- 5 %;
 *                     A heads 45 deg +- 10 deg (or the opposite way), B A's
 *                     heading + 90 deg +- 20 deg (crossing angle 70-110 deg)
 *   PAR_A, PAR_B      a pair moving together, parallel_sep_m (60 m) apart
 *                     side by side (same velocity at every time): heading
 *                     along CROSS_A's line +- 5 deg (either way), the pair's
 *                     centre line 300-500 m from the centre (either side),
 *                     its mid-run position +- 150 m along the line
 *   BIRTH             present from scan round(0.2 n) + j (j up to +-1.5 % of n)
 *   DEATH             present until scan round(0.7 n) + j (gone from it on)
 *   TURN              a coordinated turn of turn_deg (90 deg, left or right)
 *                     at turn_rate_dps (3 deg/s) x [0.8, 1.2], centred on
 *                     mid-run +- 5 %; the turn starts 500-700 m from the
 *                     centre, the legs before and after point 45 deg off the
 *                     direction to the centre (+- 10 deg)
 *   STRAIGHT          (also BIRTH and DEATH) straight, through a point
 *                     300-700 m from the centre at mid-life, heading
 *                     tangential +- 30 deg (either way)
 * Motion is deterministic (no process noise): straight legs and the turn's
 * arc (radius v / omega). Speeds are drawn uniformly in [speed_min_mps,
 * speed_max_mps] (5-15 m/s) and then, where the target's path over its life
 * would leave the region less margin_m (50 m), reduced until it stays in:
 * the path is anchored at its mid-life point (the crossing, the pair's
 * mid-run, the turn's start), so a lower speed shrinks it towards that
 * point (speed_drawn_mps keeps the draw). A straight target crosses 3 km
 * at 15 m/s in 200 s: runs of more than ~70 scans of 4 s bring every
 * target down to what its chord allows (at the default 200 scans, 800 s:
 * about 3.5-5.5 m/s).
 *
 * Detections of scan k: each present target with probability pd, at its
 * position + N(0, sigma^2 I); with amplitudes (amplitude = 1) a Swerling I
 * target of snr_db in thresholded Rayleigh clutter (amp_sample.h), the
 * threshold's P_FA chosen so that P_D = S1(t) = pd: pfa = pd^(1 + SNR).
 * Clutter: exactly clutter_count detections uniform over the region
 * (Rayleigh amplitudes above the threshold), capped so that the scan never
 * holds more than max_det (<= TRK_MAX_DETECTIONS) detections: targets' first,
 * then at most max_det - n_target clutter ones (n_clutter_capped counts the
 * clutter left out). The scan is shuffled.
 *
 * Random numbers (rng.h, philox, keyed by seed): stream 0 draws the
 * geometry; scan k uses stream 4k+1 for the targets' detections (four draws
 * per target whether present or detected or not), 4k+2 for the clutter
 * (the same draws per point, so the first N points are the same at every
 * clutter count: scans at 50 clutter hold the first 50 points of the scan at
 * 100, and the targets' detections are the same at every level; with or
 * without amplitudes the positions are the same), 4k+3 for the shuffle.
 * A scan depends only on (seed, k, clutter_count, amplitude): same seed, same
 * scenario bit for bit, in any scan order and from any thread (the scenario
 * is read-only after mtt_scen_init). */
#ifndef TRK_SIM_MTT_SCENARIO_H
#define TRK_SIM_MTT_SCENARIO_H

#include <stddef.h>
#include <stdint.h>

#include "amp_sample.h"
#include "trk/tracker.h"

enum mtt_role {
    MTT_CROSS_A = 0,
    MTT_CROSS_B,
    MTT_PAR_A,
    MTT_PAR_B,
    MTT_BIRTH,
    MTT_DEATH,
    MTT_TURN,
    MTT_STRAIGHT,
    MTT_N_TARGETS
};

struct mtt_scen_params {
    uint64_t seed;
    long n_scans;               /* >= 10 */
    double scan_period_s;       /* > 0 */
    double region_m;            /* side of the square region, >= 1000 */
    double margin_m;            /* targets stay this far inside, [0, region/10] */
    double pd;                  /* detection probability, (0, 1) */
    double meas_sigma_m;        /* position noise per axis, > 0 */
    int amplitude;              /* 1: Rayleigh amplitudes (target snr_db), 0: none */
    double snr_db;              /* target SNR, [0, 40] */
    size_t max_det;             /* scan capacity, 1 .. TRK_MAX_DETECTIONS (0: TRK_MAX_DETECTIONS) */
    double speed_min_mps, speed_max_mps; /* 0 < min <= max */
    double parallel_sep_m;      /* > 0 */
    double turn_deg;            /* (0, 180] */
    double turn_rate_dps;       /* > 0 */
};

/* Defaults: seed 1, 200 scans of 4 s, 3 km region, margin 50 m, pd 0.8,
 * sigma 5 m, amplitudes at 13 dB, capacity TRK_MAX_DETECTIONS, speeds
 * 5-15 m/s, pair 60 m apart, a 90 deg turn at 3 deg/s. */
void mtt_scen_defaults(struct mtt_scen_params *p);

struct mtt_target {
    int role;                   /* enum mtt_role (= its index) */
    long birth_scan;            /* present for birth_scan <= k < death_scan */
    long death_scan;            /* n_scans: present to the end */
    double speed_mps, speed_drawn_mps;
    double ax_m, ay_m, at_s;    /* anchor: position at time at_s */
    double heading_rad;         /* direction of motion (from +x, counter-clockwise);
                                   TURN: before the turn, which starts at the anchor */
    double turn_rad;            /* TURN: signed turn (+ left); 0 otherwise */
    double turn_rate_rps;       /* TURN: |omega| */
};

struct mtt_scenario {
    struct mtt_scen_params p;
    struct amp_model amp;       /* Rayleigh clutter law at the threshold (amplitude = 1) */
    struct amp_target amp_tg;   /* the targets' law */
    double pfa;                 /* threshold P_FA (pd^(1 + SNR)) */
    struct mtt_target tg[MTT_N_TARGETS];
    long cross_scan;            /* the scan nearest the crossing */
    double cross_x_m, cross_y_m;/* the crossing point */
    long turn_first_scan, turn_last_scan; /* scans within the turn [start, end] (first > last: none) */
};

/* 0, or -1 with a message. */
int mtt_scen_init(struct mtt_scenario *s, const struct mtt_scen_params *p, char *err, size_t errlen);
void mtt_scen_free(struct mtt_scenario *s);

/* Truth of target i at time t_s: x = [x, vx, y, vy] (TRK_CV2 order). */
void mtt_scen_truth(const struct mtt_scenario *s, int i, double t_s, double x[4]);
/* 1 when target i is present at scan k. */
int mtt_scen_present(const struct mtt_scenario *s, int i, long k);

struct mtt_scan_info {
    size_t n_target;            /* target detections */
    size_t n_clutter;           /* clutter detections */
    size_t n_clutter_capped;    /* clutter left out by the capacity */
};

/* Scan k (0 <= k < n_scans) with clutter_count clutter detections (>= 0)
 * into det[0 .. max) and *scan (scan->detections = det). max must be at
 * least the scan capacity p.max_det. origin (may be NULL; max entries):
 * the target index of each detection, -1 for clutter. *info may be NULL. */
void mtt_scen_scan(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                   size_t max, int *origin, struct trk_scan *scan, struct mtt_scan_info *info);

const char *mtt_role_name(int role);

/* The tracker defaults as they were before issue 14 (the `old`
 * configuration of trk-sim mtt): trk_tracker_mn_kn_params (M/N 3 of 5, K/N
 * 0/5, single-point initiation, no covariance bound, Delta_bar 0.01). The
 * sensor, q and the clutter density are the caller's to set. (Replacement of
 * the weakest tentative track is part of the table and applies to it too.) */
void mtt_old_defaults(struct trk_tracker_params *p);

#endif
