/* filter_ab_impl.h (private) - the constant-gain (alpha-beta) filter as a
 * track filter (track_filter_impl.h; TRK_WITH_ALPHA_BETA, params.filter =
 * TRK_FILTER_ALPHA_BETA): the seed survey's ch. 3.1 filter with the
 * steady-state gains of the CV Kalman filter (ch. 3.3.1; trk_cv_steady_state,
 * docs/conventions.md "Constant-gain filter"), per axis for the scan's gap and
 * the sensor's variance on that axis, for a firmware that cannot afford a
 * covariance recursion per track.
 *
 * No covariance is propagated: a grown-up track's covariance is the steady state's
 * (predicted for gating, as the survey's eq 3.10 recovers the prediction
 * variance from a gain; updated after the update), block-diagonal per axis.
 * The update moves the state by the gains times the PDA's combined
 * innovation sum_i beta_i nu_i (the PDA's weights with the predicted
 * steady-state S); beta0 and the spread of the innovations change no
 * covariance. Hence, and as the survey says of constant gains, a missed
 * scan does not widen the gate (a longer gap does: its steady state is the
 * gap's), and the sensor's xy correlation and a detection's own covariance
 * enter the gate and the PDA's weights but not the gains (those of the
 * sensor's variances per axis).
 * A scan at the track's own time (two sensors at one time) has no steady
 * state (a zero gap's gain is 0): it takes one Kalman update of the
 * track's own covariance, as the Kalman filter would.
 *
 * A young track is not yet in the steady state: its start (two-point
 * differencing) is far less certain, and with the steady-state gains from
 * the first update its gate is too small for its velocity error (measured:
 * a target seen every scan was lost within 3 scans and started again, over
 * and over). As the survey's ch. 3.3.2 asks, the gains before the steady
 * state come from the track's age instead of a recursion: while the track
 * has h points (n_hits), the gain and covariances are one Kalman step from
 * the least-squares line through h points at this gap (the growing-memory
 * filter; h = 2 is two-point differencing, so the first update is the
 * Kalman filter's own), as long as that gain is above the steady state's;
 * the steady state from then on (for the sonar figures of the tests, from
 * about 13 points). A track started from one point (h < 2) steps from its
 * own covariance.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_FILTER_AB_IMPL_H
#define TRK_FILTER_AB_IMPL_H

#include "track_gate_impl.h"
#include "track_pred_impl.h"

/* The steady state per axis for gap dt_us at the scan's sensor, from the
 * workspace's cache (the tracks of a scan share one gap: one computation
 * per scan), or computed into it. TRK_E_RANGE beyond the real type. */
static trk_status ab_steady(struct trk_tracker *t, const struct trk_scan *scan, int64_t dt_us, trk_real dt)
{
    if (t->ws.ab_dt_us == dt_us && t->ws.ab_sensor == scan->sensor_id) return TRK_OK;
    const trk_real *r = t->r[scan->sensor_id], q = t->params.process_noise_q;
    struct trk_cv_steady ss[2];
    trk_status st = trk_cv_steady_state(dt, q, r[S(ZX, ZX)], &ss[0]);
    if (st == TRK_OK) st = trk_cv_steady_state(dt, q, r[S(ZY, ZY)], &ss[1]);
    if (st != TRK_OK) return st;
    t->ws.ab_steady[0] = ss[0];
    t->ws.ab_steady[1] = ss[1];
    t->ws.ab_dt_us = dt_us;
    t->ws.ab_sensor = scan->sensor_id;
    return TRK_OK;
}

/* One axis's gains and covariances for this update into *g, from the
 * steady state ss, r the sensor's variance on the axis, h the track's
 * points, p_own its own covariance on the axis [pp, pv, vv] (for h < 2):
 * the steady state, or while the start-up gain is larger, one Kalman step
 * from the least-squares fit of h points at this gap (covariance [2 (2h -
 * 1) / (h (h + 1)), 6 / (T h (h + 1)), 12 / (T^2 h (h^2 - 1))] r). The
 * start-up's predicted M_pp is tested first: its gain is the larger when
 * M_pp / r > alpha_ss / (1 - alpha_ss). */
static void ab_axis(trk_real dt, trk_real q, trk_real r, uint32_t h, const trk_real p_own[3],
                    const struct trk_cv_steady *ss, struct trk_cv_steady *g)
{
    trk_real pp = p_own[0], pv = p_own[1], vv = p_own[2];
    if (h >= 2) {
        const trk_real n = (trk_real)h, c = r / (n * (n + 1));
        pp = 2 * (2 * n - 1) * c;
        pv = 6 * c / dt;
        vv = 12 * c / (dt * dt * (n - 1));
    }
    const trk_real mpp = pp + dt * (2 * pv + dt * vv) + q * dt * dt * dt / 3;
    *g = *ss;
    if (!(mpp * (1 - ss->alpha) > ss->alpha * r)) return; /* grown up: the steady state */
    const trk_real mpv = pv + dt * vv + q * dt * dt / 2, mvv = vv + q * dt;
    const trk_real alpha = mpp / (mpp + r), k_vel = mpv / (mpp + r);
    g->alpha = alpha;
    g->k_vel_per_s = k_vel;
    g->beta = k_vel * dt;
    g->pred[0] = mpp;
    g->pred[1] = mpv;
    g->pred[2] = mvv;
    g->post[0] = (1 - alpha) * mpp;
    g->post[1] = (1 - alpha) * mpv;
    g->post[2] = mvv - k_vel * mpv;
}

/* The prediction to the scan time: the state moved by the CV model, the
 * gains per axis into pr->ab (ab_axis), the predicted covariance into
 * pr->p, then pred_finish. TRK_E_RANGE when the steady state is beyond the
 * real type (trk_cv_steady_state). */
static trk_status ab_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                             struct pred *pr)
{
    const int64_t dt_us = scan->time_us - tr->time_us;
    const trk_real dt = (trk_real)dt_us * TRK_REAL_C(1e-6);
    const trk_real *r = t->r[scan->sensor_id];
    for (int i = 0; i < NX; i++) pr->x[i] = tr->x[i];
    for (int i = 0; i < NX * NX; i++) pr->p[i] = tr->p[i];
    if (dt_us <= 0) { /* a second sensor at the track's time: one Kalman update of its covariance */
        for (int a = 0; a < 2; a++) {
            const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
            const trk_real pp = tr->p[P(ip, ip)], pv = tr->p[P(ip, iv)], vv = tr->p[P(iv, iv)];
            const trk_real c = pp + r[a == 0 ? S(ZX, ZX) : S(ZY, ZY)];
            struct trk_cv_steady *g = &pr->ab[a];
            g->alpha = pp / c;
            g->k_vel_per_s = pv / c;
            g->beta = 0;
            g->pred[0] = pp;
            g->pred[1] = pv;
            g->pred[2] = vv;
            g->post[0] = (1 - g->alpha) * pp;
            g->post[1] = (1 - g->alpha) * pv;
            g->post[2] = vv - g->k_vel_per_s * pv;
        }
    } else {
        const trk_status st = ab_steady(t, scan, dt_us, dt);
        if (st != TRK_OK) return st;
        for (int a = 0; a < 2; a++) {
            const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
            const trk_real own[3] = {tr->p[P(ip, ip)], tr->p[P(ip, iv)], tr->p[P(iv, iv)]};
            ab_axis(dt, t->params.process_noise_q, r[a == 0 ? S(ZX, ZX) : S(ZY, ZY)], tr->n_hits, own,
                    &t->ws.ab_steady[a], &pr->ab[a]);
        }
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
