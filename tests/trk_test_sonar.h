/* trk_test_sonar.h - what the track-table tests (initiation, joint association) share:
 * the sonar-like sensor (P_D 0.8, R = 25 I, clutter density lambda, q 1e-3
 * on the library defaults), a detection at a point, and the count of
 * confirmed tracks. */
#ifndef TRK_TEST_SONAR_H
#define TRK_TEST_SONAR_H

#include <string.h>

#include "trk/tracker.h"
#include "trk_test.h"

static inline void trk_test_sonar_params(struct trk_tracker_params *p, double lambda)
{
    trk_tracker_default_params(p);
    p->sensor[0].pd = TRK_REAL_C(0.8);
    p->sensor[0].meas_cov_m2[0] = p->sensor[0].meas_cov_m2[2] = 25;
    p->sensor[0].meas_cov_m2[1] = 0;
    p->sensor[0].clutter_density_per_m2 = (trk_real)lambda;
    p->process_noise_q = TRK_REAL_C(1e-3);
    p->init.min_existence = 0; /* every pair starts (their odds here are ~1e-5): the tests of pairing
                                  see the pair itself; test_tracker_init's test_min_existence the wait */
}

/* The defaults with sensor 0 a polar sonar at the origin facing north
 * (sigma 7.5 m in range, 1.5 deg in bearing, P_D 0.9, clutter lambda) whose
 * targets stand still where a test puts them: targets, not persistent
 * returns (stationary_d2 0). */
static inline void trk_test_polar_params(struct trk_tracker_params *p, double lambda)
{
    trk_tracker_default_params(p);
    p->stationary_d2 = 0;
    struct trk_sensor_params *s = &p->sensor[0];
    s->kind = TRK_SENSOR_POLAR;
    s->sigma_range_m = TRK_REAL_C(7.5);
    s->sigma_bearing_rad = (trk_real)(1.5 * 3.14159265358979323846 / 180);
    s->pd = TRK_REAL_C(0.9);
    s->clutter_density_per_m2 = (trk_real)lambda;
}

static inline size_t trk_test_count_confirmed(const struct trk_tracker *t)
{
    size_t n = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(t, i);
        n += tr && tr->status == TRK_TRACK_CONFIRMED;
    }
    return n;
}

static inline struct trk_detection trk_test_det_at(double x, double y)
{
    struct trk_detection d;
    memset(&d, 0, sizeof d);
    d.x_m = (trk_real)x;
    d.y_m = (trk_real)y;
    return d;
}

/* Scan k of two targets dy_m apart moving +x at 5 m/s (each detected with
 * probability 0.8, sigma 5 m) and n_clutter uniform clutter detections over
 * [-200, 800] x [-300, 300] m, a scan every dt_s, into d: their count. The
 * draws in a fixed order (x before y), whatever the compiler. */
static inline size_t trk_test_pair_scan(int k, double dt_s, double dy_m, int n_clutter, uint64_t *rng,
                                        struct trk_detection *d)
{
    size_t n = 0;
    for (int t = 0; t < 2; t++)
        if (trk_test_urand(rng) < 0.8) {
            const double ex = 5 * trk_test_nrand(rng), ey = 5 * trk_test_nrand(rng);
            d[n++] = trk_test_det_at(100 + 5 * dt_s * k + ex, dy_m * t + ey);
        }
    for (int c = 0; c < n_clutter; c++) {
        const double cx = 1000 * trk_test_urand(rng) - 200, cy = 600 * trk_test_urand(rng) - 300;
        d[n++] = trk_test_det_at(cx, cy);
    }
    return n;
}

#endif
