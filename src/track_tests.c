/* track_tests.c - dispatch from the tracker to the confirmation and
 * termination tests (see track_tests.h and trk/tracker.h). */
#include "track_tests.h"

#include "internal.h"

int trk_i_confirm_needs_nearest(const struct trk_tracker_params *p)
{
#if TRK_WITH_CLUTTER_TESTS
    return p->confirm.method == TRK_CONFIRM_CLUTTER_CHI2 || p->confirm.method == TRK_CONFIRM_CLUTTER_AMP;
#else
    (void)p;
    return 0;
#endif
}

trk_status trk_i_tests_init(const struct trk_tracker_params *p, union trk_confirm_model *c,
                            union trk_term_model *e)
{
    trk_status st;
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN: st = trk_mn_model_init(&c->mn, &p->confirm.u.mn); break;
    case TRK_CONFIRM_SPRT: st = trk_sprt_model_init(&c->sprt, &p->confirm.u.sprt); break;
#if TRK_WITH_CLUTTER_TESTS
    case TRK_CONFIRM_CLUTTER_CHI2: st = trk_clutter_chi2_model_init(&c->chi2, &p->confirm.u.chi2); break;
    case TRK_CONFIRM_CLUTTER_AMP: st = trk_clutter_amp_model_init(&c->amp, &p->confirm.u.amp); break;
#else
    case TRK_CONFIRM_CLUTTER_CHI2:
    case TRK_CONFIRM_CLUTTER_AMP: return TRK_E_UNSUPPORTED;
#endif
    case TRK_CONFIRM_VISIBILITY: st = p->track_visibility ? TRK_OK : TRK_E_ARG; break;
    default: return TRK_E_ARG;
    }
    if (st != TRK_OK) return st;
    switch (p->term.method) {
    case TRK_TERM_KN: st = trk_kn_model_init(&e->kn, &p->term.u.kn); break;
    case TRK_TERM_PAGE: st = trk_page_model_init(&e->page, &p->term.u.page); break;
    case TRK_TERM_SHIRYAEV: st = trk_shiryaev_model_init(&e->shiryaev, &p->term.u.shiryaev); break;
    case TRK_TERM_VISIBILITY: st = p->track_visibility ? TRK_OK : TRK_E_ARG; break;
    default: return TRK_E_ARG;
    }
    if (st != TRK_OK) return st;
    /* multisensor tests must know every sensor of the tracker */
    if ((p->confirm.method == TRK_CONFIRM_SPRT && p->confirm.u.sprt.model == TRK_SPRT_HMM &&
         p->confirm.u.sprt.hmm.n_sensors < p->n_sensors) ||
        (p->term.method == TRK_TERM_PAGE && p->term.u.page.hmm.n_sensors < p->n_sensors) ||
        (p->term.method == TRK_TERM_SHIRYAEV && p->term.u.shiryaev.hmm.n_sensors < p->n_sensors))
        return TRK_E_SENSOR;
    return TRK_OK;
}

void trk_i_confirm_start(const struct trk_tracker *t, struct trk_track *tr)
{
    const union trk_confirm_model *m = &t->confirm_model;
    union trk_confirm_state *c = &tr->test.confirm;
    tr->confirm_stat = 0;
    switch (t->params.confirm.method) {
    case TRK_CONFIRM_MN: trk_mn_reset(&m->mn, &c->mn); break;
    case TRK_CONFIRM_SPRT: trk_sprt_reset(&m->sprt, &c->sprt); break;
#if TRK_WITH_CLUTTER_TESTS
    case TRK_CONFIRM_CLUTTER_CHI2:
        trk_clutter_chi2_reset(&m->chi2, &c->chi2);
        tr->confirm_stat = c->chi2.p_value;
        break;
    case TRK_CONFIRM_CLUTTER_AMP:
        trk_clutter_amp_reset(&m->amp, &c->amp);
        tr->confirm_stat = c->amp.p_value;
        break;
#endif
    case TRK_CONFIRM_VISIBILITY: tr->confirm_stat = tr->vis.pcv; break;
    default: break;
    }
}

int trk_i_confirm_step(const struct trk_tracker *t, struct trk_track *tr,
                       const struct trk_look *look)
{
    const union trk_confirm_model *m = &t->confirm_model;
    union trk_confirm_state *c = &tr->test.confirm;
    switch (t->params.confirm.method) {
    case TRK_CONFIRM_MN:
        (void)trk_mn_step(&m->mn, &c->mn, look->detected);
        tr->confirm_stat = (trk_real)c->mn.count;
        return c->mn.decision;
    case TRK_CONFIRM_SPRT:
        /* an invalid pfa (cannot happen: 0 < pfa < 1 unless lambda V_G is 0
         * or huge) leaves the statistic unchanged */
        if (look->pfa_gate > 0 && look->pfa_gate < 1)
            TRK_CHECKED(trk_sprt_step(&m->sprt, &c->sprt, look->sensor_id, look->detected,
                                      look->pfa_gate));
        tr->confirm_stat = c->sprt.stat;
        return c->sprt.decision;
#if TRK_WITH_CLUTTER_TESTS
    case TRK_CONFIRM_CLUTTER_CHI2:
        if (look->has_nearest) TRK_CHECKED(trk_clutter_chi2_step(&m->chi2, &c->chi2, look->rho_vg));
        tr->confirm_stat = c->chi2.p_value;
        return c->chi2.decision;
    case TRK_CONFIRM_CLUTTER_AMP:
        if (look->has_nearest && look->has_amp)
            TRK_CHECKED(trk_clutter_amp_step(&m->amp, &c->amp, look->a_assoc_db, look->n_others,
                                             look->a_others_db));
        tr->confirm_stat = c->amp.p_value;
        return c->amp.decision;
#endif
    case TRK_CONFIRM_VISIBILITY: /* tr->vis was updated with this scan */
        tr->confirm_stat = tr->vis.pcv;
        if (tr->vis.confirmed) return 1;
        return tr->vis.terminated ? -1 : 0; /* confidence fell below p_term: reject */
    default: break;
    }
    return 0;
}

void trk_i_term_start(const struct trk_tracker *t, struct trk_track *tr)
{
    const union trk_term_model *m = &t->term_model;
    union trk_term_state *e = &tr->test.term;
    tr->term_stat = 0;
    switch (t->params.term.method) {
    case TRK_TERM_KN: trk_kn_reset(&m->kn, &e->kn); break;
    case TRK_TERM_PAGE: trk_page_reset(&m->page, &e->page); break;
    case TRK_TERM_SHIRYAEV:
        trk_shiryaev_reset(&m->shiryaev, &e->shiryaev);
        tr->term_stat = e->shiryaev.stat; /* g_0 */
        break;
    case TRK_TERM_VISIBILITY: tr->term_stat = tr->vis.pcv; break;
    default: break;
    }
}

int trk_i_term_step(const struct trk_tracker *t, struct trk_track *tr,
                    const struct trk_look *look)
{
    const union trk_term_model *m = &t->term_model;
    union trk_term_state *e = &tr->test.term;
    const int pfa_ok = look->pfa_gate > 0 && look->pfa_gate < 1;
    switch (t->params.term.method) {
    case TRK_TERM_KN:
        (void)trk_kn_step(&m->kn, &e->kn, look->detected);
        tr->term_stat = (trk_real)e->kn.count;
        return e->kn.decision;
    case TRK_TERM_PAGE:
        if (pfa_ok)
            TRK_CHECKED(trk_page_step(&m->page, &e->page, look->sensor_id, look->detected,
                                      look->pfa_gate));
        tr->term_stat = e->page.stat;
        return e->page.decision;
    case TRK_TERM_SHIRYAEV:
        if (pfa_ok)
            TRK_CHECKED(trk_shiryaev_step(&m->shiryaev, &e->shiryaev, look->sensor_id,
                                          look->detected, look->pfa_gate));
        tr->term_stat = e->shiryaev.stat;
        return e->shiryaev.decision;
    case TRK_TERM_VISIBILITY:
        tr->term_stat = tr->vis.pcv;
        return tr->vis.terminated;
    default: break;
    }
    return 0;
}
