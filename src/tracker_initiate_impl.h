/* tracker_initiate_impl.h (private) - step 5 of the scan: initiation
 * (trk/tracker.h, struct trk_init_params): the candidate store, two-point and
 * single-point starts, the initial existence, and the slot a new track
 * takes (free, else the weakest tentative track's).
 *
 * Included by tracker.c only (the layout of struct trk_tracker depends on
 * config.h options; see tracker_update_impl.h). */
#ifndef TRK_TRACKER_INITIATE_IMPL_H
#define TRK_TRACKER_INITIATE_IMPL_H

#include <string.h>

#include "tracker_impl.h"

/* What initiation knows of the table within one scan (initiation only
 * fills slots, and changes no other track's quality): no free slot below
 * free_from; no_tentative once a search found the table full of confirmed
 * (or terminated) tracks; weakest (when >= 0) the full table's weakest
 * tentative track, of quality q_weakest, kept until it is replaced (issue
 * 19: a refused start then costs no search of the table, so that a full
 * table's initiation is not tracks x detections). */
struct slots {
    size_t free_from;
    int no_tentative;
    long weakest; /* -1: not known */
    trk_real q_weakest;
};

/* What bounds every velocity gate of a scan: no candidate farther than
 * reach_m in x from a detection can pair with it. */
struct cand_reach {
    trk_real reach_m;
};

static void sort_by_x(struct trk_tracker *t, uint16_t *idx, size_t n);
static void sort_by_key(struct trk_tracker *t, const trk_real *key, uint16_t *idx, size_t n);
static int slot_possible(const struct trk_tracker *t, struct slots *sl, struct trk_scan_report *rep);
static struct cand_reach expire_candidates(struct trk_tracker *t, const struct trk_scan *scan, const uint16_t *idx,
                                           size_t n);
static long best_candidate(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real *r_j,
                           size_t from, trk_real reach_m);
static int start_pair(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t c, size_t j,
                      const trk_real *r_j, struct trk_scan_report *rep);
static int start_single(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t j,
                        const trk_real *r_j, struct trk_scan_report *rep);
static void store_candidates(struct trk_tracker *t, const struct trk_scan *scan, uint16_t *idx, size_t n,
                             struct trk_scan_report *rep);
#if TRK_WITH_IMM
static void imm_start(const struct trk_tracker *t, struct trk_track *tr); /* tracker_imm_impl.h */
#endif
static void step_tests(struct trk_tracker *t, struct trk_track *tr, const struct trk_look *look,
                       struct trk_scan_report *rep);

/* Workspace detection j's covariance (its own or the sensor's) into r. */
static void detection_r(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real *r)
{
    const struct trk_detection *d = &scan->detections[t->ws.src[j]];
    if (d->has_cov) {
        trk_i_cov2_matrix(d->cov_m2, r); /* checked at load */
    } else {
        for (int i = 0; i < NZ * NZ; i++) r[i] = t->r[scan->sensor_id][i];
    }
}

/* Every valid detection no track used starts a track (single point), or
 * pairs with a candidate (two points: a sweep over the detections in x
 * order against the store, also in x order); the unpaired ones become
 * candidates. */
static TRK_NOINLINE void initiate(struct trk_tracker *t, const struct trk_scan *scan, struct trk_scan_report *rep)
{
    struct slots sl = {0, 0, -1, 0};
    uint16_t *idx = t->ws.cand; /* the gated-set scratch is free by now */
    size_t n = 0;
    for (size_t j = 0; j < t->ws.n_valid; j++)
        if (!t->ws.used[j]) idx[n++] = (uint16_t)j;
    if (t->params.init.method == TRK_INIT_SINGLE_POINT) {
        /* in scan order, as the detections came (the workspace holds the
         * shared ones in x order): slots and ids do not depend on gating's
         * index */
        trk_real *src = t->ws.w; /* free after the updates and the merge */
        for (size_t k = 0; k < n; k++) src[idx[k]] = (trk_real)t->ws.src[idx[k]];
        sort_by_key(t, src, idx, n);
        for (size_t k = 0; k < n; k++) {
            trk_real r_j[NZ * NZ];
            detection_r(t, scan, idx[k], r_j);
            (void)start_single(t, &sl, scan, idx[k], r_j, rep);
        }
    } else {
        sort_by_x(t, idx, n);
        const struct cand_reach reach = expire_candidates(t, scan, idx, n);
        size_t lo = 0, n_new = 0;
        if (!slot_possible(t, &sl, NULL)) { /* every slot confirmed: no pair could start */
            rep->n_init_refused_full += (uint32_t)n;
            store_candidates(t, scan, idx, n, rep);
            rep->n_candidates = (uint32_t)t->n_cand;
            return;
        }
        for (size_t k = 0; k < n; k++) { /* idx[k] by increasing x: lo only moves up */
            const size_t j = idx[k];
            while (lo < t->n_cand && t->cand[lo].x_m < t->ws.x[j] - reach.reach_m) lo++;
            if (lo < t->n_cand && t->cand[lo].x_m <= t->ws.x[j] + reach.reach_m) { /* a candidate in reach */
                trk_real r_j[NZ * NZ];
                const long c = best_candidate(t, scan, j, r_j, lo, reach.reach_m);
                if (c >= 0 && start_pair(t, &sl, scan, (size_t)c, j, r_j, rep)) continue;
            }
            idx[n_new++] = (uint16_t)j; /* stays in x order */
        }
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
#if TRK_WITH_IMM
    imm_start(t, tr);
#endif
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
    const trk_real psi0 = initial_existence(t, t->init_log_odds[scan->sensor_id].first + t->ws.log_lr[j]);
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

/* Drop the candidates older than max_gap_scans (the store stays sorted);
 * the reach of the velocity gates of the others with the scan's n
 * unexplained detections idx: v_max dt_max + sqrt(gamma (tr R_c + tr R_j)),
 * maxima over both (lambda_max(R_c + R_j) <= tr R_c + tr R_j). */
static struct cand_reach expire_candidates(struct trk_tracker *t, const struct trk_scan *scan, const uint16_t *idx,
                                           size_t n)
{
    trk_real dt_max = 0, var_c = 0, var_j = 0;
    size_t kept = 0;
    for (size_t i = 0; i < t->n_cand; i++) {
        struct trk_candidate *c = &t->cand[i];
        if (t->scan_no - c->scan_no > t->params.init.max_gap_scans) continue;
        const trk_real dt = (trk_real)(scan->time_us - c->time_us) * TRK_REAL_C(1e-6);
        const trk_real var = c->cov_m2[TRK_COV2_XX] + c->cov_m2[TRK_COV2_YY];
        if (dt > dt_max) dt_max = dt;
        if (var > var_c) var_c = var;
        if (kept != i) t->cand[kept] = *c;
        t->cand[kept++].used = 0;
    }
    t->n_cand = kept;
    const trk_real *r = t->r[scan->sensor_id];
    var_j = r[S(ZX, ZX)] + r[S(ZY, ZY)];
    for (size_t k = 0; k < n; k++) {
        const struct trk_detection *d = &scan->detections[t->ws.src[idx[k]]];
        if (d->has_cov && d->cov_m2[TRK_COV2_XX] + d->cov_m2[TRK_COV2_YY] > var_j)
            var_j = d->cov_m2[TRK_COV2_XX] + d->cov_m2[TRK_COV2_YY];
    }
    const trk_real gamma = t->pda[scan->sensor_id].gamma;
    const struct cand_reach reach = {(t->params.init.max_speed_mps * dt_max + trk_sqrt(gamma * (var_c + var_j))) *
                                     TRK_REAL_C(1.0001)};
    return reach;
}

/* The candidate detection j pairs with (trk_init_params: within the velocity
 * gate, the highest ln l^a - ln r), or -1, from the store's entries from
 * `from` on (x >= x_j - reach) up to x_j + reach. r_j gets the detection's
 * covariance once a candidate is near enough in y to need it (it is set
 * whenever the result is not -1). */
static long best_candidate(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real *r_j,
                           size_t from, trk_real reach)
{
    const trk_real vmax = t->params.init.max_speed_mps, gamma = t->pda[scan->sensor_id].gamma;
    const trk_real xj = t->ws.x[j], yj = t->ws.y[j];
    long best = -1;
    int have_r = 0;
    trk_real best_score = 0;
    for (size_t i = from; i < t->n_cand && t->cand[i].x_m <= xj + reach; i++) {
        const struct trk_candidate *c = &t->cand[i];
        if (c->used || trk_fabs(yj - c->y_m) > reach) continue;
        if (!have_r) detection_r(t, scan, j, r_j), have_r = 1;
        const trk_real dt = (trk_real)(scan->time_us - c->time_us) * TRK_REAL_C(1e-6);
        if (!(dt > 0)) continue;
        trk_real r_sum[NZ * NZ];
        candidate_r(c, r_sum);
        for (int k = 0; k < NZ * NZ; k++) r_sum[k] += r_j[k];
        const trk_real dx = xj - c->x_m, dy = yj - c->y_m, d2 = dx * dx + dy * dy;
        const trk_real lim = vmax * dt + trk_sqrt(gamma * lambda_max2(r_sum));
        if (d2 > lim * lim) continue;
        /* ln l^a - ln r: a speed uniform in [0, v_max] puts the displacement r
         * at density 1 / (2 pi r v_max dt), so nearer partners weigh more (r
         * no smaller than the noise) */
        const trk_real noise2 = r_sum[S(ZX, ZX)] + r_sum[S(ZY, ZY)];
        const trk_real score = c->log_lr - TRK_REAL_C(0.5) * trk_log(d2 > noise2 ? d2 : noise2);
        if (best < 0 || score > best_score) best = (long)i, best_score = score;
    }
    return best;
}

/* A track from candidate c and workspace detection j (two-point
 * differencing, trk_init_params): x = z_j, v = (z_j - z_c) / dt,
 * P_pp = R_j, P_pv = R_j / dt, P_vv = (R_c + R_j) / dt^2. 0 when no slot,
 * or when that P is not positive definite in this arithmetic. */
static int start_pair(struct trk_tracker *t, struct slots *sl, const struct trk_scan *scan, size_t ci, size_t j,
                      const trk_real *r_j, struct trk_scan_report *rep)
{
    if (!slot_possible(t, sl, rep)) return 0;
    struct trk_candidate *c = &t->cand[ci];
    const trk_real dt = (trk_real)(scan->time_us - c->time_us) * TRK_REAL_C(1e-6);
    const trk_real vdt = t->params.init.max_speed_mps * dt;
    /* ln O = ln(beta l_c / lambda_c) + ln(P_D l_j / lambda_j) - ln A_v */
    const trk_real pi = TRK_REAL_C(3.14159265358979323846);
    const trk_real log_odds = t->init_log_odds[c->sensor_id].first + c->log_lr +
                              t->init_log_odds[scan->sensor_id].second + t->ws.log_lr[j] - trk_log(pi * vdt * vdt);
    const trk_real psi0 = initial_existence(t, log_odds);
    trk_real r_c[NZ * NZ], x[NX], p[NX * NX];
    candidate_r(c, r_c);
    const int pos[NZ] = {X, Y}, vel[NZ] = {VX, VY};
    for (int a = 0; a < NZ; a++) {
        x[pos[a]] = a == ZX ? t->ws.x[j] : t->ws.y[j];
        x[vel[a]] = (x[pos[a]] - (a == ZX ? c->x_m : c->y_m)) / dt;
        for (int b = 0; b < NZ; b++) {
            const trk_real rj = r_j[S(a, b)];
            p[P(pos[a], pos[b])] = rj;
            p[P(pos[a], vel[b])] = p[P(vel[a], pos[b])] = rj / dt;
            p[P(vel[a], vel[b])] = (r_c[S(a, b)] + rj) / (dt * dt);
        }
    }
    /* SPD in exact arithmetic; rounding can break it when R_c is tiny
     * against R_j (the Schur complement is R_c / dt^2): then no track, the
     * detection stays a candidate */
    for (int k = 0; k < NX; k++)
        if (!isfinite(x[k])) return 0;
    if (trk_i_spd(NX, p) != TRK_OK) return 0;
    struct trk_track *tr = take_slot(t, sl, new_quality(t, psi0), rep);
    if (!tr) return 0;
    for (int k = 0; k < NX; k++) tr->x[k] = x[k];
    for (int k = 0; k < NX * NX; k++) tr->p[k] = p[k];
    c->used = 1;
    new_track(t, tr, scan, psi0, 2, rep);
    return 1;
}

/* ------------------------------------------------------------------ the store */

/* Sort idx[0..n) by the workspace x of the detection (sort_by_key). */
static void sort_by_x(struct trk_tracker *t, uint16_t *idx, size_t n) { sort_by_key(t, t->ws.x, idx, n); }

/* Sort idx[0..n) (n <= TRK_MAX_DETECTIONS) by key[idx[i]]: a counting sort
 * on n buckets of equal width over [min, max], then an insertion sort that
 * finishes the buckets (O(n) for spread keys; correct for any; stable).
 * Scratch: ws.u.sort. */
static void sort_by_key(struct trk_tracker *t, const trk_real *key, uint16_t *idx, size_t n)
{
    const trk_real *x = key;
    if (n < 2) return;
    trk_real lo = x[idx[0]], hi = lo;
    for (size_t i = 1; i < n; i++) {
        if (x[idx[i]] < lo) lo = x[idx[i]];
        if (x[idx[i]] > hi) hi = x[idx[i]];
    }
    /* skipped when all are equal, or the span overflows (hi - lo = inf
     * would give scale 0 and bucket inf * 0 = NaN: found by fuzz_lcm_copy) */
    const trk_real span = hi - lo, scale = (trk_real)(n - 1) / span;
    if (span > 0 && span <= TRK_REAL_MAX && isfinite(scale)) {
        uint16_t *count = t->ws.u.sort.count, *tmp = t->ws.u.sort.tmp;
        for (size_t b = 0; b <= n; b++) count[b] = 0;
        for (size_t i = 0; i < n; i++) count[(size_t)((x[idx[i]] - lo) * scale) + 1]++; /* bucket <= n - 1 */
        for (size_t b = 1; b <= n; b++) count[b] = (uint16_t)(count[b] + count[b - 1]);
        for (size_t i = 0; i < n; i++) tmp[count[(size_t)((x[idx[i]] - lo) * scale)]++] = idx[i];
        for (size_t i = 0; i < n; i++) idx[i] = tmp[i];
    }
    for (size_t i = 1; i < n; i++) {
        const uint16_t v = idx[i];
        size_t k = i;
        for (; k > 0 && x[idx[k - 1]] > x[v]; k--) idx[k] = idx[k - 1];
        idx[k] = v;
    }
}

/* Remove the paired candidates, and while the new ones do not fit, the
 * oldest scan's. */
static void make_room(struct trk_tracker *t, size_t n_new)
{
    size_t n = 0;
    for (size_t i = 0; i < t->n_cand; i++)
        if (!t->cand[i].used) {
            if (n != i) t->cand[n] = t->cand[i];
            n++;
        }
    t->n_cand = n;
    while (t->n_cand > 0 && t->n_cand + n_new > TRK_MAX_CANDIDATES) {
        uint32_t oldest = t->cand[0].scan_no;
        for (size_t i = 1; i < t->n_cand; i++)
            if (t->scan_no - t->cand[i].scan_no > t->scan_no - oldest) oldest = t->cand[i].scan_no;
        n = 0;
        for (size_t i = 0; i < t->n_cand; i++)
            if (t->cand[i].scan_no != oldest) {
                if (n != i) t->cand[n] = t->cand[i];
                n++;
            }
        t->n_cand = n;
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
    c->time_us = scan->time_us;
    c->scan_no = t->scan_no;
    c->sensor_id = (uint8_t)scan->sensor_id;
    c->used = 0;
}

/* The scan's unpaired detections idx[0..n) (in x order) into the store,
 * merged in x order; what does not fit even after evicting every older
 * candidate is counted as dropped (the last in x order). */
static void store_candidates(struct trk_tracker *t, const struct trk_scan *scan, uint16_t *idx, size_t n,
                             struct trk_scan_report *rep)
{
    make_room(t, n);
    if (n > TRK_MAX_CANDIDATES - t->n_cand) {
        rep->n_candidates_dropped += (uint32_t)(n - (TRK_MAX_CANDIDATES - t->n_cand));
        n = TRK_MAX_CANDIDATES - t->n_cand;
    }
    size_t i = t->n_cand, k = n, w = t->n_cand + n;
    while (k > 0) { /* merge from the back, in place */
        if (i > 0 && t->cand[i - 1].x_m > t->ws.x[idx[k - 1]]) t->cand[--w] = t->cand[--i];
        else fill_candidate(t, scan, idx[--k], &t->cand[--w]);
    }
    t->n_cand += n;
}

#endif
