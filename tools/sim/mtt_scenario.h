/* mtt_scenario.h - the multi-target scenario families of `trk-sim mtt`
 *: targets in a square region, at most eight at a time,
 * seeded, deterministic. Two families (mtt_scen_params.family, `trk-sim mtt
 * --family transit|fixed`):
 *   transit  (MTT_FAMILY_TRANSIT, the default) targets enter and leave the
 *            region at their own speeds (5-15 m/s, kept); a slot whose target
 *            has gone takes a new one: ~25 targets in a run of 200 scans,
 *            6-8 present
 *   fixed    (MTT_FAMILY_FIXED) the eight structure targets alone, alive the
 *            whole run but the birth (present from its birth on) and the
 *            death (gone from its death on); speeds drawn in 5-15 m/s and
 *            reduced until each path stays inside. The first 8-target
 *            scenario, against which the peer (Stone Soup JPDA) was
 *            measured: the same parameters and seed give the same
 *            scenario as its first implementation did, bit for bit
 *            (targets, truth and every scan's detections).
 * What the families share is one code path: the region, the slots and
 * roles, the structure's random draws and its geometry (the X, the pair's
 * side-by-side placement, the straight targets, the turn), the motion, the
 * detections, the clutter, the amplitudes, the random streams. They differ
 * in the targets' lives, where the pair, BIRTH and DEATH are anchored, the
 * turn's pull-in, the speeds (kept or fitted) and the transit targets.
 *
 * ---- Both families
 *
 * Region [0, S]^2 (S = region_m, 3 km), a scan every T s (4 s), scans
 * 0 .. n_scans-1 at t_k = k T. "Inside" is the region less margin_m (50 m):
 * [m, S - m]^2. Speeds are drawn uniformly in [speed_min_mps,
 * speed_max_mps] (5-15 m/s), one per structure target (the pair one for
 * both).
 *
 * Slots. The scenario has MTT_N_SLOTS (8) slots; a slot holds one target at
 * a time, so that at most eight are present. Each slot has one designated
 * target, its structure role (enum mtt_role, = the slot index and the
 * target's index in tg[]). The structure, drawn alike by both families (a
 * seed gives both the same crossing, headings, offsets, designated birth and
 * death scans, turn and speed draws):
 *   CROSS_A, CROSS_B  an X: both pass the crossing point (the centre + up to
 *                     +-150 m per axis) at the same time, scan n/2 +- 5 %;
 *                     A heads 45 deg +- 10 deg (or the opposite way), B A's
 *                     heading + 90 deg +- 20 deg (crossing angle 70-110 deg)
 *   PAR_A, PAR_B      a pair moving together, parallel_sep_m (60 m) apart
 *                     side by side (same velocity at every time): heading
 *                     along CROSS_A's line +- 5 deg (either way), the pair's
 *                     centre line 300-500 m from the centre (either side),
 *                     +- 150 m along the line at mid-run (from what: below)
 *   BIRTH             designated birth at scan round(0.2 n) + j (j up to
 *                     +-1.5 % of n); straight, through a point 300-700 m from
 *                     the centre, heading tangential +- 30 deg (either way)
 *   DEATH             designated death at scan round(0.7 n) + j (gone from
 *                     it on); straight like BIRTH
 *   TURN              a coordinated turn of turn_deg (90 deg, left or right)
 *                     at turn_rate_dps (3 deg/s) x [0.8, 1.2], centred on
 *                     mid-run +- 5 %; the turn starts 500-700 m from the
 *                     centre, the legs before and after point 45 deg off the
 *                     direction to the centre (+- 10 deg)
 *   STRAIGHT          straight, through a point 300-700 m from the centre at
 *                     mid-run, heading tangential +- 30 deg (either way);
 *                     with accel_mps2 > 0 ("a target that
 *                     accelerates") it speeds up along its line at
 *                     accel_mps2 from its mid-life for accel_s seconds
 *                     (0.1 m/s^2 for 60 s: +6 m/s) and keeps the new speed;
 *                     truth exact (position quadratic in t over the
 *                     acceleration). Its mid-life is that of the path
 *                     without the acceleration (scan (birth + death - 1) / 2,
 *                     as a time), its life then cut where the faster path
 *                     leaves the inside (no earlier than the acceleration's
 *                     start: the path before it is unchanged). The fixed
 *                     family fits STRAIGHT's speed on the path without the
 *                     acceleration, so the accelerating target may leave
 *                     before the run's end (its death_scan is then the first
 *                     scan outside). accel_mps2 = 0 (the default) draws and
 *                     computes nothing more: the scenario of every seed bit
 *                     for bit as without the option. The draws are the same
 *                     either way; only STRAIGHT's slot's later transit
 *                     targets (placed after its death) may differ.
 * Motion is deterministic (no process noise): straight legs and the turn's
 * arc (radius v / omega; 0.52 m/s^2 at 10 m/s and 3 deg/s).
 *
 * ---- The transit family (MTT_FAMILY_TRANSIT)
 *
 * Every target keeps its drawn speed (one exception: the pair, below), so a
 * target crosses the region in 200-600 s at the default speeds: targets
 * enter and leave during a run. The structure's anchors:
 *   CROSS_A, CROSS_B  both inside for >= ~1400 m of path either side of the
 *                     crossing (>= 22 scans at 15 m/s, 16 at 20 m/s)
 *   PAR_A, PAR_B      at mid-run the pair is at the middle of the part of its
 *                     lines inside the region +- 150 m along them. Both are
 *                     present together for at least min(40, n) scans: where
 *                     the draw does not give that, the jitter along the line
 *                     goes, then the line comes nearer the centre (down to
 *                     150 m) and then turns towards the nearest diagonal;
 *                     only beyond that (a pair speed above ~22 m/s at 4 s
 *                     scans) is the pair's speed reduced to what the
 *                     longest chord allows (speed_mps < speed_drawn_mps)
 *   BIRTH             born inside at its designated scan, there at its
 *                     300-700 m point
 *   DEATH             dies inside at its designated scan, at its 300-700 m
 *                     point at its last scan
 *   TURN              the turn's start pulled nearer the centre where its arc
 *                     would leave the region; present for the whole turn and
 *                     before and after it
 *
 * Life. A target's life is the part of its path inside: the longest run of
 * consecutive scans around its anchor scan (the crossing, mid-run, the
 * designated birth or death, the turn's start, the entry or exit below) in
 * which it is inside, cut at its designated birth or death scan and at the
 * run's ends. It is present for birth_scan <= k < death_scan.
 *
 * Re-use of a slot (transit targets, role MTT_TRANSIT, each a new target
 * with a new index = id). After a slot's target is gone (death_scan d, by
 * leaving or by dying), the next one enters at scan d + g, g uniform in
 * {1 .. gap_max_scans} (10), provided min_life_scans (25) scans of the run
 * remain (d + g + min_life_scans <= n): at a point of the boundary of the
 * inside square (uniform along its perimeter), heading into the region at up
 * to 60 deg off the inward normal, straight at a speed of its own, present
 * until it leaves. Its position and heading are redrawn (up to 64 times)
 * until it is present for at least min_life_scans scans (no target is there
 * too briefly to be tracked) and leaves room for the slot's next target
 * (min_life_scans after the next gap) or stays to the run's end; failing
 * that, the draw present min_life_scans scans with room, else the one
 * present min_life_scans, else the longest. The same backwards in time
 * before the slot's designated target (born at b): the previous one leaves
 * through the boundary at scan b - g (its death_scan; heading out at up to
 * 60 deg off the outward normal) and is present back to where it entered
 * or to scan 0, provided b - g >= min_life_scans; and so on back to the
 * run's start. So every slot, BIRTH's before its birth and DEATH's after its
 * death included, is occupied but for gaps of 1-10 scans between its
 * targets and fewer than min_life_scans + gap_max_scans scans at either end
 * of the run. At the defaults (200 seeds): about 25 targets in a run of 200
 * scans (17-29), 7.4 present per scan on average, 6-8 in 96 % of the scans
 * (fewer near the run's ends and where several slots change at once).
 *
 * ---- The fixed family (MTT_FAMILY_FIXED; the first 8-target scenario)
 *
 * The eight structure targets and no others (n_targets = 8, slot j holds
 * target j alone; min_life_scans and gap_max_scans unused).
 *   Lives        fixed, not from the path: every target present from scan 0
 *                to the run's end, but BIRTH from its designated birth scan
 *                on and DEATH up to its designated death scan: 7 present
 *                before the birth, 8 from it to the death, 7 after
 *   Anchors      the mid-life points: the X at the crossing; the pair at
 *                mid-run at its centre line's point nearest the region's
 *                centre + the drawn 150 m along it; BIRTH, DEATH and
 *                STRAIGHT through their 300-700 m point at mid-life (scan
 *                (birth_scan + death_scan - 1) / 2); the turn's start where
 *                drawn (not pulled in)
 *   Speeds       the draw, then, where the target's path over its life would
 *                leave the inside, reduced (bisection) to the largest speed
 *                that keeps it in: the path is anchored at its mid-life
 *                point, so a lower speed shrinks it towards that point
 *                (speed_drawn_mps keeps the draw; the pair one speed for
 *                both). A straight target crosses 3 km at 15 m/s in 200 s:
 *                runs of up to ~40 scans of 4 s keep the draws, runs of more
 *                than ~70 bring every target down to what its chord allows
 *                (at the default 200 scans, 796 s: 2.7-6.3 m/s, median
 *                4.2, over 40 seeds; below the draw's 5 m/s floor)
 *   par_scans    = n (the pair present together the whole run)
 *
 * ---- Detections, random numbers (both families)
 *
 * Detections of scan k: per slot, its target present at k with probability
 * pd, at its position + N(0, sigma^2 I); with amplitudes (amplitude = 1) a
 * Swerling I target of snr_db in thresholded Rayleigh clutter
 * (amp_sample.h), the threshold's P_FA chosen so that P_D = S1(t) = pd:
 * pfa = pd^(1 + SNR). Clutter: exactly clutter_count detections uniform over
 * the region (Rayleigh amplitudes above the threshold), capped so that the
 * scan never holds more than max_det (<= TRK_MAX_SCAN_DETECTIONS; the
 * tracker thins a scan beyond TRK_MAX_DETECTIONS) nor the caller's max:
 * targets' first, then at most max_det - n_target clutter ones
 * (n_clutter_capped counts the clutter left out). The scan is shuffled.
 *
 * Random numbers (rng.h, philox, keyed by seed): stream 0 draws the
 * geometry (the structure and the speeds, in that order in both families;
 * then, transit only, slot by slot the transit targets, earlier ones then
 * later ones); scan k uses stream 4k+1 for the targets' detections (four
 * draws per slot whether a target is present or detected or not), 4k+2 for
 * the clutter (the same draws per point, so the first N points are the same
 * at every clutter count: scans at 50 clutter hold the first 50 points of
 * the scan at 100, and the targets' detections are the same at every level;
 * with or without amplitudes the positions are the same), 4k+3 for the
 * shuffle. So the two families of one seed have the same clutter, the same
 * shuffle draws and the same detection draws per slot. A scan depends only
 * on (family, seed, k, clutter_count, amplitude) and the geometry
 * parameters: same seed, same scenario bit for bit, in any scan order and
 * from any thread (the scenario is read-only after mtt_scen_init).
 *
 * ---- The sonar family (MTT_FAMILY_SONAR; mtt_scen_sonar_defaults)
 *
 * What an active sonar on a moving platform produces: polar detections
 * (range, bearing) from a pose that moves, a P_D that falls with range,
 * clutter denser near the sonar and in reverberation patches, and
 * stationary scatterers that return on most pings.
 *   Platform   from (0, 0) due north (heading 0, clockwise from +y; x east)
 *              at platform_speed_mps (3 m/s): pose at scan k (0, v k T),
 *              heading 0 (mtt_scen_pose). A scan every T = 8 s (one ping),
 *              150 scans (1200 s, 3.6 km of platform track).
 *   Sector     ranges [range_min_m, range_max_m] (0.5-8 km) within
 *              +-half_width_deg (60 deg) of the heading: 66.8 km^2. A
 *              target is present while inside the sector less margin_m
 *              (50 m) in range and 1 deg in bearing.
 *   Sensor     s->sonar (struct trk_sensor_params, kind TRK_SENSOR_POLAR):
 *              sigma_range_m 7.5 m, sigma_bearing 1.5 deg, first-order
 *              conversion, coverage = the sector, pd_profile = 16 points
 *              log-spaced over the sector's ranges of
 *                P_D(r) = pfa^(1 / (1 + SRR(r))),   pfa = 0.01,
 *                SRR(r) = 18 dB - 10 log10(r / 500 m)
 *              (a Swerling I target at a fixed threshold, its echo-to-
 *              reverberation ratio falling as 10 log10 r: boundary-
 *              reverberation-limited, Urick, Principles of Underwater
 *              Sound, 3rd ed., ch. 9): 0.93 at 0.5 km, 0.76 at 2 km, 0.53
 *              at 5 km, 0.39 at 8 km. A target's detection probability at
 *              a scan is trk_sensor_pd_at(s->sonar, pose, x, y) at its
 *              true position: the library's formula. sonar_pd_mean: P_D
 *              averaged over the sector's area (0.53; the `cart`
 *              configuration's single P_D).
 *   Amplitudes (amplitude = 1, the default) the same law's: Rayleigh
 *              (Swerling I) in Rayleigh reverberation of power 1 above the
 *              threshold t^2 = -ln 0.01; a target's SNR the one whose P_D
 *              at that threshold is the profile's at its true position
 *              (1 + SNR = ln pfa / ln P_D), a persistent scatterer's the
 *              one of its 0.85, every clutter point's the clutter law
 *              (the patches and the near field too: a CFAR-normalised
 *              detector). Drawn by inverse CDF (trk_amplitude_inv_sf) from
 *              a stream of their own, so that the positions are the same
 *              with amplitudes or without.
 *   Targets    the eight slots, one target each, straight but the turn,
 *              speeds uniform in [speed_min_mps, speed_max_mps] (3-10 m/s),
 *              headings compass (clockwise from north). Positions are
 *              drawn as (range, bearing) from the platform at an anchor
 *              time; a target's life is the run of scans around its
 *              anchor inside the sector (cut at BIRTH's birth and DEATH's
 *              death); a draw whose life is too short is drawn again (up
 *              to 64 times, the longest kept):
 *     CROSS_A, CROSS_B  a shallow crossing: both at the crossing point
 *                       (range 2.5-4.5 km, bearing +-30 deg) at mid-run
 *                       +-5 %, A's heading -60..60 deg, B's A's +-(20..35)
 *                       deg; both present 10 scans either side of it
 *     PAR_A, PAR_B      one close pair along the bearing: at mid-run on one
 *                       bearing (+-40 deg), A at range 2-4.5 km, B
 *                       parallel_sep_m (100 m) farther out, one velocity
 *                       (heading -60..60 deg); both present >= min(40, n/2)
 *                       scans
 *     BIRTH             born at scan 0.2 n +- 1.5 % n at range 1.5-5 km,
 *                       bearing +-45 deg, any heading; present >= 25 scans
 *     DEATH             dies at scan 0.7 n +- 1.5 % n, its last position
 *                       drawn like BIRTH's; present >= 25 scans
 *     TURN              a coordinated turn of turn_deg (90) at
 *                       turn_rate_dps (3 deg/s) x [0.8, 1.2] starting at
 *                       mid-run - half the turn +- 5 %, at range 2-4 km,
 *                       bearing +-40 deg, heading before it -60..60 deg;
 *                       present 5 scans before to 10 after the turn
 *     STRAIGHT          the far target: at mid-run at range 6.5-7.5 km,
 *                       bearing +-25 deg, moving across the line of sight
 *                       with the platform's range rate (so its range stays
 *                       near 7 km), speed in the lower half of the range
 *                       (3-6.5 m/s); present >= 40 scans
 *   Patches    four reverberation discs fixed on the ground, 3 % of the
 *              sector's area together (radius 399 m each at the defaults),
 *              centred at mid-run at 1.5-6 km, +-45 deg (the first on the
 *              crossing point +-200 m, the second on the turn's start
 *              +-200 m); each is drawn again (up to 64 times) until clear of
 *              those before it. mtt_scen_in_patch.
 *   Clutter    exactly clutter_count points per scan: each is a patch
 *              point with probability 0.30 (uniform in a patch drawn
 *              uniformly: 10 x the sector's average density), a near-field
 *              point with 0.15 (range 500 m + Exp(400 m), bearing uniform),
 *              else uniform in range x bearing over the sector (so denser
 *              near the sonar per m^2); a patch or near-field point outside
 *              the sector is replaced by a uniform one.
 *   Persistent with persistent = 1 (the default), twelve fixed scatterers
 *              (mtt_scen_persist) return on 85 % of the pings that cover
 *              them, with the sensor's noise: one in each patch, four 250-550
 *              m to the side of a target's path (CROSS_A, PAR_A, TURN,
 *              BIRTH, at a scan of its life), four at 7-7.8 km, +-50 deg, at
 *              a quarter of the run. Their detections' origin is -2.
 *   Detections The targets' (P_D as above), the persistent returns', the
 *              clutter's: range r + N(0, sigma_r^2), bearing + N(0, sigma_b^2)
 *              relative to the heading; det[] holds their positions and
 *              covariances by trk_polar_to_cartesian (the library's
 *              conversion), polar[] (mtt_scen_scan_polar) the range and
 *              bearing. Capacity: targets first, then the persistent
 *              returns, then the clutter.
 *   Random numbers  stream 0 the geometry (the targets slot by slot, then
 *              the patches, then the scatterers); scan k: 4k+1 the targets'
 *              detections (four draws per slot, as the other families), 4k+2
 *              the clutter (six draws per point, whatever its kind: the first
 *              N points of a scan the same at every clutter count), 4k+3 the
 *              shuffle, 4k+4 the persistent returns (three draws per
 *              scatterer, whether on or not: with persistent = 0 the targets'
 *              detections and the clutter are the same). */
#ifndef TRK_SIM_MTT_SCENARIO_H
#define TRK_SIM_MTT_SCENARIO_H

#include <stddef.h>
#include <stdint.h>

#include "amp_sample.h"
#include "trk/tracker.h"

enum mtt_family {
    MTT_FAMILY_TRANSIT = 0,     /* targets enter and leave, slots re-used (the default) */
    MTT_FAMILY_FIXED,           /* the eight structure targets alone */
    MTT_FAMILY_SONAR,           /* a polar sensor on a moving platform (below) */
    MTT_N_FAMILIES
};

enum mtt_role {
    MTT_CROSS_A = 0,
    MTT_CROSS_B,
    MTT_PAR_A,
    MTT_PAR_B,
    MTT_BIRTH,
    MTT_DEATH,
    MTT_TURN,
    MTT_STRAIGHT,
    MTT_N_SLOTS,                /* the slots: at most this many targets at a time */
    MTT_TRANSIT = MTT_N_SLOTS   /* a target re-using a slot, straight through the region */
};

struct mtt_scen_params {
    int family;                 /* enum mtt_family */
    uint64_t seed;
    long n_scans;               /* [10, 1e6] */
    double scan_period_s;       /* > 0 */
    double region_m;            /* side of the square region, >= 1000 */
    double margin_m;            /* "inside": this far in, [0, region/10] */
    double pd;                  /* detection probability, (0, 1) */
    double meas_sigma_m;        /* position noise per axis, > 0 */
    int amplitude;              /* 1: Rayleigh amplitudes (target snr_db), 0: none */
    double snr_db;              /* target SNR, [0, 40] */
    size_t max_det;             /* scan capacity, 1 .. TRK_MAX_SCAN_DETECTIONS (0: that) */
    double speed_min_mps, speed_max_mps; /* 0 < min <= max <= 1000 */
    double parallel_sep_m;      /* (0, 500) */
    double turn_deg;            /* (0, 360]: up to a full circle */
    double turn_rate_dps;       /* (0, 90] */
    long min_life_scans;        /* transit targets: present at least this long, >= 1 (transit only) */
    long gap_max_scans;         /* scans between a slot's targets: 1 .. this, >= 1 (transit only) */
    double accel_mps2;          /* STRAIGHT: along-track acceleration, [0, 10]; 0 = none (the default) */
    double accel_s;             /* ... for this long from its mid-life, (0, 1e6] (60) */
    /* the sonar family (unused by the others) */
    double platform_speed_mps;  /* [0, 20] (3) */
    double range_min_m, range_max_m; /* the sector's ranges, 0 < min < max (500, 8000) */
    double half_width_deg;      /* its half width about the heading, (0, 90] (60) */
    double sigma_range_m;       /* > 0 (7.5) */
    double sigma_bearing_deg;   /* (0, 10] (1.5) */
    int persistent;             /* 1: the persistent scatterers return (the default), 0: none */
};

/* Defaults: the transit family, seed 1, 200 scans of 4 s, 3 km region, margin 50 m, pd 0.8,
 * sigma 5 m, amplitudes at 13 dB, capacity TRK_MAX_SCAN_DETECTIONS, speeds
 * 5-15 m/s, pair 60 m apart, a 90 deg turn at 3 deg/s, transit targets
 * present >= 25 scans, gaps of 1-10 scans, no acceleration (accel_s 60). */
void mtt_scen_defaults(struct mtt_scen_params *p);
/* The sonar family's defaults: mtt_scen_defaults, then family sonar, 150
 * scans of 8 s, speeds 3-10 m/s, the pair 100 m apart, Rayleigh amplitudes
 * (the P_D law's: SNR over range), the
 * platform at 3 m/s, the sector 0.5-8 km +-60 deg, sigmas 7.5 m and 1.5 deg,
 * the persistent scatterers on. */
void mtt_scen_sonar_defaults(struct mtt_scen_params *p);

#define MTT_SONAR_PATCHES 4     /* reverberation patches */
#define MTT_SONAR_PERSIST 12    /* persistent scatterers */
#define MTT_SONAR_PERSIST_PD 0.85 /* ... each returning on this share of the pings */
#define MTT_SONAR_PD_POINTS 8   /* points of the P_D and clutter profiles (<= TRK_PD_PROFILE_MAX) */

/* A disc on the ground (a reverberation patch). */
struct mtt_disc {
    double x_m, y_m, r_m;
};

struct mtt_target {
    int role;                   /* enum mtt_role: the slot's designated role, or MTT_TRANSIT */
    int slot;                   /* 0 .. MTT_N_SLOTS-1 */
    long birth_scan;            /* present for birth_scan <= k < death_scan */
    long death_scan;
    double speed_mps, speed_drawn_mps; /* transit: equal but for the pair's fallback; fixed: the fit */
    double ax_m, ay_m, at_s;    /* anchor: position at time at_s */
    double heading_rad;         /* direction of motion (from +x, counter-clockwise);
                                   TURN: before the turn, which starts at the anchor */
    double turn_rad;            /* TURN: signed turn (+ left); 0 otherwise */
    double turn_rate_rps;       /* TURN: |omega| */
    double accel_mps2;          /* STRAIGHT with p.accel_mps2 > 0: along-track acceleration */
    double accel_t0_s, accel_dur_s; /* ... from this time for this long; 0 otherwise */
};

struct mtt_scenario {
    struct mtt_scen_params p;
    struct amp_model amp;       /* Rayleigh clutter law at the threshold (amplitude = 1) */
    struct amp_target amp_tg;   /* the targets' law */
    double pfa;                 /* threshold P_FA (pd^(1 + SNR); sonar: the P_D law's, 0.01) */
    /* the targets: tg[0 .. MTT_N_SLOTS) the designated ones (index = role =
     * slot), then the transit ones; a target's index is its id */
    struct mtt_target *tg;
    size_t n_targets;
    /* per slot its targets' indices in time order: by_slot[slot_first[j] ..
     * slot_first[j + 1]) */
    long *by_slot;
    long slot_first[MTT_N_SLOTS + 1];
    long cross_scan;            /* the scan nearest the crossing */
    double cross_x_m, cross_y_m;/* the crossing point */
    long turn_first_scan, turn_last_scan; /* scans within the turn [start, end] (first > last: none) */
    long accel_first_scan, accel_last_scan; /* STRAIGHT's acceleration, the same (none: first > last) */
    long par_scans;             /* scans with both of the pair present */
    /* the sonar family (zero for the others) */
    struct trk_sensor_params sonar; /* the sensor: kind polar, sigmas, pd_profile, coverage
                                       (pd = sonar_pd_mean; clutter density the caller's) */
    double sonar_pd_mean;       /* P_D averaged over the sector's area */
    double sonar_snr_db;        /* the SNR whose P_D at pfa is sonar_pd_mean (cart's
                                   amplitude model; with amplitudes) */
    double area_m2;             /* the region's area (the square's, or the sector's) */
    struct mtt_disc patch[MTT_SONAR_PATCHES];
    double persist_x_m[MTT_SONAR_PERSIST], persist_y_m[MTT_SONAR_PERSIST];
};

/* 0, or -1 with a message (nothing to free then). */
int mtt_scen_init(struct mtt_scenario *s, const struct mtt_scen_params *p, char *err, size_t errlen);
void mtt_scen_free(struct mtt_scenario *s);

/* Truth of target i (0 <= i < n_targets) at time t_s, whether present or
 * not: x = [x, vx, y, vy] (TRK_CV2 order). */
void mtt_scen_truth(const struct mtt_scenario *s, long i, double t_s, double x[4]);
/* 1 when target i is present at scan k. */
int mtt_scen_present(const struct mtt_scenario *s, long i, long k);
/* The target of slot j present at scan k, or -1. */
long mtt_scen_slot_target(const struct mtt_scenario *s, int j, long k);
/* Targets present at scan k (0 .. MTT_N_SLOTS). */
int mtt_scen_n_present(const struct mtt_scenario *s, long k);

struct mtt_scan_info {
    size_t n_target;            /* target detections */
    size_t n_clutter;           /* clutter detections */
    size_t n_persist;           /* sonar: persistent returns (origin -2) */
    size_t n_clutter_capped;    /* clutter left out by the capacity */
};

/* Scan k (0 <= k < n_scans) with clutter_count clutter detections (>= 0)
 * into det[0 .. max) and *scan (scan->detections = det; no polar
 * detections, no pose): at most min(max, p.max_det) detections. origin
 * (may be NULL; max entries): the target index of each detection, -1 for
 * clutter, -2 for a persistent return (sonar). *info may be NULL. */
void mtt_scen_scan(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                   size_t max, long *origin, struct trk_scan *scan, struct mtt_scan_info *info);

/* The sonar family's scan k: det[], origin[] and *scan as mtt_scen_scan
 * gives them (Cartesian, each detection with its covariance:
 * trk_polar_to_cartesian), and polar[i] the range and bearing of det[i]
 * (max entries). 0, or -1 for another family. */
int mtt_scen_scan_polar(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                        struct trk_polar_detection *polar, size_t max, long *origin, struct trk_scan *scan,
                        struct mtt_scan_info *info);

/* The sensor's pose at scan k (sonar: the platform's; the others: the
 * origin, heading 0). */
void mtt_scen_pose(const struct mtt_scenario *s, long k, struct trk_pose *pose);
/* Sonar: the clutter's true density (per m^2 per scan) at (x, y) at scan
 * k with clutter_count points per scan: the uniform share's over range x
 * bearing, the near field's and the patches' (ignoring the few patch and
 * near-field points that fall outside the sector and are drawn again as
 * uniform ones); 0 outside the sector and for the other families. */
double mtt_scen_clutter_density(const struct mtt_scenario *s, long k, long clutter_count, double x_m, double y_m);

/* Sonar: 1 when (x, y) is in a reverberation patch (0 for the others). */
int mtt_scen_in_patch(const struct mtt_scenario *s, double x_m, double y_m);
/* Sonar with persistent = 1: the distance from (x, y) to the nearest
 * persistent scatterer (INFINITY without). */
double mtt_scen_persist_dist(const struct mtt_scenario *s, double x_m, double y_m);

const char *mtt_role_name(int role);
/* "transit", "fixed", "sonar" ("?" for another value); the family of a name, or -1. */
const char *mtt_family_name(int family);
int mtt_family_parse(const char *name);

/* The tracker defaults before two-point initiation (the `old`
 * configuration of trk-sim mtt): trk_tracker_mn_kn_params (M/N 3 of 5, K/N
 * 0/5, single-point initiation, no covariance bound, Delta_bar 0.01). The
 * sensor, q and the clutter density are the caller's to set. (Replacement of
 * the weakest tentative track is part of the table and applies to it too.) */
void mtt_old_defaults(struct trk_tracker_params *p);

#endif
