/* test_term_shiryaev.c - Shiryaev termination (Blanding eqs 11-14): the log
 * recursion against the probability form (eq 12) where that is accurate,
 * rho = 0, strict threshold and sticky decision, runs past exp's overflow and
 * underflow limits, bad input. */
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vs_probability_form),
        cmocka_unit_test(test_rho_zero_and_strict),
        cmocka_unit_test(test_long_runs),
        cmocka_unit_test(test_bad_input),
    };
    return trk_run_tests("term_shiryaev", tests, NULL, NULL);
}
