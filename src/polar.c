/* polar.c - polar sensors and where a sensor sees (trk/tracker.h):
 * a range/bearing detection as a Cartesian one (trk_detection_from_polar,
 * trk_polar_to_cartesian), the covariance of the conversion
 * (trk_polar_cov), and a sensor's P_D at a position (trk_sensor_pd_at, over
 * the view of sensor_view.h). Conventions: docs/conventions.md "Polar
 * detections". */
#include "sensor_view.h"

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

/* The unbiased conversion's scale e^(sb^2 / 2) (Mo et al. 1998, eq 5:
 * E[cos(b + e)] = e^(-sb^2 / 2) cos b for e ~ N(0, sb^2)). */
static trk_real unbiased_scale(trk_real sigma_b) { return trk_exp(TRK_REAL_C(0.5) * sigma_b * sigma_b); }

void trk_polar_cov(const struct trk_sensor_params *sp, trk_real dx_m, trk_real dy_m, trk_real cov_m2[3])
{
    const trk_real vr = sp->sigma_range_m * sp->sigma_range_m, vb = sp->sigma_bearing_rad * sp->sigma_bearing_rad;
    const trk_real xx = dx_m * dx_m, yy = dy_m * dy_m, xy = dx_m * dy_m, rho2 = xx + yy;
    if (vb * rho2 < TRK_COV2_MIN_REL_DET * vr) { /* at the pose, or so near it that the
                                                   cross-range variance is lost to rounding
                                                   against the range's: no bearing, and the
                                                   range's variance in every direction (a NaN
                                                   offset stays NaN) */
        cov_m2[TRK_COV2_XX] = cov_m2[TRK_COV2_YY] = vr;
        cov_m2[TRK_COV2_XY] = 0;
        return;
    }
    if (sp->conversion != TRK_POLAR_UNBIASED) {
        /* r^2 s^2 = dx^2, r^2 c^2 = dy^2 (s, c: sin, cos of the bearing):
         * C = [[vr s^2 + vb r^2 c^2, (vr - vb r^2) s c], [., vr c^2 + vb r^2 s^2]] */
        const trk_real q = vr / rho2;
        cov_m2[TRK_COV2_XX] = q * xx + vb * yy;
        cov_m2[TRK_COV2_XY] = (q - vb) * xy;
        cov_m2[TRK_COV2_YY] = q * yy + vb * xx;
        return;
    }
    /* Mo et al. eq 7 at the measured r, b (their angle from x; ours
     * clockwise from y swaps x and y), rearranged without cancellation:
     * with a = e^sb^2 - 1, c2 = 1 - e^(-2 sb^2), l4 = e^(-2 sb^2),
     *   xx = r^2 [s^2 (a - c2/2) + c^2 c2/2] + vr [s^2 (1 + l4) + c^2 (1 - l4)] / 2
     *   yy = the same with s and c swapped
     *   xy = s c [r^2 (a - c2) + vr l4]
     * and r^2 s^2 = l^2 dx^2 etc. for the converted offset (dx, dy) = (r/l)(s, c),
     * l = e^(-sb^2 / 2). */
    const trk_real a = trk_expm1(vb), c2 = -trk_expm1(-2 * vb), l4 = 1 - c2, l2 = trk_exp(-vb);
    const trk_real hv = TRK_REAL_C(0.5) * vr / rho2;
    cov_m2[TRK_COV2_XX] = l2 * (xx * (a - TRK_REAL_C(0.5) * c2) + yy * TRK_REAL_C(0.5) * c2) +
                          hv * (xx * (1 + l4) + yy * c2);
    cov_m2[TRK_COV2_YY] = l2 * (yy * (a - TRK_REAL_C(0.5) * c2) + xx * TRK_REAL_C(0.5) * c2) +
                          hv * (yy * (1 + l4) + xx * c2);
    cov_m2[TRK_COV2_XY] = xy * (l2 * (a - c2) + 2 * hv * l4);
}

/* sigma_bearing_rad's upper limit: half a radian (29 degrees); beyond it
 * neither conversion describes the spread (the first-order one's bias
 * r sb^2 / 2 exceeds 12 % of the range). */
#define SIGMA_BEARING_MAX TRK_REAL_C(0.5)

/* The conversion itself (trk_polar_to_cartesian), k the unbiased scale (1
 * first order), the inputs checked by the caller. */
static void polar_convert(const struct trk_sensor_params *sp, const struct trk_pose *pose, trk_real k,
                          const struct trk_polar_detection *pd, struct trk_detection *d)
{
    const trk_real b = pose->heading_rad + pd->bearing_rad;
    const trk_real dx = k * pd->range_m * trk_sin(b), dy = k * pd->range_m * trk_cos(b);
    d->x_m = pose->x_m + dx;
    d->y_m = pose->y_m + dy;
    /* from the offset of the position as stored: the covariance the tracker
     * derives again from it, bit for bit */
    trk_polar_cov(sp, d->x_m - pose->x_m, d->y_m - pose->y_m, d->cov_m2);
    d->has_cov = 1;
    d->has_amplitude = pd->has_amplitude;
    d->amplitude = pd->amplitude;
}

trk_status trk_polar_to_cartesian(const struct trk_sensor_params *sp, const struct trk_pose *pose,
                                  const struct trk_polar_detection *pd, struct trk_detection *d)
{
    if (!sp || !pose || !pd || !d || sp->kind != TRK_SENSOR_POLAR) return TRK_E_ARG;
    if (!isfinite(pd->range_m) || !isfinite(pd->bearing_rad) || !isfinite(pose->x_m) || !isfinite(pose->y_m) ||
        !isfinite(pose->heading_rad) || !isfinite(sp->sigma_range_m) || !isfinite(sp->sigma_bearing_rad))
        return TRK_E_NAN;
    if (!(pd->range_m > 0) || !(sp->sigma_range_m > 0) ||
        !(sp->sigma_bearing_rad > 0 && sp->sigma_bearing_rad <= SIGMA_BEARING_MAX))
        return TRK_E_RANGE;
    polar_convert(sp, pose, sp->conversion == TRK_POLAR_UNBIASED ? unbiased_scale(sp->sigma_bearing_rad) : 1, pd, d);
    return TRK_OK;
}

trk_status trk_i_view_convert(const struct trk_i_view *v, const struct trk_polar_detection *pd,
                              struct trk_detection *d)
{
    if (!isfinite(pd->range_m) || !isfinite(pd->bearing_rad)) return TRK_E_NAN;
    if (!(pd->range_m > 0)) return TRK_E_RANGE;
    polar_convert(v->sp, &v->pose, v->polar_k, pd, d);
    return TRK_OK;
}

void trk_i_view_init(struct trk_i_view *v, const struct trk_sensor_params *sp, const struct trk_pose *pose)
{
    const struct trk_coverage *c = &sp->coverage;
    v->sp = sp;
    v->pose = *pose;
    v->sector = c->half_width_rad > 0 && c->half_width_rad < TRK_PI;
    v->sin_h = trk_sin(pose->heading_rad);
    v->cos_h = trk_cos(pose->heading_rad);
    v->cos_half = v->sector ? trk_cos(c->half_width_rad) : -1;
    v->min_r2 = c->min_range_m * c->min_range_m;
    v->max_r2 = c->max_range_m * c->max_range_m;
    v->limited = v->sector || c->min_range_m > 0 || c->max_range_m > 0 || sp->pd_profile.n > 0;
    v->clutter_varies = sp->clutter_profile.n > 0;
    v->polar_k = sp->kind == TRK_SENSOR_POLAR && sp->conversion == TRK_POLAR_UNBIASED
                     ? unbiased_scale(sp->sigma_bearing_rad)
                     : 1;
    v->map = 0; /* the tracker's: trk_i_map_view */
    v->map_params = NULL;
    v->map_count = NULL;
    v->map_scans = 0;
    v->map_half_b = 0;
}

/* A profile of n points (range_m, value) at range r: linear between its
 * points, flat beyond the ends (n >= 2, ranges increasing: checked at
 * init). */
static trk_real profile_at(unsigned n, const trk_real *range_m, const trk_real *value, trk_real r)
{
    if (!(r > range_m[0])) return value[0];
    for (unsigned k = 1; k < n; k++) {
        if (r < range_m[k]) {
            const trk_real f = (r - range_m[k - 1]) / (range_m[k] - range_m[k - 1]);
            return value[k - 1] + f * (value[k] - value[k - 1]);
        }
    }
    return value[n - 1];
}

trk_real trk_i_view_pd(const struct trk_i_view *v, trk_real pd_flat, trk_real x_m, trk_real y_m)
{
    if (!v->limited) return pd_flat;
    const trk_real dx = x_m - v->pose.x_m, dy = y_m - v->pose.y_m, r2 = dx * dx + dy * dy;
    if (r2 < v->min_r2 || (v->max_r2 > 0 && r2 > v->max_r2)) return 0;
    const trk_real r = trk_sqrt(r2);
    if (v->sector && !(dx * v->sin_h + dy * v->cos_h >= r * v->cos_half)) return 0;
    const struct trk_pd_profile *pp = &v->sp->pd_profile;
    return pp->n > 0 ? profile_at(pp->n, pp->range_m, pp->pd, r) : pd_flat;
}

trk_real trk_i_view_pd_profile(const struct trk_i_view *v, trk_real x_m, trk_real y_m)
{
    const trk_real dx = x_m - v->pose.x_m, dy = y_m - v->pose.y_m;
    const struct trk_pd_profile *pp = &v->sp->pd_profile;
    return profile_at(pp->n, pp->range_m, pp->pd, trk_sqrt(dx * dx + dy * dy));
}

trk_real trk_i_view_clutter(const struct trk_i_view *v, trk_real x_m, trk_real y_m)
{
    if (v->sp->clutter_profile.n == 0) return v->sp->clutter_density_per_m2;
    const trk_real dx = x_m - v->pose.x_m, dy = y_m - v->pose.y_m;
    return trk_i_view_clutter_r(v, trk_sqrt(dx * dx + dy * dy));
}

trk_real trk_i_view_clutter_r(const struct trk_i_view *v, trk_real r_m)
{
    const struct trk_clutter_profile *cp = &v->sp->clutter_profile;
    if (cp->n == 0) return v->sp->clutter_density_per_m2;
    return profile_at(cp->n, cp->range_m, cp->density_per_m2, r_m);
}

trk_real trk_sensor_clutter_at(const struct trk_sensor_params *sp, const struct trk_pose *pose, trk_real x_m,
                               trk_real y_m)
{
    if (!sp || !pose) return (trk_real)NAN;
    struct trk_i_view v;
    trk_i_view_init(&v, sp, pose);
    return trk_i_view_clutter(&v, x_m, y_m);
}

trk_real trk_sensor_pd_at(const struct trk_sensor_params *sp, const struct trk_pose *pose, trk_real x_m,
                          trk_real y_m)
{
    if (!sp || !pose) return (trk_real)NAN;
    struct trk_i_view v;
    trk_i_view_init(&v, sp, pose);
    return trk_i_view_pd(&v, sp->use_amplitude ? trk_amplitude_pd(&sp->amplitude) : sp->pd, x_m, y_m);
}
