/* test_polar.c - polar detections and where a sensor sees (src/polar.c):
 *   - the first-order conversion at a pose equals trk_detection_from_polar
 *     at the absolute bearing, and its covariance the Jacobian's closed
 *     form along and across the axes;
 *   - the unbiased conversion (Mo et al. 1998) by Monte Carlo: its mean is
 *     the true position where the first-order one is biased towards the
 *     sensor by r (1 - e^(-sb^2 / 2)), and the sample covariance of the
 *     converted positions about the truth matches the mean of its
 *     measurement-conditioned covariance;
 *   - trk_polar_cov from the converted offset equals the covariance the
 *     conversion wrote (the tracker derives it again from the position);
 *   - trk_sensor_pd_at: the profile interpolated linearly and flat beyond
 *     its ends, 0 outside the range limits and the sector (turned with the
 *     heading and moved with the pose), the sensor's P_D without a profile;
 *   - the parameter check names each refused field. */
#include "trk_test.h"
#include "trk/tracker.h"

#define DEG (3.14159265358979323846 / 180)

static void polar_sensor(struct trk_sensor_params *sp, double sigma_r, double sigma_b_rad)
{
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    *sp = p.sensor[0];
    sp->kind = TRK_SENSOR_POLAR;
    sp->sigma_range_m = (trk_real)sigma_r;
    sp->sigma_bearing_rad = (trk_real)sigma_b_rad;
}

static void test_first_order_matches_helper(void **state)
{
    (void)state;
    struct trk_sensor_params sp;
    polar_sensor(&sp, 7.5, 1.5 * DEG);
    const struct trk_pose pose = {TRK_REAL_C(120.0), TRK_REAL_C(-40.0), (trk_real)(30 * DEG)};
    const struct trk_polar_detection pd = {TRK_REAL_C(4000.0), (trk_real)(25 * DEG), TRK_REAL_C(3.0), 1};
    struct trk_detection a, b;
    TRK_ASSERT_OK(trk_polar_to_cartesian(&sp, &pose, &pd, &a));
    TRK_ASSERT_OK(trk_detection_from_polar(pd.range_m, (trk_real)(55 * DEG), sp.sigma_range_m, sp.sigma_bearing_rad,
                                           pose.x_m, pose.y_m, &b));
    TRK_ASSERT_NEAR(a.x_m, b.x_m, 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(a.y_m, b.y_m, 0, TRK_TOL(1e-14, 1e-6));
    for (int c = 0; c < 3; c++) TRK_ASSERT_NEAR(a.cov_m2[c], b.cov_m2[c], 1e-9, TRK_TOL(1e-12, 1e-4));
    assert_int_equal(a.has_cov, 1);
    assert_int_equal(a.has_amplitude, 1);
    TRK_ASSERT_NEAR(a.amplitude, 3.0, 0, 0);
    /* along north (bearing 0 from heading 0): x is cross-range, y range */
    const struct trk_pose o = {0, 0, 0};
    const struct trk_polar_detection n = {TRK_REAL_C(2000.0), 0, 0, 0};
    TRK_ASSERT_OK(trk_polar_to_cartesian(&sp, &o, &n, &a));
    const double vt = 2000.0 * 2000.0 * (1.5 * DEG) * (1.5 * DEG);
    TRK_ASSERT_NEAR(a.cov_m2[TRK_COV2_XX], vt, 0, TRK_TOL(1e-12, 1e-5));
    TRK_ASSERT_NEAR(a.cov_m2[TRK_COV2_YY], 7.5 * 7.5, 0, TRK_TOL(1e-12, 1e-5));
    TRK_ASSERT_NEAR(a.cov_m2[TRK_COV2_XY], 0, 1e-9, 0);
    /* the covariance again from the converted offset */
    trk_real c[3];
    TRK_ASSERT_OK(trk_polar_to_cartesian(&sp, &pose, &pd, &b));
    trk_polar_cov(&sp, b.x_m - pose.x_m, b.y_m - pose.y_m, c);
    for (int k = 0; k < 3; k++) TRK_ASSERT_NEAR(c[k], b.cov_m2[k], 1e-9, TRK_TOL(1e-12, 1e-4));
}

static void test_refusals(void **state)
{
    (void)state;
    struct trk_sensor_params sp;
    polar_sensor(&sp, 7.5, 1.5 * DEG);
    const struct trk_pose o = {0, 0, 0};
    struct trk_polar_detection pd = {TRK_REAL_C(100.0), 0, 0, 0};
    struct trk_detection d;
    TRK_ASSERT_STATUS(trk_polar_to_cartesian(NULL, &o, &pd, &d), TRK_E_ARG);
    pd.range_m = 0;
    TRK_ASSERT_STATUS(trk_polar_to_cartesian(&sp, &o, &pd, &d), TRK_E_RANGE);
    pd.range_m = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_polar_to_cartesian(&sp, &o, &pd, &d), TRK_E_NAN);
    pd.range_m = 100;
    sp.kind = TRK_SENSOR_CARTESIAN;
    TRK_ASSERT_STATUS(trk_polar_to_cartesian(&sp, &o, &pd, &d), TRK_E_ARG);
    /* at the pose the bearing is lost: sr^2 I in either conversion, for an
     * offset of 0 and for one whose square underflows (it was 0/0: NaN) */
    polar_sensor(&sp, 7.5, 1.5 * DEG);
    for (int conv = 0; conv < 2; conv++) {
        sp.conversion = conv ? TRK_POLAR_UNBIASED : TRK_POLAR_FIRST_ORDER;
        const trk_real tiny = trk_sqrt(TRK_REAL_MIN) / 4, offsets[][2] = {{0, 0}, {tiny, tiny}, {0, -tiny}};
        for (size_t i = 0; i < 3; i++) {
            trk_real c[3];
            trk_polar_cov(&sp, offsets[i][0], offsets[i][1], c);
            TRK_ASSERT_NEAR(c[TRK_COV2_XX], 56.25, 0, TRK_TOL(1e-15, 1e-6));
            TRK_ASSERT_NEAR(c[TRK_COV2_XY], 0, 0, 0);
            TRK_ASSERT_NEAR(c[TRK_COV2_YY], 56.25, 0, TRK_TOL(1e-15, 1e-6));
        }
    }
    /* a range below the pose's resolution: converted onto the pose, finite */
    const struct trk_pose far = {TRK_REAL_C(1e8), TRK_REAL_C(1e8), 0};
    pd.range_m = TRK_REAL_C(1e-9);
    TRK_ASSERT_OK(trk_polar_to_cartesian(&sp, &far, &pd, &d));
    assert_true(isfinite(d.cov_m2[0]) && isfinite(d.cov_m2[1]) && isfinite(d.cov_m2[2]));
}

/* Monte Carlo of one true position (r0, b0) seen with sigma_r, sigma_b:
 * the means of both conversions, and for the unbiased one the sample
 * covariance about the truth against the mean of its covariance. */
static void test_unbiased_monte_carlo(void **state)
{
    (void)state;
    if (TRK_TEST_IS_FLOAT) skip(); /* sums of 2e5 samples: a double-build check */
    const double r0 = 6000, b0 = 40 * DEG, sr = 7.5, sb = 4 * DEG;
    struct trk_sensor_params fo, ub;
    polar_sensor(&fo, sr, sb);
    polar_sensor(&ub, sr, sb);
    ub.conversion = TRK_POLAR_UNBIASED;
    const struct trk_pose o = {0, 0, 0};
    const double tx = r0 * sin(b0), ty = r0 * cos(b0);
    const int n = 200000;
    double m_fo[2] = {0, 0}, m_ub[2] = {0, 0}, c_ub[3] = {0, 0, 0}, r_ub[3] = {0, 0, 0};
    uint64_t rng = 11;
    for (int i = 0; i < n; i++) {
        const struct trk_polar_detection pd = {(trk_real)(r0 + sr * trk_test_nrand(&rng)),
                                               (trk_real)(b0 + sb * trk_test_nrand(&rng)), 0, 0};
        struct trk_detection a, b;
        TRK_ASSERT_OK(trk_polar_to_cartesian(&fo, &o, &pd, &a));
        TRK_ASSERT_OK(trk_polar_to_cartesian(&ub, &o, &pd, &b));
        m_fo[0] += a.x_m, m_fo[1] += a.y_m;
        m_ub[0] += b.x_m, m_ub[1] += b.y_m;
        const double ex = b.x_m - tx, ey = b.y_m - ty;
        c_ub[0] += ex * ex, c_ub[1] += ex * ey, c_ub[2] += ey * ey;
        for (int k = 0; k < 3; k++) r_ub[k] += b.cov_m2[k];
    }
    for (int k = 0; k < 2; k++) m_fo[k] /= n, m_ub[k] /= n;
    for (int k = 0; k < 3; k++) c_ub[k] /= n, r_ub[k] /= n;
    /* standard error of a mean: sigma_cross / sqrt(n) = 420 m / 447 ~ 1 m */
    const double bias = r0 * (1 - exp(-sb * sb / 2)); /* 14.6 m towards the sensor */
    TRK_ASSERT_NEAR(m_ub[0], tx, 3.0, 0);
    TRK_ASSERT_NEAR(m_ub[1], ty, 3.0, 0);
    TRK_ASSERT_NEAR(m_fo[0], tx - bias * sin(b0), 3.0, 0);
    TRK_ASSERT_NEAR(m_fo[1], ty - bias * cos(b0), 3.0, 0);
    /* the sample covariance about the truth within 2 % (sampling: ~0.5 %) */
    for (int k = 0; k < 3; k += 2) TRK_ASSERT_NEAR(r_ub[k], c_ub[k], 0, 0.02);
    TRK_ASSERT_NEAR(r_ub[1], c_ub[1], 0.02 * sqrt(c_ub[0] * c_ub[2]), 0);
}

static void test_pd_at(void **state)
{
    (void)state;
    struct trk_sensor_params sp;
    polar_sensor(&sp, 7.5, 1.5 * DEG);
    const struct trk_pose o = {TRK_REAL_C(1000.0), TRK_REAL_C(500.0), (trk_real)(90 * DEG)}; /* looking east */
    sp.pd = TRK_REAL_C(0.7);
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 5000, -3000), 0.7, 0, TRK_TOL(1e-15, 1e-7)); /* no profile */
    sp.pd_profile.n = 3;
    const double rr[3] = {500, 2000, 8000}, pp[3] = {0.9, 0.8, 0.4};
    for (int k = 0; k < 3; k++) sp.pd_profile.range_m[k] = (trk_real)rr[k], sp.pd_profile.pd[k] = (trk_real)pp[k];
    /* east of the pose at range r: (1000 + r, 500) */
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 100, 500), 0.9, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 1250, 500), 0.85, 1e-12, TRK_TOL(1e-12, 1e-6));
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 5000, 500), 0.6, 1e-12, TRK_TOL(1e-12, 1e-6));
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 9000, 500), 0.4, 0, TRK_TOL(1e-15, 1e-7));
    /* coverage: 1-6 km, +-30 degrees about the heading (east) */
    sp.coverage.min_range_m = 1000;
    sp.coverage.max_range_m = 6000;
    sp.coverage.half_width_rad = (trk_real)(30 * DEG);
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 900, 500), 0, 0, 0);
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 + 6100, 500), 0, 0, 0);
    const double r = 3000;
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        const double in = (90 + sgn * 29.9) * DEG, out = (90 + sgn * 30.1) * DEG;
        assert_true(trk_sensor_pd_at(&sp, &o, (trk_real)(1000 + r * sin(in)), (trk_real)(500 + r * cos(in))) > 0.6);
        TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, (trk_real)(1000 + r * sin(out)), (trk_real)(500 + r * cos(out))), 0,
                        0, 0);
    }
    /* behind the sensor: outside a sector, inside an all-round coverage */
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 - 3000, 500), 0, 0, 0);
    sp.coverage.half_width_rad = 0;
    TRK_ASSERT_NEAR(trk_sensor_pd_at(&sp, &o, 1000 - 3000, 500), 0.8 - 0.4 / 6, 1e-12, TRK_TOL(1e-12, 1e-6));
    assert_true(isnan(trk_sensor_pd_at(NULL, &o, 0, 0)));
    /* the clutter profile: interpolated, flat beyond its ends; none: the density */
    sp.clutter_density_per_m2 = TRK_REAL_C(2e-7);
    TRK_ASSERT_NEAR(trk_sensor_clutter_at(&sp, &o, 1000 + 3000, 500), 2e-7, 0, TRK_TOL(1e-15, 1e-7));
    sp.clutter_profile.n = 2;
    sp.clutter_profile.range_m[0] = 1000, sp.clutter_profile.density_per_m2[0] = TRK_REAL_C(1e-6);
    sp.clutter_profile.range_m[1] = 5000, sp.clutter_profile.density_per_m2[1] = TRK_REAL_C(2e-7);
    TRK_ASSERT_NEAR(trk_sensor_clutter_at(&sp, &o, 1000 + 3000, 500), 6e-7, 1e-20, TRK_TOL(1e-12, 1e-6));
    TRK_ASSERT_NEAR(trk_sensor_clutter_at(&sp, &o, 1000 - 500, 500), 1e-6, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(trk_sensor_clutter_at(&sp, &o, 1000 + 9000, 500), 2e-7, 0, TRK_TOL(1e-15, 1e-7));
    assert_true(isnan(trk_sensor_clutter_at(&sp, NULL, 0, 0)));
}

/* Each refused sensor field by name. */
static void check_refused(const struct trk_tracker_params *p, const char *want_field, trk_status want)
{
    const char *field = NULL;
    TRK_ASSERT_STATUS(trk_tracker_check_params(p, &field), want);
    assert_non_null(field);
    assert_string_equal(field, want_field);
}

static void test_params(void **state)
{
    (void)state;
    struct trk_tracker_params p, q;
    trk_tracker_default_params(&p);
    p.sensor[0].kind = TRK_SENSOR_POLAR;
    p.sensor[0].sigma_range_m = TRK_REAL_C(7.5);
    p.sensor[0].sigma_bearing_rad = TRK_REAL_C(0.026);
    p.sensor[0].meas_cov_m2[TRK_COV2_XX] = -1; /* unused by a polar sensor */
    TRK_ASSERT_OK(trk_tracker_check_params(&p, NULL));
    q = p, q.sensor[0].kind = (enum trk_sensor_kind)7;
    check_refused(&q, "sensor[0].kind", TRK_E_ARG);
    q = p, q.sensor[0].sigma_bearing_rad = TRK_REAL_C(0.6);
    check_refused(&q, "sensor[0].sigma_bearing_rad", TRK_E_RANGE);
    q = p, q.sensor[0].sigma_range_m = 0;
    check_refused(&q, "sensor[0].sigma_range_m", TRK_E_RANGE);
    /* a sigma whose square (the variance) underflows: every detection would be singular */
    q = p, q.sensor[0].sigma_range_m = trk_sqrt(TRK_REAL_MIN) / 2;
    check_refused(&q, "sensor[0].sigma_range_m", TRK_E_RANGE);
    q = p, q.sensor[0].sigma_bearing_rad = trk_sqrt(TRK_REAL_MIN) / 2;
    check_refused(&q, "sensor[0].sigma_bearing_rad", TRK_E_RANGE);
    q = p, q.sensor[0].sigma_range_m = 2 * trk_sqrt(TRK_REAL_MIN);
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL));
    q = p, q.sensor[0].conversion = (enum trk_polar_conversion)2;
    check_refused(&q, "sensor[0].conversion", TRK_E_ARG);
    q = p, q.sensor[0].pose.x_m = (trk_real)INFINITY;
    check_refused(&q, "sensor[0].pose", TRK_E_NAN);
    q = p, q.sensor[0].pd_profile.n = 1;
    check_refused(&q, "sensor[0].pd_profile", TRK_E_RANGE);
    q = p, q.sensor[0].pd_profile.n = 2, q.sensor[0].pd_profile.range_m[0] = 100, q.sensor[0].pd_profile.range_m[1] = 100;
    q.sensor[0].pd_profile.pd[0] = q.sensor[0].pd_profile.pd[1] = TRK_REAL_C(0.5);
    check_refused(&q, "sensor[0].pd_profile", TRK_E_RANGE);
    q.sensor[0].pd_profile.range_m[1] = 200;
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL));
    q.sensor[0].pd_profile.pd[1] = TRK_REAL_C(1.5);
    check_refused(&q, "sensor[0].pd_profile", TRK_E_RANGE);
    q = p, q.sensor[0].coverage.min_range_m = 500, q.sensor[0].coverage.max_range_m = 400;
    check_refused(&q, "sensor[0].coverage", TRK_E_RANGE);
    q = p, q.sensor[0].coverage.half_width_rad = 4;
    check_refused(&q, "sensor[0].coverage", TRK_E_RANGE);
    q = p;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&q.sensor[0].amplitude, 1, TRK_REAL_C(10.0), TRK_REAL_C(1e-3)));
    q.sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL));
    q.sensor[0].pd_profile.n = 2, q.sensor[0].pd_profile.range_m[1] = 200;
    q.sensor[0].pd_profile.pd[0] = q.sensor[0].pd_profile.pd[1] = TRK_REAL_C(0.5);
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL)); /* Rayleigh: the target's SNR over range */
    q.sensor[0].pd_profile.pd[1] = TRK_REAL_C(1e-3);   /* = pfa: no SNR gives it */
    check_refused(&q, "sensor[0].pd_profile", TRK_E_RANGE);
    q.sensor[0].pd_profile.pd[1] = 1;
    check_refused(&q, "sensor[0].pd_profile", TRK_E_RANGE);
    q.sensor[0].pd_profile.pd[1] = TRK_REAL_C(0.5);
    q.sensor[0].amplitude.model = TRK_AMP_K; /* K clutter: no closed form for the SNR over range */
    check_refused(&q, "sensor[0].pd_profile", TRK_E_UNSUPPORTED);
    /* persistent returns in the amplitudes: a Rayleigh model, eta in [0, 1), their P_D in (pfa, 1) */
    q = p;
    q.sensor[0].persistent_share = TRK_REAL_C(0.2), q.sensor[0].persistent_pd = TRK_REAL_C(0.9);
    check_refused(&q, "sensor[0].persistent_share", TRK_E_UNSUPPORTED); /* no amplitude model */
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&q.sensor[0].amplitude, 1, TRK_REAL_C(10.0), TRK_REAL_C(1e-3)));
    q.sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL));
    q.sensor[0].persistent_share = 1;
    check_refused(&q, "sensor[0].persistent_share", TRK_E_RANGE);
    q.sensor[0].persistent_share = (trk_real)NAN;
    check_refused(&q, "sensor[0].persistent_share", TRK_E_NAN);
    q.sensor[0].persistent_share = TRK_REAL_C(0.2), q.sensor[0].persistent_pd = TRK_REAL_C(1e-3);
    check_refused(&q, "sensor[0].persistent_share", TRK_E_RANGE);
    q = p, q.sensor[0].clutter_profile.n = 2, q.sensor[0].clutter_profile.range_m[1] = 100;
    q.sensor[0].clutter_profile.density_per_m2[0] = q.sensor[0].clutter_profile.density_per_m2[1] = TRK_REAL_C(1e-6);
    TRK_ASSERT_OK(trk_tracker_check_params(&q, NULL));
    q.sensor[0].clutter_profile.density_per_m2[1] = 0;
    check_refused(&q, "sensor[0].clutter_profile", TRK_E_RANGE);
    q.sensor[0].clutter_profile.density_per_m2[1] = TRK_REAL_C(1e-6);
    q.sensor[0].clutter_density_per_m2 = 0, q.association = TRK_ASSOC_PDA; /* no reference density */
    check_refused(&q, "sensor[0].clutter_profile", TRK_E_RANGE);
    q.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-6);
    q.clutter = TRK_CLUTTER_NONPARAMETRIC;
    check_refused(&q, "sensor[0].clutter_profile", TRK_E_UNSUPPORTED);
    q = p, q.filter = TRK_FILTER_ALPHA_BETA;
    check_refused(&q, "filter", TRK_E_UNSUPPORTED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_order_matches_helper), cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_unbiased_monte_carlo),       cmocka_unit_test(test_pd_at),
        cmocka_unit_test(test_params),
    };
    trk_test_filter_from_env();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
