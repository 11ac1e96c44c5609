/* bench_worst.c - the scan's worst case: adversarial geometries, each a
 * whole trk_tracker_process_scan (the fastest of N_REPS from a copy of the
 * same table), printed against the typical scan measured in the same run
 * (64 confirmed tracks on a 150 m grid, one detection each, 192 clutter
 * detections over 1200 m x 1200 m: scan_64x256's load):
 *   worst_typical_256             the typical scan, ns
 *   worst_cluster<k>_<d>          k tracks at one point (the other 64 - k
 *                                 far away, undetected) sharing d detections
 *                                 within 1 m: k = 2, 3, 4, 8, 16, 64
 *   worst_chain_<d>               64 tracks 5 m apart on a line, d detections
 *                                 along it (each in one or two gates)
 *   worst_lattice_<d>             64 tracks on an 8 x 8 lattice at 3 m (about
 *                                 the gate's size), d detections over it
 *   worst_coincident_<d>          4 tracks at one point, d detections exactly
 *                                 on it
 *   worst_storm_empty_<d>         d unexplained detections 50 m apart on an
 *                                 empty table after two such scans
 *   worst_storm_full_<d>          the same on 63 confirmed tracks
 *   worst_gap<s>_<d>              the typical scan s seconds after the last
 * each with a "_ratio" line (the case over the typical scan, x) and the
 * methods the scan took (its report): "_own_pda", the tracks left out of the
 * joint problem (its pair store full) to their own PDA, and "_bp", the
 * clusters solved by belief propagation. A geometry's sizes end with
 * "worst_<geometry>_monotone": 1 when, between consecutive sizes that split
 * the work alike (as many tracks left to their own PDA, as many clusters by
 * belief propagation), the time never fell by more than MONO_TOL (the
 * machine's noise). Where the split changes the time may fall: the pair
 * store holds TRK_MAX_GATED_PAIRS, so twice the detections in every gate
 * leave half the tracks in the joint problem, and a cluster past the exact
 * bound takes the cheaper belief propagation. The run
 * ends with "worst_dearest_full_load": 1 when the dearest case of all is at
 * the full load (256 detections), within MONO_TOL. With TRK_WITH_IMM every
 * track an IMM track of three models (worst_imm_...). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "trk/tracker.h"

#define W_TRK 64
#define W_DET 256
#define N_REPS 15
#define MONO_TOL 0.05 /* a fall within 5 % is the machine's noise, not the scan's */

static const int sizes[] = {16, 32, 64, 128, 256};
#define N_SIZES ((int)(sizeof sizes / sizeof sizes[0]))

/* One geometry's cases over the sizes: time and how the scan split its
 * work (tracks left to their own PDA, clusters by belief propagation). */
struct worst_series {
    int n;
    double ns[N_SIZES];
    int own_pda[N_SIZES], bp[N_SIZES];
};

struct worst_job {
    struct trk_tracker_params p;
    struct trk_tracker base, work, tk;
    struct trk_detection det[W_DET];
    struct trk_scan_report rep; /* of the last timed scan */
    struct worst_series series;
    double dearest_ratio, dearest_below_full_ratio; /* over every case of the run */
    uint64_t rs;
    double typical_ns;
    const char *prefix;
};

static void worst_params(struct trk_tracker_params *p, int imm)
{
    trk_tracker_default_params(p);
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].clutter_density_per_m2 = (trk_real)(192.0 / (1200.0 * 1200.0));
    p->process_noise_q = TRK_REAL_C(0.01);
    p->stationary_d2 = 0; /* the geometries' tracks stand still: targets, not persistent returns */
#if TRK_WITH_IMM
    if (imm && trk_tracker_imm_params(p, TRK_REAL_C(0.035), TRK_REAL_C(0.95)) != TRK_OK) p->imm.n_models = 0;
#else
    (void)imm;
#endif
}

static void det_at(struct trk_detection *d, double x_m, double y_m)
{
    memset(d, 0, sizeof *d);
    d->x_m = (trk_real)x_m;
    d->y_m = (trk_real)y_m;
}

/* n_trk static tracks on a 1 km grid after 8 scans (confirmed). 0, or -1. */
static int worst_make_tracks(struct worst_job *j, int n_trk)
{
    if (trk_tracker_init(&j->base, &j->p) != TRK_OK) return -1;
    for (int k = 0; k < 8; k++) {
        for (int i = 0; i < n_trk; i++) det_at(&j->det[i], 1000.0 * (i % 8), 1000.0 * (i / 8));
        const struct trk_scan scan = {(int64_t)k * 1000000, 0, (size_t)n_trk, j->det, NULL, 0, {0, 0, 0}, NULL};
        if (trk_tracker_process_scan(&j->base, &scan, NULL) != TRK_OK) return -1;
    }
    int n = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) n += j->base.track[s].status == TRK_TRACK_CONFIRMED;
    return n == n_trk ? 0 : -1;
}

/* Place the confirmed tracks of j->base into j->work: the n-th at
 * (xy[2n], xy[2n+1]) at rest. */
static void worst_place(struct worst_job *j, const double *xy)
{
    memcpy(&j->work, &j->base, sizeof j->work);
    int n = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        struct trk_track *t = &j->work.track[s];
        if (t->status != TRK_TRACK_CONFIRMED) continue;
        t->x[TRK_CV2_X] = (trk_real)xy[2 * n];
        t->x[TRK_CV2_Y] = (trk_real)xy[2 * n + 1];
        t->x[TRK_CV2_VX] = t->x[TRK_CV2_VY] = 0;
        n++;
    }
}

/* The fastest of N_REPS scans of j->det[0..nd) at time_us from a copy of
 * j->work; -1 if a scan is refused. */
static double worst_time(struct worst_job *j, size_t nd, int64_t time_us)
{
    const struct trk_scan scan = {time_us, 0, nd, j->det, NULL, 0, {0, 0, 0}, NULL};
    double best = 1e300;
    for (int r = 0; r < N_REPS; r++) {
        memcpy(&j->tk, &j->work, sizeof j->tk);
        const double t0 = bench_now_ns();
        const trk_status st = trk_tracker_process_scan(&j->tk, &scan, &j->rep);
        const double dt = bench_now_ns() - t0;
        if (st != TRK_OK) return -1;
        if (dt < best) best = dt;
    }
    return best;
}

static void worst_report(struct worst_job *j, const char *name, int size, double ns)
{
    char what[96];
    snprintf(what, sizeof what, "%sworst_%s_%d", j->prefix, name, size);
    if (ns < 0) {
        bench_print(what, 0, "refused");
        return;
    }
    bench_print(what, ns, "ns");
    const double ratio = ns / j->typical_ns;
    snprintf(what, sizeof what, "%sworst_%s_%d_ratio", j->prefix, name, size);
    bench_print(what, ratio, "x");
    snprintf(what, sizeof what, "%sworst_%s_%d_own_pda", j->prefix, name, size);
    bench_print(what, j->rep.n_assoc_overflow, "tracks");
    snprintf(what, sizeof what, "%sworst_%s_%d_bp", j->prefix, name, size);
    bench_print(what, j->rep.n_clusters_approx, "clusters");
    if (size == W_DET && ratio > j->dearest_ratio) j->dearest_ratio = ratio;
    if (size < W_DET && ratio > j->dearest_below_full_ratio) j->dearest_below_full_ratio = ratio;
    struct worst_series *se = &j->series;
    if (se->n < N_SIZES) {
        se->ns[se->n] = ns;
        se->own_pda[se->n] = (int)j->rep.n_assoc_overflow;
        se->bp[se->n] = (int)j->rep.n_clusters_approx;
        se->n++;
    }
}

/* The geometry's sizes done: is its time monotone at each split of its work
 * (a refused case, which a full-capacity build never has, is left out)? */
static void worst_series_end(struct worst_job *j, const char *name)
{
    const struct worst_series *se = &j->series;
    int mono = se->n > 0;
    for (int q = 1; q < se->n; q++)
        if (se->own_pda[q] == se->own_pda[q - 1] && se->bp[q] == se->bp[q - 1] &&
            se->ns[q] < (1 - MONO_TOL) * se->ns[q - 1])
            mono = 0;
    char what[96];
    snprintf(what, sizeof what, "%sworst_%s_monotone", j->prefix, name);
    bench_print(what, mono, "(1: at each split of the work)");
    j->series.n = 0;
}

/* The typical scan: tracks on a 150 m grid, one detection each (within
 * 1 m), 192 clutter detections over the area. */
static double worst_typical(struct worst_job *j, double gap_s)
{
    double xy[2 * W_TRK];
    for (int i = 0; i < W_TRK; i++) {
        xy[2 * i] = 150.0 * (i % 8);
        xy[2 * i + 1] = 150.0 * (i / 8);
    }
    worst_place(j, xy);
    j->rs = 42;
    for (int i = 0; i < W_DET; i++) {
        if (i < W_TRK)
            det_at(&j->det[i], xy[2 * i] + bench_urand(&j->rs) - 0.5, xy[2 * i + 1] + bench_urand(&j->rs) - 0.5);
        else
            det_at(&j->det[i], -100 + 1200 * bench_urand(&j->rs), -100 + 1200 * bench_urand(&j->rs));
    }
    return worst_time(j, W_DET, 8000000 + (int64_t)(gap_s * 1e6));
}

static void worst_cluster(struct worst_job *j, int k)
{
    double xy[2 * W_TRK];
    for (int i = 0; i < W_TRK; i++) {
        xy[2 * i] = i < k ? 0.1 * (i % 4) : 5000.0 + 1000.0 * (i % 8);
        xy[2 * i + 1] = i < k ? 0.1 * (i / 4 % 4) : 1000.0 * (i / 8);
    }
    worst_place(j, xy);
    char name[32];
    snprintf(name, sizeof name, "cluster%d", k);
    for (int q = 0; q < N_SIZES; q++) {
        j->rs = 7;
        for (int i = 0; i < sizes[q]; i++) det_at(&j->det[i], bench_urand(&j->rs) - 0.5, bench_urand(&j->rs) - 0.5);
        worst_report(j, name, sizes[q], worst_time(j, (size_t)sizes[q], 8000000));
    }
    worst_series_end(j, name);
}

static void worst_geometry(struct worst_job *j)
{
    double xy[2 * W_TRK];
    /* the chain */
    for (int i = 0; i < W_TRK; i++) xy[2 * i] = 5.0 * i, xy[2 * i + 1] = 0;
    worst_place(j, xy);
    for (int q = 0; q < N_SIZES; q++) {
        for (int i = 0; i < sizes[q]; i++) det_at(&j->det[i], 5.0 * (W_TRK - 1) * i / sizes[q], 0.5 * ((i % 3) - 1));
        worst_report(j, "chain", sizes[q], worst_time(j, (size_t)sizes[q], 8000000));
    }
    worst_series_end(j, "chain");
    /* the lattice at gate spacing */
    for (int i = 0; i < W_TRK; i++) xy[2 * i] = 3.0 * (i % 8), xy[2 * i + 1] = 3.0 * (i / 8);
    worst_place(j, xy);
    for (int q = 0; q < N_SIZES; q++) {
        j->rs = 11;
        for (int i = 0; i < sizes[q]; i++) det_at(&j->det[i], 21.0 * bench_urand(&j->rs), 21.0 * bench_urand(&j->rs));
        worst_report(j, "lattice", sizes[q], worst_time(j, (size_t)sizes[q], 8000000));
    }
    worst_series_end(j, "lattice");
    /* coincident detections on 4 tracks at one point */
    for (int i = 0; i < W_TRK; i++) {
        xy[2 * i] = i < 4 ? 0 : 5000.0 + 1000.0 * (i % 8);
        xy[2 * i + 1] = i < 4 ? 0 : 1000.0 * (i / 8);
    }
    worst_place(j, xy);
    for (int q = 0; q < N_SIZES; q++) {
        for (int i = 0; i < sizes[q]; i++) det_at(&j->det[i], 0, 0);
        worst_report(j, "coincident", sizes[q], worst_time(j, (size_t)sizes[q], 8000000));
    }
    worst_series_end(j, "coincident");
    /* long gaps before the typical scan */
    static const int gaps_s[] = {10, 60, 300};
    for (int g = 0; g < 3; g++) {
        char name[32];
        snprintf(name, sizeof name, "gap%d", gaps_s[g]);
        worst_report(j, name, W_DET, worst_typical(j, gaps_s[g]));
        j->series.n = 0; /* one size each: nothing to be monotone */
    }
}

/* d unexplained detections 50 m apart, every scan (two before the timed
 * one), on an empty table or on 63 confirmed tracks far away. */
static void worst_storm(struct worst_job *j, int n_trk, const char *name)
{
    for (int q = 0; q < N_SIZES; q++) {
        const int nd = sizes[q];
        if (n_trk == 0) {
            if (trk_tracker_init(&j->work, &j->p) != TRK_OK) return;
        } else {
            double xy[2 * W_TRK];
            for (int i = 0; i < W_TRK; i++) xy[2 * i] = 20000.0 + 1000.0 * (i % 8), xy[2 * i + 1] = 1000.0 * (i / 8);
            worst_place(j, xy);
        }
        for (int k = 0; k < 2; k++) {
            for (int i = 0; i < nd; i++) det_at(&j->det[i], 50.0 * (i % 16) + 7.0 * k, 50.0 * (i / 16) + 3.0 * k);
            const struct trk_scan scan = {8000000 + (int64_t)k * 1000000, 0, (size_t)nd, j->det, NULL, 0, {0, 0, 0}, NULL};
            if (trk_tracker_process_scan(&j->work, &scan, NULL) != TRK_OK) return;
        }
        for (int i = 0; i < nd; i++) det_at(&j->det[i], 50.0 * (i % 16) + 25.0, 50.0 * (i / 16) + 25.0);
        worst_report(j, name, nd, worst_time(j, (size_t)nd, 10000000));
    }
    worst_series_end(j, name);
}

static void worst_run(int imm, const char *prefix)
{
    if (TRK_MAX_TRACKS < W_TRK || TRK_MAX_DETECTIONS < W_DET) {
        bench_print("worst_skipped_capacity", 0, "-");
        return;
    }
    struct worst_job *j = calloc(1, sizeof *j);
    if (!j) return;
    j->prefix = prefix;
    worst_params(&j->p, imm);
    if (worst_make_tracks(j, W_TRK - 1) == 0) {
        /* 63 tracks for the storm on a nearly full table, then 64 */
        j->typical_ns = 1; /* set below; the storm is timed after it */
        struct trk_tracker *keep63 = malloc(sizeof *keep63);
        if (keep63) {
            memcpy(keep63, &j->base, sizeof *keep63);
            if (worst_make_tracks(j, W_TRK) == 0) {
                j->typical_ns = worst_typical(j, 0);
                bench_print(imm ? "imm_worst_typical_256" : "worst_typical_256", j->typical_ns, "ns");
                for (int k = 0; k < 6; k++) {
                    static const int ks[] = {2, 3, 4, 8, 16, 64};
                    worst_cluster(j, ks[k]);
                }
                worst_geometry(j);
                worst_storm(j, 0, "storm_empty");
                memcpy(&j->base, keep63, sizeof *keep63);
                worst_storm(j, W_TRK - 1, "storm_full");
                bench_print(imm ? "imm_worst_dearest_full_load" : "worst_dearest_full_load",
                            j->dearest_ratio >= (1 - MONO_TOL) * j->dearest_below_full_ratio,
                            "(1: the dearest case is at 256 detections)");
            } else {
                bench_print(imm ? "imm_worst_failed_setup_64" : "worst_failed_setup_64", 0, "-");
            }
            free(keep63);
        }
    } else {
        bench_print(imm ? "imm_worst_failed_setup_63" : "worst_failed_setup_63", 0, "-");
    }
    free(j);
}

TRK_BENCH(worst) { worst_run(0, ""); }

TRK_BENCH(worst_imm)
{
#if TRK_WITH_IMM
    worst_run(1, "imm_");
#else
    bench_print("worst_imm_skipped_no_imm", 0, "-");
#endif
}
