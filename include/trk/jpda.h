/* trk/jpda.h - joint association of several tracks on one scan: JPDA and
 * JIPDA marginals (CONVENTIONS "Joint association (JPDA / JIPDA)").
 *
 * A joint event gives each track at most one of its gated detections and each
 * detection at most one track. Its weight is the product over tracks of
 *   w_t0 = 1 - P_D P_G psi_t                        track t takes no detection
 *   w_tj = psi_t P_D N(nu_tj; 0, S_t) l^a(a_j) / lambda   t takes detection j
 * (psi_t the predicted existence, 1 for plain JPDA). The caller passes the
 * logarithms (ln w_tj = -inf for a detection outside t's gate), so weights
 * spanning hundreds of decades are fine. trk_jpda_marginals returns, over all
 * joint events, P(t <- j) and P(t <- none); each track's row sums to 1.
 *
 * Method. Tracks that share no gated detection are independent: clusters are
 * formed by union-find over the gate matrix, and each cluster is solved on
 * its own. A cluster of n_t tracks and n_d detections is solved EXACTLY by a
 * dynamic programme over the subsets of one side (2^k states, k = n_d or
 * n_t, at most TRK_JPDA_EXACT_BITS), processing the other side one element
 * at a time (the sum over joint events factorises that way; the idea of
 * Maskell et al.'s efficient hypothesis management, without recursion).
 * Over detection subsets, track t's marginals come from the programme over
 * the other tracks: n_t (n_t - 1) 2^n_d n_d multiply-adds; over track
 * subsets, one programme per gated pair: n_d^2 (n_t + 1) 2^n_t n_t. The
 * cheaper applicable one runs while it needs at most TRK_JPDA_MAX_WORK;
 * memory is 2^TRK_JPDA_EXACT_BITS reals of workspace.
 * Per track the weights are scaled so that the largest is 1, and every layer
 * of the programme is rescaled by its largest entry, so nothing overflows and
 * only events negligible at the working precision underflow.
 * Larger clusters use loopy belief propagation (Williams & Lau, "Approximate
 * evaluation of marginal association probabilities with belief propagation",
 * IEEE TAES 2014), which converges for this problem (their Thm. 1); it stops
 * when no message changes by more than 1e-6 relatively, or after
 * TRK_JPDA_LBP_MAX_ITER iterations, and its marginals are approximate (exact
 * for a cluster without cycles). Each use is counted in the report, so a user
 * sees when the approximation was taken.
 *
 * No heap, no recursion; the workspace is caller-owned and sized here. */
#ifndef TRK_JPDA_H
#define TRK_JPDA_H

#include <stddef.h>

#include "trk/config.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "trk/types.h"

/* Capacities TRK_JPDA_EXACT_BITS, TRK_JPDA_MAX_WORK, TRK_JPDA_LBP_MAX_ITER:
 * trk/config.h. */

/* One scan's association weights (see the top of this file). */
struct trk_jpda_scan {
    size_t n_tracks;            /* 0 .. TRK_MAX_TRACKS */
    size_t n_dets;              /* 0 .. TRK_MAX_DETECTIONS */
    const trk_real *log_w_miss; /* n_tracks: ln w_t0, finite (psi_t P_D P_G < 1) */
    const trk_real *log_w;      /* n_tracks x n_dets, row-major: ln w_tj; -inf outside the gate */
};

/* Caller-owned workspace (uninitialised is fine; nothing persists between calls). */
struct trk_jpda_work {
    trk_real dp[(size_t)1 << TRK_JPDA_EXACT_BITS];
    trk_real scale[TRK_MAX_TRACKS];             /* per track: max ln w */
    trk_real det_sum[TRK_MAX_DETECTIONS];       /* LBP: sum of track -> detection messages */
    unsigned short parent[TRK_MAX_TRACKS];      /* union-find over tracks */
    unsigned short cl_tracks[TRK_MAX_TRACKS];   /* members of the cluster being solved */
    unsigned short cl_dets[TRK_MAX_DETECTIONS];
    unsigned short det_owner[TRK_MAX_DETECTIONS]; /* first track gating each detection */
};

struct trk_jpda_report {
    size_t n_clusters;      /* clusters with at least one track */
    size_t n_exact;         /* of which solved exactly */
    size_t n_approx;        /* of which by loopy belief propagation */
    size_t largest_tracks;  /* tracks of the largest cluster */
    size_t largest_dets;    /* gated detections of the largest cluster */
    int lbp_iterations;     /* most iterations any LBP cluster took */
    int lbp_converged;      /* 1 when every LBP cluster met its tolerance */
};

/* Marginal association probabilities of every track:
 *   p_assoc[t * n_dets + j] = P(t <- j)   (0 outside t's gate)
 *   p_miss[t]               = P(t <- none)
 * rep may be NULL. TRK_E_ARG NULL pointer (arrays may be NULL when their
 * length is 0), TRK_E_CAPACITY n_tracks > TRK_MAX_TRACKS or n_dets >
 * TRK_MAX_DETECTIONS, TRK_E_NAN a NaN weight or a non-finite ln w_t0, TRK_E_RANGE
 * ln w_tj = +inf. Outputs untouched on error. */
TRK_NODISCARD trk_status trk_jpda_marginals(const struct trk_jpda_scan *scan, struct trk_jpda_work *work,
                                            trk_real *p_assoc, trk_real *p_miss,
                                            struct trk_jpda_report *rep);

/* One track's row of the scan weights from its predicted measurement:
 * log_w_row[j] = ln psi + ln(P_D N(nu_j; 0, S) l^a(a_j)) - ln lambda for the
 * detections in the gate (d2 <= gamma), -inf outside; *log_w_miss =
 * ln(1 - P_D P_G psi); d2 (n_dets outputs, may be NULL). pda gives P_D, P_G,
 * gamma and the parametric clutter density lambda > 0; z is n_dets x 2, log_lr
 * NULL for none. TRK_E_ARG, TRK_E_UNSUPPORTED nonparametric clutter or
 * lambda = 0, TRK_E_RANGE psi outside (0, 1], TRK_E_NAN non-finite input. */
TRK_NODISCARD trk_status trk_jpda_track_weights(const struct trk_pda *pda, trk_real psi,
                                                const struct trk_innovation *inn, size_t n_dets,
                                                const trk_real *z, const trk_real *log_lr, trk_real *log_w_row,
                                                trk_real *log_w_miss, trk_real *d2);

/* JIPDA posterior existence and the weights of the state update, conditional
 * on existence, for one track (CONVENTIONS):
 *   psi' = sum_j P(t <- j) + P(t <- none) psi (1 - P_D P_G) / (1 - P_D P_G psi)
 *   beta_j = P(t <- j) / psi',  beta_0 = P(t <- none) psi (1 - P_D P_G) / (1 - P_D P_G psi) / psi'
 * p_assoc is the track's row (n_dets values), beta gets n_dets + 1 values
 * ([beta_0, beta_1..beta_m]); psi = 1 gives plain JPDA (psi' = 1, beta = the
 * marginals). TRK_E_ARG NULL, TRK_E_NAN non-finite input, TRK_E_RANGE psi
 * outside (0, 1] or pd_pg outside (0, 1] or psi pd_pg = 1 with psi < 1. */
TRK_NODISCARD trk_status trk_jpda_existence(trk_real psi, trk_real pd_pg, const trk_real *p_assoc, size_t n_dets,
                                            trk_real p_miss, trk_real *psi_post, trk_real *beta);

#endif /* TRK_JPDA_H */
