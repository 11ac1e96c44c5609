/* tracker_load_impl.h (private) - stage 2 of the scan: the scan's usable
 * detections into the workspace (the most useful TRK_MAX_DETECTIONS of a
 * scan beyond capacity, tracker_thin_impl.h), those with the sensor's
 * covariance in gating's 2-D index, the amplitudes the clutter tests read.
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_LOAD_IMPL_H
#define TRK_TRACKER_LOAD_IMPL_H

#include "tracker_detection_impl.h"
#include "tracker_index_impl.h"
#include "tracker_thin_impl.h"

static void order_by_grid(struct trk_tracker *t, const struct trk_scan *scan);

/* ln l^a of detection d with the caller's clutter density lambda_c there:
 * ln(lambda(z) / lambda_c) added, lambda(z) the tracker's own at the
 * detection. Every weight divides l^a by the tracker's lambda (PDA and
 * joint weights and existence at the track, a new track's start value at
 * the detection), so each then divides by lambda_c: exactly where the
 * tracker's lambda is the same at the track and at the detection (a
 * constant, a map cell or profile step wider than a gate). A thinned scan
 * scales both alike. */
static trk_real with_caller_density(const struct trk_tracker *t, const struct trk_scan *scan,
                                    const struct trk_detection *d, trk_real lambda_c, trk_real llr)
{
    return llr + trk_log(sensor_lambda_at(t, scan, d->x_m, d->y_m)) - trk_log(lambda_c);
}

/* Take scan detection i into the workspace, or count why not
 * (detection_usable). */
static void load_detection(struct trk_tracker *t, const struct trk_scan *scan, const struct trk_detection *d,
                           size_t i, const struct amp_use *au, struct trk_scan_report *rep)
{
    trk_real llr;
    const trk_real *lambda_c = caller_density(scan, i);
    if (!detection_usable(d, lambda_c, au, rep, &llr)) return;
    if (lambda_c) llr = with_caller_density(t, scan, d, *lambda_c, llr);
    const size_t n = t->ws.n_valid++;
    t->ws.x[n] = d->x_m;
    t->ws.y[n] = d->y_m;
    t->ws.src[n] = (uint16_t)i;
    t->ws.used[n] = 0;
    t->ws.log_lr[n] = llr;
    t->ws.amp_pos[n] = -1;
    if (au->want_db && d->has_amplitude && d->amplitude > 0) {
        t->ws.amp_db[t->ws.n_amp] = TRK_REAL_C(20.0) * trk_log10(d->amplitude) - au->ref_db;
        t->ws.amp_pos[n] = (int16_t)t->ws.n_amp++;
    }
}

/* Kept polar detection i of a thinned scan, the k-th kept, as converted by
 * thin_select (its position in ws.x[k], ws.y[k]: the load writes entry
 * n <= k, after this read), into *tmp: the covariance derived from the
 * position as trk_i_view_convert derives it, bit for bit. */
static const struct trk_detection *kept_polar(const struct trk_tracker *t, const struct trk_scan *scan, size_t k,
                                              size_t i, struct trk_detection *tmp)
{
    const struct trk_i_view *v = &t->ws.view;
    const struct trk_polar_detection *pd = &scan->polar[i];
    tmp->x_m = t->ws.x[k];
    tmp->y_m = t->ws.y[k];
    trk_polar_cov(v->sp, tmp->x_m - v->pose.x_m, tmp->y_m - v->pose.y_m, tmp->cov_m2);
    tmp->has_cov = 1;
    tmp->has_amplitude = pd->has_amplitude;
    tmp->amplitude = pd->amplitude;
    return tmp;
}

/* The valid detections into the workspace: those with the sensor's
 * covariance first [0, n_shared), in gating's 2-D index (ws.grid,
 * src/grid_impl.h), own-covariance ones after, in their own index
 * (ws.grid_own); rejections are counted. A scan beyond capacity loads the ones
 * thin_select kept (their scan indices, ascending, in ws.cand), the model
 * of what it kept into *th. The amplitudes (dB) are then doubled (see
 * clutter_look in track_commit_impl.h). */
static TRK_NOINLINE void load_detections(struct trk_tracker *t, const struct trk_scan *scan, struct thin *th,
                            struct trk_scan_report *rep)
{
    const struct trk_sensor_params *sp = &t->params.sensor[scan->sensor_id];
    const struct amp_use au = amp_use_of(t, sp, &t->ws.view);
    const int over = scan->n_detections > TRK_MAX_DETECTIONS;
    const size_t n_load = over ? thin_select(t, scan, &au, th, rep) : scan->n_detections;
    t->ws.n_valid = 0;
    t->ws.n_amp = 0;
    for (int own = 0; own <= 1; own++) {
        for (size_t k = 0; k < n_load; k++) {
            const size_t i = over ? t->ws.cand[k] : k;
            struct trk_detection tmp;
            if (scan->polar && !own) continue; /* converted, each has its own covariance */
            const struct trk_detection *d =
                over && scan->polar ? kept_polar(t, scan, k, i, &tmp) : scan_detection(t, scan, i, &tmp, rep);
            if (d && (d->has_cov != 0) == own) load_detection(t, scan, d, i, &au, rep);
        }
        if (!own) t->ws.n_shared = t->ws.n_valid;
    }
    rep->n_kept = (uint32_t)t->ws.n_valid;
    order_by_grid(t, scan);
    for (size_t k = 0; k + 1 < t->ws.n_amp; k++) t->ws.amp_db[t->ws.n_amp + k] = t->ws.amp_db[k];
}

/* Workspace detection k moved to j (its amplitude stays where amp_pos
 * says). */
static void ws_move(struct trk_tracker *t, size_t j, size_t k)
{
    t->ws.x[j] = t->ws.x[k];
    t->ws.y[j] = t->ws.y[k];
    t->ws.src[j] = t->ws.src[k];
    t->ws.log_lr[j] = t->ws.log_lr[k];
    t->ws.amp_pos[j] = t->ws.amp_pos[k];
}

/* Workspace positions [lo, lo + n) in the 2-D index g (grid_order: O(n)
 * for spread positions; its cells' ends in end[], its positions counted
 * from lo): position lo + j takes detection lo + idx[j], cycle by cycle in
 * place, with used[] (all 0 at load) marking the positions filled. */
static void order_range_by_grid(struct trk_tracker *t, size_t lo, size_t n, struct trk_i_grid *g, uint16_t *end)
{
    uint16_t *idx = t->ws.cand; /* free until the first track is gated */
    uint8_t *used = t->ws.used + lo;
    for (size_t j = 0; j < n; j++) idx[j] = (uint16_t)j;
    grid_order(t, t->ws.x + lo, t->ws.y + lo, idx, n, g, end);
    for (size_t i = 0; i < n; i++) {
        if (used[i] || idx[i] == i) continue;
        const trk_real x = t->ws.x[lo + i], y = t->ws.y[lo + i], llr = t->ws.log_lr[lo + i];
        const uint16_t src = t->ws.src[lo + i];
        const int16_t amp = t->ws.amp_pos[lo + i];
        size_t j = i;
        for (size_t k = idx[j]; k != i; j = k, k = idx[j]) {
            ws_move(t, lo + j, lo + k);
            used[j] = 1;
        }
        t->ws.x[lo + j] = x;
        t->ws.y[lo + j] = y;
        t->ws.src[lo + j] = src;
        t->ws.log_lr[lo + j] = llr;
        t->ws.amp_pos[lo + j] = amp;
        used[j] = 1;
    }
    for (size_t j = 0; j < n; j++) used[j] = 0;
}

/* Gating's two indices, once per scan: the shared-covariance group [0,
 * n_shared) in ws.grid, the own-covariance group in ws.grid_own with the
 * largest of its variances, which bounds a track's box for any of them
 * (S_j = H P H' + R_j). */
static void order_by_grid(struct trk_tracker *t, const struct trk_scan *scan)
{
    const size_t n_shared = t->ws.n_shared, n_own = t->ws.n_valid - n_shared;
    order_range_by_grid(t, 0, n_shared, &t->ws.grid, t->ws.cell_end);
    t->ws.own_var_max_m2[0] = t->ws.own_var_max_m2[1] = 0;
    if (n_own == 0) return;
    order_range_by_grid(t, n_shared, n_own, &t->ws.grid_own, t->ws.cell_end_own);
    for (size_t j = n_shared; j < t->ws.n_valid; j++) {
        trk_real c[3];
        det_cov(t, scan, j, c); /* checked at load */
        if (c[TRK_COV2_XX] > t->ws.own_var_max_m2[0]) t->ws.own_var_max_m2[0] = c[TRK_COV2_XX];
        if (c[TRK_COV2_YY] > t->ws.own_var_max_m2[1]) t->ws.own_var_max_m2[1] = c[TRK_COV2_YY];
    }
}

#endif
