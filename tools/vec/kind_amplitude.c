/* kind_amplitude.c - vector kinds amp_threshold, amp_loglr, amp_inv_sf,
 * amp_kennedy_loglr (tests/vectors/amplitude.vec).
 *
 * Direct evaluation, one implementation each: model k through the offline
 * high-accuracy texture integrals (tools/gen/kdist.c, double precision in
 * every build), model rayleigh through the library's closed forms
 * (trk_amplitude_init_rayleigh / _log_lr / _inv_sf), amp_kennedy_loglr
 * through trk_amplitude_db_log_lr. (The table lookup that the firmware uses
 * is checked against this direct evaluation in tests/test_amplitude.c.)
 *
 * Float tolerances (normwise, see vec.h), measured with trk-vectors
 * --report-error in the float build over the public cases (largest error in
 * brackets, as the fraction of the tolerance it used):
 *   amp_threshold   rayleigh t = sqrt(-P ln pfa), pd = exp(ln pfa/(1+SNR)) carry
 *                   a few float roundings: rel 1e-6 [2.5e-7, 0.25]; the k cases
 *                   are computed in double in every build.
 *   amp_loglr       ln l^a = lr0 + lr1 a^2 with a^2 up to ~2900 and values up
 *                   to ~120: rounding of a^2 and lr1 (a few ulp of the largest
 *                   value): rel 2e-6 normwise plus abs 1e-5 for arrays crossing
 *                   zero [0.08].
 *   amp_inv_sf      a = sqrt(t^2 + Q x): rel 1e-6 [6.6e-8, 0.04].
 *   amp_kennedy_loglr  sums of terms up to ~700: rel 1e-6 normwise [0.11]. */
#include <math.h>
#include <string.h>

#include "amp_table.h"
#include "trk/amplitude.h"
#include "vec.h"

/* model, nu, clutter_power, snr_db, pfa -> a direct evaluator */
static int setup(const struct vec_case *c, struct vec_out *o, struct amp_direct *d)
{
    const char *model;
    double nu, power, snr_db, pfa;
    if (vec_in_word(c, o, "model", &model) || vec_in_scalar(c, o, "nu", &nu) ||
        vec_in_scalar(c, o, "clutter_power", &power) || vec_in_scalar(c, o, "snr_db", &snr_db) ||
        vec_in_scalar(c, o, "pfa", &pfa))
        return -1;
    int m;
    if (strcmp(model, "rayleigh") == 0) m = TRK_AMP_RAYLEIGH;
    else if (strcmp(model, "k") == 0) m = TRK_AMP_K;
    else return vec_fail(o, "model must be rayleigh|k");
    if (amp_direct_init(d, m, nu, power, snr_db, pfa) != 0)
        return vec_fail(o, "bad amplitude model (nu %g, clutter_power %g, snr_db %g, pfa %g)", nu, power, snr_db,
                        pfa);
    return 0;
}

TRK_VEC_KIND(amp_threshold, 0, 1e-6, VEC_FAST)
{
    struct amp_direct d;
    if (setup(c, o, &d)) return -1;
    if (vec_put1(o, "t", d.t) || vec_put1(o, "pd", d.pd)) return -1;
    return 0;
}

TRK_VEC_KIND(amp_loglr, 1e-5, 2e-6, VEC_FAST)
{
    struct amp_direct d;
    const double *a;
    size_t n;
    if (setup(c, o, &d) || vec_in_array(c, o, "a", &a, &n)) return -1;
    double *out = vec_put_alloc(o, "log_lr", n);
    if (!out) return -1;
    /* The cases start at the reference's threshold, which may sit an ulp
     * below ours (or a float rounding below in the float build): such an a is
     * the threshold and is evaluated there (changes ln l^a by < 1e-11). */
    const double snap = TRK_REAL_IS_FLOAT ? 1e-6 : 1e-12;
    for (size_t i = 0; i < n; i++) {
        const double ai = a[i] < d.t && a[i] >= d.t * (1 - snap) ? d.t : a[i];
        if (amp_direct_log_lr(&d, ai, &out[i]) != 0)
            return vec_fail(o, "log_lr at a[%zu] = %.17g failed (below the threshold %.17g, or a/sqrt(P) "
                                "beyond the direct evaluation's 1e8?)",
                            i, a[i], d.t);
    }
    return 0;
}

TRK_VEC_KIND(amp_inv_sf, 0, 1e-6, VEC_FAST)
{
    struct amp_direct d;
    const double *x;
    size_t n;
    long which;
    if (setup(c, o, &d) || vec_in_int(c, o, "which", &which) || vec_in_array(c, o, "x", &x, &n)) return -1;
    if (which != 0 && which != 1) return vec_fail(o, "which must be 0 (clutter) or 1 (target)");
    double *out = vec_put_alloc(o, "a", n);
    if (!out) return -1;
    for (size_t i = 0; i < n; i++)
        if (amp_direct_inv_sf(&d, (int)which, x[i], &out[i]) != 0)
            return vec_fail(o, "inverse survival at x[%zu] = %.17g failed (no solution a/sqrt(P) <= 1e8?)", i,
                            x[i]);
    return 0;
}

TRK_VEC_KIND(amp_kennedy_loglr, 0, 1e-6, VEC_FAST)
{
    const double *a;
    size_t n;
    double amin, theta, mu, s2;
    if (vec_in_array(c, o, "a_db", &a, &n) || vec_in_scalar(c, o, "a_min_db", &amin) ||
        vec_in_scalar(c, o, "theta_db", &theta) || vec_in_scalar(c, o, "mu_db", &mu) ||
        vec_in_scalar(c, o, "s2_db2", &s2))
        return -1;
    const struct trk_amp_db_params p = {(trk_real)amin, (trk_real)theta, (trk_real)mu, (trk_real)s2};
    double *out = vec_put_alloc(o, "log_lr", n);
    if (!out) return -1;
    for (size_t i = 0; i < n; i++) {
        trk_real v;
        trk_status st = trk_amplitude_db_log_lr(&p, (trk_real)a[i], &v);
        if (st != TRK_OK) return vec_fail(o, "trk_amplitude_db_log_lr(a_db[%zu]): %s", i, trk_status_str(st));
        out[i] = (double)v;
    }
    return 0;
}
