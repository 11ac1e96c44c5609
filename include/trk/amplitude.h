/** @file
 * trk/amplitude.h - amplitude likelihood of thresholded detections (PDAFAI)
 * and inverse-CDF amplitude sampling; Kennedy's dB amplitude model.
 *
 * docs/conventions.md "Amplitude models" (Brekke eqs 6-9, 19-20, 39-49): given the
 * texture eta, an amplitude a (linear envelope) is Rayleigh with
 * E[a^2|eta] = eta (clutter) or eta + d (Swerling I target + clutter).
 *   Rayleigh clutter of power P:  S0(a) = exp(-a^2/P),  S1(a) = exp(-a^2/(P+d))
 *   K clutter, shape nu:          eta ~ Gamma(nu, scale P/nu);  S0, S1, p0, p1
 *                                 are integrals over eta (no closed form for S1)
 *   SNR = d/P, snr_db = 10 log10 SNR.
 *   threshold t: S0(t) = pfa;   P_D = S1(t)
 *   l^a(a) = (pfa/P_D) p1(a)/p0(a), a >= t                     (eqs 19-20)
 *   truncated survival S^a(a) = S(a)/S(t); x = -ln S^a(a) ~ Exp(1)  (eqs 41, 46-47)
 *
 * A model is either
 *   - Rayleigh, closed form (trk_amplitude_init_rayleigh, or a Rayleigh table):
 *       t^2 = -P ln pfa,  P_D = pfa^(1/(1+SNR)),
 *       ln l^a(a) = ln(pfa/P_D) - ln(1+SNR) + (a^2/P) SNR/(1+SNR),
 *       a(x) = sqrt(t^2 + P x) (clutter), sqrt(t^2 + P (1+SNR) x) (target);
 *   - a view on an amplitude table made by `trk-tablegen amp` (K clutter needs
 *     integrals the firmware does not evaluate). The table is used in place:
 *     it must outlive the model.
 *
 * AMPLITUDE TABLE (kind TRK_TABLE_KIND_AMP, kind version 1; see trk/table.h
 * for the container). Amplitudes in the table are normalised, u = a/sqrt(P).
 *   parameters: model (int, enum trk_amp_model), nu, snr_db, pfa,
 *     clutter_power (P), threshold (t, amplitude units), pd, log_lr_limit
 *     (K only: ln l^a as a -> inf, ln(pfa/P_D) + nu SNR), x_max, grid (int,
 *     enum trk_amp_grid), generator_version (int); optional measured errors
 *     err_log_lr (max abs error of ln l^a on [t, a_max]) and err_inv_sf (max
 *     relative error of a(x) on [0, x_max]).
 *   section TRK_AMP_SECTION_LOG_LR: one linear axis over s = ln(u)
 *     (variable TRK_TABLE_VAR_LN_AMP) from ln(t/sqrt P) to ln(a_max/sqrt P),
 *     a_max = the larger of the clutter and target amplitudes at x = x_max;
 *     cells (ln l^a, d ln l^a / ds); cubic Hermite in s (error measured:
 *     ~h^4, see docs/library.md). Beyond the last node (probability < e^-x_max under
 *     either hypothesis) ln l^a relaxes to its limit as a power of a:
 *       L(s) = L_inf - (L_inf - L_N) exp(-k (s - s_N)),  k = L'_N / (L_inf - L_N),
 *     continuous with continuous slope at s_N; when k <= 0 (the curve moves
 *     away from its limit there) the last value is held.
 *   sections TRK_AMP_SECTION_INV_SF_CLUTTER / _TARGET: a(x) for x in [0, x_max]
 *     (variable TRK_TABLE_VAR_X), either
 *       grid uniform:   linear axis from 0, cells (u^2, d u^2/dx), cubic
 *                       Hermite in x (u^2 is nearly linear in x: Rayleigh
 *                       exactly); beyond x_max the tangent line of u^2;
 *       grid geometric: Brekke eqs 43-45, explicit x nodes at amplitudes
 *                       t + A (B^p - 1)/(B - 1) (A = 0.25, last 100 sqrt P),
 *                       cells u, piecewise linear in x (the paper's scheme);
 *                       beyond the last node the last segment extended.
 *   Checks at init (TRK_E_TABLE_CORRUPT unless said otherwise): kind amp
 *   (TRK_E_TABLE_KIND), kind version (TRK_E_TABLE_VERSION), every parameter
 *   present and in range, section shapes as above, log l^a axis starting at
 *   ln(t/sqrt P), a(x) nodes starting at t and strictly increasing (with
 *   positive slopes), Rayleigh tables agreeing with the closed form, and
 *   bounds that keep every lookup finite (|node values and slopes| <= 1e12,
 *   |ln u| <= 700 on the ln l^a axis, x_max <= 1e6, clutter_power <= 1e30).
 */
#ifndef TRK_AMPLITUDE_H
#define TRK_AMPLITUDE_H

#include "trk/table.h"
#include "trk/types.h"

/** Version of the amplitude sections' layout in a table file (trk/table.h); another version is refused. */
#define TRK_AMP_TABLE_VERSION 1u

/** Largest threshold over the clutter amplitude scale, t / sqrt(P), an
 * amplitude table may carry (Rayleigh at P_FA 1e-300 is 26; K tails need
 * more): a larger one is refused as corrupt. */
#define TRK_AMP_MAX_NORM_THRESHOLD TRK_REAL_C(1e6)

/** Clutter and target law of an amplitude model. */
enum trk_amp_model {
    TRK_AMP_RAYLEIGH = 1,   /**< Rayleigh clutter, Swerling I target */
    TRK_AMP_K = 2           /**< K-distributed clutter (shape nu), Swerling I target */
};

/** Which law an amplitude follows (inverse-CDF sampling). */
enum trk_amp_source {
    TRK_AMP_CLUTTER = 0,
    TRK_AMP_TARGET = 1      /**< target + clutter */
};

/** Section ids of an amplitude table file (trk/table.h). */
enum trk_amp_section {
    TRK_AMP_SECTION_LOG_LR = 1,
    TRK_AMP_SECTION_INV_SF_CLUTTER = 2,
    TRK_AMP_SECTION_INV_SF_TARGET = 3
};

/** Node spacing of an inverse-survival curve. */
enum trk_amp_grid {
    TRK_AMP_GRID_UNIFORM = 1,    /**< uniform in x, cubic Hermite of a^2 */
    TRK_AMP_GRID_GEOMETRIC = 2   /**< Brekke eqs 43-45, piecewise linear */
};

/** One inverse-survival curve (private: use trk_amplitude_inv_sf). */
struct trk_amp_inv_curve {
    const trk_real *data;       /**< uniform: (u^2, du^2/dx) per node; geometric: u */
    struct trk_table_axis axis; /**< the x axis */
    /** @{ */
    trk_real h, inv_h;          /**< uniform: node step in x */
    /** @} */
};

/** Caller-owned model. The documented fields may be read; the rest are
 * private. Valid only after a successful init. */
struct trk_amplitude {
    int model;                  /**< enum trk_amp_model */
    int tabulated;              /**< 1: ln l^a and a(x) from a table; 0: closed form */
    trk_real clutter_power;     /**< P (amplitude units squared) */
    trk_real snr_db;            /**< target power over clutter power, dB */
    trk_real pfa;               /**< S0(threshold) */
    trk_real nu;                /**< K shape (0 for Rayleigh) */
    trk_real threshold;         /**< t, amplitude units */
    trk_real pd;                /**< S1(t) */
    /* private */
    trk_real snr;               /**< SNR, linear */
    /** @{ */
    trk_real lr0, lr1;          /**< Rayleigh: ln l^a = lr0 + lr1 a^2 */
    /** @} */
    trk_real t2;                /**< t^2 */
    /** @{ ln sqrt(P) and sqrt(P): the clutter amplitude scale */
    trk_real ln_sqrt_p, sqrt_p;
    /** @} */
    const trk_real *llr;        /**< (L, dL/ds) per node */
    uint32_t llr_n;  /**< nodes of the ln l^a table */
    /** @{ the ln l^a table's axis, s = ln(a / sqrt(P)): first and last node, node step and its inverse */
    trk_real llr_lo, llr_hi, llr_h, llr_inv_h;
    /** @} */
    /** @{ ln l^a beyond the last node: its limit and the exponential rate at which it is approached */
    trk_real llr_limit, llr_tail_rate;
    /** @} */
    struct trk_amp_inv_curve inv[2];  /**< inverse-survival curves of clutter [TRK_AMP_CLUTTER] and target [TRK_AMP_TARGET] */
    uint32_t built;             /**< set by the init functions only (trk_amplitude_check) */
};

/** TRK_OK when *m was built by trk_amplitude_init_rayleigh or
 * trk_amplitude_init_table (and not changed since in a way that breaks its
 * invariants); TRK_E_ARG for NULL or a model filled by hand, whose use could
 * read through its table pointers. The tracker checks every sensor's model
 * with it at init. */
TRK_NODISCARD trk_status trk_amplitude_check(const struct trk_amplitude *m);

/** Rayleigh clutter of power clutter_power > 0 and a Swerling I target of
 * snr_db in [-100, 100] dB, threshold at false-alarm probability pfa in
 * (0, 1). TRK_E_ARG NULL m, TRK_E_NAN non-finite input, TRK_E_RANGE out of
 * range. *m untouched on error. */
TRK_NODISCARD trk_status trk_amplitude_init_rayleigh(struct trk_amplitude *m, trk_real clutter_power,
                                                     trk_real snr_db, trk_real pfa);

/** The model of a parsed amplitude table (trk_table_parse). Statuses: see
 * "Checks at init" above; TRK_E_ARG for NULL pointers. *m untouched on error. */
TRK_NODISCARD trk_status trk_amplitude_init_table(struct trk_amplitude *m, const struct trk_table *t);

/** @{ */
/** Threshold t (amplitude units) and P_D = S1(t); NaN for a NULL model. */
trk_real trk_amplitude_threshold(const struct trk_amplitude *m);
trk_real trk_amplitude_pd(const struct trk_amplitude *m);
/** @} */

/** ln l^a(a) of a detection with amplitude a (Brekke eqs 19-20).
 * TRK_E_NAN a NaN or infinite, TRK_E_RANGE a < 0 or a < threshold (not a
 * detection of this model) or ln l^a beyond the real type (Rayleigh:
 * a^2 / P above ~1e308 in double, 3e38 in float), TRK_E_ARG NULL pointers. */
TRK_NODISCARD trk_status trk_amplitude_log_lr(const struct trk_amplitude *m, trk_real a, trk_real *log_lr);

/** ln l^a(a) of a Rayleigh model whose target is seen with P_D pd at the
 * model's threshold, in place of the model's own SNR: a P_D that falls
 * with range (a sensor's P_D profile) is a target SNR that falls with
 * range. Eq 8 solved for the SNR, 1 + SNR = u = ln pfa / ln pd, in eq 19:
 *   ln l^a(a) = (1 - 1/u) (a^2 - t^2) / P - ln u,
 * equal to trk_amplitude_log_lr at pd = the model's P_D.
 * TRK_E_UNSUPPORTED a tabulated model (no closed form), TRK_E_NAN pd or a
 * not finite, TRK_E_RANGE pd outside (pfa, 1) (no positive SNR gives it),
 * a < 0 or below the threshold, or ln l^a beyond the real type, TRK_E_ARG
 * NULL pointers. */
TRK_NODISCARD trk_status trk_amplitude_log_lr_at_pd(const struct trk_amplitude *m, trk_real pd, trk_real a,
                                                    trk_real *log_lr);

/** Inverse-CDF sampling (Brekke eqs 41-47): the amplitude a >= t with
 * -ln(S(a)/S(t)) = x, for x ~ Exp(1) (e.g. x = -ln U, U uniform in (0, 1]).
 * source: enum trk_amp_source. TRK_E_NAN x not finite, TRK_E_RANGE x < 0,
 * TRK_E_ARG NULL pointer or bad source. */
TRK_NODISCARD trk_status trk_amplitude_inv_sf(const struct trk_amplitude *m, int source, trk_real x,
                                              trk_real *a);

/** The inverse of trk_amplitude_inv_sf: x = -ln(S(a)/S(t)) >= 0 of an
 * amplitude a >= t under the law of `source`, so that a threshold raised
 * from t to a has P_FA = pfa e^-x (clutter) and P_D = pd e^-x (target)
 * (Brekke eqs 41, 46-47; the survey's adaptive thresholding). Rayleigh:
 * x = (a^2 - t^2) / Q, Q = P or P (1 + SNR); a table: its a(x) curve
 * inverted by bisection (at most 64 doublings of the bracket and 64
 * halvings, to the real type's resolution). TRK_E_ARG NULL pointer or bad
 * source, TRK_E_NAN a not finite, TRK_E_RANGE a < t or beyond the curve's
 * reach (x > 2^64). */
TRK_NODISCARD trk_status trk_amplitude_log_sf(const struct trk_amplitude *m, int source, trk_real a, trk_real *x);

/** Monte Carlo of thresholded detections (e.g. the q2 estimator of the
 * tools): log_lr[i] = ln l^a(a_i) of the amplitude a_i drawn from the law of
 * `source` by inverse CDF at x[i] (the composition of trk_amplitude_inv_sf
 * and trk_amplitude_log_lr, equal to it up to rounding, without forming a:
 * Rayleigh ln l^a is affine in x; a table gives ln(a/sqrt P) = ln(u^2)/2
 * from its a(x) curve). x and log_lr may be the same array; n may be 0. TRK_E_ARG NULL pointer (n > 0) or bad
 * source, TRK_E_NAN an x[i] not finite, TRK_E_RANGE an x[i] < 0 (nothing
 * written) or a result not finite (log_lr written). */
TRK_NODISCARD trk_status trk_amplitude_sample_log_lr(const struct trk_amplitude *m, int source, size_t n,
                                                     const trk_real *x, trk_real *log_lr);

/** Kennedy's amplitude model in dB (Kennedy 2008 eqs 11, 27, 31): clutter
 * peaks above the threshold a_min are exponential with mean theta_A,
 *   f_A(a) = exp(-(a - a_min)/(theta_A - a_min)) / (theta_A - a_min),
 * the target's SNR is Gaussian (untruncated, as printed) with predicted mean
 * mu_A and innovation variance s_A^2,
 *   g_A(a) = exp(-(a - mu_A)^2 / (2 s_A^2)) / sqrt(2 pi s_A^2). */
struct trk_amp_db_params {
    trk_real a_min_db;          /**< detection threshold SNR a_min (dB) */
    trk_real theta_db;          /**< mean SNR of clutter peaks above it, > a_min (dB) */
    trk_real mu_db;             /**< predicted target SNR mean (dB) */
    trk_real s2_db2;            /**< target SNR innovation variance, > 0 (dB^2) */
};

/** ln g_A(a_db) - ln f_A(a_db). TRK_E_ARG NULL pointer, TRK_E_NAN non-finite
 * input, TRK_E_RANGE theta_db <= a_min_db, s2_db2 <= 0 or a_db < a_min_db. */
TRK_NODISCARD trk_status trk_amplitude_db_log_lr(const struct trk_amp_db_params *p, trk_real a_db,
                                                 trk_real *log_lr);

#endif
