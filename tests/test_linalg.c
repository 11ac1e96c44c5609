/* test_linalg.c - small-matrix kernels: products, Cholesky, solves, SPD check. */
#include "trk_test.h"
#include "trk/linalg.h"

static void test_mul(void **state)
{
    (void)state;
    const trk_real a[6] = {1, 2, 3, 4, 5, 6}; /* 2x3 */
    const trk_real b[6] = {7, 8, 9, 10, 11, 12}; /* 3x2 */
    trk_real c[4], d[4];
    trk_mat_mul(2, 3, 2, a, b, c);
    TRK_ASSERT_NEAR(c[0], 58, 0, 0);
    TRK_ASSERT_NEAR(c[1], 64, 0, 0);
    TRK_ASSERT_NEAR(c[2], 139, 0, 0);
    TRK_ASSERT_NEAR(c[3], 154, 0, 0);
    trk_mat_mul_abt(2, 3, 2, a, a, d); /* A A' */
    TRK_ASSERT_NEAR(d[0], 14, 0, 0);
    TRK_ASSERT_NEAR(d[1], 32, 0, 0);
    TRK_ASSERT_NEAR(d[2], 32, 0, 0);
    TRK_ASSERT_NEAR(d[3], 77, 0, 0);
}

static void test_chol_solve(void **state)
{
    (void)state;
    /* A = L L' with L = [[2,0,0],[1,3,0],[-1,2,4]] */
    const trk_real a[9] = {4, 2, -2, 2, 10, 5, -2, 5, 21};
    trk_real l[9], x[3];
    TRK_ASSERT_OK(trk_chol(3, a, l));
    TRK_ASSERT_NEAR(l[0], 2, 1e-15, 0);
    TRK_ASSERT_NEAR(l[3], 1, 1e-15, 0);
    TRK_ASSERT_NEAR(l[4], 3, 1e-15, 0);
    TRK_ASSERT_NEAR(l[6], -1, 1e-15, 0);
    TRK_ASSERT_NEAR(l[7], 2, 1e-15, 0);
    TRK_ASSERT_NEAR(l[8], 4, 1e-15, 0);
    assert_true(l[1] == 0 && l[2] == 0 && l[5] == 0);
    TRK_ASSERT_NEAR(trk_chol_logdet(3, l), log(576.0), TRK_TOL(1e-14, 1e-6), 0);
    /* solve A x = A * [1, -2, 3] */
    const trk_real xt[3] = {1, -2, 3};
    trk_real b[3];
    trk_mat_mul(3, 3, 1, a, xt, b);
    trk_chol_solve(3, l, b, x);
    for (int i = 0; i < 3; i++) TRK_ASSERT_NEAR(x[i], xt[i], TRK_TOL(1e-14, 1e-5), 0);
}

static void test_not_spd(void **state)
{
    (void)state;
    const trk_real indef[4] = {1, 2, 2, 1};
    const trk_real nan_m[4] = {1, 0, 0, NAN};
    const trk_real asym[4] = {2, 1, 0.5, 2};
    trk_real l[4];
    TRK_ASSERT_STATUS(trk_chol(2, indef, l), TRK_E_NOT_SPD);
    TRK_ASSERT_STATUS(trk_chol(2, nan_m, l), TRK_E_NOT_SPD);
    TRK_ASSERT_STATUS(trk_chol(0, indef, l), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_mat_check_spd(2, nan_m, 1e-12), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_mat_check_spd(2, asym, 1e-12), TRK_E_NOT_SPD);
    TRK_ASSERT_STATUS(trk_mat_check_spd(2, indef, 1e-12), TRK_E_NOT_SPD);
    const trk_real ok[4] = {2, 1, 1, 2};
    TRK_ASSERT_OK(trk_mat_check_spd(2, ok, 0));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mul),
        cmocka_unit_test(test_chol_solve),
        cmocka_unit_test(test_not_spd),
    };
    return trk_run_tests("linalg", tests, NULL, NULL);
}
