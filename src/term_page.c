/* term_page.c - Page (CUSUM) termination with the HMM detection model
 * (trk/term_page.h; Blanding 2007 eqs 5-6, Willett eqs 58-59). */
#include "trk/term_page.h"

trk_status trk_page_model_init(struct trk_page_model *m, const struct trk_page_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (!isfinite(p->h)) return TRK_E_NAN;
    if (!(p->h > 0)) return TRK_E_RANGE;
    struct trk_hmm_model hmm;
    trk_status st = trk_hmm_model_init(&hmm, &p->hmm);
    if (st != TRK_OK) return st;
    m->hmm = hmm;
    m->h = p->h;
    return TRK_OK;
}

void trk_page_reset(const struct trk_page_model *m, struct trk_page *s)
{
    if (!m || !s) return;
    trk_hmm_state_reset(&m->hmm, &s->hmm);
    s->stat = 0; /* c_0 = 0 */
    s->s = 0;
    s->t = 0;
    s->fire = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_page_step_llr(const struct trk_page_model *m, struct trk_page *s, trk_real s_inc,
                             enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (!isfinite(s_inc)) return TRK_E_NAN;
    const trk_real c = s->stat + s_inc;
    s->stat = c > 0 ? c : 0; /* eq 6 */
    s->s = s_inc;
    if (s->t < UINT32_MAX) s->t++;
    s->fire = s->stat > m->h;
    if (s->fire) s->decision = TRK_DECISION_TERMINATE;
    *decision = s->decision;
    return TRK_OK;
}

trk_status trk_page_step(const struct trk_page_model *m, struct trk_page *s, unsigned sensor,
                         int detected, trk_real pfa, enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (detected != 0 && detected != 1) return TRK_E_RANGE;
    trk_real lf0, lf1;
    trk_status st = trk_hmm_log_f0(detected, pfa, &lf0); /* eq 7; checks pfa first */
    if (st != TRK_OK) return st;
    /* the HMM advances only when the step goes through: pfa was checked above
     * and trk_hmm_update checks the sensor before it writes */
    st = trk_hmm_update(&m->hmm, &s->hmm, sensor, detected, pfa, &lf1); /* eqs 8-10 */
    if (st != TRK_OK) return st;
    return trk_page_step_llr(m, s, lf0 - lf1, decision); /* eq 5 */
}
