/* two_point_impl.h (private) - the two-point-differencing covariance of the
 * CV model (Bar-Shalom and Li; per coordinate [[r, r/T], [r/T, 2r/T^2]]): the
 * start of the MRE, CRLB and HYCA iterations of the analysis library. */
#ifndef TRK_TWO_POINT_IMPL_H
#define TRK_TWO_POINT_IMPL_H

#include "trk/types.h"

/* p (2 nz x 2 nz, state [x, vx(, y, vy)]) for measurement variance r_m2 and
 * scan interval dt_s. */
static inline void trk_i_two_point_cov(int nz, trk_real r_m2, trk_real dt_s, trk_real *p)
{
    const int nx = 2 * nz;
    for (int i = 0; i < nx * nx; i++) p[i] = 0;
    for (int c = 0; c < nz; c++) {
        const int o = 2 * c;
        p[o * nx + o] = r_m2;
        p[o * nx + o + 1] = p[(o + 1) * nx + o] = r_m2 / dt_s;
        p[(o + 1) * nx + o + 1] = 2 * r_m2 / (dt_s * dt_s);
    }
}

#endif
