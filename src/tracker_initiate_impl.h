/* tracker_initiate_impl.h (private) - step 5 of the scan: initiation
 * (trk/tracker.h, struct trk_init_params): the candidate store, two-point and
 * single-point starts, the initial existence, and the slot a new track
 * takes (free, else the weakest tentative track's).
 *
 * Included by tracker.c only (tracker_internal.h). */
#ifndef TRK_TRACKER_INITIATE_IMPL_H
#define TRK_TRACKER_INITIATE_IMPL_H

#include <string.h>

#include "track_filter_impl.h"
#include "track_life_impl.h"
#include "tracker_index_impl.h"

/* What initiation knows of the table within one scan (initiation only
 * fills slots, and changes no other track's quality): no free slot below
 * free_from; no_tentative once a search found the table full of confirmed
 * (or terminated) tracks; weakest (when >= 0) the full table's weakest
 * tentative track, of quality q_weakest, kept until it is replaced (a
 * refused start then costs no search of the table, so that a full table's
 * initiation is not tracks x detections). */
struct slots {
    size_t free_from;
    int no_tentative;
    long weakest; /* -1: not known */
    trk_real q_weakest;
};


static int slot_possible(const struct trk_tracker *t, struct slots *sl, struct trk_scan_report *rep);
/* What two-point pairing needs of each run of the store in one scan, run
 * k (cand_run) at [k]: dt_s the time since its scan (<= 0: it cannot pair),
 * reach_m the half side of the box that holds its velocity gates. Once per
 * scan (expire_candidates), not per detection. */
struct run_reach {
    trk_real dt_s[TRK_MAX_CANDIDATE_SCANS], reach_m[TRK_MAX_CANDIDATE_SCANS];
};

static struct run_reach expire_candidates(struct trk_tracker *t, const struct trk_scan *scan, const uint16_t *idx,
                                          size_t n);
static long best_candidate(const struct trk_tracker *t, const struct trk_scan *scan, size_t j,
                           const struct run_reach *rr, trk_real *r_j, size_t *run_k, trk_real *score);
static int start_pair(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t run_k, size_t c,
                      size_t j, const trk_real *r_j, const struct run_reach *rr, struct trk_scan_report *rep);
static int start_single(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t j,
                        const trk_real *r_j, struct trk_scan_report *rep);
static void store_candidates(struct trk_tracker *t, const struct trk_scan *scan, uint16_t *idx, size_t n,
                             struct trk_scan_report *rep);

/* Workspace detection j's covariance (its own or the sensor's) into r. */
static void detection_r(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real *r)
{
    if (j >= t->ws.n_shared) {
        det_r(t, scan, j, r); /* checked at load */
    } else {
        for (int i = 0; i < NZ * NZ; i++) r[i] = t->r[scan->sensor_id][i];
    }
}

/* Every valid detection no track used starts a track (single point, in
 * scan order), or pairs with a candidate (two points: the detections in
 * workspace order, gating's cells then scan order, each against the
 * store's runs, box queries in their 2-D indices); the unpaired ones become
 * candidates. */
static TRK_NOINLINE void initiate(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    struct slots sl = {0, 0, -1, 0};
    uint16_t *idx = t->ws.cand; /* the gated-set scratch is free by now */
    size_t n = 0;
    for (size_t j = 0; j < t->ws.n_valid; j++) /* where the sensor cannot see (P_D 0), nothing starts */
        if (!t->ws.used[j] && (!t->ws.view.limited || sensor_pd_at(t, scan, t->ws.x[j], t->ws.y[j]) > 0))
            idx[n++] = (uint16_t)j;
    if (t->params.init.method == TRK_INIT_SINGLE_POINT) {
        /* in scan order, as the detections came (the workspace holds the
         * shared ones in gating's cells): slots and ids do not depend on
         * gating's index */
        if (scan->n_detections <= TRK_MAX_DETECTIONS) {
            uint16_t *at = t->ws.u.sort.tmp; /* workspace index by scan index */
            for (size_t i = 0; i < scan->n_detections; i++) at[i] = UINT16_MAX;
            for (size_t k = 0; k < n; k++) at[t->ws.src[idx[k]]] = idx[k];
            n = 0;
            for (size_t i = 0; i < scan->n_detections; i++)
                if (at[i] != UINT16_MAX) idx[n++] = at[i];
        } else { /* a thinned scan: its indices reach past the scratch */
            sort_u16_by(idx, n, t->ws.src);
        }
        for (size_t k = 0; k < n; k++) {
            trk_real r_j[NZ * NZ];
            detection_r(t, scan, idx[k], r_j);
            (void)start_single(t, &sl, scan, idx[k], r_j, rep);
        }
    } else {
        const struct run_reach rr = expire_candidates(t, scan, idx, n);
        size_t n_new = 0;
        for (size_t k = 0; k < n; k++) t->ws.w[idx[k]] = 0; /* no refused pair ends at it (link_refused) */
        if (!slot_possible(t, &sl, NULL)) { /* every slot confirmed: no pair could start */
            rep->n_init_refused_full += (uint32_t)n;
            store_candidates(t, scan, idx, n, rep);
            rep->n_candidates = (uint32_t)t->n_cand;
            return;
        }
        /* the strongest pairs first: each detection's best pair's score (its
         * own ln l^a included), so that a candidate goes to the detection that
         * explains it best, not to the first one in reach (a persistent
         * return's candidate to its own next return, not to clutter beside it) */
        trk_real *score = t->ws.u.set.z; /* the gated-set scratch is free by now: */
        trk_real *best = score + TRK_MAX_DETECTIONS, *best_run = t->ws.u.set.r_own; /* (exact: < 2^16) */
        for (size_t k = 0; k < n; k++) {
            const size_t j = idx[k];
            trk_real r_j[NZ * NZ], sc = 0;
            size_t run_k = 0;
            const long c = best_candidate(t, scan, j, &rr, r_j, &run_k, &sc);
            score[j] = c >= 0 ? sc + t->ws.log_lr[j] : -TRK_REAL_MAX;
            best[j] = (trk_real)c;
            best_run[j] = (trk_real)run_k;
        }
        sort_u16_by_real_desc(idx, n, score);
        for (size_t k = 0; k < n; k++) {
            const size_t j = idx[k];
            trk_real r_j[NZ * NZ] = {0}, sc; /* r_j set when c >= 0 */
            size_t run_k = (size_t)best_run[j];
            long c = score[j] > -TRK_REAL_MAX ? (long)best[j] : -1;
            if (c >= 0 && t->cand[c].used) c = best_candidate(t, scan, j, &rr, r_j, &run_k, &sc); /* taken: the next best */
            else if (c >= 0) detection_r(t, scan, j, r_j);
            if (c >= 0 && start_pair(t, &sl, scan, run_k, (size_t)c, j, r_j, &rr, rep)) continue;
            idx[n_new++] = (uint16_t)j;
        }
        sort_u16_by(idx, n_new, NULL); /* the new candidates in workspace order */
        store_candidates(t, scan, idx, n_new, rep);
    }
    rep->n_candidates = (uint32_t)t->n_cand;
}

/* ------------------------------------------------------------------ existence and slots */

/* logistic(lo) without overflow: +inf -> 1, -inf -> 0 */
static trk_real logistic(trk_real lo)
{
    return lo >= 0 ? 1 / (1 + trk_exp(-lo)) : trk_exp(lo) / (1 + trk_exp(lo));
}

/* ln(beta l^a / lambda) of a point of sensor s at (x, y) with amplitude
 * ratio ln l^a = log_lr: the odds, over clutter, that it is a new target
 * (trk_init_params: a single point's start), lambda there as the scan's
 * sensor sees it (a candidate of another sensor: that sensor's lambda). */
static trk_real point_log_odds(const struct trk_tracker *t, const struct trk_scan *scan, unsigned s, trk_real x,
                               trk_real y, trk_real log_lr)
{
    return t->init_log_odds[s].first + log_lr - (s == scan->sensor_id ? sensor_log_lambda_ratio(t, scan, x, y) : 0);
}

/* A start's ln O from log_a, the ln odds of its n points being one new
 * target over their all being clutter (start_pair,
 * three_point_log_odds), against all clutter or any one of them a new
 * target on its own and the rest clutter (its point_log_odds, in point[]):
 * ln O = log_a - ln(1 + sum_i e^point_i) (trk_init_params; two targets at
 * once, beta^2, are left out, and so are a triple's pairs without its
 * third point). Why: a strong echo alone is a target's (at 13 dB a
 * target detection's l^a is e^17 on average), so a pair of it and any
 * clutter point in its velocity gate started at existence near 1 with the
 * clutter point's velocity, took the target's next detection and was
 * confirmed on it before it drifted off. Unchanged where log_a is not
 * finite: lambda = 0 makes it and every point's odds infinite (no clutter:
 * psi0 = 1 as before). */
static trk_real start_log_odds(trk_real log_a, const trk_real *point, size_t n)
{
    if (!(trk_fabs(log_a) < (trk_real)INFINITY)) return log_a;
    trk_real m = 0, sum = 1; /* ln(1 + sum e^p_i) = m + ln(sum e^(p_i - m)), p_0 = 0, running max m */
    for (size_t i = 0; i < n; i++) {
        const trk_real d = point[i] - m;
        if (d > 0) {
            sum = sum * trk_exp(-d) + 1;
            m = point[i];
        } else {
            sum += trk_exp(d);
        }
    }
    return log_a - m - trk_log(sum);
}


/* The ranking of replacement: existence, or n_hits / n_scans without it. */
static trk_real quality(const struct trk_tracker *t, const struct trk_track *tr)
{
    return t->params.track_visibility ? tr->vis.pv : (trk_real)tr->n_hits / (trk_real)tr->n_scans;
}

/* Can a new track get a slot at all? (Cheap: before its existence is
 * computed.) Counts the refusal in rep (unless NULL) when not. */
static int slot_possible(const struct trk_tracker *t, struct slots *sl, struct trk_scan_report *rep)
{
    if (t->n_live < TRK_MAX_TRACKS) return 1;
    if (sl->weakest >= 0) return 1;
    if (!sl->no_tentative) { /* not known yet: look */
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
            if (t->track[i].status == TRK_TRACK_TENTATIVE) return 1;
        sl->no_tentative = 1;
    }
    if (rep) rep->n_init_refused_full++;
    return 0;
}

/* A slot for a new track of quality q: a free one, else the weakest
 * tentative track's when it is weaker than q (replaced, counted); NULL and
 * counted when there is none. */
static struct trk_track *take_slot(struct trk_tracker *t, struct slots *sl, trk_real q, struct trk_scan_report *rep)
{
    if (t->n_live < TRK_MAX_TRACKS)
        for (size_t i = sl->free_from; i < TRK_MAX_TRACKS; i++)
            if (t->track[i].status == TRK_TRACK_FREE) {
                sl->free_from = i + 1;
                t->n_live++;
                return &t->track[i];
            }
    if (sl->weakest < 0) { /* the first slot in series since the last replacement */
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = &t->track[i];
            if (tr->status != TRK_TRACK_TENTATIVE) continue;
            const trk_real qi = quality(t, tr);
            if (sl->weakest < 0 || qi < sl->q_weakest) sl->weakest = (long)i, sl->q_weakest = qi;
        }
        sl->no_tentative = sl->weakest < 0;
    }
    if (sl->weakest >= 0 && sl->q_weakest < q) {
        struct trk_track *weakest = &t->track[sl->weakest];
        sl->weakest = -1; /* its new track's quality is q: search again next time */
        rep->n_replaced++;
        return weakest;
    }
    rep->n_init_refused_full++;
    return NULL;
}

/* A new tentative track in tr from n_points detections (the latest at the
 * scan time), existence psi0 (NaN: the visibility parameters' pv0); the
 * caller sets x and P. M/N counts each point as a detected look; the
 * existence test, the SPRT and the clutter tests start with the first
 * update: a pair alone is never confirmed, however high its existence
 * (measured: with strong amplitudes it confirmed clutter pairs, and without
 * clutter, lambda = 0, pairs of two targets' detections). */
static void new_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, trk_real psi0,
                      uint32_t n_points, struct trk_scan_report *rep)
{
    tr->id = t->next_id;
    t->next_id = t->next_id == UINT32_MAX ? 1 : t->next_id + 1;
    tr->status = TRK_TRACK_TENTATIVE;
    tr->end_reason = TRK_END_NONE;
    tr->time_us = scan->time_us;
    tr->n_scans = n_points;
    tr->n_hits = n_points;
    tr->n_misses_in_row = 0;
    tr->n_unseen_in_row = 0;
    tr->stationary = 0;
    tr->n_still_in_row = 0;
    tr->n_gated_last = 1;
    tr->beta0_last = 0;
    tr->term_stat = 0;
    if (!t->params.track_visibility) {
        memset(&tr->vis, 0, sizeof tr->vis);
    } else if (isnan(psi0)) {
        trk_visibility_reset(&t->vis_model, &tr->vis);
    } else {
        trk_visibility_reset_to(&t->vis_model, &tr->vis, psi0);
    }
    tr->existence0 = tr->vis.pv;
    filter_start(t, tr);
    trk_i_confirm_start(t, tr);
    rep->n_started++;
    if (t->params.confirm.method == TRK_CONFIRM_MN) {
        struct trk_look look = {0};
        look.detected = 1;
        look.sensor_id = scan->sensor_id;
        look.n_gated = 1;
        for (uint32_t k = 0; k < n_points && tr->status == TRK_TRACK_TENTATIVE; k++) step_tests(t, tr, &look, rep);
    }
}

/* The existence a new track starts with from its ln O (trk_init_params;
 * the per-sensor constants of struct trk_tracker init_log_odds), or NaN
 * (pv0) when birth_density_per_m2 is 0. */
static trk_real initial_existence(const struct trk_tracker *t, trk_real log_odds)
{
    return t->params.init.birth_density_per_m2 > 0 ? logistic(log_odds) : (trk_real)NAN;
}

/* The quality take_slot compares for a new track of existence psi0. */
static trk_real new_quality(const struct trk_tracker *t, trk_real psi0)
{
    if (!t->params.track_visibility) return 1;
    return isnan(psi0) ? t->vis_model.params.pv0 : psi0;
}

/* ------------------------------------------------------------------ single point */

/* A track at workspace detection j: position and its covariance from it,
 * velocity from the zero-mean prior. 0 when no slot was free. */
static int start_single(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t j,
                        const trk_real *r_j, struct trk_scan_report *rep)
{
    if (!slot_possible(t, sl, rep)) return 0;
    const trk_real psi0 =
        initial_existence(t, point_log_odds(t, scan, scan->sensor_id, t->ws.x[j], t->ws.y[j], t->ws.log_lr[j]));
    struct trk_track *tr = take_slot(t, sl, new_quality(t, psi0), rep);
    if (!tr) return 0;
    const trk_real vv = t->params.init_speed_sigma_mps * t->params.init_speed_sigma_mps;
    tr->x[X] = t->ws.x[j];
    tr->x[VX] = 0;
    tr->x[Y] = t->ws.y[j];
    tr->x[VY] = 0;
    for (int i = 0; i < NX * NX; i++) tr->p[i] = 0;
    tr->p[P(X, X)] = r_j[S(ZX, ZX)];
    tr->p[P(X, Y)] = tr->p[P(Y, X)] = r_j[S(ZX, ZY)];
    tr->p[P(Y, Y)] = r_j[S(ZY, ZY)];
    tr->p[P(VX, VX)] = tr->p[P(VY, VY)] = vv;
    new_track(t, tr, scan, psi0, 1, rep);
    return 1;
}

/* ------------------------------------------------------------------ two points */

/* Largest eigenvalue of a 2x2 symmetric matrix. */
static trk_real lambda_max2(const trk_real *a)
{
    const trk_real m = (a[S(ZX, ZX)] + a[S(ZY, ZY)]) / 2, h = (a[S(ZX, ZX)] - a[S(ZY, ZY)]) / 2;
    return m + trk_sqrt(h * h + a[S(ZX, ZY)] * a[S(ZX, ZY)]);
}

static void candidate_r(const struct trk_candidate *c, trk_real *r)
{
    trk_i_cov2_matrix(c->cov_m2, r); /* stored from a checked detection */
}

/* ln N(e; 0, S) of the 2-D point e = (ex, ey), S 2x2 SPD in s (closed-form
 * inverse), and its d^2 = e' S^-1 e in *d2; -TRK_REAL_MAX when S is not
 * positive definite. The one Gaussian of initiation: a pair's displacement
 * (pair_log_disp) and a third point's hit (three_point_log_odds). */
static TRK_NOINLINE trk_real log_normal2(const trk_real *s, trk_real ex, trk_real ey, trk_real *d2)
{
    const trk_real pi = TRK_REAL_C(3.14159265358979323846);
    const trk_real a = s[S(ZX, ZX)], b = s[S(ZX, ZY)], c = s[S(ZY, ZY)], det = a * c - b * b;
    if (!(a > 0 && det > 0)) return -TRK_REAL_MAX;
    *d2 = (c * ex * ex - 2 * b * ex * ey + a * ey * ey) / det;
    return -trk_log(2 * pi) - TRK_REAL_C(0.5) * trk_log(det) - TRK_REAL_C(0.5) * *d2;
}

/* ln of the density of the displacement from candidate c (R_c r_c) to
 * the point (x, y) of covariance R r, dt later, under the velocity prior of
 * a new track, v ~ N(0, s_v^2 I) with s_v = init_speed_sigma_mps (the prior
 * speed_prior fuses into its state), and the two points' noise:
 *   ln N((x, y) - z_c; 0, R_c + R + s_v^2 dt^2 I).
 * The one model of a target's second point: it ranks a detection's
 * candidates (best_candidate) and gives the pair's existence
 * (start_pair). The velocity gate (max_speed_mps) truncates it; the mass
 * it cuts off (a speed beyond v_max, 1.1 % at the defaults' 3 s_v) is not
 * renormalised. -TRK_REAL_MAX when the sum is not positive definite. */
static trk_real pair_log_disp(const struct trk_tracker *t, const struct trk_candidate *c, const trk_real *r_c,
                              trk_real x, trk_real y, const trk_real *r, trk_real dt)
{
    const trk_real sv = t->params.init_speed_sigma_mps * dt;
    trk_real s[NZ * NZ], d2;
    for (int i = 0; i < NZ * NZ; i++) s[i] = r_c[i] + r[i];
    s[S(ZX, ZX)] += sv * sv;
    s[S(ZY, ZY)] += sv * sv;
    return log_normal2(s, x - c->x_m, y - c->y_m, &d2);
}

/* The slot in t->run of run k of the store (0 the oldest). */
static size_t run_slot(const struct trk_tracker *t, size_t k) { return (t->run_first + k) % TRK_MAX_CANDIDATE_SCANS; }

static struct trk_i_cand_run *cand_run(struct trk_tracker *t, size_t k) { return &t->run[run_slot(t, k)]; }

/* A pair (candidate ci of run k, workspace detection j) refused for want
 * of a slot: j, stored as a candidate, remembers the pair's first point
 * (its run's age from this scan and its offset in it: both survive the
 * store's moves) in ws.w[j], free after the merge (0: none). */
static void link_refused(struct trk_tracker *t, size_t run_k, size_t ci, size_t j)
{
    const struct trk_i_cand_run *run = cand_run(t, run_k);
    const uint32_t age = t->scan_no - run->scan_no; /* 1 .. max_gap_scans */
    t->ws.w[j] = (trk_real)(age * 65536u + (uint32_t)(ci - run->start)); /* < 2^24: exact in float */
}

/* The scan number of the first point of the refused pair candidate c (of
 * run k, c->prev_age > 0) ended. */
static uint32_t refused_first_scan_no(struct trk_tracker *t, size_t k, const struct trk_candidate *c)
{
    return cand_run(t, k)->scan_no - c->prev_age;
}

/* The first point of the refused pair candidate c (of run k) ended, and
 * its run in *run_p; NULL when there is none or its run has gone. */
static const struct trk_candidate *refused_first(struct trk_tracker *t, size_t k, const struct trk_candidate *c,
                                                 const struct trk_i_cand_run **run_p)
{
    if (c->prev_age == 0) return NULL;
    const uint32_t scan_no = refused_first_scan_no(t, k, c);
    for (size_t m = 0; m < k; m++) {
        const struct trk_i_cand_run *r = cand_run(t, m);
        if (r->scan_no != scan_no) continue;
        if (c->prev_off >= r->n) return NULL;
        *run_p = r;
        return &t->cand[r->start + c->prev_off];
    }
    return NULL;
}

/* Drop the oldest run. */
static void drop_oldest_run(struct trk_tracker *t)
{
    t->n_cand -= cand_run(t, 0)->n_unused;
    t->run_first = (uint16_t)((t->run_first + 1) % TRK_MAX_CANDIDATE_SCANS);
    t->n_runs--;
}

/* Drop the runs older than max_gap_scans (runs are in scan order); what
 * pairing needs of the others this scan (struct run_reach): their dt, and
 * the half side v_max dt + sqrt(gamma (var_max + var_j)) of the box that
 * holds their velocity gates, var_j the largest tr R_j of the scan's n
 * unexplained detections idx (lambda_max(R_c + R_j) <= tr R_c + tr R_j). */
static struct run_reach expire_candidates(struct trk_tracker *t, const struct trk_scan *scan, const uint16_t *idx,
                                          size_t n)
{
    while (t->n_runs > 0 && t->scan_no - cand_run(t, 0)->scan_no > t->params.init.max_gap_scans) drop_oldest_run(t);
    const trk_real *r = t->r[scan->sensor_id];
    trk_real var_j = r[S(ZX, ZX)] + r[S(ZY, ZY)];
    for (size_t k = 0; k < n; k++) {
        trk_real c[3];
        if (idx[k] < t->ws.n_shared) continue; /* the sensor's R */
        det_cov(t, scan, idx[k], c);
        if (c[TRK_COV2_XX] + c[TRK_COV2_YY] > var_j) var_j = c[TRK_COV2_XX] + c[TRK_COV2_YY];
    }
    struct run_reach rr = {{0}, {0}}; /* the runs past n_runs are never read */
    const trk_real vmax = t->params.init.max_speed_mps, gamma = t->pda[scan->sensor_id].gamma;
    for (size_t k = 0; k < t->n_runs; k++) {
        const struct trk_i_cand_run *run = cand_run(t, k);
        rr.dt_s[k] = (trk_real)(scan->time_us - run->time_us) * TRK_REAL_C(1e-6);
        rr.reach_m[k] = (vmax * rr.dt_s[k] + trk_sqrt(gamma * (run->var_max_m2 + var_j))) * TRK_REAL_C(1.0001);
    }
    return rr;
}

/* The candidate detection j pairs with (trk_init_params: within the velocity
 * gate, the highest ln l^a - ln r; ties: the smaller x), its index in cand[]
 * and its run's in *run_k, that score in *score, or -1. Each run is searched in its box of
 * half side rr->reach_m (expire_candidates). r_j gets the detection's
 * covariance once a candidate is in a box (it is set whenever the result is
 * not -1). */
static long best_candidate(const struct trk_tracker *t, const struct trk_scan *scan, size_t j,
                           const struct run_reach *rr, trk_real *r_j, size_t *run_k, trk_real *score)
{
    const trk_real vmax = t->params.init.max_speed_mps, gamma = t->pda[scan->sensor_id].gamma;
    const trk_real xj = t->ws.x[j], yj = t->ws.y[j];
    long best = -1;
    int have_r = 0;
    trk_real best_score = 0;
    for (size_t k = 0; k < t->n_runs; k++) {
        const struct trk_i_cand_run *run = &t->run[run_slot(t, k)];
        const trk_real dt = rr->dt_s[k], reach = rr->reach_m[k];
        if (!(dt > 0) || run->n_unused == 0) continue;
        struct trk_i_grid_box box =
            trk_i_grid_box(&run->grid, t->cand_cell_end + run->start, xj - reach, xj + reach, yj - reach, yj + reach);
        size_t i0, i1;
        while (trk_i_grid_next(&box, &i0, &i1))
            for (size_t i = run->start + i0; i < run->start + i1; i++) {
                const struct trk_candidate *c = &t->cand[i];
                if (c->used || trk_fabs(xj - c->x_m) > reach || trk_fabs(yj - c->y_m) > reach) continue;
                if (!have_r) detection_r(t, scan, j, r_j), have_r = 1;
                trk_real r_c[NZ * NZ], r_sum[NZ * NZ];
                candidate_r(c, r_c);
                for (int q = 0; q < NZ * NZ; q++) r_sum[q] = r_c[q] + r_j[q];
                const trk_real dx = xj - c->x_m, dy = yj - c->y_m, d2 = dx * dx + dy * dy;
                const trk_real lim = vmax * dt + trk_sqrt(gamma * lambda_max2(r_sum));
                if (d2 > lim * lim) continue;
                /* ln l^a of the candidate and ln of the displacement's density */
                const trk_real sc = c->log_lr + pair_log_disp(t, c, r_c, xj, yj, r_j, dt);
                if (best < 0 || sc > best_score || (sc == best_score && c->x_m < t->cand[best].x_m)) {
                    best = (long)i, best_score = sc;
                    *run_k = k;
                }
            }
    }
    *score = best_score;
    return best;
}

/* ln(P_D / lambda) of a new track's point at (x, y) of sensor s
 * (init_log_odds.second): with the scan sensor's P_D profile or coverage,
 * or its clutter profile, its P_D and lambda there (a candidate of an earlier scan seen from this scan's pose:
 * the platform moves little between two scans against the profile's
 * scale). */
static trk_real second_log_odds(const struct trk_tracker *t, const struct trk_scan *scan, unsigned s, trk_real x,
                                trk_real y)
{
    if (s != scan->sensor_id || (!t->ws.view.limited && !t->ws.view.clutter_varies)) return t->init_log_odds[s].second;
    return t->init_log_odds[s].second + trk_log(sensor_pd_at(t, scan, x, y)) - trk_log(t->pda[s].params.pd) -
           sensor_log_lambda_ratio(t, scan, x, y);
}

/* The velocity prior v ~ N(0, init_speed_sigma_mps^2 I) (the single-point
 * start's) fused into a two-point state x, P: a Kalman update with the
 * "measurement" v = 0 of that covariance (trk_kalman_update, Joseph form).
 * Two points' velocity alone has variance (R_c + R_j) / dt^2: with a
 * sonar's cross-range error at 6 km (157 m) and 8 s between pings, 28 m/s,
 * which no target reaches; the prior bounds it, so the new track's gate and
 * its next detection's likelihood are those of a target that moves as
 * targets do. Where the two points are precise (sigma 5 m, 4 s: 1.8 m/s)
 * it changes little. */
static trk_status speed_prior(const struct trk_tracker *t, trk_real *x, trk_real *p)
{
    static const trk_real h_v[NZ * NX] = {0, 1, 0, 0, 0, 0, 0, 1};
    const trk_real v = t->params.init_speed_sigma_mps * t->params.init_speed_sigma_mps;
    const trk_real r_v[NZ * NZ] = {v, 0, 0, v}, zero[NZ] = {0, 0};
    const trk_status st = trk_kalman_update(NX, NZ, h_v, r_v, zero, x, p);
    return st == TRK_OK ? trk_i_spd(NX, p) : st; /* as the two points' P: SPD or no track */
}

/* The three points' ln odds over clutter (trk_init_params) of workspace
 * detection j (R_j r_j) continuing the refused pair (p, c) that candidate
 * c of run k ended, dt after c: the pair's plus the hit's ln(P_D l^a
 * N(z_j; z^, S) / lambda), z^ = z_c + a (z_c - z_p), a = dt / dt_pc, S =
 * R_j + (1 + a)^2 R_c + a^2 R_p + q dt^3 / 3 I (the pair's two-point
 * track predicted by dt: P_pp + 2 dt P_pv + dt^2 P_vv + Q_pp), and the
 * first point's point_log_odds in *point_p; -inf when there is no such
 * pair or j is outside that track's gate (d2 > gamma). */
static trk_real three_point_log_odds(struct trk_tracker *t, const struct trk_scan *scan, size_t k,
                                     const struct trk_candidate *c, const trk_real *r_c, size_t j,
                                     const trk_real *r_j, trk_real dt, trk_real *point_p)
{
    const struct trk_i_cand_run *run_p = NULL;
    const struct trk_candidate *cp = refused_first(t, k, c, &run_p);
    if (!cp) return -TRK_REAL_MAX;
    const struct trk_i_cand_run *run_c = cand_run(t, k);
    const trk_real dt_pc = (trk_real)(run_c->time_us - run_p->time_us) * TRK_REAL_C(1e-6);
    if (!(dt_pc > 0)) return -TRK_REAL_MAX;
    const trk_real a = dt / dt_pc, qp = t->params.process_noise_q * dt * dt * dt / 3;
    trk_real r_p[NZ * NZ], s[NZ * NZ];
    candidate_r(cp, r_p);
    for (int i = 0; i < NZ * NZ; i++) s[i] = r_j[i] + (1 + a) * (1 + a) * r_c[i] + a * a * r_p[i];
    s[S(ZX, ZX)] += qp;
    s[S(ZY, ZY)] += qp;
    const trk_real ex = t->ws.x[j] - (c->x_m + a * (c->x_m - cp->x_m));
    const trk_real ey = t->ws.y[j] - (c->y_m + a * (c->y_m - cp->y_m));
    trk_real d2 = 0;
    const trk_real log_n = log_normal2(s, ex, ey, &d2);
    if (log_n == -TRK_REAL_MAX || !(d2 <= t->pda[scan->sensor_id].gamma)) return -TRK_REAL_MAX;
    const trk_real hit = second_log_odds(t, scan, scan->sensor_id, t->ws.x[j], t->ws.y[j]) + t->ws.log_lr[j] + log_n;
    *point_p = point_log_odds(t, scan, run_p->sensor_id, cp->x_m, cp->y_m, cp->log_lr);
    /* the pair (p, c)'s ln odds over clutter (as start_pair's), then the hit */
    return *point_p + (second_log_odds(t, scan, run_c->sensor_id, c->x_m, c->y_m) + c->log_lr) +
           pair_log_disp(t, cp, r_p, c->x_m, c->y_m, r_c, dt_pc) + hit;
}

/* Is workspace detection j, with candidate c of run k, the third point of
 * a refused or deferred pair (init.min_existence: three points always
 * start)? Yes when its three-point ln O log_odds3 is finite, and also when
 * c ended such a pair whose first point, young enough to be kept, has
 * left the store to make room (scans of more than half the store's
 * candidates each): the line cannot be checked, and the start falls back
 * to the pair's odds rather than wait for a third point that could never
 * be counted. A first point older than max_gap_scans has expired as every
 * candidate does: then (c, j) is a pair of its own, and waits. */
static int third_point(struct trk_tracker *t, size_t k, const struct trk_candidate *c, trk_real log_odds3)
{
    if (log_odds3 > -TRK_REAL_MAX) return 1;
    if (c->prev_age == 0) return 0;
    const uint32_t age_p = t->scan_no - refused_first_scan_no(t, k, c); /* the first point's age */
    const struct trk_i_cand_run *run_p = NULL;
    return age_p <= t->params.init.max_gap_scans && !refused_first(t, k, c, &run_p);
}

/* A track from candidate c and workspace detection j (two-point
 * differencing, trk_init_params): x = z_j, v = (z_j - z_c) / dt,
 * P_pp = R_j, P_pv = R_j / dt, P_vv = (R_c + R_j) / dt^2. 0 when no slot,
 * or when that P is not positive definite in this arithmetic. */
static int start_pair(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t run_k, size_t ci,
                      size_t j, const trk_real *r_j, const struct run_reach *rr, struct trk_scan_report *rep)
{
    if (!slot_possible(t, sl, rep)) {
        link_refused(t, run_k, ci, j);
        return 0;
    }
    struct trk_i_cand_run *run = cand_run(t, run_k);
    struct trk_candidate *c = &t->cand[ci];
    const trk_real dt = rr->dt_s[run_k];
    trk_real r_c[NZ * NZ], x[NX], p[NX * NX];
    candidate_r(c, r_c);
    /* ln O = ln(beta l_c / lambda_c) + ln(P_D l_j / lambda_j) + ln N(z_j - z_c;
     * 0, R_c + R_j + s_v^2 dt^2 I) - ln(1 + O_c + O_j), or the three
     * points' when c ended a refused pair that j continues (- ln(1 + O_p +
     * O_c + O_j)): start_log_odds */
    trk_real point[3] = {point_log_odds(t, scan, run->sensor_id, c->x_m, c->y_m, c->log_lr),
                         point_log_odds(t, scan, scan->sensor_id, t->ws.x[j], t->ws.y[j], t->ws.log_lr[j]), 0};
    const trk_real log_odds = start_log_odds(point[0] + /* the pair's ln odds over clutter */
                                                 second_log_odds(t, scan, scan->sensor_id, t->ws.x[j], t->ws.y[j]) +
                                                 t->ws.log_lr[j] + pair_log_disp(t, c, r_c, t->ws.x[j], t->ws.y[j], r_j, dt),
                                             point, 2);
    trk_real log_odds3 = three_point_log_odds(t, scan, run_k, c, r_c, j, r_j, dt, &point[2]);
    if (log_odds3 > -TRK_REAL_MAX) log_odds3 = start_log_odds(log_odds3, point, 3);
    const trk_real psi0 = initial_existence(t, log_odds3 > -TRK_REAL_MAX ? log_odds3 : log_odds);
    if (psi0 < t->params.init.min_existence && !third_point(t, run_k, c, log_odds3)) { /* a weak pair (NaN
                                                                  never is): j waits for a third point */
        link_refused(t, run_k, ci, j);
        rep->n_init_deferred++;
        return 0;
    }
    const trk_real z_c[NZ] = {c->x_m, c->y_m}, z_j[NZ] = {t->ws.x[j], t->ws.y[j]};
    /* P is SPD in exact arithmetic; rounding can break it when R_c is tiny
     * against R_j: then no track, the detection stays a candidate */
    if (trk_cv2_two_point(z_c, r_c, z_j, r_j, dt, x, p) != TRK_OK || speed_prior(t, x, p) != TRK_OK) return 0;
    struct trk_track *tr = take_slot(t, sl, new_quality(t, psi0), rep);
    if (!tr) {
        link_refused(t, run_k, ci, j);
        return 0;
    }
    for (int k = 0; k < NX; k++) tr->x[k] = x[k];
    for (int k = 0; k < NX * NX; k++) tr->p[k] = p[k];
    c->used = 1;
    run->n_unused--;
    t->n_cand--;
    new_track(t, tr, scan, psi0, 2, rep);
    return 1;
}

/* ------------------------------------------------------------------ the store */

/* The live runs by their place in cand[]: order[0, n_runs) their ages
 * (cand_run's k), by increasing start. */
static void runs_by_start(struct trk_tracker *t, uint8_t *order)
{
    for (size_t k = 0; k < t->n_runs; k++) {
        size_t m = k;
        for (; m > 0 && cand_run(t, order[m - 1])->start > cand_run(t, k)->start; m--) order[m] = order[m - 1];
        order[m] = (uint8_t)k;
    }
}

/* The live runs (by start, order) moved down to be contiguous from 0: each
 * moves down, so it never overwrites one not yet moved. */
static void pack_runs(struct trk_tracker *t, const uint8_t *order)
{
    size_t w = 0;
    for (size_t k = 0; k < t->n_runs; k++) {
        struct trk_i_cand_run *r = cand_run(t, order[k]);
        if (r->start != w) {
            memmove(t->cand + w, t->cand + r->start, r->n * sizeof t->cand[0]);
            memmove(t->cand_cell_end + w, t->cand_cell_end + r->start, r->n * sizeof t->cand_cell_end[0]);
            r->start = (uint16_t)w;
        }
        w += r->n;
    }
}

/* Where a run of n (1 .. TRK_MAX_CANDIDATES) candidates goes, over no live
 * run: the first gap between the runs (in cand[] order) that holds it;
 * else, when the free room is split into gaps each too small, after the
 * live runs moved down to 0; the oldest runs make room while the store
 * holds too many. A used candidate keeps its place until its run goes. */
static size_t place_run(struct trk_tracker *t, size_t n)
{
    for (;;) {
        if (t->n_runs < TRK_MAX_CANDIDATE_SCANS) {
            uint8_t order[TRK_MAX_CANDIDATE_SCANS];
            size_t prev = 0, held = 0;
            runs_by_start(t, order);
            for (size_t k = 0; k < t->n_runs; k++) {
                const struct trk_i_cand_run *r = cand_run(t, order[k]);
                if ((size_t)r->start - prev >= n) return prev;
                prev = (size_t)r->start + r->n;
                held += r->n;
            }
            if (TRK_MAX_CANDIDATES - prev >= n) return prev;
            if (TRK_MAX_CANDIDATES - held >= n) {
                pack_runs(t, order);
                return held;
            }
        }
        drop_oldest_run(t);
    }
}

/* The candidate of workspace detection j. */
static void fill_candidate(const struct trk_tracker *t, const struct trk_scan *scan, size_t j,
                           struct trk_candidate *c)
{
    trk_real r[NZ * NZ];
    detection_r(t, scan, j, r);
    c->x_m = t->ws.x[j];
    c->y_m = t->ws.y[j];
    c->cov_m2[TRK_COV2_XX] = r[S(ZX, ZX)];
    c->cov_m2[TRK_COV2_XY] = r[S(ZX, ZY)];
    c->cov_m2[TRK_COV2_YY] = r[S(ZY, ZY)];
    c->log_lr = t->ws.log_lr[j];
    c->used = 0;
    const uint32_t link = (uint32_t)t->ws.w[j]; /* link_refused */
    c->prev_age = (uint8_t)(link >> 16);
    c->prev_off = (uint16_t)(link & 0xffffu);
}

/* The scan's unpaired detections idx[0..n) (in workspace order) into the
 * store as the newest run, in its 2-D index (grid_order); what does not fit
 * even after evicting every older run is counted as dropped (the last in
 * workspace order). */
static void store_candidates(struct trk_tracker *t, const struct trk_scan *scan, uint16_t *idx, size_t n,
                             struct trk_scan_report *rep)
{
    if (n > TRK_MAX_CANDIDATES) {
        rep->n_candidates_dropped += (uint32_t)(n - TRK_MAX_CANDIDATES);
        n = TRK_MAX_CANDIDATES;
    }
    if (n == 0) return;
    const size_t start = place_run(t, n);
    struct trk_i_cand_run *run = cand_run(t, t->n_runs);
    t->n_runs++;
    run->time_us = scan->time_us;
    run->scan_no = t->scan_no;
    run->start = (uint16_t)start;
    run->n = run->n_unused = (uint16_t)n;
    run->sensor_id = (uint8_t)scan->sensor_id;
    grid_order(t, t->ws.x, t->ws.y, idx, n, &run->grid, t->cand_cell_end + start);
    run->var_max_m2 = 0;
    for (size_t k = 0; k < n; k++) {
        struct trk_candidate *c = &t->cand[start + k];
        fill_candidate(t, scan, idx[k], c);
        if (c->cov_m2[TRK_COV2_XX] + c->cov_m2[TRK_COV2_YY] > run->var_max_m2)
            run->var_max_m2 = c->cov_m2[TRK_COV2_XX] + c->cov_m2[TRK_COV2_YY];
    }
    t->n_cand += n;
}

#endif
