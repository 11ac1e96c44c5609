/* track_pred_impl.h (private) - one track's prediction as every filter
 * leaves it for the stages: checked, its view for the PDA and its
 * innovation with the scan sensor's R (pred_finish); the covariance bound
 * on it; the PDA's weights for a filter that updates by itself; and the
 * survey's manoeuvre statistic of an update.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACK_PRED_IMPL_H
#define TRK_TRACK_PRED_IMPL_H

#include "tracker_internal.h"

/* Is the position uncertainty of covariance p over the bound bound_m2
 * (0: none)? */
static int over_covariance_bound(trk_real bound_m2, const trk_real *p)
{
    return bound_m2 > 0 && p[P(X, X)] + p[P(Y, Y)] > bound_m2;
}

/* The PDA's constants of the scan's sensor with P_D pd in (0, 1] and
 * clutter density lambda > 0 instead of its own (trk_pda_init's, for one
 * track: the profiles). */
static void pda_with(const struct trk_pda *sensor, trk_real pd, trk_real lambda, struct trk_pda *out)
{
    *out = *sensor;
    out->params.pd = pd;
    out->params.clutter_density = lambda;
    out->log_pd_norm = trk_log(pd) - TRK_REAL_C(0.5) * (trk_real)NZ * TRK_LN_2PI;
    out->log_miss = trk_log1p(-pd * sensor->params.gate_prob);
    out->log_e0_param = trk_log(lambda) + out->log_miss;
}

/* What the scan's sensor is to the track predicted at pr->x (see struct
 * pred): R, P_D and lambda there in its PDA constants, the covariance bound (ratio^2 tr R,
 * with R at the prediction for a polar sensor). */
static void pred_sensor(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr)
{
    const struct trk_pda *sensor = &t->pda[scan->sensor_id];
    pr->r = sensor_r_at(t, scan, pr->x[X], pr->x[Y], t->ws.track_r);
    pr->pd = sensor_pd_at(t, scan, pr->x[X], pr->x[Y]);
    const trk_real lambda = sensor_lambda_at(t, scan, pr->x[X], pr->x[Y]);
    pr->pda = sensor;
    if (pr->pd > 0 && (pr->pd != sensor->params.pd || lambda != sensor->params.clutter_density)) {
        pda_with(sensor, pr->pd, lambda, &t->ws.track_pda);
        pr->pda = &t->ws.track_pda;
    }
    const trk_real ratio = t->params.max_pos_sigma_ratio;
    pr->bound_m2 = ratio * ratio * (pr->r[S(ZX, ZX)] + pr->r[S(ZY, ZY)]);
}

/* Can the scan's sensor see the predicted track (P_D > 0 there)? A track it
 * cannot see is not gated: its existence is only predicted and its tests
 * are not stepped. */
static int pred_seen(const struct pred *pr) { return pr->pd > 0; }

/* The prediction pr->x, pr->p checked, the sensor at it (pred_sensor), its
 * view for the PDA, and its innovation. A track the sensor cannot see is
 * not gated, and its innovation only gives its update the form of one
 * with nothing gated: there it is formed with the sensor's own R, since a
 * polar R far outside the coverage (cross-range sigma r sigma_b against
 * sigma_r) may be too ill-conditioned to factor, and a track that coasts
 * out of sight must not end as a numerical failure. */
static trk_status pred_finish(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr)
{
    const trk_status st = trk_i_pda_check(NX, pr->x, pr->p);
    if (st != TRK_OK) return st;
    pred_sensor(t, scan, pr);
    if (!pred_seen(pr)) pr->r = t->r[scan->sensor_id];
    const struct trk_i_pda_pred pp = {NX, NZ, trk_cv2_h, trk_i_cv2_sel(), pr->r, pr->x, pr->p, pr->pht, &pr->inn};
    pr->pp = pp;
    return trk_i_innovation_sel(NX, NZ, trk_cv2_h, trk_i_cv2_sel(), pr->r, pr->x, pr->p, pr->pht, &pr->inn);
}

/* The PDA's association weights alone, for a filter that forms its own
 * posterior from them (IMM, alpha-beta): the clutter terms into *out, the
 * gated set's ln e_i (set->w) normalised into beta_i, and beta0 (1 when
 * nothing was gated). */
#if TRK_WITH_IMM || TRK_WITH_ALPHA_BETA
static void pda_weights(const struct trk_pda *pda, const struct pred *pr, struct trk_i_pda_set *set,
                        struct trk_i_pda_out *out)
{
    trk_i_pda_clutter(pda, &pr->pp, set, out);
    if (set->m_gated > 0) {
        trk_i_pda_find_w_max(set);
        out->beta0 = trk_i_pda_normalise(trk_i_pda_log_e0(pda, out->lambda), set->n, set->w, set->w_max, out);
    }
}
#endif

#if TRK_WITH_IMM
/* The survey's manoeuvre statistic (eqs 3.11-3.13) of the update: d2 of
 * the innovation given a detection, sum_i beta_i nu_i / sum_i beta_i (the
 * sum, not 1 - beta0: beta0 near 1 keeps only its rounding), with the
 * prediction's S of the sensor's R; 0 when nothing was gated or every
 * detection's weight is 0. */
static trk_real maneuver_d2(const struct trk_i_pda_set *set, const struct trk_innovation *inn)
{
    trk_real nu[NZ] = {0, 0}, sum = 0;
    for (size_t i = 0; i < set->n; i++) {
        sum += set->w[i];
        nu[ZX] += set->w[i] * (set->z[NZ * i + ZX] - inn->z_pred[ZX]);
        nu[ZY] += set->w[i] * (set->z[NZ * i + ZY] - inn->z_pred[ZY]);
    }
    if (!(sum > 0)) return 0;
    nu[ZX] /= sum;
    nu[ZY] /= sum;
    return trk_i_mahalanobis2(NZ, inn->s_chol_inv, nu);
}
#endif

#endif
