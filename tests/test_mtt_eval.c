/* test_mtt_eval.c - the multi-target evaluation (tools/sim/mtt_eval.h) on a
 * scripted run whose statistics are counted by hand: a late confirmation,
 * an identity switch with a duplicate, a fragmentation, a false track. */
#include "trk_test.h"
#include "mtt_eval.h"

static void test_scripted_run(void **state)
{
    (void)state;
    struct mtt_eval e;
    mtt_eval_init(&e, 20);
    const struct mtt_obj truth[2] = {{1, 0, 0}, {2, 100, 0}};
    /* scan 0: nothing tracked: GOSPA = sqrt(2 * c^2 / 2) = c */
    assert_int_equal(mtt_eval_scan(&e, truth, 2, NULL, 0), 0);
    /* scan 1: track 10 on target 1 (1 m off), a false track 99 */
    const struct mtt_obj s1[2] = {{10, 1, 0}, {99, 5000, 5000}};
    assert_int_equal(mtt_eval_scan(&e, truth, 2, s1, 2), 0);
    /* scan 2: track 20 on target 2 too */
    const struct mtt_obj s2[3] = {{10, 1, 0}, {20, 101, 0}, {99, 5000, 5000}};
    assert_int_equal(mtt_eval_scan(&e, truth, 2, s2, 3), 0);
    /* scan 3: track 30 closer to target 1 than track 10: a switch, 10 a duplicate */
    const struct mtt_obj s3[4] = {{30, 0.5, 0}, {10, 3, 0}, {20, 101, 0}, {99, 5000, 5000}};
    assert_int_equal(mtt_eval_scan(&e, truth, 2, s3, 4), 0);
    /* scan 4: target 1 untracked (a gap) */
    const struct mtt_obj s4[2] = {{20, 101, 0}, {99, 5000, 5000}};
    assert_int_equal(mtt_eval_scan(&e, truth, 2, s4, 2), 0);
    /* scan 5: track 30 back on target 1: a fragmentation, no switch */
    const struct mtt_obj s5[3] = {{30, 0, 0}, {20, 101, 0}, {99, 5000, 5000}};
    assert_int_equal(mtt_eval_scan(&e, truth, 2, s5, 3), 0);

    struct mtt_summary s;
    mtt_eval_summary(&e, &s);
    assert_int_equal(s.n_scans, 6);
    assert_int_equal(s.n_targets, 2);
    assert_int_equal(s.n_never, 0);
    TRK_ASSERT_NEAR(s.scans_to_confirm_mean, 1.5, 0, 0);    /* target 1 at scan 1, target 2 at scan 2 */
    TRK_ASSERT_NEAR(mtt_eval_target_to_confirm(&e, 1), 1, 0, 0);
    TRK_ASSERT_NEAR(mtt_eval_target_to_confirm(&e, 2), 2, 0, 0);
    assert_true(isnan(mtt_eval_target_to_confirm(&e, 3))); /* never seen */
    TRK_ASSERT_NEAR(s.coverage, 8.0 / 12.0, 1e-12, 0);       /* assigned 0, 1, 2, 2, 1, 2 of 2 per scan */
    assert_int_equal(s.id_switches, 1);
    assert_int_equal(s.fragmentations, 1);
    assert_int_equal(s.n_false_tracks, 1);
    assert_int_equal(s.n_tracks, 4);
    TRK_ASSERT_NEAR(s.false_track_scans_per_100, 100.0 * 5 / 6, 1e-9, 0);
    TRK_ASSERT_NEAR(s.duplicate_track_scans_per_100, 100.0 * 1 / 6, 1e-9, 0);
    /* errors of the 8 assigned pairs: 1 | 1, 1 | 0.5, 1 | 1 | 0, 1 */
    TRK_ASSERT_NEAR(s.rmse_m, sqrt((1 + 1 + 1 + 0.25 + 1 + 1 + 0 + 1) / 8.0), 1e-12, 0);
    /* GOSPA of scan 0 is c = 20; the mean includes it */
    assert_true(s.gospa_mean_m > 20.0 / 6);
    mtt_eval_free(&e);
}

static void test_gospa_mean_closed_form(void **state)
{
    (void)state;
    struct mtt_eval e;
    mtt_eval_init(&e, 10);
    const struct mtt_obj t[1] = {{1, 0, 0}}, y[1] = {{5, 3, 4}};
    assert_int_equal(mtt_eval_scan(&e, t, 1, y, 1), 0); /* GOSPA 5 (all localisation) */
    assert_int_equal(mtt_eval_scan(&e, t, 1, NULL, 0), 0); /* GOSPA sqrt(50) (missed) */
    struct mtt_summary s;
    mtt_eval_summary(&e, &s);
    TRK_ASSERT_NEAR(s.gospa_mean_m, (5 + sqrt(50.0)) / 2, 1e-12, 0);
    TRK_ASSERT_NEAR(s.loc_mean_m2, 25.0 / 2, 1e-12, 0);
    TRK_ASSERT_NEAR(s.missed_mean_m2, 50.0 / 2, 1e-12, 0);
    TRK_ASSERT_NEAR(s.false_mean_m2, 0, 0, 0);
    TRK_ASSERT_NEAR(s.coverage, 0.5, 0, 0);
    mtt_eval_free(&e);
}

/* A target present but never within c of a track: counted in n_never, and
 * its own scans to confirm are undefined (not 0, not the run's length). */
static void test_never_confirmed(void **state)
{
    (void)state;
    struct mtt_eval e;
    mtt_eval_init(&e, 10);
    const struct mtt_obj t[1] = {{7, 0, 0}}, far[1] = {{1, 100, 0}};
    for (int k = 0; k < 3; k++) assert_int_equal(mtt_eval_scan(&e, t, 1, far, 1), 0);
    struct mtt_summary s;
    mtt_eval_summary(&e, &s);
    assert_int_equal(s.n_never, 1);
    assert_true(isnan(s.scans_to_confirm_mean));
    assert_true(isnan(mtt_eval_target_to_confirm(&e, 7)));
    mtt_eval_free(&e);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scripted_run),
        cmocka_unit_test(test_gospa_mean_closed_form),
        cmocka_unit_test(test_never_confirmed),
    };
    return trk_run_tests("mtt_eval", tests, NULL, NULL);
}
