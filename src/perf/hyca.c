/* hyca.c - hybrid conditional averaging (trk/hyca.h; Willett 2010 eqs 43-48,
 * Figs 7-8; docs/conventions.md "HYCA"). */
#include "trk/hyca.h"

#include "internal.h"
#include "fixed_point_impl.h"
#include "two_point_impl.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/linalg.h"
#include "trk/mre.h"
#include "trk/special.h"

/* Return the status of a call that can fail on its input. */
#define RETURN_IF_ERROR(call)             \
    do {                                  \
        const trk_status st_ = (call);    \
        if (st_ != TRK_OK) return st_;    \
    } while (0)

#define NXMAX TRK_HYCA_MAX_NX
#define NN (NXMAX * NXMAX)

static const trk_real h1[2] = {1, 0}; /* nz = 1: H = [1, 0] */

/* The CV model both forms share: F, Q, H, R. */
struct cv {
    int nz, nx;
    const trk_real *h;
    trk_real f[NN], q[NN], r[4];
};

static trk_status cv_init(struct cv *m, int nz, trk_real dt_s, trk_real q_m2_per_s3, trk_real r_m2)
{
    m->nz = nz;
    m->nx = 2 * nz;
    m->h = nz == 2 ? trk_cv2_h : h1;
    for (int i = 0; i < 4; i++) m->r[i] = 0;
    for (int i = 0; i < nz; i++) m->r[i * nz + i] = r_m2;
    return trk_cv_model(nz, dt_s, q_m2_per_s3, m->f, m->q);
}

/* The scan of eq 43 from the posterior p: the prediction pp = F p F' + Q,
 * the innovation (S, det S) and the Kalman update pc (Joseph form, SPD). */
static trk_status predict_update(const struct cv *m, const trk_real *p, trk_real *pp, trk_real *pc,
                                 struct trk_innovation *inn)
{
    trk_real x[NXMAX] = {0, 0, 0, 0}, k[NXMAX * 2];
    for (int i = 0; i < m->nx * m->nx; i++) pp[i] = p[i];
    RETURN_IF_ERROR(trk_kalman_predict(m->nx, m->f, m->q, x, pp));
    RETURN_IF_ERROR(trk_kalman_innovation(m->nx, m->nz, m->h, m->r, x, pp, inn));
    trk_kalman_gain(m->nx, m->nz, m->h, pp, inn, k);
    trk_kalman_joseph(m->nx, m->nz, m->h, m->r, k, pp, pc);
    return TRK_OK;
}

static int finite_all(int n, const trk_real *v)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static trk_real max_abs(int n, const trk_real *v)
{
    trk_real m = 0;
    for (int i = 0; i < n; i++)
        if (trk_fabs(v[i]) > m) m = trk_fabs(v[i]);
    return m;
}

static trk_real max_abs_diff(int n, const trk_real *a, const trk_real *b)
{
    trk_real m = 0;
    for (int i = 0; i < n; i++)
        if (trk_fabs(a[i] - b[i]) > m) m = trk_fabs(a[i] - b[i]);
    return m;
}

static trk_status check_model(int nz, trk_real dt_s, trk_real q, trk_real r, trk_real pd)
{
    if (nz != 1 && nz != 2) return TRK_E_ARG;
    if (!isfinite(dt_s) || !isfinite(q) || !isfinite(r) || !isfinite(pd)) return TRK_E_NAN;
    if (!(dt_s > 0) || !(q > 0) || !(r > 0) || !(pd > 0 && pd <= 1)) return TRK_E_RANGE;
    return TRK_OK;
}

/* ---- 1. missed detections only ---- */

trk_status trk_hyca_md(const struct trk_hyca_md_params *pr, struct trk_hyca_md_result *res)
{
    if (!pr || !res || pr->max_iter < 0) return TRK_E_ARG;
    RETURN_IF_ERROR(check_model(pr->nz, pr->dt_s, pr->q_m2_per_s3, pr->r_m2, pr->pd));
    if (!isfinite(pr->rel_tol)) return TRK_E_NAN;
    if (!(pr->rel_tol >= 0)) return TRK_E_RANGE;
    struct cv m;
    RETURN_IF_ERROR(cv_init(&m, pr->nz, pr->dt_s, pr->q_m2_per_s3, pr->r_m2));
    const int nx = m.nx, n = nx * nx, max_iter = pr->max_iter ? pr->max_iter : 1000000;
    const trk_real pd = pr->pd, rel_tol = pr->rel_tol > 0 ? pr->rel_tol : 64 * TRK_REAL_EPS;
    /* P_1 = P_2 = 0: the fixed point is unique, the first prediction is Q */
    trk_real p1[NN] = {0}, p2[NN] = {0};
    struct trk_i_fixed_point fp;
    trk_i_fixed_point_init(&fp);
    res->nx = nx;
    res->rel_tol = rel_tol;
    for (int it = 1; it <= max_iter; it++) {
        trk_real pp1[NN], pc1[NN], pp2[NN], pc2[NN], n1[NN], n2[NN];
        struct trk_innovation inn;
        RETURN_IF_ERROR(predict_update(&m, p1, pp1, pc1, &inn));
        RETURN_IF_ERROR(predict_update(&m, p2, pp2, pc2, &inn));
        /* eq 46: P_j(k+1) = sum_i mu_i f_j(P_i(k)); f_1 update, f_2 prediction */
        for (int i = 0; i < n; i++) {
            n1[i] = pd * pc1[i] + (1 - pd) * pc2[i];
            n2[i] = pd * pp1[i] + (1 - pd) * pp2[i];
        }
        trk_mat_symmetrize(nx, n1);
        trk_mat_symmetrize(nx, n2);
        if (!finite_all(n, n1) || !finite_all(n, n2)) return TRK_E_NAN;
        trk_real change = max_abs_diff(n, n1, p1), c2 = max_abs_diff(n, n2, p2);
        if (c2 > change) change = c2;
        const trk_real scale = max_abs(n, n2); /* P_2 >= P_1 elementwise on the diagonal */
        for (int i = 0; i < n; i++) {
            p1[i] = n1[i];
            p2[i] = n2[i];
        }
        res->iterations = it;
        res->last_change = change;
        if (trk_i_fixed_point_done(&fp, change, scale, rel_tol)) break;
        if (it == max_iter) {
            for (int i = 0; i < NN; i++) res->p_det[i] = res->p_miss[i] = res->p[i] = 0;
            return TRK_E_DIVERGED;
        }
    }
    for (int i = 0; i < NN; i++) res->p_det[i] = res->p_miss[i] = res->p[i] = 0;
    for (int i = 0; i < n; i++) {
        res->p_det[i] = p1[i];
        res->p_miss[i] = p2[i];
        res->p[i] = pd * p1[i] + (1 - pd) * p2[i]; /* eq 48 */
    }
    res->rmse_m = trk_mre_rmse(pr->nz, res->p);
    return TRK_OK;
}

/* ---- 2. with clutter ---- */

trk_status trk_hyca_init(struct trk_hyca *h, const struct trk_hyca_params *pr)
{
    if (!h || !pr || pr->max_scans < 0 || pr->horizon_scans < 0) return TRK_E_ARG;
    if (pr->m_lost != 0 && (pr->m_lost < 2 || pr->m_lost > TRK_HYCA_MAX_STATES)) return TRK_E_ARG;
    RETURN_IF_ERROR(check_model(pr->nz, pr->dt_s, pr->q_m2_per_s3, pr->r_m2, pr->pd));
    if (!isfinite(pr->gate_prob) || !isfinite(pr->gate_gamma) || !isfinite(pr->clutter_density) ||
        !isfinite(pr->rel_tol))
        return TRK_E_NAN;
    if (!(pr->clutter_density >= 0) || !(pr->rel_tol >= 0) || pr->gate_gamma < 0) return TRK_E_RANGE;
    trk_real gamma = pr->gate_gamma;
    if (gamma == 0) RETURN_IF_ERROR(trk_gate_gamma(pr->nz, pr->gate_prob, &gamma));
    struct cv m;
    RETURN_IF_ERROR(cv_init(&m, pr->nz, pr->dt_s, pr->q_m2_per_s3, pr->r_m2));
    RETURN_IF_ERROR(trk_irf_init(&h->irf, pr->nz, gamma));
    h->params = *pr;
    if (h->params.m_lost == 0) h->params.m_lost = 10;
    if (h->params.max_scans == 0) h->params.max_scans = 100000;
    if (h->params.rel_tol == 0) h->params.rel_tol = TRK_REAL_IS_FLOAT ? TRK_REAL_C(1e-5) : TRK_REAL_C(1e-10);
    h->nx = m.nx;
    h->gamma = gamma;
    for (int i = 0; i < NN; i++) h->f[i] = m.f[i], h->q[i] = m.q[i];
    return TRK_OK;
}

/* One state's transitions: from covariance p, the probabilities of each
 * gated count j < m_lost (pij), the reduction weights P{j} eta_j (red), the
 * loss probability P{m' >= m_lost}, the prediction pp and the update pc. */
struct from_state {
    trk_real pij[TRK_HYCA_MAX_STATES], red[TRK_HYCA_MAX_STATES];
    trk_real loss;
    trk_real pp[NN], pc[NN];
};

static trk_status transitions(const struct trk_hyca *h, const struct cv *m, const trk_real *p,
                              struct from_state *s)
{
    const struct trk_hyca_params *pr = &h->params;
    const int ml = pr->m_lost;
    struct trk_innovation inn;
    RETURN_IF_ERROR(predict_update(m, p, s->pp, s->pc, &inn));
    const trk_real lvg = pr->clutter_density * trk_gate_volume_inn(&inn, h->gamma);
    if (!isfinite(lvg)) return TRK_E_NAN;
    const trk_real pdpg = pr->pd * h->irf.pg;
    trk_real e[TRK_HYCA_MAX_STATES];
    RETURN_IF_ERROR(trk_irf_beta1(&h->irf, trk_irf_b(&h->irf, pr->pd, lvg), ml - 2, e));
    /* Poisson(j; lvg) in the log domain (lvg may be large) */
    trk_real pois_prev = 0; /* Pois(j - 1) */
    const trk_real ln_l = lvg > 0 ? trk_log(lvg) : 0;
    trk_real ln_fact = 0;
    for (int j = 0; j < ml; j++) {
        if (j > 0) ln_fact += trk_log((trk_real)j);
        const trk_real pois = lvg > 0 ? trk_exp((trk_real)j * ln_l - lvg - ln_fact) : (j == 0 ? 1 : 0);
        s->pij[j] = (1 - pdpg) * pois + pdpg * pois_prev;
        /* P{j} eta_j = pd F_{nz+2} Pois(j - 1) E_{j-1}[beta_1] (Brekke eqs 28-30) */
        s->red[j] = j > 0 ? pr->pd * h->irf.f_target * pois_prev * e[j - 1] : 0;
        pois_prev = pois;
    }
    /* P{N > k} = P(chi2(2k + 2) <= 2 lvg), each tail computed directly */
    s->loss = lvg > 0 ? (1 - pdpg) * trk_chi2_cdf(2 * ml, 2 * lvg) + pdpg * trk_chi2_cdf(2 * ml - 2, 2 * lvg)
                      : 0;
    return TRK_OK;
}

/* The held chain: state probabilities (sum 1 over the held states) and the
 * covariance conditioned on each. */
struct chain {
    trk_real mu[TRK_HYCA_MAX_STATES];
    trk_real p[TRK_HYCA_MAX_STATES][NN];
};

/* One scan of the chain (hybrid conditional averaging): next <- cur; the
 * probability of loss at this scan in *loss. */
static trk_status chain_step(const struct trk_hyca *h, const struct cv *m, const struct chain *cur,
                             struct chain *next, trk_real *loss)
{
    const int ml = h->params.m_lost, n = m->nx * m->nx;
    trk_real a[TRK_HYCA_MAX_STATES][NN];
    for (int j = 0; j < ml; j++) {
        next->mu[j] = 0;
        for (int i = 0; i < n; i++) a[j][i] = 0;
    }
    *loss = 0;
    for (int i = 0; i < ml; i++) {
        if (!(cur->mu[i] > 0)) continue;
        struct from_state s;
        RETURN_IF_ERROR(transitions(h, m, cur->p[i], &s));
        *loss += cur->mu[i] * s.loss;
        for (int j = 0; j < ml; j++) {
            const trk_real w = cur->mu[i] * s.pij[j], wr = cur->mu[i] * s.red[j];
            if (!(w > 0)) continue;
            next->mu[j] += w;
            /* w P- - wr (P- - Pc): the expected update given j gated */
            for (int k = 0; k < n; k++) a[j][k] += (w - wr) * s.pp[k] + wr * s.pc[k];
        }
    }
    trk_real held = 0;
    for (int j = 0; j < ml; j++) held += next->mu[j];
    if (!(held > 0)) return TRK_E_DIVERGED; /* every track lost in one scan */
    for (int j = 0; j < ml; j++) {
        if (next->mu[j] > 0) {
            for (int k = 0; k < n; k++) next->p[j][k] = a[j][k] / next->mu[j];
            trk_mat_symmetrize(m->nx, next->p[j]);
            if (!finite_all(n, next->p[j])) return TRK_E_NAN;
        } else {
            for (int k = 0; k < n; k++) next->p[j][k] = cur->p[j][k];
        }
        next->mu[j] /= held;
    }
    return TRK_OK;
}

static void fill_held(const struct trk_hyca *h, const struct chain *c, trk_real loss, struct trk_hyca_result *res)
{
    const int ml = h->params.m_lost, n = h->nx * h->nx;
    for (int k = 0; k < NN; k++) res->p_held[k] = 0;
    res->mean_gated = 0;
    for (int j = 0; j < TRK_HYCA_MAX_STATES; j++) res->mu[j] = j < ml ? c->mu[j] : 0;
    for (int j = 0; j < ml; j++) {
        res->mean_gated += (trk_real)j * c->mu[j];
        for (int k = 0; k < n; k++) res->p_held[k] += c->mu[j] * c->p[j][k];
    }
    res->rmse_m = trk_mre_rmse(h->params.nz, res->p_held);
    res->loss_per_scan = loss;
}

/* Change of the chain between two scans: covariances weighted by their
 * state's probability, relative to the held average; probabilities as they are. */
static trk_real chain_change(int ml, int n, const struct chain *a, const struct chain *b, trk_real scale)
{
    trk_real c = 0;
    for (int j = 0; j < ml; j++) {
        const trk_real dm = trk_fabs(a->mu[j] - b->mu[j]);
        const trk_real dp = b->mu[j] * max_abs_diff(n, a->p[j], b->p[j]) / scale;
        if (dm > c) c = dm;
        if (dp > c) c = dp;
    }
    return c;
}

/* The horizon's figures past the last iterated scan k, where S falls
 * geometrically: S(k + i) = S(k) r^i, r = 1 - p, ln S(k) = log_s. */
static void horizon_tail(int horizon, int k, trk_real log_s, trk_real p, struct trk_hyca_result *res)
{
    if (horizon <= k) return;
    const int j = horizon - k; /* scans k+1 .. horizon */
    const trk_real ln_r = trk_log1p(-p);
    /* sum_{i=1}^{j-1} S(k) r^i = S(k) r (1 - r^(j-1)) / p (without cancellation) */
    const trk_real s_k = trk_exp(log_s);
    res->mean_life_horizon += p > 0 ? s_k * (1 - p) * -trk_expm1((trk_real)(j - 1) * ln_r) / p
                                    : s_k * (trk_real)(j - 1);
    res->lost_by_horizon = -trk_expm1(log_s + (trk_real)j * ln_r);
}

trk_status trk_hyca_run(const struct trk_hyca *h, const trk_real *p0, struct trk_hyca_result *res)
{
    if (!h || !res) return TRK_E_ARG;
    const struct trk_hyca_params *pr = &h->params;
    const int ml = pr->m_lost, nx = h->nx, n = nx * nx;
    struct cv m;
    RETURN_IF_ERROR(cv_init(&m, pr->nz, pr->dt_s, pr->q_m2_per_s3, pr->r_m2));
    struct chain c[2];
    for (int j = 0; j < TRK_HYCA_MAX_STATES; j++) c[0].mu[j] = c[1].mu[j] = 0;
    /* a new track: m = 1, P_0 */
    if (p0) {
        trk_real l[NN];
        if (!finite_all(n, p0)) return TRK_E_NAN;
        if (trk_chol(nx, p0, l) != TRK_OK) return TRK_E_NOT_SPD;
        for (int k = 0; k < n; k++) c[0].p[1][k] = p0[k];
    } else {
        trk_i_two_point_cov(pr->nz, pr->r_m2, pr->dt_s, c[0].p[1]);
    }
    for (int j = 0; j < ml; j++)
        for (int k = 0; k < n; k++) c[0].p[j][k] = c[0].p[1][k];
    c[0].mu[1] = 1;
    res->nx = nx;
    res->m_lost = ml;
    res->converged = 0;
    /* S(k) = P{held after k scans} in the log domain; E[L] = sum_k S(k) */
    trk_real log_s = 0, sum_s = 1, median = (trk_real)INFINITY, loss = 0, loss_prev = -1;
    /* the run cut at the horizon N: E[min(L, N)] = sum_{k<N} S(k), 1 - S(N) */
    const int horizon = pr->horizon_scans;
    res->mean_life_horizon = horizon > 0 ? 1 : 0;
    res->lost_by_horizon = 0;
    struct trk_i_fixed_point fp;
    trk_i_fixed_point_init(&fp);
    int cur = 0;
    for (int it = 1; it <= pr->max_scans; it++) {
        trk_status st = chain_step(h, &m, &c[cur], &c[1 - cur], &loss);
        if (st == TRK_E_DIVERGED) { /* lost with certainty at this scan */
            loss = 1;
            if (!isfinite(median)) median = (trk_real)it;
            if (horizon >= it) res->lost_by_horizon = 1;
            fill_held(h, &c[cur], loss, res);
            res->mean_life_scans = sum_s;
            res->median_life_scans = median;
            res->iterations = it;
            return TRK_OK;
        }
        if (st != TRK_OK) return st;
        log_s += trk_log1p(-loss);
        const trk_real s_k = trk_exp(log_s);
        sum_s += s_k;
        if (!isfinite(median) && s_k <= TRK_REAL_C(0.5)) median = (trk_real)it;
        if (it < horizon) res->mean_life_horizon += s_k;
        if (it == horizon) res->lost_by_horizon = -trk_expm1(log_s);
        fill_held(h, &c[1 - cur], loss, res);
        res->iterations = it;
        const trk_real scale = max_abs(n, res->p_held);
        trk_real change = chain_change(ml, n, &c[cur], &c[1 - cur], scale > 0 ? scale : 1);
        if (loss > 0 && loss_prev >= 0) {
            const trk_real dl = trk_fabs(loss - loss_prev) / loss;
            if (dl > change) change = dl;
        }
        loss_prev = loss;
        cur = 1 - cur;
        if (s_k < TRK_REAL_C(1e-15) * sum_s) { /* the rest of the sum is negligible */
            if (horizon > it) res->lost_by_horizon = -trk_expm1(log_s);
            res->mean_life_scans = sum_s;
            res->median_life_scans = median;
            return TRK_OK;
        }
        if (trk_i_fixed_point_done(&fp, change, 1, pr->rel_tol)) {
            /* geometric tail: S(k + j) = S(k) (1 - p)^j */
            res->converged = 1;
            horizon_tail(horizon, it, log_s, loss, res);
            if (!(loss > 0)) {
                res->mean_life_scans = res->median_life_scans = (trk_real)INFINITY;
                return TRK_OK;
            }
            res->mean_life_scans = sum_s + s_k * (1 - loss) / loss;
            if (!isfinite(median))
                median = (trk_real)it - trk_floor(-trk_log(TRK_REAL_C(0.5) / s_k) / trk_log1p(-loss));
            res->median_life_scans = median;
            return TRK_OK;
        }
    }
    res->mean_life_scans = res->median_life_scans = (trk_real)INFINITY;
    return TRK_E_DIVERGED;
}
