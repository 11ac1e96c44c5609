/* tracker.c - the scan (trk/tracker.h): trk_tracker_process_scan and its
 * stages, in the order they run (as Stone Soup's MultiTargetTracker loop),
 * then trk_tracker_init and the table accessors. The only module that loops
 * over tracks. One track's update (predict, gate, PDA) is
 * tracker_update_impl.h, initiation tracker_initiate_impl.h, the parameter
 * check tracker_params.c. */
#include <string.h>

#include "tracker_impl.h"
#include "tracker_initiate_impl.h"
#include "tracker_update_impl.h"
#if TRK_WITH_JOINT
#include "tracker_joint_impl.h"
#endif

/* How the scan's detections are read. */
struct amp_use {
    const struct trk_sensor_params *sp;
    trk_real max_coord_m; /* the surveillance bound (params.max_coord_m) */
    int want_db;       /* the clutter-amplitude test needs the amplitudes in dB */
    trk_real ref_db;   /* mean clutter power (dB): the amplitudes' reference */
};

static int detection_usable(const struct trk_detection *d, const struct amp_use *au, struct trk_scan_report *rep,
                            trk_real *llr);
#include "tracker_thin_impl.h" /* a scan beyond capacity: uses the two above */

static trk_status check_scan(const struct trk_tracker *t, const struct trk_scan *scan);
static void free_terminated(struct trk_tracker *t);
static TRK_NOINLINE void load_detections(struct trk_tracker *t, const struct trk_scan *scan, struct thin *th,
                            struct trk_scan_report *rep);
static void order_by_grid(struct trk_tracker *t);
static void update_each(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep);
#if TRK_WITH_JOINT
static void update_joint(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep);
#endif
static void update_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, size_t joint_k,
                         struct trk_scan_report *rep);
static void step_tests(struct trk_tracker *t, struct trk_track *tr, const struct trk_look *look,
                       struct trk_scan_report *rep);
static void merge_duplicates(struct trk_tracker *t, struct trk_scan_report *rep);

/* update_track's joint_k of a track updated by its own PDA */
#define JOINT_NONE ((size_t)-1)

static int is_live(const struct trk_track *tr)
{
    return tr->status == TRK_TRACK_TENTATIVE || tr->status == TRK_TRACK_CONFIRMED;
}

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
    free_terminated(t);
    struct thin th = {0, 0, 0, 0, 0};
    load_detections(t, scan, &th, &rep);
    struct thin_saved saved = {0}; /* written by thin_apply when it returns TRK_OK */
    const int model = th.in_gates && thin_apply(t, scan->sensor_id, &th, &saved) == TRK_OK;
#if TRK_WITH_JOINT
    if (t->params.association == TRK_ASSOC_JOINT) update_joint(t, scan, &rep);
    else
#endif
        update_each(t, scan, &rep);
    if (model) thin_restore(t, scan->sensor_id, &saved);
    if (t->params.merge_gate_d2 > 0) merge_duplicates(t, &rep);
    initiate(t, scan, &rep);
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
    if (scan->n_detections > 0 && !scan->detections) return TRK_E_ARG;
    if (scan->sensor_id >= t->params.n_sensors) return TRK_E_SENSOR;
    /* |time| <= 2^62 keeps every difference of two times representable */
    if (scan->time_us > TRK_TIME_US_MAX || scan->time_us < -TRK_TIME_US_MAX) return TRK_E_RANGE;
    if (t->has_time && scan->time_us < t->last_time_us) return TRK_E_TIME;
    if (t->has_time && scan->time_us - t->last_time_us > t->max_dt_us) return TRK_E_RANGE;
    return TRK_OK;
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

/* TRK_OK for a usable detection, else why not: TRK_E_NAN non-finite
 * position or covariance, TRK_E_NOT_SPD covariance, TRK_E_RANGE amplitude
 * NaN, infinite or negative. */
static trk_status check_detection(const struct trk_detection *d)
{
    trk_real r[NZ * NZ];
    if (!isfinite(d->x_m) || !isfinite(d->y_m)) return TRK_E_NAN;
    if (d->has_amplitude && !(d->amplitude >= 0 && d->amplitude <= TRK_REAL_MAX)) return TRK_E_RANGE;
    return d->has_cov ? trk_i_cov2_unpack(d->cov_m2, r) : TRK_OK;
}

/* Is detection d usable: 1 with its ln l^a in *llr, else 0 and counted
 * why not: a finite position outside the surveillance bound, the checks
 * above, then with an amplitude model its ln l^a (PDAFAI, Brekke eqs
 * 19-20, once per scan), refusing amplitudes below the threshold. */
static int detection_usable(const struct trk_detection *d, const struct amp_use *au, struct trk_scan_report *rep,
                            trk_real *llr)
{
    if (isfinite(d->x_m) && isfinite(d->y_m) && !(trk_fabs(d->x_m) <= au->max_coord_m && trk_fabs(d->y_m) <= au->max_coord_m)) {
        rep->n_rejected_region++; /* outside the surveillance bound: no position (trk/tracker.h) */
        return 0;
    }
    trk_status st = check_detection(d);
    if (st != TRK_OK) {
        if (st == TRK_E_NAN) rep->n_rejected_nonfinite++;
        else if (st == TRK_E_RANGE) rep->n_rejected_amplitude++;
        else rep->n_rejected_cov++;
        return 0;
    }
    *llr = 0; /* positions only: l^a = 1 */
    if (au->sp->use_amplitude && d->has_amplitude) {
        st = trk_amplitude_log_lr(&au->sp->amplitude, d->amplitude, llr);
        /* TRK_E_RANGE at or above the threshold: ln l^a beyond the real type (a Rayleigh
         * amplitude above ~1e154 sqrt(P)), a bad amplitude, not one below the threshold */
        if (st == TRK_E_RANGE && d->amplitude < trk_amplitude_threshold(&au->sp->amplitude))
            rep->n_below_threshold++;
        else if (st != TRK_OK) rep->n_rejected_amplitude++;
        if (st != TRK_OK) return 0;
    }
    return 1;
}

/* Take scan detection i into the workspace, or count why not
 * (detection_usable). */
static void load_detection(struct trk_tracker *t, const struct trk_scan *scan, size_t i,
                           const struct amp_use *au, struct trk_scan_report *rep)
{
    const struct trk_detection *d = &scan->detections[i];
    trk_real llr;
    if (!detection_usable(d, au, rep, &llr)) return;
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

/* The valid detections into the workspace: those with the sensor's
 * covariance first [0, n_shared), in gating's 2-D index (ws.grid,
 * src/grid_impl.h), own-covariance ones after, in scan
 * order; rejections are counted. A scan beyond capacity loads the ones
 * thin_select kept (their scan indices, ascending, in ws.cand), the model
 * of what it kept into *th. The amplitudes (dB) are then doubled (see
 * clutter_look in tracker_update_impl.h). */
static TRK_NOINLINE void load_detections(struct trk_tracker *t, const struct trk_scan *scan, struct thin *th,
                            struct trk_scan_report *rep)
{
    const struct trk_sensor_params *sp = &t->params.sensor[scan->sensor_id];
    const struct amp_use au = {
        sp, t->params.max_coord_m, t->params.confirm.method == TRK_CONFIRM_CLUTTER_AMP, /* the dB values' only user */
        TRK_REAL_C(10.0) * trk_log10(sp->use_amplitude ? sp->amplitude.clutter_power : 1)};
    const int over = scan->n_detections > TRK_MAX_DETECTIONS;
    const size_t n_load = over ? thin_select(t, scan, &au, th, rep) : scan->n_detections;
    t->ws.n_valid = 0;
    t->ws.n_amp = 0;
    for (int own = 0; own <= 1; own++) {
        for (size_t k = 0; k < n_load; k++) {
            const size_t i = over ? t->ws.cand[k] : k;
            if ((scan->detections[i].has_cov != 0) == own) load_detection(t, scan, i, &au, rep);
        }
        if (!own) t->ws.n_shared = t->ws.n_valid;
    }
    rep->n_kept = (uint32_t)t->ws.n_valid;
    order_by_grid(t);
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

/* The shared-covariance group [0, n_shared) in gating's 2-D index, once
 * per scan (ws.grid, grid_order: O(n) for spread positions): position j
 * takes detection idx[j], cycle by cycle in place, with used[] (all 0 at
 * load) marking the positions filled. */
static void order_by_grid(struct trk_tracker *t)
{
    const size_t n = t->ws.n_shared;
    uint16_t *idx = t->ws.cand; /* free until the first track is gated */
    for (size_t j = 0; j < n; j++) idx[j] = (uint16_t)j;
    grid_order(t, t->ws.x, t->ws.y, idx, n, &t->ws.grid, t->ws.cell_end);
    for (size_t i = 0; i < n; i++) {
        if (t->ws.used[i] || idx[i] == i) continue;
        const trk_real x = t->ws.x[i], y = t->ws.y[i], llr = t->ws.log_lr[i];
        const uint16_t src = t->ws.src[i];
        const int16_t amp = t->ws.amp_pos[i];
        size_t j = i;
        for (size_t k = idx[j]; k != i; j = k, k = idx[j]) {
            ws_move(t, j, k);
            t->ws.used[j] = 1;
        }
        t->ws.x[j] = x;
        t->ws.y[j] = y;
        t->ws.src[j] = src;
        t->ws.log_lr[j] = llr;
        t->ws.amp_pos[j] = amp;
        t->ws.used[j] = 1;
    }
    for (size_t j = 0; j < n; j++) t->ws.used[j] = 0;
}

static void end_track(struct trk_track *tr, enum trk_track_end why, struct trk_scan_report *rep)
{
    tr->status = TRK_TRACK_TERMINATED;
    tr->end_reason = (uint8_t)why;
    rep->n_terminated++;
    if (why == TRK_END_NUMERICAL) rep->n_numerical++;
    if (why == TRK_END_MERGED) rep->n_merged++;
}

/* Per-track PDA: confirmed tracks first, since a tentative track may not
 * use the detections in a confirmed track's gate (it would become its
 * duplicate). */
static void update_each(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (t->track[i].status == TRK_TRACK_CONFIRMED) update_track(t, &t->track[i], scan, JOINT_NONE, rep);
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (t->track[i].status == TRK_TRACK_TENTATIVE) update_track(t, &t->track[i], scan, JOINT_NONE, rep);
}

#if TRK_WITH_JOINT
/* Joint association (tracker_joint_impl.h): gate every live track, solve
 * the clusters, update each joint track in the order it was gated; then the
 * tracks left out of the joint problem, each by its own PDA (confirmed ones
 * first), whose gated sets take the pair store from its start. */
static void update_joint(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    joint_gate(t, scan, rep);
    joint_solve(t, rep);
    for (size_t k = 0; k < t->ws.n_joint; k++) update_track(t, &t->track[t->ws.joint_slot[k]], scan, k, rep);
    for (int confirmed = 1; confirmed >= 0; confirmed--) {
        const uint8_t want = confirmed ? TRK_TRACK_CONFIRMED : TRK_TRACK_TENTATIVE;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
            if (!t->ws.in_joint[i] && t->track[i].status == want) update_track(t, &t->track[i], scan, JOINT_NONE, rep);
    }
}
#endif

/* One live track: update (predict, gate, PDA; or, as joint track joint_k,
 * the joint association's update), the covariance bound, count the look,
 * step its test. */
static void update_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, size_t joint_k,
                         struct trk_scan_report *rep)
{
    struct trk_look look;
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
    tr->n_scans++;
    if (failed > 0 || over_covariance_bound(t, tr->p, scan->sensor_id)) {
        end_track(tr, TRK_END_COVARIANCE, rep);
        rep->n_covariance++;
        return;
    }
    if (look.detected) {
        tr->n_hits++;
        tr->n_misses_in_row = 0;
        rep->n_tracks_hit++;
    } else {
        tr->n_misses_in_row++;
    }
    step_tests(t, tr, &look, rep);
}

/* The track's test on this look and what it decides: confirmation (or
 * rejection, or the tentative age limit) of a tentative track, termination
 * of a confirmed one. */
static void step_tests(struct trk_tracker *t, struct trk_track *tr, const struct trk_look *look,
                       struct trk_scan_report *rep)
{
    if (tr->status == TRK_TRACK_TENTATIVE) {
        const int d = trk_i_confirm_step(t, tr, look);
        if (d > 0) {
            tr->status = TRK_TRACK_CONFIRMED;
            trk_i_term_start(t, tr);
            rep->n_confirmed++;
        } else if (d < 0) {
            end_track(tr, TRK_END_REJECTED, rep);
        } else if (t->params.max_tentative_scans && tr->n_scans > t->params.max_tentative_scans) {
            end_track(tr, TRK_END_TENTATIVE_AGE, rep);
        }
    } else if (trk_i_term_step(t, tr, look)) {
        end_track(tr, TRK_END_TERMINATED, rep);
    }
}

/* Is track a stronger than b (kept when they merge)? Confirmed over
 * tentative, then more hits, then older (smaller id: ids only grow, except
 * after 2^32 tracks). */
static int stronger(const struct trk_track *a, const struct trk_track *b)
{
    if (a->status != b->status) return a->status == TRK_TRACK_CONFIRMED;
    if (a->n_hits != b->n_hits) return a->n_hits > b->n_hits;
    return a->id < b->id;
}

/* Can live tracks a and b follow one target? The cheap test on the
 * positions alone (inlined in the pair loop): d2 >= dx^2 / (Pa_xx + Pb_xx)
 * for the x (and y) component, so a pair failing it is not a duplicate. */
static int may_duplicate(const struct trk_track *a, const struct trk_track *b, trk_real g)
{
    const trk_real ex = a->x[X] - b->x[X], ey = a->x[Y] - b->x[Y];
    return ex * ex <= g * (a->p[P(X, X)] + b->p[P(X, X)]) && ey * ey <= g * (a->p[P(Y, Y)] + b->p[P(Y, Y)]);
}

/* Do live tracks a and b follow one target: d2 = dx' (P_a + P_b)^-1 dx <= g
 * over [x, vx, y, vy] (the track-to-track test without the common
 * process-noise cross-covariance, which would only make d2 larger)? */
static TRK_NOINLINE int duplicates(const struct trk_track *a, const struct trk_track *b, trk_real g)
{
    trk_real c[NX * NX], l[NX * NX], li[NX * NX], dx[NX], y[NX], d2 = 0;
    for (int k = 0; k < NX * NX; k++) c[k] = a->p[k] + b->p[k];
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
    if (!is_live(a) || !is_live(b) || !may_duplicate(a, b, g) || !duplicates(a, b, g)) return;
    end_track(stronger(a, b) ? b : a, TRK_END_MERGED, rep);
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
            idx[n++] = (uint16_t)i;
            kx[i] = a->x[X];
            ky[i] = a->x[Y];
            if (a->p[P(X, X)] > pmax_x) pmax_x = a->p[P(X, X)];
            if (a->p[P(Y, Y)] > pmax_y) pmax_y = a->p[P(Y, Y)];
        }
    struct trk_i_grid grid;
    grid_order(t, kx, ky, idx, n, &grid, t->ws.cell_end);
    uint16_t *out = t->ws.u.merge.pair; /* after the index: its scratch shares the union */
    for (size_t k = 0; k < n; k++) {
        const struct trk_track *a = &t->track[idx[k]];
        const trk_real rx = trk_sqrt(g * (a->p[P(X, X)] + pmax_x)) * (1 + 16 * TRK_REAL_EPS);
        const trk_real ry = trk_sqrt(g * (a->p[P(Y, Y)] + pmax_y)) * (1 + 16 * TRK_REAL_EPS);
        struct trk_i_grid_box box = trk_i_grid_box(&grid, t->ws.cell_end, a->x[X] - rx, a->x[X] + rx, a->x[Y] - ry,
                                                   a->x[Y] + ry);
        size_t l0, l1;
        while (trk_i_grid_next(&box, &l0, &l1))
            for (size_t l = l0; l < l1; l++) {
                const uint16_t i = idx[k], j = idx[l];
                if (i >= j || !may_duplicate(a, &t->track[j], g)) continue; /* each pair once */
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
        t->max_pos_var_m2[s] = p->max_pos_sigma_ratio * p->max_pos_sigma_ratio * (r[s][S(ZX, ZX)] + r[s][S(ZY, ZY)]);
        const trk_real lambda = pda[s].params.clutter_density, beta = p->init.birth_density_per_m2;
        t->init_log_odds[s].first = lambda > 0 ? trk_log(beta) - trk_log(lambda) : (trk_real)INFINITY;
        t->init_log_odds[s].second = lambda > 0 ? trk_log(pda[s].params.pd) - trk_log(lambda) : (trk_real)INFINITY;
#if TRK_WITH_JOINT
        t->log_clutter_density[s] = lambda > 0 ? trk_log(lambda) : -(trk_real)INFINITY; /* joint needs > 0 */
#endif
    }
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

size_t trk_tracker_sizeof(void) { return sizeof(struct trk_tracker); }
