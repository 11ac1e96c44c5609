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
 *     clutter_count), uniform over the region, clutter amplitudes; or, with
 *     clutter_around_m > 0, the clutter field below (Poisson, density
 *     clutter_density_per_m2) inside the union of the squares of half-width
 *     clutter_around_m centred on the targets' true positions ("around the
 *     target": clutter only where a track on a target can gate it)
 *   a target may end (target_end_scan): from that scan on it is never detected
 *   optional two-state fluctuating detection (Blanding eqs 1-2, fluct = 1):
 *     each target carries a Markov state high/low, p = P(low -> high),
 *     q = P(high -> low) per scan, started from the stationary law
 *     P(high) = p / (p + q); high detects with the target's P_D, low with
 *     fluct_pd_low. A detection's amplitude follows the target's law in
 *     either state (the fading changes how often the echo is detected, not
 *     the law of a detected echo).
 *   the scan's detections are shuffled (no target-first order)
 * Random numbers: rng (philox) keyed by seed; stream 0 draws the random
 * initial targets, their motion and their detection states, stream 1 + k
 * everything scan k detects, so a scan's detections do not depend on how many
 * numbers earlier scans used (same seed -> same scenario, bit for bit). The
 * options off, the scenario is the same as before they existed. */
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
    double clutter_around_m;    /* > 0: clutter only within this half-width of the
                                   targets (clutter field; region and clutter_count
                                   unused for clutter); 0: over the region */
    const long *target_end_scan;/* NULL, or per target: from this scan index on the
                                   target is gone (moves on, never detected); 0 = never */
    int fluct;                  /* 1: two-state fluctuating detection (above) */
    double fluct_p, fluct_q;    /* P(low -> high), P(high -> low) per scan, [0, 1], p + q > 0 */
    double fluct_pd_low;        /* P_D of the low state, [0, 1] */
};

/* Defaults: seed 1, sensor 0, t0 0, T 2 s, region [0, 2000]^2 m, clutter
 * 5e-6 /m^2 (20 per scan), Poisson, pd 0.9, sigma 3 m, no covariance,
 * q 0.01, Rayleigh amplitudes at pfa 1e-3 and 15 dB (pd = 0.8), 3 random
 * targets at 1-5 m/s, clutter over the region, no fluctuation. */
void scen_defaults(struct scen_params *p);

struct scen_target {
    double x[4];                /* truth [x, vx, y, vy] at the current scan */
    struct amp_target amp;
    double pd;                  /* nominal P_D (the high state's when fluct) */
    int high;                   /* fluct: current detection state (1 high) */
    long end_scan;              /* gone from this scan index on (0: never) */
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
    struct scen_field *field;   /* clutter_around_m > 0: the clutter field (heap) */
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

/* ---------------------------------------------------------------- clutter field
 * A homogeneous Poisson clutter field over the whole plane, generated lazily
 * tile by tile where it is asked for: a simulation pays for clutter only
 * where it can matter (around a track's prediction, or around the targets),
 * and the realisation is the same whoever asks (two filters run on one
 * (seed, run) see the same clutter: common random numbers).
 * The plane is cut into square tiles of side tile_m (tile (i, j) covers
 * [i L, (i+1) L) x [j L, (j+1) L)); a tile holds Poisson(density L^2) points,
 * uniform in the tile (32-bit resolution), each with a uniform variate u in
 * (0, 1) (53 bits) for its amplitude (x = -ln u is the Exp(1) variate of the
 * truncated survival: trk_amplitude_inv_sf / amp_sample.h). A tile's points depend only on
 * (seed, run, scan, i, j): philox4x32 with key seed ^ SCEN_FIELD_SALT and
 * counter (i mod 2^16 | (j mod 2^16) << 16, scan, block, run), so scan and
 * run are 32-bit and the field repeats every 65536 tiles in each direction.
 * A window query returns exactly the field's points inside the window: a
 * Poisson number with mean density x window area, uniform in it, whatever
 * the tile size (area-exact). The tile size only trades the cost of tiles
 * against the cost of points outside the window: auto (tile_m = 0) is
 * sqrt(4 / density), about 4 points per tile. */
#define SCEN_FIELD_SALT UINT64_C(0x5DEECE66D1F2B3A7)
/* Clutter detections per scan (clutter_count, or the mean density x region
 * area): at most this many, else scen_init refuses the parameters. */
#define SCEN_MAX_CLUTTER 1000000L
#define SCEN_FIELD_MAX_TILES 65536u   /* a window over more tiles is refused */

struct scen_field {
    uint64_t seed;
    double density_per_m2;      /* >= 0 */
    double tile_m;              /* > 0 */
};

struct scen_field_point {
    double x_m, y_m;
    double u;                   /* amplitude variate, uniform in (0, 1) */
};

/* 0, or -1 (density negative or not finite, tile_m negative or not finite). */
int scen_field_init(struct scen_field *f, uint64_t seed, double density_per_m2, double tile_m);

/* The points of (run, scan) in [x_lo, x_hi) x [y_lo, y_hi), in a fixed order
 * (tiles row by row, points in tile order). Writes at most max points to pts
 * (pts may be NULL when max = 0) and returns how many are inside (more than
 * max: only the first max were written); 0 for an empty window; SIZE_MAX
 * when the window covers more than SCEN_FIELD_MAX_TILES tiles or a bound is
 * not finite. */
size_t scen_field_window(const struct scen_field *f, uint32_t run, uint32_t scan, double x_lo,
                         double x_hi, double y_lo, double y_hi, struct scen_field_point *pts,
                         size_t max);

/* The same at another density for this (run, scan) (e.g. a clutter power
 * drawn per scan): the tiles' Poisson means use `density`, the tiling and
 * the random streams stay those of f. */
size_t scen_field_window_at(const struct scen_field *f, double density, uint32_t run, uint32_t scan,
                            double x_lo, double x_hi, double y_lo, double y_hi,
                            struct scen_field_point *pts, size_t max);

#endif
