/* filter_cv_impl.h (private) - the CV Kalman filter as a track filter
 * (track_filter_impl.h): prediction with the CV model of process_noise_q
 * (trk_i_cv2_predict; docs/conventions.md "State and covariance layout"),
 * gating of its one Gaussian prediction (gate()), and the PDA update (pda_impl.h, the same code
 * as trk_pda_update, inlined with the CV model's constant dimensions so its
 * small matrix loops unroll) with its own weights or with given ones (the
 * joint association's).
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_FILTER_CV_IMPL_H
#define TRK_FILTER_CV_IMPL_H

#include "track_gate_impl.h"
#include "track_pred_impl.h"

/* CV prediction to the scan time, checked (finite, variances > 0; its
 * positive definiteness is checked once it is known to be the posterior),
 * and its innovation (S = H P H' + R of the scan's sensor; TRK_E_NOT_SPD
 * when S is not positive definite). */
static trk_status cv_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                             struct pred *pr)
{
    const trk_real dt = (trk_real)(scan->time_us - tr->time_us) * TRK_REAL_C(1e-6);
    for (int i = 0; i < NX; i++) pr->x[i] = tr->x[i];
    for (int i = 0; i < NX * NX; i++) pr->p[i] = tr->p[i];
    trk_i_cv2_predict(dt, t->params.process_noise_q, pr->x, pr->p);
    return pred_finish(t, scan, pr);
}

/* The PDA over the gated set: *out, beta_i into set->w, the posterior over
 * pr->x, pr->p (checked). */
static trk_status cv_pda(struct pred *pr, struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    const trk_status st = trk_i_pda_run(pr->pda, &pr->pp, set, out);
    /* the PDA checked a posterior it formed; with nothing gated it is the
     * prediction: check that one here (one factorisation per track) */
    return st == TRK_OK && set->m_gated == 0 ? trk_i_spd(NX, pr->p) : st;
}

#if TRK_WITH_JOINT
/* The posterior for given weights (set->w = beta_i, beta0: the joint
 * association's), over pr->x, pr->p, checked. */
static trk_status cv_update_beta(struct pred *pr, const struct trk_i_pda_set *set, trk_real beta0)
{
    return set->n > 0 ? trk_i_pda_run_beta(&pr->pp, set, beta0) : trk_i_spd(NX, pr->p);
}
#endif

#endif
