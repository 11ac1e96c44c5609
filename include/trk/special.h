/** @file
 * trk/special.h - special functions the library needs at run time:
 * chi-square distribution for integer degrees of freedom, F distribution for
 * even degrees of freedom.
 *
 * Accuracy: in double, relative error of cdf and sf below 1e-13 wherever the
 * value is above 1e-300 (each tail is computed directly, never as 1 - other
 * tail when it is the small one). */
#ifndef TRK_SPECIAL_H
#define TRK_SPECIAL_H

#include "trk/types.h"

/** @{ */
/** P(chi2(dof) <= x) and P(chi2(dof) > x), dof >= 1, x >= 0.
 * Return NaN for dof < 1, x < 0 or x NaN. */
trk_real trk_chi2_cdf(int dof, trk_real x);
trk_real trk_chi2_sf(int dof, trk_real x);
/** @} */

/** x with P(chi2(dof) <= x) = p, 0 < p < 1 (safeguarded Newton on the smaller
 * tail in log space). TRK_E_RANGE for p outside (0,1), TRK_E_ARG for dof < 1
 * or dof > 1000. */
TRK_NODISCARD trk_status trk_chi2_inv(int dof, trk_real p, trk_real *x);

/** @{ */
/** F distribution with EVEN degrees of freedom (the F of Kennedy's clutter
 * amplitude test: dof1 = 2K, dof2 = 2 sum N_k). With a = dof2/2, b = dof1/2,
 * x = dof2 / (dof2 + dof1 z) and n = a + b - 1:
 *   P(F >= z) = P(Binomial(n, x) >= a) = sum_{m<b} C(n,m) (1-x)^m x^(n-m)
 *   P(F <= z) = P(Binomial(n, 1-x) >= b)
 * Each tail is a finite sum of positive terms (b and a terms), summed in
 * scaled linear arithmetic (no per-term log or exp). The shorter sum is
 * computed directly; the other tail is 1 minus it, or its own sum when that
 * is more accurate (a tail near 1 is never subtracted from 1). Relative
 * error: a few ulp for the shorter sum (the clutter test's P(F >= z) has
 * b = K <= 32 terms); for a long direct sum about (n ln(1 + r) + terms) ulp:
 * the cdf with dof2 = 1000 is within 3e-13, with dof2 = 4000 within 1.1e-11
 * (measured against 50-digit mpmath).
 * Return NaN for odd dof, dof < 2 or > 2000000, z < 0 or NaN; z = +inf gives
 * sf 0, cdf 1. */
trk_real trk_f_sf(int dof1, int dof2, trk_real z);
trk_real trk_f_cdf(int dof1, int dof2, trk_real z);
/** @} */

/** z with P(F(dof1, dof2) >= z) = p_upper, 0 < p_upper < 1 (even dof as above;
 * closed form for dof1 = 2, else safeguarded Newton on ln P(F >= e^u)).
 * TRK_E_ARG NULL or bad dof, TRK_E_RANGE p_upper outside (0, 1),
 * TRK_E_DIVERGED no convergence (not seen). */
TRK_NODISCARD trk_status trk_f_inv_sf(int dof1, int dof2, trk_real p_upper, trk_real *z);

#endif
