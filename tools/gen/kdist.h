/* kdist.h - high-accuracy K-distributed clutter / Swerling I target amplitude
 * model for the offline tools (trk-tablegen, the amp_* vector kinds, tests and
 * benchmarks). Double precision always, whatever the library's trk_real.
 *
 * Convention (docs/conventions.md "Amplitude models", amplitude.vec header): given the
 * texture eta, a is Rayleigh with E[a^2|eta] = eta (clutter) or eta + d
 * (target + clutter); eta ~ Gamma(shape nu, scale b), clutter power P = nu b,
 * SNR = d / P. Everything here works in normalised units P = 1 (amplitudes in
 * units of sqrt(P)); callers scale a by 1/sqrt(P).
 *
 * With v = eta/P ~ Gamma(nu, mean 1), A = a^2, D = SNR and w = v (clutter) or
 * v + D (target):
 *   S(a)  = E[exp(-A/w)]                          (Brekke eqs 48-49, corrected)
 *   p(a)  = 2a E[w^-1 exp(-A/w)]                  (eqs 7, 9, corrected)
 *   l^a(a) = (pfa/pd) p1(a)/p0(a)                 (eqs 19-20)
 * Each expectation is one integral over s = ln v of exp(phi(s)),
 *   phi(s) = nu (s - e^s + 1) + C_nu - m ln w - A/w,  C_nu = nu ln nu - nu - ln Gamma(nu),
 * evaluated in log space by adaptive Gauss-Kronrod (7/15) with breakpoints at
 * the integrand's peaks (the positive roots of a cubic in e^s) scaled to their
 * widths, so sharp peaks at large a, two-peaked target integrands, nu < 1 and
 * large nu are all resolved. Relative accuracy of the expectations ~1e-14.
 */
#ifndef TRK_KDIST_H
#define TRK_KDIST_H

struct kdist {
    double nu;    /* K shape, > 0 */
    double snr;   /* D = d/P, linear, >= 0 */
    double c_nu;  /* nu ln nu - nu - lgamma(nu), accurate for large nu */
};

/* 0 on success, -1 for nu <= 0, nu > 1e6, non-finite or snr_db out of [-50, 80]. */
int kdist_init(struct kdist *k, double nu, double snr_db);

/* The direct evaluation's range: A = (a/sqrt(P))^2 <= KDIST_MAX_A, i.e. a
 * normalised amplitude up to 1e8. Beyond it the log-moments are of order
 * 2 sqrt(nu A) > 2e8 and their difference (ln l^a) keeps no digits (at 1e20
 * it came out 0, at 1e50 NaN, and at 1e100 the quadrature hung): every function below returns NaN (or -1) there instead. */
#define KDIST_MAX_A 1e16

/* ln E[w^-m exp(-A/w)], w = v (target == 0) or v + D (target == 1), m in 0..3,
 * 0 <= A <= KDIST_MAX_A (else NaN). */
double kdist_log_moment(const struct kdist *k, int target, int m, double A);

/* ln S(a) and ln p(a) (a > 0 for the density), normalised units. */
double kdist_log_sf(const struct kdist *k, int target, double a);
double kdist_log_pdf(const struct kdist *k, int target, double a);

/* Threshold t with S0(t) = pfa (0 < pfa < 1); 0 or -1 (bad pfa / no convergence). */
int kdist_threshold(const struct kdist *k, double pfa, double *t);

/* a >= t with -ln(S(a)/S(t)) = x (x >= 0); also da/dx when dadx != NULL. */
int kdist_inv_sf(const struct kdist *k, int target, double t, double x, double *a, double *dadx);

/* ln l^a(a) = ln(pfa/pd) + ln p1(a) - ln p0(a), and its derivative with
 * respect to A = a^2 when dlda2 != NULL. */
double kdist_log_lr(const struct kdist *k, double pfa, double pd, double a, double *dlda2);

/* The limit of ln l^a as a -> infinity: ln(pfa/pd) + nu D. */
double kdist_log_lr_inf(const struct kdist *k, double pfa, double pd);

#endif
