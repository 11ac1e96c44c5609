/* test_gate.c - gate threshold (chi-square inverse), volume and distance;
 * chi-square cdf/sf against closed forms. */
#include "trk_test.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/special.h"

static void test_gamma_closed_forms(void **state)
{
    (void)state;
    trk_real g;
    /* nz = 2: -2 ln(1 - P_G) exactly */
    TRK_ASSERT_OK(trk_gate_gamma(2, TRK_REAL_C(0.99), &g));
    TRK_ASSERT_NEAR(g, -2 * log(1 - (double)TRK_REAL_C(0.99)), TRK_TOL(1e-15, 1e-6), TRK_TOL(1e-15, 1e-6));
    /* nz = 1: gamma = z^2 with z the two-sided normal quantile: P_G = 0.95 -> 1.959963984540054^2 */
    TRK_ASSERT_OK(trk_gate_gamma(1, TRK_REAL_C(0.95), &g));
    TRK_ASSERT_NEAR(g, 3.841458820694124, 0, TRK_TOL(1e-13, 1e-5));
    /* nz = 3, P_G = 0.99: 11.344866730144373 (chi2.ppf(0.99, 3)) */
    TRK_ASSERT_OK(trk_gate_gamma(3, TRK_REAL_C(0.99), &g));
    TRK_ASSERT_NEAR(g, 11.344866730144373, 0, TRK_TOL(1e-13, 1e-5));
    /* extreme gate probabilities: round trip through the cdf */
    const double pgs[] = {1e-6, 0.5, 0.999999};
    for (int nz = 1; nz <= 3; nz++)
        for (size_t i = 0; i < 3; i++) {
            TRK_ASSERT_OK(trk_gate_gamma(nz, (trk_real)pgs[i], &g));
            TRK_ASSERT_NEAR(trk_chi2_cdf(nz, g), pgs[i], 0, TRK_TOL(1e-12, 1e-4));
        }
}

static void test_gamma_bad(void **state)
{
    (void)state;
    trk_real g = 0;
    TRK_ASSERT_STATUS(trk_gate_gamma(2, 0, &g), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_gate_gamma(2, 1, &g), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_gate_gamma(2, NAN, &g), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_gate_gamma(4, TRK_REAL_C(0.9), &g), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_gate_gamma(0, TRK_REAL_C(0.9), &g), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_gate_gamma(2, TRK_REAL_C(0.9), NULL), TRK_E_ARG);
}

static void test_chi2(void **state)
{
    (void)state;
    /* dof 2: cdf = 1 - exp(-x/2); dof 4: sf = exp(-x/2)(1 + x/2) */
    /* x = 200: tails near 1e-44, below float's normal range: double only */
    const double xs[] = {1e-8, 0.1, 1, 5, 30, 200};
    for (size_t i = 0; i < (TRK_TEST_IS_FLOAT ? 5u : 6u); i++) {
        double x = xs[i];
        TRK_ASSERT_NEAR(trk_chi2_cdf(2, (trk_real)x), -expm1(-x / 2), 0, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_NEAR(trk_chi2_sf(2, (trk_real)x), exp(-x / 2), 1e-300, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_NEAR(trk_chi2_sf(4, (trk_real)x), exp(-x / 2) * (1 + x / 2), 1e-300, TRK_TOL(1e-13, 1e-5));
        /* dof 1: sf = erfc(sqrt(x/2)); dof 3: sf = erfc(sqrt(x/2)) + sqrt(2x/pi) e^(-x/2) */
        TRK_ASSERT_NEAR(trk_chi2_sf(1, (trk_real)x), erfc(sqrt(x / 2)), 1e-300, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_NEAR(trk_chi2_sf(3, (trk_real)x),
                        erfc(sqrt(x / 2)) + sqrt(2 * x / 3.141592653589793) * exp(-x / 2), 1e-300,
                        TRK_TOL(1e-13, 1e-5));
    }
    /* tiny lower tail without cancellation: P(chi2(10) <= 0.01) = 2.5933e-14 (exact sum, 40 digits) */
    TRK_ASSERT_NEAR(trk_chi2_cdf(10, TRK_REAL_C(0.01)), 2.5933391898395395e-14, 0, TRK_TOL(1e-12, 1e-4));
    assert_true(isnan(trk_chi2_cdf(0, 1)));
    assert_true(isnan(trk_chi2_sf(2, -1)));
}

static void test_volume_and_d2(void **state)
{
    (void)state;
    /* S = diag(4, 9): sqrt(det S) = 6; V = pi gamma 6 for nz = 2 */
    TRK_ASSERT_NEAR(trk_gate_volume(2, 9, log(36.0)), 3.141592653589793 * 9 * 6, 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(trk_gate_volume(1, 4, log(9.0)), 2 * 2 * 3, 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(trk_gate_volume(3, 4, log(64.0)), 4.0 / 3 * 3.141592653589793 * 8 * 8, 0, TRK_TOL(1e-14, 1e-6));
    const trk_real nu[2] = {2, 3}, x[4] = {0, 0, 0, 0}, p[16] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 8, 0, 0, 0, 0, 1};
    const trk_real r[4] = {1, 0, 0, 1};
    struct trk_innovation inn;
    TRK_ASSERT_OK(trk_kalman_innovation(4, 2, trk_cv2_h, r, x, p, &inn)); /* S = diag(4, 9) */
    TRK_ASSERT_NEAR(trk_gate_d2(&inn, nu), 2.0, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(inn.log_det_s, log(36.0), 0, TRK_TOL(1e-15, 1e-6));
    /* the volume from the innovation: the same formula, and at gamma = d2 the
     * ellipse through that detection (Kennedy's V_g) */
    TRK_ASSERT_NEAR(trk_gate_volume_inn(&inn, 9), 3.141592653589793 * 9 * 6, 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(trk_gate_volume_inn(&inn, trk_gate_d2(&inn, nu)), 3.141592653589793 * 2 * 6, 0,
                    TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(trk_gate_volume_inn(&inn, 9), trk_gate_volume(2, 9, inn.log_det_s), 0, TRK_TOL(1e-14, 1e-6));
    struct trk_innovation big = inn; /* sqrt(det S) overflowed (float): from ln det S */
    big.sqrt_det_s = (trk_real)INFINITY;
    TRK_ASSERT_NEAR(trk_gate_volume_inn(&big, 9), 3.141592653589793 * 9 * 6, 0, TRK_TOL(1e-14, 1e-6));
    /* less-or-equal rule, NaN outside */
    assert_true(trk_gate_inside(TRK_REAL_C(2.0), TRK_REAL_C(2.0)));
    assert_false(trk_gate_inside(TRK_REAL_C(2.001), TRK_REAL_C(2.0)));
    assert_false(trk_gate_inside(NAN, TRK_REAL_C(2.0)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gamma_closed_forms),
        cmocka_unit_test(test_gamma_bad),
        cmocka_unit_test(test_chi2),
        cmocka_unit_test(test_volume_and_d2),
    };
    return trk_run_tests("gate", tests, NULL, NULL);
}
