/* test_tracker_imm.c - IMM tracks in the track table (TRK_WITH_IMM = 1,
 * config.h; src/filter_imm_impl.h):
 *   - parameters: IMM off by default, the three-model set, refusals "imm";
 *   - one CV model through the IMM path is the CV tracker (two targets in
 *     clutter, per-track PDA and joint association);
 *   - a lone IMM track's update is the library's IMM-PDA
 *     (trk_imm_mix, trk_imm_predict, trk_imm_pda_update, trk_imm_combine),
 *     with either association; it is confirmed, and terminated once its
 *     target is gone;
 *   - the manoeuvre statistic is nu' S^-1 nu of the one detection (a CV and
 *     an IMM track);
 *   - a second scan at the same time neither mixes nor moves; a model that
 *     cannot be reached gates nothing;
 *   - a turning target: the turn model takes the mode probability, and the
 *     IMM track's position error over the turn is below the CV track's;
 *   - two close targets' IMM tracks are not merged into one (the merge
 *     weighs an IMM track with its most probable model's covariance);
 *   - a polar sensor on a moving platform: each model's R at its own
 *     prediction; polar scans tracked exactly as the caller's conversion,
 *     a turning target held, and a track out of the sector only predicted.
 * tests/test_tracker_imm.mk links this program with the library files whose
 * layout depends on the knob compiled in the same configuration. */
#undef TRK_WITH_IMM
#define TRK_WITH_IMM 1
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/gate.h"
#include "trk/imm.h"
#include "trk/tracker.h"

static struct trk_tracker tk, tk2;

#define DT_S 4.0
#define SCAN_US(k) ((int64_t)(k) * 4000000)

static void test_params(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    TRK_ASSERT_OK(trk_tracker_abi_check());
    trk_tracker_default_params(&p);
    assert_int_equal(p.imm.n_models, 0);
    TRK_ASSERT_OK(trk_tracker_imm_params(&p, TRK_REAL_C(0.035), TRK_REAL_C(0.95)));
    assert_int_equal(p.imm.n_models, 3);
    TRK_ASSERT_NEAR(p.imm.omega_rad_s[1], 0.035, 1e-7, 0);
    TRK_ASSERT_NEAR(p.imm.omega_rad_s[2], -0.035, 1e-7, 0);
    TRK_ASSERT_NEAR(p.imm.p_switch[0 * 3 + 1], 0.025, 1e-7, 0);
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    assert_null(field);
    p.imm.p_switch[0] = TRK_REAL_C(0.9); /* row 0 sums to 0.95 */
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "imm");
    TRK_ASSERT_OK(trk_tracker_imm_params(&p, TRK_REAL_C(0.035), TRK_REAL_C(0.95)));
    p.imm.n_models = TRK_MAX_MODELS + 1;
    TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_ARG);
    p.imm.n_models = 3;
    p.imm.omega_rad_s[1] = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_NAN);
    assert_string_equal(field, "imm");
}

/* Two targets 60 m apart crossing clutter; the same scans into tk (CV) and
 * tk2 (IMM with one CV model of the same q). */
static void run_pair(enum trk_assoc_method assoc)
{
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-5);
    p.association = assoc;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    p.imm.n_models = 1;
    p.imm.omega_rad_s[0] = 0;
    p.imm.q_m2_per_s3[0] = p.process_noise_q;
    p.imm.p_switch[0] = 1;
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    uint64_t rng = 7;
    for (int k = 0; k < 30; k++) {
        struct trk_detection d[8];
        const size_t n = trk_test_pair_scan(k, DT_S, 60, 3, &rng, d);
        const struct trk_scan scan = {SCAN_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report r1, r2;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &r1));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &scan, &r2));
        assert_int_equal(r1.n_started, r2.n_started);
        assert_int_equal(r1.n_confirmed, r2.n_confirmed);
        assert_int_equal(r1.n_terminated, r2.n_terminated);
    }
    size_t n_confirmed = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *a = trk_tracker_track(&tk, i), *b = trk_tracker_track(&tk2, i);
        assert_true((a == NULL) == (b == NULL));
        if (!a) continue;
        assert_int_equal(a->id, b->id);
        assert_int_equal(a->status, b->status);
        n_confirmed += a->status == TRK_TRACK_CONFIRMED;
        /* the same arithmetic but the prediction (trk_kalman_predict with F
         * of omega = 0 against the CV kernel): rounding only */
        for (int j = 0; j < TRK_CV2_NX; j++) TRK_ASSERT_NEAR(b->x[j], a->x[j], TRK_TOL(1e-8, 2e-2), TRK_TOL(1e-9, 1e-4));
        for (int j = 0; j < TRK_CV2_NX * TRK_CV2_NX; j++)
            TRK_ASSERT_NEAR(b->p[j], a->p[j], TRK_TOL(1e-8, 1e-2), TRK_TOL(1e-8, 1e-3));
        TRK_ASSERT_NEAR(b->vis.pv, a->vis.pv, TRK_TOL(1e-9, 1e-4), 0);
        TRK_ASSERT_NEAR(b->imm.mu[0], 1, 1e-12, 0);
    }
    assert_int_equal(n_confirmed, 2);
}

static void test_one_model_is_cv(void **state)
{
    (void)state;
    run_pair(TRK_ASSOC_PDA);
    run_pair(TRK_ASSOC_JOINT);
}

/* One target, no clutter detections, 8 scans: one confirmed IMM track. */
static const struct trk_track *lone_track(enum trk_assoc_method assoc, struct trk_tracker_params *p)
{
    trk_test_sonar_params(p, 1e-6);
    p->association = assoc;
    p->sensor[0].pd = TRK_REAL_C(0.95);
    TRK_ASSERT_OK(trk_tracker_imm_params(p, TRK_REAL_C(0.05), TRK_REAL_C(0.9)));
    p->imm.q_m2_per_s3[1] = p->imm.q_m2_per_s3[2] = TRK_REAL_C(0.01); /* the turns' own q */
    TRK_ASSERT_OK(trk_tracker_init(&tk, p));
    uint64_t rng = 11;
    for (int k = 0; k < 8; k++) {
        struct trk_detection d = trk_test_det_at(5 * DT_S * k + 3 * trk_test_nrand(&rng), 3 * trk_test_nrand(&rng));
        const struct trk_scan scan = {SCAN_US(k), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
    }
    const struct trk_track *found = NULL;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk, i);
        if (!tr) continue;
        assert_null(found);
        found = tr;
    }
    assert_non_null(found);
    assert_int_equal(found->status, TRK_TRACK_CONFIRMED);
    return found;
}

static void lone_is_imm_pda(enum trk_assoc_method assoc)
{
    struct trk_tracker_params p;
    const struct trk_track *tr = lone_track(assoc, &p);
    /* the library's IMM-PDA on the track's state and the next scan */
    struct trk_imm_state s = tr->imm;
    trk_real c[TRK_MAX_MODELS];
    TRK_ASSERT_OK(trk_imm_mix(&p.imm, &s, c));
    TRK_ASSERT_OK(trk_imm_predict(&p.imm, (trk_real)DT_S, &s));
    struct trk_innovation inn;
    TRK_ASSERT_OK(trk_kalman_innovation(TRK_CV2_NX, TRK_CV2_NZ, trk_cv2_h, tk.r[0], s.x[0], s.p[0], &inn));
    const double zx = inn.z_pred[TRK_CV2_ZX], zy = inn.z_pred[TRK_CV2_ZY];
    struct trk_detection d[3] = {trk_test_det_at(zx + 4, zy - 2), trk_test_det_at(zx - 6, zy + 5),
                                 trk_test_det_at(zx + 1, zy + 9)};
    trk_real z[6];
    for (int i = 0; i < 3; i++) {
        z[2 * i] = d[i].x_m;
        z[2 * i + 1] = d[i].y_m;
    }
    static struct trk_imm_work w;
    unsigned char valid[3];
    TRK_ASSERT_OK(trk_imm_pda_update(&p.imm, &tk.pda[0], tk.r[0], 3, z, NULL, c, &s, &w, valid, NULL));
    assert_true(valid[0] && valid[1] && valid[2]);
    trk_real x[TRK_CV2_NX], pc[TRK_CV2_NX * TRK_CV2_NX];
    trk_imm_combine(&p.imm, &s, x, pc);
    /* the tracker's */
    const struct trk_scan scan = {SCAN_US(8), 0, 3, d, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_started, 0);
    assert_int_equal(tr->n_gated_last, 3);
    for (int m = 0; m < 3; m++) {
        TRK_ASSERT_NEAR(tr->imm.mu[m], s.mu[m], TRK_TOL(1e-12, 1e-5), TRK_TOL(1e-10, 1e-4));
        for (int j = 0; j < TRK_CV2_NX; j++)
            TRK_ASSERT_NEAR(tr->imm.x[m][j], s.x[m][j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-11, 1e-5));
        for (int j = 0; j < TRK_CV2_NX * TRK_CV2_NX; j++)
            TRK_ASSERT_NEAR(tr->imm.p[m][j], s.p[m][j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-10, 1e-4));
    }
    for (int j = 0; j < TRK_CV2_NX; j++) TRK_ASSERT_NEAR(tr->x[j], x[j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-11, 1e-5));
    for (int j = 0; j < TRK_CV2_NX * TRK_CV2_NX; j++)
        TRK_ASSERT_NEAR(tr->p[j], pc[j], TRK_TOL(1e-9, 1e-3), TRK_TOL(1e-10, 1e-4));
    TRK_ASSERT_NEAR(tr->imm.mu[0] + tr->imm.mu[1] + tr->imm.mu[2], 1, TRK_TOL(1e-12, 1e-6), 0);
    /* the target gone: the existence test ends the IMM track */
    int ended = 0;
    for (int k = 9; k < 40 && !ended; k++) {
        const struct trk_scan empty = {SCAN_US(k), 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &empty, &rep));
        if (rep.n_terminated > 0) {
            ended = k;
            assert_int_equal(tr->status, TRK_TRACK_TERMINATED);
            assert_int_equal(tr->end_reason, TRK_END_TERMINATED);
        }
    }
    assert_true(ended > 9); /* not at once: it coasts on its models */
}

static void test_lone_track_is_imm_pda(void **state)
{
    (void)state;
    lone_is_imm_pda(TRK_ASSOC_PDA);
    lone_is_imm_pda(TRK_ASSOC_JOINT);
}

/* The manoeuvre statistic of a CV track with one detection at nu from its
 * prediction: nu' S^-1 nu; 0 after a scan without detection. */
static void test_maneuver_d2(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-6);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const struct trk_track *tr = NULL;
    for (int k = 0; k < 8; k++) {
        struct trk_detection d = trk_test_det_at(5 * DT_S * k, 0);
        const struct trk_scan scan = {SCAN_US(k), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
    }
    for (size_t i = 0; i < TRK_MAX_TRACKS && !tr; i++) tr = trk_tracker_track(&tk, i);
    assert_non_null(tr);
    trk_real x[TRK_CV2_NX], pp[TRK_CV2_NX * TRK_CV2_NX];
    memcpy(x, tr->x, sizeof x);
    memcpy(pp, tr->p, sizeof pp);
    TRK_ASSERT_OK(trk_cv2_predict((trk_real)DT_S, p.process_noise_q, x, pp));
    struct trk_innovation inn;
    TRK_ASSERT_OK(trk_kalman_innovation(TRK_CV2_NX, TRK_CV2_NZ, trk_cv2_h, tk.r[0], x, pp, &inn));
    const trk_real nu[2] = {6, -4};
    struct trk_detection d = trk_test_det_at(inn.z_pred[TRK_CV2_ZX] + nu[0], inn.z_pred[TRK_CV2_ZY] + nu[1]);
    const struct trk_scan scan = {SCAN_US(8), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
    assert_int_equal(tr->n_gated_last, 1);
    TRK_ASSERT_NEAR(tr->maneuver_d2, trk_gate_d2(&inn, nu), 0, TRK_TOL(1e-10, 1e-4));
    assert_true(tr->maneuver_d2 > 0.5);
    const struct trk_scan empty = {SCAN_US(9), 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &empty, NULL));
    assert_true(tr->maneuver_d2 == 0);
}

/* An IMM track's manoeuvre statistic with one detection: nu' S^-1 nu with
 * the S of its combined prediction (the models mixed, predicted and
 * combined with the predicted mode probabilities). */
static void test_maneuver_d2_imm(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const struct trk_track *tr = lone_track(TRK_ASSOC_PDA, &p);
    struct trk_imm_state s = tr->imm;
    trk_real c[TRK_MAX_MODELS], x[TRK_CV2_NX], pc[TRK_CV2_NX * TRK_CV2_NX];
    TRK_ASSERT_OK(trk_imm_mix(&p.imm, &s, c));
    TRK_ASSERT_OK(trk_imm_predict(&p.imm, (trk_real)DT_S, &s));
    for (int m = 0; m < p.imm.n_models; m++) s.mu[m] = c[m];
    trk_imm_combine(&p.imm, &s, x, pc);
    struct trk_innovation inn;
    TRK_ASSERT_OK(trk_kalman_innovation(TRK_CV2_NX, TRK_CV2_NZ, trk_cv2_h, tk.r[0], x, pc, &inn));
    const trk_real nu[2] = {-5, 7};
    struct trk_detection d = trk_test_det_at(inn.z_pred[TRK_CV2_ZX] + nu[0], inn.z_pred[TRK_CV2_ZY] + nu[1]);
    const struct trk_scan scan = {SCAN_US(8), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
    assert_int_equal(tr->n_gated_last, 1);
    TRK_ASSERT_NEAR(tr->maneuver_d2, trk_gate_d2(&inn, nu), 0, TRK_TOL(1e-9, 1e-4));
}

/* A second scan at the same time (another sensor, here empty) neither
 * mixes nor moves: the mode probabilities and the models stay. A model that
 * cannot be reached (p_stay = 1, mu_m = 0) gates nothing: a detection at its
 * prediction, far from the others', is not the track's. */
static void test_same_time_and_unreachable(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const struct trk_track *tr = lone_track(TRK_ASSOC_PDA, &p);
    const struct trk_imm_state before = tr->imm;
    const struct trk_scan again = {tr->time_us, 0, 0, NULL, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &again, NULL));
    for (int m = 0; m < 3; m++) {
        TRK_ASSERT_NEAR(tr->imm.mu[m], before.mu[m], TRK_TOL(1e-12, 1e-6), 0);
        for (int j = 0; j < TRK_CV2_NX; j++) TRK_ASSERT_NEAR(tr->imm.x[m][j], before.x[m][j], 1e-9, 0);
    }
    for (int assoc = 0; assoc < 2; assoc++) {
        tr = lone_track(assoc ? TRK_ASSOC_JOINT : TRK_ASSOC_PDA, &p);
        p.imm.p_switch[0] = p.imm.p_switch[4] = p.imm.p_switch[8] = 1;
        p.imm.p_switch[1] = p.imm.p_switch[2] = p.imm.p_switch[3] = 0;
        p.imm.p_switch[5] = p.imm.p_switch[6] = p.imm.p_switch[7] = 0;
        tk.params.imm = p.imm; /* the same track, its switching made the identity */
        struct trk_track *w = &tk.track[tr - tk.track];
        w->imm.mu[0] = 1;
        w->imm.mu[1] = w->imm.mu[2] = 0;
        w->imm.x[1][TRK_CV2_X] += 8000; /* the left turn's estimate, stale and far away */
        const double far_x = (double)w->imm.x[1][TRK_CV2_X] + (double)w->imm.x[1][TRK_CV2_VX] * DT_S;
        const double far_y = (double)w->imm.x[1][TRK_CV2_Y] + (double)w->imm.x[1][TRK_CV2_VY] * DT_S;
        struct trk_detection d = trk_test_det_at(far_x, far_y);
        const struct trk_scan scan = {SCAN_US(8), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
        assert_int_equal(tr->n_gated_last, 0);
        assert_int_equal(tr->n_misses_in_row, 1);
        assert_true(tr->imm.mu[1] == 0 && tr->imm.mu[2] == 0);
    }
}

/* A target at 6 m/s: 15 scans straight east, 30 scans turning left at
 * 1.5 deg/s, P_D 1, sigma 5 m, no clutter. Position errors of the one
 * confirmed track of the CV tracker (tk) and of the IMM tracker (tk2). */
static void test_turn(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-6);
    p.sensor[0].pd = TRK_REAL_C(0.99);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    TRK_ASSERT_OK(trk_tracker_imm_params(&p, TRK_REAL_C(0.0262), TRK_REAL_C(0.95))); /* turns at 1.5 deg/s */
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    const double w = 1.5 * 3.14159265358979323846 / 180;
    double px = 0, py = 0, heading = 0;
    double se_cv = 0, se_imm = 0, mu_left = 0, mu_cv_straight = 0;
    int n_turn = 0, n_late = 0, n_straight = 0, n_cv_lost = 0;
    uint32_t id_imm = 0;
    uint64_t rng = 5;
    for (int k = 0; k < 45; k++) {
        if (k > 0) {
            if (k <= 15) {
                px += 6 * DT_S;
            } else { /* exact arc of the turn */
                const double h1 = heading + w * DT_S;
                px += 6 / w * (sin(h1) - sin(heading));
                py += 6 / w * (cos(heading) - cos(h1));
                heading = h1;
            }
        }
        struct trk_detection d = trk_test_det_at(px + 5 * trk_test_nrand(&rng), py + 5 * trk_test_nrand(&rng));
        const struct trk_scan scan = {SCAN_US(k), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &scan, NULL));
        if (k < 6) continue;
        const struct trk_track *a = NULL, *b = NULL;
        int n_imm = 0;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *t1 = trk_tracker_track(&tk, i), *t2 = trk_tracker_track(&tk2, i);
            if (t1 && t1->status == TRK_TRACK_CONFIRMED) a = t1;
            if (t2 && t2->status == TRK_TRACK_CONFIRMED) {
                b = t2;
                n_imm++;
            }
        }
        assert_non_null(b);
        assert_int_equal(n_imm, 1);
        if (id_imm == 0) id_imm = b->id;
        assert_int_equal(b->id, id_imm); /* one IMM track throughout */
        if (k >= 8 && k <= 15) {
            mu_cv_straight += b->imm.mu[0];
            n_straight++;
        }
        if (k > 15) {
            /* a CV track lost in the turn counts as an error of 100 m */
            se_cv += a ? pow(a->x[TRK_CV2_X] - px, 2) + pow(a->x[TRK_CV2_Y] - py, 2) : 1e4;
            n_cv_lost += !a;
            se_imm += pow(b->x[TRK_CV2_X] - px, 2) + pow(b->x[TRK_CV2_Y] - py, 2);
            n_turn++;
            if (k >= 25) {
                mu_left += b->imm.mu[1];
                n_late++;
            }
        }
    }
    const double rmse_cv = sqrt(se_cv / n_turn), rmse_imm = sqrt(se_imm / n_turn);
    print_message("turn: position RMSE CV %.2f m (no CV track in %d of %d scans), IMM %.2f m; mean mu CV "
                  "(straight) %.3f, left (turn) %.3f\n",
                  rmse_cv, n_cv_lost, n_turn, rmse_imm, mu_cv_straight / n_straight, mu_left / n_late);
    assert_true(rmse_imm < 6);              /* sigma 5 m per axis: 3.6 m measured */
    assert_true(rmse_imm < 0.5 * rmse_cv);
    assert_true(mu_left / n_late > 0.7);    /* 0.90 */
    assert_true(mu_cv_straight / n_straight > 0.6); /* 0.84 */
}

/* A detection at model 0's prediction and model 1's estimate moved away
 * from it (no switching, so no mixing pulls it back; mu = 1/2, 1/2): as
 * d2_1 goes from 0 to 1700, model 1's weight of the detection, beta_i
 * rho_1i / mu_1, falls through the subnormals (ln rho_1i about -d2_1 / 2).
 * A subnormal weight is an exactly-zero contribution: every update
 * succeeds, the track stays confirmed, and beyond the band (d2_1 >= 1500;
 * 220 in float) model 1 keeps its prediction exactly. With either
 * association. */
static void test_subnormal_model_weight(void **state)
{
    (void)state;
    static struct trk_tracker base;
    for (int assoc = 0; assoc < 2; assoc++) {
        struct trk_tracker_params p;
        const struct trk_track *tr = lone_track(assoc ? TRK_ASSOC_JOINT : TRK_ASSOC_PDA, &p);
        const size_t slot = (size_t)(tr - tk.track);
        p.imm.p_switch[0] = p.imm.p_switch[4] = p.imm.p_switch[8] = 1;
        p.imm.p_switch[1] = p.imm.p_switch[2] = p.imm.p_switch[3] = 0;
        p.imm.p_switch[5] = p.imm.p_switch[6] = p.imm.p_switch[7] = 0;
        tk.params.imm = p.imm;
        struct trk_track *w = &tk.track[slot];
        w->imm.mu[0] = w->imm.mu[1] = TRK_REAL_C(0.5);
        w->imm.mu[2] = 0;
        memcpy(w->imm.x[1], w->imm.x[0], sizeof w->imm.x[1]);
        memcpy(w->imm.p[1], w->imm.p[0], sizeof w->imm.p[1]);
        /* model 0's (and unmoved model 1's) predicted innovation */
        struct trk_imm_state s = w->imm;
        TRK_ASSERT_OK(trk_imm_predict(&p.imm, (trk_real)DT_S, &s));
        struct trk_innovation inn;
        TRK_ASSERT_OK(trk_kalman_innovation(TRK_CV2_NX, TRK_CV2_NZ, trk_cv2_h, tk.r[0], s.x[0], s.p[0], &inn));
        const trk_real unit[2] = {1, 0};
        const double d2_per_m2 = (double)trk_gate_d2(&inn, unit);
        struct trk_detection d = trk_test_det_at(inn.z_pred[TRK_CV2_ZX], inn.z_pred[TRK_CV2_ZY]);
        const struct trk_scan scan = {SCAN_US(8), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
        base = tk;
        int n_kept = 0;
        for (int k = 0; k <= 3400; k++) {
            const double d2 = 0.5 * k, dx = sqrt(d2 / d2_per_m2);
            tk = base;
            tk.track[slot].imm.x[1][TRK_CV2_X] -= (trk_real)dx;
            struct trk_imm_state s1 = tk.track[slot].imm; /* model 1's prediction */
            TRK_ASSERT_OK(trk_imm_predict(&p.imm, (trk_real)DT_S, &s1));
            struct trk_scan_report rep;
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
            const struct trk_track *t1 = &tk.track[slot];
            if (t1->status != TRK_TRACK_CONFIRMED || rep.n_terminated != 0)
                fail_msg("d2_1 %.1f: track %d, end reason %d", d2, (int)t1->status, (int)t1->end_reason);
            assert_int_equal(t1->n_gated_last, 1);
            TRK_ASSERT_NEAR(t1->imm.mu[0] + t1->imm.mu[1], 1, TRK_TOL(1e-12, 1e-6), 0);
            const int kept = t1->imm.x[1][TRK_CV2_X] == s1.x[1][TRK_CV2_X] && t1->imm.p[1][0] == s1.p[1][0];
            if (d2 >= TRK_TOL(1500, 220)) assert_true(kept); /* its weight below the smallest normal: 0 */
            n_kept += kept;
        }
        print_message("%s: model 1 kept its prediction in %d of 3401\n", assoc ? "joint" : "pda", n_kept);
        assert_true(n_kept > 0);
    }
}

/* Two targets 40 m apart on parallel straight paths (R = 25 I, P_D 0.8, a
 * little clutter), IMM tracks of three models, 20 runs of 60 scans: the
 * merge test weighs an IMM track with its most probable model's covariance,
 * not the combined one that holds the spread between the models, so that no
 * track on one target is merged into the other's. Counted: merges that end
 * a track confirmed at the scan before, and merges that leave the ended
 * track's target with no live track within 20 m (a tentative duplicate,
 * which initiation may start beside a weak tentative track, is merged by
 * design, and its target keeps the other). Measured: 0, 0 and 40 of 40
 * tracks held at the end (23 merges in all); with the combined covariance
 * 0, 3 and 40 (31 merges). */
static void test_close_pair_not_merged(void **state)
{
    (void)state;
    uint32_t merged = 0, merged_all = 0, lost = 0;
    size_t held = 0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        struct trk_tracker_params p;
        trk_test_sonar_params(&p, 1e-5);
        TRK_ASSERT_OK(trk_tracker_imm_params(&p, TRK_REAL_C(0.035), TRK_REAL_C(0.95)));
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        static uint32_t confirmed_id[TRK_MAX_TRACKS]; /* per slot: its id while confirmed, else 0 */
        memset(confirmed_id, 0, sizeof confirmed_id);
        uint64_t rng = seed;
        for (int k = 0; k < 60; k++) {
            struct trk_detection d[8];
            size_t n = 0;
            for (int t = 0; t < 2; t++)
                if (trk_test_urand(&rng) < 0.8) {
                    const double ex = 5 * trk_test_nrand(&rng), ey = 5 * trk_test_nrand(&rng);
                    d[n++] = trk_test_det_at(10 * DT_S * k + ex, 40 * t + ey);
                }
            for (int c = 0; c < 4; c++) {
                const double cx = 3000 * trk_test_urand(&rng) - 500, cy = 1000 * trk_test_urand(&rng) - 500;
                d[n++] = trk_test_det_at(cx, cy);
            }
            const struct trk_scan s = {SCAN_US(k), 0, n, d, NULL, 0, {0, 0, 0}, NULL};
            struct trk_scan_report rep;
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
            merged_all += rep.n_merged;
            for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
                const struct trk_track *tr = trk_tracker_track(&tk, i);
                if (tr && tr->status == TRK_TRACK_TERMINATED && tr->end_reason == TRK_END_MERGED) {
                    /* on which target, and does another live track stay on it? */
                    const double tx = 10 * DT_S * k, ty = tr->x[TRK_CV2_Y] < 20 ? 0 : 40;
                    int other = 0;
                    for (size_t j = 0; j < TRK_MAX_TRACKS; j++) {
                        const struct trk_track *o = trk_tracker_track(&tk, j);
                        other |= j != i && o && o->status != TRK_TRACK_TERMINATED && fabs(o->x[TRK_CV2_X] - tx) < 20 &&
                                 fabs(o->x[TRK_CV2_Y] - ty) < 20;
                    }
                    if (fabs(tr->x[TRK_CV2_X] - tx) < 20 && fabs(tr->x[TRK_CV2_Y] - ty) < 20 && !other) lost++;
                    if (confirmed_id[i] == tr->id) merged++;
                }
                confirmed_id[i] = tr && tr->status == TRK_TRACK_CONFIRMED ? tr->id : 0;
            }
        }
        held += trk_test_count_confirmed(&tk);
    }
    print_message("confirmed tracks merged %u (all merges %u, %u leaving their target no track), held %zu of 40\n",
                  (unsigned)merged, (unsigned)merged_all, (unsigned)lost, held);
    assert_true(merged <= 1);
    assert_int_equal(lost, 0);
    assert_true(held >= 36);
}

/* A polar sensor (sigma 7.5 m, 1.5 deg; a +-60 degree sector) on a
 * platform moving north: a target turning at 2 deg/s at 3-4 km, polar scans
 * into tk and the same converted by the caller into tk2 (the same tracks,
 * bit for bit); the track held through the turn; then the platform looks
 * east for 4 scans: existence only predicted. */
static void test_polar_imm(void **state)
{
    (void)state;
    const double deg = 3.14159265358979323846 / 180;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-8);
    p.sensor[0].kind = TRK_SENSOR_POLAR;
    p.sensor[0].sigma_range_m = TRK_REAL_C(7.5);
    p.sensor[0].sigma_bearing_rad = (trk_real)(1.5 * deg);
    p.sensor[0].coverage.half_width_rad = (trk_real)(60 * deg);
    p.max_unseen_scans = 4; /* the sector turns away for 4 scans at the end */
    TRK_ASSERT_OK(trk_tracker_imm_params(&p, (trk_real)(2 * deg), TRK_REAL_C(0.95)));
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    uint64_t rng = 77;
    double x = -1500, y = 3500, hd = 90 * deg, err = 0;
    const double v = 8;
    int k = 0;
    for (; k < 60; k++) {
        if (k >= 20 && k < 40) hd += 2 * deg * DT_S; /* the turn */
        x += v * DT_S * sin(hd), y += v * DT_S * cos(hd);
        const struct trk_pose o = {0, (trk_real)(2.0 * DT_S * k), 0};
        struct trk_polar_detection pd = {0, 0, 0, 0};
        struct trk_detection cd;
        const double dx = x - o.x_m, dy = y - o.y_m;
        pd.range_m = (trk_real)(hypot(dx, dy) + 7.5 * trk_test_nrand(&rng));
        pd.bearing_rad = (trk_real)(atan2(dx, dy) + 1.5 * deg * trk_test_nrand(&rng));
        TRK_ASSERT_OK(trk_polar_to_cartesian(&p.sensor[0], &o, &pd, &cd));
        cd.has_cov = 0;
        const struct trk_scan sa = {SCAN_US(k), 0, 1, NULL, &pd, 1, o, NULL}, sb = {SCAN_US(k), 0, 1, &cd, NULL, 1, o, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &sa, NULL));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &sb, NULL));
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *a = trk_tracker_track(&tk, i), *b = trk_tracker_track(&tk2, i);
            assert_true((a == NULL) == (b == NULL));
            if (!a) continue;
            for (int j = 0; j < TRK_CV2_NX; j++) TRK_ASSERT_NEAR(b->x[j], a->x[j], 0, 0);
            if (k >= 10 && a->status == TRK_TRACK_CONFIRMED) {
                const double e = hypot(a->x[TRK_CV2_X] - x, a->x[TRK_CV2_Y] - y);
                if (e > err) err = e;
            }
        }
    }
    assert_int_equal(trk_test_count_confirmed(&tk), 1);
    assert_true(err < 150); /* cross-range sigma at 3.5 km: 92 m */
    const struct trk_track *tr = NULL;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (trk_tracker_track(&tk, i)) tr = trk_tracker_track(&tk, i);
    double pv = tr->vis.pv;
    for (int j = 0; j < 4; j++, k++) {
        const struct trk_pose east = {0, (trk_real)(2.0 * DT_S * k), (trk_real)(100 * deg)};
        const struct trk_scan s = {SCAN_US(k), 0, 0, NULL, NULL, 1, east, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, NULL));
        pv *= p.visibility.delta_stay;
        TRK_ASSERT_NEAR(tr->vis.pv, pv, 0, TRK_TOL(1e-13, 1e-6));
        assert_int_equal(tr->status, TRK_TRACK_CONFIRMED);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_params),
        cmocka_unit_test(test_one_model_is_cv),
        cmocka_unit_test(test_lone_track_is_imm_pda),
        cmocka_unit_test(test_maneuver_d2),
        cmocka_unit_test(test_maneuver_d2_imm),
        cmocka_unit_test(test_same_time_and_unreachable),
        cmocka_unit_test(test_turn),
        cmocka_unit_test(test_subnormal_model_weight),
        cmocka_unit_test(test_close_pair_not_merged),
        cmocka_unit_test(test_polar_imm),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
