/* test_grid.c - the 2-D index of gating and initiation (src/grid_impl.h):
 * the fill is a stable permutation into the cells, and a box query with the
 * caller's exact test returns exactly the points a scan of all of them
 * finds, for point sets of every shape (square, a strip, one row, one
 * column, one point, coincident points, coordinates near the largest real)
 * and boxes of every size, NaN and reversed bounds (empty). */
#include "trk_test.h"
#include "../src/grid_impl.h"

enum { N_MAX = 512 };

static uint64_t rng_state;
static double urand(void) { return trk_test_urand(&rng_state); }

static trk_real px[N_MAX], py[N_MAX];
static uint16_t idx[N_MAX], end_[N_MAX], cell[N_MAX], tmp[N_MAX];
static uint8_t seen[N_MAX];

/* Index points 0 .. n-1; check the permutation, the cells and stability. */
static void index_points(struct trk_i_grid *g, size_t n)
{
    trk_real lo_x = px[0], hi_x = px[0], lo_y = py[0], hi_y = py[0];
    for (size_t i = 0; i < n; i++) {
        idx[i] = (uint16_t)i;
        lo_x = px[i] < lo_x ? px[i] : lo_x;
        hi_x = px[i] > hi_x ? px[i] : hi_x;
        lo_y = py[i] < lo_y ? py[i] : lo_y;
        hi_y = py[i] > hi_y ? py[i] : hi_y;
    }
    trk_i_grid_plan(g, n, lo_x, hi_x, lo_y, hi_y);
    const size_t n_cell = (size_t)g->n_col * g->n_row;
    assert_true(n_cell >= 1 && n_cell <= (n > 1 ? n : 1));
    trk_i_grid_fill(g, px, py, idx, n, end_, cell, tmp);
    memset(seen, 0, sizeof seen);
    for (size_t c = 0, i = 0; c < n_cell; c++) {
        assert_true(end_[c] >= i);
        for (size_t i0 = i; i < end_[c]; i++) {
            assert_int_equal(seen[idx[i]], 0);
            seen[idx[i]] = 1;
            assert_int_equal(trk_i_grid_cell(g, px[idx[i]], py[idx[i]]), c);
            if (i > i0) assert_true(idx[i] > idx[i - 1]); /* stable: given order within a cell */
        }
    }
    assert_int_equal(end_[n_cell - 1], n);
}

/* The query's points passing the exact box test are the brute force's. */
static void check_box(const struct trk_i_grid *g, size_t n, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                      trk_real hi_y)
{
    size_t want = 0, got = 0;
    for (size_t i = 0; i < n; i++) want += px[i] >= lo_x && px[i] <= hi_x && py[i] >= lo_y && py[i] <= hi_y;
    struct trk_i_grid_box b = trk_i_grid_box(g, end_, lo_x, hi_x, lo_y, hi_y);
    size_t j0, j1;
    memset(seen, 0, sizeof seen);
    while (trk_i_grid_next(&b, &j0, &j1)) {
        assert_true(j0 < j1 && j1 <= n);
        for (size_t j = j0; j < j1; j++) {
            const size_t i = idx[j];
            assert_int_equal(seen[i], 0); /* each point once */
            seen[i] = 1;
            got += px[i] >= lo_x && px[i] <= hi_x && py[i] >= lo_y && py[i] <= hi_y;
        }
    }
    assert_int_equal(got, want);
}

/* Random boxes around random points, of sizes from 0 to the whole set. */
static void check_boxes(const struct trk_i_grid *g, size_t n, double span)
{
    for (int k = 0; k < 200; k++) {
        const size_t i = (size_t)(urand() * (double)n) % n;
        const double w = span * pow(10.0, -4.0 * urand()), h = k % 7 == 0 ? 0 : span * pow(10.0, -4.0 * urand());
        check_box(g, n, (trk_real)(px[i] - w), (trk_real)(px[i] + w), (trk_real)(py[i] - h), (trk_real)(py[i] + h));
    }
    check_box(g, n, -TRK_REAL_MAX, TRK_REAL_MAX, -TRK_REAL_MAX, TRK_REAL_MAX);
}

static void test_shapes(void **state)
{
    (void)state;
    rng_state = 11;
    struct trk_i_grid g;
    static const size_t sizes[] = {1, 2, 3, 17, 256, N_MAX};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        const size_t n = sizes[s];
        for (int shape = 0; shape < 6; shape++) {
            for (size_t i = 0; i < n; i++) {
                const double u = urand(), v = urand();
                switch (shape) {
                case 0: px[i] = (trk_real)(1000 * u), py[i] = (trk_real)(1000 * v); break;        /* square */
                case 1: px[i] = (trk_real)(1e5 * u), py[i] = (trk_real)(10 * v); break;           /* a strip in x */
                case 2: px[i] = (trk_real)(3 * u), py[i] = (trk_real)(-4e4 * v); break;           /* a strip in y */
                case 3: px[i] = (trk_real)(500 * u), py[i] = 7; break;                            /* one row */
                case 4: px[i] = (trk_real)(i % 3), py[i] = (trk_real)(i % 5); break;              /* coincident */
                default: px[i] = (trk_real)((2 * u - 1) * 0.9) * TRK_REAL_MAX, py[i] = (trk_real)(v * 1e30); /* huge */
                }
            }
            index_points(&g, n);
            check_boxes(&g, n, shape == 5 ? 0.9 * TRK_REAL_MAX : 1e5);
        }
    }
}

/* About square cells, about one point per cell. */
static void test_plan(void **state)
{
    (void)state;
    struct trk_i_grid g;
    trk_i_grid_plan(&g, 256, 0, 1200, 0, 1200);
    assert_int_equal(g.n_col, 16);
    assert_int_equal(g.n_row, 16);
    trk_i_grid_plan(&g, 256, 0, 4800, 0, 300); /* 16 times wider than high */
    assert_int_equal(g.n_col, 64);
    assert_int_equal(g.n_row, 4);
    trk_i_grid_plan(&g, 100, 5, 5, 0, 10); /* no x span: one column */
    assert_int_equal(g.n_col, 1);
    assert_int_equal(g.n_row, 100);
    trk_i_grid_plan(&g, 100, 0, TRK_REAL_MAX, -TRK_REAL_MAX, TRK_REAL_MAX); /* the y span overflows */
    assert_int_equal(g.n_col, 1);
    assert_true(g.inv_h_per_m == 0); /* one bin in y: a single cell */
    trk_i_grid_plan(&g, 100, 0, 10, 3, 3); /* one row */
    assert_int_equal(g.n_col, 100);
    assert_int_equal(g.n_row, 1);
    trk_i_grid_plan(&g, 0, 0, 0, 0, 0);
    assert_int_equal((size_t)g.n_col * g.n_row, 1);
}

/* NaN or reversed bounds: nothing. */
static void test_empty_boxes(void **state)
{
    (void)state;
    struct trk_i_grid g;
    for (size_t i = 0; i < 64; i++) px[i] = (trk_real)(i % 8), py[i] = (trk_real)(i / 8);
    index_points(&g, 64);
    size_t j0, j1;
    struct trk_i_grid_box b = trk_i_grid_box(&g, end_, (trk_real)NAN, 10, 0, 10);
    assert_false(trk_i_grid_next(&b, &j0, &j1));
    b = trk_i_grid_box(&g, end_, 0, 10, 0, (trk_real)NAN);
    assert_false(trk_i_grid_next(&b, &j0, &j1));
    b = trk_i_grid_box(&g, end_, 5, 4, 0, 10);
    assert_false(trk_i_grid_next(&b, &j0, &j1));
    b = trk_i_grid_box(&g, end_, 3, 3, 2, 2); /* one point exactly */
    check_box(&g, 64, 3, 3, 2, 2);
    assert_true(trk_i_grid_next(&b, &j0, &j1));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_plan),
        cmocka_unit_test(test_empty_boxes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
