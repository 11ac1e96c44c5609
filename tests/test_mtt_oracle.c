/* test_mtt_oracle.c - the known-association bound of trk-sim mtt
 * (tools/sim/mtt_oracle.h): exact detections of a constant-velocity target
 * give the truth to rounding from the second detection on; the first
 * update after the start against its closed form; clutter and other
 * targets' detections ignored; the end of a target; refused input. */
#include "trk_test.h"
#include "mtt_oracle.h"

#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define T_S 4.0 /* scan period */

/* Scan k at k T_S holding det[0 .. n). */
static struct trk_scan scan_at(long k, const struct trk_detection *det, size_t n)
{
    struct trk_scan s = {(int64_t)(k * T_S * 1e6), 0, n, det, NULL, 0, {0, 0, 0}, NULL};
    return s;
}

static struct trk_detection det_at(double x, double y)
{
    struct trk_detection d = {(trk_real)x, (trk_real)y, {0, 0, 0}, 0, 0, 0};
    return d;
}

/* P_D 1, no noise: target 0 at (100 + 3 t, 50 - 2 t), target 1 elsewhere,
 * clutter beside them; from scan 1 (its second detection) the estimate of
 * target 0 is its truth at every scan, position and velocity */
static void test_exact_cv(void **state)
{
    (void)state;
    struct mtt_oracle o;
    const trk_real cov[3] = {25, 0, 25};
    assert_int_equal(mtt_oracle_init(&o, 2, cov, TRK_REAL_C(1e-3)), 0);
    for (long k = 0; k < 30; k++) {
        const double t = (double)k * T_S;
        struct trk_detection det[3] = {det_at(7, 7), det_at(100 + 3 * t, 50 - 2 * t), det_at(2000 - t, 900)};
        const long origin[3] = {-1, 0, 1};
        const struct trk_scan s = scan_at(k, det, 3);
        struct mtt_oracle_report rep;
        assert_int_equal(mtt_oracle_scan(&o, &s, origin, &rep), 0);
        assert_int_equal(rep.n_target_det, 2);
        assert_int_equal(rep.n_started, k == 1 ? 2 : 0);
        assert_int_equal(rep.n_updated, k >= 2 ? 2 : 0);
        const struct mtt_oracle_track *tr = mtt_oracle_track(&o, 0);
        if (k == 0) {
            assert_null(tr);
            continue;
        }
        assert_non_null(tr);
        assert_int_equal(tr->start_scan, 1);
        TRK_ASSERT_NEAR(tr->x[X], 100 + 3 * t, 1e-9, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(tr->x[Y], 50 - 2 * t, 1e-9, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(tr->x[VX], 3, TRK_TOL(1e-11, 1e-3), 0);
        TRK_ASSERT_NEAR(tr->x[VY], -2, TRK_TOL(1e-11, 1e-3), 0);
        const struct mtt_oracle_track *t1 = mtt_oracle_track(&o, 1);
        assert_non_null(t1);
        TRK_ASSERT_NEAR(t1->x[X], 2000 - t, 1e-9, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(t1->x[VX], -1, TRK_TOL(1e-11, 1e-3), 0);
    }
    mtt_oracle_free(&o);
}

/* The track starts at the second detection (a missed scan first): x = the
 * second detection, v = the difference over the time between them, P of
 * two-point differencing. Then, q = 0 and R = r I, the next update with a
 * detection d off the prediction: the predicted position variance is
 * r + 2 T (r / T) + T^2 (2 r / T^2) = 5 r, the position-velocity one
 * r / T + T (2 r / T^2) = 3 r / T, S = 6 r: the position moves by 5 d / 6,
 * the velocity by (3 r / T) / (6 r) d = d / (2 T). */
static void test_start_and_first_update(void **state)
{
    (void)state;
    struct mtt_oracle o;
    const trk_real cov[3] = {4, 0, 4};
    assert_int_equal(mtt_oracle_init(&o, 1, cov, 0), 0);
    const long origin[1] = {0};
    struct trk_scan s = scan_at(0, NULL, 0); /* scan 0: missed */
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    struct trk_detection d1 = det_at(10, 20);
    s = scan_at(1, &d1, 1);
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    assert_null(mtt_oracle_track(&o, 0)); /* one detection: no track yet */
    struct trk_detection d2 = det_at(30, 8);
    s = scan_at(3, &d2, 1); /* scan 3 (scan 2 not given): dt = 2 T_S */
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    const struct mtt_oracle_track *tr = mtt_oracle_track(&o, 0);
    assert_non_null(tr);
    assert_int_equal(tr->start_scan, 2); /* the third scan the oracle was given */
    const double dt = 2 * T_S;
    TRK_ASSERT_NEAR(tr->x[X], 30, 0, 0);
    TRK_ASSERT_NEAR(tr->x[Y], 8, 0, 0);
    TRK_ASSERT_NEAR(tr->x[VX], 20 / dt, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(tr->x[VY], -12 / dt, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(X, X)], 4, 0, 0);
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(X, VX)], 4 / dt, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(VY, VY)], 8 / (dt * dt), 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(X, Y)], 0, 0, 0);
    /* scan 5, dt again: the prediction (30 + 20, 8 - 12) = (50, -4); detection 6 m off in x */
    struct trk_detection d3 = det_at(56, -4);
    s = scan_at(5, &d3, 1);
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    TRK_ASSERT_NEAR(tr->x[X], 50 + 5.0 * 6 / 6, TRK_TOL(1e-12, 1e-4), 0);
    TRK_ASSERT_NEAR(tr->x[Y], -4, TRK_TOL(1e-12, 1e-4), 0);
    TRK_ASSERT_NEAR(tr->x[VX], 20 / dt + 6 / (2 * dt), TRK_TOL(1e-12, 1e-5), 0);
    TRK_ASSERT_NEAR(tr->x[VY], -12 / dt, TRK_TOL(1e-12, 1e-5), 0);
    /* position variance after the update: 5 r - (5 r)^2 / 6 r = 5 r / 6 */
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(X, X)], 5.0 * 4 / 6, 0, TRK_TOL(1e-12, 1e-5));
    mtt_oracle_free(&o);
}

/* A scan without the target's detection keeps the prediction; the target's
 * end removes its track for good; a detection's own covariance is used */
static void test_miss_end_own_cov(void **state)
{
    (void)state;
    struct mtt_oracle o;
    const trk_real cov[3] = {1, 0, 1};
    assert_int_equal(mtt_oracle_init(&o, 1, cov, 0), 0);
    const long origin[1] = {0};
    for (long k = 0; k < 2; k++) {
        struct trk_detection d = det_at(10 * (double)k, 0);
        const struct trk_scan s = scan_at(k, &d, 1);
        assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    }
    struct trk_scan s = scan_at(2, NULL, 0); /* missed: predicted to (20, 0) */
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    const struct mtt_oracle_track *tr = mtt_oracle_track(&o, 0);
    TRK_ASSERT_NEAR(tr->x[X], 20, TRK_TOL(1e-12, 1e-5), 0);
    /* predicted position variance (q = 0) over T from P_pp 1, P_pv 1 / T,
     * P_vv 2 / T^2: 1 + 2 T (1 / T) + T^2 (2 / T^2) = 5 */
    TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(X, X)], 5, 0, TRK_TOL(1e-12, 1e-5));
    /* scan 3: P_pp 5 + 2 T (3 / T) + 2 = 13 (P_pv was 1 / T + T (2 / T^2));
     * a detection on the predicted x, 2 m off in y, with its own covariance
     * 13 I: S = 26, y moves by 2 x 13 / 26 = 1 (with the sensor's R = I:
     * 2 x 13 / 14) */
    struct trk_detection d = det_at(30, 2);
    d.cov_m2[TRK_COV2_XX] = d.cov_m2[TRK_COV2_YY] = 13;
    d.has_cov = 1;
    s = scan_at(3, &d, 1);
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    TRK_ASSERT_NEAR(tr->x[X], 30, TRK_TOL(1e-12, 1e-5), 0);
    TRK_ASSERT_NEAR(tr->x[Y], 1, TRK_TOL(1e-12, 1e-6), 0);
    assert_int_equal(mtt_oracle_end(&o, 0), 1);
    assert_null(mtt_oracle_track(&o, 0));
    assert_int_equal(mtt_oracle_end(&o, 0), 0);
    for (long k = 4; k < 7; k++) { /* no restart */
        struct trk_detection e = det_at(10 * (double)k, 0);
        const struct trk_scan se = scan_at(k, &e, 1);
        assert_int_equal(mtt_oracle_scan(&o, &se, origin, NULL), 0);
        assert_null(mtt_oracle_track(&o, 0));
    }
    mtt_oracle_free(&o);
}

static void test_refused(void **state)
{
    (void)state;
    struct mtt_oracle o;
    const trk_real bad[3] = {1, 2, 1}, neg[3] = {-1, 0, 1}, cov[3] = {1, 0, 1};
    assert_int_equal(mtt_oracle_init(&o, 1, bad, 0), -1);
    assert_int_equal(mtt_oracle_init(&o, 1, neg, 0), -1);
    assert_int_equal(mtt_oracle_init(&o, 1, cov, -1), -1);
    assert_int_equal(mtt_oracle_init(&o, 1, cov, 0), 0);
    struct trk_detection d = det_at(0, 0);
    const long beyond[1] = {1}, origin[1] = {0};
    struct trk_scan s = scan_at(0, &d, 1);
    assert_int_equal(mtt_oracle_scan(&o, &s, beyond, NULL), -1); /* origin beyond the targets */
    assert_int_equal(mtt_oracle_scan(&o, &s, NULL, NULL), -1);
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    s = scan_at(1, &d, 1);
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), 0);
    s = scan_at(0, &d, 1); /* back in time */
    assert_int_equal(mtt_oracle_scan(&o, &s, origin, NULL), -1);
    mtt_oracle_free(&o);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_cv),
        cmocka_unit_test(test_start_and_first_update),
        cmocka_unit_test(test_miss_end_own_cov),
        cmocka_unit_test(test_refused),
    };
    return trk_run_tests("mtt_oracle", tests, NULL, NULL);
}
