/* jpda.c - JPDA / JIPDA marginal association probabilities (trk/jpda.h;
 * CONVENTIONS "Joint association"): clusters by union-find, an exact
 * subset dynamic programme per cluster, loopy belief propagation beyond the
 * exact bound. */
#include "trk/jpda.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "internal.h"
#include "pda_impl.h"

#if TRK_MAX_TRACKS > 65535 || TRK_MAX_DETECTIONS > 65535
#error "jpda.c indexes tracks and detections with unsigned short"
#endif

/* A cluster being solved: its tracks and gated detections (indices into the
 * scan), and the scaled linear weights read from the scan on the fly. */
struct cluster {
    const struct trk_jpda_scan *scan;
    struct trk_jpda_work *w;
    size_t nt, nd;
};

static trk_status check_scan(const struct trk_jpda_scan *s, const trk_real *p_assoc, const trk_real *p_miss);
static void form_clusters(const struct trk_jpda_scan *s, struct trk_jpda_work *w);
static size_t cluster_root(struct trk_jpda_work *w, size_t t);
static void gather_cluster(const struct trk_jpda_scan *s, struct trk_jpda_work *w, size_t root, struct cluster *c);
static int solve_exact(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss);
static int solve_lbp(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss, int *converged);

/* ------------------------------------------------------------------ API */

trk_status trk_jpda_marginals(const struct trk_jpda_scan *scan, struct trk_jpda_work *work, trk_real *p_assoc,
                              trk_real *p_miss, struct trk_jpda_report *rep)
{
    if (!work) return TRK_E_ARG;
    trk_status st = check_scan(scan, p_assoc, p_miss);
    if (st != TRK_OK) return st;
    struct trk_jpda_report r = {0, 0, 0, 0, 0, 0, 1};
    const size_t nt = scan->n_tracks, nd = scan->n_dets;
    if (nt > 0 && nd > 0) memset(p_assoc, 0, nt * nd * sizeof *p_assoc);
    form_clusters(scan, work);
    for (size_t t = 0; t < nt; t++) {
        if (cluster_root(work, t) != t) continue;
        struct cluster c;
        gather_cluster(scan, work, t, &c);
        r.n_clusters++;
        if (c.nt > r.largest_tracks) r.largest_tracks = c.nt;
        if (c.nd > r.largest_dets) r.largest_dets = c.nd;
        if (solve_exact(&c, p_assoc, p_miss)) {
            r.n_exact++;
        } else {
            int conv = 0;
            const int it = solve_lbp(&c, p_assoc, p_miss, &conv);
            r.n_approx++;
            if (it > r.lbp_iterations) r.lbp_iterations = it;
            if (!conv) r.lbp_converged = 0;
        }
    }
    if (rep) *rep = r;
    return TRK_OK;
}

trk_status trk_jpda_existence(trk_real psi, trk_real pd_pg, const trk_real *p_assoc, size_t n_dets, trk_real p_miss,
                              trk_real *psi_post, trk_real *beta)
{
    if (!psi_post || !beta || (n_dets > 0 && !p_assoc)) return TRK_E_ARG;
    if (!isfinite(psi) || !isfinite(pd_pg) || !isfinite(p_miss)) return TRK_E_NAN;
    if (!(psi > 0 && psi <= 1) || !(pd_pg > 0 && pd_pg <= 1)) return TRK_E_RANGE;
    const trk_real den = 1 - pd_pg * psi;
    if (!(den > 0) && psi < 1) return TRK_E_RANGE;
    trk_real assoc = 0;
    for (size_t j = 0; j < n_dets; j++) {
        if (!isfinite(p_assoc[j])) return TRK_E_NAN;
        assoc += p_assoc[j];
    }
    /* P(t exists and took nothing): with psi = 1 the factor is 1 exactly */
    const trk_real miss_exists = psi < 1 ? p_miss * psi * (1 - pd_pg) / den : p_miss;
    const trk_real post = assoc + miss_exists;
    if (!(post > 0)) return TRK_E_RANGE;
    beta[0] = miss_exists / post;
    for (size_t j = 0; j < n_dets; j++) beta[j + 1] = p_assoc[j] / post;
    *psi_post = post;
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

static trk_status check_scan(const struct trk_jpda_scan *s, const trk_real *p_assoc, const trk_real *p_miss)
{
    if (!s) return TRK_E_ARG;
    if (s->n_tracks > TRK_MAX_TRACKS || s->n_dets > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (s->n_tracks > 0 && (!s->log_w_miss || !p_miss)) return TRK_E_ARG;
    if (s->n_tracks > 0 && s->n_dets > 0 && (!s->log_w || !p_assoc)) return TRK_E_ARG;
    for (size_t t = 0; t < s->n_tracks; t++) {
        if (!isfinite(s->log_w_miss[t])) return TRK_E_NAN;
        for (size_t j = 0; j < s->n_dets; j++) {
            const trk_real v = s->log_w[t * s->n_dets + j];
            if (isnan(v)) return TRK_E_NAN;
            if (v > 0 && isinf(v)) return TRK_E_RANGE;
        }
    }
    return TRK_OK;
}

static int gated(const struct trk_jpda_scan *s, size_t t, size_t j)
{
    return isfinite(s->log_w[t * s->n_dets + j]);
}

/* root with path halving (iterative: no recursion) */
static size_t cluster_root(struct trk_jpda_work *w, size_t t)
{
    while (w->parent[t] != t) {
        w->parent[t] = w->parent[w->parent[t]];
        t = w->parent[t];
    }
    return t;
}

/* Tracks gating a common detection are joined; the smaller index is the root,
 * so a cluster is met at its first track by the caller's loop. */
static void form_clusters(const struct trk_jpda_scan *s, struct trk_jpda_work *w)
{
    const unsigned short none = 0xFFFFu;
    for (size_t t = 0; t < s->n_tracks; t++) w->parent[t] = (unsigned short)t;
    for (size_t j = 0; j < s->n_dets; j++) w->det_owner[j] = none;
    for (size_t t = 0; t < s->n_tracks; t++)
        for (size_t j = 0; j < s->n_dets; j++) {
            if (!gated(s, t, j)) continue;
            if (w->det_owner[j] == none) {
                w->det_owner[j] = (unsigned short)t;
                continue;
            }
            size_t a = cluster_root(w, w->det_owner[j]), b = cluster_root(w, t);
            if (a == b) continue;
            if (a < b) w->parent[b] = (unsigned short)a;
            else w->parent[a] = (unsigned short)b;
        }
}

/* The members of root's cluster, and each member track's scale (its largest
 * ln w), so that every scaled weight is at most 1. */
static void gather_cluster(const struct trk_jpda_scan *s, struct trk_jpda_work *w, size_t root, struct cluster *c)
{
    c->scan = s;
    c->w = w;
    c->nt = c->nd = 0;
    for (size_t t = root; t < s->n_tracks; t++) {
        if (cluster_root(w, t) != root) continue;
        w->cl_tracks[c->nt++] = (unsigned short)t;
        trk_real m = s->log_w_miss[t];
        for (size_t j = 0; j < s->n_dets; j++)
            if (gated(s, t, j) && s->log_w[t * s->n_dets + j] > m) m = s->log_w[t * s->n_dets + j];
        w->scale[t] = m;
    }
    for (size_t j = 0; j < s->n_dets; j++)
        if (w->det_owner[j] != 0xFFFFu && cluster_root(w, w->det_owner[j]) == root)
            w->cl_dets[c->nd++] = (unsigned short)j;
}

/* scaled weights of cluster track a (index into the cluster) */
static trk_real wmiss(const struct cluster *c, size_t a)
{
    const size_t t = c->w->cl_tracks[a];
    return trk_exp(c->scan->log_w_miss[t] - c->w->scale[t]);
}

static trk_real wdet(const struct cluster *c, size_t a, size_t b)
{
    const size_t t = c->w->cl_tracks[a], j = c->w->cl_dets[b];
    const trk_real v = c->scan->log_w[t * c->scan->n_dets + j];
    return isfinite(v) ? trk_exp(v - c->w->scale[t]) : 0;
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

/* Subsets of the cluster's detections (nd <= bits): f(S) sums the events of
 * the tracks processed so far that use exactly the detections S. Track a's
 * marginals come from the programme over the other tracks:
 *   P(a <- b) ~ w_ab sum_{S not containing b} f(S),  P(a <- none) ~ w_a0 sum_S f(S).
 * Work: nt (nt - 1) 2^nd nd multiply-adds. */
static void exact_by_detections(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss)
{
    trk_real *f = c->w->dp;
    trk_real row[TRK_JPDA_EXACT_BITS];
    const size_t ns = (size_t)1 << c->nd, n_dets = c->scan->n_dets;
    for (size_t a = 0; a < c->nt; a++) {
        for (size_t s = 0; s < ns; s++) f[s] = 0;
        f[0] = 1;
        for (size_t o = 0; o < c->nt; o++) {
            if (o == a) continue;
            const trk_real w0 = wmiss(c, o);
            for (size_t b = 0; b < c->nd; b++) row[b] = wdet(c, o, b);
            for (size_t s = ns; s-- > 0;) { /* high to low: f(S \ b) is still the old layer */
                trk_real v = f[s] * w0;
                for (size_t b = 0; b < c->nd; b++)
                    if (s & ((size_t)1 << b)) v += f[s ^ ((size_t)1 << b)] * row[b];
                f[s] = v;
            }
            (void)rescale(f, ns);
        }
        trk_real total = 0;
        for (size_t s = 0; s < ns; s++) total += f[s];
        const size_t t = c->w->cl_tracks[a];
        const trk_real pm = wmiss(c, a) * total;
        trk_real z = pm;
        for (size_t b = 0; b < c->nd; b++) {
            const trk_real wb = wdet(c, a, b);
            trk_real v = 0;
            if (wb != 0) {
                trk_real free_sum = 0;
                for (size_t s = 0; s < ns; s++)
                    if (!(s & ((size_t)1 << b))) free_sum += f[s];
                v = wb * free_sum;
            }
            row[b] = v;
            z += v;
        }
        p_miss[t] = pm / z;
        for (size_t b = 0; b < c->nd; b++) p_assoc[t * n_dets + c->w->cl_dets[b]] = row[b] / z;
    }
}

/* Subsets of the cluster's tracks (nt <= bits): g(S) sums the events of the
 * detections processed so far in which exactly the tracks S took one; the
 * events close with the misses of the tracks outside S. Returns that sum
 * over the detections but skip_b, and with track skip_a left out (no
 * factor, excluded from S) when skip_a < nt, as total * exp(*ln_scale). */
static trk_real exact_tracks_sum(const struct cluster *c, size_t skip_b, size_t skip_a, trk_real *ln_scale)
{
    trk_real *g = c->w->dp;
    trk_real col[TRK_JPDA_EXACT_BITS], miss[TRK_JPDA_EXACT_BITS];
    const size_t ns = (size_t)1 << c->nt;
    for (size_t s = 0; s < ns; s++) g[s] = 0;
    g[0] = 1;
    *ln_scale = 0;
    for (size_t b = 0; b < c->nd; b++) {
        if (b == skip_b) continue;
        for (size_t o = 0; o < c->nt; o++) col[o] = o == skip_a ? 0 : wdet(c, o, b);
        for (size_t s = ns; s-- > 0;) {
            trk_real v = g[s];
            for (size_t o = 0; o < c->nt; o++)
                if (s & ((size_t)1 << o)) v += g[s ^ ((size_t)1 << o)] * col[o];
            g[s] = v;
        }
        *ln_scale += trk_log(rescale(g, ns));
    }
    for (size_t o = 0; o < c->nt; o++) miss[o] = o == skip_a ? 1 : wmiss(c, o);
    trk_real total = 0;
    for (size_t s = 0; s < ns; s++) {
        trk_real v = g[s];
        for (size_t o = 0; o < c->nt && v != 0; o++)
            if (!(s & ((size_t)1 << o))) v *= miss[o];
        total += v;
    }
    return total;
}

/* P(a <- b) = w_ab Z(-a, -b) / Z(-b, b free), with every programme over the
 * same detections (all but b) so that their rescalings agree:
 * Z(-b, b free) = Z(b clutter) + sum_a w_ab Z(-a, -b). P(a <- none) is what
 * is left of track a's unit row. Work: nd (nt + 1) (nd - 1) 2^nt nt. */
static void exact_by_tracks(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss)
{
    const size_t n_dets = c->scan->n_dets;
    for (size_t b = 0; b < c->nd; b++) {
        trk_real ln0, lna;
        trk_real z = exact_tracks_sum(c, b, (size_t)-1, &ln0);
        for (size_t a = 0; a < c->nt; a++) {
            const trk_real wb = wdet(c, a, b);
            trk_real v = 0;
            if (wb != 0) {
                v = exact_tracks_sum(c, b, a, &lna);
                v *= wb * trk_exp(lna - ln0);
            }
            p_assoc[c->w->cl_tracks[a] * n_dets + c->w->cl_dets[b]] = v;
            z += v;
        }
        for (size_t a = 0; a < c->nt; a++) p_assoc[c->w->cl_tracks[a] * n_dets + c->w->cl_dets[b]] /= z;
    }
    for (size_t a = 0; a < c->nt; a++) {
        const size_t t = c->w->cl_tracks[a];
        trk_real sum = 0;
        for (size_t b = 0; b < c->nd; b++) sum += p_assoc[t * n_dets + c->w->cl_dets[b]];
        p_miss[t] = sum < 1 ? 1 - sum : 0;
    }
}

/* multiply-adds of each exact method (+1), 0 when it does not apply; at most
 * 256^2 * 65 * 2^16 * 64 < 2^63 */
static uint64_t work_by_detections(const struct cluster *c)
{
    if (c->nd > TRK_JPDA_EXACT_BITS) return 0;
    return (uint64_t)c->nt * (uint64_t)(c->nt > 0 ? c->nt - 1 : 0) * ((uint64_t)1 << c->nd) * (uint64_t)c->nd + 1;
}

static uint64_t work_by_tracks(const struct cluster *c)
{
    if (c->nt > TRK_JPDA_EXACT_BITS) return 0;
    return (uint64_t)c->nd * (uint64_t)(c->nt + 1) * (uint64_t)c->nd * ((uint64_t)1 << c->nt) * (uint64_t)c->nt + 1;
}

/* 1 when solved exactly (the cheaper method within TRK_JPDA_MAX_WORK) */
static int solve_exact(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss)
{
    const uint64_t wd = work_by_detections(c), wt = work_by_tracks(c);
    const int use_d = wd > 0 && (wt == 0 || wd <= wt);
    const uint64_t w = use_d ? wd : wt;
    if (w == 0 || w > (uint64_t)TRK_JPDA_MAX_WORK) return 0;
    if (use_d) exact_by_detections(c, p_assoc, p_miss);
    else exact_by_tracks(c, p_assoc, p_miss);
    return 1;
}

/* ------------------------------------------------------------------ loopy belief propagation */

/* Williams & Lau 2014, eqs (29)-(30), with the messages mu_ab (track ->
 * detection) kept in p_assoc and the detection sums S_b = sum_a mu_ab in
 * work->det_sum:
 *   nu_ab = 1 / (1 + S_b - mu_ab),   T_a = w_a0 + sum_b w_ab nu_ab,
 *   mu_ab <- w_ab / (T_a - w_ab nu_ab).
 * Marginals: P(a <- b) = w_ab nu_ab / T_a, P(a <- none) = w_a0 / T_a. */
#define MU(a, b) p_assoc[(size_t)c->w->cl_tracks[a] * c->scan->n_dets + c->w->cl_dets[b]]

/* S_b = sum_a mu_ab of every detection of the cluster */
static void lbp_sums(const struct cluster *c, const trk_real *p_assoc, trk_real *sum)
{
    for (size_t b = 0; b < c->nd; b++) sum[c->w->cl_dets[b]] = 0;
    for (size_t a = 0; a < c->nt; a++)
        for (size_t b = 0; b < c->nd; b++) sum[c->w->cl_dets[b]] += MU(a, b);
}

/* nu_ab = 1 / (1 + S_b - mu_ab) (0 outside the gate) */
static trk_real lbp_nu(const struct cluster *c, const trk_real *p_assoc, const trk_real *sum, size_t a, size_t b,
                       trk_real wb)
{
    return wb != 0 ? 1 / (1 + sum[c->w->cl_dets[b]] - MU(a, b)) : 0;
}

/* T_a = w_a0 + sum_b w_ab nu_ab */
static trk_real lbp_total(const struct cluster *c, const trk_real *p_assoc, const trk_real *sum, size_t a)
{
    trk_real ta = wmiss(c, a);
    for (size_t b = 0; b < c->nd; b++) {
        const trk_real wb = wdet(c, a, b);
        ta += wb * lbp_nu(c, p_assoc, sum, a, b, wb);
    }
    return ta;
}

static int solve_lbp(const struct cluster *c, trk_real *p_assoc, trk_real *p_miss, int *converged)
{
    trk_real *sum = c->w->det_sum;
    for (size_t a = 0; a < c->nt; a++)
        for (size_t b = 0; b < c->nd; b++) MU(a, b) = wdet(c, a, b);
    int it = 0;
    *converged = 0;
    while (it < TRK_JPDA_LBP_MAX_ITER) {
        it++;
        lbp_sums(c, p_assoc, sum);
        trk_real change = 0;
        for (size_t a = 0; a < c->nt; a++) {
            const trk_real ta = lbp_total(c, p_assoc, sum, a);
            for (size_t b = 0; b < c->nd; b++) {
                const trk_real wb = wdet(c, a, b);
                if (wb == 0) continue;
                const trk_real mu = wb / (ta - wb * lbp_nu(c, p_assoc, sum, a, b, wb));
                const trk_real d = trk_fabs(mu - MU(a, b)) / (mu > 0 ? mu : 1);
                if (d > change) change = d;
                MU(a, b) = mu;
            }
        }
        if (change <= TRK_REAL_C(1e-6)) {
            *converged = 1;
            break;
        }
    }
    /* marginals from the final messages; each row's nu from the sums taken
     * before any row is overwritten */
    lbp_sums(c, p_assoc, sum);
    for (size_t a = 0; a < c->nt; a++) {
        const trk_real ta = lbp_total(c, p_assoc, sum, a);
        for (size_t b = 0; b < c->nd; b++) {
            const trk_real wb = wdet(c, a, b);
            MU(a, b) = wb * lbp_nu(c, p_assoc, sum, a, b, wb) / ta;
        }
        p_miss[c->w->cl_tracks[a]] = wmiss(c, a) / ta;
    }
    return it;
}
#undef MU
