/* test_gospa.c - GOSPA and its assignment (tools/sim/gospa.h): closed forms,
 * the Hungarian method against every permutation, GOSPA against every
 * partial assignment, and bad arguments. */
#include "trk_test.h"
#include "gospa.h"

static uint32_t lcg = 777u;
static double urand(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (double)(lcg >> 8) / 16777216.0;
}

/* smallest sum over injective maps rows -> cols, by recursion (test code) */
static double best_perm(const double *c, size_t rows, size_t cols, size_t i, unsigned used)
{
    if (i == rows) return 0;
    double best = INFINITY;
    for (size_t j = 0; j < cols; j++) {
        if (used & (1u << j)) continue;
        const double v = c[i * cols + j] + best_perm(c, rows, cols, i + 1, used | (1u << j));
        if (v < best) best = v;
    }
    return best;
}

/* GOSPA^p by every partial assignment with pairs d < c only */
static double best_gospa_p(const double *d, size_t n, size_t m, double c, double p, size_t i, unsigned used,
                           size_t pairs)
{
    if (i == n) return pow(c, p) / 2 * (double)(n + m - 2 * pairs);
    double best = best_gospa_p(d, n, m, c, p, i + 1, used, pairs);
    for (size_t j = 0; j < m; j++) {
        if ((used & (1u << j)) || !(d[i * m + j] < c)) continue;
        const double v = pow(d[i * m + j], p) + best_gospa_p(d, n, m, c, p, i + 1, used | (1u << j), pairs + 1);
        if (v < best) best = v;
    }
    return best;
}

static void test_hungarian_is_optimal(void **state)
{
    (void)state;
    double c[7 * 8];
    long col[7];
    for (int rep = 0; rep < 400; rep++) {
        const size_t rows = 1 + (size_t)(urand() * 6), cols = rows + (size_t)(urand() * 3);
        for (size_t k = 0; k < rows * cols; k++) c[k] = urand() < 0.1 ? 0 : 10 * urand();
        const double got = hungarian(c, rows, cols, col);
        TRK_ASSERT_NEAR(got, best_perm(c, rows, cols, 0, 0), 1e-12, 1e-12);
        /* a valid injective map whose cost is the returned total */
        double sum = 0;
        unsigned seen = 0;
        for (size_t i = 0; i < rows; i++) {
            assert_true(col[i] >= 0 && (size_t)col[i] < cols);
            assert_false(seen & (1u << col[i]));
            seen |= 1u << col[i];
            sum += c[i * cols + (size_t)col[i]];
        }
        TRK_ASSERT_NEAR(sum, got, 1e-12, 1e-12);
    }
}

static void test_gospa_matches_enumeration(void **state)
{
    (void)state;
    double d[6 * 6];
    long assign[6];
    struct gospa_result r;
    for (int rep = 0; rep < 400; rep++) {
        const size_t n = (size_t)(urand() * 6), m = (size_t)(urand() * 6);
        const double c = 1 + 9 * urand(), p = urand() < 0.5 ? 2 : 1 + 2 * urand();
        for (size_t k = 0; k < n * m; k++) d[k] = 12 * urand();
        assert_int_equal(gospa(d, n, m, c, p, assign, &r), 0);
        const double want = best_gospa_p(d, n, m, c, p, 0, 0, 0);
        TRK_ASSERT_NEAR(pow(r.gospa, p), want, 1e-9, 1e-9);
        TRK_ASSERT_NEAR(r.loc + r.missed + r.false_, want, 1e-9, 1e-9);
        assert_int_equal(r.n_missed + r.n_assigned, n);
        assert_int_equal(r.n_false + r.n_assigned, m);
        double loc = 0;
        size_t pairs = 0;
        for (size_t i = 0; i < n; i++)
            if (assign[i] >= 0) {
                assert_true(d[i * m + (size_t)assign[i]] < c);
                loc += pow(d[i * m + (size_t)assign[i]], p);
                pairs++;
            }
        assert_int_equal(pairs, r.n_assigned);
        TRK_ASSERT_NEAR(loc, r.loc, 1e-9, 1e-9);
    }
}

static void test_closed_forms(void **state)
{
    (void)state;
    struct gospa_result r;
    long a[3];
    assert_int_equal(gospa(NULL, 0, 0, 10, 2, NULL, &r), 0);
    TRK_ASSERT_NEAR(r.gospa, 0, 0, 0);
    /* three missed targets: (c^2 / 2 * 3)^(1/2) */
    assert_int_equal(gospa(NULL, 3, 0, 10, 2, a, &r), 0);
    TRK_ASSERT_NEAR(r.gospa, sqrt(150.0), 1e-12, 1e-12);
    assert_int_equal(r.n_missed, 3);
    assert_true(a[0] == -1 && a[1] == -1 && a[2] == -1);
    /* one pair at 3 m, cut-off 10: GOSPA 3, all localisation */
    const double one = 3;
    assert_int_equal(gospa(&one, 1, 1, 10, 2, a, &r), 0);
    TRK_ASSERT_NEAR(r.gospa, 3, 1e-12, 0);
    TRK_ASSERT_NEAR(r.loc, 9, 1e-12, 0);
    assert_int_equal(a[0], 0);
    /* the same pair beyond the cut-off: a miss and a false estimate, GOSPA c */
    const double far = 30;
    assert_int_equal(gospa(&far, 1, 1, 10, 2, a, &r), 0);
    TRK_ASSERT_NEAR(r.gospa, 10, 1e-12, 0);
    assert_int_equal(r.n_missed, 1);
    assert_int_equal(r.n_false, 1);
    assert_int_equal(a[0], -1);
    /* two targets, two estimates crossed: the assignment swaps */
    const double d[4] = {5, 1, 1, 5};
    assert_int_equal(gospa(d, 2, 2, 10, 2, a, &r), 0);
    assert_true(a[0] == 1 && a[1] == 0);
    TRK_ASSERT_NEAR(r.gospa, sqrt(2.0), 1e-12, 0);
}

static void test_bad_arguments(void **state)
{
    (void)state;
    struct gospa_result r;
    const double d[2] = {1, NAN}, neg[1] = {-1};
    assert_int_equal(gospa(d, 1, 2, 10, 2, NULL, &r), -1);
    assert_int_equal(gospa(neg, 1, 1, 10, 2, NULL, &r), -1);
    assert_int_equal(gospa(d, 1, 1, 0, 2, NULL, &r), -1);
    assert_int_equal(gospa(d, 1, 1, 10, 0.5, NULL, &r), -1);
    assert_int_equal(gospa(NULL, 1, 1, 10, 2, NULL, &r), -1);
    assert_int_equal(gospa(d, 1, 1, 10, 2, NULL, NULL), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hungarian_is_optimal),
        cmocka_unit_test(test_gospa_matches_enumeration),
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_bad_arguments),
    };
    return trk_run_tests("gospa", tests, NULL, NULL);
}
