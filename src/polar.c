/* polar.c - a range/bearing detection as a Cartesian one
 * (trk_detection_from_polar, trk/tracker.h). */
#include "trk/tracker.h"

trk_status trk_detection_from_polar(trk_real range_m, trk_real bearing_rad, trk_real sigma_range_m,
                                    trk_real sigma_bearing_rad, trk_real sensor_x_m,
                                    trk_real sensor_y_m, struct trk_detection *d)
{
    if (!d) return TRK_E_ARG;
    if (!isfinite(range_m) || !isfinite(bearing_rad) || !isfinite(sigma_range_m) ||
        !isfinite(sigma_bearing_rad) || !isfinite(sensor_x_m) || !isfinite(sensor_y_m))
        return TRK_E_NAN;
    if (!(range_m >= 0) || !(sigma_range_m > 0) || !(sigma_bearing_rad > 0)) return TRK_E_RANGE;
    const trk_real sb = trk_sin(bearing_rad), cb = trk_cos(bearing_rad);
    const trk_real vr = sigma_range_m * sigma_range_m;
    const trk_real vt = range_m * range_m * sigma_bearing_rad * sigma_bearing_rad; /* cross-range */
    /* J = [[sb, r cb], [cb, -r sb]];  C = J diag(vr, sigma_b^2) J' */
    d->x_m = sensor_x_m + range_m * sb;
    d->y_m = sensor_y_m + range_m * cb;
    d->cov_m2[TRK_COV2_XX] = vr * sb * sb + vt * cb * cb;
    d->cov_m2[TRK_COV2_XY] = (vr - vt) * sb * cb;
    d->cov_m2[TRK_COV2_YY] = vr * cb * cb + vt * sb * sb;
    d->has_cov = 1;
    d->has_amplitude = 0;
    d->amplitude = 0;
    if (!(d->cov_m2[TRK_COV2_XX] * d->cov_m2[TRK_COV2_YY] - d->cov_m2[TRK_COV2_XY] * d->cov_m2[TRK_COV2_XY] > 0)) {
        /* range 0: cross-range variance 0, covariance singular */
        return TRK_E_RANGE;
    }
    return TRK_OK;
}
