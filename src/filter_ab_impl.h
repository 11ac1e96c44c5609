/* filter_ab_impl.h (private) - the constant-gain (alpha-beta) filter as a
 * track filter (track_filter_impl.h; TRK_WITH_ALPHA_BETA, params.filter =
 * TRK_FILTER_ALPHA_BETA): the seed survey's ch. 3.1 filter with the
 * steady-state gains of the CV Kalman filter (ch. 3.3.1; trk_cv_steady_state,
 * docs/conventions.md "Constant-gain filter"), per axis for the scan's gap and
 * the sensor's variance on that axis, for a firmware that cannot afford a
 * covariance recursion per track.
 *
 * No covariance is propagated: a track's covariance is the steady state's
 * (predicted for gating, as the survey's eq 3.10 recovers the prediction
 * variance from a gain; updated after the update), block-diagonal per axis.
 * The update moves the state by the gains times the PDA's combined
 * innovation sum_i beta_i nu_i (the PDA's weights with the predicted
 * steady-state S); beta0 and the spread of the innovations change no
 * covariance. Hence, and as the survey says of constant gains, a missed
 * scan does not widen the gate (a longer gap does: its steady state is the
 * gap's), and the sensor's xy correlation enters the gate but not the gains.
 * A scan at the track's own time (two sensors at one time) leaves the state
 * and covariance as they are: the steady state of a zero gap is a gain of 0.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_FILTER_AB_IMPL_H
#define TRK_FILTER_AB_IMPL_H

#include "track_gate_impl.h"
#include "track_pred_impl.h"

/* The prediction to the scan time: the state moved by the CV model, the
 * steady state per axis into pr->ab, its predicted covariance into pr->p,
 * then pred_finish. TRK_E_RANGE when the steady state is beyond the real
 * type (trk_cv_steady_state). */
static trk_status ab_predict(const struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                             struct pred *pr)
{
    const trk_real dt = (trk_real)(scan->time_us - tr->time_us) * TRK_REAL_C(1e-6);
    const trk_real *r = t->r[scan->sensor_id];
    for (int i = 0; i < NX; i++) pr->x[i] = tr->x[i];
    for (int i = 0; i < NX * NX; i++) pr->p[i] = tr->p[i];
    pr->ab[0].alpha = pr->ab[1].alpha = 0; /* no gain over no time */
    if (dt > 0) {
        const trk_real q = t->params.process_noise_q;
        trk_status st = trk_cv_steady_state(dt, q, r[S(ZX, ZX)], &pr->ab[0]);
        if (st == TRK_OK) st = trk_cv_steady_state(dt, q, r[S(ZY, ZY)], &pr->ab[1]);
        if (st != TRK_OK) return st;
        for (int i = 0; i < NX * NX; i++) pr->p[i] = 0;
        for (int a = 0; a < 2; a++) {
            const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
            pr->x[ip] += dt * pr->x[iv];
            pr->p[P(ip, ip)] = pr->ab[a].pred[0];
            pr->p[P(ip, iv)] = pr->p[P(iv, ip)] = pr->ab[a].pred[1];
            pr->p[P(iv, iv)] = pr->ab[a].pred[2];
        }
    }
    return pred_finish(t, scan, pr);
}

/* The update with the association weights (set->w = beta_i): the state by
 * the gains times sum_i beta_i nu_i, the covariance the steady state's
 * updated one (with nothing gated, the prediction's). TRK_E_NAN when the
 * state is no longer finite. */
static trk_status ab_update(struct pred *pr, const struct trk_i_pda_set *set)
{
    if (set->n == 0 || !(pr->ab[0].alpha > 0)) return TRK_OK; /* the prediction stands */
    const trk_real *z_pred = pr->inn.z_pred;
    trk_real nu[NZ] = {0, 0};
    for (size_t i = 0; i < set->n; i++) {
        nu[ZX] += set->w[i] * (set->z[NZ * i + ZX] - z_pred[ZX]);
        nu[ZY] += set->w[i] * (set->z[NZ * i + ZY] - z_pred[ZY]);
    }
    for (int a = 0; a < 2; a++) {
        const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
        const trk_real v = nu[a == 0 ? ZX : ZY];
        pr->x[ip] += pr->ab[a].alpha * v;
        pr->x[iv] += pr->ab[a].k_vel_per_s * v;
        pr->p[P(ip, ip)] = pr->ab[a].post[0];
        pr->p[P(ip, iv)] = pr->p[P(iv, ip)] = pr->ab[a].post[1];
        pr->p[P(iv, iv)] = pr->ab[a].post[2];
    }
    return trk_i_pda_check(NX, pr->x, pr->p);
}

/* The PDA's weights of the gated set, then the update with them: *out,
 * beta_i into set->w, the posterior over pr->x, pr->p. */
static trk_status ab_pda(const struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                         struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    pda_weights(&t->pda[scan->sensor_id], pr, set, out);
    return ab_update(pr, set);
}

#endif
