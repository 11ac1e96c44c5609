/* q2_amp_rayleigh.h - Rayleigh clutter / Swerling I target amplitude closed
 * forms for the q2 importance sampler (q2_is.h), in normalised units (clutter
 * power P = 1, target mean power d = SNR).
 *
 * TO BE REPLACED by the functions of include/trk/amplitude.h once that module
 * exists: this is the one place in the q2 code that states these formulas.
 *
 * CONVENTIONS "Amplitude models" (Brekke eqs 6, 8, 19), power P, d:
 *   clutter survival S0(a) = exp(-a^2/P), threshold t^2 = -P ln P_FA
 *   P_D = S1(t) = exp(-t^2/(P+d)) = P_FA^(P/(P+d))              (the ROC)
 *   ln l^a(a) = ln(P_FA/P_D) + ln(P/(P+d)) + a^2 d/(P(P+d))
 * Thresholded samples (truncated survival x = -ln(S(a)/S(t)) ~ Exp(1)):
 *   clutter a^2 = t^2 + P x,  target a^2 = t^2 + (P+d) x
 * so that, with t^2 d/(P(P+d)) = ln(P_D/P_FA),
 *   clutter ln l^a = ln(P/(P+d)) + x d/(P+d)
 *   target  ln l^a = ln(P/(P+d)) + x d/P.
 */
#ifndef TRK_Q2_AMP_RAYLEIGH_H
#define TRK_Q2_AMP_RAYLEIGH_H

#include <stddef.h>

#include "q2_is.h"

struct q2_amp_rayleigh {
    double snr;        /* d/P, linear */
    double pfa;        /* P_FA */
    double pd;         /* P_D = S1(t) */
    double t2;         /* threshold t^2 (P = 1) */
    double ln_p_pd;    /* ln(P/(P+d)) */
    double slope_c;    /* d/(P+d): clutter ln l^a per unit x */
    double slope_t;    /* d/P: target ln l^a per unit x */
};

/* 0, or -1 for snr_db outside [-30, 60] or pfa outside (0, 1) (or NaN). */
int q2_amp_rayleigh_init(struct q2_amp_rayleigh *r, double snr_db, double pfa);

/* P_D at false-alarm probability pfa (the Rayleigh/Swerling I ROC). */
double q2_amp_rayleigh_pd(double snr_db, double pfa);

/* ln l^a(a) for an amplitude a >= t (normalised units). */
double q2_amp_rayleigh_log_lr(const struct q2_amp_rayleigh *r, double a);

/* Amplitude a >= t with truncated survival exp(-x) (target != 0: target law). */
double q2_amp_rayleigh_inv_sf(const struct q2_amp_rayleigh *r, int target, double x);

/* The q2_is sampler (ctx = struct q2_amp_rayleigh): out[i] = ln l^a(a_i),
 * a_i drawn from u[i] in (0, 1) by x = -ln u[i]. */
void q2_amp_rayleigh_sample(const void *ctx, int target, size_t n, const double *u, double *out);

/* A sampler over *r (r must outlive the sampler). */
struct q2_amp_sampler q2_amp_rayleigh_sampler(const struct q2_amp_rayleigh *r);

#endif
