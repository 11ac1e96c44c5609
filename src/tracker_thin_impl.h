/* tracker_thin_impl.h (private) - a scan beyond the workspace's capacity
 * (trk/tracker.h "Scans beyond capacity", docs/overcapacity.md): which
 * TRK_MAX_DETECTIONS of its valid detections the scan keeps, and the
 * sensor's P_D and clutter density that hold for what it kept.
 *
 * One pass over the scan, fixed memory (the workspace before the
 * detections are loaded): each valid detection gets a rank (in a live
 * track's gate box first; then its amplitude, or without amplitudes a hash
 * of its position) and a bounded min-heap of TRK_MAX_DETECTIONS entries
 * keeps the highest ranks (ws.w the keys, ws.cand the scan indices, ws.used
 * the in-a-gate flags); the heap's root is the last kept detection. The
 * kept indices are then sorted, so that the workspace is loaded in scan
 * order as for a scan within capacity.
 *
 * Part of the load stage (tracker_load_impl.h), included by it only. */
#ifndef TRK_TRACKER_THIN_IMPL_H
#define TRK_TRACKER_THIN_IMPL_H

#include <string.h>

#include "track_filter_impl.h"
#include "tracker_detection_impl.h"
#include "tracker_index_impl.h"

/* The live tracks whose gate boxes rank detections: all of them while
 * TRK_MAX_TRACKS <= TRK_MAX_DETECTIONS (the boxes take 4 reals each of
 * ws.u.set.r_own, 4 TRK_MAX_DETECTIONS reals), else the first this many in
 * slot order, confirmed ones first. */
#define THIN_MAX_BOXES (TRK_MAX_TRACKS < TRK_MAX_DETECTIONS ? TRK_MAX_TRACKS : TRK_MAX_DETECTIONS)

/* The rank of a detection without an amplitude, from its position's bits:
 * 23 bits (exact in float), the same wherever it stands in the scan. */
static uint32_t thin_hash(const struct trk_detection *d)
{
    unsigned char b[2 * sizeof(trk_real)];
    uint32_t h = 2166136261u; /* FNV-1a over the bytes of x_m, y_m, then a final mix */
    memcpy(b, &d->x_m, sizeof(trk_real));
    memcpy(b + sizeof(trk_real), &d->y_m, sizeof(trk_real));
    for (size_t k = 0; k < sizeof b; k++) h = (h ^ b[k]) * 16777619u;
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    return h >> 9;
}

/* Is heap entry a ranked below entry b: not in a gate below in one, then
 * the smaller key, then the later in the scan? */
static int thin_below(const struct trk_tracker *t, size_t a, size_t b)
{
    if (t->ws.used[a] != t->ws.used[b]) return t->ws.used[a] < t->ws.used[b];
    if (t->ws.w[a] != t->ws.w[b]) return t->ws.w[a] < t->ws.w[b];
    return t->ws.cand[a] > t->ws.cand[b];
}

static void thin_swap(struct trk_tracker *t, size_t a, size_t b)
{
    const trk_real w = t->ws.w[a], x = t->ws.x[a], y = t->ws.y[a];
    const uint16_t c = t->ws.cand[a];
    const uint8_t u = t->ws.used[a];
    t->ws.w[a] = t->ws.w[b];
    t->ws.x[a] = t->ws.x[b];
    t->ws.y[a] = t->ws.y[b];
    t->ws.cand[a] = t->ws.cand[b];
    t->ws.used[a] = t->ws.used[b];
    t->ws.w[b] = w;
    t->ws.x[b] = x;
    t->ws.y[b] = y;
    t->ws.cand[b] = c;
    t->ws.used[b] = u;
}

/* The kept entries [0, n) in scan order: ws.cand ascending, and for a
 * polar scan their converted positions ws.x, ws.y with them (so that the
 * load converts no detection twice; ws.src, ws.w and ws.log_lr are the
 * scratch, free until the load). */
static void thin_sort_kept(struct trk_tracker *t, const struct trk_scan *scan, size_t n)
{
    if (!scan->polar) {
        sort_u16_by(t->ws.cand, n, NULL);
        return;
    }
    uint16_t *perm = t->ws.src, *cand = t->ws.cell_end;
    for (size_t k = 0; k < n; k++) perm[k] = (uint16_t)k;
    sort_u16_by(perm, n, t->ws.cand); /* the scan indices are distinct: one order */
    for (size_t k = 0; k < n; k++) {
        t->ws.w[k] = t->ws.x[perm[k]];
        t->ws.log_lr[k] = t->ws.y[perm[k]];
        cand[k] = t->ws.cand[perm[k]];
    }
    for (size_t k = 0; k < n; k++) {
        t->ws.x[k] = t->ws.w[k];
        t->ws.y[k] = t->ws.log_lr[k];
        t->ws.cand[k] = cand[k];
    }
}

/* The min-heap [0, n) after its root changed: sift it down. */
static void thin_sift_down(struct trk_tracker *t, size_t n)
{
    for (size_t i = 0;;) {
        size_t m = i;
        const size_t l = 2 * i + 1, r = l + 1;
        if (l < n && thin_below(t, l, m)) m = l;
        if (r < n && thin_below(t, r, m)) m = r;
        if (m == i) return;
        thin_swap(t, i, m);
        i = m;
    }
}

/* The gate boxes: per live track its predicted position and position
 * variances H P H' (without R), sorted by x: n of them at b[4 k ..]
 * (x, y, pxx, pyy). The largest pxx and pyy into *pmax. A track whose
 * prediction fails has no box (its update will end it). */
static size_t thin_boxes(struct trk_tracker *t, const struct trk_scan *scan, trk_real *b, trk_real pmax[2])
{
    size_t n = 0;
    pmax[0] = pmax[1] = 0;
    for (int confirmed = 1; confirmed >= 0; confirmed--)
        for (size_t i = 0; i < TRK_MAX_TRACKS && n < THIN_MAX_BOXES; i++) {
            const struct trk_track *tr = &t->track[i];
            struct pred pr;
            if (tr->status != (confirmed ? TRK_TRACK_CONFIRMED : TRK_TRACK_TENTATIVE)) continue;
            if (filter_predict(t, tr, scan, &pr) != TRK_OK) continue;
            const trk_real v[4] = {pr.x[X], pr.x[Y], pr.p[P(X, X)], pr.p[P(Y, Y)]};
            size_t k = n++; /* insertion by x: the boxes are few */
            for (; k > 0 && b[4 * (k - 1)] > v[0]; k--) memcpy(b + 4 * k, b + 4 * (k - 1), 4 * sizeof *b);
            memcpy(b + 4 * k, v, sizeof v);
            if (v[2] > pmax[0]) pmax[0] = v[2];
            if (v[3] > pmax[1]) pmax[1] = v[3];
        }
    return n;
}

/* Is detection d (covariance r) in a box |dx| <= sqrt(gamma (pxx + rxx)),
 * |dy| likewise (the bounding box of the gate d2 <= gamma)? The boxes of
 * x within the largest half width, by bisection on the sorted x. */
static int thin_in_box(const trk_real *b, size_t n, const trk_real pmax[2], trk_real gamma,
                       const struct trk_detection *d, const trk_real *r)
{
    const trk_real rxx = d->has_cov ? d->cov_m2[TRK_COV2_XX] : r[S(ZX, ZX)];
    const trk_real ryy = d->has_cov ? d->cov_m2[TRK_COV2_YY] : r[S(ZY, ZY)];
    const trk_real wmax = trk_sqrt(gamma * (pmax[0] + rxx)) * (1 + 16 * TRK_REAL_EPS);
    size_t lo = 0, hi = n; /* the first box of x >= d->x_m - wmax */
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (b[4 * mid] < d->x_m - wmax) lo = mid + 1;
        else hi = mid;
    }
    for (size_t k = lo; k < n && b[4 * k] <= d->x_m + wmax; k++) {
        const trk_real dx = d->x_m - b[4 * k], dy = d->y_m - b[4 * k + 1];
        if (dx * dx <= gamma * (b[4 * k + 2] + rxx) && dy * dy <= gamma * (b[4 * k + 3] + ryy)) return 1;
    }
    return 0;
}

/* What a thinned scan's selection found (when thinned is 1). */
struct thin {
    int thinned;          /* valid detections were left out */
    int in_gates;         /* ... some of them in a gate box (the cut fell there) */
    trk_real pd;          /* P_D and */
    trk_real lambda;      /* clutter density at what was kept */
    trk_real dl;          /* ln l^a at the raised threshold minus at the sensor's */
    /* an amplitude model with a P_D profile (Rayleigh): P_D' = P_D^pd_power
     * at every range, pd_power = a_cut^2 / t^2 (1 otherwise), and each
     * detection's ln l^a gains -(pd_power - 1) ln P_D(r) - x0 in place of dl */
    trk_real pd_power;
    trk_real x0;          /* -ln(pfa'/pfa) */
    int mixture;          /* persistent returns in the amplitudes: ln l^a anew at x0 */
};

/* P_D and lambda of the kept part of the class the cut fell in (*th):
 * with amplitudes, the model's at the raised threshold a_cut (PDAFAI:
 * lambda' = lambda S0(a_cut) / S0(t), P_D' = S1(a_cut), and ln l^a gains
 * ln(pfa'/pfa) - ln(P_D'/P_D)); else uniform thinning of a fraction f:
 * lambda' = f lambda, P_D' = f P_D (a target's detection is left out as
 * often as a clutter one). With a P_D profile and amplitudes P_D and the
 * target's S1 depend on the range: thin_shift. */
static void thin_model(const struct trk_sensor_params *sp, const struct trk_pda *pda, int by_amp, trk_real a_cut,
                       trk_real f, struct thin *th, struct trk_scan_report *rep)
{
    trk_real x0 = 0, x1 = 0;
    if (by_amp && trk_amplitude_log_sf(&sp->amplitude, TRK_AMP_CLUTTER, a_cut, &x0) == TRK_OK &&
        trk_amplitude_log_sf(&sp->amplitude, TRK_AMP_TARGET, a_cut, &x1) == TRK_OK) {
        th->pd = pda->params.pd * trk_exp(-x1);
        th->lambda = pda->params.clutter_density * trk_exp(-x0);
        th->dl = x1 - x0;
        th->x0 = x0;
        th->mixture = sp->persistent_share > 0;
        if (sp->pd_profile.n > 0) /* Rayleigh: S1(a) = P_D^(a^2/t^2) */
            th->pd_power = a_cut * a_cut / sp->amplitude.t2;
        rep->thin_threshold = a_cut;
    } else {
        th->pd = pda->params.pd * f;
        th->lambda = pda->params.clutter_density * f;
        th->dl = 0;
    }
}

/* A scan of more than TRK_MAX_DETECTIONS detections: count the invalid
 * ones (as load_detection would), rank the valid ones, keep the
 * TRK_MAX_DETECTIONS highest: their scan indices, ascending, in
 * ws.cand[0, n) (n returned), their positions in ws.x, ws.y (read back by
 * the load of a polar scan: thin_sort_kept); the rest counted as thinned, the model at
 * the cut into *th and the report. O(n_det (log boxes + boxes in the strip
 * + log TRK_MAX_DETECTIONS)) + O(TRK_MAX_TRACKS^2) for the boxes' order.
 * Not inlined: its predictions' frame stays off the scan's deepest path
 * (process_scan > update_track > the PDA update). */
static TRK_NOINLINE size_t thin_select(struct trk_tracker *t, const struct trk_scan *scan, const struct amp_use *au,
                                       struct thin *th, struct trk_scan_report *rep)
{
    const struct trk_sensor_params *sp = au->sp;
    const struct trk_pda *pda = &t->pda[scan->sensor_id];
    const int by_amp = sp->use_amplitude;
    trk_real *box = t->ws.u.set.r_own, pmax[2];
    const size_t n_box = thin_boxes(t, scan, box, pmax);
    size_t n = 0, n_valid = 0, n_gated = 0;
    for (size_t i = 0; i < scan->n_detections; i++) {
        struct trk_detection tmp;
        const struct trk_detection *d = scan_detection(t, scan, i, &tmp, rep);
        trk_real llr;
        if (!d || !detection_usable(d, caller_density(scan, i), au, rep, &llr)) continue;
        n_valid++;
        const uint8_t in = (uint8_t)thin_in_box(box, n_box, pmax, pda->gamma, d, t->r[scan->sensor_id]);
        n_gated += in;
        /* with amplitudes: the amplitude, detections without one after all
         * those with one; else the position's hash */
        const trk_real key = !by_amp ? (trk_real)thin_hash(d)
                             : d->has_amplitude ? d->amplitude
                                                : -1 - (trk_real)thin_hash(d);
        if (n < TRK_MAX_DETECTIONS) { /* room: append, sift up */
            t->ws.w[n] = key;
            t->ws.x[n] = d->x_m;
            t->ws.y[n] = d->y_m;
            t->ws.cand[n] = (uint16_t)i;
            t->ws.used[n] = in;
            for (size_t c = n++; c > 0 && thin_below(t, c, (c - 1) / 2); c = (c - 1) / 2) thin_swap(t, c, (c - 1) / 2);
            continue;
        }
        /* full: over the root (the lowest kept) when it ranks above it (a
         * tie goes to the root: earlier in the scan) */
        if (in != t->ws.used[0] ? in < t->ws.used[0] : !(key > t->ws.w[0])) continue;
        t->ws.w[0] = key;
        t->ws.x[0] = d->x_m;
        t->ws.y[0] = d->y_m;
        t->ws.cand[0] = (uint16_t)i;
        t->ws.used[0] = in;
        thin_sift_down(t, n);
    }
    th->thinned = n_valid > n;
    rep->n_thinned = (uint32_t)(n_valid - n);
    if (th->thinned) {
        size_t kept_in_class = 0;
        th->in_gates = t->ws.used[0];
        for (size_t k = 0; k < n; k++) kept_in_class += t->ws.used[k] == t->ws.used[0];
        const size_t class_total = th->in_gates ? n_gated : n_valid - n_gated;
        const trk_real a_cut = t->ws.w[0];
        thin_model(sp, pda, by_amp && a_cut >= 0, a_cut, (trk_real)kept_in_class / (trk_real)class_total, th, rep);
        rep->thin_pd = th->pd;
        rep->thin_clutter_density = th->lambda;
        rep->thin_in_gates = (uint32_t)th->in_gates;
    }
    thin_sort_kept(t, scan, n);
    return n;
}

/* The sensor's constants for the updates of a scan thinned inside the
 * gates: P_D' and lambda' in its PDA (and the joint weights' ln lambda),
 * each loaded ln l^a moved to the raised threshold (dl), the initial
 * existence terms moved back by dl (initiation's odds beta l^a / lambda and
 * P_D l^a / lambda are the same at either threshold when beta scales with
 * P_D). The previous constants into *saved. TRK_OK, or the PDA's refusal
 * of P_D' (below the smallest normal number): the scan then keeps the
 * sensor's constants. */
struct thin_saved {
    const struct thin *th; /* what thin_apply applied (the scan's, kept by its caller) */
#if TRK_WITH_JOINT
    trk_real log_lambda;
#endif
};

/* Each loaded ln l^a moved to the raised threshold (sign 1) or back (-1):
 * with persistent returns by its amplitude's mixture there less here
 * (every kept detection has one: the cut fell among amplitudes; a caller's
 * clutter density folded in at load stays); else by dl, or with a P_D
 * profile and amplitudes by ln(pfa/pfa') -
 * ln(P_D'/P_D) at the detection's range, x1 - x0 with the target's
 * x1 = -(pd_power - 1) ln P_D(r) (Rayleigh). */
static TRK_NOINLINE void thin_shift(struct trk_tracker *t, const struct trk_scan *scan, const struct thin *th,
                                    trk_real sign)
{
    if (th->mixture) { /* by each amplitude's amp_mixture_log_lr at x0 less at 0 (or back) */
        const struct amp_use au = amp_use_of(t, &t->params.sensor[scan->sensor_id], &t->ws.view);
        const trk_real x_to = sign > 0 ? th->x0 : 0, x_from = sign > 0 ? 0 : th->x0;
        for (size_t j = 0; j < t->ws.n_valid; j++) {
            const size_t i = t->ws.src[j];
            struct trk_detection d = {t->ws.x[j], t->ws.y[j], {0, 0, 0}, 0, 0, 0};
            (void)scan_amplitude(scan, i, &d.amplitude);
            const trk_real pd = amp_pd(&au, &d);
            trk_real to, from;
            if (amp_mixture_log_lr(&au, pd, x_to, d.amplitude, &to) == TRK_OK &&
                amp_mixture_log_lr(&au, pd, x_from, d.amplitude, &from) == TRK_OK)
                t->ws.log_lr[j] += to - from;
        }
        return;
    }
    if (th->pd_power == 1) {
        for (size_t j = 0; j < t->ws.n_valid; j++) t->ws.log_lr[j] += sign * th->dl;
        return;
    }
    for (size_t j = 0; j < t->ws.n_valid; j++) {
        const trk_real pd = trk_i_view_pd_profile(&t->ws.view, t->ws.x[j], t->ws.y[j]);
        t->ws.log_lr[j] += sign * (-(th->pd_power - 1) * trk_log(pd) - th->x0);
    }
}

static trk_status thin_apply(struct trk_tracker *t, const struct trk_scan *scan, const struct thin *th,
                             struct thin_saved *saved)
{
    const unsigned s = scan->sensor_id;
    struct trk_pda_params pp = t->pda[s].params;
    pp.pd = th->pd;
    pp.clutter_density = th->lambda;
    if (!(th->lambda > 0) && t->pda[s].params.clutter_density > 0) return TRK_E_RANGE; /* lambda' underflowed */
    /* the sensor's constants kept in the tracker, not on the stack (a
     * struct trk_pda is a few hundred bytes of a firmware's stack) */
    t->pda_saved = t->pda[s];
    const trk_status st = trk_pda_init(&t->pda[s], &pp);
    if (st != TRK_OK) {
        t->pda[s] = t->pda_saved;
        return st;
    }
    saved->th = th;
    t->ws.pd_power = th->pd_power;
    t->ws.pd_scale = th->pd_power == 1 ? th->pd / t->pda_saved.params.pd : 1;
    t->ws.lambda_scale = t->pda_saved.params.clutter_density > 0 ? th->lambda / t->pda_saved.params.clutter_density : 1;
    thin_shift(t, scan, th, 1);
#if TRK_WITH_JOINT
    saved->log_lambda = t->log_clutter_density[s];
    if (th->lambda > 0) t->log_clutter_density[s] = trk_log(th->lambda);
#endif
    return TRK_OK;
}

/* Undo thin_apply once the updates are done. */
static void thin_restore(struct trk_tracker *t, const struct trk_scan *scan, const struct thin_saved *saved)
{
    const unsigned s = scan->sensor_id;
    t->pda[s] = t->pda_saved;
    t->ws.pd_scale = t->ws.lambda_scale = t->ws.pd_power = 1;
    thin_shift(t, scan, saved->th, -1);
#if TRK_WITH_JOINT
    t->log_clutter_density[s] = saved->log_lambda;
#endif
}

#endif
