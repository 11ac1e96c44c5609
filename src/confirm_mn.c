/* confirm_mn.c - M-of-N confirmation (trk/confirm_mn.h). */
#include "trk/confirm_mn.h"

#include "window_impl.h"

trk_status trk_mn_model_init(struct trk_mn_model *m, const struct trk_mn_params *p)
{
    if (!m || !p) return TRK_E_ARG;
    if (p->mode != TRK_MN_FIXED && p->mode != TRK_MN_SLIDING) return TRK_E_ARG;
    if (p->n < 1 || p->n > TRK_MN_MAX_N || p->m < 1 || p->m > p->n) return TRK_E_RANGE;
    m->m = p->m;
    m->n = p->n;
    m->mode = p->mode;
    return TRK_OK;
}

void trk_mn_reset(const struct trk_mn_model *m, struct trk_mn *s)
{
    if (!m || !s) return;
    s->history = 0;
    s->t = 0;
    s->count = 0;
    s->decision = TRK_DECISION_CONTINUE;
}

trk_status trk_mn_step(const struct trk_mn_model *md, struct trk_mn *s, int detected,
                       enum trk_decision *decision)
{
    if (!md || !s || !decision) return TRK_E_ARG;
    if (detected != 0 && detected != 1) return TRK_E_RANGE;
    const int m = md->m, n = md->n;
    if (md->mode == TRK_MN_FIXED) {
        /* count over scans 1..n only */
        if (s->t < (uint32_t)n) {
            s->count += detected;
            s->history = (s->history << 1) | (uint64_t)detected;
        }
        if (s->t < UINT32_MAX) s->t++;
        if (s->decision == TRK_DECISION_CONTINUE && s->t <= (uint32_t)n) {
            if (s->count >= m) s->decision = TRK_DECISION_CONFIRM;
            else if (s->count + (n - (int)s->t) < m) s->decision = TRK_DECISION_TERMINATE;
        }
    } else {
        trk_i_window_push(&s->history, &s->count, s->t, n, detected);
        if (s->t < UINT32_MAX) s->t++;
        if (s->decision == TRK_DECISION_CONTINUE && s->count >= m) s->decision = TRK_DECISION_CONFIRM;
    }
    *decision = s->decision;
    return TRK_OK;
}
