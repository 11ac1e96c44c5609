/* mc_stats.h - confidence intervals for the Monte Carlo tools (trk-sim).
 *
 *   mc_binom_ci    exact (Clopper-Pearson) interval of a binomial proportion:
 *                  lo = B^-1(a/2; k, n-k+1), hi = B^-1(1-a/2; k+1, n-k), with
 *                  lo = 0 at k = 0 and hi = 1 at k = n (a = 1 - level), from
 *                  the regularised incomplete beta function (continued
 *                  fraction, ~1e-13) and bisection
 *   mc_binom_accept  the exact two-sided acceptance interval [lo, hi] of
 *                  Binomial(n, p): P(X < lo) <= tail, P(X > hi) <= tail
 *   mc_mean_ci     mean and normal-approximation interval of iid values
 *                  (mean -+ z se, se = s / sqrt(n), z from the level)
 *   mc_mean_ci_t   the same with Student's t quantile of n - 1 degrees of
 *                  freedom (few samples, e.g. a mean over 10 seeds):
 *                  P(|T| <= t) = 1 - I_{nu/(nu+t^2)}(nu/2, 1/2), by bisection
 * Everything in double precision. */
#ifndef TRK_TOOLS_MC_STATS_H
#define TRK_TOOLS_MC_STATS_H

#include <stddef.h>

/* Regularised incomplete beta I_x(a, b), a, b > 0, x in [0, 1]. */
double mc_betai(double a, double b, double x);

/* Clopper-Pearson interval of k successes in n trials at level (e.g. 0.95). */
void mc_binom_ci(long k, long n, double level, double *lo, double *hi);

/* Acceptance interval of Binomial(n, p) with tail probability `tail` each side. */
void mc_binom_accept(long n, double p, double tail, long *lo, long *hi);

/* Two-sided standard normal quantile z with P(|Z| <= z) = level. */
double mc_z(double level);

/* Mean of x[0..n) and its interval at level; n >= 1 (n = 1: lo = hi = mean). */
void mc_mean_ci(const double *x, size_t n, double level, double *mean, double *lo, double *hi);

/* Two-sided Student t quantile t with P(|T| <= t) = level, nu > 0 degrees of freedom. */
double mc_t(double level, double nu);

/* Mean of x[0..n) and its Student t interval at level (nu = n - 1); n = 1:
 * lo = hi = mean; n = 0: all NaN. */
void mc_mean_ci_t(const double *x, size_t n, double level, double *mean, double *lo, double *hi);

#endif
