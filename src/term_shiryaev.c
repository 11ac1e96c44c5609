/* term_shiryaev.c - Shiryaev termination in the log domain with the HMM
 * detection model (trk/term_shiryaev.h; Blanding 2007 eqs 11-14, Willett
 * eqs 65-68). */
#include "trk/term_shiryaev.h"

trk_status trk_shiryaev_model_init(struct trk_shiryaev_model *m,
                                   const struct trk_shiryaev_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (!isfinite(p->h) || !isfinite(p->beta0) || !isfinite(p->rho)) return TRK_E_NAN;
    if (!(p->beta0 > 0 && p->beta0 < 1) || !(p->rho >= 0 && p->rho < 1)) return TRK_E_RANGE;
    struct trk_hmm_model hmm;
    trk_status st = trk_hmm_model_init(&hmm, &p->hmm);
    if (st != TRK_OK) return st;
    m->hmm = hmm;
    m->h = p->h;
    m->g0 = trk_log(p->beta0) - trk_log1p(-p->beta0); /* eq 13 at k = 0 */
    m->rho_zero = p->rho == 0;
    m->log_rho = m->rho_zero ? 0 : trk_log(p->rho);
    m->log1m_rho = trk_log1p(-p->rho);
    return TRK_OK;
}

void trk_shiryaev_reset(const struct trk_shiryaev_model *m, struct trk_shiryaev *s)
{
    if (!m || !s) return;
    trk_hmm_state_reset(&m->hmm, &s->hmm);
    s->stat = m->g0;
    s->s = 0;
    s->t = 0;
    s->fire = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_shiryaev_step_llr(const struct trk_shiryaev_model *m, struct trk_shiryaev *s,
                                 trk_real s_inc, enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (!isfinite(s_inc)) return TRK_E_NAN;
    trk_real g = s->stat;
    if (!m->rho_zero) {
        /* ln(rho + e^g) = logaddexp(ln rho, g), never forming e^g */
        const trk_real a = m->log_rho;
        const trk_real hi = a > g ? a : g, lo = a > g ? g : a;
        g = hi + trk_log1p(trk_exp(lo - hi));
    }
    s->stat = g - m->log1m_rho + s_inc; /* eq 14 */
    s->s = s_inc;
    if (s->t < UINT32_MAX) s->t++;
    s->fire = s->stat > m->h;
    if (s->fire) s->decision = TRK_DECISION_TERMINATE;
    *decision = s->decision;
    return TRK_OK;
}

trk_status trk_shiryaev_step(const struct trk_shiryaev_model *m, struct trk_shiryaev *s,
                             unsigned sensor, int detected, trk_real pfa,
                             enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (detected != 0 && detected != 1) return TRK_E_RANGE;
    trk_real lf0, lf1;
    trk_status st = trk_hmm_log_f0(detected, pfa, &lf0); /* eq 7 */
    if (st != TRK_OK) return st;
    st = trk_hmm_update(&m->hmm, &s->hmm, sensor, detected, pfa, &lf1); /* eqs 8-10 */
    if (st != TRK_OK) return st;
    return trk_shiryaev_step_llr(m, s, lf0 - lf1, decision); /* eq 5 increment */
}
