/* test_hmm_detect.c - two-state Markov detection model (Blanding eqs 7-10):
 * predictive likelihoods against brute-force enumeration (Willett eq 53),
 * priors, per-sensor independence, accuracy near 1, bad parameters. */
#include "trk_test.h"
#include "hmm_brute.h"
#include "trk/hmm_detect.h"

static const struct trk_hmm_sensor_params blanding = {
    TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1), TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};

/* The product of the predictive likelihoods f1 of eq 8 is the joint
 * likelihood of eq 53: sum_t ln f1_t = ln P(d_1..n | H1). */
static void test_chain_rule_vs_enumeration(void **state)
{
    (void)state;
    const int d[14] = {1, 0, 0, 1, 1, 1, 0, 0, 0, 0, 1, 0, 1, 1};
    const double p = 0.1 / 3, q = 0.1, pl = 0.1, ph = 0.9;
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, 1, &blanding);
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    double sum = 0;
    for (int t = 0; t < 14; t++) {
        trk_real lf1;
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, d[t], &lf1));
        sum += (double)lf1;
        /* prefix likelihoods agree at every step */
        TRK_ASSERT_NEAR(sum, brute_log_lik(t + 1, d, p, q, pl, ph, p / (p + q)), 0,
                        TRK_TOL(1e-13, 1e-5));
    }
    assert_int_equal(h.n_looks[0], 14);
}

/* Two sensors interleaved: each keeps its own chain (one transition per look
 * of that sensor), so the total is the sum of the per-sensor enumerations. */
static void test_two_sensors_independent(void **state)
{
    (void)state;
#if TRK_MAX_SENSORS >= 2
    const int sensor[12] = {0, 1, 1, 0, 1, 0, 0, 1, 1, 1, 0, 0};
    const int d[12] = {1, 0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 1};
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, 2, &blanding);
    hp.sensor[1].pd_low = TRK_REAL_C(0.3); /* sensors may differ */
    hp.sensor[1].pi0_high = TRK_REAL_C(0.6);
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    int d0[12], d1[12], n0 = 0, n1 = 0;
    double sum = 0;
    for (int t = 0; t < 12; t++) {
        trk_real lf1;
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, (unsigned)sensor[t], d[t], &lf1));
        sum += (double)lf1;
        if (sensor[t]) d1[n1++] = d[t];
        else d0[n0++] = d[t];
    }
    const double p = 0.1 / 3, q = 0.1;
    const double want = brute_log_lik(n0, d0, p, q, 0.1, 0.9, p / (p + q)) +
                        brute_log_lik(n1, d1, p, q, (double)TRK_REAL_C(0.3), 0.9, (double)TRK_REAL_C(0.6));
    TRK_ASSERT_NEAR(sum, want, 0, TRK_TOL(1e-13, 1e-5));
#else
    skip();
#endif
}

static void test_priors(void **state)
{
    (void)state;
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, 1, &blanding);
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    /* stationary p/(p+q) = 0.25 (eq 2) */
    TRK_ASSERT_NEAR(trk_hmm_prior_high(&m, &h, 0), 0.25, 0, TRK_TOL(1e-15, 1e-6));
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 1, &lf1));
    /* f1 = 0.25*0.9 + 0.75*0.1 = 0.3, post = 0.225/0.3 = 0.75, next prior 0.75*0.9 + 0.25/30 */
    TRK_ASSERT_NEAR(lf1, log(0.3), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(h.post_high[0], 0.75, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(trk_hmm_prior_high(&m, &h, 0), 0.75 * 0.9 + 0.25 / 30, 0, TRK_TOL(1e-15, 1e-6));
    /* reset returns to the first-look prior */
    trk_hmm_state_reset(&m, &h);
    TRK_ASSERT_NEAR(trk_hmm_prior_high(&m, &h, 0), 0.25, 0, TRK_TOL(1e-15, 1e-6));
    assert_true(isnan((double)trk_hmm_prior_high(&m, &h, TRK_MAX_SENSORS)));
    assert_true(isnan((double)trk_hmm_prior_high(&m, &h, 1))); /* n_sensors = 1 */
    assert_true(isnan((double)trk_hmm_prior_high(NULL, &h, 0)));
    assert_true(isnan((double)trk_hmm_prior_high(&m, NULL, 0)));
    /* p = q = 0 with an explicit prior: static mixture */
    struct trk_hmm_sensor_params st = {0, 0, TRK_REAL_C(0.2), TRK_REAL_C(0.7), TRK_REAL_C(0.3)};
    trk_hmm_params_uniform(&hp, 1, &st);
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 0, &lf1));
    TRK_ASSERT_NEAR(lf1, log(0.3 * 0.3 + 0.7 * 0.8), 0, TRK_TOL(1e-15, 1e-6));
}

/* ln f1 near 1 without cancellation: a miss with P_D = 1e-9 has
 * ln f1 = log1p(-1e-9); fixed P_D (pd_low = pd_high) gives ln P_D. */
static void test_accuracy_near_one(void **state)
{
    (void)state;
    struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1), TRK_REAL_C(0.2), TRK_REAL_C(1e-9),
                                       TRK_REAL_C(3e-9), TRK_REAL_C(0.5)};
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, 1, &sp);
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 0, &lf1));
    TRK_ASSERT_NEAR(lf1, log1p(-(0.5 * (double)TRK_REAL_C(1e-9) + 0.5 * (double)TRK_REAL_C(3e-9))), 0,
                    TRK_TOL(1e-14, 1e-6));
    struct trk_hmm_sensor_params fx = {TRK_REAL_C(0.3), TRK_REAL_C(0.3), TRK_REAL_C(0.8),
                                       TRK_REAL_C(0.8), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&hp, 1, &fx);
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    for (int t = 0; t < 20; t++) {
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, t % 3 == 0, &lf1));
        TRK_ASSERT_NEAR(lf1, t % 3 == 0 ? log((double)TRK_REAL_C(0.8)) : log1p(-(double)TRK_REAL_C(0.8)),
                        0, TRK_TOL(1e-15, 1e-6));
    }
    trk_real lf0;
    TRK_ASSERT_OK(trk_hmm_log_f0(0, TRK_REAL_C(1e-12), &lf0));
    TRK_ASSERT_NEAR(lf0, log1p(-(double)TRK_REAL_C(1e-12)), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_OK(trk_hmm_log_f0(1, TRK_REAL_C(0.25), &lf0));
    TRK_ASSERT_NEAR(lf0, log(0.25), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(trk_hmm_gate_pfa(TRK_REAL_C(1e-10)), -expm1(-(double)TRK_REAL_C(1e-10)), 0, TRK_TOL(1e-15, 1e-6));
}

static void test_bad_params(void **state)
{
    (void)state;
    struct trk_hmm_params hp;
    struct trk_hmm_model m, mbefore;
    memset(&m, 0x5a, sizeof m);
    mbefore = m;
    const trk_real bad_prob[] = {0, 1, -TRK_REAL_C(0.1), TRK_REAL_C(1.5)};
    for (int i = 0; i < 4; i++) {
        trk_hmm_params_uniform(&hp, 1, &blanding);
        hp.sensor[0].pd_low = bad_prob[i];
        TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
        trk_hmm_params_uniform(&hp, 1, &blanding);
        hp.sensor[0].pd_high = bad_prob[i];
        TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    }
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].p_low_high = TRK_REAL_C(1.01);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].q_high_low = -TRK_REAL_C(0.01);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].pi0_high = TRK_REAL_C(1.2);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].p_low_high = 0;
    hp.sensor[0].q_high_low = 0; /* stationary prior undefined */
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].pd_high = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_NAN);
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.sensor[0].q_high_low = (trk_real)INFINITY;
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_NAN);
    trk_hmm_params_uniform(&hp, 0, &blanding);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_RANGE);
    trk_hmm_params_uniform(&hp, TRK_MAX_SENSORS + 1, &blanding);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_hmm_model_init(NULL, &hp), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, NULL), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m); /* never half-initialised */
    /* bad look: state and model untouched */
    trk_hmm_params_uniform(&hp, 1, &blanding);
    struct trk_hmm_state h, before;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    trk_real lf1 = 0, lf0 = 0;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 1, &lf1));
    before = h;
    mbefore = m;
    TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 1, 1, &lf1), TRK_E_SENSOR);
    TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, 1, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_hmm_update(NULL, &h, 0, 1, &lf1), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_hmm_update(&m, NULL, 0, 1, &lf1), TRK_E_ARG);
    trk_hmm_state_reset(NULL, &h); /* no-op */
    assert_memory_equal(&h, &before, sizeof h);
    assert_memory_equal(&m, &mbefore, sizeof m);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(1, 0, &lf0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(1, 1, &lf0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(0, (trk_real)NAN, &lf0), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(0, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_rule_vs_enumeration),
        cmocka_unit_test(test_two_sensors_independent),
        cmocka_unit_test(test_priors),
        cmocka_unit_test(test_accuracy_near_one),
        cmocka_unit_test(test_bad_params),
    };
    return trk_run_tests("hmm_detect", tests, NULL, NULL);
}
