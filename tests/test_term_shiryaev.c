/* test_term_shiryaev.c - Shiryaev termination (Blanding eqs 11-14): the log
 * recursion against the probability form (eq 12) where that is accurate,
 * rho = 0, strict threshold and sticky decision, runs past exp's overflow and
 * underflow limits, bad input, closed forms of the paper's and the complete
 * event model (docs/conventions.md "Complete detection-event model") and the
 * coasting track that only the complete model terminates. */
#include "trk_test.h"
#include "trk/term_shiryaev.h"

/* The steps through the decision output: on success the decision written
 * must be the state's sticky one; on error *decision stays as it was. */
#define UNWRITTEN ((enum trk_decision)77)
static trk_status step(const struct trk_shiryaev_model *m, struct trk_shiryaev *s, unsigned sensor,
                       int detected, trk_real pfa)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_shiryaev_step(m, s, sensor, detected, pfa, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}
static trk_status step_llr(const struct trk_shiryaev_model *m, struct trk_shiryaev *s, trk_real inc)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_shiryaev_step_llr(m, s, inc, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}

/* Blanding's HMM, complete event model (the default). */
static struct trk_shiryaev_params params(trk_real beta0, trk_real rho, trk_real h)
{
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    struct trk_shiryaev_params p;
    trk_hmm_params_uniform(&p.hmm, 1, &sp);
    p.beta0 = beta0;
    p.rho = rho;
    p.h = h;
    return p;
}

/* Build the shared model and start one track's state with it. */
static void start(struct trk_shiryaev_model *m, struct trk_shiryaev *s,
                  const struct trk_shiryaev_params *p)
{
    TRK_ASSERT_OK(trk_shiryaev_model_init(m, p));
    trk_shiryaev_reset(m, s);
}

/* eq 12 in probabilities, with f0/f1 = e^s from the library's increments:
 * beta_k = [b + (1-b) rho] f0 / ([b + (1-b) rho] f0 + (1-b)(1-rho) f1). */
static void test_vs_probability_form(void **state)
{
    (void)state;
    struct trk_shiryaev_params p = params(TRK_REAL_C(0.3), TRK_REAL_C(0.02), 100);
    struct trk_shiryaev_model m;
    struct trk_shiryaev sh;
    start(&m, &sh, &p);
    const double rho = (double)TRK_REAL_C(0.02);
    double beta = (double)TRK_REAL_C(0.3);
    TRK_ASSERT_NEAR(sh.stat, log(beta / (1 - beta)), 0, TRK_TOL(1e-15, 1e-6));
    const int d[20] = {1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
    for (int t = 0; t < 20; t++) {
        TRK_ASSERT_OK(step(&m, &sh, 0, d[t], TRK_REAL_C(0.08)));
        const double ratio = exp((double)sh.s); /* f0 / f1 */
        const double num = (beta + (1 - beta) * rho) * ratio;
        beta = num / (num + (1 - beta) * (1 - rho));
        assert_true(beta > 1e-6 && beta < 1 - 1e-6); /* where eq 12 keeps its digits */
        TRK_ASSERT_NEAR(sh.stat, log(beta / (1 - beta)), 1e-12, TRK_TOL(1e-12, 1e-5));
    }
}

static void test_rho_zero_and_strict(void **state)
{
    (void)state;
    struct trk_shiryaev_params p = params(TRK_REAL_C(0.5), 0, TRK_REAL_C(1.5));
    struct trk_shiryaev_model m;
    struct trk_shiryaev sh;
    start(&m, &sh, &p);
    assert_true(sh.stat == 0); /* logit 0.5 */
    for (int i = 0; i < 3; i++) TRK_ASSERT_OK(step_llr(&m, &sh, TRK_REAL_C(0.5)));
    assert_true(sh.stat == TRK_REAL_C(1.5)); /* rho = 0: g += s exactly; g == h does not fire */
    assert_int_equal(sh.fire, 0);
    TRK_ASSERT_OK(step_llr(&m, &sh, TRK_REAL_C(0.25)));
    assert_int_equal(sh.fire, 1);
    TRK_ASSERT_OK(step_llr(&m, &sh, -5));
    assert_int_equal(sh.fire, 0);
    assert_int_equal(sh.decision, TRK_DECISION_TERMINATE); /* sticky, no reset of g */
    TRK_ASSERT_NEAR(sh.stat, -3.25, 0, TRK_TOL(1e-15, 1e-6));
    trk_shiryaev_reset(&m, &sh);
    assert_true(sh.stat == 0 && sh.decision == TRK_DECISION_CONTINUE && sh.t == 0);
    /* reset starts at the model's g_0 = logit(beta0) */
    struct trk_shiryaev_model m2;
    p.beta0 = TRK_REAL_C(0.2);
    TRK_ASSERT_OK(trk_shiryaev_model_init(&m2, &p));
    trk_shiryaev_reset(&m2, &sh);
    TRK_ASSERT_NEAR(sh.stat, log(0.2 / 0.8), 0, TRK_TOL(1e-15, 1e-6));
    assert_true(sh.stat == m2.g0);
    /* negative and zero thresholds are valid log-odds thresholds */
    p.h = -2;
    TRK_ASSERT_OK(trk_shiryaev_model_init(&m, &p));
    p.h = 0;
    TRK_ASSERT_OK(trk_shiryaev_model_init(&m, &p));
}

/* g passes +709 (exp overflows) on misses against tiny P_FA, and falls below
 * -745 (exp underflows) on detections with rho = 0; 10^6 looks each. With
 * rho > 0, g never falls below ln(rho/(1-rho)) + min s. */
static void test_long_runs(void **state)
{
    (void)state;
    struct trk_shiryaev_model m;
    struct trk_shiryaev sh;
    struct trk_shiryaev_params p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), 5);
    start(&m, &sh, &p);
    for (long t = 0; t < 1000000; t++) TRK_ASSERT_OK(step(&m, &sh, 0, 0, TRK_REAL_C(1e-6)));
    assert_true(isfinite((double)sh.stat) && sh.stat > 1e4);
    assert_int_equal(sh.decision, TRK_DECISION_TERMINATE);
    p = params(TRK_REAL_C(0.5), 0, 5);
    start(&m, &sh, &p);
    for (long t = 0; t < 1000000; t++) TRK_ASSERT_OK(step(&m, &sh, 0, 1, TRK_REAL_C(1e-6)));
    assert_true(isfinite((double)sh.stat) && sh.stat < -1e6);
    assert_int_equal(sh.decision, TRK_DECISION_CONTINUE);
    p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), 5);
    start(&m, &sh, &p);
    for (long t = 0; t < 1000000; t++) TRK_ASSERT_OK(step(&m, &sh, 0, 1, TRK_REAL_C(1e-6)));
    /* s >= ln P_FA (f1 <= 1): g >= ln rho - ln(1 - rho) + ln 1e-6 */
    assert_true(isfinite((double)sh.stat) && sh.stat > log(0.005 / 0.995) + log(1e-6) - 1e-3);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_shiryaev_model m, mbefore;
    memset(&m, 0x77, sizeof m);
    mbefore = m;
    struct trk_shiryaev_params p = params(0, TRK_REAL_C(0.005), 1);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_RANGE);
    p = params(1, TRK_REAL_C(0.005), 1);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_RANGE);
    p = params(TRK_REAL_C(0.5), 1, 1);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_RANGE);
    p = params(TRK_REAL_C(0.5), -TRK_REAL_C(0.1), 1);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_RANGE);
    p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), (trk_real)NAN);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_NAN);
    p = params((trk_real)NAN, TRK_REAL_C(0.005), 1);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_NAN);
    p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), 1);
    p.hmm.sensor[0].pd_low = 0;
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, NULL), TRK_E_ARG);
    p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), 1);
    p.hmm.events = (enum trk_event_model)3; /* unknown event model */
    TRK_ASSERT_STATUS(trk_shiryaev_model_init(&m, &p), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m); /* never half-initialised */
    struct trk_shiryaev sh, before;
    p = params(TRK_REAL_C(0.5), TRK_REAL_C(0.005), 1);
    start(&m, &sh, &p);
    before = sh;
    mbefore = m;
    TRK_ASSERT_STATUS(step(&m, &sh, 0, 0, TRK_REAL_C(1.5)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(step(&m, &sh, 2, 0, TRK_REAL_C(0.1)), TRK_E_SENSOR);
    TRK_ASSERT_STATUS(step_llr(&m, &sh, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(step(NULL, &sh, 0, 0, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step(&m, NULL, 0, 0, TRK_REAL_C(0.1)), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(NULL, &sh, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(step_llr(&m, NULL, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(step(&m, &sh, 0, 3, TRK_REAL_C(0.1)), TRK_E_RANGE); /* detected 0 or 1 */
    TRK_ASSERT_STATUS(trk_shiryaev_step(&m, &sh, 0, 0, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_shiryaev_step_llr(&m, &sh, 1, NULL), TRK_E_ARG);
    trk_shiryaev_reset(NULL, &sh); /* no-op */
    assert_memory_equal(&sh, &before, sizeof sh);
    assert_memory_equal(&m, &mbefore, sizeof m);
}

/* Fixed P_D = 0.7 in both event models (docs/conventions.md "Complete
 * detection-event model"): paper s = ln(pfa / pd) on a hit, ln((1-pfa) /
 * (1-pd)) on a miss; complete s = ln pfa - ln(1 - (1-pd)(1-pfa)) on a hit,
 * -ln(1-pd) on a miss (pfa near 1 included), and
 * g = logaddexp(ln rho, g) - ln(1 - rho) + s. */
static void test_fixed_pd_both_forms(void **state)
{
    (void)state;
    const trk_real pfas[5] = {TRK_REAL_C(0.01), TRK_REAL_C(0.2), TRK_REAL_C(0.7), TRK_REAL_C(0.99),
                              1 - (trk_real)TRK_TOL(1e-12, 1e-6)};
    const int d[15] = {1, 0, 1, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0};
    const double pd = (double)TRK_REAL_C(0.7), rho = (double)TRK_REAL_C(0.02);
    for (int complete = 0; complete < 2; complete++) {
        struct trk_shiryaev_params p = params(TRK_REAL_C(0.1), TRK_REAL_C(0.02), 1000);
        p.hmm.sensor[0].pd_low = p.hmm.sensor[0].pd_high = TRK_REAL_C(0.7);
        p.hmm.events = complete ? TRK_EVENTS_COMPLETE : TRK_EVENTS_PAPER;
        struct trk_shiryaev_model m;
        struct trk_shiryaev sh;
        start(&m, &sh, &p);
        double g = log((double)TRK_REAL_C(0.1) / (1 - (double)TRK_REAL_C(0.1)));
        for (int t = 0; t < 15; t++) {
            const trk_real pfa = pfas[t % 5];
            const double f = (double)pfa;
            TRK_ASSERT_OK(step(&m, &sh, 0, d[t], pfa));
            double s;
            if (complete) s = d[t] ? log(f) - log1p(-(1 - pd) * (1 - f)) : -log1p(-pd);
            else s = d[t] ? log(f / pd) : log1p(-f) - log1p(-pd);
            TRK_ASSERT_NEAR(sh.s, s, TRK_TOL(1e-13, 4e-6), TRK_TOL(1e-14, 1e-6));
            if (complete && !d[t]) assert_true(sh.s > 0);
            const double hi = g > log(rho) ? g : log(rho), lo = g > log(rho) ? log(rho) : g;
            g = hi + log1p(exp(lo - hi)) - log1p(-rho) + s;
            TRK_ASSERT_NEAR(sh.stat, g, TRK_TOL(1e-13, 2e-5), TRK_TOL(1e-13, 1e-6));
        }
    }
}

/* The coasting track of the complete event model (see test_term_page.c,
 * test_coasting_track_terminates, for the scenario and pfa_k): fading HMM
 * (pd_high 0.9, pd_low 0.1, p = 0.1, q = 0.02), 12 hits at pfa 1e-3, then
 * 40 misses with lambda V_k = 0.2 .. 41; Shiryaev beta0 = rho = 0.01,
 * h = ln 99 (posterior 0.99). */
#define COAST_HITS 12
#define COAST_LOOKS 40
static trk_real coast_pfa(int k, int *rounds_to_one)
{
    const double lv = 0.2 + (41 - 0.2) * k / (COAST_LOOKS - 1);
    const trk_real pfa = (trk_real)-expm1(-lv);
    *rounds_to_one = pfa >= 1;
    return pfa < 1 ? pfa : (TRK_TEST_IS_FLOAT ? (trk_real)nextafterf(1, 0) : (trk_real)nextafter(1, 0));
}

/* Complete: g_t >= g_{t-1} + s_t (logaddexp(ln rho, g) >= g, -ln(1-rho) >
 * 0) and every miss adds s = -ln M >= -ln 0.82 = 0.198 (prior P(u=1) >=
 * min(p, 1-q) = 0.1). The hits leave g near ln(rho/(1-rho)) + ln(pfa/f1) =
 * -11.4; the first four misses (2.14, 1.45, 0.56, 0.26) bring it to -0.01
 * > -0.05, so g > ln 99 = 4.595 after at most 4 + ceil((4.595 + 0.05) /
 * 0.198) = 28 misses (computed: the 25th; the slow part is the chain
 * settling at P(u=1) ~ 0.11 under misses, where a miss says little: s =
 * -ln 0.81). Paper: s = -lambda V_k - ln M, negative from the third miss
 * on: g peaks at -2.31 and the track is never terminated. */
static void test_coasting_track_terminates(void **state)
{
    (void)state;
    const struct trk_hmm_sensor_params fading = {TRK_REAL_C(0.1), TRK_REAL_C(0.02), TRK_REAL_C(0.1),
                                                 TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    for (int complete = 0; complete < 2; complete++) {
        struct trk_shiryaev_params p;
        trk_hmm_params_uniform(&p.hmm, 1, &fading);
        p.hmm.events = complete ? TRK_EVENTS_COMPLETE : TRK_EVENTS_PAPER;
        p.beta0 = TRK_REAL_C(0.01);
        p.rho = TRK_REAL_C(0.01);
        p.h = (trk_real)log(99.0);
        struct trk_shiryaev_model m;
        struct trk_shiryaev sh, before;
        start(&m, &sh, &p);
        for (int t = 0; t < COAST_HITS; t++) TRK_ASSERT_OK(step(&m, &sh, 0, 1, TRK_REAL_C(1e-3)));
        assert_true(sh.stat < -11 && sh.decision == TRK_DECISION_CONTINUE);
        int fired = 0;
        double g4 = 0, gmax = -1e300;
        for (int k = 0; k < COAST_LOOKS; k++) {
            int one;
            const trk_real pfa = coast_pfa(k, &one);
            if (one) { /* pfa = 1 is refused and changes nothing */
                before = sh;
                TRK_ASSERT_STATUS(step(&m, &sh, 0, 0, 1), TRK_E_RANGE);
                assert_memory_equal(&sh.stat, &before.stat, sizeof sh.stat);
                assert_memory_equal(sh.hmm.post_high, before.hmm.post_high, sizeof sh.hmm.post_high);
                assert_int_equal(sh.t, before.t);
            }
            const double g_prev = (double)sh.stat;
            TRK_ASSERT_OK(step(&m, &sh, 0, 0, pfa));
            assert_true(isfinite((double)sh.s) && isfinite((double)sh.stat));
            if (complete) {
                assert_true(sh.s > 0.198);                       /* s >= -ln 0.82 */
                assert_true((double)sh.stat >= g_prev + (double)sh.s - 1e-5);
            } else if (k >= 2) {
                assert_true(sh.s < 0); /* the paper's flaw: the empty gate counts for the target */
            }
            if (k == 3) g4 = (double)sh.stat;
            if (sh.stat > gmax) gmax = (double)sh.stat;
            if (!fired && sh.decision == TRK_DECISION_TERMINATE) fired = k + 1;
        }
        if (complete) {
            assert_true(g4 > -0.05);
            assert_true(fired >= 1 && fired <= 28);
        } else {
            assert_int_equal(fired, 0); /* 40 empty, growing gates: not terminated */
            assert_int_equal(sh.decision, TRK_DECISION_CONTINUE);
            assert_true(gmax < -2.3);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vs_probability_form),
        cmocka_unit_test(test_rho_zero_and_strict),
        cmocka_unit_test(test_long_runs),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_fixed_pd_both_forms),
        cmocka_unit_test(test_coasting_track_terminates),
    };
    return trk_run_tests("term_shiryaev", tests, NULL, NULL);
}
