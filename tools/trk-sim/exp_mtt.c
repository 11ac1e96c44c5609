/* exp_mtt.c - trk-sim mtt and mtt-compare: the multi-target evaluation
 * (GOSPA and track maintenance over clutter levels).
 *
 * mtt: a scenario family of tools/sim/mtt_scenario.h (--family): transit
 * (the default; eight slots of one target at a time: an X, a pair 60 m
 * apart, a birth, a death, a 90 deg turn, one straight, and targets crossing
 * the region in the slots freed by those that left; speeds in [--speed-min,
 * --speed-max], 5-15 m/s) or fixed (the eight structure targets
 * alone, alive the whole run but the birth and the death, speeds
 * reduced to keep each path inside; the scenario the peer was measured on);
 * 3 km x 3 km, a scan every 4 s, P_D 0.8, sigma 5 m, Rayleigh amplitudes,
 * seeds S, S+1, ..., S+seeds-1, each at every clutter count of the list
 * (exactly N uniform clutter detections per scan; --clutter-sweep: 0 to 4 x
 * TRK_MAX_DETECTIONS; every detection goes to the tracker, which thins a
 * scan beyond its capacity: kept, thinned and refused counts per level;
 * --over-capacity refuse / cap for the behaviours before) through each
 * configuration (common random
 * numbers: every configuration and clutter level sees the same targets'
 * detections, and a level's clutter is the first N points of the largest's):
 *   new  trk_tracker_default_params() with the scenario's sensor
 *   pda  the same with association = pda
 *   old  mtt_old_defaults() (the defaults before two-point initiation) with the same
 *   imm  new with IMM tracks (a build with TRK_WITH_IMM = 1 only, `make
 *        mtt-imm`): CV at q and coordinated turns at
 *        +-omega (--imm-rate, --imm-stay, --imm-turn-q; MTT_IMM_* below)
 *   oracle  no tracker: per target a CV Kalman filter fed with that
 *        target's own detections (known association, tools/sim/mtt_oracle.h)
 *        with new's sensor R and q (after --set), started at its second
 *        detection, reported until it leaves or dies; it sees every scan
 *        (also one --over-capacity refuse withholds from the trackers). What
 *        the sensor and the motion model allow: every table shows it. No
 *        bound where a target manoeuvres beyond q (the 3 deg/s turn at
 *        q 1e-3): the filter lags it past the cut-off and never restarts
 *   cart the sonar family only: new the old way, each polar detection
 *        converted by the caller (trk_detection_from_polar at its
 *        absolute bearing), a Cartesian sensor with one P_D (the profile
 *        averaged over the sector's area), no pose, no coverage
 *   cfar the sonar family only: new with each detection's true clutter
 *        density in the scan (trk_scan.clutter_density_per_m2,
 *        mtt_scen_clutter_density): what a CFAR that knew its background
 *        would pass
 *   known  new given only the targets' detections (the scan without its
 *        clutter and persistent returns: the association known), each
 *        still weighed against the clutter it would be among: in the
 *        sonar family with its true clutter density (as cfar) and no
 *        persistent-return description (the scans hold none); elsewhere
 *        the configured density. Between the oracle and new: what trk's
 *        own start, confirmation and filter allow with the association
 *        solved, so that new's gap to the oracle splits into the price of
 *        the association (new against known) and that of trk's evidence
 *        rule (known against the oracle, which reports every target from
 *        its second detection and weighs no clutter at all). Its clutter
 *        and persistent returns per scan are the scenario's (what it was
 *        spared); --over-capacity refuse never refuses its small scans
 * (sensor: pd, R = sigma^2 I, clutter density N / area, the Rayleigh model
 * of the scenario with use_amplitude, q = 1e-3; then every --set).
 *
 * The sonar family (--family sonar, mtt_scenario.h): a polar sensor on a
 * platform moving north at 3 m/s, its sector 0.5-8 km +-60 deg, a ping
 * every 8 s, 150 scans, P_D over range, clutter in patches and the near
 * field, persistent scatterers (--no-persistent), Rayleigh amplitudes of the P_D
 * law's SNR over range (--no-amplitude: none); GOSPA c
 * 200 m. The trackers (new, pda, old) get each scan as a user of a polar
 * sensor gives it: scan.polar, has_pose, pose (detections NULL), the
 * sensor of kind TRK_SENSOR_POLAR with its sigmas, P_D profile and
 * coverage (the scenario's s->sonar), clutter density N / the sector's
 * area; the oracle the detections the scenario converted
 * (trk_polar_to_cartesian, each with its covariance). Its own measures (columns of sonar rows only):
 * coverage in the patches and beyond SONAR_FAR_M, the P_D seen, the
 * persistent returns per scan, and the false confirmed tracks split by
 * where they were (mostly in a patch or not; mostly within c of a
 * persistent scatterer).
 *
 * The manoeuvres: the turning target (--turn-rate,
 * --turn-deg) and, with --accel, the straight target accelerating along
 * its line from its mid-life (--accel-s); per run over the manoeuvre's
 * scans the target's coverage and its assigned track's RMSE, the coverage
 * in the MAN_AFTER scans after, and whether its track at the first scan is
 * still its track MAN_LOST scans after the last (turn_*, accel_*; the
 * table "-- manoeuvres", PREFIX_manoeuvre.png).
 * Per scan the CONFIRMED tracks are scored against the targets present
 * (tools/sim/mtt_eval.h: GOSPA p = 2, alpha = 2, cut-off c, and the
 * track-maintenance statistics); per (configuration, clutter) the mean over
 * seeds and its 95 % Student t interval of every metric. The CPU time is the
 * thread's (CLOCK_THREAD_CPUTIME_ID) around trk_tracker_process_scan only:
 * the process clock would add the other OpenMP threads' time.
 *
 * The CSV's rows are keyed by (capacity, config, clutter, family).
 *
 * mtt-compare: the CSV files of several builds (TRK_MAX_TRACKS differs)
 * merged into one table and one set of plots, and per metric the ratio of
 * the smallest capacity's mean to the largest's and whether it is within
 * the largest's interval; rows of different families are kept apart (a
 * ratio pairs rows of one family; a file without the family column, from
 * before --family, has family "unknown"). */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "errmsg.h"
#include "kvfile.h"
#include "mc_stats.h"
#include "mtt_eval.h"
#include "mtt_oracle.h"
#include "mtt_params.h"
#include "mtt_scenario.h"
#include "sim.h"
#include "tracker_config.h"
#include "trk/amplitude.h"
#include "trk/tracker.h"

#define MAX_LEVELS 64
#define MAX_FILES 16
#define MAX_ROWS 4096
#define CROSS_WINDOW 5 /* scans either side of the crossing */
#define CROSS_AFTER 20 /* the crossing's duplicates and coalescence: to 20 scans after it */
#define MAN_AFTER 20   /* a manoeuvre's after-coverage: the 20 scans after its last scan */
#define MAN_LOST 10    /* a manoeuvre's track loss: its track at the first scan against this many
                          scans after its last */

/* The imm configuration (TRK_WITH_IMM): CV (q = --q,
 * 1e-3) and coordinated turns at +-MTT_IMM_RATE_DPS (q = MTT_IMM_TURN_Q),
 * keeping the model with MTT_IMM_STAY per scan. Chosen by measurement
 * (transit family, 200 scans, turns of 30 scans at 1, 2 and 3 deg/s, each
 * seed's rate x [0.8, 1.2], clutter 0-256 per scan; the coverage of the
 * turning target over its turn, ranges over the clutter levels):
 *   omega 2 deg/s (the first guess): 1.000 at 1 and 2 deg/s but 0.64-0.82
 *     at 3 deg/s (10 seeds, any turn q of 1e-3, 3e-3, 1e-2 and p_stay 0.9
 *     or 0.95), the track lost in 70-100 % of the runs
 *   omega 2.5 deg/s: 0.88-0.94 at 3 deg/s (20 seeds)
 *   omega 3 deg/s: 0.991-1.000 at every rate and level (20 seeds), no
 *     track lost, false tracks as CV-only (0-0.2 per 1000 scans): with a
 *     turn model at the fastest rate expected the slower turns lie between
 *     it and CV, which the mixed estimate follows
 *   turn q 1e-2 against 3e-3 and 1e-3 (omega 3): the same coverage and
 *     GOSPA (within 0.1 m), the turn's RMSE lower at 3 deg/s (20 seeds: 6.5
 *     against 7.2 m with 3e-3; 10 seeds: 6.0, 6.4, 6.9 m) and at 2 deg/s
 *     (20 seeds: 8.5-9.1 against 8.8-9.4 m), equal at 1 deg/s: 1e-2
 *   p_stay 0.95 against 0.9 (omega 3, 10 seeds): the same coverage; 0.9 cuts
 *     the turn's RMSE at 1 deg/s by 0.6 m but raises GOSPA by ~0.9 m at
 *     every level (the straight targets' estimates wander between the
 *     models): 0.95 (a mean sojourn of 20 scans)
 * The brief's first omega of 2 deg/s: --imm-rate 2. */
#define MTT_IMM_RATE_DPS 3.0
#define MTT_IMM_STAY 0.95
#define MTT_IMM_TURN_Q 1e-2
#define MTT_STR_(x) #x
#define MTT_STR(x) MTT_STR_(x) /* a constant as an option's default */

/* ---------------------------------------------------------------- metrics */

/* Every counter of struct trk_scan_report (summed over a run's scans). */
#define MTT_REPORT_COUNTERS(X)                                                                             \
    X(n_detections) X(n_rejected_nonfinite) X(n_rejected_cov) X(n_rejected_amplitude) X(n_rejected_region) \
    X(n_below_threshold) X(n_rejected_density) \
    X(n_kept) X(n_thinned) X(n_tracks_updated) X(n_tracks_hit) X(n_started) X(n_confirmed) X(n_stationary) X(n_terminated) X(n_init_refused_full) X(n_init_deferred) \
    X(n_numerical) X(n_merged) X(n_replaced) X(n_covariance) X(n_candidates) X(n_candidates_dropped)       \
    X(n_clusters) X(n_clusters_approx) X(largest_cluster) X(n_assoc_overflow)

enum {
    M_GOSPA, M_LOC, M_MISSED, M_FALSE, M_STC, M_NEVER, M_COV, M_TURN, M_TURN_RMSE, M_TURN_AFTER, M_TURN_LOST,
    M_ACC, M_ACC_RMSE, M_ACC_AFTER, M_ACC_LOST, M_PAR, M_CROSS,
    M_CROSS_IDSW, M_CROSS_DUP, M_CROSS_COAL, M_PAR_IDSW, M_PAR_DUP, M_PAR_COAL, M_FALSE_TRK,
    M_FALSE_TS, M_DUP_TS, M_FRAG, M_IDSW, M_RMSE, M_CPU, M_CONF, M_LIVE, M_FULL, M_CLUTTER, M_CAPPED,
    M_TARGETS, M_PRESENT, M_KEPT, M_THINNED, M_THIN_SCANS, M_THIN_GATES, M_REFUSED,
    M_STC_CROSS, M_STC_PAIR, M_STC_TURN, M_STC_STRAIGHT, M_STC_BIRTH, M_STC_DEATH,
#define X(f) M_REP_##f,
    MTT_REPORT_COUNTERS(X)
#undef X
    /* the sonar family's (columns of its rows only) */
    M_COV_PATCH, M_COV_FAR, M_FAR_BEFORE, M_TGT_PD, M_PERSIST, M_FALSE_PATCH, M_FALSE_OUT, M_FALSE_PERSIST,
    M_N
};
#define M_REP_FIRST M_REP_n_detections
#define M_SONAR_FIRST M_COV_PATCH
#define N_REP (M_SONAR_FIRST - M_REP_FIRST)
#define SONAR_FAR_M 5000 /* "far": the coverage beyond this range from the sonar */

static const char *const metric_name[M_N] = {
    "gospa_m", "gospa_loc_m2", "gospa_missed_m2", "gospa_false_m2", "scans_to_confirm", "never_confirmed",
    "coverage", "turn_coverage", "turn_rmse_m", "turn_after_coverage", "turn_lost", "accel_coverage",
    "accel_rmse_m", "accel_after_coverage", "accel_lost", "parallel_both", "cross_both", "cross_id_switches", "cross_duplicate_per_100",
    "cross_coalesced_per_100", "parallel_id_switches", "parallel_duplicate_per_100", "parallel_coalesced_per_100",
    "false_tracks_per_1000_scans",
    "false_track_scans_per_100", "duplicate_track_scans_per_100", "fragmentations", "id_switches", "rmse_m",
    "cpu_us_per_scan", "confirmed_per_scan", "live_per_scan", "table_full_frac", "clutter_per_scan",
    "clutter_capped_scans",
    "targets_per_run", "targets_present_per_scan", "kept_per_scan", "thinned_per_scan", "thinned_scans",
    "thinned_in_gates_scans", "refused_scans",
    "to_confirm_cross", "to_confirm_pair", "to_confirm_turn", "to_confirm_straight", "to_confirm_birth",
    "to_confirm_death",
#define X(f) "rep_" #f,
    MTT_REPORT_COUNTERS(X)
#undef X
    "patch_coverage", "far_coverage", "far_missed_before_first", "target_pd", "persistent_per_scan", "false_tracks_patch_per_1000_scans",
    "false_tracks_outside_per_1000_scans", "false_tracks_persistent_per_1000_scans",
};

static int metric_index(const char *name)
{
    for (int m = 0; m < M_N; m++)
        if (strcmp(name, metric_name[m]) == 0) return m;
    return -1;
}

/* One run: (seed, clutter level, configuration). */
struct run_result {
    double v[M_N];
};

/* One (capacity, configuration, clutter, family) cell: mean and interval
 * over seeds. */
struct mtt_row {
    long capacity;
    char config[16];
    double clutter;
    char family[16];            /* mtt_family_name(), "unknown" in an older CSV */
    long seeds, scans;
    int amplitude;
    double mean[M_N], lo[M_N], hi[M_N];
};

/* ---------------------------------------------------------------- configurations */

/* ---------------------------------------------------------------- one run */

/* What a scan beyond TRK_MAX_DETECTIONS becomes (--over-capacity): the
 * tracker thins it (the library's behaviour), or, for comparison, the
 * behaviours before: the library refused it (TRK_E_CAPACITY: the tracker
 * does not see the scan), or the tool cut its clutter to fit. */
enum { OVER_THIN, OVER_REFUSE, OVER_CAP };
static const int over_values[] = {OVER_THIN, OVER_REFUSE, OVER_CAP};

/* One thread's buffers: a scan of up to TRK_MAX_SCAN_DETECTIONS (the
 * library's bound; 4 MB in double, allocated once per thread). */
struct run_ws {
    struct trk_tracker *tk;
    struct trk_detection det[TRK_MAX_SCAN_DETECTIONS];
    struct trk_polar_detection polar[TRK_MAX_SCAN_DETECTIONS]; /* the sonar family's */
    trk_real lambda[TRK_MAX_SCAN_DETECTIONS];                  /* ... their clutter densities (cfar) */
    long origin[TRK_MAX_SCAN_DETECTIONS];
    struct mtt_obj est[TRK_MAX_TRACKS];
};

/* The sonar family's false tracks by where they were: per track id its
 * scored scans, and of them the false ones (farther than c from every
 * target), in a patch, within c of a persistent scatterer. A false track
 * (every scored scan false, as mtt_eval counts it) is a patch track when
 * most of its scans were in a patch, a persistent one when most were near
 * a scatterer. */
struct sonar_track {
    long id, scans, false_scans, patch, persist;
};
struct sonar_false {
    struct sonar_track *v;
    size_t n, cap;
};

static struct sonar_track *sonar_track_of(struct sonar_false *f, long id)
{
    for (size_t i = f->n; i-- > 0;) /* recent ids are at the end */
        if (f->v[i].id == id) return &f->v[i];
    if (f->n == f->cap) {
        const size_t cap = f->cap ? 2 * f->cap : 64;
        struct sonar_track *v = realloc(f->v, cap * sizeof *v);
        if (!v) return NULL;
        f->v = v;
        f->cap = cap;
    }
    struct sonar_track *t = &f->v[f->n++];
    memset(t, 0, sizeof *t);
    t->id = id;
    return t;
}

static double thread_cpu_s(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) return NAN;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One pair of targets (the X, the parallel pair) while both are present:
 * identity switches of either target's assigned track (all such scans),
 * and, over the scans counted (the X: its window), target-scans with two or
 * more confirmed tracks within c nearest it (duplicates) and scans where one
 * target has two or more and the other none (coalesced: the other's track
 * went over to it). */
struct pair_stats {
    long last_id[2];
    long idsw, dup, coal, n;
};

static void pair_scan(struct pair_stats *ps, const struct mtt_obj *truth, int ia, int ib, const struct mtt_obj *est,
                      size_t ne, const long *assign, double c_m, int counted)
{
    const struct mtt_obj *a = &truth[ia], *b = &truth[ib];
    const int idx[2] = {ia, ib};
    for (int w = 0; w < 2; w++) {
        const long as = assign[idx[w]];
        if (as < 0) continue;
        if (ps->last_id[w] >= 0 && ps->last_id[w] != est[as].id) ps->idsw++;
        ps->last_id[w] = est[as].id;
    }
    if (!counted) return;
    long near[2] = {0, 0};
    for (size_t i = 0; i < ne; i++) {
        const double da = hypot(est[i].x_m - a->x_m, est[i].y_m - a->y_m);
        const double db = hypot(est[i].x_m - b->x_m, est[i].y_m - b->y_m);
        if (fmin(da, db) <= c_m) near[db < da]++;
    }
    ps->n++;
    ps->dup += (near[0] >= 2) + (near[1] >= 2);
    ps->coal += (near[0] >= 2 && near[1] == 0) || (near[1] >= 2 && near[0] == 0);
}

/* One manoeuvring target (the turn, the acceleration) over its manoeuvre's
 * scans [first, last]: coverage and the squared error of its assigned track
 * (scans where it is present), coverage over the MAN_AFTER scans after
 * last, and whether the track it had at first is the one it has MAN_LOST
 * scans after last (lost = 1 also when it has none then; NaN when it had
 * none at first, nothing to lose, or is not present at either scan). */
struct man_stats {
    long first, last;
    long n, hit, after_n, after_hit;
    double sq;
    long id0;                   /* its track at first; -1 none, -2 not present there */
    double lost;
};

static void man_init(struct man_stats *ms, long first, long last)
{
    memset(ms, 0, sizeof *ms);
    ms->first = first;
    ms->last = last;
    ms->id0 = -2;
    ms->lost = NAN;
}

/* Scan k: tr the target's truth (NULL: not present), e its assigned track
 * (NULL: none). */
static void man_scan(struct man_stats *ms, long k, const struct mtt_obj *tr, const struct mtt_obj *e)
{
    if (ms->first > ms->last || !tr) return;
    if (k >= ms->first && k <= ms->last) {
        ms->n++;
        if (e) {
            ms->hit++;
            ms->sq += (e->x_m - tr->x_m) * (e->x_m - tr->x_m) + (e->y_m - tr->y_m) * (e->y_m - tr->y_m);
        }
    }
    if (k > ms->last && k <= ms->last + MAN_AFTER) {
        ms->after_n++;
        ms->after_hit += e != NULL;
    }
    if (k == ms->first) ms->id0 = e ? e->id : -1;
    if (k == ms->last + MAN_LOST && ms->id0 >= 0) ms->lost = !e || e->id != ms->id0;
}

/* Its metrics into v[m0 .. m0 + 3] (coverage, RMSE, after-coverage, lost:
 * the order of M_TURN .. M_TURN_LOST and M_ACC .. M_ACC_LOST). */
static void man_result(const struct man_stats *ms, double *v, int m0)
{
    v[m0] = ms->n ? (double)ms->hit / (double)ms->n : NAN;
    v[m0 + 1] = ms->hit ? sqrt(ms->sq / (double)ms->hit) : NAN;
    v[m0 + 2] = ms->after_n ? (double)ms->after_hit / (double)ms->after_n : NAN;
    v[m0 + 3] = ms->lost;
}

/* The oracle's scan k (mtt_oracle.h): targets gone ended, the scan given
 * with its detections' origins, the report's counters of what it did (it
 * sees and keeps every detection). 0, or -1. */
static int oracle_scan(struct mtt_oracle *orc, const struct mtt_scenario *sc, long k, const struct trk_scan *scan,
                       const long *origin, struct trk_scan_report *rep)
{
    uint32_t ended = 0;
    for (size_t i = 0; i < sc->n_targets; i++)
        if (k >= sc->tg[i].death_scan) ended += (uint32_t)mtt_oracle_end(orc, i);
    struct mtt_oracle_report orep;
    if (mtt_oracle_scan(orc, scan, origin, &orep) != 0) return -1;
    rep->n_detections = rep->n_kept = (uint32_t)scan->n_detections;
    rep->n_tracks_updated = (uint32_t)orep.n_updated;
    rep->n_started = rep->n_confirmed = (uint32_t)orep.n_started;
    rep->n_terminated = ended;
    return 0;
}

/* known's scan: *scan reduced to the targets' detections (origin >= 0), in
 * their order, with their positions (ws->det, and ws->polar for a polar
 * scan), before any clutter density is given to them. */
static void keep_targets(struct run_ws *ws, struct trk_scan *scan)
{
    size_t m = 0;
    for (size_t i = 0; i < scan->n_detections; i++) {
        if (ws->origin[i] < 0) continue;
        ws->det[m] = ws->det[i];
        if (scan->polar) ws->polar[m] = ws->polar[i];
        ws->origin[m] = ws->origin[i];
        m++;
    }
    scan->n_detections = m;
}

/* The sonar family's scan k for configuration kind (CFG_*) into *scan
 * (mtt_scenario.h): the oracle gets the detections converted by the
 * scenario (trk_polar_to_cartesian, each with its covariance); cart the
 * old way, each converted by the caller with trk_detection_from_polar at
 * its absolute bearing, no pose; the others the polar scan as a user
 * gives it: scan.polar, has_pose, pose, detections NULL; cfar with each
 * detection's true clutter density (mtt_scen_clutter_density: what a
 * CFAR that knew its background would pass; where the truth has none, a
 * return beyond the clutter's sector, the density of tp's sensor there;
 * none at clutter 0); known the same for the targets' detections alone
 * (keep_targets). 0, or -1. */
static int sonar_scan_for(const struct mtt_scenario *sc, long k, long clutter, size_t max, int kind,
                          const struct trk_tracker_params *tp, struct run_ws *ws, struct trk_scan *scan,
                          struct mtt_scan_info *info)
{
    if (mtt_scen_scan_polar(sc, k, clutter, ws->det, ws->polar, max, ws->origin, scan, info) != 0) return -1;
    if (kind == CFG_ORACLE) return 0;
    struct trk_pose pose;
    mtt_scen_pose(sc, k, &pose);
    if (kind == CFG_CART) {
        const struct trk_sensor_params *sp = &sc->sonar;
        for (size_t i = 0; i < scan->n_detections; i++)
            if (trk_detection_from_polar(ws->polar[i].range_m, pose.heading_rad + ws->polar[i].bearing_rad,
                                         sp->sigma_range_m, sp->sigma_bearing_rad, pose.x_m, pose.y_m,
                                         &ws->det[i]) != TRK_OK)
                return -1;
        return 0;
    }
    scan->polar = ws->polar;
    scan->detections = NULL;
    scan->has_pose = 1;
    scan->pose = pose;
    if (kind == CFG_KNOWN) keep_targets(ws, scan); /* its densities for the detections it keeps */
    if ((kind == CFG_CFAR || kind == CFG_KNOWN) && clutter > 0) {
        for (size_t i = 0; i < scan->n_detections; i++) { /* at det[i], polar[i] converted by the library */
            const trk_real x = ws->det[i].x_m, y = ws->det[i].y_m;
            const double truth = mtt_scen_clutter_density(sc, k, clutter, (double)x, (double)y);
            /* outside the clutter's region (a return beyond the sector) the sensor's description */
            ws->lambda[i] = truth > 0 ? (trk_real)truth : trk_sensor_clutter_at(&tp->sensor[0], &pose, x, y);
        }
        scan->clutter_density_per_m2 = ws->lambda;
    }
    return 0;
}

/* Scans to confirm per designated role (the scenario's tg[r] has role r;
 * the pairs' two averaged): a run's mean over its targets of that role
 * that were ever confirmed, NAN when none was: which situations the
 * overall figure comes from (on the sonar, the far target's). */
static void role_to_confirm(const struct mtt_eval *ev, const struct mtt_scenario *sc, double *v)
{
    static const struct {
        int metric, first, last; /* roles first .. last */
    } group[] = {
        {M_STC_CROSS, MTT_CROSS_A, MTT_CROSS_B}, {M_STC_PAIR, MTT_PAR_A, MTT_PAR_B},
        {M_STC_TURN, MTT_TURN, MTT_TURN},        {M_STC_STRAIGHT, MTT_STRAIGHT, MTT_STRAIGHT},
        {M_STC_BIRTH, MTT_BIRTH, MTT_BIRTH},     {M_STC_DEATH, MTT_DEATH, MTT_DEATH},
    };
    for (size_t g = 0; g < sizeof group / sizeof group[0]; g++) {
        double sum = 0;
        int n = 0;
        for (int r = group[g].first; r <= group[g].last && (size_t)r < sc->n_targets; r++) {
            const double x = mtt_eval_target_to_confirm(ev, r);
            if (isnan(x)) continue;
            sum += x;
            n++;
        }
        v[group[g].metric] = n ? sum / n : NAN;
    }
}

/* One run of the trackers' configuration tp, or of the oracle (tp gives
 * its sensor R and q). cart: the sonar family's (sonar_scan_for). */
static int run_one(const struct mtt_scenario *sc, long clutter, int over, int kind,
                   const struct trk_tracker_params *tp, double c_m, struct run_ws *ws, struct run_result *res)
{
    const int oracle = kind == CFG_ORACLE;
    const int sonar = sc->p.family == MTT_FAMILY_SONAR;
    struct sonar_false sf = {NULL, 0, 0};
    long patch_n = 0, patch_hit = 0, far_n = 0, far_hit = 0, far_before = 0, tgt_det = 0, persist_sum = 0;
    struct pair_stats cross = {{-1, -1}, 0, 0, 0, 0}, par = {{-1, -1}, 0, 0, 0, 0};
    struct mtt_eval ev;
    struct man_stats turn, acc;
    man_init(&turn, sc->turn_first_scan, sc->turn_last_scan);
    man_init(&acc, sc->accel_first_scan, sc->accel_last_scan);
    struct mtt_oracle orc;
    if (oracle ? mtt_oracle_init(&orc, sc->n_targets, tp->sensor[0].meas_cov_m2, tp->process_noise_q) != 0
               : trk_tracker_init(ws->tk, tp) != TRK_OK)
        return -1;
    /* sonar: per target, whether it has had a confirmed track yet */
    unsigned char *held_once = sonar ? calloc(sc->n_targets ? sc->n_targets : 1, 1) : NULL;
    if (sonar && !held_once) {
        if (oracle) mtt_oracle_free(&orc);
        return -1;
    }
    mtt_eval_init(&ev, c_m);
    const long ns = sc->p.n_scans;
    double cpu = 0, rep_sum[N_REP] = {0};
    long conf_sum = 0, live_sum = 0, full = 0, clutter_sum = 0, capped = 0, thin_scans = 0, thin_gates = 0;
    long refused = 0;
    long par_n = 0, par_hit = 0, cross_n = 0, cross_hit = 0, present_sum = 0;
    int rc = 0;
    for (long k = 0; k < ns && rc == 0; k++) {
        struct trk_scan scan;
        struct mtt_scan_info info;
        const size_t max = over == OVER_CAP ? TRK_MAX_DETECTIONS : TRK_MAX_SCAN_DETECTIONS;
        if (!sonar) {
            mtt_scen_scan(sc, k, clutter, ws->det, max, ws->origin, &scan, &info);
            if (kind == CFG_KNOWN) keep_targets(ws, &scan);
        } else if (sonar_scan_for(sc, k, clutter, max, kind, tp, ws, &scan, &info) != 0) {
            rc = -1;
            break;
        }
        clutter_sum += (long)info.n_clutter;
        capped += info.n_clutter_capped > 0;
        struct trk_scan_report rep = {0};
        trk_status st = TRK_E_CAPACITY;
        if (oracle) {
            const double t0 = thread_cpu_s();
            st = oracle_scan(&orc, sc, k, &scan, ws->origin, &rep) == 0 ? TRK_OK : TRK_E_ARG;
            cpu += thread_cpu_s() - t0;
        } else if (over != OVER_REFUSE || scan.n_detections <= TRK_MAX_DETECTIONS) {
            const double t0 = thread_cpu_s();
            st = trk_tracker_process_scan(ws->tk, &scan, &rep);
            cpu += thread_cpu_s() - t0;
        }
        if (st == TRK_E_CAPACITY) { /* refused: the table as before the scan */
            refused++;
        } else if (st != TRK_OK) {
            rc = -1;
            break;
        }
        thin_scans += rep.n_thinned > 0;
        thin_gates += rep.thin_in_gates;
        {
            int j = 0;
#define X(f) rep_sum[j++] += (double)rep.f;
            MTT_REPORT_COUNTERS(X)
#undef X
            (void)j;
        }
        /* the confirmed tracks and the targets present */
        size_t ne = 0;
        long live = 0;
        for (size_t i = 0; oracle && i < sc->n_targets; i++) { /* the oracle's: one per target present */
            const struct mtt_oracle_track *t = mtt_oracle_track(&orc, i);
            if (!t) continue;
            live++;
            ws->est[ne++] = (struct mtt_obj){(long)i, (double)t->x[TRK_CV2_X], (double)t->x[TRK_CV2_Y]};
        }
        for (size_t s = 0; !oracle && s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *t = trk_tracker_track(ws->tk, s);
            if (!t) continue;
            live++;
            if (t->status != TRK_TRACK_CONFIRMED) continue;
            ws->est[ne++] = (struct mtt_obj){(long)t->id, (double)t->x[TRK_CV2_X], (double)t->x[TRK_CV2_Y]};
        }
        conf_sum += (long)ne;
        live_sum += live;
        full += !oracle && live >= TRK_MAX_TRACKS;
        /* the targets present, one per occupied slot; a target's id is its
         * index (a slot re-used holds a new target, with a new id) */
        struct mtt_obj truth[MTT_N_SLOTS];
        int idx[MTT_N_SLOTS]; /* per slot: its target's entry in truth, or -1 */
        size_t nt = 0;
        for (int j = 0; j < MTT_N_SLOTS; j++) {
            const long i = mtt_scen_slot_target(sc, j, k);
            idx[j] = -1;
            if (i < 0) continue;
            double x[4];
            mtt_scen_truth(sc, i, (double)k * sc->p.scan_period_s, x);
            idx[j] = (int)nt;
            truth[nt++] = (struct mtt_obj){i, x[TRK_CV2_X], x[TRK_CV2_Y]};
        }
        present_sum += (long)nt;
        long assign[MTT_N_SLOTS];
        if (mtt_eval_scan_assign(&ev, truth, nt, ws->est, ne, assign) != 0) {
            rc = -1;
            break;
        }
        if (sonar) {
            /* per situation: targets in a patch, far ones; false tracks by where */
            struct trk_pose pose;
            mtt_scen_pose(sc, k, &pose);
            persist_sum += (long)info.n_persist;
            for (size_t j = 0; j < scan.n_detections; j++) tgt_det += ws->origin[j] >= 0;
            unsigned char used[TRK_MAX_TRACKS];
            memset(used, 0, ne);
            for (size_t i = 0; i < nt; i++) {
                const int hit = assign[i] >= 0;
                if (hit) used[assign[i]] = 1;
                if (mtt_scen_in_patch(sc, truth[i].x_m, truth[i].y_m)) {
                    patch_n++;
                    patch_hit += hit;
                }
                if (hypot(truth[i].x_m - (double)pose.x_m, truth[i].y_m - (double)pose.y_m) > SONAR_FAR_M) {
                    far_n++;
                    far_hit += hit;
                    far_before += !hit && !held_once[truth[i].id];
                }
                if (hit) held_once[truth[i].id] = 1;
            }
            for (size_t j = 0; j < ne && rc == 0; j++) {
                struct sonar_track *t = sonar_track_of(&sf, ws->est[j].id);
                if (!t) {
                    rc = -1;
                    break;
                }
                t->scans++;
                if (used[j]) continue;
                int near = 0;
                for (size_t i = 0; i < nt && !near; i++)
                    near = hypot(truth[i].x_m - ws->est[j].x_m, truth[i].y_m - ws->est[j].y_m) < c_m;
                if (near) continue; /* a duplicate, not false */
                t->false_scans++;
                t->patch += mtt_scen_in_patch(sc, ws->est[j].x_m, ws->est[j].y_m);
                t->persist += mtt_scen_persist_dist(sc, ws->est[j].x_m, ws->est[j].y_m) <= c_m;
            }
            if (rc != 0) break;
        }
        for (int w = 0; w < 2; w++) { /* the manoeuvring targets: the turn, the acceleration */
            const int role = w ? MTT_STRAIGHT : MTT_TURN;
            const struct mtt_obj *tr = NULL, *e = NULL;
            if (mtt_scen_present(sc, role, k)) {
                tr = &truth[idx[role]];
                if (assign[idx[role]] >= 0) e = &ws->est[assign[idx[role]]];
            }
            man_scan(w ? &acc : &turn, k, tr, e);
        }
        if (mtt_scen_present(sc, MTT_PAR_A, k) && mtt_scen_present(sc, MTT_PAR_B, k)) {
            par_n++;
            par_hit += assign[idx[MTT_PAR_A]] >= 0 && assign[idx[MTT_PAR_B]] >= 0;
            pair_scan(&par, truth, idx[MTT_PAR_A], idx[MTT_PAR_B], ws->est, ne, assign, c_m, 1);
        }
        if (mtt_scen_present(sc, MTT_CROSS_A, k) && mtt_scen_present(sc, MTT_CROSS_B, k))
            pair_scan(&cross, truth, idx[MTT_CROSS_A], idx[MTT_CROSS_B], ws->est, ne, assign, c_m,
                      k >= sc->cross_scan - CROSS_WINDOW && k <= sc->cross_scan + CROSS_AFTER);
        if (labs(k - sc->cross_scan) <= CROSS_WINDOW && mtt_scen_present(sc, MTT_CROSS_A, k) &&
            mtt_scen_present(sc, MTT_CROSS_B, k)) {
            cross_n++;
            cross_hit += assign[idx[MTT_CROSS_A]] >= 0 && assign[idx[MTT_CROSS_B]] >= 0;
        }
    }
    if (rc == 0) {
        struct mtt_summary su;
        mtt_eval_summary(&ev, &su);
        const double dn = (double)ns;
        double *v = res->v;
        v[M_GOSPA] = su.gospa_mean_m;
        v[M_LOC] = su.loc_mean_m2;
        v[M_MISSED] = su.missed_mean_m2;
        v[M_FALSE] = su.false_mean_m2;
        v[M_STC] = su.scans_to_confirm_mean;
        role_to_confirm(&ev, sc, v);
        v[M_NEVER] = (double)su.n_never;
        v[M_COV] = su.coverage;
        man_result(&turn, v, M_TURN);
        man_result(&acc, v, M_ACC);
        v[M_PAR] = par_n ? (double)par_hit / (double)par_n : NAN;
        v[M_CROSS] = cross_n ? (double)cross_hit / (double)cross_n : NAN;
        v[M_CROSS_IDSW] = (double)cross.idsw;
        v[M_CROSS_DUP] = cross.n ? 100.0 * (double)cross.dup / (double)cross.n : NAN;
        v[M_CROSS_COAL] = cross.n ? 100.0 * (double)cross.coal / (double)cross.n : NAN;
        v[M_PAR_IDSW] = (double)par.idsw;
        v[M_PAR_DUP] = par.n ? 100.0 * (double)par.dup / (double)par.n : NAN;
        v[M_PAR_COAL] = par.n ? 100.0 * (double)par.coal / (double)par.n : NAN;
        v[M_FALSE_TRK] = 1000.0 * (double)su.n_false_tracks / dn;
        v[M_FALSE_TS] = su.false_track_scans_per_100;
        v[M_DUP_TS] = su.duplicate_track_scans_per_100;
        v[M_FRAG] = (double)su.fragmentations;
        v[M_IDSW] = (double)su.id_switches;
        v[M_RMSE] = su.rmse_m;
        v[M_CPU] = 1e6 * cpu / dn;
        v[M_CONF] = (double)conf_sum / dn;
        v[M_LIVE] = (double)live_sum / dn;
        v[M_FULL] = (double)full / dn;
        v[M_CLUTTER] = (double)clutter_sum / dn;
        v[M_CAPPED] = (double)capped;
        v[M_TARGETS] = (double)su.n_targets;
        v[M_PRESENT] = (double)present_sum / dn;
        v[M_KEPT] = rep_sum[M_REP_n_kept - M_REP_FIRST] / dn;
        v[M_THINNED] = rep_sum[M_REP_n_thinned - M_REP_FIRST] / dn;
        v[M_THIN_SCANS] = (double)thin_scans;
        v[M_THIN_GATES] = (double)thin_gates;
        v[M_REFUSED] = (double)refused;
        for (int j = 0; j < N_REP; j++) v[M_REP_FIRST + j] = rep_sum[j];
        for (int m = M_SONAR_FIRST; m < M_N; m++) v[m] = NAN;
        if (sonar) {
            long f_patch = 0, f_out = 0, f_pers = 0;
            for (size_t i = 0; i < sf.n; i++) {
                const struct sonar_track *t = &sf.v[i];
                if (t->scans == 0 || t->false_scans != t->scans) continue;
                if (2 * t->patch > t->false_scans) f_patch++;
                else f_out++;
                f_pers += 2 * t->persist > t->false_scans;
            }
            v[M_COV_PATCH] = patch_n ? (double)patch_hit / (double)patch_n : NAN;
            v[M_COV_FAR] = far_n ? (double)far_hit / (double)far_n : NAN;
            v[M_FAR_BEFORE] = far_n ? (double)far_before / (double)far_n : NAN;
            v[M_TGT_PD] = present_sum ? (double)tgt_det / (double)present_sum : NAN;
            v[M_PERSIST] = (double)persist_sum / dn;
            v[M_FALSE_PATCH] = 1000.0 * (double)f_patch / dn;
            v[M_FALSE_OUT] = 1000.0 * (double)f_out / dn;
            v[M_FALSE_PERSIST] = 1000.0 * (double)f_pers / dn;
        }
    }
    free(sf.v);
    free(held_once);
    mtt_eval_free(&ev);
    if (oracle) mtt_oracle_free(&orc);
    return rc;
}

/* ---------------------------------------------------------------- output */

/* The metrics' columns: the sonar family's only in a file with sonar
 * rows (so that the other families' files are as before). */
static int n_metric_cols(int sonar) { return sonar ? M_N : M_SONAR_FIRST; }

static int any_sonar(const struct mtt_row *rows, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(rows[i].family, "sonar") == 0) return 1;
    return 0;
}

static void csv_header(FILE *f, int sonar)
{
    fprintf(f, "capacity,config,clutter,seeds,scans,amplitude,family");
    for (int m = 0; m < n_metric_cols(sonar); m++)
        fprintf(f, ",%s_mean,%s_lo,%s_hi", metric_name[m], metric_name[m], metric_name[m]);
    fprintf(f, "\n");
}

static void csv_row(FILE *f, const struct mtt_row *r, int sonar)
{
    fprintf(f, "%ld,%s,%g,%ld,%ld,%d,%s", r->capacity, r->config, r->clutter, r->seeds, r->scans, r->amplitude,
            r->family);
    for (int m = 0; m < n_metric_cols(sonar); m++) fprintf(f, ",%.6g,%.6g,%.6g", r->mean[m], r->lo[m], r->hi[m]);
    fprintf(f, "\n");
}

static int write_csv(const struct sim_common *com, const char *suffix, const struct mtt_row *rows, int n,
                     char *path, size_t pathlen)
{
    struct fileio_out f_out;
    FILE *f = sim_csv_open(com, &f_out, suffix, path, pathlen, NULL);
    if (!f) return -1;
    const int sonar = any_sonar(rows, n);
    csv_header(f, sonar);
    for (int i = 0; i < n; i++) csv_row(f, &rows[i], sonar);
    return sim_csv_close(&f_out);
}

/* Run (seed i, level l, configuration c)'s metric m: the runs are stored
 * seed-major, as sim_run_units filled them. */
static double run_metric(const struct run_result *res, int nl, int nc, long i, int l, int c, int m)
{
    return res[(i * nl + l) * nc + c].v[m];
}

/* The index in levels (as given) of the ls-th sorted level, -1 when it
 * repeats the one before (a level given twice): the tables' rows. */
static int sorted_level(const double *levels, const double *lv_sorted, int ls)
{
    if (ls > 0 && lv_sorted[ls] == lv_sorted[ls - 1]) return -1;
    int l = 0;
    while (levels[l] != lv_sorted[ls]) l++;
    return l;
}

/* Every run's metrics, one row per (configuration, clutter, seed):
 * configurations in --config order, levels as given, for the analyst's own
 * statistics (the bad seeds, paired differences):
 * capacity,config,clutter,family,seed, then the metrics. */
static int write_runs_csv(const struct sim_common *com, const struct run_result *res, long seeds, const double *levels,
                          int nl, const int *kinds, int nc, const char *family, int sonar, char *path, size_t pathlen)
{
    struct fileio_out f_out;
    FILE *f = sim_csv_open(com, &f_out, "_runs.csv", path, pathlen, NULL);
    if (!f) return -1;
    fprintf(f, "capacity,config,clutter,family,seed");
    for (int m = 0; m < n_metric_cols(sonar); m++) fprintf(f, ",%s", metric_name[m]);
    fprintf(f, "\n");
    for (int c = 0; c < nc; c++)
        for (int l = 0; l < nl; l++)
            for (long i = 0; i < seeds; i++) {
                fprintf(f, "%d,%s,%g,%s,%llu", TRK_MAX_TRACKS, cfg_name[kinds[c]], levels[l], family,
                        (unsigned long long)(com->seed + (uint64_t)i));
                for (int m = 0; m < n_metric_cols(sonar); m++)
                    fprintf(f, ",%.6g", run_metric(res, nl, nc, i, l, c, m));
                fprintf(f, "\n");
            }
    return sim_csv_close(&f_out);
}

/* Configuration c against the base b at level l, over the seeds where both
 * have metric m: the mean of the per-seed differences and its Student t
 * interval (paired: the same scenarios, so the scenario-to-scenario spread
 * cancels); NaN without a seed. */
static void paired_diff(const struct run_result *res, long seeds, int nl, int nc, int l, int c, int b, int m,
                        double *x, double *mean, double *lo, double *hi)
{
    size_t k = 0;
    for (long i = 0; i < seeds; i++) {
        const double vc = run_metric(res, nl, nc, i, l, c, m), vb = run_metric(res, nl, nc, i, l, b, m);
        if (isfinite(vc) && isfinite(vb)) x[k++] = vc - vb;
    }
    mc_mean_ci_t(x, k, 0.95, mean, lo, hi);
}

/* "+1.23+-0.45" in w characters ("-" for NaN). */
static void put_diff(double mean, double lo, double hi, int w, int prec)
{
    char b[64];
    if (isnan(mean)) snprintf(b, sizeof b, "-");
    else snprintf(b, sizeof b, "%+.*f+-%.*f", prec, mean, prec, 0.5 * (hi - lo));
    printf(" %*s", w, b);
}

/* Each configuration against the base b on the same seeds: GOSPA as the
 * ratio of the means (sum over seeds over the base's sum; its interval by
 * the delta method on the paired seeds, mc_ratio_ci's standard error with
 * Student's t of seeds - 1 degrees of freedom) and as the mean
 * difference, and the differences in coverage, false tracks and (sonar)
 * the coverage beyond SONAR_FAR_M. Levels ascending, as the tables. */
static void print_paired(const struct run_result *res, long seeds, const double *lv_sorted, const double *levels,
                         int nl, const int *kinds, int nc, int b, int sonar, const char *family)
{
    double *x = malloc((size_t)seeds * sizeof *x), *num = malloc((size_t)seeds * sizeof *num),
           *den = malloc((size_t)seeds * sizeof *den);
    if (!x || !num || !den) {
        free(x);
        free(num);
        free(den);
        return;
    }
    printf("-- paired against %s on the same seeds (common random numbers): GOSPA as the ratio of the means\n"
           "   (95 %% interval: delta method, Student t) and the difference; per-seed differences in coverage,\n"
           "   false confirmed tracks per 1000 scans%s (mean +- the 95 %% Student t half width)\n",
           cfg_name[kinds[b]], sonar ? " and coverage beyond 5 km" : "");
    printf("%5s %-7s %-6s %7s %20s %13s %15s %15s", "slots", "family", "cfg", "clutter", "GOSPA / base", "GOSPA diff m",
           "coverage diff", "falseT diff");
    if (sonar) printf(" %15s", "beyond 5 km diff");
    printf("\n");
    for (int c = 0; c < nc; c++) {
        if (c == b) continue;
        for (int ls = 0; ls < nl; ls++) {
            const int l = sorted_level(levels, lv_sorted, ls);
            if (l < 0) continue;
            size_t k = 0;
            for (long i = 0; i < seeds; i++) {
                const double vc = run_metric(res, nl, nc, i, l, c, M_GOSPA), vb = run_metric(res, nl, nc, i, l, b, M_GOSPA);
                if (!isfinite(vc) || !isfinite(vb)) continue;
                num[k] = vc;
                den[k++] = vb;
            }
            double r, rlo, rhi, mean, lo, hi;
            mc_ratio_ci(num, den, k, 0.95, &r, &rlo, &rhi);
            if (k >= 2) { /* the delta method's standard error with Student's t of k - 1, as the others */
                const double half = 0.5 * (rhi - rlo) * mc_t(0.95, (double)(k - 1)) / mc_z(0.95);
                rlo = r - half;
                rhi = r + half;
            }
            char rb[64];
            if (isnan(r)) snprintf(rb, sizeof rb, "-");
            else snprintf(rb, sizeof rb, "%.3f [%.3f, %.3f]", r, rlo, rhi);
            printf("%5d %-7s %-6s %7g %20s", TRK_MAX_TRACKS, family, cfg_name[kinds[c]], levels[l], rb);
            paired_diff(res, seeds, nl, nc, l, c, b, M_GOSPA, x, &mean, &lo, &hi);
            put_diff(mean, lo, hi, 13, 1);
            paired_diff(res, seeds, nl, nc, l, c, b, M_COV, x, &mean, &lo, &hi);
            put_diff(mean, lo, hi, 15, 3);
            paired_diff(res, seeds, nl, nc, l, c, b, M_FALSE_TRK, x, &mean, &lo, &hi);
            put_diff(mean, lo, hi, 15, 1);
            if (sonar) {
                paired_diff(res, seeds, nl, nc, l, c, b, M_COV_FAR, x, &mean, &lo, &hi);
                put_diff(mean, lo, hi, 15, 3);
            }
            printf("\n");
        }
    }
    free(x);
    free(num);
    free(den);
}

/* "12.3+-0.4" (mean and the interval's half width) in w characters. */
static void put_ci(const struct mtt_row *r, int m, int w, int prec)
{
    char b[64];
    if (isnan(r->mean[m])) snprintf(b, sizeof b, "-");
    else snprintf(b, sizeof b, "%.*f+-%.*f", prec, r->mean[m], prec, 0.5 * (r->hi[m] - r->lo[m]));
    printf(" %*s", w, b);
}

/* One column of the tables on stdout: a metric's mean (times scale), or
 * with ci its mean and interval. */
struct column {
    const char *head;
    int m, width, prec, ci;
    double scale;
};

static void print_table(const struct mtt_row *rows, int n, const struct column *col, int n_col)
{
    printf("%5s %-7s %-6s %7s", "slots", "family", "cfg", "clutter");
    for (int c = 0; c < n_col; c++) printf(" %*s", col[c].width, col[c].head);
    printf("\n");
    for (int i = 0; i < n; i++) {
        const struct mtt_row *r = &rows[i];
        printf("%5ld %-7s %-6s %7g", r->capacity, r->family, r->config, r->clutter);
        for (int c = 0; c < n_col; c++) {
            if (col[c].ci) put_ci(r, col[c].m, col[c].width, col[c].prec);
            else if (isnan(r->mean[col[c].m])) printf(" %*s", col[c].width, "-");
            else printf(" %*.*f", col[c].width, col[c].prec, r->mean[col[c].m] * col[c].scale);
        }
        printf("\n");
    }
}

static void print_tables(const struct mtt_row *rows, int n)
{
    static const struct column accuracy[] = {
        {"GOSPA m", M_GOSPA, 13, 1, 1, 1},     {"loc", M_LOC, 8, 0, 0, 1},
        {"missed", M_MISSED, 8, 0, 0, 1},      {"false", M_FALSE, 8, 0, 0, 1},
        {"to-confirm", M_STC, 12, 1, 1, 1},    {"never", M_NEVER, 5, 1, 0, 1},
        {"coverage", M_COV, 12, 3, 1, 1},      {"turn", M_TURN, 6, 2, 0, 1},
        {"pair2", M_PAR, 6, 2, 0, 1},          {"cross2", M_CROSS, 6, 2, 0, 1},
        {"RMSE m", M_RMSE, 7, 2, 0, 1},
    };
    static const struct column management[] = {
        {"falseT/1000sc", M_FALSE_TRK, 13, 1, 1, 1}, {"falseTS%", M_FALSE_TS, 9, 1, 0, 1},
        {"dupTS%", M_DUP_TS, 8, 1, 0, 1},            {"frag", M_FRAG, 6, 1, 0, 1},
        {"idsw", M_IDSW, 6, 1, 0, 1},                {"cpu us/scan", M_CPU, 10, 0, 1, 1},
        {"live", M_LIVE, 7, 1, 0, 1},                {"full%", M_FULL, 6, 1, 0, 100},
        {"conf", M_CONF, 6, 1, 0, 1},                {"refused", M_REP_n_init_refused_full, 9, 0, 0, 1},
        {"replaced", M_REP_n_replaced, 8, 0, 0, 1},  {"merged", M_REP_n_merged, 7, 0, 0, 1},
        {"held", M_REP_n_stationary, 7, 0, 0, 1},
    };
    static const struct column capacity[] = {
        {"dets/scan", M_CLUTTER, 9, 1, 0, 1},        {"kept/scan", M_KEPT, 9, 1, 0, 1},
        {"thinned/scan", M_THINNED, 12, 1, 0, 1},    {"thinned scans", M_THIN_SCANS, 13, 1, 0, 1},
        {"in gates", M_THIN_GATES, 8, 1, 0, 1},      {"refused scans", M_REFUSED, 13, 1, 0, 1},
        {"capped scans", M_CAPPED, 12, 1, 0, 1},
    };
    static const struct column confirm[] = {
        {"all", M_STC, 11, 1, 1, 1},              {"crossing", M_STC_CROSS, 11, 1, 1, 1},
        {"pair", M_STC_PAIR, 11, 1, 1, 1},        {"turn", M_STC_TURN, 11, 1, 1, 1},
        {"straight", M_STC_STRAIGHT, 11, 1, 1, 1}, {"birth", M_STC_BIRTH, 11, 1, 1, 1},
        {"death", M_STC_DEATH, 11, 1, 1, 1},
    };
    static const struct column pairs[] = {
        {"X both", M_CROSS, 7, 2, 0, 1},        {"X idsw", M_CROSS_IDSW, 7, 2, 0, 1},
        {"X dup%", M_CROSS_DUP, 7, 1, 0, 1},    {"X coal%", M_CROSS_COAL, 7, 1, 0, 1},
        {"par both", M_PAR, 8, 2, 0, 1},        {"par idsw", M_PAR_IDSW, 8, 2, 0, 1},
        {"par dup%", M_PAR_DUP, 8, 1, 0, 1},    {"par coal%", M_PAR_COAL, 8, 1, 0, 1},
    };
    static const struct column manoeuvre[] = {
        {"turn cov", M_TURN, 11, 3, 1, 1},        {"turn RMSE m", M_TURN_RMSE, 12, 1, 1, 1},
        {"after", M_TURN_AFTER, 6, 2, 0, 1},      {"turn lost", M_TURN_LOST, 11, 2, 1, 1},
        {"falseT/1000sc", M_FALSE_TRK, 13, 1, 1, 1}, {"GOSPA m", M_GOSPA, 11, 1, 1, 1},
        /* the acceleration's (left out without one) */
        {"accel cov", M_ACC, 11, 3, 1, 1},        {"accel RMSE", M_ACC_RMSE, 11, 1, 1, 1},
        {"after", M_ACC_AFTER, 6, 2, 0, 1},       {"acc lost", M_ACC_LOST, 8, 2, 0, 1},
    };
    static const struct column sonar[] = {
        {"coverage", M_COV, 12, 3, 1, 1},           {"in patches", M_COV_PATCH, 12, 3, 1, 1},
        {"beyond 5 km", M_COV_FAR, 12, 3, 1, 1},    {"before 1st", M_FAR_BEFORE, 10, 3, 0, 1},
        {"pair2", M_PAR, 6, 2, 0, 1},
        {"cross2", M_CROSS, 6, 2, 0, 1},            {"turn", M_TURN, 6, 2, 0, 1},
        {"falseT/1000sc", M_FALSE_TRK, 13, 1, 1, 1}, {"in patch", M_FALSE_PATCH, 8, 1, 0, 1},
        {"outside", M_FALSE_OUT, 8, 1, 0, 1},       {"on persist", M_FALSE_PERSIST, 10, 1, 0, 1},
        {"P_D seen", M_TGT_PD, 8, 3, 0, 1},         {"persist/scan", M_PERSIST, 12, 1, 0, 1},
    };
    int accel = 0;
    for (int i = 0; i < n; i++) accel |= !isnan(rows[i].mean[M_ACC]);
#define N_COLS(a) (int)(sizeof a / sizeof a[0])
    printf("-- accuracy (mean +- half the 95%% interval over seeds; GOSPA parts in m^2 per scan)\n");
    print_table(rows, n, accuracy, N_COLS(accuracy));
    printf("-- track management and cost (per run of %ld scans unless noted)\n", n ? rows[0].scans : 0L);
    print_table(rows, n, management, N_COLS(management));
    printf("-- scans beyond capacity (TRK_MAX_DETECTIONS %d): clutter, kept and thinned detections per scan,\n"
           "   per run: scans thinned (in gates: the cut inside the gate boxes), refused, clutter capped\n",
           TRK_MAX_DETECTIONS);
    print_table(rows, n, capacity, N_COLS(capacity));
    printf("-- scans to the first confirmed track (from the target's first scan) per designated target: all,\n"
           "   the crossing's and the pair's two (their mean), the turn, the straight one (sonar: the far\n"
           "   target, across the line of sight near the sector's end), the birth, the death\n");
    print_table(rows, n, confirm, N_COLS(confirm));
    printf("-- the crossing (X) and the parallel pair: both held (fraction of scans), identity switches per run,\n"
           "   duplicate target-scans and coalesced scans per 100 (X: from %d scans before to %d after)\n",
           CROSS_WINDOW, CROSS_AFTER);
    print_table(rows, n, pairs, N_COLS(pairs));
    printf("-- manoeuvres: the turn%s over its scans (coverage, RMSE of its track), coverage in the %d scans after,\n"
           "   lost = its track at the first scan not its track %d scans after the last (fraction of runs)\n",
           accel ? " and the straight target's acceleration" : "", MAN_AFTER, MAN_LOST);
    print_table(rows, n, manoeuvre, N_COLS(manoeuvre) - (accel ? 0 : 4));
    if (any_sonar(rows, n)) {
        printf("-- sonar situations: coverage of all targets, in the reverberation patches, beyond %g km from the\n"
               "   sonar (and the share of those target-scans missed before the target's first confirmed track),\n"
               "   of the close pair (both held), the shallow crossing (both, its window), the turn; false\n"
               "   confirmed tracks per 1000 scans: all, mostly in a patch, mostly outside (these two add up to\n"
               "   all), mostly within c of a persistent scatterer; P_D seen (target detections per target-scan),\n"
               "   persistent returns per scan\n",
               SONAR_FAR_M / 1000.0);
        print_table(rows, n, sonar, N_COLS(sonar));
    }
#undef N_COLS
}

/* (Titles and labels go into single-quoted gnuplot strings: no apostrophes.)
 * Plots against clutter count, one line (with its interval) per (capacity,
 * configuration, family; the family in the key when there are several);
 * the data go into the scripts as datablocks. */
static void plot_all(const struct sim_common *com, const struct mtt_row *rows, int n, const char *title)
{
    if (com->no_plot || n == 0) return;
    static long caps[MAX_ROWS];
    static char cfgs[MAX_ROWS][40];
    static int grp[MAX_ROWS];
    int ng = 0, multi_family = 0;
    double xmax = 0;
    for (int i = 1; i < n; i++) multi_family |= strcmp(rows[i].family, rows[0].family) != 0;
    for (int i = 0; i < n; i++) {
        char cfg[40];
        if (multi_family) snprintf(cfg, sizeof cfg, "%s, %s", rows[i].config, rows[i].family);
        else snprintf(cfg, sizeof cfg, "%s", rows[i].config);
        int g = 0;
        while (g < ng && !(caps[g] == rows[i].capacity && strcmp(cfgs[g], cfg) == 0)) g++;
        if (g == ng) {
            caps[ng] = rows[i].capacity;
            snprintf(cfgs[ng], sizeof cfgs[ng], "%s", cfg);
            ng++;
        }
        grp[i] = g;
        if (rows[i].clutter > xmax) xmax = rows[i].clutter;
    }
    int accel = 0; /* the acceleration's panel only with an accelerating target */
    for (int i = 0; i < n; i++) accel |= !isnan(rows[i].mean[M_ACC]);
    const struct {
        const char *suffix, *what;
        int m[3];
        int nm;
        const char *key; /* where the key goes */
    } plots[] = {
        {"_gospa", "GOSPA (m), p = 2, alpha = 2", {M_GOSPA}, 1, "top left"},
        {"_gospa_parts", "", {M_LOC, M_MISSED, M_FALSE}, 3, "top left"},
        {"_confirm", "", {M_STC, M_NEVER}, 2, "top left"},
        {"_false", "", {M_FALSE_TRK, M_FALSE_TS}, 2, "top left"},
        {"_manoeuvre", "coverage of the turning target over its turn", {M_TURN, M_ACC}, accel ? 2 : 1,
         "bottom left"}, /* fractions near 1 */
    };
    static const char *const ylabel[M_N] = {
        [M_GOSPA] = "GOSPA (m)",
        [M_LOC] = "localisation part (m^2 per scan)",
        [M_MISSED] = "missed part (m^2 per scan)",
        [M_FALSE] = "false part (m^2 per scan)",
        [M_STC] = "scans to the first confirmed track",
        [M_NEVER] = "targets never confirmed (per run)",
        [M_FALSE_TRK] = "false confirmed tracks per 1000 scans",
        [M_FALSE_TS] = "false track-scans per 100 scans",
        [M_TURN] = "turning target covered (fraction of the scans of its turn)",
        [M_ACC] = "accelerating target covered (fraction of its scans)",
    };
    const double dx = xmax > 0 ? xmax / 150 : 1; /* groups side by side */
    for (size_t pl = 0; pl < sizeof plots / sizeof plots[0]; pl++) {
        struct sim_text t = {NULL, 0, 0, 0};
        for (int g = 0; g < ng; g++) {
            sim_text_add(&t, "$g%d << EOD\n", g);
            for (int i = 0; i < n; i++) {
                if (grp[i] != g) continue;
                sim_text_add(&t, "%.6g", rows[i].clutter + ((double)g - 0.5 * (ng - 1)) * dx);
                for (int k = 0; k < plots[pl].nm; k++) {
                    const int m = plots[pl].m[k];
                    sim_text_add(&t, " %.6g %.6g %.6g", rows[i].mean[m], rows[i].lo[m], rows[i].hi[m]);
                }
                sim_text_add(&t, "\n");
            }
            sim_text_add(&t, "EOD\n");
        }
        if (plots[pl].nm > 1)
            sim_text_add(&t, "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                             "  set terminal pngcairo size %d,520 enhanced font 'sans,10'\n"
                             "} else {\n  set terminal png size %d,520\n}\n"
                             "set output '%s%s.png'\nset multiplot layout 1,%d title '%s'\n",
                         450 * plots[pl].nm, 450 * plots[pl].nm, com->out, plots[pl].suffix, plots[pl].nm, title);
        for (int k = 0; k < plots[pl].nm; k++) {
            const int m = plots[pl].m[k];
            double ymax = 0; /* an all-zero panel gets [0:1], not gnuplot's warning */
            for (int i = 0; i < n; i++)
                if (isfinite(rows[i].hi[m]) && rows[i].hi[m] > ymax) ymax = rows[i].hi[m];
            sim_text_add(&t, "set grid\nset key %s font ',9'\nset xlabel 'clutter detections per scan'\n"
                             "set ylabel '%s'\nset xrange [%g:%g]\nset yrange [0:%s]\n",
                         plots[pl].key, ylabel[m], -0.04 * xmax - 1, 1.04 * xmax + 1, ymax > 0 ? "*" : "1");
            if (plots[pl].nm == 1) sim_text_add(&t, "set title '%s: %s'\n", title, plots[pl].what);
            else sim_text_add(&t, "unset title\n");
            sim_text_add(&t, "plot ");
            for (int g = 0; g < ng; g++)
                sim_text_add(&t, "%s$g%d using 1:%d:%d:%d with yerrorlines lw 2 pt %d title '%ld slots, %s'",
                             g ? ", \\\n     " : "", g, 2 + 3 * k, 3 + 3 * k, 4 + 3 * k, 5 + 2 * g, caps[g], cfgs[g]);
            sim_text_add(&t, "\n");
        }
        if (plots[pl].nm > 1) sim_text_add(&t, "unset multiplot\n");
        if (!t.failed) sim_plot(com, plots[pl].suffix, t.s);
        sim_text_free(&t);
    }
}

/* ---------------------------------------------------------------- mtt */

/* The directory of the output prefix (mkdir -p of everything before the
 * last '/'). 0, or -1. */
static int make_parent(const char *prefix)
{
    char buf[1024];
    const char *slash = strrchr(prefix, '/');
    if (!slash) return 0;
    const size_t n = (size_t)(slash - prefix);
    if (n == 0 || n >= sizeof buf) return n == 0 ? 0 : -1;
    memcpy(buf, prefix, n);
    buf[n] = 0;
    return sim_mkdir_p(buf);
}

static int take_configs(const char *s, int *kinds, int *n, char *err, size_t errlen)
{
    *n = 0;
    while (*s) {
        const size_t len = strcspn(s, ",");
        int k = -1;
        for (int i = 0; i < N_CFG_KINDS; i++)
            if (strlen(cfg_name[i]) == len && strncmp(s, cfg_name[i], len) == 0) k = i;
        if (k < 0 || *n >= N_CFG_KINDS) {
            snprintf(err, errlen, "--config: '%.*s' is not one of new, pda, old, imm, oracle, cart, cfar, known (each once)",
                     (int)len, s);
            return -1;
        }
        if (k == CFG_IMM && !TRK_WITH_IMM) {
            snprintf(err, errlen,
                     "--config imm: this trk-sim is built without IMM tracks (TRK_WITH_IMM = 0); use the IMM "
                     "build: `make mtt-imm`, or make BUILD=build/imm CONFIG_DEFS='-DTRK_WITH_IMM=1 "
                     "-DTRK_MAX_MODELS=3' build/imm/bin/trk-sim");
            return -1;
        }
        for (int i = 0; i < *n; i++)
            if (kinds[i] == k) {
                snprintf(err, errlen, "--config: '%s' twice", cfg_name[k]);
                return -1;
            }
        kinds[(*n)++] = k;
        s += len;
        if (*s == ',') s++;
    }
    if (*n == 0) {
        snprintf(err, errlen, "--config: no configuration");
        return -1;
    }
    return 0;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static const int family_values[] = {MTT_FAMILY_TRANSIT, MTT_FAMILY_FIXED, MTT_FAMILY_SONAR};

/* The runs as work units (sim_run_units): unit j = (seed j / (nl nc),
 * level (j / nc) % nl, configuration j % nc). */
struct mtt_units {
    const struct mtt_scenario *sc;
    const double *levels;
    int over;
    const struct trk_tracker_params *tp;
    const int *kinds;           /* per configuration */
    double c_m;
    long nl, nc;
};

static int mtt_unit(void *ctx, size_t j, void *res, void **wsp)
{
    const struct mtt_units *u = ctx;
    struct run_ws *ws = *wsp;
    if (!ws) {
        if (!(ws = malloc(sizeof *ws))) return 1;
        if (!(ws->tk = malloc(sizeof *ws->tk))) {
            free(ws);
            return 1;
        }
        *wsp = ws;
    }
    const long i = (long)j / (u->nl * u->nc), l = ((long)j / u->nc) % u->nl, c = (long)j % u->nc;
    return run_one(&u->sc[i], (long)u->levels[l], u->over, u->kinds[c],
                   &u->tp[l * u->nc + c], u->c_m, ws, res) != 0;
}

static void mtt_ws_free(void *ctx, void *wsp)
{
    struct run_ws *ws = wsp;
    (void)ctx;
    free(ws->tk);
    free(ws);
}

/* The sonar family's clutter map against the truth: the first seed's run
 * of `new` at each clutter level, its map after the last scan, per cell
 * (at its centre, from the last pose) the true density
 * (mtt_scen_clutter_density), the configured one (the sensor's profile) and
 * the tracker's (trk_tracker_clutter_at): PREFIX_clutter_map.csv and
 * PREFIX_clutter_map.png (tracker's and configured against the truth,
 * log-log). 0, or -1 on a failed run or write. */
static int clutter_map_dump(const struct sim_common *com, const struct mtt_scenario *sc, const double *levels, int nl,
                            const struct trk_tracker_params *tp, const int *kinds, int nc)
{
    int c = 0;
    while (c < nc && kinds[c] != CFG_NEW) c++;
    const struct trk_clutter_map_params *mp = c < nc ? &tp[c].clutter_map : NULL;
    if (!mp || sc->p.family != MTT_FAMILY_SONAR || mp->n_range == 0) return 0;
    struct run_ws *ws = malloc(sizeof *ws);
    if (!ws || !(ws->tk = malloc(sizeof *ws->tk))) {
        free(ws);
        return -1;
    }
    struct fileio_out f_out;
    char path[1024];
    FILE *f = sim_csv_open(com, &f_out, "_clutter_map.csv", path, sizeof path,
                           "clutter,range_cell,bearing_cell,x_m,y_m,in_patch,true_per_m2,configured_per_m2,"
                           "tracker_per_m2");
    int rc = f ? 0 : -1;
    const long ns = sc->p.n_scans;
    for (int l = 0; l < nl && rc == 0; l++) {
        const long clutter = (long)levels[l];
        if (trk_tracker_init(ws->tk, &tp[l * nc + c]) != TRK_OK) rc = -1;
        for (long k = 0; k < ns && rc == 0; k++) {
            struct trk_scan scan;
            struct mtt_scan_info info;
            if (sonar_scan_for(sc, k, clutter, TRK_MAX_SCAN_DETECTIONS, CFG_NEW, &tp[l * nc + c], ws, &scan, &info) != 0 ||
                trk_tracker_process_scan(ws->tk, &scan, NULL) != TRK_OK)
                rc = -1;
        }
        struct trk_pose pose;
        mtt_scen_pose(sc, ns - 1, &pose);
        const struct trk_coverage *cv = &sc->sonar.coverage;
        const double r0 = (double)cv->min_range_m, dr = ((double)cv->max_range_m - r0) / mp->n_range;
        const double hb = (double)cv->half_width_rad, db = 2 * hb / mp->n_bearing;
        for (unsigned ir = 0; ir < mp->n_range && rc == 0; ir++)
            for (unsigned ib = 0; ib < mp->n_bearing && rc == 0; ib++) {
                const double r = r0 + (ir + 0.5) * dr, b = (double)pose.heading_rad - hb + (ib + 0.5) * db;
                const double x = (double)pose.x_m + r * sin(b), y = (double)pose.y_m + r * cos(b);
                trk_real lt = 0;
                if (trk_tracker_clutter_at(ws->tk, 0, &pose, (trk_real)x, (trk_real)y, &lt) != TRK_OK) rc = -1;
                fprintf(f, "%ld,%u,%u,%.1f,%.1f,%d,%.6g,%.6g,%.6g\n", clutter, ir, ib, x, y,
                        mtt_scen_in_patch(sc, x, y), mtt_scen_clutter_density(sc, ns - 1, clutter, x, y),
                        (double)trk_sensor_clutter_at(&tp[l * nc + c].sensor[0], &pose, (trk_real)x, (trk_real)y),
                        (double)lt);
            }
    }
    if (f && (rc != 0 ? (sim_csv_discard(&f_out), -1) : sim_csv_close(&f_out)) != 0) rc = -1;
    free(ws->tk);
    free(ws);
    if (rc != 0) return -1;
    struct sim_text body = {NULL, 0, 0, 0};
    sim_text_add(&body,
                 "set datafile separator ','\nset key top left\nset logscale xy\nset grid\n"
                 "set xlabel 'true clutter density (per km^2 per ping)'\n"
                 "set ylabel 'density the tracker uses (per km^2 per ping)'\n"
                 "set title 'clutter map after %ld pings, seed %lu, %u x %u cells (first seed, config new)'\n"
                 "plot x title 'truth' with lines lc rgb 'black'",
                 ns, (unsigned long)sc->p.seed, mp ? mp->n_range : 0u, mp ? mp->n_bearing : 0u);
    for (int l = 0; l < nl; l++)
        sim_text_add(&body,
                     ", '%s' using ($1 == %ld && $7 > 0 ? $7 * 1e6 : 1/0):($9 * 1e6) title 'map, %ld per ping' "
                     "with points pt 7 ps 0.6, '' using ($1 == %ld && $7 > 0 ? $7 * 1e6 : 1/0):($8 * 1e6) title "
                     "'configured (profile), %ld per ping' with points pt 6 ps 0.6",
                     path, (long)levels[l], (long)levels[l], (long)levels[l], (long)levels[l]);
    sim_text_add(&body, "\n");
    const int prc = body.failed ? -1 : sim_plot(com, "_clutter_map", body.s);
    sim_text_free(&body);
    printf("-- clutter map against the truth (first seed, new): %s%s\n", path,
           com->no_plot ? "" : " and its PNG");
    return prc < 0 ? -1 : 0;
}

SIM_EXPERIMENT(mtt, "mtt", "multi-target evaluation (GOSPA, track maintenance) over clutter levels")
{
    /* the options whose default is the family's: -1 / NULL until given */
    long scans = -1, seeds;
    double levels[MAX_LEVELS], c_m = -1, pd, snr_db, q, v_min = -1, v_max = -1, par_sep = -1, turn_rate, turn_deg,
                               accel, accel_s;
    struct imm_opts im;
    int n_levels, no_amp = 0, family, over, sweep = 0, no_persist = 0;
    const char *configs = NULL, *paired_base = NULL;
    struct mtt_settings set = {{NULL}, 0};
    const struct sim_opt opts[] = {
        SIM_OPT_CHOICE("--family", &family, "transit|fixed|sonar", family_values, "transit",
                       "the scenario family (mtt_scenario.h): transit,\n"
                       "targets entering and leaving, slots re-used; fixed, the 8\n"
                       "targets alone, alive the whole run but the birth and the\n"
                       "death, speeds reduced to keep each path inside (the scenario\n"
                       "the peer was measured on); sonar, a polar sensor on a platform\n"
                       "at 3 m/s, its sector 0.5-8 km +-60 deg, a ping every 8 s,\n"
                       "P_D falling with range, patches, persistent scatterers"),
        SIM_OPT_LONG("--scans", &scans, "N", NULL, SIM_IN, 10, 100000,
                     "scans per run (default 200, one every 4 s; sonar 150, one\n"
                     "every 8 s)"),
        SIM_OPT_LONG("--seeds", &seeds, "N", "10", SIM_IN, 1, 100000,
                     "scenarios of the family: seeds S .. S+N-1 (S = --seed)"),
        SIM_OPT_LIST("--clutter-count", levels, &n_levels, MAX_LEVELS, "0,20,50,100,150,200,256", SIM_IN, 0,
                     100000,
                     "clutter detections per scan (exactly N, uniform over the region;\n"
                     "a scan beyond TRK_MAX_DETECTIONS is thinned by the tracker)"),
        SIM_OPT_FLAG("--clutter-sweep", &sweep,
                     "clutter levels from 0 to 4 x TRK_MAX_DETECTIONS (0, 1/8, 1/4,\n"
                     "1/2, 1, 2, 3, 4 x), in place of --clutter-count"),
        SIM_OPT_CHOICE("--over-capacity", &over, "thin|refuse|cap", over_values, "thin",
                       "a scan beyond TRK_MAX_DETECTIONS: thin, the tracker keeps the\n"
                       "most useful detections (trk/tracker.h); for comparison, the\n"
                       "behaviours before: refuse, the library refused the scan\n"
                       "(TRK_E_CAPACITY; counted, the run goes on), cap, the clutter\n"
                       "cut to TRK_MAX_DETECTIONS minus the target detections"),
        SIM_OPT_STRING("--config", &configs, "LIST", NULL,
                       "configurations (default new,pda,old,oracle; sonar\n"
                       "new,pda,cart,oracle): new (trk_tracker_default_params: joint\n"
                       "association), pda (the same with association = pda: each\n"
                       "track's own PDA), old (the defaults before two-point initiation, per-track\n"
                       "PDA), imm (new with IMM tracks: CV and turns at +-omega,\n"
                       "--imm-*; only in a build with TRK_WITH_IMM = 1: make mtt-imm),\n"
                       "oracle (no tracker: per target a CV Kalman filter fed with\n"
                       "its own detections, known association, new's R and q: what\n"
                       "this sensor and motion model allow; no bound on a target\n"
                       "turning beyond q, which it never restarts on);\n"
                       "with association = joint and no clutter, the tracker\n"
                       "assumes one clutter detection per scan in the region;\n"
                       "cart (sonar only): new the old way, the polar detections\n"
                       "converted by the caller (trk_detection_from_polar), one P_D\n"
                       "averaged over the sector, no pose, no coverage; new and pda\n"
                       "get sonar scans as polar scans with the platform's pose;\n"
                       "cfar (sonar only): new with each detection's true clutter\n"
                       "density passed (trk_scan.clutter_density_per_m2: a CFAR\n"
                       "that knew its background); known: new given only the\n"
                       "targets' detections (association known), each weighed\n"
                       "against its clutter density (sonar: the true one, as cfar;\n"
                       "no persistent-return description): trk's start and\n"
                       "confirmation without the association's price"),
        SIM_OPT_STRING("--paired-base", &paired_base, "CFG", NULL,
                       "the configuration the others are paired against, seed by\n"
                       "seed (the table \"paired against\"; default: oracle when it\n"
                       "runs, else the first of --config)"),
        SIM_OPT_FLAG("--no-persistent", &no_persist,
                     "sonar: no persistent scatterers (the same targets' detections\n"
                     "and clutter)"),
        SIM_OPT_STRINGS("--set", set.kv, &set.n, MTT_MAX_SETTINGS, "KEY=VALUE",
                        "a tracker setting for every configuration (the keys below)"),
        SIM_OPT_FLAG("--no-amplitude", &no_amp, "no amplitudes: positions only, use_amplitude off"),
        SIM_OPT_DOUBLE("--gospa-c", &c_m, "M", NULL, SIM_GT, 0, 0,
                       "GOSPA cut-off c (m; default 50, sonar 200: its cross-range\n"
                       "sigma is 105 m at 4 km)"),
        SIM_OPT_DOUBLE("--pd", &pd, "P", "0.8", SIM_OPEN, 0, 1,
                       "detection probability (sonar: unused, its profile over range)"),
        SIM_OPT_DOUBLE("--snr-db", &snr_db, "D", "13", SIM_IN, 0, 40,
                       "target SNR (Swerling I, Rayleigh clutter); the threshold's\n"
                       "P_FA is pd^(1 + SNR), so that P_D = pd"),
        SIM_OPT_DOUBLE("--q", &q, "Q", "1e-3", SIM_GE, 0, 0, "the tracker's process noise (m^2/s^3)"),
        SIM_OPT_DOUBLE("--speed-min", &v_min, "V", NULL, SIM_GT, 0, 0,
                       "target speeds drawn uniformly in [--speed-min, --speed-max] (m/s;\n"
                       "default 5-15, sonar 3-10)"),
        SIM_OPT_DOUBLE("--speed-max", &v_max, "V", NULL, SIM_GT, 0, 0,
                       "upper end of the speed range, e.g. 20 to go past the tracker's\n"
                       "two-point velocity gate (its own: --set init.max_speed_mps=V)"),
        SIM_OPT_DOUBLE("--parallel-sep", &par_sep, "M", NULL, SIM_OPEN, 0, 500,
                       "the parallel pair's separation (m; default 60 side by side;\n"
                       "sonar 100 along the bearing): closer pairs share detections"),
        SIM_OPT_DOUBLE("--turn-rate", &turn_rate, "DPS", "3", SIM_IN, 0.01, 90,
                       "the turning target's rate (deg/s; each seed's x [0.8, 1.2])"),
        SIM_OPT_DOUBLE("--turn-deg", &turn_deg, "DEG", "90", SIM_IN, 1, 360,
                       "its turn (deg): it lasts turn-deg / turn-rate s, e.g.\n"
                       "--turn-rate 1 --turn-deg 120: 30 scans of 4 s"),
        SIM_OPT_DOUBLE("--accel", &accel, "M/S2", "0", SIM_IN, 0, 10,
                       "the straight target's along-track acceleration from its\n"
                       "mid-life (m/s^2; 0 = none, the scenario unchanged)"),
        SIM_OPT_DOUBLE("--accel-s", &accel_s, "S", "60", SIM_IN, 1, 100000,
                       "... for this long (s): 0.1 m/s^2 for 60 s is +6 m/s"),
        SIM_OPT_DOUBLE("--imm-rate", &im.rate_dps, "DPS", MTT_STR(MTT_IMM_RATE_DPS), SIM_IN, 0.01, 57,
                       "imm: the turn models' rate omega (deg/s)"),
        SIM_OPT_DOUBLE("--imm-stay", &im.p_stay, "P", MTT_STR(MTT_IMM_STAY), SIM_IN, 0, 1,
                       "imm: the probability of staying in a model per scan"),
        SIM_OPT_DOUBLE("--imm-turn-q", &im.turn_q, "Q", MTT_STR(MTT_IMM_TURN_Q), SIM_GT, 0, 0,
                       "imm: the turn models' process noise (m^2/s^3; the CV\n"
                       "model's is --q)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "mtt", "[options] [--set key=value ...]",
        "Multi-target evaluation: a scenario family of tools/sim/mtt_scenario.h\n"
        "(3 km x 3 km, a scan every 4 s, P_D 0.8, sigma 5 m, Rayleigh amplitudes; eight\n"
        "slots, each holding one target at a time: an X through the centre, a pair 60 m\n"
        "apart, a birth at ~20 % of the run, a death at ~70 %, a 90 deg turn at ~3 deg/s\n"
        "mid-run, one straight; speeds drawn in [--speed-min, --speed-max], 5-15 m/s).\n"
        "--family transit (the default): a target is present while inside the region and\n"
        "keeps its speed, and a slot whose target has left or died takes a new target\n"
        "entering at the edge 1-10 scans later: 6-8 present. --family fixed (the\n"
        "8-target scenario the peer, Stone Soup's JPDA, was measured on): the\n"
        "eight alone, alive the whole run but the birth and the death, each speed reduced\n"
        "until its path stays inside (at 200 scans about 3-6 m/s). --family sonar: a polar\n"
        "sensor (7.5 m, 1.5 deg) on a platform at 3 m/s, its sector 0.5-8 km +-60 deg, a ping\n"
        "every 8 s with the platform's pose, P_D falling with range, clutter in patches and\n"
        "the near field, 12 persistent scatterers; eight targets at 3-10 m/s (a shallow\n"
        "crossing, a pair 100 m apart on one bearing, a 3 deg/s turn, a far one, a birth, a\n"
        "death); the trackers get polar scans, cart the old way. Each seed at every\n"
        "clutter count through every configuration (the same scenarios: common random\n"
        "numbers). Scored per scan on the confirmed tracks (GOSPA p = 2, alpha = 2, cut-off\n"
        "c; tools/sim/mtt_eval.h); mean and 95 % Student t interval over seeds.",
        opts, "build/results/mtt", NULL, SIM_UNUSED_RUNS,
        "Writes PREFIX.csv: one row per (TRK_MAX_TRACKS, config, clutter), the family in\n"
        "the column family, then columns <metric>_mean, _lo, _hi; and PREFIX_gospa.png,\n"
        "_gospa_parts.png, _confirm.png, _false.png, _manoeuvre.png (gnuplot). Compare builds with\n"
        "`trk-sim mtt-compare A.csv B.csv`. PREFIX_runs.csv: every run's metrics, one row per\n"
        "(config, clutter, seed), for statistics of your own.\n"
        "--set key=value: tracker settings (the keys below), applied after each\n"
        "configuration's own and the scenario's sensor (sensor.0.*, process_noise_q).\n",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse_more(&cli, tcfg_help, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    char err[1024];
    if (make_parent(com.out) != 0) {
        fprintf(stderr, "trk-sim mtt: cannot create the directory of %s\n", com.out);
        return 1;
    }
    const int sonar = family == MTT_FAMILY_SONAR;
    {
        /* the family's defaults of the options not given */
        struct mtt_scen_params d;
        if (sonar) mtt_scen_sonar_defaults(&d);
        else mtt_scen_defaults(&d);
        if (scans < 0) scans = d.n_scans;
        if (v_min < 0) v_min = d.speed_min_mps;
        if (v_max < 0) v_max = d.speed_max_mps;
        if (par_sep < 0) par_sep = d.parallel_sep_m;
        if (c_m < 0) c_m = sonar ? 200 : 50;
        if (!configs) configs = sonar ? "new,pda,cart,oracle" : "new,pda,old,oracle";
    }
    int kinds[N_CFG_KINDS], n_cfg;
    if (take_configs(configs, kinds, &n_cfg, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim mtt: %s\n", err);
        return 2;
    }
    for (int c = 0; c < n_cfg; c++)
        if ((kinds[c] == CFG_CART || kinds[c] == CFG_CFAR) && !sonar) {
            fprintf(stderr, "trk-sim mtt: --config %s: only with --family sonar (polar detections)\n",
                    cfg_name[kinds[c]]);
            return 2;
        }
    int base = 0; /* the paired table's base: --paired-base, else the oracle, else the first */
    for (int c = 0; c < n_cfg; c++)
        if (paired_base ? strcmp(paired_base, cfg_name[kinds[c]]) == 0 : kinds[c] == CFG_ORACLE) base = c;
    if (paired_base && strcmp(paired_base, cfg_name[kinds[base]]) != 0) {
        fprintf(stderr, "trk-sim mtt: --paired-base %s: not one of --config %s\n", paired_base, configs);
        return 2;
    }
    if (sweep) {
        static const double frac[] = {0, 0.125, 0.25, 0.5, 1, 2, 3, 4};
        n_levels = (int)(sizeof frac / sizeof frac[0]);
        for (int l = 0; l < n_levels; l++) levels[l] = floor(frac[l] * TRK_MAX_DETECTIONS);
    }
    for (int l = 0; l < n_levels; l++)
        if (levels[l] != floor(levels[l])) {
            fprintf(stderr, "trk-sim mtt: --clutter-count: %g is not a whole number\n", levels[l]);
            return 2;
        }
    if (offsetof(struct trk_scan_report, thin_in_gates) != (size_t)N_REP * sizeof(uint32_t))
        fprintf(stderr, "trk-sim mtt: note: struct trk_scan_report holds %zu bytes of counters, the %d listed "
                        "here %zu: update MTT_REPORT_COUNTERS in %s\n",
                offsetof(struct trk_scan_report, thin_in_gates), N_REP, (size_t)N_REP * sizeof(uint32_t), __FILE__);
    if (v_min > v_max) {
        fprintf(stderr, "trk-sim mtt: --speed-min %g exceeds --speed-max %g\n", v_min, v_max);
        return 2;
    }
    /* ---- the scenarios (one per seed; read-only from here on) */
    struct mtt_scenario *sc = calloc((size_t)seeds, sizeof *sc);
    if (!sc) return 1;
    double vmin = INFINITY, vmax = 0, n_tg_sum = 0, pres_sum = 0;
    long n_tg_min = LONG_MAX, n_tg_max = 0, reduced = 0;
    int pres_min = MTT_N_SLOTS, pres_max = 0;
    for (long i = 0; i < seeds; i++) {
        struct mtt_scen_params sp;
        if (sonar) mtt_scen_sonar_defaults(&sp);
        else mtt_scen_defaults(&sp);
        sp.family = family;
        sp.seed = com.seed + (uint64_t)i;
        sp.n_scans = scans;
        sp.pd = pd;
        sp.snr_db = snr_db;
        sp.amplitude = !no_amp;
        sp.persistent = !no_persist;
        sp.speed_min_mps = v_min;
        sp.speed_max_mps = v_max;
        sp.parallel_sep_m = par_sep;
        sp.turn_rate_dps = turn_rate;
        sp.turn_deg = turn_deg;
        sp.accel_mps2 = accel;
        sp.accel_s = accel_s;
        if (mtt_scen_init(&sc[i], &sp, err, sizeof err) != 0) {
            fprintf(stderr, "trk-sim mtt: scenario: %s\n", err);
            while (i-- > 0) mtt_scen_free(&sc[i]);
            free(sc);
            return 2;
        }
        for (size_t j = 0; j < sc[i].n_targets; j++) {
            const struct mtt_target *g = &sc[i].tg[j];
            if (g->death_scan <= g->birth_scan) continue;
            vmin = fmin(vmin, g->speed_mps);
            vmax = fmax(vmax, g->speed_mps);
            reduced += g->speed_mps != g->speed_drawn_mps;
        }
        const long nti = (long)sc[i].n_targets;
        n_tg_sum += (double)nti;
        n_tg_min = nti < n_tg_min ? nti : n_tg_min;
        n_tg_max = nti > n_tg_max ? nti : n_tg_max;
        for (long k = 0; k < scans; k++) {
            const int np = mtt_scen_n_present(&sc[i], k);
            pres_sum += np;
            pres_min = np < pres_min ? np : pres_min;
            pres_max = np > pres_max ? np : pres_max;
        }
    }
    const double area = sc[0].area_m2;
    /* ---- the configurations at every level (the clutter density differs) */
    const int nl = n_levels, nc = n_cfg;
    struct trk_tracker_params *tp = malloc((size_t)(nl * nc) * sizeof *tp);
    struct tcfg_runtime *rts = calloc((size_t)(nl * nc), sizeof *rts);
    if (!tp || !rts) return 1;
    for (int l = 0; l < nl; l++)
        for (int c = 0; c < nc; c++) {
            /* the clutter density the tracker sees: all of it, but what a cut left */
            const double n_eff = over == OVER_CAP ? fmin(levels[l], (double)TRK_MAX_DETECTIONS) : levels[l];
            if (mtt_build_params(kinds[c], &sc[0], n_eff / area, q, &im, &set, &tp[l * nc + c], &rts[l * nc + c], err,
                             sizeof err) != 0) {
                fprintf(stderr, "trk-sim mtt: %s (see trk-sim mtt --help)\n", err);
                return 2;
            }
        }
    /* ---- run: every (seed, level, configuration) on its own, in parallel */
    const long n_jobs = seeds * nl * nc;
    struct run_result *res = calloc((size_t)n_jobs, sizeof *res);
    if (!res) return 1;
    const int threads = sim_threads(&com);
    if (sonar)
        printf("== trk-sim mtt: family %s, %ld seeds (%llu..%llu) x %ld scans of %g s, sector %g-%g km +-%g deg "
               "(%.1f km^2), TRK_MAX_TRACKS %d, TRK_MAX_DETECTIONS %d, %d threads\n",
               mtt_family_name(family), seeds, (unsigned long long)com.seed,
               (unsigned long long)(com.seed + (uint64_t)seeds - 1), scans, sc[0].p.scan_period_s,
               sc[0].p.range_min_m / 1000, sc[0].p.range_max_m / 1000, sc[0].p.half_width_deg, area / 1e6,
               TRK_MAX_TRACKS, TRK_MAX_DETECTIONS, threads);
    else
        printf("== trk-sim mtt: family %s, %ld seeds (%llu..%llu) x %ld scans of %g s, region %g km x %g km, "
               "TRK_MAX_TRACKS %d, TRK_MAX_DETECTIONS %d, %d threads\n",
               mtt_family_name(family), seeds, (unsigned long long)com.seed,
               (unsigned long long)(com.seed + (uint64_t)seeds - 1), scans,
               sc[0].p.scan_period_s, sc[0].p.region_m / 1000, sc[0].p.region_m / 1000, TRK_MAX_TRACKS,
               TRK_MAX_DETECTIONS, threads);
    if (sonar) {
        const struct trk_pd_profile *pr = &sc[0].sonar.pd_profile;
        printf("   sonar family, 8 targets: %.2f present per scan (%d-%d); speeds %.1f-%.1f m/s (drawn in [%g, %g]); "
               "platform %g m/s due north\n",
               pres_sum / ((double)seeds * (double)scans), pres_min, pres_max, vmin, vmax, sc[0].p.speed_min_mps,
               sc[0].p.speed_max_mps, sc[0].p.platform_speed_mps);
        printf("   polar sensor: sigma %g m, %g deg; P_D %.2f at %g km to %.2f at %g km (profile of %u points), "
               "%.3f over the sector (cart's); %s\n",
               sc[0].p.sigma_range_m, sc[0].p.sigma_bearing_deg, (double)pr->pd[0], (double)pr->range_m[0] / 1000,
               (double)pr->pd[pr->n - 1], (double)pr->range_m[pr->n - 1] / 1000, pr->n, sc[0].sonar_pd_mean,
               no_amp ? "no amplitudes"
                      : "Rayleigh amplitudes at the P_D law's threshold (P_FA 0.01), the target's SNR its P_D's, "
                        "use_amplitude on (cart: one SNR, the mean P_D's)");
        printf("   clutter: 30 %% in 4 patches (3 %% of the area), 15 %% near-field, the rest uniform in range x "
               "bearing; persistent scatterers %s\n",
               no_persist ? "off" : "on (12, 85 % of pings)");
    } else if (family == MTT_FAMILY_FIXED)
        printf("   fixed family: 8 targets, alive the whole run but the birth (from ~20 %%) and the death "
               "(to ~70 %%), %.2f present per scan (%d-%d); speeds %.1f-%.1f m/s (drawn in [%g, %g]; %ld of %ld "
               "reduced to keep the path inside)\n",
               pres_sum / ((double)seeds * (double)scans), pres_min, pres_max, vmin, vmax, sc[0].p.speed_min_mps,
               sc[0].p.speed_max_mps, reduced, (long)n_tg_sum);
    else
        printf("   transit family, 8 slots: %.1f targets per run (%ld-%ld), %.2f present per scan (%d-%d); speeds "
               "%.1f-%.1f m/s (drawn in [%g, %g]%s)\n",
               n_tg_sum / (double)seeds, n_tg_min, n_tg_max, pres_sum / ((double)seeds * (double)scans), pres_min,
               pres_max, vmin, vmax, sc[0].p.speed_min_mps, sc[0].p.speed_max_mps,
               reduced ? "; the pair's reduced to keep 40 scans together" : "");
    if (!sonar)
        printf("   P_D %g, sigma %g m, %s, q %g; GOSPA c %g m\n", pd, sc[0].p.meas_sigma_m,
               no_amp ? "no amplitudes" : "Rayleigh amplitudes", q, c_m);
    else
        printf("   q %g; GOSPA c %g m\n", q, c_m);
    {
        /* the manoeuvres: the turn's length in scans over the seeds */
        long t_min = LONG_MAX, t_max = 0;
        for (long i = 0; i < seeds; i++) {
            const long nt = sc[i].turn_last_scan - sc[i].turn_first_scan + 1;
            t_min = nt < t_min ? nt : t_min;
            t_max = nt > t_max ? nt : t_max;
        }
        printf("   turn %g deg at %g deg/s x [0.8, 1.2]: %ld-%ld scans", turn_deg, turn_rate, t_min, t_max);
        if (accel > 0) printf("; the straight target accelerates at %g m/s^2 for %g s (+%g m/s)", accel, accel_s,
                              accel * accel_s);
        printf("\n");
    }
    for (int c = 0; c < n_cfg; c++)
        if (kinds[c] == CFG_IMM)
            printf("   imm: CV (q %g) and turns at +-%g deg/s (q %g), p_stay %g\n", q, im.rate_dps, im.turn_q,
                   im.p_stay);
    if (sc[0].p.amplitude && !sonar)
        printf("   amplitudes: target SNR %g dB, threshold P_FA %.4g (P_D = %.3f), use_amplitude on\n", snr_db,
               sc[0].pfa, sc[0].amp_tg.pd);
    printf("   clutter per scan:");
    for (int l = 0; l < nl; l++) printf(" %g", levels[l]);
    printf(over == OVER_THIN     ? " (a scan beyond TRK_MAX_DETECTIONS = %d is thinned by the tracker)\n"
           : over == OVER_REFUSE ? " (a scan beyond TRK_MAX_DETECTIONS = %d is refused, as before thinning)\n"
                                 : " (a scan holds at most TRK_MAX_DETECTIONS = %d: the clutter is cut to fit)\n",
           TRK_MAX_DETECTIONS);
    if (set.n) {
        printf("   settings for every configuration:");
        for (int i = 0; i < set.n; i++) printf(" %s", set.kv[i]);
        printf("\n");
    }
    fflush(stdout);
    /* every (seed, level, configuration) a work unit */
    struct mtt_units mu = {sc, levels, over, tp, kinds, c_m, nl, nc};
    double wall;
    const int urc = sim_run_units(&com, "mtt", (size_t)n_jobs, sizeof *res, 1, mtt_unit, mtt_ws_free, &mu, res, &wall,
                                  NULL);
    if (urc == 1) fprintf(stderr, "trk-sim mtt: a run failed (tracker refused a scan, or out of memory)\n");
    if (urc != 0) return 1;
    /* ---- reduce over seeds, in seed order */
    struct mtt_row *rows = calloc((size_t)(nl * nc), sizeof *rows);
    double *x = malloc((size_t)seeds * sizeof *x);
    if (!rows || !x) return 1;
    /* rows: configurations in --config order, clutter ascending */
    double lv_sorted[MAX_LEVELS];
    memcpy(lv_sorted, levels, sizeof lv_sorted);
    qsort(lv_sorted, (size_t)nl, sizeof *lv_sorted, cmp_double);
    int nr = 0;
    for (int c = 0; c < nc; c++)
        for (int ls = 0; ls < nl; ls++) {
            const int l = sorted_level(levels, lv_sorted, ls);
            if (l < 0) continue; /* a level given twice */
            struct mtt_row *r = &rows[nr++];
            r->capacity = TRK_MAX_TRACKS;
            snprintf(r->config, sizeof r->config, "%s", cfg_name[kinds[c]]);
            snprintf(r->family, sizeof r->family, "%s", mtt_family_name(family));
            r->clutter = levels[l];
            r->seeds = seeds;
            r->scans = scans;
            r->amplitude = sc[0].p.amplitude;
            for (int m = 0; m < M_N; m++) {
                size_t k = 0;
                for (long i = 0; i < seeds; i++) {
                    const double v = run_metric(res, nl, nc, i, l, c, m);
                    if (isfinite(v)) x[k++] = v;
                }
                mc_mean_ci_t(x, k, 0.95, &r->mean[m], &r->lo[m], &r->hi[m]);
            }
        }
    char path[1024];
    if (write_csv(&com, ".csv", rows, nr, path, sizeof path) != 0) return 1;
    print_tables(rows, nr);
    if (nc > 1) print_paired(res, seeds, lv_sorted, levels, nl, kinds, nc, base, sonar, mtt_family_name(family));
    char runs_path[1024];
    if (write_runs_csv(&com, res, seeds, levels, nl, kinds, nc, mtt_family_name(family), sonar, runs_path,
                       sizeof runs_path) != 0)
        return 1;
    char title[256];
    snprintf(title, sizeof title, "trk-sim mtt: %s family, %ld seeds x %ld scans, %d slots", mtt_family_name(family),
             seeds, scans, TRK_MAX_TRACKS);
    plot_all(&com, rows, nr, title);
    printf("-- %ld runs in %.1f s wall on %d threads; CSV %s%s; every run in %s\n", n_jobs, wall, threads, path,
           com.no_plot ? "" : " and PNG plots beside it", runs_path);
    if (family == MTT_FAMILY_SONAR && clutter_map_dump(&com, &sc[0], levels, nl, tp, kinds, nc) != 0) return 1;
    for (int k = 0; k < nl * nc; k++) tcfg_unload(&rts[k]);
    for (long i = 0; i < seeds; i++) mtt_scen_free(&sc[i]);
    free(rts);
    free(tp);
    free(sc);
    free(res);
    free(rows);
    free(x);
    return 0;
}

/* ---------------------------------------------------------------- mtt-compare */

struct compare_files {
    const char *path[MAX_FILES];
    int n;
};

static int take_file(const char *arg, void *ctx)
{
    struct compare_files *f = ctx;
    if (arg[0] == '-' || f->n >= MAX_FILES) return -1;
    f->path[f->n++] = arg;
    return 0;
}

/* Split a CSV line in place: up to max fields, returns the count. */
static int split(char *line, char **fld, int max)
{
    int n = 0;
    char *s = line;
    line[strcspn(line, "\r\n")] = 0;
    while (n < max) {
        fld[n++] = s;
        char *c = strchr(s, ',');
        if (!c) break;
        *c = 0;
        s = c + 1;
    }
    return n;
}

#define MAX_COLS (7 + 3 * M_N + 64)

/* Did fgets read a whole line (its '\n', or the file's last line)? A
 * longer line fills the buffer without one. */
static int whole_line(const char *line, FILE *f)
{
    const size_t n = strlen(line);
    if (n > 0 && line[n - 1] == '\n') return 1;
    const int c = getc(f);
    if (c == EOF) return 1;
    ungetc(c, f);
    return 0;
}

/* Rows of one mtt CSV appended to rows[*n]. 0, or -1 with a message. */
static int read_csv(const char *path, struct mtt_row *rows, int *n, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read", path);
        return -1;
    }
    static char line[65536], head[65536];
    char *h[MAX_COLS], *v[MAX_COLS];
    int col_m[MAX_COLS], col_part[MAX_COLS]; /* metric and 0 mean, 1 lo, 2 hi; -1 key */
    if (!fgets(head, sizeof head, f)) {
        fclose(f);
        snprintf(err, errlen, "%s: empty", path);
        return -1;
    }
    if (!whole_line(head, f)) {
        fclose(f);
        snprintf(err, errlen, "%s:1: line longer than %d characters", path, (int)sizeof head - 2);
        return -1;
    }
    const int nh = split(head, h, MAX_COLS);
    if (nh < 6 || strcmp(h[0], "capacity") != 0 || strcmp(h[1], "config") != 0 || strcmp(h[2], "clutter") != 0) {
        fclose(f);
        snprintf(err, errlen, "%s: not a trk-sim mtt CSV (header capacity,config,clutter,...)", path);
        return -1;
    }
    for (int j = 0; j < nh; j++) {
        col_m[j] = -1;
        col_part[j] = -1;
        static const char *const sfx[3] = {"_mean", "_lo", "_hi"};
        for (int p = 0; p < 3; p++) {
            const size_t lh = strlen(h[j]), ls = strlen(sfx[p]);
            if (lh > ls && strcmp(h[j] + lh - ls, sfx[p]) == 0) {
                char name[256];
                snprintf(name, sizeof name, "%.*s", (int)(lh - ls), h[j]);
                col_m[j] = metric_index(name);
                col_part[j] = p;
            }
        }
    }
    int lineno = 1;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (!whole_line(line, f)) { /* the rest must not be read as a line of its own */
            fclose(f);
            snprintf(err, errlen, "%s:%d: line longer than %d characters", path, lineno, (int)sizeof line - 2);
            return -1;
        }
        if (line[0] == '#' || line[0] == '\n') continue;
        if (*n >= MAX_ROWS) {
            fclose(f);
            snprintf(err, errlen, "%s: more than %d rows in all", path, MAX_ROWS);
            return -1;
        }
        const int nv = split(line, v, MAX_COLS);
        if (nv != nh) {
            fclose(f);
            snprintf(err, errlen, "%s:%d: %d fields, the header has %d", path, lineno, nv, nh);
            return -1;
        }
        struct mtt_row *r = &rows[*n];
        memset(r, 0, sizeof *r);
        for (int m = 0; m < M_N; m++) r->mean[m] = r->lo[m] = r->hi[m] = NAN;
        r->capacity = strtol(v[0], NULL, 10);
        snprintf(r->config, sizeof r->config, "%s", v[1]);
        r->clutter = strtod(v[2], NULL);
        snprintf(r->family, sizeof r->family, "unknown"); /* a CSV from before --family */
        for (int j = 3; j < nh; j++) {
            if (strcmp(h[j], "family") == 0) snprintf(r->family, sizeof r->family, "%s", v[j]);
            else if (strcmp(h[j], "seeds") == 0) r->seeds = strtol(v[j], NULL, 10);
            else if (strcmp(h[j], "scans") == 0) r->scans = strtol(v[j], NULL, 10);
            else if (strcmp(h[j], "amplitude") == 0) r->amplitude = (int)strtol(v[j], NULL, 10);
            else if (col_m[j] >= 0) {
                const double d = strtod(v[j], NULL);
                double *dst = col_part[j] == 0 ? r->mean : col_part[j] == 1 ? r->lo : r->hi;
                dst[col_m[j]] = d;
            }
        }
        ++*n;
    }
    fclose(f);
    return 0;
}

/* Rows by capacity, family, configuration, clutter. */
static int cmp_row(const void *a, const void *b)
{
    const struct mtt_row *x = a, *y = b;
    if (x->capacity != y->capacity) return x->capacity < y->capacity ? -1 : 1;
    const int f = strcmp(x->family, y->family);
    if (f) return f;
    const int c = strcmp(x->config, y->config);
    if (c) return c; /* "new" before "old" */
    return x->clutter < y->clutter ? -1 : x->clutter > y->clutter;
}

/* The same (family, configuration, clutter): rows a ratio may pair. */
static int same_cell(const struct mtt_row *x, const struct mtt_row *y)
{
    return strcmp(x->family, y->family) == 0 && strcmp(x->config, y->config) == 0 && x->clutter == y->clutter;
}

/* The same (family, configuration): one line of the ratio table. */
static int same_group(const struct mtt_row *x, const struct mtt_row *y)
{
    return strcmp(x->family, y->family) == 0 && strcmp(x->config, y->config) == 0;
}

SIM_EXPERIMENT(mtt_compare, "mtt-compare", "merge trk-sim mtt CSVs of builds with other TRK_MAX_TRACKS, ratios")
{
    struct compare_files files = {{NULL}, 0};
    const struct sim_opt opts[] = {SIM_OPT_END};
    const struct sim_cli cli = {
        "mtt-compare", "A.csv B.csv ... [--out PREFIX]",
        "Merges the PREFIX.csv files of `trk-sim mtt` run by builds with different\n"
        "TRK_MAX_TRACKS (e.g. 64 and 1024, `make mtt`) into one table and one set of plots,\n"
        "and prints per metric, family, configuration and clutter count the ratio of the\n"
        "smallest capacity's mean to the largest's, marked when it is outside the largest\n"
        "build's 95 % interval. Rows are keyed by (capacity, family, config, clutter): files\n"
        "of both families may be merged, a ratio pairs rows of one family (a CSV without\n"
        "the family column, written before --family, counts as family \"unknown\").",
        opts, "build/results/mtt", NULL, SIM_UNUSED_RUNS | SIM_UNUSED_THREADS,
        "Writes PREFIX.csv (the merged rows, the columns of trk-sim mtt), PREFIX_ratio.csv\n"
        "(family, config, clutter, metric, the two means, the large build's interval,\n"
        "ratio, within) and the plots of trk-sim mtt with one line per (capacity, config,\n"
        "family).\n",
        take_file, &files};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (files.n < 1) {
        fprintf(stderr, "trk-sim mtt-compare: give the CSV files of trk-sim mtt runs\n");
        return 2;
    }
    if (make_parent(com.out) != 0) {
        fprintf(stderr, "trk-sim mtt-compare: cannot create the directory of %s\n", com.out);
        return 1;
    }
    struct mtt_row *rows = malloc(MAX_ROWS * sizeof *rows);
    if (!rows) return 1;
    int n = 0;
    char err[1200];
    for (int i = 0; i < files.n; i++)
        if (read_csv(files.path[i], rows, &n, err, sizeof err) != 0) {
            fprintf(stderr, "trk-sim mtt-compare: %s\n", err);
            free(rows);
            return 2;
        }
    qsort(rows, (size_t)n, sizeof *rows, cmp_row);
    for (int i = 1; i < n; i++)
        if (rows[i].capacity == rows[i - 1].capacity && same_cell(&rows[i], &rows[i - 1])) {
            fprintf(stderr, "trk-sim mtt-compare: (%ld slots, family %s, %s, clutter %g) appears twice\n",
                    rows[i].capacity, rows[i].family, rows[i].config, rows[i].clutter);
            free(rows);
            return 2;
        }
    if (n == 0) {
        fprintf(stderr, "trk-sim mtt-compare: no rows\n");
        free(rows);
        return 2;
    }
    const long small = rows[0].capacity, large = rows[n - 1].capacity;
    char path[1024];
    if (write_csv(&com, ".csv", rows, n, path, sizeof path) != 0) {
        free(rows);
        return 1;
    }
    printf("== trk-sim mtt-compare: %d files, %d rows, capacities %ld .. %ld\n", files.n, n, small, large);
    {
        /* the families present (rows are sorted by capacity first: look at all) */
        char fams[256] = "";
        int nf = 0;
        for (int i = 0; i < n; i++) {
            int seen = 0;
            for (int j = 0; j < i && !seen; j++) seen = strcmp(rows[j].family, rows[i].family) == 0;
            if (seen) continue;
            const size_t len = strlen(fams);
            snprintf(fams + len, sizeof fams - len, "%s%s", nf ? ", " : "", rows[i].family);
            nf++;
        }
        printf("   famil%s %s%s\n", nf > 1 ? "ies" : "y", fams,
               nf > 1 ? " (kept apart: a ratio pairs rows of one family)" : "");
    }
    for (int i = 1; i < n; i++)
        if (rows[i].scans != rows[0].scans || rows[i].seeds != rows[0].seeds ||
            rows[i].amplitude != rows[0].amplitude) {
            printf("   NOTE: the files differ in scans, seeds or amplitudes: not the same runs\n");
            break;
        }
    print_tables(rows, n);
    char title[256];
    int one_family = 1;
    for (int i = 1; i < n; i++) one_family &= strcmp(rows[i].family, rows[0].family) == 0;
    snprintf(title, sizeof title, "trk-sim mtt: %s%s%ld seeds x %ld scans, %ld vs %ld slots",
             one_family ? rows[0].family : "", one_family ? " family, " : "", rows[0].seeds, rows[0].scans, small,
             large);
    plot_all(&com, rows, n, title);
    if (small == large) {
        printf("-- one capacity only: no ratios. CSV %s\n", path);
        free(rows);
        return 0;
    }
    /* ---- ratios small / large per (config, clutter) and metric */
    struct fileio_out fr_out;
    FILE *fr = sim_csv_open(&com, &fr_out, "_ratio.csv", NULL, 0,
                            "family,config,clutter,metric,small_capacity,large_capacity,small_mean,large_mean,"
                            "large_lo,large_hi,ratio,within");
    if (!fr) {
        free(rows);
        return 1;
    }
    int pair_s[MAX_ROWS], pair_l[MAX_ROWS], np = 0;
    for (int i = 0; i < n; i++) {
        if (rows[i].capacity != small) continue;
        for (int j = 0; j < n; j++)
            if (rows[j].capacity == large && same_cell(&rows[j], &rows[i])) {
                pair_s[np] = i;
                pair_l[np] = j;
                np++;
            }
    }
    printf("-- %ld slots / %ld slots: ratio of the means; '*' = the %ld-slot mean is outside the %ld-slot 95%% "
           "interval ('-': undefined)\n",
           small, large, small, large);
    printf("%-30s %-7s %-6s", "metric", "family", "cfg");
    for (int k = 0; k < np && same_group(&rows[pair_s[k]], &rows[pair_s[0]]); k++)
        printf(" %8g", rows[pair_s[k]].clutter);
    printf("   within\n");
    for (int m = 0; m < M_N; m++) {
        for (int k0 = 0; k0 < np;) {
            int k1 = k0;
            while (k1 < np && same_group(&rows[pair_s[k1]], &rows[pair_s[k0]])) k1++;
            printf("%-30s %-7s %-6s", metric_name[m], rows[pair_s[k0]].family, rows[pair_s[k0]].config);
            int within_n = 0, defined = 0;
            for (int k = k0; k < k1; k++) {
                const struct mtt_row *a = &rows[pair_s[k]], *b = &rows[pair_l[k]];
                const double sm = a->mean[m], lm = b->mean[m];
                const double ratio = lm != 0 ? sm / lm : sm == 0 ? 1 : INFINITY;
                const int ok = !isnan(sm) && !isnan(lm);
                const int within = ok && sm >= b->lo[m] && sm <= b->hi[m];
                fprintf(fr, "%s,%s,%g,%s,%ld,%ld,%.6g,%.6g,%.6g,%.6g,%.6g,%d\n", a->family, a->config, a->clutter,
                        metric_name[m], small, large, sm, lm, b->lo[m], b->hi[m], ok ? ratio : NAN, within);
                if (!ok) {
                    printf(" %8s", "-");
                    continue;
                }
                defined++;
                within_n += within;
                char b8[32];
                snprintf(b8, sizeof b8, "%.3f%s", ratio, within ? " " : "*");
                printf(" %8s", b8);
            }
            printf("   %d/%d\n", within_n, defined);
            k0 = k1;
        }
    }
    if (sim_csv_close(&fr_out) != 0) {
        free(rows);
        return 1;
    }
    printf("-- CSV %s, %s_ratio.csv%s\n", path, com.out, com.no_plot ? "" : "; PNG plots beside them");
    free(rows);
    return 0;
}
