/** @file
 * trk/jpda.h - joint association of several tracks on one scan: JPDA and
 * JIPDA marginals (docs/conventions.md "Joint association (JPDA / JIPDA)").
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
 * formed by union-find over the gated pairs (work in proportion to the pairs,
 * not to tracks x detections), and each cluster is solved on its own; a
 * cluster of one track in closed form (its PDA weights), of two tracks in
 * closed form too: P(a <- j) ~ w_aj (w_o0 + sum_{k != j} w_ok), the other
 * track's sum without j as its part before j plus its part after j (no
 * subtraction), O(pairs). A cluster of n_t >= 3 tracks and n_d detections is solved EXACTLY by a
 * dynamic programme over the subsets of one side (2^k states, k = n_d or
 * n_t, at most TRK_JPDA_EXACT_BITS), processing the other side one element
 * at a time (the sum over joint events factorises that way; the idea of
 * Maskell et al.'s efficient hypothesis management, without recursion).
 * Over detection subsets, track t's marginals come from the programme over
 * the other tracks: about n_t (n_t - 1) 2^n_d (n_d + 2) operations; over
 * track subsets, one programme per gated pair: about n_d^2 (n_t + 1)
 * (2^n_t (n_t + 1) + n_t + 8) (the per-layer costs counted). The
 * cheaper applicable one runs while it needs at most TRK_JPDA_MAX_WORK and
 * the call's exact programmes together at most TRK_JPDA_SCAN_WORK;
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
#include <stdint.h>

#include "trk/config.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "trk/types.h"

/* Capacities TRK_JPDA_EXACT_BITS, TRK_JPDA_MAX_WORK, TRK_JPDA_LBP_MAX_ITER,
 * TRK_MAX_GATED_PAIRS: trk/config.h. */

/** One scan's association weights, sparse (the form a tracker has): track t's
 * gated detections are the pairs [first[t], first[t+1]), each with its
 * detection det[k] (strictly increasing within a track, < n_dets) and its
 * ln w_tj = w[k] (finite). n_pairs = first[n_tracks] <= TRK_MAX_GATED_PAIRS.
 * The solver overwrites w (with the scaled linear weights: one exponential
 * per pair, and no copy). */
struct trk_jpda_pairs {
    size_t n_tracks;            /**< 0 .. TRK_MAX_TRACKS */
    size_t n_dets;              /**< 0 .. TRK_MAX_DETECTIONS */
    const uint16_t *first;      /**< n_tracks + 1 offsets, first[0] = 0 */
    const uint16_t *det;        /**< n_pairs */
    trk_real *w;                /**< n_pairs: in ln w_tj, then overwritten */
    const trk_real *log_w_miss; /**< n_tracks: ln w_t0, finite (psi_t P_D P_G < 1) */
};

/** The solver's caller-owned scratch (uninitialised is fine; nothing persists
 * between calls): clusters and the exact programme or the LBP sums. */
struct trk_jpda_solver {
    union {
        trk_real dp[(size_t)1 << TRK_JPDA_EXACT_BITS]; /**< exact: the subset programme */
        struct {                                       /**< LBP, per detection: */
            trk_real top[TRK_MAX_DETECTIONS];          /**< the largest track -> detection message */
            trk_real rest[TRK_MAX_DETECTIONS];         /**< the sum of the others */
        } lbp;
    } u;  /**< exact programme or LBP sums, per cluster */
    trk_real miss[TRK_MAX_TRACKS];                /**< per track: w_t0 scaled by its largest weight */
    uint16_t parent[TRK_MAX_TRACKS];              /**< union-find over tracks, then each track's cluster */
    uint16_t tr_first[TRK_MAX_TRACKS + 1];        /**< cluster c's tracks: tracks[tr_first[c] ..] */
    uint16_t det_first[TRK_MAX_TRACKS + 1];       /**< and its detections: dets[det_first[c] ..] */
    uint16_t tracks[TRK_MAX_TRACKS];  /**< tracks in cluster order */
    uint16_t dets[TRK_MAX_DETECTIONS];  /**< detections in cluster order */
    union {                                       /**< per detection: */
        uint16_t local[TRK_MAX_DETECTIONS];       /**< first gating track, then index in its cluster */
        uint16_t lbp_top[TRK_MAX_DETECTIONS];     /**< LBP: the pair of its largest message */
    } det;  /**< per-detection indices */
};

/** The dense interface's workspace: the solver and the sparse copy of the scan. */
struct trk_jpda_work {
    struct trk_jpda_solver solver;  /**< clusters and their solution */
    uint16_t first[TRK_MAX_TRACKS + 1];  /**< per track: offset of its first pair (sparse copy) */
    uint16_t det[TRK_MAX_GATED_PAIRS];  /**< per pair: detection index */
    trk_real w[TRK_MAX_GATED_PAIRS];  /**< per pair: weight */
    trk_real p_pair[TRK_MAX_GATED_PAIRS];  /**< per pair: association probability */
};

/** One scan's association weights, dense (the reference vectors' form). */
struct trk_jpda_scan {
    size_t n_tracks;            /**< 0 .. TRK_MAX_TRACKS */
    size_t n_dets;              /**< 0 .. TRK_MAX_DETECTIONS */
    const trk_real *log_w_miss; /**< n_tracks: ln w_t0, finite (psi_t P_D P_G < 1) */
    const trk_real *log_w;      /**< n_tracks x n_dets, row-major: ln w_tj; -inf outside the gate */
};

/** What one joint-association solution did: clusters and how they were solved. */
struct trk_jpda_report {
    size_t n_clusters;      /**< clusters with at least one track */
    size_t n_exact;         /**< of which solved exactly */
    size_t n_approx;        /**< of which approximately: by loopy belief propagation,
                               or with floored weights (n_floored) */
    size_t largest_tracks;  /**< tracks of the largest cluster */
    size_t largest_dets;    /**< gated detections of the largest cluster */
    int lbp_iterations;     /**< most iterations any LBP cluster took */
    int lbp_converged;      /**< 1 when every LBP cluster met its tolerance */
    size_t n_floored;       /**< clusters whose every joint event underflowed the
                               arithmetic (a track's weights spanning more than
                               its range, about e^745 in double, e^103 in float):
                               solved again with each weight raised to at least
                               TRK_REAL_MIN^(1 / (n_t + 1)), n_t its tracks, so
                               that no event vanishes; approximate (in n_approx) */
};

/** Marginal association probabilities of every gated pair and track, from
 * the sparse weights: p_pair[k] = P(t <- det[k]) for pair k of track t,
 * p_miss[t] = P(t <- none); each track's values sum to 1. rep may be NULL.
 * TRK_E_ARG NULL pointer (arrays may be NULL when their length is 0), or
 * offsets that do not increase from 0, or detections not strictly
 * increasing within a track or >= n_dets; TRK_E_CAPACITY n_tracks >
 * TRK_MAX_TRACKS, n_dets > TRK_MAX_DETECTIONS or n_pairs >
 * TRK_MAX_GATED_PAIRS; TRK_E_NAN a non-finite weight. Outputs and
 * pairs->w untouched on error. The tracker's joint association
 * (trk/tracker.h) calls this. */
TRK_NODISCARD trk_status trk_jpda_solve(const struct trk_jpda_pairs *pairs, struct trk_jpda_solver *solver,
                                        trk_real *p_pair, trk_real *p_miss, struct trk_jpda_report *rep);

/** Marginal association probabilities of every track:
 *   p_assoc[t * n_dets + j] = P(t <- j)   (0 outside t's gate)
 *   p_miss[t]               = P(t <- none)
 * rep may be NULL. TRK_E_ARG NULL pointer (arrays may be NULL when their
 * length is 0), TRK_E_CAPACITY n_tracks > TRK_MAX_TRACKS or n_dets >
 * TRK_MAX_DETECTIONS or more gated pairs than TRK_MAX_GATED_PAIRS, TRK_E_NAN a
 * NaN weight or a non-finite ln w_t0, TRK_E_RANGE ln w_tj = +inf. Outputs
 * untouched on error. The sparse copy into work, then trk_jpda_solve. */
TRK_NODISCARD trk_status trk_jpda_marginals(const struct trk_jpda_scan *scan, struct trk_jpda_work *work,
                                            trk_real *p_assoc, trk_real *p_miss,
                                            struct trk_jpda_report *rep);

/** One track's row of the scan weights from its predicted measurement:
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

/** JIPDA posterior existence and the weights of the state update, conditional
 * on existence, for one track (docs/conventions.md):
 *   psi' = sum_j P(t <- j) + P(t <- none) psi (1 - P_D P_G) / (1 - P_D P_G psi)
 *   beta_j = P(t <- j) / psi',  beta_0 = P(t <- none) psi (1 - P_D P_G) / (1 - P_D P_G psi) / psi'
 * p_assoc is the track's row (n_dets values), beta gets n_dets + 1 values
 * ([beta_0, beta_1..beta_m]); psi = 1 gives plain JPDA (psi' = 1, beta = the
 * marginals). psi' is computed as 1 - P(t <- none) (1 - psi) / (1 - P_D P_G
 * psi) when it is 1/2 or more, so rounding never takes it above 1; when every
 * term underflows (psi tiny) psi' = 0 and beta_0 = 1. TRK_E_ARG NULL,
 * TRK_E_NAN non-finite input, TRK_E_RANGE psi outside (0, 1] or pd_pg outside
 * (0, 1] or psi pd_pg = 1 with psi < 1; outputs untouched on error. */
TRK_NODISCARD trk_status trk_jpda_existence(trk_real psi, trk_real pd_pg, const trk_real *p_assoc, size_t n_dets,
                                            trk_real p_miss, trk_real *psi_post, trk_real *beta);

#endif /* TRK_JPDA_H */
