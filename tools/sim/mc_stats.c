/* mc_stats.c - confidence intervals (mc_stats.h). */
#include "mc_stats.h"

#include <math.h>
#include <stdlib.h>

/* Continued fraction of I_x(a, b) (modified Lentz). */
static double betacf(double a, double b, double x)
{
    const double tiny = 1e-300;
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    if (fabs(d) < tiny) d = tiny;
    d = 1 / d;
    double h = d;
    for (int m = 1; m <= 10000; m++) {
        const double m2 = 2.0 * m;
        double aa = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
        d = 1 + aa * d;
        if (fabs(d) < tiny) d = tiny;
        c = 1 + aa / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1 / d;
        h *= d * c;
        aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
        d = 1 + aa * d;
        if (fabs(d) < tiny) d = tiny;
        c = 1 + aa / c;
        if (fabs(c) < tiny) c = tiny;
        d = 1 / d;
        const double del = d * c;
        h *= del;
        if (fabs(del - 1) < 1e-15) break;
    }
    return h;
}

double mc_betai(double a, double b, double x)
{
    if (!(x > 0)) return 0;
    if (!(x < 1)) return 1;
    const double lbt = lgamma(a + b) - lgamma(a) - lgamma(b) + a * log(x) + b * log1p(-x);
    if (x < (a + 1) / (a + b + 2)) return exp(lbt) * betacf(a, b, x) / a;
    return 1 - exp(lbt) * betacf(b, a, 1 - x) / b;
}

/* x with I_x(a, b) = p, by bisection (I is increasing in x). */
static double betainv(double a, double b, double p)
{
    double lo = 0, hi = 1;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * (hi > 1e-300 ? hi : 1e-300); i++) {
        const double mid = 0.5 * (lo + hi);
        if (mc_betai(a, b, mid) < p) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

void mc_binom_ci(long k, long n, double level, double *lo, double *hi)
{
    const double a = 1 - level;
    if (n <= 0) {
        *lo = 0;
        *hi = 1;
        return;
    }
    *lo = k <= 0 ? 0 : betainv((double)k, (double)(n - k + 1), a / 2);
    *hi = k >= n ? 1 : betainv((double)(k + 1), (double)(n - k), 1 - a / 2);
}

/* P(X <= k) for X ~ Binomial(n, p) = I_{1-p}(n - k, k + 1). */
static double binom_cdf(long k, long n, double p)
{
    if (k < 0) return 0;
    if (k >= n) return 1;
    return mc_betai((double)(n - k), (double)(k + 1), 1 - p);
}

void mc_binom_accept(long n, double p, double tail, long *lo, long *hi)
{
    /* lo: the largest k with P(X < k) = P(X <= k-1) <= tail */
    long a = 0, b = n;
    while (a < b) {
        long mid = a + (b - a + 1) / 2;
        if (binom_cdf(mid - 1, n, p) <= tail) a = mid;
        else b = mid - 1;
    }
    *lo = a;
    /* hi: the smallest k with P(X > k) = 1 - P(X <= k) <= tail */
    a = 0, b = n;
    while (a < b) {
        long mid = a + (b - a) / 2;
        if (1 - binom_cdf(mid, n, p) <= tail) b = mid;
        else a = mid + 1;
    }
    *hi = a;
}

double mc_z(double level)
{
    /* bisection on erf: P(|Z| <= z) = erf(z / sqrt 2) */
    double lo = 0, hi = 40;
    for (int i = 0; i < 200; i++) {
        const double mid = 0.5 * (lo + hi);
        if (erf(mid / sqrt(2.0)) < level) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

void mc_mean_ci(const double *x, size_t n, double level, double *mean, double *lo, double *hi)
{
    double s = 0;
    for (size_t i = 0; i < n; i++) s += x[i];
    const double m = n ? s / (double)n : NAN;
    double v = 0;
    for (size_t i = 0; i < n; i++) v += (x[i] - m) * (x[i] - m);
    const double se = n > 1 ? sqrt(v / (double)(n - 1) / (double)n) : 0;
    const double z = mc_z(level);
    *mean = m;
    *lo = m - z * se;
    *hi = m + z * se;
}

double mc_t(double level, double nu)
{
    /* P(|T| <= t) = 1 - I_x(nu/2, 1/2), x = nu / (nu + t^2): increasing in t */
    double lo = 0, hi = 1;
    while (hi < 1e12 && 1 - mc_betai(0.5 * nu, 0.5, nu / (nu + hi * hi)) < level) hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
        const double mid = 0.5 * (lo + hi);
        if (1 - mc_betai(0.5 * nu, 0.5, nu / (nu + mid * mid)) < level) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

void mc_mean_ci_t(const double *x, size_t n, double level, double *mean, double *lo, double *hi)
{
    if (n == 0) {
        *mean = *lo = *hi = NAN;
        return;
    }
    double s = 0;
    for (size_t i = 0; i < n; i++) s += x[i];
    const double m = s / (double)n;
    double v = 0;
    for (size_t i = 0; i < n; i++) v += (x[i] - m) * (x[i] - m);
    const double h = n > 1 ? mc_t(level, (double)(n - 1)) * sqrt(v / (double)(n - 1) / (double)n) : 0;
    *mean = m;
    *lo = m - h;
    *hi = m + h;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void mc_sort(double *x, size_t n)
{
    if (n > 1) qsort(x, n, sizeof *x, cmp_double);
}

double mc_quantile_sorted(const double *x, size_t n, double p)
{
    if (n == 0 || !(p >= 0 && p <= 1)) return NAN;
    const double h = (double)(n - 1) * p;
    size_t i = (size_t)h;
    if (i >= n - 1) return x[n - 1];
    return x[i] + (h - (double)i) * (x[i + 1] - x[i]);
}

long mc_hist_bin(double x, double lo, double w, long n_bins)
{
    if (!(x >= lo)) return -1;
    const double u = (x - lo) / w;
    if (!(u < (double)n_bins)) return n_bins;
    long i = (long)u;
    /* rounding at a bin edge: keep lo + i w <= x < lo + (i + 1) w */
    if (i > 0 && x < lo + (double)i * w) i--;
    else if (i + 1 < n_bins && x >= lo + (double)(i + 1) * w) i++;
    return i;
}

long mc_hist_mode(const double *counts, long n_bins)
{
    long best = -1;
    for (long i = 0; i < n_bins; i++)
        if (counts[i] > 0 && (best < 0 || counts[i] > counts[best])) best = i;
    return best;
}

void mc_ratio_ci(const double *num, const double *den, size_t n, double level, double *r, double *lo, double *hi)
{
    double sn = 0, sd = 0;
    for (size_t i = 0; i < n; i++) sn += num[i], sd += den[i];
    if (n == 0 || !(sd != 0)) {
        *r = *lo = *hi = NAN;
        return;
    }
    const double q = sn / sd;
    double v = 0;
    for (size_t i = 0; i < n; i++) {
        const double d = num[i] - q * den[i];
        v += d * d;
    }
    const double dbar = sd / (double)n;
    const double h = n > 1 ? mc_z(level) * sqrt(v / ((double)n * (double)(n - 1))) / fabs(dbar) : 0;
    *r = q;
    *lo = q - h;
    *hi = q + h;
}
