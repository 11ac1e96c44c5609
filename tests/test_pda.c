/* test_pda.c - PDA update invariants: sum of beta = 1, symmetry and SPD of
 * the posterior, permutation invariance, limits (no detection, certain
 * detection = Kalman), nonparametric and include-all modes, bad input, the
 * variant with the innovation given, the parameter check's field names. */
#include "trk_test.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/linalg.h"
#include "trk/pda.h"
#include "../src/pda_impl.h"

static struct trk_pda make_pda(enum trk_clutter_mode mode, trk_real pd, trk_real lambda, int gating)
{
    struct trk_pda pda;
    struct trk_pda_params pp = {2, pd, TRK_REAL_C(0.99), mode, lambda, gating};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    return pda;
}

static void prior(trk_real x[4], trk_real p[16])
{
    const trk_real x0[4] = {100, 1, 50, -2};
    const trk_real p0[16] = {9, 1, 0.5, 0, 1, 1, 0, 0, 0.5, 0, 16, 2, 0, 0, 2, 1};
    for (int i = 0; i < 4; i++) x[i] = x0[i];
    for (int i = 0; i < 16; i++) p[i] = p0[i];
}

static const trk_real R[4] = {4, 0, 0, 4};

static void test_invariants(void **state)
{
    (void)state;
    struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.8), TRK_REAL_C(0.01), 1);
    const trk_real z[10] = {101, 50, 97, 53, 104, 44, 100.5, 50.5, 130, 90};
    trk_real x[4], p[16], beta[5], d2[5];
    struct trk_pda_report rep;
    prior(x, p);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 5, z, NULL, beta, d2, &rep));
    double sum = rep.beta0;
    for (int i = 0; i < 5; i++) sum += beta[i];
    TRK_ASSERT_NEAR(sum, 1, TRK_TOL(1e-15, 1e-6), 0);
    assert_true(beta[4] == 0); /* far outside */
    assert_int_equal(rep.n_gated, 4);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) assert_true(p[i * 4 + j] == p[j * 4 + i]);
    TRK_ASSERT_OK(trk_mat_check_spd(4, p, 0));

    /* permuting the detections leaves the result unchanged */
    const int perm[5] = {3, 0, 4, 2, 1};
    trk_real zp[10], x2[4], p2[16], beta2[5];
    for (int i = 0; i < 5; i++) {
        zp[2 * i] = z[2 * perm[i]];
        zp[2 * i + 1] = z[2 * perm[i] + 1];
    }
    prior(x2, p2);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x2, p2, 5, zp, NULL, beta2, NULL, NULL));
    for (int i = 0; i < 5; i++) TRK_ASSERT_NEAR(beta2[i], beta[perm[i]], TRK_TOL(1e-15, 1e-6), 0);
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(x2[i], x[i], TRK_TOL(1e-12, 1e-4), 0);
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(p2[i], p[i], TRK_TOL(1e-12, 1e-4), 0);
}

/* A random CV prior: x uniform in [0, 100), P = L L' + I with L random
 * lower triangular (SPD). */
static void random_prior(uint64_t *rs, trk_real x[4], trk_real p[16])
{
    trk_real l[16] = {0};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j <= i; j++) l[i * 4 + j] = (trk_real)(2 * trk_test_urand(rs) - 1) * 3;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double v = i == j;
            for (int k = 0; k < 4; k++) v += (double)l[i * 4 + k] * (double)l[j * 4 + k];
            p[i * 4 + j] = (trk_real)v;
        }
    for (int i = 0; i < 4; i++) x[i] = (trk_real)(100 * trk_test_urand(rs));
}

/* The 2-D CV model's fixed-index combination (pda_impl.h,
 * trk_i_pda_combine_cv2) against the general code: the same track embedded
 * in 5 states (an extra state uncorrelated with the rest, H picking x and y)
 * runs the general code (two-pass centred moments), and must give the same
 * x, P and beta, for random priors and detection sets (some clustered), with
 * and without the gate. */
static void test_cv_fast_path(void **state)
{
    (void)state;
    uint64_t rs = 7;
    for (int rep = 0; rep < 200; rep++) {
        struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.85), TRK_REAL_C(0.02), rep % 4 != 3);
        trk_real x[4], p[16], x5[5], p5[25] = {0}, h5[10] = {0}, z[2 * 12], beta[12], beta5[12];
        random_prior(&rs, x, p);
        const size_t m = (size_t)(rep % 12);
        /* every fifth set clustered, with R << H P H': within 1e-3 of a
         * point up to 2 m off (the spread W small against the shift: the
         * one-pass moments' case) */
        const int clustered = rep % 5 == 4;
        static const trk_real r_small[4] = {TRK_REAL_C(1e-4), 0, 0, TRK_REAL_C(1e-4)};
        const trk_real *rr = clustered ? r_small : R;
        const trk_real cx = (trk_real)(4 * trk_test_urand(&rs) - 2), cy = (trk_real)(4 * trk_test_urand(&rs) - 2);
        for (size_t i = 0; i < m; i++) {
            const trk_real ux = (trk_real)(8 * trk_test_urand(&rs) - 4), uy = (trk_real)(8 * trk_test_urand(&rs) - 4);
            z[2 * i] = x[TRK_CV2_X] + (clustered ? cx + TRK_REAL_C(1e-3) * ux : ux);
            z[2 * i + 1] = x[TRK_CV2_Y] + (clustered ? cy + TRK_REAL_C(1e-3) * uy : uy);
        }
        /* the embedding: states [x, vx, y, vy, e] */
        for (int i = 0; i < 4; i++) {
            x5[i] = x[i];
            for (int j = 0; j < 4; j++) p5[i * 5 + j] = p[i * 4 + j];
        }
        x5[4] = 3;
        p5[24] = 2;
        h5[0 * 5 + TRK_CV2_X] = 1;
        h5[1 * 5 + TRK_CV2_Y] = 1;
        struct trk_pda_report r4, r5;
        TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, rr, x, p, m, z, NULL, beta, NULL, &r4));
        TRK_ASSERT_OK(trk_pda_update(&pda, 5, h5, rr, x5, p5, m, z, NULL, beta5, NULL, &r5));
        TRK_ASSERT_NEAR(r4.beta0, r5.beta0, TRK_TOL(1e-13, 1e-5), 0);
        for (size_t i = 0; i < m; i++) TRK_ASSERT_NEAR(beta[i], beta5[i], TRK_TOL(1e-13, 1e-5), 0);
        for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(x[i], x5[i], TRK_TOL(1e-11, 1e-3), TRK_TOL(1e-12, 1e-5));
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                TRK_ASSERT_NEAR(p[i * 4 + j], p5[i * 5 + j], TRK_TOL(1e-10, 1e-3), TRK_TOL(1e-11, 1e-4));
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) assert_true(p[i * 4 + j] == p[j * 4 + i]);
        TRK_ASSERT_OK(trk_mat_check_spd(4, p, 0));
    }
}

/* The CV path with detections of their own R_j (pda_impl.h,
 * trk_i_pda_combine_cv2_own: one gain per detection, the spread about the
 * heaviest component) against the general code (the same track embedded in
 * 5 states), for random priors, shared and own detections, weights (beta0
 * small or dominant) and clustered sets with R << H P H'. */
static void test_cv_own_path(void **state)
{
    (void)state;
    uint64_t rs = 19;
    for (int rep = 0; rep < 300; rep++) {
        trk_real x[4], p[16], x5[5], p5[25] = {0}, h5[10] = {0};
        random_prior(&rs, x, p);
        const int clustered = rep % 5 == 4;
        const size_t n_sh = (size_t)(rep % 4), n = n_sh + 1 + (size_t)(rep % 7);
        trk_real z[2 * 12], r_own[4 * 12], w[12];
        static const trk_real r_small[4] = {TRK_REAL_C(1e-4), 0, 0, TRK_REAL_C(1e-4)};
        const trk_real *rr = clustered ? r_small : R;
        for (size_t i = 0; i < n; i++) {
            const trk_real ux = (trk_real)(8 * trk_test_urand(&rs) - 4), uy = (trk_real)(8 * trk_test_urand(&rs) - 4);
            z[2 * i] = x[TRK_CV2_X] + (clustered ? 1 + TRK_REAL_C(1e-3) * ux : ux);
            z[2 * i + 1] = x[TRK_CV2_Y] + (clustered ? -1 + TRK_REAL_C(1e-3) * uy : uy);
            if (i >= n_sh) { /* an own R_j: a rotated ellipse, scale 0.1-10 (clustered: 1e-4) */
                trk_real *rj = r_own + 4 * (i - n_sh);
                const double a = clustered ? 1e-4 : 0.1 + 10 * trk_test_urand(&rs), b = clustered ? 2e-4 : 0.1 + 3 * trk_test_urand(&rs);
                const double th = 3 * trk_test_urand(&rs), cs = cos(th), sn = sin(th);
                rj[0] = (trk_real)(a * cs * cs + b * sn * sn);
                rj[1] = rj[2] = (trk_real)((a - b) * cs * sn);
                rj[3] = (trk_real)(a * sn * sn + b * cs * cs);
            }
        }
        double sum = 0;
        for (size_t i = 0; i < n; i++) sum += (w[i] = (trk_real)trk_test_urand(&rs));
        const double beta0 = rep % 3 == 0 ? 0.9 : 0.05;
        for (size_t i = 0; i < n; i++) w[i] = (trk_real)((1 - beta0) * w[i] / sum);
        for (int i = 0; i < 4; i++) {
            x5[i] = x[i];
            for (int j = 0; j < 4; j++) p5[i * 5 + j] = p[i * 4 + j];
        }
        x5[4] = 3;
        p5[24] = 2;
        h5[0 * 5 + TRK_CV2_X] = 1;
        h5[1 * 5 + TRK_CV2_Y] = 1;
        trk_real pht4[8], pht5[10], xn4[4], xn5[5], acc4[16], acc5[25];
        struct trk_innovation inn4, inn5;
        TRK_ASSERT_OK(trk_i_innovation_sel(4, 2, trk_cv2_h, trk_i_cv2_sel(), rr, x, p, pht4, &inn4));
        TRK_ASSERT_OK(trk_i_innovation_sel(5, 2, h5, NULL, rr, x5, p5, pht5, &inn5));
        const struct trk_i_pda_pred pr4 = {4, 2, trk_cv2_h, trk_i_cv2_sel(), rr, x, p, pht4, &inn4};
        const struct trk_i_pda_pred pr5 = {5, 2, h5, NULL, rr, x5, p5, pht5, &inn5};
        const struct trk_i_pda_set set = {n, n_sh, n, z, w, r_own, 0, 0};
        trk_i_pda_combine(&pr4, &set, (trk_real)beta0, xn4, acc4);
        trk_i_pda_combine(&pr5, &set, (trk_real)beta0, xn5, acc5);
        for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(xn4[i], xn5[i], TRK_TOL(1e-10, 1e-3), TRK_TOL(1e-12, 1e-5));
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                TRK_ASSERT_NEAR(acc4[i * 4 + j], acc5[i * 5 + j], TRK_TOL(1e-10, 1e-3), TRK_TOL(1e-10, 1e-4));
                assert_true(acc4[i * 4 + j] == acc4[j * 4 + i]);
            }
        TRK_ASSERT_OK(trk_mat_check_spd(4, acc4, 0));
    }
}

/* Found by review of the CV fast path's kernel: a huge finite detection outside
 * the gate (weight 0, whitened innovation infinite) is accepted by the
 * general path too, not turned into TRK_E_NAN; clustered detections with
 * H P H' >> R keep the float covariance accurate (the centred spread); a
 * subnormal pivot does not make an SPD matrix fail the check. */
static void test_review_cases(void **state)
{
    (void)state;
    struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.9), TRK_REAL_C(1e-3), 1);
    /* state [x, y, vx, vy]: H picks 0 and 1 (the general path) */
    const trk_real h[8] = {1, 0, 0, 0, 0, 1, 0, 0};
    const trk_real r_small[4] = {TRK_REAL_C(1e-4), 0, 0, TRK_REAL_C(1e-4)};
    trk_real x[4] = {0, 0, 1, 1}, p[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const trk_real z[4] = {TRK_REAL_C(0.001), TRK_REAL_C(0.001), TRK_REAL_MAX / 2, 0};
    trk_real beta[2];
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, h, r_small, x, p, 2, z, NULL, beta, NULL, NULL));
    assert_true(beta[1] == 0);
    /* clustered: eight detections at one point, R 1e-6, P ~ 1: the posterior
     * position variance against the closed form of one detection's update
     * repeated (all weights on one point: W = 0) */
    const trk_real r6[4] = {TRK_REAL_C(1e-6), 0, 0, TRK_REAL_C(1e-6)};
    trk_real xc[4], pc[16], zc[16], bc[8];
    prior(xc, pc);
    for (int i = 0; i < 8; i++) {
        zc[2 * i] = xc[TRK_CV2_X] + TRK_REAL_C(0.25);
        zc[2 * i + 1] = xc[TRK_CV2_Y] - TRK_REAL_C(0.5);
    }
    trk_real xk[4], pk[16];
    prior(xk, pk);
    struct trk_pda_report rep;
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, r6, xc, pc, 8, zc, NULL, bc, NULL, &rep));
    /* the same through the Kalman update and the PDA mixture by hand:
     * P = beta0 P- + (1 - beta0) P_c (+ beta0 (1 - beta0) dx dx') */
    TRK_ASSERT_OK(trk_kalman_update(4, 2, trk_cv2_h, r6, zc, xk, pk));
    trk_real xp[4], pp[16];
    prior(xp, pp);
    for (int i = 0; i < 16; i++) {
        const int a = i / 4, b = i % 4;
        const double dxa = (double)xk[a] - (double)xp[a], dxb = (double)xk[b] - (double)xp[b];
        const double b0 = (double)rep.beta0;
        const double want = b0 * (double)pp[i] + (1 - b0) * (double)pk[i] + b0 * (1 - b0) * dxa * dxb;
        /* float: 1e-3 of the entry (the cross-covariances here are 1e-5 of
         * P's scale, and the libm variant in use, FMA or not, moves them by
         * 2e-4 of themselves, 4e-9 absolute); the loss of digits this case
         * guards against is of the order of the entry itself */
        TRK_ASSERT_NEAR(pc[i], want, TRK_TOL(1e-9, 1e-3) * (1e-6 + fabs(want)), 0);
    }
    /* a subnormal pivot: diag(tiny, 1) is SPD */
    const trk_real tiny = TRK_REAL_MIN / 4;
    const trk_real a2[4] = {tiny, 0, 0, 1};
    TRK_ASSERT_OK(trk_mat_check_spd(2, a2, 0));
}

static void test_limits(void **state)
{
    (void)state;
    trk_real x[4], p[16], x0[4], p0[16], beta[1];
    struct trk_pda_report rep;
    /* no detections: posterior = prior, beta0 = 1 */
    struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.9), TRK_REAL_C(1e-3), 1);
    prior(x, p);
    prior(x0, p0);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 0, NULL, NULL, NULL, NULL, &rep));
    TRK_ASSERT_NEAR(rep.beta0, 1, 0, 0);
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(p[i], p0[i], TRK_TOL(1e-15, 1e-6), 0);
    /* pd = 1, lambda = 0, one detection: exactly the Kalman update */
    pda = make_pda(TRK_CLUTTER_PARAMETRIC, 1, 0, 1);
    const trk_real z[2] = {102, 49};
    prior(x, p);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 1, z, NULL, beta, NULL, &rep));
    TRK_ASSERT_NEAR(rep.beta0, 0, 0, 0);
    TRK_ASSERT_NEAR(beta[0], 1, 0, 0);
    TRK_ASSERT_OK(trk_kalman_update(4, 2, trk_cv2_h, R, z, x0, p0));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(x[i], x0[i], TRK_TOL(1e-12, 1e-4), 0);
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(p[i], p0[i], TRK_TOL(1e-12, 1e-4), 0);
}

static void test_amplitude_weights(void **state)
{
    (void)state;
    /* ln l^a shifts the weight of a detection: two symmetric detections get
     * beta ratio exp(lr1 - lr2) */
    struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.9), TRK_REAL_C(1e-3), 1);
    const trk_real z[4] = {101, 50, 99, 50}, lr[2] = {TRK_REAL_C(1.5), TRK_REAL_C(-0.5)};
    trk_real x[4], p[16], beta[2];
    prior(x, p);
    p[2] = p[8] = 0; /* symmetric in x */
    x[0] = 100;
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, z, lr, beta, NULL, NULL));
    TRK_ASSERT_NEAR(beta[0] / beta[1], exp(2.0), 0, TRK_TOL(1e-12, 1e-5));
    /* huge log-LR never overflows */
    const trk_real lr2[2] = {TRK_REAL_C(800.0) * (TRK_TEST_IS_FLOAT ? TRK_REAL_C(0.1) : 1), 0};
    prior(x, p);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, z, lr2, beta, NULL, NULL));
    TRK_ASSERT_NEAR(beta[0], 1, TRK_TOL(1e-15, 1e-6), 0);
}

static void test_nonparametric_and_include_all(void **state)
{
    (void)state;
    trk_real x[4], p[16], beta[2];
    struct trk_pda_report rep;
    const trk_real zout[4] = {200, 200, -100, 0};
    /* nonparametric with nothing in the gate: beta0 = 1 */
    struct trk_pda pda = make_pda(TRK_CLUTTER_NONPARAMETRIC, TRK_REAL_C(0.9), 0, 1);
    prior(x, p);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, zout, NULL, beta, NULL, &rep));
    TRK_ASSERT_NEAR(rep.beta0, 1, 0, 0);
    assert_int_equal(rep.n_gated, 0);
    /* include all: far detections get (tiny) weight, beta0 < 1 */
    pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.9), TRK_REAL_C(1e-30), 0);
    const trk_real zfar[2] = {112, 50};
    prior(x, p);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 1, zfar, NULL, beta, NULL, &rep));
    assert_int_equal(rep.n_gated, 0);
    assert_true(beta[0] > 0.5);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_pda pda;
    struct trk_pda_params pp = {2, TRK_REAL_C(0.9), TRK_REAL_C(0.99), TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(1e-3), 1};
    pp.pd = 0;
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_RANGE);
    pp.pd = TRK_REAL_C(1.1);
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_RANGE);
    pp.pd = NAN;
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_NAN);
    pp.pd = TRK_REAL_C(0.9);
    pp.clutter_density = -1;
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_RANGE);
    pp.clutter_density = TRK_REAL_C(1e-3);
    pp.gate_prob = 1;
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_RANGE);
    pp.gate_prob = TRK_REAL_C(0.99);
    pp.nz = 4;
    TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), TRK_E_ARG);
    pp.nz = 2;
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    trk_real x[4], p[16], x0[4], p0[16], beta[2];
    const trk_real z[4] = {100, NAN, 100, 50}, lr[2] = {0, INFINITY}, zok[4] = {100, 50, 100, 50};
    prior(x, p);
    prior(x0, p0);
    TRK_ASSERT_STATUS(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, z, NULL, beta, NULL, NULL), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, zok, lr, beta, NULL, NULL), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, TRK_MAX_DETECTIONS + 1, zok, NULL, beta, NULL, NULL),
                      TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, zok, NULL, NULL, NULL, NULL), TRK_E_ARG);
    p[0] = -50; /* S not SPD */
    TRK_ASSERT_STATUS(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 2, zok, NULL, beta, NULL, NULL), TRK_E_NOT_SPD);
    p[0] = p0[0];
    for (int i = 0; i < 4; i++) assert_true(x[i] == x0[i]);
    for (int i = 0; i < 16; i++) assert_true(p[i] == p0[i]);
}

/* trk_pda_update_inn with the innovation of trk_kalman_innovation gives
 * exactly what trk_pda_update gives; a missing or mismatched innovation is
 * refused. */
static void test_given_innovation(void **state)
{
    (void)state;
    struct trk_pda pda = make_pda(TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(0.8), TRK_REAL_C(0.01), 1);
    const trk_real z[10] = {101, 50, 97, 53, 104, 44, 100.5, 50.5, 130, 90}, lr[5] = {TRK_REAL_C(0.5), -1, 2, 0, 1};
    trk_real x[4], p[16], beta[5], d2[5], x2[4], p2[16], beta2[5], d22[5];
    struct trk_pda_report rep, rep2;
    struct trk_innovation inn;
    prior(x, p);
    prior(x2, p2);
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, R, x, p, 5, z, lr, beta, d2, &rep));
    TRK_ASSERT_OK(trk_kalman_innovation(4, 2, trk_cv2_h, R, x2, p2, &inn));
    TRK_ASSERT_OK(trk_pda_update_inn(&pda, 4, trk_cv2_h, R, x2, p2, &inn, 5, z, lr, beta2, d22, &rep2));
    for (int i = 0; i < 5; i++) assert_true(beta2[i] == beta[i] && d22[i] == d2[i]);
    for (int i = 0; i < 4; i++) assert_true(x2[i] == x[i]);
    for (int i = 0; i < 16; i++) assert_true(p2[i] == p[i]);
    assert_true(rep2.beta0 == rep.beta0 && rep2.gate_volume == rep.gate_volume && rep2.n_gated == rep.n_gated);
    TRK_ASSERT_NEAR(rep.gate_volume, trk_gate_volume_inn(&inn, pda.gamma), 0, 0);
    TRK_ASSERT_STATUS(trk_pda_update_inn(&pda, 4, trk_cv2_h, R, x2, p2, NULL, 5, z, lr, beta2, NULL, NULL), TRK_E_ARG);
    inn.nz = 1;
    TRK_ASSERT_STATUS(trk_pda_update_inn(&pda, 4, trk_cv2_h, R, x2, p2, &inn, 5, z, lr, beta2, NULL, NULL), TRK_E_ARG);
    for (int i = 0; i < 4; i++) assert_true(x2[i] == x[i]);
}

/* trk_pda_check_params names the field trk_pda_init refuses. */
static void test_check_params(void **state)
{
    (void)state;
    const struct trk_pda_params ok = {2, TRK_REAL_C(0.9), TRK_REAL_C(0.99), TRK_CLUTTER_PARAMETRIC, TRK_REAL_C(1e-3), 1};
    const char *field = "(not set)";
    TRK_ASSERT_OK(trk_pda_check_params(&ok, &field));
    assert_null(field);
    struct trk_pda_params pp = ok;
    struct trk_pda pda;
#define REFUSE(member, value, name, status)                              \
    do {                                                                 \
        pp = ok;                                                         \
        pp.member = value;                                               \
        TRK_ASSERT_STATUS(trk_pda_check_params(&pp, &field), status);    \
        assert_string_equal(field, name);                                \
        TRK_ASSERT_STATUS(trk_pda_init(&pda, &pp), status);              \
    } while (0)
    REFUSE(nz, 0, "nz", TRK_E_ARG);
    REFUSE(clutter, (enum trk_clutter_mode)5, "clutter", TRK_E_ARG);
    REFUSE(gating, 2, "gating", TRK_E_ARG);
    REFUSE(pd, 0, "pd", TRK_E_RANGE);
    REFUSE(pd, NAN, "pd", TRK_E_NAN);
    REFUSE(gate_prob, 1, "gate_prob", TRK_E_RANGE);
    REFUSE(gate_prob, NAN, "gate_prob", TRK_E_NAN);
    REFUSE(clutter_density, -1, "clutter_density", TRK_E_RANGE);
    REFUSE(clutter_density, (trk_real)INFINITY, "clutter_density", TRK_E_NAN);
#undef REFUSE
    TRK_ASSERT_STATUS(trk_pda_check_params(NULL, &field), TRK_E_ARG);
    assert_string_equal(field, "params");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_invariants),
        cmocka_unit_test(test_cv_fast_path),
        cmocka_unit_test(test_cv_own_path),
        cmocka_unit_test(test_review_cases),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_amplitude_weights),
        cmocka_unit_test(test_nonparametric_and_include_all),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_given_innovation),
        cmocka_unit_test(test_check_params),
    };
    return trk_run_tests("pda", tests, NULL, NULL);
}
