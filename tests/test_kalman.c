/* test_kalman.c - CV model matrices, predict/update against closed forms,
 * Joseph form invariants, non-SPD and NaN input. */
#include "trk_test.h"
#include "trk/kalman.h"
#include "trk/linalg.h"

#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define P(i, j) TRK_CV2_P(i, j)

static void test_cv_model(void **state)
{
    (void)state;
    /* the named indices: state [x, vx, y, vy], row-major 4x4 and 2x2 */
    assert_int_equal(X, 0);
    assert_int_equal(VX, 1);
    assert_int_equal(Y, 2);
    assert_int_equal(VY, 3);
    assert_int_equal(P(X, X), 0);
    assert_int_equal(P(VX, VX), 5);
    assert_int_equal(P(Y, Y), 10);
    assert_int_equal(P(VY, VY), 15);
    assert_int_equal(P(X, Y), 2);
    assert_int_equal(P(Y, X), 8);
    assert_int_equal(TRK_CV2_S(TRK_CV2_ZY, TRK_CV2_ZY), 3);
    assert_int_equal(TRK_CV2_S(TRK_CV2_ZX, TRK_CV2_ZY), 1);
    trk_real f[16], q[16];
    trk_cv2_transition(2, f);
    trk_cv2_process_noise(2, TRK_REAL_C(0.5), q);
    TRK_ASSERT_NEAR(f[P(X, VX)], 2, 0, 0);
    TRK_ASSERT_NEAR(f[P(Y, VY)], 2, 0, 0);
    TRK_ASSERT_NEAR(f[P(X, X)] + f[P(VX, VX)] + f[P(Y, Y)] + f[P(VY, VY)], 4, 0, 0);
    /* q T^3/3 = 0.5*8/3, q T^2/2 = 1, q T = 1 */
    TRK_ASSERT_NEAR(q[P(X, X)], 4.0 / 3, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(q[P(X, VX)], 1, 0, 0);
    TRK_ASSERT_NEAR(q[P(VX, X)], 1, 0, 0);
    TRK_ASSERT_NEAR(q[P(VX, VX)], 1, 0, 0);
    TRK_ASSERT_NEAR(q[P(Y, Y)], 4.0 / 3, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(q[P(X, Y)], 0, 0, 0);
}

/* trk_cv2_predict equals the general predict with the CV matrices */
static void test_cv2_predict(void **state)
{
    (void)state;
    trk_real f[16], q[16], x1[4] = {3, -1, 7, 2}, x2[4];
    trk_real p1[16] = {4, 1, 0.5, 0.2, 1, 2, 0.1, 0.3, 0.5, 0.1, 9, 1.5, 0.2, 0.3, 1.5, 3}, p2[16];
    for (int i = 0; i < 4; i++) x2[i] = x1[i];
    for (int i = 0; i < 16; i++) p2[i] = p1[i];
    trk_cv2_transition(TRK_REAL_C(2.5), f);
    trk_cv2_process_noise(TRK_REAL_C(2.5), TRK_REAL_C(0.3), q);
    TRK_ASSERT_OK(trk_kalman_predict(4, f, q, x1, p1));
    TRK_ASSERT_OK(trk_cv2_predict(TRK_REAL_C(2.5), TRK_REAL_C(0.3), x2, p2));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(x2[i], x1[i], 0, TRK_TOL(1e-15, 1e-6));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(p2[i], p1[i], TRK_TOL(1e-14, 1e-5), TRK_TOL(1e-14, 1e-6));
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) assert_true(p2[i * 4 + j] == p2[j * 4 + i]);
    TRK_ASSERT_STATUS(trk_cv2_predict(NAN, 1, x2, p2), TRK_E_NAN);
}

static void test_scalar_update(void **state)
{
    (void)state;
    /* 1-D: x = 0, P = 4, R = 1, z = 5 -> K = 0.8, x = 4, P = 0.8 */
    trk_real x = 0, p = 4, h = 1, r = 1, z = 5;
    TRK_ASSERT_OK(trk_kalman_update(1, 1, &h, &r, &z, &x, &p));
    TRK_ASSERT_NEAR(x, 4, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(p, 0.8, 0, TRK_TOL(1e-15, 1e-6));
}

static void test_predict_update_cv(void **state)
{
    (void)state;
    trk_real f[16], q[16], x[4] = {10, 1, -5, 2}, p[16] = {0};
    const trk_real r[4] = {2, 0.5, 0.5, 3}, z[2] = {12, -2};
    p[0] = p[5] = p[10] = p[15] = 1;
    trk_cv2_transition(1, f);
    trk_cv2_process_noise(1, TRK_REAL_C(0.1), q);
    TRK_ASSERT_OK(trk_kalman_predict(4, f, q, x, p));
    TRK_ASSERT_NEAR(x[0], 11, 0, 1e-6);
    TRK_ASSERT_NEAR(x[2], -3, 0, 1e-6);
    /* P- = F F' + Q: P00 = 2 + q/3, P01 = 1 + q/2, P11 = 1 + q */
    TRK_ASSERT_NEAR(p[0], 2 + 0.1 / 3, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(p[1], 1.05, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(p[5], 1.1, 0, TRK_TOL(1e-15, 1e-6));
    trk_real pp[16];
    for (int i = 0; i < 16; i++) pp[i] = p[i];
    TRK_ASSERT_OK(trk_kalman_update(4, 2, trk_cv2_h, r, z, x, p));
    /* Joseph result equals the standard form P- - K S K' and stays SPD */
    struct trk_innovation inn;
    trk_real k[8], xs[4] = {11, 1, -3, 2};
    TRK_ASSERT_OK(trk_kalman_innovation(4, 2, trk_cv2_h, r, xs, pp, &inn));
    trk_kalman_gain(4, 2, trk_cv2_h, pp, &inn, k);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double kskt = 0;
            for (int a = 0; a < 2; a++)
                for (int b = 0; b < 2; b++) kskt += k[i * 2 + a] * inn.s[a * 2 + b] * k[j * 2 + b];
            TRK_ASSERT_NEAR(p[i * 4 + j], pp[i * 4 + j] - kskt, TRK_TOL(1e-13, 1e-5), 0);
            assert_true(p[i * 4 + j] == p[j * 4 + i]);
        }
    TRK_ASSERT_OK(trk_mat_check_spd(4, p, 0));
    /* state: x = x- + K (z - H x-) */
    TRK_ASSERT_NEAR(x[0], 11 + k[0] * 1 + k[1] * 1, TRK_TOL(1e-13, 1e-5), 0);
}

static void test_bad_input(void **state)
{
    (void)state;
    trk_real x[4] = {0, 0, 0, 0}, p[16] = {0}, f[16], q[16];
    const trk_real r[4] = {1, 0, 0, 1}, z[2] = {1, 1}, znan[2] = {NAN, 1};
    trk_cv2_transition(1, f);
    trk_cv2_process_noise(1, 1, q);
    /* P = 0 and R indefinite -> S not SPD; nothing written */
    const trk_real rbad[4] = {-1, 0, 0, 1};
    TRK_ASSERT_STATUS(trk_kalman_update(4, 2, trk_cv2_h, rbad, z, x, p), TRK_E_NOT_SPD);
    for (int i = 0; i < 16; i++) assert_true(p[i] == 0);
    p[0] = p[5] = p[10] = p[15] = 1;
    TRK_ASSERT_STATUS(trk_kalman_update(4, 2, trk_cv2_h, r, znan, x, p), TRK_E_NAN);
    assert_true(x[0] == 0);
    p[3] = NAN;
    TRK_ASSERT_STATUS(trk_kalman_predict(4, f, q, x, p), TRK_E_NAN);
    assert_true(x[0] == 0 && p[0] == 1);
    p[3] = 0;
    TRK_ASSERT_STATUS(trk_kalman_update(7, 2, trk_cv2_h, r, z, x, p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_kalman_predict(4, NULL, q, x, p), TRK_E_ARG);
}

/* two-point differencing: x = z1, v = (z1 - z0) / dt, P per axis pair
 * [[R1, R1/dt], [R1/dt, (R0 + R1)/dt^2]] with the xy terms; refusals */
static void test_cv2_two_point(void **state)
{
    (void)state;
    const trk_real z0[2] = {100, -20}, z1[2] = {112, -12}, r0[4] = {4, 1, 1, 9}, r1[4] = {16, -2, -2, 25};
    trk_real x[4], p[16];
    TRK_ASSERT_OK(trk_cv2_two_point(z0, r0, z1, r1, 4, x, p));
    TRK_ASSERT_NEAR(x[X], 112, 0, 0);
    TRK_ASSERT_NEAR(x[Y], -12, 0, 0);
    TRK_ASSERT_NEAR(x[VX], 3, 0, 0);
    TRK_ASSERT_NEAR(x[VY], 2, 0, 0);
    TRK_ASSERT_NEAR(p[P(X, X)], 16, 0, 0);
    TRK_ASSERT_NEAR(p[P(X, Y)], -2, 0, 0);
    TRK_ASSERT_NEAR(p[P(Y, Y)], 25, 0, 0);
    TRK_ASSERT_NEAR(p[P(X, VX)], 4, 0, 0);
    TRK_ASSERT_NEAR(p[P(VY, Y)], 6.25, 0, 0);
    TRK_ASSERT_NEAR(p[P(X, VY)], -0.5, 0, 0);
    TRK_ASSERT_NEAR(p[P(VX, VX)], 20.0 / 16, 0, 0);
    TRK_ASSERT_NEAR(p[P(VX, VY)], -1.0 / 16, 0, 0);
    TRK_ASSERT_NEAR(p[P(VY, VY)], 34.0 / 16, 0, 0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) assert_true(p[i * 4 + j] == p[j * 4 + i]);
    TRK_ASSERT_STATUS(trk_cv2_two_point(z0, r0, z1, r1, 0, x, p), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_cv2_two_point(z0, r0, z1, NULL, 4, x, p), TRK_E_ARG);
    const trk_real znan[2] = {NAN, 0}, rzero[4] = {0, 0, 0, 0};
    TRK_ASSERT_STATUS(trk_cv2_two_point(znan, r0, z1, r1, 4, x, p), TRK_E_NAN);
    /* R0 = 0: the velocity block's Schur complement R0 / dt^2 vanishes */
    TRK_ASSERT_STATUS(trk_cv2_two_point(z0, rzero, z1, r1, 4, x, p), TRK_E_NOT_SPD);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cv_model),
        cmocka_unit_test(test_cv2_predict),
        cmocka_unit_test(test_cv2_two_point),
        cmocka_unit_test(test_scalar_update),
        cmocka_unit_test(test_predict_update_cv),
        cmocka_unit_test(test_bad_input),
    };
    return trk_run_tests("kalman", tests, NULL, NULL);
}
