/* test_jpda.c - JPDA / JIPDA marginals (trk/jpda.h) against a brute-force
 * enumeration of every joint event written here independently; clusters;
 * both exact orientations; the belief-propagation fallback (exact on a
 * cluster without cycles, close on a loopy one); the existence update's
 * closed forms; bad input. */
#include "trk_test.h"
#include "trk/jpda.h"

#define MAXT 6
#define MAXD 9

static struct trk_jpda_work work;

/* ------------------------------------------------------------ brute force */

struct problem {
    size_t nt, nd;
    double lw0[MAXT];
    double lw[MAXT * MAXD]; /* -INFINITY: not gated */
};

/* every event by recursion over tracks (test code: depth <= MAXT), in the
 * log domain: a first pass finds the largest event log-weight (*lmax), the
 * second accumulates exp(lw - lmax) */
struct acc {
    double *pa, *pm, z, lmax;
    int pass;
};

static void enumerate(const struct problem *p, size_t t, unsigned used, double lw, int *assign, struct acc *a)
{
    if (t == p->nt) {
        if (a->pass == 0) {
            if (lw > a->lmax) a->lmax = lw;
            return;
        }
        const double w = exp(lw - a->lmax);
        a->z += w;
        for (size_t k = 0; k < p->nt; k++) {
            if (assign[k] < 0) a->pm[k] += w;
            else a->pa[k * p->nd + (size_t)assign[k]] += w;
        }
        return;
    }
    assign[t] = -1;
    enumerate(p, t + 1, used, lw + p->lw0[t], assign, a);
    for (size_t j = 0; j < p->nd; j++) {
        if ((used >> j) & 1u || !isfinite(p->lw[t * p->nd + j])) continue;
        assign[t] = (int)j;
        enumerate(p, t + 1, used | (1u << j), lw + p->lw[t * p->nd + j], assign, a);
    }
}

static void brute(const struct problem *p, double *pa, double *pm)
{
    int assign[MAXT];
    struct acc a = {pa, pm, 0, -INFINITY, 0};
    memset(pa, 0, sizeof(double) * p->nt * p->nd);
    memset(pm, 0, sizeof(double) * p->nt);
    enumerate(p, 0, 0, 0, assign, &a);
    a.pass = 1;
    enumerate(p, 0, 0, 0, assign, &a);
    for (size_t k = 0; k < p->nt * p->nd; k++) pa[k] /= a.z;
    for (size_t k = 0; k < p->nt; k++) pm[k] /= a.z;
}

static uint32_t lcg = 12345u;
static double urand(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (double)(lcg >> 8) / 16777216.0;
}

/* random problem: gate density, log-weights spread over `spread` nats */
static void random_problem(struct problem *p, size_t nt, size_t nd, double density, double spread)
{
    p->nt = nt;
    p->nd = nd;
    for (size_t t = 0; t < nt; t++) {
        p->lw0[t] = log(0.05 + 0.9 * urand());
        for (size_t j = 0; j < nd; j++)
            p->lw[t * nd + j] = urand() < density ? spread * (urand() - 0.5) : -INFINITY;
    }
}

static void run(const struct problem *p, trk_real *pa, trk_real *pm, struct trk_jpda_report *rep)
{
    static trk_real lw0[MAXT], lw[MAXT * MAXD];
    for (size_t t = 0; t < p->nt; t++) lw0[t] = (trk_real)p->lw0[t];
    for (size_t k = 0; k < p->nt * p->nd; k++) lw[k] = (trk_real)p->lw[k];
    struct trk_jpda_scan s = {p->nt, p->nd, lw0, lw};
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, rep));
}

static void compare(const struct problem *p, double tol)
{
    double ba[MAXT * MAXD], bm[MAXT];
    trk_real pa[MAXT * MAXD], pm[MAXT];
    struct trk_jpda_report rep;
    brute(p, ba, bm);
    run(p, pa, pm, &rep);
    assert_int_equal(rep.n_approx, 0);
    for (size_t t = 0; t < p->nt; t++) {
        double row = pm[t];
        TRK_ASSERT_NEAR(pm[t], bm[t], tol, tol);
        for (size_t j = 0; j < p->nd; j++) {
            TRK_ASSERT_NEAR(pa[t * p->nd + j], ba[t * p->nd + j], tol, tol);
            if (!isfinite(p->lw[t * p->nd + j])) assert_true(pa[t * p->nd + j] == 0);
            row += pa[t * p->nd + j];
        }
        TRK_ASSERT_NEAR(row, 1, tol, 0);
    }
}

/* ------------------------------------------------------------ tests */

/* Random clusters of every shape up to 6 x 9 match the enumeration: both
 * exact orientations are taken (more tracks than detections and fewer). */
static void test_exact_matches_enumeration(void **state)
{
    (void)state;
    const double tol = TRK_TOL(1e-12, 2e-5);
    struct problem p;
    for (int rep = 0; rep < 300; rep++) {
        const size_t nt = 1 + (size_t)(urand() * MAXT), nd = (size_t)(urand() * (MAXD + 1));
        random_problem(&p, nt, nd > MAXD ? MAXD : nd, 0.2 + 0.8 * urand(), 8);
        compare(&p, tol);
    }
}

/* Weights spanning hundreds of decades (double) do not overflow or
 * underflow the programme: per-track scaling and layer rescaling. */
static void test_wide_dynamic_range(void **state)
{
    (void)state;
    struct problem p;
    for (int rep = 0; rep < 50; rep++) {
        random_problem(&p, 4, 5, 0.9, TRK_TEST_IS_FLOAT ? 60 : 600);
        compare(&p, TRK_TOL(1e-10, 1e-4));
    }
}

/* Events beyond the arithmetic: tracks whose misses lie e^-800 (double;
 * e^-120 in float) below their one gated weight, every track on the same
 * detection(s). Each track's scaled miss underflows to 0, every joint event
 * then weighs 0 and the marginals were 0 / 0 (tracks ended as numerical in
 * the track table). Now the cluster is solved again with floored weights
 * (n_floored): finite marginals, each track's summing to 1, and for the
 * symmetric cluster its exact value by symmetry. Two tracks (the closed
 * form), four on two detections (the exact programme). */
static void test_events_beyond_range(void **state)
{
    (void)state;
    const double deep = TRK_TEST_IS_FLOAT ? -120 : -800; /* past the subnormals: e^-103, e^-745 */
    for (int shape = 0; shape < 2; shape++) {
        struct problem p;
        p.nt = shape ? 4 : 2;
        p.nd = shape ? 2 : 1;
        for (size_t t = 0; t < p.nt; t++) {
            p.lw0[t] = deep;
            for (size_t j = 0; j < p.nd; j++) p.lw[t * p.nd + j] = 0;
        }
        trk_real pa[MAXT * MAXD], pm[MAXT];
        struct trk_jpda_report rep;
        run(&p, pa, pm, &rep);
        assert_int_equal(rep.n_floored, 1);
        assert_int_equal(rep.n_clusters, 1);
        assert_int_equal(rep.n_approx, 1);
        assert_int_equal(rep.n_exact, 0);
        for (size_t t = 0; t < p.nt; t++) {
            double row = pm[t];
            assert_true(isfinite(pm[t]) && pm[t] >= 0);
            for (size_t j = 0; j < p.nd; j++) {
                assert_true(isfinite(pa[t * p.nd + j]) && pa[t * p.nd + j] >= 0);
                row += pa[t * p.nd + j];
                /* n_d of the n_t tracks take a detection, each of them alike */
                TRK_ASSERT_NEAR(pa[t * p.nd + j], 1.0 / (double)p.nt, 1e-6, 0);
            }
            TRK_ASSERT_NEAR(row, 1, TRK_TOL(1e-12, 1e-5), 0);
        }
    }
    /* within the range nothing is floored */
    struct problem q;
    random_problem(&q, 4, 5, 0.9, TRK_TEST_IS_FLOAT ? 60 : 600);
    trk_real pa[MAXT * MAXD], pm[MAXT];
    struct trk_jpda_report rep;
    run(&q, pa, pm, &rep);
    assert_int_equal(rep.n_floored, 0);
}

/* Two tracks (their closed form): random gates, weights over hundreds of
 * decades, and both tracks on one dominant shared detection with every
 * other weight and the misses far below it, where a form that subtracts
 * the shared events from W_1 W_2 cancels; every marginal, however small,
 * to the working precision (relative). */
static void test_two_tracks(void **state)
{
    (void)state;
    const double spread = TRK_TEST_IS_FLOAT ? 60 : 600, tiny = TRK_TEST_IS_FLOAT ? -40 : -300;
    struct problem p;
    for (int rep = 0; rep < 100; rep++) {
        random_problem(&p, 2, 1 + (size_t)(urand() * MAXD) % MAXD, 0.3 + 0.7 * urand(), spread);
        compare(&p, TRK_TOL(1e-12, 1e-4));
    }
    for (int rep = 0; rep < 20; rep++) {
        p.nt = 2;
        p.nd = 2 + (size_t)rep % (MAXD - 1);
        for (size_t t = 0; t < 2; t++) {
            p.lw0[t] = tiny + urand();
            for (size_t j = 0; j < p.nd; j++) p.lw[t * p.nd + j] = j == 0 ? urand() : tiny + 10 * urand();
        }
        double ba[MAXT * MAXD], bm[MAXT];
        trk_real pa[MAXT * MAXD], pm[MAXT];
        struct trk_jpda_report rep_out;
        brute(&p, ba, bm);
        run(&p, pa, pm, &rep_out);
        assert_int_equal(rep_out.n_exact, 1);
        for (size_t t = 0; t < 2; t++) {
            TRK_ASSERT_NEAR(pm[t], bm[t], 0, TRK_TOL(1e-12, 1e-4));
            for (size_t j = 0; j < p.nd; j++) TRK_ASSERT_NEAR(pa[t * p.nd + j], ba[t * p.nd + j], 0, TRK_TOL(1e-12, 1e-4));
        }
    }
}

/* One track: the PDA weights w_j / (w_0 + sum w). */
static void test_single_track_is_pda(void **state)
{
    (void)state;
    const trk_real lw0[1] = {(trk_real)log(0.3)};
    const trk_real lw[4] = {(trk_real)log(2.0), -(trk_real)INFINITY, (trk_real)log(0.5), 0};
    struct trk_jpda_scan s = {1, 4, lw0, lw};
    trk_real pa[4], pm[1];
    struct trk_jpda_report rep;
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, &rep));
    const double z = 0.3 + 2.0 + 0.5 + 1.0;
    TRK_ASSERT_NEAR(pm[0], 0.3 / z, 1e-6, 1e-6);
    TRK_ASSERT_NEAR(pa[0], 2.0 / z, 1e-6, 1e-6);
    assert_true(pa[1] == 0);
    TRK_ASSERT_NEAR(pa[2], 0.5 / z, 1e-6, 1e-6);
    TRK_ASSERT_NEAR(pa[3], 1.0 / z, 1e-6, 1e-6);
    assert_int_equal(rep.n_clusters, 1);
    assert_int_equal(rep.n_exact, 1);
}

/* Two tracks sharing nothing form two clusters and are independent PDAs;
 * a track gating nothing is its own cluster with P(none) = 1. */
static void test_clusters(void **state)
{
    (void)state;
    const trk_real ninf = -(trk_real)INFINITY;
    const trk_real lw0[3] = {-1, -2, -0.5};
    const trk_real lw[3 * 3] = {0, ninf, ninf, ninf, 1, 2, ninf, ninf, ninf};
    struct trk_jpda_scan s = {3, 3, lw0, lw};
    trk_real pa[9], pm[3];
    struct trk_jpda_report rep;
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, &rep));
    assert_int_equal(rep.n_clusters, 3);
    assert_int_equal(rep.largest_tracks, 1);
    assert_int_equal(rep.largest_dets, 2);
    TRK_ASSERT_NEAR(pa[0], 1 / (1 + exp(-1.0)), 1e-6, 1e-6);
    const double z1 = exp(-2.0) + exp(1.0) + exp(2.0);
    TRK_ASSERT_NEAR(pa[4], exp(1.0) / z1, 1e-6, 1e-6);
    TRK_ASSERT_NEAR(pa[5], exp(2.0) / z1, 1e-6, 1e-6);
    TRK_ASSERT_NEAR(pm[2], 1, 0, 0);
    /* no detections at all */
    struct trk_jpda_scan e = {3, 0, lw0, NULL};
    TRK_ASSERT_OK(trk_jpda_marginals(&e, &work, NULL, pm, &rep));
    for (int t = 0; t < 3; t++) TRK_ASSERT_NEAR(pm[t], 1, 0, 0);
}

/* Two identical tracks on the same detections: symmetric marginals. */
static void test_symmetry(void **state)
{
    (void)state;
    const trk_real lw0[2] = {-0.7f, -0.7f};
    const trk_real lw[2 * 3] = {1, 0.2f, -1, 1, 0.2f, -1};
    struct trk_jpda_scan s = {2, 3, lw0, lw};
    trk_real pa[6], pm[2];
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, NULL));
    for (int j = 0; j < 3; j++) TRK_ASSERT_NEAR(pa[j], pa[3 + j], 1e-6, 1e-6);
    TRK_ASSERT_NEAR(pm[0], pm[1], 1e-6, 1e-6);
}

/* A cluster beyond the exact bound (12 tracks x 12 detections: both
 * orientations would need 2^12 states) takes belief propagation, counted in
 * the report. On a chain-shaped (acyclic) gate matrix belief propagation is
 * exact: checked against a transfer-matrix recursion written here, with the
 * detections' weights near the misses' (strength 0) and e^18.5 above them
 * (a strong return in sparse clutter: the leave-one-out sums then cancelled
 * to 0 in float and the cluster became NaN, reported as converged). */
static void lbp_chain(double strength)
{
    enum { N = 12 };
    static trk_real lw0[N], lw[N * N], pa[N * N], pm[N];
    if (TRK_MAX_TRACKS < N || TRK_MAX_DETECTIONS < N) skip(); /* a small-capacity build */
    /* a chain: track t gates detections t and t+1 (no cycle) */
    for (int t = 0; t < N; t++) {
        lw0[t] = (trk_real)log(0.2 + 0.05 * t);
        for (int j = 0; j < N; j++)
            lw[t * N + j] = (j == t || j == t + 1) ? (trk_real)(strength + 0.3 * ((t + j) % 5) - 0.5) : -(trk_real)INFINITY;
    }
    struct trk_jpda_scan s = {N, N, lw0, lw};
    struct trk_jpda_report rep;
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, &rep));
    assert_int_equal(rep.n_clusters, 1);
    assert_int_equal(rep.largest_tracks, N);
    assert_int_equal(rep.n_approx, 1);
    assert_true(rep.lbp_converged);
    assert_true(rep.lbp_iterations > 1 && rep.lbp_iterations <= TRK_JPDA_LBP_MAX_ITER);
    /* exact reference: the same chain, split where it can be: enumerate the
     * chain's marginals by a transfer-matrix recursion written here. */
    double fwd[N + 2][2], bwd[N + 2][2]; /* state: is detection t taken by track t-1 (1) or not (0) */
    /* forward over tracks: track t takes none, det t (if free), or det t+1 */
    fwd[0][0] = 1, fwd[0][1] = 0;
    for (int t = 0; t < N; t++) {
        const double w0 = exp(lw0[t]), wa = exp(lw[t * N + t]), wb = t + 1 < N ? exp(lw[t * N + t + 1]) : 0;
        const double free_t = fwd[t][0], taken_t = fwd[t][1];
        fwd[t + 1][0] = (free_t + taken_t) * w0 + free_t * wa;
        fwd[t + 1][1] = (free_t + taken_t) * wb;
    }
    bwd[N][0] = bwd[N][1] = 1;
    for (int t = N - 1; t >= 0; t--) {
        const double w0 = exp(lw0[t]), wa = exp(lw[t * N + t]), wb = t + 1 < N ? exp(lw[t * N + t + 1]) : 0;
        bwd[t][0] = w0 * bwd[t + 1][0] + wa * bwd[t + 1][0] + wb * bwd[t + 1][1];
        bwd[t][1] = w0 * bwd[t + 1][0] + wb * bwd[t + 1][1];
    }
    const double z = fwd[N][0] + fwd[N][1];
    for (int t = 0; t < N; t++) {
        const double w0 = exp(lw0[t]), wa = exp(lw[t * N + t]);
        const double p_none = (fwd[t][0] + fwd[t][1]) * w0 * bwd[t + 1][0] / z;
        const double p_a = fwd[t][0] * wa * bwd[t + 1][0] / z;
        TRK_ASSERT_NEAR(pm[t], p_none, TRK_TOL(1e-5, 1e-4), 0);
        TRK_ASSERT_NEAR(pa[t * N + t], p_a, TRK_TOL(1e-5, 1e-4), 0);
        double row = pm[t];
        for (int j = 0; j < N; j++) row += pa[t * N + j];
        TRK_ASSERT_NEAR(row, 1, 1e-5, 0);
    }
}

static void test_lbp_fallback(void **state)
{
    (void)state;
    lbp_chain(0);
    lbp_chain(18.5);
}

/* On a loopy dense cluster beyond the bound (14 x 14, half the pairs gated)
 * the approximation is still a distribution per track, and no detection is
 * given away more than once in total. */
static void test_lbp_rows_are_distributions(void **state)
{
    (void)state;
    enum { N = 14, M = 14 };
    static trk_real lw0[N], lw[N * M], pa[N * M], pm[N];
    if (TRK_MAX_TRACKS < N || TRK_MAX_DETECTIONS < M) skip(); /* a small-capacity build */
    for (int t = 0; t < N; t++) {
        lw0[t] = (trk_real)log(0.1 + 0.8 * urand());
        for (int j = 0; j < M; j++) lw[t * M + j] = urand() < 0.5 ? (trk_real)(4 * (urand() - 0.5)) : -(trk_real)INFINITY;
    }
    struct trk_jpda_scan s = {N, M, lw0, lw};
    struct trk_jpda_report rep;
    TRK_ASSERT_OK(trk_jpda_marginals(&s, &work, pa, pm, &rep));
    assert_true(rep.n_approx >= 1);
    for (int t = 0; t < N; t++) {
        double row = pm[t];
        assert_true(pm[t] >= 0 && pm[t] <= 1);
        for (int j = 0; j < M; j++) {
            assert_true(pa[t * M + j] >= 0 && pa[t * M + j] <= 1);
            row += pa[t * M + j];
        }
        TRK_ASSERT_NEAR(row, 1, 1e-5, 0);
    }
    /* a detection's total over tracks is at most 1 (approximately) */
    for (int j = 0; j < M; j++) {
        double col = 0;
        for (int t = 0; t < N; t++) col += pa[t * M + j];
        assert_true(col <= 1 + 1e-4);
    }
}

/* The existence update: plain JPDA (psi = 1) keeps psi' = 1 and beta = the
 * marginals; JIPDA's closed form for one track with no detection:
 * psi' = psi (1 - pd pg) / (1 - pd pg psi). */
static void test_existence(void **state)
{
    (void)state;
    const trk_real pa[2] = {0.5f, 0.25f};
    trk_real post, beta[3];
    TRK_ASSERT_OK(trk_jpda_existence(1, 0.9f, pa, 2, 0.25f, &post, beta));
    TRK_ASSERT_NEAR(post, 1, 1e-6, 0);
    TRK_ASSERT_NEAR(beta[0], 0.25, 1e-6, 0);
    TRK_ASSERT_NEAR(beta[1], 0.5, 1e-6, 0);
    TRK_ASSERT_NEAR(beta[2], 0.25, 1e-6, 0);
    /* no detection at all: P(none) = 1 */
    TRK_ASSERT_OK(trk_jpda_existence(0.6f, 0.9f, NULL, 0, 1, &post, beta));
    TRK_ASSERT_NEAR(post, 0.6 * 0.1 / (1 - 0.9 * 0.6), 1e-6, 1e-6);
    TRK_ASSERT_NEAR(beta[0], 1, 1e-6, 0);
    /* a general case: betas sum to 1 */
    const trk_real pb[2] = {0.3f, 0.1f};
    TRK_ASSERT_OK(trk_jpda_existence(0.5f, 0.8f, pb, 2, 0.6f, &post, beta));
    const double me = 0.6 * 0.5 * 0.2 / (1 - 0.8 * 0.5);
    TRK_ASSERT_NEAR(post, 0.4 + me, 1e-6, 1e-6);
    TRK_ASSERT_NEAR(beta[0] + beta[1] + beta[2], 1, 1e-6, 0);
    TRK_ASSERT_NEAR(beta[1], 0.3 / (0.4 + me), 1e-6, 1e-6);
}

static void test_bad_input(void **state)
{
    (void)state;
    const trk_real lw0[2] = {-1, -1};
    trk_real lw[4] = {0, 0, 0, 0}, pa[4], pm[2], post, beta[3];
    struct trk_jpda_scan s = {2, 2, lw0, lw};
    TRK_ASSERT_STATUS(trk_jpda_marginals(NULL, &work, pa, pm, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s, NULL, pa, pm, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s, &work, NULL, pm, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s, &work, pa, NULL, NULL), TRK_E_ARG);
    lw[1] = (trk_real)NAN;
    pa[0] = 42;
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s, &work, pa, pm, NULL), TRK_E_NAN);
    assert_true(pa[0] == 42); /* untouched on error */
    lw[1] = (trk_real)INFINITY;
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s, &work, pa, pm, NULL), TRK_E_RANGE);
    const trk_real bad0[2] = {-(trk_real)INFINITY, 0};
    struct trk_jpda_scan s0 = {2, 2, bad0, lw};
    lw[1] = 0;
    TRK_ASSERT_STATUS(trk_jpda_marginals(&s0, &work, pa, pm, NULL), TRK_E_NAN);
    struct trk_jpda_scan big = {TRK_MAX_TRACKS + 1, 2, lw0, lw};
    TRK_ASSERT_STATUS(trk_jpda_marginals(&big, &work, pa, pm, NULL), TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_jpda_existence(0, 0.9f, pa, 2, 0.1f, &post, beta), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_jpda_existence(1.5f, 0.9f, pa, 2, 0.1f, &post, beta), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_jpda_existence((trk_real)NAN, 0.9f, pa, 2, 0.1f, &post, beta), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_jpda_existence(0.5f, 0.9f, NULL, 2, 0.1f, &post, beta), TRK_E_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_matches_enumeration),
        cmocka_unit_test(test_wide_dynamic_range),
        cmocka_unit_test(test_events_beyond_range),
        cmocka_unit_test(test_two_tracks),
        cmocka_unit_test(test_single_track_is_pda),
        cmocka_unit_test(test_clusters),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_lbp_fallback),
        cmocka_unit_test(test_lbp_rows_are_distributions),
        cmocka_unit_test(test_existence),
        cmocka_unit_test(test_bad_input),
    };
    return trk_run_tests("jpda", tests, NULL, NULL);
}
