/** @file
 * trk/tracker.h - the preallocated track table: one call runs a whole scan.
 *
 * struct trk_tracker is caller-owned (static storage in firmware) and holds
 * everything, sized at compile time by config.h: TRK_MAX_TRACKS track slots
 * and a workspace for TRK_MAX_DETECTIONS detections. No heap, no globals.
 *
 * Model: 2-D constant velocity, state [x, vx, y, vy] (m, m/s), Cartesian
 * position measurements [x, y] (m). Up to TRK_MAX_SENSORS sensors, each with
 * its own detection probability, measurement covariance and clutter density
 * (multistatic sonar); a detection may carry its own covariance instead.
 *
 * Polar sensors and where a sensor sees (docs/tracker.md "Polar sensors").
 * A sensor has a pose (position, heading): its own fixed one, or each scan's
 * (trk_scan.has_pose: a moving platform). A polar sensor (kind
 * TRK_SENSOR_POLAR) measures range and bearing: its scans give
 * trk_polar_detection (trk_scan.polar) and the tracker converts each to a
 * position with its own covariance (trk_polar_to_cartesian: first order, or
 * unbiased); a track's R is the conversion's covariance at its predicted
 * position, and so are its gate volume and its covariance bound. Any sensor
 * may have a P_D profile over range and a coverage (range limits, a sector
 * about the heading): a track's P_D is the sensor's at its predicted
 * position (trk_sensor_pd_at) wherever P_D enters its update (PDA and joint
 * weights, existence) and a new track's at its detections (initiation's
 * existence); where P_D is 0 a confirmed track is predicted and not gated,
 * its existence only predicted, its tests not stepped, for up to
 * max_unseen_scans scans in a row (default 0: a track that leaves the
 * coverage ends, as its target left it); a tentative track there ends
 * (TRK_END_REJECTED: it could never be confirmed), and nothing starts. A clutter profile over range does the same for lambda.
 *
 * One scan, trk_tracker_process_scan():
 *   1. validate the scan (at most TRK_MAX_SCAN_DETECTIONS, time order,
 *      sensor id); a refused scan leaves the table untouched; free the slots
 *      of tracks terminated by the previous scan
 *   2. validate each detection (finite position, SPD covariance); bad ones are
 *      counted in the report and skipped, the rest of the scan is processed
 *      (beyond TRK_MAX_DETECTIONS valid ones: the most useful of them, see
 *      "Scans beyond capacity" below);
 *      the valid ones with the sensor's covariance go into a 2-D index (a
 *      grid of about one detection per cell, built in O(detections))
 *   3. every live track: predict to the scan time, gate (the index's cells
 *      under the bounding box of the gate ellipse, then the box, then d2 <=
 *      gamma; detections with their own covariance one by one), then the
 *      association
 *      (params.association):
 *      - TRK_ASSOC_PDA: each track's own PDA over every detection in its
 *        gate (a detection may serve several tracks; confirmed tracks go
 *        first and a tentative track may not use a detection a confirmed
 *        track gated) and its existence by IPDA;
 *      - TRK_ASSOC_JOINT: JIPDA (trk/jpda.h): the gated pairs of all live
 *        tracks form clusters of tracks that share detections; each
 *        cluster's joint events give every track its association weights
 *        and posterior existence; each track's state is the PDA combination
 *        with those weights. A track alone in its cluster gets exactly its
 *        PDA/IPDA update. Every live track competes for every detection (the
 *        per-track rule for tentative tracks does not apply); a track whose
 *        gated pairs do not fit TRK_MAX_GATED_PAIRS is updated after the
 *        joint ones by its own PDA (n_assoc_overflow);
 *      then the covariance bound, then its confirmation test (tentative) or
 *      termination test (confirmed)
 *   4. tracks that have converged onto one target (PDA tracks sharing
 *      detections do) are merged: of two live tracks whose 4-D states are
 *      within merge_gate_d2, the confirmed (else the one with more hits,
 *      else the older) is kept (the pairs to test from a 2-D index of the
 *      tracks' positions)
 *   5. initiation (struct trk_init_params) from the valid detections that no
 *      confirmed track gated nor found within its init_exclusion_d2, and no
 *      tentative track claimed: with joint association and existence, a
 *      tentative track claims a gated detection it more likely than not
 *      explains (posterior existence x its joint weight >= 1/2), so that a
 *      weak tentative track near a target does not keep the target's own
 *      pair from starting; otherwise every one it gated:
 *      two-point (default): a detection that pairs with a candidate, an
 *      unexplained detection of a recent scan within the velocity gate,
 *      starts a tentative track whose velocity and covariance come from the
 *      two points with the velocity prior init_speed_sigma_mps fused in; the
 *      others become candidates (a bounded store of
 *      TRK_MAX_CANDIDATES, config.h). Single-point: every such detection
 *      starts a track (velocity from a zero-mean prior).
 *      A new track takes a free slot, else the slot of the weakest tentative
 *      track when that one's existence is lower than the new track's
 *      (never a confirmed track's); else the initiation is refused. Both
 *      are counted.
 *   6. the report counts what happened
 * Track ids are stable, start at 1 and are never reused within 2^32 tracks.
 * A terminated track stays visible (status TRK_TRACK_TERMINATED) until the
 * next scan, so a consumer sees its end; its slot is then reused. A
 * replaced tentative track is the exception: its slot is taken at once
 * (trk_scan_report.n_replaced).
 *
 * Scans beyond capacity (docs/overcapacity.md). A scan may hold up to
 * TRK_MAX_SCAN_DETECTIONS (65535) detections, however many the build's
 * workspace takes: of its valid detections the scan keeps TRK_MAX_DETECTIONS
 * and counts the rest (n_kept, n_thinned; the caller's array is only read).
 * Rank, highest kept:
 *   1. in a gate box: within the bounding box of some live track's gate
 *      d2 <= gamma (its CV prediction to the scan time with the process
 *      noise q, S = H P H' + R with the detection's R; an IMM track's
 *      combined estimate predicted so: an approximation of its models'
 *      gates); all live tracks while TRK_MAX_TRACKS <= TRK_MAX_DETECTIONS,
 *      else the first TRK_MAX_DETECTIONS, confirmed first;
 *   2. then, when the sensor has an amplitude model (use_amplitude), the
 *      larger amplitude, detections without one after every one with an
 *      amplitude; without a model, a hash of the position's bits (x_m, y_m):
 *      a deterministic thinning that does not depend on the scan's order;
 *   3. ties: the earlier in the scan.
 * The cut (the last kept detection) falls in one class: the gate boxes' or
 * the rest. What was kept of that class follows a known model:
 *   amplitudes: the detection threshold raised to the last kept amplitude
 *     a (the survey's adaptive thresholding): P_D' = S1(a), lambda' = lambda
 *     S0(a) / S0(t) (trk_amplitude_log_sf; thin_threshold = a);
 *   no amplitudes: a uniform thinning to the kept fraction f of the class:
 *     lambda' = f lambda, P_D' = f P_D (a target's detection is left out as
 *     often as a clutter one).
 * They are reported (thin_pd, thin_clutter_density) and used where they
 * hold: when the cut falls in the gate boxes (more gated detections than
 * the workspace holds; thin_in_gates = 1) every track's update (PDA or
 * joint, visibility, the tests' gate P_FA) runs with P_D', lambda' and
 * ln l^a at the raised threshold. When it falls outside, the gates are
 * complete at the sensor's threshold and the updates keep its P_D and
 * lambda; initiation is unchanged either way: its odds beta l^a / lambda and
 * P_D l^a / lambda do not depend on the threshold when the birth density
 * counts detected births (it scales with P_D). Should P_D' or lambda'
 * underflow (a cut beyond ~e^700 of the model's scale), the sensor's values
 * are kept.
 * Cost of a thinned scan, n detections, T live tracks, K =
 * TRK_MAX_DETECTIONS: one CV prediction per track, then per detection its
 * checks, a bisection over the boxes sorted by x and a test of the boxes
 * within the widest half-width (at most T), and a bounded heap of K
 * entries: O(T^2 + n (log T + T_strip + log K) + K log K), worst case
 * (every box overlapping every detection) O(n (T + log K)); memory: the
 * workspace only (no heap, nothing per scan detection).
 */
#ifndef TRK_TRACKER_H
#define TRK_TRACKER_H

#include "trk/amplitude.h"
#include "trk/clutter_test.h"
#include "trk/confirm_mn.h"
#include "trk/confirm_sprt.h"
#include "trk/imm.h"
#include "trk/jpda.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "trk/term_kn.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"
#include "trk/types.h"
#include "trk/visibility.h"

/* ---------------------------------------------------------------- inputs */

/** One detection of a scan. Amplitude fields are used by amplitude-aided
 * association when the sensor has an amplitude model. */
struct trk_detection {
    /** @{ */
    trk_real x_m, y_m;       /**< position */
    /** @} */
    trk_real cov_m2[3];      /**< own covariance [xx, xy, yy] (TRK_COV2_*), used when has_cov */
    trk_real amplitude;      /**< linear envelope amplitude, used when has_amplitude */
    uint8_t has_cov;         /**< 0: use the sensor's covariance */
    uint8_t has_amplitude;  /**< 0: no amplitude (position only) */
};

/** One detection of a polar sensor (TRK_SENSOR_POLAR): range and bearing
 * from the scan's pose. The tracker converts it to a position with its own
 * covariance (the sensor's sigma_range_m, sigma_bearing_rad and
 * conversion; trk_polar_to_cartesian). */
struct trk_polar_detection {
    trk_real range_m;        /**< from the pose's position, > 0 */
    trk_real bearing_rad;    /**< clockwise from the pose's heading */
    trk_real amplitude;      /**< linear envelope amplitude, used when has_amplitude */
    uint8_t has_amplitude;   /**< 0: no amplitude (position only) */
};

/** Where a sensor is and where it looks, in the tracker's frame (x east,
 * y north). Bearings are clockwise from +y: a point at range r and
 * absolute bearing b from (x_m, y_m) is at (x_m + r sin b, y_m + r cos b). */
struct trk_pose {
    /** @{ */
    trk_real x_m, y_m;       /**< position */
    /** @} */
    trk_real heading_rad;    /**< the sensor's reference direction, clockwise from +y;
                                a polar detection's bearing and the coverage sector
                                are measured from it */
};

/** The elements of a packed 2x2 covariance [xx, xy, yy] (cov_m2,
 * meas_cov_m2). */
/** @{ */
#define TRK_COV2_XX 0
#define TRK_COV2_XY 1
#define TRK_COV2_YY 2
/** @} */

/** A covariance [xx, xy, yy] is usable when it is SPD, xx yy does not
 * overflow, and det >= TRK_COV2_MIN_REL_DET xx yy, i.e. its correlation
 * |xy| / sqrt(xx yy) is at most sqrt(1 - 64 eps) (eps the trk_real epsilon:
 * 0.999999999999993 in double, 0.999996 in float): nearer to singular, the
 * gate and the update lose every digit. Refused as not SPD (detections:
 * n_rejected_cov; sensors: TRK_E_NOT_SPD at init). */
#define TRK_COV2_MIN_REL_DET (64 * TRK_REAL_EPS)

/** Largest |time_us| of a scan: 2^62 - 1 us (146,000 years), so that any two
 * times subtract without overflow (the difference stays below 2^63 - 1). */
#define TRK_TIME_US_MAX ((INT64_C(1) << 62) - 1)
/** Least max_dt_s: one microsecond, the resolution of the scan times (a
 * smaller one would allow no gap at all and refuse every scan after the
 * first; refused at init, TRK_E_RANGE "max_dt_s"). */
#define TRK_MAX_DT_S_MIN TRK_REAL_C(1e-6)
/** The surveillance bound (max_coord_m): a detection with |x_m| or |y_m|
 * above it is no position but an error (a unit slip, a corrupt value): it
 * is counted (n_rejected_region) and skipped, never gated or started.
 * Default 1e8 m, 2.5 times round the Earth: beyond any sonar's range and
 * any projected map coordinate (UTM northings stay below 1e7 m). At most
 * TRK_MAX_COORD_M_LIMIT = 1e15 m: a difference of two coordinates inside it
 * squared, 4e30 m^2, stays 1e8 below float's largest value, so that gates,
 * distances and covariances of accepted detections never overflow. */
/** @{ */
#define TRK_MAX_COORD_M_DEFAULT TRK_REAL_C(1e8)
#define TRK_MAX_COORD_M_LIMIT TRK_REAL_C(1e15)
/** @} */

/** The most detections a scan may hold: 65535, so that a scan index fits
 * the workspace's 16-bit indices. A longer scan is refused (TRK_E_CAPACITY). */
#define TRK_MAX_SCAN_DETECTIONS 65535u

/** Looks in a row that a confirmed track's velocity must be consistent with
 * standing still (trk_tracker_params.stationary_d2) before it goes back to
 * held: a few, so that a moving target whose velocity is one scan's noise
 * from zero is not taken for a persistent return. Also the looks in a row a
 * tentative track whose echoes are a scatterer's must move before it is
 * confirmed (TRK_SCATTERER_ECHO_LLR). */
#define TRK_STILL_LOOKS 3

/** ln L_target / L_scatterer (a tentative track's echo evidence, struct
 * trk_track test.confirm.existence.persist_llr) below minus this: echoes a
 * scatterer's by more than e^2 (7.4) to 1. Such a track whose motion test
 * passes is confirmed only after it has passed on TRK_STILL_LOOKS looks in a
 * row, each with its existence test confirming: a track drawn onto a
 * scatterer (its velocity the pull of its first points, not the scatterer's)
 * passes once and then loses the scatterer (docs/tracker.md "Echoes weighed
 * against a scatterer's"). S is kept within +-stationary_d2 / 2, so with
 * stationary_d2 <= 4 no track waits. */
#define TRK_SCATTERER_ECHO_LLR 2

/** One scan of one sensor. The detections are read, never written. */
struct trk_scan {
    int64_t time_us;                        /**< scan time (microseconds, any epoch);
                                               never decreasing. Integer time keeps
                                               float builds free of soft double. */
    unsigned sensor_id;                     /**< 0 .. n_sensors-1 */
    size_t n_detections;                    /**< <= TRK_MAX_SCAN_DETECTIONS; beyond
                                               TRK_MAX_DETECTIONS the scan is thinned
                                               (see "Scans beyond capacity") */
    const struct trk_detection *detections; /**< Cartesian detections; NULL when
                                               n_detections = 0 or polar is given */
    const struct trk_polar_detection *polar; /**< a polar sensor's detections as range
                                                and bearing (n_detections of them;
                                                detections then NULL); NULL otherwise */
    int has_pose;                           /**< 1: pose is this scan's (a moving
                                               platform); 0: the sensor's fixed pose */
    struct trk_pose pose;                   /**< the sensor's pose at time_us, when has_pose */
    const trk_real *clutter_density_per_m2; /**< the caller's clutter density at each detection
                                               (n_detections of them, per m^2 at its
                                               position; e.g. its CFAR's local estimate),
                                               or NULL: the tracker's own (the sensor's,
                                               its profile or its clutter map). Where given
                                               it wins (docs/tracker.md "The caller's
                                               clutter density"); parametric clutter and a
                                               sensor density > 0 only (else the scan is
                                               refused, TRK_E_UNSUPPORTED); a value not
                                               finite or not > 0 rejects its detection
                                               (n_rejected_density) */
};

/** Set up every member of *scan: a scan of n_detections Cartesian
 * detections of sensor sensor_id at time_us, the sensor's fixed pose. A
 * scan built member by member must start from this (or from a zeroed
 * struct): members added in later versions then keep their defaults. */
void trk_scan_init(struct trk_scan *scan, int64_t time_us, unsigned sensor_id, size_t n_detections,
                   const struct trk_detection *detections);

/** The same for a polar sensor's scan: n_detections polar detections seen
 * from *pose (the platform's at time_us; NULL: the sensor's fixed pose). */
void trk_scan_init_polar(struct trk_scan *scan, int64_t time_us, unsigned sensor_id, size_t n_detections,
                         const struct trk_polar_detection *polar, const struct trk_pose *pose);

/* ---------------------------------------------------------------- configuration */

/** What a sensor's detections are. */
enum trk_sensor_kind {
    TRK_SENSOR_CARTESIAN = 0, /**< positions (x, y), with the sensor's covariance or their own */
    TRK_SENSOR_POLAR = 1      /**< range and bearing from the scan's pose (trk_scan.polar),
                                 or positions converted by the caller */
};

/** How a polar detection becomes a position and covariance
 * (docs/conventions.md "Polar detections"). */
enum trk_polar_conversion {
    TRK_POLAR_FIRST_ORDER = 0, /**< x = r sin b, y = r cos b; covariance J diag(sr^2, sb^2) J'
                                  (J the Jacobian). Biased towards the sensor by about
                                  r sb^2 / 2 along the range: negligible while
                                  r sb^2 / sr is small (the default) */
    TRK_POLAR_UNBIASED = 1     /**< Mo et al. (1998): the same scaled by e^(sb^2 / 2), with
                                  their measurement-conditioned covariance (eqs 5, 7) */
};

/** A detection-probability profile over range from the sensor (e.g.
 * from transmission loss): P_D at range_m[k] is pd[k], linear between
 * points, flat beyond the ends. n = 0: no profile, the sensor's pd (or
 * the amplitude model's) everywhere. */
struct trk_pd_profile {
    unsigned n;                            /**< points, 0 or 2 .. TRK_PD_PROFILE_MAX */
    trk_real range_m[TRK_PD_PROFILE_MAX];  /**< strictly increasing, >= 0 */
    trk_real pd[TRK_PD_PROFILE_MAX];       /**< each in [0, 1] */
};

/** A clutter-density profile over range from the sensor (e.g. a sonar's
 * reverberation, falling with range; a polar sensor's uniform clutter in
 * range and bearing, N / (w r) per m^2): lambda at range_m[k] is
 * density_per_m2[k], linear between points, flat beyond the ends. n = 0: no
 * profile, the sensor's clutter_density_per_m2 everywhere. */
struct trk_clutter_profile {
    unsigned n;                                    /**< points, 0 or 2 .. TRK_PD_PROFILE_MAX */
    trk_real range_m[TRK_PD_PROFILE_MAX];          /**< strictly increasing, >= 0 */
    trk_real density_per_m2[TRK_PD_PROFILE_MAX];   /**< each > 0 and finite */
};

/** Where a sensor can see: an annulus sector about the pose's heading.
 * Outside it the sensor's P_D is 0: a track there is predicted, not
 * gated, and not penalised for the scan (its existence only predicted,
 * its tests not stepped). All zero: everywhere. */
struct trk_coverage {
    trk_real min_range_m;      /**< >= 0 */
    trk_real max_range_m;      /**< 0: no limit, else > min_range_m */
    trk_real half_width_rad;   /**< the sector's half width about the heading, [0, pi];
                                  0 or pi: all round */
};

/** One sensor's parameters: detection probability, measurement covariance, clutter density and amplitude model. */
struct trk_sensor_params {
    trk_real pd;                      /**< detection probability of a target, (0, 1];
                                         with an amplitude model its P_D is used */
    trk_real meas_cov_m2[3];          /**< default measurement covariance [xx, xy, yy], SPD */
    trk_real clutter_density_per_m2;  /**< lambda for parametric clutter (and the clutter
                                         tests' rho), in [0, 1e6] (a clutter profile's
                                         bound) */
    /** Amplitude-aided association (PDAFAI, Brekke eqs 19-25): when
     * use_amplitude is 1 each detection's weight is multiplied by
     * l^a(amplitude) of this model (trk_amplitude_init_rayleigh or
     * trk_amplitude_init_table); P_D becomes the model's P_D at its threshold,
     * or with a P_D profile (Rayleigh only) the profile's, the model's SNR
     * then replaced by the one that gives the profile's P_D at each range.
     * A detection below the threshold, or with a NaN/negative amplitude, is
     * rejected and counted; one without an amplitude is used by position only.
     * A table-backed model points into the table's bytes: they must outlive
     * the tracker. */
    int use_amplitude;
    struct trk_amplitude amplitude;  /**< the model used when use_amplitude is 1 */
    /** Polar sensors: each detection's covariance comes from sigma_range_m
     * and sigma_bearing_rad at its range and bearing, and a track's R (its
     * gate volume, its covariance bound) from the same at its predicted
     * position; meas_cov_m2 is then unused. */
    enum trk_sensor_kind kind;
    trk_real sigma_range_m;             /**< polar: range noise (1 sigma), (0, 1e6], its
                                           square a normal number */
    trk_real sigma_bearing_rad;         /**< polar: bearing noise (1 sigma), (0, 0.5], its
                                           square a normal number */
    enum trk_polar_conversion conversion; /**< polar: first-order (default) or unbiased */
    struct trk_pose pose;               /**< the pose of a scan without its own (has_pose 0) */
    struct trk_pd_profile pd_profile;   /**< P_D over range from the pose (n = 0: pd everywhere);
                                           with use_amplitude a Rayleigh model's target SNR
                                           over range (P_D in (pfa, 1): each detection's
                                           l^a at its range, trk_amplitude_log_lr_at_pd) */
    struct trk_coverage coverage;       /**< where P_D is not 0 (all zero: everywhere) */
    struct trk_clutter_profile clutter_profile; /**< lambda over range from the pose (n = 0:
                                                   clutter_density_per_m2 everywhere);
                                                   parametric clutter only, and
                                                   clutter_density_per_m2 > 0 with it (the
                                                   reference, e.g. the mean) */
    /** Persistent returns in the amplitudes (a Rayleigh model, use_amplitude):
     * a share eta of the detections that are not targets' are persistent
     * scatterers' (a rock, a wreck), Swerling I with the SNR whose P_D at
     * the threshold is persistent_pd; the rest is the model's clutter. A
     * detection's l^a is then its target density over that mixture,
     *   l = l_t / ((1 - eta) + eta l_s),
     * l_t, l_s the target's and the scatterers' l^a against the clutter
     * (trk_amplitude_log_lr_at_pd): a return stronger than targets are is
     * taken for a scatterer's, not a target's. 0: none. */
    trk_real persistent_share;         /**< eta, [0, 1) */
    trk_real persistent_pd;            /**< their P_D at the threshold, (pfa, 1) when eta > 0 */
};

/** Confirmation of a tentative track (one method per tracker). */
enum trk_confirm_method {
    TRK_CONFIRM_MN = 0,          /**< M-of-N (confirm_mn.h) */
    TRK_CONFIRM_SPRT = 1,        /**< Wald SPRT on detections (confirm_sprt.h) */
    TRK_CONFIRM_CLUTTER_CHI2 = 2,/**< Kennedy clutter-density test (clutter_test.h) */
    TRK_CONFIRM_CLUTTER_AMP = 3, /**< Kennedy clutter-amplitude test (clutter_test.h);
                                    both need TRK_WITH_CLUTTER_TESTS (config.h) */
    TRK_CONFIRM_VISIBILITY = 4,  /**< visibility confidence: confirm at pcv >= p_con,
                                    reject at pcv < p_term (visibility.h); needs
                                    track_visibility */
    TRK_CONFIRM_EXISTENCE = 5    /**< existence vis.pv (IPDA, with the initial value of
                                    trk_init_params): confirm at pv >= p_confirm, unless
                                    the gate-count check (count_alpha) finds more
                                    detections in the outer ring of the track's recent
                                    gates than its clutter density and its own target
                                    explain; reject
                                    when its odds fell below reject_odds_ratio times
                                    the track's initial odds (a Wald lower threshold on
                                    the likelihood ratio since initiation); needs
                                    track_visibility */
};

/** The most detections one target gives a scan that the gate-count check
 * (trk_existence_confirm_params count_alpha) allows over its whole gate: a
 * sonar target's echo may split into highlights (bow, sail, stern). */
#define TRK_TARGET_RETURNS_MAX 3

/** The existence methods' probabilities must be normal numbers: a value
 * written through another member of the method union (e.g. confirm.u.mn.m = 4
 * while the method is existence) reads as a subnormal and is refused. */
struct trk_existence_confirm_params {
    trk_real p_confirm;          /**< [0.5, 1): confirm what more likely exists than not */
    trk_real reject_odds_ratio;  /**< [0, 1), 0 = never reject */
    trk_real count_alpha;        /**< [0, 1), 0 = off: the gate-count check's size. A
                                    track whose existence reaches p_confirm is not
                                    confirmed at that look while its gates' rings held
                                    too many detections: with n the detections in the
                                    outer half of the gate's area (gamma / 2 < d2 <=
                                    gamma), where half the clutter falls but few of a
                                    target's own returns, however many it gives (a
                                    split echo), and mu = lambda V_G / 2 + P_D
                                    (sqrt(1 - P_G) - (1 - P_G)) expected there (the
                                    clutter density it was given and its own target),
                                    each summed over its looks with the weight
                                    (1 - 1/tau)^age (tau = clutter_map.time_constant_scans,
                                    the window of the density it is given), the Poisson
                                    tail P(N >= floor(n); mu) < count_alpha; or the same
                                    test over the whole gate with mu = lambda V_G +
                                    TRK_TARGET_RETURNS_MAX P_D P_G (a spot denser than a
                                    target's highlights, inside the ring). The density
                                    is then wrong at the track (a reverberation patch the
                                    map averages over a larger cell, a persistent return
                                    more often seen than a target there). Default 0.01 */
};

/** Confirmation of tentative tracks: the method and its parameters. */
struct trk_confirm_params {
    enum trk_confirm_method method;  /**< which test confirms tentative tracks */
    union {
        struct trk_mn_params mn;
        struct trk_sprt_params sprt;
        struct trk_clutter_chi2_params chi2;
        struct trk_clutter_amp_params amp;
        struct trk_existence_confirm_params existence;
    } u;  /**< the parameters of the chosen method (the member of its name) */
};

/** Termination of a confirmed track (one method per tracker). */
enum trk_term_method {
    TRK_TERM_KN = 0,      /**< K-of-N (term_kn.h); K = 0 is "N consecutive misses" */
    TRK_TERM_PAGE = 1,    /**< Page CUSUM with the fluctuating-P_D HMM (term_page.h) */
    TRK_TERM_SHIRYAEV = 2, /**< Shiryaev rule with the same HMM (term_shiryaev.h) */
    TRK_TERM_VISIBILITY = 3, /**< visibility confidence pcv < p_term (visibility.h) */
    TRK_TERM_EXISTENCE = 4   /**< existence vis.pv < p_terminate; needs track_visibility */
};

/** Parameters of the existence termination (TRK_TERM_EXISTENCE). */
struct trk_existence_term_params {
    trk_real p_terminate;        /**< normal, in (0, 1); below p_confirm with existence
                                    confirmation */
};

/** Termination of confirmed tracks: the method and its parameters. */
struct trk_term_params {
    enum trk_term_method method;  /**< which test ends confirmed tracks */
    union {
        struct trk_kn_params kn;
        struct trk_page_params page;
        struct trk_shiryaev_params shiryaev;
        struct trk_existence_term_params existence;
    } u;  /**< the parameters of the chosen method (the member of its name) */
};

/** Per-track state of the chosen tests (fixed size: the largest method; with
 * TRK_WITH_CLUTTER_TESTS = 0 (config.h) the clutter tests are left out). The
 * parameters and derived constants live once in the tracker (struct
 * trk_tracker confirm_model / term_model), not per track. */
union trk_confirm_state {
    struct trk_mn mn;  /**< TRK_CONFIRM_MN */
    struct trk_sprt sprt;  /**< TRK_CONFIRM_SPRT */
    struct {
        trk_real reject_below;   /**< TRK_CONFIRM_EXISTENCE: pv below this rejects (set at start) */
        trk_real count_gated;    /**< the gate-count check's weighted sums of the
                                    detections in the gate's ring, */
        trk_real count_expected; /**< ... and of lambda V_G / 2 + P_D (sqrt(1 - P_G) -
                                    (1 - P_G)) (count_alpha); */
        trk_real count_gated_all;    /**< of the detections in the whole gate, */
        trk_real count_expected_all; /**< ... and of lambda V_G + TRK_TARGET_RETURNS_MAX
                                        P_D P_G */
        trk_real persist_llr;    /**< with a persistent-return description
                                    (trk_sensor_params persistent_share): the sum over
                                    the looks of ln L_target / L_scatterer, within
                                    +-stationary_d2 / 2 (docs/tracker.md "Echoes
                                    weighed against a scatterer's") */
    } existence;  /**< TRK_CONFIRM_EXISTENCE */
#if TRK_WITH_CLUTTER_TESTS
    struct trk_clutter_chi2 chi2;  /**< TRK_CONFIRM_CLUTTER_CHI2 */
    struct trk_clutter_amp amp;  /**< TRK_CONFIRM_CLUTTER_AMP */
#endif
};
/** Per-track state of the chosen termination test (see union trk_confirm_state). */
union trk_term_state {
    struct trk_kn kn;  /**< TRK_TERM_KN */
    struct trk_page page;  /**< TRK_TERM_PAGE */
    struct trk_shiryaev shiryaev;  /**< TRK_TERM_SHIRYAEV */
};

/** The chosen tests' shared models (one per tracker). */
union trk_confirm_model {
    struct trk_mn_model mn;  /**< TRK_CONFIRM_MN */
    struct trk_sprt_model sprt;  /**< TRK_CONFIRM_SPRT */
    struct {
        trk_real count_keep; /**< the gate-count check's weight per look, 1 - 1/tau */
    } existence;  /**< TRK_CONFIRM_EXISTENCE */
#if TRK_WITH_CLUTTER_TESTS
    struct trk_clutter_chi2_model chi2;  /**< TRK_CONFIRM_CLUTTER_CHI2 */
    struct trk_clutter_amp_model amp;  /**< TRK_CONFIRM_CLUTTER_AMP */
#endif
};
/** The chosen termination test's shared model (one per tracker). */
union trk_term_model {
    struct trk_kn_model kn;  /**< TRK_TERM_KN */
    struct trk_page_model page;  /**< TRK_TERM_PAGE */
    struct trk_shiryaev_model shiryaev;  /**< TRK_TERM_SHIRYAEV */
};

/** How tracks start (step 5 above). */
enum trk_init_method {
    TRK_INIT_SINGLE_POINT = 0, /**< every unexplained detection starts a track */
    TRK_INIT_TWO_POINT = 1     /**< two detections of different scans within the velocity gate */
};

/** Initiation and the existence a new track starts with.
 *
 * Two-point initiation (Bar-Shalom, Willett & Tian, "Tracking and Data
 * Fusion" 2011, two-point differencing): candidate c (time t_c, R_c) and
 * detection z (t, R), dt = t - t_c > 0, pair when
 *   |z - z_c| <= max_speed_mps dt + sqrt(gamma lambda_max(R_c + R))
 * (gamma the sensor's gate); the track starts at x = z, v = (z - z_c) / dt,
 * P_pp = R, P_pv = R / dt, P_vv = (R_c + R) / dt^2 (per axis pair, with the
 * xy terms), then the velocity prior v ~ N(0, s_v^2 I), s_v =
 * init_speed_sigma_mps, fused in. A detection pairs with the candidate of
 * the highest ln l^a(z_c) + ln N(z - z_c; 0, R_c + R + s_v^2 dt^2 I): the
 * density of the displacement under that prior and the two points' noise,
 * the same density as in the pair's odds below; a candidate serves one
 * track. Detections are taken in the workspace's order (by the
 * cells of gating's 2-D index, then in scan order; ties of the score: the
 * candidate of smaller x). A candidate pairs with detections of the next
 * max_gap_scans scans (scans processed by this tracker, any sensor), then
 * it is dropped. The store keeps each scan's candidates together, in a 2-D
 * index of their own, so that pairing costs the candidates near each
 * detection and storing costs the scan's new ones; a used
 * candidate keeps its place until its scan's candidates go (under capacity
 * pressure the store holds fewer than a store that squeezed it out).
 *
 * Initial existence (the track score of Blackman & Popoli, "Design and
 * Analysis of Modern Tracking Systems" 1999, sec. 6.2: new-target over
 * false-alarm density, times the amplitude likelihood ratio l^a of each
 * detection (1 without an amplitude model)), as odds:
 *   single point: O = beta l^a(z) / lambda
 *   two points:   O = beta l^a(z_c) / lambda_c * P_D l^a(z) / lambda
 *                     * N(z - z_c; 0, R_c + R + s_v^2 dt^2 I)
 *                 (the target's second point at the density of its
 *                 displacement under the velocity prior and the two
 *                 points' noise, truncated by the gate and not
 *                 renormalised; a clutter one has density lambda)
 *   three points: a pair refused for want of a slot, or too weak to
 *                 start (psi0 below min_existence), leaves its second
 *                 point a candidate that remembers the first; a detection
 *                 that pairs with it inside the gate of that pair's track
 *                 (predicted: S = R + (1 + a)^2 R_c + a^2 R_p + q dt^3 / 3,
 *                 a = dt / dt_pc) has the pair's O times the hit's
 *                 P_D l^a(z) N(z; z^, S) / lambda (Blackman & Popoli's
 *                 score of a third point). The track still starts from the
 *                 last two points; only its existence counts the third.
 *                 So a target whose starts a full table refused outranks
 *                 the fresh clutter pairs that would otherwise hold the few
 *                 free slots (they all start at the same pair odds, and
 *                 replacement needs a strictly lower existence);
 *   the start:    O_start = O / (1 + sum_i beta l^a(z_i) / lambda_i), the
 *                 two or three points' O over all clutter (1) or any one
 *                 of them a new target on its own and the rest clutter
 *                 (its single-point odds; two new targets at once, and a
 *                 triple's pairs without its third point, are left out).
 *                 A strong echo alone is a target's (at 13 dB a target
 *                 detection's l^a is e^17 on average): without the sum a
 *                 pair of it and any clutter point in its velocity gate
 *                 started at existence near 1 with the clutter point's
 *                 velocity. Each term is beta l^a / lambda_i: small
 *                 wherever the clutter density is far above the birth
 *                 density and no echo is strong. A detection's partner is
 *                 still chosen by ln l^a(z_c) + ln N (above), the pair's
 *                 own score, not by O_start, which saturates in l^a(z_c):
 *                 a strong candidate may take a detection whose start then
 *                 waits for a third point;
 *   psi0 = O_start / (1 + O_start); lambda = 0 gives psi0 = 1.
 * A pair whose psi0 is below min_existence starts no track: its second
 * point waits as a candidate for a third, so that the many weak pairs of
 * dense clutter do not each hold a slot and share the targets' detections,
 * while a target's pair, continued, starts with the three points'
 * existence (counted: trk_scan_report.n_init_deferred). Three points
 * within the candidates' lifetime (max_gap_scans + 1 scans: three scans in
 * a row at the default 2) always start, whatever their existence: a weak
 * target waits for three detections in a row where two within two scans
 * would have started it, and is never kept from starting.
 * beta = birth_density_per_m2, lambda the sensor's clutter density, P_D the
 * sensor's. With birth_density_per_m2 = 0 a track starts at the visibility
 * parameters' pv0 / pcv0 instead (Kennedy 2008). The existence is
 * trk_track.vis.pv (needs track_visibility); it orders replacement (lowest
 * first). Without track_visibility replacement orders by n_hits / n_scans. */
struct trk_init_params {
    enum trk_init_method method;  /**< single point or two points */
    trk_real max_speed_mps;           /**< two-point velocity gate, > 0 */
    uint32_t max_gap_scans;           /**< two-point: candidate lifetime in scans,
                                         1 .. TRK_MAX_CANDIDATE_SCANS - 1 (config.h) */
    trk_real birth_density_per_m2;    /**< new targets per m^2 per scan, >= 0 (0: pv0) */
    trk_real min_existence;           /**< two points: the least initial existence psi0 a
                                         pair starts a track with, [0, 1); a weaker pair
                                         waits for a third point (three within the
                                         candidates' lifetime always start; above).
                                         0: every pair starts; no effect with
                                         birth_density_per_m2 = 0 (no psi0) */
};

/** How the live tracks share a scan's detections (step 3 above). */
enum trk_assoc_method {
    TRK_ASSOC_PDA = 0,  /**< per-track PDA (IPDA existence) */
    TRK_ASSOC_JOINT = 1 /**< joint: JPDA, or JIPDA with track_visibility (the track's
                           existence trk_track.vis.pv is then the JIPDA existence);
                           needs parametric clutter with a density > 0 per sensor,
                           and TRK_WITH_JOINT (config.h) */
};

/** The filter every track runs (with imm.n_models = 0; an IMM tracker runs
 * the IMM of its models). */
enum trk_filter_kind {
    TRK_FILTER_KALMAN = 0,    /**< the CV Kalman filter (covariance recursion per track) */
    TRK_FILTER_ALPHA_BETA = 1 /**< the constant-gain filter with the CV Kalman filter's
                                 steady-state gains per axis for the scan's gap
                                 (trk_cv_steady_state; needs TRK_WITH_ALPHA_BETA and
                                 process_noise_q > 0; docs/tracker.md "Track filters") */
};

/** Largest trk_clutter_map_params.window_cells: a lookup reads at most
 * (2 x 8 + 1)^2 = 289 cells. */
#define TRK_CLUTTER_MAP_WINDOW_MAX 8

/** A clutter map per sensor (seed survey ch. 5.3; docs/tracker.md "Clutter
 * map"): the sensor's coverage (trk_coverage: range limits and sector about
 * the heading; a sensor without a maximum range has no map) cut into
 * n_range x n_bearing cells, even in range and in bearing, in the sensor's
 * own frame. Each scan counts per cell the detections no confirmed track
 * gated (weighted by 1 / the kept share in a thinned scan) into an
 * exponentially weighted sum N_c, and the scans into W (both with memory
 * time_constant_scans); a cell's expected count per scan from the
 * configured density is e_c (its profile integrated over the cell). A
 * position's ratio pools the window of cells about its own (window_cells;
 * the guard cells' count less one detection per scan, guard_cells): the
 * Gamma-Poisson posterior mean with prior_count pseudo-counts at the
 * configured density,
 *     rho = (sum N_c + a) / (W sum e_c + a)   over the window;
 * where one of the window's four corner quadrants (up to window_cells + 1
 * rows and columns, each with the position's own cell) holds significantly more
 * than the window's rho predicts (edge_alpha), the greatest such quadrant's
 * rho instead (a greatest-of CFAR at a clutter edge); the result is
 * bounded to [min_ratio, max_ratio], and the density the tracker uses at a
 * position is the configured one (profile) there times its rho:
 * wherever lambda enters (PDA and joint weights, existence, a new track's
 * initial existence). The map starts at rho = 1 (the configured density)
 * and is used before it is updated with the scan's own detections. */
struct trk_clutter_map_params {
    unsigned n_range;              /**< cells over the coverage's ranges; 0: no map */
    unsigned n_bearing;            /**< cells over its bearings (n_range x n_bearing
                                      <= TRK_CLUTTER_MAP_CELLS) */
    trk_real time_constant_scans;  /**< the counts' memory tau, >= 1 scan: weight
                                      (1 - 1/tau)^k on the scan k scans ago */
    trk_real prior_count;          /**< a, a normal number in (0, 1e6]: pseudo-counts at
                                      the configured density */
    trk_real min_ratio;            /**< rho's floor, a normal number in (0, 1]; each
                                      sensor's density (and its clutter profile's) times
                                      it must be normal too, so a cell never reads 0 */
    trk_real max_ratio;            /**< rho's ceiling, >= 1 */
    unsigned window_cells;         /**< a position's ratio pools the cells within this many
                                      rows and columns of its own (a CFAR's training cells,
                                      cut at the map's edges in range, and in bearing
                                      unless the map goes all round); 0: its cell alone;
                                      <= TRK_CLUTTER_MAP_WINDOW_MAX */
    unsigned guard_cells;          /**< <= window_cells + 1: of those, the cells within
                                      guard_cells - 1 rows and columns (1: the position's
                                      own cell) together count one detection per scan
                                      less, not below 0 (a CFAR's guard cells: what a point
                                      target there added before its track was confirmed);
                                      0: none */
    trk_real edge_alpha;           /**< 0 (off) or [TRK_REAL_MIN, 1): a quadrant's rho is
                                      taken when its count n (guard as above) exceeds its
                                      mean mu under the window's rho with a Poisson tail
                                      whose Chernoff bound exp(n - mu - n ln(n / mu)) is
                                      below edge_alpha / 4 (for a known mean, an even
                                      window would be raised with probability at most
                                      edge_alpha): a reverberation patch or a scatterer
                                      beside the position is not averaged away. Needs
                                      window_cells >= 1. Default 0.2 */
};

/** The tracker's parameters: fill with trk_tracker_default_params, then set the sonar's figures; checked by trk_tracker_check_params and trk_tracker_init (docs/parameters.md lists every field). */
struct trk_tracker_params {
    unsigned n_sensors;                               /**< 1 .. TRK_MAX_SENSORS */
    struct trk_sensor_params sensor[TRK_MAX_SENSORS];  /**< sensor[0 .. n_sensors - 1] */
    trk_real process_noise_q;                         /**< m^2/s^3 (docs/conventions.md), >= 0 */
    trk_real gate_prob;                               /**< P_G, (0, 1) */
    enum trk_clutter_mode clutter;                    /**< parametric: the sensor's density */
    trk_real init_speed_sigma_mps;                    /**< velocity prior std per axis, > 0: a
                                                         single-point track's velocity, fused
                                                         into a two-point track's, and the
                                                         density of a pair's displacement
                                                         (trk_init_params) */
    trk_real max_dt_s;                                /**< longest gap between scans, [1e-6, 1e9]
                                                         (TRK_MAX_DT_S_MIN: the scan times'
                                                         resolution, 1 us; to the nearest us);
                                                         a larger gap is refused (TRK_E_RANGE) */
    /** Visibility (IPDA existence, Kennedy eqs 1-2, 21-24), updated for every
     * track each scan with its PDA weights (amplitude included) when
     * track_visibility is 1; required by the visibility confirmation and
     * termination methods. */
    int track_visibility;
    struct trk_visibility_params visibility;  /**< the visibility model (track_visibility, the visibility and existence methods) */
    struct trk_confirm_params confirm;                /**< tentative -> confirmed / rejected */
    struct trk_term_params term;                      /**< confirmed -> terminated */
    trk_real merge_gate_d2;                           /**< two live tracks with state difference
                                                         d2 = dx' (P_i + P_j)^-1 dx <= this
                                                         (4-D, positions and velocities) follow
                                                         one target: the weaker one ends
                                                         (TRK_END_MERGED). 0 = never merge */
    trk_real init_exclusion_d2;                       /**< a detection with d2 <= this to a
                                                         CONFIRMED track (outside its gate)
                                                         starts no new track: the target's
                                                         own stray detections would make
                                                         duplicates. <= gamma: gate only */
    uint32_t max_tentative_scans;                     /**< drop a tentative track after this
                                                         many scans (0 = no limit) */
    uint32_t max_unseen_scans;                        /**< a confirmed track out of the scan
                                                         sensor's sight (P_D 0 at its
                                                         prediction: outside the coverage)
                                                         for more than this many scans in a
                                                         row ends (TRK_END_TERMINATED): 0
                                                         (default) ends a track that leaves
                                                         the coverage at once, as its target
                                                         left it; a sector that turns away
                                                         and back keeps its tracks with a
                                                         larger value */
    trk_real stationary_d2;                           /**< a tentative track whose test would
                                                         confirm it is held tentative (flag
                                                         stationary) while its velocity is
                                                         consistent with standing still:
                                                         v' P_v^-1 v < this (v, P_v its
                                                         velocity and covariance). A
                                                         persistent return (a rock, a wreck)
                                                         then keeps a tentative track that
                                                         takes its returns (they start no
                                                         track; joint association shares
                                                         them) and is never reported
                                                         confirmed; once it moves it is
                                                         confirmed (under its id when its
                                                         gate can follow; a sudden jump
                                                         starts a new track) (seed survey
                                                         ch. 5.3, stationary point tracks).
                                                         A confirmed track whose velocity is
                                                         consistent with standing still for
                                                         TRK_STILL_LOOKS looks in a row goes
                                                         back to held the same way (a pair
                                                         that passed a scatterer with a
                                                         clutter point's velocity, confirmed,
                                                         then held still by its returns; a
                                                         target that stops is not reported
                                                         while it stands, as a new one).
                                                         With a persistent-return description
                                                         (persistent_share) a tentative track
                                                         under the existence test is held
                                                         while v' P_v^-1 v < this - 2
                                                         min(S, this / 10), S the ln
                                                         likelihood ratio of its echoes as
                                                         a target's against a scatterer's,
                                                         summed over its looks within
                                                         +-this / 2
                                                         (test.confirm.existence.persist_llr),
                                                         and one whose echoes are a
                                                         scatterer's (S <
                                                         -TRK_SCATTERER_ECHO_LLR) is held
                                                         until it has moved on
                                                         TRK_STILL_LOOKS looks in a row
                                                         (docs/tracker.md "Echoes weighed
                                                         against a scatterer's").
                                                         Default 25: motion beyond 5 sigma
                                                         (a still object passes at 3.7e-6,
                                                         chi^2 2 dof; at 4.5e-5 at most when
                                                         its echoes are a target's, the bar
                                                         20; measured against
                                                         9.21, chi^2 at 0.99, which reports
                                                         a slow target under a large q
                                                         sooner at more false tracks on
                                                         persistent returns: docs/tracker.md);
                                                         0 = off (a tracker of objects that
                                                         stand still) */
    struct trk_init_params init;                      /**< how tracks start */
    struct trk_clutter_map_params clutter_map;        /**< each sensor's clutter map (a
                                                         sensor with a coverage's maximum
                                                         range; parametric clutter only) */
    trk_real max_pos_sigma_ratio;                     /**< covariance bound (as Stone Soup's
                                                         CovarianceBasedDeleter): a track
                                                         ends (TRK_END_COVARIANCE) when
                                                         trace of its position covariance
                                                         > ratio^2 trace R of the scan's
                                                         sensor, predicted (then it is
                                                         not gated) or updated; >= 0,
                                                         0 = no bound */
    enum trk_assoc_method association;                /**< per-track PDA or joint (JIPDA) */
    enum trk_filter_kind filter;                      /**< the track filter: Kalman (default) or
                                                         alpha-beta */
    trk_real max_coord_m;                             /**< surveillance bound: |x_m|, |y_m| of a
                                                         detection at most this, else counted
                                                         (n_rejected_region) and skipped;
                                                         (0, TRK_MAX_COORD_M_LIMIT], default
                                                         TRK_MAX_COORD_M_DEFAULT (1e8 m) */
#if TRK_WITH_IMM
    /** Manoeuvring targets (TRK_WITH_IMM, config.h; docs/library.md "Manoeuvres"):
     * imm.n_models = 0 (default) runs every track on the CV model of
     * process_noise_q, as a build without IMM; 1 .. TRK_MAX_MODELS makes
     * every track an IMM track on these models (trk/imm.h: turn rates, each
     * model's own q, the switching matrix per scan; process_noise_q is then
     * unused). trk_tracker_imm_params() fills a CV and two-turn set. */
    struct trk_imm_params imm;
#endif
};

/** Tests and their inputs per scan (docs/conventions.md "Track confirmation and
 * termination"): a scan "detects" a track when a detection is in its gate;
 * P_FA of the gate is 1 - exp(-lambda V_G); the sensor id of the scan selects
 * the HMM of multisensor tests. The clutter tests use the detection nearest
 * to the prediction (smallest d2 with the sensor's S, over the whole scan):
 * rho V_g = lambda c_nz d2^(nz/2) sqrt(det S), and its amplitude in dB
 * (20 log10 a, a the linear envelope normalised to mean clutter power 1)
 * against the amplitudes of the scan's other detections. A scan without a
 * detection (or, for the amplitude test, without an amplitude on the nearest
 * detection) leaves the clutter tests unchanged. Clutter tests never reject:
 * pair them with max_tentative_scans.
 *
 * The defaults are in trk_tracker_default_params() (src/tracker_params.c),
 * documented there and in docs/parameters.md; they live in code only. */
void trk_tracker_default_params(struct trk_tracker_params *p);

/** The configuration the defaults were before existence-based confirmation
 * (kept for comparison and for users of M/N): the defaults with M/N 3-of-5
 * confirmation, termination after 5 consecutive misses (K/N 0/5),
 * single-point initiation at the visibility's pv0, no covariance bound,
 * Delta_bar 0.01, the per-track PDA (TRK_ASSOC_PDA) and no hold of tracks
 * that stand still (stationary_d2 = 0). */
void trk_tracker_mn_kn_params(struct trk_tracker_params *p);

#if TRK_WITH_IMM
/** The manoeuvre models of docs/library.md "Manoeuvres" into p->imm: CV, and
 * coordinated turns at +omega_rad_s (left) and -omega_rad_s (right), each
 * with p->process_noise_q; the model stays with probability p_stay per scan
 * and switches to each other one with (1 - p_stay) / 2. Meant for
 * 0 < omega_rad_s <= 1 and p_stay in (0, 1): with p_stay = 1 the turn models
 * are never reached from CV (and never gate; docs/library.md "Manoeuvres"); values
 * are checked by trk_tracker_init, not here. TRK_E_ARG p NULL,
 * TRK_E_CAPACITY a build with TRK_MAX_MODELS < 3 (p untouched). */
TRK_NODISCARD trk_status trk_tracker_imm_params(struct trk_tracker_params *p, trk_real omega_rad_s, trk_real p_stay);
#endif

/* ---------------------------------------------------------------- tracks */

/** Life stage of a track slot. */
enum trk_track_status {
    TRK_TRACK_FREE = 0,
    TRK_TRACK_TENTATIVE = 1,
    TRK_TRACK_CONFIRMED = 2,
    TRK_TRACK_TERMINATED = 3
};

/** Why a track ended (valid when status is TRK_TRACK_TERMINATED). */
enum trk_track_end {
    TRK_END_NONE = 0,
    TRK_END_REJECTED,     /**< tentative track failed its confirmation test, or went out of
                             the sensor's sight (P_D 0 at its prediction) */
    TRK_END_TENTATIVE_AGE,/**< tentative longer than max_tentative_scans */
    TRK_END_TERMINATED,   /**< confirmed track's termination test fired, or it stayed out of
                             the sensor's sight longer than max_unseen_scans */
    TRK_END_NUMERICAL,    /**< covariance lost positive definiteness */
    TRK_END_MERGED,       /**< duplicate of a stronger track (merge_gate_d2) */
    TRK_END_COVARIANCE    /**< position uncertainty over max_pos_sigma_ratio */
};

/** One slot of the track table (trk_tracker_track); read-only for the caller. */
struct trk_track {
    uint32_t id;                      /**< stable, > 0 */
    uint8_t status;                   /**< enum trk_track_status */
    uint8_t end_reason;               /**< enum trk_track_end */
    uint8_t stationary;               /**< 1: a tentative track held because its
                                         velocity is consistent with standing still
                                         (trk_tracker_params.stationary_d2), or
                                         because it has not yet moved on
                                         TRK_STILL_LOOKS looks in a row with echoes
                                         a scatterer's (TRK_SCATTERER_ECHO_LLR) */
    uint8_t n_still_in_row;           /**< a confirmed track: consecutive looks whose
                                         velocity was consistent with standing still;
                                         at TRK_STILL_LOOKS it goes back to held. A
                                         tentative track whose echoes are a
                                         scatterer's (TRK_SCATTERER_ECHO_LLR):
                                         consecutive looks it moved with its test
                                         confirming; it is confirmed at the
                                         TRK_STILL_LOOKS-th */
    int64_t time_us;                  /**< time of x and P */
    trk_real x[TRK_CV2_NX];           /**< [x, vx, y, vy] */
    trk_real p[TRK_CV2_NX * TRK_CV2_NX];  /**< covariance of x (4 x 4, row-major; TRK_CV2_P) */
    uint32_t n_scans;                 /**< scans this track has seen (incl. its first) */
    uint32_t n_hits;                  /**< scans with at least one detection in the gate */
    uint32_t n_misses_in_row;         /**< consecutive scans without */
    uint16_t n_gated_last;            /**< detections in the gate at the last scan */
    uint16_t n_unseen_in_row;         /**< consecutive scans out of the sensor's sight */
    trk_real beta0_last;              /**< P(no detection is the target's), last scan */
    trk_real existence0;              /**< existence at initiation (trk_init_params) */
    struct trk_visibility vis;        /**< existence (IPDA) vis.pv and its smoothed
                                         confidence vis.pcv, when track_visibility:
                                         the track's quality (trk_init_params) */
    trk_real confirm_stat;            /**< current statistic of the confirmation test:
                                         M/N count, SPRT log-LR, clutter-test p-value */
    trk_real term_stat;               /**< current statistic of the termination test:
                                         K/N count, Page c_t, Shiryaev log-odds g_t */
    union {                           /**< a track needs one test at a time: */
        union trk_confirm_state confirm; /**< while tentative (params.confirm.method) */
        union trk_term_state term;       /**< once confirmed (params.term.method) */
    } test;  /**< the confirmation or termination test's state */
#if TRK_WITH_IMM
    trk_real maneuver_d2;             /**< the survey's manoeuvre statistic (eqs 3.11-3.13):
                                         d2 = nu' S^-1 nu of the last scan's innovation
                                         given a detection, nu = sum_i beta_i nu_i /
                                         sum_i beta_i, S that of the prediction with the
                                         sensor's R; chi-square with 2 degrees of freedom
                                         while the model fits (e.g. > 9.21: 1 %); 0 when
                                         nothing was gated or every weight is 0 */
    struct trk_imm_state imm;         /**< an IMM track (params.imm.n_models >= 1): its
                                         models' estimates and mode probabilities imm.mu;
                                         x and P above are their combination */
#endif
};

/* ---------------------------------------------------------------- report */

/** What one scan did (trk_tracker_process_scan): the detections' fate and the tracks' changes. n_detections = n_kept + n_thinned + the rejected (n_rejected_*) and below-threshold counts. */
struct trk_scan_report {
    uint32_t n_detections;          /**< in the scan */
    uint32_t n_rejected_nonfinite;  /**< NaN/inf position or covariance (polar: range or bearing) */
    uint32_t n_rejected_cov;        /**< own covariance not SPD */
    uint32_t n_rejected_amplitude;  /**< amplitude NaN, infinite or negative, or one whose
                                       ln l^a overflows the real type */
    uint32_t n_rejected_region;     /**< finite position outside the surveillance bound
                                       (|x_m| or |y_m| > params.max_coord_m), or a polar
                                       detection of range <= 0 */
    uint32_t n_below_threshold;     /**< amplitude below the sensor's detection threshold */
    uint32_t n_rejected_density;    /**< the caller's clutter density (trk_scan
                                       clutter_density_per_m2) NaN, infinite or not > 0 */
    uint32_t n_kept;                /**< valid detections processed (at most TRK_MAX_DETECTIONS);
                                       n_detections = n_kept + n_thinned + n_rejected_nonfinite
                                       + n_rejected_cov + n_rejected_amplitude + n_rejected_region
                                       + n_below_threshold + n_rejected_density */
    uint32_t n_thinned;             /**< valid detections left out: the scan held more than
                                       TRK_MAX_DETECTIONS ("Scans beyond capacity") */
    uint32_t n_tracks_updated;      /**< live tracks predicted and updated */
    uint32_t n_tracks_hit;          /**< ... with at least one detection gated */
    uint32_t n_started;             /**< new tentative tracks */
    uint32_t n_confirmed;           /**< tentative -> confirmed */
    uint32_t n_stationary;          /**< tentative tracks held (struct trk_track
                                       stationary; trk_tracker_params.stationary_d2) */
    uint32_t n_terminated;          /**< tracks ended this scan (any reason) */
    uint32_t n_init_refused_full;   /**< initiations refused: table full (single point: each
                                       detection that could not start; two points: each pair
                                       without a slot, or, while every slot holds a confirmed
                                       track, each unexplained detection: no pairing runs) */
    uint32_t n_init_deferred;       /**< pairs below init.min_existence: their second
                                       point waits as a candidate for a third */
    uint32_t n_numerical;           /**< tracks ended for a numerical failure */
    uint32_t n_merged;              /**< tracks ended as duplicates of another */
    uint32_t n_replaced;            /**< tentative tracks whose slot a new track took */
    uint32_t n_covariance;          /**< tracks ended by the covariance bound */
    uint32_t n_candidates;          /**< initiation candidates held after the scan */
    uint32_t n_candidates_dropped;  /**< unexplained detections the store could not hold */
    /* joint association (TRK_ASSOC_JOINT) */
    uint32_t n_clusters;            /**< clusters of the joint problem (a track alone, with or
                                       without gated detections, is a cluster of one) */
    uint32_t n_clusters_approx;     /**< ... solved approximately: by loopy belief propagation, or
                                       with floored weights where every joint event underflowed
                                       (jpda.h, trk_jpda_report n_approx, of them n_floored) */
    uint32_t largest_cluster;       /**< tracks in the largest cluster */
    uint32_t n_assoc_overflow;      /**< tracks left out of the joint problem and updated by their
                                       own PDA after the joint tracks: the scan's gated pairs
                                       exceeded TRK_MAX_GATED_PAIRS, or (cannot happen) the
                                       solver refused; also a track whose prediction failed
                                       (it then ends as numerical) */
    /* a thinned scan (n_thinned > 0; all 0 otherwise): the model of what it kept */
    uint32_t thin_in_gates;         /**< 1: the cut fell inside the gate boxes (more gated
                                       detections than TRK_MAX_DETECTIONS): the updates used
                                       thin_pd and thin_clutter_density */
    trk_real thin_threshold;        /**< the raised threshold: the amplitude of the last kept
                                       detection (0: thinned without amplitudes) */
    trk_real thin_pd;               /**< P_D and clutter density (per m^2) of the kept part */
    trk_real thin_clutter_density;  /**< of the class the cut fell in */
    /* persistent returns in the amplitudes (struct trk_sensor_params persistent_share) */
    trk_real persistent_share;      /**< the share the scan's amplitude mixture took: the
                                       sensor's, less the returns its held tracks explain
                                       (joint association; docs/tracker.md "Amplitudes on a
                                       sonar"); 0 without persistent returns */
};

/* ---------------------------------------------------------------- tracker */

/** An unexplained detection kept for two-point initiation (its scan's
 * time, count and sensor are its run's, struct trk_i_cand_run). */
struct trk_candidate {
    /** @{ position (m) */
    trk_real x_m, y_m;
    /** @} */
    trk_real cov_m2[3];      /**< its covariance [xx, xy, yy] (own or the sensor's) */
    trk_real log_lr;         /**< ln l^a (0 without amplitude) */
    uint8_t used;            /**< it started a track: it pairs no more */
    uint8_t prev_age;        /**< 0, or it ended a pair refused for want of a slot: the
                                  pair's first point is in the run prev_age scans older, */
    uint16_t prev_off;       /**< at this offset in it (the three-point existence) */
};

/** The pair store: every track's gated pairs with joint association, else
 * one track's gated set. */
#if TRK_WITH_JOINT
#define TRK_I_PAIRS TRK_MAX_GATED_PAIRS
#else
#define TRK_I_PAIRS TRK_MAX_DETECTIONS
#endif

/** The 2-D index of a set of points (the scan's detections, or one scan's
 * initiation candidates): cells of a regular grid, column by column, about
 * one point per cell (src/grid_impl.h); the cells' ends are kept beside it. */
struct trk_i_grid {
    /** @{ */
    trk_real x0_m, y0_m;               /**< the cell of (x, y): column floor((x - x0) inv_w), */
    /** @} */
    /** @{ */
    trk_real inv_w_per_m, inv_h_per_m; /**< row floor((y - y0) inv_h), both clamped */
    /** @} */
    /** @{ */
    uint16_t n_col, n_row;             /**< n_col n_row <= max(1, points) */
    /** @} */
};

/** A sensor as one scan sees it: its pose (the scan's or the sensor's own)
 * with the heading's sine and cosine and the coverage's limits worked out
 * once (src/sensor_view.h). */
struct trk_i_view {
    const struct trk_sensor_params *sp;  /**< the scan's sensor */
    struct trk_pose pose;                /**< the scan's pose */
    /** @{ */
    trk_real sin_h, cos_h;               /**< the heading's sine and cosine */
    /** @} */
    trk_real cos_half;                   /**< the coverage sector's half width's cosine */
    /** @{ */
    trk_real min_r2, max_r2;             /**< the coverage's ranges squared (max 0: none) */
    /** @} */
    uint8_t sector;                      /**< 1: the coverage is a sector */
    uint8_t limited;                     /**< 1: P_D depends on the position */
    uint8_t clutter_varies;              /**< 1: lambda depends on the position */
    trk_real polar_k;                    /**< a polar sensor's conversion scale (1, or the
                                            unbiased conversion's e^(sb^2 / 2)) */
    uint8_t map;                         /**< 1: the sensor's clutter map scales lambda: */
    const struct trk_clutter_map_params *map_params;  /**< its cells and estimator, */
    const trk_real *map_count;           /**< its cells' N_c, */
    trk_real map_scans;                  /**< its W, */
    trk_real map_half_b;                 /**< and its bearings' half span (rad) */
};

/** One scan's initiation candidates: cand[start, start + n) in the run's
 * 2-D index, its cells' ends at cand_cell_end[start ..]. */
struct trk_i_cand_run {
    int64_t time_us;  /**< the scan's time */
    uint32_t scan_no;    /**< the tracker's scan count when it was seen */
    /** @{ cand[start, start + n): its candidates */
    uint16_t start, n;
    /** @} */
    uint16_t n_unused;   /**< of them not used */
    uint8_t sensor_id;  /**< the scan's sensor */
    trk_real var_max_m2; /**< the largest tr R_c of its candidates (the pairing's reach) */
    struct trk_i_grid grid;  /**< the 2-D index of its candidates */
};

/** The track table: caller-owned (large: usually static; trk_tracker_sizeof), set up by trk_tracker_init, changed only by the tracker's functions. Read tracks through trk_tracker_track; the other members are private. */
struct trk_tracker {
    struct trk_tracker_params params;  /**< as given to trk_tracker_init */
    struct trk_pda pda[TRK_MAX_SENSORS];        /**< per sensor: pd, gate, clutter */
    struct trk_pda pda_saved;                   /**< a thinned scan's sensor constants while
                                                   pda[] holds its model (no caller use) */
    trk_real r[TRK_MAX_SENSORS][TRK_CV2_NZ * TRK_CV2_NZ];  /**< per sensor: the default measurement covariance R (2 x 2) */
    int64_t last_time_us;  /**< time of the last scan processed */
    int64_t max_dt_us;  /**< max_dt_s in microseconds */
    int has_time;                               /**< a scan has been processed */
    uint32_t next_id;  /**< id of the next new track */
    uint32_t n_live;                            /**< tentative + confirmed + terminated */
    struct trk_visibility_model vis_model;  /**< the visibility test's model */
    union trk_confirm_model confirm_model;      /**< the tests' validated parameters and */
    union trk_term_model term_model;            /**< derived constants, shared by all tracks */
    struct trk_track track[TRK_MAX_TRACKS];  /**< the track slots */
    struct {                                    /**< initial existence terms per sensor
                                                   (trk_init_params; +inf when lambda = 0): */
        trk_real first;                         /**< ln(beta / lambda), a track's first point */
        trk_real second;                        /**< ln(P_D / lambda), its second point */
    } init_log_odds[TRK_MAX_SENSORS];  /**< per sensor */
#if TRK_WITH_JOINT
    trk_real log_clutter_density[TRK_MAX_SENSORS]; /**< ln lambda of the joint weights (lambda > 0) */
#endif
#if TRK_CLUTTER_MAP_CELLS > 0
    trk_real clutter_map[TRK_MAX_SENSORS][TRK_CLUTTER_MAP_CELLS]; /**< per sensor and cell:
                                                   N_c, the weighted count of detections no
                                                   confirmed track gated (trk_clutter_map_params) */
    trk_real clutter_map_scans[TRK_MAX_SENSORS];  /**< per sensor: W, the scans' weighted sum */
#endif
    uint32_t scan_no;                           /**< scans processed (initiation ages) */
    size_t n_cand;                              /**< initiation candidates not used */
    /** @{ */
    uint16_t run_first, n_runs;                 /**< their runs, one per scan, oldest first:
                                                   run[(run_first + k) % TRK_MAX_CANDIDATE_SCANS],
                                                   each contiguous in cand[], without overlap */
    /** @} */
    struct trk_i_cand_run run[TRK_MAX_CANDIDATE_SCANS];  /**< the candidates' runs (a ring) */
    struct trk_candidate cand[TRK_MAX_CANDIDATES];  /**< initiation candidates, run after run */
    uint16_t cand_cell_end[TRK_MAX_CANDIDATES];  /**< per candidate: the end of its cell in its run's index */
    /** per-scan workspace (contents meaningless between calls, but for the
     * alpha-beta filter's steady-state cache ab_steady, which its key
     * ab_dt_us, ab_sensor keeps valid) */
    struct {
        size_t n_valid;                                        /**< valid detections, */
        size_t n_shared;                                       /**< [0, n_shared) with the sensor's
                                                                  covariance, then own ones */
        struct trk_i_view view;                                /**< the scan's sensor and pose */
        trk_real pd_scale;                                     /**< a thinned scan's P_D over the
                                                                  sensor's (its profile's factor) */
        trk_real lambda_scale;                                 /**< the same for lambda */
        trk_real persistent_share;                             /**< the sensor's eta less the returns
                                                                  its held tracks explain (this
                                                                  scan's amplitude mixture) */
        trk_real pd_power;                                     /**< with amplitudes and a P_D
                                                                  profile: P_D' = P_D^pd_power
                                                                  (Rayleigh; 1 unthinned) */
        struct trk_pda track_pda;                              /**< the track being updated: the
                                                                  PDA's constants with its P_D
                                                                  and lambda (profiles), */
        trk_real track_r[TRK_CV2_NZ * TRK_CV2_NZ];             /**< and its R (polar) */
        struct trk_i_grid grid;                                /**< gating's index of [0, n_shared), */
        uint16_t cell_end[TRK_MAX_DETECTIONS];                 /**< its cells' ends (after the
                                                                  updates: the merge's index) */
        struct trk_i_grid grid_own;                            /**< gating's index of the own-
                                                                  covariance group [n_shared,
                                                                  n_valid), positions from 0, */
        uint16_t cell_end_own[TRK_MAX_DETECTIONS];             /**< its cells' ends, */
        trk_real own_var_max_m2[2];                            /**< and the group's largest
                                                                  R_xx, R_yy (its boxes' bound) */
        /** @{ */
        trk_real x[TRK_MAX_DETECTIONS], y[TRK_MAX_DETECTIONS]; /**< their positions */
        /** @} */
        trk_real log_lr[TRK_MAX_DETECTIONS];                   /**< amplitude ln l^a */
        uint16_t src[TRK_MAX_DETECTIONS];                      /**< index in the scan */
        uint8_t used[TRK_MAX_DETECTIONS];                      /**< gated by some track */
        uint16_t cand[TRK_I_PAIRS];                            /**< gated pairs: one track's set
                                                                  (per-track PDA), or every
                                                                  track's (joint); before and
                                                                  after the updates the 2-D
                                                                  indices' index arrays */
        trk_real w[TRK_I_PAIRS];                               /**< their weights; after the
                                                                  updates the merge's track
                                                                  positions */
#if TRK_WITH_JOINT
        uint16_t joint_slot[TRK_MAX_TRACKS];                   /**< joint: the slot of joint track k, */
        uint16_t pair_first[TRK_MAX_TRACKS + 1];               /**< its pairs [pair_first[k],
                                                                  pair_first[k + 1]) */
        trk_real miss[TRK_MAX_TRACKS];                         /**< ln w_k0, then P(k <- none) */
        size_t n_joint;
#endif
        uint8_t done[TRK_MAX_TRACKS];                          /**< per slot: updated in this
                                                                  scan, or (joint association)
                                                                  a joint track, from its
                                                                  gating on */
        trk_real amp_db[2 * TRK_MAX_DETECTIONS];               /**< amplitudes (dB) of the
                                                                  detections that have one,
                                                                  twice over: the others of
                                                                  entry k are k+1 .. k+n-1 */
        int16_t amp_pos[TRK_MAX_DETECTIONS];                   /**< index in amp_db, -1 none */
        size_t n_amp;
        struct trk_cv_steady ab_steady[2];                     /**< the alpha-beta filter's steady
                                                                  state per axis for gap ab_dt_us
                                                                  at sensor ab_sensor: a cache,
                                                                  since a scan's tracks share
                                                                  one gap (TRK_WITH_ALPHA_BETA) */
        uint32_t ab_grown_h[2];                                /**< per axis the points from which
                                                                  a track takes the steady state
                                                                  (its start-up gain is no larger) */
        int64_t ab_dt_us;                                      /**< its gap, 0: nothing cached */
        unsigned ab_sensor;                                    /**< its sensor */
#if TRK_WITH_IMM
        struct {                                               /**< one IMM track's update: */
            struct trk_imm_state s;                            /**< mixed, predicted, posterior */
            trk_real c[TRK_MAX_MODELS];                        /**< predicted mode probabilities */
            trk_real log_c[TRK_MAX_MODELS];                    /**< ... their logarithms (-inf: 0) */
            trk_real pht[TRK_MAX_MODELS][TRK_CV2_NX * TRK_CV2_NZ];
            struct trk_innovation inn[TRK_MAX_MODELS];         /**< per model, with its R: */
            trk_real r[TRK_MAX_MODELS][TRK_CV2_NZ * TRK_CV2_NZ]; /**< the sensor's R at the
                                                                  model's prediction (polar) */
            trk_real rho[TRK_MAX_MODELS][TRK_MAX_DETECTIONS];  /**< rho_mi = P(model m |
                                                                  detection i), then beta_i
                                                                  rho_mi, then beta_mi */
        } imm;
#endif
        union {                                                /**< used one at a time: */
            struct {                                           /**< one track's update: */
                trk_real z[TRK_CV2_NZ * TRK_MAX_DETECTIONS];   /**< its gated detections */
                trk_real r_own[TRK_CV2_NZ * TRK_CV2_NZ * TRK_MAX_DETECTIONS]; /**< their own R_j */
            } set;
#if TRK_WITH_JOINT
            struct {                                           /**< the joint marginals: */
                struct trk_jpda_solver solver;
                trk_real p_pair[TRK_MAX_GATED_PAIRS];
                trk_real p_miss[TRK_MAX_TRACKS];
            } joint;
#endif
            struct {                                           /**< the 2-D indices' scratch
                                                                  (grid_order: the scan's at
                                                                  load, the merge's tracks, a
                                                                  run of candidates; and the
                                                                  single-point scan order) */
                uint16_t tmp[TRK_MAX_DETECTIONS];
                uint16_t count[TRK_MAX_DETECTIONS + 1];
            } sort;
            struct {                                           /**< the merge's candidate pairs */
                uint16_t pair[2 * TRK_MAX_TRACKS];
            } merge;
        } u;
        trk_real persistent_inv_u;                             /**< the scan's scatterers' 1/u_s =
                                                                  ln persistent_pd / ln pfa (0: no
                                                                  persistent returns) */
    } ws;
};

/** Check params as trk_tracker_init does, without a tracker. On a refusal
 * *field (field may be NULL) names the refused member of struct
 * trk_tracker_params, a constant string:
 *   "n_sensors", "clutter", "process_noise_q", "gate_prob",
 *   "init_speed_sigma_mps", "max_dt_s", "merge_gate_d2", "init_exclusion_d2",
 *   "track_visibility", "visibility" (its model refused the parameters),
 *   "init.method", "init.max_speed_mps", "init.max_gap_scans",
 *   "init.birth_density_per_m2", "max_pos_sigma_ratio", "max_coord_m", "association"
 *   (unknown, or joint without parametric clutter of density > 0), "imm"
 *   (TRK_WITH_IMM: n_models not 0 and trk_imm_check_params refused it),
 *   "sensor[i].pd", "sensor[i].meas_cov_m2", "sensor[i].clutter_density_per_m2",
 *   "sensor[i].use_amplitude", "sensor[i].amplitude" (no usable model, or its
 *   P_D), "sensor[i].kind", "sensor[i].sigma_range_m", "sensor[i].sigma_bearing_rad",
 *   "sensor[i].conversion", "sensor[i].pose", "sensor[i].pd_profile" (also
 *   TRK_E_UNSUPPORTED with use_amplitude), "sensor[i].coverage",
 *   "sensor[i].clutter_profile" (also TRK_E_UNSUPPORTED with nonparametric
 *   clutter), i the sensor
 *   index; "filter" (also TRK_E_UNSUPPORTED: alpha-beta with a polar sensor);
 *   "confirm.method" (unknown, not built in, or a visibility method without
 *   track_visibility), "confirm.u.mn", "confirm.u.sprt", "confirm.u.chi2",
 *   "confirm.u.amp", "confirm.u.existence" (the method's parameters), "confirm.u.sprt.hmm" (fewer
 *   sensors than the tracker); the same for "term.method", "term.u.kn",
 *   "term.u.page", "term.u.shiryaev", "term.u.existence", "term.u.page.hmm", "term.u.shiryaev.hmm";
 *   "params" for a NULL p.
 * *field is NULL on success. Statuses as trk_tracker_init. */
TRK_NODISCARD trk_status trk_tracker_check_params(const struct trk_tracker_params *p, const char **field);

/** Validate params (trk_tracker_check_params), build the confirmation and
 * termination models once (the clutter-density threshold table, HMMs, ...)
 * and initialise an empty table.
 * TRK_E_ARG NULL/enum, TRK_E_NAN non-finite, TRK_E_RANGE out of range,
 * TRK_E_NOT_SPD a sensor covariance, TRK_E_SENSOR an HMM test with fewer
 * sensors than the tracker, TRK_E_UNSUPPORTED a clutter confirmation test in
 * a build with TRK_WITH_CLUTTER_TESTS = 0; *t untouched on error. */
TRK_NODISCARD trk_status trk_tracker_init(struct trk_tracker *t, const struct trk_tracker_params *p);

/** Process one scan (see the top of this file). report may be NULL.
 * Whole-scan refusals (table untouched, report zeroed):
 * TRK_E_ARG NULL pointers, detections and polar both or neither given (with
 * n_detections > 0), polar for a Cartesian sensor, has_pose not 0 or 1;
 * TRK_E_CAPACITY more than TRK_MAX_SCAN_DETECTIONS
 * (65535) detections (a scan of TRK_MAX_DETECTIONS + 1 .. 65535 is
 * thinned, never refused), TRK_E_TIME time before the previous scan, TRK_E_RANGE gap
 * longer than max_dt_s or |time_us| > 2^62, or a pose outside the surveillance
 * bound (or |heading| > 1e6 rad), TRK_E_NAN a non-finite pose, TRK_E_SENSOR
 * unknown sensor, TRK_E_UNSUPPORTED the caller's clutter densities with
 * nonparametric clutter or a sensor density of 0.
 * Per-detection and per-track problems are counted in the report; the call
 * then still returns TRK_OK. */
TRK_NODISCARD trk_status trk_tracker_process_scan(struct trk_tracker *t, const struct trk_scan *scan,
                                                  struct trk_scan_report *report);

/** Track in slot i (0 .. TRK_MAX_TRACKS-1), or NULL when the slot is free.
 * Iterate over all slots to list tracks (order = slot, not id). */
const struct trk_track *trk_tracker_track(const struct trk_tracker *t, size_t slot);

/** Number of slots in use (tentative, confirmed or terminated-this-scan). */
size_t trk_tracker_live_count(const struct trk_tracker *t);

/** sizeof(struct trk_tracker) as the library was built. */
size_t trk_tracker_sizeof(void);

/** TRK_OK when the library was built with the capacities, real type and
 * options (TRK_WITH_CLUTTER_TESTS, TRK_CLUTTER_KMAX, ...) that this
 * translation unit sees: call it once at start-up. */
#define trk_tracker_abi_check()                                                        \
    ((trk_config_check() == TRK_OK && trk_tracker_sizeof() == sizeof(struct trk_tracker)) \
         ? TRK_OK                                                                      \
         : TRK_E_ABI)

/* ---------------------------------------------------------------- helpers */

/** Polar detection pd of sensor sp (kind TRK_SENSOR_POLAR) at pose as the
 * Cartesian detection the tracker uses (has_cov 1; its amplitude copied):
 * absolute bearing b = heading + bearing, position pose + k r (sin b, cos b)
 * with k = 1 (TRK_POLAR_FIRST_ORDER) or e^(sb^2 / 2) (TRK_POLAR_UNBIASED),
 * and the covariance of the conversion (trk_polar_cov of the stored
 * position's offset from the pose). The tracker converts
 * a polar scan with this function. TRK_E_ARG NULL or not a polar sensor,
 * TRK_E_NAN non-finite input, TRK_E_RANGE range <= 0 or sigma out of range
 * (*d untouched on error). */
TRK_NODISCARD trk_status trk_polar_to_cartesian(const struct trk_sensor_params *sp, const struct trk_pose *pose,
                                                const struct trk_polar_detection *pd, struct trk_detection *d);

/** The covariance [xx, xy, yy] of a converted polar detection of sensor sp
 * (kind polar) whose position is (dx_m, dy_m) from the pose: it depends on
 * the range and bearing only through that offset, so that the tracker
 * derives it again from the converted position (and a track's R from its
 * predicted position) with no trigonometric function.
 *   first order:  C = J diag(sr^2, sb^2) J' (J the Jacobian of
 *                 (r sin b, r cos b) at the measured r, b)
 *   unbiased:     Mo et al. (1998) eq 7 at the measured r, b (see
 *                 docs/conventions.md "Polar detections")
 * At the pose, or so near it that the cross-range variance sb^2 (dx^2 +
 * dy^2) is below TRK_COV2_MIN_REL_DET sr^2 (lost to rounding against the
 * range's), the bearing is lost: the covariance is sr^2 I, the range's
 * variance in every direction. */
void trk_polar_cov(const struct trk_sensor_params *sp, trk_real dx_m, trk_real dy_m, trk_real cov_m2[3]);

/** The clutter density of sensor sp at (x_m, y_m) with the sensor at pose:
 * its clutter profile at the range (linear, flat beyond the ends), else its
 * clutter_density_per_m2. The tracker takes each track's lambda from this
 * function at its predicted position and each new track's at its
 * detections. NaN for NULL pointers. */
trk_real trk_sensor_clutter_at(const struct trk_sensor_params *sp, const struct trk_pose *pose, trk_real x_m,
                               trk_real y_m);

/** The clutter density tracker t uses at (x_m, y_m) in a scan of sensor
 * sensor_id from pose (NULL: the sensor's own pose): the configured one
 * (trk_sensor_clutter_at) times its clutter map's ratio there, pooled over
 * the window of cells about it (trk_clutter_map_params; outside the map,
 * or without one, 1), into
 * *lambda_per_m2. TRK_E_ARG for NULL t or lambda_per_m2, TRK_E_SENSOR for
 * an unknown sensor, TRK_E_NAN for a non-finite position or pose. */
trk_status trk_tracker_clutter_at(const struct trk_tracker *t, unsigned sensor_id, const struct trk_pose *pose,
                                  trk_real x_m, trk_real y_m, trk_real *lambda_per_m2);

/** The detection probability of sensor sp at (x_m, y_m) with the sensor at
 * pose: 0 outside its coverage, else its P_D profile at the range (linear,
 * flat beyond the ends), else its pd (the amplitude model's P_D with
 * use_amplitude). The tracker takes each track's P_D from this function at
 * its predicted position and each new track's at its detection. */
trk_real trk_sensor_pd_at(const struct trk_sensor_params *sp, const struct trk_pose *pose, trk_real x_m,
                          trk_real y_m);

/** Range/bearing of a sensor at (sensor_x_m, sensor_y_m) to a Cartesian
 * detection. Bearing is clockwise from +y (north), x east:
 *   x = xs + r sin(b), y = ys + r cos(b).
 * The covariance is the first-order (Jacobian) transform of
 * diag(sigma_range^2, sigma_bearing^2); it is accurate while
 * r sigma_bearing^2 is small against sigma_range (a few degrees at most).
 * TRK_E_NAN non-finite input, TRK_E_RANGE range < 0 or sigma <= 0. */
TRK_NODISCARD trk_status trk_detection_from_polar(trk_real range_m, trk_real bearing_rad,
                                                  trk_real sigma_range_m, trk_real sigma_bearing_rad,
                                                  trk_real sensor_x_m, trk_real sensor_y_m,
                                                  struct trk_detection *d);

#endif
