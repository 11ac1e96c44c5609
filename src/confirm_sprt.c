/* confirm_sprt.c - Wald SPRT track confirmation (trk/confirm_sprt.h;
 * Willett eqs 49-57 in sequential form; complete or paper event model,
 * docs/conventions.md "Complete detection-event model"). */
#include "trk/confirm_sprt.h"

trk_status trk_sprt_model_init(struct trk_sprt_model *m, const struct trk_sprt_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (p->model != TRK_SPRT_FIXED_PD && p->model != TRK_SPRT_HMM) return TRK_E_ARG;
    if (!isfinite(p->alpha) || !isfinite(p->beta)) return TRK_E_NAN;
    if (!(p->alpha > 0 && p->alpha < 1) || !(p->beta > 0 && p->beta < 1) ||
        !(p->alpha + p->beta < 1))
        return TRK_E_RANGE;
    struct trk_hmm_model hmm;
    trk_real log_pd = 0, log_miss = 0;
    if (p->model == TRK_SPRT_FIXED_PD) {
        if (!isfinite(p->pd)) return TRK_E_NAN;
        if (!(p->pd > 0 && p->pd < 1)) return TRK_E_RANGE;
        log_pd = trk_log(p->pd);
        log_miss = trk_log1p(-p->pd);
        /* a valid one-sensor model so that the struct is fully defined; it
         * carries (and validates) hmm.events, the rest of hmm is ignored */
        struct trk_hmm_params hp;
        const struct trk_hmm_sensor_params one = {0, 0, p->pd, p->pd, 1};
        trk_hmm_params_uniform(&hp, 1, &one);
        hp.events = p->hmm.events;
        trk_status st = trk_hmm_model_init(&hmm, &hp);
        if (st != TRK_OK) return st;
    } else {
        trk_status st = trk_hmm_model_init(&hmm, &p->hmm);
        if (st != TRK_OK) return st;
    }
    m->pd_model = p->model;
    m->ln_a = trk_log1p(-p->beta) - trk_log(p->alpha); /* ln((1-beta)/alpha) */
    m->ln_b = trk_log(p->beta) - trk_log1p(-p->alpha); /* ln(beta/(1-alpha)) */
    m->events = hmm.events;
    m->pd = p->model == TRK_SPRT_FIXED_PD ? p->pd : 0;
    m->miss = 1 - m->pd;
    m->log_pd = log_pd;
    m->log_miss = log_miss;
    m->hmm = hmm;
    return TRK_OK;
}

void trk_sprt_reset(const struct trk_sprt_model *m, struct trk_sprt *s)
{
    if (!m || !s) return;
    trk_hmm_state_reset(&m->hmm, &s->hmm);
    s->stat = 0;
    s->inc = 0;
    s->t = 0;
    s->fire = TRK_DECISION_CONTINUE;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_sprt_step_llr(const struct trk_sprt_model *m, struct trk_sprt *s, trk_real inc,
                             enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (!isfinite(inc)) return TRK_E_NAN;
    s->stat += inc;
    s->inc = inc;
    if (s->t < UINT32_MAX) s->t++;
    s->fire = s->stat >= m->ln_a   ? TRK_DECISION_CONFIRM
              : s->stat <= m->ln_b ? TRK_DECISION_TERMINATE
                                   : TRK_DECISION_CONTINUE;
    if (s->decision == TRK_DECISION_CONTINUE) s->decision = s->fire;
    *decision = s->decision;
    return TRK_OK;
}

trk_status trk_sprt_step(const struct trk_sprt_model *m, struct trk_sprt *s, unsigned sensor,
                         int detected, trk_real pfa, enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (detected != 0 && detected != 1) return TRK_E_RANGE;
    trk_real lf0, lf1;
    trk_status st = trk_hmm_log_f0(detected, pfa, &lf0); /* Willett eq 55 factor */
    if (st != TRK_OK) return st;
    if (m->pd_model == TRK_SPRT_FIXED_PD && m->events == TRK_EVENTS_PAPER) {
        lf1 = detected ? m->log_pd : m->log_miss;
    } else if (m->pd_model == TRK_SPRT_FIXED_PD) {
        /* complete model: hit ln(1 - (1-Pd)(1-pfa)), e = Pd + pfa (1-Pd) with
         * log1p of the complement near 1; miss ln(1-Pd) + ln(1-pfa) */
        if (detected) {
            const trk_real e = m->pd + pfa * m->miss;
            lf1 = e <= TRK_REAL_C(0.5) ? trk_log(e) : trk_log1p(-(m->miss * (1 - pfa)));
        } else {
            lf1 = m->log_miss + trk_log1p(-pfa);
        }
    } else {
        st = trk_hmm_update(&m->hmm, &s->hmm, sensor, detected, pfa, &lf1); /* eq 53 factor */
        if (st != TRK_OK) return st;
    }
    return trk_sprt_step_llr(m, s, lf1 - lf0, decision);
}
