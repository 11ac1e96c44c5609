/* test_imm.c - the IMM estimator (trk/imm.h): with one model it is the
 * Kalman filter and the IMM-PDA the PDA; the turn model tends to CV; mixing
 * with no switching leaves each model alone; the combination's moments; the
 * parameter checks. (The cycle's numbers against FilterPy and Stone Soup are
 * the imm_update / imm_pda_update vectors.) */
#include "trk_test.h"
#include "trk/imm.h"

static const trk_real X0[4] = {100, 2, -50, 1};
static const trk_real P0[16] = {20, 1, 0, 0, 1, 2, 0, 0, 0, 0, 20, 1, 0, 0, 1, 2};
static const trk_real R[4] = {25, 0, 0, 25};

static void one_model(struct trk_imm_params *m, struct trk_imm_state *s, trk_real omega)
{
    memset(m, 0, sizeof *m);
    m->n_models = 1;
    m->omega_rad_s[0] = omega;
    m->q_m2_per_s3[0] = TRK_REAL_C(0.05);
    m->p_switch[0] = 1;
    memset(s, 0, sizeof *s);
    s->mu[0] = 1;
    memcpy(s->x[0], X0, sizeof X0);
    memcpy(s->p[0], P0, sizeof P0);
}

static void test_one_model_is_kalman(void **state)
{
    (void)state;
    struct trk_imm_params m;
    struct trk_imm_state s;
    one_model(&m, &s, 0);
    TRK_ASSERT_OK(trk_imm_check_params(&m));
    trk_real mu_pred[TRK_MAX_MODELS], ll[TRK_MAX_MODELS];
    TRK_ASSERT_OK(trk_imm_mix(&m, &s, mu_pred));
    TRK_ASSERT_NEAR(mu_pred[0], 1, 1e-6, 0);
    TRK_ASSERT_OK(trk_imm_predict(&m, 2, &s));
    const trk_real z[2] = {105, -47};
    TRK_ASSERT_OK(trk_imm_update(&m, R, z, mu_pred, &s, ll));
    /* the same with the Kalman functions */
    trk_real x[4], p[16];
    memcpy(x, X0, sizeof x);
    memcpy(p, P0, sizeof p);
    TRK_ASSERT_OK(trk_cv2_predict(2, TRK_REAL_C(0.05), x, p));
    TRK_ASSERT_OK(trk_kalman_update(4, 2, trk_cv2_h, R, z, x, p));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(s.x[0][i], x[i], 1e-9, TRK_TOL(1e-12, 1e-5));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(s.p[0][i], p[i], 1e-9, TRK_TOL(1e-12, 1e-5));
    TRK_ASSERT_NEAR(s.mu[0], 1, 1e-6, 0);
    trk_real xc[4], pc[16];
    trk_imm_combine(&m, &s, xc, pc);
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(xc[i], x[i], 1e-9, TRK_TOL(1e-12, 1e-5));
}

static void test_one_model_pda_is_pda(void **state)
{
    (void)state;
    struct trk_imm_params m;
    struct trk_imm_state s;
    static struct trk_imm_work w;
    one_model(&m, &s, 0);
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, TRK_REAL_C(0.9), TRK_REAL_C(0.99), TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(1e-3), 1};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    trk_real mu_pred[TRK_MAX_MODELS];
    TRK_ASSERT_OK(trk_imm_mix(&m, &s, mu_pred));
    TRK_ASSERT_OK(trk_imm_predict(&m, 2, &s));
    const trk_real z[6] = {105, -47, 99, -52, 400, 400};
    unsigned char val[3];
    TRK_ASSERT_OK(trk_imm_pda_update(&m, &pda, R, 3, z, NULL, mu_pred, &s, &w, val, NULL));
    assert_true(val[0] == 1 && val[1] == 1 && val[2] == 0);
    trk_real x[4], p[16], beta[3];
    memcpy(x, X0, sizeof x);
    memcpy(p, P0, sizeof p);
    TRK_ASSERT_OK(trk_cv2_predict(2, TRK_REAL_C(0.05), x, p));
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 3, z, NULL, beta, NULL, NULL));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(s.x[0][i], x[i], 1e-9, TRK_TOL(1e-12, 1e-5));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(s.p[0][i], p[i], 1e-9, TRK_TOL(1e-12, 1e-5));
}

/* F_ct -> F_cv as omega -> 0, continuously across the series switch */
static void test_turn_tends_to_cv(void **state)
{
    (void)state;
    trk_real f0[16], f1[16], f2[16];
    trk_ct_transition(4, 0, f0);
    const trk_real cv[16] = {1, 4, 0, 0, 0, 1, 0, 0, 0, 0, 1, 4, 0, 0, 0, 1};
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(f0[i], cv[i], 0, 0);
    /* tiny rates: s/w and (1-c)/w stay accurate (no cancellation), against
     * the formula evaluated here in double */
    const double ws[2] = {2.4e-9, 2.6e-5};
    for (int k = 0; k < 2; k++) {
        trk_real *f = k ? f2 : f1;
        trk_ct_transition(4, (trk_real)ws[k], f);
        const double wt = ws[k] * 4, sw = sin(wt) / ws[k], cw = 2 * sin(wt / 2) * sin(wt / 2) / ws[k];
        TRK_ASSERT_NEAR(f[1], sw, 1e-9, TRK_TOL(1e-12, 1e-6));
        TRK_ASSERT_NEAR(f[3], -cw, 1e-9, TRK_TOL(1e-8, 1e-5));
        TRK_ASSERT_NEAR(f[9], cw, 1e-9, TRK_TOL(1e-8, 1e-5));
        TRK_ASSERT_NEAR(f[7], -sin(wt), 1e-12, TRK_TOL(1e-12, 1e-5));
    }
    /* a quarter turn: velocity (1, 0) becomes (0, 1) */
    trk_real f[16];
    const trk_real w = TRK_REAL_C(0.1);
    trk_ct_transition((trk_real)(3.14159265358979 / 2 / 0.1), w, f);
    const trk_real x[4] = {0, 1, 0, 0};
    trk_real y[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) y[i] += f[i * 4 + j] * x[j];
    TRK_ASSERT_NEAR(y[1], 0, 1e-5, 0);
    TRK_ASSERT_NEAR(y[3], 1, 1e-5, 0);
    TRK_ASSERT_NEAR(y[0], 10, 1e-4, 0); /* radius v / w */
    TRK_ASSERT_NEAR(y[2], 10, 1e-4, 0);
}

/* no switching: mixing returns every model's own estimate; the combination
 * is the mixture's mean and covariance (two models, closed form) */
static void test_mix_and_combine(void **state)
{
    (void)state;
    struct trk_imm_params m;
    struct trk_imm_state s;
    memset(&m, 0, sizeof m);
    memset(&s, 0, sizeof s);
    m.n_models = 2;
    m.q_m2_per_s3[0] = TRK_REAL_C(0.01);
    m.q_m2_per_s3[1] = 1;
    m.p_switch[0] = m.p_switch[3] = 1;
    s.mu[0] = TRK_REAL_C(0.25);
    s.mu[1] = TRK_REAL_C(0.75);
    memcpy(s.x[0], X0, sizeof X0);
    memcpy(s.x[1], X0, sizeof X0);
    s.x[1][0] += 4;
    memcpy(s.p[0], P0, sizeof P0);
    memcpy(s.p[1], P0, sizeof P0);
    trk_real mu_pred[TRK_MAX_MODELS];
    TRK_ASSERT_OK(trk_imm_mix(&m, &s, mu_pred));
    TRK_ASSERT_NEAR(mu_pred[0], 0.25, 1e-7, 0);
    TRK_ASSERT_NEAR(s.x[1][0], 104, 1e-5, 0);
    TRK_ASSERT_NEAR(s.p[0][0], 20, 1e-5, 0);
    trk_real x[4], p[16];
    trk_imm_combine(&m, &s, x, p);
    TRK_ASSERT_NEAR(x[0], 103, 1e-5, 0);                   /* 0.25 * 100 + 0.75 * 104 */
    TRK_ASSERT_NEAR(p[0], 20 + 0.25 * 9 + 0.75 * 1, 1e-5, 0); /* + spread */
    TRK_ASSERT_NEAR(p[5], 2, 1e-6, 0);
}

static void test_bad_params(void **state)
{
    (void)state;
    struct trk_imm_params m;
    struct trk_imm_state s;
    one_model(&m, &s, 0);
    m.n_models = 0;
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_ARG);
    m.n_models = TRK_MAX_MODELS + 1;
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_ARG);
    one_model(&m, &s, 0);
    m.q_m2_per_s3[0] = -1;
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_RANGE);
    one_model(&m, &s, 2);
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_RANGE);
    one_model(&m, &s, (trk_real)NAN);
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_NAN);
    one_model(&m, &s, 0);
    m.p_switch[0] = TRK_REAL_C(0.9);
    TRK_ASSERT_STATUS(trk_imm_check_params(&m), TRK_E_RANGE);
    one_model(&m, &s, 0);
    s.mu[0] = TRK_REAL_C(0.5);
    trk_real mu_pred[TRK_MAX_MODELS];
    TRK_ASSERT_STATUS(trk_imm_mix(&m, &s, mu_pred), TRK_E_RANGE);
    one_model(&m, &s, 0);
    TRK_ASSERT_STATUS(trk_imm_predict(&m, 0, &s), TRK_E_RANGE);
    const trk_real z[2] = {(trk_real)NAN, 0};
    TRK_ASSERT_STATUS(trk_imm_update(&m, R, z, mu_pred, &s, NULL), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_imm_update(NULL, R, z, mu_pred, &s, NULL), TRK_E_ARG);
}

/* Two models far apart and one detection at model 0's prediction: as it
 * moves away from model 1 (d2_1 from 0 to 1600), model 1's weight of it,
 * e_1 / (e_0 + e_1), falls through the subnormals (ln e_1 - ln e_0 about
 * 3.4 - d2_1 / 2: d2_1 in 1423..1495 in double, 180..215 in float). A
 * subnormal weight is an exactly-zero contribution: every update succeeds,
 * and beyond the band (d2_1 >= 1500; 220 in float) model 1 keeps its
 * prediction exactly (beta_1 = 0, beta0 = 1). */
static void test_subnormal_weight_is_zero(void **state)
{
    (void)state;
    struct trk_imm_params m;
    struct trk_imm_state s0;
    static struct trk_imm_work w;
    memset(&m, 0, sizeof m);
    memset(&s0, 0, sizeof s0);
    m.n_models = 2;
    m.q_m2_per_s3[0] = m.q_m2_per_s3[1] = TRK_REAL_C(0.05);
    m.p_switch[0] = m.p_switch[3] = TRK_REAL_C(0.9);
    m.p_switch[1] = m.p_switch[2] = TRK_REAL_C(0.1);
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, TRK_REAL_C(0.9), TRK_REAL_C(0.99), TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(1e-3), 1};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    const trk_real mu_pred[TRK_MAX_MODELS] = {TRK_REAL_C(0.5), TRK_REAL_C(0.5)};
    int n_zero = 0;
    for (int k = 0; k <= 6400; k++) {
        const double d2 = 0.25 * k; /* S_1 = P_xx + R_xx = 45 */
        struct trk_imm_state s = s0;
        s.mu[0] = s.mu[1] = TRK_REAL_C(0.5);
        memcpy(s.x[0], X0, sizeof X0);
        memcpy(s.x[1], X0, sizeof X0);
        s.x[1][0] -= (trk_real)sqrt(d2 * 45);
        memcpy(s.p[0], P0, sizeof P0);
        memcpy(s.p[1], P0, sizeof P0);
        const trk_real z[2] = {X0[0], X0[2]};
        trk_real ll[TRK_MAX_MODELS];
        const trk_status st = trk_imm_pda_update(&m, &pda, R, 1, z, NULL, mu_pred, &s, &w, NULL, ll);
        if (st != TRK_OK) fail_msg("d2 %.2f: %s", d2, trk_status_str(st));
        TRK_ASSERT_NEAR(s.mu[0] + s.mu[1], 1, 1e-6, 0);
        for (int i = 0; i < 16; i++) assert_true(isfinite(s.p[1][i]));
        /* ln e_1 - ln e_0 below ln of the smallest normal: model 1 untouched */
        const trk_real x1 = X0[0] - (trk_real)sqrt(d2 * 45);
        const int kept = s.x[1][0] == x1 && s.p[1][0] == P0[0];
        if (d2 >= TRK_TOL(1500, 220)) assert_true(kept);
        n_zero += kept;
    }
    print_message("model 1 kept its prediction in %d of 6401\n", n_zero);
    assert_true(n_zero >= 6400 - 4 * TRK_TOL(1500, 220));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_model_is_kalman),
        cmocka_unit_test(test_one_model_pda_is_pda),
        cmocka_unit_test(test_turn_tends_to_cv),
        cmocka_unit_test(test_mix_and_combine),
        cmocka_unit_test(test_bad_params),
        cmocka_unit_test(test_subnormal_weight_is_zero),
    };
    return trk_run_tests("imm", tests, NULL, NULL);
}
