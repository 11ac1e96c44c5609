/* test_alpha_beta.c - the steady state of the one-axis CV Kalman filter and
 * the alpha-beta gains it gives (trk/kalman.h trk_cv_steady_state):
 *   - against the Riccati recursion of the same model iterated to its fixed
 *     point here (F = [1 T; 0 1], Q = q [T^3/3 T^2/2; T^2/2 T], H = [1 0]),
 *     over tracking indices from 1e-4 to 1e4;
 *   - the two relations of the gains (beta^2 / (1 - alpha) = lambda^2 and
 *     alpha^2 + alpha beta - 2 beta + beta^2 / 6 = 0);
 *   - the limits: alpha -> sqrt(2 lambda) for small lambda, alpha -> 1 for
 *     large;
 *   - refusals. */
#include "trk_test.h"
#include "trk/kalman.h"

/* The Riccati recursion M = F P F' + Q, K = M H' / (M_pp + r), P = (I - K H)
 * M in long double from P = r I until it stops moving: the gains and both
 * covariances. */
struct riccati {
    long double alpha, k_vel, pred[3], post[3];
};

static struct riccati riccati_fixed_point(double t, double q, double r)
{
    long double pp = r, pv = 0, vv = r, mpp = 0, mpv = 0, mvv = 0;
    for (int it = 0; it < 2000000; it++) {
        mpp = pp + 2 * t * pv + t * t * vv + q * t * t * t / 3;
        mpv = pv + t * vv + q * t * t / 2;
        mvv = vv + q * t;
        const long double s = mpp + r, k1 = mpp / s, k2 = mpv / s;
        const long double npp = (1 - k1) * mpp, npv = (1 - k1) * mpv, nvv = mvv - k2 * mpv;
        const int still = npp == pp && npv == pv && nvv == vv;
        pp = npp;
        pv = npv;
        vv = nvv;
        if (still) break;
    }
    struct riccati f = {mpp / (mpp + r), mpv / (mpp + r), {mpp, mpv, mvv}, {pp, pv, vv}};
    return f;
}

static void test_against_riccati(void **state)
{
    (void)state;
    static const double cases[][3] = { /* dt_s, q, r */
        {4, 1e-3, 25}, {1, 0.01, 1}, {10, 0.1, 100}, {0.5, 1e-6, 400}, {60, 1, 4},
        {2, 1e-9, 1e4}, {4, 100, 1}, {1e-3, 1, 1}, {30, 5, 1e-2},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const double t = cases[c][0], q = cases[c][1], r = cases[c][2];
        struct trk_cv_steady ss;
        TRK_ASSERT_OK(trk_cv_steady_state((trk_real)t, (trk_real)q, (trk_real)r, &ss));
        const struct riccati f = riccati_fixed_point(t, q, r);
        const double rel = TRK_TOL(1e-9, 2e-4);
        TRK_ASSERT_NEAR(ss.alpha, (double)f.alpha, 0, rel);
        TRK_ASSERT_NEAR(ss.k_vel_per_s, (double)f.k_vel, 0, rel);
        TRK_ASSERT_NEAR(ss.beta, (double)f.k_vel * t, 0, rel);
        for (int i = 0; i < 3; i++) {
            TRK_ASSERT_NEAR(ss.pred[i], (double)f.pred[i], 0, rel);
            TRK_ASSERT_NEAR(ss.post[i], (double)f.post[i], 0, TRK_TOL(1e-8, 2e-3));
        }
    }
}

static void test_relations(void **state)
{
    (void)state;
    for (double lambda = 1e-4; lambda <= TRK_TOL(1e4, 1e2); lambda *= 3) { /* float: 1 - alpha rounds beyond 1e2 */
        const double t = 2, r = 9, q = lambda * lambda * r / (t * t * t);
        struct trk_cv_steady ss;
        TRK_ASSERT_OK(trk_cv_steady_state((trk_real)t, (trk_real)q, (trk_real)r, &ss));
        const double a = ss.alpha, b = ss.beta;
        TRK_ASSERT_NEAR(b * b / (1 - a), lambda * lambda, 0, TRK_TOL(1e-9, 1e-3));
        TRK_ASSERT_NEAR(a * a + a * b - 2 * b + b * b / 6, 0, TRK_TOL(1e-12, 1e-5) * (a * a + 2 * b), 0);
        assert_true(a > 0 && a < 1 && b > 0);
    }
    struct trk_cv_steady ss;
    TRK_ASSERT_OK(trk_cv_steady_state(1, TRK_REAL_C(1e-12), 1, &ss)); /* lambda 1e-6 */
    TRK_ASSERT_NEAR(ss.alpha, sqrt(2e-6), 0, 1e-3);
    TRK_ASSERT_OK(trk_cv_steady_state(1, TRK_REAL_C(1e12), 1, &ss)); /* lambda 1e6 */
    TRK_ASSERT_NEAR(ss.alpha, 1, TRK_TOL(1e-11, 1e-6), 0);
}

static void test_refusals(void **state)
{
    (void)state;
    struct trk_cv_steady ss;
    memset(&ss, 0x5a, sizeof ss);
    const struct trk_cv_steady before = ss;
    TRK_ASSERT_STATUS(trk_cv_steady_state(1, 1, 1, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state(0, 1, 1, &ss), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state(1, 0, 1, &ss), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state(1, 1, -1, &ss), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state((trk_real)NAN, 1, 1, &ss), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state(1, (trk_real)INFINITY, 1, &ss), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv_steady_state(1e6, 1e20, 1e-20, &ss), TRK_E_RANGE); /* lambda 1e29 */
    TRK_ASSERT_STATUS(trk_cv_steady_state(1e-6, (trk_real)TRK_TOL(1e-300, 1e-30), (trk_real)TRK_TOL(1e300, 1e30), &ss),
                      TRK_E_RANGE); /* q / r underflows: lambda and alpha 0 */
    assert_memory_equal(&ss, &before, sizeof ss);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_riccati),
        cmocka_unit_test(test_relations),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
