/* clutter_test.c - Kennedy's clutter density (chi-square) and clutter
 * amplitude (F) confirmation tests (trk/clutter_test.h; Kennedy 2008 eqs
 * 3-16, sec. 1.4). */
#include "trk/clutter_test.h"

#include "trk/special.h"

/* ------------------------------------------------------------ density */

trk_status trk_clutter_chi2_model_init(struct trk_clutter_chi2_model *m,
                                       const struct trk_clutter_chi2_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (!isfinite(p->alpha)) return TRK_E_NAN;
    if (!(p->alpha > 0 && p->alpha < 1) || p->kmax == 0) return TRK_E_RANGE;
    if (p->kmax > TRK_CLUTTER_KMAX) return TRK_E_CAPACITY;
    /* thresholds first, into the caller's struct only when all succeed */
    trk_real tab[TRK_CLUTTER_KMAX];
    for (unsigned k = 1; k <= p->kmax; k++) {
        trk_status st = trk_chi2_inv(2 * (int)k, p->alpha, &tab[k - 1]); /* eq 10 = alpha */
        if (st != TRK_OK) return st;
    }
    m->alpha = p->alpha;
    m->kmax = p->kmax;
    for (unsigned k = 0; k < TRK_CLUTTER_KMAX; k++) m->threshold_tab[k] = k < p->kmax ? tab[k] : 0;
    return TRK_OK;
}

void trk_clutter_chi2_reset(const struct trk_clutter_chi2_model *m, struct trk_clutter_chi2 *s)
{
    if (!m || !s) return;
    for (unsigned k = 0; k < TRK_CLUTTER_KMAX; k++) s->win[k] = 0;
    s->head = 0;
    s->k = 0;
    s->t = 0;
    s->dof = 0;
    s->stat = 0;
    s->p_value = 1;
    s->threshold = 0;
    s->reject = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_clutter_chi2_step(const struct trk_clutter_chi2_model *m, struct trk_clutter_chi2 *s,
                                 trk_real rho_vg, enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (!isfinite(rho_vg)) return TRK_E_NAN;
    if (!(rho_vg >= 0)) return TRK_E_RANGE;
    s->win[s->head] = rho_vg;
    s->head = s->head + 1 < m->kmax ? s->head + 1 : 0;
    if (s->k < m->kmax) s->k++;
    if (s->t < UINT32_MAX) s->t++;
    /* eq 9: Z_D = 2 sum_window rho V_g, summed afresh (no drift of a running
     * sum over a sliding window) */
    trk_real sum = 0;
    for (unsigned i = 0; i < s->k; i++) sum += s->win[i];
    s->dof = 2 * (int)s->k;
    s->stat = 2 * sum;
    s->p_value = trk_chi2_cdf(s->dof, s->stat); /* eq 10, lower tail */
    s->threshold = m->threshold_tab[s->k - 1];
    s->reject = s->p_value <= m->alpha;
    if (s->reject) s->decision = TRK_DECISION_CONFIRM; /* H0 (clutter) rejected */
    *decision = s->decision;
    return TRK_OK;
}

/* ------------------------------------------------------------ amplitude */

trk_status trk_clutter_amp_model_init(struct trk_clutter_amp_model *m,
                                      const struct trk_clutter_amp_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (!isfinite(p->alpha) || !isfinite(p->a_min_db)) return TRK_E_NAN;
    if (!(p->alpha > 0 && p->alpha < 1) || p->kmax == 0) return TRK_E_RANGE;
    if (p->kmax > TRK_CLUTTER_KMAX) return TRK_E_CAPACITY;
    m->a_min_db = p->a_min_db;
    m->alpha = p->alpha;
    m->kmax = p->kmax;
    return TRK_OK;
}

void trk_clutter_amp_reset(const struct trk_clutter_amp_model *m, struct trk_clutter_amp *s)
{
    if (!m || !s) return;
    for (unsigned k = 0; k < TRK_CLUTTER_KMAX; k++) {
        s->sa[k] = 0;
        s->so[k] = 0;
        s->n_others[k] = 0;
    }
    s->head = 0;
    s->k = 0;
    s->t = 0;
    s->dof1 = 0;
    s->dof2 = 0;
    s->stat = 0;
    s->p_value = 1;
    s->reject = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_clutter_amp_step(const struct trk_clutter_amp_model *m, struct trk_clutter_amp *s,
                                trk_real a_assoc_db, size_t n_others, const trk_real *a_others_db,
                                enum trk_decision *decision)
{
    if (!m || !s || !decision || (n_others > 0 && !a_others_db)) return TRK_E_ARG;
    if (n_others > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (!isfinite(a_assoc_db)) return TRK_E_NAN;
    if (!(a_assoc_db >= m->a_min_db)) return TRK_E_RANGE;
    trk_real so = 0; /* eq 14 numerator of this scan */
    for (size_t i = 0; i < n_others; i++) {
        if (!isfinite(a_others_db[i])) return TRK_E_NAN;
        if (!(a_others_db[i] >= m->a_min_db)) return TRK_E_RANGE;
        so += a_others_db[i] - m->a_min_db;
    }
    s->sa[s->head] = a_assoc_db - m->a_min_db; /* eq 13 term */
    s->so[s->head] = so;
    s->n_others[s->head] = (uint16_t)n_others; /* <= TRK_MAX_DETECTIONS <= 65535 */
    s->head = s->head + 1 < m->kmax ? s->head + 1 : 0;
    if (s->k < m->kmax) s->k++;
    if (s->t < UINT32_MAX) s->t++;
    trk_real sa_sum = 0, so_sum = 0;
    long n_sum = 0;
    for (unsigned i = 0; i < s->k; i++) {
        sa_sum += s->sa[i];
        so_sum += s->so[i];
        n_sum += (long)s->n_others[i];
    }
    s->dof1 = 2 * (int)s->k;
    s->dof2 = (int)(2 * n_sum);
    if (s->dof2 == 0 || (so_sum == 0 && sa_sum == 0)) {
        /* no other peak in the window (or every amplitude at a_min): no test */
        s->stat = 0;
        s->p_value = 1;
    } else if (so_sum == 0) {
        s->stat = TRK_REAL_MAX; /* Z_A infinite */
        s->p_value = 0;
    } else {
        s->stat = (sa_sum / (trk_real)s->dof1) / (so_sum / (trk_real)s->dof2); /* eq 15 */
        s->p_value = trk_f_sf(s->dof1, s->dof2, s->stat); /* 1 - eq 16 */
    }
    s->reject = s->p_value <= m->alpha;
    if (s->reject) s->decision = TRK_DECISION_CONFIRM; /* H0 (clutter) rejected */
    *decision = s->decision;
    return TRK_OK;
}

trk_status trk_clutter_amp_threshold(const struct trk_clutter_amp_model *m,
                                     const struct trk_clutter_amp *s, trk_real *threshold)
{
    if (!m || !s || !threshold) return TRK_E_ARG;
    if (s->dof2 == 0) return TRK_E_RANGE;
    return trk_f_inv_sf(s->dof1, s->dof2, m->alpha, threshold);
}
