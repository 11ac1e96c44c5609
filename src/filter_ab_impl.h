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

/* One Kalman update on one axis from the predicted covariance m = [pp, pv,
 * vv] with the sensor's variance r over the gap dt into *g: gains, m, and
 * the updated covariance. */
static void ab_kalman_step(const trk_real m[3], trk_real r, trk_real dt, struct trk_cv_steady *g)
{
    const trk_real alpha = m[0] / (m[0] + r), k_vel = m[1] / (m[0] + r);
    g->alpha = alpha;
    g->k_vel_per_s = k_vel;
    g->beta = k_vel * dt;
    g->pred[0] = m[0];
    g->pred[1] = m[1];
    g->pred[2] = m[2];
    g->post[0] = (1 - alpha) * m[0];
    g->post[1] = (1 - alpha) * m[1];
    g->post[2] = m[2] - k_vel * m[1];
}

/* The start-up prediction of a track of h >= 2 points: the least-squares
 * line through h points dt apart (covariance [2 (2h - 1) / (h (h + 1)),
 * 6 / (T h (h + 1)), 12 / (T^2 h (h^2 - 1))] r; h = 2 is two-point
 * differencing) predicted over dt with the CV model of q, into m. */
static void ab_startup_pred(trk_real dt, trk_real q, trk_real r, uint32_t h, trk_real m[3])
{
    const trk_real n = (trk_real)h, c = r / (n * (n + 1));
    const trk_real pp = 2 * (2 * n - 1) * c, pv = 6 * c / dt, vv = 12 * c / (dt * dt * (n - 1));
    m[0] = pp + dt * (2 * pv + dt * vv) + q * dt * dt * dt / 3;
    m[1] = pv + dt * vv + q * dt * dt / 2;
    m[2] = vv + q * dt;
}

/* Is the start-up gain of predicted position variance mpp above the
 * steady state's (mpp / (mpp + r) > alpha)? */
static int ab_startup_larger(trk_real mpp, trk_real r, const struct trk_cv_steady *ss)
{
    return mpp * (1 - ss->alpha) > ss->alpha * r;
}

/* The smallest h >= 2 whose start-up gain is no larger than the steady
 * state's (the start-up prediction shrinks as h grows), by bisection over
 * uint32_t: once per cached gap, so that a grown-up track's update costs no
 * start-up arithmetic. */
static uint32_t ab_grown_h(trk_real dt, trk_real q, trk_real r, const struct trk_cv_steady *ss)
{
    uint32_t lo = 2, hi = UINT32_MAX; /* the answer is in [lo, hi] */
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        trk_real m[3];
        ab_startup_pred(dt, q, r, mid, m);
        if (ab_startup_larger(m[0], r, ss)) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

/* The steady state per axis for gap dt_us at the scan's sensor, and the
 * points from which a track takes it, from the workspace's cache (the
 * tracks of a scan share one gap: one computation per scan), or computed
 * into it. TRK_E_RANGE beyond the real type. */
static trk_status ab_steady(struct trk_tracker *t, const struct trk_scan *scan, int64_t dt_us, trk_real dt)
{
    if (t->ws.ab_dt_us == dt_us && t->ws.ab_sensor == scan->sensor_id) return TRK_OK;
    const trk_real *r = t->r[scan->sensor_id], q = t->params.process_noise_q;
    const trk_real r_axis[2] = {r[S(ZX, ZX)], r[S(ZY, ZY)]};
    struct trk_cv_steady ss[2];
    for (int a = 0; a < 2; a++) {
        const trk_status st = trk_cv_steady_state(dt, q, r_axis[a], &ss[a]);
        if (st != TRK_OK) return st;
    }
    for (int a = 0; a < 2; a++) {
        t->ws.ab_steady[a] = ss[a];
        t->ws.ab_grown_h[a] = ab_grown_h(dt, q, r_axis[a], &ss[a]);
    }
    t->ws.ab_dt_us = dt_us;
    t->ws.ab_sensor = scan->sensor_id;
    return TRK_OK;
}

/* One axis's gains and covariances for this update into *g (a): the
 * steady state once the track has ws.ab_grown_h[a] points; before, one
 * Kalman step from the start-up prediction (from the track's own covariance
 * p_own = [pp, pv, vv] predicted over dt while it has fewer than 2 points)
 * when its gain is the larger. */
static void ab_axis(const struct trk_tracker *t, int a, trk_real dt, trk_real r, uint32_t h, const trk_real p_own[3],
                    struct trk_cv_steady *g)
{
    const struct trk_cv_steady *ss = &t->ws.ab_steady[a];
    const trk_real q = t->params.process_noise_q;
    *g = *ss;
    if (h >= t->ws.ab_grown_h[a]) return; /* grown up: the steady state */
    trk_real m[3];
    if (h >= 2) {
        ab_startup_pred(dt, q, r, h, m);
    } else {
        m[0] = p_own[0] + dt * (2 * p_own[1] + dt * p_own[2]) + q * dt * dt * dt / 3;
        m[1] = p_own[1] + dt * p_own[2] + q * dt * dt / 2;
        m[2] = p_own[2] + q * dt;
    }
    if (ab_startup_larger(m[0], r, ss)) ab_kalman_step(m, r, dt, g);
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
    if (dt_us <= 0) { /* a second sensor at the track's time: one Kalman update of its covariance */
        for (int i = 0; i < NX * NX; i++) pr->p[i] = tr->p[i];
        for (int a = 0; a < 2; a++) {
            const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
            const trk_real own[3] = {tr->p[P(ip, ip)], tr->p[P(ip, iv)], tr->p[P(iv, iv)]};
            ab_kalman_step(own, r[a == 0 ? S(ZX, ZX) : S(ZY, ZY)], 0, &pr->ab[a]);
        }
        return pred_finish(t, scan, pr);
    }
    const trk_status st = ab_steady(t, scan, dt_us, dt);
    if (st != TRK_OK) return st;
    for (int i = 0; i < NX * NX; i++) pr->p[i] = 0;
    for (int a = 0; a < 2; a++) {
        const int ip = a == 0 ? X : Y, iv = a == 0 ? VX : VY;
        const trk_real own[3] = {tr->p[P(ip, ip)], tr->p[P(ip, iv)], tr->p[P(iv, iv)]};
        ab_axis(t, a, dt, r[a == 0 ? S(ZX, ZX) : S(ZY, ZY)], tr->n_hits, own, &pr->ab[a]);
        pr->x[ip] += dt * pr->x[iv];
        pr->p[P(ip, ip)] = pr->ab[a].pred[0];
        pr->p[P(ip, iv)] = pr->p[P(iv, ip)] = pr->ab[a].pred[1];
        pr->p[P(iv, iv)] = pr->ab[a].pred[2];
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
static trk_status ab_pda(struct pred *pr, struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    pda_weights(pr->pda, pr, set, out);
    return ab_update(pr, set);
}

#endif
