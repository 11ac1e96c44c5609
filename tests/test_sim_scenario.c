/* test_sim_scenario.c - the scenario engine's extensions for trk-sim
 * (tools/sim/scenario.h): the lazily generated Poisson clutter field,
 * clutter around the targets, targets that end, two-state fluctuating
 * detection; and the confidence intervals of tools/sim/mc_stats.h.
 * Fixed seeds; the statistical checks use bounds several standard errors
 * wide (a failure is a bug, not bad luck). */
#include "trk_test.h"

#include "mc_stats.h"
#include "scenario.h"

/* Mean count in windows = density x area, for two tile sizes (area-exact
 * whatever the tiling), and the variance of a Poisson count (= mean). */
static void test_field_counts(void **state)
{
    (void)state;
    const double dens = 0.01, tiles[2] = {0, 3.7};
    for (int t = 0; t < 2; t++) {
        struct scen_field f;
        assert_int_equal(scen_field_init(&f, 11, dens, tiles[t]), 0);
        const int n = 4000;
        double s = 0, s2 = 0;
        for (int k = 0; k < n; k++) {
            const double x0 = 13.1 * k - 7, y0 = -5.3 * k;
            const size_t c = scen_field_window(&f, 3, (uint32_t)k, x0, x0 + 20, y0, y0 + 25, NULL, 0);
            assert_true(c != SIZE_MAX);
            s += (double)c;
            s2 += (double)c * (double)c;
        }
        const double mean = s / n, var = s2 / n - mean * mean, want = dens * 500;
        /* se of the mean sqrt(5/4000) = 0.035: 5 se */
        TRK_ASSERT_NEAR(mean, want, 0.18, 0);
        TRK_ASSERT_NEAR(var, want, 0.6, 0);
    }
}

/* The same (seed, run, scan) gives the same points; a sub-window gives
 * exactly the points of the big window inside it (common random numbers);
 * another run or scan gives other points; points are inside and u in (0,1). */
static void test_field_consistency(void **state)
{
    (void)state;
    struct scen_field f;
    assert_int_equal(scen_field_init(&f, 5, 0.5, 0), 0);
    struct scen_field_point big[400], small[200], again[400];
    const size_t nb = scen_field_window(&f, 7, 9, -10, 10, -8, 8, big, 400);
    assert_true(nb > 100 && nb < 250); /* mean 160 */
    assert_int_equal(scen_field_window(&f, 7, 9, -10, 10, -8, 8, again, 400), nb);
    assert_memory_equal(big, again, nb * sizeof big[0]);
    const size_t ns = scen_field_window(&f, 7, 9, -3.3, 4.1, -2, 5.5, small, 200);
    size_t inside = 0;
    for (size_t i = 0; i < nb; i++) {
        assert_true(big[i].x_m >= -10 && big[i].x_m < 10 && big[i].y_m >= -8 && big[i].y_m < 8);
        assert_true(big[i].u > 0 && big[i].u < 1);
        if (big[i].x_m >= -3.3 && big[i].x_m < 4.1 && big[i].y_m >= -2 && big[i].y_m < 5.5) {
            int found = 0;
            for (size_t j = 0; j < ns; j++)
                found |= small[j].x_m == big[i].x_m && small[j].y_m == big[i].y_m && small[j].u == big[i].u;
            assert_true(found);
            inside++;
        }
    }
    assert_int_equal(inside, ns);
    /* other run, other scan: different points */
    assert_true(scen_field_window(&f, 8, 9, -10, 10, -8, 8, again, 400) != nb ||
                memcmp(again, big, nb * sizeof big[0]) != 0);
    /* truncation: count beyond max, refusal of a huge window, empty window */
    assert_int_equal(scen_field_window(&f, 7, 9, -10, 10, -8, 8, again, 3), nb);
    assert_int_equal(scen_field_window(&f, 7, 9, -1e9, 1e9, -1e9, 1e9, NULL, 0), SIZE_MAX);
    assert_int_equal(scen_field_window(&f, 7, 9, 1, 1, -8, 8, NULL, 0), 0);
    assert_int_equal(scen_field_window(&f, 7, 9, NAN, 1, -8, 8, NULL, 0), SIZE_MAX);
    assert_int_equal(scen_field_init(&f, 1, -1, 0), -1);
}

/* Clutter around the targets: every clutter detection within the half-width
 * of a target; the mean count is density x (2h)^2 for one target. */
static void test_clutter_around(void **state)
{
    (void)state;
    struct scen_params p;
    scen_defaults(&p);
    const struct scen_target_init tg[1] = {{1000, 1000, 2, -1, NAN}};
    p.targets = tg;
    p.n_targets = 1;
    p.amp_kind = AMP_NONE;
    p.pd = 0.5;
    p.clutter_density_per_m2 = 0.002;
    p.clutter_around_m = 50;
    p.process_noise_q = 0;
    struct scenario s;
    char err[256];
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    static struct trk_detection det[64];
    double sum = 0;
    const int scans = 600;
    for (int k = 0; k < scans; k++) {
        struct trk_scan sc;
        size_t nt, nd;
        scen_next(&s, det, 64, &sc, &nt, &nd);
        assert_int_equal(nd, 0);
        sum += (double)(sc.n_detections - nt);
        const double cx = s.tg[0].x[0], cy = s.tg[0].x[2];
        for (size_t i = 0; i < sc.n_detections; i++) {
            /* target detections are within a few sigma, clutter within h */
            assert_true(fabs((double)det[i].x_m - cx) <= 50 + 30 && fabs((double)det[i].y_m - cy) <= 50 + 30);
        }
    }
    /* mean 20 per scan, se sqrt(20/600) = 0.18: 5 se */
    TRK_ASSERT_NEAR(sum / scans, 0.002 * 100 * 100, 0.95, 0);
    scen_free(&s);
}

/* A target that ends is never detected again; fluctuating detection has the
 * stationary detection rate pi_high pd + pi_low pd_low. */
static void test_end_and_fluct(void **state)
{
    (void)state;
    struct scen_params p;
    scen_defaults(&p);
    const struct scen_target_init tg[2] = {{0, 0, 1, 0, NAN}, {500, 0, -1, 0, NAN}};
    const long ends[2] = {0, 40};
    p.targets = tg;
    p.n_targets = 2;
    p.target_end_scan = ends;
    p.amp_kind = AMP_NONE;
    p.pd = 0.9;
    p.clutter_density_per_m2 = 0;
    p.fluct = 1;
    p.fluct_p = 0.1;
    p.fluct_q = 0.05;
    p.fluct_pd_low = 0.2;
    struct scenario s;
    char err[256];
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    static struct trk_detection det[8];
    long hits0 = 0, hits1_after = 0;
    const long scans = 6000;
    for (long k = 0; k < scans; k++) {
        struct trk_scan sc;
        scen_next(&s, det, 8, &sc, NULL, NULL);
        for (size_t i = 0; i < sc.n_detections; i++) {
            if (fabs((double)det[i].x_m - s.tg[0].x[0]) < 50) hits0++;
            else if (k >= 40) hits1_after++;
        }
    }
    assert_int_equal(hits1_after, 0);
    /* pi_high = 2/3: rate 2/3 0.9 + 1/3 0.2 = 0.6667; the Markov chain's
     * correlation (time constant ~7 scans) widens the se to ~0.02 */
    TRK_ASSERT_NEAR((double)hits0 / (double)scans, 2.0 / 3 * 0.9 + 1.0 / 3 * 0.2, 0.06, 0);
    scen_free(&s);
    /* bad fluctuation parameters are refused */
    p.fluct_p = p.fluct_q = 0;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), -1);
}

/* Clopper-Pearson and binomial acceptance intervals against closed forms. */
static void test_mc_stats(void **state)
{
    (void)state;
    double lo, hi;
    mc_binom_ci(0, 10, 0.95, &lo, &hi);
    TRK_ASSERT_NEAR(lo, 0, 0, 0);
    TRK_ASSERT_NEAR(hi, 1 - pow(0.025, 0.1), 1e-9, 0);
    mc_binom_ci(10, 10, 0.95, &lo, &hi);
    TRK_ASSERT_NEAR(lo, pow(0.025, 0.1), 1e-9, 0);
    mc_binom_ci(5, 10, 0.95, &lo, &hi); /* R: binom.test(5, 10) */
    TRK_ASSERT_NEAR(lo, 0.1870860, 1e-6, 0);
    TRK_ASSERT_NEAR(hi, 0.8129140, 1e-6, 0);
    TRK_ASSERT_NEAR(mc_betai(2, 3, 0.4), 0.5248, 1e-12, 0);
    long a, b;
    mc_binom_accept(1000, 0.01, 0.025, &a, &b);
    assert_true(a == 4 && b == 17);
    TRK_ASSERT_NEAR(mc_z(0.95), 1.959963984540054, 1e-9, 0);
    const double x[4] = {1, 2, 3, 4};
    double m;
    mc_mean_ci(x, 4, 0.95, &m, &lo, &hi);
    TRK_ASSERT_NEAR(m, 2.5, 1e-15, 0);
    TRK_ASSERT_NEAR(hi - m, 1.959963984540054 * sqrt(5.0 / 3 / 4), 1e-9, 0);
}

/* Quantiles (type 7), histogram bins and mode, the ratio estimator's
 * interval: the statistics of brekke-errpdf and brekke-trackloss's kept-track
 * RMSE distribution. */
static void test_mc_hist_quantile(void **state)
{
    (void)state;
    double x[5] = {4, 1, 3, 2, 5};
    mc_sort(x, 5);
    for (int i = 0; i < 5; i++) TRK_ASSERT_NEAR(x[i], i + 1, 0, 0);
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 5, 0), 1, 0, 0);
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 5, 1), 5, 0, 0);
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 5, 0.5), 3, 0, 0);
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 5, 0.1), 1.4, 1e-15, 0); /* R: quantile(1:5, 0.1) */
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 5, 0.95), 4.8, 1e-15, 0);
    TRK_ASSERT_NEAR(mc_quantile_sorted(x, 1, 0.3), 1, 0, 0);
    assert_true(isnan(mc_quantile_sorted(x, 0, 0.5)));
    assert_true(isnan(mc_quantile_sorted(x, 5, 1.5)));
    /* bins of width 0.1 over [0, 1): edges as computed (k w), overflow, refusals */
    assert_int_equal(mc_hist_bin(0, 0, 0.1, 10), 0);
    assert_int_equal(mc_hist_bin(0.25, 0, 0.1, 10), 2);
    assert_int_equal(mc_hist_bin(0.3, 0, 0.1, 10), 2); /* 3 * 0.1 = 0.30000000000000004 > 0.3 */
    assert_int_equal(mc_hist_bin(0.999, 0, 0.1, 10), 9);
    assert_int_equal(mc_hist_bin(1.0, 0, 0.1, 10), 10);
    assert_int_equal(mc_hist_bin(7.5, 0, 0.1, 10), 10);
    assert_int_equal(mc_hist_bin(-0.01, 0, 0.1, 10), -1);
    assert_int_equal(mc_hist_bin(NAN, 0, 0.1, 10), -1);
    for (int k = 0; k < 100000; k++) {
        const double v = k * 1e-5, w = 0.0137;
        const long b = mc_hist_bin(v, 0, w, 100);
        assert_true(b >= 0 && b <= 100);
        if (b < 100) assert_true((double)b * w <= v && v < (double)(b + 1) * w);
        else assert_true(v >= 100 * w);
    }
    const double c[5] = {0, 3, 5, 5, 1}, z[3] = {0, 0, 0};
    assert_int_equal(mc_hist_mode(c, 5), 2);
    assert_int_equal(mc_hist_mode(z, 3), -1);
    /* the ratio estimator: equal denominators give the mean of the ratios */
    const double num[4] = {2, 4, 6, 8}, den[4] = {2, 2, 2, 2}, q[4] = {1, 2, 3, 4};
    double r, lo, hi, m, mlo, mhi;
    mc_ratio_ci(num, den, 4, 0.95, &r, &lo, &hi);
    mc_mean_ci(q, 4, 0.95, &m, &mlo, &mhi);
    TRK_ASSERT_NEAR(r, m, 1e-15, 0);
    TRK_ASSERT_NEAR(lo, mlo, 1e-12, 0);
    TRK_ASSERT_NEAR(hi, mhi, 1e-12, 0);
    /* unequal: 9 / 4, se = sqrt(sum (num - r den)^2 / (n (n - 1))) / mean den */
    const double n2[3] = {1, 2, 6}, d2[3] = {1, 1, 2};
    mc_ratio_ci(n2, d2, 3, 0.95, &r, &lo, &hi);
    TRK_ASSERT_NEAR(r, 2.25, 1e-15, 0);
    TRK_ASSERT_NEAR(hi - r, 1.959963984540054 * sqrt(3.875 / 6) / (4.0 / 3), 1e-9, 0);
    TRK_ASSERT_NEAR(r - lo, hi - r, 1e-12, 0);
    mc_ratio_ci(n2, d2, 1, 0.95, &r, &lo, &hi);
    assert_true(r == 1 && lo == 1 && hi == 1);
    mc_ratio_ci(n2, d2, 0, 0.95, &r, &lo, &hi);
    assert_true(isnan(r) && isnan(lo) && isnan(hi));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_field_counts),   cmocka_unit_test(test_field_consistency),
        cmocka_unit_test(test_clutter_around), cmocka_unit_test(test_end_and_fluct),
        cmocka_unit_test(test_mc_stats),       cmocka_unit_test(test_mc_hist_quantile),
    };
    return trk_run_tests("sim_scenario", tests, NULL, NULL);
}
