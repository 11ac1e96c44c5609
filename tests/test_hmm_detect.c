/* test_hmm_detect.c - two-state Markov detection model (Blanding eqs 7-10):
 * predictive likelihoods against brute-force enumeration (Willett eq 53)
 * for the paper's and the complete event model (docs/conventions.md "Complete
 * detection-event model"), closed forms of the complete model, the two
 * forms agreeing at pfa = 0, priors, per-sensor independence, accuracy near
 * 1, bad parameters. */
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
    hp.events = TRK_EVENTS_PAPER; /* eq 8 as printed: pfa plays no part */
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    double sum = 0;
    for (int t = 0; t < 14; t++) {
        trk_real lf1;
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, d[t], TRK_REAL_C(0.05) * (trk_real)t, &lf1));
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
    hp.events = TRK_EVENTS_PAPER;
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
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, (unsigned)sensor[t], d[t], TRK_REAL_C(0.2), &lf1));
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
    hp.events = TRK_EVENTS_PAPER;
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    /* stationary p/(p+q) = 0.25 (eq 2) */
    TRK_ASSERT_NEAR(trk_hmm_prior_high(&m, &h, 0), 0.25, 0, TRK_TOL(1e-15, 1e-6));
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 1, TRK_REAL_C(0.5), &lf1));
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
    hp.events = TRK_EVENTS_PAPER;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 0, TRK_REAL_C(0.5), &lf1));
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
    hp.events = TRK_EVENTS_PAPER;
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 0, TRK_REAL_C(0.5), &lf1));
    TRK_ASSERT_NEAR(lf1, log1p(-(0.5 * (double)TRK_REAL_C(1e-9) + 0.5 * (double)TRK_REAL_C(3e-9))), 0,
                    TRK_TOL(1e-14, 1e-6));
    struct trk_hmm_sensor_params fx = {TRK_REAL_C(0.3), TRK_REAL_C(0.3), TRK_REAL_C(0.8),
                                       TRK_REAL_C(0.8), TRK_HMM_PI0_STATIONARY};
    trk_hmm_params_uniform(&hp, 1, &fx);
    hp.events = TRK_EVENTS_PAPER;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    for (int t = 0; t < 20; t++) {
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, t % 3 == 0, TRK_REAL_C(0.5), &lf1));
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
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.events = (enum trk_event_model)2; /* neither COMPLETE nor PAPER */
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_ARG);
    hp.events = (enum trk_event_model)-1;
    TRK_ASSERT_STATUS(trk_hmm_model_init(&m, &hp), TRK_E_ARG);
    assert_memory_equal(&m, &mbefore, sizeof m); /* never half-initialised */
    /* bad look: state and model untouched */
    trk_hmm_params_uniform(&hp, 1, &blanding);
    struct trk_hmm_state h, before;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    trk_real lf1 = 0, lf0 = 0;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 1, TRK_REAL_C(0.1), &lf1));
    before = h;
    mbefore = m;
    const trk_real lf1_before = lf1;
    TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 1, 1, TRK_REAL_C(0.1), &lf1), TRK_E_SENSOR);
    TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, 1, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_hmm_update(NULL, &h, 0, 1, TRK_REAL_C(0.1), &lf1), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_hmm_update(&m, NULL, 0, 1, TRK_REAL_C(0.1), &lf1), TRK_E_ARG);
    /* complete model (the default): pfa in [0, 1) */
    assert_int_equal(m.events, TRK_EVENTS_COMPLETE);
    const trk_real bad_pfa[] = {1, TRK_REAL_C(1.5), -TRK_REAL_C(1e-30), -1};
    for (int i = 0; i < 4; i++)
        for (int det = 0; det < 2; det++)
            TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, det, bad_pfa[i], &lf1), TRK_E_RANGE);
    for (int det = 0; det < 2; det++) {
        TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, det, (trk_real)NAN, &lf1), TRK_E_NAN);
        TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, det, (trk_real)INFINITY, &lf1), TRK_E_NAN);
        TRK_ASSERT_STATUS(trk_hmm_update(&m, &h, 0, det, -(trk_real)INFINITY, &lf1), TRK_E_NAN);
    }
    assert_memory_equal(&lf1, &lf1_before, sizeof lf1);
    trk_hmm_state_reset(NULL, &h); /* no-op */
    assert_memory_equal(&h, &before, sizeof h);
    assert_memory_equal(&m, &mbefore, sizeof m);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(1, 0, &lf0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(1, 1, &lf0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(0, (trk_real)NAN, &lf0), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_hmm_log_f0(0, TRK_REAL_C(0.1), NULL), TRK_E_ARG);
}

/* ---------------------------------------------------------------- event models
 * docs/conventions.md "Complete detection-event model": under TRK_EVENTS_COMPLETE
 * (the default) e = 1 - (1-Pd)(1-pfa) for a hit, (1-Pd)(1-pfa) for a miss. */

/* Zeroed or uniform-filled parameters are the complete model; the model
 * carries the event model it was built with. */
static void test_default_is_complete(void **state)
{
    (void)state;
    struct trk_hmm_params hp;
    memset(&hp, 0, sizeof hp);
    assert_int_equal(hp.events, TRK_EVENTS_COMPLETE); /* zero = complete */
    hp.events = TRK_EVENTS_PAPER;
    trk_hmm_params_uniform(&hp, 1, &blanding);         /* fills events too */
    assert_int_equal(hp.events, TRK_EVENTS_COMPLETE);
    struct trk_hmm_model m;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    assert_int_equal(m.events, TRK_EVENTS_COMPLETE);
    hp.events = TRK_EVENTS_PAPER;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    assert_int_equal(m.events, TRK_EVENTS_PAPER);
}

/* One look from the first-look prior x: hit f1 = x e_H + (1-x) e_L with
 * e = 1 - (1-Pd)(1-pfa), post = x e_H / f1; miss f1 = (1-pfa) M with
 * M = x (1-pd_high) + (1-x)(1-pd_low), post = x (1-pd_high) / M. */
static void check_first_look(const struct trk_hmm_model *m, int det, trk_real pfa)
{
    struct trk_hmm_state h;
    trk_hmm_state_reset(m, &h);
    const double x = (double)trk_hmm_prior_high(m, &h, 0);
    const double pdh = (double)m->s[0].pd_high, pdl = (double)m->s[0].pd_low, f = (double)pfa;
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(m, &h, 0, det, pfa, &lf1));
    if (det) {
        const double eh = 1 - (1 - pdh) * (1 - f), el = 1 - (1 - pdl) * (1 - f);
        const double f1 = x * eh + (1 - x) * el;
        /* ln f1 from 1 - f1 = (1-pfa) M: f1 near 1 at pfa = 0.999 */
        const double c = (1 - f) * (x * (1 - pdh) + (1 - x) * (1 - pdl));
        TRK_ASSERT_NEAR(lf1, log1p(-c), 0, TRK_TOL(1e-14, 1e-6));
        TRK_ASSERT_NEAR(h.post_high[0], x * eh / f1, 0, TRK_TOL(1e-14, 1e-6));
    } else {
        const double mix = x * (1 - pdh) + (1 - x) * (1 - pdl);
        TRK_ASSERT_NEAR(lf1, log1p(-f) + log(mix), 1e-300, TRK_TOL(1e-14, 1e-6));
        TRK_ASSERT_NEAR(h.post_high[0], x * (1 - pdh) / mix, 0, TRK_TOL(1e-14, 1e-6));
    }
    assert_int_equal(h.n_looks[0], 1);
}

static void test_complete_closed_form(void **state)
{
    (void)state;
    const trk_real pfas[] = {0, TRK_REAL_C(1e-9), TRK_REAL_C(0.05), TRK_REAL_C(0.5), TRK_REAL_C(0.9),
                             TRK_REAL_C(0.999)};
    /* fixed P_D (pd_low = pd_high = 0.8): hit ln(1 - 0.2 (1-pfa)), miss
     * ln 0.2 + ln(1-pfa), whatever the state */
    struct trk_hmm_sensor_params fx = {TRK_REAL_C(0.3), TRK_REAL_C(0.3), TRK_REAL_C(0.8),
                                       TRK_REAL_C(0.8), TRK_HMM_PI0_STATIONARY};
    struct trk_hmm_params hp;
    struct trk_hmm_model m;
    trk_hmm_params_uniform(&hp, 1, &fx);
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    struct trk_hmm_state h;
    trk_hmm_state_reset(&m, &h);
    const double pd = (double)TRK_REAL_C(0.8);
    for (int t = 0; t < 24; t++) {
        const trk_real pfa = pfas[t % 6];
        const int det = (t / 6) % 2 == 0 ? t % 2 : t % 3 == 0;
        trk_real lf1;
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, det, pfa, &lf1));
        const double f = (double)pfa;
        TRK_ASSERT_NEAR(lf1, det ? log1p(-(1 - pd) * (1 - f)) : log1p(-pd) + log1p(-f), 0,
                        TRK_TOL(1e-14, 1e-6));
    }
    /* the HMM (Blanding: stationary prior 0.25, P_D 0.1 / 0.9) at its first
     * look, hit and miss */
    trk_hmm_params_uniform(&hp, 1, &blanding);
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    for (int i = 0; i < 6; i++)
        for (int det = 0; det < 2; det++) check_first_look(&m, det, pfas[i]);
    /* e.g. pfa = 0.5: hit f1 = 0.25 (0.95) + 0.75 (0.55) = 0.65, post =
     * 0.2375 / 0.65; miss f1 = 0.5 (0.25 (0.1) + 0.75 (0.9)) = 0.35 */
    trk_hmm_state_reset(&m, &h);
    trk_real lf1;
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 1, TRK_REAL_C(0.5), &lf1));
    TRK_ASSERT_NEAR(lf1, log(0.65), 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(h.post_high[0], 0.2375 / 0.65, 0, TRK_TOL(1e-14, 1e-6));
    trk_hmm_state_reset(&m, &h);
    TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, 0, TRK_REAL_C(0.5), &lf1));
    TRK_ASSERT_NEAR(lf1, log(0.35), 0, TRK_TOL(1e-14, 1e-6));
    TRK_ASSERT_NEAR(h.post_high[0], 0.025 / 0.7, 0, TRK_TOL(1e-14, 1e-6));
}

/* pfa near 1 (1 - 1e-12; float 1 - 1e-6): a hit has f1 = 1 - eps M, ln f1
 * ~ -eps M to full relative accuracy (log1p of the complement); a miss has
 * ln f1 = ln eps + ln M, and s = ln f0 - ln f1 = -ln M: finite and > 0, the
 * same as for any other pfa. */
static void test_complete_pfa_near_one(void **state)
{
    (void)state;
    const trk_real pfa = 1 - (trk_real)TRK_TOL(1e-12, 1e-6);
    const double eps = 1 - (double)pfa; /* exact */
    assert_true(pfa < 1 && eps > 0);
    const struct trk_hmm_sensor_params fx = {TRK_REAL_C(0.3), TRK_REAL_C(0.3), TRK_REAL_C(0.6),
                                             TRK_REAL_C(0.6), TRK_HMM_PI0_STATIONARY};
    const struct trk_hmm_sensor_params *sps[2] = {&blanding, &fx};
    for (int k = 0; k < 2; k++) {
        struct trk_hmm_params hp;
        struct trk_hmm_model m;
        struct trk_hmm_state h;
        trk_hmm_params_uniform(&hp, 1, sps[k]);
        TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
        trk_hmm_state_reset(&m, &h);
        for (int t = 0; t < 10; t++) {
            const int det = t % 4 == 1;
            const double x = (double)trk_hmm_prior_high(&m, &h, 0);
            const double mix = x * (1 - (double)m.s[0].pd_high) + (1 - x) * (1 - (double)m.s[0].pd_low);
            trk_real lf1, lf0;
            TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, det, pfa, &lf1));
            TRK_ASSERT_OK(trk_hmm_log_f0(det, pfa, &lf0));
            const double s = (double)lf0 - (double)lf1;
            assert_true(isfinite((double)lf1) && isfinite(s));
            if (det) {
                TRK_ASSERT_NEAR(lf1, log1p(-eps * mix), 0, TRK_TOL(1e-14, 1e-5));
                assert_true(lf1 < 0);
            } else {
                TRK_ASSERT_NEAR(lf1, log(eps) + log(mix), 0, TRK_TOL(1e-14, 1e-6));
                /* s = -ln M > 0; |ln f0| ~ 27.6 (float 13.8) cancels */
                TRK_ASSERT_NEAR(s, -log(mix), TRK_TOL(1e-13, 4e-6), 0);
                assert_true(s > 0);
            }
        }
    }
}

/* The product of the complete model's predictive likelihoods is the joint
 * likelihood by enumeration with P(miss | u) = (1 - Pd_u)(1 - pfa_t). */
static void test_complete_chain_rule_vs_enumeration(void **state)
{
    (void)state;
    const int d[14] = {1, 0, 0, 1, 1, 1, 0, 0, 0, 0, 1, 0, 1, 1};
    double pfa[14];
    const double p = 0.1 / 3, q = 0.1;
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, 1, &blanding);
    struct trk_hmm_model m;
    struct trk_hmm_state h;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    trk_hmm_state_reset(&m, &h);
    double sum = 0;
    for (int t = 0; t < 14; t++) {
        const trk_real f = TRK_REAL_C(0.02) + TRK_REAL_C(0.07) * (trk_real)t; /* up to 0.93 */
        pfa[t] = (double)f;
        trk_real lf1;
        TRK_ASSERT_OK(trk_hmm_update(&m, &h, 0, d[t], f, &lf1));
        sum += (double)lf1;
        TRK_ASSERT_NEAR(sum, brute_log_lik_events(t + 1, d, pfa, p, q, 0.1, 0.9, p / (p + q)), 0,
                        TRK_TOL(1e-13, 1e-5));
    }
    /* the complete model differs from the paper's by far more than rounding */
    assert_true(fabs(sum - brute_log_lik(14, d, p, q, 0.1, 0.9, p / (p + q))) > 1);
}

/* With pfa = 0 the complete model is the paper's: the same bits, looks of
 * hits and misses, near-1 and mid-range P_D. */
static void test_forms_agree_at_pfa_zero(void **state)
{
    (void)state;
    const struct trk_hmm_sensor_params tiny = {TRK_REAL_C(0.1), TRK_REAL_C(0.2), TRK_REAL_C(1e-9),
                                               TRK_REAL_C(3e-9), TRK_REAL_C(0.5)};
    const struct trk_hmm_sensor_params *sps[2] = {&blanding, &tiny};
    for (int k = 0; k < 2; k++) {
        struct trk_hmm_params hp;
        struct trk_hmm_model mc, mp;
        struct trk_hmm_state hc, hq;
        trk_hmm_params_uniform(&hp, 1, sps[k]);
        TRK_ASSERT_OK(trk_hmm_model_init(&mc, &hp));
        hp.events = TRK_EVENTS_PAPER;
        TRK_ASSERT_OK(trk_hmm_model_init(&mp, &hp));
        trk_hmm_state_reset(&mc, &hc);
        trk_hmm_state_reset(&mp, &hq);
        for (int t = 0; t < 30; t++) {
            const int det = (t * 7) % 5 < 2;
            trk_real lc, lp;
            TRK_ASSERT_OK(trk_hmm_update(&mc, &hc, 0, det, 0, &lc));
            TRK_ASSERT_OK(trk_hmm_update(&mp, &hq, 0, det, 0, &lp));
            assert_memory_equal(&lc, &lp, sizeof lc);
            assert_memory_equal(hc.post_high, hq.post_high, sizeof hc.post_high);
        }
        assert_int_equal(hc.n_looks[0], hq.n_looks[0]);
    }
}

/* The paper's form does not read pfa: any value, NaN and out of range
 * included, gives the bits of pfa = 0. */
static void test_paper_ignores_pfa(void **state)
{
    (void)state;
    const trk_real odd[] = {(trk_real)NAN, (trk_real)INFINITY, 1, 2, -1, TRK_REAL_C(0.3)};
    struct trk_hmm_params hp;
    struct trk_hmm_model m;
    trk_hmm_params_uniform(&hp, 1, &blanding);
    hp.events = TRK_EVENTS_PAPER;
    TRK_ASSERT_OK(trk_hmm_model_init(&m, &hp));
    for (int i = 0; i < 6; i++) {
        struct trk_hmm_state a, b;
        trk_hmm_state_reset(&m, &a);
        trk_hmm_state_reset(&m, &b);
        for (int t = 0; t < 12; t++) {
            const int det = t % 3 == 0;
            trk_real la, lb;
            TRK_ASSERT_OK(trk_hmm_update(&m, &a, 0, det, 0, &la));
            TRK_ASSERT_OK(trk_hmm_update(&m, &b, 0, det, odd[i], &lb));
            assert_memory_equal(&la, &lb, sizeof la);
            assert_memory_equal(a.post_high, b.post_high, sizeof a.post_high);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_rule_vs_enumeration),
        cmocka_unit_test(test_two_sensors_independent),
        cmocka_unit_test(test_priors),
        cmocka_unit_test(test_accuracy_near_one),
        cmocka_unit_test(test_bad_params),
        cmocka_unit_test(test_default_is_complete),
        cmocka_unit_test(test_complete_closed_form),
        cmocka_unit_test(test_complete_pfa_near_one),
        cmocka_unit_test(test_complete_chain_rule_vs_enumeration),
        cmocka_unit_test(test_forms_agree_at_pfa_zero),
        cmocka_unit_test(test_paper_ignores_pfa),
    };
    return trk_run_tests("hmm_detect", tests, NULL, NULL);
}
