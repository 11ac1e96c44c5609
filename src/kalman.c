/* kalman.c - linear-Gaussian predict/update and the 2-D CV model
 * (docs/conventions.md "State and covariance layout"; Bar-Shalom's Kalman
 * filter, Joseph form). */
#include "trk/kalman.h"

#define TRK_I_KALMAN_DEFINE /* the external copies of the Kalman kernels in size builds */
#include "kalman_impl.h"

const trk_real trk_cv2_h[TRK_CV2_NZ * TRK_CV2_NX] = {1, 0, 0, 0, 0, 0, 1, 0};

/* F = blkdiag([[1, T], [0, 1]] x n), Q = blkdiag(q [[T^3/3, T^2/2], [T^2/2, T]] x n)
 * (docs/conventions.md "State and covariance layout"); either output may be NULL. */
static void cv_blocks(int n_axes, trk_real t, trk_real qd, trk_real *f, trk_real *q)
{
    const int nx = 2 * n_axes;
    const trk_real t2 = t * t;
    for (int i = 0; i < nx * nx; i++) {
        if (f) f[i] = 0;
        if (q) q[i] = 0;
    }
    for (int a = 0; a < n_axes; a++) {
        const int i = 2 * a;
        if (f) {
            f[i * nx + i] = f[(i + 1) * nx + i + 1] = 1;
            f[i * nx + i + 1] = t;
        }
        if (q) {
            q[i * nx + i] = qd * t2 * t / 3;
            q[i * nx + i + 1] = q[(i + 1) * nx + i] = qd * t2 / 2;
            q[(i + 1) * nx + i + 1] = qd * t;
        }
    }
}

void trk_cv2_transition(trk_real dt_s, trk_real f[TRK_CV2_NX * TRK_CV2_NX])
{
    cv_blocks(2, dt_s, 0, f, NULL);
}

void trk_cv2_process_noise(trk_real dt_s, trk_real q_m2_per_s3, trk_real q[TRK_CV2_NX * TRK_CV2_NX])
{
    cv_blocks(2, dt_s, q_m2_per_s3, NULL, q);
}

trk_status trk_cv_model(int n_axes, trk_real dt_s, trk_real q_m2_per_s3, trk_real *f, trk_real *q)
{
    if ((n_axes != 1 && n_axes != 2) || !f || !q) return TRK_E_ARG;
    cv_blocks(n_axes, dt_s, q_m2_per_s3, f, q);
    return TRK_OK;
}

trk_status trk_cv2_predict(trk_real dt_s, trk_real q_m2_per_s3, trk_real x[TRK_CV2_NX],
                           trk_real p[TRK_CV2_NX * TRK_CV2_NX])
{
    if (!x || !p) return TRK_E_ARG;
    if (!isfinite(dt_s) || !isfinite(q_m2_per_s3)) return TRK_E_NAN;
    trk_i_cv2_predict(dt_s, q_m2_per_s3, x, p);
    return TRK_OK;
}

trk_status trk_cv2_two_point(const trk_real z0[TRK_CV2_NZ], const trk_real r0[TRK_CV2_NZ * TRK_CV2_NZ],
                             const trk_real z1[TRK_CV2_NZ], const trk_real r1[TRK_CV2_NZ * TRK_CV2_NZ], trk_real dt_s,
                             trk_real x[TRK_CV2_NX], trk_real p[TRK_CV2_NX * TRK_CV2_NX])
{
    if (!z0 || !r0 || !z1 || !r1 || !x || !p || !(dt_s > 0)) return TRK_E_ARG;
    static const int pos[TRK_CV2_NZ] = {TRK_CV2_X, TRK_CV2_Y}, vel[TRK_CV2_NZ] = {TRK_CV2_VX, TRK_CV2_VY};
    for (int a = 0; a < TRK_CV2_NZ; a++) {
        x[pos[a]] = z1[a];
        x[vel[a]] = (z1[a] - z0[a]) / dt_s;
        for (int b = 0; b < TRK_CV2_NZ; b++) {
            const trk_real rb = r1[TRK_CV2_S(a, b)];
            p[TRK_CV2_P(pos[a], pos[b])] = rb;
            p[TRK_CV2_P(pos[a], vel[b])] = p[TRK_CV2_P(vel[a], pos[b])] = rb / dt_s;
            p[TRK_CV2_P(vel[a], vel[b])] = (r0[TRK_CV2_S(a, b)] + rb) / (dt_s * dt_s);
        }
    }
    for (int k = 0; k < TRK_CV2_NX; k++)
        if (!isfinite(x[k])) return TRK_E_NAN;
    return trk_i_spd(TRK_CV2_NX, p) == TRK_OK ? TRK_OK : TRK_E_NOT_SPD;
}

static int dims_ok(int nx, int nz)
{
    return nx >= 1 && nx <= TRK_MAX_STATE && nz >= 1 && nz <= TRK_MAX_MEAS && nz <= nx;
}

static int all_finite(int n, const trk_real *v)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

trk_status trk_kalman_predict(int nx, const trk_real *f, const trk_real *q, trk_real *x, trk_real *p)
{
    trk_real xn[TRK_MAX_STATE], pn[TRK_MAX_STATE * TRK_MAX_STATE];
    if (!dims_ok(nx, 1) || !f || !q || !x || !p) return TRK_E_ARG;
    for (int i = 0; i < nx; i++) xn[i] = x[i];
    for (int i = 0; i < nx * nx; i++) pn[i] = p[i];
#if !TRK_SIZE_OPT
    if (nx == TRK_CV2_NX) trk_i_predict(TRK_CV2_NX, f, q, xn, pn); /* unrolled copy (speed) */
    else
#endif
        trk_i_predict(nx, f, q, xn, pn);
    if (!all_finite(nx, xn) || !all_finite(nx * nx, pn)) return TRK_E_NAN;
    for (int i = 0; i < nx; i++) x[i] = xn[i];
    for (int i = 0; i < nx * nx; i++) p[i] = pn[i];
    return TRK_OK;
}

trk_status trk_kalman_innovation(int nx, int nz, const trk_real *h, const trk_real *r,
                                 const trk_real *x, const trk_real *p, struct trk_innovation *inn)
{
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    if (!dims_ok(nx, nz) || !h || !r || !x || !p || !inn) return TRK_E_ARG;
    trk_status st = trk_i_innovation(nx, nz, h, r, x, p, pht, inn);
    if (st != TRK_OK) return st;
    if (!all_finite(nz, inn->z_pred)) return TRK_E_NAN;
    return TRK_OK;
}

void trk_kalman_gain(int nx, int nz, const trk_real *h, const trk_real *p,
                     const struct trk_innovation *inn, trk_real *k)
{
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_i_mat_mul_abt(nx, nx, nz, p, h, pht);
    trk_i_gain(nx, nz, pht, inn->s_chol_inv, k);
}

void trk_kalman_joseph(int nx, int nz, const trk_real *h, const trk_real *r, const trk_real *k,
                       const trk_real *p, trk_real *pc)
{
    trk_i_joseph(nx, nz, h, r, k, p, pc);
}

trk_status trk_kalman_update(int nx, int nz, const trk_real *h, const trk_real *r,
                             const trk_real *z, trk_real *x, trk_real *p)
{
    struct trk_innovation inn;
    trk_real pht[TRK_MAX_STATE * TRK_MAX_MEAS], k[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_real pc[TRK_MAX_STATE * TRK_MAX_STATE], xn[TRK_MAX_STATE], nu[TRK_MAX_MEAS];
    if (!dims_ok(nx, nz) || !h || !r || !z || !x || !p) return TRK_E_ARG;
    if (!all_finite(nz, z)) return TRK_E_NAN;
    trk_status st = trk_i_innovation(nx, nz, h, r, x, p, pht, &inn);
    if (st != TRK_OK) return st;
    trk_i_gain(nx, nz, pht, inn.s_chol_inv, k);
    for (int i = 0; i < nz; i++) nu[i] = z[i] - inn.z_pred[i];
    for (int i = 0; i < nx; i++) {
        trk_real s = x[i];
        for (int t = 0; t < nz; t++) s += k[i * nz + t] * nu[t];
        xn[i] = s;
    }
    trk_i_joseph(nx, nz, h, r, k, p, pc);
    if (!all_finite(nx, xn) || !all_finite(nx * nx, pc)) return TRK_E_NAN;
    for (int i = 0; i < nx; i++) x[i] = xn[i];
    for (int i = 0; i < nx * nx; i++) p[i] = pc[i];
    return TRK_OK;
}
