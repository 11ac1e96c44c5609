/* bench_pda.c - PDA track update and whole-scan benchmarks:
 *   pda_update_m<m>   ns per predict + gate + PDA update of one track with m
 *                     detections in its gate (public API: trk_cv2_predict +
 *                     trk_pda_update), alternating in the same run with
 *                     pda_update_m<m>_baseline, the hand-written loop of
 *                     baseline_pda.c, and their ratio pda_update_m<m>_vs_baseline;
 *                     and pda_update_m<m>_baseline_o2 / _vs_baseline_o2
 *                     the same loop compiled at -O2 -funroll-loops
 *                     (baseline_pda_o2.c: gcc 12's -O3 slows the float loop);
 *                     pda_update_m<m>_baseline_rel_diff is the largest
 *                     difference of the two posteriors (x, P) relative to
 *                     the largest |value|: the same arithmetic
 *   scan_64x256       ns per trk_tracker_process_scan with 64 confirmed tracks
 *                     and 256 detections (64 targets + 192 clutter), the
 *                     default configuration (two-point initiation, existence,
 *                     joint association); scan_64x256_pda the same with the
 *                     per-track PDA, alternating with it in the same run, and
 *                     the ratio scan_64x256_vs_scan_64x256_pda
 *   scan_64x256_mn_kn the same scans with trk_tracker_mn_kn_params (M/N 2/3
 *                     here, single-point initiation): the old default path,
 *                     for the ratio in the same run
 *   scan_64x256_imm   (TRK_WITH_IMM builds) scan_64x256_cv, the default scans
 *                     of this build, against scan_64x256_imm3, every track an
 *                     IMM track of three models, same run, and their ratio
 *   scan_64x256_own   scan_64x256_shared against scan_64x256_own_cov, the same
 *                     detections each with its own covariance (a sonar's
 *                     polar conversion), same run, and their ratio
 *   scan_64x256_ab    (TRK_WITH_ALPHA_BETA builds) scan_64x256_kalman against
 *                     scan_64x256_alpha_beta, every track on the constant-gain
 *                     filter, same run, and their ratio
 *   scan_64x1024      a scan of 4 x capacity: the scans of scan_64x256 with
 *                     768 more clutter detections over the area (960, the
 *                     sensor's density to match), thinned to the build's 256
 *                     (trk/tracker.h "Scans beyond capacity"), alternating
 *                     with scan_64x256 in the same run; the ratio
 *                     scan_64x1024_vs_scan_64x256
 *   scan_64x1024_polar  the scans of scan_64x1024 (1024 detections) as a polar
 *                     sensor's (range and bearing from a sonar 2 km west,
 *                     sigma_r 1 m, sigma_b 0.5 mrad: converted and gated with
 *                     their own covariances by the tracker) against the same
 *                     positions as Cartesian detections of one shared
 *                     covariance, same run, and their ratio
 *   scan_64x1024_map  the polar scans with a coverage (0.5-4.5 km, all
 *                     round) and the default clutter map (16 x 32 cells over
 *                     it) against the same without a map, same run, and
 *                     their ratio
 *   candidates_full   ns per scan of the initiation stage at full scan capacity
 *                     (TRK_MAX_DETECTIONS unexplained detections) and the store's bytes
 *   sizeof_tracker    bytes of struct trk_tracker at this build's capacities */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "baseline.h"
#include "bench.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "trk/tracker.h"

static uint64_t rs = 42;
static double urand(void) { return bench_urand(&rs); }

struct pda_job {
    struct trk_pda pda;
    struct baseline_pda base;
    trk_real x0[4], p0[16], x[4], p[16];
    size_t m;
    trk_real z[2 * 128], beta[128];
};

static void pda_once(void *arg)
{
    struct pda_job *j = arg;
    memcpy(j->x, j->x0, sizeof j->x);
    memcpy(j->p, j->p0, sizeof j->p);
    trk_status st = trk_cv2_predict(1, TRK_REAL_C(0.05), j->x, j->p);
    st |= trk_pda_update(&j->pda, 4, trk_cv2_h, j->base.r, j->x, j->p, j->m, j->z, NULL, j->beta, NULL, NULL);
    bench_sink((double)j->x[TRK_CV2_X] + (double)st);
}

typedef void baseline_fn(const struct baseline_pda *b, trk_real x[4], trk_real p[16], size_t m,
                         const trk_real *z, trk_real *beta);

/* one baseline update from the job's prior */
static void baseline_run(struct pda_job *j, baseline_fn *fn)
{
    memcpy(j->x, j->x0, sizeof j->x);
    memcpy(j->p, j->p0, sizeof j->p);
    fn(&j->base, j->x, j->p, j->m, j->z, j->beta);
    bench_sink((double)j->x[TRK_CV2_X]);
}

static void baseline_once(void *arg) { baseline_run(arg, baseline_pda_cv2); }
static void baseline_o2_once(void *arg) { baseline_run(arg, baseline_pda_cv2_o2); }

/* max |a - b| over x and P relative to max |a| */
static double rel_diff(void (*one)(void *), void (*two)(void *), struct pda_job *j)
{
    trk_real a[20];
    one(j);
    memcpy(a, j->x, sizeof j->x);
    memcpy(a + 4, j->p, sizeof j->p);
    two(j);
    double dmax = 0, amax = 0;
    trk_real b2[20];
    memcpy(b2, j->x, sizeof j->x);
    memcpy(b2 + 4, j->p, sizeof j->p);
    for (int i = 0; i < 20; i++) {
        const double b = (double)b2[i];
        if (fabs((double)a[i] - b) > dmax) dmax = fabs((double)a[i] - b);
        if (fabs((double)a[i]) > amax) amax = fabs((double)a[i]);
    }
    return dmax / amax;
}

/* name, name_baseline, name_vs_baseline: fn and base alternating, 5 times
 * each, the fastest of each; base_o2 (not NULL) the same loop at -O2, with
 * name_baseline_o2 and name_vs_baseline_o2 */
static void time_vs_baseline(const char *name, void (*fn)(void *), void (*base)(void *), void (*base_o2)(void *),
                             void *arg)
{
    double t_fn = 1e300, t_base = 1e300, t_o2 = 1e300;
    for (int rep = 0; rep < 5; rep++) {
        const double a = bench_time_ns(fn, arg, 3), b = bench_time_ns(base, arg, 3);
        const double c = base_o2 ? bench_time_ns(base_o2, arg, 3) : 1e300;
        if (a < t_fn) t_fn = a;
        if (b < t_base) t_base = b;
        if (c < t_o2) t_o2 = c;
    }
    char what[96];
    bench_print(name, t_fn, "ns");
    snprintf(what, sizeof what, "%s_baseline", name);
    bench_print(what, t_base, "ns");
    snprintf(what, sizeof what, "%s_vs_baseline", name);
    bench_print(what, t_fn / t_base, "x");
    if (!base_o2) return;
    snprintf(what, sizeof what, "%s_baseline_o2", name);
    bench_print(what, t_o2, "ns");
    snprintf(what, sizeof what, "%s_vs_baseline_o2", name);
    bench_print(what, t_fn / t_o2, "x");
}

TRK_BENCH(pda_update)
{
    static struct pda_job j;
    struct trk_pda_params pp = {2, TRK_REAL_C(0.9), TRK_REAL_C(0.99), TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(1e-3), 1};
    if (trk_pda_init(&j.pda, &pp) != TRK_OK) return;
    j.base = (struct baseline_pda){1, TRK_REAL_C(0.05), {4, 0, 0, 4}, pp.pd, pp.gate_prob, pp.clutter_density,
                                   j.pda.gamma};
    const trk_real x0[4] = {1000, 2, -500, 1}; /* [x, vx, y, vy] */
    memcpy(j.x0, x0, sizeof x0);
    memset(j.p0, 0, sizeof j.p0);
    static const int pos[2] = {TRK_CV2_X, TRK_CV2_Y}, vel[2] = {TRK_CV2_VX, TRK_CV2_VY};
    for (int a = 0; a < 2; a++) {
        j.p0[TRK_CV2_P(pos[a], pos[a])] = 5;
        j.p0[TRK_CV2_P(vel[a], vel[a])] = 1;
        j.p0[TRK_CV2_P(pos[a], vel[a])] = j.p0[TRK_CV2_P(vel[a], pos[a])] = TRK_REAL_C(0.5);
    }
    /* detections inside the gate (d2 < 4 < gamma = 9.2) around the prediction */
    const size_t ms[] = {0, 1, 10, 100};
    for (size_t k = 0; k < 4; k++) {
        j.m = ms[k];
        for (size_t i = 0; i < j.m; i++) {
            double ang = 6.283185307179586 * urand(), rad = 2.0 * urand();
            j.z[2 * i] = (trk_real)(1002 + rad * 3 * cos(ang));
            j.z[2 * i + 1] = (trk_real)(-499 + rad * 3 * sin(ang));
        }
        char name[64], what[96];
        snprintf(name, sizeof name, "pda_update_m%zu", j.m);
        time_vs_baseline(name, pda_once, baseline_once, baseline_o2_once, &j);
        snprintf(what, sizeof what, "%s_baseline_rel_diff", name);
        bench_print(what, rel_diff(pda_once, baseline_once, &j), "-");
    }
}

/* 64 targets on a 150 m grid moving at 1-3 m/s, pd 1 for the benchmark's
 * steady state, 192 uniform clutter detections over the area. */
#define N_SCANS 64
#define N_TGT 64
#define N_DET 256
#define N_DET_OVER (4 * N_DET) /* scan_64x1024 */

struct scan_job {
    struct trk_tracker tk;
    struct trk_detection det[N_SCANS][N_DET_OVER]; /* the first N_DET: scan_64x256's */
    struct trk_detection det_own[N_SCANS][N_DET];  /* the same with their own covariances */
    struct trk_polar_detection polar[N_SCANS][N_DET_OVER]; /* det as the polar sensor sees them */
    struct trk_scan scan[N_SCANS];
    struct trk_scan_report rep;
    double n_updated; /* track updates in the timed scans (all repetitions) */
};

/* The scans' configurations: the defaults (joint association), the same
 * with the per-track PDA, and the M/N path. */
enum scan_cfg {
    SCAN_DEFAULT, SCAN_PDA, SCAN_MN_KN, SCAN_IMM, SCAN_OVER, SCAN_AB, SCAN_OWN, SCAN_POLAR,
    SCAN_POLAR_COV, /* the polar scans with a coverage (0.5-4.5 km, all round), no clutter map */
    SCAN_POLAR_MAP  /* ... and the default clutter map over it */
};

/* Detections per scan of a configuration. */
static int scan_polar(enum scan_cfg cfg) { return cfg == SCAN_POLAR || cfg == SCAN_POLAR_COV || cfg == SCAN_POLAR_MAP; }

static size_t scan_n_det(enum scan_cfg cfg) { return cfg == SCAN_OVER || scan_polar(cfg) ? N_DET_OVER : N_DET; }

/* The polar sensor of scan_64x1024_polar: 2 km west of the area. */
#define POLAR_X_M (-2000.0)
#define POLAR_Y_M 500.0

static void scan_params(enum scan_cfg cfg, struct trk_tracker_params *p)
{
    if (cfg == SCAN_MN_KN) {
        trk_tracker_mn_kn_params(p);
        p->confirm.u.mn.m = 2;
        p->confirm.u.mn.n = 3;
    } else {
        trk_tracker_default_params(p);
    }
    if (cfg == SCAN_PDA) p->association = TRK_ASSOC_PDA;
    if (cfg == SCAN_AB) p->filter = TRK_FILTER_ALPHA_BETA;
    if (scan_polar(cfg)) {
        p->sensor[0].kind = TRK_SENSOR_POLAR;
        p->sensor[0].sigma_range_m = 1;
        p->sensor[0].sigma_bearing_rad = TRK_REAL_C(0.0005);
        p->sensor[0].pose.x_m = (trk_real)POLAR_X_M;
        p->sensor[0].pose.y_m = (trk_real)POLAR_Y_M;
    }
    if (cfg == SCAN_POLAR_COV || cfg == SCAN_POLAR_MAP) {
        p->sensor[0].coverage.min_range_m = 500;
        p->sensor[0].coverage.max_range_m = 4500;
    }
    if (cfg != SCAN_POLAR_MAP) p->clutter_map.n_range = p->clutter_map.n_bearing = 0;
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].clutter_density_per_m2 = (trk_real)((double)(scan_n_det(cfg) - N_TGT) / (1200.0 * 1200.0));
    p->process_noise_q = TRK_REAL_C(0.01);
#if TRK_WITH_IMM
    if (cfg == SCAN_IMM && trk_tracker_imm_params(p, TRK_REAL_C(0.035), TRK_REAL_C(0.95)) != TRK_OK) /* turns at 2 deg/s */
        p->imm.n_models = 0;                                                                        /* (TRK_MAX_MODELS < 3) */
#endif
}

static struct scan_job *scan_job_new(void)
{
    struct scan_job *j = calloc(1, sizeof *j);
    if (!j) return NULL;
    rs = 42;
    double tx[N_TGT], ty[N_TGT], vx[N_TGT], vy[N_TGT];
    for (int i = 0; i < N_TGT; i++) {
        tx[i] = 150.0 * (i % 8);
        ty[i] = 150.0 * (i / 8);
        vx[i] = 1 + 2 * urand();
        vy[i] = 1 + 2 * urand();
    }
    for (int k = 0; k < N_SCANS; k++) {
        for (int i = 0; i < N_DET; i++) {
            struct trk_detection *d = &j->det[k][i];
            memset(d, 0, sizeof *d);
            if (i < N_TGT) {
                d->x_m = (trk_real)(tx[i] + vx[i] * k + (urand() - 0.5) * 2);
                d->y_m = (trk_real)(ty[i] + vy[i] * k + (urand() - 0.5) * 2);
            } else {
                d->x_m = (trk_real)(-100 + 1200 * urand() + k);
                d->y_m = (trk_real)(-100 + 1200 * urand() + k);
            }
        }
        j->scan[k].sensor_id = 0;
        j->scan[k].n_detections = N_DET;
        j->scan[k].detections = j->det[k];
    }
    for (int k = 0; k < N_SCANS; k++) /* scan_64x256_own: the same detections as a sonar 2 km */
        for (int i = 0; i < N_DET; i++) {  /* west of the area reports them, each with its covariance */
            const struct trk_detection *d = &j->det[k][i];
            const double ex = d->x_m + 2000, ey = d->y_m - 500;
            struct trk_detection *o = &j->det_own[k][i];
            if (trk_detection_from_polar((trk_real)hypot(ex, ey), (trk_real)atan2(ex, ey), TRK_REAL_C(1.0),
                                         TRK_REAL_C(0.0005), -2000, 500, o) != TRK_OK)
                memset(o, 0, sizeof *o);
            o->x_m = d->x_m; /* the same positions: only the covariances differ */
            o->y_m = d->y_m;
        }
    for (int k = 0; k < N_SCANS; k++) /* scan_64x1024's extra clutter, after: the rest unchanged */
        for (int i = N_DET; i < N_DET_OVER; i++) {
            struct trk_detection *d = &j->det[k][i];
            memset(d, 0, sizeof *d);
            d->x_m = (trk_real)(-100 + 1200 * urand() + k);
            d->y_m = (trk_real)(-100 + 1200 * urand() + k);
        }
    for (int k = 0; k < N_SCANS; k++) /* scan_64x1024_polar: range, bearing from the sensor */
        for (int i = 0; i < N_DET_OVER; i++) {
            const double ex = j->det[k][i].x_m - POLAR_X_M, ey = j->det[k][i].y_m - POLAR_Y_M;
            j->polar[k][i].range_m = (trk_real)hypot(ex, ey);
            j->polar[k][i].bearing_rad = (trk_real)atan2(ex, ey);
        }
    return j;
}

/* One repetition: init, warm up (targets first, so all 64 tracks exist),
 * then the timed full scans; ns per scan, or -1. *n_conf: confirmed tracks
 * at the end. */
static double scan_rep(struct scan_job *j, const struct trk_tracker_params *p, size_t n_det, enum scan_cfg cfg,
                       int *n_conf)
{
    if (trk_tracker_init(&j->tk, p) != TRK_OK) return -1;
    for (int k = 0; k < N_SCANS; k++) {
        j->scan[k].detections = scan_polar(cfg) ? NULL : cfg == SCAN_OWN ? j->det_own[k] : j->det[k];
        j->scan[k].polar = scan_polar(cfg) ? j->polar[k] : NULL;
    }
    for (int k = 0; k < 4; k++) {
        j->scan[k].time_us = (int64_t)k * 1000000;
        j->scan[k].n_detections = N_TGT;
        const trk_status st = trk_tracker_process_scan(&j->tk, &j->scan[k], NULL);
        j->scan[k].n_detections = N_DET;
        if (st != TRK_OK) return -1;
    }
    double t0 = bench_now_ns();
    for (int k = 4; k < N_SCANS; k++) {
        j->scan[k].time_us = (int64_t)k * 1000000;
        j->scan[k].n_detections = n_det;
        if (trk_tracker_process_scan(&j->tk, &j->scan[k], &j->rep) != TRK_OK) return -1;
        j->n_updated += j->rep.n_tracks_updated;
    }
    const double per = (bench_now_ns() - t0) / (N_SCANS - 4);
    *n_conf = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *t = trk_tracker_track(&j->tk, s);
        *n_conf += t && t->status == TRK_TRACK_CONFIRMED;
    }
    return per;
}

/* The configurations cfg[0..n) alternating, 5 repetitions each: the
 * fastest of each (printed as names[c]), and cfg[c] / cfg[0] ratios. */
static void scan_bench(const char *const *names, const enum scan_cfg *cfg, int n)
{
    if (TRK_MAX_TRACKS < N_TGT || TRK_MAX_DETECTIONS < N_DET) {
        bench_print("scan_64x256_skipped_capacity", 0, "-");
        return;
    }
    struct scan_job *j = scan_job_new();
    if (!j) return;
    double best[3] = {1e300, 1e300, 1e300}, updated[3] = {0, 0, 0};
    int n_conf[3] = {0, 0, 0};
    for (int rep = 0; rep < 5; rep++)
        for (int c = 0; c < n; c++) {
            struct trk_tracker_params p;
            scan_params(cfg[c], &p);
            j->n_updated = 0;
            const double per = scan_rep(j, &p, scan_n_det(cfg[c]), cfg[c], &n_conf[c]);
            if (per >= 0 && per < best[c]) best[c] = per;
            updated[c] += j->n_updated;
        }
    for (int c = 0; c < n; c++) {
        char what[96];
        bench_print(names[c], best[c], "ns");
        snprintf(what, sizeof what, "%s_confirmed_tracks", names[c]);
        bench_print(what, n_conf[c], "tracks");
        snprintf(what, sizeof what, "%s_tracks_per_scan", names[c]);
        bench_print(what, updated[c] / (5.0 * (N_SCANS - 4)), "tracks");
        if (c > 0) {
            snprintf(what, sizeof what, "%s_vs_%s", names[0], names[c]);
            bench_print(what, best[0] / best[c], "x");
        }
    }
    free(j);
}

/* The default (joint association) against the per-track PDA, same run. */
TRK_BENCH(scan_64x256)
{
    static const char *const names[] = {"scan_64x256", "scan_64x256_pda"};
    static const enum scan_cfg cfg[] = {SCAN_DEFAULT, SCAN_PDA};
    scan_bench(names, cfg, 2);
}

/* The instruction count of one scan_64x256 (a figure that does
 * not depend on the machine's load): the default configuration's timed
 * scans once, with callgrind's instrumentation on for them alone (make
 * bench-instr runs this under valgrind --instr-atstart=no and divides its
 * count by the scans printed here; without valgrind the macros do
 * nothing). */
TRK_BENCH(scan_64x256_instr)
{
    if (TRK_MAX_TRACKS < N_TGT || TRK_MAX_DETECTIONS < N_DET) {
        bench_print("scan_64x256_instr_skipped_capacity", 0, "-");
        return;
    }
    struct scan_job *j = scan_job_new();
    struct trk_tracker_params p;
    if (!j) return;
    scan_params(SCAN_DEFAULT, &p);
    int ok = trk_tracker_init(&j->tk, &p) == TRK_OK;
    for (int k = 0; ok && k < 4; k++) {
        j->scan[k].time_us = (int64_t)k * 1000000;
        j->scan[k].n_detections = N_TGT;
        ok = trk_tracker_process_scan(&j->tk, &j->scan[k], NULL) == TRK_OK;
        j->scan[k].n_detections = N_DET;
    }
    BENCH_INSTR_START();
    for (int k = 4; ok && k < N_SCANS; k++) {
        j->scan[k].time_us = (int64_t)k * 1000000;
        ok = trk_tracker_process_scan(&j->tk, &j->scan[k], &j->rep) == TRK_OK;
    }
    BENCH_INSTR_STOP();
    if (ok) bench_print("scan_64x256_instr_scans", N_SCANS - 4, "scans");
    free(j);
}

/* A scan of 4 x capacity against scan_64x256, same run. */
TRK_BENCH(scan_64x1024)
{
    static const char *const names[] = {"scan_64x256", "scan_64x1024"};
    static const enum scan_cfg cfg[] = {SCAN_DEFAULT, SCAN_OVER};
    scan_bench(names, cfg, 2);
}

TRK_BENCH(scan_64x256_mn_kn)
{
    static const char *const names[] = {"scan_64x256_mn_kn"};
    static const enum scan_cfg cfg[] = {SCAN_MN_KN};
    scan_bench(names, cfg, 1);
}

/* The IMM budget: the same scans with every track an IMM track of
 * three models (CV and turns at +-2 deg/s, joint association) against the
 * CV tracks of the same build, alternating in the same run; the per-track
 * update is the scan over the tracks updated per scan (initiation and the
 * joint solve included in both). A build without TRK_WITH_IMM says so. */
TRK_BENCH(scan_64x256_imm)
{
#if TRK_WITH_IMM
    static const char *const names[] = {"scan_64x256_cv", "scan_64x256_imm3"};
    static const enum scan_cfg cfg[] = {SCAN_DEFAULT, SCAN_IMM};
    scan_bench(names, cfg, 2);
#else
    bench_print("scan_64x256_imm_skipped_no_imm", 0, "-");
#endif
}

/* Gating with the detections' own covariances: the same scans, every
 * detection with its own covariance (a sonar 2 km west, sigma_r 1 m,
 * sigma_b 0.5 mrad: 1-1.7 m across, as the shared R of 1 m^2), against the
 * shared-covariance scans, alternating in the same run. */
TRK_BENCH(scan_64x256_own)
{
    static const char *const names[] = {"scan_64x256_shared", "scan_64x256_own_cov"};
    static const enum scan_cfg cfg[] = {SCAN_DEFAULT, SCAN_OWN};
    scan_bench(names, cfg, 2);
}

/* A polar sensor's 1024 detections per scan against the same positions
 * with one shared covariance, alternating in the same run. */
TRK_BENCH(scan_64x1024_polar)
{
    static const char *const names[] = {"scan_64x1024", "scan_64x1024_polar"};
    static const enum scan_cfg cfg[] = {SCAN_OVER, SCAN_POLAR};
    scan_bench(names, cfg, 2);
}

/* The clutter map's cost: the polar scans of 1024 detections with a
 * coverage, with the default map (16 x 32 cells over it) and without,
 * alternating in the same run. */
TRK_BENCH(scan_64x1024_map)
{
    static const char *const names[] = {"scan_64x1024_polar_nomap", "scan_64x1024_polar_map"};
    static const enum scan_cfg cfg[] = {SCAN_POLAR_COV, SCAN_POLAR_MAP};
    scan_bench(names, cfg, 2);
}

/* The alpha-beta track filter: the same scans with every track on constant
 * gains against the CV Kalman tracks of the same build, alternating in the
 * same run. A build without TRK_WITH_ALPHA_BETA says so. */
TRK_BENCH(scan_64x256_ab)
{
#if TRK_WITH_ALPHA_BETA
    static const char *const names[] = {"scan_64x256_kalman", "scan_64x256_alpha_beta"};
    static const enum scan_cfg cfg[] = {SCAN_DEFAULT, SCAN_AB};
    scan_bench(names, cfg, 2);
#else
    bench_print("scan_64x256_ab_skipped_no_alpha_beta", 0, "-");
#endif
}

TRK_BENCH(sizeof_tracker) { bench_print("sizeof_tracker", (double)sizeof(struct trk_tracker), "bytes"); }

/* The candidate store at full scan capacity: a tracker without tracks fed
 * TRK_MAX_DETECTIONS uniform clutter detections per scan over 30 km x 30 km
 * (pairs are rare: every detection is looked up in the store and becomes a
 * candidate), so the scan's time is the initiation stage's: expiry, one
 * binary search and window per detection, the sort and the merge. */
TRK_BENCH(candidates_full)
{
    enum { N_SC = 32 };
    struct cand_job {
        struct trk_tracker tk;
        struct trk_detection det[N_SC][TRK_MAX_DETECTIONS];
    } *j = calloc(1, sizeof *j);
    if (!j) return;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.sensor[0].clutter_density_per_m2 = (trk_real)(TRK_MAX_DETECTIONS / 9e8);
    rs = 7;
    for (int k = 0; k < N_SC; k++)
        for (int i = 0; i < TRK_MAX_DETECTIONS; i++) {
            j->det[k][i].x_m = (trk_real)(30000 * urand());
            j->det[k][i].y_m = (trk_real)(30000 * urand());
        }
    double best = 1e300;
    uint32_t n_cand = 0, n_started = 0;
    for (int rep = 0; rep < 5; rep++) {
        if (trk_tracker_init(&j->tk, &p) != TRK_OK) break;
        struct trk_scan_report r;
        const struct trk_scan first = {0, 0, TRK_MAX_DETECTIONS, j->det[0], NULL, 0, {0, 0, 0}, NULL};
        if (trk_tracker_process_scan(&j->tk, &first, &r) != TRK_OK) break;
        double t0 = bench_now_ns();
        for (int k = 1; k < N_SC; k++) {
            const struct trk_scan scan = {(int64_t)k * 4000000, 0, TRK_MAX_DETECTIONS, j->det[k], NULL, 0, {0, 0, 0}, NULL};
            if (trk_tracker_process_scan(&j->tk, &scan, &r) != TRK_OK) break;
            n_cand = r.n_candidates;
            n_started += r.n_started;
        }
        const double per = (bench_now_ns() - t0) / (N_SC - 1);
        if (per < best) best = per;
    }
    bench_print("candidates_full_scan", best, "ns");
    bench_print("candidates_full_held", n_cand, "candidates");
    bench_print("candidates_full_started_per_scan", n_started / (5.0 * (N_SC - 1)), "tracks");
    bench_print("candidates_store_bytes", (double)sizeof j->tk.cand, "bytes");
    free(j);
}
