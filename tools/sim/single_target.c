/* single_target.c - single-target Monte Carlo runs (single_target.h). */
#include "errmsg.h"
#include "single_target.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "rng.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/table.h"

/* The CV state [x, vx, y, vy] and its matrices by name (trk/kalman.h); per
 * axis a (0: x, 1: y) the position POS[a] and velocity VEL[a]. */
#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define ZX TRK_CV2_ZX
#define ZY TRK_CV2_ZY
#define P(i, j) TRK_CV2_P(i, j)
#define S(i, j) TRK_CV2_S(i, j)
static const int POS[2] = {X, Y}, VEL[2] = {VX, VY};

/* ---------------------------------------------------------------- amplitude model */

int st_amp_init(struct st_amp *a, int model, double nu, double snr_db, double pfa, int grid,
                unsigned size, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    a->model = model;
    a->snr_db = snr_db;
    a->pfa = pfa;
    if (!(pfa > 0 && pfa < 1) || !isfinite(snr_db)) {
        snprintf(err, errlen, "amplitude model: pfa must be in (0, 1) and snr_db finite");
        return -1;
    }
    if (model == TRK_AMP_RAYLEIGH) {
        trk_status st = trk_amplitude_init_rayleigh(&a->m, 1, (trk_real)snr_db, (trk_real)pfa);
        if (st != TRK_OK) {
            snprintf(err, errlen, "Rayleigh model (snr %g dB, pfa %g): %s", snr_db, pfa, ERRMSG_STATUS(st));
            return -1;
        }
    } else if (model == TRK_AMP_K) {
        struct amp_table_opts o;
        amp_table_opts_init(&o, TRK_AMP_K, nu, snr_db, pfa);
        o.grid = grid ? grid : TRK_AMP_GRID_UNIFORM;
        o.size = size;
        struct amp_table_result r;
        if (amp_table_model(&o, &a->m, &r, err, errlen) != 0) return -1;
        a->table = r.bytes;
        a->nu = nu;
    } else {
        snprintf(err, errlen, "amplitude model must be Rayleigh or K");
        return -1;
    }
    a->pd = (double)trk_amplitude_pd(&a->m);
    a->threshold = (double)trk_amplitude_threshold(&a->m);
    return 0;
}

void st_amp_free(struct st_amp *a)
{
    free(a->table);
    a->table = NULL;
}

/* ---------------------------------------------------------------- PDA runs */

void st_params_brekke(struct st_params *p)
{
    memset(p, 0, sizeof *p);
    p->dt_s = 1;
    p->q_m2_per_s3 = 0.0125 * 0.0125;
    p->r_m2 = 1.0 / 12;
    p->gate_gamma = 36;
    p->lambda_per_m2 = 0;
    p->pd = 1;
    p->amp = NULL;
    p->n_scans = 300;
    p->init = ST_INIT_TWOPOINT;
    p->speed_mps = 1;
    p->loss = ST_LOSS_BREKKE;
    p->c1_m = 5;
    p->c2_m = 15;
    p->thresh_m = 4;
    p->count = 3;
    p->tile_m = 0;
    p->seed = 1;
}

/* Per-axis Cholesky factor [l00, l10, l11] of the 2x2 block [[a, b], [b, c]]. */
static int chol2(double a, double b, double c, double l[3])
{
    if (!(a > 0)) return -1;
    l[0] = sqrt(a);
    l[1] = b / l[0];
    const double d = c - l[1] * l[1];
    l[2] = d > 0 ? sqrt(d) : 0;
    return 0;
}

/* Steady state of the clutter-free Kalman filter (P_D = 1), by iterating the
 * library's prediction and update. */
static int kalman_steady(const struct st_params *p, const trk_real r[4], double out[16])
{
    trk_real x[4] = {0, 0, 0, 0}, pm[16] = {0}, z[2] = {0, 0};
    const double r0 = p->r_m2, t = p->dt_s;
    for (int a = 0; a < 2; a++) { /* two-point start */
        pm[P(POS[a], POS[a])] = (trk_real)r0;
        pm[P(POS[a], VEL[a])] = pm[P(VEL[a], POS[a])] = (trk_real)(r0 / t);
        pm[P(VEL[a], VEL[a])] = (trk_real)(2 * r0 / (t * t));
    }
    for (int it = 0; it < 100000; it++) {
        trk_real prev = pm[P(X, X)];
        if (trk_cv2_predict((trk_real)t, (trk_real)p->q_m2_per_s3, x, pm) != TRK_OK) return -1;
        if (trk_kalman_update(4, 2, trk_cv2_h, r, z, x, pm) != TRK_OK) return -1;
        if (it > 10 && fabs((double)(pm[P(X, X)] - prev)) <= 1e-15 * (double)pm[P(X, X)]) break;
    }
    for (int i = 0; i < 16; i++) out[i] = (double)pm[i];
    return 0;
}

int st_model_init(struct st_model *m, const struct st_params *p, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    if (!(p->dt_s > 0) || !(p->q_m2_per_s3 >= 0) || !(p->r_m2 > 0) || !(p->gate_gamma > 0) ||
        !(p->lambda_per_m2 >= 0) || !isfinite(p->dt_s) || !isfinite(p->q_m2_per_s3) ||
        !isfinite(p->r_m2) || !isfinite(p->gate_gamma) || !isfinite(p->lambda_per_m2)) {
        snprintf(err, errlen, "model: T, r, gamma must be > 0, q and lambda >= 0 (finite)");
        return -1;
    }
    if (p->n_scans < 1 || p->n_scans > 2147483647L) {
        snprintf(err, errlen, "scans must be in 1 .. 2^31-1");
        return -1;
    }
    if (p->loss == ST_LOSS_BREKKE ? !(p->c1_m > 0 && p->c2_m >= p->c1_m)
                                  : !(p->thresh_m > 0 && p->count >= 1)) {
        snprintf(err, errlen, "loss rule: need 0 < c1 <= c2 (brekke) or thresh > 0, count >= 1 (willett)");
        return -1;
    }
    if (p->loss != ST_LOSS_BREKKE && p->loss != ST_LOSS_WILLETT) {
        snprintf(err, errlen, "unknown loss rule");
        return -1;
    }
    if (p->texture != ST_TEXTURE_CELL &&
        (p->texture != ST_TEXTURE_SCAN || !p->amp || p->amp->model != TRK_AMP_K)) {
        snprintf(err, errlen, "texture per scan needs a K amplitude model");
        return -1;
    }
    const struct st_gate_cap *gc = &p->gate_cap;
    if (gc->mode == ST_GATE_TRUNCATE   ? !(gc->n >= 0 && gc->n <= TRK_MAX_DETECTIONS)
        : gc->mode == ST_GATE_COUNT ? !(gc->n >= 1 && gc->n <= TRK_MAX_DETECTIONS)
                                    : gc->mode != ST_GATE_LOST || !(gc->lambda_vg > 0 && isfinite(gc->lambda_vg))) {
        snprintf(err, errlen,
                 "gate cap: truncate to 1..%d detections, lost above a lambda V_G > 0, or lost at a count 1..%d",
                 TRK_MAX_DETECTIONS, TRK_MAX_DETECTIONS);
        return -1;
    }
    if (p->init != ST_INIT_TWOPOINT && p->init != ST_INIT_STEADY) {
        snprintf(err, errlen, "unknown initialisation");
        return -1;
    }
    m->p = *p;
    m->pd = p->amp ? (double)trk_amplitude_pd(p->amp) : p->pd;
    if (!(m->pd > 0 && m->pd <= 1)) {
        snprintf(err, errlen, "detection probability %g outside (0, 1]", m->pd);
        return -1;
    }
    /* P_G of the gate: 1 - exp(-gamma/2) (nz = 2); in float it may round to
     * 1, then the largest P_G below 1 */
    trk_real pg = (trk_real)(-expm1(-p->gate_gamma / 2));
    if (!(pg < 1)) pg = nextafterf(1.0f, 0.0f);
    m->gate_prob = (double)pg;
    struct trk_pda_params pp = {2, (trk_real)m->pd, pg, TRK_CLUTTER_PARAMETRIC, (trk_real)p->lambda_per_m2, 1};
    trk_status st = trk_pda_init(&m->pda, &pp);
    if (st != TRK_OK) {
        snprintf(err, errlen, "trk_pda_init: %s", ERRMSG_STATUS(st));
        return -1;
    }
    m->gamma_used = (double)m->pda.gamma;
    m->r[S(ZX, ZX)] = m->r[S(ZY, ZY)] = (trk_real)p->r_m2;
    m->r[S(ZX, ZY)] = m->r[S(ZY, ZX)] = 0;
    const double r0 = p->r_m2, t = p->dt_s;
    if (p->init == ST_INIT_TWOPOINT) {
        for (int a = 0; a < 2; a++) {
            m->p0[P(POS[a], POS[a])] = r0;
            m->p0[P(POS[a], VEL[a])] = m->p0[P(VEL[a], POS[a])] = r0 / t;
            m->p0[P(VEL[a], VEL[a])] = 2 * r0 / (t * t);
        }
    } else if (kalman_steady(p, m->r, m->p0) != 0) {
        snprintf(err, errlen, "steady-state Kalman covariance failed");
        return -1;
    }
    if (chol2(m->p0[P(X, X)], m->p0[P(X, VX)], m->p0[P(VX, VX)], m->p0_chol) != 0) {
        snprintf(err, errlen, "initial covariance not positive definite");
        return -1;
    }
    trk_real q[16];
    trk_cv2_process_noise((trk_real)t, (trk_real)p->q_m2_per_s3, q);
    if (p->q_m2_per_s3 > 0) chol2((double)q[P(X, X)], (double)q[P(X, VX)], (double)q[P(VX, VX)], m->q_chol);
    if (scen_field_init(&m->field, p->seed, p->lambda_per_m2, p->tile_m) != 0) {
        snprintf(err, errlen, "clutter field: bad density or tile");
        return -1;
    }
    return 0;
}

void st_ws_free(struct st_ws *ws)
{
    free(ws->pts);
    free(ws->cand);
    memset(ws, 0, sizeof *ws);
}

static int cand_push(struct st_ws *ws, size_t *n, double d2, double x, double y, double x_amp, int target)
{
    if (*n == ws->cand_cap) {
        const size_t cap = ws->cand_cap ? 2 * ws->cand_cap : 64;
        struct st_cand *nc = realloc(ws->cand, cap * sizeof *nc);
        if (!nc) return -1;
        ws->cand = nc;
        ws->cand_cap = cap;
    }
    ws->cand[(*n)++] = (struct st_cand){d2, x, y, x_amp, target};
    return 0;
}

/* Strict order of candidates: d2, then the target first (ties are exact
 * coincidences; any fixed rule keeps runs reproducible). */
static int cand_less(const struct st_cand *x, const struct st_cand *y)
{
    return x->d2 < y->d2 || (x->d2 == y->d2 && x->target > y->target);
}

/* Move the k smallest candidates to c[0..k) (quickselect, median-of-three
 * pivot; deterministic). */
static void cand_select(struct st_cand *c, size_t n, size_t k)
{
    size_t lo = 0, hi = n - 1;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        struct st_cand t;
        if (cand_less(&c[mid], &c[lo])) t = c[mid], c[mid] = c[lo], c[lo] = t;
        if (cand_less(&c[hi], &c[lo])) t = c[hi], c[hi] = c[lo], c[lo] = t;
        if (cand_less(&c[hi], &c[mid])) t = c[hi], c[hi] = c[mid], c[mid] = t;
        const struct st_cand piv = c[mid];
        size_t i = lo, j = hi;
        while (i <= j) {
            while (cand_less(&c[i], &piv)) i++;
            while (cand_less(&piv, &c[j])) j--;
            if (i <= j) {
                t = c[i], c[i] = c[j], c[j] = t;
                i++;
                if (j == 0) break;
                j--;
            }
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return;
    }
}

/* Gamma(shape a, scale 1) (Marsaglia and Tsang 2000; a < 1 by a U^(1/a) boost). */
static double gamma_draw(struct rng *r, double a)
{
    double boost = 1;
    if (a < 1) {
        boost = pow(rng_uniform(r), 1 / a);
        a += 1;
    }
    const double d = a - 1.0 / 3, c = 1 / sqrt(9 * d);
    for (;;) {
        double z, v;
        do {
            z = rng_normal(r);
            v = 1 + c * z;
        } while (v <= 0);
        v = v * v * v;
        const double u = rng_uniform(r);
        if (u < 1 - 0.0331 * z * z * z * z || log(u) < 0.5 * z * z + d * (1 - v + log(v))) return boost * d * v;
    }
}

/* The run's stream for scan k (k = 0: the initial estimate). */
static void run_stream(const struct st_model *m, uint32_t run, uint32_t k, struct rng *r)
{
    rng_init(r, m->p.seed, (uint64_t)run << 32 | k);
}

int st_run(const struct st_model *m, struct st_ws *ws, uint32_t run, int ai, long from_scan,
           double *err_by_scan, struct st_result *res)
{
    memset(res, 0, sizeof *res);
    if (!m || !ws || (ai && !m->p.amp)) return -1;
    const struct st_params *p = &m->p;
    const trk_real dt = (trk_real)p->dt_s, qq = (trk_real)p->q_m2_per_s3, gamma = m->pda.gamma;
    const double sg = sqrt(p->r_m2);
    struct rng r;
    double xt[4] = {0};
    trk_real x[4], pm[16];
    xt[VX] = p->speed_mps;
    run_stream(m, run, 0, &r);
    for (int ax = 0; ax < 2; ax++) {
        const double z1 = rng_normal(&r), z2 = rng_normal(&r);
        x[POS[ax]] = (trk_real)(xt[POS[ax]] + m->p0_chol[0] * z1);
        x[VEL[ax]] = (trk_real)(xt[VEL[ax]] + m->p0_chol[1] * z1 + m->p0_chol[2] * z2);
    }
    for (int i = 0; i < 16; i++) pm[i] = (trk_real)m->p0[i];
    trk_real z[2 * TRK_MAX_DETECTIONS], llr[TRK_MAX_DETECTIONS], beta[TRK_MAX_DETECTIONS];
    int in_exc = 0, run_over = 0;
    long exc_start = 0;
    for (long k = 1; k <= p->n_scans; k++) {
        run_stream(m, run, (uint32_t)k, &r);
        /* truth: x_k = F x_{k-1} + w */
        for (int ax = 0; ax < 2; ax++) {
            const double z1 = rng_normal(&r), z2 = rng_normal(&r);
            xt[POS[ax]] += p->dt_s * xt[VEL[ax]] + m->q_chol[0] * z1;
            xt[VEL[ax]] += m->q_chol[1] * z1 + m->q_chol[2] * z2;
        }
        /* the target's detection: position and amplitude variate */
        const double u_det = rng_uniform(&r);
        const double zx = xt[X] + sg * rng_normal(&r), zy = xt[Y] + sg * rng_normal(&r);
        const double x_amp = rng_exp(&r);
        /* the scan's clutter: density and amplitude laws */
        double lambda_k = p->lambda_per_m2, pd_k = m->pd;
        const struct trk_amplitude *amp_c = p->amp, *amp_t = p->amp;
        int src_t = TRK_AMP_TARGET;
        struct trk_amplitude ray_c, ray_t;
        if (p->texture == ST_TEXTURE_SCAN) { /* eta ~ Gamma(nu, P / nu): see single_target.h */
            const double cp = (double)p->amp->clutter_power, nu = (double)p->amp->nu;
            const double eta = cp * gamma_draw(&r, nu) / nu, t = (double)p->amp->threshold;
            const double d = cp * pow(10.0, (double)p->amp->snr_db / 10);
            const double pfa_k = exp(-t * t / eta), pfa_t = exp(-t * t / (eta + d));
            pd_k = pfa_t;
            lambda_k = (trk_real)pfa_k > 0 ? p->lambda_per_m2 * pfa_k / (double)p->amp->pfa : 0;
            if (lambda_k > 0 && trk_amplitude_init_rayleigh(&ray_c, (trk_real)eta, -100, (trk_real)pfa_k) != TRK_OK)
                lambda_k = 0;
            if (trk_amplitude_init_rayleigh(&ray_t, (trk_real)(eta + d), -100, (trk_real)pfa_t) != TRK_OK) {
                res->failed = 1;
                res->status = (int)TRK_E_RANGE;
                break;
            }
            amp_c = &ray_c;
            amp_t = &ray_t;
            src_t = TRK_AMP_CLUTTER; /* ray_t's "clutter" law is Rayleigh(eta + d) above t */
        }
        const int det = u_det < pd_k;
        /* track: predict, innovation, gate box */
        trk_status st = trk_cv2_predict(dt, qq, x, pm);
        struct trk_innovation inn;
        if (st == TRK_OK) st = trk_kalman_innovation(4, 2, trk_cv2_h, m->r, x, pm, &inn);
        if (st != TRK_OK) {
            res->failed = 1;
            res->status = (int)st;
            break;
        }
        if (p->gate_cap.mode == ST_GATE_LOST &&
            p->lambda_per_m2 * (double)trk_gate_volume_inn(&inn, gamma) > p->gate_cap.lambda_vg) {
            res->lost = res->gate_lost = 1; /* the runaway-gate rule: lost here */
            res->lost_scan = k;
            break;
        }
        const size_t n_cap = p->gate_cap.mode == ST_GATE_TRUNCATE && p->gate_cap.n > 0 ? (size_t)p->gate_cap.n
                                                                                        : TRK_MAX_DETECTIONS;
        const double cx = (double)inn.z_pred[ZX], cy = (double)inn.z_pred[ZY];
        /* gated detections: the target's (if detected) and the clutter of the
         * gate's bounding box [c - w, c + w) with d2 <= gamma. The library
         * takes TRK_MAX_DETECTIONS (n_cap: the gate cap's n, at most that): a
         * gate holding more passes its nearest (smallest d2). To find those without drawing the whole gate, the
         * first pass looks inside d2 <= gq, an ellipse expected to hold twice
         * the capacity; when it holds fewer than the capacity, the whole gate
         * is taken (the same result as one pass over the gate, cheaper). */
        double gq = 2.0 * (double)n_cap / (lambda_k * (double)trk_gate_volume_inn(&inn, 1));
        if (!(gq < (double)gamma)) gq = (double)gamma;
        trk_real nu_t[2] = {(trk_real)(zx - cx), (trk_real)(zy - cy)};
        const double d2_t = det ? (double)trk_gate_d2(&inn, nu_t) : INFINITY;
        if (det) res->detections++;
        size_t nca = 0;
        int early = 0;
        for (int pass = 0; pass < 2 && st == TRK_OK; pass++) {
            const double g = pass ? (double)gamma : gq;
            const double wx = sqrt(g * (double)inn.s[S(ZX, ZX)]), wy = sqrt(g * (double)inn.s[S(ZY, ZY)]);
            nca = 0;
            if (det && (pass ? trk_gate_inside((trk_real)d2_t, gamma) : d2_t <= g) &&
                cand_push(ws, &nca, d2_t, zx, zy, x_amp, 1) != 0)
                return -1;
            size_t nc = scen_field_window_at(&m->field, lambda_k, run, (uint32_t)k, cx - wx, cx + wx, cy - wy,
                                             cy + wy, ws->pts, ws->cap);
            if (nc != SIZE_MAX && nc > ws->cap) {
                size_t cap = nc + nc / 2 + 16;
                struct scen_field_point *np = realloc(ws->pts, cap * sizeof *np);
                if (!np) return -1;
                ws->pts = np;
                ws->cap = cap;
                nc = scen_field_window_at(&m->field, lambda_k, run, (uint32_t)k, cx - wx, cx + wx, cy - wy, cy + wy,
                                          ws->pts, ws->cap);
            }
            if (nc == SIZE_MAX) {
                st = TRK_E_CAPACITY;
                break;
            }
            for (size_t i = 0; i < nc; i++) {
                const struct scen_field_point *c = &ws->pts[i];
                trk_real nu[2] = {(trk_real)(c->x_m - cx), (trk_real)(c->y_m - cy)};
                const trk_real d2 = trk_gate_d2(&inn, nu);
                if (pass ? !trk_gate_inside(d2, gamma) : !((double)d2 <= g)) continue;
                if (cand_push(ws, &nca, (double)d2, c->x_m, c->y_m, -log(c->u), 0) != 0) return -1;
            }
            if (g == (double)gamma) break;
            if (nca >= n_cap) { /* the nearest are all inside d2 <= gq */
                early = 1;
                break;
            }
        }
        if (nca > n_cap || early) {
            if (nca > n_cap) cand_select(ws->cand, nca, n_cap);
            if (nca > n_cap) nca = n_cap;
            res->truncated++;
        }
        size_t m_g = 0;
        for (size_t i = 0; st == TRK_OK && i < nca; i++, m_g++) {
            const struct st_cand *c = &ws->cand[i];
            z[2 * m_g] = (trk_real)c->x_m;
            z[2 * m_g + 1] = (trk_real)c->y_m;
            if (ai) {
                trk_real a;
                st = trk_amplitude_inv_sf(c->target ? amp_t : amp_c, c->target ? src_t : TRK_AMP_CLUTTER,
                                          (trk_real)c->x_amp, &a);
                /* texture per scan: the scan's Rayleigh threshold equals the K
                 * threshold t up to rounding; an amplitude a rounding below t
                 * is t (the K model refuses a < t) */
                const trk_real thr = p->amp->threshold;
                if (st == TRK_OK && a < thr && (double)a >= (double)thr * (1 - 1e-5)) a = thr;
                if (st == TRK_OK) st = trk_amplitude_log_lr(p->amp, a, &llr[m_g]);
            }
        }
        if (st == TRK_OK) /* the library's PDA over the gated set, with the innovation above */
            st = trk_pda_update_inn(&m->pda, 4, trk_cv2_h, m->r, x, pm, &inn, m_g, z, ai ? llr : NULL, beta,
                                    NULL, NULL);
        if (st != TRK_OK) {
            res->failed = 1;
            res->status = (int)st;
            break;
        }
        res->gated += (long)m_g;
        if (p->gate_cap.mode == ST_GATE_COUNT && m_g >= (size_t)p->gate_cap.n) {
            res->lost = res->gate_lost = 1; /* the gate-count rule: lost here */
            res->lost_scan = k;
            res->scans = k;
            break;
        }
        for (size_t i = 0; i < m_g; i++) res->gated_clutter += !ws->cand[i].target;
        res->scans = k;
        const double ex = (double)x[X] - xt[X], ey = (double)x[Y] - xt[Y];
        const double e = sqrt(ex * ex + ey * ey);
        if (err_by_scan) err_by_scan[k - 1] = e;
        if (e > res->max_err_m) res->max_err_m = e;
        if (k >= from_scan) {
            res->sse += e * e;
            res->n_sse++;
        }
        if (p->loss == ST_LOSS_BREKKE) {
            if (!(e <= p->c2_m)) { /* NaN counts as beyond */
                res->lost = res->lost_hard = 1;
                res->lost_scan = k;
                run_over = 1;
            } else if (e > p->c1_m) {
                if (!in_exc) exc_start = k;
                in_exc = 1;
            } else {
                in_exc = 0;
            }
        } else { /* the 1-D criterion on each coordinate */
            if (!(fabs(ex) <= p->thresh_m && fabs(ey) <= p->thresh_m)) {
                if (!in_exc) exc_start = k;
                in_exc++;
                if (in_exc >= p->count) {
                    res->lost = 1;
                    res->lost_scan = exc_start;
                    run_over = 1;
                }
            } else {
                in_exc = 0;
            }
        }
        if (run_over) break;
    }
    if (res->failed) {
        res->lost = 1;
        res->lost_scan = res->scans + 1;
    } else if (!res->lost && p->loss == ST_LOSS_BREKKE && in_exc) {
        res->lost = 1;
        res->lost_scan = exc_start;
    }
    if (err_by_scan)
        for (long k = res->scans + 1; k <= p->n_scans; k++) err_by_scan[k - 1] = NAN;
    return 0;
}

/* ---------------------------------------------------------------- Kennedy null */

void kn_params_kennedy(struct kn_params *p)
{
    memset(p, 0, sizeof *p);
    p->x_min_m = 10e3;
    p->x_max_m = 20e3;
    p->y_min_m = 100e3;
    p->y_max_m = 200e3;
    p->n_peaks = 100;
    p->dt_s = 1;
    p->sigma_x_m = (p->x_max_m - p->x_min_m) / 50;
    p->sigma_y_m = (p->y_max_m - p->y_min_m) / 50;
    p->accel_x = (p->x_max_m - p->x_min_m) / 1000;
    p->accel_y = (p->y_max_m - p->y_min_m) / 1000;
    p->init_vx_sigma = 80;
    p->init_vy_sigma = 1150;
    p->gate_prob = 0.99;
    p->a_min_db = 5;
    p->theta_db = 10;
    p->alpha = 0.01;
    p->kmax = 25;
    p->seed = 1;
}

int kn_model_init(struct kn_model *m, const struct kn_params *p, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    const double area = (p->x_max_m - p->x_min_m) * (p->y_max_m - p->y_min_m);
    if (!(area > 0) || !isfinite(area) || !(p->dt_s > 0) || !(p->sigma_x_m > 0) || !(p->sigma_y_m > 0) ||
        !(p->accel_x >= 0) || !(p->accel_y >= 0) || !(p->init_vx_sigma > 0) || !(p->init_vy_sigma > 0)) {
        snprintf(err, errlen, "Kennedy model: region, T, sigmas must be positive");
        return -1;
    }
    if (p->n_peaks < 2 || p->n_peaks > TRK_MAX_DETECTIONS) {
        snprintf(err, errlen, "peaks per scan must be in 2 .. %d (TRK_MAX_DETECTIONS)", TRK_MAX_DETECTIONS);
        return -1;
    }
    if (!(p->theta_db > p->a_min_db)) {
        snprintf(err, errlen, "theta must exceed a_min");
        return -1;
    }
    m->p = *p;
    m->rho = (double)p->n_peaks / area;
    struct trk_pda_params pp = {2, 1, (trk_real)p->gate_prob, TRK_CLUTTER_PARAMETRIC, (trk_real)m->rho, 1};
    struct trk_clutter_chi2_params cp = {(trk_real)p->alpha, p->kmax};
    struct trk_clutter_amp_params ap = {(trk_real)p->a_min_db, (trk_real)p->alpha, p->kmax};
    trk_status st = trk_pda_init(&m->pda, &pp);
    if (st == TRK_OK) st = trk_clutter_chi2_model_init(&m->chi2, &cp);
    if (st == TRK_OK) st = trk_clutter_amp_model_init(&m->amp, &ap);
    if (st != TRK_OK) {
        snprintf(err, errlen, "Kennedy model refused by the library: %s", ERRMSG_STATUS(st));
        return -1;
    }
    /* Kennedy sec. 3: F CV, Q = diag((s' T^2 / 2)^2, (s' T)^2) per axis */
    const double t = p->dt_s;
    trk_cv2_transition((trk_real)t, m->f);
    memset(m->q, 0, sizeof m->q);
    m->q[P(X, X)] = (trk_real)pow(p->accel_x * t * t / 2, 2);
    m->q[P(VX, VX)] = (trk_real)pow(p->accel_x * t, 2);
    m->q[P(Y, Y)] = (trk_real)pow(p->accel_y * t * t / 2, 2);
    m->q[P(VY, VY)] = (trk_real)pow(p->accel_y * t, 2);
    m->r[S(ZX, ZX)] = (trk_real)(p->sigma_x_m * p->sigma_x_m);
    m->r[S(ZY, ZY)] = (trk_real)(p->sigma_y_m * p->sigma_y_m);
    m->r[S(ZX, ZY)] = m->r[S(ZY, ZX)] = 0;
    return 0;
}

int kn_run(const struct kn_model *m, long n_scans, uint32_t tag, uint32_t run, struct kn_result *res)
{
    memset(res, 0, sizeof *res);
    if (!m || n_scans < 2) return -1;
    const struct kn_params *p = &m->p;
    const long np = p->n_peaks;
    struct rng r;
    rng_init(&r, p->seed, (uint64_t)tag << 32 | run);
    trk_real px[TRK_MAX_DETECTIONS + 1], py[TRK_MAX_DETECTIONS + 1], adb[TRK_MAX_DETECTIONS + 1];
    trk_real z[2 * TRK_MAX_DETECTIONS], beta[TRK_MAX_DETECTIONS], d2[TRK_MAX_DETECTIONS + 1];
    trk_real others[TRK_MAX_DETECTIONS];
    struct trk_clutter_chi2 chi;
    struct trk_clutter_amp amp;
    trk_clutter_chi2_reset(&m->chi2, &chi);
    trk_clutter_amp_reset(&m->amp, &amp);
    trk_real x[4], pm[16] = {0};
    const double wx = p->x_max_m - p->x_min_m, wy = p->y_max_m - p->y_min_m;
    for (long k = 1; k <= n_scans; k++) {
        for (long i = 0; i < np; i++) { /* the scan's peaks (Kennedy: exactly N_s, uniform) */
            px[i] = (trk_real)(p->x_min_m + wx * rng_uniform(&r));
            py[i] = (trk_real)(p->y_min_m + wy * rng_uniform(&r));
            adb[i] = (trk_real)(p->a_min_db + (p->theta_db - p->a_min_db) * rng_exp(&r));
        }
        if (k == 1) { /* initiation on a random peak */
            long j = (long)(rng_uniform(&r) * (double)np);
            if (j >= np) j = np - 1;
            x[X] = px[j];
            x[Y] = py[j];
            x[VX] = x[VY] = 0;
            pm[P(X, X)] = m->r[S(ZX, ZX)];
            pm[P(Y, Y)] = m->r[S(ZY, ZY)];
            pm[P(VX, VX)] = (trk_real)(p->init_vx_sigma * p->init_vx_sigma);
            pm[P(VY, VY)] = (trk_real)(p->init_vy_sigma * p->init_vy_sigma);
            continue;
        }
        struct trk_innovation inn;
        trk_status st = trk_kalman_predict(4, m->f, m->q, x, pm);
        if (st == TRK_OK) st = trk_kalman_innovation(4, 2, trk_cv2_h, m->r, x, pm, &inn);
        if (st != TRK_OK) {
            res->failed = 1;
            res->status = (int)st;
            return 0;
        }
        const double cx = (double)inn.z_pred[ZX], cy = (double)inn.z_pred[ZY];
        if (!p->torus && (cx < p->x_min_m || cx > p->x_max_m || cy < p->y_min_m || cy > p->y_max_m)) res->outside = 1;
        if (p->torus) /* each peak's copy nearest the prediction */
            for (long i = 0; i < np; i++) {
                px[i] = (trk_real)(cx + remainder((double)px[i] - cx, wx));
                py[i] = (trk_real)(cy + remainder((double)py[i] - cy, wy));
            }
        long best = 0;
        size_t m_g = 0;
        for (long i = 0; i < np; i++) {
            trk_real nu[2] = {px[i] - inn.z_pred[ZX], py[i] - inn.z_pred[ZY]};
            d2[i] = trk_gate_d2(&inn, nu);
            if (d2[i] < d2[best]) best = i;
            if (trk_gate_inside(d2[i], m->pda.gamma)) { /* n_peaks <= TRK_MAX_DETECTIONS */
                z[2 * m_g] = px[i];
                z[2 * m_g + 1] = py[i];
                m_g++;
            }
        }
        /* the clutter tests: nearest peak (Kennedy eqs 5-9, 13-15) */
        const trk_real rho_vg = (trk_real)(m->rho * (double)trk_gate_volume_inn(&inn, d2[best]));
        size_t no = 0;
        for (long i = 0; i < np; i++)
            if (i != best) others[no++] = adb[i];
        enum trk_decision d_chi, d_amp;
        st = trk_clutter_chi2_step(&m->chi2, &chi, rho_vg, &d_chi);
        if (st == TRK_OK) st = trk_clutter_amp_step(&m->amp, &amp, adb[best], no, others, &d_amp);
        if (st == TRK_OK) st = trk_pda_update_inn(&m->pda, 4, trk_cv2_h, m->r, x, pm, &inn, m_g, z, NULL, beta, NULL, NULL);
        if (st != TRK_OK) {
            res->failed = 1;
            res->status = (int)st;
            return 0;
        }
    }
    res->chi2_reject = chi.reject;
    res->amp_reject = amp.reject;
    res->chi2_ever = chi.decision == TRK_DECISION_CONFIRM;
    res->amp_ever = amp.decision == TRK_DECISION_CONFIRM;
    res->chi2_p = (double)chi.p_value;
    res->amp_p = (double)amp.p_value;
    return 0;
}
