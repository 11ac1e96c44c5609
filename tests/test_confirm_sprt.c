/* test_confirm_sprt.c - Wald SPRT confirmation: thresholds and llr against
 * closed forms, ties (>= / <=), sticky decisions, the HMM model against
 * Willett's eq 49 by enumeration, both in the paper's and the complete
 * event model (docs/conventions.md "Complete detection-event model"), bad input,
 * one model shared by several tracks, 10^6-step runs. */
#include "trk_test.h"
#include "hmm_brute.h"
#include "trk/confirm_sprt.h"

/* The steps through the decision output: on success the decision written
 * must be the state's sticky one; on error *decision stays as it was. */
#define UNWRITTEN ((enum trk_decision)77)
static trk_status step(const struct trk_sprt_model *m, struct trk_sprt *s, unsigned sensor,
                       int detected, trk_real pfa)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_sprt_step(m, s, sensor, detected, pfa, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}
static trk_status step_llr(const struct trk_sprt_model *m, struct trk_sprt *s, trk_real inc)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_sprt_step_llr(m, s, inc, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}

/* Fixed P_D, complete event model (zeroed hmm: the default). */
static struct trk_sprt_params fixed(trk_real pd, trk_real alpha, trk_real beta)
{
    struct trk_sprt_params p;
    memset(&p, 0, sizeof p);
    p.alpha = alpha;
    p.beta = beta;
    p.model = TRK_SPRT_FIXED_PD;
    p.pd = pd;
    return p;
}

/* Build the shared model and start one track's state with it. */
static void start(struct trk_sprt_model *m, struct trk_sprt *s, const struct trk_sprt_params *p)
{
    TRK_ASSERT_OK(trk_sprt_model_init(m, p));
    trk_sprt_reset(m, s);
}

/* The paper's form: hit ln(P_D / P_FA), miss ln(1-P_D) - ln(1-P_FA). */
static void test_fixed_pd(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.01), TRK_REAL_C(0.1));
    p.hmm.events = TRK_EVENTS_PAPER;
    struct trk_sprt_model m;
    struct trk_sprt s;
    start(&m, &s, &p);
    const double a = (double)TRK_REAL_C(0.01), b = (double)TRK_REAL_C(0.1), pd = (double)TRK_REAL_C(0.8);
    TRK_ASSERT_NEAR(m.ln_a, log((1 - b) / a), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(m.ln_b, log(b / (1 - a)), 0, TRK_TOL(1e-15, 1e-6));
    const int d[8] = {1, 0, 1, 1, 0, 1, 1, 1};
    double llr = 0;
    enum trk_decision dec = TRK_DECISION_CONTINUE;
    for (int t = 0; t < 8; t++) {
        const double pfa = 0.05 + 0.02 * t;
        TRK_ASSERT_OK(step(&m, &s, 3, d[t], (trk_real)pfa)); /* sensor ignored (fixed P_D) */
        const double pf = (double)(trk_real)pfa;
        llr += d[t] ? log(pd / pf) : log1p(-pd) - log1p(-pf);
        TRK_ASSERT_NEAR(s.stat, llr, 0, TRK_TOL(1e-14, 1e-6));
        const enum trk_decision fire = llr >= log((1 - b) / a)   ? TRK_DECISION_CONFIRM
                                       : llr <= log(b / (1 - a)) ? TRK_DECISION_TERMINATE
                                                                 : TRK_DECISION_CONTINUE;
        assert_int_equal(s.fire, fire);
        if (dec == TRK_DECISION_CONTINUE) dec = fire;
        assert_int_equal(s.decision, dec);
    }
    assert_int_equal(dec, TRK_DECISION_CONFIRM);
}

static void test_ties_and_sticky(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.05), TRK_REAL_C(0.05));
    struct trk_sprt_model m;
    struct trk_sprt s;
    start(&m, &s, &p);
    TRK_ASSERT_OK(step_llr(&m, &s, m.ln_a)); /* llr == ln A exactly: confirm */
    assert_int_equal(s.fire, TRK_DECISION_CONFIRM);
    assert_int_equal(s.decision, TRK_DECISION_CONFIRM);
    TRK_ASSERT_OK(step_llr(&m, &s, -100));
    assert_int_equal(s.fire, TRK_DECISION_TERMINATE);
    assert_int_equal(s.decision, TRK_DECISION_CONFIRM); /* the first decision holds */
    TRK_ASSERT_NEAR(s.stat, (double)m.ln_a - 100, 0, TRK_TOL(1e-14, 1e-6)); /* llr runs on */
    TRK_ASSERT_OK(step_llr(&m, &s, 100 - m.ln_a)); /* back between the thresholds */
    assert_int_equal(s.fire, TRK_DECISION_CONTINUE);
    assert_int_equal(s.decision, TRK_DECISION_CONFIRM);
    trk_sprt_reset(&m, &s);
    assert_true(s.stat == 0 && s.decision == TRK_DECISION_CONTINUE && s.t == 0);
    TRK_ASSERT_OK(step_llr(&m, &s, m.ln_b)); /* llr == ln B exactly: reject */
    assert_int_equal(s.fire, TRK_DECISION_TERMINATE);
    assert_int_equal(s.decision, TRK_DECISION_TERMINATE);
    TRK_ASSERT_OK(step_llr(&m, &s, 100));
    assert_int_equal(s.fire, TRK_DECISION_CONFIRM);
    assert_int_equal(s.decision, TRK_DECISION_TERMINATE);
    enum trk_decision d = UNWRITTEN; /* the step's output is the sticky decision too */
    TRK_ASSERT_OK(trk_sprt_step(&m, &s, 0, 1, TRK_REAL_C(0.01), &d));
    assert_int_equal(d, TRK_DECISION_TERMINATE);
}

/* HMM model, the paper's form: llr = ln P(d | H1) - ln P(d | H0) over
 * several sensors (Willett eqs 49, 53, 55; without the TT conditioning,
 * i.e. the initiating detection not passed). */
static void test_hmm_vs_enumeration(void **state)
{
    (void)state;
#if TRK_MAX_SENSORS >= 2
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.5), TRK_REAL_C(1e-9), TRK_REAL_C(1e-9));
    p.model = TRK_SPRT_HMM;
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&p.hmm, 2, &sp);
    p.hmm.events = TRK_EVENTS_PAPER;
    struct trk_sprt_model m;
    struct trk_sprt s;
    start(&m, &s, &p);
    const int d[16] = {1, 1, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0, 0, 0, 1, 1};
    int d0[8], d1[8];
    double lf0 = 0;
    for (int t = 0; t < 16; t++) {
        const double pfa = 0.04 + 0.005 * t;
        TRK_ASSERT_OK(step(&m, &s, (unsigned)(t % 2), d[t], (trk_real)pfa));
        const double pf = (double)(trk_real)pfa;
        lf0 += d[t] ? log(pf) : log1p(-pf);
        if (t % 2) d1[t / 2] = d[t];
        else d0[t / 2] = d[t];
    }
    const double pp = 0.1 / 3, q = 0.1;
    const double lf1 = brute_log_lik(8, d0, pp, q, 0.1, 0.9, pp / (pp + q)) +
                       brute_log_lik(8, d1, pp, q, 0.1, 0.9, pp / (pp + q));
    TRK_ASSERT_NEAR(s.stat, lf1 - lf0, 0, TRK_TOL(1e-13, 1e-5));
    TRK_ASSERT_STATUS(step(&m, &s, 2, 1, TRK_REAL_C(0.1)), TRK_E_SENSOR);
#else
    skip();
#endif
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_sprt_model m, mbefore;
    memset(&m, 0x11, sizeof m);
    mbefore = m;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.6), TRK_REAL_C(0.4));
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_RANGE); /* alpha + beta >= 1 */
    p = fixed(TRK_REAL_C(0.8), 0, TRK_REAL_C(0.1));
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_RANGE);
    p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.1), 1);
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_RANGE);
    p = fixed(1, TRK_REAL_C(0.1), TRK_REAL_C(0.1));
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_RANGE);
    p = fixed((trk_real)NAN, TRK_REAL_C(0.1), TRK_REAL_C(0.1));
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_NAN);
    p = fixed(TRK_REAL_C(0.8), (trk_real)NAN, TRK_REAL_C(0.1));
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_NAN);
    p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.1), TRK_REAL_C(0.1));
    p.model = (enum trk_sprt_pd_model)7;
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_ARG);
    p.model = TRK_SPRT_HMM; /* hmm left zeroed: no sensors */
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_sprt_model_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, NULL), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m); /* never half-initialised */
    struct trk_sprt s, before;
    p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.1), TRK_REAL_C(0.1));
    start(&m, &s, &p);
    before = s;
    mbefore = m;
    TRK_ASSERT_STATUS(step(&m, &s, 0, 1, 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(step(&m, &s, 0, 0, (trk_real)INFINITY), TRK_E_NAN);
    TRK_ASSERT_STATUS(step(&m, &s, 0, 2, TRK_REAL_C(0.1)), TRK_E_RANGE); /* detected 0 or 1 */
    TRK_ASSERT_STATUS(step(&m, &s, 0, -1, TRK_REAL_C(0.1)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(step_llr(&m, &s, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(step_llr(&m, &s, (trk_real)INFINITY), TRK_E_NAN);
    TRK_ASSERT_STATUS(step(NULL, &s, 0, 1, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step(&m, NULL, 0, 1, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(NULL, &s, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(&m, NULL, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_sprt_step(&m, &s, 0, 1, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_sprt_step_llr(&m, &s, 1, NULL), TRK_E_ARG);
    trk_sprt_reset(NULL, &s); /* no-op */
    assert_memory_equal(&s, &before, sizeof s);
    assert_memory_equal(&m, &mbefore, sizeof m);
}

/* Every field of two states bit for bit (not memcmp: padding). */
static void assert_same_state(const struct trk_sprt *x, const struct trk_sprt *y)
{
    assert_memory_equal(x->hmm.post_high, y->hmm.post_high, sizeof x->hmm.post_high);
    assert_memory_equal(x->hmm.n_looks, y->hmm.n_looks, sizeof x->hmm.n_looks);
    assert_memory_equal(&x->stat, &y->stat, sizeof x->stat);
    assert_memory_equal(&x->inc, &y->inc, sizeof x->inc);
    assert_int_equal(x->t, y->t);
    assert_int_equal(x->fire, y->fire);
    assert_int_equal(x->decision, y->decision);
}

/* One HMM model shared by several tracks: each track's per-sensor posteriors
 * are its own (same result as a private model), and the model is not
 * written by stepping. */
static void test_shared_model(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.5), TRK_REAL_C(0.01), TRK_REAL_C(0.1));
    p.model = TRK_SPRT_HMM;
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&p.hmm, TRK_MAX_SENSORS >= 2 ? 2 : 1, &sp);
    struct trk_sprt_model shared, own[2], copy;
    struct trk_sprt s[2], r[2];
    TRK_ASSERT_OK(trk_sprt_model_init(&shared, &p));
    copy = shared;
    for (int k = 0; k < 2; k++) {
        start(&own[k], &r[k], &p);
        trk_sprt_reset(&shared, &s[k]);
    }
    for (int t = 0; t < 30; t++)
        for (int k = 0; k < 2; k++) {
            const unsigned sensor = (unsigned)(t % p.hmm.n_sensors);
            const int det = k == 0 ? t % 3 != 0 : 0; /* track 1: misses only */
            TRK_ASSERT_OK(step(&shared, &s[k], sensor, det, TRK_REAL_C(0.05)));
            TRK_ASSERT_OK(step(&own[k], &r[k], sensor, det, TRK_REAL_C(0.05)));
            assert_same_state(&s[k], &r[k]);
        }
    assert_memory_equal(&shared, &copy, sizeof shared);
    assert_int_equal(s[0].decision, TRK_DECISION_CONFIRM);
    assert_int_equal(s[1].decision, TRK_DECISION_TERMINATE);
}

static void test_long_runs(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.9), TRK_REAL_C(0.01), TRK_REAL_C(0.01));
    struct trk_sprt_model m;
    struct trk_sprt s;
    TRK_ASSERT_OK(trk_sprt_model_init(&m, &p));
    for (int det = 0; det < 2; det++) {
        trk_sprt_reset(&m, &s);
        for (long t = 0; t < 1000000; t++) TRK_ASSERT_OK(step(&m, &s, 0, det, TRK_REAL_C(1e-7)));
        assert_true(isfinite((double)s.stat));
        assert_int_equal(s.decision, det ? TRK_DECISION_CONFIRM : TRK_DECISION_TERMINATE);
        assert_true(det ? s.stat > 1e6 : s.stat < -1e6);
    }
}

/* Complete event model with fixed P_D = 0.8 (the default; docs/conventions.md
 * "Complete detection-event model"): hit ln f1 = ln(1 - (1-P_D)(1-P_FA)),
 * miss ln f1 = ln(1-P_D) + ln(1-P_FA), so a miss adds ln(1-P_D) whatever
 * the gate (pfa near 1 included). */
static void test_fixed_pd_complete(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.01), TRK_REAL_C(0.1));
    struct trk_sprt_model m;
    struct trk_sprt s;
    start(&m, &s, &p);
    assert_int_equal(m.events, TRK_EVENTS_COMPLETE);
    const trk_real pfas[6] = {TRK_REAL_C(1e-4), TRK_REAL_C(0.05), TRK_REAL_C(0.5), TRK_REAL_C(0.95),
                              TRK_REAL_C(0.999), 1 - (trk_real)TRK_TOL(1e-12, 1e-6)};
    const int d[12] = {0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 1, 0};
    const double pd = (double)TRK_REAL_C(0.8);
    double llr = 0;
    for (int t = 0; t < 12; t++) {
        const trk_real pfa = pfas[t % 6];
        const double f = (double)pfa;
        TRK_ASSERT_OK(step(&m, &s, 0, d[t], pfa));
        const double inc = d[t] ? log1p(-(1 - pd) * (1 - f)) - log(f) : log1p(-pd);
        /* a miss near pfa = 1: |ln(1-pfa)| ~ 27.6 (float 13.8) cancels */
        TRK_ASSERT_NEAR(s.inc, inc, TRK_TOL(1e-13, 4e-6), TRK_TOL(1e-14, 1e-6));
        llr += inc;
        TRK_ASSERT_NEAR(s.stat, llr, TRK_TOL(1e-13, 1e-5), TRK_TOL(1e-14, 1e-6));
    }
    /* a hit at pfa near 1 says almost nothing: ln(1 - 0.2 eps) - ln(1 - eps) ~ 0.8 eps */
    trk_sprt_reset(&m, &s);
    const trk_real near1 = pfas[5];
    const double eps = 1 - (double)near1;
    TRK_ASSERT_OK(step(&m, &s, 0, 1, near1));
    TRK_ASSERT_NEAR(s.inc, log1p(-0.2 * eps) - log1p(-eps), 0, TRK_TOL(1e-12, 1e-3));
}

/* The event model of a fixed-P_D SPRT is hmm.events; the rest of hmm is
 * ignored (here left invalid). An unknown events value is TRK_E_ARG for
 * both P_D models. */
static void test_events_selection(void **state)
{
    (void)state;
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.8), TRK_REAL_C(0.01), TRK_REAL_C(0.1));
    p.hmm.n_sensors = 0;                         /* ignored with fixed P_D */
    p.hmm.sensor[0].pd_low = (trk_real)NAN;
    p.hmm.events = TRK_EVENTS_PAPER;
    struct trk_sprt_model m, mbefore;
    struct trk_sprt s;
    start(&m, &s, &p);
    assert_int_equal(m.events, TRK_EVENTS_PAPER);
    TRK_ASSERT_OK(step(&m, &s, 0, 0, TRK_REAL_C(0.5)));
    TRK_ASSERT_NEAR(s.inc, log1p(-(double)TRK_REAL_C(0.8)) - log(0.5), 0, TRK_TOL(1e-15, 1e-6));
    memset(&m, 0x2d, sizeof m);
    mbefore = m;
    p.hmm.events = (enum trk_event_model)2;
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_ARG);
    p.model = TRK_SPRT_HMM;
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&p.hmm, 1, &sp);
    p.hmm.events = (enum trk_event_model)-3;
    TRK_ASSERT_STATUS(trk_sprt_model_init(&m, &p), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m);
    p.hmm.events = TRK_EVENTS_PAPER;
    TRK_ASSERT_OK(trk_sprt_model_init(&m, &p));
    assert_int_equal(m.events, TRK_EVENTS_PAPER);
    assert_int_equal(m.hmm.events, TRK_EVENTS_PAPER);
}

/* HMM, complete event model: llr = ln P(d | H1) - ln P(d | H0) with
 * P(miss | u) = (1 - Pd_u)(1 - pfa_t) under H1, by enumeration. */
static void test_hmm_complete_vs_enumeration(void **state)
{
    (void)state;
#if TRK_MAX_SENSORS >= 2
    struct trk_sprt_params p = fixed(TRK_REAL_C(0.5), TRK_REAL_C(1e-9), TRK_REAL_C(1e-9));
    p.model = TRK_SPRT_HMM;
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&p.hmm, 2, &sp);
    struct trk_sprt_model m;
    struct trk_sprt s;
    start(&m, &s, &p);
    const int d[16] = {1, 1, 0, 1, 0, 0, 1, 1, 1, 0, 1, 0, 0, 0, 1, 1};
    int d0[8], d1[8];
    double f0[8], f1[8], lf0 = 0;
    for (int t = 0; t < 16; t++) {
        const trk_real pfa = (trk_real)(0.04 + 0.05 * t); /* up to 0.79 */
        TRK_ASSERT_OK(step(&m, &s, (unsigned)(t % 2), d[t], pfa));
        const double pf = (double)pfa;
        lf0 += d[t] ? log(pf) : log1p(-pf);
        if (t % 2) d1[t / 2] = d[t], f1[t / 2] = pf;
        else d0[t / 2] = d[t], f0[t / 2] = pf;
    }
    const double pp = 0.1 / 3, q = 0.1;
    const double lik = brute_log_lik_events(8, d0, f0, pp, q, 0.1, 0.9, pp / (pp + q)) +
                       brute_log_lik_events(8, d1, f1, pp, q, 0.1, 0.9, pp / (pp + q));
    TRK_ASSERT_NEAR(s.stat, lik - lf0, 0, TRK_TOL(1e-13, 1e-5));
#else
    skip();
#endif
}

/* Empty gates of a growing size (pfa 0.9, fixed P_D 0.5): the paper's miss
 * adds ln(0.5 / 0.1) = +1.61 and confirms a track that never had a
 * detection; the complete model's adds ln 0.5 and rejects it. */
static void test_empty_large_gates(void **state)
{
    (void)state;
    for (int complete = 0; complete < 2; complete++) {
        struct trk_sprt_params p = fixed(TRK_REAL_C(0.5), TRK_REAL_C(0.01), TRK_REAL_C(0.1));
        p.hmm.events = complete ? TRK_EVENTS_COMPLETE : TRK_EVENTS_PAPER;
        struct trk_sprt_model m;
        struct trk_sprt s;
        start(&m, &s, &p);
        for (int t = 0; t < 10; t++) TRK_ASSERT_OK(step(&m, &s, 0, 0, TRK_REAL_C(0.9)));
        assert_int_equal(s.decision, complete ? TRK_DECISION_TERMINATE : TRK_DECISION_CONFIRM);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fixed_pd),
        cmocka_unit_test(test_ties_and_sticky),
        cmocka_unit_test(test_hmm_vs_enumeration),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_shared_model),
        cmocka_unit_test(test_long_runs),
        cmocka_unit_test(test_fixed_pd_complete),
        cmocka_unit_test(test_events_selection),
        cmocka_unit_test(test_hmm_complete_vs_enumeration),
        cmocka_unit_test(test_empty_large_gates),
    };
    return trk_run_tests("confirm_sprt", tests, NULL, NULL);
}
