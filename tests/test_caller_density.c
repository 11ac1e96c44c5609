/* test_caller_density.c - the caller's clutter density per detection
 * (trk_scan.clutter_density_per_m2; docs/tracker.md "The caller's clutter
 * density"):
 *   - a scan whose every detection carries lambda_2 runs, scan by scan, as
 *     a tracker configured with lambda_2 (existence, states, statuses): the
 *     caller's density wins in the weights, existence and the start values;
 *   - with densities that vary from detection to detection, the sensor's
 *     configured density no longer changes anything (two trackers
 *     configured 1e-7 and 1e-5 run alike);
 *   - densities NaN, infinite, 0 or negative reject their detections
 *     (n_rejected_density), the rest of the scan is processed and the
 *     counts add up, also in a scan beyond capacity;
 *   - a subnormal density on a detection two tracks share: the joint
 *     cluster is solved (floored weights), no track ends as numerical;
 *   - nonparametric clutter or a sensor density of 0: the scan is refused
 *     (TRK_E_UNSUPPORTED), the table untouched. */
#include "trk_test.h"
#include "trk/tracker.h"

#define SEC(k) ((int64_t)(k) * 2000000)
#define N_TGT 2
#define N_CLUTTER 6
#define N_DET (N_TGT + N_CLUTTER)
#define AREA_M 2000.0

static struct trk_tracker tk_a, tk_b;

static void params_with(struct trk_tracker_params *p, double lambda)
{
    trk_tracker_default_params(p);
    p->sensor[0].clutter_density_per_m2 = (trk_real)lambda;
    p->sensor[0].meas_cov_m2[TRK_COV2_XX] = p->sensor[0].meas_cov_m2[TRK_COV2_YY] = 25; /* sigma 5 m */
    p->process_noise_q = TRK_REAL_C(0.1);
}

/* Scan k: two targets moving at 5 m/s, detected unless (k + i) % 5 == 0,
 * with 5 m noise, then clutter uniform over 2 km x 2 km; *n set. */
static void scan_detections(int k, uint64_t *rng, struct trk_detection *d, size_t *n)
{
    size_t m = 0;
    memset(d, 0, N_DET * sizeof *d);
    for (int i = 0; i < N_TGT; i++) {
        if ((k + i) % 5 == 0) continue;
        d[m].x_m = (trk_real)(400.0 + 600.0 * i + 10.0 * k + 5 * trk_test_nrand(rng));
        d[m].y_m = (trk_real)(800.0 - 200.0 * i + 5 * trk_test_nrand(rng));
        m++;
    }
    for (int c = 0; c < N_CLUTTER; c++, m++) {
        d[m].x_m = (trk_real)(AREA_M * trk_test_urand(rng));
        d[m].y_m = (trk_real)(AREA_M * trk_test_urand(rng));
    }
    *n = m;
}

/* Every slot of a and b alike: status, id, state and existence. */
static void assert_tables_alike(const struct trk_tracker *a, const struct trk_tracker *b, double rel)
{
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *ta = trk_tracker_track(a, s), *tb = trk_tracker_track(b, s);
        assert_true(!ta == !tb);
        if (!ta) continue;
        assert_int_equal(ta->status, tb->status);
        assert_int_equal(ta->id, tb->id);
        TRK_ASSERT_NEAR(ta->vis.pv, tb->vis.pv, 1e-12, rel);
        for (int i = 0; i < TRK_CV2_NX; i++) TRK_ASSERT_NEAR(ta->x[i], tb->x[i], 1e-9, rel);
    }
}

/* tk_a and tk_b configured with densities lambda_a and lambda_b */
static void init_pair(double lambda_a, double lambda_b)
{
    struct trk_tracker_params pa, pb;
    params_with(&pa, lambda_a);
    params_with(&pb, lambda_b);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &pa));
    TRK_ASSERT_OK(trk_tracker_init(&tk_b, &pb));
}

/* a runs the scans with lambda_c(detection) given, b without; confirmed
 * tracks counted at the end. */
static size_t run_pair(double (*lambda_c)(const struct trk_detection *), int given_b)
{
    uint64_t rng = 7;
    size_t confirmed = 0;
    for (int k = 0; k < 30; k++) {
        struct trk_detection d[N_DET];
        trk_real lam[N_DET];
        size_t n;
        scan_detections(k, &rng, d, &n);
        for (size_t j = 0; j < n; j++) lam[j] = (trk_real)lambda_c(&d[j]);
        struct trk_scan sa, sb;
        trk_scan_init(&sa, SEC(k), 0, n, d);
        sb = sa;
        sa.clutter_density_per_m2 = lam;
        if (given_b) sb.clutter_density_per_m2 = lam;
        struct trk_scan_report ra, rb;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &sa, &ra));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_b, &sb, &rb));
        assert_int_equal(ra.n_kept, n);
        assert_int_equal(ra.n_started, rb.n_started);
        assert_int_equal(ra.n_confirmed, rb.n_confirmed);
        assert_tables_alike(&tk_a, &tk_b, TRK_TOL(1e-9, 2e-4));
        confirmed += ra.n_confirmed;
    }
    return confirmed;
}

static double uniform_4e6(const struct trk_detection *d)
{
    (void)d;
    return 4e-6;
}

/* every detection at 4e-6 per m^2 in a tracker configured 1e-6: as a
 * tracker configured 4e-6 */
static void test_uniform_density_is_the_configured_one(void **state)
{
    (void)state;
    init_pair(1e-6, 4e-6);
    assert_int_equal(run_pair(uniform_4e6, 0), N_TGT);
}

/* dense east of x = 1000 m (3e-6), sparse west (3e-7), as a CFAR would see
 * a patch */
static double patchy(const struct trk_detection *d) { return d->x_m > 1000 ? 3e-6 : 3e-7; }

/* the same varying densities in trackers configured 1e-7 and 1e-5 */
static void test_configured_density_no_longer_matters(void **state)
{
    (void)state;
    init_pair(1e-7, 1e-5);
    assert_int_equal(run_pair(patchy, 1), N_TGT);
}

/* bad densities reject their detections only; the counts add up */
static void test_bad_densities_counted(void **state)
{
    (void)state;
    static struct trk_detection d[2 * TRK_MAX_DETECTIONS];
    static trk_real lam[2 * TRK_MAX_DETECTIONS];
    const trk_real bad[4] = {(trk_real)NAN, (trk_real)INFINITY, 0, -1};
    struct trk_tracker_params p;
    params_with(&p, 1e-6);
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    for (int over = 0; over <= 1; over++) {
        const size_t n = over ? 2 * TRK_MAX_DETECTIONS : 12;
        uint64_t rng = 11;
        memset(d, 0, sizeof d);
        for (size_t j = 0; j < n; j++) {
            d[j].x_m = (trk_real)(AREA_M * trk_test_urand(&rng));
            d[j].y_m = (trk_real)(AREA_M * trk_test_urand(&rng));
            lam[j] = j % 3 == 0 ? bad[(j / 3) % 4] : TRK_REAL_C(2e-6);
        }
        d[1].x_m = (trk_real)NAN; /* counted as non-finite, its density not looked at */
        lam[1] = bad[0];
        struct trk_scan s;
        trk_scan_init(&s, SEC(over), 0, n, d);
        s.clutter_density_per_m2 = lam;
        struct trk_scan_report r;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, &r));
        const size_t n_bad = (n + 2) / 3;
        assert_int_equal(r.n_rejected_density, n_bad);
        assert_int_equal(r.n_rejected_nonfinite, 1);
        assert_int_equal(r.n_kept + r.n_thinned, n - n_bad - 1);
        assert_int_equal(r.n_detections, r.n_kept + r.n_thinned + r.n_rejected_nonfinite + r.n_rejected_cov +
                                             r.n_rejected_amplitude + r.n_rejected_region + r.n_below_threshold +
                                             r.n_rejected_density);
        assert_int_equal(r.n_thinned > 0, over);
    }
}

/* A caller's density at the arithmetic's end (the smallest subnormal:
 * accepted, > 0) on one detection that two tracks gate: its joint weight
 * lies more than e^745 (double; e^103 float) above either track's miss,
 * each track's scaled miss underflows to 0, every joint event of the
 * cluster weighed 0 and
 * the marginals were 0 / 0: both tracks ended as numerical. Now the
 * cluster is solved with floored weights (counted in n_clusters_approx)
 * and both tracks go on, one of them on the detection. */
static void test_density_beyond_the_range(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params_with(&p, 1e-6);
    /* a precise sensor (sigma 1 m) that rarely misses: the shared pair's
     * weight is the larger, the misses' the smaller */
    p.sensor[0].meas_cov_m2[TRK_COV2_XX] = p.sensor[0].meas_cov_m2[TRK_COV2_YY] = 1;
    p.sensor[0].pd = TRK_REAL_C(0.999);
    p.gate_prob = TRK_REAL_C(0.9999);
    p.visibility.delta_stay = TRK_REAL_C(0.9999);
    p.merge_gate_d2 = 0; /* two tracks 4 m apart stay two */
    TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
    struct trk_detection d[2];
    memset(d, 0, sizeof d);
    uint64_t rng = 5;
    for (int k = 0; k < 12; k++) { /* two targets 4 m apart, 5 m/s */
        for (int i = 0; i < 2; i++) {
            d[i].x_m = (trk_real)(500.0 + 10.0 * k + 0.3 * trk_test_nrand(&rng));
            d[i].y_m = (trk_real)(500.0 + 4.0 * i + 0.3 * trk_test_nrand(&rng));
        }
        struct trk_scan s;
        trk_scan_init(&s, SEC(k), 0, 2, d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
    }
    assert_int_equal(trk_tracker_live_count(&tk_a), 2);
    d[0].x_m = (trk_real)(500.0 + 10.0 * 12);
    d[0].y_m = (trk_real)502.0; /* between them, in both gates */
    const trk_real lam[1] = {TRK_REAL_MIN * TRK_REAL_EPS}; /* the smallest subnormal */
    struct trk_scan s;
    trk_scan_init(&s, SEC(12), 0, 1, d);
    s.clutter_density_per_m2 = lam;
    struct trk_scan_report r;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, &r));
    assert_int_equal(r.n_kept, 1);
    assert_int_equal(r.n_tracks_hit, 2);
    assert_int_equal(r.n_numerical, 0);
    assert_true(r.n_clusters_approx >= 1);
    assert_int_equal(trk_tracker_live_count(&tk_a), 2);
}

/* where the caller's densities cannot stand in for lambda: refused whole */
static void test_refused_where_unsupported(void **state)
{
    (void)state;
    struct trk_detection d[1];
    memset(d, 0, sizeof d);
    const trk_real lam[1] = {TRK_REAL_C(1e-6)};
    struct trk_tracker_params p;
    for (int c = 0; c < 2; c++) {
        params_with(&p, c == 0 ? 1e-6 : 0);
        p.association = TRK_ASSOC_PDA; /* joint association needs lambda > 0 and parametric clutter */
        if (c == 0) p.clutter = TRK_CLUTTER_NONPARAMETRIC;
        TRK_ASSERT_OK(trk_tracker_init(&tk_a, &p));
        struct trk_scan s;
        trk_scan_init(&s, 0, 0, 1, d);
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, NULL));
        s.time_us = SEC(1);
        s.clutter_density_per_m2 = lam;
        memcpy(&tk_b, &tk_a, sizeof tk_a);
        struct trk_scan_report r;
        TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk_a, &s, &r), TRK_E_UNSUPPORTED);
        assert_int_equal(r.n_detections, 0);
        assert_memory_equal(&tk_a, &tk_b, sizeof tk_a);
        s.clutter_density_per_m2 = NULL; /* the same scan without: processed */
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk_a, &s, &r));
        assert_int_equal(r.n_kept, 1);
    }
}

int main(void)
{
    trk_test_filter_from_env();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform_density_is_the_configured_one),
        cmocka_unit_test(test_configured_density_no_longer_matters),
        cmocka_unit_test(test_bad_densities_counted),
        cmocka_unit_test(test_density_beyond_the_range),
        cmocka_unit_test(test_refused_where_unsupported),
    };
    return trk_run_tests("caller_density", tests, NULL, NULL);
}
