/* test_irf.c - the PDAF's information-reduction factor by quadrature
 * (trk/irf.h): against the importance-sampling reference values of q2.vec,
 * against a direct Monte Carlo of E_n[beta_1], closed forms at the limits,
 * monotonicity, the MRE driven by it, and bad input. */
#include "trk_test.h"
#include "trk/gate.h"
#include "trk/irf.h"
#include "trk/mre.h"
#include "trk/special.h"

/* The q2_pdaf cases of tests/vectors/q2.vec (independent importance
 * sampling): nz, pd, pg, lambda_vg, q2, tolerance (4 sqrt(2) se_ref). */
static const double q2_ref[][6] = {
    {2, 0.90000000000000002, 0.98999999999999999, 0.10000000000000001, 0.79408244418723439, 0.00010015180616971148},
    {2, 0.90000000000000002, 0.98999999999999999, 1, 0.50360341306552991, 0.00030220914933156123},
    {2, 0.90000000000000002, 0.98999999999999999, 3, 0.2667821365265593, 0.00021496242106266831},
    {2, 0.69999999999999996, 0.999, 0.5, 0.4752315219763058, 0.00031709549551402411},
    {2, 0.69999999999999996, 0.999, 2, 0.27037167008960328, 0.00022038520123443168},
    {2, 0.69999999999999996, 0.999, 5, 0.14380052456756581, 0.00012379189479024436},
    {2, 0.5, 0.99990000000000001, 0.20000000000000001, 0.38810283199636464, 0.00025516471751451173},
    {2, 0.5, 0.99990000000000001, 1, 0.24647624324955936, 0.00020513282778279393},
    {2, 0.5, 0.99990000000000001, 4, 0.11023110092013351, 9.8197506723355897e-05},
    {2, 1, 0.99999998477002028, 0.5, 0.94139551429183921, 0.00022394759518182435},
    {2, 1, 0.99999998477002028, 2, 0.79406624009254501, 0.00039387924754948956},
    {2, 1, 0.99999998477002028, 8, 0.45812513990671389, 0.0003231714032115532},
    {2, 0.80000000000000004, 0.94999999999999996, 0.29999999999999999, 0.48640786808650777, 0.00014759487700948285},
    {2, 0.80000000000000004, 0.94999999999999996, 1.5, 0.23974979709450076, 0.00016734318889306433},
};

static void test_irf_q2_reference(void **state)
{
    (void)state;
    static struct trk_irf irf;
    for (size_t c = 0; c < sizeof q2_ref / sizeof q2_ref[0]; c++) {
        const double *v = q2_ref[c];
        const double gamma = -2 * log(1 - v[2]); /* nz = 2 */
        TRK_ASSERT_OK(trk_irf_init(&irf, (int)v[0], (trk_real)gamma));
        trk_real q2;
        TRK_ASSERT_OK(trk_irf_q2(&irf, (trk_real)v[1], (trk_real)v[3], &q2));
        TRK_ASSERT_NEAR(q2, v[4], v[5], 0);
    }
}

/* E_n[beta_1] by plain Monte Carlo (nz = 2): the target's rho^2 ~ chi2(4)
 * truncated to [0, gamma] (chi2(4)/2 = E1 + E2, rejection), clutter
 * rho^2 = gamma U. Returns the mean, *se its standard error. */
static double beta1_mc(double gamma, double b, int n, int samples, uint64_t *rng, double *se)
{
    double s = 0, s2 = 0;
    for (int k = 0; k < samples; k++) {
        double r2;
        do {
            r2 = -2 * (log(1 - trk_test_urand(rng)) + log(1 - trk_test_urand(rng)));
        } while (r2 > gamma);
        const double l1 = exp(-r2 / 2);
        double sum = b + l1;
        for (int j = 0; j < n; j++) sum += exp(-gamma * trk_test_urand(rng) / 2);
        const double beta = l1 / sum;
        s += beta;
        s2 += beta * beta;
    }
    const double mean = s / samples;
    *se = sqrt((s2 / samples - mean * mean) / samples);
    return mean;
}

static void test_irf_beta1_monte_carlo(void **state)
{
    (void)state;
    static struct trk_irf irf;
    const double gammas[2] = {9.21, 25.0};
    const double bs[3] = {0.0, 0.05, 1.0};
    uint64_t rng = 12345;
    for (int g = 0; g < 2; g++) {
        TRK_ASSERT_OK(trk_irf_init(&irf, 2, (trk_real)gammas[g]));
        for (int ib = 0; ib < 3; ib++) {
            trk_real e[6];
            TRK_ASSERT_OK(trk_irf_beta1(&irf, (trk_real)bs[ib], 5, e));
            for (int n = 0; n <= 5; n += (n == 0 ? 1 : 2)) {
                double se;
                const double mc = beta1_mc(gammas[g], bs[ib], n, 200000, &rng, &se);
                TRK_ASSERT_NEAR(e[n], mc, 5 * se + TRK_TOL(1e-12, 1e-5), 0);
            }
        }
    }
}

/* Closed forms: no clutter and b = 0 give beta_1 = 1 (E_0 = 1, q2 = pd F);
 * the quadrature's tables hold the densities' normalisation. */
static void test_irf_limits(void **state)
{
    (void)state;
    static struct trk_irf irf;
    for (int nz = 1; nz <= 3; nz++) {
        const trk_real gammas[3] = {TRK_REAL_C(4.0), TRK_REAL_C(16.0), TRK_REAL_C(150.0)};
        for (int g = 0; g < 3; g++) {
            TRK_ASSERT_OK(trk_irf_init(&irf, nz, gammas[g]));
            trk_real e[1], q2;
            TRK_ASSERT_OK(trk_irf_beta1(&irf, 0, 0, e));
            TRK_ASSERT_NEAR(e[0], 1, TRK_TOL(1e-12, 1e-5), 0);
            TRK_ASSERT_OK(trk_irf_q2(&irf, TRK_REAL_C(0.8), 0, &q2));
            TRK_ASSERT_NEAR(q2, 0.8 * trk_chi2_cdf(nz + 2, gammas[g]), TRK_TOL(1e-12, 1e-5), 0);
            TRK_ASSERT_NEAR(irf.pg, trk_chi2_cdf(nz, gammas[g]), 0, TRK_TOL(1e-15, 1e-6));
            /* phi(t) + (1 - phi(t)) = 1 at every node (each a sum of up to
             * 800 radial terms: in float a few 1e-6 of rounding) */
            for (int k = 0; k < irf.n; k++)
                TRK_ASSERT_NEAR(irf.phi[k] + irf.one_m_phi[k], 1, TRK_TOL(1e-14, 1e-5), 0);
        }
    }
}

/* q2 falls with clutter and rises with pd; E_n[beta_1] falls with n and b. */
static void test_irf_monotone(void **state)
{
    (void)state;
    static struct trk_irf irf;
    TRK_ASSERT_OK(trk_irf_init(&irf, 2, TRK_REAL_C(16.0)));
    trk_real prev = 2;
    for (int i = 0; i <= 40; i++) {
        trk_real q2;
        TRK_ASSERT_OK(trk_irf_q2(&irf, TRK_REAL_C(0.9), (trk_real)i * TRK_REAL_C(0.5), &q2));
        assert_true(q2 < prev && q2 > 0);
        prev = q2;
    }
    trk_real lo, hi;
    TRK_ASSERT_OK(trk_irf_q2(&irf, TRK_REAL_C(0.7), 2, &lo));
    TRK_ASSERT_OK(trk_irf_q2(&irf, TRK_REAL_C(0.9), 2, &hi));
    assert_true(lo < hi);
    trk_real e1[10], e2[10];
    TRK_ASSERT_OK(trk_irf_beta1(&irf, TRK_REAL_C(0.1), 9, e1));
    TRK_ASSERT_OK(trk_irf_beta1(&irf, TRK_REAL_C(0.2), 9, e2));
    for (int n = 0; n < 10; n++) {
        assert_true(e2[n] < e1[n]);
        if (n > 0) assert_true(e1[n] < e1[n - 1]);
    }
}

/* The MRE driven by the quadrature (trk_irf_line_eval as its q2_fn): each
 * step's q2 is the quadrature's at that step's lambda_vg. */
static void test_irf_drives_mre(void **state)
{
    (void)state;
    static struct trk_irf irf;
    struct trk_mre_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2;
    p.dt_s = 1;
    p.q_m2_per_s3 = 1;
    p.r_m2 = 100;
    p.gate_prob = TRK_REAL_C(0.99);
    p.clutter_density = TRK_REAL_C(1e-5);
    trk_real gamma;
    TRK_ASSERT_OK(trk_gate_gamma(2, p.gate_prob, &gamma));
    TRK_ASSERT_OK(trk_irf_init(&irf, 2, gamma));
    struct trk_irf_line line = {&irf, TRK_REAL_C(0.9)};
    p.q2_fn = trk_irf_line_eval;
    p.q2_ctx = &line;
    struct trk_mre m;
    TRK_ASSERT_OK(trk_mre_init(&m, &p));
    struct trk_mre_result res;
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &res));
    trk_real q2;
    TRK_ASSERT_OK(trk_irf_q2(&irf, TRK_REAL_C(0.9), res.lambda_vg, &q2));
    TRK_ASSERT_NEAR(res.q2, q2, 0, TRK_TOL(1e-15, 1e-6));
    assert_true(res.q2 > 0 && res.q2 < TRK_REAL_C(0.9));
}

static void test_irf_bad_input(void **state)
{
    (void)state;
    static struct trk_irf irf;
    TRK_ASSERT_STATUS(trk_irf_init(NULL, 2, 9), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_irf_init(&irf, 0, 9), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_irf_init(&irf, 4, 9), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_irf_init(&irf, 2, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_irf_init(&irf, 2, 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_irf_init(&irf, 2, TRK_IRF_MAX_GAMMA * 2), TRK_E_RANGE);
    TRK_ASSERT_OK(trk_irf_init(&irf, 2, 9));
    trk_real q2, e[2];
    TRK_ASSERT_STATUS(trk_irf_q2(&irf, 0, 1, &q2), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_irf_q2(&irf, TRK_REAL_C(1.1), 1, &q2), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_irf_q2(&irf, TRK_REAL_C(0.9), -1, &q2), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_irf_q2(&irf, TRK_REAL_C(0.9), (trk_real)NAN, &q2), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_irf_q2(&irf, TRK_REAL_C(0.9), 1, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_irf_beta1(&irf, -1, 1, e), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_irf_beta1(&irf, (trk_real)NAN, 1, e), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_irf_beta1(&irf, 1, -1, e), TRK_E_ARG);
    assert_true(isnan(trk_irf_b(&irf, 0, 1)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_irf_q2_reference),
        cmocka_unit_test(test_irf_beta1_monte_carlo),
        cmocka_unit_test(test_irf_limits),
        cmocka_unit_test(test_irf_monotone),
        cmocka_unit_test(test_irf_drives_mre),
        cmocka_unit_test(test_irf_bad_input),
    };
    return trk_run_tests("irf", tests, NULL, NULL);
}
