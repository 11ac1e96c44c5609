/* sensor_view.h (private) - a sensor as one scan sees it: its pose (the
 * scan's or the sensor's own) with the heading's sine and cosine and the
 * coverage's limits worked out once, so that a track's or a detection's
 * P_D and a polar sensor's covariance at a position take no trigonometric
 * function (src/polar.c; used by the tracker and by trk_sensor_pd_at). */
#ifndef TRK_SENSOR_VIEW_H
#define TRK_SENSOR_VIEW_H

#include "trk/tracker.h" /* struct trk_i_view */

/* The view of sensor sp from pose (finite: checked by the caller). */
void trk_i_view_init(struct trk_i_view *v, const struct trk_sensor_params *sp, const struct trk_pose *pose);

/* A polar detection of the view's sensor as a Cartesian one with its
 * covariance, exactly as trk_polar_to_cartesian gives it (the sensor and
 * the pose checked already: at init and with the scan): TRK_E_NAN for a
 * range or bearing that is not finite, TRK_E_RANGE for a range <= 0. */
trk_status trk_i_view_convert(const struct trk_i_view *v, const struct trk_polar_detection *pd,
                              struct trk_detection *d);

/* P_D at (x_m, y_m): trk_sensor_pd_at with the view's pose. pd_flat is
 * the sensor's P_D without a profile (its pd, or its amplitude model's). */
trk_real trk_i_view_pd(const struct trk_i_view *v, trk_real pd_flat, trk_real x_m, trk_real y_m);

/* The P_D profile's value at the range of (x_m, y_m), inside the coverage
 * or not (a profile is set: n >= 2): the SNR a target there would have, for
 * the amplitude likelihood ratio of a detection there. */
trk_real trk_i_view_pd_profile(const struct trk_i_view *v, trk_real x_m, trk_real y_m);

/* lambda at (x_m, y_m): trk_sensor_clutter_at with the view's pose (its
 * configured density, without the tracker's clutter map). */
trk_real trk_i_view_clutter(const struct trk_i_view *v, trk_real x_m, trk_real y_m);

/* The same at range r_m from the pose. */
trk_real trk_i_view_clutter_r(const struct trk_i_view *v, trk_real r_m);

#endif
