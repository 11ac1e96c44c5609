/* test_confirm_mn.c - M-of-N confirmation (trk/confirm_mn.h): every
 * detection pattern of 10 scans against the rule stated directly (fixed and
 * sliding windows, every M <= N <= 6), the sticky decision, N = 64 (the
 * whole 64-bit history), bad input, one model shared by several tracks. */
#include "trk_test.h"
#include "trk/confirm_mn.h"

#define UNWRITTEN ((enum trk_decision)77)

/* The rule of docs/conventions.md "M/N confirmation", stated directly: the decision
 * after scan t (1-based) of the pattern d[0..t-1]. */
static enum trk_decision reference(const int *d, int t, int m, int n, enum trk_mn_mode mode)
{
    for (int u = 1; u <= t; u++) { /* first scan at which a rule fires */
        int count = 0;
        if (mode == TRK_MN_FIXED) {
            if (u > n) break; /* undecided after the window: pending for good */
            for (int i = 0; i < u; i++) count += d[i];
            if (count >= m) return TRK_DECISION_CONFIRM;
            if (count + (n - u) < m) return TRK_DECISION_TERMINATE;
        } else {
            for (int i = u - n < 0 ? 0 : u - n; i < u; i++) count += d[i];
            if (count >= m) return TRK_DECISION_CONFIRM;
        }
    }
    return TRK_DECISION_CONTINUE;
}

static int ref_count(const int *d, int t, int n, enum trk_mn_mode mode)
{
    int count = 0;
    if (mode == TRK_MN_FIXED)
        for (int i = 0; i < t && i < n; i++) count += d[i];
    else
        for (int i = t - n < 0 ? 0 : t - n; i < t; i++) count += d[i];
    return count;
}

static void test_exhaustive(void **state)
{
    (void)state;
    enum { T = 10 };
    long checked = 0;
    for (int mode = 0; mode < 2; mode++)
        for (int n = 1; n <= 6; n++)
            for (int m = 1; m <= n; m++) {
                const struct trk_mn_params p = {m, n, mode ? TRK_MN_SLIDING : TRK_MN_FIXED};
                struct trk_mn_model md;
                TRK_ASSERT_OK(trk_mn_model_init(&md, &p));
                for (unsigned pat = 0; pat < (1u << T); pat++) {
                    int d[T];
                    for (int i = 0; i < T; i++) d[i] = (int)((pat >> i) & 1u);
                    struct trk_mn s;
                    trk_mn_reset(&md, &s);
                    for (int t = 1; t <= T; t++) {
                        enum trk_decision dec = UNWRITTEN;
                        TRK_ASSERT_OK(trk_mn_step(&md, &s, d[t - 1], &dec));
                        const enum trk_decision want = reference(d, t, m, n, p.mode);
                        if (dec != want || s.decision != want || s.count != ref_count(d, t, n, p.mode))
                            fail_msg("M/N %d/%d %s pattern %#x scan %d: decision %s (state %s) count %d, "
                                     "want %s count %d",
                                     m, n, mode ? "sliding" : "fixed", pat, t, trk_decision_str(dec),
                                     trk_decision_str(s.decision), s.count, trk_decision_str(want),
                                     ref_count(d, t, n, p.mode));
                        assert_int_equal(s.t, t);
                        checked++;
                    }
                }
            }
    assert_int_equal(checked, 2L * 21 * 1024 * T);
}

/* Sticky: after CONFIRM the count keeps moving (sliding window empties) and
 * the decision holds; a fixed-window rejection holds even if every later
 * scan is a detection. Reset starts afresh. */
static void test_sticky(void **state)
{
    (void)state;
    const struct trk_mn_params ps = {2, 3, TRK_MN_SLIDING};
    struct trk_mn_model m;
    struct trk_mn s;
    TRK_ASSERT_OK(trk_mn_model_init(&m, &ps));
    trk_mn_reset(&m, &s);
    enum trk_decision d = UNWRITTEN;
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
    assert_int_equal(d, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
    assert_int_equal(d, TRK_DECISION_CONFIRM);
    for (int t = 0; t < 5; t++) {
        TRK_ASSERT_OK(trk_mn_step(&m, &s, 0, &d));
        assert_int_equal(d, TRK_DECISION_CONFIRM);
    }
    assert_int_equal(s.count, 0); /* the window has emptied; the decision stands */
    trk_mn_reset(&m, &s);
    assert_true(s.decision == TRK_DECISION_CONTINUE && s.count == 0 && s.t == 0 && s.history == 0);

    const struct trk_mn_params pf = {3, 4, TRK_MN_FIXED};
    TRK_ASSERT_OK(trk_mn_model_init(&m, &pf));
    trk_mn_reset(&m, &s);
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 0, &d));
    assert_int_equal(d, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 0, &d)); /* 0 + 2 scans left < 3: certain failure */
    assert_int_equal(d, TRK_DECISION_TERMINATE);
    for (int t = 0; t < 10; t++) {
        TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
        assert_int_equal(d, TRK_DECISION_TERMINATE);
    }
    assert_int_equal(s.count, 2); /* scans 3 and 4 counted, nothing after the window */
    assert_int_equal(s.t, 12);
}

/* N = 64: the history uses every bit of its uint64_t (no mask). */
static void test_window_64(void **state)
{
    (void)state;
    const struct trk_mn_params p = {64, 64, TRK_MN_SLIDING};
    struct trk_mn_model m;
    struct trk_mn s;
    TRK_ASSERT_OK(trk_mn_model_init(&m, &p));
    trk_mn_reset(&m, &s);
    enum trk_decision d = UNWRITTEN;
    for (int t = 1; t <= 63; t++) {
        TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
        assert_int_equal(d, TRK_DECISION_CONTINUE);
    }
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
    assert_int_equal(d, TRK_DECISION_CONFIRM);
    assert_int_equal(s.count, 64);
    assert_true(s.history == UINT64_MAX);
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 0, &d)); /* the oldest 1 leaves the window */
    assert_int_equal(s.count, 63);
    assert_int_equal(d, TRK_DECISION_CONFIRM);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_mn_model m, mb;
    memset(&m, 0x5a, sizeof m);
    mb = m;
    struct trk_mn_params p = {0, 5, TRK_MN_FIXED};
    TRK_ASSERT_STATUS(trk_mn_model_init(&m, &p), TRK_E_RANGE);
    p.m = 6;
    TRK_ASSERT_STATUS(trk_mn_model_init(&m, &p), TRK_E_RANGE); /* m > n */
    p.m = 3;
    p.n = TRK_MN_MAX_N + 1;
    TRK_ASSERT_STATUS(trk_mn_model_init(&m, &p), TRK_E_RANGE);
    p.n = 5;
    p.mode = (enum trk_mn_mode)2;
    TRK_ASSERT_STATUS(trk_mn_model_init(&m, &p), TRK_E_ARG);
    p.mode = TRK_MN_FIXED;
    TRK_ASSERT_STATUS(trk_mn_model_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mn_model_init(&m, NULL), TRK_E_ARG);
    assert_memory_equal(&m, &mb, sizeof m); /* never half-initialised */

    TRK_ASSERT_OK(trk_mn_model_init(&m, &p));
    struct trk_mn s, sb;
    trk_mn_reset(&m, &s);
    enum trk_decision d = UNWRITTEN;
    TRK_ASSERT_OK(trk_mn_step(&m, &s, 1, &d));
    sb = s;
    d = UNWRITTEN;
    TRK_ASSERT_STATUS(trk_mn_step(NULL, &s, 1, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mn_step(&m, NULL, 1, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mn_step(&m, &s, 1, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mn_step(&m, &s, 2, &d), TRK_E_RANGE); /* detected is 0 or 1 */
    TRK_ASSERT_STATUS(trk_mn_step(&m, &s, -1, &d), TRK_E_RANGE);
    assert_int_equal(d, UNWRITTEN);
    trk_mn_reset(NULL, &s); /* no-ops */
    trk_mn_reset(&m, NULL);
    assert_memory_equal(&s, &sb, sizeof s);
}

/* One model, two tracks: each track's result is that of a private model. */
static void test_shared_model(void **state)
{
    (void)state;
    const struct trk_mn_params p = {3, 5, TRK_MN_FIXED};
    struct trk_mn_model shared, own, copy;
    TRK_ASSERT_OK(trk_mn_model_init(&shared, &p));
    TRK_ASSERT_OK(trk_mn_model_init(&own, &p));
    copy = shared;
    struct trk_mn a, b, r;
    trk_mn_reset(&shared, &a);
    trk_mn_reset(&shared, &b);
    trk_mn_reset(&own, &r);
    enum trk_decision da = UNWRITTEN, db = UNWRITTEN, dr = UNWRITTEN;
    for (int t = 0; t < 8; t++) {
        TRK_ASSERT_OK(trk_mn_step(&shared, &a, 1, &da));
        TRK_ASSERT_OK(trk_mn_step(&shared, &b, 0, &db));
        TRK_ASSERT_OK(trk_mn_step(&own, &r, 1, &dr));
        assert_true(a.history == r.history && a.t == r.t && a.count == r.count && a.decision == r.decision);
    }
    assert_int_equal(da, TRK_DECISION_CONFIRM);
    assert_int_equal(db, TRK_DECISION_TERMINATE);
    assert_memory_equal(&shared, &copy, sizeof shared);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exhaustive),
        cmocka_unit_test(test_sticky),
        cmocka_unit_test(test_window_64),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_shared_model),
    };
    return trk_run_tests("confirm_mn", tests, NULL, NULL);
}
