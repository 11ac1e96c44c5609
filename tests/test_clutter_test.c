/* test_clutter_test.c - Kennedy's clutter density (chi-square) and amplitude
 * (F) confirmation tests: closed forms for K = 1, window growth and sliding,
 * decision <=> threshold, degenerate windows, bad input, one model shared
 * by several tracks, 10^6-step runs, sticky decisions. */
#include "trk_test.h"
#include "trk/clutter_test.h"
#include "trk/special.h"

/* The steps through the decision output: on success the decision written
 * must be the state's sticky one; on error *decision stays as it was. */
#define UNWRITTEN ((enum trk_decision)77)
static trk_status chi2_step(const struct trk_clutter_chi2_model *m, struct trk_clutter_chi2 *s,
                            trk_real rho_vg)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_clutter_chi2_step(m, s, rho_vg, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}
static trk_status amp_step(const struct trk_clutter_amp_model *m, struct trk_clutter_amp *s,
                           trk_real a_assoc_db, size_t n_others, const trk_real *a_others_db)
{
    enum trk_decision d = UNWRITTEN;
    const trk_status st = trk_clutter_amp_step(m, s, a_assoc_db, n_others, a_others_db, &d);
    if (st == TRK_OK) assert_int_equal(d, s->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}

/* K = 1: Z = 2 rho V_g ~ chi2(2): p = 1 - exp(-rho V_g); threshold
 * -2 ln(1 - alpha). Window sums grow to kmax, then slide. */
static void test_chi2_window(void **state)
{
    (void)state;
    const struct trk_clutter_chi2_params p = {TRK_REAL_C(0.05), 3};
    struct trk_clutter_chi2_model m;
    struct trk_clutter_chi2 s;
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&m, &p));
    trk_clutter_chi2_reset(&m, &s);
    assert_true(s.p_value == 1 && s.decision == TRK_DECISION_CONTINUE && s.t == 0);
    TRK_ASSERT_NEAR(m.threshold_tab[0], -2 * log1p(-(double)TRK_REAL_C(0.05)), 0, TRK_TOL(1e-14, 1e-6));
    const double rv[7] = {0.7, 1.3, 0.2, 2.5, 0.05, 0.01, 0.02};
    for (int t = 0; t < 7; t++) {
        TRK_ASSERT_OK(chi2_step(&m, &s, (trk_real)rv[t]));
        const int k = t + 1 < 3 ? t + 1 : 3;
        double sum = 0;
        for (int i = t + 1 - k; i <= t; i++) sum += (double)(trk_real)rv[i];
        assert_int_equal(s.dof, 2 * k);
        assert_int_equal(s.k, k);
        TRK_ASSERT_NEAR(s.stat, 2 * sum, 0, TRK_TOL(1e-15, 1e-6));
        /* even dof: P(chi2(2k) <= 2y) = e^-y sum_{j>=k} y^j/j! (no cancellation) */
        double term = 1, want = 0;
        for (int j = 1; j <= k; j++) term *= sum / j;
        for (int j = k; j < k + 200; j++) {
            want += term;
            term *= sum / (j + 1);
        }
        want *= exp(-sum);
        TRK_ASSERT_NEAR(s.p_value, want, 1e-300, TRK_TOL(1e-12, 1e-5));
        assert_int_equal(s.reject, s.p_value <= m.alpha);
        assert_int_equal(s.reject, s.stat <= s.threshold); /* same test, two forms */
        TRK_ASSERT_NEAR(trk_chi2_cdf(s.dof, s.threshold), 0.05, 0, TRK_TOL(1e-12, 1e-5));
    }
    assert_int_equal(s.reject, 1); /* Z = 2(0.05 + 0.01 + 0.02) = 0.16 <= 1.635 */
    assert_int_equal(s.decision, TRK_DECISION_CONFIRM);
    trk_clutter_chi2_reset(&m, &s);
    assert_true(s.k == 0 && s.decision == TRK_DECISION_CONTINUE && s.p_value == 1);
    TRK_ASSERT_NEAR(m.threshold_tab[2], 1.6353828943279067, 0, TRK_TOL(1e-13, 1e-5));
    assert_true(m.threshold_tab[3] == 0); /* beyond kmax */
}

/* K = 1 with m other peaks: Z ~ F(2, 2m), P(F >= z) = (1 + z/m)^-m. */
static void test_amp_closed_form(void **state)
{
    (void)state;
    const struct trk_clutter_amp_params p = {TRK_REAL_C(5.0), TRK_REAL_C(0.01), 4};
    struct trk_clutter_amp_model m;
    struct trk_clutter_amp s;
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&m, &p));
    trk_clutter_amp_reset(&m, &s);
    const trk_real others[3] = {TRK_REAL_C(6.0), TRK_REAL_C(7.5), TRK_REAL_C(5.5)};
    TRK_ASSERT_OK(amp_step(&m, &s, TRK_REAL_C(20.0), 3, others));
    const double sa = 15, so = 1 + 2.5 + 0.5;
    const double z = (sa / 2) / (so / 6);
    assert_int_equal(s.dof1, 2);
    assert_int_equal(s.dof2, 6);
    TRK_ASSERT_NEAR(s.stat, z, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(s.p_value, pow(1 + z / 3, -3), 0, TRK_TOL(1e-14, 1e-5));
    assert_int_equal(s.reject, s.p_value <= m.alpha);
    trk_real thr;
    TRK_ASSERT_OK(trk_clutter_amp_threshold(&m, &s, &thr));
    TRK_ASSERT_NEAR(thr, 3 * (pow(0.01, -1.0 / 3) - 1), 0, TRK_TOL(1e-13, 1e-5)); /* 10.9248 */
    assert_int_equal(s.reject, s.stat >= thr);
    /* a varying number of others per scan: dof2 = 2 sum N_k, sums over the window */
    const trk_real o2[1] = {TRK_REAL_C(9.0)};
    TRK_ASSERT_OK(amp_step(&m, &s, TRK_REAL_C(8.0), 1, o2));
    TRK_ASSERT_OK(amp_step(&m, &s, TRK_REAL_C(12.0), 0, NULL));
    assert_int_equal(s.dof1, 6);
    assert_int_equal(s.dof2, 8);
    const double z3 = ((15 + 3 + 7) / 6.0) / ((so + 4) / 8.0);
    TRK_ASSERT_NEAR(s.stat, z3, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(s.p_value, trk_f_sf(6, 8, (trk_real)z3), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_OK(trk_clutter_amp_threshold(&m, &s, &thr));
    TRK_ASSERT_NEAR(trk_f_sf(6, 8, thr), 0.01, 0, TRK_TOL(1e-12, 1e-4));
    /* slide: kmax 4, two more scans drop the first */
    TRK_ASSERT_OK(amp_step(&m, &s, TRK_REAL_C(5.0), 1, o2));
    TRK_ASSERT_OK(amp_step(&m, &s, TRK_REAL_C(5.0), 1, o2));
    assert_int_equal(s.dof1, 8);
    assert_int_equal(s.dof2, 6); /* N = 1, 0, 1, 1 */
    TRK_ASSERT_NEAR(s.stat, ((3 + 7 + 0 + 0) / 8.0) / (12 / 6.0), 0, TRK_TOL(1e-15, 1e-6));
}

static void test_amp_degenerate(void **state)
{
    (void)state;
    const struct trk_clutter_amp_params p = {0, TRK_REAL_C(0.05), 2};
    struct trk_clutter_amp_model m;
    struct trk_clutter_amp s;
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&m, &p));
    trk_clutter_amp_reset(&m, &s);
    TRK_ASSERT_OK(amp_step(&m, &s, 3, 0, NULL)); /* no other peak: no test */
    assert_true(s.stat == 0 && s.p_value == 1 && s.reject == 0 && s.dof2 == 0);
    trk_real thr;
    TRK_ASSERT_STATUS(trk_clutter_amp_threshold(&m, &s, &thr), TRK_E_RANGE);
    const trk_real at_min[2] = {0, 0};
    TRK_ASSERT_OK(amp_step(&m, &s, 3, 2, at_min)); /* So = 0 < Sa: Z infinite */
    assert_true(s.stat == TRK_REAL_MAX && s.p_value == 0 && s.reject == 1 && s.decision == TRK_DECISION_CONFIRM);
    trk_clutter_amp_reset(&m, &s);
    TRK_ASSERT_OK(amp_step(&m, &s, 0, 2, at_min)); /* everything at a_min: 0/0 */
    assert_true(s.stat == 0 && s.p_value == 1 && s.reject == 0);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_clutter_chi2_model cm, cmb;
    struct trk_clutter_amp_model am, amb;
    memset(&cm, 0x21, sizeof cm);
    memset(&am, 0x21, sizeof am);
    cmb = cm;
    amb = am;
    struct trk_clutter_chi2_params cp = {0, 25};
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, &cp), TRK_E_RANGE);
    cp.alpha = 1;
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, &cp), TRK_E_RANGE);
    cp.alpha = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, &cp), TRK_E_NAN);
    cp.alpha = TRK_REAL_C(0.01);
    cp.kmax = 0;
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, &cp), TRK_E_RANGE);
    cp.kmax = TRK_CLUTTER_KMAX + 1;
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, &cp), TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(NULL, &cp), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_clutter_chi2_model_init(&cm, NULL), TRK_E_ARG);
    assert_memory_equal(&cm, &cmb, sizeof cm); /* never half-initialised */
    struct trk_clutter_amp_params ap = {5, TRK_REAL_C(1.5), 25};
    TRK_ASSERT_STATUS(trk_clutter_amp_model_init(&am, &ap), TRK_E_RANGE);
    ap.alpha = TRK_REAL_C(0.01);
    ap.a_min_db = (trk_real)INFINITY;
    TRK_ASSERT_STATUS(trk_clutter_amp_model_init(&am, &ap), TRK_E_NAN);
    ap.a_min_db = 5;
    ap.kmax = TRK_CLUTTER_KMAX + 1;
    TRK_ASSERT_STATUS(trk_clutter_amp_model_init(&am, &ap), TRK_E_CAPACITY);
    ap.kmax = 0;
    TRK_ASSERT_STATUS(trk_clutter_amp_model_init(&am, &ap), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_clutter_amp_model_init(NULL, &ap), TRK_E_ARG);
    assert_memory_equal(&am, &amb, sizeof am);
    cp.kmax = 25;
    ap.kmax = 25;
    struct trk_clutter_chi2 c, cb;
    struct trk_clutter_amp a, ab;
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&cm, &cp));
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&am, &ap));
    trk_clutter_chi2_reset(&cm, &c);
    trk_clutter_amp_reset(&am, &a);
    TRK_ASSERT_OK(chi2_step(&cm, &c, TRK_REAL_C(0.5)));
    cb = c;
    cmb = cm;
    TRK_ASSERT_STATUS(chi2_step(&cm, &c, -TRK_REAL_C(0.1)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(chi2_step(&cm, &c, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(chi2_step(&cm, NULL, 1), TRK_E_ARG);
    TRK_ASSERT_STATUS(chi2_step(NULL, &c, 1), TRK_E_ARG);
    trk_clutter_chi2_reset(NULL, &c); /* no-op */
    assert_memory_equal(&c, &cb, sizeof c);
    assert_memory_equal(&cm, &cmb, sizeof cm);
    const trk_real ok[2] = {6, 7}, low[2] = {6, 4}, nan_[2] = {6, (trk_real)NAN};
    TRK_ASSERT_OK(amp_step(&am, &a, 9, 2, ok));
    ab = a;
    amb = am;
    TRK_ASSERT_STATUS(amp_step(&am, &a, 4, 2, ok), TRK_E_RANGE);   /* below a_min */
    TRK_ASSERT_STATUS(amp_step(&am, &a, 9, 2, low), TRK_E_RANGE);
    TRK_ASSERT_STATUS(amp_step(&am, &a, 9, 2, nan_), TRK_E_NAN);
    TRK_ASSERT_STATUS(amp_step(&am, &a, (trk_real)NAN, 2, ok), TRK_E_NAN);
    TRK_ASSERT_STATUS(amp_step(&am, &a, 9, 2, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(amp_step(NULL, &a, 9, 2, ok), TRK_E_ARG);
    TRK_ASSERT_STATUS(amp_step(&am, &a, 9, (size_t)TRK_MAX_DETECTIONS + 1, ok), TRK_E_CAPACITY);
    trk_real thr;
    TRK_ASSERT_STATUS(trk_clutter_amp_threshold(NULL, &a, &thr), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_clutter_amp_threshold(&am, &a, NULL), TRK_E_ARG);
    assert_memory_equal(&a, &ab, sizeof a);
    assert_memory_equal(&am, &amb, sizeof am);
}

/* Every field of two states bit for bit (not memcmp: padding). */
static void same_chi2(const struct trk_clutter_chi2 *x, const struct trk_clutter_chi2 *y)
{
    assert_memory_equal(x->win, y->win, sizeof x->win);
    assert_true(x->head == y->head && x->k == y->k && x->t == y->t && x->dof == y->dof);
    assert_memory_equal(&x->stat, &y->stat, sizeof x->stat);
    assert_memory_equal(&x->p_value, &y->p_value, sizeof x->p_value);
    assert_memory_equal(&x->threshold, &y->threshold, sizeof x->threshold);
    assert_true(x->reject == y->reject && x->decision == y->decision);
}
static void same_amp(const struct trk_clutter_amp *x, const struct trk_clutter_amp *y)
{
    assert_memory_equal(x->sa, y->sa, sizeof x->sa);
    assert_memory_equal(x->so, y->so, sizeof x->so);
    assert_memory_equal(x->n_others, y->n_others, sizeof x->n_others);
    assert_true(x->head == y->head && x->k == y->k && x->t == y->t);
    assert_true(x->dof1 == y->dof1 && x->dof2 == y->dof2);
    assert_memory_equal(&x->stat, &y->stat, sizeof x->stat);
    assert_memory_equal(&x->p_value, &y->p_value, sizeof x->p_value);
    assert_true(x->reject == y->reject && x->decision == y->decision);
}

/* One model, several tracks: states reset from a shared model evolve
 * independently and match a private model's bit for bit; the model (and its
 * threshold table) is never written by a step. */
static void test_shared_model(void **state)
{
    (void)state;
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.05), 4};
    const struct trk_clutter_amp_params ap = {TRK_REAL_C(2.0), TRK_REAL_C(0.05), 3};
    static struct trk_clutter_chi2_model cm, cm_own, cm_copy;
    static struct trk_clutter_amp_model am, am_own, am_copy;
    static struct trk_clutter_chi2 c[2], c_own;
    static struct trk_clutter_amp a[2], a_own;
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&cm, &cp));
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&cm_own, &cp));
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&am, &ap));
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&am_own, &ap));
    cm_copy = cm;
    am_copy = am;
    for (int k = 0; k < 2; k++) {
        trk_clutter_chi2_reset(&cm, &c[k]);
        trk_clutter_amp_reset(&am, &a[k]);
    }
    trk_clutter_chi2_reset(&cm_own, &c_own);
    trk_clutter_amp_reset(&am_own, &a_own);
    const trk_real others[3] = {TRK_REAL_C(3.0), TRK_REAL_C(4.5), TRK_REAL_C(2.5)};
    for (int t = 0; t < 12; t++) {
        const trk_real rv0 = TRK_REAL_C(0.05) * (trk_real)(t % 3), rv1 = TRK_REAL_C(0.9);
        const trk_real aa0 = TRK_REAL_C(15.0), aa1 = TRK_REAL_C(3.0) + TRK_REAL_C(0.1) * (trk_real)t;
        const size_t n_o = (size_t)(t % 4);
        TRK_ASSERT_OK(chi2_step(&cm, &c[0], rv0));
        TRK_ASSERT_OK(chi2_step(&cm, &c[1], rv1));
        TRK_ASSERT_OK(chi2_step(&cm_own, &c_own, rv0));
        TRK_ASSERT_OK(amp_step(&am, &a[0], aa0, n_o, others));
        TRK_ASSERT_OK(amp_step(&am, &a[1], aa1, n_o, others));
        TRK_ASSERT_OK(amp_step(&am_own, &a_own, aa0, n_o, others));
        same_chi2(&c[0], &c_own);
        same_amp(&a[0], &a_own);
        assert_true(c[0].threshold == cm.threshold_tab[c[0].k - 1]);
    }
    assert_memory_equal(&cm, &cm_copy, sizeof cm);
    assert_memory_equal(&am, &am_copy, sizeof am);
    assert_int_equal(c[0].decision, TRK_DECISION_CONFIRM); /* near the prediction: confirmed */
    assert_int_equal(c[1].decision, TRK_DECISION_CONTINUE);
    assert_int_equal(a[0].decision, TRK_DECISION_CONFIRM); /* strong associated peak: confirmed */
    assert_int_equal(a[1].decision, TRK_DECISION_CONTINUE);
}

/* 10^6 updates: tiny rho V_g (a target sitting on the prediction, p-value
 * underflows towards 0) and large ones; amplitudes far above and at the
 * threshold. Statistics stay finite and p-values in [0, 1]. */
static void test_long_runs(void **state)
{
    (void)state;
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.01), 25};
    static struct trk_clutter_chi2_model cm;
    static struct trk_clutter_chi2 c;
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&cm, &cp));
    trk_clutter_chi2_reset(&cm, &c);
    for (long t = 0; t < 1000000; t++) {
        const trk_real rv = t % 2 ? TRK_REAL_C(1e-30) : TRK_REAL_C(40.0);
        TRK_ASSERT_OK(chi2_step(&cm, &c, t < 500000 ? TRK_REAL_C(1e-30) : rv));
        assert_true(isfinite((double)c.stat) && c.p_value >= 0 && c.p_value <= 1);
    }
    assert_int_equal(c.decision, TRK_DECISION_CONFIRM);
    const struct trk_clutter_amp_params ap = {5, TRK_REAL_C(0.01), 25};
    static struct trk_clutter_amp_model am;
    static struct trk_clutter_amp a;
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&am, &ap));
    trk_clutter_amp_reset(&am, &a);
    const trk_real others[1] = {TRK_REAL_C(5.001)};
    for (long t = 0; t < 1000000; t++) {
        TRK_ASSERT_OK(amp_step(&am, &a, t % 2 ? TRK_REAL_C(60.0) : 5, 1, others));
        assert_true(isfinite((double)a.stat) && a.p_value >= 0 && a.p_value <= 1);
    }
    assert_int_equal(a.decision, TRK_DECISION_CONFIRM);
}

/* The decision is sticky: once H0 is rejected (CONFIRM), later updates that
 * do not reject (reject 0, p-value back above alpha) keep CONFIRM while the
 * statistics keep running; only a reset starts afresh. A NULL decision
 * pointer is refused like any NULL (TRK_E_ARG, state untouched). */
static void test_decision_sticky(void **state)
{
    (void)state;
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.05), 2};
    struct trk_clutter_chi2_model cm;
    struct trk_clutter_chi2 c, cb;
    TRK_ASSERT_OK(trk_clutter_chi2_model_init(&cm, &cp));
    trk_clutter_chi2_reset(&cm, &c);
    enum trk_decision d = UNWRITTEN;
    TRK_ASSERT_OK(trk_clutter_chi2_step(&cm, &c, 5, &d)); /* far: no rejection */
    assert_int_equal(d, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(trk_clutter_chi2_step(&cm, &c, TRK_REAL_C(1e-4), &d)); /* Z = 2(5 + 1e-4): none */
    assert_int_equal(d, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(trk_clutter_chi2_step(&cm, &c, TRK_REAL_C(1e-4), &d)); /* window slides: rejects */
    assert_int_equal(c.reject, 1);
    assert_int_equal(d, TRK_DECISION_CONFIRM);
    for (int t = 0; t < 5; t++) {
        const double before = (double)c.stat;
        TRK_ASSERT_OK(trk_clutter_chi2_step(&cm, &c, (trk_real)(10 + t), &d));
        assert_int_equal(c.reject, 0);
        assert_true(c.p_value > cm.alpha && (double)c.stat != before); /* statistic runs on */
        assert_int_equal(d, TRK_DECISION_CONFIRM);
        assert_int_equal(c.decision, TRK_DECISION_CONFIRM);
    }
    TRK_ASSERT_NEAR(c.stat, 2 * (13 + 14), 0, TRK_TOL(1e-15, 1e-6)); /* window of the last two */
    cb = c;
    TRK_ASSERT_STATUS(trk_clutter_chi2_step(&cm, &c, 1, NULL), TRK_E_ARG);
    assert_memory_equal(&c, &cb, sizeof c);
    trk_clutter_chi2_reset(&cm, &c);
    assert_int_equal(c.decision, TRK_DECISION_CONTINUE);

    const struct trk_clutter_amp_params ap = {0, TRK_REAL_C(0.05), 2};
    struct trk_clutter_amp_model am;
    struct trk_clutter_amp a, ab;
    TRK_ASSERT_OK(trk_clutter_amp_model_init(&am, &ap));
    trk_clutter_amp_reset(&am, &a);
    const trk_real weak[2] = {TRK_REAL_C(1.0), TRK_REAL_C(1.0)};
    d = UNWRITTEN;
    TRK_ASSERT_OK(trk_clutter_amp_step(&am, &a, 1, 2, weak, &d)); /* like the others: Z = 1 */
    assert_int_equal(d, TRK_DECISION_CONTINUE);
    TRK_ASSERT_OK(trk_clutter_amp_step(&am, &a, 40, 2, weak, &d)); /* strong: rejects H0 */
    assert_int_equal(a.reject, 1);
    assert_int_equal(d, TRK_DECISION_CONFIRM);
    for (int t = 0; t < 4; t++) {
        TRK_ASSERT_OK(trk_clutter_amp_step(&am, &a, TRK_REAL_C(0.5), 2, weak, &d));
        assert_int_equal(d, TRK_DECISION_CONFIRM);
    }
    assert_int_equal(a.reject, 0); /* window of two weak peaks: Z = 0.5 */
    TRK_ASSERT_NEAR(a.stat, 0.5, 0, TRK_TOL(1e-15, 1e-6));
    ab = a;
    TRK_ASSERT_STATUS(trk_clutter_amp_step(&am, &a, 1, 2, weak, NULL), TRK_E_ARG);
    d = UNWRITTEN;
    TRK_ASSERT_STATUS(trk_clutter_amp_step(&am, &a, -1, 2, weak, &d), TRK_E_RANGE);
    assert_int_equal(d, UNWRITTEN);
    assert_memory_equal(&a, &ab, sizeof a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chi2_window),
        cmocka_unit_test(test_amp_closed_form),
        cmocka_unit_test(test_amp_degenerate),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_shared_model),
        cmocka_unit_test(test_long_runs),
        cmocka_unit_test(test_decision_sticky),
    };
    return trk_run_tests("clutter_test", tests, NULL, NULL);
}
