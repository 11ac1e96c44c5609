/* test_tracker_own.c - detections with their own covariances in the track
 * table, gated through their own 2-D index (src/track_gate_impl.h,
 * ws.grid_own) in a box bound by the scan's largest own covariance:
 *   - detections carrying the sensor's own R are tracked exactly as the
 *     same detections without a covariance (the same tracks, ids and
 *     states: both groups' indices order the same points alike);
 *   - a detection whose own covariance is far larger than the others' (a
 *     sonar's cross-range error at long range) reaches the gate of a
 *     precise track 70 m off its prediction, two index columns beyond the
 *     box the other covariances would give: the index's box is bound by the
 *     scan's largest own variance. */
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/tracker.h"

static struct trk_tracker tk_a, tk_b;

#define SCAN_US(k) ((int64_t)(k) * 4000000)

static void test_own_r_equals_shared(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-5);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
    uint64_t rng = 3;
    for (int k = 0; k < 40; k++) {
        struct trk_detection a[16], b[16];
        size_t n = 0;
        for (int t = 0; t < 4; t++)
            if (trk_test_urand(&rng) < 0.8) {
                const double ex = 5 * trk_test_nrand(&rng), ey = 5 * trk_test_nrand(&rng);
                a[n++] = trk_test_det_at(100 * t + 20.0 * k + ex, 80 * t + ey);
            }
        for (int c = 0; c < 6; c++) {
            const double cx = 1500 * trk_test_urand(&rng) - 200, cy = 800 * trk_test_urand(&rng) - 200;
            a[n++] = trk_test_det_at(cx, cy);
        }
        for (size_t i = 0; i < n; i++) {
            b[i] = a[i];
            b[i].has_cov = 1;
            for (int c = 0; c < 3; c++) b[i].cov_m2[c] = p.sensor[0].meas_cov_m2[c];
        }
        const struct trk_scan sa = {SCAN_US(k), 0, n, a, NULL, 0, {0, 0, 0}, NULL}, sb = {SCAN_US(k), 0, n, b, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &sa, NULL));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &sb, NULL));
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *ta = trk_tracker_track(&tk_a, i), *tb = trk_tracker_track(&tk_b, i);
            assert_true((ta == NULL) == (tb == NULL));
            if (!ta) continue;
            assert_int_equal(ta->id, tb->id);
            assert_int_equal(ta->status, tb->status);
            assert_int_equal(ta->n_gated_last, tb->n_gated_last);
            for (int j = 0; j < TRK_CV2_NX; j++)
                TRK_ASSERT_NEAR(tb->x[j], ta->x[j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-11, 1e-5));
        }
    }
    assert_true(trk_test_count_confirmed(&tk_a) >= 4);
}

/* One target seen with own R = 4 I (a precise track, small P) among far
 * clutter of the same covariance; at scan 20 its detection arrives 70 m
 * off in x with R = diag(3600, 4): S_j = H P H' + R_j makes d2 about 1.4,
 * so it is in the gate, with 25 detections of R = 4 I on a lattice 60-160 m
 * north of the target. The index then has 40 m columns, and the detection
 * lies two columns east of the box the small covariances alone would give
 * (about 23 m wide): only a box bound by the scan's largest own variance
 * reaches it (measured: with the sensor's R in that bound instead, nothing
 * is gated). */
static void test_large_own_covariance_reaches_gate(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-6);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    uint64_t rng = 9;
    for (int k = 0; k <= 20; k++) {
        struct trk_detection d[32];
        size_t n = 0;
        const double tx = 100 + 5.0 * 4 * k, ty = 50;
        const double ex = 2 * trk_test_nrand(&rng), ey = 2 * trk_test_nrand(&rng);
        d[n] = trk_test_det_at(tx + (k == 20 ? 70 : ex), ty + (k == 20 ? 0 : ey));
        d[n].has_cov = 1;
        d[n].cov_m2[TRK_COV2_XX] = k == 20 ? 3600 : 4;
        d[n].cov_m2[TRK_COV2_XY] = 0;
        d[n].cov_m2[TRK_COV2_YY] = 4;
        n++;
        for (int c = 0; c < (k == 20 ? 25 : 4); c++) {
            const double cx = k == 20 ? tx - 100 + 50 * (c % 5) : 3000 * trk_test_urand(&rng) - 1000;
            const double cy = k == 20 ? ty + 60 + 25 * (c / 5) : 3000 * trk_test_urand(&rng) + 1000;
            d[n] = trk_test_det_at(cx, cy);
            d[n].has_cov = 1;
            d[n].cov_m2[TRK_COV2_XX] = d[n].cov_m2[TRK_COV2_YY] = 4;
            d[n].cov_m2[TRK_COV2_XY] = 0;
            n++;
        }
        const struct trk_scan s = {SCAN_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    size_t found = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk_a, i);
        if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
        found++;
        assert_int_equal(tr->n_gated_last, 1);
    }
    assert_int_equal(found, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_own_r_equals_shared),
        cmocka_unit_test(test_large_own_covariance_reaches_gate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
