/* track_filter_impl.h (private) - the track filter: the one interface
 * through which the scan's stages reach a track's motion model, and the one
 * place that chooses the model (filter_kind). Every track of a tracker runs
 * the same filter:
 *   FILTER_CV   the CV Kalman filter (filter_cv_impl.h), the default;
 *   FILTER_IMM  the IMM (filter_imm_impl.h; TRK_WITH_IMM, imm.n_models >= 1);
 *   FILTER_AB   the constant-gain alpha-beta filter (filter_ab_impl.h;
 *               TRK_WITH_ALPHA_BETA, params.filter = TRK_FILTER_ALPHA_BETA).
 * A build without a knob compiles none of its filter: filter_kind is then a
 * constant and the switches below fold.
 *
 * The operations, in the order a scan calls them for one track:
 *   filter_start        a new track's filter state, from its x and P
 *   filter_predict      the prediction to the scan time with its innovation
 *                       (struct pred: x, P, S with the sensor's R)
 *   filter_gate         the gated set from pair off on, with ln e_i per
 *                       detection (the track-detection likelihood)
 *   filter_pda          the PDA's own weights and the posterior with them
 *   filter_reweigh      a joint track's set again before its update (the
 *                       IMM's per-model weights; the others keep nothing)
 *   filter_update_beta  the posterior for given weights (the joint ones)
 *   filter_commit       the filter's own state into the track
 *   filter_merge_cov    the covariance the merge test weighs a track with
 * The combined estimate is always the track's x and P (CV layout), so the
 * stages that only read a track (covariance bound, merge, initiation's
 * slots, the report) need no filter.
 *
 * To add a filter: a filter_NAME_impl.h with these operations (it may use
 * track_gate_impl.h and track_pred_impl.h), a kind here and a case in each
 * switch, a params.filter value and its check in tracker_params.c; no stage
 * changes (docs/architecture.md "Where to change what").
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACK_FILTER_IMPL_H
#define TRK_TRACK_FILTER_IMPL_H

#include "filter_cv_impl.h"
#if TRK_WITH_IMM
#include "filter_imm_impl.h"
#endif
#if TRK_WITH_ALPHA_BETA
#include "filter_ab_impl.h"
#endif

enum filter_kind { FILTER_CV, FILTER_IMM, FILTER_AB };

/* The tracker's filter (the same for every track). */
static enum filter_kind filter_kind(const struct trk_tracker *t)
{
#if TRK_WITH_IMM
    if (t->params.imm.n_models > 0) return FILTER_IMM;
#endif
#if TRK_WITH_ALPHA_BETA
    if (t->params.filter == TRK_FILTER_ALPHA_BETA) return FILTER_AB;
#endif
    (void)t;
    return FILTER_CV;
}

/* A new track (x, P set) gets its filter's state. */
static void filter_start(const struct trk_tracker *t, struct trk_track *tr)
{
#if TRK_WITH_IMM
    imm_start(t, tr); /* with imm.n_models 0, a CV track of an IMM build: the IMM state cleared */
#else
    (void)t;
    (void)tr;
#endif
}

/* Track tr's prediction to the scan time into *pr, checked: TRK_OK, or why
 * it failed (the track is untouched). */
static trk_status filter_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                                 struct pred *pr)
{
    switch (filter_kind(t)) {
#if TRK_WITH_IMM
    case FILTER_IMM: return imm_predict(t, tr, scan, pr);
#endif
#if TRK_WITH_ALPHA_BETA
    case FILTER_AB: return ab_predict(t, tr, scan, pr);
#endif
    default: return cv_predict(t, tr, scan, pr);
    }
}

/* Its gated set with ln e_i from workspace pair off on: 1 when cut (the
 * pairs from off on could not hold it, see gate()), -1 on a numerical
 * failure (cannot happen), else 0. */
static int filter_gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                       const struct pred *pr, size_t off, struct trk_i_pda_set *set)
{
#if TRK_WITH_IMM
    if (filter_kind(t) == FILTER_IMM) {
        const int cut = imm_gate(t, tr, scan, pr, off, set);
        return imm_weights(t, scan, pr->pda, set, t->ws.cand + off, set->w) != TRK_OK ? -1 : cut;
    }
#endif
    return gate(t, tr, scan, pr, off, set);
}

/* The PDA over the gated set: *out, beta_i into set->w, the posterior over
 * pr->x, pr->p (checked). */
static trk_status filter_pda(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                             struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    switch (filter_kind(t)) {
#if TRK_WITH_IMM
    case FILTER_IMM: return imm_pda(t, scan, pr, set, out);
#endif
#if TRK_WITH_ALPHA_BETA
    case FILTER_AB: return ab_pda(pr, set, out);
#endif
    default: (void)scan; return cv_pda(pr, set, out);
    }
}

#if TRK_WITH_JOINT
/* A joint track's gated set (detections cand) once more before its update:
 * the filter's per-detection state that later tracks' gating overwrote
 * (the IMM's rho_mi; set->w, the marginals, stays). */
static trk_status filter_reweigh(struct trk_tracker *t, const struct trk_scan *scan, const struct pred *pr,
                                 const struct trk_i_pda_set *set, const uint16_t *cand)
{
#if TRK_WITH_IMM
    if (filter_kind(t) == FILTER_IMM) return imm_weights(t, scan, pr->pda, set, cand, NULL);
#endif
    (void)t;
    (void)scan;
    (void)pr;
    (void)set;
    (void)cand;
    return TRK_OK;
}

/* The posterior for given weights (set->w = beta_i, beta0: the joint
 * association's), over pr->x, pr->p, checked. */
static trk_status filter_update_beta(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                                     const struct trk_i_pda_set *set, trk_real beta0)
{
    switch (filter_kind(t)) {
#if TRK_WITH_IMM
    case FILTER_IMM: return imm_update(t, scan, set, beta0, pr);
#endif
#if TRK_WITH_ALPHA_BETA
    case FILTER_AB: return ab_update(pr, set);
#endif
    default: (void)t; (void)scan; return cv_update_beta(pr, set, beta0);
    }
}
#endif

/* The covariance of track tr that the merge test weighs its state with:
 * its P, or an IMM track's most probable model's (the combined P also holds
 * the spread between the models' estimates, which made the tracks of two
 * close targets pass for one). */
static const trk_real *filter_merge_cov(const struct trk_tracker *t, const struct trk_track *tr)
{
#if TRK_WITH_IMM
    if (filter_kind(t) == FILTER_IMM) {
        int best = 0;
        for (int m = 1; m < t->params.imm.n_models; m++)
            if (tr->imm.mu[m] > tr->imm.mu[best]) best = m;
        return tr->imm.p[best];
    }
#endif
    (void)t;
    return tr->p;
}

/* The accepted update's filter state into the track (its x, P, the
 * commit's): the IMM's models, and in an IMM build every track's manoeuvre
 * statistic. */
static void filter_commit(const struct trk_tracker *t, struct trk_track *tr, const struct trk_i_pda_set *set,
                          const struct pred *pr)
{
#if TRK_WITH_IMM
    tr->maneuver_d2 = maneuver_d2(set, &pr->inn);
    if (filter_kind(t) == FILTER_IMM) tr->imm = t->ws.imm.s;
#else
    (void)t;
    (void)tr;
    (void)set;
    (void)pr;
#endif
}

#endif
