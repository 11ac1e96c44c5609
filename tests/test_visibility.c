/* test_visibility.c - IPDA visibility (trk/visibility.h): the recurrence
 * against its linear-domain statement (Kennedy eqs 1-2, 21-24), the
 * log-domain update with huge amplitude ratios, amplitude on/off, the
 * sticky decision (CONTINUE -> CONFIRM -> TERMINATE), every bad input. */
#include "trk_test.h"
#include "trk/visibility.h"

/* One scan from the gated set: trk_visibility_log_sum, then the step. On
 * success the decision written must be the state's; on error *decision
 * stays as it was. */
#define UNWRITTEN ((enum trk_decision)77)
static trk_status update(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pd, trk_real pg,
                         size_t n, const trk_real *gd, trk_real rho, const trk_real *log_la)
{
    trk_real log_sum;
    trk_status st = trk_visibility_log_sum(n, gd, rho, log_la, &log_sum);
    if (st != TRK_OK) return st;
    enum trk_decision d = UNWRITTEN;
    st = trk_visibility_step(m, v, pd, pg, log_sum, &d);
    if (st == TRK_OK) assert_int_equal(d, v->decision);
    else assert_int_equal(d, UNWRITTEN);
    return st;
}

/* One shared model (as in the tracker); vis_init = model init + track reset. */
static struct trk_visibility_model vm;
static trk_status vis_init(struct trk_visibility *v, const struct trk_visibility_params *p)
{
    struct trk_visibility_model m;
    trk_status st = trk_visibility_model_init(&m, p);
    if (st != TRK_OK) return st;
    vm = m;
    trk_visibility_reset(&vm, v);
    return TRK_OK;
}

static const struct trk_visibility_params kp = {
    TRK_REAL_C(0.5), TRK_REAL_C(0.5), TRK_REAL_C(0.99), TRK_REAL_C(0.01), TRK_REAL_C(0.75), TRK_REAL_C(0.7), 0};

/* the docs/conventions.md statement, in double */
static void reference_step(double *pv, double *pcv, double pd, double pg, int n, const double *gd, double rho,
                           const double *la, double *pv_pred_out)
{
    const double pv_pred = 0.99 * *pv + 0.01 * (1 - *pv);
    double lam = 1 - pd * pg;
    for (int i = 0; i < n; i++) lam += pd * gd[i] / rho * (la ? la[i] : 1);
    *pv = pv_pred * lam / ((1 - pv_pred) + pv_pred * lam);
    *pcv = 0.25 * *pv + 0.75 * *pcv;
    *pv_pred_out = pv_pred;
}

static void test_recurrence(void **state)
{
    (void)state;
    struct trk_visibility v;
    TRK_ASSERT_OK(vis_init(&v, &kp));
    double pv = 0.5, pcv = 0.5, pv_pred;
    const double rho = 2e-6;
    unsigned seed = 12345;
    for (int t = 0; t < 40; t++) {
        double gd[4], la[4];
        trk_real g[4], l[4];
        const int n = t % 5 == 3 ? 0 : 1 + t % 4;
        for (int i = 0; i < n; i++) {
            seed = seed * 1103515245u + 12345u;
            gd[i] = 1e-5 * (double)((seed >> 8) % 1000) / 1000.0;
            seed = seed * 1103515245u + 12345u;
            la[i] = 0.2 + 5.0 * (double)((seed >> 8) % 1000) / 1000.0;
            g[i] = (trk_real)gd[i];
            l[i] = (trk_real)log(la[i]);
        }
        const int amp = t % 2;
        reference_step(&pv, &pcv, 0.8, 0.99, n, gd, rho, amp ? la : NULL, &pv_pred);
        TRK_ASSERT_OK(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), (size_t)n, g, (trk_real)rho,
                                            amp ? l : NULL));
        TRK_ASSERT_NEAR(v.pv_pred, pv_pred, 0, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_NEAR(v.pv, pv, 0, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_NEAR(v.pcv, pcv, 0, TRK_TOL(1e-13, 1e-5));
        assert_int_equal(v.scans, t + 1);
    }
}

static void test_log_domain(void **state)
{
    (void)state;
    struct trk_visibility v, w;
    TRK_ASSERT_OK(vis_init(&v, &kp));
    w = v;
    /* no detection: Lam = 1 - pd pg */
    TRK_ASSERT_OK(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 0, NULL, 1, NULL));
    TRK_ASSERT_OK(trk_visibility_update_log(&vm, &w, TRK_REAL_C(0.8), TRK_REAL_C(0.99), -(trk_real)INFINITY));
    const double lam = 1 - 0.8 * 0.99;
    TRK_ASSERT_NEAR(v.pv, 0.5 * lam / (0.5 + 0.5 * lam), 0, TRK_TOL(1e-14, 1e-6));
    assert_true(v.pv == w.pv);
    /* an amplitude ratio of e^800 (Rayleigh l^a of a strong echo): no overflow */
    const trk_real g = TRK_REAL_C(1e-5), l = 800;
    TRK_ASSERT_OK(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, &g, TRK_REAL_C(1e-6), &l));
    assert_true(v.pv == 1);
    TRK_ASSERT_NEAR(v.pcv, 0.25 + 0.75 * w.pcv, 0, TRK_TOL(1e-14, 1e-6));
    /* and e^-800: as no detection at all */
    TRK_ASSERT_OK(vis_init(&v, &kp));
    w = v;
    const trk_real lm = -800;
    TRK_ASSERT_OK(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, &g, TRK_REAL_C(1e-6), &lm));
    TRK_ASSERT_OK(trk_visibility_update_log(&vm, &w, TRK_REAL_C(0.8), TRK_REAL_C(0.99), -(trk_real)INFINITY));
    TRK_ASSERT_NEAR(v.pv, w.pv, 0, TRK_TOL(1e-14, 1e-6));
    /* pd pg = 1: a scan without detection proves invisibility */
    TRK_ASSERT_OK(trk_visibility_update_log(&vm, &w, 1, 1, -(trk_real)INFINITY));
    assert_true(w.pv == 0);
    /* a zero spatial likelihood contributes nothing */
    TRK_ASSERT_OK(vis_init(&v, &kp));
    w = v;
    const trk_real g2[2] = {0, TRK_REAL_C(3e-6)};
    TRK_ASSERT_OK(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 2, g2, TRK_REAL_C(1e-6), NULL));
    TRK_ASSERT_OK(update(&vm, &w, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, g2 + 1, TRK_REAL_C(1e-6), NULL));
    TRK_ASSERT_NEAR(v.pv, w.pv, 0, TRK_TOL(1e-15, 1e-6));
}

/* Sticky decision of the visibility test (visibility.h): CONTINUE ->
 * CONFIRM at the first pcv >= p_con, held while pcv sinks between p_term and
 * p_con; CONFIRM -> TERMINATE at the first pcv < p_term (the same state
 * serves the termination role), and TERMINATE is final even when pcv
 * climbs back above p_con. The statistics keep running throughout. */
static void test_decisions(void **state)
{
    (void)state;
    struct trk_visibility_params p = kp;
    p.p_term = TRK_REAL_C(0.2);
    struct trk_visibility v;
    TRK_ASSERT_OK(vis_init(&v, &p));
    assert_int_equal(v.decision, TRK_DECISION_CONTINUE);
    const trk_real g = TRK_REAL_C(1e-5), pd = TRK_REAL_C(0.8), pg = TRK_REAL_C(0.99);
    const trk_real none = -(trk_real)INFINITY;
    int t_conf = 0;
    for (int t = 1; t <= 10; t++) { /* strong detections: confirmed, and it sticks */
        TRK_ASSERT_OK(update(&vm, &v, pd, pg, 1, &g, TRK_REAL_C(1e-6), NULL));
        if (v.pcv >= p.p_con && !t_conf) t_conf = t;
        assert_int_equal(v.decision, t_conf ? TRK_DECISION_CONFIRM : TRK_DECISION_CONTINUE);
    }
    assert_true(t_conf >= 2 && t_conf <= 4);
    int t_term = 0, below_con = 0;
    enum trk_decision d = UNWRITTEN;
    for (int t = 1; t <= 40; t++) { /* then nothing: confirmed until pcv < p_term */
        TRK_ASSERT_OK(trk_visibility_step(&vm, &v, pd, pg, none, &d));
        if (v.pcv < p.p_term && !t_term) t_term = t;
        if (v.pcv < p.p_con && v.pcv >= p.p_term) below_con++;
        assert_int_equal(d, t_term ? TRK_DECISION_TERMINATE : TRK_DECISION_CONFIRM);
        assert_int_equal(v.decision, d);
    }
    assert_true(below_con >= 2); /* CONFIRM held while pcv was below p_con */
    assert_true(t_term > 0 && t_term < 40);
    for (int t = 0; t < 10; t++) { /* strong detections again: pcv recovers, TERMINATE holds */
        const trk_real before = v.pcv;
        TRK_ASSERT_OK(trk_visibility_step(&vm, &v, pd, pg, trk_log(g / TRK_REAL_C(1e-6)), &d));
        assert_true(v.pcv > before || v.pcv >= TRK_REAL_C(0.99));
        assert_int_equal(d, TRK_DECISION_TERMINATE);
    }
    assert_true(v.pcv >= p.p_con);
    /* a track that never reached p_con: CONTINUE -> TERMINATE, never confirmed later */
    TRK_ASSERT_OK(vis_init(&v, &p));
    for (int t = 0; t < 5; t++) TRK_ASSERT_OK(trk_visibility_step(&vm, &v, pd, pg, none, &d));
    assert_int_equal(d, TRK_DECISION_TERMINATE);
    for (int t = 0; t < 10; t++) TRK_ASSERT_OK(update(&vm, &v, pd, pg, 1, &g, TRK_REAL_C(1e-6), NULL));
    assert_true(v.pcv >= p.p_con);
    assert_int_equal(v.decision, TRK_DECISION_TERMINATE);
    /* reset starts afresh */
    trk_visibility_reset(&vm, &v);
    assert_int_equal(v.decision, TRK_DECISION_CONTINUE);
    /* trk_visibility_update_log (the tracker's call) keeps the same decision */
    struct trk_visibility a, b;
    TRK_ASSERT_OK(vis_init(&a, &p));
    b = a;
    for (int t = 0; t < 30; t++) {
        const trk_real ls = t < 8 ? trk_log(g / TRK_REAL_C(1e-6)) : none;
        TRK_ASSERT_OK(trk_visibility_step(&vm, &a, pd, pg, ls, &d));
        TRK_ASSERT_OK(trk_visibility_update_log(&vm, &b, pd, pg, ls));
        assert_int_equal(a.decision, b.decision);
        assert_true(a.pcv == b.pcv && a.pv == b.pv && a.pv_pred == b.pv_pred && a.scans == b.scans);
    }
    assert_int_equal(b.decision, TRK_DECISION_TERMINATE);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_visibility v, keep;
    TRK_ASSERT_OK(vis_init(&v, &kp));
    keep = v;
    struct trk_visibility_params p;
    const trk_real bad_vals[] = {(trk_real)NAN, (trk_real)INFINITY, -TRK_REAL_C(0.1), TRK_REAL_C(1.1)};
    for (int f = 0; f < 7; f++)
        for (int k = 0; k < 4; k++) {
            p = kp;
            trk_real *field[7] = {&p.pv0, &p.pcv0, &p.delta_stay, &p.delta_become, &p.omega_c, &p.p_con, &p.p_term};
            *field[f] = bad_vals[k];
            trk_status st = vis_init(&v, &p);
            assert_true(st == (k < 2 ? TRK_E_NAN : TRK_E_RANGE));
        }
    p = kp;
    p.pv0 = 0; /* the logistic update needs 0 < pv0 < 1 */
    TRK_ASSERT_STATUS(vis_init(&v, &p), TRK_E_RANGE);
    p = kp;
    p.omega_c = 1;
    TRK_ASSERT_STATUS(vis_init(&v, &p), TRK_E_RANGE);
    p = kp;
    p.p_term = p.p_con;
    TRK_ASSERT_STATUS(vis_init(&v, &p), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_visibility_model_init(NULL, &kp), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_visibility_model_init(&vm, NULL), TRK_E_ARG);
    assert_memory_equal(&v, &keep, sizeof v);

    const trk_real g[2] = {TRK_REAL_C(1e-5), TRK_REAL_C(2e-5)}, l[2] = {0, (trk_real)NAN};
    const trk_real gneg[1] = {-TRK_REAL_C(1e-5)}, ginf[1] = {(trk_real)INFINITY};
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), (trk_real)NAN), TRK_E_NAN);
    {   /* +inf: a detection where clutter is impossible: visible for certain */
        struct trk_visibility w = v;
        TRK_ASSERT_OK(trk_visibility_update_log(&vm, &w, TRK_REAL_C(0.8), TRK_REAL_C(0.99), (trk_real)INFINITY));
        TRK_ASSERT_NEAR(w.pv, 1, 0, 0);
    }
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, &v, 0, TRK_REAL_C(0.99), 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, &v, TRK_REAL_C(1.01), TRK_REAL_C(0.99), 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, &v, TRK_REAL_C(0.8), 0, 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, &v, (trk_real)NAN, TRK_REAL_C(0.99), 0), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_visibility_update_log(&vm, NULL, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 0), TRK_E_ARG);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 2, g, TRK_REAL_C(1e-6), l),
                      TRK_E_NAN);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, gneg, TRK_REAL_C(1e-6), NULL),
                      TRK_E_RANGE);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, ginf, TRK_REAL_C(1e-6), NULL),
                      TRK_E_NAN);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, g, 0, NULL), TRK_E_RANGE);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, g, (trk_real)NAN, NULL),
                      TRK_E_NAN);
    TRK_ASSERT_STATUS(update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 1, NULL, 1, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(
        update(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), TRK_MAX_DETECTIONS + 1, g, 1, NULL),
        TRK_E_CAPACITY);
    enum trk_decision d = UNWRITTEN;
    TRK_ASSERT_STATUS(trk_visibility_step(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 0, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_visibility_step(NULL, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 0, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_visibility_step(&vm, NULL, TRK_REAL_C(0.8), TRK_REAL_C(0.99), 0, &d), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_visibility_step(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(1.5), 0, &d), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_visibility_step(&vm, &v, TRK_REAL_C(0.8), TRK_REAL_C(0.99), (trk_real)NAN, &d), TRK_E_NAN);
    assert_int_equal(d, UNWRITTEN);
    trk_real ls = 42;
    TRK_ASSERT_STATUS(trk_visibility_log_sum(1, g, 1, NULL, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_visibility_log_sum(1, gneg, 1, NULL, &ls), TRK_E_RANGE);
    assert_true(ls == 42);
    TRK_ASSERT_OK(trk_visibility_log_sum(0, NULL, 1, NULL, &ls));
    assert_true(ls == -(trk_real)INFINITY);
    trk_visibility_reset(NULL, &v); /* no-op */
    assert_memory_equal(&v, &keep, sizeof v); /* untouched by every refusal */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recurrence),
        cmocka_unit_test(test_log_domain),
        cmocka_unit_test(test_decisions),
        cmocka_unit_test(test_bad_input),
    };
    return trk_run_tests("visibility", tests, NULL, NULL);
}
