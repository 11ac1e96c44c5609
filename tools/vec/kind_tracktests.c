/* kind_tracktests.c - vector kinds page_hmm, shiryaev_hmm, sprt, clutter_chi2,
 * clutter_amp_f (tests/vectors/tracktests.vec): the library's step
 * functions fed scan by scan; every per-scan output is recorded.
 *
 * Capacity: a case with more sensors (ns) than this build's TRK_MAX_SENSORS
 * (the small-capacity test build has 2) runs the same library code with one
 * single-sensor trk_hmm_model and one trk_hmm_state per sensor feeding
 * trk_page_step_llr / trk_shiryaev_step_llr (the per-sensor Markov states
 * are independent, so the outputs are identical); with enough capacity the
 * integrated trk_page_step / trk_shiryaev_step path runs.
 *
 * Float build (normwise tolerances, see vec.h; measured with
 * `trk-vectors --report-error` in the float build, see the numbers by each
 * kind): the statistics are sums of many float increments, each carrying
 * ~6e-8 relative rounding, so the error grows with the number of scans (up
 * to a few hundred here). Decisions are exact integers but flip when a
 * statistic lies within float rounding of its threshold: such a case is
 * reported as not resolvable in float (VEC_NOT_APPLICABLE) when
 * |stat - threshold| is below a bound on the accumulated float error
 * (FLOAT_FLIP times the sum of the magnitudes that entered the statistic);
 * no public case comes that close. A case whose detection probability is so
 * close to 1 that float cannot hold 1 - P_D to 5e-6 (pshir_overflow: P_D =
 * 0.99999, 1 - P_D off by 1.7e-4 relative in float) cannot match either and
 * is reported the same way.
 * Measured in the float build (max |err| / tolerance used, public set):
 * page_hmm 0.017, shiryaev_hmm 0.037, sprt 0.011, clutter_chi2 0.055,
 * clutter_amp_f 0.013 -- i.e. errors of 1e-7..1e-6 normwise against a
 * tolerance of 2e-5 normwise relative (abs 1e-6): margin for hidden cases
 * with longer runs.
 *
 * Event model (docs/conventions.md "Complete detection-event model"): the cases of
 * tracktests.vec use the paper's form (Blanding eq 8 and the SPRT as
 * printed); a case of page_hmm, shiryaev_hmm or sprt with `in model complete`
 * runs the library's complete model (TRK_EVENTS_COMPLETE), any other word
 * or no `model` line the paper's (TRK_EVENTS_PAPER); a numeric `model` is
 * an error.
 *
 * Decisions: the vector file codes them as numbers (docs/conventions.md "Track
 * confirmation and termination"): confirmation tests +1 confirm, -1 reject,
 * 0 pending; termination tests 1 terminate, 0 continue. The library's
 * enum trk_decision (the step's output, and the SPRT's per-look fire) is
 * translated here, once, into that coding. Every step's decision output is
 * checked against the state's sticky decision. */
#include <math.h>
#include <string.h>

#include "trk/clutter_test.h"
#include "trk/confirm_sprt.h"
#include "trk/special.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"
#include "vec.h"

#define BANK_MAX 64        /* sensors of a case in the capacity fallback */

/* enum trk_decision -> the vector file's coding */
static double confirm_code(enum trk_decision d)
{
    return d == TRK_DECISION_CONFIRM ? 1 : d == TRK_DECISION_TERMINATE ? -1 : 0;
}
static double term_code(enum trk_decision d) { return d == TRK_DECISION_TERMINATE ? 1 : 0; }

/* The decision a step wrote must be the state's sticky one. */
static int same_decision(struct vec_out *o, size_t t, enum trk_decision out, enum trk_decision state)
{
    if (out == state) return 0;
    return vec_fail(o, "scan %zu: step wrote %s, state holds %s", t + 1, trk_decision_str(out),
                    trk_decision_str(state));
}
#define FLOAT_FLIP 2e-5    /* relative margin (vs accumulated magnitude) for a tie in float */

/* The case's event model: `model complete` or the paper's (see the top). */
static int case_events(const struct vec_case *c, struct vec_out *o, enum trk_event_model *ev)
{
    const char *w;
    *ev = TRK_EVENTS_PAPER;
    if (!vec_has_in(c, "model")) return 0;
    if (vec_in_word(c, o, "model", &w)) return -1;
    if (strcmp(w, "complete") == 0) *ev = TRK_EVENTS_COMPLETE;
    return 0;
}

static int deltas(const struct vec_case *c, struct vec_out *o, size_t n, const double **d)
{
    if (vec_in_array_n(c, o, "delta", n, d)) return -1;
    for (size_t i = 0; i < n; i++)
        if ((*d)[i] != 0 && (*d)[i] != 1) return vec_fail(o, "delta must be 0 or 1");
    return 0;
}

/* Float build: a probability close to 1 loses its complement to input
 * rounding (pd = 0.99999 becomes 1 - 1.0001e-5 in float, and ln(1 - pd)
 * moves by 1e-4); outputs cannot match within the float tolerance. */
#define FLOAT_INPUT_REL 5e-6
static int complement_unrepresentable(struct vec_out *o, const char *name, double v)
{
    if (!TRK_REAL_IS_FLOAT || !(v > 0 && v < 1)) return 0;
    const double c = 1 - v, cf = 1 - (double)(float)v;
    if (fabs(cf - c) > FLOAT_INPUT_REL * c) {
        vec_fail(o, "1 - %s = %.3g has relative error %.2g in float", name, c, fabs(cf - c) / c);
        return 1;
    }
    return 0;
}

static int near_tie(struct vec_out *o, size_t t, double stat, double thr, double mag)
{
    if (TRK_REAL_IS_FLOAT && fabs(stat - thr) <= FLOAT_FLIP * (mag + fabs(thr))) {
        vec_fail(o, "scan %zu: statistic %.9g within float rounding of threshold %.9g", t + 1, stat,
                 thr);
        return 1;
    }
    return 0;
}

/* ---------------------------------------------------------------- HMM tests */

struct hmm_case {
    long ns;
    size_t n;
    const double *sensor, *pfa, *delta;
    struct trk_hmm_params hp;   /* ns sensors, or 1 in the capacity fallback;
                                   hp.events the case's event model */
    int bank;                   /* ns > TRK_MAX_SENSORS */
    struct trk_hmm_model bank_model;          /* the one-sensor model */
    struct trk_hmm_state bank_state[BANK_MAX]; /* one chain per sensor */
};

static int hmm_setup(const struct vec_case *c, struct vec_out *o, struct hmm_case *hc)
{
    double p, q, pdl, pdh, pi0;
    const double *sensor;
    enum trk_event_model ev;
    if (case_events(c, o, &ev) || vec_in_int(c, o, "ns", &hc->ns) ||
        vec_in_array(c, o, "sensor", &sensor, &hc->n) ||
        vec_in_scalar(c, o, "p", &p) || vec_in_scalar(c, o, "q", &q) ||
        vec_in_scalar(c, o, "pd_low", &pdl) || vec_in_scalar(c, o, "pd_high", &pdh) ||
        vec_in_scalar(c, o, "pi0_high", &pi0) || vec_in_array_n(c, o, "pfa", hc->n, &hc->pfa) ||
        deltas(c, o, hc->n, &hc->delta))
        return -1;
    hc->sensor = sensor;
    if (complement_unrepresentable(o, "pd_low", pdl) || complement_unrepresentable(o, "pd_high", pdh))
        return VEC_NOT_APPLICABLE;
    if (hc->ns < 1 || hc->ns > BANK_MAX) return vec_fail(o, "ns out of range");
    for (size_t t = 0; t < hc->n; t++)
        if (sensor[t] < 0 || sensor[t] >= (double)hc->ns || sensor[t] != floor(sensor[t]))
            return vec_fail(o, "sensor[%zu] not in 0..ns-1", t);
    const struct trk_hmm_sensor_params sp = {(trk_real)p, (trk_real)q, (trk_real)pdl,
                                             (trk_real)pdh, (trk_real)pi0};
    hc->bank = hc->ns > TRK_MAX_SENSORS;
    trk_hmm_params_uniform(&hc->hp, hc->bank ? 1 : (unsigned)hc->ns, &sp);
    hc->hp.events = ev;
    if (hc->bank) {
        trk_status st = trk_hmm_model_init(&hc->bank_model, &hc->hp);
        if (st != TRK_OK) return vec_fail(o, "trk_hmm_model_init: %s", trk_status_str(st));
        for (long i = 0; i < hc->ns; i++) trk_hmm_state_reset(&hc->bank_model, &hc->bank_state[i]);
    }
    return 0;
}

/* Capacity fallback: s of scan t from sensor i's own single-sensor model. */
static int bank_s(struct hmm_case *hc, struct vec_out *o, size_t t, trk_real *s, double *post)
{
    unsigned i = (unsigned)hc->sensor[t];
    trk_real lf0, lf1;
    trk_status st = trk_hmm_log_f0(hc->delta[t] != 0, (trk_real)hc->pfa[t], &lf0);
    if (st == TRK_OK)
        st = trk_hmm_update(&hc->bank_model, &hc->bank_state[i], 0, hc->delta[t] != 0,
                            (trk_real)hc->pfa[t], &lf1);
    if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
    *s = lf0 - lf1;
    *post = (double)hc->bank_state[i].post_high[0];
    return 0;
}

struct hmm_outs {
    double *s, *post, *stat, *fire, *dec;
};

static int hmm_outs(struct vec_out *o, size_t n, struct hmm_outs *h)
{
    h->s = vec_put_alloc(o, "s", n);
    h->post = vec_put_alloc(o, "post_high", n);
    h->stat = vec_put_alloc(o, "stat", n);
    h->fire = vec_put_alloc(o, "fire", n);
    h->dec = vec_put_alloc(o, "decision", n);
    return h->s && h->post && h->stat && h->fire && h->dec ? 0 : -1;
}

/* page_hmm: float error of c over a run between resets is below
 * ~1e-6 * sum|s|; measured max abs error 1.5e-6 (tolerance use 0.017). */
TRK_VEC_KIND(page_hmm, 1e-6, 2e-5, VEC_FAST)
{
    static struct hmm_case hc;
    double h;
    int rc = hmm_setup(c, o, &hc);
    if (rc) return rc;
    if (vec_in_scalar(c, o, "h", &h)) return -1;
    struct trk_page_params pp;
    pp.hmm = hc.hp;
    pp.h = (trk_real)h;
    static struct trk_page_model pm;
    struct trk_page pg;
    trk_status st = trk_page_model_init(&pm, &pp);
    if (st != TRK_OK) return vec_fail(o, "trk_page_model_init: %s", trk_status_str(st));
    trk_page_reset(&pm, &pg);
    struct hmm_outs out;
    if (hmm_outs(o, hc.n, &out)) return -1;
    double mag = 0;
    for (size_t t = 0; t < hc.n; t++) {
        unsigned i = (unsigned)hc.sensor[t];
        enum trk_decision d = TRK_DECISION_CONTINUE;
        if (hc.bank) {
            trk_real s;
            if (bank_s(&hc, o, t, &s, &out.post[t])) return -1;
            st = trk_page_step_llr(&pm, &pg, s, &d);
        } else {
            st = trk_page_step(&pm, &pg, i, hc.delta[t] != 0, (trk_real)hc.pfa[t], &d);
            out.post[t] = (double)pg.hmm.post_high[i];
        }
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        if (same_decision(o, t, d, pg.decision)) return -1;
        out.s[t] = (double)pg.s;
        out.stat[t] = (double)pg.stat;
        out.fire[t] = pg.fire;
        out.dec[t] = term_code(d);
        mag = pg.stat == 0 ? 0 : mag + fabs((double)pg.s);
        if (near_tie(o, t, (double)pg.stat, h, mag)) return VEC_NOT_APPLICABLE;
    }
    return 0;
}

/* shiryaev_hmm: g accumulates over the whole run (|g| up to a few hundred),
 * error ~ n * 6e-8 * max|g| in float; measured tolerance use 0.037. */
TRK_VEC_KIND(shiryaev_hmm, 1e-6, 2e-5, VEC_FAST)
{
    static struct hmm_case hc;
    double h, beta0, rho;
    int rc = hmm_setup(c, o, &hc);
    if (rc) return rc;
    if (vec_in_scalar(c, o, "h", &h) ||
        vec_in_scalar(c, o, "beta0", &beta0) || vec_in_scalar(c, o, "rho", &rho))
        return -1;
    struct trk_shiryaev_params sp;
    sp.hmm = hc.hp;
    sp.h = (trk_real)h;
    sp.beta0 = (trk_real)beta0;
    sp.rho = (trk_real)rho;
    static struct trk_shiryaev_model sm;
    struct trk_shiryaev sh;
    trk_status st = trk_shiryaev_model_init(&sm, &sp);
    if (st != TRK_OK) return vec_fail(o, "trk_shiryaev_model_init: %s", trk_status_str(st));
    trk_shiryaev_reset(&sm, &sh);
    struct hmm_outs out;
    if (hmm_outs(o, hc.n, &out)) return -1;
    double mag = fabs((double)sh.stat);
    for (size_t t = 0; t < hc.n; t++) {
        unsigned i = (unsigned)hc.sensor[t];
        enum trk_decision d = TRK_DECISION_CONTINUE;
        if (hc.bank) {
            trk_real s;
            if (bank_s(&hc, o, t, &s, &out.post[t])) return -1;
            st = trk_shiryaev_step_llr(&sm, &sh, s, &d);
        } else {
            st = trk_shiryaev_step(&sm, &sh, i, hc.delta[t] != 0, (trk_real)hc.pfa[t], &d);
            out.post[t] = (double)sh.hmm.post_high[i];
        }
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        if (same_decision(o, t, d, sh.decision)) return -1;
        out.s[t] = (double)sh.s;
        out.stat[t] = (double)sh.stat;
        out.fire[t] = sh.fire;
        out.dec[t] = term_code(d);
        mag += fabs((double)sh.s) + fabs((double)sh.stat) * 1e-2;
        if (near_tie(o, t, (double)sh.stat, h, mag)) return VEC_NOT_APPLICABLE;
    }
    return 0;
}

/* ---------------------------------------------------------------- SPRT */

/* sprt: llr is a plain sum of ~40 float increments; measured tolerance use
 * 0.011. */
TRK_VEC_KIND(sprt, 1e-6, 2e-5, VEC_FAST)
{
    double pd, alpha, beta;
    const double *pfa, *delta;
    size_t n;
    enum trk_event_model ev;
    if (case_events(c, o, &ev) || vec_in_scalar(c, o, "pd", &pd) ||
        vec_in_scalar(c, o, "alpha", &alpha) || vec_in_scalar(c, o, "beta", &beta) || vec_in_array(c, o, "pfa", &pfa, &n) ||
        deltas(c, o, n, &delta))
        return -1;
    if (complement_unrepresentable(o, "pd", pd)) return VEC_NOT_APPLICABLE;
    struct trk_sprt_params p;
    memset(&p, 0, sizeof p);
    p.alpha = (trk_real)alpha;
    p.beta = (trk_real)beta;
    p.model = TRK_SPRT_FIXED_PD;
    p.pd = (trk_real)pd;
    p.hmm.events = ev; /* hmm.events applies to fixed P_D too */
    static struct trk_sprt_model m;
    struct trk_sprt s;
    trk_status st = trk_sprt_model_init(&m, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_sprt_model_init: %s", trk_status_str(st));
    trk_sprt_reset(&m, &s);
    double *llr = vec_put_alloc(o, "llr", n), *fire = vec_put_alloc(o, "fire", n),
           *dec = vec_put_alloc(o, "decision", n);
    if (!llr || !fire || !dec || vec_put1(o, "ln_a", (double)m.ln_a) ||
        vec_put1(o, "ln_b", (double)m.ln_b))
        return -1;
    double mag = 0;
    for (size_t t = 0; t < n; t++) {
        enum trk_decision d = TRK_DECISION_CONTINUE;
        st = trk_sprt_step(&m, &s, 0, delta[t] != 0, (trk_real)pfa[t], &d);
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        if (same_decision(o, t, d, s.decision)) return -1;
        llr[t] = (double)s.stat;
        fire[t] = confirm_code(s.fire);
        dec[t] = confirm_code(d);
        mag += fabs((double)s.inc);
        if (near_tie(o, t, (double)s.stat, (double)m.ln_a, mag) ||
            near_tie(o, t, (double)s.stat, (double)m.ln_b, mag))
            return VEC_NOT_APPLICABLE;
    }
    return 0;
}

/* ---------------------------------------------------------------- clutter */

/* p_value <= alpha near a tie in float: the float p-value carries a relative
 * error of ~1e-5 at most (measured <= 2e-6); not_applicable within 1e-4. */
static int p_tie(struct vec_out *o, size_t t, double p, double alpha)
{
    if (TRK_REAL_IS_FLOAT && fabs(p - alpha) <= 1e-4 * alpha) {
        vec_fail(o, "scan %zu: p-value %.9g within float rounding of alpha %.9g", t + 1, p, alpha);
        return 1;
    }
    return 0;
}

/* clutter_chi2: float sums of <= 25 terms and the float chi-square cdf and
 * quantile; measured tolerance use 0.055. */
TRK_VEC_KIND(clutter_chi2, 1e-6, 2e-5, VEC_FAST)
{
    double alpha;
    long kmax;
    const double *rv;
    size_t n;
    if (vec_in_scalar(c, o, "alpha", &alpha) || vec_in_int(c, o, "kmax", &kmax) ||
        vec_in_array(c, o, "rho_vg", &rv, &n))
        return -1;
    if (kmax < 1) return vec_fail(o, "kmax < 1");
    struct trk_clutter_chi2_params p = {(trk_real)alpha, (unsigned)kmax};
    static struct trk_clutter_chi2_model m;
    static struct trk_clutter_chi2 s;
    trk_status st = trk_clutter_chi2_model_init(&m, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_clutter_chi2_model_init: %s", trk_status_str(st));
    trk_clutter_chi2_reset(&m, &s);
    double *dof = vec_put_alloc(o, "dof", n), *stat = vec_put_alloc(o, "stat", n),
           *pv = vec_put_alloc(o, "p_value", n), *thr = vec_put_alloc(o, "threshold", n),
           *rej = vec_put_alloc(o, "reject", n), *dec = vec_put_alloc(o, "decision", n);
    if (!dof || !stat || !pv || !thr || !rej || !dec) return -1;
    for (size_t t = 0; t < n; t++) {
        enum trk_decision d = TRK_DECISION_CONTINUE;
        st = trk_clutter_chi2_step(&m, &s, (trk_real)rv[t], &d);
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        if (same_decision(o, t, d, s.decision)) return -1;
        dof[t] = s.dof;
        stat[t] = (double)s.stat;
        pv[t] = (double)s.p_value;
        thr[t] = (double)s.threshold;
        rej[t] = s.reject;
        dec[t] = confirm_code(d);
        if (p_tie(o, t, pv[t], alpha)) return VEC_NOT_APPLICABLE;
    }
    return 0;
}

/* clutter_amp_f: float sums of dB values, the float F tail and quantile;
 * measured tolerance use 0.013. */
TRK_VEC_KIND(clutter_amp_f, 1e-6, 2e-5, VEC_FAST)
{
    static trk_real others[TRK_MAX_DETECTIONS];
    double a_min, alpha;
    long kmax;
    const double *aa, *no, *ao;
    size_t n, n_ao;
    if (vec_in_scalar(c, o, "a_min", &a_min) || vec_in_scalar(c, o, "alpha", &alpha) ||
        vec_in_int(c, o, "kmax", &kmax) || vec_in_array(c, o, "a_assoc", &aa, &n) ||
        vec_in_array_n(c, o, "n_others", n, &no) || vec_in_array(c, o, "a_others", &ao, &n_ao))
        return -1;
    if (kmax < 1) return vec_fail(o, "kmax < 1");
    size_t total = 0;
    for (size_t t = 0; t < n; t++) {
        if (no[t] < 0 || no[t] != floor(no[t]) || no[t] > TRK_MAX_DETECTIONS)
            return vec_fail(o, "n_others[%zu] not an integer in 0..TRK_MAX_DETECTIONS", t);
        total += (size_t)no[t];
    }
    if (total != n_ao) return vec_fail(o, "a_others has %zu values, n_others sums to %zu", n_ao, total);
    struct trk_clutter_amp_params p = {(trk_real)a_min, (trk_real)alpha, (unsigned)kmax};
    static struct trk_clutter_amp_model m;
    static struct trk_clutter_amp s;
    trk_status st = trk_clutter_amp_model_init(&m, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_clutter_amp_model_init: %s", trk_status_str(st));
    trk_clutter_amp_reset(&m, &s);
    double *dof1 = vec_put_alloc(o, "dof1", n), *dof2 = vec_put_alloc(o, "dof2", n),
           *stat = vec_put_alloc(o, "stat", n), *pv = vec_put_alloc(o, "p_value", n),
           *thr = vec_put_alloc(o, "threshold", n), *rej = vec_put_alloc(o, "reject", n),
           *dec = vec_put_alloc(o, "decision", n);
    if (!dof1 || !dof2 || !stat || !pv || !thr || !rej || !dec) return -1;
    size_t off = 0;
    for (size_t t = 0; t < n; t++) {
        size_t m_others = (size_t)no[t];
        for (size_t i = 0; i < m_others; i++) others[i] = (trk_real)ao[off + i];
        off += m_others;
        enum trk_decision d = TRK_DECISION_CONTINUE;
        st = trk_clutter_amp_step(&m, &s, (trk_real)aa[t], m_others, others, &d);
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        if (same_decision(o, t, d, s.decision)) return -1;
        trk_real th = 0;
        if (s.dof2 > 0) {
            st = trk_clutter_amp_threshold(&m, &s, &th);
            if (st != TRK_OK) return vec_fail(o, "scan %zu threshold: %s", t + 1, trk_status_str(st));
        }
        dof1[t] = s.dof1;
        dof2[t] = s.dof2;
        stat[t] = (double)s.stat;
        pv[t] = (double)s.p_value;
        thr[t] = (double)th;
        rej[t] = s.reject;
        dec[t] = confirm_code(d);
        if (p_tie(o, t, pv[t], alpha)) return VEC_NOT_APPLICABLE;
    }
    return 0;
}
