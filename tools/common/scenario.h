/* scenario.h - a seeded sonar scenario: constant-velocity targets with
 * process noise, detection with P_D, Poisson clutter over a region, and
 * thresholded amplitudes (amp_sample.h). Shared by trk-sonar-sim (LCM
 * publisher) and trk-sim, tests and benchmarks.
 *
 * Per scan k (time t0 + k T):
 *   targets move: x_k = F x_{k-1} + w, w ~ N(0, Q(T, q)) (trk_cv2_process_noise,
 *     the tracker's own model; the first scan is at the initial states)
 *   each target is detected with P_D (the configured pd, or with an amplitude
 *     model its S1(t) at its SNR): position + N(0, sigma^2 I), amplitude drawn
 *     above the threshold
 *   clutter: Poisson(density x region area) detections (or exactly
 *     clutter_count), uniform over the region, clutter amplitudes
 *   the scan's detections are shuffled (no target-first order)
 * Random numbers: rng (philox) keyed by seed; stream 0 draws the random
 * initial targets and their motion, stream 1 + k everything scan k detects,
 * so a scan's detections do not depend on how many numbers earlier scans
 * used (same seed -> same scenario, bit for bit). */
#ifndef TRK_TOOLS_SCENARIO_H
#define TRK_TOOLS_SCENARIO_H

#include <stddef.h>
#include <stdint.h>

#include "amp_sample.h"
#include "rng.h"
#include "trk/tracker.h"

struct scen_target_init {
    double x_m, y_m, vx_mps, vy_mps;
    double snr_db;              /* NaN: the scenario's snr_db */
};

struct scen_params {
    uint64_t seed;
    unsigned sensor_id;
    int64_t t0_us;              /* time of scan 0, >= 0 */
    double scan_period_s;       /* > 0 */
    double x_min_m, x_max_m, y_min_m, y_max_m; /* clutter region (and random targets) */
    double clutter_density_per_m2;             /* Poisson mean = density x area */
    long clutter_count;         /* >= 0: exactly this many per scan instead */
    double pd;                  /* without amplitude model, (0, 1] */
    double meas_sigma_m;        /* position noise per axis, > 0 */
    int attach_cov;             /* detections carry their covariance sigma^2 I */
    double process_noise_q;     /* m^2/s^3, >= 0 */
    int amp_kind;               /* enum amp_kind (AMP_TABLE: set amp_table) */
    const char *amp_table;      /* amplitude table file (amp_kind AMP_TABLE) */
    double pfa, k_shape, snr_db;/* amplitude model, default target SNR */
    size_t n_targets;           /* targets (explicit when targets != NULL) */
    const struct scen_target_init *targets;
    double speed_min_mps, speed_max_mps; /* random targets: speed range */
};

/* Defaults: seed 1, sensor 0, t0 0, T 2 s, region [0, 2000]^2 m, clutter
 * 5e-6 /m^2 (20 per scan), Poisson, pd 0.9, sigma 3 m, no covariance,
 * q 0.01, Rayleigh amplitudes at pfa 1e-3 and 15 dB (pd = 0.8), 3 random
 * targets at 1-5 m/s. */
void scen_defaults(struct scen_params *p);

struct scen_target {
    double x[4];                /* truth [x, vx, y, vy] at the current scan */
    struct amp_target amp;
    double pd;
};

struct scenario {
    struct scen_params p;
    struct amp_model amp;
    struct scen_target *tg;     /* n_targets (heap) */
    size_t n_tg;
    struct rng motion;
    uint64_t k;                 /* scans produced */
    double q_chol[3];           /* per-axis Cholesky factor of the 2x2 Q block */
    uint64_t n_amp_failures;    /* K inversions that failed (detection dropped) */
};

/* 0, or -1 with a message. */
int scen_init(struct scenario *s, const struct scen_params *p, char *err, size_t errlen);
void scen_free(struct scenario *s);

/* Produce the next scan into det[0 .. max_det) and *scan (scan->detections =
 * det). Detections beyond max_det are dropped (clutter first) and counted in
 * *n_dropped (may be NULL). *n_target_dets (may be NULL): how many come from
 * targets. */
void scen_next(struct scenario *s, struct trk_detection *det, size_t max_det, struct trk_scan *scan,
               size_t *n_target_dets, size_t *n_dropped);

#endif
