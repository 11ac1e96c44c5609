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

/* The finite sums' terms grow like y^j/j! and overflow float (y = 400,
 * dof = 50) or even double (y = 2000, dof = 1000) before e^-y brings them
 * back: the running term is rescaled (its log moved to lscale) above this. */
#if TRK_REAL_IS_FLOAT
#define CHI2_BIG TRK_REAL_C(1e20)
#else
#define CHI2_BIG 1e200
#endif

/* Upper tail by the finite sums (used for y >= a + 1). */
static trk_real q_finite(int dof, trk_real y)
{
    if (dof % 2 == 0) {
        int k = dof / 2;
        trk_real term = 1, sum = 1, lscale = 0;
        for (int j = 1; j < k; j++) {
            term *= y / (trk_real)j;
            sum += term;
            if (term > CHI2_BIG) {
                lscale += trk_log(term);
                sum /= term;
                term = 1;
            }
        }
        return trk_exp(-y + lscale + trk_log(sum));
    } else {
        int k = (dof - 1) / 2;
        trk_real sq = trk_sqrt(y);
        trk_real q = trk_erfc(sq);
        if (k > 0) {
            /* term_j = y^(j+1/2)/Gamma(j+3/2); term_0 = sqrt(y)/Gamma(3/2) = 2 sqrt(y/pi) */
            trk_real term = 2 * sq / trk_sqrt(TRK_PI), sum = term, lscale = 0;
            for (int j = 1; j < k; j++) {
                term *= y / ((trk_real)j + TRK_REAL_C(0.5));
                sum += term;
                if (term > CHI2_BIG) {
                    lscale += trk_log(term);
                    sum /= term;
                    term = 1;
                }
            }
            q += trk_exp(-y + lscale + trk_log(sum));
        }
        return q;
    }
}

static int args_ok(int dof, trk_real x) { return dof >= 1 && x >= 0; }

/* ln of the smallest positive trk_real, minus a margin: an upper tail whose
 * bound e^-y y^a falls below it is 0 in this arithmetic. */
#if TRK_REAL_IS_FLOAT
#define LOG_TAIL_ZERO TRK_REAL_C(-110.0)
#else
#define LOG_TAIL_ZERO (-750.0)
#endif

/* Is the upper tail Q(a, y) below every positive trk_real (y >= a + 1)?
 * Q <= e^-y y^(a-1) / Gamma(a) (1 + (a-1)/(y-a+1) + ...) <= e^-y y^a for
 * y >= a + 1; x = +inf or a huge x would otherwise overflow the finite
 * sums' terms into inf - inf = NaN. */
static int tail_is_zero(trk_real a, trk_real y) { return !(y <= TRK_REAL_MAX) || -y + a * trk_log(y) < LOG_TAIL_ZERO; }

trk_real trk_chi2_cdf(int dof, trk_real x)
{
    if (!args_ok(dof, x)) return (trk_real)NAN;
    if (x == 0) return 0;
    trk_real a = (trk_real)dof / 2, y = x / 2;
    if (y < a + 1) return trk_exp(log_p_series(a, y));
    if (tail_is_zero(a, y)) return 1;
    return 1 - q_finite(dof, y);
}

trk_real trk_chi2_sf(int dof, trk_real x)
{
    if (!args_ok(dof, x)) return (trk_real)NAN;
    if (x == 0) return 1;
    trk_real a = (trk_real)dof / 2, y = x / 2;
    if (y < a + 1) return 1 - trk_exp(log_p_series(a, y));
    if (tail_is_zero(a, y)) return 0;
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

/* ------------------------------------------------------------------ F
 * Even degrees of freedom: with a = dof2/2, b = dof1/2 (integers),
 * n = a + b - 1 and r = (1 - x)/x = dof1 z / dof2,
 *   P(F >= z) = x^n sum_{m=0}^{b-1} C(n, m) r^m,   x^n = (1 + r)^-n,
 * a finite sum of positive terms (the binomial form of the regularised
 * incomplete beta I_x(a, b) for integer a, b). The lower tail is the same sum
 * with a and b swapped and r -> 1/r. */

#if TRK_REAL_IS_FLOAT
#define F_BIG TRK_REAL_C(1e12)  /* rescale the running term above this */
#define F_RLIN TRK_REAL_C(1e12) /* above this ratio, sum in logs */
#else
#define F_BIG 1e100
#define F_RLIN 1e100
#endif

/* ln sum_{m=0}^{b-1} C(n, m) r^m, n = a + b - 1, r >= 0 finite. The terms
 * are unimodal in m; the running term is rescaled (its log moved to lscale)
 * before it could overflow; r above F_RLIN (each term dwarfs the previous
 * ones) is summed normalised to the latest term. */
static trk_real log_binom_poly(long a, long b, trk_real r)
{
    const trk_real n1 = (trk_real)(a + b); /* n + 1 */
    trk_real lscale = 0, term = 1, sum = 1;
    if (r <= F_RLIN) {
        for (long m = 1; m < b; m++) {
            term *= (n1 - (trk_real)m) / (trk_real)m * r; /* C(n,m)/C(n,m-1) r */
            sum += term;
            if (term > F_BIG) {
                lscale += trk_log(term);
                sum /= term;
                term = 1;
            }
        }
    } else {
        const trk_real lr = trk_log(r);
        for (long m = 1; m < b; m++) {
            const trk_real lf = trk_log((n1 - (trk_real)m) / (trk_real)m) + lr;
            lscale += lf;
            sum = sum * trk_exp(-lf) + 1;
        }
    }
    return lscale + trk_log(sum);
}

/* ln P(Binomial(a + b - 1, x) >= a), r = (1 - x)/x >= 0 finite. */
static trk_real log_binom_upper(long a, long b, trk_real r)
{
    return -(trk_real)(a + b - 1) * trk_log1p(r) + log_binom_poly(a, b, r);
}

static int f_dof_ok(int d) { return d >= 2 && d <= 2000000 && d % 2 == 0; }

/* Upper (upper = 1) or lower tail. The sum with fewer terms is computed
 * directly; the other tail is 1 - that one when that is the more accurate
 * way (error estimates in ulp below), else summed directly too. */
static trk_real f_tail(int dof1, int dof2, trk_real z, int upper)
{
    if (!f_dof_ok(dof1) || !f_dof_ok(dof2) || !(z >= 0)) return (trk_real)NAN;
    if (z == 0) return upper ? 1 : 0;
    const long a = dof2 / 2, b = dof1 / 2;
    const trk_real r = (trk_real)dof1 * z / (trk_real)dof2;      /* (1 - x)/x */
    const trk_real rinv = (trk_real)dof2 / ((trk_real)dof1 * z); /* x/(1 - x) */
    if (isinf(r)) return upper ? 0 : 1;
    if (isinf(rinv)) return upper ? 1 : 0;
    /* P(F >= z) = P(Bin(n, x) >= a): b terms; P(F <= z) = P(Bin(n, 1-x) >= b): a terms */
    const int short_upper = b <= a;
    trk_real t = trk_exp(short_upper ? log_binom_upper(a, b, r) : log_binom_upper(b, a, rinv));
    if (t > 1) t = 1;
    if (short_upper == upper) return t;
    /* 1 - t carries ~ t/(1-t) ulp; the long sum ~ n ln(1+r) + (its terms) ulp
     * (the large exponent n ln(1+r) cancels against the sum's scale) */
    const trk_real lr_long = trk_log1p(upper ? r : rinv);
    const trk_real err_long = (trk_real)(a + b - 1) * lr_long + (trk_real)(upper ? b : a);
    if (t < 1 && t <= err_long * (1 - t)) return 1 - t;
    t = trk_exp(upper ? log_binom_upper(a, b, r) : log_binom_upper(b, a, rinv));
    return t < 1 ? t : 1;
}

trk_real trk_f_sf(int dof1, int dof2, trk_real z) { return f_tail(dof1, dof2, z, 1); }

trk_real trk_f_cdf(int dof1, int dof2, trk_real z) { return f_tail(dof1, dof2, z, 0); }

trk_status trk_f_inv_sf(int dof1, int dof2, trk_real p, trk_real *z)
{
    if (!z || !f_dof_ok(dof1) || !f_dof_ok(dof2)) return TRK_E_ARG;
    if (!(p > 0 && p < 1)) return TRK_E_RANGE;
    const long a = dof2 / 2, b = dof1 / 2;
    const trk_real fa = (trk_real)a, fb = (trk_real)b;
    const trk_real lp = trk_log(p);
    if (b == 1) { /* P(F >= z) = (1 + r)^-a, r = z / a */
        *z = fa * trk_expm1(-lp / fa);
        return TRK_OK;
    }
    /* f(u) = ln P(F >= e^u) - ln p, decreasing in u; r = (b/a) e^u */
    const trk_real ratio = fb / fa;
#if TRK_REAL_IS_FLOAT
    const trk_real umax = TRK_REAL_C(80.0);
#else
    const trk_real umax = 700;
#endif
    trk_real lo = 0, hi = 0, f = log_binom_upper(a, b, ratio) - lp;
    if (f > 0) { /* root above u = 0 */
        for (hi = 1;; hi *= 2) {
            if (hi > umax) return TRK_E_DIVERGED;
            if (log_binom_upper(a, b, ratio * trk_exp(hi)) - lp <= 0) break;
            lo = hi;
        }
    } else if (f < 0) {
        for (lo = -1;; lo *= 2) {
            if (lo < -umax) return TRK_E_DIVERGED;
            if (log_binom_upper(a, b, ratio * trk_exp(lo)) - lp >= 0) break;
            hi = lo;
        }
    } else {
        *z = 1;
        return TRK_OK;
    }
    const trk_real lbeta = trk_lgamma(fa) + trk_lgamma(fb) - trk_lgamma(fa + fb);
    trk_real u = TRK_REAL_C(0.5) * (lo + hi);
    for (int it = 0; it < 200; it++) {
        const trk_real r = ratio * trk_exp(u);
        const trk_real l1p = trk_log1p(r);
        const trk_real ls = -(fa + fb - 1) * l1p + log_binom_poly(a, b, r);
        f = ls - lp;
        if (f == 0) break;
        if (f > 0) lo = u;
        else hi = u;
        /* d ln P / du = -x^a (1-x)^b / (B(a,b) P), ln x = -ln(1+r),
         * ln(1-x) = ln r - ln(1+r) */
        const trk_real d = -trk_exp(-fa * l1p + fb * (trk_log(r) - l1p) - lbeta - ls);
        trk_real un = u - f / d;
        if (!(un > lo && un < hi)) un = TRK_REAL_C(0.5) * (lo + hi);
        const trk_real tol = 4 * TRK_REAL_EPS * (trk_fabs(u) > 1 ? trk_fabs(u) : 1);
        if (trk_fabs(un - u) <= tol || hi - lo <= tol) {
            u = un;
            *z = trk_exp(u);
            return TRK_OK;
        }
        u = un;
    }
    if (f == 0) {
        *z = trk_exp(u);
        return TRK_OK;
    }
    return TRK_E_DIVERGED;
}
