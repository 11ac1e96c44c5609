/* special.c - chi-square distribution for integer degrees of freedom.
 *
 * With a = dof/2 and y = x/2 the cdf is the regularised lower incomplete gamma
 * P(a, y). For y < a + 1 the series P = e^-y y^a sum_n y^n / Gamma(a+n+1) has
 * positive terms and converges fast; otherwise the upper tail Q is a finite sum
 * of positive terms for integer or half-integer a:
 *   even dof: Q = e^-y sum_{j<a} y^j/j!
 *   odd dof:  Q = erfc(sqrt y) + e^-y sum_{j<a-1/2} y^(j+1/2)/Gamma(j+3/2).
 * Whichever tail is computed directly is the small or moderate one, so neither
 * loses digits to cancellation. */
#include "trk/special.h"

/* ln of the lower tail series (y < a + 1). */
static trk_real log_p_series(trk_real a, trk_real y)
{
    /* term_n = y^n / ((a+1)(a+2)...(a+n)); P = e^-y y^a / Gamma(a+1) sum term_n */
    trk_real sum = 1, term = 1;
    for (int n = 1; n < 10000; n++) {
        term *= y / (a + (trk_real)n);
        sum += term;
        if (term < sum * TRK_REAL_EPS * TRK_REAL_C(0.25)) break;
    }
    return -y + a * trk_log(y) - trk_lgamma(a + 1) + trk_log(sum);
}

/* Upper tail by the finite sums (used for y >= a + 1). */
static trk_real q_finite(int dof, trk_real y)
{
    if (dof % 2 == 0) {
        int k = dof / 2;
        trk_real term = 1, sum = 1;
        for (int j = 1; j < k; j++) {
            term *= y / (trk_real)j;
            sum += term;
        }
        return trk_exp(-y + trk_log(sum));
    } else {
        int k = (dof - 1) / 2;
        trk_real sq = trk_sqrt(y);
        trk_real q = trk_erfc(sq);
        if (k > 0) {
            /* term_j = y^(j+1/2)/Gamma(j+3/2); term_0 = sqrt(y)/Gamma(3/2) = 2 sqrt(y/pi) */
            trk_real term = 2 * sq / trk_sqrt(TRK_PI), sum = term;
            for (int j = 1; j < k; j++) {
                term *= y / ((trk_real)j + TRK_REAL_C(0.5));
                sum += term;
            }
            q += trk_exp(-y + trk_log(sum));
        }
        return q;
    }
}

static int args_ok(int dof, trk_real x) { return dof >= 1 && x >= 0; }

trk_real trk_chi2_cdf(int dof, trk_real x)
{
    if (!args_ok(dof, x)) return (trk_real)NAN;
    if (x == 0) return 0;
    trk_real a = (trk_real)dof / 2, y = x / 2;
    if (y < a + 1) return trk_exp(log_p_series(a, y));
    return 1 - q_finite(dof, y);
}

trk_real trk_chi2_sf(int dof, trk_real x)
{
    if (!args_ok(dof, x)) return (trk_real)NAN;
    if (x == 0) return 1;
    trk_real a = (trk_real)dof / 2, y = x / 2;
    if (y < a + 1) return 1 - trk_exp(log_p_series(a, y));
    return q_finite(dof, y);
}

/* chi2 density */
static trk_real chi2_pdf(int dof, trk_real x)
{
    trk_real a = (trk_real)dof / 2;
    return trk_exp((a - 1) * trk_log(x) - x / 2 - a * trk_log(TRK_REAL_C(2.0)) - trk_lgamma(a));
}

trk_status trk_chi2_inv(int dof, trk_real p, trk_real *x)
{
    if (!x) return TRK_E_ARG;
    if (dof < 1 || dof > 1000) return TRK_E_ARG;
    if (!(p > 0 && p < 1)) return TRK_E_RANGE;
    if (dof == 2) { /* closed form */
        *x = -2 * trk_log1p(-p);
        return TRK_OK;
    }
    /* Work on the smaller tail t in log space: f(x) = ln tail(x) - ln t. */
    const int upper = p > TRK_REAL_C(0.5);
    const trk_real lt = upper ? trk_log1p(-p) : trk_log(p);
    trk_real lo = 0, hi = (trk_real)dof + 10;
    for (;;) { /* grow hi until it brackets the root */
        trk_real f = upper ? trk_log(trk_chi2_sf(dof, hi)) - lt : lt - trk_log(trk_chi2_cdf(dof, hi));
        if (f < 0 || hi > TRK_REAL_C(1e6)) break;
        lo = hi;
        hi *= 2;
    }
    trk_real xc = TRK_REAL_C(0.5) * (lo + hi);
    for (int it = 0; it < 200; it++) {
        trk_real tail = upper ? trk_chi2_sf(dof, xc) : trk_chi2_cdf(dof, xc);
        trk_real f = trk_log(tail) - lt;
        /* upper tail decreases in x, lower tail increases */
        if ((f > 0) == upper) lo = xc;
        else hi = xc;
        trk_real d = chi2_pdf(dof, xc) / tail; /* |d ln tail / dx| */
        trk_real step = upper ? f / d : -f / d;
        trk_real xn = xc + step;
        if (!(xn > lo && xn < hi)) xn = TRK_REAL_C(0.5) * (lo + hi);
        if (trk_fabs(xn - xc) <= 4 * TRK_REAL_EPS * xc) {
            xc = xn;
            break;
        }
        xc = xn;
    }
    *x = xc;
    return TRK_OK;
}
