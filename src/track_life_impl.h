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

/* Is track tr's velocity consistent with standing still, v' P_v^-1 v < h
 * (h = stationary_d2; 0: never)? A P_v that is not positive definite
 * cannot tell: not held. For a tentative track under the existence test,
 * whose returns have been weighed against a persistent scatterer's (S =
 * ln L_t / L_s over its looks, within +-h/2: existence_look), the two
 * kinds of evidence add as log odds: v' P_v^-1 v / 2 is the motion's ln
 * likelihood ratio at most (its Gaussian's peak against its value at v =
 * 0), so the track is held while v' P_v^-1 v / 2 + S < h / 2, that is
 * below the bar h - 2S. A track whose echoes are a scatterer's must move
 * the more clearly (S < 0: a bar up to 2h). Echoes that are a target's
 * lower the bar by at most h/5 (S capped at h/10: 20 at the default 25),
 * so that an object that stands still is reported at e^(-2h/5) per look at
 * most (4.5e-5), however it echoes: a weak rock is not told from a target
 * by its echoes alone. */
static int standing_still(const struct trk_tracker *t, const struct trk_track *tr)
{
    trk_real h = t->params.stationary_d2;
    if (!(h > 0)) return 0;
    if (tr->status == TRK_TRACK_TENTATIVE && t->params.confirm.method == TRK_CONFIRM_EXISTENCE) {
        const trk_real s = tr->test.confirm.existence.persist_llr, s_max = h / 10;
        h -= 2 * (s < s_max ? s : s_max);
    }
    const trk_real a = tr->p[P(VX, VX)], b = tr->p[P(VX, VY)], c = tr->p[P(VY, VY)];
    const trk_real vx = tr->x[VX], vy = tr->x[VY], det = a * c - b * b;
    if (!(a > 0 && det > 0)) return 0;
    return c * vx * vx - 2 * b * vx * vy + a * vy * vy < h * det; /* v' P_v^-1 v < h */
}

/* Tentative track tr, whose test confirms it on this look and which does
 * not stand still: is it confirmed now? Yes, but for echoes a scatterer's
 * (S < -TRK_SCATTERER_ECHO_LLR): then only once it has moved on
 * TRK_STILL_LOOKS looks in a row, each with its test confirming (counted in
 * n_still_in_row, which any other look sets to 0: step_tests). A track
 * drawn onto a scatterer from clutter or a target's point has the pull for
 * velocity: it passes the motion test once, then coasts off the scatterer
 * and its existence falls. */
static int moved_enough(const struct trk_tracker *t, struct trk_track *tr)
{
    if (!(t->params.confirm.method == TRK_CONFIRM_EXISTENCE &&
          tr->test.confirm.existence.persist_llr < -TRK_SCATTERER_ECHO_LLR))
        return 1;
    return ++tr->n_still_in_row >= TRK_STILL_LOOKS;
}

/* The share of the scan's detections that are not targets' taken for
 * persistent returns no held track explains: the amplitude mixture's eta
 * for this scan (struct trk_sensor_params persistent_share). The sensor's
 * eta puts eta n of the scan's n detections on persistent scatterers; a
 * tentative track standing still that the sensor can see holds one and
 * explains pv P_s of them (its existence times their P_D): in joint
 * association its returns are its own target's, and a moving track near
 * it shares them with it, without the mixture. What is left,
 *   n_u = max(eta n - sum pv P_s, P_s)   (at least one scatterer not yet held),
 * against the clutter's (1 - eta) n gives eta' = n_u / ((1 - eta) n + n_u),
 * at most eta. Without existence (visibility off) a held track counts 1.
 * Per-track PDA weighs no other track, so there a return in a held track's
 * gate is a moving track's but for the mixture: eta stays (trk-sim mtt
 * --family sonar --config pda: false tracks 19.7 / 37.0 -> 28.7 / 76.7 per
 * 1000 pings at 20 / 100 clutter with eta' there), and a build without
 * joint association has only that. */
#if TRK_WITH_JOINT
static trk_real unexplained_persistent_share(const struct trk_tracker *t, const struct trk_scan *scan)
{
    const struct trk_sensor_params *sp = &t->params.sensor[scan->sensor_id];
    const trk_real eta = sp->persistent_share, p_s = sp->persistent_pd, n = (trk_real)scan->n_detections;
    if (!(eta * n > p_s) || t->params.association != TRK_ASSOC_JOINT)
        return eta; /* none, fewer than one scatterer's returns expected, or per-track PDA */
    trk_real held = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = &t->track[i];
        if (tr->status != TRK_TRACK_TENTATIVE || !standing_still(t, tr)) continue;
        if (t->ws.view.limited && !(sensor_pd_at(t, scan, tr->x[X], tr->x[Y]) > 0)) continue;
        held += (t->params.track_visibility ? tr->vis.pv : 1) * p_s;
    }
    const trk_real n_u = eta * n - held > p_s ? eta * n - held : p_s;
    return n_u / ((1 - eta) * n + n_u);
}
#endif

/* Confirmed track tr's velocity on this look: consistent with standing
 * still for TRK_STILL_LOOKS looks in a row, it goes back to held (tentative,
 * stationary; its confirmation test starts again): a pair that passed a
 * persistent return with a clutter point's velocity, was confirmed, and
 * was then held still by the scatterer's returns (the survey's stationary
 * point tracks, ch. 5.3). It is confirmed again, under its id, once it
 * moves (and, with echoes a scatterer's, has moved on TRK_STILL_LOOKS looks
 * in a row: moved_enough). 1 when it went back. */
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
        const int moving = d > 0 && !standing_still(t, tr);
        const int confirm = moving && moved_enough(t, tr);
        if (!moving || confirm) tr->n_still_in_row = 0;
        tr->stationary = (uint8_t)(d > 0 && !confirm);
        if (tr->stationary) {
            rep->n_stationary++;
        } else if (confirm) {
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
