/* term_kn.c - K-of-N termination (trk/term_kn.h). */
#include "trk/term_kn.h"

#include "window_impl.h"

trk_status trk_kn_init(struct trk_kn *s, const struct trk_kn_params *p)
{
    if (!s || !p) return TRK_E_ARG;
    if (p->n < 1 || p->n > TRK_KN_MAX_N || p->k < 0 || p->k >= p->n) return TRK_E_RANGE;
    s->params = *p;
    s->history = 0;
    s->t = 0;
    s->count = 0;
    s->fire = 0;
    s->decision = 0;
    return TRK_OK;
}

int trk_kn_step(struct trk_kn *s, int detected)
{
    trk_i_window_push(&s->history, &s->count, s->t, s->params.n, detected);
    s->t++;
    s->fire = s->t >= (uint32_t)s->params.n && s->count <= s->params.k;
    if (s->fire) s->decision = 1;
    return s->decision;
}
