/* kind_visibility.c - vector kind visibility (tests/vectors/tracktests.vec):
 * the library's IPDA visibility recurrence (trk/visibility.h) scan by scan.
 *
 * Float tolerance (normwise): probabilities in (0, 1) through ~20 steps of
 * logistic updates and smoothing; float rounding of ln(gd/rho) (|.| ~ 10) and
 * of the logistic is ~1e-6 per step and is damped by the recursion. Measured
 * over the public cases (trk-vectors --report-error, float build): largest
 * error 1.4e-6, 0.14 of the tolerance abs 1e-5. The decisions never sat
 * within that of p_con in the public cases; a case where pcv comes within
 * 2e-5 of p_con before the confirmation is reported as not resolvable in
 * float (VEC_FLOAT_UNRESOLVABLE): its sticky decision may flip by a scan.
 *
 * The vector's decision column is 1 once confirmed (pcv >= p_con), else 0;
 * the cases have no termination threshold (p_term = 0), so the library's
 * enum trk_decision is CONFIRM or CONTINUE here. */
#include <math.h>

#include "trk/visibility.h"
#include "vec.h"

TRK_VEC_KIND(visibility, 1e-5, 0, VEC_FAST)
{
    double pv0, pcv0, dstay, dbecome, omega, pd, pg, pcon;
    const double *rho, *ng, *gd, *la;
    size_t nt, nng, ngd, nla;
    if (vec_in_scalar(c, o, "pv0", &pv0) || vec_in_scalar(c, o, "pcv0", &pcv0) ||
        vec_in_scalar(c, o, "delta_stay", &dstay) || vec_in_scalar(c, o, "delta_become", &dbecome) ||
        vec_in_scalar(c, o, "omega_c", &omega) || vec_in_scalar(c, o, "pd", &pd) || vec_in_scalar(c, o, "pg", &pg) ||
        vec_in_scalar(c, o, "p_con", &pcon) || vec_in_array(c, o, "rho", &rho, &nt) ||
        vec_in_array(c, o, "ng", &ng, &nng) || vec_in_array(c, o, "gd", &gd, &ngd) ||
        vec_in_array(c, o, "la", &la, &nla))
        return -1;
    if (nng != nt || nla != ngd) return vec_fail(o, "ng must have one value per scan, la one per gd");
    struct trk_visibility_params p = {(trk_real)pv0, (trk_real)pcv0, (trk_real)dstay, (trk_real)dbecome,
                                      (trk_real)omega, (trk_real)pcon, 0};
    struct trk_visibility_model m;
    struct trk_visibility v;
    trk_status st = trk_visibility_model_init(&m, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_visibility_model_init: %s", trk_status_str(st));
    trk_visibility_reset(&m, &v);
    double *pv_pred = vec_put_alloc(o, "pv_pred", nt), *pv_post = vec_put_alloc(o, "pv_post", nt);
    double *pcv = vec_put_alloc(o, "pcv", nt), *dec = vec_put_alloc(o, "decision", nt);
    if (!pv_pred || !pv_post || !pcv || !dec) return -1;
    size_t k = 0;
    for (size_t t = 0; t < nt; t++) {
        if (!(ng[t] >= 0) || ng[t] != floor(ng[t]) || ng[t] > TRK_MAX_DETECTIONS || (size_t)ng[t] > ngd - k)
            return vec_fail(o, "ng[%zu] = %g does not fit gd", t, ng[t]);
        const size_t n = (size_t)ng[t];
        trk_real g[TRK_MAX_DETECTIONS], l[TRK_MAX_DETECTIONS];
        for (size_t i = 0; i < n; i++) {
            g[i] = (trk_real)gd[k + i];
            if (!(la[k + i] > 0)) return vec_fail(o, "la must be positive");
            l[i] = (trk_real)log(la[k + i]);
        }
        k += n;
        trk_real log_sum;
        enum trk_decision d = TRK_DECISION_CONTINUE;
        st = trk_visibility_log_sum(n, g, (trk_real)rho[t], l, &log_sum);
        if (st != TRK_OK) return vec_fail(o, "trk_visibility_log_sum (scan %zu): %s", t + 1, trk_status_str(st));
        st = trk_visibility_step(&m, &v, (trk_real)pd, (trk_real)pg, log_sum, &d);
        if (st != TRK_OK) return vec_fail(o, "trk_visibility_step (scan %zu): %s", t + 1, trk_status_str(st));
        if (d != v.decision || d == TRK_DECISION_TERMINATE)
            return vec_fail(o, "scan %zu: decision %s (state %s)", t + 1, trk_decision_str(d),
                            trk_decision_str(v.decision));
        pv_pred[t] = (double)v.pv_pred;
        pv_post[t] = (double)v.pv;
        pcv[t] = (double)v.pcv;
        dec[t] = d == TRK_DECISION_CONFIRM;
        if (TRK_REAL_IS_FLOAT && (t == 0 || dec[t - 1] == 0) && fabs(pcv[t] - pcon) <= 2e-5) {
            vec_fail(o, "scan %zu: pcv %.8g within float rounding of p_con %.8g", t + 1, pcv[t], pcon);
            return VEC_FLOAT_UNRESOLVABLE;
        }
    }
    if (k != ngd) return vec_fail(o, "gd has %zu values, ng sums to %zu", ngd, k);
    return 0;
}
