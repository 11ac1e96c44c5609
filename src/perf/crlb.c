/* crlb.c - CRLB information recursion with q2 (trk/crlb.h; Willett eq 37). */
#include "trk/crlb.h"

#include "internal.h"
#include "fixed_point_impl.h"
#include "two_point_impl.h"
#include "trk/kalman.h"
#include "trk/linalg.h"

#define NXMAX TRK_CRLB_MAX_NX

static int finite_all(int n, const trk_real *v)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* ainv = A^-1 for a symmetric positive definite A (n <= 4), symmetrised. */
static trk_status spd_inverse(int n, const trk_real *a, trk_real *ainv)
{
    trk_real l[NXMAX * NXMAX], col[NXMAX];
    if (trk_chol(n, a, l) != TRK_OK) return TRK_E_NOT_SPD;
    for (int j = 0; j < n; j++) {
        for (int i = 0; i < n; i++) col[i] = i == j;
        trk_chol_solve(n, l, col, col);
        for (int i = 0; i < n; i++) ainv[i * n + j] = col[i];
    }
    trk_mat_symmetrize(n, ainv);
    return TRK_OK;
}

trk_status trk_crlb_init(struct trk_crlb *c, const struct trk_crlb_params *pr)
{
    if (!c || !pr) return TRK_E_ARG;
    if (pr->nz != 1 && pr->nz != 2) return TRK_E_ARG;
    if (pr->max_iter < 0) return TRK_E_ARG;
    if (!isfinite(pr->dt_s) || !isfinite(pr->q_m2_per_s3) || !isfinite(pr->r_m2) ||
        !isfinite(pr->q2) || !isfinite(pr->rel_tol))
        return TRK_E_NAN;
    if (!(pr->dt_s > 0) || !(pr->q_m2_per_s3 > 0) || !(pr->r_m2 > 0)) return TRK_E_RANGE;
    if (!(pr->q2 > 0 && pr->q2 <= 1) || !(pr->rel_tol >= 0)) return TRK_E_RANGE;
    c->params = *pr;
    if (c->params.max_iter == 0) c->params.max_iter = 100000;
    if (c->params.rel_tol == 0) c->params.rel_tol = 64 * TRK_REAL_EPS;
    const int nx = 2 * pr->nz;
    c->nx = nx;
    /* the CV model of each coordinate (nz = 1: [x, vx]; nz = 2: [x, vx, y, vy]) */
    TRK_CHECKED(trk_cv_model(pr->nz, pr->dt_s, pr->q_m2_per_s3, c->f, c->q));
    /* q2 H' R^-1 H: q2 / r on the position diagonal (Willett eqs 35-36) */
    for (int i = 0; i < nx * nx; i++) c->hrh[i] = 0;
    for (int k = 0; k < pr->nz; k++) c->hrh[(2 * k) * nx + 2 * k] = pr->q2 / pr->r_m2;
    return TRK_OK;
}

trk_status trk_crlb_initial_info(const struct trk_crlb *c, const trk_real *p0, trk_real *j0)
{
    trk_real p[NXMAX * NXMAX];
    if (!c || !j0) return TRK_E_ARG;
    const int nx = c->nx;
    if (p0) {
        if (!finite_all(nx * nx, p0)) return TRK_E_NAN;
        for (int i = 0; i < nx * nx; i++) p[i] = p0[i];
    } else {
        trk_i_two_point_cov(c->params.nz, c->params.r_m2, c->params.dt_s, p);
    }
    return spd_inverse(nx, p, j0);
}

trk_status trk_crlb_step(const struct trk_crlb *c, trk_real *j, trk_real *j_inv)
{
    trk_real a[NXMAX * NXMAX] = {0}, b[NXMAX * NXMAX] = {0}, fa[NXMAX * NXMAX] = {0};
    if (!c || !j) return TRK_E_ARG;
    const int nx = c->nx;
    /* J+ = (Q + F J^-1 F')^-1 + q2 H'R^-1 H  (eq 37 by the matrix inversion lemma) */
    trk_status st = spd_inverse(nx, j, a);
    if (st != TRK_OK) return st;
    trk_mat_mul(nx, nx, nx, c->f, a, fa);
    trk_mat_mul_abt(nx, nx, nx, fa, c->f, b);
    for (int i = 0; i < nx * nx; i++) b[i] += c->q[i];
    trk_mat_symmetrize(nx, b);
    st = spd_inverse(nx, b, a);
    if (st != TRK_OK) return st;
    for (int i = 0; i < nx * nx; i++) a[i] += c->hrh[i];
    if (!finite_all(nx * nx, a)) return TRK_E_NAN;
    if (j_inv) {
        st = spd_inverse(nx, a, b);
        if (st != TRK_OK) return st;
        if (!finite_all(nx * nx, b)) return TRK_E_NAN;
        for (int i = 0; i < nx * nx; i++) j_inv[i] = b[i];
    }
    for (int i = 0; i < nx * nx; i++) j[i] = a[i];
    return TRK_OK;
}

trk_status trk_crlb_steady_state(const struct trk_crlb *c, const trk_real *j0,
                                 struct trk_crlb_result *res)
{
    trk_real j[NXMAX * NXMAX], ji[NXMAX * NXMAX], prev[NXMAX * NXMAX];
    if (!c || !res) return TRK_E_ARG;
    const int nx = c->nx;
    trk_status st;
    if (j0) {
        if (!finite_all(nx * nx, j0)) return TRK_E_NAN;
        for (int i = 0; i < nx * nx; i++) j[i] = j0[i];
    } else {
        st = trk_crlb_initial_info(c, NULL, j);
        if (st != TRK_OK) return st;
    }
    st = spd_inverse(nx, j, prev);
    if (st != TRK_OK) return st;
    res->nx = nx;
    struct trk_i_fixed_point fp; /* stopping rule: fixed_point_impl.h */
    trk_i_fixed_point_init(&fp);
    for (int it = 1; it <= c->params.max_iter; it++) {
        st = trk_crlb_step(c, j, ji);
        if (st == TRK_E_NAN) return TRK_E_DIVERGED;
        if (st != TRK_OK) return st;
        trk_real change = 0, scale = 0;
        for (int i = 0; i < nx * nx; i++) {
            trk_real d = trk_fabs(ji[i] - prev[i]), m = trk_fabs(ji[i]);
            if (d > change) change = d;
            if (m > scale) scale = m;
            prev[i] = ji[i];
        }
        if (trk_i_fixed_point_done(&fp, change, scale, c->params.rel_tol)) {
            for (int i = 0; i < NXMAX * NXMAX; i++) {
                res->j[i] = i < nx * nx ? j[i] : 0;
                res->j_inv[i] = i < nx * nx ? ji[i] : 0;
            }
            res->pos_rmse_m = trk_sqrt(c->params.nz == 2 ? ji[0] + ji[10] : ji[0]);
            res->iterations = it;
            return TRK_OK;
        }
    }
    return TRK_E_DIVERGED;
}
