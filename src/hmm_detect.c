/* hmm_detect.c - two-state Markov detection model: predictive likelihood f1
 * per sensor, complete or paper event model (trk/hmm_detect.h; Blanding
 * 2007 eqs 7-10, Willett eqs 60-64; docs/conventions.md "Complete detection-event
 * model"). */
#include "trk/hmm_detect.h"

void trk_hmm_params_uniform(struct trk_hmm_params *params, unsigned n_sensors,
                            const struct trk_hmm_sensor_params *each)
{
    if (!params || !each) return;
    params->n_sensors = n_sensors;
    for (unsigned i = 0; i < TRK_MAX_SENSORS; i++) params->sensor[i] = *each;
    params->events = TRK_EVENTS_COMPLETE;
}

static int prob_open(trk_real v) { return v > 0 && v < 1; }
static int prob_closed(trk_real v) { return v >= 0 && v <= 1; }

trk_status trk_hmm_model_init(struct trk_hmm_model *m, const struct trk_hmm_params *params)
{
    if (!m || !params) return TRK_E_ARG;
    if (params->events != TRK_EVENTS_COMPLETE && params->events != TRK_EVENTS_PAPER)
        return TRK_E_ARG;
    if (params->n_sensors > TRK_MAX_SENSORS) return TRK_E_CAPACITY;
    if (params->n_sensors == 0) return TRK_E_RANGE;
    for (unsigned i = 0; i < params->n_sensors; i++) {
        const struct trk_hmm_sensor_params *sp = &params->sensor[i];
        if (!isfinite(sp->p_low_high) || !isfinite(sp->q_high_low) ||
            !isfinite(sp->pd_low) || !isfinite(sp->pd_high) || !isfinite(sp->pi0_high))
            return TRK_E_NAN;
        if (!prob_closed(sp->p_low_high) || !prob_closed(sp->q_high_low) ||
            !prob_open(sp->pd_low) || !prob_open(sp->pd_high))
            return TRK_E_RANGE;
        if (sp->pi0_high == TRK_HMM_PI0_STATIONARY) {
            if (!(sp->p_low_high + sp->q_high_low > 0)) return TRK_E_RANGE;
        } else if (!prob_closed(sp->pi0_high)) {
            return TRK_E_RANGE;
        }
    }
    m->n_sensors = params->n_sensors;
    m->events = params->events;
    for (unsigned i = 0; i < TRK_MAX_SENSORS; i++) {
        const struct trk_hmm_sensor_params *sp = &params->sensor[i < params->n_sensors ? i : 0];
        m->s[i].p = sp->p_low_high;
        m->s[i].q = sp->q_high_low;
        m->s[i].pd_low = sp->pd_low;
        m->s[i].pd_high = sp->pd_high;
        /* eq 2: stationary P(u = 1) = p / (p + q) */
        m->s[i].pi0_high = sp->pi0_high == TRK_HMM_PI0_STATIONARY
                               ? sp->p_low_high / (sp->p_low_high + sp->q_high_low)
                               : sp->pi0_high;
    }
    return TRK_OK;
}

void trk_hmm_state_reset(const struct trk_hmm_model *m, struct trk_hmm_state *st)
{
    if (!m || !st) return;
    for (unsigned i = 0; i < TRK_MAX_SENSORS; i++) {
        st->post_high[i] = 0;
        st->n_looks[i] = 0;
    }
}

/* eq 10: one transition of the chain per look of the sensor. */
static trk_real prior_high(const struct trk_hmm_model *m, const struct trk_hmm_state *st,
                           unsigned i)
{
    if (st->n_looks[i] == 0) return m->s[i].pi0_high;
    const trk_real post = st->post_high[i];
    return post * (1 - m->s[i].q) + (1 - post) * m->s[i].p;
}

trk_real trk_hmm_prior_high(const struct trk_hmm_model *m, const struct trk_hmm_state *st,
                            unsigned sensor)
{
    if (!m || !st || sensor >= m->n_sensors) return (trk_real)NAN;
    return prior_high(m, st, sensor);
}

/* The paper's eq 8 as printed (TRK_EVENTS_PAPER): e = Pd for a hit, 1 - Pd
 * for a miss. Kept bit for bit as before the complete model existed. */
static void update_paper(const struct trk_hmm_model *m, struct trk_hmm_state *st, unsigned sensor,
                         int detected, trk_real ph, trk_real *log_f1)
{
    const trk_real pl = 1 - ph;
    const trk_real pdh = m->s[sensor].pd_high, pdl = m->s[sensor].pd_low;
    /* e: likelihood of the outcome per state; c = 1 - e (the other outcome) */
    trk_real eh, el, ch, cl;
    if (detected) {
        eh = pdh, el = pdl, ch = 1 - pdh, cl = 1 - pdl;
    } else {
        eh = 1 - pdh, el = 1 - pdl, ch = pdh, cl = pdl;
    }
    const trk_real f1 = ph * eh + pl * el; /* eq 8 */
    /* ln f1 without cancellation: near 1, take log1p of the complement
     * mixture (e.g. a miss with P_D = 1e-6 has ln f1 ~ -1e-6). */
    *log_f1 = f1 <= TRK_REAL_C(0.5) ? trk_log(f1) : trk_log1p(-(ph * ch + pl * cl));
    st->post_high[sensor] = ph * eh / f1; /* eq 9 */
}

/* Complete event model: per state e = 1 - (1-Pd)(1-pfa) for a hit and
 * (1-Pd)(1-pfa) for a miss (docs/conventions.md "Complete detection-event model"). */
static void update_complete(const struct trk_hmm_model *m, struct trk_hmm_state *st,
                            unsigned sensor, int detected, trk_real pfa, trk_real ph,
                            trk_real *log_f1)
{
    const trk_real pl = 1 - ph;
    const trk_real pdh = m->s[sensor].pd_high, pdl = m->s[sensor].pd_low;
    const trk_real mh = 1 - pdh, ml = 1 - pdl; /* target missed, per state */
    if (detected) {
        /* e = Pd + pfa (1-Pd): a sum of non-negative terms, no cancellation */
        const trk_real eh = pdh + pfa * mh, el = pdl + pfa * ml;
        const trk_real f1 = ph * eh + pl * el; /* eq 8, complete */
        /* near 1: log1p of the complement (1-pfa) * (miss mixture) */
        *log_f1 = f1 <= TRK_REAL_C(0.5) ? trk_log(f1)
                                        : trk_log1p(-((1 - pfa) * (ph * mh + pl * ml)));
        st->post_high[sensor] = ph * eh / f1; /* eq 9 */
    } else {
        /* f1 = (1-pfa) * miss mixture; the factor cancels in eq 9, so the
         * posterior is the paper's; ln f1 = log1p(-pfa) + ln(mixture) */
        const trk_real mix = ph * mh + pl * ml;
        const trk_real lmix = mix <= TRK_REAL_C(0.5) ? trk_log(mix)
                                                     : trk_log1p(-(ph * pdh + pl * pdl));
        *log_f1 = trk_log1p(-pfa) + lmix;
        st->post_high[sensor] = ph * mh / mix; /* eq 9 */
    }
}

trk_status trk_hmm_update(const struct trk_hmm_model *m, struct trk_hmm_state *st,
                          unsigned sensor, int detected, trk_real pfa, trk_real *log_f1)
{
    if (!m || !st || !log_f1) return TRK_E_ARG;
    if (sensor >= m->n_sensors) return TRK_E_SENSOR;
    const trk_real ph = prior_high(m, st, sensor); /* eq 10 */
    if (m->events == TRK_EVENTS_PAPER) {
        update_paper(m, st, sensor, detected, ph, log_f1); /* pfa ignored */
    } else {
        if (!isfinite(pfa)) return TRK_E_NAN;
        if (!(pfa >= 0 && pfa < 1)) return TRK_E_RANGE;
        update_complete(m, st, sensor, detected, pfa, ph, log_f1);
    }
    if (st->n_looks[sensor] < UINT32_MAX) st->n_looks[sensor]++;
    return TRK_OK;
}

trk_status trk_hmm_log_f0(int detected, trk_real pfa, trk_real *log_f0)
{
    if (!log_f0) return TRK_E_ARG;
    if (!isfinite(pfa)) return TRK_E_NAN;
    if (!(pfa > 0 && pfa < 1)) return TRK_E_RANGE;
    *log_f0 = detected ? trk_log(pfa) : trk_log1p(-pfa); /* eq 7 */
    return TRK_OK;
}
