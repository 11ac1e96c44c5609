/* test_tracker_polar.c - a polar sensor on a moving platform in the track
 * table, with a P_D profile and a coverage sector (trk/tracker.h "Polar
 * sensors and where a sensor sees"):
 *   - a polar scan is tracked exactly as the same detections converted by
 *     the caller and given as positions (the same tracks, ids, states);
 *   - stationary targets seen from a moving platform (the pose per scan)
 *     are held where they are;
 *   - a track's existence after a missed scan is the IPDA closed form with
 *     the profile's P_D at its predicted position, at two ranges;
 *   - a track out of the sensor's sight (the platform turned away) is only
 *     predicted: existence delta^K pv, no miss counted, no test stepped; it
 *     continues under its id when seen again (max_unseen_scans), ends
 *     after more scans out of sight than that (at once by default: its
 *     target left the coverage); a tentative track out of sight ends
 *     (rejected);
 *   - a coasting track ends on the covariance bound ratio^2 tr R with R the
 *     conversion's covariance at its predicted position, at the first scan
 *     its predicted trace is over it;
 *   - nothing starts outside the coverage; malformed polar detections are
 *     counted, malformed polar scans refused;
 *   - with a clutter profile, a lone track's beta0 is the PDA's closed form
 *     with lambda and P_D at its predicted position, at two ranges. */
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/kalman.h"
#include "trk/tracker.h"

#define DEG (3.14159265358979323846 / 180)
#define SCAN_US(k) ((int64_t)(k) * 8000000)
#define DT_S 8.0

static struct trk_tracker tk_a, tk_b;

/* Range sigma 7.5 m, bearing 1.5 deg, clutter 1e-8 per m^2, P_D 0.9 near
 * falling to 0.5 at 8 km. */
static void polar_params(struct trk_tracker_params *p)
{
    trk_test_polar_params(p, 1e-8);
    struct trk_sensor_params *s = &p->sensor[0];
    s->pd_profile.n = 3;
    const double r[3] = {500, 2000, 8000}, pd[3] = {0.9, 0.9, 0.5};
    for (int k = 0; k < 3; k++) s->pd_profile.range_m[k] = (trk_real)r[k], s->pd_profile.pd[k] = (trk_real)pd[k];
    p->process_noise_q = TRK_REAL_C(1e-3);
    p->init.max_speed_mps = 12;
}

/* The platform at scan k: from the origin north at 3 m/s, heading north. */
static struct trk_pose platform(int k)
{
    const struct trk_pose o = {0, (trk_real)(3.0 * DT_S * k), 0};
    return o;
}

/* A polar detection of (x, y) from pose o with noise (rng) or without. */
static struct trk_polar_detection seen(const struct trk_pose *o, double x, double y, uint64_t *rng)
{
    const double dx = x - o->x_m, dy = y - o->y_m;
    struct trk_polar_detection d = {0, 0, 0, 0};
    d.range_m = (trk_real)(sqrt(dx * dx + dy * dy) + (rng ? 7.5 * trk_test_nrand(rng) : 0));
    d.bearing_rad = (trk_real)(atan2(dx, dy) - o->heading_rad + (rng ? 1.5 * DEG * trk_test_nrand(rng) : 0));
    return d;
}

static struct trk_scan polar_scan(int k, const struct trk_pose *o, size_t n, const struct trk_polar_detection *d)
{
    const struct trk_scan s = {SCAN_US(k), 0, n, NULL, d, 1, *o, NULL};
    return s;
}

static void assert_same_tables(const struct trk_tracker *a, const struct trk_tracker *b)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *ta = trk_tracker_track(a, i), *tb = trk_tracker_track(b, i);
        assert_true((ta == NULL) == (tb == NULL));
        if (!ta) continue;
        assert_int_equal(ta->id, tb->id);
        assert_int_equal(ta->status, tb->status);
        for (int j = 0; j < TRK_CV2_NX; j++) TRK_ASSERT_NEAR(tb->x[j], ta->x[j], 0, 0);
        for (int j = 0; j < TRK_CV2_NX * TRK_CV2_NX; j++) TRK_ASSERT_NEAR(tb->p[j], ta->p[j], 0, 0);
        TRK_ASSERT_NEAR(tb->vis.pv, ta->vis.pv, 0, 0);
    }
}

/* Four targets (one stationary, three moving) and clutter over the
 * sector: polar scans into tk_a, the same converted into positions
 * (trk_polar_to_cartesian, no covariance given: the sensor's conversion
 * covariance at the position) into tk_b. */
static void test_polar_equals_converted(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-7);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
    uint64_t rng = 5;
    for (int k = 0; k < 40; k++) {
        const struct trk_pose o = platform(k);
        struct trk_polar_detection pd[32];
        struct trk_detection cd[32];
        size_t n = 0;
        const double tx[4] = {800, -2500 + 4.0 * DT_S * k, 3000, -1000}, ty[4] = {3000, 5000, 6000 - 5.0 * DT_S * k, 1500};
        for (int t = 0; t < 4; t++)
            if (trk_test_urand(&rng) < 0.85) pd[n++] = seen(&o, tx[t], ty[t], &rng);
        for (int c = 0; c < 12; c++) {
            struct trk_polar_detection d = {(trk_real)(500 + 7500 * trk_test_urand(&rng)),
                                            (trk_real)((120 * trk_test_urand(&rng) - 60) * DEG), 0, 0};
            pd[n++] = d;
        }
        for (size_t i = 0; i < n; i++) {
            TRK_ASSERT_OK(trk_polar_to_cartesian(&p.sensor[0], &o, &pd[i], &cd[i]));
            cd[i].has_cov = 0;
        }
        const struct trk_scan sa = polar_scan(k, &o, n, pd);
        struct trk_scan sb = sa;
        sb.polar = NULL;
        sb.detections = cd;
        struct trk_scan_report ra, rb;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &sa, &ra));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &sb, &rb));
        assert_int_equal(ra.n_kept, n);
        assert_int_equal(rb.n_kept, n);
        assert_same_tables(&tk_a, &tk_b);
    }
    size_t confirmed = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk_a, i);
        confirmed += tr && tr->status == TRK_TRACK_CONFIRMED;
    }
    assert_true(confirmed >= 4);
}

/* Scans of twice the capacity: the polar scan is thinned and tracked
 * exactly as the same detections converted by the caller (the same kept
 * detections, reports and tables, bit for bit: the load reuses the
 * selection's conversions). */
static void test_thinned_polar_equals_converted(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-6);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
    enum { N = 2 * TRK_MAX_DETECTIONS + 5 };
    static struct trk_polar_detection pd[N];
    static struct trk_detection cd[N];
    uint64_t rng = 9;
    size_t thinned = 0;
    for (int k = 0; k < 12; k++) {
        const struct trk_pose o = platform(k);
        const double tx[3] = {800, -2500 + 4.0 * DT_S * k, 3000}, ty[3] = {3000, 5000, 6000 - 5.0 * DT_S * k};
        size_t n = 0;
        for (int t = 0; t < 3; t++) pd[n++] = seen(&o, tx[t], ty[t], &rng);
        while (n < N) {
            const struct trk_polar_detection d = {(trk_real)(500 + 7500 * trk_test_urand(&rng)),
                                                  (trk_real)((120 * trk_test_urand(&rng) - 60) * DEG), 0, 0};
            pd[n++] = d;
        }
        for (size_t i = 0; i < n; i++) TRK_ASSERT_OK(trk_polar_to_cartesian(&p.sensor[0], &o, &pd[i], &cd[i]));
        const struct trk_scan sa = polar_scan(k, &o, n, pd);
        struct trk_scan sb = sa;
        sb.polar = NULL;
        sb.detections = cd;
        struct trk_scan_report ra, rb;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &sa, &ra));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &sb, &rb));
        assert_int_equal(ra.n_kept, rb.n_kept);
        assert_int_equal(ra.n_thinned, rb.n_thinned);
        assert_int_equal(ra.n_kept + ra.n_thinned, N);
        assert_int_equal(ra.n_started, rb.n_started);
        assert_int_equal(ra.thin_in_gates, rb.thin_in_gates);
        thinned += ra.n_thinned;
        assert_same_tables(&tk_a, &tk_b);
    }
    assert_true(thinned > 0);
}

/* The confirmed track nearest (x, y), or NULL. */
static const struct trk_track *track_near(const struct trk_tracker *t, double x, double y, double within_m)
{
    const struct trk_track *best = NULL;
    double bd = within_m;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(t, i);
        if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
        const double d = hypot(tr->x[TRK_CV2_X] - x, tr->x[TRK_CV2_Y] - y);
        if (d < bd) bd = d, best = tr;
    }
    return best;
}

/* Three stationary targets at 1.5-6 km from a platform moving north: each
 * held within 3 sigma of its cross-range error, at rest. */
static void test_moving_platform(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const double tx[3] = {1000, -3000, 2000}, ty[3] = {1500, 4000, 6000};
    uint64_t rng = 9;
    for (int k = 0; k < 30; k++) {
        const struct trk_pose o = platform(k);
        struct trk_polar_detection pd[3];
        for (int t = 0; t < 3; t++) pd[t] = seen(&o, tx[t], ty[t], &rng);
        const struct trk_scan s = polar_scan(k, &o, 3, pd);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    const struct trk_pose o = platform(29);
    for (int t = 0; t < 3; t++) {
        const struct trk_track *tr = track_near(&tk_a, tx[t], ty[t], 500);
        assert_non_null(tr);
        const double r = hypot(tx[t] - o.x_m, ty[t] - o.y_m), sigma_cross = r * 1.5 * DEG;
        assert_true(hypot(tr->x[TRK_CV2_X] - tx[t], tr->x[TRK_CV2_Y] - ty[t]) < 3 * sigma_cross);
        assert_true(hypot(tr->x[TRK_CV2_VX], tr->x[TRK_CV2_VY]) < 1.0);
    }
}

/* pv after a scan without detections, IPDA: pv_pred (1 - P_D P_G) / (1 -
 * pv_pred P_D P_G), pv_pred = delta pv (delta_become 0). */
static double missed_pv(double pv, double delta, double pd, double pg)
{
    const double pp = delta * pv;
    return pp * (1 - pd * pg) / (1 - pp * pd * pg);
}

static void test_existence_with_profile(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const double tx[2] = {300, -500}, ty[2] = {1200, 6500}; /* P_D 0.9 and about 0.6 */
    uint64_t rng = 21;
    for (int k = 0; k < 12; k++) {
        const struct trk_pose o = platform(k);
        struct trk_polar_detection pd[2];
        for (int t = 0; t < 2; t++) pd[t] = seen(&o, tx[t], ty[t], &rng);
        const struct trk_scan s = polar_scan(k, &o, 2, pd);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    double pv[2], px[2], py[2];
    const struct trk_track *tr[2];
    for (int t = 0; t < 2; t++) {
        tr[t] = track_near(&tk_a, tx[t], ty[t], 300);
        assert_non_null(tr[t]);
        pv[t] = tr[t]->vis.pv;
        px[t] = tr[t]->x[TRK_CV2_X] + DT_S * tr[t]->x[TRK_CV2_VX];
        py[t] = tr[t]->x[TRK_CV2_Y] + DT_S * tr[t]->x[TRK_CV2_VY];
    }
    const struct trk_pose o = platform(12);
    const struct trk_scan s = polar_scan(12, &o, 0, NULL);
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    double pd_at[2];
    for (int t = 0; t < 2; t++) {
        pd_at[t] = trk_sensor_pd_at(&p.sensor[0], &o, (trk_real)px[t], (trk_real)py[t]);
        TRK_ASSERT_NEAR(tr[t]->vis.pv, missed_pv(pv[t], p.visibility.delta_stay, pd_at[t], p.gate_prob), 0,
                        TRK_TOL(1e-12, 1e-5));
    }
    assert_true(pd_at[0] > 0.89 && pd_at[1] < 0.65); /* the profile, not the sensor's pd */
}

/* A confirmed track, then the platform turns east for K scans: with a
 * +-60 degree sector the track (north) is out of sight. */
static void test_out_of_sight(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.sensor[0].coverage.half_width_rad = (trk_real)(60 * DEG);
    p.sensor[0].coverage.max_range_m = 8000;
    const int K = 6;
    p.max_unseen_scans = (uint32_t)K; /* the sector turns away for K scans and back */
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const struct trk_pose north = {0, 0, 0}, east = {0, 0, (trk_real)(90 * DEG)};
    const double tx = 200, ty = 3000;
    uint64_t rng = 33;
    int k = 0;
    for (; k < 10; k++) {
        const struct trk_polar_detection d = seen(&north, tx, ty, &rng);
        const struct trk_scan s = polar_scan(k, &north, 1, &d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    const struct trk_track *tr = track_near(&tk_a, tx, ty, 100);
    assert_non_null(tr);
    const uint32_t id = tr->id, n_scans = tr->n_scans, misses = tr->n_misses_in_row;
    double pv = tr->vis.pv;
    for (int j = 0; j < K; j++, k++) { /* looking east: the track is 86 degrees off */
        const struct trk_scan s = polar_scan(k, &east, 0, NULL);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
        pv *= p.visibility.delta_stay;
        TRK_ASSERT_NEAR(tr->vis.pv, pv, 0, TRK_TOL(1e-13, 1e-6));
        assert_int_equal(tr->status, TRK_TRACK_CONFIRMED);
        assert_int_equal(tr->n_scans, n_scans);
        assert_int_equal(tr->n_misses_in_row, misses);
    }
    for (int j = 0; j < 3; j++, k++) { /* north again: the same track */
        const struct trk_polar_detection d = seen(&north, tx, ty, &rng);
        const struct trk_scan s = polar_scan(k, &north, 1, &d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    assert_int_equal(tr->status, TRK_TRACK_CONFIRMED);
    assert_int_equal(tr->id, id);
    assert_true(tr->vis.pv > 0.99);
    /* K + 1 scans out of sight end it (terminated); with the default 0, the
     * first does: a track whose target left the coverage */
    for (int limit = K; limit >= 0; limit -= K) {
        p.max_unseen_scans = (uint32_t)limit;
        TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
        int kk = 0;
        for (; kk < 10; kk++) {
            const struct trk_polar_detection d = seen(&north, tx, ty, &rng);
            const struct trk_scan s = polar_scan(kk, &north, 1, &d);
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &s, NULL));
        }
        const struct trk_track *tb = track_near(&tk_b, tx, ty, 100);
        assert_non_null(tb);
        for (int j = 0; j <= limit; j++, kk++) {
            assert_int_equal(tb->status, TRK_TRACK_CONFIRMED);
            const struct trk_scan s = polar_scan(kk, &east, 0, NULL);
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &s, NULL));
        }
        assert_int_equal(tb->status, TRK_TRACK_TERMINATED);
        assert_int_equal(tb->end_reason, TRK_END_TERMINATED);
        if (limit == 0) break;
    }
    /* the same K scans seen but missed end it (existence below 0.1) */
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
    for (k = 0; k < 10; k++) {
        const struct trk_polar_detection d = seen(&north, tx, ty, &rng);
        const struct trk_scan s = polar_scan(k, &north, 1, &d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &s, NULL));
    }
    for (int j = 0; j < K; j++, k++) {
        const struct trk_scan s = polar_scan(k, &north, 0, NULL);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &s, NULL));
    }
    assert_null(track_near(&tk_b, tx, ty, 1000));
    /* a tentative track out of sight ends at once (rejected): two points
     * north make it, then the platform looks east */
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &p));
    for (k = 0; k < 2; k++) {
        const struct trk_polar_detection d = seen(&north, tx, ty, NULL);
        const struct trk_scan s = polar_scan(k, &north, 1, &d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &s, NULL));
    }
    const struct trk_track *tent = trk_tracker_track(&tk_b, 0);
    assert_non_null(tent);
    assert_int_equal(tent->status, TRK_TRACK_TENTATIVE);
    const struct trk_scan se = polar_scan(k, &east, 0, NULL);
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &se, &rep));
    assert_int_equal(tent->status, TRK_TRACK_TERMINATED);
    assert_int_equal(tent->end_reason, TRK_END_REJECTED);
    assert_int_equal(rep.n_terminated, 1);
}

/* ratio^2 tr R at (x, y) from pose o (R the first-order conversion's). */
static double bound_at(const struct trk_tracker_params *p, const struct trk_pose *o, double x, double y)
{
    trk_real c[3];
    trk_polar_cov(&p->sensor[0], (trk_real)(x - o->x_m), (trk_real)(y - o->y_m), c);
    return p->max_pos_sigma_ratio * p->max_pos_sigma_ratio * (c[TRK_COV2_XX] + c[TRK_COV2_YY]);
}

static void test_covariance_bound_at_position(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.max_pos_sigma_ratio = 3;
    p.term.u.existence.p_terminate = TRK_REAL_C(1e-30); /* only the bound ends it */
    p.process_noise_q = TRK_REAL_C(0.5);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const struct trk_pose o = {0, 0, 0};
    const double tx = 100, ty = 1500; /* near: R small, the bound tight */
    uint64_t rng = 44;
    int k = 0;
    for (; k < 10; k++) {
        const struct trk_polar_detection d = seen(&o, tx, ty, &rng);
        const struct trk_scan s = polar_scan(k, &o, 1, &d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    const struct trk_track *tr = track_near(&tk_a, tx, ty, 100);
    assert_non_null(tr);
    int ended = 0;
    for (int j = 0; j < 40 && !ended; j++, k++) {
        trk_real x[TRK_CV2_NX], pp[TRK_CV2_NX * TRK_CV2_NX];
        memcpy(x, tr->x, sizeof x);
        memcpy(pp, tr->p, sizeof pp);
        TRK_ASSERT_OK(trk_cv2_predict((trk_real)DT_S, p.process_noise_q, x, pp));
        const double trace = pp[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + pp[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)];
        const double bound = bound_at(&p, &o, x[TRK_CV2_X], x[TRK_CV2_Y]);
        const struct trk_scan s = polar_scan(k, &o, 0, NULL);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
        if (trace > bound * (1 + 1e-9)) {
            assert_int_equal(tr->status, TRK_TRACK_TERMINATED);
            assert_int_equal(tr->end_reason, TRK_END_COVARIANCE);
            ended = 1;
        } else if (trace < bound * (1 - 1e-9)) {
            assert_int_equal(tr->status, TRK_TRACK_CONFIRMED);
        }
    }
    assert_true(ended);
}

static void test_coverage_and_bad_input(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.sensor[0].coverage.min_range_m = 500;
    p.sensor[0].coverage.max_range_m = 8000;
    p.sensor[0].coverage.half_width_rad = (trk_real)(60 * DEG);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const struct trk_pose o = {0, 0, 0};
    struct trk_scan_report rep;
    /* outside: behind, too near, too far: nothing starts or waits */
    for (int k = 0; k < 5; k++) {
        const struct trk_polar_detection d[3] = {seen(&o, 0, -3000 - 10.0 * k, NULL), seen(&o, 0, 300 + 5.0 * k, NULL),
                                                 seen(&o, 100, 9000 + 10.0 * k, NULL)};
        const struct trk_scan s = polar_scan(k, &o, 3, d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, &rep));
        assert_int_equal(rep.n_kept, 3);
        assert_int_equal(rep.n_started, 0);
        assert_int_equal(rep.n_candidates, 0);
    }
    /* malformed detections are counted, the scan processed */
    const struct trk_polar_detection bad[4] = {{-5, 0, 0, 0}, {0, 0, 0, 0}, {100, (trk_real)NAN, 0, 0},
                                               {2000, 0, 0, 0}};
    struct trk_scan s = polar_scan(5, &o, 4, bad);
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, &rep));
    assert_int_equal(rep.n_rejected_region, 2);
    assert_int_equal(rep.n_rejected_nonfinite, 1);
    assert_int_equal(rep.n_kept, 1);
    /* malformed scans are refused */
    struct trk_detection cd = {0, 0, {1, 0, 1}, 0, 0, 0};
    s.time_us = SCAN_US(6);
    s.detections = &cd;
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_a, &s, &rep), TRK_E_ARG); /* both arrays */
    s.detections = NULL;
    s.has_pose = 2;
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_a, &s, &rep), TRK_E_ARG);
    s.has_pose = 1;
    s.pose.heading_rad = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_a, &s, &rep), TRK_E_NAN);
    s.pose.heading_rad = 0;
    s.pose.x_m = TRK_REAL_C(1e9);
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_a, &s, &rep), TRK_E_RANGE);
    struct trk_tracker_params c;
    trk_tracker_default_params(&c);
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &c));
    s.pose.x_m = 0;
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_b, &s, &rep), TRK_E_ARG); /* polar to a Cartesian sensor */
}

/* A clutter profile: the PDA's beta0 of a lone track (per-track PDA) is
 * lambda (1 - P_D P_G) / (lambda (1 - P_D P_G) + P_D N(nu; 0, S)) with
 * lambda and P_D the profiles' at its predicted position and S with the
 * conversion's R there, at two ranges. */
static void test_clutter_profile_beta0(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    polar_params(&p);
    p.association = TRK_ASSOC_PDA;
    struct trk_clutter_profile *cp = &p.sensor[0].clutter_profile;
    cp->n = 2;
    cp->range_m[0] = 500, cp->density_per_m2[0] = TRK_REAL_C(1e-6);
    cp->range_m[1] = 8000, cp->density_per_m2[1] = TRK_REAL_C(1e-8);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    const struct trk_pose o = {0, 0, 0};
    const double tx[2] = {200, -400}, ty[2] = {1200, 6000};
    uint64_t rng = 51;
    for (int k = 0; k < 12; k++) {
        struct trk_polar_detection pd[2];
        for (int t = 0; t < 2; t++) pd[t] = seen(&o, tx[t], ty[t], &rng);
        const struct trk_scan s = polar_scan(k, &o, 2, pd);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    const struct trk_track *tr[2];
    trk_real x[2][TRK_CV2_NX], pp[2][TRK_CV2_NX * TRK_CV2_NX];
    struct trk_polar_detection pd[2];
    for (int t = 0; t < 2; t++) {
        tr[t] = track_near(&tk_a, tx[t], ty[t], 300);
        assert_non_null(tr[t]);
        memcpy(x[t], tr[t]->x, sizeof x[t]);
        memcpy(pp[t], tr[t]->p, sizeof pp[t]);
        TRK_ASSERT_OK(trk_cv2_predict((trk_real)DT_S, p.process_noise_q, x[t], pp[t]));
        pd[t] = seen(&o, tx[t] + 20, ty[t] - 10, NULL);
    }
    const struct trk_scan s = polar_scan(12, &o, 2, pd);
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    double lambda_at[2];
    for (int t = 0; t < 2; t++) {
        struct trk_detection d;
        trk_real r[3];
        TRK_ASSERT_OK(trk_polar_to_cartesian(&p.sensor[0], &o, &pd[t], &d));
        trk_polar_cov(&p.sensor[0], d.x_m, d.y_m, r); /* the detection's own R */
        const double sxx = pp[t][TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + r[0], sxy = pp[t][TRK_CV2_P(TRK_CV2_X, TRK_CV2_Y)] + r[1];
        const double syy = pp[t][TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)] + r[2], det = sxx * syy - sxy * sxy;
        const double nx = d.x_m - x[t][TRK_CV2_X], ny = d.y_m - x[t][TRK_CV2_Y];
        const double d2 = (syy * nx * nx - 2 * sxy * nx * ny + sxx * ny * ny) / det;
        const double g = exp(-0.5 * d2) / (2 * 3.14159265358979323846 * sqrt(det));
        const double pdv = trk_sensor_pd_at(&p.sensor[0], &o, x[t][TRK_CV2_X], x[t][TRK_CV2_Y]);
        lambda_at[t] = trk_sensor_clutter_at(&p.sensor[0], &o, x[t][TRK_CV2_X], x[t][TRK_CV2_Y]);
        const double e0 = lambda_at[t] * (1 - pdv * p.gate_prob);
        TRK_ASSERT_NEAR(tr[t]->beta0_last, e0 / (e0 + pdv * g), 0, TRK_TOL(1e-9, 1e-3));
    }
    assert_true(lambda_at[0] > 3 * lambda_at[1]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polar_equals_converted),
        cmocka_unit_test(test_thinned_polar_equals_converted),
        cmocka_unit_test(test_moving_platform),
        cmocka_unit_test(test_existence_with_profile),
        cmocka_unit_test(test_out_of_sight),
        cmocka_unit_test(test_covariance_bound_at_position),
        cmocka_unit_test(test_coverage_and_bad_input),
        cmocka_unit_test(test_clutter_profile_beta0),
    };
    trk_test_filter_from_env();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
