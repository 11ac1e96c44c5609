/* test_tracker_ab.c - the constant-gain (alpha-beta) track filter in the
 * track table (TRK_WITH_ALPHA_BETA = 1, config.h; src/filter_ab_impl.h):
 *   - parameters: the Kalman filter by default; alpha-beta accepted, refused
 *     without process noise ("filter"), an unknown filter refused;
 *   - a target seen every scan (the same scans through two tables): the
 *     first update, from two-point differencing, is the CV Kalman filter's;
 *     once the Kalman gain has converged the alpha-beta track is the CV
 *     track, and its covariance the steady state's;
 *   - a grown-up track's update is the alpha-beta recursion by hand (gains
 *     of trk_cv_steady_state), a missed scan the prediction alone with the
 *     steady state's predicted covariance;
 *   - a second scan at the track's own time is one Kalman update of its
 *     covariance;
 *   - two targets in clutter at P_D 0.8 are both held.
 * tests/test_tracker_ab.mk links this program with the scan and the
 * parameter check compiled in the same configuration. */
#undef TRK_WITH_ALPHA_BETA
#define TRK_WITH_ALPHA_BETA 1
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/kalman.h"
#include "trk/tracker.h"

static struct trk_tracker tk_cv, tk_ab;

#define DT_S 4.0
#define SCAN_US(k) ((int64_t)(k) * 4000000)

static void test_params(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    trk_tracker_default_params(&p);
    assert_int_equal(p.filter, TRK_FILTER_KALMAN);
    p.filter = TRK_FILTER_ALPHA_BETA;
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    assert_null(field);
    TRK_ASSERT_OK(trk_tracker_init(&tk_ab, &p));
    p.process_noise_q = 0;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_UNSUPPORTED);
    assert_string_equal(field, "filter");
    p.process_noise_q = TRK_REAL_C(0.01);
    p.filter = (enum trk_filter_kind)7;
    TRK_ASSERT_STATUS(trk_tracker_init(&tk_ab, &p), TRK_E_ARG);
}

/* The one live track of t (NULL when there is not exactly one). */
static const struct trk_track *only_track(const struct trk_tracker *t)
{
    const struct trk_track *one = NULL;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(t, i);
        if (!tr || (tr->status != TRK_TRACK_TENTATIVE && tr->status != TRK_TRACK_CONFIRMED)) continue;
        if (one) return NULL;
        one = tr;
    }
    return one;
}

/* One target at (100, 50) m moving (3, -2) m/s, seen every scan (P_D 1, R
 * = 25 I, clutter density 1e-12: beta0 ~ 1e-11), into the CV table and
 * the alpha-beta table; a missed scan draws its noise all the same. */
static void one_target_scan(int k, uint64_t *rng, int detected)
{
    const double ex = 5 * trk_test_nrand(rng), ey = 5 * trk_test_nrand(rng); /* in this order */
    struct trk_detection d = trk_test_det_at(100 + 3 * DT_S * k + ex, 50 - 2 * DT_S * k + ey);
    const struct trk_scan s = {SCAN_US(k), 0, detected ? 1u : 0u, &d, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_cv, &s, &rep));
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_ab, &s, &rep));
}

static void init_pair(double pd, double lambda)
{
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, lambda);
    p.sensor[0].pd = (trk_real)pd;
    /* no velocity prior on the two-point start: the alpha-beta start-up
     * (the least-squares line through its points) does not weigh one, and
     * the comparison is of the filters, not of the start */
    p.init_speed_sigma_mps = TRK_REAL_C(1e6);
    TRK_ASSERT_OK(trk_tracker_init(&tk_cv, &p));
    p.filter = TRK_FILTER_ALPHA_BETA;
    TRK_ASSERT_OK(trk_tracker_init(&tk_ab, &p));
}

static void test_converged_is_cv(void **state)
{
    (void)state;
    init_pair(1, 1e-12);
    uint64_t rng = 11;
    struct trk_cv_steady ss;
    TRK_ASSERT_OK(trk_cv_steady_state((trk_real)DT_S, TRK_REAL_C(1e-3), 25, &ss));
    for (int k = 0; k < 200; k++) {
        one_target_scan(k, &rng, 1);
        if (k == 2) { /* the first update: from two-point differencing, the Kalman filter's own */
            const struct trk_track *a = only_track(&tk_cv), *b = only_track(&tk_ab);
            assert_non_null(a);
            assert_non_null(b);
            for (int j = 0; j < TRK_CV2_NX; j++)
                TRK_ASSERT_NEAR(b->x[j], a->x[j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-9, 1e-5));
        }
        if (k < 170) continue;
        const struct trk_track *a = only_track(&tk_cv), *b = only_track(&tk_ab);
        assert_non_null(a);
        assert_non_null(b);
        assert_int_equal(a->status, TRK_TRACK_CONFIRMED);
        assert_int_equal(b->status, TRK_TRACK_CONFIRMED);
        for (int j = 0; j < TRK_CV2_NX; j++)
            TRK_ASSERT_NEAR(b->x[j], a->x[j], TRK_TOL(1e-7, 1e-2), TRK_TOL(1e-9, 1e-4));
        for (int ax = 0; ax < 2; ax++) { /* the alpha-beta track's covariance: the steady state's */
            const int ip = ax ? TRK_CV2_Y : TRK_CV2_X, iv = ax ? TRK_CV2_VY : TRK_CV2_VX;
            TRK_ASSERT_NEAR(b->p[TRK_CV2_P(ip, ip)], ss.post[0], 0, TRK_TOL(1e-12, 1e-5));
            TRK_ASSERT_NEAR(b->p[TRK_CV2_P(ip, iv)], ss.post[1], 0, TRK_TOL(1e-12, 1e-5));
            TRK_ASSERT_NEAR(b->p[TRK_CV2_P(iv, iv)], ss.post[2], 0, TRK_TOL(1e-12, 1e-4));
            TRK_ASSERT_NEAR(b->p[TRK_CV2_P(ip, ip)], a->p[TRK_CV2_P(ip, ip)], 0, TRK_TOL(1e-6, 1e-3));
            TRK_ASSERT_NEAR(b->p[TRK_CV2_P(iv, iv)], a->p[TRK_CV2_P(iv, iv)], 0, TRK_TOL(1e-6, 1e-3));
            assert_true(b->p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_Y)] == 0);
        }
    }
}

static void test_one_update_by_hand(void **state)
{
    (void)state;
    init_pair(1, 1e-12);
    uint64_t rng = 5;
    for (int k = 0; k < 20; k++) one_target_scan(k, &rng, 1);
    assert_non_null(only_track(&tk_ab));
    struct trk_track before = *only_track(&tk_ab);
    struct trk_cv_steady ss;
    TRK_ASSERT_OK(trk_cv_steady_state((trk_real)DT_S, TRK_REAL_C(1e-3), 25, &ss));
    /* scan 20, detected: x_p = x + T v; x = x_p + alpha nu, v += (beta / T) nu */
    uint64_t peek = rng;
    const double zx = 100 + 3 * DT_S * 20 + 5 * trk_test_nrand(&peek);
    const double zy = 50 - 2 * DT_S * 20 + 5 * trk_test_nrand(&peek);
    one_target_scan(20, &rng, 1);
    const struct trk_track *tr = only_track(&tk_ab);
    assert_non_null(tr);
    const double px = before.x[TRK_CV2_X] + DT_S * before.x[TRK_CV2_VX];
    const double py = before.x[TRK_CV2_Y] + DT_S * before.x[TRK_CV2_VY];
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_X], px + ss.alpha * (zx - px), TRK_TOL(1e-8, 1e-3), 0);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_Y], py + ss.alpha * (zy - py), TRK_TOL(1e-8, 1e-3), 0);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_VX], before.x[TRK_CV2_VX] + ss.k_vel_per_s * (zx - px), TRK_TOL(1e-9, 1e-4), 0);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_VY], before.x[TRK_CV2_VY] + ss.k_vel_per_s * (zy - py), TRK_TOL(1e-9, 1e-4), 0);
    /* scan 21, missed: the prediction, and its covariance (the steady state's predicted one) */
    before = *tr;
    one_target_scan(21, &rng, 0);
    tr = only_track(&tk_ab);
    assert_non_null(tr);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_X], before.x[TRK_CV2_X] + DT_S * before.x[TRK_CV2_VX], TRK_TOL(1e-9, 1e-3), 0);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_Y], before.x[TRK_CV2_Y] + DT_S * before.x[TRK_CV2_VY], TRK_TOL(1e-9, 1e-3), 0);
    assert_true(tr->x[TRK_CV2_VX] == before.x[TRK_CV2_VX]);
    for (int ax = 0; ax < 2; ax++) {
        const int ip = ax ? TRK_CV2_Y : TRK_CV2_X, iv = ax ? TRK_CV2_VY : TRK_CV2_VX;
        TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(ip, ip)], ss.pred[0], 0, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(ip, iv)], ss.pred[1], 0, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(tr->p[TRK_CV2_P(iv, iv)], ss.pred[2], 0, TRK_TOL(1e-12, 1e-4));
    }
}

/* A second scan at the track's own time (no gap, no steady state): one
 * Kalman update of the track's own covariance, x += P_xx / (P_xx + r) nu. */
static void test_same_time_is_a_kalman_update(void **state)
{
    (void)state;
    init_pair(1, 1e-12);
    uint64_t rng = 5;
    for (int k = 0; k < 20; k++) one_target_scan(k, &rng, 1);
    const struct trk_track *tr = only_track(&tk_ab);
    assert_non_null(tr);
    const struct trk_track before = *tr;
    struct trk_detection d = trk_test_det_at(before.x[TRK_CV2_X] + 6, before.x[TRK_CV2_Y] - 4);
    const struct trk_scan s = {SCAN_US(19), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_ab, &s, NULL));
    tr = only_track(&tk_ab);
    assert_non_null(tr);
    const double px = before.p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)], py = before.p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)];
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_X], before.x[TRK_CV2_X] + px / (px + 25) * 6, TRK_TOL(1e-7, 1e-3), 0);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_Y], before.x[TRK_CV2_Y] - py / (py + 25) * 4, TRK_TOL(1e-7, 1e-3), 0);
    assert_true(tr->p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] < px);
}

/* Two targets 60 m apart through uniform clutter (3 per scan over 1 km x
 * 600 m), P_D 0.8: the alpha-beta table holds both, near the truth. */
static void test_two_targets_in_clutter(void **state)
{
    (void)state;
    init_pair(0.8, 1e-5);
    uint64_t rng = 7;
    for (int k = 0; k < 40; k++) {
        struct trk_detection d[8];
        const size_t n = trk_test_pair_scan(k, DT_S, 60, 3, &rng, d);
        const struct trk_scan s = {SCAN_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_ab, &s, NULL));
    }
    int held[2] = {0, 0};
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk_ab, i);
        if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
        for (int t = 0; t < 2; t++)
            if (fabs(tr->x[TRK_CV2_X] - (100 + 5 * DT_S * 39)) < 15 && fabs(tr->x[TRK_CV2_Y] - 60 * t) < 15 &&
                fabs(tr->x[TRK_CV2_VX] - 5) < 2)
                held[t]++;
    }
    assert_int_equal(held[0], 1);
    assert_int_equal(held[1], 1);
    assert_int_equal(trk_test_count_confirmed(&tk_ab), 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_params),
        cmocka_unit_test(test_converged_is_cv),
        cmocka_unit_test(test_one_update_by_hand),
        cmocka_unit_test(test_same_time_is_a_kalman_update),
        cmocka_unit_test(test_two_targets_in_clutter),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
