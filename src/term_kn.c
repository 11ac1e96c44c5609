/* term_kn.c - K-of-N termination (trk/term_kn.h). */
#include "trk/term_kn.h"

#include "window_impl.h"

trk_status trk_kn_model_init(struct trk_kn_model *m, const struct trk_kn_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (p->n < 1 || p->n > TRK_KN_MAX_N || p->k < 0 || p->k >= p->n) return TRK_E_RANGE;
    m->k = p->k;
    m->n = p->n;
    return TRK_OK;
}

void trk_kn_reset(const struct trk_kn_model *m, struct trk_kn *s)
{
    if (!m || !s) return;
    s->history = 0;
    s->t = 0;
    s->count = 0;
    s->fire = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_kn_step(const struct trk_kn_model *m, struct trk_kn *s, int detected,
                       enum trk_decision *decision)
{
    if (!m || !s || !decision) return TRK_E_ARG;
    if (detected != 0 && detected != 1) return TRK_E_RANGE;
    trk_i_window_push(&s->history, &s->count, s->t, m->n, detected);
    if (s->t < UINT32_MAX) s->t++;
    s->fire = s->t >= (uint32_t)m->n && s->count <= m->k;
    if (s->fire) s->decision = TRK_DECISION_TERMINATE;
    *decision = s->decision;
    return TRK_OK;
}
