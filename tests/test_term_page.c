/* test_term_page.c - Page (CUSUM) termination with the HMM detection model
 * (Blanding eqs 5-10), paper and complete event models (docs/conventions.md
 * "Complete detection-event model"): recursion against closed forms and
 * brute-force likelihoods, strict threshold, sticky decision, multisensor,
 * bad input, one shared model for many tracks, 10^6-step runs that stay
 * finite, and the coasting track that only the complete model terminates. */
#include "trk_test.h"
#include "hmm_brute.h"
#include "trk/term_page.h"

/* The steps through the decision output: on success the decision written
 * must be the state's sticky one; on error *decision stays as it was. */
#define UNWRITTEN ((enum trk_decision)77)
static trk_status step(const struct trk_page_model *m, struct trk_page *s, unsigned sensor,
                       int detected, trk_real pfa)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_page_step(m, s, sensor, detected, pfa, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}
static trk_status step_llr(const struct trk_page_model *m, struct trk_page *s, trk_real inc)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_page_step_llr(m, s, inc, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}

/* Blanding's HMM, complete event model (the default). */
static struct trk_page_params params(unsigned ns, trk_real h)
{
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    struct trk_page_params p;
    trk_hmm_params_uniform(&p.hmm, ns, &sp);
    p.h = h;
    return p;
}

/* Build the shared model and start one track's state with it. */
static void start(struct trk_page_model *m, struct trk_page *s, const struct trk_page_params *p)
{
    TRK_ASSERT_OK(trk_page_model_init(m, p));
    trk_page_reset(m, s);
}

/* The paper's form, fixed P_D (pd_low = pd_high): s = ln(pfa/pd) on a hit,
 * ln((1-pfa)/(1-pd)) on a miss; c = max(c + s, 0). */
static void test_fixed_pd_closed_form(void **state)
{
    (void)state;
    struct trk_page_params p = params(1, 3);
    p.hmm.events = TRK_EVENTS_PAPER;
    p.hmm.sensor[0].pd_low = p.hmm.sensor[0].pd_high = TRK_REAL_C(0.6);
    struct trk_page_model m;
    struct trk_page pg;
    start(&m, &pg, &p);
    const int d[12] = {0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0};
    const double pd = (double)TRK_REAL_C(0.6), pfa = (double)TRK_REAL_C(0.02);
    double c = 0;
    enum trk_decision dec = TRK_DECISION_CONTINUE;
    for (int t = 0; t < 12; t++) {
        TRK_ASSERT_OK(step(&m, &pg, 0, d[t], TRK_REAL_C(0.02)));
        const double s = d[t] ? log(pfa / pd) : log((1 - pfa) / (1 - pd));
        c = c + s > 0 ? c + s : 0;
        TRK_ASSERT_NEAR(pg.s, s, 0, TRK_TOL(1e-14, 1e-6));
        TRK_ASSERT_NEAR(pg.stat, c, 1e-300, TRK_TOL(1e-14, 1e-6));
        assert_int_equal(pg.fire, c > 3);
        if (c > 3) dec = TRK_DECISION_TERMINATE;
        assert_int_equal(pg.decision, dec);
        assert_int_equal(pg.t, t + 1);
    }
    assert_int_equal(dec, TRK_DECISION_TERMINATE); /* 0.896 per miss: fires after four misses in a row */
}

/* Without a reset to 0, sum s = sum ln f0 - ln P(d | H1) (eq 53 by
 * enumeration): the increments are the HMM's predictive log-ratios, in the
 * paper's event model and in the complete one. */
static void test_increments_vs_enumeration(void **state)
{
    (void)state;
    for (int complete = 0; complete < 2; complete++) {
        struct trk_page_params p = params(1, 100);
        p.hmm.events = complete ? TRK_EVENTS_COMPLETE : TRK_EVENTS_PAPER;
        struct trk_page_model m;
        struct trk_page pg;
        start(&m, &pg, &p);
        const int d[16] = {1, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 1, 0, 1, 0};
        double sum_s = 0, sum_f0 = 0, pfas[16];
        for (int t = 0; t < 16; t++) {
            const trk_real pfa = (trk_real)(0.05 + 0.01 * t);
            pfas[t] = (double)pfa;
            TRK_ASSERT_OK(step(&m, &pg, 0, d[t], pfa));
            sum_s += (double)pg.s;
            sum_f0 += d[t] ? log(pfas[t]) : log1p(-pfas[t]);
        }
        const double p_ = 0.1 / 3, q = 0.1;
        TRK_ASSERT_NEAR(sum_s,
                        sum_f0 - brute_log_lik_events(16, d, complete ? pfas : NULL, p_, q, 0.1,
                                                      0.9, p_ / (p_ + q)),
                        0, TRK_TOL(1e-13, 1e-5));
    }
}

/* Strict '>' and sticky decision, with exactly representable increments. */
static void test_strict_and_sticky(void **state)
{
    (void)state;
    struct trk_page_params p = params(1, 2);
    struct trk_page_model m;
    struct trk_page pg;
    start(&m, &pg, &p);
    for (int i = 0; i < 4; i++) TRK_ASSERT_OK(step_llr(&m, &pg, TRK_REAL_C(0.5)));
    assert_true(pg.stat == 2); /* c == h: no firing */
    assert_int_equal(pg.fire, 0);
    assert_int_equal(pg.decision, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(step_llr(&m, &pg, TRK_REAL_C(0.25)));
    assert_int_equal(pg.fire, 1);
    assert_int_equal(pg.decision, TRK_DECISION_TERMINATE);
    TRK_ASSERT_OK(step_llr(&m, &pg, -10));
    assert_true(pg.stat == 0); /* clamped at 0, no reset after the decision */
    assert_int_equal(pg.fire, 0);
    assert_int_equal(pg.decision, TRK_DECISION_TERMINATE); /* sticky */
    trk_page_reset(&m, &pg);
    assert_true(pg.stat == 0 && pg.decision == TRK_DECISION_CONTINUE && pg.t == 0);
}

/* Multisensor: two sensors interleaved give the same increments as each
 * sensor's looks through its own single-sensor model. */
static void test_multisensor(void **state)
{
    (void)state;
#if TRK_MAX_SENSORS >= 2
    struct trk_page_params p2 = params(2, 50), p1 = params(1, 50);
    struct trk_page_model m2, m1;
    struct trk_page both, a, b;
    start(&m2, &both, &p2);
    start(&m1, &a, &p1);
    trk_page_reset(&m1, &b); /* a and b: two tracks sharing model m1 */
    for (int t = 0; t < 40; t++) {
        const unsigned sensor = (unsigned)((t * 7 + t / 3) % 2);
        const int det = (t * 5) % 7 < 2;
        const trk_real pfa = TRK_REAL_C(0.05) + TRK_REAL_C(0.002) * (trk_real)t;
        TRK_ASSERT_OK(step(&m2, &both, sensor, det, pfa));
        struct trk_page *one = sensor ? &b : &a;
        TRK_ASSERT_OK(step(&m1, one, 0, det, pfa));
        TRK_ASSERT_NEAR(both.s, one->s, 0, TRK_TOL(1e-15, 1e-6));
    }
#else
    skip();
#endif
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_page_model m, mbefore;
    memset(&m, 0x3c, sizeof m);
    mbefore = m;
    struct trk_page_params p = params(1, 0);
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_RANGE); /* h = 0 */
    p.h = -1;
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_RANGE);
    p.h = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_NAN);
    p.h = (trk_real)INFINITY;
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_NAN);
    p = params(1, 3);
    p.hmm.sensor[0].pd_high = 1;
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_RANGE);
    p = params(TRK_MAX_SENSORS + 1, 3);
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_page_model_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_page_model_init(&m, NULL), TRK_E_ARG);
    p = params(1, 3);
    p.hmm.events = (enum trk_event_model)5; /* unknown event model */
    TRK_ASSERT_STATUS(trk_page_model_init(&m, &p), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m); /* never half-initialised */
    struct trk_page pg, before;
    p = params(1, 3);
    start(&m, &pg, &p);
    TRK_ASSERT_OK(step(&m, &pg, 0, 0, TRK_REAL_C(0.1)));
    before = pg;
    mbefore = m;
    TRK_ASSERT_STATUS(step(&m, &pg, 0, 1, 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(step(&m, &pg, 0, 1, 1), TRK_E_RANGE);
    TRK_ASSERT_STATUS(step(&m, &pg, 0, 1, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(step(&m, &pg, 1, 1, TRK_REAL_C(0.1)), TRK_E_SENSOR);
    TRK_ASSERT_STATUS(step_llr(&m, &pg, (trk_real)INFINITY), TRK_E_NAN);
    TRK_ASSERT_STATUS(step(NULL, &pg, 0, 1, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step(&m, NULL, 0, 1, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(NULL, &pg, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(&m, NULL, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(step(&m, &pg, 0, 2, TRK_REAL_C(0.1)), TRK_E_RANGE); /* detected 0 or 1 */
    TRK_ASSERT_STATUS(trk_page_step(&m, &pg, 0, 1, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_page_step_llr(&m, &pg, 1, NULL), TRK_E_ARG);
    trk_page_reset(NULL, &pg); /* no-op */
    assert_memory_equal(&pg, &before, sizeof pg);
    assert_memory_equal(&m, &mbefore, sizeof m);
}

/* Every field of two states bit for bit (not memcmp: padding). */
static void assert_same_state(const struct trk_page *x, const struct trk_page *y)
{
    assert_memory_equal(x->hmm.post_high, y->hmm.post_high, sizeof x->hmm.post_high);
    assert_memory_equal(x->hmm.n_looks, y->hmm.n_looks, sizeof x->hmm.n_looks);
    assert_memory_equal(&x->stat, &y->stat, sizeof x->stat);
    assert_memory_equal(&x->s, &y->s, sizeof x->s);
    assert_int_equal(x->t, y->t);
    assert_int_equal(x->fire, y->fire);
    assert_int_equal(x->decision, y->decision);
}

/* One model, many tracks: states started from a shared model evolve
 * independently, exactly as with a model of their own, and stepping never
 * writes the model. */
static void test_shared_model(void **state)
{
    (void)state;
    struct trk_page_params p = params(TRK_MAX_SENSORS >= 2 ? 2 : 1, 4);
    struct trk_page_model shared, own[3], copy;
    struct trk_page s[3], r[3];
    TRK_ASSERT_OK(trk_page_model_init(&shared, &p));
    copy = shared;
    for (int k = 0; k < 3; k++) {
        start(&own[k], &r[k], &p);
        trk_page_reset(&shared, &s[k]);
    }
    for (int t = 0; t < 60; t++)
        for (int k = 0; k < 3; k++) {
            const unsigned sensor = (unsigned)(t % p.hmm.n_sensors);
            const int det = (t * (k + 3) + k) % 5 < 2;
            const trk_real pfa = TRK_REAL_C(0.01) * (trk_real)(k + 1);
            TRK_ASSERT_OK(step(&shared, &s[k], sensor, det, pfa));
            TRK_ASSERT_OK(step(&own[k], &r[k], sensor, det, pfa));
            assert_same_state(&s[k], &r[k]);
        }
    assert_memory_equal(&shared, &copy, sizeof shared);
    assert_true(s[0].stat != s[1].stat); /* different histories, different states */
}

/* 10^6 looks of misses (c grows without bound under H0), of detections
 * (c pinned at 0) and alternating sensors: always finite. */
static void test_long_runs(void **state)
{
    (void)state;
    struct trk_page_params p = params(TRK_MAX_SENSORS >= 2 ? 2 : 1, 5);
    struct trk_page_model m;
    struct trk_page pg;
    TRK_ASSERT_OK(trk_page_model_init(&m, &p));
    for (int mode = 0; mode < 3; mode++) {
        trk_page_reset(&m, &pg);
        for (long t = 0; t < 1000000; t++) {
            const int det = mode == 1 || (mode == 2 && t % 3 == 0);
            TRK_ASSERT_OK(step(&m, &pg, (unsigned)(t % p.hmm.n_sensors), det, TRK_REAL_C(1e-6)));
        }
        assert_true(isfinite((double)pg.stat) && pg.stat >= 0);
        assert_int_equal(pg.t, 1000000);
        if (mode == 0) { /* each miss adds -ln(1-pd_mix) >= ln(1/0.9) (complete model) */
            assert_true(pg.stat > 1e5);
            assert_int_equal(pg.decision, TRK_DECISION_TERMINATE);
        }
        if (mode == 1) assert_true(pg.stat == 0 && pg.decision == TRK_DECISION_CONTINUE);
    }
}

/* Complete event model, fixed P_D = 0.6 (docs/conventions.md "Complete
 * detection-event model"): s = ln pfa - ln(1 - 0.4 (1-pfa)) on a hit and
 * s = -ln 0.4 on a miss, whatever pfa (near 1 included: finite, > 0). */
static void test_fixed_pd_complete_closed_form(void **state)
{
    (void)state;
    struct trk_page_params p = params(1, 3);
    p.hmm.sensor[0].pd_low = p.hmm.sensor[0].pd_high = TRK_REAL_C(0.6);
    struct trk_page_model m;
    struct trk_page pg;
    start(&m, &pg, &p);
    const trk_real pfas[5] = {TRK_REAL_C(0.02), TRK_REAL_C(0.3), TRK_REAL_C(0.9), TRK_REAL_C(0.999),
                              1 - (trk_real)TRK_TOL(1e-12, 1e-6)};
    const int d[16] = {1, 0, 0, 1, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 1, 0};
    const double pd = (double)TRK_REAL_C(0.6);
    double c = 0;
    enum trk_decision dec = TRK_DECISION_CONTINUE;
    for (int t = 0; t < 16; t++) {
        const trk_real pfa = pfas[t % 5];
        const double f = (double)pfa;
        TRK_ASSERT_OK(step(&m, &pg, 0, d[t], pfa));
        const double s = d[t] ? log(f) - log1p(-(1 - pd) * (1 - f)) : -log1p(-pd);
        /* a miss at pfa near 1: |ln f0| ~ 27.6 (float 13.8) cancels in s */
        TRK_ASSERT_NEAR(pg.s, s, TRK_TOL(1e-13, 4e-6), TRK_TOL(1e-14, 1e-6));
        if (!d[t]) assert_true(pg.s > 0);
        c = c + s > 0 ? c + s : 0;
        TRK_ASSERT_NEAR(pg.stat, c, TRK_TOL(1e-13, 1e-5), TRK_TOL(1e-14, 1e-6));
        if (c > 3) dec = TRK_DECISION_TERMINATE;
        assert_int_equal(pg.decision, dec);
    }
    /* 0.916 per miss: the run of four misses (scans 11-14) fires, at any pfa */
    assert_int_equal(dec, TRK_DECISION_TERMINATE);
}

/* At a small pfa the two event models give nearly the same increments
 * (they differ by O(pfa): exactly equal at pfa = 0, see test_hmm_detect). */
static void test_forms_agree_at_small_pfa(void **state)
{
    (void)state;
    struct trk_page_params pc = params(1, 50), pp = params(1, 50);
    pp.hmm.events = TRK_EVENTS_PAPER;
    struct trk_page_model mc, mp;
    struct trk_page sc, sp;
    start(&mc, &sc, &pc);
    start(&mp, &sp, &pp);
    for (int t = 0; t < 30; t++) {
        const int det = (t * 5) % 7 < 3;
        TRK_ASSERT_OK(step(&mc, &sc, 0, det, TRK_REAL_C(1e-9)));
        TRK_ASSERT_OK(step(&mp, &sp, 0, det, TRK_REAL_C(1e-9)));
        /* |ds| <= pfa M / f1 <= 1e-9 * 0.9 / 0.1 */
        TRK_ASSERT_NEAR(sc.s, sp.s, TRK_TOL(1e-8, 1e-6), TRK_TOL(1e-14, 1e-6));
    }
}

/* The coasting track that the complete model exists for (docs/conventions.md "Complete detection-event
 * model"): a fading HMM (pd_high 0.9, pd_low 0.1, p = 0.1, q = 0.02), 12
 * looks detected at pfa 1e-3, then only misses while the coasting gate
 * grows: lambda V_k = 0.2 + (41 - 0.2) k / 39 over 40 looks, pfa_k = 1 -
 * exp(-lambda V_k). A pfa that rounds to 1 (double: lambda V > 37.4, float:
 * > 17.3) is refused (TRK_E_RANGE, state untouched); the caller then passes
 * the largest value below 1. */
#define COAST_HITS 12
#define COAST_LOOKS 40
static trk_real coast_pfa(int k, int *rounds_to_one)
{
    const double lv = 0.2 + (41 - 0.2) * k / (COAST_LOOKS - 1);
    const trk_real pfa = (trk_real)-expm1(-lv);
    *rounds_to_one = pfa >= 1;
    return pfa < 1 ? pfa : (TRK_TEST_IS_FLOAT ? (trk_real)nextafterf(1, 0) : (trk_real)nextafter(1, 0));
}
static const struct trk_hmm_sensor_params fading = {TRK_REAL_C(0.1), TRK_REAL_C(0.02), TRK_REAL_C(0.1),
                                                     TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};

/* Page, h = 5. Complete: each miss adds s = -ln M, M = 0.9 - 0.8 x the
 * miss mixture at prior x = P(u = 1); after any look x >= min(p, 1 - q) =
 * 0.1, so s >= -ln 0.82 = 0.198 whatever pfa. The first four misses, from
 * the high state the hits left, add 2.14, 1.45, 0.56, 0.26 (c = 4.41), so c
 * > 5 after at most 4 + ceil((5 - 4.40) / 0.198) = 8 misses (computed: the
 * 7th). Paper: s = ln(1 - pfa_k) - ln M = -lambda V_k - ln M, negative from
 * the third miss on (the empty gate counts FOR the target): c peaks at 2.14
 * and the track is never terminated. */
static void test_coasting_track_terminates(void **state)
{
    (void)state;
    for (int complete = 0; complete < 2; complete++) {
        struct trk_page_params p;
        trk_hmm_params_uniform(&p.hmm, 1, &fading);
        p.hmm.events = complete ? TRK_EVENTS_COMPLETE : TRK_EVENTS_PAPER;
        p.h = 5;
        struct trk_page_model m;
        struct trk_page pg, before;
        start(&m, &pg, &p);
        for (int t = 0; t < COAST_HITS; t++) {
            TRK_ASSERT_OK(step(&m, &pg, 0, 1, TRK_REAL_C(1e-3)));
            assert_true(pg.stat == 0);
        }
        int fired = 0, refused = 0;
        double c4 = 0, cmax = 0;
        for (int k = 0; k < COAST_LOOKS; k++) {
            int one;
            const trk_real pfa = coast_pfa(k, &one);
            if (one) { /* pfa = 1 is refused and changes nothing */
                before = pg;
                TRK_ASSERT_STATUS(step(&m, &pg, 0, 0, 1), TRK_E_RANGE);
                assert_same_state(&pg, &before);
                refused++;
            }
            TRK_ASSERT_OK(step(&m, &pg, 0, 0, pfa));
            assert_true(isfinite((double)pg.s) && isfinite((double)pg.stat));
            if (complete) assert_true(pg.s > 0.198);     /* s >= -ln 0.82 */
            else if (k >= 2) assert_true(pg.s < 0);      /* the paper's flaw */
            if (k == 3) c4 = (double)pg.stat;
            if (pg.stat > cmax) cmax = (double)pg.stat;
            if (!fired && pg.decision == TRK_DECISION_TERMINATE) fired = k + 1;
        }
        assert_true(refused >= 1 && refused <= (TRK_TEST_IS_FLOAT ? 24 : 4));
        if (complete) {
            assert_true(c4 > 4.40);
            assert_true(fired >= 1 && fired <= 8);
        } else {
            assert_int_equal(fired, 0); /* 40 empty, growing gates: not terminated */
            assert_int_equal(pg.decision, TRK_DECISION_CONTINUE);
            assert_true(cmax < 2.2);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fixed_pd_closed_form),
        cmocka_unit_test(test_increments_vs_enumeration),
        cmocka_unit_test(test_strict_and_sticky),
        cmocka_unit_test(test_multisensor),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_shared_model),
        cmocka_unit_test(test_long_runs),
        cmocka_unit_test(test_fixed_pd_complete_closed_form),
        cmocka_unit_test(test_forms_agree_at_small_pfa),
        cmocka_unit_test(test_coasting_track_terminates),
    };
    return trk_run_tests("term_page", tests, NULL, NULL);
}
