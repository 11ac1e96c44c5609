/* tracker_merge_impl.h (private) - stage 4 of the scan: live tracks that
 * follow one target (PDA tracks sharing detections converge onto it) are
 * merged: the weaker one ends (TRK_END_MERGED). Candidate pairs come from a
 * 2-D index of the tracks' positions; the test is the track-to-track d2
 * over the estimates x with the filter's merge covariance (an IMM track's
 * most probable model's: filter_merge_cov).
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_MERGE_IMPL_H
#define TRK_TRACKER_MERGE_IMPL_H

#include "track_filter_impl.h"
#include "track_life_impl.h"
#include "tracker_index_impl.h"

/* Is track a stronger than b (kept when they merge)? Confirmed over
 * tentative; of two tentative tracks with existence, the more probable one
 * (a tentative track's existence is its quality, as when a slot is taken:
 * a track on clutter that has gathered hits in its wide gate must not
 * absorb a younger track on a target whose existence is higher: trk-sim mtt
 * --family sonar at 100 per ping, 1 024 slots, 40 seeds: GOSPA 178.1 ->
 * 175.0 m); then more hits, then older (smaller id: ids only grow, except
 * after 2^32 tracks). */
static int stronger(const struct trk_tracker *t, const struct trk_track *a, const struct trk_track *b)
{
    if (a->status != b->status) return a->status == TRK_TRACK_CONFIRMED;
    if (a->status == TRK_TRACK_TENTATIVE && t->params.track_visibility && a->vis.pv != b->vis.pv)
        return a->vis.pv > b->vis.pv;
    if (a->n_hits != b->n_hits) return a->n_hits > b->n_hits;
    return a->id < b->id;
}

/* Can live tracks a and b follow one target? The cheap test on the
 * positions alone (inlined in the pair loop): d2 >= dx^2 / (Pa_xx + Pb_xx)
 * for the x (and y) component, so a pair failing it is not a duplicate. */
static int may_duplicate(const struct trk_tracker *t, const struct trk_track *a, const struct trk_track *b,
                         trk_real g)
{
    const trk_real *pa = filter_merge_cov(t, a), *pb = filter_merge_cov(t, b);
    const trk_real ex = a->x[X] - b->x[X], ey = a->x[Y] - b->x[Y];
    return ex * ex <= g * (pa[P(X, X)] + pb[P(X, X)]) && ey * ey <= g * (pa[P(Y, Y)] + pb[P(Y, Y)]);
}

/* Do live tracks a and b follow one target: d2 = dx' (P_a + P_b)^-1 dx <= g
 * over [x, vx, y, vy] (the track-to-track test without the common
 * process-noise cross-covariance, which would only make d2 larger)? */
static TRK_NOINLINE int duplicates(const struct trk_tracker *t, const struct trk_track *a, const struct trk_track *b,
                                   trk_real g)
{
    const trk_real *pa = filter_merge_cov(t, a), *pb = filter_merge_cov(t, b);
    trk_real c[NX * NX], l[NX * NX], li[NX * NX], dx[NX], y[NX], d2 = 0;
    for (int k = 0; k < NX * NX; k++) c[k] = pa[k] + pb[k];
    for (int k = 0; k < NX; k++) dx[k] = a->x[k] - b->x[k];
    if (trk_i_chol(NX, c, l) != TRK_OK) return 0; /* cannot happen: both SPD */
    trk_i_tril_inverse(NX, l, li);
    trk_i_tril_mul(NX, li, dx, y);
    for (int k = 0; k < NX; k++) d2 += y[k] * y[k];
    return d2 <= g;
}

/* The pair (a, b) of live tracks that may follow one target: end the
 * weaker when they do. */
static void merge_pair(struct trk_tracker *t, struct trk_track *a, struct trk_track *b, struct trk_scan_report *rep)
{
    const trk_real g = t->params.merge_gate_d2;
    if (!is_live(a) || !is_live(b) || !may_duplicate(t, a, b, g) || !duplicates(t, a, b, g)) return;
    end_track(stronger(t, a, b) ? b : a, TRK_END_MERGED, rep);
}

/* Every pair (i < j) of live slots in slot order, as merge_duplicates'
 * definition. */
static void merge_all_pairs(struct trk_tracker *t, struct trk_scan_report *rep)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        for (size_t j = i + 1; j < TRK_MAX_TRACKS && is_live(&t->track[i]); j++)
            merge_pair(t, &t->track[i], &t->track[j], rep);
}

/* The pairs of live tracks that may_duplicate can pass, by box queries in a
 * 2-D index of the tracks' positions (a pair's |dx| is at most sqrt(g
 * (P_xx + max P_xx)), |dy| likewise), as (i, j) slot pairs (i < j) sorted,
 * into ws.u.merge.pair[0, 2 n): n, or -1 when they do not fit. O(tracks +
 * pairs) for tracks spread over the area, instead of tracks^2. Needs 2
 * TRK_MAX_TRACKS <= TRK_I_PAIRS and TRK_MAX_TRACKS <= TRK_MAX_DETECTIONS
 * (the positions in ws.w, the cells' ends in ws.cell_end, gating's index
 * no longer needed). */
static long merge_candidates(struct trk_tracker *t)
{
    const size_t cap = sizeof t->ws.u.merge.pair / sizeof t->ws.u.merge.pair[0] / 2;
    const trk_real g = t->params.merge_gate_d2;
    uint16_t *idx = t->ws.cand;
    trk_real *kx = t->ws.w, *ky = t->ws.w + TRK_MAX_TRACKS; /* free between the updates and initiation */
    trk_real pmax_x = 0, pmax_y = 0;
    size_t n = 0, n_pair = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (is_live(&t->track[i])) {
            const struct trk_track *a = &t->track[i];
            const trk_real *pa = filter_merge_cov(t, a);
            idx[n++] = (uint16_t)i;
            kx[i] = a->x[X];
            ky[i] = a->x[Y];
            if (pa[P(X, X)] > pmax_x) pmax_x = pa[P(X, X)];
            if (pa[P(Y, Y)] > pmax_y) pmax_y = pa[P(Y, Y)];
        }
    struct trk_i_grid grid;
    grid_order(t, kx, ky, idx, n, &grid, t->ws.cell_end);
    uint16_t *out = t->ws.u.merge.pair; /* after the index: its scratch shares the union */
    for (size_t k = 0; k < n; k++) {
        const struct trk_track *a = &t->track[idx[k]];
        const trk_real *pa = filter_merge_cov(t, a);
        const trk_real rx = trk_sqrt(g * (pa[P(X, X)] + pmax_x)) * (1 + 16 * TRK_REAL_EPS);
        const trk_real ry = trk_sqrt(g * (pa[P(Y, Y)] + pmax_y)) * (1 + 16 * TRK_REAL_EPS);
        struct trk_i_grid_box box = trk_i_grid_box(&grid, t->ws.cell_end, a->x[X] - rx, a->x[X] + rx, a->x[Y] - ry,
                                                   a->x[Y] + ry);
        size_t l0, l1;
        while (trk_i_grid_next(&box, &l0, &l1))
            for (size_t l = l0; l < l1; l++) {
                const uint16_t i = idx[k], j = idx[l];
                if (i >= j || !may_duplicate(t, a, &t->track[j], g)) continue; /* each pair once */
                if (n_pair == cap) return -1;
                size_t m = n_pair++; /* insertion in (i, j) order: the pairs are few */
                for (; m > 0 && (out[2 * m - 2] > i || (out[2 * m - 2] == i && out[2 * m - 1] > j)); m--) {
                    out[2 * m] = out[2 * m - 2];
                    out[2 * m + 1] = out[2 * m - 1];
                }
                out[2 * m] = i;
                out[2 * m + 1] = j;
            }
    }
    return (long)n_pair;
}

/* End the weaker of every pair of live tracks that follow one target
 * (PDA tracks sharing detections converge onto it), pair by pair in slot
 * order: the candidate pairs of the index (merge_candidates), or every
 * pair when there are more than the workspace holds or than its arrays can
 * take (the same decisions). */
static TRK_NOINLINE void merge_duplicates(struct trk_tracker *t, struct trk_scan_report *rep)
{
    const long n = TRK_MAX_TRACKS <= TRK_MAX_DETECTIONS && 2 * TRK_MAX_TRACKS <= TRK_I_PAIRS ? merge_candidates(t) : -1;
    const uint16_t *pair = t->ws.u.merge.pair;
    if (n < 0) {
        merge_all_pairs(t, rep);
        return;
    }
    for (long k = 0; k < n; k++) merge_pair(t, &t->track[pair[2 * k]], &t->track[pair[2 * k + 1]], rep);
}

#endif
