/* test_mre.c - modified Riccati equation (trk/mre.h): q2 = 1 is the Kalman
 * steady state, the fixed point, the vector values, q2 looked up per step,
 * divergence, the TOC optimum and bad input. */
#include "trk_test.h"
#include "trk/mre.h"
#include "trk/toc.h"
#include "trk/q2.h"

/* Independent Kalman (q2 = 1) steady state of the 1-D CV model by the plain
 * Riccati recursion in double: P- = F P F' + Q, K = P- H'/S, P = (I - K H) P-. */
static void kalman_cv1(double t, double q, double r, double q2, double p_out[4], double *s_out)
{
    double p[4] = {r, r / t, r / t, 2 * r / (t * t)};
    double s = 0;
    for (int it = 0; it < 200000; it++) {
        double a = p[0] + t * (p[1] + p[2]) + t * t * p[3] + q * t * t * t / 3;
        double b = p[1] + t * p[3] + q * t * t / 2;
        double d = p[3] + q * t;
        s = a + r;
        /* P = P- - q2 P-H' S^-1 H P- */
        double n0 = a - q2 * a * a / s, n1 = b - q2 * a * b / s, n3 = d - q2 * b * b / s;
        double ch = fabs(n0 - p[0]) + fabs(n1 - p[1]) + fabs(n3 - p[3]);
        p[0] = n0, p[1] = p[2] = n1, p[3] = n3;
        if (ch < 1e-17 * (fabs(n0) + fabs(n3))) break;
    }
    memcpy(p_out, p, sizeof p);
    *s_out = s;
}

static struct trk_mre_params base(int nz, double t, double q, double r, double q2)
{
    struct trk_mre_params p;
    memset(&p, 0, sizeof p);
    p.nz = nz;
    p.dt_s = (trk_real)t;
    p.q_m2_per_s3 = (trk_real)q;
    p.r_m2 = (trk_real)r;
    p.gate_prob = TRK_REAL_C(0.99);
    p.clutter_density = TRK_REAL_C(0.01);
    p.q2 = (trk_real)q2;
    return p;
}

/* q2 = 1: the Kalman steady state; q2 < 1: the same recursion with q2
 * (1-D reference above; the 2-D model is two copies of it). */
static void test_mre_against_reference(void **state)
{
    (void)state;
    const double cases[][4] = {{1, 1, 1, 1}, {1, 1, 1, 0.45}, {0.5, 2, 0.25, 0.8}, {1, 1.5625e-4, 1.0 / 12, 0.3}};
    for (size_t c = 0; c < 4; c++) {
        double pr[4], sr;
        kalman_cv1(cases[c][0], cases[c][1], cases[c][2], cases[c][3], pr, &sr);
        for (int nz = 1; nz <= 2; nz++) {
            struct trk_mre_params pp = base(nz, cases[c][0], cases[c][1], cases[c][2], cases[c][3]);
            struct trk_mre m;
            struct trk_mre_result res;
            TRK_ASSERT_OK(trk_mre_init(&m, &pp));
            TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &res));
            const int nx = 2 * nz;
            for (int k = 0; k < nz; k++) {
                const int o = 2 * k;
                TRK_ASSERT_NEAR(res.p[o * nx + o], pr[0], 0, TRK_TOL(1e-10, 2e-4));
                TRK_ASSERT_NEAR(res.p[o * nx + o + 1], pr[1], 0, TRK_TOL(1e-10, 2e-4));
                TRK_ASSERT_NEAR(res.p[(o + 1) * nx + o + 1], pr[3], 0, TRK_TOL(1e-10, 2e-4));
                TRK_ASSERT_NEAR(res.s[k * nz + k], sr, 0, TRK_TOL(1e-10, 2e-4));
            }
            if (nz == 2) { /* no cross-coordinate terms */
                TRK_ASSERT_NEAR(res.p[0 * 4 + 2], 0, 1e-30, 0);
                TRK_ASSERT_NEAR(res.p[1 * 4 + 3], 0, 1e-30, 0);
            }
            /* eq 35 and lambda_vg = lambda c gamma sqrt(det S) */
            TRK_ASSERT_NEAR(res.rmse_m, sqrt(nz * pr[0]), 0, TRK_TOL(1e-10, 2e-4));
            const double gamma = -2 * log(1 - 0.99); /* nz = 2 */
            if (nz == 2) TRK_ASSERT_NEAR(res.lambda_vg, 0.01 * 3.14159265358979323846 * gamma * sr, 0, TRK_TOL(1e-10, 1e-4));
            /* a fixed point: one more step changes nothing */
            trk_real p2[16];
            memcpy(p2, res.p, sizeof p2);
            TRK_ASSERT_OK(trk_mre_step(&m, p2, NULL));
            for (int i = 0; i < nx * nx; i++)
                TRK_ASSERT_NEAR(p2[i], res.p[i], TRK_TOL(1e-15, 1e-9), TRK_TOL(1e-11, 1e-5));
        }
    }
}

/* q2.vec mre_01 (Brekke Table I model): P, S, lambda_vg. */
static void test_mre_vector(void **state)
{
    (void)state;
    struct trk_mre_params pp = base(2, 1, 0.00015625000000000003, 0.083333333333333329, 0.88);
    pp.gate_gamma = 36; /* pg = 0.99999998477002028 */
    pp.clutter_density = TRK_REAL_C(0.001);
    struct trk_mre m;
    struct trk_mre_result res;
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &res));
    TRK_ASSERT_NEAR(res.p[0], 0.02433622698869593, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.p[1], 0.0034177753056154198, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.p[5], 0.0010344512014653668, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.s[0], 0.11559164546805864, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.lambda_vg, 0.013073107112969339, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(trk_mre_rmse(2, res.p), sqrt(2 * 0.02433622698869593), 0, TRK_TOL(1e-9, 1e-4));
    assert_true(isnan(trk_mre_rmse(3, res.p)));
}

/* q2 per step from a function: constant function = constant mode; a law
 * falling with lambda_vg gives a self-consistent steady state with a larger
 * error; one falling fast enough makes the MRE diverge. */
static trk_status q2_const(const void *ctx, trk_real lv, trk_real *q2)
{
    (void)lv;
    *q2 = *(const trk_real *)ctx;
    return TRK_OK;
}
static trk_status q2_falling(const void *ctx, trk_real lv, trk_real *q2)
{
    (void)ctx;
    *q2 = TRK_REAL_C(0.9) / (1 + lv);
    return TRK_OK;
}

static void test_mre_lookup(void **state)
{
    (void)state;
    struct trk_mre m;
    struct trk_mre_result a, b, c;
    struct trk_mre_params pp = base(2, 1, 1, 1, 0.7);
    pp.clutter_density = TRK_REAL_C(0.001);
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &a));
    const trk_real k = TRK_REAL_C(0.7);
    pp.q2_fn = q2_const;
    pp.q2_ctx = &k;
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &b));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(b.p[i], a.p[i], 0, 0);
    pp.q2_fn = q2_falling;
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &c));
    TRK_ASSERT_NEAR(c.q2, 0.9 / (1 + (double)c.lambda_vg), 0, TRK_TOL(1e-12, 1e-5));
    /* self-consistent: the constant-q2 MRE at that q2 has the same steady state */
    struct trk_mre_params pc = pp;
    pc.q2_fn = NULL;
    pc.q2 = c.q2;
    TRK_ASSERT_OK(trk_mre_init(&m, &pc));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &a));
    TRK_ASSERT_NEAR(a.rmse_m, c.rmse_m, 0, TRK_TOL(1e-10, 1e-4));
    /* dense clutter: q2 -> 0 as S grows, P grows without bound */
    pp.clutter_density = 5;
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, NULL, &c), TRK_E_DIVERGED);
    assert_true(isinf(c.rmse_m));
}

/* A grid that ends at lambda_vg = 10: leaving it is reported, not clamped. */
static void test_mre_grid_range(void **state)
{
    (void)state;
    static const trk_real pd[2] = {TRK_REAL_C(0.5), 1};
    static trk_real lv[5], v[10];
    for (int j = 0; j < 5; j++) lv[j] = (trk_real)log(pow(10.0, -3 + j));
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 5; j++) v[i * 5 + j] = (trk_real)((double)pd[i] / (1 + exp((double)lv[j])));
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    g.detector = TRK_Q2_PDAF;
    g.axis[0] = (struct trk_q2_axis){2, pd, 0, 0, 0, TRK_Q2_LINEAR};
    g.axis[1] = (struct trk_q2_axis){5, lv, 0, 0, 1, TRK_Q2_LINEAR};
    g.values = v;
    struct trk_q2_lookup q;
    TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
    struct trk_q2_line line = {&q, {TRK_REAL_C(0.9)}};
    struct trk_mre_params pp = base(2, 1, 1, 1, 1);
    pp.q2_fn = trk_q2_line_eval;
    pp.q2_ctx = &line;
    pp.clutter_density = TRK_REAL_C(0.001);
    struct trk_mre m;
    struct trk_mre_result res;
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &res));
    pp.clutter_density = 2; /* lambda_vg beyond the grid's 10 */
    TRK_ASSERT_OK(trk_mre_init(&m, &pp));
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, NULL, &res), TRK_E_RANGE);
    /* the TOC evaluation of one point propagates the same status */
}

/* TOC with a synthetic detector: pd = pfa^(1/(1+SNR)) and q2 = pd/(1+lambda_vg):
 * the optimum of e(pfa) is interior and no worse than any point of a fine scan. */
static trk_status q2_synth(const void *ctx, trk_real pfa, trk_real lv, trk_real *q2)
{
    const double snr = *(const double *)ctx;
    *q2 = (trk_real)(pow((double)pfa, 1 / (1 + snr)) / (1 + (double)lv));
    return TRK_OK;
}

/* Brekke's Table I model with the synthetic q2 along the ROC, 1 m^2 cells. */
static struct trk_toc_params toc_setup(const double *snr)
{
    struct trk_toc_params tp;
    memset(&tp, 0, sizeof tp);
    tp.mre = base(2, 1, 0.00015625, 1.0 / 12, 1);
    tp.mre.gate_gamma = 36;
    tp.cells_per_m = 1;
    tp.pfa_min = TRK_REAL_C(1e-6);
    tp.pfa_max = TRK_REAL_C(0.5);
    tp.q2_fn = q2_synth;
    tp.q2_ctx = snr;
    return tp;
}

static void test_toc(void **state)
{
    (void)state;
    static const double snr = 10;
    struct trk_toc_params tp = toc_setup(&snr);
    struct trk_toc_result r;
    TRK_ASSERT_OK(trk_toc_optimise(&tp, &r));
    assert_true(r.pfa > tp.pfa_min && r.pfa < tp.pfa_max);
    double best = INFINITY;
    for (double lp = log(1e-6); lp <= log(0.5); lp += 0.02) {
        trk_real e;
        trk_status st = trk_toc_rmse(&tp, (trk_real)exp(lp), &e, NULL);
        if (st == TRK_OK && (double)e < best) best = (double)e;
    }
    if (!((double)r.rmse_m <= best * (1 + TRK_TOL(1e-9, 1e-5))))
        fail_msg("TOC optimum %g above the scan's best %g", (double)r.rmse_m, best);
    trk_real e;
    TRK_ASSERT_OK(trk_toc_rmse(&tp, r.pfa, &e, NULL));
    TRK_ASSERT_NEAR(e, r.rmse_m, 0, TRK_TOL(1e-12, 1e-5));
    assert_true(r.n_evals > 41);
    /* bad TOC parameters */
    struct trk_toc_params b = tp;
    b.pfa_min = TRK_REAL_C(0.6);
    TRK_ASSERT_STATUS(trk_toc_optimise(&b, &r), TRK_E_RANGE);
    b = tp;
    b.n_grid = 2;
    TRK_ASSERT_STATUS(trk_toc_optimise(&b, &r), TRK_E_RANGE);
    b = tp;
    b.cells_per_m = NAN;
    TRK_ASSERT_STATUS(trk_toc_optimise(&b, &r), TRK_E_NAN);
    b = tp;
    b.q2_fn = NULL;
    TRK_ASSERT_STATUS(trk_toc_optimise(&b, &r), TRK_E_ARG);
    b = tp;
    b.mre.r_m2 = 0; /* a bad model is refused, not reported as divergence */
    TRK_ASSERT_STATUS(trk_toc_optimise(&b, &r), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_toc_rmse(&tp, 1, &e, NULL), TRK_E_RANGE);
}

/* The MRE's start (trk_toc_params.p0): from P_0 = 0 or from the steady state
 * the iteration reaches the two-point start's fixed point; a non-SPD start
 * other than zero is refused. */
static void test_toc_start(void **state)
{
    (void)state;
    static const double snr = 10;
    struct trk_toc_params tp = toc_setup(&snr);
    trk_real e2, e0, es, zero[16] = {0};
    struct trk_mre_result r2, r0;
    TRK_ASSERT_OK(trk_toc_rmse(&tp, TRK_REAL_C(1e-2), &e2, &r2));
    tp.p0 = zero;
    TRK_ASSERT_OK(trk_toc_rmse(&tp, TRK_REAL_C(1e-2), &e0, &r0));
    TRK_ASSERT_NEAR(e0, e2, 0, TRK_TOL(1e-9, 1e-4));
    assert_true(r0.iterations != r2.iterations); /* another path to it */
    tp.p0 = r2.p;
    TRK_ASSERT_OK(trk_toc_rmse(&tp, TRK_REAL_C(1e-2), &es, NULL));
    TRK_ASSERT_NEAR(es, e2, 0, TRK_TOL(1e-9, 1e-4));
    trk_real bad[16] = {0};
    bad[0] = -1;
    tp.p0 = bad;
    TRK_ASSERT_STATUS(trk_toc_rmse(&tp, TRK_REAL_C(1e-2), &es, NULL), TRK_E_NOT_SPD);
}

static void test_mre_bad_input(void **state)
{
    (void)state;
    struct trk_mre m;
    struct trk_mre_params p = base(2, 1, 1, 1, 0.5), b;
    TRK_ASSERT_STATUS(trk_mre_init(NULL, &p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mre_init(&m, NULL), TRK_E_ARG);
    b = p, b.nz = 3;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_ARG);
    b = p, b.dt_s = 0;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.r_m2 = -1;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.q_m2_per_s3 = NAN;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_NAN);
    b = p, b.q2 = 0;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.q2 = TRK_REAL_C(1.01);
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.q2 = NAN;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_NAN);
    b = p, b.gate_prob = 1;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.gate_gamma = -1;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.clutter_density = -1;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_RANGE);
    b = p, b.max_iter = -1;
    TRK_ASSERT_STATUS(trk_mre_init(&m, &b), TRK_E_ARG);
    TRK_ASSERT_OK(trk_mre_init(&m, &p));
    struct trk_mre_result res;
    trk_real bad[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, bad, &res), TRK_E_NOT_SPD);
    bad[5] = NAN;
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, bad, &res), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, NULL, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mre_step(&m, NULL, NULL), TRK_E_ARG);
    /* too few iterations to converge */
    b = p, b.max_iter = 3;
    TRK_ASSERT_OK(trk_mre_init(&m, &b));
    TRK_ASSERT_STATUS(trk_mre_steady_state(&m, NULL, &res), TRK_E_DIVERGED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mre_against_reference),
        cmocka_unit_test(test_mre_vector),
        cmocka_unit_test(test_mre_lookup),
        cmocka_unit_test(test_mre_grid_range),
        cmocka_unit_test(test_toc),
        cmocka_unit_test(test_toc_start),
        cmocka_unit_test(test_mre_bad_input),
    };
    return trk_run_tests("mre", tests, NULL, NULL);
}
