/* tracker_clutter_map_impl.h (private) - the last step of the scan: the
 * scan's sensor's clutter map (clutter_map.h) learns from the detections no
 * confirmed track gated, after every stage has used the map as it was
 * before the scan (a detection's own count never weighs its association).
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_CLUTTER_MAP_IMPL_H
#define TRK_TRACKER_CLUTTER_MAP_IMPL_H

#include "clutter_map.h"

#if TRK_CLUTTER_MAP_CELLS > 0
/* Forget (1 - 1/tau), then count each valid detection outside every
 * confirmed track's gate in its cell, weighted by 1 / kept_share (a
 * thinned scan kept that share of the clutter; below 1e-6 the scan is
 * skipped). A polar detection's cell
 * is taken from its own range and bearing, a Cartesian one's from its
 * position. */
static TRK_NOINLINE void learn_clutter_map(struct trk_tracker *t, const struct trk_scan *scan, trk_real kept_share)
{
    const struct trk_i_view *v = &t->ws.view;
    /* a scan that kept less than a millionth of its clutter (an amplitude
     * threshold raised that far) says nothing of the density below it:
     * the map skips it rather than count each kept detection a million
     * times over */
    if (!v->map || !(kept_share >= TRK_REAL_C(1e-6))) return;
    trk_real *count = t->clutter_map[scan->sensor_id];
    trk_i_map_forget(&t->params.clutter_map, count, &t->clutter_map_scans[scan->sensor_id]);
    const trk_real w = 1 / kept_share;
    for (size_t j = 0; j < t->ws.n_valid; j++) {
        if (t->ws.used[j] == USED_CONFIRMED) continue;
        trk_real r, b;
        if (scan->polar) {
            const struct trk_polar_detection *pd = &scan->polar[t->ws.src[j]];
            r = pd->range_m;
            b = pd->bearing_rad;
            if (b > TRK_PI || b <= -TRK_PI) b -= 2 * TRK_PI * trk_floor((b + TRK_PI) / (2 * TRK_PI));
        } else {
            trk_i_view_polar(v, t->ws.x[j], t->ws.y[j], &r, &b);
        }
        const long c = trk_i_map_cell(v, r, b);
        if (c >= 0) count[c] += w;
    }
}
#endif

#endif
