/* tracker.c - the scan (trk/tracker.h): trk_tracker_process_scan as the
 * list of its stages, in the order they run (as Stone Soup's
 * MultiTargetTracker loop), the loops over the tracks that run them, then
 * trk_tracker_init and the table accessors. Each stage is a module of its
 * own (tracker_internal.h lists them); a track's motion model is reached
 * only through the track filter (track_filter_impl.h). */
#include <string.h>

#include "tracker_internal.h"

/* the stages, each a module on the ones below it (tracker_internal.h) */
#include "tracker_clutter_map_impl.h"
#include "tracker_initiate_impl.h"
#include "tracker_load_impl.h"
#include "tracker_merge_impl.h"
#include "tracker_update_impl.h"
#if TRK_WITH_JOINT
#include "tracker_joint_impl.h"
#endif

static trk_status check_scan(const struct trk_tracker *t, const struct trk_scan *scan);
static void see_from(struct trk_tracker *t, const struct trk_scan *scan);
static void free_terminated(struct trk_tracker *t);
static trk_real clutter_kept_share(const struct trk_tracker *t, const struct trk_scan_report *rep);
static void update_tracks(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep);
static void update_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, size_t joint_k,
                         struct trk_scan_report *rep);

/* update_track's joint_k of a track updated by its own PDA */
#define JOINT_NONE ((size_t)-1)

/* Check the scan; load its detections (the most useful
 * TRK_MAX_DETECTIONS of a scan beyond capacity); per live track (confirmed
 * ones first), update (predict, gate, PDA or joint association; with the
 * model of what was kept when a gate was thinned) then step its test;
 * merge; initiate. */
trk_status trk_tracker_process_scan(struct trk_tracker *t, const struct trk_scan *scan,
                                    struct trk_scan_report *report)
{
    struct trk_scan_report rep = {0};
    if (report) *report = rep;
    const trk_status st = check_scan(t, scan);
    if (st != TRK_OK) return st;
    /* the scan is accepted: from here on the table changes */
    rep.n_detections = (uint32_t)scan->n_detections;
    t->scan_no++;
    see_from(t, scan);
    rep.persistent_share = t->ws.persistent_share;
    free_terminated(t);
    struct thin th = {0, 0, 0, 0, 0, 1, 0, 0};
    load_detections(t, scan, &th, &rep);
    struct thin_saved saved = {0}; /* written by thin_apply when it returns TRK_OK */
    const int model = th.in_gates && thin_apply(t, scan, &th, &saved) == TRK_OK;
    update_tracks(t, scan, &rep);
    const trk_real kept_share = model ? t->ws.lambda_scale : clutter_kept_share(t, &rep);
    if (model) thin_restore(t, scan, &saved);
    if (t->params.merge_gate_d2 > 0) merge_duplicates(t, &rep);
    initiate(t, scan, &rep);
#if TRK_CLUTTER_MAP_CELLS > 0
    learn_clutter_map(t, scan, kept_share);
#else
    (void)kept_share;
#endif
    t->last_time_us = scan->time_us;
    t->has_time = 1;
    if (report) *report = rep;
    return TRK_OK;
}

/* ------------------------------------------------------------------ the stages */

/* A scan that cannot be processed is refused whole (see trk/tracker.h). */
static trk_status check_scan(const struct trk_tracker *t, const struct trk_scan *scan)
{
    if (!t || !scan) return TRK_E_ARG;
    if (scan->n_detections > TRK_MAX_SCAN_DETECTIONS) return TRK_E_CAPACITY;
    if (scan->sensor_id >= t->params.n_sensors) return TRK_E_SENSOR;
    /* Cartesian detections, or a polar sensor's polar ones: one array */
    if (scan->n_detections > 0 && !scan->detections == !scan->polar) return TRK_E_ARG;
    if (scan->polar && t->params.sensor[scan->sensor_id].kind != TRK_SENSOR_POLAR) return TRK_E_ARG;
    if (scan->has_pose != 0 && scan->has_pose != 1) return TRK_E_ARG;
    /* the caller's densities stand in for lambda as ratios to the tracker's own */
    if (scan->clutter_density_per_m2 && (t->params.clutter != TRK_CLUTTER_PARAMETRIC ||
                                          !(t->params.sensor[scan->sensor_id].clutter_density_per_m2 > 0)))
        return TRK_E_UNSUPPORTED;
    if (scan->has_pose) {
        const struct trk_pose *o = &scan->pose;
        if (!isfinite(o->x_m) || !isfinite(o->y_m) || !isfinite(o->heading_rad)) return TRK_E_NAN;
        const trk_real bound = t->params.max_coord_m; /* the surveillance bound */
        if (!(trk_fabs(o->x_m) <= bound && trk_fabs(o->y_m) <= bound && trk_fabs(o->heading_rad) <= TRK_REAL_C(1e6)))
            return TRK_E_RANGE;
    }
    /* |time| <= 2^62 keeps every difference of two times representable */
    if (scan->time_us > TRK_TIME_US_MAX || scan->time_us < -TRK_TIME_US_MAX) return TRK_E_RANGE;
    if (t->has_time && scan->time_us < t->last_time_us) return TRK_E_TIME;
    if (t->has_time && scan->time_us - t->last_time_us > t->max_dt_us) return TRK_E_RANGE;
    return TRK_OK;
}

/* The scan's sensor from its pose (the scan's, or the sensor's fixed
 * one), with its clutter map as it stands before the scan: the view every
 * stage asks for R, P_D and lambda at a position; and the share of
 * persistent returns no held track explains (the amplitude mixture's)
 * with their 1/u_s. */
static void see_from(struct trk_tracker *t, const struct trk_scan *scan)
{
    const struct trk_sensor_params *sp = &t->params.sensor[scan->sensor_id];
    trk_i_view_init(&t->ws.view, sp, scan->has_pose ? &scan->pose : &sp->pose);
#if TRK_CLUTTER_MAP_CELLS > 0
    if (t->params.clutter == TRK_CLUTTER_PARAMETRIC)
        trk_i_map_view(&t->ws.view, &t->params.clutter_map, t->clutter_map[scan->sensor_id],
                       t->clutter_map_scans[scan->sensor_id]);
#endif
    t->ws.pd_scale = t->ws.lambda_scale = t->ws.pd_power = 1;
#if TRK_WITH_JOINT
    t->ws.persistent_share = unexplained_persistent_share(t, scan);
#else
    t->ws.persistent_share = sp->persistent_share;
#endif
    t->ws.persistent_inv_u = sp->persistent_share > 0 ? persistent_inv_u(sp) : 0;
}

/* The share of a scan's clutter that a thinning without the amplitude
 * model kept: its kept detections over its valid ones (1 unthinned). */
static trk_real clutter_kept_share(const struct trk_tracker *t, const struct trk_scan_report *rep)
{
    const trk_real kept = (trk_real)t->ws.n_valid;
    return rep->n_thinned > 0 && kept > 0 ? kept / (kept + (trk_real)rep->n_thinned) : 1;
}

/* Tracks that ended in the previous scan were shown once: free their slots. */
static void free_terminated(struct trk_tracker *t)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (t->track[i].status == TRK_TRACK_TERMINATED) {
            t->track[i].status = TRK_TRACK_FREE;
            t->n_live--;
        }
}

/* Every live track, once (ws.done). With joint association the joint
 * tracks first (tracker_joint_impl.h: gate every live track, solve the
 * clusters, update each joint track in the order it was gated); then each
 * track not yet updated by its own PDA (with joint association the tracks
 * left out of the joint problem, whose gated sets take the pair store from
 * its start), confirmed ones first, since a tentative track may not use the
 * detections in a confirmed track's gate (it would become its duplicate). A
 * confirmed track that goes back to held in the first pass is tentative in
 * the second, and done. */
static void update_tracks(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) t->ws.done[i] = 0;
#if TRK_WITH_JOINT
    if (t->params.association == TRK_ASSOC_JOINT) {
        joint_gate(t, scan, rep);
        joint_solve(t, rep);
        for (size_t k = 0; k < t->ws.n_joint; k++) update_track(t, &t->track[t->ws.joint_slot[k]], scan, k, rep);
    }
#endif
    for (int confirmed = 1; confirmed >= 0; confirmed--) {
        const uint8_t want = confirmed ? TRK_TRACK_CONFIRMED : TRK_TRACK_TENTATIVE;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
            if (!t->ws.done[i] && t->track[i].status == want) update_track(t, &t->track[i], scan, JOINT_NONE, rep);
    }
}

/* One live track: update (predict, gate, PDA; or, as joint track joint_k,
 * the joint association's update), the covariance bound, count the look,
 * step its test. */
static void update_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, size_t joint_k,
                         struct trk_scan_report *rep)
{
    struct trk_look look;
    t->ws.done[tr - t->track] = 1;
    rep->n_tracks_updated++;
#if TRK_WITH_JOINT
    const int failed = joint_k == JOINT_NONE ? track_update(t, tr, scan, &look)
                                             : track_update_joint(t, tr, scan, joint_k, &look);
#else
    const int failed = track_update(t, tr, scan, &look);
    (void)joint_k;
#endif
    if (failed < 0) {
        end_track(tr, TRK_END_NUMERICAL, rep);
        return;
    }
    if (failed > 0) {
        tr->n_scans++;
        end_track(tr, TRK_END_COVARIANCE, rep);
        rep->n_covariance++;
        return;
    }
    if (!look.seen) { /* out of the sensor's sight: no look, no test step */
        if (tr->status == TRK_TRACK_TENTATIVE) end_track(tr, TRK_END_REJECTED, rep); /* never confirmed there */
        else if ((tr->n_unseen_in_row < UINT16_MAX ? ++tr->n_unseen_in_row : tr->n_unseen_in_row) >
                 t->params.max_unseen_scans) /* (65535 or more: never) */
            end_track(tr, TRK_END_TERMINATED, rep);
        return;
    }
    tr->n_unseen_in_row = 0;
    tr->n_scans++;
    if (look.detected) {
        tr->n_hits++;
        tr->n_misses_in_row = 0;
        rep->n_tracks_hit++;
    } else {
        tr->n_misses_in_row++;
    }
    step_tests(t, tr, &look, rep);
}

/* ------------------------------------------------------------------ the table */

trk_status trk_tracker_init(struct trk_tracker *t, const struct trk_tracker_params *p)
{
    struct trk_pda pda[TRK_MAX_SENSORS];
    trk_real r[TRK_MAX_SENSORS][NZ * NZ];
    struct trk_visibility_model vis;
    union trk_confirm_model confirm;
    union trk_term_model term;
    const struct trk_i_tracker_built b = {pda, r, &vis, &confirm, &term};
    if (!t) return TRK_E_ARG;
    const trk_status st = trk_i_tracker_check(p, NULL, &b);
    if (st != TRK_OK) return st;
    t->params = *p;
    t->confirm_model = confirm;
    t->term_model = term;
    if (p->track_visibility) t->vis_model = vis;
    for (unsigned s = 0; s < p->n_sensors; s++) {
        t->pda[s] = pda[s];
        for (int i = 0; i < NZ * NZ; i++) t->r[s][i] = r[s][i];
        const trk_real lambda = pda[s].params.clutter_density, beta = p->init.birth_density_per_m2;
        t->init_log_odds[s].first = lambda > 0 ? trk_log(beta) - trk_log(lambda) : (trk_real)INFINITY;
        t->init_log_odds[s].second = lambda > 0 ? trk_log(pda[s].params.pd) - trk_log(lambda) : (trk_real)INFINITY;
#if TRK_WITH_JOINT
        t->log_clutter_density[s] = lambda > 0 ? trk_log(lambda) : -(trk_real)INFINITY; /* joint needs > 0 */
#endif
    }
#if TRK_CLUTTER_MAP_CELLS > 0
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) { /* every cell at the configured density */
        for (size_t c = 0; c < TRK_CLUTTER_MAP_CELLS; c++) t->clutter_map[s][c] = 0;
        t->clutter_map_scans[s] = 0;
    }
#endif
    t->scan_no = 0;
    t->n_cand = 0;
    t->run_first = t->n_runs = 0;
    t->last_time_us = 0;
    {   /* seconds (<= 1e9) to the nearest microsecond (>= 1: TRK_MAX_DT_S_MIN)
         * with 32-bit conversions only: a float -> int64 conversion is soft
         * double on Cortex-M (__aeabi_f2lz) */
        const trk_real whole = trk_floor(p->max_dt_s);
        t->max_dt_us = (int64_t)(int32_t)whole * 1000000 +
                       (int64_t)(int32_t)((p->max_dt_s - whole) * TRK_REAL_C(1e6) + TRK_REAL_C(0.5));
    }
    t->has_time = 0;
    t->ws.ab_dt_us = 0; /* no steady state cached */
    t->next_id = 1;
    t->n_live = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        t->track[i].status = TRK_TRACK_FREE;
        t->track[i].id = 0;
    }
    return TRK_OK;
}

const struct trk_track *trk_tracker_track(const struct trk_tracker *t, size_t slot)
{
    if (!t || slot >= TRK_MAX_TRACKS || t->track[slot].status == TRK_TRACK_FREE) return NULL;
    return &t->track[slot];
}

size_t trk_tracker_live_count(const struct trk_tracker *t) { return t ? t->n_live : 0; }

trk_status trk_tracker_clutter_at(const struct trk_tracker *t, unsigned sensor_id, const struct trk_pose *pose,
                                  trk_real x_m, trk_real y_m, trk_real *lambda_per_m2)
{
    if (!t || !lambda_per_m2) return TRK_E_ARG;
    if (sensor_id >= t->params.n_sensors) return TRK_E_SENSOR;
    const struct trk_sensor_params *sp = &t->params.sensor[sensor_id];
    if (!pose) pose = &sp->pose;
    if (!isfinite(x_m) || !isfinite(y_m) || !isfinite(pose->x_m) || !isfinite(pose->y_m) ||
        !isfinite(pose->heading_rad))
        return TRK_E_NAN;
    struct trk_i_view v;
    trk_i_view_init(&v, sp, pose);
#if TRK_CLUTTER_MAP_CELLS > 0
    if (t->params.clutter == TRK_CLUTTER_PARAMETRIC)
        trk_i_map_view(&v, &t->params.clutter_map, t->clutter_map[sensor_id], t->clutter_map_scans[sensor_id]);
#endif
    *lambda_per_m2 = v.map ? trk_i_map_lambda_at(&v, x_m, y_m) : trk_i_view_clutter(&v, x_m, y_m);
    return TRK_OK;
}

size_t trk_tracker_sizeof(void) { return sizeof(struct trk_tracker); }
