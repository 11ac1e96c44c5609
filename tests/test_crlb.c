/* test_crlb.c - CRLB with the information-reduction factor (trk/crlb.h,
 * Willett eq 37): steady state = Kalman steady state with R/q2, the printed
 * form of eq 37 gives the same fixed point, per-step recursion, the vector
 * values, CRLB below the MRE, bad input. */
#include "trk_test.h"
#include "trk/crlb.h"
#include "trk/mre.h"

/* Kalman steady-state covariance of the 1-D CV model with noise variance r,
 * by the plain Riccati recursion in double (independent of the library). */
static void kalman_cv1(double t, double q, double r, double p_out[4])
{
    double p[4] = {r, r / t, r / t, 2 * r / (t * t)};
    for (int it = 0; it < 200000; it++) {
        double a = p[0] + t * (p[1] + p[2]) + t * t * p[3] + q * t * t * t / 3;
        double b = p[1] + t * p[3] + q * t * t / 2;
        double d = p[3] + q * t;
        double s = a + r;
        double n0 = a - a * a / s, n1 = b - a * b / s, n3 = d - b * b / s;
        double ch = fabs(n0 - p[0]) + fabs(n1 - p[1]) + fabs(n3 - p[3]);
        p[0] = n0, p[1] = p[2] = n1, p[3] = n3;
        if (ch < 1e-17 * (fabs(n0) + fabs(n3))) break;
    }
    memcpy(p_out, p, 4 * sizeof(double));
}

static struct trk_crlb_params base(int nz, double t, double q, double r, double q2)
{
    struct trk_crlb_params p;
    memset(&p, 0, sizeof p);
    p.nz = nz;
    p.dt_s = (trk_real)t;
    p.q_m2_per_s3 = (trk_real)q;
    p.r_m2 = (trk_real)r;
    p.q2 = (trk_real)q2;
    return p;
}

/* Steady state = Kalman with R/q2 (q2 = 1: the Kalman filter itself). */
static void test_crlb_kalman_r_over_q2(void **state)
{
    (void)state;
    const double cases[][4] = {{1, 1, 1, 1}, {1, 1, 1, 0.7457}, {0.5, 2, 0.25, 0.6}, {1, 1.5625e-4, 1.0 / 12, 0.3}};
    for (size_t c = 0; c < 4; c++) {
        double pk[4];
        kalman_cv1(cases[c][0], cases[c][1], cases[c][2] / cases[c][3], pk);
        for (int nz = 1; nz <= 2; nz++) {
            struct trk_crlb_params pp = base(nz, cases[c][0], cases[c][1], cases[c][2], cases[c][3]);
            struct trk_crlb cr;
            struct trk_crlb_result res;
            TRK_ASSERT_OK(trk_crlb_init(&cr, &pp));
            TRK_ASSERT_OK(trk_crlb_steady_state(&cr, NULL, &res));
            const int nx = 2 * nz;
            for (int k = 0; k < nz; k++) {
                const int o = 2 * k;
                TRK_ASSERT_NEAR(res.j_inv[o * nx + o], pk[0], 0, TRK_TOL(1e-10, 5e-4));
                TRK_ASSERT_NEAR(res.j_inv[o * nx + o + 1], pk[1], 0, TRK_TOL(1e-10, 5e-4));
                TRK_ASSERT_NEAR(res.j_inv[(o + 1) * nx + o + 1], pk[3], 0, TRK_TOL(1e-10, 5e-4));
            }
            TRK_ASSERT_NEAR(res.pos_rmse_m, sqrt(nz * pk[0]), 0, TRK_TOL(1e-10, 5e-4));
        }
    }
}

/* 2x2 helpers for the printed form of eq 37 (1-D model, double). */
static void inv2(const double a[4], double o[4])
{
    double d = a[0] * a[3] - a[1] * a[2];
    o[0] = a[3] / d, o[1] = -a[1] / d, o[2] = -a[2] / d, o[3] = a[0] / d;
}
static void mul2(const double a[4], const double b[4], double o[4])
{
    o[0] = a[0] * b[0] + a[1] * b[2], o[1] = a[0] * b[1] + a[1] * b[3];
    o[2] = a[2] * b[0] + a[3] * b[2], o[3] = a[2] * b[1] + a[3] * b[3];
}

/* J+ = Q^-1 + q2 H'R^-1 H - Q^-1 F (J + F'Q^-1 F)^-1 F'Q^-1 as printed, q = 1
 * (well conditioned), iterated in double: the same fixed point. */
static void test_crlb_printed_form(void **state)
{
    (void)state;
    const double t = 1, q = 1, r = 1, q2 = 0.5257;
    const double f[4] = {1, t, 0, 1}, ft[4] = {1, 0, t, 1};
    const double qm[4] = {q * t * t * t / 3, q * t * t / 2, q * t * t / 2, q * t};
    double qi[4], j[4], a[4], b[4], c[4];
    inv2(qm, qi);
    double p0[4] = {r, r / t, r / t, 2 * r / (t * t)};
    inv2(p0, j);
    for (int it = 0; it < 2000; it++) {
        mul2(ft, qi, a);
        mul2(a, f, b); /* F'Q^-1 F */
        for (int i = 0; i < 4; i++) b[i] += j[i];
        inv2(b, c);
        mul2(qi, f, a);
        mul2(a, c, b);
        mul2(b, ft, a);
        mul2(a, qi, b); /* Q^-1 F (.)^-1 F' Q^-1 */
        for (int i = 0; i < 4; i++) j[i] = qi[i] - b[i];
        j[0] += q2 / r;
    }
    inv2(j, a);
    struct trk_crlb cr;
    struct trk_crlb_result res;
    struct trk_crlb_params pp = base(1, t, q, r, q2);
    TRK_ASSERT_OK(trk_crlb_init(&cr, &pp));
    TRK_ASSERT_OK(trk_crlb_steady_state(&cr, NULL, &res));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(res.j_inv[i], a[i], 0, TRK_TOL(1e-11, 5e-5));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(res.j[i], j[i], 0, TRK_TOL(1e-11, 5e-5));
}

/* q2.vec crlb_01 and crlb_05; the per-step recursion reaches the same value. */
static void test_crlb_vectors_and_steps(void **state)
{
    (void)state;
    struct trk_crlb cr;
    struct trk_crlb_result res;
    struct trk_crlb_params pp = base(2, 1, 1, 1, 0.74570000000000003);
    TRK_ASSERT_OK(trk_crlb_init(&cr, &pp));
    TRK_ASSERT_OK(trk_crlb_steady_state(&cr, NULL, &res));
    TRK_ASSERT_NEAR(res.j_inv[0], 0.98055213008121411, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.j_inv[1], 0.60039131287443226, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.j_inv[5], 1.1331884040538882, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.j_inv[2], 0, 1e-15, 0);
    /* from P0 = 100 x two-point differencing, above the steady state: the
     * Riccati map is monotone, so the bound falls step by step */
    trk_real j[16], ji[16], p0[16] = {0};
    for (int k = 0; k < 2; k++) {
        const int o = 2 * k;
        p0[o * 4 + o] = 100, p0[o * 4 + o + 1] = p0[(o + 1) * 4 + o] = 100, p0[(o + 1) * 4 + o + 1] = 200;
    }
    TRK_ASSERT_OK(trk_crlb_initial_info(&cr, p0, j));
    trk_real prev = INFINITY;
    for (int k = 0; k < 200; k++) {
        TRK_ASSERT_OK(trk_crlb_step(&cr, j, ji));
        assert_true(ji[0] <= prev * (1 + TRK_TOL(1e-12, 1e-5)));
        prev = ji[0];
    }
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(ji[i], res.j_inv[i], 1e-12, TRK_TOL(1e-9, 1e-4));
    pp = base(1, 0.5, 2, 0.25, 0.59999999999999998);
    TRK_ASSERT_OK(trk_crlb_init(&cr, &pp));
    TRK_ASSERT_OK(trk_crlb_steady_state(&cr, NULL, &res));
    TRK_ASSERT_NEAR(res.j_inv[0], 0.29661476785416596, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.j_inv[1], 0.34648506289954673, 1e-12, TRK_TOL(1e-9, 1e-4));
    TRK_ASSERT_NEAR(res.j_inv[3], 1.2121359597551464, 1e-12, TRK_TOL(1e-9, 1e-4));
}

/* The bound lies below the MRE with the same q2 (docs/conventions.md: 2-4x larger). */
static void test_crlb_below_mre(void **state)
{
    (void)state;
    const double q2s[3] = {0.9, 0.6, 0.3};
    for (int i = 0; i < 3; i++) {
        struct trk_crlb cr;
        struct trk_crlb_result rc;
        struct trk_crlb_params pc = base(2, 1, 1, 1, q2s[i]);
        TRK_ASSERT_OK(trk_crlb_init(&cr, &pc));
        TRK_ASSERT_OK(trk_crlb_steady_state(&cr, NULL, &rc));
        struct trk_mre_params pm;
        memset(&pm, 0, sizeof pm);
        pm.nz = 2, pm.dt_s = 1, pm.q_m2_per_s3 = 1, pm.r_m2 = 1, pm.gate_prob = TRK_REAL_C(0.99);
        pm.q2 = (trk_real)q2s[i];
        struct trk_mre m;
        struct trk_mre_result rm;
        TRK_ASSERT_OK(trk_mre_init(&m, &pm));
        TRK_ASSERT_OK(trk_mre_steady_state(&m, NULL, &rm));
        assert_true(rc.j_inv[0] < rm.p[0]);
    }
}

static void test_crlb_bad_input(void **state)
{
    (void)state;
    struct trk_crlb cr;
    struct trk_crlb_params p = base(2, 1, 1, 1, 0.5), b;
    TRK_ASSERT_STATUS(trk_crlb_init(NULL, &p), TRK_E_ARG);
    b = p, b.nz = 0;
    TRK_ASSERT_STATUS(trk_crlb_init(&cr, &b), TRK_E_ARG);
    b = p, b.q2 = 0;
    TRK_ASSERT_STATUS(trk_crlb_init(&cr, &b), TRK_E_RANGE);
    b = p, b.q2 = 2;
    TRK_ASSERT_STATUS(trk_crlb_init(&cr, &b), TRK_E_RANGE);
    b = p, b.r_m2 = 0;
    TRK_ASSERT_STATUS(trk_crlb_init(&cr, &b), TRK_E_RANGE);
    b = p, b.dt_s = NAN;
    TRK_ASSERT_STATUS(trk_crlb_init(&cr, &b), TRK_E_NAN);
    TRK_ASSERT_OK(trk_crlb_init(&cr, &p));
    trk_real j[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    TRK_ASSERT_STATUS(trk_crlb_step(&cr, j, NULL), TRK_E_NOT_SPD);
    TRK_ASSERT_STATUS(trk_crlb_initial_info(&cr, j, j), TRK_E_NOT_SPD);
    j[5] = NAN;
    struct trk_crlb_result res;
    TRK_ASSERT_STATUS(trk_crlb_steady_state(&cr, j, &res), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_crlb_steady_state(&cr, NULL, NULL), TRK_E_ARG);
    b = p, b.max_iter = 2;
    TRK_ASSERT_OK(trk_crlb_init(&cr, &b));
    TRK_ASSERT_STATUS(trk_crlb_steady_state(&cr, NULL, &res), TRK_E_DIVERGED);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crlb_kalman_r_over_q2),
        cmocka_unit_test(test_crlb_printed_form),
        cmocka_unit_test(test_crlb_vectors_and_steps),
        cmocka_unit_test(test_crlb_below_mre),
        cmocka_unit_test(test_crlb_bad_input),
    };
    return trk_run_tests("crlb", tests, NULL, NULL);
}
