/* test_tracker_nojoint.c - the tracker built with TRK_WITH_JOINT = 0
 * (config.h): the defaults take the per-track PDA, joint association is
 * refused with TRK_E_UNSUPPORTED naming "association", the pair store is one
 * track's gated set, and the table tracks two targets as usual.
 * tests/test_tracker_nojoint.mk links this program with tracker.c and
 * tracker_params.c compiled in the same configuration. */
#define TRK_WITH_JOINT 0
#include "trk_test.h"
#include "trk/tracker.h"

static struct trk_tracker tk;

static void test_defaults_and_refusal(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    trk_tracker_default_params(&p);
    assert_int_equal(p.association, TRK_ASSOC_PDA);
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    p.association = TRK_ASSOC_JOINT;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_UNSUPPORTED);
    assert_string_equal(field, "association");
    TRK_ASSERT_STATUS(trk_tracker_init(&tk, &p), TRK_E_UNSUPPORTED);
    assert_int_equal(sizeof tk.ws.cand / sizeof tk.ws.cand[0], TRK_MAX_DETECTIONS);
}

/* two targets 500 m apart, detected every scan: two confirmed tracks */
static void test_tracks(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-6);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    for (int k = 0; k < 10; k++) {
        struct trk_detection d[2];
        memset(d, 0, sizeof d);
        d[0].x_m = (trk_real)(2 * k);
        d[1].x_m = (trk_real)(500 - 2 * k);
        d[1].y_m = 300;
        const struct trk_scan scan = {(int64_t)k * 1000000, 0, 2, d, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
        assert_int_equal(rep.n_clusters, 0);
    }
    size_t confirmed = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk, i);
        confirmed += tr && tr->status == TRK_TRACK_CONFIRMED;
    }
    assert_int_equal(confirmed, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults_and_refusal),
        cmocka_unit_test(test_tracks),
    };
    return trk_run_tests("tracker_nojoint", tests, NULL, NULL);
}
