/* tracker_index_impl.h (private) - order helpers of the scan's modules: a
 * set of points into a 2-D index (grid_impl.h) and a small in-place sort of
 * indices.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACKER_INDEX_IMPL_H
#define TRK_TRACKER_INDEX_IMPL_H

#include "grid_impl.h"
#include "tracker_internal.h"

/* idx[0, n) of the points (x[idx[i]], y[idx[i]]) in the 2-D index g
 * (grid_impl.h), its cells' ends in end[] (O(n)). Scratch: ws.u.sort. */
static void grid_order(struct trk_tracker *t, const trk_real *x, const trk_real *y, uint16_t *idx, size_t n,
                       struct trk_i_grid *g, uint16_t *end)
{
    trk_real lo_x = 0, hi_x = 0, lo_y = 0, hi_y = 0;
    for (size_t i = 0; i < n; i++) {
        const trk_real xi = x[idx[i]], yi = y[idx[i]];
        if (i == 0 || xi < lo_x) lo_x = xi;
        if (i == 0 || xi > hi_x) hi_x = xi;
        if (i == 0 || yi < lo_y) lo_y = yi;
        if (i == 0 || yi > hi_y) hi_y = yi;
    }
    trk_i_grid_plan(g, n, lo_x, hi_x, lo_y, hi_y);
    trk_i_grid_fill(g, x, y, idx, n, end, t->ws.u.sort.count, t->ws.u.sort.tmp);
}

/* Does a[i] go after a[m]: ascending key16[a[]] (NULL: a[] itself), or
 * with key_desc descending key_desc[a[]], ties in ascending a[] (a total
 * order: the same result whatever the input's order)? */
static int sort_after(const uint16_t *a, size_t i, size_t m, const uint16_t *key16, const trk_real *key_desc)
{
    if (key_desc) return key_desc[a[i]] < key_desc[a[m]] || (key_desc[a[i]] == key_desc[a[m]] && a[i] > a[m]);
    return key16 ? key16[a[i]] > key16[a[m]] : a[i] > a[m];
}

/* a[0, n) in place in sort_after's order: heapsort, O(n log n), no scratch. */
static void sort_u16(uint16_t *a, size_t n, const uint16_t *key16, const trk_real *key_desc)
{
    for (size_t end = n, start = n / 2;;) {
        if (start > 0) {
            start--;
        } else {
            if (end <= 1) break;
            end--;
            const uint16_t v = a[0];
            a[0] = a[end];
            a[end] = v;
        }
        for (size_t i = start;;) { /* sift a[i] down in the heap [0, end) whose root goes last */
            size_t m = i;
            const size_t l = 2 * i + 1, r = l + 1;
            if (l < end && sort_after(a, l, m, key16, key_desc)) m = l;
            if (r < end && sort_after(a, r, m, key16, key_desc)) m = r;
            if (m == i) break;
            const uint16_t v = a[i];
            a[i] = a[m];
            a[m] = v;
            i = m;
        }
    }
}

/* a[0, n) sorted ascending by key[a[i]] (key NULL: by a[i]). */
static void sort_u16_by(uint16_t *a, size_t n, const uint16_t *key) { sort_u16(a, n, key, NULL); }

/* a[0, n) into descending order of key[a[i]], ties in ascending a[i]. */
static void sort_u16_by_real_desc(uint16_t *a, size_t n, const trk_real *key) { sort_u16(a, n, NULL, key); }

#endif
