/* visibility.c - IPDA target visibility of one track (trk/visibility.h;
 * Kennedy 2008 eqs 1-2, 21-24; docs/conventions.md "Existence and visibility"). */
#include "trk/visibility.h"

#include <limits.h>

static int prob(trk_real p) { return p >= 0 && p <= 1; }

trk_status trk_visibility_model_init(struct trk_visibility_model *m, const struct trk_visibility_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (!isfinite(p->pv0) || !isfinite(p->pcv0) || !isfinite(p->delta_stay) || !isfinite(p->delta_become) ||
        !isfinite(p->omega_c) || !isfinite(p->p_con) || !isfinite(p->p_term))
        return TRK_E_NAN;
    if (!(p->pv0 > 0 && p->pv0 < 1) || !prob(p->pcv0) || !prob(p->delta_stay) || !prob(p->delta_become) ||
        !(p->omega_c >= 0 && p->omega_c < 1) || !(p->p_con > 0 && p->p_con <= 1) ||
        !(p->p_term >= 0 && p->p_term < p->p_con))
        return TRK_E_RANGE;
    m->params = *p;
    return TRK_OK;
}

void trk_visibility_reset(const struct trk_visibility_model *m, struct trk_visibility *v)
{
    if (!m || !v) return;
    v->pv_pred = m->params.pv0;
    v->pv = m->params.pv0;
    v->pcv = m->params.pcv0;
    v->decision = TRK_DECISION_CONTINUE;
    v->scans = 0;
}

void trk_visibility_reset_to(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pv0)
{
    if (!m || !v) return;
    trk_visibility_reset(m, v);
    v->pv_pred = v->pv = v->pcv = pv0;
}

/* ln(e^a + e^b) */
static trk_real log_add(trk_real a, trk_real b)
{
    if (a < b) {
        trk_real t = a;
        a = b;
        b = t;
    }
    if (b == -(trk_real)INFINITY) return a;
    return a + trk_log1p(trk_exp(b - a));
}

trk_real trk_visibility_predict(const struct trk_visibility_model *m, const struct trk_visibility *v)
{
    /* eq 1: Markov prediction */
    return m->params.delta_stay * v->pv + m->params.delta_become * (1 - v->pv);
}

/* The scan's posterior pv into v, then eq 2 and the decision. */
static void commit(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pv_pred, trk_real pv)
{
    const struct trk_visibility_params *p = &m->params;
    /* eq 2: smoothed confidence */
    const trk_real pcv = (1 - p->omega_c) * pv + p->omega_c * v->pcv;
    v->pv_pred = pv_pred;
    v->pv = pv;
    v->pcv = pcv;
    /* sticky decision (visibility.h): CONTINUE -> CONFIRM -> TERMINATE or
     * CONTINUE -> TERMINATE; TERMINATE is final (p_term < p_con: at most one
     * of the two rules fires in a scan) */
    if (v->decision != TRK_DECISION_TERMINATE) {
        if (pcv < p->p_term) v->decision = TRK_DECISION_TERMINATE;
        else if (v->decision == TRK_DECISION_CONTINUE && pcv >= p->p_con) v->decision = TRK_DECISION_CONFIRM;
    }
    if (v->scans < INT_MAX) v->scans++;
}

trk_status trk_visibility_update_posterior(const struct trk_visibility_model *m, struct trk_visibility *v,
                                           trk_real pv_post)
{
    if (!m || !v) return TRK_E_ARG;
    if (!isfinite(pv_post)) return TRK_E_NAN;
    if (!(pv_post >= 0 && pv_post <= 1)) return TRK_E_RANGE;
    commit(m, v, trk_visibility_predict(m, v), pv_post);
    return TRK_OK;
}

trk_status trk_visibility_update_log(const struct trk_visibility_model *m, struct trk_visibility *v,
                                     trk_real pd, trk_real pg, trk_real log_sum)
{
    if (!m || !v) return TRK_E_ARG;
    /* log_sum = +inf (a detection where the clutter density is 0) is a
     * certain detection: Lam = inf, pv = 1 unless pv_pred = 0 */
    if (!isfinite(pd) || !isfinite(pg) || isnan(log_sum)) return TRK_E_NAN;
    if (!(pd > 0 && pd <= 1) || !(pg > 0 && pg <= 1)) return TRK_E_RANGE;
    const trk_real pv_pred = trk_visibility_predict(m, v);
    /* ln Lam = ln((1 - pd pg) + pd e^log_sum) */
    const trk_real miss = 1 - pd * pg;
    const trk_real ln_det = trk_log(pd) + log_sum;
    const trk_real ln_lam = miss > 0 ? log_add(trk_log(miss), ln_det) : ln_det;
    /* pv = 1 - beta_-1 = logistic(ln(pv_pred / (1 - pv_pred)) + ln Lam) (eqs 21-24) */
    trk_real pv;
    if (pv_pred <= 0 || ln_lam == -(trk_real)INFINITY) {
        pv = 0;
    } else if (pv_pred >= 1) {
        pv = 1;
    } else {
        const trk_real z = trk_log(pv_pred) - trk_log1p(-pv_pred) + ln_lam;
        pv = z >= 0 ? 1 / (1 + trk_exp(-z)) : trk_exp(z) / (1 + trk_exp(z));
    }
    commit(m, v, pv_pred, pv);
    return TRK_OK;
}

trk_status trk_visibility_step(const struct trk_visibility_model *m, struct trk_visibility *v, trk_real pd,
                               trk_real pg, trk_real log_sum, enum trk_decision *decision)
{
    if (!m || !v || !decision) return TRK_E_ARG;
    trk_status st = trk_visibility_update_log(m, v, pd, pg, log_sum);
    if (st != TRK_OK) return st;
    *decision = v->decision;
    return TRK_OK;
}

trk_status trk_visibility_log_sum(size_t n, const trk_real *gd, trk_real rho, const trk_real *log_la,
                                  trk_real *log_sum)
{
    if (!log_sum || (n > 0 && !gd)) return TRK_E_ARG;
    if (n > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (!isfinite(rho)) return TRK_E_NAN;
    if (!(rho > 0)) return TRK_E_RANGE;
    /* log-sum-exp of ln(gd_i/rho) + ln l_i: first the maximum, then the sum */
    const trk_real ln_rho = trk_log(rho);
    trk_real top = -(trk_real)INFINITY;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(gd[i]) || (log_la && !isfinite(log_la[i]))) return TRK_E_NAN;
        if (!(gd[i] >= 0)) return TRK_E_RANGE;
        const trk_real t = trk_log(gd[i]) - ln_rho + (log_la ? log_la[i] : 0);
        if (t > top) top = t;
    }
    trk_real ls = top;
    if (top > -(trk_real)INFINITY) {
        trk_real sum = 0;
        for (size_t i = 0; i < n; i++) sum += trk_exp(trk_log(gd[i]) - ln_rho + (log_la ? log_la[i] : 0) - top);
        ls = top + trk_log(sum);
    }
    *log_sum = ls;
    return TRK_OK;
}
