/* clutter_map.h (private) - each sensor's clutter map (trk/tracker.h,
 * struct trk_clutter_map_params): its cells over the sensor's coverage in
 * the view of one scan, the ratio rho pooled over the window of cells about
 * a position and the density it gives there, and the scan's update of the
 * counts. */
#ifndef TRK_CLUTTER_MAP_H
#define TRK_CLUTTER_MAP_H

#include "sensor_view.h"

/* Is a map kept for sensor sp under map parameters mp (cells asked for,
 * a coverage with a maximum range, a configured density > 0)? */
int trk_i_map_kept(const struct trk_clutter_map_params *mp, const struct trk_sensor_params *sp);

/* Turn view v's map on over the sensor's counts (N_c) and scans (W), when
 * the map is kept (trk_i_map_kept); off otherwise. After trk_i_view_init. */
void trk_i_map_view(struct trk_i_view *v, const struct trk_clutter_map_params *mp, const trk_real *count,
                    trk_real scans);

/* Range and bearing (relative to the heading, (-pi, pi]) of (x_m, y_m)
 * from the view's pose. */
void trk_i_view_polar(const struct trk_i_view *v, trk_real x_m, trk_real y_m, trk_real *r_m, trk_real *b_rad);

/* The cell of the view's map at range r_m, relative bearing b_rad; -1
 * outside the map (or without one). */
long trk_i_map_cell(const struct trk_i_view *v, trk_real r_m, trk_real b_rad);

/* The density at (x_m, y_m) with the view's map: the configured one times
 * rho pooled over the window of cells about its cell (1 outside the map). */
trk_real trk_i_map_lambda_at(const struct trk_i_view *v, trk_real x_m, trk_real y_m);

/* One scan's forgetting: every count and the scans' sum times 1 - 1/tau,
 * then the scan itself (W + 1). The scan's detections are then added to
 * their cells' counts by the caller. */
void trk_i_map_forget(const struct trk_clutter_map_params *mp, trk_real *count, trk_real *scans);

#endif
