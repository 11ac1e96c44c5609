/* track_tests.c - dispatch from the tracker to the confirmation and
 * termination tests (see track_tests.h and trk/tracker.h). Every test's step
 * has the same shape and reports the same sticky enum trk_decision
 * (types.h), so nothing here translates decision codings: each case feeds
 * its test the per-scan input and copies the statistic for display. Only the
 * int forms kept for src/tracker.c (trk_i_confirm_step, trk_i_term_step)
 * map the enum to their return codes. */
#include "track_tests.h"

#include "internal.h"
#include "trk/special.h"

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
    case TRK_CONFIRM_EXISTENCE: {
        const struct trk_existence_confirm_params *x = &p->confirm.u.existence;
        if (!p->track_visibility) return TRK_E_ARG;
        if (!isfinite(x->p_confirm) || !isfinite(x->reject_odds_ratio) || !isfinite(x->count_alpha)) return TRK_E_NAN;
        st = trk_i_existence_confirm_ok(x) ? TRK_OK : TRK_E_RANGE;
        c->existence.count_keep = 1 - 1 / p->clutter_map.time_constant_scans; /* tau checked with the map */
        break;
    }
    default: return TRK_E_ARG;
    }
    if (st != TRK_OK) return st;
    switch (p->term.method) {
    case TRK_TERM_KN: st = trk_kn_model_init(&e->kn, &p->term.u.kn); break;
    case TRK_TERM_PAGE: st = trk_page_model_init(&e->page, &p->term.u.page); break;
    case TRK_TERM_SHIRYAEV: st = trk_shiryaev_model_init(&e->shiryaev, &p->term.u.shiryaev); break;
    case TRK_TERM_VISIBILITY: st = p->track_visibility ? TRK_OK : TRK_E_ARG; break;
    case TRK_TERM_EXISTENCE: {
        const trk_real pt = p->term.u.existence.p_terminate;
        if (!p->track_visibility) return TRK_E_ARG;
        if (!isfinite(pt)) return TRK_E_NAN;
        st = pt >= TRK_REAL_MIN && pt < 1 &&
                     !(p->confirm.method == TRK_CONFIRM_EXISTENCE && pt >= p->confirm.u.existence.p_confirm)
                 ? TRK_OK
                 : TRK_E_RANGE;
        break;
    }
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
    case TRK_CONFIRM_EXISTENCE: {
        /* odds(pv) < r odds(e0)  <=>  pv < r e0 / (1 - e0 + r e0): once per track */
        const trk_real r = t->params.confirm.u.existence.reject_odds_ratio, e0 = tr->existence0;
        c->existence.reject_below = r > 0 && e0 < 1 ? r * e0 / (1 - e0 + r * e0) : 0;
        c->existence.count_gated = c->existence.count_expected = 0;
        c->existence.count_gated_all = c->existence.count_expected_all = 0;
        c->existence.persist_llr = 0;
        tr->confirm_stat = tr->vis.pv;
        break;
    }
    default: break;
    }
}

/* The existence test's sums with this look: the gate-count check's
 * (trk/tracker.h count_alpha), the detections in the gate's ring and the
 * count the track's model expects there, each forgotten at 1 - 1/tau per
 * look; and the evidence of a target against a persistent scatterer, ln
 * L_t / L_s summed over the track's looks and kept within +-h/2 (h =
 * stationary_d2): it moves the motion test's bar to h - 2 min(S, h/10), in
 * [4h/5, 2h] (standing_still, track_life_impl.h), and a bound lets a held scatterer
 * that starts to move, or a target that a few strong echoes made look like
 * one, show it within a few looks rather than after as many as it has
 * had (the survey's counter capped at M, ch. 5.3). */
static void existence_look(const struct trk_tracker *t, struct trk_track *tr, const struct trk_look *look)
{
    const trk_real keep = t->confirm_model.existence.count_keep;
    tr->test.confirm.existence.count_gated = keep * tr->test.confirm.existence.count_gated + (trk_real)look->n_ring;
    tr->test.confirm.existence.count_expected = keep * tr->test.confirm.existence.count_expected + look->n_ring_expected;
    tr->test.confirm.existence.count_gated_all =
        keep * tr->test.confirm.existence.count_gated_all + (trk_real)look->n_gated;
    tr->test.confirm.existence.count_expected_all =
        keep * tr->test.confirm.existence.count_expected_all + look->n_expected_all;
    const trk_real half = t->params.stationary_d2 / 2, s = tr->test.confirm.existence.persist_llr + look->persist_llr;
    tr->test.confirm.existence.persist_llr = s > half ? half : s < -half ? -half : s;
}

trk_real trk_i_gate_count_tail(trk_real gated, trk_real expected)
{
    /* P(N >= k; mu) = P(chi2 with 2k degrees of freedom <= 2 mu), k = floor(gated).
     * The target's detections are Bernoulli, not Poisson: the Poisson tail of
     * the same mean is the larger, so the check errs towards confirming. */
    const trk_real k = trk_floor(gated);
    if (!(k >= 1)) return 1;
    if (!(expected > 0)) return 0;
    if (k > TRK_REAL_C(1e6)) return 0; /* beyond any gate's count: 2k must stay an int */
    return trk_chi2_cdf(2 * (int)k, 2 * expected);
}

/* TRK_CONFIRM_EXISTENCE on the existence the scan's update left in tr->vis
 * (the rejection threshold was derived at the track's start); at p_confirm
 * the gate-count check may hold the confirmation for this look */
static enum trk_decision existence_confirm(const struct trk_existence_confirm_params *x,
                                           const struct trk_track *tr)
{
    if (tr->vis.pv >= x->p_confirm) {
        const trk_real alpha = x->count_alpha;
        if (alpha > 0 && (trk_i_gate_count_tail(tr->test.confirm.existence.count_gated,
                                                tr->test.confirm.existence.count_expected) < alpha ||
                          trk_i_gate_count_tail(tr->test.confirm.existence.count_gated_all,
                                                tr->test.confirm.existence.count_expected_all) < alpha))
            return TRK_DECISION_CONTINUE;
        return TRK_DECISION_CONFIRM;
    }
    if (tr->vis.pv < tr->test.confirm.existence.reject_below) return TRK_DECISION_TERMINATE;
    return TRK_DECISION_CONTINUE;
}

/* d starts as the state's decision: a step that is skipped (no input for
 * the clutter tests) or refused (pfa outside (0, 1), possible only when
 * lambda V_G is 0 or huge) leaves the state and the decision as they were. */
enum trk_decision trk_i_confirm_decide(const struct trk_tracker *t, struct trk_track *tr,
                                       const struct trk_look *look)
{
    const union trk_confirm_model *m = &t->confirm_model;
    union trk_confirm_state *c = &tr->test.confirm;
    const int det = look->detected != 0;
    enum trk_decision d = TRK_DECISION_CONTINUE;
    switch (t->params.confirm.method) {
    case TRK_CONFIRM_MN:
        d = c->mn.decision;
        TRK_CHECKED(trk_mn_step(&m->mn, &c->mn, det, &d));
        tr->confirm_stat = (trk_real)c->mn.count;
        break;
    case TRK_CONFIRM_SPRT:
        d = c->sprt.decision;
        TRK_CHECKED(trk_sprt_step(&m->sprt, &c->sprt, look->sensor_id, det, look->pfa_gate, &d));
        tr->confirm_stat = c->sprt.stat;
        break;
#if TRK_WITH_CLUTTER_TESTS
    case TRK_CONFIRM_CLUTTER_CHI2:
        d = c->chi2.decision;
        if (look->has_nearest) TRK_CHECKED(trk_clutter_chi2_step(&m->chi2, &c->chi2, look->rho_vg, &d));
        tr->confirm_stat = c->chi2.p_value;
        break;
    case TRK_CONFIRM_CLUTTER_AMP:
        d = c->amp.decision;
        if (look->has_nearest && look->has_amp)
            TRK_CHECKED(trk_clutter_amp_step(&m->amp, &c->amp, look->a_assoc_db, look->n_others,
                                             look->a_others_db, &d));
        tr->confirm_stat = c->amp.p_value;
        break;
#endif
    case TRK_CONFIRM_VISIBILITY: /* tr->vis was stepped with this scan */
        d = tr->vis.decision;
        tr->confirm_stat = tr->vis.pcv;
        break;
    case TRK_CONFIRM_EXISTENCE:
        if (look->seen) existence_look(t, tr, look);
        d = existence_confirm(&t->params.confirm.u.existence, tr);
        tr->confirm_stat = tr->vis.pv;
        break;
    default: break;
    }
    return d;
}

int trk_i_confirm_step(const struct trk_tracker *t, struct trk_track *tr,
                       const struct trk_look *look)
{
    switch (trk_i_confirm_decide(t, tr, look)) {
    case TRK_DECISION_CONFIRM: return 1;
    case TRK_DECISION_TERMINATE: return -1;
    default: return 0;
    }
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
    case TRK_TERM_VISIBILITY:
        /* confirmed by another test: the visibility test starts from here,
         * its confidence at the current visibility (its sticky decision may
         * hold a TERMINATE from a start below p_term) */
        if (t->params.confirm.method != TRK_CONFIRM_VISIBILITY) {
            tr->vis.pcv = tr->vis.pv;
            tr->vis.decision = TRK_DECISION_CONFIRM;
        }
        tr->term_stat = tr->vis.pcv;
        break;
    case TRK_TERM_EXISTENCE: tr->term_stat = tr->vis.pv; break;
    default: break;
    }
}

enum trk_decision trk_i_term_decide(const struct trk_tracker *t, struct trk_track *tr,
                                    const struct trk_look *look)
{
    const union trk_term_model *m = &t->term_model;
    union trk_term_state *e = &tr->test.term;
    const int det = look->detected != 0;
    enum trk_decision d = TRK_DECISION_CONTINUE;
    switch (t->params.term.method) {
    case TRK_TERM_KN:
        d = e->kn.decision;
        TRK_CHECKED(trk_kn_step(&m->kn, &e->kn, det, &d));
        tr->term_stat = (trk_real)e->kn.count;
        break;
    case TRK_TERM_PAGE:
        d = e->page.decision;
        TRK_CHECKED(trk_page_step(&m->page, &e->page, look->sensor_id, det, look->pfa_gate, &d));
        tr->term_stat = e->page.stat;
        break;
    case TRK_TERM_SHIRYAEV:
        d = e->shiryaev.decision;
        TRK_CHECKED(trk_shiryaev_step(&m->shiryaev, &e->shiryaev, look->sensor_id, det,
                                      look->pfa_gate, &d));
        tr->term_stat = e->shiryaev.stat;
        break;
    case TRK_TERM_VISIBILITY:
        /* the visibility state serves both roles: CONFIRM (of its own
         * confirmation rule) means "continue" to a termination test */
        d = tr->vis.decision;
        tr->term_stat = tr->vis.pcv;
        break;
    case TRK_TERM_EXISTENCE:
        d = tr->vis.pv < t->params.term.u.existence.p_terminate ? TRK_DECISION_TERMINATE : TRK_DECISION_CONTINUE;
        tr->term_stat = tr->vis.pv;
        break;
    default: break;
    }
    return d == TRK_DECISION_TERMINATE ? TRK_DECISION_TERMINATE : TRK_DECISION_CONTINUE;
}

int trk_i_term_step(const struct trk_tracker *t, struct trk_track *tr,
                    const struct trk_look *look)
{
    return trk_i_term_decide(t, tr, look) == TRK_DECISION_TERMINATE;
}
