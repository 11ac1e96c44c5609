/* jpda.c - JPDA / JIPDA marginal association probabilities (trk/jpda.h;
 * docs/conventions.md "Joint association (JPDA / JIPDA)"): clusters by
 * union-find over the gated pairs, closed forms for one and two tracks, an exact subset dynamic programme
 * per cluster, loopy belief propagation beyond the exact bound. */
#include "trk/jpda.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "internal.h"
#include "jpda_impl.h"
#include "pda_impl.h"

#if TRK_MAX_TRACKS > 65535 || TRK_MAX_DETECTIONS > 65535
#error "jpda.c indexes tracks and detections with uint16_t"
#endif

#define NONE 0xFFFFu

/* A cluster being solved: its tracks and gated detections (indices into the
 * scan: tracks[0, nt), dets[0, nd)); det_local maps a detection to its index
 * in dets. The scaled linear weights are read from the pairs on the fly. */
struct cluster {
    const struct trk_jpda_pairs *s;
    struct trk_jpda_solver *w;
    const uint16_t *tracks, *dets;
    size_t nt, nd;
};

static trk_status check_pairs(const struct trk_jpda_pairs *s, const trk_real *p_pair, const trk_real *p_miss);
static size_t form_clusters(const struct trk_jpda_pairs *s, struct trk_jpda_solver *w);
static void solve_lone(const struct cluster *c, trk_real *p_pair, trk_real *p_miss);
static void solve_two(const struct cluster *c, trk_real *p_pair, trk_real *p_miss);
static int solve_exact(const struct cluster *c, trk_real *p_pair, trk_real *p_miss, uint64_t *budget);
static int solve_lbp(const struct cluster *c, trk_real *p_pair, trk_real *p_miss, int *converged);
static int cluster_solved(const struct cluster *c, const trk_real *p_miss);
static void floor_weights(const struct cluster *c);

/* One cluster by the cheapest exact method its size allows within the
 * scan's budget (0), else by loopy belief propagation (1; its iterations
 * and convergence into *it, *conv). */
TRK_INLINE int solve_cluster(const struct cluster *c, trk_real *p_pair, trk_real *p_miss, uint64_t *budget,
                             int *it, int *conv)
{
    if (c->nt == 1) solve_lone(c, p_pair, p_miss);
    else if (c->nt == 2) solve_two(c, p_pair, p_miss);
    else if (!solve_exact(c, p_pair, p_miss, budget)) {
        *it = solve_lbp(c, p_pair, p_miss, conv);
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------------ API */

trk_status trk_jpda_solve(const struct trk_jpda_pairs *pairs, struct trk_jpda_solver *solver, trk_real *p_pair,
                          trk_real *p_miss, struct trk_jpda_report *rep)
{
    if (!solver) return TRK_E_ARG;
    const trk_status st = check_pairs(pairs, p_pair, p_miss);
    if (st != TRK_OK) return st;
    struct trk_jpda_report r = {0, 0, 0, 0, 0, 0, 1, 0};
    uint64_t budget = (uint64_t)TRK_JPDA_SCAN_WORK; /* the exact programmes' work this call */
    const size_t n_clusters = form_clusters(pairs, solver);
    for (size_t k = 0; k < n_clusters; k++) {
        const struct cluster c = {pairs, solver, solver->tracks + solver->tr_first[k],
                                  solver->dets + solver->det_first[k],
                                  (size_t)(solver->tr_first[k + 1] - solver->tr_first[k]),
                                  (size_t)(solver->det_first[k + 1] - solver->det_first[k])};
        r.n_clusters++;
        if (c.nt > r.largest_tracks) r.largest_tracks = c.nt;
        if (c.nd > r.largest_dets) r.largest_dets = c.nd;
        int it = 0, conv = 1, floored = 0;
        int lbp = solve_cluster(&c, p_pair, p_miss, &budget, &it, &conv);
        if (c.nt > 1 && !cluster_solved(&c, p_miss)) { /* every event underflowed (0 / 0): again, floored
                                                          (a lone track's normaliser is >= 1) */
            floor_weights(&c);
            lbp = solve_cluster(&c, p_pair, p_miss, &budget, &it, &conv);
            floored = 1;
            r.n_floored++;
        }
        if (lbp) {
            if (it > r.lbp_iterations) r.lbp_iterations = it;
            if (!conv) r.lbp_converged = 0;
        }
        if (lbp || floored) r.n_approx++;
        else r.n_exact++;
    }
    if (rep) *rep = r;
    return TRK_OK;
}

/* Did every track of the cluster get finite marginals? A track's
 * normaliser is 0 (and its marginals 0 / 0) only when every joint event
 * underflowed: the scaled weights (each track's divided by its largest,
 * form_clusters) are then 0 wherever an event needs them, as when two
 * tracks each have a weight near 1 on one shared detection and misses
 * below about e^-745 (double; e^-103 float: past the subnormals). */
static int cluster_solved(const struct cluster *c, const trk_real *p_miss)
{
    for (size_t a = 0; a < c->nt; a++)
        if (!(p_miss[c->tracks[a]] >= 0 && p_miss[c->tracks[a]] <= 1)) return 0;
    return 1;
}

/* Raise each scaled weight of the cluster (its tracks' misses and pairs) to
 * at least f = TRK_REAL_MIN^(1 / (n_t + 1)): an event multiplies n_t of
 * them, so none is below TRK_REAL_MIN / f and every normaliser is
 * positive. Weights that small against their track's largest weigh nothing
 * where the arithmetic can hold the events; here they decide between events
 * it cannot, and the marginals become approximate (trk_jpda_report
 * n_floored). */
static void floor_weights(const struct cluster *c)
{
    const trk_real f = trk_exp(trk_log(TRK_REAL_MIN) / (trk_real)(c->nt + 1));
    for (size_t a = 0; a < c->nt; a++) {
        const size_t t = c->tracks[a];
        if (c->w->miss[t] < f) c->w->miss[t] = f;
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++)
            if (c->s->w[k] < f) c->s->w[k] = f;
    }
}

/* The dense scan as pairs (gated: ln w finite), solved, and scattered back. */
trk_status trk_jpda_marginals(const struct trk_jpda_scan *scan, struct trk_jpda_work *work, trk_real *p_assoc,
                              trk_real *p_miss, struct trk_jpda_report *rep)
{
    if (!work || !scan) return TRK_E_ARG;
    const size_t nt = scan->n_tracks, nd = scan->n_dets;
    if (nt > TRK_MAX_TRACKS || nd > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (nt > 0 && (!scan->log_w_miss || !p_miss)) return TRK_E_ARG;
    if (nt > 0 && nd > 0 && (!scan->log_w || !p_assoc)) return TRK_E_ARG;
    size_t n = 0;
    work->first[0] = 0;
    for (size_t t = 0; t < nt; t++) {
        for (size_t j = 0; j < nd; j++) {
            const trk_real v = scan->log_w[t * nd + j];
            if (isnan(v)) return TRK_E_NAN;
            if (v > 0 && isinf(v)) return TRK_E_RANGE;
            if (!isfinite(v)) continue;
            if (n == TRK_MAX_GATED_PAIRS) return TRK_E_CAPACITY;
            work->det[n] = (uint16_t)j;
            work->w[n++] = v;
        }
        work->first[t + 1] = (uint16_t)n;
    }
    const struct trk_jpda_pairs pairs = {nt, nd, work->first, work->det, work->w, scan->log_w_miss};
    const trk_status st = trk_jpda_solve(&pairs, &work->solver, work->p_pair, p_miss, rep);
    if (st != TRK_OK) return st;
    if (nt > 0 && nd > 0) memset(p_assoc, 0, nt * nd * sizeof *p_assoc);
    for (size_t t = 0; t < nt; t++)
        for (size_t k = work->first[t]; k < work->first[t + 1]; k++) p_assoc[t * nd + work->det[k]] = work->p_pair[k];
    return TRK_OK;
}

/* The scalars of the existence update: TRK_E_NAN non-finite, TRK_E_RANGE psi
 * outside (0, 1], pd_pg outside (0, 1], or psi pd_pg = 1 with psi < 1. */
static trk_status check_condition(trk_real psi, trk_real pd_pg, trk_real p_miss)
{
    if (!isfinite(psi) || !isfinite(pd_pg) || !isfinite(p_miss)) return TRK_E_NAN;
    if (!(psi > 0 && psi <= 1) || !(pd_pg > 0 && pd_pg <= 1)) return TRK_E_RANGE;
    if (!(1 - pd_pg * psi > 0) && psi < 1) return TRK_E_RANGE;
    return TRK_OK;
}

trk_status trk_jpda_existence(trk_real psi, trk_real pd_pg, const trk_real *p_assoc, size_t n_dets, trk_real p_miss,
                              trk_real *psi_post, trk_real *beta)
{
    if (!psi_post || !beta || (n_dets > 0 && !p_assoc)) return TRK_E_ARG;
    const trk_status st = check_condition(psi, pd_pg, p_miss);
    if (st != TRK_OK) return st;
    for (size_t j = 0; j < n_dets; j++)
        if (!isfinite(p_assoc[j])) return TRK_E_NAN;
    for (size_t j = 0; j < n_dets; j++) beta[j + 1] = p_assoc[j];
    return trk_i_jpda_condition(psi, pd_pg, n_dets, beta + 1, p_miss, beta, psi_post);
}

trk_status trk_i_jpda_condition(trk_real psi, trk_real pd_pg, size_t n, trk_real *p, trk_real p_miss,
                                trk_real *beta0, trk_real *psi_post)
{
    const trk_status st = check_condition(psi, pd_pg, p_miss);
    if (st != TRK_OK) return st;
    const trk_real den = 1 - pd_pg * psi;
    trk_real assoc = 0;
    for (size_t j = 0; j < n; j++) {
        if (!isfinite(p[j])) return TRK_E_NAN;
        assoc += p[j];
    }
    /* P(t exists and took nothing): with psi = 1 the factor is 1 exactly */
    const trk_real miss_exists = psi < 1 ? p_miss * psi * (1 - pd_pg) / den : p_miss;
    const trk_real sum = assoc + miss_exists; /* beta's normaliser: they sum to 1 */
    if (!(sum > 0)) { /* every term underflowed (psi tiny): the track does not exist */
        for (size_t j = 0; j < n; j++) p[j] = 0;
        *beta0 = 1;
        *psi_post = 0;
        return TRK_OK;
    }
    *beta0 = miss_exists / sum;
    for (size_t j = 0; j < n; j++) p[j] /= sum;
    /* psi' = sum = 1 - P(t <- none) (1 - psi) / (1 - P_D P_G psi) (the marginals
     * sum to 1): the second form cannot exceed 1 by rounding, the first keeps a
     * small psi' accurate */
    const trk_real from_one = psi < 1 ? 1 - p_miss * (1 - psi) / den : 1;
    *psi_post = sum < TRK_REAL_C(0.5) ? sum : from_one;
    return TRK_OK;
}

trk_status trk_jpda_track_weights(const struct trk_pda *pda, trk_real psi, const struct trk_innovation *inn,
                                  size_t n_dets, const trk_real *z, const trk_real *log_lr, trk_real *log_w_row,
                                  trk_real *log_w_miss, trk_real *d2)
{
    if (!pda || !inn || !log_w_miss || (n_dets > 0 && (!z || !log_w_row)) || inn->nz != pda->params.nz)
        return TRK_E_ARG;
    if (pda->params.clutter != TRK_CLUTTER_PARAMETRIC || !(pda->params.clutter_density > 0)) return TRK_E_UNSUPPORTED;
    if (!isfinite(psi)) return TRK_E_NAN;
    if (!(psi > 0 && psi <= 1)) return TRK_E_RANGE;
    const int nz = inn->nz;
    const trk_real miss = 1 - pda->params.pd * pda->params.gate_prob * psi;
    if (!(miss > 0)) return TRK_E_RANGE; /* psi P_D P_G = 1: a track that cannot be missed */
    const trk_real base = trk_log(psi) - trk_log(pda->params.clutter_density);
    for (size_t j = 0; j < n_dets; j++) {
        trk_real nu[TRK_MAX_MEAS];
        for (int a = 0; a < nz; a++) nu[a] = z[j * (size_t)nz + (size_t)a] - inn->z_pred[a];
        const trk_real dj = trk_gate_d2(inn, nu), lr = log_lr ? log_lr[j] : 0;
        if (!isfinite(dj) || !isfinite(lr)) return TRK_E_NAN;
        log_w_row[j] = dj <= pda->gamma ? base + trk_i_pda_log_e(pda, inn->log_det_s, dj, lr) : -(trk_real)INFINITY;
        if (d2) d2[j] = dj;
    }
    *log_w_miss = trk_log(miss);
    return TRK_OK;
}

/* ------------------------------------------------------------------ checks and clusters */

static trk_status check_pairs(const struct trk_jpda_pairs *s, const trk_real *p_pair, const trk_real *p_miss)
{
    if (!s) return TRK_E_ARG;
    if (s->n_tracks > TRK_MAX_TRACKS || s->n_dets > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (s->n_tracks == 0) return TRK_OK;
    if (!s->first || !s->log_w_miss || !p_miss || s->first[0] != 0) return TRK_E_ARG;
    const size_t n_pairs = s->first[s->n_tracks];
    if (n_pairs > TRK_MAX_GATED_PAIRS) return TRK_E_CAPACITY;
    if (n_pairs > 0 && (!s->det || !s->w || !p_pair)) return TRK_E_ARG;
    for (size_t t = 0; t < s->n_tracks; t++) {
        if (s->first[t + 1] < s->first[t]) return TRK_E_ARG;
        if (!isfinite(s->log_w_miss[t])) return TRK_E_NAN;
        for (size_t k = s->first[t]; k < s->first[t + 1]; k++) {
            if (s->det[k] >= s->n_dets || (k > s->first[t] && s->det[k] <= s->det[k - 1])) return TRK_E_ARG;
            if (!isfinite(s->w[k])) return TRK_E_NAN;
        }
    }
    return TRK_OK;
}

/* root with path halving (iterative: no recursion) */
static size_t cluster_root(uint16_t *parent, size_t t)
{
    while (parent[t] != t) {
        parent[t] = parent[parent[t]];
        t = parent[t];
    }
    return t;
}

/* Clusters of tracks gating a common detection, in O(tracks + pairs):
 * union-find (det_local first holds each detection's first gating track),
 * then the members of cluster c listed in scan order at tracks[tr_first[c]
 * ..] and dets[det_first[c] ..] (counting sort), det_local then each
 * detection's index in its cluster. Each track's scale (its largest ln w)
 * makes every scaled weight w_tj exp(-scale) at most 1: the pairs' w become
 * these, the solver's miss[t] the scaled w_t0 (one exponential each, not
 * one per use). Returns the number of clusters. */
static size_t form_clusters(const struct trk_jpda_pairs *s, struct trk_jpda_solver *w)
{
    const size_t nt = s->n_tracks, nd = s->n_dets;
    uint16_t *parent = w->parent, *owner = w->det.local;
    for (size_t t = 0; t < nt; t++) parent[t] = (uint16_t)t;
    for (size_t j = 0; j < nd; j++) owner[j] = NONE;
    for (size_t t = 0; t < nt; t++) {
        trk_real m = s->log_w_miss[t];
        for (size_t k = s->first[t]; k < s->first[t + 1]; k++) {
            const size_t j = s->det[k];
            if (s->w[k] > m) m = s->w[k];
            if (owner[j] == NONE) {
                owner[j] = (uint16_t)t;
                continue;
            }
            const size_t a = cluster_root(parent, owner[j]), b = cluster_root(parent, t);
            if (a < b) parent[b] = (uint16_t)a;
            else if (b < a) parent[a] = (uint16_t)b;
        }
        w->miss[t] = trk_exp(s->log_w_miss[t] - m);
        for (size_t k = s->first[t]; k < s->first[t + 1]; k++) s->w[k] = trk_exp(s->w[k] - m);
    }
    /* number the clusters by their first track; parent[t] becomes t's cluster */
    size_t n = 0;
    for (size_t t = 0; t < nt; t++) parent[t] = (uint16_t)cluster_root(parent, t); /* a root is its cluster's
                                                                                     smallest track */
    for (size_t t = 0; t < nt; t++) parent[t] = (uint16_t)(parent[t] == t ? n++ : parent[parent[t]]);
    for (size_t c = 0; c <= n; c++) w->tr_first[c] = w->det_first[c] = 0;
    for (size_t t = 0; t < nt; t++) w->tr_first[parent[t] + 1]++;
    for (size_t j = 0; j < nd; j++)
        if (owner[j] != NONE) w->det_first[parent[owner[j]] + 1]++;
    for (size_t c = 0; c < n; c++) {
        w->tr_first[c + 1] = (uint16_t)(w->tr_first[c + 1] + w->tr_first[c]);
        w->det_first[c + 1] = (uint16_t)(w->det_first[c + 1] + w->det_first[c]);
    }
    /* fill, with tr_first / det_first advanced as cursors, then restored */
    for (size_t t = 0; t < nt; t++) w->tracks[w->tr_first[parent[t]]++] = (uint16_t)t;
    for (size_t j = 0; j < nd; j++) {
        if (owner[j] == NONE) continue;
        const size_t c = parent[owner[j]], pos = w->det_first[c]++;
        w->dets[pos] = (uint16_t)j;
    }
    for (size_t c = n; c > 0; c--) {
        w->tr_first[c] = w->tr_first[c - 1];
        w->det_first[c] = w->det_first[c - 1];
    }
    w->tr_first[0] = w->det_first[0] = 0;
    for (size_t c = 0; c < n; c++)
        for (size_t b = w->det_first[c]; b < w->det_first[c + 1]; b++)
            owner[w->dets[b]] = (uint16_t)(b - w->det_first[c]); /* det_local */
    return n;
}

/* scaled weights of cluster track a (index into the cluster) */
static trk_real wmiss(const struct cluster *c, size_t a)
{
    const size_t t = c->tracks[a];
    return c->w->miss[t];
}

/* the scaled weight of pair k (form_clusters made them linear in place) */
static trk_real wpair(const struct cluster *c, size_t k)
{
    return c->s->w[k];
}

/* the pair of scan track t and detection j, or NONE (binary search: a
 * track's detections increase) */
static size_t pair_of(const struct trk_jpda_pairs *s, size_t t, size_t j)
{
    size_t lo = s->first[t], hi = s->first[t + 1];
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (s->det[mid] < j) lo = mid + 1;
        else hi = mid;
    }
    return lo < s->first[t + 1] && s->det[lo] == j ? lo : NONE;
}

/* ------------------------------------------------------------------ one track */

/* A track alone in its cluster: P(t <- j) = w_tj / (w_t0 + sum_j w_tj), the
 * PDA weights. */
static void solve_lone(const struct cluster *c, trk_real *p_pair, trk_real *p_miss)
{
    const struct trk_jpda_pairs *s = c->s;
    const size_t t = c->tracks[0];
    trk_real z = wmiss(c, 0);
    for (size_t k = s->first[t]; k < s->first[t + 1]; k++) z += p_pair[k] = wpair(c, k);
    for (size_t k = s->first[t]; k < s->first[t + 1]; k++) p_pair[k] /= z;
    p_miss[t] = wmiss(c, 0) / z;
}

/* ------------------------------------------------------------------ two tracks */

/* Track a of a two-track cluster, o the other. The joint events are each
 * track missed or on its own detection, so
 *   P(a <- j) ~ w_aj (w_o0 + sum_{k != j} w_ok),
 *   P(a <- none) ~ w_a0 (w_o0 + sum_k w_ok),
 * with o's sum without j formed as its part before j (forward) plus its
 * part after j (backward, held in p_pair meanwhile): every term a sum of
 * products of weights, no subtraction (as in the programmes below), in
 * O(pairs) where the programmes take O(2^2 n_d) with a larger constant. */
static void two_track_marginals(const struct cluster *c, size_t a, trk_real *p_pair, trk_real *p_miss)
{
    const struct trk_jpda_pairs *s = c->s;
    const size_t ta = c->tracks[a], to = c->tracks[1 - a];
    const size_t a_lo = s->first[ta], a_hi = s->first[ta + 1], o_lo = s->first[to], o_hi = s->first[to + 1];
    trk_real after = 0, before = wmiss(c, 1 - a), w_o = wmiss(c, 1 - a);
    size_t q = o_hi;
    for (size_t k = a_hi; k-- > a_lo;) { /* o's weights on the detections after k's */
        while (q > o_lo && s->det[q - 1] > s->det[k]) after += wpair(c, --q);
        p_pair[k] = after;
    }
    for (q = o_lo; q < o_hi; q++) w_o += wpair(c, q);
    const trk_real pm = wmiss(c, a) * w_o;
    trk_real z = pm;
    q = o_lo;
    for (size_t k = a_lo; k < a_hi; k++) { /* and those before it, with o's miss */
        while (q < o_hi && s->det[q] < s->det[k]) before += wpair(c, q++);
        z += p_pair[k] = wpair(c, k) * (before + p_pair[k]);
    }
    p_miss[ta] = pm / z;
    for (size_t k = a_lo; k < a_hi; k++) p_pair[k] /= z;
}

static void solve_two(const struct cluster *c, trk_real *p_pair, trk_real *p_miss)
{
    two_track_marginals(c, 0, p_pair, p_miss);
    two_track_marginals(c, 1, p_pair, p_miss);
}

/* ------------------------------------------------------------------ exact */

/* Divide the first n entries by their largest, which is returned (1 when
 * all are 0): ratios within one programme are unchanged, nothing drifts
 * towards underflow or overflow, and programmes compared with each other
 * carry the sum of the logarithms. */
static trk_real rescale(trk_real *f, size_t n)
{
    trk_real m = 0;
    for (size_t s = 0; s < n; s++)
        if (f[s] > m) m = f[s];
    if (!(m > 0)) return 1;
    for (size_t s = 0; s < n; s++) f[s] /= m;
    return m;
}

/* One more element of the programme's other side, with weight w0 when it
 * is left out and x[i] when it joins member i of a subset (n members):
 *   g(S) <- w0 g(S) + sum_{i in S} x[i] g(S - i),
 * high to low (g(S - i) is still the old layer), then rescaled. */
static void subset_layer(trk_real *g, size_t n, trk_real w0, const trk_real *x)
{
    for (size_t s = (size_t)1 << n; s-- > 0;) {
        trk_real v = g[s] * w0;
        for (size_t i = 0; i < n; i++)
            if (s & ((size_t)1 << i)) v += g[s ^ ((size_t)1 << i)] * x[i];
        g[s] = v;
    }
    (void)rescale(g, (size_t)1 << n);
}

/* track a's scaled weights over the cluster's detections (nd <= bits) */
static void track_row(const struct cluster *c, size_t a, trk_real *row)
{
    const size_t t = c->tracks[a];
    for (size_t b = 0; b < c->nd; b++) row[b] = 0;
    for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) row[c->w->det.local[c->s->det[k]]] = wpair(c, k);
}

/* Subsets of the cluster's detections (nd <= bits): f(S) sums the events of
 * the tracks processed so far that use exactly the detections S. Track a's
 * marginals come from the programme over the other tracks:
 *   P(a <- b) ~ w_ab sum_{S not containing b} f(S),  P(a <- none) ~ w_a0 sum_S f(S).
 * Work: nt (nt - 1) 2^nd nd multiply-adds. */
static void exact_by_detections(const struct cluster *c, trk_real *p_pair, trk_real *p_miss)
{
    trk_real *f = c->w->u.dp;
    trk_real row[TRK_JPDA_EXACT_BITS], free_sum[TRK_JPDA_EXACT_BITS];
    const size_t ns = (size_t)1 << c->nd;
    for (size_t a = 0; a < c->nt; a++) {
        for (size_t s = 0; s < ns; s++) f[s] = 0;
        f[0] = 1;
        for (size_t o = 0; o < c->nt; o++) {
            if (o == a) continue;
            track_row(c, o, row);
            subset_layer(f, c->nd, wmiss(c, o), row);
        }
        trk_real total = 0;
        for (size_t b = 0; b < c->nd; b++) free_sum[b] = 0;
        for (size_t s = 0; s < ns; s++) {
            total += f[s];
            for (size_t b = 0; b < c->nd; b++)
                if (!(s & ((size_t)1 << b))) free_sum[b] += f[s];
        }
        const size_t t = c->tracks[a];
        const trk_real pm = wmiss(c, a) * total;
        trk_real z = pm;
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++)
            z += p_pair[k] = wpair(c, k) * free_sum[c->w->det.local[c->s->det[k]]];
        p_miss[t] = pm / z;
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) p_pair[k] /= z;
    }
}

/* Subsets of the cluster's tracks (nt <= bits), forward and backward over
 * its detections. f_b(S) sums the events of the detections before b in
 * which exactly the tracks S took one, h_b(S) those of the detections after
 * b; the events in which b is free or taken by track a split into
 *   Q_b(S) = sum over disjoint S1 u S2 = S of f_b(S1) h_b(S2),
 *   Z_b(free) = sum_S Q_b(S) M(S),   Z_b(a) = w_ab sum_{S not a} Q_b(S) M(S + a),
 * M(S) the product of the misses of the tracks outside S, and
 *   P(a <- b) = Z_b(a) / (Z_b(free) + sum_a Z_b(a)):
 * one normaliser per detection, so every layer's rescaling cancels, and
 * every term a sum of products of weights (no subtraction): the marginals
 * keep the working precision over any dynamic range. The misses come the
 * same way at the first detection. The backward layers are kept at every
 * B-th detection (B = ceil(sqrt(n_d))) and a block's recomputed from its
 * checkpoint: 1 + B + ceil(n_d / B) layers of 2^nt reals, about
 * n_d (3^nt + 4 nt 2^nt) operations (fb_work). */

/* the block length B = ceil(sqrt(nd)) */
static size_t fb_block(size_t nd)
{
    size_t b = 1;
    while (b * b < nd) b++;
    return b;
}

/* detection b's column: col[a] = w_ab (0 outside a's gate), k_of[a] its pair */
static void fb_column(const struct cluster *c, size_t b, trk_real *col, size_t *k_of)
{
    for (size_t a = 0; a < c->nt; a++) {
        k_of[a] = pair_of(c->s, c->tracks[a], c->dets[b]);
        col[a] = k_of[a] == NONE ? 0 : wpair(c, k_of[a]);
    }
}

/* Detection b's marginals from f (the detections before it), h (those
 * after), m (M) and its column; the misses too when p_miss is not NULL. */
static void fb_detection(const struct cluster *c, const trk_real *f, const trk_real *h, const trk_real *m,
                         const trk_real *col, const size_t *k_of, trk_real *p_pair, trk_real *p_miss)
{
    const size_t nt = c->nt, ns = (size_t)1 << nt;
    trk_real za[TRK_JPDA_EXACT_BITS], zm[TRK_JPDA_EXACT_BITS], z = 0;
    for (size_t a = 0; a < nt; a++) za[a] = zm[a] = 0;
    for (size_t s = 0; s < ns; s++) {
        trk_real q = 0;
        for (size_t s1 = s;; s1 = (s1 - 1) & s) { /* the subsets of s */
            q += f[s1] * h[s ^ s1];
            if (s1 == 0) break;
        }
        z += q * m[s];
        for (size_t a = 0; a < nt; a++) {
            const size_t bit = (size_t)1 << a;
            if (s & bit) continue;
            za[a] += q * m[s | bit];
            if (!p_miss) continue;
            trk_real v = m[s]; /* a takes nothing: b free or taken by another track outside s */
            for (size_t o = 0; o < nt; o++)
                if (o != a && !(s & ((size_t)1 << o))) v += col[o] * m[s | ((size_t)1 << o)];
            zm[a] += q * v;
        }
    }
    for (size_t a = 0; a < nt; a++) z += za[a] *= col[a];
    for (size_t a = 0; a < nt; a++) {
        if (k_of[a] != NONE) p_pair[k_of[a]] = za[a] / z;
        if (p_miss) p_miss[c->tracks[a]] = zm[a] / z;
    }
}

static void exact_by_tracks(const struct cluster *c, trk_real *p_pair, trk_real *p_miss)
{
    const size_t nt = c->nt, nd = c->nd, ns = (size_t)1 << nt, bl = fb_block(nd), len = ns * sizeof(trk_real);
    trk_real *m = c->w->u.dp, *f = m + ns, *blk = f + ns, *chk = blk + bl * ns; /* chk[k - 1]: h from detection k bl */
    trk_real col[TRK_JPDA_EXACT_BITS];
    size_t k_of[TRK_JPDA_EXACT_BITS];
    for (size_t s = 0; s < ns; s++) {
        m[s] = 1;
        for (size_t o = 0; o < nt; o++)
            if (!(s & ((size_t)1 << o))) m[s] *= wmiss(c, o);
        f[s] = blk[s] = 0;
    }
    f[0] = blk[0] = 1;
    for (size_t b = nd; b-- > bl;) { /* backward: the checkpoints */
        fb_column(c, b, col, k_of);
        subset_layer(blk, nt, 1, col);
        if (b % bl == 0) memcpy(chk + (b / bl - 1) * ns, blk, len);
    }
    for (size_t start = 0; start < nd; start += bl) {
        const size_t end = start + bl < nd ? start + bl : nd;
        trk_real *h = blk + (end - 1 - start) * ns; /* blk[i]: h after detection start + i */
        if (end < nd) {
            memcpy(h, chk + (end / bl - 1) * ns, len);
        } else {
            for (size_t s = 0; s < ns; s++) h[s] = 0;
            h[0] = 1;
        }
        for (size_t b = end - 1; b > start; b--, h -= ns) {
            fb_column(c, b, col, k_of);
            memcpy(h - ns, h, len);
            subset_layer(h - ns, nt, 1, col);
        }
        for (size_t b = start; b < end; b++) {
            fb_column(c, b, col, k_of);
            fb_detection(c, f, blk + (b - start) * ns, m, col, k_of, p_pair, b == 0 ? p_miss : NULL);
            subset_layer(f, nt, 1, col);
        }
    }
}

/* The work of each exact method (+1), 0 when it does not apply: its
 * multiply-adds plus the per-layer costs (building a row or column, the
 * rescaling), which dominate when the subset side is small (a 2-track
 * cluster over 256 detections costs 22 operations per detection step, not
 * the DP's 8). At most 256^2 * 65 * 2^16 * 80 < 2^63. */
static uint64_t work_by_detections(const struct cluster *c)
{
    if (c->nd > TRK_JPDA_EXACT_BITS) return 0;
    const uint64_t ns = (uint64_t)1 << c->nd, nt = c->nt;
    return nt * (nt > 0 ? nt - 1 : 0) * (ns * (c->nd + 2) + c->nd) + 1;
}

static uint64_t work_by_tracks(const struct cluster *c)
{
    if (c->nt > TRK_JPDA_EXACT_BITS) return 0;
    const uint64_t nt = c->nt, ns = (uint64_t)1 << nt, bl = fb_block(c->nd);
    if ((1 + bl + (c->nd + bl - 1) / bl) * ns > ((uint64_t)1 << TRK_JPDA_EXACT_BITS)) return 0;
    uint64_t pow3 = 1;
    for (uint64_t a = 0; a < nt; a++) pow3 *= 3;
    return c->nd * (pow3 + ns * (4 * nt + 6) + 30 * nt) + ns * nt * (nt + 1) + 1;
}

/* 1 when solved exactly: the cheaper method, within TRK_JPDA_MAX_WORK and
 * what is left of the call's TRK_JPDA_SCAN_WORK (*budget, reduced by it) */
static int solve_exact(const struct cluster *c, trk_real *p_pair, trk_real *p_miss, uint64_t *budget)
{
    const uint64_t wd = work_by_detections(c), wt = work_by_tracks(c);
    const int use_d = wd > 0 && (wt == 0 || wd <= wt);
    const uint64_t w = use_d ? wd : wt;
    if (w == 0 || w > (uint64_t)TRK_JPDA_MAX_WORK || w > *budget) return 0;
    *budget -= w;
    if (use_d) exact_by_detections(c, p_pair, p_miss);
    else exact_by_tracks(c, p_pair, p_miss);
    return 1;
}

/* ------------------------------------------------------------------ loopy belief propagation */

/* Williams & Lau 2014, eqs (29)-(30), with the messages mu_ab (track ->
 * detection) kept in p_pair:
 *   nu_ab = 1 / (1 + sum_{a' != a} mu_a'b),   T_a = w_a0 + sum_b w_ab nu_ab,
 *   mu_ab <- w_ab / (T_a - w_ab nu_ab),
 * marginals P(a <- b) = w_ab nu_ab / T_a, P(a <- none) = w_a0 / T_a.
 * Both leave-one-out sums are formed without subtracting a dominant term:
 * per detection the largest message (its pair in the solver's lbp_top, its
 * value in lbp.top) and the sum of the others (lbp.rest); per track the
 * largest term w_ab nu_ab and the sum of the others. A strong detection (mu or w nu beyond 1/eps of
 * the rest) would otherwise cancel to 0 in float and turn the cluster into
 * NaN. */

/* per detection of the cluster: lbp_top = the pair of its largest message
 * and lbp.top its value, lbp.rest = the sum of its other messages (all from
 * the messages as they are when called) */
static void lbp_sums(const struct cluster *c, const trk_real *mu)
{
    trk_real *rest = c->w->u.lbp.rest, *top_val = c->w->u.lbp.top;
    uint16_t *top = c->w->det.lbp_top;
    for (size_t b = 0; b < c->nd; b++) {
        rest[c->dets[b]] = 0;
        top[c->dets[b]] = NONE;
    }
    for (size_t a = 0; a < c->nt; a++) {
        const size_t t = c->tracks[a];
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) {
            const size_t j = c->s->det[k];
            if (top[j] == NONE) {
                top[j] = (uint16_t)k;
            } else if (mu[k] > top_val[j]) {
                rest[j] += top_val[j];
                top[j] = (uint16_t)k;
            } else {
                rest[j] += mu[k];
                continue;
            }
            top_val[j] = mu[k];
        }
    }
}

/* nu of pair k = 1 / (1 + the messages to its detection but its own), with
 * mu[k] as lbp_sums saw it */
static trk_real lbp_nu(const struct cluster *c, const trk_real *mu, size_t k)
{
    const size_t j = c->s->det[k];
    const trk_real rest = c->w->u.lbp.rest[j];
    return 1 / (1 + (k == c->w->det.lbp_top[j] ? rest : rest - mu[k] + c->w->u.lbp.top[j]));
}

/* Track a's T_a = w_a0 + sum_b w_ab nu_ab, its largest term's pair and T_a
 * less that term, summed directly. */
struct lbp_row {
    trk_real total, top_rest;
    size_t top;
};

static struct lbp_row lbp_row(const struct cluster *c, const trk_real *mu, size_t a)
{
    const size_t t = c->tracks[a];
    struct lbp_row r = {wmiss(c, a), wmiss(c, a), NONE};
    trk_real top_term = 0;
    for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) {
        const trk_real term = wpair(c, k) * lbp_nu(c, mu, k);
        r.total += term;
        if (r.top == NONE || term > top_term) {
            r.top = k;
            top_term = term;
        }
    }
    for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++)
        if (k != r.top) r.top_rest += wpair(c, k) * lbp_nu(c, mu, k);
    return r;
}

static int solve_lbp(const struct cluster *c, trk_real *p_pair, trk_real *p_miss, int *converged)
{
    trk_real *mu = p_pair;
    for (size_t a = 0; a < c->nt; a++) {
        const size_t t = c->tracks[a];
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) mu[k] = wpair(c, k);
    }
    int it = 0;
    *converged = 0;
    while (it < TRK_JPDA_LBP_MAX_ITER) {
        it++;
        lbp_sums(c, mu);
        trk_real change = 0;
        for (size_t a = 0; a < c->nt; a++) {
            const size_t t = c->tracks[a];
            const struct lbp_row r = lbp_row(c, mu, a);
            for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) {
                const trk_real wb = wpair(c, k);
                const trk_real m = wb / (k == r.top ? r.top_rest : r.total - wb * lbp_nu(c, mu, k));
                const trk_real d = trk_fabs(m - mu[k]) / (m > 0 ? m : 1);
                if (!(d <= change)) change = d; /* a NaN never passes for convergence */
                mu[k] = m;
            }
        }
        if (change <= TRK_REAL_C(1e-6)) {
            *converged = 1;
            break;
        }
    }
    /* marginals from the final messages (each row's nu from the sums taken
     * before any row is overwritten; a pair's own message is read before it
     * is written) */
    lbp_sums(c, mu);
    for (size_t a = 0; a < c->nt; a++) {
        const size_t t = c->tracks[a];
        const struct lbp_row r = lbp_row(c, mu, a);
        for (size_t k = c->s->first[t]; k < c->s->first[t + 1]; k++) mu[k] = wpair(c, k) * lbp_nu(c, mu, k) / r.total;
        p_miss[t] = wmiss(c, a) / r.total;
    }
    return it;
}
