/* track_life_impl.h (private) - one track's life in the table: the end of
 * a track (why, counted in the report) and the step of its test on a look:
 * confirmation (or rejection, or the tentative age limit) of a tentative
 * track, termination of a confirmed one (track_tests.h).
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACK_LIFE_IMPL_H
#define TRK_TRACK_LIFE_IMPL_H

#include "tracker_internal.h"

/* Track tr ends now, for reason why (shown once in this scan's table,
 * freed at the next). */
static void end_track(struct trk_track *tr, enum trk_track_end why, struct trk_scan_report *rep)
{
    tr->status = TRK_TRACK_TERMINATED;
    tr->end_reason = (uint8_t)why;
    rep->n_terminated++;
    if (why == TRK_END_NUMERICAL) rep->n_numerical++;
    if (why == TRK_END_MERGED) rep->n_merged++;
}

/* Is tentative track tr's velocity consistent with standing still,
 * v' P_v^-1 v < stationary_d2 (0: never)? A P_v that is not positive
 * definite cannot tell: not held. */
static int standing_still(const struct trk_tracker *t, const struct trk_track *tr)
{
    const trk_real h = t->params.stationary_d2;
    if (!(h > 0)) return 0;
    const trk_real a = tr->p[P(VX, VX)], b = tr->p[P(VX, VY)], c = tr->p[P(VY, VY)];
    const trk_real vx = tr->x[VX], vy = tr->x[VY], det = a * c - b * b;
    if (!(a > 0 && det > 0)) return 0;
    return c * vx * vx - 2 * b * vx * vy + a * vy * vy < h * det; /* v' P_v^-1 v < h */
}

/* Confirmed track tr's velocity on this look: consistent with standing
 * still for TRK_STILL_LOOKS looks in a row, it goes back to held (tentative,
 * stationary; its confirmation test starts again): a pair that passed a
 * persistent return with a clutter point's velocity, was confirmed, and
 * was then held still by the scatterer's returns (the survey's stationary
 * point tracks, ch. 5.3). It is confirmed again, under its id, once it
 * moves. 1 when it went back. */
static int hold_if_still(struct trk_tracker *t, struct trk_track *tr, struct trk_scan_report *rep)
{
    if (!standing_still(t, tr)) {
        tr->n_still_in_row = 0;
        return 0;
    }
    if (++tr->n_still_in_row < TRK_STILL_LOOKS) return 0;
    tr->n_still_in_row = 0;
    tr->status = TRK_TRACK_TENTATIVE;
    tr->stationary = 1;
    trk_i_confirm_start(t, tr);
    rep->n_stationary++;
    return 1;
}

/* The track's test on this look and what it decides: confirmation (or
 * rejection, or the tentative age limit) of a tentative track, held while
 * it stands still (a persistent return), termination of a confirmed one,
 * or its return to held when it has stood still (hold_if_still). */
static void step_tests(struct trk_tracker *t, struct trk_track *tr, const struct trk_look *look,
                       struct trk_scan_report *rep)
{
    if (tr->status == TRK_TRACK_TENTATIVE) {
        const int d = trk_i_confirm_step(t, tr, look);
        tr->stationary = (uint8_t)(d > 0 && standing_still(t, tr));
        if (tr->stationary) {
            rep->n_stationary++;
        } else if (d > 0) {
            tr->status = TRK_TRACK_CONFIRMED;
            trk_i_term_start(t, tr);
            rep->n_confirmed++;
        } else if (d < 0) {
            end_track(tr, TRK_END_REJECTED, rep);
        } else if (t->params.max_tentative_scans && tr->n_scans > t->params.max_tentative_scans) {
            end_track(tr, TRK_END_TENTATIVE_AGE, rep);
        }
    } else if (trk_i_term_step(t, tr, look)) {
        end_track(tr, TRK_END_TERMINATED, rep);
    } else {
        (void)hold_if_still(t, tr, rep);
    }
}

#endif
