/* test_tracker_joint.c - joint association in the track table
 * (TRK_ASSOC_JOINT): a track alone in its cluster gets exactly its
 * per-track PDA / IPDA update (states, covariances, existence and decisions
 * scan after scan); two tracks sharing detections get the JIPDA update
 * composed from the public pieces (trk_jpda_track_weights,
 * trk_jpda_marginals, trk_jpda_existence, trk_pda_update_weights); the pair
 * store's overflow falls back to the track's own PDA and is counted; the
 * parameter check. */
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/jpda.h"
#include "trk/kalman.h"
#include "trk/tracker.h"

static struct trk_tracker tk_pda, tk_joint; /* static, as in firmware */

#define T_US(k) ((int64_t)(k) * 4000000)

static uint64_t rng_state; /* the generator of trk_test.h */
static double urand(void) { return trk_test_urand(&rng_state); }
static double nrand(void) { return trk_test_nrand(&rng_state); }

/* the sonar of trk_test_sonar.h with association a */
static void sonar_params(struct trk_tracker_params *p, double lambda, enum trk_assoc_method a)
{
    trk_test_sonar_params(p, lambda);
    p->association = a;
}

#define det_at trk_test_det_at

static trk_status run(struct trk_tracker *t, int k, const struct trk_detection *d, size_t n,
                      struct trk_scan_report *rep)
{
    const struct trk_scan scan = {T_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
    return trk_tracker_process_scan(t, &scan, rep);
}

static void assert_tracks_equal(const struct trk_track *a, const struct trk_track *b, double rel)
{
    assert_int_equal(a->status, b->status);
    assert_int_equal(a->id, b->id);
    assert_int_equal(a->n_hits, b->n_hits);
    for (int i = 0; i < TRK_CV2_NX; i++) TRK_ASSERT_NEAR(a->x[i], b->x[i], rel * 1e3, rel);
    for (int i = 0; i < TRK_CV2_NX * TRK_CV2_NX; i++) TRK_ASSERT_NEAR(a->p[i], b->p[i], rel, rel);
    TRK_ASSERT_NEAR(a->vis.pv, b->vis.pv, rel, rel);
    TRK_ASSERT_NEAR(a->beta0_last, b->beta0_last, rel, rel);
}

/* Four targets 1.5 km apart, P_D 0.8, with clutter everywhere at lambda: the
 * tracks that do not share detections (clusters of one) follow the same
 * course under both methods. Compared: every slot whose track gated no
 * detection another live track gated; checked that those are most of them
 * and include all four targets' confirmed tracks. */
static void test_lone_track_is_ipda(void **state)
{
    (void)state;
    const double lambda = 2e-6, area = 6000.0 * 6000.0;
    struct trk_tracker_params p;
    sonar_params(&p, lambda, TRK_ASSOC_PDA);
    TRK_ASSERT_OK(trk_tracker_init(&tk_pda, &p));
    p.association = TRK_ASSOC_JOINT;
    TRK_ASSERT_OK(trk_tracker_init(&tk_joint, &p));
    rng_state = 11;
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    size_t compared = 0, confirmed_targets = 0;
    for (int k = 0; k < 60; k++) {
        size_t n = 0;
        for (int g = 0; g < 4; g++)
            if (urand() < 0.8)
                d[n++] = det_at(1000 + 1500.0 * g + 5 * k + 5 * nrand(), 2000 - 3 * k + 5 * nrand());
        /* clutter away from the targets' lanes (x within 300 m of a lane: none) */
        const size_t n_clutter = (size_t)(lambda * area);
        for (size_t c = 0; c < n_clutter && n < TRK_MAX_DETECTIONS; c++) {
            const double x = 6000 * urand(), y = 6000 * urand();
            int near = 0;
            for (int g = 0; g < 4; g++) near |= fabs(x - (1000 + 1500.0 * g + 5 * k)) < 300;
            if (!near) d[n++] = det_at(x, y);
        }
        struct trk_scan_report ra, rb;
        TRK_ASSERT_OK(run(&tk_pda, k, d, n, &ra));
        TRK_ASSERT_OK(run(&tk_joint, k, d, n, &rb));
        assert_int_equal(rb.n_assoc_overflow, 0);
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *a = trk_tracker_track(&tk_pda, i), *b = trk_tracker_track(&tk_joint, i);
            if (!a || !b || a->id != b->id) continue;
            /* target tracks: in a lane, never near clutter; all their history lone */
            int lane = 0;
            for (int g = 0; g < 4; g++) lane |= fabs(a->x[TRK_CV2_X] - (1000 + 1500.0 * g + 5 * k)) < 100;
            if (!lane) continue;
            assert_tracks_equal(a, b, TRK_TOL(1e-9, 2e-3));
            compared++;
            if (k == 59 && b->status == TRK_TRACK_CONFIRMED) confirmed_targets++;
        }
    }
    assert_true(compared > 150);
    assert_int_equal(confirmed_targets, 4);
}

/* Two confirmed tracks 12 m apart on converging courses share the scan's
 * detections: the tracker's joint update equals the one composed from the
 * public JPDA pieces on copies of the two tracks. */
static void test_shared_detections_compose(void **state)
{
    (void)state;
    const double lambda = 1e-6;
    struct trk_tracker_params p;
    sonar_params(&p, lambda, TRK_ASSOC_JOINT);
    TRK_ASSERT_OK(trk_tracker_init(&tk_joint, &p));
    rng_state = 5;
    int k = 0;
    struct trk_detection d[3];
    for (; k < 12; k++) { /* two clean targets converging from 60 m to 16 m */
        d[0] = det_at(100 + 4 * k + 2 * nrand(), 100 + 2 * k + 2 * nrand());
        d[1] = det_at(100 + 4 * k + 2 * nrand(), 160 - 2 * k + 2 * nrand());
        TRK_ASSERT_OK(run(&tk_joint, k, d, 2, NULL));
    }
    size_t slot[2], n = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS && n < 2; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk_joint, i);
        if (tr && tr->status == TRK_TRACK_CONFIRMED) slot[n++] = i;
    }
    assert_int_equal(n, 2);
    struct trk_track before[2] = {tk_joint.track[slot[0]], tk_joint.track[slot[1]]};
    /* the scan: one detection between the two, one near each */
    d[0] = det_at(100 + 4 * k, 130);
    d[1] = det_at(100 + 4 * k + 1, 125);
    d[2] = det_at(100 + 4 * k - 1, 135);
    struct trk_scan_report rep;
    TRK_ASSERT_OK(run(&tk_joint, k, d, 3, &rep));
    assert_int_equal(rep.n_clusters, 1);
    assert_int_equal(rep.largest_cluster, 2);
    assert_int_equal(rep.n_clusters_approx, 0);

    /* the same from the public pieces */
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, TRK_REAL_C(0.8), p.gate_prob, TRK_CLUTTER_PARAMETRIC, (trk_real)lambda, 1};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    const trk_real r[4] = {25, 0, 0, 25};
    trk_real z[6], log_w[6], log_w0[2], x[2][4], pm[2][16], psi[2];
    struct trk_innovation inn[2];
    struct trk_visibility_model vm;
    TRK_ASSERT_OK(trk_visibility_model_init(&vm, &p.visibility));
    for (int j = 0; j < 3; j++) {
        z[2 * j] = d[j].x_m;
        z[2 * j + 1] = d[j].y_m;
    }
    for (int a = 0; a < 2; a++) {
        memcpy(x[a], before[a].x, sizeof x[a]);
        memcpy(pm[a], before[a].p, sizeof pm[a]);
        TRK_ASSERT_OK(trk_cv2_predict(4, p.process_noise_q, x[a], pm[a]));
        TRK_ASSERT_OK(trk_kalman_innovation(4, 2, trk_cv2_h, r, x[a], pm[a], &inn[a]));
        psi[a] = trk_visibility_predict(&vm, &before[a].vis);
        TRK_ASSERT_OK(trk_jpda_track_weights(&pda, psi[a], &inn[a], 3, z, NULL, log_w + 3 * a, &log_w0[a], NULL));
    }
    static struct trk_jpda_work work;
    const struct trk_jpda_scan js = {2, 3, log_w0, log_w};
    trk_real pa[6], pmiss[2];
    TRK_ASSERT_OK(trk_jpda_marginals(&js, &work, pa, pmiss, NULL));
    for (int a = 0; a < 2; a++) {
        trk_real post, beta[4], zg[6], bg[4];
        TRK_ASSERT_OK(trk_jpda_existence(psi[a], pda.params.pd * pda.params.gate_prob, pa + 3 * a, 3, pmiss[a],
                                         &post, beta));
        /* the gated detections only (the tracker's set) */
        size_t m = 0;
        bg[0] = beta[0];
        for (int j = 0; j < 3; j++)
            if (isfinite(log_w[3 * a + j])) {
                zg[2 * m] = z[2 * j];
                zg[2 * m + 1] = z[2 * j + 1];
                bg[++m] = beta[j + 1];
            }
        assert_true(m >= 2);
        TRK_ASSERT_OK(trk_pda_update_weights(4, trk_cv2_h, r, x[a], pm[a], &inn[a], m, zg, bg));
        const struct trk_track *tr = trk_tracker_track(&tk_joint, slot[a]);
        const double tol = TRK_TOL(1e-10, 1e-4);
        for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(tr->x[i], x[a][i], tol * 100, tol);
        for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(tr->p[i], pm[a][i], tol, tol);
        TRK_ASSERT_NEAR(tr->vis.pv, post, tol, tol);
        TRK_ASSERT_NEAR(tr->beta0_last, beta[0], tol, tol);
    }
}

/* More gated pairs than TRK_MAX_GATED_PAIRS: three tracks 30 m apart and a
 * scan of TRK_MAX_DETECTIONS detections inside all three gates. The tracks
 * that do not fit are counted and updated by their own PDA: the last one
 * gated gets exactly the per-track method's update. */
static void test_pair_store_overflow(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-7, TRK_ASSOC_PDA);
    p.init.method = TRK_INIT_SINGLE_POINT;
    p.merge_gate_d2 = 0;
    TRK_ASSERT_OK(trk_tracker_init(&tk_pda, &p));
    p.association = TRK_ASSOC_JOINT;
    TRK_ASSERT_OK(trk_tracker_init(&tk_joint, &p));
    static struct trk_detection d[TRK_MAX_DETECTIONS];
    for (int g = 0; g < 3; g++) d[g] = det_at(30.0 * g, 0);
    struct trk_scan_report ra, rb;
    TRK_ASSERT_OK(run(&tk_pda, 0, d, 3, &ra));
    TRK_ASSERT_OK(run(&tk_joint, 0, d, 3, &rb));
    assert_int_equal(rb.n_started, 3);
    rng_state = 3;
    for (size_t c = 0; c < TRK_MAX_DETECTIONS; c++) d[c] = det_at(20 + 20 * urand(), -10 + 20 * urand());
    TRK_ASSERT_OK(run(&tk_pda, 1, d, TRK_MAX_DETECTIONS, &ra));
    TRK_ASSERT_OK(run(&tk_joint, 1, d, TRK_MAX_DETECTIONS, &rb));
    const size_t fit = TRK_MAX_GATED_PAIRS / TRK_MAX_DETECTIONS; /* tracks whose full sets fit */
    assert_true(fit < 3);
    assert_int_equal(rb.n_assoc_overflow, 3 - fit);
    assert_int_equal(rb.n_clusters, 1);
    assert_int_equal(rb.largest_cluster, fit);
    size_t last = TRK_MAX_TRACKS; /* the slot of the last of the three (the joint tracker's weak
                                     tentative tracks claimed few of the 256: new ones started beside) */
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk_joint, i);
        if (tr && tr->id <= 3) last = i;
    }
    assert_true(last < TRK_MAX_TRACKS);
    assert_tracks_equal(trk_tracker_track(&tk_pda, last), trk_tracker_track(&tk_joint, last), TRK_TOL(1e-12, 1e-6));
}

/* Strong returns in sparse clutter (three targets 1 km apart, each
 * returning up to two detections with P_D 0.8 and sigma 5 m, lambda 1e-8):
 * P(t <- none) is tiny, so the posterior existence is within rounding of 1.
 * Rounding must never take it above 1 (the float build ended such tracks as
 * numerical, 60 in these 2000 scans), and every existence stays in [0, 1]. */
static void test_strong_returns(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    sonar_params(&p, 1e-8, TRK_ASSOC_JOINT);
    TRK_ASSERT_OK(trk_tracker_init(&tk_joint, &p));
    rng_state = 17;
    uint32_t numerical = 0, confirmed = 0;
    for (int k = 0; k < 2000; k++) {
        struct trk_detection d[6];
        size_t n = 0;
        for (int g = 0; g < 3; g++)
            for (int e = 0; e < 2; e++)
                if (urand() < 0.8) d[n++] = det_at(1000.0 * g + 3 * k + 5 * nrand(), 500 + 5 * nrand());
        struct trk_scan_report rep;
        TRK_ASSERT_OK(run(&tk_joint, k, d, n, &rep));
        numerical += rep.n_numerical;
        confirmed += rep.n_confirmed;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tk_joint, i);
            if (tr) assert_true(tr->vis.pv >= 0 && tr->vis.pv <= 1);
        }
    }
    assert_int_equal(numerical, 0);
    assert_true(confirmed >= 3);
}

static void test_params(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    sonar_params(&p, 1e-6, TRK_ASSOC_JOINT);
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    p.clutter = TRK_CLUTTER_NONPARAMETRIC;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_UNSUPPORTED);
    assert_string_equal(field, "association");
    sonar_params(&p, 0, TRK_ASSOC_JOINT);
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_UNSUPPORTED);
    assert_string_equal(field, "association");
    sonar_params(&p, 1e-6, (enum trk_assoc_method)7);
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_ARG);
    assert_string_equal(field, "association");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lone_track_is_ipda),
        cmocka_unit_test(test_shared_detections_compose),
        cmocka_unit_test(test_pair_store_overflow),
        cmocka_unit_test(test_strong_returns),
        cmocka_unit_test(test_params),
    };
    return trk_run_tests("tracker_joint", tests, NULL, NULL);
}
