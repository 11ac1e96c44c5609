/* test_special_f.c - F distribution (even degrees of freedom): tails against
 * closed forms, both tails small without cancellation, quantile round trips,
 * bad arguments; chi-square upper tail at large x (overflow regression). */
#include "trk_test.h"
#include "trk/special.h"

/* Closed forms with a = dof2/2, b = dof1/2, r = dof1 z / dof2, x = 1/(1+r):
 *   b = 1:  sf = (1 + r)^-a
 *   a = 1:  cdf = (r / (1 + r))^b
 *   F(4,4): sf = x^3 (1 + 3r)        F(6,4): sf = x^4 (1 + 4r + 6r^2) */
static void test_f_closed_forms(void **state)
{
    (void)state;
    const double zs[] = {1e-6, 0.01, 0.3, 1, 2.5, 10, 99, 1e4};
    const double rel = TRK_TOL(4e-14, 2e-5);
    for (size_t i = 0; i < sizeof zs / sizeof zs[0]; i++) {
        const double z = zs[i];
        const int d2s[] = {2, 6, 40, 500};
        for (size_t j = 0; j < 4; j++) {
            const int d2 = d2s[j];
            const double a = d2 / 2.0, r = 2 * z / d2;
            const double want = exp(-a * log1p(r));
            if (TRK_TEST_IS_FLOAT && want < 1e-30) continue;
            TRK_ASSERT_NEAR(trk_f_sf(2, d2, (trk_real)z), want, 0, rel);
        }
        const int d1s[] = {2, 8, 50};
        for (size_t j = 0; j < 3; j++) {
            const int d1 = d1s[j];
            const double b = d1 / 2.0, r = d1 * z / 2;
            const double want = exp(b * (log(r) - log1p(r)));
            if (TRK_TEST_IS_FLOAT && want < 1e-30) continue;
            TRK_ASSERT_NEAR(trk_f_cdf(d1, 2, (trk_real)z), want, 0, rel);
        }
        double r = z, x = 1 / (1 + r);
        TRK_ASSERT_NEAR(trk_f_sf(4, 4, (trk_real)z), x * x * x * (1 + 3 * r), 0, rel);
        r = 1.5 * z;
        x = 1 / (1 + r);
        TRK_ASSERT_NEAR(trk_f_sf(6, 4, (trk_real)z), x * x * x * x * (1 + 4 * r + 6 * r * r), 0, rel);
    }
    /* ends */
    assert_true(trk_f_sf(4, 6, 0) == 1);
    assert_true(trk_f_cdf(4, 6, 0) == 0);
    assert_true(trk_f_sf(4, 6, (trk_real)INFINITY) == 0);
    assert_true(trk_f_cdf(4, 6, (trk_real)INFINITY) == 1);
}

/* Both tails are sums of positive terms: cdf + sf = 1, and each small tail is
 * right to full relative precision (checked where a closed form exists). */
static void test_f_tails(void **state)
{
    (void)state;
    const int d1s[] = {2, 4, 10, 50, 64};
    const int d2s[] = {2, 4, 12, 100, 1000};
    const double zs[] = {0.05, 0.5, 1, 2, 8};
    for (size_t i = 0; i < 5; i++)
        for (size_t j = 0; j < 5; j++)
            for (size_t k = 0; k < 5; k++) {
                const double s = (double)trk_f_sf(d1s[i], d2s[j], (trk_real)zs[k]);
                const double c = (double)trk_f_cdf(d1s[i], d2s[j], (trk_real)zs[k]);
                assert_true(s >= 0 && s <= 1 && c >= 0 && c <= 1);
                TRK_ASSERT_NEAR(s + c, 1, TRK_TOL(2e-14, 2e-5), 0);
            }
    /* far upper tail, F(2, 1000) at z = 300: (1 + 0.6)^-500 = 6.6e-103, no 1 - cdf */
    if (!TRK_TEST_IS_FLOAT) {
        TRK_ASSERT_NEAR(trk_f_sf(2, 1000, 300), exp(-500 * log1p(0.6)), 0, 1e-13);
        /* far lower tail, F(50, 2) at z = 1e-3: (r/(1+r))^25, r = 0.025 */
        TRK_ASSERT_NEAR(trk_f_cdf(50, 2, 1e-3), exp(25 * (log(0.025) - log1p(0.025))), 0, 1e-13);
    }
    /* monotone in z */
    double prev = 1;
    for (int i = 1; i <= 200; i++) {
        double s = (double)trk_f_sf(20, 60, (trk_real)(0.05 * i));
        assert_true(s <= prev);
        prev = s;
    }
}

static void test_f_quantile(void **state)
{
    (void)state;
    trk_real z;
    /* F(2, 2) upper 1 %: sf = 1/(1+z) -> 99 */
    TRK_ASSERT_OK(trk_f_inv_sf(2, 2, TRK_REAL_C(0.01), &z));
    TRK_ASSERT_NEAR(z, 99, 0, TRK_TOL(1e-14, 1e-5));
    /* F(4, 4): sf(z) = (1 + 3z)/(1 + z)^3 */
    TRK_ASSERT_OK(trk_f_inv_sf(4, 4, TRK_REAL_C(0.05), &z));
    TRK_ASSERT_NEAR((1 + 3 * (double)z) / pow(1 + (double)z, 3), 0.05, 0, TRK_TOL(1e-13, 1e-5));
    /* round trips over Kennedy's range of dof and small/large p */
    const double ps[] = {1e-10, 1e-4, 0.01, 0.05, 0.5, 0.9, 0.999};
    const int d1s[] = {2, 4, 10, 26, 50, 64};
    const int d2s[] = {2, 6, 24, 96, 500, 4000};
    for (size_t i = 0; i < 6; i++)
        for (size_t j = 0; j < 6; j++)
            for (size_t k = 0; k < 7; k++) {
                if (TRK_TEST_IS_FLOAT && ps[k] < 1e-4) continue;
                TRK_ASSERT_OK(trk_f_inv_sf(d1s[i], d2s[j], (trk_real)ps[k], &z));
                assert_true(z > 0 && isfinite((double)z));
                TRK_ASSERT_NEAR(trk_f_sf(d1s[i], d2s[j], z), ps[k], 0, TRK_TOL(1e-12, 2e-4));
            }
}

static void test_f_bad(void **state)
{
    (void)state;
    trk_real z = 0;
    assert_true(isnan((double)trk_f_sf(3, 4, 1)));  /* odd dof */
    assert_true(isnan((double)trk_f_sf(4, 5, 1)));
    assert_true(isnan((double)trk_f_sf(0, 4, 1)));
    assert_true(isnan((double)trk_f_sf(4, 4, -1)));
    assert_true(isnan((double)trk_f_cdf(4, 4, (trk_real)NAN)));
    assert_true(isnan((double)trk_f_cdf(4, -2, 1)));
    TRK_ASSERT_STATUS(trk_f_inv_sf(4, 4, 0, &z), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_f_inv_sf(4, 4, 1, &z), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_f_inv_sf(4, 4, (trk_real)NAN, &z), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_f_inv_sf(3, 4, TRK_REAL_C(0.1), &z), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_f_inv_sf(4, 4, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
}

/* Regression (trk_chi2_sf/cdf): the finite sums' terms grow like y^j/j! and
 * overflowed float at x = 800, dof = 50 (the clutter density test on a
 * window of large rho V_g) before the rescaling; values from 40-digit mpmath. */
static void test_chi2_large_x(void **state)
{
    (void)state;
    TRK_ASSERT_NEAR(trk_chi2_sf(50, 120), 1.0958807112599779112e-7, 0, TRK_TOL(1e-13, 1e-4));
    assert_true(trk_chi2_cdf(50, 800) == 1);
    const double s = (double)trk_chi2_sf(50, 800);
    assert_true(s >= 0 && s < 1e-30);
    if (!TRK_TEST_IS_FLOAT) {
        TRK_ASSERT_NEAR(s, 9.2414517563327586669e-136, 0, 1e-12);
        TRK_ASSERT_NEAR(trk_chi2_sf(501, 800), 4.0336426175993281882e-16, 0, 1e-11);
        assert_true(trk_chi2_sf(1000, 4000) == 0); /* 2.3e-353 underflows cleanly */
        assert_true(trk_chi2_cdf(1000, 4000) == 1);
    }
}

/* Huge and infinite x: the upper tail is 0 and the cdf 1 at every dof,
 * never NaN (x = +inf at dof >= 3 and x = 1e300 or the
 * largest real at odd dof >= 5 gave NaN). */
static void test_chi2_huge_x(void **state)
{
    (void)state;
    const trk_real xs[] = {(trk_real)INFINITY, TRK_REAL_MAX, TRK_TEST_IS_FLOAT ? (trk_real)1e30 : (trk_real)1e300,
                           TRK_TEST_IS_FLOAT ? (trk_real)1e6 : (trk_real)1e5};
    for (int dof = 1; dof <= 25; dof++)
        for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
            const trk_real c = trk_chi2_cdf(dof, xs[i]), q = trk_chi2_sf(dof, xs[i]);
            if (!(c == 1 && q == 0)) fail_msg("dof %d x %g: cdf %g sf %g", dof, (double)xs[i], (double)c, (double)q);
        }
    assert_true(isnan(trk_chi2_cdf(3, (trk_real)NAN)) && isnan(trk_chi2_sf(0, 1)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_f_closed_forms),
        cmocka_unit_test(test_f_tails),
        cmocka_unit_test(test_f_quantile),
        cmocka_unit_test(test_f_bad),
        cmocka_unit_test(test_chi2_large_x),
        cmocka_unit_test(test_chi2_huge_x),
    };
    return trk_run_tests("special_f", tests, NULL, NULL);
}
