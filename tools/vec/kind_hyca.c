/* kind_hyca.c - vector kind hyca_md (tests/vectors/hyca.vec): the expected
 * covariance of the CV Kalman filter with missed detections by hybrid
 * conditional averaging (trk/hyca.h; Willett 2010 eqs 43-48). 2-D model,
 * state [x, vx, y, vy], R = r I.
 *
 * Float tolerance (normwise, see vec.h): the fixed point is iterated to the
 * float convergence rule (64 eps relative); the Riccati map's condition
 * number at r/q = 100 is a few hundred, so 1e-4 of the largest element. */
#include <string.h>

#include "trk/hyca.h"
#include "vec.h"

TRK_VEC_KIND(hyca_md, 0, 1e-4, VEC_FAST)
{
    double t, r, q, pd;
    if (vec_in_scalar(c, o, "T", &t) || vec_in_scalar(c, o, "r", &r) || vec_in_scalar(c, o, "q", &q) ||
        vec_in_scalar(c, o, "pd", &pd))
        return -1;
    struct trk_hyca_md_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2;
    p.dt_s = (trk_real)t;
    p.r_m2 = (trk_real)r;
    p.q_m2_per_s3 = (trk_real)q;
    p.pd = (trk_real)pd;
    struct trk_hyca_md_result res;
    trk_status st = trk_hyca_md(&p, &res);
    if (st != TRK_OK) return vec_fail(o, "trk_hyca_md: %s", trk_status_str(st));
    const size_t n = (size_t)(res.nx * res.nx);
    if (vec_put_real(o, "P_det", res.p_det, n) || vec_put_real(o, "P_miss", res.p_miss, n) ||
        vec_put_real(o, "P", res.p, n))
        return -1;
    return 0;
}
