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

/* a[0, n) sorted ascending by key[a[i]] (key NULL: by a[i]), in place:
 * heapsort, O(n log n), no scratch. */
static void sort_u16_by(uint16_t *a, size_t n, const uint16_t *key)
{
#define SORT_KEY(i) (key ? key[a[i]] : a[i])
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
        for (size_t i = start;;) { /* sift a[i] down in the max-heap [0, end) */
            size_t m = i;
            const size_t l = 2 * i + 1, r = l + 1;
            if (l < end && SORT_KEY(l) > SORT_KEY(m)) m = l;
            if (r < end && SORT_KEY(r) > SORT_KEY(m)) m = r;
            if (m == i) break;
            const uint16_t v = a[i];
            a[i] = a[m];
            a[m] = v;
            i = m;
        }
    }
#undef SORT_KEY
}

/* a[0, n) into descending order of key[a[i]], ties in ascending a[i] (a
 * total order: the same result whatever the input's order); heap sort. */
static void sort_u16_by_real_desc(uint16_t *a, size_t n, const trk_real *key)
{
#define SORT_BELOW(i, m) (key[a[i]] < key[a[m]] || (key[a[i]] == key[a[m]] && a[i] > a[m]))
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
        for (size_t i = start;;) { /* sift a[i] down in the heap [0, end) whose root ranks last */
            size_t m = i;
            const size_t l = 2 * i + 1, r = l + 1;
            if (l < end && SORT_BELOW(l, m)) m = l;
            if (r < end && SORT_BELOW(r, m)) m = r;
            if (m == i) break;
            const uint16_t v = a[i];
            a[i] = a[m];
            a[m] = v;
            i = m;
        }
    }
#undef SORT_BELOW
}

#endif
