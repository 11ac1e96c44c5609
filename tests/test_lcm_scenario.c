/* test_lcm_scenario.c - the simulated sonar's scenario (tools/sim/
 * scenario.c) and amplitude draws (amp_sample.c): the same seed gives the
 * same scans, targets move as constant velocity (exactly with q = 0, with
 * velocity increments of variance q T otherwise), detections come with the
 * model's P_D, clutter counts are Poisson with the configured mean (or
 * fixed), amplitudes follow the thresholded laws (Rayleigh: a^2 - t^2 is
 * Exp(1) for clutter and Exp(1 + SNR) for targets; K: the truncated survival
 * S(a)/S(t) of the drawn amplitudes is uniform). Sample sizes give standard
 * errors well inside the tolerances; the seeds are fixed, so the outcome is
 * deterministic. */
#include "trk_test.h"

#include "amp_sample.h"
#include "scenario.h"

#define MAXD 512
static struct trk_detection det[MAXD], det2[MAXD];

static void test_same_seed_same_scans(void **state)
{
    (void)state;
    struct scen_params p;
    struct scenario a, b;
    char err[256];
    scen_defaults(&p);
    p.seed = 99;
    assert_int_equal(scen_init(&a, &p, err, sizeof err), 0);
    assert_int_equal(scen_init(&b, &p, err, sizeof err), 0);
    int differs = 0;
    for (int k = 0; k < 20; k++) {
        struct trk_scan s1, s2;
        scen_next(&a, det, MAXD, &s1, NULL, NULL);
        scen_next(&b, det2, MAXD, &s2, NULL, NULL);
        assert_true(s1.time_us == s2.time_us);
        assert_int_equal(s1.n_detections, s2.n_detections);
        assert_memory_equal(det, det2, s1.n_detections * sizeof det[0]);
        assert_true(s1.time_us == (int64_t)k * 2000000); /* t0 0, T 2 s */
    }
    scen_free(&b);
    p.seed = 100;
    assert_int_equal(scen_init(&b, &p, err, sizeof err), 0);
    struct trk_scan s1, s2;
    scen_next(&a, det, MAXD, &s1, NULL, NULL);
    scen_next(&b, det2, MAXD, &s2, NULL, NULL);
    differs = s1.n_detections != s2.n_detections ||
              memcmp(det, det2, s1.n_detections * sizeof det[0]) != 0;
    assert_true(differs);
    scen_free(&a);
    scen_free(&b);
}

static void test_cv_motion_and_pd1(void **state)
{
    (void)state;
    struct scen_params p;
    struct scenario s;
    char err[256];
    const struct scen_target_init tg[2] = {{100, 200, 1.5, -2, NAN}, {-50, 0, 0, 3, NAN}};
    scen_defaults(&p);
    p.amp_kind = AMP_NONE;
    p.pd = 1;
    p.process_noise_q = 0;
    p.clutter_count = 0;
    p.targets = tg;
    p.n_targets = 2;
    p.scan_period_s = 0.5;
    p.t0_us = 1000;
    p.meas_sigma_m = 1e-3;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    for (int k = 0; k < 10; k++) {
        struct trk_scan sc;
        size_t nt, nd;
        scen_next(&s, det, MAXD, &sc, &nt, &nd);
        assert_int_equal(sc.n_detections, 2);
        assert_int_equal(nt, 2);
        assert_int_equal(nd, 0);
        assert_true(sc.time_us == 1000 + (int64_t)k * 500000);
        for (int i = 0; i < 2; i++) {
            const double x = tg[i].x_m + tg[i].vx_mps * 0.5 * k;
            const double y = tg[i].y_m + tg[i].vy_mps * 0.5 * k;
            TRK_ASSERT_NEAR(s.tg[i].x[0], x, 1e-9, 1e-12);
            TRK_ASSERT_NEAR(s.tg[i].x[2], y, 1e-9, 1e-12);
            /* a detection within 10 sigma of each target (order is shuffled) */
            int found = 0;
            for (size_t j = 0; j < 2; j++)
                found |= fabs((double)det[j].x_m - x) < 0.01 && fabs((double)det[j].y_m - y) < 0.01;
            assert_true(found);
            assert_int_equal(det[i].has_amplitude, 0);
            assert_int_equal(det[i].has_cov, 0);
        }
    }
    scen_free(&s);
}

static void test_process_noise(void **state)
{
    (void)state;
    /* velocity increments per scan: N(0, q T) per axis */
    struct scen_params p;
    struct scenario s;
    char err[256];
    scen_defaults(&p);
    p.amp_kind = AMP_NONE;
    p.clutter_count = 0;
    p.n_targets = 200;
    p.process_noise_q = 0.5;
    p.scan_period_s = 2;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    double sum2 = 0;
    long n = 0;
    for (int k = 0; k < 10; k++) {
        double v0[200][2];
        for (int i = 0; i < 200; i++) v0[i][0] = s.tg[i].x[1], v0[i][1] = s.tg[i].x[3];
        struct trk_scan sc;
        scen_next(&s, det, MAXD, &sc, NULL, NULL);
        if (k == 0) continue; /* scan 0 is at the initial states */
        for (int i = 0; i < 200; i++) {
            const double d1 = s.tg[i].x[1] - v0[i][0], d2 = s.tg[i].x[3] - v0[i][1];
            sum2 += d1 * d1 + d2 * d2;
            n += 2;
        }
    }
    /* var = q T = 1; 3600 samples: relative standard error 2.4 % */
    TRK_ASSERT_NEAR(sum2 / (double)n, 1.0, 0, 0.1);
    scen_free(&s);
}

static void test_clutter_counts(void **state)
{
    (void)state;
    struct scen_params p;
    struct scenario s;
    char err[256];
    scen_defaults(&p);
    p.amp_kind = AMP_NONE;
    p.n_targets = 0;
    p.clutter_density_per_m2 = 10.0 / (2000.0 * 2000.0); /* mean 10 per scan */
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    double sum = 0, sum2 = 0;
    const int n = 400;
    for (int k = 0; k < n; k++) {
        struct trk_scan sc;
        scen_next(&s, det, MAXD, &sc, NULL, NULL);
        sum += (double)sc.n_detections;
        sum2 += (double)sc.n_detections * (double)sc.n_detections;
        for (size_t j = 0; j < sc.n_detections; j++) {
            assert_true(det[j].x_m >= 0 && det[j].x_m <= 2000);
            assert_true(det[j].y_m >= 0 && det[j].y_m <= 2000);
        }
    }
    const double mean = sum / n, var = sum2 / n - mean * mean;
    TRK_ASSERT_NEAR(mean, 10, 0.8, 0);  /* standard error 0.16 */
    TRK_ASSERT_NEAR(var, 10, 2.5, 0);   /* Poisson: variance = mean */
    scen_free(&s);
    /* fixed count, and capacity: detections beyond max_det are dropped and counted */
    p.clutter_count = 40;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    struct trk_scan sc;
    size_t nt, nd;
    scen_next(&s, det, MAXD, &sc, &nt, &nd);
    assert_int_equal(sc.n_detections, 40);
    scen_next(&s, det, 25, &sc, &nt, &nd);
    assert_int_equal(sc.n_detections, 25);
    assert_int_equal(nd, 15);
    scen_free(&s);
}

static void test_rayleigh_amplitudes(void **state)
{
    (void)state;
    struct scen_params p;
    struct scenario s;
    char err[256];
    scen_defaults(&p);
    p.amp_kind = AMP_RAYLEIGH;
    p.pfa = 1e-3;
    p.snr_db = 10;
    p.n_targets = 50;
    p.clutter_count = 30;
    p.meas_sigma_m = 0.01;
    p.process_noise_q = 0;
    p.x_min_m = 0, p.x_max_m = 1e6, p.y_min_m = 0, p.y_max_m = 1e6; /* targets far from clutter */
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    const double t = sqrt(-log(1e-3)), D = 10;
    TRK_ASSERT_NEAR(s.amp.t, t, 1e-12, TRK_TOL(1e-12, 1e-6));
    const double pd = pow(1e-3, 1 / (1 + D)); /* 0.533 */
    TRK_ASSERT_NEAR(s.tg[0].pd, pd, 1e-12, TRK_TOL(1e-12, 1e-5));
    double sc_sum = 0, tg_sum = 0;
    long nc = 0, ntg = 0, scans = 40;
    for (int k = 0; k < scans; k++) {
        struct trk_scan sc;
        size_t nt;
        scen_next(&s, det, MAXD, &sc, &nt, NULL);
        for (size_t j = 0; j < sc.n_detections; j++) {
            assert_int_equal(det[j].has_amplitude, 1);
            const double a = (double)det[j].amplitude;
            assert_true(a >= t * (1 - TRK_TOL(1e-12, 1e-6)));
            /* a target detection sits on its target (sigma 1 cm) */
            int is_target = 0;
            for (size_t i = 0; i < s.n_tg && !is_target; i++)
                is_target = fabs((double)det[j].x_m - s.tg[i].x[0]) < 1 &&
                            fabs((double)det[j].y_m - s.tg[i].x[2]) < 1;
            if (is_target) tg_sum += a * a - t * t, ntg++;
            else sc_sum += a * a - t * t, nc++;
        }
    }
    assert_int_equal(nc, 30 * scans);
    /* detections per target look: P_D (2000 looks, standard error 0.011) */
    TRK_ASSERT_NEAR((double)ntg / (50.0 * scans), pd, 0.045, 0);
    TRK_ASSERT_NEAR(sc_sum / nc, 1, 0, 0.12);        /* Exp(1): rel. s.e. 2.9 % */
    TRK_ASSERT_NEAR(tg_sum / ntg, 1 + D, 0, 0.12);   /* Exp(1+D): rel. s.e. 3 % */
    scen_free(&s);
}

/* K clutter: the probability integral transform u = S(a)/S(t) of drawn
 * amplitudes is uniform; check its mean (1/2) and the fraction below 0.1. */
static void test_k_amplitudes(void **state)
{
    (void)state;
    struct amp_model m;
    struct amp_target tg;
    char err[256];
    assert_int_equal(amp_model_init(&m, AMP_K, 1e-3, 1.5, err, sizeof err), 0);
    TRK_ASSERT_NEAR(exp(kdist_log_sf(&m.k0, 0, m.t)), 1e-3, 0, 1e-8); /* S0(t) = pfa */
    assert_int_equal(amp_target_init(&m, 12, &tg), 0);
    TRK_ASSERT_NEAR(tg.pd, exp(kdist_log_sf(&tg.k1, 1, m.t)), 0, 1e-14);
    assert_true(tg.pd > 0.05 && tg.pd < 1);
    struct rng r;
    rng_init(&r, 5, 0);
    const int n = 400;
    for (int target = 0; target < 2; target++) {
        const struct kdist *k = target ? &tg.k1 : &m.k0;
        const double lst = kdist_log_sf(k, target, m.t);
        double sum = 0;
        int low = 0;
        for (int i = 0; i < n; i++) {
            double a;
            assert_int_equal(amp_draw(&m, target ? &tg : NULL, &r, &a), 0);
            assert_true(a >= m.t * (1 - 1e-12));
            const double u = exp(kdist_log_sf(k, target, a) - lst);
            sum += u;
            low += u < 0.1;
        }
        TRK_ASSERT_NEAR(sum / n, 0.5, 0.06, 0);            /* s.e. 0.0144 */
        TRK_ASSERT_NEAR((double)low / n, 0.1, 0.06, 0);    /* s.e. 0.015 */
    }
    assert_int_equal(amp_model_init(&m, AMP_K, 1e-3, -1, err, sizeof err), -1);
    assert_int_equal(amp_model_init(&m, AMP_RAYLEIGH, 1.5, 1, err, sizeof err), -1);
    assert_int_equal(amp_kind_parse("k"), AMP_K);
    assert_int_equal(amp_kind_parse("rayleigh"), AMP_RAYLEIGH);
    assert_int_equal(amp_kind_parse("none"), AMP_NONE);
    assert_int_equal(amp_kind_parse("gauss"), -1);
}

static void test_bad_params(void **state)
{
    (void)state;
    struct scen_params p;
    struct scenario s;
    char err[256];
    scen_defaults(&p);
    p.scan_period_s = 0;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), -1);
    scen_defaults(&p);
    p.x_max_m = p.x_min_m;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), -1);
    scen_defaults(&p);
    p.amp_kind = AMP_NONE;
    p.pd = 0;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), -1);
    scen_defaults(&p);
    p.snr_db = 300;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), -1);
    assert_true(strlen(err) > 0);
    /* detections carry their covariance when asked */
    scen_defaults(&p);
    p.attach_cov = 1;
    p.meas_sigma_m = 2;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    struct trk_scan sc;
    scen_next(&s, det, MAXD, &sc, NULL, NULL);
    assert_true(sc.n_detections > 0);
    assert_int_equal(det[0].has_cov, 1);
    assert_true(det[0].cov_m2[0] == 4 && det[0].cov_m2[1] == 0 && det[0].cov_m2[2] == 4);
    scen_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_seed_same_scans), cmocka_unit_test(test_cv_motion_and_pd1),
        cmocka_unit_test(test_process_noise),        cmocka_unit_test(test_clutter_counts),
        cmocka_unit_test(test_rayleigh_amplitudes),  cmocka_unit_test(test_k_amplitudes),
        cmocka_unit_test(test_bad_params),
    };
    return trk_run_tests("lcm_scenario", tests, NULL, NULL);
}
