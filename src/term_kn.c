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
    s->decision = 0;
}

int trk_kn_step(const struct trk_kn_model *m, struct trk_kn *s, int detected)
{
    trk_i_window_push(&s->history, &s->count, s->t, m->n, detected);
    s->t++;
    s->fire = s->t >= (uint32_t)m->n && s->count <= m->k;
    if (s->fire) s->decision = 1;
    return s->decision;
}
