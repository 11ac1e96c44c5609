/* replay_csv.c - the C side of the Python binding's identity test and
 * benchmark (tests/python_binding.sh, tools/python/bench_scan.py): the
 * detections of a CSV file (trk-sim demo's detections.csv: scan, time_s,
 * x_m, y_m and optionally amplitude; one row per detection, scans in
 * order) through
 * trk_tracker_process_scan, every live track of every scan printed exactly
 * (%.17g of each value: the Python side prints the same).
 *
 *   py-replay-csv DETECTIONS.csv [--sigma M] [--q Q] [--lambda L] [--pd PD]
 *                 [--table AMP.tbl] [--bench]
 * The tracker: trk_tracker_default_params with sensor 0's covariance
 * sigma^2 I, clutter density lambda, P_D pd, process noise q and the
 * amplitude table's model (PDAFAI) when given. The scan time is the row's
 * time_s rounded to the microsecond. --bench prints only the mean time of
 * one trk_tracker_process_scan call (ns), over every scan of the file. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "trk/table_file.h"
#include "trk/tracker.h"

static struct trk_tracker tk;
static struct trk_detection det[TRK_MAX_DETECTIONS];

struct row {
    long scan;
    double t, x, y, a;
    int has_a;
};

static void print_tracks(long scan, const struct trk_scan_report *r)
{
    printf("scan %ld report %u %u %u %u %u %u %u %u %u\n", scan, r->n_detections, r->n_tracks_updated,
           r->n_tracks_hit, r->n_started, r->n_confirmed, r->n_terminated, r->n_merged, r->n_replaced,
           r->n_candidates);
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *k = trk_tracker_track(&tk, s);
        if (!k) continue;
        printf("scan %ld track %u %u %u", scan, k->id, k->status, k->end_reason);
        for (int i = 0; i < TRK_CV2_NX; i++) printf(" %.17g", (double)k->x[i]);
        for (int i = 0; i < TRK_CV2_NX * TRK_CV2_NX; i++) printf(" %.17g", (double)k->p[i]);
        printf(" %.17g %.17g\n", (double)k->vis.pv, (double)k->vis.pcv);
    }
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    double sigma = 5, q = 1e-3, lambda = 1e-6, pd = 0.9;
    const char *table = NULL;
    int bench = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: py-replay-csv DETECTIONS.csv [--sigma M] [--q Q] [--lambda L] [--pd PD] "
                        "[--table AMP.tbl] [--bench]\n");
        return 2;
    }
    for (int i = 2; i < argc; i++) {
        const int more = i + 1 < argc;
        if (strcmp(argv[i], "--bench") == 0) bench = 1;
        else if (more && strcmp(argv[i], "--sigma") == 0) sigma = atof(argv[++i]);
        else if (more && strcmp(argv[i], "--q") == 0) q = atof(argv[++i]);
        else if (more && strcmp(argv[i], "--lambda") == 0) lambda = atof(argv[++i]);
        else if (more && strcmp(argv[i], "--pd") == 0) pd = atof(argv[++i]);
        else if (more && strcmp(argv[i], "--table") == 0) table = argv[++i];
        else {
            fprintf(stderr, "py-replay-csv: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.sensor[0].meas_cov_m2[TRK_COV2_XX] = (trk_real)(sigma * sigma);
    p.sensor[0].meas_cov_m2[TRK_COV2_YY] = (trk_real)(sigma * sigma);
    p.sensor[0].clutter_density_per_m2 = (trk_real)lambda;
    p.sensor[0].pd = (trk_real)pd;
    p.process_noise_q = (trk_real)q;
    void *tbuf = NULL;
    struct trk_table t;
    if (table) {
        size_t n;
        trk_status st = trk_table_file_size(table, &n);
        tbuf = st == TRK_OK ? malloc(n + 8) : NULL;
        if (st == TRK_OK && !tbuf) st = TRK_E_CAPACITY;
        if (st == TRK_OK) st = trk_table_load_file(table, tbuf, n + 8, &t, NULL);
        if (st == TRK_OK) st = trk_amplitude_init_table(&p.sensor[0].amplitude, &t);
        if (st != TRK_OK) {
            fprintf(stderr, "py-replay-csv: %s: %s\n", table, trk_status_str(st));
            return 1;
        }
        p.sensor[0].use_amplitude = 1;
    }
    trk_status st = trk_tracker_init(&tk, &p);
    if (st != TRK_OK) {
        fprintf(stderr, "py-replay-csv: trk_tracker_init: %s\n", trk_status_str(st));
        return 1;
    }
    FILE *f = fopen(argv[1], "r");
    if (!f) {
        perror(argv[1]);
        return 1;
    }
    char line[512];
    if (!fgets(line, sizeof line, f)) return 1; /* header */
    struct row r, next;
    int have = 0, eof = 0;
    long n_scans = 0;
    double t_ns = 0;
    while (!eof) {
        size_t n = 0;
        long scan = -1;
        double time_s = 0;
        for (;;) {
            if (!have) {
                if (!fgets(line, sizeof line, f)) {
                    eof = 1;
                    break;
                }
                const int got = sscanf(line, "%ld,%lf,%lf,%lf,%lf", &next.scan, &next.t, &next.x, &next.y, &next.a);
                next.has_a = got == 5;
                if (got != 4 && got != 5) {
                    fprintf(stderr, "py-replay-csv: bad line: %s", line);
                    return 1;
                }
                have = 1;
            }
            if (scan >= 0 && next.scan != scan) break;
            r = next;
            have = 0;
            scan = r.scan;
            time_s = r.t;
            if (n == TRK_MAX_DETECTIONS) {
                fprintf(stderr, "py-replay-csv: scan %ld has more than %d detections\n", scan, TRK_MAX_DETECTIONS);
                return 1;
            }
            memset(&det[n], 0, sizeof det[n]);
            det[n].x_m = (trk_real)r.x;
            det[n].y_m = (trk_real)r.y;
            det[n].amplitude = (trk_real)r.a;
            det[n].has_amplitude = (uint8_t)r.has_a;
            n++;
        }
        if (scan < 0) break;
        struct trk_scan sc = {(int64_t)llround(time_s * 1e6), 0, n, det, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        const double t0 = bench ? now_ns() : 0;
        st = trk_tracker_process_scan(&tk, &sc, &rep);
        if (bench) t_ns += now_ns() - t0;
        if (st != TRK_OK) {
            fprintf(stderr, "py-replay-csv: scan %ld: %s\n", scan, trk_status_str(st));
            return 1;
        }
        n_scans++;
        if (!bench) print_tracks(scan, &rep);
    }
    fclose(f);
    free(tbuf);
    if (bench) printf("c_scan_ns %.1f scans %ld\n", n_scans ? t_ns / (double)n_scans : 0.0, n_scans);
    return 0;
}
