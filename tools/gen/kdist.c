/* kdist.c - K-distributed clutter / Swerling I target amplitude model by
 * adaptive quadrature of the texture integral (see kdist.h). */
#include "kdist.h"

#include <math.h>
#include <string.h>

/* ln(nu^nu e^-nu / Gamma(nu)) without cancellation for large nu (Stirling). */
static double c_nu_of(double nu)
{
    if (nu < 10) return nu * log(nu) - nu - lgamma(nu);
    const double r = 1 / nu, r2 = r * r;
    /* ln Gamma(nu) = (nu - 1/2) ln nu - nu + ln(2 pi)/2 + series(1/nu) */
    const double series =
        r * (1.0 / 12 -
             r2 * (1.0 / 360 -
                   r2 * (1.0 / 1260 -
                         r2 * (1.0 / 1680 -
                               r2 * (1.0 / 1188 - r2 * (691.0 / 360360 - r2 * (1.0 / 156)))))));
    return 0.5 * log(nu) - 0.91893853320467274178 - series;
}

int kdist_init(struct kdist *k, double nu, double snr_db)
{
    if (!k || !isfinite(nu) || !isfinite(snr_db)) return -1;
    if (!(nu > 0 && nu <= 1e6) || !(snr_db >= -50 && snr_db <= 80)) return -1;
    k->nu = nu;
    k->snr = pow(10.0, snr_db / 10);
    k->c_nu = c_nu_of(nu);
    return 0;
}

/* The integrand exponent phi(s) and its derivatives for one expectation. */
struct integrand {
    double nu, c_nu, D, A;
    int m, target;
};

static double phi(const struct integrand *f, double s)
{
    const double base = f->nu * (s - expm1(s)) + f->c_nu;
    if (!f->target) /* w = e^s */
        return base - f->m * s - (f->A > 0 ? f->A * exp(-s) : 0);
    const double w = exp(s) + f->D;
    return base - f->m * log(w) - (f->A > 0 ? f->A / w : 0);
}

/* phi''(s) (negative at a maximum). */
static double phi2(const struct integrand *f, double s)
{
    const double x = exp(s);
    if (!f->target) return -f->nu * x - f->A / x;
    const double w = x + f->D;
    return -f->nu * x - f->m * x * f->D / (w * w) + f->A * x * (w - 2 * x) / (w * w * w);
}

/* sign of phi'(s) = sign of G(x), x = e^s:
 * G(x) = nu (1-x)(x+D)^2 - m x (x+D) + A x. */
static double g_cubic(const struct integrand *f, double x)
{
    const double w = x + f->D;
    return f->nu * (1 - x) * w * w - f->m * x * w + f->A * x;
}

/* Critical points of phi (x = e^s > 0) in increasing order; returns their
 * count (1 or 3). is_max[i] says whether point i is a maximum. */
static int critical_points(const struct integrand *f, double *xs, int *is_max)
{
    const double nu = f->nu, m = f->m, A = f->A, D = f->D;
    if (!f->target || D == 0) {
        /* -nu x^2 + (nu - m) x + A = 0 (times x for the clutter form) */
        const double bq = nu - m, disc = sqrt(bq * bq + 4 * nu * A);
        double x;
        if (bq >= 0) x = (bq + disc) / (2 * nu);
        else x = disc > -bq ? 2 * A / (disc - bq) : 0;
        if (!(x > 0)) x = 1e-300; /* A = 0 and nu <= m: integrand monotone */
        xs[0] = x;
        is_max[0] = 1;
        return 1;
    }
    /* Split (0, inf) at the positive roots of G'(x) = al x^2 + be x + ga. */
    const double al = -3 * nu, be = nu * (2 - 4 * D) - 2 * m, ga = nu * D * (2 - D) - m * D + A;
    double brk[4];
    int nb = 0;
    brk[nb++] = 0;
    const double dd = be * be - 4 * al * ga;
    if (dd > 0) {
        const double sq = sqrt(dd);
        /* stable quadratic roots */
        const double q = -0.5 * (be + (be >= 0 ? sq : -sq));
        double r1 = q / al, r2 = q != 0 ? ga / q : r1;
        if (r1 > r2) {
            double tmp = r1;
            r1 = r2;
            r2 = tmp;
        }
        if (r1 > 0) brk[nb++] = r1;
        if (r2 > 0 && r2 > r1) brk[nb++] = r2;
    }
    double up = brk[nb - 1] > 1 ? 2 * brk[nb - 1] : 2;
    while (g_cubic(f, up) >= 0 && up < 1e300) up *= 2;
    brk[nb++] = up;
    int n = 0;
    for (int i = 0; i + 1 < nb; i++) {
        double lo = brk[i], hi = brk[i + 1];
        double glo = g_cubic(f, lo), ghi = g_cubic(f, hi);
        if ((glo > 0) == (ghi > 0)) continue;
        for (int it = 0; it < 400 && hi - lo > 1e-15 * hi; it++) {
            double mid = lo > 0 && hi / lo > 4 ? sqrt(lo * hi) : 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) mid = 0.5 * (lo + hi);
            double gm = g_cubic(f, mid);
            if ((gm > 0) == (glo > 0)) lo = mid;
            else hi = mid;
        }
        xs[n] = 0.5 * (lo + hi);
        is_max[n] = glo > 0; /* G: + -> - at a maximum of phi */
        n++;
        if (n == 3) break;
    }
    if (n == 0) { /* cannot happen (G(0) > 0 > G(up)); keep a sane peak */
        xs[0] = 1;
        is_max[0] = 1;
        n = 1;
    }
    return n;
}

/* Gauss-Kronrod 7/15 (QUADPACK qk15). */
static const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static void gk15(const struct integrand *f, double peak, double a, double b, double *res, double *err)
{
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = exp(phi(f, c) - peak);
    double rk = fc * wgk[7], rg = fc * wg[3];
    for (int j = 0; j < 7; j++) {
        const double dx = h * xgk[j];
        const double f1 = exp(phi(f, c - dx) - peak), f2 = exp(phi(f, c + dx) - peak);
        rk += wgk[j] * (f1 + f2);
        if (j % 2 == 1) rg += wg[j / 2] * (f1 + f2);
    }
    *res = rk * h;
    *err = fabs((rk - rg) * h);
}

#define MAX_PANELS 512 /* 118 at most over nu 0.05..1e4, SNR -10..40 dB, pfa 1e-10..0.5 */
#define MAX_BREAKS 40

struct panel {
    double a, b, res, err;
};

static double log_integral(const struct integrand *f)
{
    double xs[3];
    int is_max[3];
    const int nc = critical_points(f, xs, is_max);
    double ss[3], peak = -INFINITY;
    for (int i = 0; i < nc; i++) {
        ss[i] = log(xs[i]);
        if (is_max[i]) {
            const double p = phi(f, ss[i]);
            if (p > peak) peak = p;
        }
    }
    if (!isfinite(peak)) return peak;
    double brk[MAX_BREAKS];
    int nb = 0;
    double s_left = INFINITY, s_right = -INFINITY, w_left = 1, w_right = 1;
    for (int i = 0; i < nc; i++) {
        if (!is_max[i]) {
            brk[nb++] = ss[i];
            continue;
        }
        const double d2 = phi2(f, ss[i]);
        double w = d2 < 0 ? 1 / sqrt(-d2) : 1;
        if (w > 1e3) w = 1e3;
        /* the walk below doubles w: never from 0 (phi2 = -inf; it looped forever) */
        if (!(w >= 1e-12)) w = 1e-12;
        static const double off[] = {-8, -3, -1, 0, 1, 3, 8};
        for (int j = 0; j < 7; j++) brk[nb++] = ss[i] + off[j] * w;
        if (ss[i] < s_left) {
            s_left = ss[i];
            w_left = w;
        }
        if (ss[i] > s_right) {
            s_right = ss[i];
            w_right = w;
        }
    }
    /* phi is monotone outside the outermost maxima: walk out until it is 80
     * below the peak (e^-80 relative). */
    double lo = s_left, hi = s_right;
    for (double d = w_left; d < 1e6; d *= 2) {
        lo = s_left - d;
        if (phi(f, lo) < peak - 80) break;
    }
    for (double d = w_right; d < 1e6; d *= 2) {
        hi = s_right + d;
        if (phi(f, hi) < peak - 80) break;
    }
    brk[nb++] = lo;
    brk[nb++] = hi;
    /* sort, clip, dedupe */
    for (int i = 1; i < nb; i++)
        for (int j = i; j > 0 && brk[j] < brk[j - 1]; j--) {
            double t = brk[j];
            brk[j] = brk[j - 1];
            brk[j - 1] = t;
        }
    struct panel pan[MAX_PANELS]; /* 16 KB of stack: reentrant (OpenMP callers) */
    int np = 0;
    double prev = lo;
    for (int i = 0; i < nb; i++) {
        double b = brk[i];
        if (b <= prev) continue;
        if (b > hi) b = hi;
        if (b - prev <= 1e-13 * (fabs(b) + 1)) continue;
        pan[np].a = prev;
        pan[np].b = b;
        gk15(f, peak, prev, b, &pan[np].res, &pan[np].err);
        np++;
        prev = b;
        if (b >= hi) break;
    }
    for (;;) {
        double tot = 0, terr = 0, emax = -1;
        int imax = 0;
        for (int i = 0; i < np; i++) {
            tot += pan[i].res;
            terr += pan[i].err;
            if (pan[i].err > emax) {
                emax = pan[i].err;
                imax = i;
            }
        }
        if (terr <= 1e-13 * tot || np >= MAX_PANELS - 1) return peak + log(tot);
        const double a = pan[imax].a, b = pan[imax].b, mid = 0.5 * (a + b);
        if (!(mid > a && mid < b)) return peak + log(tot);
        pan[imax].b = mid;
        gk15(f, peak, a, mid, &pan[imax].res, &pan[imax].err);
        pan[np].a = mid;
        pan[np].b = b;
        gk15(f, peak, mid, b, &pan[np].res, &pan[np].err);
        np++;
    }
}

double kdist_log_moment(const struct kdist *k, int target, int m, double A)
{
    if (!(A >= 0 && A <= KDIST_MAX_A)) return NAN; /* outside the direct evaluation's range */
    struct integrand f;
    f.nu = k->nu;
    f.c_nu = k->c_nu;
    f.D = target ? k->snr : 0;
    f.A = A;
    f.m = m;
    f.target = target != 0;
    return log_integral(&f);
}

double kdist_log_sf(const struct kdist *k, int target, double a)
{
    return kdist_log_moment(k, target, 0, a * a);
}

double kdist_log_pdf(const struct kdist *k, int target, double a)
{
    return log(2 * a) + kdist_log_moment(k, target, 1, a * a);
}

/* Solve ln S(A) = target_log for A >= 0 by Newton's method. ln S is convex
 * and decreasing in A (the log of a mixture of exponentials in A), so every
 * Newton step from the right lands left of the root and the iteration then
 * increases monotonically to it. */
static int solve_log_sf(const struct kdist *k, int target, double target_log, double A0,
                        double *A_out, double *rho_out)
{
    double A = A0 > 0 ? A0 : 1;
    for (int it = 0; it < 200; it++) {
        const double l0 = kdist_log_moment(k, target, 0, A);
        const double l1 = kdist_log_moment(k, target, 1, A);
        const double rho = exp(l1 - l0); /* -d ln S / dA */
        const double fA = l0 - target_log;
        double An = A + fA / rho;
        if (!(An > 0)) An = 0.5 * A;
        const double step = fabs(An - A);
        A = An;
        if (step <= 1e-14 * A || fA == 0) {
            *A_out = A;
            if (rho_out) *rho_out = exp(kdist_log_moment(k, target, 1, A) - kdist_log_moment(k, target, 0, A));
            return 0;
        }
    }
    return -1;
}

int kdist_threshold(const struct kdist *k, double pfa, double *t)
{
    if (!(pfa > 0 && pfa < 1)) return -1;
    double A;
    if (solve_log_sf(k, 0, log(pfa), -log(pfa), &A, NULL)) return -1;
    *t = sqrt(A);
    return 0;
}

int kdist_inv_sf(const struct kdist *k, int target, double t, double x, double *a, double *dadx)
{
    if (!(x >= 0) || !(t > 0)) return -1;
    const double A_t = t * t;
    const double l0t = kdist_log_moment(k, target, 0, A_t);
    if (x == 0) {
        *a = t;
        if (dadx) *dadx = 1 / (2 * t * exp(kdist_log_moment(k, target, 1, A_t) - l0t));
        return 0;
    }
    const double rho_t = exp(kdist_log_moment(k, target, 1, A_t) - l0t);
    double A, rho;
    if (solve_log_sf(k, target, l0t - x, A_t + x / rho_t, &A, &rho)) return -1;
    *a = sqrt(A);
    if (dadx) *dadx = 1 / (2 * *a * rho);
    return 0;
}

double kdist_log_lr(const struct kdist *k, double pfa, double pd, double a, double *dlda2)
{
    const double A = a * a;
    const double l1t = kdist_log_moment(k, 1, 1, A), l1c = kdist_log_moment(k, 0, 1, A);
    if (dlda2) {
        const double l2t = kdist_log_moment(k, 1, 2, A), l2c = kdist_log_moment(k, 0, 2, A);
        *dlda2 = exp(l2c - l1c) - exp(l2t - l1t);
    }
    return log(pfa / pd) + l1t - l1c;
}

double kdist_log_lr_inf(const struct kdist *k, double pfa, double pd)
{
    return log(pfa / pd) + k->nu * k->snr;
}
