/* test_term_kn.c - K-of-N termination (trk/term_kn.h): every detection
 * pattern of 10 scans against the rule stated directly (every K < N <= 6),
 * a long pseudo-random run at N = 64 against a plain array window, the
 * sticky decision, bad input. */
#include "trk_test.h"
#include "trk/term_kn.h"

#define UNWRITTEN ((enum trk_decision)77)

/* count of the last min(t, n) scans of d[0..t-1] */
static int ref_count(const int *d, int t, int n)
{
    int count = 0;
    for (int i = t - n < 0 ? 0 : t - n; i < t; i++) count += d[i];
    return count;
}

static void test_exhaustive(void **state)
{
    (void)state;
    enum { T = 10 };
    for (int n = 1; n <= 6; n++)
        for (int k = 0; k < n; k++) {
            const struct trk_kn_params p = {k, n};
            struct trk_kn_model m;
            TRK_ASSERT_OK(trk_kn_model_init(&m, &p));
            for (unsigned pat = 0; pat < (1u << T); pat++) {
                int d[T];
                for (int i = 0; i < T; i++) d[i] = (int)((pat >> i) & 1u);
                struct trk_kn s;
                trk_kn_reset(&m, &s);
                enum trk_decision want = TRK_DECISION_CONTINUE;
                for (int t = 1; t <= T; t++) {
                    enum trk_decision dec = UNWRITTEN;
                    TRK_ASSERT_OK(trk_kn_step(&m, &s, d[t - 1], &dec));
                    const int count = ref_count(d, t, n);
                    const int fire = t >= n && count <= k; /* "K or fewer in the last N" */
                    if (fire) want = TRK_DECISION_TERMINATE;
                    if (dec != want || s.decision != want || s.count != count || s.fire != fire)
                        fail_msg("K/N %d/%d pattern %#x scan %d: decision %s count %d fire %d, want %s %d %d",
                                 k, n, pat, t, trk_decision_str(dec), s.count, s.fire,
                                 trk_decision_str(want), count, fire);
                }
            }
        }
}

/* N = 64 (the whole history word) over 10^5 pseudo-random scans. */
static void test_window_64(void **state)
{
    (void)state;
    const struct trk_kn_params p = {20, 64};
    struct trk_kn_model m;
    struct trk_kn s;
    TRK_ASSERT_OK(trk_kn_model_init(&m, &p));
    trk_kn_reset(&m, &s);
    static int d[100000];
    uint64_t x = 88172645463325252ull;
    enum trk_decision want = TRK_DECISION_CONTINUE, dec = UNWRITTEN;
    int t_fire = 0;
    for (int t = 1; t <= 100000; t++) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        d[t - 1] = (x % 100) < 50; /* about 32 of 64: fires now and then */
        TRK_ASSERT_OK(trk_kn_step(&m, &s, d[t - 1], &dec));
        const int count = ref_count(d, t, 64);
        assert_int_equal(s.count, count);
        assert_int_equal(s.fire, t >= 64 && count <= 20);
        if (s.fire && !t_fire) {
            t_fire = t;
            want = TRK_DECISION_TERMINATE;
        }
        assert_int_equal(dec, want);
    }
    assert_true(t_fire > 0);
}

/* Sticky: TERMINATE holds while detections come back (count above K, fire
 * 0) and the count keeps running; reset starts afresh. K = 0 is "N misses in
 * a row". */
static void test_sticky(void **state)
{
    (void)state;
    const struct trk_kn_params p = {0, 3};
    struct trk_kn_model m;
    struct trk_kn s;
    TRK_ASSERT_OK(trk_kn_model_init(&m, &p));
    trk_kn_reset(&m, &s);
    enum trk_decision d = UNWRITTEN;
    const int pat[5] = {0, 0, 1, 0, 0}; /* never 3 misses in a row */
    for (int t = 0; t < 5; t++) {
        TRK_ASSERT_OK(trk_kn_step(&m, &s, pat[t], &d));
        assert_int_equal(d, TRK_DECISION_CONTINUE);
    }
    TRK_ASSERT_OK(trk_kn_step(&m, &s, 0, &d)); /* the third miss in a row */
    assert_int_equal(d, TRK_DECISION_TERMINATE);
    for (int t = 0; t < 4; t++) {
        TRK_ASSERT_OK(trk_kn_step(&m, &s, 1, &d));
        assert_int_equal(s.fire, 0);
        assert_int_equal(d, TRK_DECISION_TERMINATE);
    }
    assert_int_equal(s.count, 3);
    trk_kn_reset(&m, &s);
    assert_true(s.decision == TRK_DECISION_CONTINUE && s.count == 0 && s.t == 0 && s.fire == 0);
    /* no decision before N scans, even with nothing detected */
    TRK_ASSERT_OK(trk_kn_step(&m, &s, 0, &d));
    TRK_ASSERT_OK(trk_kn_step(&m, &s, 0, &d));
    assert_int_equal(d, TRK_DECISION_CONTINUE);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_kn_model m, mb;
    memset(&m, 0x5a, sizeof m);
    mb = m;
    struct trk_kn_params p = {3, 3};
    TRK_ASSERT_STATUS(trk_kn_model_init(&m, &p), TRK_E_RANGE); /* k >= n */
    p.k = -1;
    TRK_ASSERT_STATUS(trk_kn_model_init(&m, &p), TRK_E_RANGE);
    p.k = 0;
    p.n = 0;
    TRK_ASSERT_STATUS(trk_kn_model_init(&m, &p), TRK_E_RANGE);
    p.n = TRK_KN_MAX_N + 1;
    TRK_ASSERT_STATUS(trk_kn_model_init(&m, &p), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_kn_model_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_kn_model_init(&m, NULL), TRK_E_ARG);
    assert_memory_equal(&m, &mb, sizeof m);

    p.n = 4;
    TRK_ASSERT_OK(trk_kn_model_init(&m, &p));
    struct trk_kn s, sb;
    trk_kn_reset(&m, &s);
    enum trk_decision d = UNWRITTEN;
    TRK_ASSERT_OK(trk_kn_step(&m, &s, 1, &d));
    sb = s;
    d = UNWRITTEN;
    TRK_ASSERT_STATUS(trk_kn_step(NULL, &s, 1, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_kn_step(&m, NULL, 1, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_kn_step(&m, &s, 0, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_kn_step(&m, &s, 5, &d), TRK_E_RANGE); /* detected is 0 or 1 */
    assert_int_equal(d, UNWRITTEN);
    trk_kn_reset(NULL, &s); /* no-op */
    assert_memory_equal(&s, &sb, sizeof s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exhaustive),
        cmocka_unit_test(test_window_64),
        cmocka_unit_test(test_sticky),
        cmocka_unit_test(test_bad_input),
    };
    return trk_run_tests("term_kn", tests, NULL, NULL);
}
