/* grid_impl.h (private) - the 2-D index of struct trk_i_grid (trk/tracker.h):
 * a set of n points in cells of a regular grid, about one point per cell,
 * the cells column by column (cell = column n_row + row), the points of a
 * cell in their given order. A box [lo_x, hi_x] x [lo_y, hi_y] is then, per
 * column it overlaps, one contiguous range of points: gating (the scan's
 * detections) and two-point initiation (each scan's candidates) cost the
 * points near the box, not the whole strip of a sort by x, whose content
 * grows with the side of the area. Built by one counting
 * sort, O(n).
 *
 * The cells' ends are kept outside the struct (end[cell], one past its last
 * point, n_col n_row <= n entries), so that a store of several indexed sets
 * sizes them with its points. Queries take the cells' ends only. */
#ifndef TRK_GRID_IMPL_H
#define TRK_GRID_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "internal.h"
#include "trk/tracker.h"

/* floor((v - v0) inv) clamped to [0, n - 1] (0 for NaN): monotone in v,
 * so that every point of v in [lo, hi] lies in [bin(lo), bin(hi)]. */
TRK_INLINE size_t trk_i_grid_bin(trk_real v, trk_real v0, trk_real inv, size_t n)
{
    const trk_real u = (v - v0) * inv;
    if (!(u > 0)) return 0;
    if (u >= (trk_real)(n - 1)) return n - 1;
    return (size_t)u;
}

/* The cells for n points spanning [lo_x, hi_x] x [lo_y, hi_y]: about
 * square, about n of them: n_col = sqrt(n sx / sy) (sx, sy the spans; 1 when
 * that is 0 or NaN, n when it is larger or infinite), n_row = n / n_col, so
 * n_col n_row <= max(1, n). A span of 0 or out of range leaves its axis one
 * bin wide (inverse width 0). */
TRK_INLINE void trk_i_grid_plan(struct trk_i_grid *g, size_t n, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                                trk_real hi_y)
{
    const trk_real sx = hi_x - lo_x, sy = hi_y - lo_y, c = trk_sqrt((trk_real)n * (sx / sy));
    const size_t n_col = n > 1 && c >= (trk_real)n ? n : c >= 2 ? (size_t)c : 1;
    const size_t n_row = n > n_col ? n / n_col : 1;
    const trk_real inv_x = (trk_real)n_col / sx, inv_y = (trk_real)n_row / sy;
    g->x0_m = lo_x;
    g->y0_m = lo_y;
    g->inv_w_per_m = inv_x <= TRK_REAL_MAX ? inv_x : 0;
    g->inv_h_per_m = inv_y <= TRK_REAL_MAX ? inv_y : 0;
    g->n_col = (uint16_t)n_col;
    g->n_row = (uint16_t)n_row;
}

/* The cell of (x, y). */
TRK_INLINE size_t trk_i_grid_cell(const struct trk_i_grid *g, trk_real x, trk_real y)
{
    return trk_i_grid_bin(x, g->x0_m, g->inv_w_per_m, g->n_col) * g->n_row +
           trk_i_grid_bin(y, g->y0_m, g->inv_h_per_m, g->n_row);
}

/* idx[0, n) of the points (x[idx[i]], y[idx[i]]) into g's cells (g
 * planned for them): a stable counting sort, and end[] the cells' ends.
 * Scratch: cell and tmp, n each. */
TRK_INLINE void trk_i_grid_fill(const struct trk_i_grid *g, const trk_real *x, const trk_real *y, uint16_t *idx,
                                size_t n, uint16_t *end, uint16_t *cell, uint16_t *tmp)
{
    const size_t n_cell = (size_t)g->n_col * g->n_row;
    for (size_t c = 0; c < n_cell; c++) end[c] = 0;
    for (size_t i = 0; i < n; i++) {
        cell[i] = (uint16_t)trk_i_grid_cell(g, x[idx[i]], y[idx[i]]);
        end[cell[i]]++;
    }
    size_t first = 0; /* end[c] becomes the cell's first point, then one past its last */
    for (size_t c = 0; c < n_cell; c++) {
        const size_t k = end[c];
        end[c] = (uint16_t)first;
        first += k;
    }
    for (size_t i = 0; i < n; i++) tmp[end[cell[i]]++] = idx[i];
    for (size_t i = 0; i < n; i++) idx[i] = tmp[i];
}

/* A box query: the columns [c, c_end) left to visit and the rows [r0, r1]
 * of each, from the bounds widened by a few ulps, so that the caller's own
 * test of each point (|x - x_c| <= w_x, say) decides at the edges. */
struct trk_i_grid_box {
    const uint16_t *end;
    size_t n_row, c, c_end, r0, r1;
};

/* The box [lo_x, hi_x] x [lo_y, hi_y] over g's cells (ends end[]); empty
 * for a NaN or reversed bound. */
TRK_INLINE struct trk_i_grid_box trk_i_grid_box(const struct trk_i_grid *g, const uint16_t *end, trk_real lo_x,
                                                trk_real hi_x, trk_real lo_y, trk_real hi_y)
{
    const trk_real sx = 4 * TRK_REAL_EPS * (trk_fabs(lo_x) > trk_fabs(hi_x) ? trk_fabs(lo_x) : trk_fabs(hi_x));
    const trk_real sy = 4 * TRK_REAL_EPS * (trk_fabs(lo_y) > trk_fabs(hi_y) ? trk_fabs(lo_y) : trk_fabs(hi_y));
    struct trk_i_grid_box b = {end, g->n_row, 0, 0, 0, 0};
    if (lo_x <= hi_x && lo_y <= hi_y && g->n_col > 0 && g->n_row > 0) {
        b.c = trk_i_grid_bin(lo_x - sx, g->x0_m, g->inv_w_per_m, g->n_col);
        b.c_end = trk_i_grid_bin(hi_x + sx, g->x0_m, g->inv_w_per_m, g->n_col) + 1;
        b.r0 = trk_i_grid_bin(lo_y - sy, g->y0_m, g->inv_h_per_m, g->n_row);
        b.r1 = trk_i_grid_bin(hi_y + sy, g->y0_m, g->inv_h_per_m, g->n_row);
    }
    return b;
}

/* The next column's points in the box's rows: [*j0, *j1) (a superset of
 * the box's points there); 0 when no column is left. */
TRK_INLINE int trk_i_grid_next(struct trk_i_grid_box *b, size_t *j0, size_t *j1)
{
    while (b->c < b->c_end) {
        const size_t first = b->c * b->n_row + b->r0, last = b->c * b->n_row + b->r1;
        b->c++;
        *j0 = first > 0 ? b->end[first - 1] : 0;
        *j1 = b->end[last];
        if (*j1 > *j0) return 1;
    }
    return 0;
}

#endif
