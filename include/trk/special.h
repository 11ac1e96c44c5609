/* trk/special.h - special functions the library needs at run time:
 * chi-square distribution for integer degrees of freedom.
 *
 * Accuracy: in double, relative error of cdf and sf below 1e-13 wherever the
 * value is above 1e-300 (each tail is computed directly, never as 1 - other
 * tail when it is the small one). */
#ifndef TRK_SPECIAL_H
#define TRK_SPECIAL_H

#include "trk/types.h"

/* P(chi2(dof) <= x) and P(chi2(dof) > x), dof >= 1, x >= 0.
 * Return NaN for dof < 1, x < 0 or x NaN. */
trk_real trk_chi2_cdf(int dof, trk_real x);
trk_real trk_chi2_sf(int dof, trk_real x);

/* x with P(chi2(dof) <= x) = p, 0 < p < 1 (safeguarded Newton on the smaller
 * tail in log space). TRK_E_RANGE for p outside (0,1), TRK_E_ARG for dof < 1
 * or dof > 1000. */
TRK_NODISCARD trk_status trk_chi2_inv(int dof, trk_real p, trk_real *x);

#endif
