/* tracker_detection_impl.h (private) - is a scan's detection usable: in
 * the surveillance bound, finite, its covariance positive definite, its
 * amplitude valid and (with an amplitude model) its likelihood ratio
 * l^a; the reasons it is not are counted in the scan report.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACKER_DETECTION_IMPL_H
#define TRK_TRACKER_DETECTION_IMPL_H

#include "tracker_internal.h"

/* How the scan's detections are read. */
struct amp_use {
    const struct trk_sensor_params *sp;
    trk_real max_coord_m; /* the surveillance bound (params.max_coord_m) */
    int want_db;       /* the clutter-amplitude test needs the amplitudes in dB */
    trk_real ref_db;   /* mean clutter power (dB): the amplitudes' reference */
    /* an amplitude model with a P_D profile: the view whose profile gives
     * the target SNR at each detection's range (else NULL: the model's) */
    const struct trk_i_view *snr_view;
    trk_real eta, pd_s; /* persistent returns: their share and P_D (eta 0: none), */
    trk_real ln_eta, ln_1m_eta; /* ln eta, ln(1 - eta), */
    trk_real inv_ln_pfa, inv_us, ln_inv_us; /* 1 / ln pfa, 1/u_s = ln pd_s / ln pfa and its log */
};

/* How sensor sp's detections are read in scan view v. */
static struct amp_use amp_use_of(const struct trk_tracker *t, const struct trk_sensor_params *sp,
                                 const struct trk_i_view *v)
{
    struct amp_use au = {
        sp, t->params.max_coord_m, t->params.confirm.method == TRK_CONFIRM_CLUTTER_AMP, /* the dB values' only user */
        TRK_REAL_C(10.0) * trk_log10(sp->use_amplitude ? sp->amplitude.clutter_power : 1),
        sp->use_amplitude && sp->pd_profile.n > 0 ? v : NULL, t->ws.persistent_share, /* > 0 only with use_amplitude (checked at init) */
        sp->persistent_pd, 0, 0, 0, 0, 0};
    if (au.eta > 0) { /* the mixture's constants, once per scan (checked at init: eta in (0, 1), pd_s in (pfa, 1)) */
        au.ln_eta = trk_log(au.eta);
        au.ln_1m_eta = trk_log1p(-au.eta);
        au.inv_ln_pfa = -sp->amplitude.clutter_power / sp->amplitude.t2; /* ln pfa = -t^2/P (eq 6) */
        au.inv_us = persistent_inv_u(sp);
        au.ln_inv_us = trk_log(au.inv_us);
    }
    return au;
}

/* The target's P_D behind detection d's amplitude: the profile's at its
 * range, else the model's. */
static trk_real amp_pd(const struct amp_use *au, const struct trk_detection *d)
{
    return au->snr_view ? trk_i_view_pd_profile(au->snr_view, d->x_m, d->y_m) : au->sp->amplitude.pd;
}

/* ln l^a of amplitude a over clutter and persistent returns (struct
 * trk_sensor_params: l = l_t / ((1 - eta) + eta l_s), Rayleigh), the
 * target at P_D pd, at the threshold raised by x0 >= 0 (pfa' = pfa e^-x0;
 * 0: the sensor's): there each l^a loses (1 - 1/u) x0 (u = 1 + SNR: eq 19
 * at t'^2 = t^2 + P x0) and the scatterers' share becomes
 * eta' = eta e^(-x0/u_s) / ((1 - eta) e^-x0 + eta e^(-x0/u_s)). */
static trk_status amp_mixture_log_lr(const struct amp_use *au, trk_real pd, trk_real x0, trk_real a, trk_real *llr)
{
    const struct trk_amplitude *m = &au->sp->amplitude;
    if (!isfinite(pd)) return TRK_E_NAN;
    if (!(pd > m->pfa && pd < 1)) return TRK_E_RANGE;
    const trk_real inv_ut = trk_log(pd) * au->inv_ln_pfa, inv_us = au->inv_us; /* 1/u = ln P_D / ln pfa */
    trk_real lt, ls;
    trk_status st = trk_i_amplitude_log_lr_inv_u(m, inv_ut, trk_log(inv_ut), a, &lt);
    if (st == TRK_OK) st = trk_i_amplitude_log_lr_inv_u(m, inv_us, au->ln_inv_us, a, &ls);
    if (st != TRK_OK) return st;
    lt -= (1 - inv_ut) * x0;
    ls -= (1 - inv_us) * x0;
    /* ln((1 - eta') + eta' e^ls) = ln((1 - eta) e^-x0 + eta e^(-x0/u_s) e^ls) - ln((1 - eta) e^-x0 + eta e^(-x0/u_s));
     * the second term is ln 1 = 0 at the sensor's threshold (x0 = 0) */
    const trk_real c0 = au->ln_1m_eta - x0, c1 = au->ln_eta - x0 * inv_us;
    const trk_real top_hi = c0 > c1 + ls ? c0 : c1 + ls, top_lo = c0 > c1 + ls ? c1 + ls : c0;
    const trk_real bot_hi = c0 > c1 ? c0 : c1, bot_lo = c0 > c1 ? c1 : c0;
    const trk_real bot = x0 > 0 ? bot_hi + trk_log1p(trk_exp(bot_lo - bot_hi)) : 0;
    const trk_real v = lt - (top_hi + trk_log1p(trk_exp(top_lo - top_hi))) + bot;
    if (!isfinite(v)) return TRK_E_RANGE;
    *llr = v;
    return TRK_OK;
}

/* Scan detection i as a Cartesian detection: the caller's; a polar
 * sensor's converted (trk_polar_to_cartesian) into *tmp, or a Cartesian
 * one without its own covariance given its conversion covariance there.
 * NULL when a polar detection cannot be converted (counted: non-finite, or
 * a range <= 0 as outside the region). */
static const struct trk_detection *scan_detection(const struct trk_tracker *t, const struct trk_scan *scan, size_t i,
                                                  struct trk_detection *tmp, struct trk_scan_report *rep)
{
    const struct trk_i_view *v = &t->ws.view;
    if (v->sp->kind != TRK_SENSOR_POLAR) return &scan->detections[i]; /* a Cartesian sensor's, as given */
    if (scan->polar) {
        const trk_status st = trk_i_view_convert(v, &scan->polar[i], tmp);
        if (st == TRK_OK) return tmp; /* its covariance is the one det_cov derives from its position */
        if (st == TRK_E_NAN) rep->n_rejected_nonfinite++;
        else rep->n_rejected_region++;
        return NULL;
    }
    const struct trk_detection *d = &scan->detections[i];
    if (d->has_cov) return d;
    *tmp = *d;
    tmp->has_cov = 1;
    if (isfinite(d->x_m) && isfinite(d->y_m))
        trk_polar_cov(v->sp, d->x_m - v->pose.x_m, d->y_m - v->pose.y_m, tmp->cov_m2);
    return tmp;
}

/* The caller's clutter density at scan detection i (NULL: none given). */
static const trk_real *caller_density(const struct trk_scan *scan, size_t i)
{
    return scan->clutter_density_per_m2 ? &scan->clutter_density_per_m2[i] : NULL;
}

/* TRK_OK for a usable detection, else why not: TRK_E_NAN non-finite
 * position or covariance, TRK_E_NOT_SPD covariance, TRK_E_RANGE amplitude
 * NaN, infinite or negative. */
static trk_status check_detection(const struct trk_detection *d)
{
    trk_real r[NZ * NZ];
    if (!isfinite(d->x_m) || !isfinite(d->y_m)) return TRK_E_NAN;
    if (d->has_amplitude && !(d->amplitude >= 0 && d->amplitude <= TRK_REAL_MAX)) return TRK_E_RANGE;
    return d->has_cov ? trk_i_cov2_unpack(d->cov_m2, r) : TRK_OK;
}

/* Is detection d usable: 1 with its ln l^a in *llr, else 0 and counted
 * why not: a finite position outside the surveillance bound, the checks
 * above, then with an amplitude model its ln l^a (PDAFAI, Brekke eqs
 * 19-20, once per scan; with a P_D profile, the target SNR of the
 * profile's P_D at the detection's range: trk_amplitude_log_lr_at_pd; with
 * persistent returns over their mixture with the clutter),
 * refusing amplitudes below the threshold; the caller's clutter density
 * lambda_c (NULL: none) must be finite and > 0. */
static int detection_usable(const struct trk_detection *d, const trk_real *lambda_c, const struct amp_use *au,
                            struct trk_scan_report *rep, trk_real *llr)
{
    if (isfinite(d->x_m) && isfinite(d->y_m) && !(trk_fabs(d->x_m) <= au->max_coord_m && trk_fabs(d->y_m) <= au->max_coord_m)) {
        rep->n_rejected_region++; /* outside the surveillance bound: no position (trk/tracker.h) */
        return 0;
    }
    trk_status st = check_detection(d);
    if (st != TRK_OK) {
        if (st == TRK_E_NAN) rep->n_rejected_nonfinite++;
        else if (st == TRK_E_RANGE) rep->n_rejected_amplitude++;
        else rep->n_rejected_cov++;
        return 0;
    }
    if (lambda_c && !(*lambda_c > 0 && *lambda_c <= TRK_REAL_MAX)) {
        rep->n_rejected_density++;
        return 0;
    }
    *llr = 0; /* positions only: l^a = 1 */
    if (au->sp->use_amplitude && d->has_amplitude) {
        st = au->eta > 0 ? amp_mixture_log_lr(au, amp_pd(au, d), 0, d->amplitude, llr)
             : au->snr_view ? trk_amplitude_log_lr_at_pd(&au->sp->amplitude, amp_pd(au, d), d->amplitude, llr)
                            : trk_amplitude_log_lr(&au->sp->amplitude, d->amplitude, llr);
        /* TRK_E_RANGE at or above the threshold: ln l^a beyond the real type (a Rayleigh
         * amplitude above ~1e154 sqrt(P)), a bad amplitude, not one below the threshold */
        if (st == TRK_E_RANGE && d->amplitude < trk_amplitude_threshold(&au->sp->amplitude))
            rep->n_below_threshold++;
        else if (st != TRK_OK) rep->n_rejected_amplitude++;
        if (st != TRK_OK) return 0;
    }
    return 1;
}

#endif
