/* mre.c - modified Riccati equation, steady-state RMSE and TOC optimum
 * (trk/mre.h; Brekke eqs 27, 35, Sec. V-C; docs/conventions.md "q2, MRE and CRLB"). */
#include "trk/mre.h"

#include "internal.h"
#include "fixed_point_impl.h"
#include "two_point_impl.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/linalg.h"

#define NXMAX TRK_MRE_MAX_NX

static const trk_real h1[2] = {1, 0}; /* nz = 1: H = [1, 0] */

static int finite_all(int n, const trk_real *v)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

trk_status trk_mre_init(struct trk_mre *m, const struct trk_mre_params *pr)
{
    if (!m || !pr) return TRK_E_ARG;
    if (pr->nz != 1 && pr->nz != 2) return TRK_E_ARG;
    if (pr->max_iter < 0) return TRK_E_ARG;
    if (!isfinite(pr->dt_s) || !isfinite(pr->q_m2_per_s3) || !isfinite(pr->r_m2) ||
        !isfinite(pr->gate_prob) || !isfinite(pr->clutter_density) || !isfinite(pr->rel_tol) ||
        !isfinite(pr->max_pos_var_m2))
        return TRK_E_NAN;
    if (!(pr->dt_s > 0) || !(pr->q_m2_per_s3 > 0) || !(pr->r_m2 > 0)) return TRK_E_RANGE;
    if (!(pr->clutter_density >= 0) || !(pr->rel_tol >= 0) || !(pr->max_pos_var_m2 >= 0))
        return TRK_E_RANGE;
    if (!pr->q2_fn) {
        if (!isfinite(pr->q2)) return TRK_E_NAN;
        if (!(pr->q2 > 0 && pr->q2 <= 1)) return TRK_E_RANGE;
    }
    trk_real gamma = pr->gate_gamma;
    if (!isfinite(gamma)) return TRK_E_NAN;
    if (gamma < 0) return TRK_E_RANGE;
    if (gamma == 0) {
        trk_status st = trk_gate_gamma(pr->nz, pr->gate_prob, &gamma);
        if (st != TRK_OK) return st;
    }

    m->params = *pr;
    if (m->params.max_iter == 0) m->params.max_iter = 100000;
    if (m->params.rel_tol == 0) m->params.rel_tol = 64 * TRK_REAL_EPS;
    m->nx = 2 * pr->nz;
    m->gamma = gamma;
    /* the CV model of each coordinate (nz = 1: [x, vx]; nz = 2: [x, vx, y, vy]) */
    TRK_CHECKED(trk_cv_model(pr->nz, pr->dt_s, pr->q_m2_per_s3, m->f, m->q));
    return TRK_OK;
}

void trk_mre_initial_cov(const struct trk_mre *m, trk_real *p)
{
    trk_i_two_point_cov(m->params.nz, m->params.r_m2, m->params.dt_s, p);
}

trk_status trk_mre_step(const struct trk_mre *m, trk_real *p, struct trk_mre_step_info *info)
{
    trk_real pp[NXMAX * NXMAX], pc[NXMAX * NXMAX], k[NXMAX * 2];
    trk_real x[NXMAX] = {0, 0, 0, 0}, r[4];
    struct trk_innovation inn;
    if (!m || !p) return TRK_E_ARG;
    const int nx = m->nx, nz = m->params.nz;
    const trk_real *h = nz == 2 ? trk_cv2_h : h1;
    for (int i = 0; i < nx * nx; i++) pp[i] = p[i];
    for (int i = 0; i < nz * nz; i++) r[i] = 0;
    for (int i = 0; i < nz; i++) r[i * nz + i] = m->params.r_m2;

    /* P- = F P F' + Q, S = H P- H' + R (Brekke eq 27) */
    trk_status st = trk_kalman_predict(nx, m->f, m->q, x, pp);
    if (st != TRK_OK) return st;
    st = trk_kalman_innovation(nx, nz, h, r, x, pp, &inn);
    if (st != TRK_OK) return st;
    const trk_real lambda_vg = m->params.clutter_density * trk_gate_volume_inn(&inn, m->gamma);
    trk_real q2 = m->params.q2;
    if (m->params.q2_fn) {
        st = m->params.q2_fn(m->params.q2_ctx, lambda_vg, &q2);
        if (st != TRK_OK) return st;
    }
    if (!isfinite(q2)) return TRK_E_NAN;
    if (!(q2 >= 0 && q2 <= 1)) return TRK_E_RANGE; /* q2 = 0: no information (a grid may hold it) */

    /* P = P- - q2 K S K' = (1 - q2) P- + q2 Pc, Pc in Joseph form (SPD) */
    trk_kalman_gain(nx, nz, h, pp, &inn, k);
    trk_kalman_joseph(nx, nz, h, r, k, pp, pc);
    for (int i = 0; i < nx * nx; i++) pc[i] = (1 - q2) * pp[i] + q2 * pc[i];
    trk_mat_symmetrize(nx, pc);
    if (!finite_all(nx * nx, pc)) return TRK_E_NAN;
    for (int i = 0; i < nx * nx; i++) p[i] = pc[i];
    if (info) {
        for (int i = 0; i < nz * nz; i++) info->s[i] = inn.s[i];
        info->lambda_vg = lambda_vg;
        info->q2 = q2;
    }
    return TRK_OK;
}

trk_real trk_mre_rmse(int nz, const trk_real *p)
{
    if (!p) return (trk_real)NAN;
    if (nz == 2) return trk_sqrt(p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)]);
    if (nz == 1) return trk_sqrt(p[0]);
    return (trk_real)NAN;
}

static trk_real pos_var(int nz, const trk_real *p) { return nz == 2 ? p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)] : p[0]; }

static void fill_result(const struct trk_mre *m, const trk_real *p, const struct trk_mre_step_info *in,
                        int it, struct trk_mre_result *res)
{
    res->nx = m->nx;
    for (int i = 0; i < m->nx * m->nx; i++) res->p[i] = p[i];
    for (int i = m->nx * m->nx; i < NXMAX * NXMAX; i++) res->p[i] = 0;
    for (int i = 0; i < 4; i++) res->s[i] = i < m->params.nz * m->params.nz ? in->s[i] : 0;
    res->lambda_vg = in->lambda_vg;
    res->q2 = in->q2;
    res->rmse_m = trk_mre_rmse(m->params.nz, p);
    res->iterations = it;
}

trk_status trk_mre_steady_state(const struct trk_mre *m, const trk_real *p0,
                                struct trk_mre_result *res)
{
    trk_real p[NXMAX * NXMAX], prev[NXMAX * NXMAX];
    struct trk_mre_step_info info = {{0, 0, 0, 0}, 0, 0};
    if (!m || !res) return TRK_E_ARG;
    const int nx = m->nx, nz = m->params.nz;
    if (p0) {
        if (!finite_all(nx * nx, p0)) return TRK_E_NAN;
        int zero = 1;
        for (int i = 0; i < nx * nx; i++) {
            p[i] = p0[i];
            if (p[i] != 0) zero = 0;
        }
        trk_real l[NXMAX * NXMAX];
        if (!zero && trk_chol(nx, p, l) != TRK_OK) return TRK_E_NOT_SPD; /* P_0 = 0: P_1- = Q */
    } else {
        trk_mre_initial_cov(m, p);
    }
    fill_result(m, p, &info, 0, res);
    /* Divergence: the position variance above `soft` while its growth keeps
     * accelerating for 20 steps, or above 1e8 soft at all. soft defaults to
     * 1e4 times the largest of the measurement variance, the one-step
     * process-noise position variance and the initial position variance. */
    const trk_real t = m->params.dt_s, fnz = (trk_real)nz;
    trk_real pv_scale = fnz * m->params.r_m2;
    const trk_real q_pos = fnz * m->params.q_m2_per_s3 * t * t * t / 3;
    if (q_pos > pv_scale) pv_scale = q_pos;
    if (pos_var(nz, p) > pv_scale) pv_scale = pos_var(nz, p);
    const trk_real soft = m->params.max_pos_var_m2 > 0 ? m->params.max_pos_var_m2 : TRK_REAL_C(1e4) * pv_scale;
    const trk_real hard = TRK_REAL_C(1e8) * soft;
    trk_real pv_prev = pos_var(nz, p), d_prev = 0;
    int accel = 0;
    struct trk_i_fixed_point fp; /* stopping rule: fixed_point_impl.h */
    trk_i_fixed_point_init(&fp);
    for (int it = 1; it <= m->params.max_iter; it++) {
        for (int i = 0; i < nx * nx; i++) prev[i] = p[i];
        trk_status st = trk_mre_step(m, p, &info);
        if (st == TRK_E_NAN) {
            res->rmse_m = (trk_real)INFINITY;
            return TRK_E_DIVERGED;
        }
        if (st != TRK_OK) return st; /* res: last good iterate */
        fill_result(m, p, &info, it, res);
        const trk_real pv = pos_var(nz, p), dpv = pv - pv_prev;
        accel = (dpv > 0 && dpv >= d_prev) ? accel + 1 : 0;
        pv_prev = pv;
        d_prev = dpv;
        if (!(pv <= hard) || (pv > soft && accel >= 20)) {
            res->rmse_m = (trk_real)INFINITY;
            return TRK_E_DIVERGED;
        }
        trk_real change = 0, scale = 0;
        for (int i = 0; i < nx * nx; i++) {
            trk_real d = trk_fabs(p[i] - prev[i]), a = trk_fabs(p[i]);
            if (d > change) change = d;
            if (a > scale) scale = a;
        }
        if (trk_i_fixed_point_done(&fp, change, scale, m->params.rel_tol)) {
            /* S, lambda_vg and q2 of the steady state itself */
            for (int i = 0; i < nx * nx; i++) prev[i] = p[i];
            st = trk_mre_step(m, prev, &info);
            if (st != TRK_OK) return st;
            fill_result(m, p, &info, it, res);
            return TRK_OK;
        }
    }
    res->rmse_m = (trk_real)INFINITY;
    return TRK_E_DIVERGED;
}
