/* bench_grid.c - how the whole scan grows with the surveyed area:
 *   scan_grid_T<t>_D<d>   ns per trk_tracker_process_scan with t confirmed
 *                         tracks and d detections (t targets + d - t
 *                         clutter) at the fixed detection density of
 *                         scan_64x256 (256 per 1200 m x 1200 m): the area
 *                         grows with d; the defaults (joint association)
 *   scan_grid_growth_4x_area   scan_grid_T256_D1024 / scan_grid_T64_D256:
 *                         four times the area, tracks and detections (brute
 *                         force gating, every track against every
 *                         detection: 16x; the bound aimed at: 5x)
 * Sizes beyond the build's capacities are skipped (`make bench` runs a
 * build with TRK_MAX_TRACKS 256 and TRK_MAX_DETECTIONS 4096). The grid
 * runs round-robin, 3 repetitions, the fastest of each. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "trk/tracker.h"

enum { GRID_SCANS = 24, GRID_WARM = 4 };

static uint64_t grid_rs;
static double grid_urand(void) { return bench_urand(&grid_rs); }

struct grid_job {
    size_t n_tgt, n_det;
    double side_m;
    struct trk_tracker tk;
    struct trk_detection *det; /* GRID_SCANS x n_det */
};

/* Targets on a square grid over side x side moving at 1-3 m/s, then
 * uniform clutter over the area. */
static struct grid_job *grid_new(size_t n_tgt, size_t n_det)
{
    struct grid_job *j = calloc(1, sizeof *j);
    if (!j) return NULL;
    j->det = calloc((size_t)GRID_SCANS * n_det, sizeof *j->det);
    if (!j->det) {
        free(j);
        return NULL;
    }
    j->n_tgt = n_tgt;
    j->n_det = n_det;
    j->side_m = 1200.0 * sqrt((double)n_det / 256.0);
    const size_t per_row = (size_t)ceil(sqrt((double)n_tgt));
    const double spacing = j->side_m / (double)per_row;
    grid_rs = 42;
    for (size_t i = 0; i < n_tgt; i++) {
        const double x0 = spacing * (double)(i % per_row), y0 = spacing * (double)(i / per_row);
        const double vx = 1 + 2 * grid_urand(), vy = 1 + 2 * grid_urand();
        for (int k = 0; k < GRID_SCANS; k++) {
            struct trk_detection *d = &j->det[(size_t)k * n_det + i];
            d->x_m = (trk_real)(x0 + vx * k + (grid_urand() - 0.5) * 2);
            d->y_m = (trk_real)(y0 + vy * k + (grid_urand() - 0.5) * 2);
        }
    }
    for (int k = 0; k < GRID_SCANS; k++)
        for (size_t i = n_tgt; i < n_det; i++) {
            struct trk_detection *d = &j->det[(size_t)k * n_det + i];
            d->x_m = (trk_real)(-100 + j->side_m * grid_urand() + k);
            d->y_m = (trk_real)(-100 + j->side_m * grid_urand() + k);
        }
    return j;
}

/* One repetition: ns per scan over the timed scans, or -1; *n_conf the
 * confirmed tracks at the end. */
static double grid_rep(struct grid_job *j, int *n_conf)
{
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.sensor[0].pd = TRK_REAL_C(0.9);
    const double n_clutter = j->n_det > j->n_tgt ? (double)(j->n_det - j->n_tgt) : 1.0;
    p.sensor[0].clutter_density_per_m2 = (trk_real)(n_clutter / (j->side_m * j->side_m));
    p.process_noise_q = TRK_REAL_C(0.01);
    if (trk_tracker_init(&j->tk, &p) != TRK_OK) return -1;
    double t0 = 0;
    for (int k = 0; k < GRID_SCANS; k++) {
        if (k == GRID_WARM) t0 = bench_now_ns();
        const struct trk_scan scan = {(int64_t)k * 1000000, 0, k < GRID_WARM ? j->n_tgt : j->n_det,
                                      j->det + (size_t)k * j->n_det, NULL, 0, {0, 0, 0}, NULL};
        if (trk_tracker_process_scan(&j->tk, &scan, NULL) != TRK_OK) return -1;
    }
    const double per = (bench_now_ns() - t0) / (GRID_SCANS - GRID_WARM);
    *n_conf = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *t = trk_tracker_track(&j->tk, s);
        *n_conf += t && t->status == TRK_TRACK_CONFIRMED;
    }
    return per;
}

TRK_BENCH(scan_grid)
{
    static const size_t tgts[] = {64, 256}, dets[] = {256, 1024, 4096};
    enum { N_T = 2, N_D = 3 };
    struct grid_job *job[N_T][N_D] = {{NULL}};
    double best[N_T][N_D];
    int conf[N_T][N_D];
    for (int a = 0; a < N_T; a++)
        for (int b = 0; b < N_D; b++) {
            best[a][b] = -1;
            conf[a][b] = 0;
            if (tgts[a] <= TRK_MAX_TRACKS && dets[b] <= TRK_MAX_DETECTIONS && tgts[a] <= dets[b])
                job[a][b] = grid_new(tgts[a], dets[b]);
        }
    for (int rep = 0; rep < 3; rep++)
        for (int a = 0; a < N_T; a++)
            for (int b = 0; b < N_D; b++) {
                if (!job[a][b]) continue;
                const double per = grid_rep(job[a][b], &conf[a][b]);
                if (per >= 0 && (best[a][b] < 0 || per < best[a][b])) best[a][b] = per;
            }
    for (int a = 0; a < N_T; a++)
        for (int b = 0; b < N_D; b++) {
            char name[96];
            if (!job[a][b]) {
                snprintf(name, sizeof name, "scan_grid_T%zu_D%zu_skipped_capacity", tgts[a], dets[b]);
                bench_print(name, 0, "-");
                continue;
            }
            snprintf(name, sizeof name, "scan_grid_T%zu_D%zu", tgts[a], dets[b]);
            bench_print(name, best[a][b], "ns");
            snprintf(name, sizeof name, "scan_grid_T%zu_D%zu_confirmed_tracks", tgts[a], dets[b]);
            bench_print(name, conf[a][b], "tracks");
            free(job[a][b]->det);
            free(job[a][b]);
        }
    if (best[0][0] > 0 && best[1][1] > 0) bench_print("scan_grid_growth_4x_area", best[1][1] / best[0][0], "x");
    if (best[0][0] > 0 && best[0][1] > 0) bench_print("scan_grid_growth_4x_detections_T64", best[0][1] / best[0][0], "x");
    if (best[1][1] > 0 && best[1][2] > 0)
        bench_print("scan_grid_growth_4x_detections_T256", best[1][2] / best[1][1], "x");
}
