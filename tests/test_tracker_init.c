/* test_tracker_init.c - the track table in clutter: two-point
 * initiation (state, covariance and initial existence in closed form; the
 * velocity gate; the candidates' lifetime), a full table that replaces its
 * weakest tentative track and never a confirmed one, existence-based
 * confirmation and rejection, the covariance bound, no duplicate tracks, and
 * every termination method ending a vanished target's track within its
 * design delay at every clutter level. */
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/kalman.h"
#include "trk/tracker.h"

static struct trk_tracker tk; /* static, as in firmware */

#define SCAN_S 4.0
#define T_US(k) ((int64_t)(k) * 4000000)
#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define P(i, j) TRK_CV2_P(i, j)
#define AREA_M2 9e6 /* the 3 km x 3 km region of the clutter */

static uint64_t rng_state; /* the generator of trk_test.h */
static double urand(void) { return trk_test_urand(&rng_state); }
static double nrand(void) { return trk_test_nrand(&rng_state); }

/* The sonar-like sensor of the track-table tests: P_D 0.8, R = 25 I, clutter density lambda. */
#define sonar_params trk_test_sonar_params
#define det_at trk_test_det_at

static trk_status run_scan(int k, const struct trk_detection *d, size_t n, struct trk_scan_report *rep)
{
    const struct trk_scan scan = {T_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
    return trk_tracker_process_scan(&tk, &scan, rep);
}

static size_t count_confirmed(void) { return trk_test_count_confirmed(&tk); }

static const struct trk_track *only_live_track(void)
{
    const struct trk_track *found = NULL;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk, i);
        if (tr && tr->status != TRK_TRACK_TERMINATED) {
            assert_null(found);
            found = tr;
        }
    }
    return found;
}

/* Two detections 4 s apart start one track: x = z2, v = (z2 - z1) / dt,
 * P_pp = R, P_pv = R / dt, P_vv = 2 R / dt^2 (then the velocity prior),
 * existence from the odds beta / lambda * P_D / lambda * N(z2 - z1; 0,
 * 2 R + s^2 dt^2 I). */
static void test_two_point_start(void **state)
{
    (void)state;
    const double lambda = 1e-5, beta = 1e-9, pd = 0.8;
    struct trk_tracker_params p;
    sonar_params(&p, lambda);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_scan_report rep;
    struct trk_detection d = det_at(100, 200);
    TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
    assert_int_equal(rep.n_started, 0);
    assert_int_equal(rep.n_candidates, 1);
    assert_null(only_live_track());
    d = det_at(140, 220);
    TRK_ASSERT_OK(run_scan(1, &d, 1, &rep));
    assert_int_equal(rep.n_started, 1);
    assert_int_equal(rep.n_candidates, 0);
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
    const double tol = TRK_REAL_IS_FLOAT ? 1e-5 : 1e-12;
    /* two-point differencing (x = z_j, v = dz / dt, P_pp = R, P_pv = R / dt,
     * P_vv = 2 R / dt^2 per axis), then the velocity prior N(0, s^2) fused
     * per axis in closed form: g = P_vv / (P_vv + s^2), v' = (1 - g) v,
     * x' = x - (P_pv / (P_vv + s^2)) v, P'_vv = P_vv s^2 / (P_vv + s^2),
     * P'_pv = P_pv s^2 / (P_vv + s^2), P'_pp = P_pp - P_pv^2 / (P_vv + s^2) */
    const double s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps, ppp = 25, ppv = 25 / SCAN_S,
                 pvv = 50 / (SCAN_S * SCAN_S), den = pvv + s2;
    TRK_ASSERT_NEAR(tr->x[X], 140 - ppv / den * 10, 0, tol);
    TRK_ASSERT_NEAR(tr->x[Y], 220 - ppv / den * 5, 0, tol);
    TRK_ASSERT_NEAR(tr->x[VX], 10 * s2 / den, 0, tol);
    TRK_ASSERT_NEAR(tr->x[VY], 5 * s2 / den, 0, tol);
    TRK_ASSERT_NEAR(tr->p[P(X, X)], ppp - ppv * ppv / den, 0, tol);
    TRK_ASSERT_NEAR(tr->p[P(X, VX)], ppv * s2 / den, 0, tol);
    TRK_ASSERT_NEAR(tr->p[P(VX, X)], ppv * s2 / den, 0, tol);
    TRK_ASSERT_NEAR(tr->p[P(VX, VX)], pvv * s2 / den, 0, tol);
    TRK_ASSERT_NEAR(tr->p[P(VY, VY)], pvv * s2 / den, 0, tol);
    assert_true(trk_fabs(tr->p[P(X, Y)]) < 1e-12 && trk_fabs(tr->p[P(X, VY)]) < 1e-12 &&
                trk_fabs(tr->p[P(VX, VY)]) < 1e-12);
    /* the displacement (40, 20) m under the velocity prior and the two
     * points' noise: N(dz; 0, (2 R + s^2 dt^2) I); against all clutter or
     * either point a new target alone (beta / lambda each, no amplitudes) */
    const double var = 50 + s2 * SCAN_S * SCAN_S;
    const double dens = exp(-0.5 * (40.0 * 40.0 + 20.0 * 20.0) / var) / (2 * 3.14159265358979323846 * var);
    const double odds = beta / lambda * pd / lambda * dens / (1 + 2 * beta / lambda);
    TRK_ASSERT_NEAR(tr->existence0, odds / (1 + odds), 0, TRK_REAL_IS_FLOAT ? 1e-5 : 1e-12);
    TRK_ASSERT_NEAR(tr->vis.pv, tr->existence0, 0, 0);
    assert_int_equal(tr->n_hits, 2);
}

/* A pair below init.min_existence starts no track (counted); its second
 * point waits as a candidate that remembers the first, and the third
 * detection on the line starts the track with the three points' odds: the
 * pair's times P_D N(z3; z^, S) / lambda, z^ = 2 z2 - z1 (equal gaps),
 * S = R + 4 R + R + q dt^3 / 3 I, over 1 + 3 beta / lambda (all clutter, or
 * one of the three a new target alone). Three points start however weak; a
 * pair above the threshold starts at once. */
static void test_min_existence(void **state)
{
    (void)state;
    const double lambda = 1e-5, beta = 1e-9, pd = 0.8, pi = 3.14159265358979323846;
    for (int above = 0; above <= 1; above++) {
        struct trk_tracker_params p;
        sonar_params(&p, lambda);
        p.init.min_existence = above ? TRK_REAL_C(1e-30) : TRK_REAL_C(0.99);
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        struct trk_scan_report rep;
        struct trk_detection d = det_at(100, 200);
        TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
        d = det_at(140, 220);
        TRK_ASSERT_OK(run_scan(1, &d, 1, &rep));
        assert_int_equal(rep.n_started, above ? 1 : 0);
        assert_int_equal(rep.n_init_deferred, above ? 0 : 1);
        assert_int_equal(rep.n_candidates, above ? 0 : 2); /* the first stays, the second waits */
        if (above) continue;
        assert_null(only_live_track());
        d = det_at(181, 239); /* (180, 240) predicted, 1 m and -1 m off */
        TRK_ASSERT_OK(run_scan(2, &d, 1, &rep));
        assert_int_equal(rep.n_started, 1);
        assert_int_equal(rep.n_init_deferred, 0);
        const struct trk_track *tr = only_live_track();
        assert_non_null(tr);
        assert_int_equal(tr->n_hits, 2); /* it starts from the last two points */
        const double s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps, var2 = 50 + s2 * SCAN_S * SCAN_S;
        const double dens2 = exp(-0.5 * (40.0 * 40.0 + 20.0 * 20.0) / var2) / (2 * pi * var2);
        const double var3 = 6 * 25 + (double)p.process_noise_q * SCAN_S * SCAN_S * SCAN_S / 3;
        const double dens3 = exp(-0.5 * (1.0 + 1.0) / var3) / (2 * pi * var3);
        const double odds = beta / lambda * pd / lambda * dens2 * pd * dens3 / lambda / (1 + 3 * beta / lambda);
        TRK_ASSERT_NEAR(tr->existence0, odds / (1 + odds), 0, TRK_REAL_IS_FLOAT ? 1e-5 : 1e-12);
        assert_true(tr->existence0 < p.init.min_existence);
    }
}

/* Scans of more than half the candidate store each: the store keeps only
 * the last scan's candidates, so a deferred pair's first point has gone
 * when its third detection comes. The three points still start (on the
 * pair's odds), as they must: otherwise a crowded sea would start nothing
 * while init.min_existence waits for a third point it can never count. */
static void test_min_existence_crowded_store(void **state)
{
    (void)state;
    const size_t n_clutter = TRK_MAX_CANDIDATES / 2 + 1;
    if (n_clutter + 1 > TRK_MAX_DETECTIONS) {
        skip();
        return;
    }
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    struct trk_tracker_params p;
    sonar_params(&p, 1e-5);
    p.init.min_existence = TRK_REAL_C(0.99);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    rng_state = 7;
    size_t near = 0;
    for (int k = 0; k < 3; k++) {
        size_t n = 0;
        d[n++] = det_at(40.0 * k, 20.0 * k); /* the target */
        for (size_t i = 0; i < n_clutter; i++) /* far from it and from each other: no pairs */
            d[n++] = det_at(5e4 + 2e5 * urand(), 5e4 + 2e5 * urand());
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, n, &rep));
        if (k == 1) {
            assert_int_equal(rep.n_init_deferred, 1); /* the target's pair waits */
            assert_int_equal(rep.n_candidates, n);    /* only this scan's: scan 0's left for room */
        }
        if (k == 2) assert_int_equal(rep.n_started, 1);
    }
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk, i);
        if (tr && tr->status == TRK_TRACK_TENTATIVE && fabs(tr->x[X] - 80) < 20 && fabs(tr->x[Y] - 40) < 20) near++;
    }
    assert_int_equal(near, 1);
}

/* A detection's partner is the candidate of the highest ln l^a + ln N(dz;
 * 0, R_c + R + s^2 dt^2 I), the model that also gives the pair's odds: of
 * candidate A 60 m away with R = 1 m^2 and B 80 m away with R = 1e4 m^2
 * (its position known to 100 m), B explains the detection better (the
 * density of 80 m under 10 401 m^2 against 60 m under 402 m^2), though A is
 * nearer; the track's existence is B's pair's, in closed form. */
static void test_pair_by_displacement_density(void **state)
{
    (void)state;
    const double lambda = 1e-5, beta = 1e-9, pd = 0.8, pi = 3.14159265358979323846;
    struct trk_tracker_params p;
    sonar_params(&p, lambda);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const double s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps;
    struct trk_scan_report rep;
    struct trk_detection c[2] = {det_at(0, 0), det_at(-20, 0)};
    c[0].has_cov = c[1].has_cov = 1;
    c[0].cov_m2[TRK_COV2_XX] = c[0].cov_m2[TRK_COV2_YY] = 1;
    c[1].cov_m2[TRK_COV2_XX] = c[1].cov_m2[TRK_COV2_YY] = 1e4;
    c[0].cov_m2[TRK_COV2_XY] = c[1].cov_m2[TRK_COV2_XY] = 0;
    TRK_ASSERT_OK(run_scan(0, c, 2, &rep));
    assert_int_equal(rep.n_candidates, 2);
    struct trk_detection d = det_at(60, 0);
    d.has_cov = 1;
    d.cov_m2[TRK_COV2_XX] = d.cov_m2[TRK_COV2_YY] = 1;
    d.cov_m2[TRK_COV2_XY] = 0;
    TRK_ASSERT_OK(run_scan(1, &d, 1, &rep));
    assert_int_equal(rep.n_started, 1);
    assert_int_equal(rep.n_candidates, 1); /* A is left */
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    const double var_a = 2 + s2 * SCAN_S * SCAN_S, var_b = 1e4 + 1 + s2 * SCAN_S * SCAN_S;
    const double dens_a = exp(-0.5 * 60 * 60 / var_a) / (2 * pi * var_a);
    const double dens_b = exp(-0.5 * 80 * 80 / var_b) / (2 * pi * var_b);
    assert_true(dens_b > dens_a);
    const double odds = beta / lambda * pd / lambda * dens_b / (1 + 2 * beta / lambda);
    TRK_ASSERT_NEAR(tr->existence0, odds / (1 + odds), 0, TRK_REAL_IS_FLOAT ? 1e-5 : 1e-12);
    /* its velocity points from B: (z - z_B) / dt = 20 m/s east, shrunk by
     * the prior (per axis, P_vv = (1e4 + 1) / dt^2 against s^2) */
    const double pvv = (1e4 + 1) / (SCAN_S * SCAN_S);
    TRK_ASSERT_NEAR(tr->x[VX], 80 / SCAN_S * s2 / (pvv + s2), 0, TRK_REAL_IS_FLOAT ? 1e-4 : 1e-10);
}

/* A pair's odds weigh every way its points arise: one new target (A), all
 * clutter (1), or either point a new target on its own with the other
 * clutter (its single-point odds beta l^a / lambda): O = A / (1 + O_c +
 * O_j). A weak echo at the threshold (a clutter point's) followed by a
 * strong one (a target's at 13 dB) is the strong echo's target far likelier
 * than a target that moved from the weak point: the pair starts at the
 * closed form, below 1/2, where A alone would give it above 0.99 (such a
 * pair then took the target's next detection and was confirmed on it with
 * the clutter point's velocity). Two strong echoes on one line start near 1. */
static void test_pair_against_a_strong_point(void **state)
{
    (void)state;
    const double lambda = 1e-5, beta = 1e-9, pi = 3.14159265358979323846;
    struct trk_tracker_params p;
    sonar_params(&p, lambda);
    p.sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&p.sensor[0].amplitude, 1, 13, TRK_REAL_C(1e-2)));
    const struct trk_amplitude *m = &p.sensor[0].amplitude;
    const trk_real thr = trk_amplitude_threshold(m), a_weak = thr * TRK_REAL_C(1.01), a_strong = thr * TRK_REAL_C(2.5);
    trk_real l_weak, l_strong;
    TRK_ASSERT_OK(trk_amplitude_log_lr(m, a_weak, &l_weak));
    TRK_ASSERT_OK(trk_amplitude_log_lr(m, a_strong, &l_strong));
    const double pd = (double)trk_amplitude_pd(m), s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps;
    const double var = 50 + s2 * SCAN_S * SCAN_S;
    const double dens = exp(-0.5 * (40.0 * 40.0 + 20.0 * 20.0) / var) / (2 * pi * var);
    for (int strong_first = 0; strong_first <= 1; strong_first++) {
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        struct trk_scan_report rep;
        struct trk_detection d = det_at(100, 200);
        d.has_amplitude = 1;
        d.amplitude = strong_first ? a_strong : a_weak;
        TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
        d = det_at(140, 220);
        d.has_amplitude = 1;
        d.amplitude = a_strong;
        TRK_ASSERT_OK(run_scan(1, &d, 1, &rep));
        assert_int_equal(rep.n_started, 1);
        const struct trk_track *tr = only_live_track();
        assert_non_null(tr);
        const double l_c = strong_first ? (double)l_strong : (double)l_weak, l_j = (double)l_strong;
        const double o_c = beta / lambda * exp(l_c), o_j = beta / lambda * exp(l_j);
        const double a = o_c * pd * exp(l_j) / lambda * dens, odds = a / (1 + o_c + o_j);
        TRK_ASSERT_NEAR(tr->existence0, odds / (1 + odds), 0, TRK_REAL_IS_FLOAT ? 1e-4 : 1e-10);
        if (strong_first) {
            assert_true(tr->existence0 > 0.999);
        } else {
            assert_true(a / (1 + a) > 0.99);
            assert_true(tr->existence0 < 0.5);
        }
    }
}

/* Three points, each echo of its own strength (a weak first, a strong
 * second, a middling third): the pair of the first two waits
 * (min_existence: the strong second point alone explains most of it), and
 * the third starts the track at the three points' odds over all clutter or
 * any one of them alone, each with its own single-point odds: O = O_p (P_D
 * l_c / lambda) N_2 (P_D l_j / lambda) N_3 / (1 + O_p + O_c + O_j), N_2
 * and N_3 as in test_min_existence. */
static void test_three_points_against_each_alone(void **state)
{
    (void)state;
    const double lambda = 1e-5, beta = 1e-9, pi = 3.14159265358979323846;
    struct trk_tracker_params p;
    sonar_params(&p, lambda);
    p.init.min_existence = TRK_REAL_C(0.99);
    p.sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&p.sensor[0].amplitude, 1, 13, TRK_REAL_C(1e-2)));
    const struct trk_amplitude *m = &p.sensor[0].amplitude;
    const trk_real thr = trk_amplitude_threshold(m);
    const trk_real amp[3] = {thr * TRK_REAL_C(1.05), thr * TRK_REAL_C(2.2), thr * TRK_REAL_C(1.6)};
    const double x[3] = {100, 140, 181}, y[3] = {200, 220, 239}; /* (180, 240) predicted: 1 m and -1 m off */
    double l[3];
    for (int k = 0; k < 3; k++) {
        trk_real lr;
        TRK_ASSERT_OK(trk_amplitude_log_lr(m, amp[k], &lr));
        l[k] = (double)lr;
    }
    assert_true(l[1] > l[2] && l[2] > l[0]); /* three different strengths */
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_scan_report rep;
    for (int k = 0; k < 3; k++) {
        struct trk_detection d = det_at(x[k], y[k]);
        d.has_amplitude = 1;
        d.amplitude = amp[k];
        TRK_ASSERT_OK(run_scan(k, &d, 1, &rep));
        if (k == 1) assert_int_equal(rep.n_init_deferred, 1);
    }
    assert_int_equal(rep.n_started, 1);
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    const double pd = (double)trk_amplitude_pd(m), s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps;
    const double var2 = 50 + s2 * SCAN_S * SCAN_S, var3 = 6 * 25 + (double)p.process_noise_q * SCAN_S * SCAN_S * SCAN_S / 3;
    const double dens2 = exp(-0.5 * (40.0 * 40.0 + 20.0 * 20.0) / var2) / (2 * pi * var2);
    const double dens3 = exp(-0.5 * (1.0 + 1.0) / var3) / (2 * pi * var3);
    double o[3];
    for (int k = 0; k < 3; k++) o[k] = beta / lambda * exp(l[k]);
    const double a = o[0] * pd * exp(l[1]) / lambda * dens2 * pd * exp(l[2]) / lambda * dens3;
    const double odds = a / (1 + o[0] + o[1] + o[2]);
    TRK_ASSERT_NEAR(tr->existence0, odds / (1 + odds), 0, TRK_REAL_IS_FLOAT ? 1e-4 : 1e-10);
}

/* The velocity gate: |dz| <= v_max dt + sqrt(gamma lambda_max(R1 + R2)),
 * gamma = -2 ln(1 - P_G) = 9.21 for P_G 0.99: 60 + 21.46 = 81.46 m. A
 * candidate lives max_gap_scans scans (1 here, then 2). */
static void test_velocity_gate_and_lifetime(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-5);
    p.init.max_gap_scans = 1; /* candidates of the previous scan only */
    const double limit = 60 + sqrt(-2 * log(0.01) * 50);
    for (int inside = 0; inside <= 1; inside++) {
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        struct trk_scan_report rep;
        struct trk_detection d = det_at(0, 0);
        TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
        d = det_at(0.6 * (limit + (inside ? -0.5 : 0.5)), 0.8 * (limit + (inside ? -0.5 : 0.5)));
        TRK_ASSERT_OK(run_scan(1, &d, 1, &rep));
        assert_int_equal(rep.n_started, inside ? 1 : 0);
        assert_int_equal(rep.n_candidates, inside ? 0 : 2);
    }
    /* lifetime: the scan-0 candidate has expired at scan 2 */
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_scan_report rep;
    struct trk_detection d = det_at(0, 0);
    TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
    TRK_ASSERT_OK(run_scan(1, NULL, 0, &rep));
    assert_int_equal(rep.n_candidates, 1);
    d = det_at(50, 0); /* within 2 v_max dt of the first, but two scans later */
    TRK_ASSERT_OK(run_scan(2, &d, 1, &rep));
    assert_int_equal(rep.n_started, 0);
    assert_int_equal(rep.n_candidates, 1);
    /* with max_gap_scans 2 it pairs */
    p.init.max_gap_scans = 2;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    d = det_at(0, 0);
    TRK_ASSERT_OK(run_scan(0, &d, 1, &rep));
    TRK_ASSERT_OK(run_scan(1, NULL, 0, &rep));
    d = det_at(50, 0);
    TRK_ASSERT_OK(run_scan(2, &d, 1, &rep));
    assert_int_equal(rep.n_started, 1);
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    const double pvv = 50 / (4 * SCAN_S * SCAN_S), s2 = p.init_speed_sigma_mps * p.init_speed_sigma_mps;
    TRK_ASSERT_NEAR(tr->x[VX], 50 / (2 * SCAN_S) * s2 / (pvv + s2), 0, TRK_REAL_IS_FLOAT ? 1e-5 : 1e-12);
}

/* A target followed with P_D 1 from scan 0; n_fresh new "clutter pairs" per
 * scan (a detection near one of the previous scan's, never seen again) keep
 * the table full of weak tentative tracks. The target's confirmed track is
 * never replaced, a second target appearing later still gets a track, and
 * the replacements are counted. */
static void test_full_table_replaces_weakest(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-5);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const size_t n_fresh = (TRK_MAX_DETECTIONS - 2) / 2 < TRK_MAX_TRACKS ? (TRK_MAX_DETECTIONS - 2) / 2 : TRK_MAX_TRACKS;
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    double fresh_x[TRK_MAX_DETECTIONS], fresh_y[TRK_MAX_DETECTIONS];
    uint32_t target_id = 0, second_id = 0;
    size_t n_prev = 0;
    uint32_t replaced = 0;
    rng_state = 7;
    for (int k = 0; k < 40; k++) {
        size_t n = 0;
        d[n++] = det_at(-1000 + 10.0 * SCAN_S * k, 0); /* target 1: 10 m/s east */
        if (k >= 20) d[n++] = det_at(1000, -1000 + 5.0 * SCAN_S * (k - 20)); /* target 2: 5 m/s north */
        if (k >= 8) { /* once target 1 is confirmed, fill the table */
            for (size_t i = 0; i < n_prev; i++) d[n++] = det_at(fresh_x[i] + 20, fresh_y[i]);
            for (size_t i = 0; i < n_fresh && n < TRK_MAX_DETECTIONS; i++) {
                fresh_x[i] = 20000 + 300.0 * (double)i;
                fresh_y[i] = 20000 + 300.0 * k;
                d[n++] = det_at(fresh_x[i], fresh_y[i]);
            }
            n_prev = n_fresh;
        }
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, n, &rep));
        replaced += rep.n_replaced;
        int seen_target = 0;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tk, i);
            if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
            if (fabs(tr->x[Y]) < 30 && fabs(tr->x[X] - (-1000 + 10.0 * SCAN_S * k)) < 30) {
                if (!target_id) target_id = tr->id;
                assert_int_equal(tr->id, target_id); /* one track, never replaced */
                seen_target = 1;
            }
            if (k >= 20 && fabs(tr->x[X] - 1000) < 30 && fabs(tr->x[Y] - (-1000 + 5.0 * SCAN_S * (k - 20))) < 30)
                second_id = tr->id;
        }
        if (k >= 8) assert_true(seen_target);
    }
    assert_true(target_id != 0);
    assert_true(second_id != 0);
    if (TRK_MAX_TRACKS < 2 * n_fresh) assert_true(replaced > 0);
}

/* A fresh table of parameters p on one detection at (0, 0) at scan 0
 * and one at (x1_m, 0) at scan 1: their pair's tentative track, the only
 * live one; *rep the second scan's report. */
static const struct trk_track *start_on_pair(const struct trk_tracker_params *p, double x1_m,
                                             struct trk_scan_report *rep)
{
    TRK_ASSERT_OK(trk_tracker_init(&tk, p));
    struct trk_detection d = det_at(0, 0);
    TRK_ASSERT_OK(run_scan(0, &d, 1, rep));
    d = det_at(x1_m, 0);
    TRK_ASSERT_OK(run_scan(1, &d, 1, rep));
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    return tr;
}

/* With joint association a tentative track claims (starts no track
 * from) only the gated detections it more likely than not explains:
 * posterior existence x joint weight >= 1/2. A fresh pair's track
 * (existence ~1e-3) whose next detection lies at its prediction rises only
 * to pv ~0.1: that detection is still stored as a candidate. At the next
 * scan the track (pv ~0.9, beta ~1, still tentative) claims its detection:
 * neither a candidate nor a pair with the one before. With per-track PDA
 * a tentative track claims every gated detection (no candidate at k = 2). */
static void run_claims(enum trk_assoc_method assoc)
{
    struct trk_tracker_params p;
    sonar_params(&p, 1e-5);
    p.association = assoc;
    struct trk_scan_report rep;
    const struct trk_track *tr = start_on_pair(&p, 40, &rep);
    assert_int_equal(rep.n_started, 1);
    struct trk_detection d;
    const uint32_t id = tr->id;
    assert_true(tr->vis.pv < 0.01);
    for (int k = 2; k <= 3; k++) {
        d = det_at(tr->x[X] + tr->x[VX] * SCAN_S, tr->x[Y] + tr->x[VY] * SCAN_S); /* at its prediction */
        TRK_ASSERT_OK(run_scan(k, &d, 1, &rep));
        tr = only_live_track();
        assert_non_null(tr);
        assert_int_equal(tr->id, id);
        assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
        assert_int_equal(rep.n_started, 0);
        if (k == 2) assert_true(tr->vis.pv < 0.5 * 0.99);
        else assert_true(tr->vis.pv > 0.5 / 0.99 && tr->vis.pv < 0.999);
        /* joint, k = 2: its own detection; k = 3: still the one of k = 2 */
        assert_int_equal(rep.n_candidates, assoc == TRK_ASSOC_JOINT ? 1 : 0);
    }
}

static void test_weak_tentative_claims_nothing(void **state)
{
    (void)state;
#if TRK_WITH_JOINT
    run_claims(TRK_ASSOC_JOINT);
#endif
    run_claims(TRK_ASSOC_PDA);
}

/* A table nearly full of confirmed tracks (all slots but one, 63 of 64 by
 * default: targets on a 300 m grid with P_D 0.9, confirmed before the
 * clutter begins) under 100 clutter detections per scan (lambda = 100 /
 * 9 km^2, from scan 10 on): a target that appears at scan 40
 * is confirmed within 25 scans in each of 8 seeds (an empty table confirms
 * it in 5-11). The free slots hold clutter-born tentative tracks, which a
 * fresh pair must be able to displace. */
static void test_new_target_in_nearly_full_table(void **state)
{
    (void)state;
    const size_t n_old = TRK_MAX_TRACKS - 1, n_clutter = 100;
    if (n_old + 1 + n_clutter > TRK_MAX_DETECTIONS || TRK_MAX_TRACKS < 16) {
        skip();
        return;
    }
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    const double lambda = (double)n_clutter / AREA_M2;
    int worst = 0;
    for (int seed = 0; seed < 8; seed++) {
        struct trk_tracker_params p;
        sonar_params(&p, lambda);
        p.sensor[0].pd = TRK_REAL_C(0.9);
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        rng_state = 100 + (uint64_t)seed;
        const int appear = 40;
        int confirmed_at = -1;
        size_t n_old_confirmed = 0;
        for (int k = 0; k < appear + 60 && confirmed_at < 0; k++) {
            size_t n = 0;
            for (size_t i = 0; i < n_old; i++) /* a grid, at 1 m/s east */
                if (urand() < 0.9)
                    d[n++] = det_at(-1400 + 300.0 * (double)(i % 10) + 1.0 * SCAN_S * k + 5 * nrand(),
                                    -1400 + 300.0 * (double)(i / 10) + 5 * nrand());
            const double tx = -1250 + 5.0 * SCAN_S * (k - appear), ty = 1350; /* the new one, 5 m/s east */
            if (k >= appear && urand() < 0.9) d[n++] = det_at(tx + 5 * nrand(), ty + 5 * nrand());
            for (size_t i = 0; k >= 10 && i < n_clutter && n < TRK_MAX_DETECTIONS; i++) /* once the old ones are confirmed */
                d[n++] = det_at(-1500 + 3000 * urand(), -1500 + 3000 * urand());
            struct trk_scan_report rep;
            TRK_ASSERT_OK(run_scan(k, d, n, &rep));
            if (k == appear - 1) n_old_confirmed = count_confirmed();
            for (size_t i = 0; k >= appear && i < TRK_MAX_TRACKS; i++) {
                const struct trk_track *a = trk_tracker_track(&tk, i);
                if (a && a->status == TRK_TRACK_CONFIRMED && fabs(a->x[X] - tx) < 40 && fabs(a->x[Y] - ty) < 40)
                    confirmed_at = k - appear;
            }
        }
        print_message("seed %d: %zu old tracks confirmed; the new target confirmed after %d scans\n", seed,
                      n_old_confirmed, confirmed_at);
        assert_true(n_old_confirmed >= n_old - 2); /* the table is nearly full of confirmed tracks */
        if (confirmed_at < 0 || confirmed_at > 25) fail_msg("seed %d: not confirmed within 25 scans", seed);
        if (confirmed_at > worst) worst = confirmed_at;
    }
    print_message("worst: %d scans\n", worst);
}

/* Tentative tracks on clutter: a pair with nothing after it is rejected
 * within two scans (its existence odds fall below 1/100 of the initial
 * ones: each miss multiplies them by at most Delta (1 - P_D P_G) = 0.21). */
static void test_existence_rejects_clutter_pair(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-5);
    struct trk_scan_report rep;
    const struct trk_track *tr = start_on_pair(&p, 30, &rep);
    TRK_ASSERT_OK(run_scan(2, NULL, 0, &rep));
    assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
    const double pv_pred = p.visibility.delta_stay * tr->existence0; /* the Markov prediction */
    TRK_ASSERT_NEAR(tr->vis.pv / (1 - tr->vis.pv), pv_pred / (1 - pv_pred) * (1 - 0.8 * 0.99), 0, 1e-4);
    TRK_ASSERT_OK(run_scan(3, NULL, 0, &rep));
    TRK_ASSERT_OK(run_scan(4, NULL, 0, &rep));
    assert_int_equal(tr->status, TRK_TRACK_TERMINATED);
    assert_int_equal(tr->end_reason, TRK_END_REJECTED);
}

/* Uniform clutter of density lambda over the 3 km region around (0, 0),
 * appended to d[n..]; at most TRK_MAX_DETECTIONS in all. */
static size_t add_clutter(struct trk_detection *d, size_t n, double lambda)
{
    double mean = lambda * AREA_M2, u = urand(), pk = exp(-mean), cdf = pk;
    size_t m = 0;
    while (u > cdf && m < 100000) { /* Poisson by inversion */
        m++;
        pk *= mean / (double)m;
        cdf += pk;
    }
    for (size_t i = 0; i < m && n < TRK_MAX_DETECTIONS; i++) d[n++] = det_at(-1500 + 3000 * urand(), -1500 + 3000 * urand());
    return n;
}

/* The scans a coasting track needs to pass the covariance bound: its
 * predicted position variance (no update) from the covariance at the last
 * detection. An upper bound on the wait of a track that PDA updates with
 * clutter would not shrink more than the target's detections did. */
static int covariance_bound_delay(const struct trk_track *tr, const struct trk_tracker_params *p)
{
    trk_real x[TRK_CV2_NX], pp[TRK_CV2_NX * TRK_CV2_NX];
    memcpy(x, tr->x, sizeof x);
    memcpy(pp, tr->p, sizeof pp);
    const double bound = p->max_pos_sigma_ratio * p->max_pos_sigma_ratio * 50;
    for (int k = 1; k < 1000; k++) {
        TRK_ASSERT_OK(trk_cv2_predict((trk_real)SCAN_S, p->process_noise_q, x, pp));
        if (pp[P(X, X)] + pp[P(Y, Y)] > bound) return k;
    }
    return 1000;
}

#define LAST_DET 19 /* the target's last detected scan */

enum term_case { T_EXISTENCE, T_KN, T_PAGE, T_SHIRYAEV, T_VISIBILITY, N_TERM_CASES };

static void set_term(struct trk_tracker_params *p, enum term_case c)
{
    struct trk_hmm_params hmm;
    memset(&hmm, 0, sizeof hmm);
    const struct trk_hmm_sensor_params fading = {TRK_REAL_C(0.1), TRK_REAL_C(0.02), TRK_REAL_C(0.1),
                                                 TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&hmm, 1, &fading); /* events: complete (0) */
    switch (c) {
    case T_EXISTENCE: break; /* the default */
    case T_KN:
        p->term.method = TRK_TERM_KN;
        p->term.u.kn.k = 0;
        p->term.u.kn.n = 5;
        break;
    case T_PAGE:
        p->term.method = TRK_TERM_PAGE;
        p->term.u.page.hmm = hmm;
        p->term.u.page.h = 5;
        break;
    case T_SHIRYAEV: /* a coasting track of a fading target must end */
        p->term.method = TRK_TERM_SHIRYAEV;
        p->term.u.shiryaev.hmm = hmm;
        p->term.u.shiryaev.beta0 = TRK_REAL_C(0.01);
        p->term.u.shiryaev.rho = TRK_REAL_C(0.01);
        p->term.u.shiryaev.h = TRK_REAL_C(4.59511985013459); /* ln 99 */
        break;
    case T_VISIBILITY: /* Kennedy's configuration: visibility confirmation too, pv0 = 0.5 */
        p->term.method = TRK_TERM_VISIBILITY;
        p->confirm.method = TRK_CONFIRM_VISIBILITY;
        p->init.birth_density_per_m2 = 0;
        break;
    default: break;
    }
}

/* One target detected for 20 scans (every scan), then gone; uniform
 * clutter from none to the scan capacity. Every termination method ends the
 * track within its design delay: the scans its test needs on empty gates
 * (measured at lambda = 0, where K/N 0/5 needs exactly 5), and at any
 * clutter level at most the covariance bound's delay plus one. */
static void test_vanished_target_every_method(void **state)
{
    (void)state;
    static const double lambdas[] = {0, 2.2e-6, 1.1e-5, 2.8e-5};
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    for (int c = 0; c < N_TERM_CASES; c++) {
        int empty_delay = -1;
        for (size_t li = 0; li < sizeof lambdas / sizeof *lambdas; li++) {
            const double lambda = lambdas[li];
            struct trk_tracker_params p;
            sonar_params(&p, lambda > 0 ? lambda : 1e-5); /* the tracker's model keeps clutter */
            set_term(&p, (enum term_case)c);
            TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
            rng_state = 1000 + li;
            uint32_t id = 0;
            const struct trk_track *tr = NULL;
            int delay_cov = 0, ended = -1;
            for (int k = 0; k < 400 && ended < 0; k++) {
                size_t n = 0;
                const double tx = -300 + 8.0 * SCAN_S * k, ty = 100 + 3.0 * SCAN_S * k;
                if (k < LAST_DET + 1) d[n++] = det_at(tx + 5 * nrand(), ty + 5 * nrand());
                n = add_clutter(d, n, lambda);
                struct trk_scan_report rep;
                TRK_ASSERT_OK(run_scan(k, d, n, &rep));
                if (k == LAST_DET) { /* the target's confirmed track */
                    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
                        const struct trk_track *a = trk_tracker_track(&tk, i);
                        if (a && a->status == TRK_TRACK_CONFIRMED && fabs(a->x[X] - tx) < 30 && fabs(a->x[Y] - ty) < 30)
                            tr = a, id = a->id;
                    }
                    assert_non_null(tr);
                    delay_cov = covariance_bound_delay(tr, &p);
                }
                if (k > LAST_DET && (tr->id != id || tr->status == TRK_TRACK_TERMINATED)) ended = k - LAST_DET;
            }
            print_message("term %d lambda %.1e: ended %d scans after the last detection (covariance bound %d)\n", c,
                          lambda, ended, delay_cov);
            assert_true(ended > 0);
            if (lambda == 0) {
                empty_delay = ended;
                if (c == T_KN) assert_int_equal(ended, 5);
            } else {
                assert_true(ended <= (empty_delay > delay_cov ? empty_delay : delay_cov) + 1);
            }
        }
    }
}

/* No track starts inside the gate of a live track: a target with P_D 0.8 in
 * clutter of 100 per 9 km^2 never has two confirmed tracks within 50 m. */
static void test_no_duplicates(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1.1e-5);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    rng_state = 99;
    int confirmed_scans = 0;
    for (int k = 0; k < 100; k++) {
        size_t n = 0;
        const double tx = -1000 + 6.0 * SCAN_S * k, ty = -500 + 4.0 * SCAN_S * k;
        if (urand() < 0.8) d[n++] = det_at(tx + 5 * nrand(), ty + 5 * nrand());
        n = add_clutter(d, n, 1.1e-5);
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, n, &rep));
        int near = 0;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *a = trk_tracker_track(&tk, i);
            if (a && a->status == TRK_TRACK_CONFIRMED && hypot(a->x[X] - tx, a->x[Y] - ty) < 50) near++;
        }
        assert_true(near <= 1);
        confirmed_scans += near;
    }
    assert_true(confirmed_scans >= 85);
}

/* The candidate store's invariants: the runs (one per scan, oldest first)
 * lie in cand[] without overlap, n_cand counts their unused candidates, and
 * each run's index puts every candidate in its cell (trk/tracker.h struct
 * trk_i_cand_run; the index itself: test_grid). */
static void check_store(const struct trk_tracker *t)
{
    size_t n_unused = 0;
    static uint8_t taken[TRK_MAX_CANDIDATES];
    memset(taken, 0, sizeof taken);
    assert_true(t->n_runs <= TRK_MAX_CANDIDATE_SCANS);
    for (size_t k = 0; k < t->n_runs; k++) {
        const struct trk_i_cand_run *r = &t->run[(t->run_first + k) % TRK_MAX_CANDIDATE_SCANS];
        if (k > 0) assert_true(r->scan_no - t->run[(t->run_first + k - 1) % TRK_MAX_CANDIDATE_SCANS].scan_no > 0);
        assert_true(r->n > 0 && (size_t)r->start + r->n <= TRK_MAX_CANDIDATES);
        size_t unused = 0;
        for (size_t i = r->start; i < (size_t)r->start + r->n; i++) {
            assert_int_equal(taken[i], 0);
            taken[i] = 1;
            unused += !t->cand[i].used;
        }
        assert_int_equal(unused, r->n_unused);
        n_unused += unused;
        const size_t n_cell = (size_t)r->grid.n_col * r->grid.n_row;
        assert_true(n_cell >= 1 && n_cell <= r->n);
        assert_int_equal(t->cand_cell_end[r->start + n_cell - 1], r->n);
        for (size_t c = 0, i = 0; c < n_cell; c++)
            for (; i < t->cand_cell_end[r->start + c]; i++) {
                const struct trk_candidate *a = &t->cand[r->start + i];
                const double u = ((double)a->x_m - (double)r->grid.x0_m) * (double)r->grid.inv_w_per_m;
                const double v = ((double)a->y_m - (double)r->grid.y0_m) * (double)r->grid.inv_h_per_m;
                /* its column and row, to within the rounding of the library's arithmetic */
                assert_true(u >= (double)(c / r->grid.n_row) - 1e-3 || c / r->grid.n_row == 0);
                assert_true(u <= (double)(c / r->grid.n_row + 1) + 1e-3 || c / r->grid.n_row == r->grid.n_col - 1u);
                assert_true(v >= (double)(c % r->grid.n_row) - 1e-3 || c % r->grid.n_row == 0);
                assert_true(v <= (double)(c % r->grid.n_row + 1) + 1e-3 || c % r->grid.n_row == r->grid.n_row - 1u);
            }
    }
    assert_int_equal(n_unused, t->n_cand);
}

/* The store holds only candidates within max_gap_scans,
 * and when a scan's unexplained detections do not fit, the oldest scan's
 * candidates make room first (a full scan of far-apart detections never
 * pairs: each scan replaces the previous one's). */
static void test_candidate_store(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-7);
    p.init.max_gap_scans = 3;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    rng_state = 5;
    for (int k = 0; k < 6; k++) {
        for (size_t i = 0; i < TRK_MAX_DETECTIONS; i++) /* 1 km apart in y: no pairs */
            d[i] = det_at(1e5 * urand(), 1000.0 * (double)(i + TRK_MAX_DETECTIONS * (size_t)k));
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, TRK_MAX_DETECTIONS, &rep));
        assert_int_equal(rep.n_started, 0);
        assert_int_equal(rep.n_candidates, TRK_MAX_CANDIDATES < TRK_MAX_DETECTIONS ? TRK_MAX_CANDIDATES : TRK_MAX_DETECTIONS);
        assert_int_equal(rep.n_candidates_dropped,
                         TRK_MAX_CANDIDATES < TRK_MAX_DETECTIONS ? TRK_MAX_DETECTIONS - TRK_MAX_CANDIDATES : 0);
        check_store(&tk);
        assert_int_equal(tk.n_runs, 1); /* the newest scan's only */
        assert_int_equal(tk.run[tk.run_first].scan_no, tk.scan_no);
    }
    /* small scans: three scans' worth kept, then the oldest expires */
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    for (int k = 0; k < 6; k++) {
        for (size_t i = 0; i < 4; i++) d[i] = det_at(5000.0 * (double)i + 1e5 * k, 0);
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, 4, &rep));
        assert_int_equal(rep.n_candidates, 4 * (k < 3 ? k + 1 : 4)); /* ages 0 .. 3 */
        check_store(&tk);
    }
    /* scans of varying size wrap the runs round the store; a target seen
     * in every scan still pairs with its previous detection, whichever
     * runs were evicted to make room, and its track starts at once */
    p.init.max_gap_scans = TRK_MAX_CANDIDATE_SCANS - 1;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    size_t n_started = 0;
    for (int k = 0; k < 40; k++) {
        const size_t n = 1 + (size_t)(urand() * 0.6 * TRK_MAX_DETECTIONS);
        d[0] = det_at(3.0 * k, 0); /* 3 m/s in x; a new target once the first starts */
        for (size_t i = 1; i < n; i++) { /* over 1e5 m x 1e8 m: a clutter pair has odds ~1e-4 */
            const double x = 1e5 * urand(), y = 1000.0 + 1e8 * urand();
            d[i] = det_at(x, y);
        }
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, n, &rep));
        assert_int_equal(rep.n_candidates_dropped, 0);
        n_started += rep.n_started;
        check_store(&tk);
        if (k == 1) assert_int_equal(rep.n_started, 1);
    }
    assert_int_equal(n_started, 1);
    const struct trk_track *tr = only_live_track();
    assert_non_null(tr);
    TRK_ASSERT_NEAR(tr->x[TRK_CV2_X], 3.0 * 39, 5.0, 0);
    /* runs of 39, 39, 23 and 35 % of the store, never pairing: the third
     * evicts the first, and the fourth finds the free room split in two
     * gaps each too small (the runs wrapped round): the runs move down and
     * all three are kept. The store keeps the newest scans whose sizes sum
     * to at most TRK_MAX_CANDIDATES. */
    p.init.max_gap_scans = TRK_MAX_CANDIDATE_SCANS - 1;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    static const double part[4] = {0.39, 0.39, 0.234, 0.35};
    size_t size[4], first = 0, held = 0;
    for (int k = 0; k < 4; k++) {
        const size_t n = size[k] = (size_t)(part[k] * TRK_MAX_CANDIDATES);
        assert_true(n >= 1 && n <= TRK_MAX_DETECTIONS);
        for (size_t i = 0; i < n; i++) d[i] = det_at(1e5 * (double)k, 1000.0 * (double)i);
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run_scan(k, d, n, &rep));
        check_store(&tk);
        for (held += n; held > TRK_MAX_CANDIDATES;) held -= size[first++];
        assert_int_equal(rep.n_candidates, held);
        assert_int_equal(tk.n_runs, (size_t)k + 1 - first);
        assert_int_equal(rep.n_started, 0);
    }
    assert_int_equal(first, 1);
    /* max_gap_scans is bounded by the runs the store holds */
    p.init.max_gap_scans = TRK_MAX_CANDIDATE_SCANS;
    const char *field = NULL;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "init.max_gap_scans");
}

/* The example's old mistake: M/N and K/N members written while the methods
 * are existence (the defaults) pun the probabilities into subnormals, which
 * confirmed clutter at once and never ended it. Refused, naming the field. */
static void test_existence_params_punned(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    sonar_params(&p, 1e-6);
    p.confirm.u.mn.m = 4;
    p.confirm.u.mn.n = 5;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "confirm.u.existence");
    sonar_params(&p, 1e-6);
    p.term.u.kn.k = 1;
    p.term.u.kn.n = 6;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "term.u.existence");
    sonar_params(&p, 1e-6);
    p.confirm.u.existence.p_confirm = TRK_REAL_C(0.4); /* confirm what more likely does not exist */
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    sonar_params(&p, 1e-6);
    p.term.u.existence.p_terminate = TRK_REAL_C(0.9995); /* above p_confirm 0.999 */
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "term.u.existence");
    sonar_params(&p, 1e-6);
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_point_start),
        cmocka_unit_test(test_min_existence),
        cmocka_unit_test(test_min_existence_crowded_store),
        cmocka_unit_test(test_pair_by_displacement_density),
        cmocka_unit_test(test_pair_against_a_strong_point),
        cmocka_unit_test(test_three_points_against_each_alone),
        cmocka_unit_test(test_velocity_gate_and_lifetime),
        cmocka_unit_test(test_candidate_store),
        cmocka_unit_test(test_existence_rejects_clutter_pair),
        cmocka_unit_test(test_full_table_replaces_weakest),
        cmocka_unit_test(test_new_target_in_nearly_full_table),
        cmocka_unit_test(test_weak_tentative_claims_nothing),
        cmocka_unit_test(test_no_duplicates),
        cmocka_unit_test(test_vanished_target_every_method),
        cmocka_unit_test(test_existence_params_punned),
    };
    return trk_run_tests("tracker_init", tests, NULL, NULL);
}
