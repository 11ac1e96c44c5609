/* test_tracker_noclutter.c - the tracker built with TRK_WITH_CLUTTER_TESTS = 0
 * (config.h): the clutter tests' states and models are left out of the track
 * table, selecting them is refused with TRK_E_UNSUPPORTED (table untouched),
 * the other methods run as usual, and the clutter_test module itself still
 * works. tests/test_tracker_noclutter.mk links this program with tracker.c
 * and track_tests.c compiled in the same configuration. */
#define TRK_WITH_CLUTTER_TESTS 0
#include "trk_test.h"
#include "trk/clutter_test.h"
#include "trk/tracker.h"

static struct trk_tracker tk;

#define SEC(k) ((int64_t)(k) * 1000000)

static void test_union_without_clutter(void **state)
{
    (void)state;
    /* the per-track union is the larger of M/N and SPRT, not the clutter
     * tests' windows */
    union mn_or_sprt {
        struct trk_mn mn;
        struct trk_sprt sprt;
    };
    assert_int_equal(sizeof(union trk_confirm_state), sizeof(union mn_or_sprt));
    assert_true(sizeof(union trk_confirm_state) < sizeof(struct trk_clutter_chi2));
    union mn_or_sprt_model {
        struct trk_mn_model mn;
        struct trk_sprt_model sprt;
    };
    assert_int_equal(sizeof(union trk_confirm_model), sizeof(union mn_or_sprt_model));
}

static void test_clutter_unsupported(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_mn_kn_params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const uint32_t next_id = tk.next_id;
    p.confirm.method = TRK_CONFIRM_CLUTTER_CHI2;
    p.confirm.u.chi2.alpha = TRK_REAL_C(0.01);
    p.confirm.u.chi2.kmax = 25;
    TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_UNSUPPORTED);
    p.confirm.u.chi2.kmax = 0; /* invalid too: still "not built in" */
    TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_UNSUPPORTED);
    p.confirm.method = TRK_CONFIRM_CLUTTER_AMP;
    p.confirm.u.amp.a_min_db = 3;
    p.confirm.u.amp.alpha = TRK_REAL_C(0.01);
    p.confirm.u.amp.kmax = 25;
    TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_UNSUPPORTED);
    /* *t untouched on error: still the M/N tracker of the first init */
    assert_int_equal(tk.params.confirm.method, TRK_CONFIRM_MN);
    assert_int_equal(tk.next_id, next_id);
    /* the module itself is always built */
    struct trk_clutter_chi2_model m;
    struct trk_clutter_chi2 s;
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.05), 3};
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&m, &cp));
    trk_clutter_chi2_reset(&m, &s);
    enum trk_decision d;
    TRK_ASSERT_OK(trk_clutter_chi2_step(&m, &s, TRK_REAL_C(0.5), &d));
    TRK_ASSERT_NEAR(s.p_value, -expm1(-0.5), 0, TRK_TOL(1e-14, 1e-6)); /* chi2(2) cdf at 1 */
}

/* M/N and SPRT confirmation with K/N and Page termination: a target is
 * confirmed, then terminated after it disappears. */
static void test_other_methods_run(void **state)
{
    (void)state;
    const struct trk_hmm_sensor_params hs = {TRK_REAL_C(0.05), TRK_REAL_C(0.1), TRK_REAL_C(0.3),
                                             TRK_REAL_C(0.95), TRK_HMM_PI0_STATIONARY};
    for (int cm = 0; cm < 2; cm++)
        for (int tm = 0; tm < 2; tm++) {
            struct trk_tracker_params p;
            trk_tracker_mn_kn_params(&p);
            p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-6);
            p.confirm.method = cm ? TRK_CONFIRM_SPRT : TRK_CONFIRM_MN;
            if (cm) {
                memset(&p.confirm.u.sprt, 0, sizeof p.confirm.u.sprt);
                p.confirm.u.sprt.alpha = TRK_REAL_C(0.01);
                p.confirm.u.sprt.beta = TRK_REAL_C(0.1);
                p.confirm.u.sprt.model = TRK_SPRT_HMM;
                trk_hmm_params_uniform(&p.confirm.u.sprt.hmm, 1, &hs);
            }
            p.term.method = tm ? TRK_TERM_PAGE : TRK_TERM_KN;
            if (tm) {
                trk_hmm_params_uniform(&p.term.u.page.hmm, 1, &hs);
                p.term.u.page.h = 3;
            }
            TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
            struct trk_detection d;
            memset(&d, 0, sizeof d);
            int confirmed_at = -1, ended_at = -1;
            for (int k = 0; k < 30 && ended_at < 0; k++) {
                d.x_m = (trk_real)(2.0 * k);
                struct trk_scan scan = {SEC(k), 0, k < 10 ? 1u : 0u, &d, NULL, 0, {0, 0, 0}, NULL};
                TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
                const struct trk_track *tr = trk_tracker_track(&tk, 0);
                assert_non_null(tr);
                if (tr->status == TRK_TRACK_CONFIRMED && confirmed_at < 0) confirmed_at = k;
                if (tr->status == TRK_TRACK_TERMINATED) {
                    assert_int_equal(tr->end_reason, TRK_END_TERMINATED);
                    ended_at = k;
                }
            }
            assert_int_equal(confirmed_at, cm ? 1 : 2);
            assert_int_equal(ended_at, tm ? 12 : 14); /* Page: 3 misses; K/N 0/5: 5 misses */
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_union_without_clutter),
        cmocka_unit_test(test_clutter_unsupported),
        cmocka_unit_test(test_other_methods_run),
    };
    return trk_run_tests("tracker_noclutter", tests, NULL, NULL);
}
