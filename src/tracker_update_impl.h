/* tracker_update_impl.h (private) - stage 3 of the scan with per-track
 * association: one live track's update by its own PDA (IPDA existence):
 * predict, the covariance bound, gate, the PDA weights and posterior,
 * visibility, commit, look. The filter does the model's part
 * (track_filter_impl.h); this stage holds no model.
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_UPDATE_IMPL_H
#define TRK_TRACKER_UPDATE_IMPL_H

#include "track_commit_impl.h"
#include "track_filter_impl.h"

/* Predict track tr to the scan time, gate the scan's valid detections (the
 * workspace), PDA-update it and mark the detections it used; *look gets what
 * the scan told its tests. 0; 1 when the prediction is already over the
 * covariance bound (the track has lost its target: it is ended without
 * gating, which with so wide a gate would be a pass over most of the scan
 * for a track that the bound ends anyway); -1 on a numerical failure (tr
 * untouched). */
static TRK_NOINLINE int track_update(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                        struct trk_look *look)
{
    struct pred pr;
    struct trk_i_pda_set set;
    struct trk_i_pda_out out;
    if (filter_predict(t, tr, scan, &pr) != TRK_OK) return -1;
    if (over_covariance_bound(pr.bound_m2, pr.p)) return 1;
    if (!pred_seen(&pr)) return track_unseen(t, tr, scan, &pr, look);
    if (filter_gate(t, tr, scan, &pr, 0, &set) < 0) return -1; /* one track's set fits: TRK_I_PAIRS >= TRK_MAX_DETECTIONS */
    if (filter_pda(t, scan, &pr, &set, &out) != TRK_OK) return -1; /* pr.x, pr.p: the posterior */
    struct trk_visibility vis = tr->vis;
    if (t->params.track_visibility && update_visibility(t, pr.pda, &set, &out, &vis) != TRK_OK) return -1;
    commit(t, tr, scan, &set, t->ws.cand, &pr, &vis, out.beta0);
    build_look(t, tr, scan, &pr, &set, t->ws.cand, &out, look);
    return over_covariance_bound(pr.bound_m2, tr->p);
}

#endif
