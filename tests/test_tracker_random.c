/* test_tracker_random.c - the track table under long random and hostile
 * input: after every scan of a long random
 * run every live track's covariance is symmetric and positive definite (its
 * Cholesky succeeds) and finite, a tentative track's evidence against a
 * scatterer is within its bound, ids are unique, the live count and the
 * report agree; near-singular, overflowing and tiny covariances, squared
 * parameters that overflow or underflow, and time differences that would
 * overflow are refused or end the track as numerical. Runs in double and
 * float (make test's configurations). */
#include "trk_test.h"
#include "trk/linalg.h"
#include "trk/tracker.h"

static struct trk_tracker tk;

static uint64_t rng_state; /* the generator of trk_test.h */
static double urand(void) { return trk_test_urand(&rng_state); }

/* Invariants of the table after a scan; returns the numerical ends seen. */
static unsigned check_table(const struct trk_scan_report *rep)
{
    size_t live = 0;
    unsigned numerical = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *a = trk_tracker_track(&tk, i);
        if (!a) continue;
        live++;
        assert_true(a->id > 0);
        for (size_t j = i + 1; j < TRK_MAX_TRACKS; j++) {
            const struct trk_track *b = trk_tracker_track(&tk, j);
            if (b) assert_true(a->id != b->id);
        }
        if (a->status == TRK_TRACK_TERMINATED && a->end_reason == TRK_END_NUMERICAL) {
            numerical++;
            continue;
        }
        for (int k = 0; k < 4; k++) assert_true(isfinite(a->x[k]));
        for (int r = 0; r < 4; r++)
            for (int c = 0; c < 4; c++) assert_true(a->p[r * 4 + c] == a->p[c * 4 + r]);
        TRK_ASSERT_OK(trk_mat_check_spd(4, a->p, 0));
        assert_true(a->vis.pv >= 0 && a->vis.pv <= 1);
        if (a->status == TRK_TRACK_TENTATIVE && tk.params.confirm.method == TRK_CONFIRM_EXISTENCE) {
            /* the echoes' evidence against a scatterer: finite, within +-stationary_d2 / 2 */
            const trk_real s = a->test.confirm.existence.persist_llr, half = tk.params.stationary_d2 / 2;
            assert_true(s >= -half && s <= half);
        }
#if TRK_WITH_IMM
        double mu_sum = 0;
        for (int m = 0; m < tk.params.imm.n_models; m++) {
            for (int k = 0; k < 4; k++) assert_true(isfinite(a->imm.x[m][k]));
            TRK_ASSERT_OK(trk_mat_check_spd(4, a->imm.p[m], 0));
            assert_true(a->imm.mu[m] >= 0 && a->imm.mu[m] <= 1);
            mu_sum += a->imm.mu[m];
        }
        if (tk.params.imm.n_models > 0) TRK_ASSERT_NEAR(mu_sum, 1, 1e-4, 0);
        assert_true(a->maneuver_d2 >= 0);
#endif
    }
    assert_int_equal(live, trk_tracker_live_count(&tk));
    assert_true(rep->n_tracks_hit <= rep->n_tracks_updated);
    assert_int_equal(rep->n_numerical, numerical);
    return numerical;
}

/* A random detection: position in a 2 km square, one in four with its own
 * covariance, sometimes nearly singular (correlation up to 1 - 1e-6) or
 * tiny (1e-20 m^2) or huge (1e12 m^2). */
static struct trk_detection random_detection(void)
{
    struct trk_detection d;
    memset(&d, 0, sizeof d);
    d.x_m = (trk_real)(2000 * urand() - 1000);
    d.y_m = (trk_real)(2000 * urand() - 1000);
    if (urand() < 0.25) {
        const double u = urand();
        const double var = u < 0.1 ? 1e-20 : u < 0.2 ? 1e12 : 0.5 + 50 * urand();
        const double rho = (urand() < 0.3 ? 1 - 1e-6 : 0.9) * (2 * urand() - 1);
        d.has_cov = 1;
        d.cov_m2[TRK_COV2_XX] = (trk_real)var;
        d.cov_m2[TRK_COV2_YY] = (trk_real)(var * (0.5 + urand()));
        d.cov_m2[TRK_COV2_XY] =
            (trk_real)(rho * sqrt((double)d.cov_m2[TRK_COV2_XX] * (double)d.cov_m2[TRK_COV2_YY]));
    }
    return d;
}

/* Scan k's clutter density for detection i, from its own hash (the
 * detections' stream is untouched): mostly log-uniform over 1e-9 .. 1e-2
 * per m^2, 2 % each 0 (rejected), the smallest normal number and the
 * largest finite one (ratios of e^+-700 to the configured 1e-5). */
static trk_real random_density(long k, size_t i)
{
    uint64_t h = (uint64_t)k * 0x9E3779B97F4A7C15u + (uint64_t)i * 0xBF58476D1CE4E5B9u;
    h ^= h >> 31;
    h *= 0x94D049BB133111EBu;
    h ^= h >> 29;
    const double u = (double)(h >> 11) * 0x1.0p-53;
    if (u < 0.02) return 0;
    if (u < 0.04) return TRK_REAL_MIN;
    if (u < 0.06) return TRK_REAL_MAX;
    return (trk_real)pow(10.0, -9.0 + 7.0 * (u - 0.06) / 0.94);
}

/* A positive count from the environment variable name (a long run of the
 * same test: TRK_RANDOM_SCANS=100000), else def. */
static long env_count(const char *name, long def)
{
    const char *v = getenv(name);
    char *end;
    const long n = v ? strtol(v, &end, 10) : 0;
    return v && *v && !*end && n > 0 ? n : def;
}

/* Random scans (random gaps, counts, covariances) through configurations
 * that stress the arithmetic: the defaults, q = 0 (P becomes singular
 * along the tiny own covariances), and M/N with single-point initiation
 * and a huge velocity prior; in a build with TRK_WITH_IMM also IMM tracks of
 * three models (turns at 3 deg/s) with the per-track PDA and, with q = 0,
 * joint association; every third scan carries the caller's clutter
 * densities, extreme ones among them. Every scan: the invariants (every
 * model's too). Numerical ends are printed, not asserted: q = 0 (a
 * singular prediction), the 1e7 m/s velocity prior (a coasting track's
 * prediction at the arithmetic's limit, where the caller's densities
 * weigh its detections nothing) and the 1e-20 m^2 covariances given
 * nearly all the weight (a posterior whose factorisation rounds either
 * way: in the size-optimised builds' plain LDL' test it fails) may end
 * tracks so. A joint cluster whose every event underflowed gave 0 / 0
 * marginals in the defaults (test_caller_density, jpda.h n_floored).
 * TRK_RANDOM_SCANS (scans per configuration, 4000) and TRK_RANDOM_SEED
 * (added to each configuration's seed, 0) make a longer or another run. */
static void test_random_scans(void **state)
{
    (void)state;
    static struct trk_detection det[TRK_MAX_DETECTIONS];
    static trk_real lam[TRK_MAX_DETECTIONS];
    const long n_scans = env_count("TRK_RANDOM_SCANS", 4000), seed = env_count("TRK_RANDOM_SEED", 0);
    unsigned numerical = 0;
    const int n_cfg = TRK_WITH_IMM ? 5 : 3;
    for (int cfg = 0; cfg < n_cfg; cfg++) {
        struct trk_tracker_params p;
        if (cfg == 2) trk_tracker_mn_kn_params(&p);
        else trk_tracker_default_params(&p);
        p.sensor[0].meas_cov_m2[0] = p.sensor[0].meas_cov_m2[2] = 4;
        p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-5);
        if (cfg == 1 || cfg == 4) p.process_noise_q = 0;
        if (cfg == 2) p.init_speed_sigma_mps = TRK_REAL_C(1e7);
#if TRK_WITH_IMM
        if (cfg >= 3) TRK_ASSERT_OK(trk_tracker_imm_params(&p, TRK_REAL_C(0.0524), TRK_REAL_C(0.9)));
        if (cfg == 3) p.association = TRK_ASSOC_PDA;
#endif
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        unsigned numerical_cfg = 0;
        rng_state = 77 + (uint64_t)cfg + (uint64_t)seed;
        int64_t t_us = 0;
        for (long k = 0; k < n_scans; k++) {
            const size_t cap = TRK_MAX_DETECTIONS < 40 ? TRK_MAX_DETECTIONS : 40;
            const size_t n = (size_t)(urand() * (double)(cap + 1)) % (cap + 1);
            for (size_t i = 0; i < n; i++) det[i] = random_detection();
            /* a few detections repeat a previous position: tracks form */
            for (size_t i = 0; i + 1 < n && i < 4; i++) {
                det[i].x_m = (trk_real)(100.0 * (double)i + 3 * urand());
                det[i].y_m = (trk_real)(-50.0 * (double)i + 3 * urand());
            }
            t_us += 1 + (int64_t)(urand() * 8e6);
            /* every third scan with the caller's densities */
            const int dense = k % 3 == 2;
            for (size_t i = 0; dense && i < n; i++) lam[i] = random_density(k, i);
            const struct trk_scan scan = {t_us, 0, n, det, NULL, 0, {0, 0, 0}, dense ? lam : NULL};
            struct trk_scan_report rep;
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
            assert_int_equal(rep.n_detections, n);
            assert_true(dense || rep.n_rejected_density == 0);
            numerical_cfg += check_table(&rep);
        }
        print_message("configuration %d: %u tracks ended as numerical\n", cfg, numerical_cfg);
        numerical += numerical_cfg;
    }
    print_message("%u tracks ended as numerical in %ld random scans\n", numerical, n_cfg * n_scans);
}

/* One polar detection from world point (x, y) seen from pose: its range
 * and bearing with noise (sigma_r, sigma_b), an amplitude above the
 * threshold (1) or, one in 20, below it. */
static struct trk_polar_detection polar_of(const struct trk_pose *pose, double x, double y, double sr, double sb)
{
    struct trk_polar_detection d;
    memset(&d, 0, sizeof d);
    const double dx = x - (double)pose->x_m, dy = y - (double)pose->y_m;
    d.range_m = (trk_real)(hypot(dx, dy) + sr * (2 * urand() - 1));
    d.bearing_rad = (trk_real)(atan2(dx, dy) - (double)pose->heading_rad + sb * (2 * urand() - 1));
    d.has_amplitude = 1;
    d.amplitude = (trk_real)(urand() < 0.05 ? 0.5 * urand() : 1 + 4 * urand());
    return d;
}

/* A hostile polar detection: range 0, negative, NaN or far beyond the
 * surveillance bound, bearing NaN or infinite or many turns round,
 * amplitude NaN, negative or infinite, or none. */
static struct trk_polar_detection hostile_polar(void)
{
    struct trk_polar_detection d;
    memset(&d, 0, sizeof d);
    d.range_m = (trk_real)(8000 * urand());
    d.bearing_rad = (trk_real)(2 * urand() - 1);
    d.has_amplitude = urand() < 0.8;
    d.amplitude = (trk_real)(1 + urand());
    switch ((int)(urand() * 9)) {
    case 0: d.range_m = 0; break;
    case 1: d.range_m = (trk_real)-100; break;
    case 2: d.range_m = (trk_real)NAN; break;
    case 3: d.range_m = TRK_REAL_IS_FLOAT ? (trk_real)1e30 : (trk_real)1e200; break;
    case 4: d.bearing_rad = (trk_real)NAN; break;
    case 5: d.bearing_rad = (trk_real)INFINITY; break;
    case 6: d.bearing_rad = (trk_real)(1000 * urand()); break; /* many turns: a valid bearing */
    case 7: d.amplitude = (trk_real)(urand() < 0.5 ? -1.0 : (double)NAN); break;
    default: d.amplitude = (trk_real)INFINITY; break;
    }
    return d;
}

/* The sonar configurations of the random run: a polar sensor (sigmas
 * 7.5 m and 1.5 deg, 0.5-8 km, +-60 deg, a P_D profile falling with range,
 * a clutter profile, the 16 x 32 clutter map of the defaults), its pose
 * carried by every scan. cfg 0: the defaults with a Rayleigh amplitude
 * model and persistent returns in it; 1: positions only, the unbiased
 * conversion, no hold of still tracks, weak pairs started at once, the
 * coverage all round with a map of 16 x 3 cells pooled over 5 x 5 (the
 * window wraps in bearing and is wider than the map), guard 2; 2:
 * the per-track PDA with amplitudes, the gate-count check at 0.5; 3 (a
 * build with TRK_WITH_IMM): the defaults with IMM tracks (turns at
 * 3 deg/s). */
static void polar_params(int cfg, struct trk_tracker_params *p)
{
    trk_tracker_default_params(p);
    struct trk_sensor_params *s = &p->sensor[0];
    s->kind = TRK_SENSOR_POLAR;
    s->sigma_range_m = TRK_REAL_C(7.5);
    s->sigma_bearing_rad = TRK_REAL_C(0.026);
    s->coverage.min_range_m = 500;
    s->coverage.max_range_m = 8000;
    s->coverage.half_width_rad = TRK_REAL_C(1.047);
    s->pd_profile.n = 3;
    s->clutter_profile.n = 3;
    static const double range_m[3] = {500, 3000, 8000}, pd[3] = {0.9, 0.7, 0.4}, lam[3] = {2e-5, 1e-6, 3e-7};
    for (int k = 0; k < 3; k++) {
        s->pd_profile.range_m[k] = s->clutter_profile.range_m[k] = (trk_real)range_m[k];
        s->pd_profile.pd[k] = (trk_real)pd[k];
        s->clutter_profile.density_per_m2[k] = (trk_real)lam[k];
    }
    s->clutter_density_per_m2 = TRK_REAL_C(1e-6);
    s->pd = TRK_REAL_C(0.6);
    trk_polar_cov(s, 0, 4000, s->meas_cov_m2);
    if (cfg != 1) {
        TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&s->amplitude, 1, 10, TRK_REAL_C(1e-3)));
        s->use_amplitude = 1;
        s->persistent_share = TRK_REAL_C(0.1);
        s->persistent_pd = TRK_REAL_C(0.85);
    }
    if (cfg == 1) {
        s->conversion = TRK_POLAR_UNBIASED;
        p->stationary_d2 = 0;
        p->init.min_existence = 0;
        s->coverage.half_width_rad = 0;
        if (p->clutter_map.n_range > 0) { /* a build with the map */
            p->clutter_map.n_bearing = 3;
            p->clutter_map.window_cells = 2;
            p->clutter_map.guard_cells = 2;
            p->clutter_map.edge_alpha = TRK_REAL_C(0.5); /* quadrants of a wrapping window, often taken */
        }
    }
    if (cfg == 2) {
        p->association = TRK_ASSOC_PDA;
        p->confirm.u.existence.count_alpha = TRK_REAL_C(0.5);
    }
#if TRK_WITH_IMM
    if (cfg == 3) TRK_ASSERT_OK(trk_tracker_imm_params(p, TRK_REAL_C(0.0524), TRK_REAL_C(0.9)));
#endif
}

/* Random scans of a sonar on a platform that moves and turns: movers that
 * cross the sector and still points (persistent returns) among uniform
 * clutter; counts from 0 to 4 x TRK_MAX_DETECTIONS (thinned beyond
 * capacity); one detection in 50 hostile (hostile_polar); gaps of 1 us to
 * 20 s; every third scan with the caller's densities (random_density).
 * Every scan: the table's invariants (check_table), the report's counts
 * add up, and the density the tracker uses is finite and positive. */
static void test_random_polar_scans(void **state)
{
    (void)state;
    enum { N_POLAR_MAX = 4 * TRK_MAX_DETECTIONS, N_MOVERS = 6, N_STILL = 4 };
    static struct trk_polar_detection det[N_POLAR_MAX];
    static trk_real lam[N_POLAR_MAX];
    const long n_scans = env_count("TRK_RANDOM_SCANS", 4000) / 2, seed = env_count("TRK_RANDOM_SEED", 0);
    for (int cfg = 0; cfg < (TRK_WITH_IMM ? 4 : 3); cfg++) {
        struct trk_tracker_params p;
        polar_params(cfg, &p);
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        rng_state = 1077 + (uint64_t)cfg + (uint64_t)seed;
        int64_t t_us = 0;
        struct trk_pose pose = {0, 0, 0};
        double mx[N_MOVERS], my[N_MOVERS], mvx[N_MOVERS], mvy[N_MOVERS], sx[N_STILL], sy[N_STILL];
        for (int i = 0; i < N_MOVERS; i++) {
            mx[i] = 6000 * urand() - 3000;
            my[i] = 1000 + 6000 * urand();
            mvx[i] = 20 * urand() - 10;
            mvy[i] = 20 * urand() - 10;
        }
        for (int i = 0; i < N_STILL; i++) {
            sx[i] = 4000 * urand() - 2000;
            sy[i] = 1000 + 5000 * urand();
        }
        unsigned numerical = 0;
        for (long k = 0; k < n_scans; k++) {
            const double u = urand();
            const double dt_s = u < 0.02 ? 1e-6 : u < 0.05 ? 20 * urand() : 2 + 4 * urand();
            t_us += 1 + (int64_t)(dt_s * 1e6);
            pose.x_m = (trk_real)((double)pose.x_m + 3 * dt_s * sin((double)pose.heading_rad));
            pose.y_m = (trk_real)((double)pose.y_m + 3 * dt_s * cos((double)pose.heading_rad));
            pose.heading_rad = (trk_real)((double)pose.heading_rad + (urand() < 0.1 ? 0.5 * (2 * urand() - 1) : 0));
            const double v = urand();
            const size_t n_clutter = (size_t)(v < 0.05 ? (double)(N_POLAR_MAX - N_MOVERS - N_STILL) * urand()
                                                       : v < 0.1 ? 0 : 120 * urand());
            size_t n = 0;
            for (int i = 0; i < N_MOVERS; i++) {
                mx[i] += mvx[i] * dt_s;
                my[i] += mvy[i] * dt_s;
                if (urand() < 0.7) det[n++] = polar_of(&pose, mx[i], my[i], 7.5, 0.026);
            }
            for (int i = 0; i < N_STILL; i++)
                if (urand() < 0.85) det[n++] = polar_of(&pose, sx[i], sy[i], 7.5, 0.026);
            for (size_t i = 0; i < n_clutter; i++) {
                struct trk_polar_detection *d = &det[n++];
                if (urand() < 0.02) {
                    *d = hostile_polar();
                    continue;
                }
                memset(d, 0, sizeof *d);
                d->range_m = (trk_real)(500 + 7500 * urand());
                d->bearing_rad = (trk_real)(2.2 * urand() - 1.1);
                d->has_amplitude = 1;
                d->amplitude = (trk_real)(1 + urand() * urand() * 3);
            }
            const int dense = k % 3 == 2;
            for (size_t i = 0; dense && i < n; i++) lam[i] = random_density(k, i);
            struct trk_scan scan;
            trk_scan_init_polar(&scan, t_us, 0, n, det, &pose);
            if (dense) scan.clutter_density_per_m2 = lam;
            struct trk_scan_report rep;
            const trk_status st = trk_tracker_process_scan(&tk, &scan, &rep);
            if (dt_s > (double)p.max_dt_s) {
                assert_int_equal(st, TRK_E_RANGE);
                continue;
            }
            TRK_ASSERT_OK(st);
            assert_int_equal(rep.n_detections, n);
            assert_int_equal(rep.n_detections, rep.n_kept + rep.n_thinned + rep.n_rejected_nonfinite +
                                                   rep.n_rejected_cov + rep.n_rejected_amplitude +
                                                   rep.n_rejected_region + rep.n_below_threshold +
                                                   rep.n_rejected_density);
            assert_true(rep.n_kept <= TRK_MAX_DETECTIONS);
            assert_true(rep.n_thinned == 0 || rep.n_kept == TRK_MAX_DETECTIONS); /* thinned only when full */
            numerical += check_table(&rep);
            trk_real l = 0;
            const double rr = 500 + 7500 * urand(), bb = 2 * urand() - 1 + (double)pose.heading_rad;
            TRK_ASSERT_OK(trk_tracker_clutter_at(&tk, 0, &pose, (trk_real)((double)pose.x_m + rr * sin(bb)),
                                                 (trk_real)((double)pose.y_m + rr * cos(bb)), &l));
            assert_true(isfinite(l) && l > 0);
        }
        print_message("polar configuration %d: %u tracks ended as numerical\n", cfg, numerical);
        assert_int_equal(numerical, 0);
    }
}

/* Covariances too near singular for the arithmetic, or whose xx yy
 * overflows, are refused (TRK_COV2_MIN_REL_DET); tiny ones with q = 0 end
 * their track as numerical rather than leaving a rank-deficient P. */
static void test_hostile_covariances(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_detection d[3];
    memset(d, 0, sizeof d);
    d[0].has_cov = 1; /* det 2.2e-16: passes a plain det > 0 test */
    d[0].cov_m2[TRK_COV2_XX] = d[0].cov_m2[TRK_COV2_YY] = 1;
    d[0].cov_m2[TRK_COV2_XY] = (trk_real)0.99999999999999989;
    d[1].has_cov = 1; /* xx yy overflows */
    d[1].cov_m2[TRK_COV2_XX] = d[1].cov_m2[TRK_COV2_YY] = TRK_REAL_IS_FLOAT ? (trk_real)1e30 : (trk_real)1e200;
    d[2].has_cov = 1; /* correlation 0.5: fine */
    d[2].cov_m2[TRK_COV2_XX] = d[2].cov_m2[TRK_COV2_YY] = 4;
    d[2].cov_m2[TRK_COV2_XY] = 2;
    const struct trk_scan scan = {0, 0, 3, d, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_rejected_cov, 2);
    /* the same for a sensor's covariance */
    const char *field = NULL;
    p.sensor[0].meas_cov_m2[TRK_COV2_XX] = p.sensor[0].meas_cov_m2[TRK_COV2_YY] = TRK_REAL_IS_FLOAT ? (trk_real)1e30 : (trk_real)1e200;
    p.sensor[0].meas_cov_m2[TRK_COV2_XY] = 0;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_NOT_SPD);
    assert_string_equal(field, "sensor[0].meas_cov_m2");
    /* q = 0 and detections of variance 1e-20 m^2 at one place: P loses
     * rank, the track ends as numerical (never an indefinite P) */
    trk_tracker_mn_kn_params(&p);
    p.process_noise_q = 0;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    unsigned numerical = 0;
    for (int k = 0; k < 20; k++) {
        struct trk_detection one;
        memset(&one, 0, sizeof one);
        one.has_cov = 1;
        one.cov_m2[TRK_COV2_XX] = one.cov_m2[TRK_COV2_YY] = (trk_real)1e-20;
        one.x_m = 1000;
        const struct trk_scan s1 = {(int64_t)k * 1000000, 0, 1, &one, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s1, &rep));
        numerical += check_table(&rep);
    }
    print_message("q = 0, 1e-20 m^2 detections: %u numerical ends\n", numerical);
}

/* Parameters whose square overflows or underflows are refused with the
 * field named. */
static void test_squared_parameters(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    const trk_real bad[] = {TRK_REAL_IS_FLOAT ? (trk_real)1e20 : (trk_real)1.4e154,
                            TRK_REAL_IS_FLOAT ? (trk_real)1e-20 : (trk_real)1e-160};
    for (int i = 0; i < 2; i++) {
        trk_tracker_default_params(&p);
        p.init_speed_sigma_mps = bad[i];
        TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
        assert_string_equal(field, "init_speed_sigma_mps");
        TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_RANGE);
    }
    trk_tracker_default_params(&p);
    p.init_speed_sigma_mps = TRK_REAL_C(1e7); /* large but representable squared */
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
}

/* The two extreme times in range are a gap the tracker refuses, never an
 * overflowing difference (TRK_TIME_US_MAX = 2^62 - 1). */
static void test_extreme_times(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.max_dt_s = TRK_REAL_C(1e9);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_scan_report rep;
    const struct trk_scan first = {-TRK_TIME_US_MAX, 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &first, &rep));
    const struct trk_scan last = {TRK_TIME_US_MAX, 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk, &last, &rep), TRK_E_RANGE);
    const struct trk_scan beyond = {TRK_TIME_US_MAX + 1, 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk, &beyond, &rep), TRK_E_RANGE);
    assert_true((double)TRK_TIME_US_MAX - (double)(-TRK_TIME_US_MAX) < 9.3e18); /* below 2^63 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hostile_covariances),
        cmocka_unit_test(test_squared_parameters),
        cmocka_unit_test(test_extreme_times),
        cmocka_unit_test(test_random_scans),
        cmocka_unit_test(test_random_polar_scans),
    };
    return trk_run_tests("tracker_random", tests, NULL, NULL);
}
