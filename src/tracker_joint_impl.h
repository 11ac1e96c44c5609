/* tracker_joint_impl.h (private) - joint association of a scan
 * (TRK_ASSOC_JOINT; trk/jpda.h, docs/conventions.md "Joint association (JPDA / JIPDA)"):
 *   1. joint_gate: every live track (confirmed first, as the per-track
 *      update) is predicted and gated into the scan's pair store, its ln e_i
 *      turned into the JIPDA weights ln w_tj = ln psi_t + ln e_i - ln lambda,
 *      its miss weight ln(1 - P_D P_G psi_t);
 *   2. joint_solve: the clusters' marginals (trk_jpda_solve) into the store;
 *   3. track_update_joint, per track: predicted again (the same arithmetic,
 *      so the same prediction: cheaper than keeping 64 of them), its
 *      posterior existence and conditional weights (trk_i_jpda_condition),
 *      the PDA combination with them, commit and look as the per-track
 *      update. The filter does the model's part (track_filter_impl.h): an
 *      IMM track is mixed, predicted and gated in step 1 with its mixture
 *      weights ln e_i; in step 3 it is mixed and predicted again,
 *      filter_reweigh recomputes only its models' rho_mi (the marginals in
 *      ws.w stay), then its models' updates take the conditional weights.
 * psi_t is the predicted existence (trk_visibility_predict) with
 * track_visibility, else 1 (plain JPDA). A track alone in its cluster gets
 * its IPDA (PDA) update: the same weights, the same existence.
 * A track whose gated pairs do not fit the store (TRK_MAX_GATED_PAIRS), or
 * whose prediction fails, is left out and updated by its own PDA after every
 * joint track (its gated set then takes the store from its start; counted:
 * n_assoc_overflow; a failed prediction ends the track as numerical there).
 * Joint tracks compete for every detection: the per-track rule that a
 * tentative track may not use a detection a confirmed track gated applies
 * only to the left-out tracks.
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_JOINT_IMPL_H
#define TRK_TRACKER_JOINT_IMPL_H

#include "jpda_impl.h"
#include "track_commit_impl.h"
#include "track_filter_impl.h"

/* The existence the track's joint events are weighed with. */
static trk_real joint_psi(const struct trk_tracker *t, const struct trk_track *tr)
{
    return t->params.track_visibility ? trk_visibility_predict(&t->vis_model, &tr->vis) : 1;
}

/* Track tr into the joint problem as joint track n_joint: predict, gate
 * into the pairs from the store's end, and its weights. 0; -1 when it is
 * left out (prediction failed, or its pairs do not fit); 1 when left out
 * because its prediction is over the covariance bound (its own update
 * ends it) or the sensor cannot see it (its own update coasts it). */
static int joint_gate_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan)
{
    const size_t k = t->ws.n_joint, off = t->ws.pair_first[k];
    struct pred pr;
    struct trk_i_pda_set set;
    if (filter_predict(t, tr, scan, &pr) != TRK_OK) return -1;
    if (over_covariance_bound(pr.bound_m2, pr.p) || !pred_seen(&pr)) return 1;
    if (filter_gate(t, tr, scan, &pr, off, &set) != 0) return -1;
    const struct trk_pda *pda = pr.pda;
    const trk_real psi = joint_psi(t, tr);
    if (psi > 0) {
        const trk_real log_lambda = t->ws.view.clutter_varies ? trk_log(pda->params.clutter_density)
                                                              : t->log_clutter_density[scan->sensor_id];
        const trk_real base = trk_log(psi) - log_lambda; /* lambda at the track (its profile) */
        for (size_t i = 0; i < set.n; i++) set.w[i] += base;
        t->ws.miss[k] = trk_log1p(-pda->params.pd * pda->params.gate_prob * psi);
    } else { /* a track that cannot exist takes nothing */
        set.n = 0;
        t->ws.miss[k] = 0;
    }
    t->ws.joint_slot[k] = (uint16_t)(tr - t->track);
    t->ws.done[tr - t->track] = 1;
    t->ws.pair_first[k + 1] = (uint16_t)(off + set.n);
    t->ws.n_joint = k + 1;
    return 0;
}

/* Step 1 for every live track, confirmed ones first. */
static TRK_NOINLINE void joint_gate(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    t->ws.n_joint = 0;
    t->ws.pair_first[0] = 0; /* (ws.done: cleared by the scan's update stage) */
    for (int confirmed = 1; confirmed >= 0; confirmed--)
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            struct trk_track *tr = &t->track[i];
            const uint8_t want = confirmed ? TRK_TRACK_CONFIRMED : TRK_TRACK_TENTATIVE;
            if (tr->status == want && joint_gate_track(t, tr, scan) < 0) rep->n_assoc_overflow++;
        }
}

/* Step 2: the marginals, P(k <- j) over the pairs' ln w (ws.w) and P(k <-
 * none) over ws.miss. A refusal (cannot happen: the weights are finite)
 * leaves every track to its own PDA. */
static TRK_NOINLINE void joint_solve(struct trk_tracker *t, struct trk_scan_report *rep)
{
    const size_t n = t->ws.n_joint, n_pairs = t->ws.pair_first[n];
    const struct trk_jpda_pairs pairs = {n, t->ws.n_valid, t->ws.pair_first, t->ws.cand, t->ws.w, t->ws.miss};
    struct trk_jpda_report jr;
    if (trk_jpda_solve(&pairs, &t->ws.u.joint.solver, t->ws.u.joint.p_pair, t->ws.u.joint.p_miss, &jr) != TRK_OK) {
        rep->n_assoc_overflow += (uint32_t)n;
        for (size_t k = 0; k < n; k++) t->ws.done[t->ws.joint_slot[k]] = 0;
        t->ws.n_joint = 0;
        return;
    }
    for (size_t k = 0; k < n_pairs; k++) t->ws.w[k] = trk_i_pda_weight(t->ws.u.joint.p_pair[k]); /* subnormal: 0 */
    for (size_t k = 0; k < n; k++) t->ws.miss[k] = t->ws.u.joint.p_miss[k];
    rep->n_clusters += (uint32_t)jr.n_clusters;
    rep->n_clusters_approx += (uint32_t)jr.n_approx;
    if (jr.largest_tracks > rep->largest_cluster) rep->largest_cluster = (uint32_t)jr.largest_tracks;
}

/* Joint track k's gated set from its pairs: z from the workspace, R_j of
 * the own-covariance detections from the scan; w = its marginals. */
static void joint_set(struct trk_tracker *t, const struct trk_scan *scan, size_t k, struct trk_i_pda_set *set)
{
    const size_t off = t->ws.pair_first[k], n = (size_t)(t->ws.pair_first[k + 1] - off);
    set->n = set->m_gated = n;
    set->n_shared = 0;
    set->w_max = -(trk_real)INFINITY; /* (w: marginals, not normalised here) */
    set->w_arg = 0;
    set->z = t->ws.u.set.z;
    set->w = t->ws.w + off;
    set->r_own = t->ws.u.set.r_own;
    for (size_t i = 0; i < n; i++) {
        const size_t j = t->ws.cand[off + i];
        t->ws.u.set.z[NZ * i + ZX] = t->ws.x[j];
        t->ws.u.set.z[NZ * i + ZY] = t->ws.y[j];
        if (j < t->ws.n_shared) set->n_shared = i + 1; /* the shared ones come first */
        else det_r(t, scan, j, t->ws.u.set.r_own + NZ * NZ * (i - set->n_shared));
    }
}

/* Step 3 for joint track k (slot tr): as track_update, with the joint
 * weights. 0, or -1 on a numerical failure (tr untouched). */
static TRK_NOINLINE int track_update_joint(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, size_t k,
                              struct trk_look *look)
{
    struct pred pr;
    if (filter_predict(t, tr, scan, &pr) != TRK_OK) return -1; /* cannot fail: it did in step 1 */
    const struct trk_pda *pda = pr.pda;
    struct trk_i_pda_set set;
    joint_set(t, scan, k, &set);
    if (filter_reweigh(t, scan, &pr, &set, t->ws.cand + t->ws.pair_first[k]) != TRK_OK) return -1;
    struct trk_i_pda_out out;
    trk_i_pda_clutter(pda, &pr.pp, &set, &out);
    const trk_real psi = joint_psi(t, tr);
    trk_real psi_post = 0;
    if (psi > 0 && trk_i_jpda_condition(psi, pda->params.pd * pda->params.gate_prob, set.n, set.w,
                                        t->ws.miss[k], &out.beta0, &psi_post) != TRK_OK)
        return -1;
    if (filter_update_beta(t, scan, &pr, &set, out.beta0) != TRK_OK) return -1;
    struct trk_visibility vis = tr->vis;
    if (t->params.track_visibility && trk_visibility_update_posterior(&t->vis_model, &vis, psi_post) != TRK_OK)
        return -1;
    commit(t, tr, scan, &set, t->ws.cand + t->ws.pair_first[k], &pr, &vis, out.beta0);
    build_look(t, tr, scan, &pr, &set, t->ws.cand + t->ws.pair_first[k], &out, look);
    return over_covariance_bound(pr.bound_m2, tr->p);
}

#endif
