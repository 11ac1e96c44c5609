/* q2_amp_rayleigh.c - Rayleigh clutter / Swerling I target closed forms for
 * the q2 sampler (see q2_amp_rayleigh.h). TO BE REPLACED by the functions of
 * include/trk/amplitude.h once that module exists. */
#include "q2_amp_rayleigh.h"

#include <math.h>

#include "q2_fastmath.h"

int q2_amp_rayleigh_init(struct q2_amp_rayleigh *r, double snr_db, double pfa)
{
    if (!(snr_db >= -30 && snr_db <= 60) || !(pfa > 0 && pfa < 1)) return -1;
    const double d = pow(10.0, snr_db / 10), p = 1;
    r->snr = d;
    r->pfa = pfa;
    r->t2 = -p * log(pfa);                   /* S0(t) = exp(-t^2/P) = pfa */
    r->pd = exp(-r->t2 / (p + d));           /* S1(t) = exp(-t^2/(P+d)) */
    r->ln_p_pd = -log1p(d / p);              /* ln(P/(P+d)) */
    r->slope_c = d / (p + d);
    r->slope_t = d / p;
    return 0;
}

double q2_amp_rayleigh_pd(double snr_db, double pfa)
{
    struct q2_amp_rayleigh r;
    if (q2_amp_rayleigh_init(&r, snr_db, pfa)) return NAN;
    return r.pd;
}

double q2_amp_rayleigh_log_lr(const struct q2_amp_rayleigh *r, double a)
{
    /* Brekke eq 19 with E[a^2] = P (clutter), P + d (target) */
    const double p = 1, d = r->snr;
    return log(r->pfa / r->pd) + r->ln_p_pd + a * a * d / (p * (p + d));
}

double q2_amp_rayleigh_inv_sf(const struct q2_amp_rayleigh *r, int target, double x)
{
    const double p = 1, d = r->snr;
    return sqrt(r->t2 + (target ? p + d : p) * x);
}

Q2_CLONES
static void sample_loop(double c, double s, size_t n, const double *restrict u, double *restrict out)
{
    for (size_t i = 0; i < n; i++) out[i] = c - s * q2_log(u[i]); /* x = -ln u */
}

void q2_amp_rayleigh_sample(const void *ctx, int target, size_t n, const double *u, double *out)
{
    const struct q2_amp_rayleigh *r = ctx;
    sample_loop(r->ln_p_pd, target ? r->slope_t : r->slope_c, n, u, out);
}

struct q2_amp_sampler q2_amp_rayleigh_sampler(const struct q2_amp_rayleigh *r)
{
    struct q2_amp_sampler s = {"rayleigh", q2_amp_rayleigh_sample, r, r->pd};
    return s;
}
