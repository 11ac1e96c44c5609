/* trk/config.h - compile-time capacities and the scalar type.
 *
 * Every capacity is a default that a build may override with -DNAME=value or by
 * pointing TRK_CONFIG_FILE at a header of its own (-DTRK_CONFIG_FILE='"my_trk.h"'),
 * which is included first. check_config.h rejects impossible combinations with
 * an #error that says how to fix them.
 *
 * The library and the program that links it must agree on these values:
 * trk_config_check() (types.h) compares the header's view with the library's.
 */
#ifndef TRK_CONFIG_H
#define TRK_CONFIG_H

#ifdef TRK_CONFIG_FILE
#include TRK_CONFIG_FILE
#endif

/* Live tracks in one trk_tracker (tentative + confirmed). */
#ifndef TRK_MAX_TRACKS
#define TRK_MAX_TRACKS 64
#endif

/* Detections in one scan. A larger scan is refused whole (TRK_E_CAPACITY). */
#ifndef TRK_MAX_DETECTIONS
#define TRK_MAX_DETECTIONS 256
#endif

/* Sensors (e.g. multistatic receivers) with their own noise and detection
 * parameters that one tracker fuses. */
#ifndef TRK_MAX_SENSORS
#define TRK_MAX_SENSORS 4
#endif

/* Largest state and measurement dimension of the general linear-Gaussian
 * functions (kalman.h, gate.h, pda.h). The tracker itself runs the 2-D
 * constant-velocity model (4 states, 2 measurements). */
#ifndef TRK_MAX_STATE
#define TRK_MAX_STATE 6
#endif
#ifndef TRK_MAX_MEAS
#define TRK_MAX_MEAS 3
#endif

/* Kennedy's clutter tests (clutter_test.h) as confirmation methods of the
 * tracker. Their per-track state carries a window of TRK_CLUTTER_KMAX updates
 * (about 0.6 KB per track in double, 0.35 KB in float), by far the largest
 * member of union trk_confirm_state (trk/tracker.h), which every track slot
 * holds. 0 leaves the clutter tests' states and models out of the track
 * table (then selecting TRK_CONFIRM_CLUTTER_CHI2 or TRK_CONFIRM_CLUTTER_AMP
 * makes trk_tracker_init return TRK_E_UNSUPPORTED); the clutter_test module
 * itself is always built and usable on its own. 1 (default) keeps them. */
#ifndef TRK_WITH_CLUTTER_TESTS
#define TRK_WITH_CLUTTER_TESTS 1
#endif

#include "trk/check_config.h"

#endif /* TRK_CONFIG_H */
