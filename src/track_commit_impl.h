/* track_commit_impl.h (private) - the end of one track's update, shared
 * by the per-track and the joint association: the visibility (IPDA
 * existence) from the PDA's weights, the commit of an accepted update into
 * the track, and the look: what the scan told the track's tests.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACK_COMMIT_IMPL_H
#define TRK_TRACK_COMMIT_IMPL_H

#include "track_filter_impl.h"

/* Kennedy eqs 21-24 with the PDA weights: ln sum_i (g_D,i / rho) l_i =
 * ln sum_i e_i - ln P_D - ln lambda (e_i = P_D g_D,i l_i; lambda = 0: +inf,
 * a certain detection). */
static trk_status update_visibility(const struct trk_tracker *t, const struct trk_pda *pda,
                                    const struct trk_i_pda_set *set, const struct trk_i_pda_out *out,
                                    struct trk_visibility *vis)
{
    trk_real log_sum = trk_i_pda_log_sum_e(out);
    if (set->n > 0) {
        /* ln P_D and, for parametric clutter, ln lambda from trk_pda_init's logs */
        const trk_real log_pd = pda->log_pd_norm + TRK_REAL_C(0.5) * (trk_real)pda->params.nz * TRK_LN_2PI;
        const trk_real log_lambda = pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->log_e0_param - pda->log_miss
                                                                                 : trk_log(out->lambda);
        log_sum = out->lambda > 0 ? log_sum - log_pd - log_lambda : (trk_real)INFINITY;
    }
    return trk_visibility_update_log(&t->vis_model, vis, pda->params.pd, pda->params.gate_prob, log_sum);
}

/* Does a tentative track of posterior existence pv claim its gated
 * detection of weight beta (given existence), so that it starts no track?
 * With joint association and existence (JIPDA: pv beta is the probability
 * that the detection is this track's target, the other tracks weighed),
 * only one it more likely than not explains, pv beta >= 1/2: a weak
 * tentative track near a target (often a pair of one target detection and
 * one clutter point, its velocity wrong, its gate wide) then does not keep
 * the target's own detections from starting the pair that holds it.
 * Otherwise every gated one: per-track PDA weighs no other track, and
 * there the detections it left free started duplicates (trk-sim mtt
 * --family sonar, 40 seeds: GOSPA 270 -> 297 m at 20 per ping). */
static int tentative_claims(const struct trk_tracker *t, trk_real pv, trk_real beta)
{
    if (!t->params.track_visibility || t->params.association != TRK_ASSOC_JOINT) return 1;
    return pv * beta >= TRK_REAL_C(0.5);
}

/* The update is accepted: from here on the track changes. The posterior
 * (pr->x, pr->p), its visibility and beta0 into the track; its gated
 * detections (cand) start no track: a confirmed track's all, a tentative
 * one's those it claims. */
static void commit(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                   const struct trk_i_pda_set *set, const uint16_t *cand, const struct pred *pr,
                   const struct trk_visibility *vis, trk_real beta0)
{
    const int confirmed = tr->status == TRK_TRACK_CONFIRMED;
    const uint8_t mark = confirmed ? USED_CONFIRMED : USED_NO_START;
    for (size_t i = 0; i < set->n; i++)
        if (t->ws.used[cand[i]] < mark && (confirmed || tentative_claims(t, vis->pv, set->w[i])))
            t->ws.used[cand[i]] = mark;
    for (int i = 0; i < NX; i++) tr->x[i] = pr->x[i];
    for (int i = 0; i < NX * NX; i++) tr->p[i] = pr->p[i];
    tr->vis = *vis;
    tr->beta0_last = beta0;
    tr->time_us = scan->time_us;
    tr->n_gated_last = (uint16_t)set->n;
    filter_commit(t, tr, set, pr);
}

/* The clutter tests' inputs (Kennedy eqs 5-9, 13-15): the scan's detection
 * nearest the prediction (smallest d2 with the sensor's S), rho V_g of the
 * ellipse it encloses (rho the clutter density at the track, as its PDA
 * weights take it), and its amplitude (dB) against the scan's others
 * (workspace amp_db holds the amplitudes twice over, so the others of entry
 * k are the n_amp - 1 entries from k + 1). */
static void clutter_look(const struct trk_tracker *t, const struct trk_innovation *inn, trk_real rho,
                         struct trk_look *look)
{
    trk_real best = TRK_REAL_MAX;
    size_t jb = 0;
    for (size_t j = 0; j < t->ws.n_valid; j++) {
        const trk_real nu[NZ] = {t->ws.x[j] - inn->z_pred[ZX], t->ws.y[j] - inn->z_pred[ZY]};
        const trk_real d2 = trk_i_mahalanobis2(NZ, inn->s_chol_inv, nu);
        if (d2 < best || (d2 == best && t->ws.src[j] < t->ws.src[jb])) { /* ties: the first in scan order */
            best = d2;
            jb = j;
        }
    }
    look->has_nearest = 1;
    look->nearest = jb;
    look->rho_vg = rho * trk_gate_volume_inn(inn, best);
    if (t->ws.amp_pos[jb] >= 0) {
        const size_t k = (size_t)t->ws.amp_pos[jb];
        look->has_amp = 1;
        look->a_assoc_db = t->ws.amp_db[k];
        look->n_others = t->ws.n_amp - 1;
        look->a_others_db = t->ws.amp_db + k + 1;
    }
}

/* The gate-count check's ring (trk/tracker.h count_alpha): how many of the
 * gated set's detections lie in the outer half of the gate's area, gamma /
 * 2 < d2, d2 formed as gating forms it (the prediction's S, or S_j for a
 * detection with its own covariance, through their Cholesky factors; an
 * IMM track's from its combined prediction pr, and only inside that
 * ellipse: the expected count is of its area). Clutter spreads over the
 * gate, so half of it falls there; a target's own returns, however many (a
 * split echo, multipath), sit about its prediction, and only
 * sqrt(1 - P_G) - (1 - P_G) of each does. */
static int gate_ring_count(const struct pred *pr, const struct trk_i_pda_set *set, trk_real gamma)
{
    const trk_real half = gamma / 2;
    const struct trk_innovation *inn = pr->pp.inn;
    int n = 0;
    for (size_t i = 0; i < set->n; i++) {
        const trk_real nu[NZ] = {set->z[NZ * i + ZX] - inn->z_pred[ZX], set->z[NZ * i + ZY] - inn->z_pred[ZY]};
        trk_real d2 = (trk_real)INFINITY;
        if (i < set->n_shared) {
            d2 = trk_i_mahalanobis2(NZ, inn->s_chol_inv, nu);
        } else { /* S_j: SPD, the detection was gated with it */
            trk_real s[NZ * NZ], l_inv[NZ * NZ], log_det;
            trk_i_pda_own_s(&pr->pp, set->r_own + NZ * NZ * (i - set->n_shared), s);
            if (trk_i_pda_factor(NZ, s, l_inv, &log_det) == TRK_OK) d2 = trk_i_mahalanobis2(NZ, l_inv, nu);
        }
        n += d2 > half && d2 <= gamma; /* an IMM track's union of gates reaches beyond
                                          the combined ellipse, whose area V_G is */
    }
    return n;
}

/* ln L_t / L_s of the look of a track predicted at pr, gated set set
 * (workspace indices cand, weights given existence: set w normalised to
 * 1 - beta0): its target (P_D pd at the track; with a Rayleigh amplitude
 * model, Swerling I of the SNR that P_D gives at the threshold) against a
 * persistent scatterer there (P_s = persistent_pd, and its SNR). Either
 * source sits at the prediction and the rest of the gate is clutter alike,
 * so the position likelihoods and the clutter cancel, and
 *   L_s / L_t = beta_0 (1 - P_s P_G) / (1 - P_D P_G) + sum_i beta_i f_s(a_i) / f_t(a_i),
 *   f_x(a) = P_x p_x(a | above the threshold) = (2a / (P u_x)) e^(-a^2 / (P u_x)),
 * 1/u_x = ln P_x / ln pfa (Brekke eq 19's u = 1 + SNR; P the clutter's
 * power): f_s / f_t = (u_t / u_s) e^((a^2 / P)(1/u_t - 1/u_s)); a detection
 * without an amplitude: P_s / P_D. A gated detection of weight 0 (another
 * track's, or an echo so strong that its target weight underflowed) says
 * nothing of beta_i f_s / f_t, which may be large: where f_s / f_t > 1 the
 * look gives no evidence (0), rather than that of a miss; where it is at
 * most 1 its term is left out, a bound. The ratio may overflow (underflow)
 * the real type: -inf (+inf), certain, which the sum over the looks bounds
 * (existence_look, track_tests.c). 0 (no evidence) on a thinned scan,
 * whose raised threshold this does not model, and where P_D is not in
 * (pfa, 1). */
static trk_real persist_log_lr(const struct trk_tracker *t, const struct trk_scan *scan, const struct pred *pr,
                               const struct trk_i_pda_set *set, const uint16_t *cand, trk_real beta0)
{
    const struct trk_sensor_params *sp = t->ws.view.sp;
    const struct trk_amplitude *m = &sp->amplitude;
    const trk_real pd = pr->pd, ps = sp->persistent_pd, pg = pr->pda->params.gate_prob;
    const trk_real iu_t = trk_i_amplitude_inv_u(m, pd), iu_s = t->ws.persistent_inv_u, d = iu_t - iu_s;
    if (t->ws.pd_power != 1 || t->ws.pd_scale != 1 || !(iu_t > 0 && iu_t < 1)) return 0; /* P_D in (pfa, 1) */
    trk_real w_sum = 0;
    for (size_t i = 0; i < set->n; i++) w_sum += set->w[i];
    trk_real ratio = beta0 * (1 - ps * pg) / (1 - pd * pg);
    for (size_t i = 0; i < set->n; i++) {
        const trk_real b = w_sum > 0 ? set->w[i] / w_sum * (1 - beta0) : 0; /* beta_i given existence */
        trk_real a;
        const int has = scan_amplitude(scan, t->ws.src[cand[i]], &a);
        /* f_s / f_t (d = 0: one SNR, 1 at any amplitude; a^2 may be +inf) */
        const trk_real rho = has ? iu_s / iu_t * (d != 0 ? trk_exp(a * a / m->clutter_power * d) : 1) : ps / pd;
        if (b > 0) {
            ratio += b * rho;
        } else if (rho > 1) {
            return 0; /* its weight lost to the arithmetic or to another track: b rho unknown */
        }
    }
    return -trk_log(ratio);
}

/* What this scan told the track's tests: the one place a look is built
 * (the M/N test's first look at initiation apart). The gate-count ring only
 * for a tentative track whose existence confirmation checks it. */
static void build_look(const struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                       const struct pred *pr, const struct trk_i_pda_set *set, const uint16_t *cand,
                       const struct trk_i_pda_out *out, struct trk_look *look)
{
    look->seen = 1;
    look->detected = tr->n_gated_last > 0;
    look->sensor_id = scan->sensor_id;
    look->n_gated = (int)tr->n_gated_last;
    const trk_real lambda_vg = out->lambda * out->gate_volume;
    look->pfa_gate = -trk_expm1(-lambda_vg);
    look->n_ring = 0;
    look->n_ring_expected = look->n_expected_all = 0;
    if (tr->status == TRK_TRACK_TENTATIVE && t->params.confirm.method == TRK_CONFIRM_EXISTENCE &&
        t->params.confirm.u.existence.count_alpha > 0) {
        const trk_real miss = 1 - pr->pda->params.gate_prob; /* e^(-gamma/2) */
        look->n_ring = gate_ring_count(pr, set, pr->pda->gamma);
        look->n_ring_expected = lambda_vg / 2 + pr->pd * (trk_sqrt(miss) - miss);
        look->n_expected_all = lambda_vg + TRK_TARGET_RETURNS_MAX * pr->pd * pr->pda->params.gate_prob;
    }
    look->beta0 = out->beta0;
    look->persist_llr = 0;
    if (tr->status == TRK_TRACK_TENTATIVE && t->params.confirm.method == TRK_CONFIRM_EXISTENCE &&
        t->ws.persistent_inv_u > 0) /* a persistent-return description (with a Rayleigh model) */
        look->persist_llr = persist_log_lr(t, scan, pr, set, cand, out->beta0);
    look->has_nearest = 0;
    look->nearest = 0;
    look->rho_vg = 0;
    look->has_amp = 0;
    look->a_assoc_db = 0;
    look->n_others = 0;
    look->a_others_db = t->ws.amp_db;
    if (tr->status == TRK_TRACK_TENTATIVE && trk_i_confirm_needs_nearest(&t->params) && t->ws.n_valid > 0)
        clutter_look(t, &pr->inn, pr->pda->params.clutter_density, look); /* lambda at the track: its
                                                                             profile's and the map's */
}

/* A track the scan's sensor cannot see (P_D 0 at its prediction pr): its
 * prediction becomes its posterior (the filter's update with nothing
 * gated), its existence is only predicted, and its look says it was not
 * seen. As track_update's return: 0, 1 over the covariance bound, -1 on a
 * numerical failure (tr untouched). */
static int track_unseen(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan, struct pred *pr,
                        struct trk_look *look)
{
    struct trk_i_pda_set set;
    struct trk_i_pda_out out;
    (void)gate_begin(t, tr, pr->pda, 0, &set); /* an empty set */
    if (filter_pda(t, scan, pr, &set, &out) != TRK_OK) return -1;
    struct trk_visibility vis = tr->vis;
    if (t->params.track_visibility &&
        trk_visibility_update_posterior(&t->vis_model, &vis, trk_visibility_predict(&t->vis_model, &vis)) != TRK_OK)
        return -1;
    commit(t, tr, scan, &set, t->ws.cand, pr, &vis, out.beta0);
    build_look(t, tr, scan, pr, &set, t->ws.cand, &out, look);
    look->seen = 0;
    return over_covariance_bound(pr->bound_m2, tr->p);
}

#endif
