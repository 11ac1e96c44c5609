/* track_tests.h (private) - the tracker's dispatch to the per-track
 * confirmation and termination tests chosen in its configuration. Adding a
 * method: a case in each function of track_tests.c, a member of the unions in
 * trk/tracker.h, and its parameter check. */
#ifndef TRK_TRACK_TESTS_H
#define TRK_TRACK_TESTS_H

#include "trk/tracker.h"

/* What one scan told a track (the tests' per-scan input). */
struct trk_look {
    int detected;        /* at least one detection in the gate */
    unsigned sensor_id;
    int n_gated;
    trk_real pfa_gate;   /* P(clutter in the gate) = 1 - exp(-lambda V_G) */
    trk_real beta0;
};

/* Check the methods' parameters (init a scratch state). */
trk_status trk_i_tests_check(const struct trk_tracker_params *p);

/* Start the confirmation test of a new tentative track. */
void trk_i_confirm_start(const struct trk_tracker_params *p, struct trk_track *tr);

/* One scan of a tentative track: +1 confirm, -1 reject, 0 pending. */
int trk_i_confirm_step(const struct trk_tracker_params *p, struct trk_track *tr,
                       const struct trk_look *look);

/* Start the termination test of a newly confirmed track. */
void trk_i_term_start(const struct trk_tracker_params *p, struct trk_track *tr);

/* One scan of a confirmed track: 1 terminate, 0 continue. */
int trk_i_term_step(const struct trk_tracker_params *p, struct trk_track *tr,
                    const struct trk_look *look);

#endif
