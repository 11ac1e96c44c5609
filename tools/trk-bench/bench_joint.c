/* bench_joint.c - joint association's worst cases, the default
 * configuration (joint association) with single-point starts:
 *   joint_chain_64x256  ns per scan of 64 tracks 5 m apart on a line and 256
 *                       detections 1.25 m apart along it: every detection in
 *                       the gates of one or two neighbouring tracks, so one
 *                       cluster of all 64 tracks and 256 detections, which the
 *                       pair store holds (loopy belief propagation solves it)
 *   joint_dense_64x256  ns per scan of 64 tracks within 3 m and 256
 *                       detections among them: every detection in every gate,
 *                       16 384 gated pairs, beyond TRK_MAX_GATED_PAIRS: the
 *                       tracks whose pairs do not fit are updated by their own
 *                       PDA (n_assoc_overflow), so the time stays bounded
 * with each scan's cluster figures; jpda_solve_exact_worst the solver alone
 * on its worst exact work (below). The tracks are made on a 1 km grid (8
 * scans), then moved into place in a copy of the table; each timed scan
 * starts from that copy. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "trk/jpda.h"
#include "trk/tracker.h"

#define N_TRK 64
#define N_DETS 256

struct joint_job {
    struct trk_tracker base, tk;
    struct trk_detection det[N_DETS];
};

/* 64 single-point tracks of static targets on a 1 km grid after 8 scans,
 * then moved: the n-th to (spacing_m n, 0), at rest. 0, or -1. */
static int make_tracks(struct joint_job *j, double spacing_m)
{
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.init.method = TRK_INIT_SINGLE_POINT;
    p.merge_gate_d2 = 0; /* the close tracks are the point */
    if (trk_tracker_init(&j->base, &p) != TRK_OK) return -1;
    for (int k = 0; k < 8; k++) {
        for (int i = 0; i < N_TRK; i++) {
            memset(&j->det[i], 0, sizeof j->det[i]);
            j->det[i].x_m = (trk_real)(1000.0 * (i % 8));
            j->det[i].y_m = (trk_real)(1000.0 * (i / 8));
        }
        const struct trk_scan scan = {(int64_t)k * 1000000, 0, N_TRK, j->det, NULL, 0, {0, 0, 0}, NULL};
        if (trk_tracker_process_scan(&j->base, &scan, NULL) != TRK_OK) return -1;
    }
    int n = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        struct trk_track *t = &j->base.track[s];
        if (t->status != TRK_TRACK_TENTATIVE && t->status != TRK_TRACK_CONFIRMED) continue;
        t->x[TRK_CV2_X] = (trk_real)(spacing_m * n);
        t->x[TRK_CV2_Y] = 0;
        t->x[TRK_CV2_VX] = t->x[TRK_CV2_VY] = 0;
        n++;
    }
    return n == N_TRK ? 0 : -1;
}

/* The fastest of 30 scans from the copy, and the last one's report. */
static void time_scan(struct joint_job *j, const char *name)
{
    const struct trk_scan scan = {8 * 1000000, 0, N_DETS, j->det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    double best = 1e300;
    for (int r = 0; r < 30; r++) {
        memcpy(&j->tk, &j->base, sizeof j->tk);
        const double t0 = bench_now_ns();
        const trk_status st = trk_tracker_process_scan(&j->tk, &scan, &rep);
        const double dt = bench_now_ns() - t0;
        if (st != TRK_OK) return;
        if (dt < best) best = dt;
    }
    char what[96];
    bench_print(name, best, "ns");
    snprintf(what, sizeof what, "%s_largest_cluster", name);
    bench_print(what, rep.largest_cluster, "tracks");
    snprintf(what, sizeof what, "%s_clusters", name);
    bench_print(what, rep.n_clusters, "clusters");
    snprintf(what, sizeof what, "%s_approx_clusters", name);
    bench_print(what, rep.n_clusters_approx, "clusters");
    snprintf(what, sizeof what, "%s_overflow_tracks", name);
    bench_print(what, rep.n_assoc_overflow, "tracks");
}

static void joint_bench(const char *name, double spacing_m, double det_spacing_m, double det_rows_m)
{
    if (TRK_MAX_TRACKS < N_TRK || TRK_MAX_DETECTIONS < N_DETS) {
        bench_print("joint_skipped_capacity", 0, "-");
        return;
    }
    struct joint_job *j = calloc(1, sizeof *j);
    if (!j) return;
    if (make_tracks(j, spacing_m) == 0) {
        for (int i = 0; i < N_DETS; i++) {
            memset(&j->det[i], 0, sizeof j->det[i]);
            j->det[i].x_m = (trk_real)(det_spacing_m * i);
            j->det[i].y_m = (trk_real)(det_rows_m * ((i % 3) - 1));
        }
        time_scan(j, name);
    }
    free(j);
}

TRK_BENCH(joint_chain_64x256) { joint_bench("joint_chain_64x256", 5, 1.25, 0); }

TRK_BENCH(joint_dense_64x256) { joint_bench("joint_dense_64x256", 0.05, 3.2 / N_DETS, 0.3); }

/* The exact solver's worst scan: 2 clusters of 25 tracks each gating all 9
 * detections of its cluster (450 pairs; 3.4 M operations each by the
 * subsets of detections): over the default TRK_JPDA_MAX_WORK both take
 * belief propagation; in a build that raises it to 2^22, more than
 * TRK_JPDA_SCAN_WORK together, so the budget lets the first be solved
 * exactly and sends the other to belief propagation: either way the scan's
 * time stays bounded. trk_jpda_solve alone, ns per call. */
TRK_BENCH(jpda_solve_exact_worst)
{
    enum { NC = 2, NT = 25, ND = 9 };
    static uint16_t first[NC * NT + 1], det[NC * NT * ND];
    static trk_real w0[NC * NT * ND], w[NC * NT * ND], miss[NC * NT], p[NC * NT * ND], pm[NC * NT];
    static struct trk_jpda_solver solver;
    if (TRK_MAX_TRACKS < NC * NT || TRK_MAX_GATED_PAIRS < NC * NT * ND || TRK_MAX_DETECTIONS < NC * ND) {
        bench_print("jpda_solve_exact_worst_skipped_capacity", 0, "-");
        return;
    }
    size_t n = 0;
    for (int t = 0; t < NC * NT; t++) {
        first[t] = (uint16_t)n;
        miss[t] = (trk_real)log(0.3);
        for (int j = 0; j < ND; j++) {
            det[n] = (uint16_t)((t / NT) * ND + j);
            w0[n++] = (trk_real)(0.1 * ((t * 7 + j * 3) % 11) - 0.5);
        }
    }
    first[NC * NT] = (uint16_t)n;
    struct trk_jpda_report rep;
    double best = 1e300;
    for (int r = 0; r < 10; r++) {
        memcpy(w, w0, sizeof w); /* the solver overwrites the weights */
        const struct trk_jpda_pairs pairs = {NC * NT, NC * ND, first, det, w, miss};
        const double t0 = bench_now_ns();
        if (trk_jpda_solve(&pairs, &solver, p, pm, &rep) != TRK_OK) return;
        const double dt = bench_now_ns() - t0;
        if (dt < best) best = dt;
    }
    bench_print("jpda_solve_exact_worst", best, "ns");
    bench_print("jpda_solve_exact_worst_exact_clusters", rep.n_exact, "clusters");
    bench_print("jpda_solve_exact_worst_approx_clusters", rep.n_approx, "clusters");
}

/* Two tracks sharing nd detections (every pair gated): the exact solver's
 * cost in the number of detections, up to a full scan. The two-track
 * cluster was the scan's worst case (quadratic in the detections) before
 * the forward-backward exact method (jpda.c), which is linear. */
TRK_BENCH(jpda_two_tracks)
{
    enum { ND_MAX = 256 };
    static uint16_t first[3], det[2 * ND_MAX];
    static trk_real w0[2 * ND_MAX], w[2 * ND_MAX], miss[2], p[2 * ND_MAX], pm[2];
    static struct trk_jpda_solver solver;
    static const int nds[] = {16, 64, 128, 250, 256};
    if (TRK_MAX_GATED_PAIRS < 2 * ND_MAX || TRK_MAX_DETECTIONS < ND_MAX) {
        bench_print("jpda_two_tracks_skipped_capacity", 0, "-");
        return;
    }
    for (size_t q = 0; q < sizeof nds / sizeof nds[0]; q++) {
        const int nd = nds[q];
        size_t n = 0;
        for (int t = 0; t < 2; t++) {
            first[t] = (uint16_t)n;
            miss[t] = (trk_real)log(0.3);
            for (int j = 0; j < nd; j++) {
                det[n] = (uint16_t)j;
                w0[n++] = (trk_real)(0.1 * ((t * 7 + j * 3) % 11) - 0.5);
            }
        }
        first[2] = (uint16_t)n;
        struct trk_jpda_report rep;
        double best = 1e300;
        for (int r = 0; r < 10; r++) {
            memcpy(w, w0, n * sizeof w[0]);
            const struct trk_jpda_pairs pairs = {2, (size_t)nd, first, det, w, miss};
            const double t0 = bench_now_ns();
            if (trk_jpda_solve(&pairs, &solver, p, pm, &rep) != TRK_OK) return;
            const double dt = bench_now_ns() - t0;
            if (dt < best) best = dt;
        }
        char name[64];
        snprintf(name, sizeof name, "jpda_two_tracks_%d%s", nd, rep.n_exact ? "" : "_approx");
        bench_print(name, best, "ns");
    }
}
