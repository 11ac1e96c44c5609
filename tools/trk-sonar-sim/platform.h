/* platform.h - trk-sonar-sim's polar sonar on a moving platform: the
 * scenario's targets (tools/sim/scenario.h: their motion and amplitude
 * laws) seen as range and bearing from a platform moving at constant
 * velocity, with the detection probability of the sensor's P_D profile and
 * coverage (trk_sensor_pd_at: the formula the tracker uses), and clutter
 * where the sensor sees.
 *
 * Per scan k (time t_k = k T from the first scan):
 *   pose: (x0 + v sin(c) t_k, y0 + v cos(c) t_k), heading c (the course,
 *     clockwise from north: the sensor looks along the platform's course)
 *   a target at (x, y) is detected with P_D = trk_sensor_pd_at(sensor, pose,
 *     x, y) (the sensor's pd the target's own, without a profile); its range
 *     and bearing from the pose with N(0, sigma_range_m^2) and
 *     N(0, sigma_bearing_rad^2) noise, the bearing relative to the heading in
 *     (-pi, pi]; amplitude drawn from the target's law
 *   clutter: the scenario's Poisson mean over its region (or its count),
 *     uniform over the region, kept where the coverage is (P_D of a sensor
 *     with P_D 1 and no profile > 0): the clutter density is the scenario's
 *     inside the coverage, 0 outside
 *   the detections are shuffled
 * Random numbers: rng keyed by the scenario's seed on streams of their own
 * (POLAR_STREAM + k), apart from the scenario's. */
#ifndef TRK_SONAR_SIM_PLATFORM_H
#define TRK_SONAR_SIM_PLATFORM_H

#include <stddef.h>
#include <stdint.h>

#include "scenario.h"
#include "trk/tracker.h"

#define POLAR_STREAM (UINT64_C(1) << 62)

struct polar_platform {
    double x_m, y_m;        /* position at the first scan */
    double course_rad;      /* clockwise from north; also the sensor's heading */
    double speed_mps;       /* >= 0 */
};

/* The pose at scan k of scenario period period_s. */
struct trk_pose polar_pose(const struct polar_platform *pf, uint64_t k, double period_s);

/* Scan k's polar detections of sensor sp (kind polar: sigma_range_m,
 * sigma_bearing_rad, pd_profile, coverage) at pose, from the scenario's
 * current truth (after scen_next of the same scan) into out[0 .. max)
 * (beyond: dropped, clutter first, counted in *n_dropped). Returns the
 * number written; *n_target: how many are targets'. */
size_t polar_scan(struct scenario *sc, const struct trk_sensor_params *sp, const struct trk_pose *pose, uint64_t k,
                  struct trk_polar_detection *out, size_t max, size_t *n_target, size_t *n_dropped);

#endif
