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
 *   mc_ratio_ci    a ratio of sums over iid units (sum num / sum den: e.g.
 *                  the mean error over the scans of all runs, per-run sums
 *                  over per-run counts) and its normal-approximation
 *                  interval by linearisation (the delta method): se^2 =
 *                  sum (num_i - r den_i)^2 / (n (n - 1) dbar^2); equal den
 *                  give mc_mean_ci of num / den
 *   mc_sort, mc_quantile_sorted  empirical quantiles (linear interpolation
 *                  between order statistics, Hyndman & Fan type 7, R's
 *                  default): the distribution of per-run values
 *   mc_hist_bin, mc_hist_mode  a histogram of equal bins over [lo, lo + n w):
 *                  the bin of a value, the fullest bin (the error pdfs of
 *                  brekke-errpdf)
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

/* r = sum num / sum den over n units and its interval at level; n = 0 (or
 * sum den = 0): NaN; n = 1: lo = hi = r. */
void mc_ratio_ci(const double *num, const double *den, size_t n, double level, double *r, double *lo, double *hi);

/* x[0..n) in ascending order (NaN not allowed). */
void mc_sort(double *x, size_t n);

/* The p-quantile (0 <= p <= 1) of the ascending x[0..n): with h = (n - 1) p,
 * x[floor h] + (h - floor h)(x[floor h + 1] - x[floor h]); n = 0: NaN. */
double mc_quantile_sorted(const double *x, size_t n, double p);

/* The bin of x in a histogram of n_bins bins of width w from lo: bin i holds
 * lo + i w <= x < lo + (i + 1) w; n_bins for x >= lo + n_bins w (overflow),
 * -1 for x < lo or NaN. w > 0, n_bins >= 1. */
long mc_hist_bin(double x, double lo, double w, long n_bins);

/* The index of the largest of counts[0..n_bins) (the first of equal ones);
 * -1 when all are 0 (or n_bins = 0). */
long mc_hist_mode(const double *counts, long n_bins);

#endif
