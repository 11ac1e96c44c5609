/* tracker_config.c - the tracker's configuration for the tools
 * (tracker_config.h). */
#include "errmsg.h"
#include "tracker_config.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kvfile.h"
#include "number.h"
#include "suggest.h"
#include "trk/confirm_mn.h"
#include "trk/amplitude.h"
#include "trk/table.h"
#include "trk/table_file.h"
#include "trk/term_kn.h"

/* ------------------------------------------------------------------ defaults */

void tcfg_defaults(struct tcfg *c)
{
    memset(c, 0, sizeof *c);
    trk_tracker_default_params(&c->params);
    for (unsigned s = 1; s < TRK_MAX_SENSORS; s++) c->params.sensor[s] = c->params.sensor[0];
    c->confirm = c->params.confirm.method;
    c->term = c->params.term.method;
    c->existence_confirm = c->params.confirm.u.existence; /* the defaults' methods */
    c->existence_term = c->params.term.u.existence;
    c->mn.m = 3;
    c->mn.n = 5;
    c->mn.mode = TRK_MN_FIXED;
    c->kn.k = 0;
    c->kn.n = 5;
    c->sprt.alpha = TRK_REAL_C(0.01);
    c->sprt.beta = TRK_REAL_C(0.1);
    c->sprt.model = TRK_SPRT_FIXED_PD;
    c->sprt.pd = TRK_REAL_C(0.9);
    c->clutter_density.alpha = TRK_REAL_C(0.01);
    c->clutter_density.kmax = TRK_CLUTTER_KMAX < 25 ? TRK_CLUTTER_KMAX : 25;
    c->clutter_amplitude.alpha = TRK_REAL_C(0.01);
    c->clutter_amplitude.kmax = c->clutter_density.kmax;
    c->clutter_amplitude.a_min_db = 10;
    c->page.h = 5;
    c->shiryaev.beta0 = TRK_REAL_C(0.01);
    c->shiryaev.rho = TRK_REAL_C(0.01);
    c->shiryaev.h = TRK_REAL_C(4.59511985013459); /* ln(0.99 / 0.01) */
    c->hmm.p_low_high = TRK_REAL_C(0.1);
    c->hmm.q_high_low = TRK_REAL_C(0.1);
    c->hmm.pd_low = TRK_REAL_C(0.3);
    c->hmm.pd_high = TRK_REAL_C(0.9);
    c->hmm.pi0_high = TRK_HMM_PI0_STATIONARY;
    c->hmm_events = TRK_EVENTS_COMPLETE;
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) {
        /* a polar sensor's noise: the library leaves it 0 (refused for a
         * polar sensor); the tools start from a valid one */
        c->params.sensor[s].sigma_range_m = 1;
        c->params.sensor[s].sigma_bearing_rad = TRK_REAL_C(0.01);
        c->amp[s].model = TCFG_AMP_NONE;
        c->amp[s].k_shape = 1;
        c->amp[s].snr_db = 15;
        c->amp[s].pfa = 1e-3;
    }
#if TRK_WITH_IMM
    c->imm_turn_rate_dps = 0;
    c->imm_p_stay = 0.95;
    c->imm_turn_q = 0;
#endif
}

void tcfg_params(const struct tcfg *c, struct trk_tracker_params *out)
{
    struct trk_hmm_params hp;
    memset(&hp, 0, sizeof hp);
    trk_hmm_params_uniform(&hp, c->params.n_sensors, &c->hmm);
    hp.events = c->hmm_events; /* SPRT (both P_D models), Page, Shiryaev */
    *out = c->params;
    memset(&out->confirm, 0, sizeof out->confirm);
    memset(&out->term, 0, sizeof out->term);
    out->confirm.method = c->confirm;
    switch (c->confirm) {
    case TRK_CONFIRM_MN: out->confirm.u.mn = c->mn; break;
    case TRK_CONFIRM_SPRT:
        out->confirm.u.sprt = c->sprt;
        out->confirm.u.sprt.hmm = hp;
        break;
    case TRK_CONFIRM_CLUTTER_CHI2: out->confirm.u.chi2 = c->clutter_density; break;
    case TRK_CONFIRM_CLUTTER_AMP: out->confirm.u.amp = c->clutter_amplitude; break;
    case TRK_CONFIRM_VISIBILITY: break; /* uses out->visibility */
    case TRK_CONFIRM_EXISTENCE: out->confirm.u.existence = c->existence_confirm; break;
    }
    out->term.method = c->term;
    switch (c->term) {
    case TRK_TERM_KN: out->term.u.kn = c->kn; break;
    case TRK_TERM_PAGE:
        out->term.u.page = c->page;
        out->term.u.page.hmm = hp;
        break;
    case TRK_TERM_SHIRYAEV:
        out->term.u.shiryaev = c->shiryaev;
        out->term.u.shiryaev.hmm = hp;
        break;
    case TRK_TERM_VISIBILITY: break; /* uses out->visibility */
    case TRK_TERM_EXISTENCE: out->term.u.existence = c->existence_term; break;
    }
#if TRK_WITH_IMM
    /* IMM tracks from the imm.* keys: CV (process_noise_q) and turns at
     * +-imm.turn_rate_dps (imm.turn_q, 0 = process_noise_q) */
    memset(&out->imm, 0, sizeof out->imm);
    if (c->imm_turn_rate_dps > 0 &&
        tcfg_imm_models(out, c->imm_turn_rate_dps, c->imm_p_stay, c->imm_turn_q) != TRK_OK) /* refused at tcfg_set */
        memset(&out->imm, 0, sizeof out->imm);
#endif
}

#if TRK_WITH_IMM
trk_status tcfg_imm_models(struct trk_tracker_params *p, double turn_rate_dps, double p_stay, double turn_q)
{
    const trk_status st =
        trk_tracker_imm_params(p, (trk_real)(turn_rate_dps * 3.14159265358979323846 / 180), (trk_real)p_stay);
    if (st == TRK_OK && turn_q > 0)
        for (int m = 1; m < p->imm.n_models; m++) p->imm.q_m2_per_s3[m] = (trk_real)turn_q;
    return st;
}
#endif

/* ------------------------------------------------------------------ values */

/* Range of a number: lo/hi with open (1) or closed (0) ends. */
struct range {
    double lo, hi;
    int lo_open, hi_open;
};

static int in_range(double v, struct range r)
{
    if (r.lo_open ? !(v > r.lo) : !(v >= r.lo)) return 0;
    if (r.hi_open ? !(v < r.hi) : !(v <= r.hi)) return 0;
    return 1;
}

static void range_text(struct range r, char *buf, size_t n)
{
    if (r.hi >= 1e300) snprintf(buf, n, "%s %g", r.lo_open ? ">" : ">=", r.lo);
    else
        snprintf(buf, n, "in %c%g, %g%c", r.lo_open ? '(' : '[', r.lo, r.hi, r.hi_open ? ')' : ']');
}

static int get_double(const char *v, struct range r, double *out, char *err, size_t n)
{
    double d;
    const int bad = kv_parse_number(v, &d);
    if (bad != 0) {
        snprintf(err, n, "%s", kv_num_error(bad));
        return -1;
    }
    if (!in_range(d, r)) {
        char t[64];
        range_text(r, t, sizeof t);
        snprintf(err, n, "must be %s", t);
        return -1;
    }
    /* a value the float build cannot hold would turn into inf or 0 */
    if (TRK_REAL_IS_FLOAT && d != 0 && (fabs(d) > 3.4e38 || fabs(d) < 1.2e-38)) {
        snprintf(err, n, "outside the float range of this build");
        return -1;
    }
    *out = d;
    return 0;
}

static int get_real(const char *v, struct range r, trk_real *out, char *err, size_t n)
{
    double d;
    if (get_double(v, r, &d, err, n) != 0) return -1;
    *out = (trk_real)d;
    return 0;
}

static int get_long(const char *v, long lo, long hi, long *out, char *err, size_t n)
{
    if (kv_parse_long(v, lo, hi, out) != 0) {
        snprintf(err, n, "must be an integer in %ld .. %ld", lo, hi);
        return -1;
    }
    return 0;
}

static int get_name(const char *v, const char *const *names, int *out, char *err, size_t n)
{
    for (int i = 0; names[i]; i++)
        if (strcmp(v, names[i]) == 0) {
            *out = i;
            return 0;
        }
    size_t k = (size_t)snprintf(err, n, "must be one of:");
    for (int i = 0; names[i] && k < n; i++) k += (size_t)snprintf(err + k, n - k, " %s", names[i]);
    return -1;
}

static int get_path(const char *v, char *dst, char *err, size_t n)
{
    if (strlen(v) >= TCFG_PATH_MAX) {
        snprintf(err, n, "path longer than %d characters", TCFG_PATH_MAX - 1);
        return -1;
    }
    strcpy(dst, v);
    return 0;
}

static const struct range R_PROB_OC = {0, 1, 1, 0};    /* (0, 1] */
static const struct range R_PROB_OO = {0, 1, 1, 1};    /* (0, 1) */
static const struct range R_PROB_CC = {0, 1, 0, 0};    /* [0, 1] */
static const struct range R_PROB_CO = {0, 1, 0, 1};    /* [0, 1) */
static const struct range R_POS = {0, 1e308, 1, 0};    /* > 0 */
static const struct range R_NONNEG = {0, 1e308, 0, 0}; /* >= 0 */
static const struct range R_ANY = {-1e308, 1e308, 0, 0};
static const struct range R_COORD = {0, 1e15, 1, 0}; /* TRK_MAX_COORD_M_LIMIT */
static const struct range R_MAXDT = {1e-6, 1e9, 0, 0}; /* TRK_MAX_DT_S_MIN: 1 us */

static const char *const CLUTTER_NAMES[] = {"parametric", "nonparametric", NULL};
static const char *const MODE_NAMES[] = {"fixed", "sliding", NULL};
static const char *const CONFIRM_NAMES[] = {"mn", "sprt", "clutter_density", "clutter_amplitude",
                                            "visibility", "existence", NULL};
static const char *const TERM_NAMES[] = {"kn", "page", "shiryaev", "visibility", "existence", NULL};
static const char *const INIT_NAMES[] = {"single_point", "two_point", NULL}; /* enum trk_init_method */
static const char *const ASSOC_NAMES[] = {"pda", "joint", NULL};               /* enum trk_assoc_method */
static const char *const FILTER_NAMES[] = {"kalman", "alpha_beta", NULL};      /* enum trk_filter_kind */
static const char *const SPRT_MODEL_NAMES[] = {"fixed_pd", "hmm", NULL};
static const char *const EVENTS_NAMES[] = {"complete", "paper", NULL}; /* enum trk_event_model */
static const char *const AMP_NAMES[] = {"none", "rayleigh", "k", NULL};
static const char *const KIND_NAMES[] = {"cartesian", "polar", NULL};             /* enum trk_sensor_kind */
static const char *const CONVERSION_NAMES[] = {"first_order", "unbiased", NULL}; /* enum trk_polar_conversion */

/* Every key tcfg_set knows (but the sensor.N.* ones), for the suggestion
 * after a misspelled one; test_lcm_config checks it against tcfg_set and
 * tcfg_write. */
static const char *const KEYS[] = {
    "sensors", "process_noise_q", "gate_prob", "clutter", "init_speed_sigma_mps", "max_dt_s",
    "max_tentative_scans", "max_unseen_scans", "merge_gate_d2", "init_exclusion_d2", "stationary_d2", "association", "filter", "init.method",
    "init.max_speed_mps", "init.max_gap_scans", "init.birth_density_per_m2", "init.min_existence", "clutter_map.n_range",
    "clutter_map.n_bearing", "clutter_map.time_constant_scans", "clutter_map.prior_count", "clutter_map.min_ratio",
    "clutter_map.max_ratio", "clutter_map.window_cells", "clutter_map.guard_cells", "clutter_map.edge_alpha", "max_pos_sigma_ratio",
    "max_coord_m", "visibility", "visibility.pv0", "visibility.pcv0", "visibility.delta_stay",
    "visibility.delta_become", "visibility.omega_c", "visibility.p_con", "visibility.p_term", "confirm",
    "confirm.existence.p_confirm", "confirm.existence.reject_odds_ratio", "confirm.existence.count_alpha",
    "confirm.mn.m", "confirm.mn.n",
    "confirm.mn.mode", "confirm.sprt.alpha", "confirm.sprt.beta", "confirm.sprt.pd", "confirm.sprt.model",
    "confirm.clutter_density.alpha", "confirm.clutter_density.kmax", "confirm.clutter_amplitude.alpha",
    "confirm.clutter_amplitude.kmax", "confirm.clutter_amplitude.a_min_db", "term",
    "term.existence.p_terminate", "term.kn.k", "term.kn.n", "term.page.h", "term.shiryaev.beta0",
    "term.shiryaev.rho", "term.shiryaev.h", "hmm.p_low_high", "hmm.q_high_low", "hmm.pd_low", "hmm.pd_high",
    "hmm.events", "hmm.pi0_high", "q2_table", "imm.turn_rate_dps", "imm.p_stay", "imm.turn_q", NULL};
/* The keys of one sensor, after "sensor.N.". */
static const char *const SENSOR_KEYS[] = {"pd",
                                          "clutter_density_per_m2",
                                          "meas_cov_m2",
                                          "meas_sigma_m",
                                          "amplitude",
                                          "k_shape",
                                          "snr_db",
                                          "pfa",
                                          "amp_table",
                                          "kind",
                                          "sigma_range_m",
                                          "sigma_bearing_rad",
                                          "conversion",
                                          "pose.x_m",
                                          "pose.y_m",
                                          "pose.heading_rad",
                                          "pd_profile",
                                          "clutter_profile",
                                          "persistent_share",
                                          "persistent_pd",
                                          "coverage.min_range_m",
                                          "coverage.max_range_m",
                                          "coverage.half_width_rad",
                                          NULL};

const char *const *tcfg_keys(void) { return KEYS; }
const char *const *tcfg_sensor_keys(void) { return SENSOR_KEYS; }

/* An unknown key: the nearest known one into err ("" when none is close),
 * and 1. A sensor key is compared with sensor `s`'s keys (s < 0: with
 * sensor 0's among the others). */
static int unknown_key(const char *key, long s, char *err, size_t n)
{
    char cand[sizeof SENSOR_KEYS / sizeof SENSOR_KEYS[0]][64];
    struct cli_near near;
    cli_near_init(&near, key);
    if (s < 0)
        for (int i = 0; KEYS[i]; i++) cli_near_add(&near, KEYS[i]);
    for (int i = 0; SENSOR_KEYS[i]; i++) {
        snprintf(cand[i], sizeof cand[i], "sensor.%ld.%s", s < 0 ? 0 : s, SENSOR_KEYS[i]);
        cli_near_add(&near, cand[i]);
    }
    snprintf(err, n, "%s", near.best ? near.best : "");
    return 1;
}

/* ------------------------------------------------------------------ set */

/* sp->meas_cov_m2 = m after the tracker's own check (the authority), on its
 * defaults with this covariance for sensor s: 0, or -1 with the reason. */
static int set_meas_cov(struct trk_sensor_params *sp, unsigned s, const double m[3], char *err, size_t n)
{
    struct trk_tracker_params t;
    const char *field;
    trk_tracker_default_params(&t);
    t.n_sensors = s + 1;
    for (unsigned k = 1; k <= s; k++) t.sensor[k] = t.sensor[0];
    for (int i = 0; i < 3; i++) t.sensor[s].meas_cov_m2[i] = (trk_real)m[i];
    const trk_status st = trk_tracker_check_params(&t, &field);
    if (st != TRK_OK) {
        snprintf(err, n, "refused by the tracker (%s): %s%s", field, ERRMSG_STATUS(st),
                 st == TRK_E_NOT_SPD ? "; need xx > 0, yy > 0, xx yy > xy^2" : "");
        return -1;
    }
    for (int i = 0; i < 3; i++) sp->meas_cov_m2[i] = t.sensor[s].meas_cov_m2[i];
    return 0;
}

/* Ranges of the polar and coverage keys: those of the tracker's check
 * (sigma_bearing_rad at most half a radian: beyond it no conversion
 * describes the spread; a heading within a turn either way; ranges and
 * positions within TRK_MAX_COORD_M_LIMIT). */
static const struct range R_SIGMA_BEARING = {0, 0.5, 1, 0};
static const struct range R_SIGMA_RANGE = {0, 1e6, 1, 0};
static const struct range R_HEADING = {-6.283185307179586, 6.283185307179586, 0, 0};
static const struct range R_POSE = {-1e15, 1e15, 0, 0};
static const struct range R_DIST = {0, 1e15, 0, 0};
static const struct range R_HALF_WIDTH = {0, 3.141592653589793, 0, 0};

/* A profile over range being read: "none", or "R:V, R:V, ..." (range m :
 * value) with 2 .. TRK_PD_PROFILE_MAX points, ranges >= 0 and increasing;
 * the values P_D in [0, 1] (density 0) or densities in (0, 1e6] per m^2
 * (density 1). */
struct points {
    unsigned n;
    trk_real range_m[TRK_PD_PROFILE_MAX], v[TRK_PD_PROFILE_MAX];
};

static int get_points(const char *v, int density, struct points *out, char *err, size_t n);

/* sensor.N.pd_profile into *pr (untouched on error). */
static int get_profile(const char *v, struct trk_pd_profile *pr, char *err, size_t n)
{
    struct points t;
    if (get_points(v, 0, &t, err, n) != 0) return -1;
    memset(pr, 0, sizeof *pr);
    pr->n = t.n;
    for (unsigned i = 0; i < t.n; i++) pr->range_m[i] = t.range_m[i], pr->pd[i] = t.v[i];
    return 0;
}

/* sensor.N.clutter_profile into *cp (untouched on error). */
static int get_clutter_profile(const char *v, struct trk_clutter_profile *cp, char *err, size_t n)
{
    struct points t;
    if (get_points(v, 1, &t, err, n) != 0) return -1;
    memset(cp, 0, sizeof *cp);
    cp->n = t.n;
    for (unsigned i = 0; i < t.n; i++) cp->range_m[i] = t.range_m[i], cp->density_per_m2[i] = t.v[i];
    return 0;
}

static int get_points(const char *v, int density, struct points *out, char *err, size_t n)
{
    struct points t;
    memset(&t, 0, sizeof t);
    while (*v == ' ' || *v == '\t') v++;
    if (strcmp(v, "none") == 0) {
        *out = t;
        return 0;
    }
    const char *p = v;
    for (;;) {
        double r, d;
        char *end;
        if (t.n == TRK_PD_PROFILE_MAX) {
            snprintf(err, n, "more than %d points (TRK_PD_PROFILE_MAX)", TRK_PD_PROFILE_MAX);
            return -1;
        }
        while (*p == ' ' || *p == '\t') p++;
        if (kv_strtod(p, &end, &r) != 0) break;
        p = end;
        while (*p == ' ' || *p == '\t') p++;
        if (*p++ != ':') break;
        while (*p == ' ' || *p == '\t') p++;
        if (kv_strtod(p, &end, &d) != 0) break;
        p = end;
        if (!in_range(r, R_DIST) || (t.n > 0 && !(r > (double)t.range_m[t.n - 1]))) {
            snprintf(err, n, "point %u: range %g m: ranges must be >= 0, <= 1e15 and increasing", t.n + 1, r);
            return -1;
        }
        if (!density && !in_range(d, R_PROB_CC)) {
            snprintf(err, n, "point %u: P_D %g must be in [0, 1]", t.n + 1, d);
            return -1;
        }
        if (density && !(d > 0 && d <= 1e6)) {
            snprintf(err, n, "point %u: density %g must be in (0, 1e6] per m^2", t.n + 1, d);
            return -1;
        }
        t.range_m[t.n] = (trk_real)r;
        t.v[t.n++] = (trk_real)d;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == 0) {
            if (t.n < 2) break;
            *out = t;
            return 0;
        }
        if (*p++ != ',') break;
    }
    snprintf(err, n, "expected none, or 2 .. %d points RANGE_M:%s separated by commas (e.g. %s)", TRK_PD_PROFILE_MAX,
             density ? "DENSITY" : "PD", density ? "500:1e-6, 8000:2e-8" : "0:0.9, 2000:0.3");
    return -1;
}

/* full: the whole key ("sensor.1.pd"), key: after "sensor.N." */
static int set_sensor(struct tcfg *c, unsigned s, const char *full, const char *key, const char *v, char *err,
                      size_t n)
{
    struct trk_sensor_params *sp = &c->params.sensor[s];
    struct tcfg_amp *a = &c->amp[s];
    if (strcmp(key, "pd") == 0) return get_real(v, R_PROB_OC, &sp->pd, err, n);
    if (strcmp(key, "clutter_density_per_m2") == 0)
        return get_real(v, R_NONNEG, &sp->clutter_density_per_m2, err, n);
    if (strcmp(key, "meas_cov_m2") == 0) {
        double m[3];
        if (kv_parse_doubles(v, m, 3) != 0) {
            snprintf(err, n, "expected three numbers xx, xy, yy (m^2)");
            return -1;
        }
        return set_meas_cov(sp, s, m, err, n);
    }
    if (strcmp(key, "meas_sigma_m") == 0) {
        double sg;
        if (get_double(v, R_POS, &sg, err, n) != 0) return -1;
        /* the same check as meas_cov_m2 (fuzz_kvfile: 8.9e118 squared passed unchecked and the
         * configuration written back was refused) */
        const double m[3] = {sg * sg, 0, sg * sg};
        return set_meas_cov(sp, s, m, err, n);
    }
    if (strcmp(key, "amplitude") == 0) return get_name(v, AMP_NAMES, &a->model, err, n);
    if (strcmp(key, "k_shape") == 0) return get_double(v, R_POS, &a->k_shape, err, n);
    if (strcmp(key, "snr_db") == 0) {
        const struct range r = {-50, 80, 0, 0};
        return get_double(v, r, &a->snr_db, err, n);
    }
    if (strcmp(key, "pfa") == 0) return get_double(v, R_PROB_OO, &a->pfa, err, n);
    if (strcmp(key, "amp_table") == 0) return get_path(v, a->table, err, n);
    /* polar sensors, the pose, where the sensor sees */
    int e;
    if (strcmp(key, "kind") == 0) {
        if (get_name(v, KIND_NAMES, &e, err, n) != 0) return -1;
        sp->kind = e ? TRK_SENSOR_POLAR : TRK_SENSOR_CARTESIAN;
        return 0;
    }
    if (strcmp(key, "sigma_range_m") == 0) return get_real(v, R_SIGMA_RANGE, &sp->sigma_range_m, err, n);
    if (strcmp(key, "sigma_bearing_rad") == 0) return get_real(v, R_SIGMA_BEARING, &sp->sigma_bearing_rad, err, n);
    if (strcmp(key, "conversion") == 0) {
        if (get_name(v, CONVERSION_NAMES, &e, err, n) != 0) return -1;
        sp->conversion = e ? TRK_POLAR_UNBIASED : TRK_POLAR_FIRST_ORDER;
        return 0;
    }
    if (strcmp(key, "pose.x_m") == 0) return get_real(v, R_POSE, &sp->pose.x_m, err, n);
    if (strcmp(key, "pose.y_m") == 0) return get_real(v, R_POSE, &sp->pose.y_m, err, n);
    if (strcmp(key, "pose.heading_rad") == 0) return get_real(v, R_HEADING, &sp->pose.heading_rad, err, n);
    if (strcmp(key, "pd_profile") == 0) return get_profile(v, &sp->pd_profile, err, n);
    if (strcmp(key, "clutter_profile") == 0) return get_clutter_profile(v, &sp->clutter_profile, err, n);
    if (strcmp(key, "persistent_share") == 0) return get_real(v, R_PROB_CO, &sp->persistent_share, err, n);
    if (strcmp(key, "persistent_pd") == 0) return get_real(v, R_PROB_CO, &sp->persistent_pd, err, n);
    if (strcmp(key, "coverage.min_range_m") == 0) return get_real(v, R_DIST, &sp->coverage.min_range_m, err, n);
    if (strcmp(key, "coverage.max_range_m") == 0) return get_real(v, R_DIST, &sp->coverage.max_range_m, err, n);
    if (strcmp(key, "coverage.half_width_rad") == 0)
        return get_real(v, R_HALF_WIDTH, &sp->coverage.half_width_rad, err, n);
    return unknown_key(full, (long)s, err, n);
}

int tcfg_set(void *ctx, const char *key, const char *v, char *err, size_t n)
{
    struct tcfg *c = ctx;
    struct trk_tracker_params *p = &c->params;
    long l;
    int e;

    if (strncmp(key, "sensor.", 7) == 0) {
        char *end;
        errno = 0;
        /* digits only: strtoul took "-1" as 18446744073709551615 */
        if (key[7] == '-' || key[7] == '+') {
            snprintf(err, n, "sensor index '%.*s': must be an integer >= 0", (int)strcspn(key + 7, "."), key + 7);
            return -1;
        }
        unsigned long s = isdigit((unsigned char)key[7]) ? strtoul(key + 7, &end, 10) : 0;
        if (!isdigit((unsigned char)key[7]) || *end != '.' || errno) return unknown_key(key, -1, err, n);
        if (s >= TRK_MAX_SENSORS) {
            snprintf(err, n, "sensor index %lu: this build has TRK_MAX_SENSORS = %d", s,
                     TRK_MAX_SENSORS);
            return -1;
        }
        return set_sensor(c, (unsigned)s, key, end + 1, v, err, n);
    }
    if (strcmp(key, "sensors") == 0) {
        if (get_long(v, 1, TRK_MAX_SENSORS, &l, err, n) != 0) return -1;
        p->n_sensors = (unsigned)l;
        return 0;
    }
    if (strcmp(key, "process_noise_q") == 0) return get_real(v, R_NONNEG, &p->process_noise_q, err, n);
    if (strcmp(key, "gate_prob") == 0) return get_real(v, R_PROB_OO, &p->gate_prob, err, n);
    if (strcmp(key, "clutter") == 0) {
        if (get_name(v, CLUTTER_NAMES, &e, err, n) != 0) return -1;
        p->clutter = e ? TRK_CLUTTER_NONPARAMETRIC : TRK_CLUTTER_PARAMETRIC;
        return 0;
    }
    if (strcmp(key, "init_speed_sigma_mps") == 0)
        return get_real(v, R_POS, &p->init_speed_sigma_mps, err, n);
    if (strcmp(key, "max_dt_s") == 0) return get_real(v, R_MAXDT, &p->max_dt_s, err, n);
    if (strcmp(key, "max_tentative_scans") == 0) {
        if (get_long(v, 0, LONG_MAX < 4294967295L ? LONG_MAX : 4294967295L, &l, err, n) != 0)
            return -1;
        p->max_tentative_scans = (uint32_t)l;
        return 0;
    }
    if (strcmp(key, "max_unseen_scans") == 0) {
        if (get_long(v, 0, LONG_MAX < 4294967295L ? LONG_MAX : 4294967295L, &l, err, n) != 0)
            return -1;
        p->max_unseen_scans = (uint32_t)l;
        return 0;
    }
    if (strcmp(key, "merge_gate_d2") == 0) return get_real(v, R_NONNEG, &p->merge_gate_d2, err, n);
    if (strcmp(key, "init_exclusion_d2") == 0) return get_real(v, R_NONNEG, &p->init_exclusion_d2, err, n);
    if (strcmp(key, "stationary_d2") == 0) return get_real(v, R_NONNEG, &p->stationary_d2, err, n);
    if (strcmp(key, "association") == 0) {
        if (get_name(v, ASSOC_NAMES, &e, err, n) != 0) return -1;
        p->association = e ? TRK_ASSOC_JOINT : TRK_ASSOC_PDA;
        return 0;
    }
    if (strcmp(key, "filter") == 0) {
        if (get_name(v, FILTER_NAMES, &e, err, n) != 0) return -1;
        p->filter = e ? TRK_FILTER_ALPHA_BETA : TRK_FILTER_KALMAN;
        return 0;
    }
    /* initiation and the covariance bound */
    if (strcmp(key, "init.method") == 0) {
        if (get_name(v, INIT_NAMES, &e, err, n) != 0) return -1;
        p->init.method = e ? TRK_INIT_TWO_POINT : TRK_INIT_SINGLE_POINT;
        return 0;
    }
    if (strcmp(key, "init.max_speed_mps") == 0) return get_real(v, R_POS, &p->init.max_speed_mps, err, n);
    if (strcmp(key, "init.max_gap_scans") == 0) {
        if (get_long(v, 1, LONG_MAX < 4294967295L ? LONG_MAX : 4294967295L, &l, err, n) != 0) return -1;
        p->init.max_gap_scans = (uint32_t)l;
        return 0;
    }
    if (strcmp(key, "init.birth_density_per_m2") == 0)
        return get_real(v, R_NONNEG, &p->init.birth_density_per_m2, err, n);
    if (strcmp(key, "init.min_existence") == 0) return get_real(v, R_NONNEG, &p->init.min_existence, err, n);
    /* the clutter maps (cells 0: none; the library checks the rest) */
    if (strcmp(key, "clutter_map.n_range") == 0 || strcmp(key, "clutter_map.n_bearing") == 0) {
        if (get_long(v, 0, 65535, &l, err, n) != 0) return -1;
        *(strcmp(key, "clutter_map.n_range") == 0 ? &p->clutter_map.n_range : &p->clutter_map.n_bearing) = (unsigned)l;
        return 0;
    }
    if (strcmp(key, "clutter_map.time_constant_scans") == 0)
        return get_real(v, R_POS, &p->clutter_map.time_constant_scans, err, n);
    if (strcmp(key, "clutter_map.prior_count") == 0) return get_real(v, R_POS, &p->clutter_map.prior_count, err, n);
    if (strcmp(key, "clutter_map.min_ratio") == 0) return get_real(v, R_PROB_OC, &p->clutter_map.min_ratio, err, n);
    if (strcmp(key, "clutter_map.max_ratio") == 0) return get_real(v, R_POS, &p->clutter_map.max_ratio, err, n);
    if (strcmp(key, "clutter_map.window_cells") == 0 || strcmp(key, "clutter_map.guard_cells") == 0) {
        const int window = strcmp(key, "clutter_map.window_cells") == 0;
        if (get_long(v, 0, TRK_CLUTTER_MAP_WINDOW_MAX + (window ? 0 : 1), &l, err, n) != 0) return -1;
        *(window ? &p->clutter_map.window_cells : &p->clutter_map.guard_cells) = (unsigned)l;
        return 0;
    }
    if (strcmp(key, "clutter_map.edge_alpha") == 0) return get_real(v, R_PROB_CO, &p->clutter_map.edge_alpha, err, n);
    if (strcmp(key, "max_pos_sigma_ratio") == 0) return get_real(v, R_NONNEG, &p->max_pos_sigma_ratio, err, n);
    if (strcmp(key, "max_coord_m") == 0) return get_real(v, R_COORD, &p->max_coord_m, err, n);
    /* visibility (IPDA existence) */
    if (strcmp(key, "visibility") == 0) {
        if (get_long(v, 0, 1, &l, err, n) != 0) return -1;
        p->track_visibility = (int)l;
        return 0;
    }
    if (strcmp(key, "visibility.pv0") == 0) return get_real(v, R_PROB_OO, &p->visibility.pv0, err, n);
    if (strcmp(key, "visibility.pcv0") == 0) return get_real(v, R_PROB_CC, &p->visibility.pcv0, err, n);
    if (strcmp(key, "visibility.delta_stay") == 0)
        return get_real(v, R_PROB_CC, &p->visibility.delta_stay, err, n);
    if (strcmp(key, "visibility.delta_become") == 0)
        return get_real(v, R_PROB_CC, &p->visibility.delta_become, err, n);
    if (strcmp(key, "visibility.omega_c") == 0) return get_real(v, R_PROB_CO, &p->visibility.omega_c, err, n);
    if (strcmp(key, "visibility.p_con") == 0) return get_real(v, R_PROB_OC, &p->visibility.p_con, err, n);
    if (strcmp(key, "visibility.p_term") == 0) return get_real(v, R_PROB_CO, &p->visibility.p_term, err, n);
    /* confirmation */
    if (strcmp(key, "confirm") == 0) {
        static const enum trk_confirm_method m[] = {TRK_CONFIRM_MN, TRK_CONFIRM_SPRT,
                                                    TRK_CONFIRM_CLUTTER_CHI2, TRK_CONFIRM_CLUTTER_AMP,
                                                    TRK_CONFIRM_VISIBILITY, TRK_CONFIRM_EXISTENCE};
        if (get_name(v, CONFIRM_NAMES, &e, err, n) != 0) return -1;
        c->confirm = m[e];
        return 0;
    }
    if (strcmp(key, "confirm.existence.p_confirm") == 0)
        return get_real(v, R_PROB_OO, &c->existence_confirm.p_confirm, err, n);
    if (strcmp(key, "confirm.existence.reject_odds_ratio") == 0)
        return get_real(v, R_PROB_CO, &c->existence_confirm.reject_odds_ratio, err, n);
    if (strcmp(key, "confirm.existence.count_alpha") == 0)
        return get_real(v, R_PROB_CO, &c->existence_confirm.count_alpha, err, n);
    if (strcmp(key, "confirm.mn.m") == 0) {
        if (get_long(v, 1, TRK_MN_MAX_N, &l, err, n) != 0) return -1;
        c->mn.m = (int)l;
        return 0;
    }
    if (strcmp(key, "confirm.mn.n") == 0) {
        if (get_long(v, 1, TRK_MN_MAX_N, &l, err, n) != 0) return -1;
        c->mn.n = (int)l;
        return 0;
    }
    if (strcmp(key, "confirm.mn.mode") == 0) {
        if (get_name(v, MODE_NAMES, &e, err, n) != 0) return -1;
        c->mn.mode = e ? TRK_MN_SLIDING : TRK_MN_FIXED;
        return 0;
    }
    if (strcmp(key, "confirm.sprt.alpha") == 0) return get_real(v, R_PROB_OO, &c->sprt.alpha, err, n);
    if (strcmp(key, "confirm.sprt.beta") == 0) return get_real(v, R_PROB_OO, &c->sprt.beta, err, n);
    if (strcmp(key, "confirm.sprt.pd") == 0) return get_real(v, R_PROB_OO, &c->sprt.pd, err, n);
    if (strcmp(key, "confirm.sprt.model") == 0) {
        if (get_name(v, SPRT_MODEL_NAMES, &e, err, n) != 0) return -1;
        c->sprt.model = e ? TRK_SPRT_HMM : TRK_SPRT_FIXED_PD;
        return 0;
    }
    if (strcmp(key, "confirm.clutter_density.alpha") == 0)
        return get_real(v, R_PROB_OO, &c->clutter_density.alpha, err, n);
    if (strcmp(key, "confirm.clutter_density.kmax") == 0) {
        if (get_long(v, 1, TRK_CLUTTER_KMAX, &l, err, n) != 0) return -1;
        c->clutter_density.kmax = (unsigned)l;
        return 0;
    }
    if (strcmp(key, "confirm.clutter_amplitude.alpha") == 0)
        return get_real(v, R_PROB_OO, &c->clutter_amplitude.alpha, err, n);
    if (strcmp(key, "confirm.clutter_amplitude.kmax") == 0) {
        if (get_long(v, 1, TRK_CLUTTER_KMAX, &l, err, n) != 0) return -1;
        c->clutter_amplitude.kmax = (unsigned)l;
        return 0;
    }
    if (strcmp(key, "confirm.clutter_amplitude.a_min_db") == 0)
        return get_real(v, R_ANY, &c->clutter_amplitude.a_min_db, err, n);
    /* termination */
    if (strcmp(key, "term") == 0) {
        static const enum trk_term_method m[] = {TRK_TERM_KN, TRK_TERM_PAGE, TRK_TERM_SHIRYAEV,
                                                 TRK_TERM_VISIBILITY, TRK_TERM_EXISTENCE};
        if (get_name(v, TERM_NAMES, &e, err, n) != 0) return -1;
        c->term = m[e];
        return 0;
    }
    if (strcmp(key, "term.existence.p_terminate") == 0)
        return get_real(v, R_PROB_OO, &c->existence_term.p_terminate, err, n);
    if (strcmp(key, "term.kn.k") == 0) {
        if (get_long(v, 0, TRK_KN_MAX_N - 1, &l, err, n) != 0) return -1;
        c->kn.k = (int)l;
        return 0;
    }
    if (strcmp(key, "term.kn.n") == 0) {
        if (get_long(v, 1, TRK_KN_MAX_N, &l, err, n) != 0) return -1;
        c->kn.n = (int)l;
        return 0;
    }
    if (strcmp(key, "term.page.h") == 0) return get_real(v, R_POS, &c->page.h, err, n);
    if (strcmp(key, "term.shiryaev.beta0") == 0)
        return get_real(v, R_PROB_OO, &c->shiryaev.beta0, err, n);
    if (strcmp(key, "term.shiryaev.rho") == 0) return get_real(v, R_PROB_CO, &c->shiryaev.rho, err, n);
    if (strcmp(key, "term.shiryaev.h") == 0) return get_real(v, R_ANY, &c->shiryaev.h, err, n);
    /* fluctuating-SNR detection model */
    if (strcmp(key, "hmm.p_low_high") == 0) return get_real(v, R_PROB_CC, &c->hmm.p_low_high, err, n);
    if (strcmp(key, "hmm.q_high_low") == 0) return get_real(v, R_PROB_CC, &c->hmm.q_high_low, err, n);
    if (strcmp(key, "hmm.pd_low") == 0) return get_real(v, R_PROB_OO, &c->hmm.pd_low, err, n);
    if (strcmp(key, "hmm.pd_high") == 0) return get_real(v, R_PROB_OO, &c->hmm.pd_high, err, n);
    if (strcmp(key, "hmm.events") == 0) {
        if (get_name(v, EVENTS_NAMES, &e, err, n) != 0) return -1;
        c->hmm_events = e ? TRK_EVENTS_PAPER : TRK_EVENTS_COMPLETE;
        return 0;
    }
    if (strcmp(key, "hmm.pi0_high") == 0) {
        if (strcmp(v, "stationary") == 0) {
            c->hmm.pi0_high = TRK_HMM_PI0_STATIONARY;
            return 0;
        }
        return get_real(v, R_PROB_CC, &c->hmm.pi0_high, err, n);
    }
    if (strcmp(key, "q2_table") == 0) return get_path(v, c->q2_table, err, n);
    /* IMM tracks */
#if TRK_WITH_IMM
    if (strcmp(key, "imm.turn_rate_dps") == 0) {
        const struct range r = {0, 57.29, 0, 0}; /* the library's |omega| <= 1 rad/s */
        if (TRK_MAX_MODELS < 3) {
            snprintf(err, n, "IMM tracks of CV and two turns need TRK_MAX_MODELS >= 3 (this build: %d)", TRK_MAX_MODELS);
            return -1;
        }
        return get_double(v, r, &c->imm_turn_rate_dps, err, n);
    }
    if (strcmp(key, "imm.p_stay") == 0) return get_double(v, R_PROB_CC, &c->imm_p_stay, err, n);
    if (strcmp(key, "imm.turn_q") == 0) return get_double(v, R_NONNEG, &c->imm_turn_q, err, n);
#else
    if (strcmp(key, "imm.turn_rate_dps") == 0 || strcmp(key, "imm.p_stay") == 0 || strcmp(key, "imm.turn_q") == 0) {
        snprintf(err, n, "this build has no IMM tracks (TRK_WITH_IMM = 0): build with CONFIG_DEFS=-DTRK_WITH_IMM=1");
        return -1;
    }
#endif
    return unknown_key(key, -1, err, n);
}

/* ------------------------------------------------------------------ check */

/* Load a table file with the library's host helper (trk/table_file.h:
 * read into an 8-byte aligned buffer, trk_table_parse: magic, version, real
 * width of this build, layout, CRC), then check its kind and, for amplitude
 * tables, the amplitude model's own checks. */
static int check_table(const char *path, const char *what, const uint32_t *kinds, int n_kinds,
                       int amp, char *err, size_t n)
{
    size_t len;
    trk_status st = trk_table_file_size(path, &len);
    if (st == TRK_E_CAPACITY) {
        snprintf(err, n, "%s '%s': longer than any table (%zu bytes at most)", what, path,
                 (size_t)TRK_TABLE_FILE_MAX_BYTES);
        return -1;
    }
    if (st != TRK_OK) {
        snprintf(err, n, "%s '%s': cannot open: %s", what, path, strerror(errno));
        return -1;
    }
    if (len == 0 || len > (size_t)TRK_TABLE_MAX_REALS * 8u) {
        snprintf(err, n, "%s '%s': %s", what, path, len ? "too large for a table" : "empty file");
        return -1;
    }
    void *bytes = malloc(len); /* malloc: aligned for double, as trk_table_parse needs */
    if (!bytes) {
        snprintf(err, n, "%s '%s': out of memory", what, path);
        return -1;
    }
    struct trk_table t;
    st = trk_table_load_file(path, bytes, len, &t, NULL);
    if (st != TRK_OK) {
        free(bytes);
        snprintf(err, n, "%s '%s': not a usable table for this build: %s", what, path,
                 ERRMSG_STATUS(st));
        return -1;
    }
    int kind_ok = 0;
    for (int i = 0; i < n_kinds; i++) kind_ok |= t.info.kind == kinds[i];
    if (!kind_ok) {
        free(bytes);
        snprintf(err, n, "%s '%s': a table of kind %lu, not the kind this setting needs", what,
                 path, (unsigned long)t.info.kind);
        return -1;
    }
    if (amp) { /* the amplitude model's own checks of its table */
        struct trk_amplitude m;
        st = trk_amplitude_init_table(&m, &t);
        if (st != TRK_OK) {
            free(bytes);
            snprintf(err, n, "%s '%s': trk_amplitude_init_table: %s", what, path,
                     ERRMSG_STATUS(st));
            return -1;
        }
    }
    free(bytes);
    return 0;
}

/* Names of the methods, indexed by the tracker's enums. */
static const char *confirm_name(enum trk_confirm_method m)
{
    switch (m) {
    case TRK_CONFIRM_MN: return "mn";
    case TRK_CONFIRM_SPRT: return "sprt";
    case TRK_CONFIRM_CLUTTER_CHI2: return "clutter_density";
    case TRK_CONFIRM_CLUTTER_AMP: return "clutter_amplitude";
    case TRK_CONFIRM_VISIBILITY: return "visibility";
    case TRK_CONFIRM_EXISTENCE: return "existence";
    }
    return "?";
}

static const char *term_name(enum trk_term_method m)
{
    switch (m) {
    case TRK_TERM_KN: return "kn";
    case TRK_TERM_PAGE: return "page";
    case TRK_TERM_SHIRYAEV: return "shiryaev";
    case TRK_TERM_VISIBILITY: return "visibility";
    case TRK_TERM_EXISTENCE: return "existence";
    }
    return "?";
}

static const char *method_hint(trk_status st, const char *field, int visibility_method)
{
    if (st == TRK_E_UNSUPPORTED) return " (not built into this libtrk: TRK_WITH_CLUTTER_TESTS = 0)";
    if (st == TRK_E_SENSOR) return " (the HMM needs a model for every sensor)";
    if (visibility_method && strstr(field, ".method")) return " (needs visibility = 1)";
    return "";
}

/* Name the setting behind the field that trk_tracker_check_params refused
 * (a member of struct trk_tracker_params) in this file's keys. */
static void explain(const struct tcfg *c, const char *field, trk_status st, char *err, size_t n)
{
    const char *f = field ? field : "?";
    unsigned s;
    char member[48];
    if (strcmp(f, "confirm.method") == 0 || strcmp(f, "term.method") == 0) {
        const int conf = f[0] == 'c';
        snprintf(err, n, "%s = %s: refused by the tracker (%s): %s%s", conf ? "confirm" : "term",
                 conf ? confirm_name(c->confirm) : term_name(c->term), f, ERRMSG_STATUS(st),
                 method_hint(st, f,
                             conf ? c->confirm == TRK_CONFIRM_VISIBILITY || c->confirm == TRK_CONFIRM_EXISTENCE
                                  : c->term == TRK_TERM_VISIBILITY || c->term == TRK_TERM_EXISTENCE));
    } else if (strncmp(f, "confirm.", 8) == 0) {
        snprintf(err, n, "confirm = %s: its parameters (confirm.%s.*%s) are refused (%s): %s%s",
                 confirm_name(c->confirm), confirm_name(c->confirm),
                 c->confirm == TRK_CONFIRM_SPRT ? ", hmm.*" : "", f, ERRMSG_STATUS(st),
                 method_hint(st, f, c->confirm == TRK_CONFIRM_VISIBILITY));
    } else if (strncmp(f, "term.", 5) == 0) {
        snprintf(err, n, "term = %s: its parameters (term.%s.*%s) are refused (%s): %s%s", term_name(c->term),
                 term_name(c->term), c->term == TRK_TERM_PAGE || c->term == TRK_TERM_SHIRYAEV ? ", hmm.*" : "",
                 f, ERRMSG_STATUS(st), method_hint(st, f, c->term == TRK_TERM_VISIBILITY));
    } else if (sscanf(f, "sensor[%u].%47s", &s, member) == 2) {
        snprintf(err, n, "sensor.%u.%s: refused by the tracker (%s): %s", s,
                 strcmp(member, "use_amplitude") == 0 ? "amplitude"
                 : strcmp(member, "pose") == 0        ? "pose.*"
                 : strcmp(member, "coverage") == 0    ? "coverage.*"
                                                      : member,
                 f, ERRMSG_STATUS(st));
    } else {
        const char *key = strcmp(f, "n_sensors") == 0          ? "sensors"
                          : strcmp(f, "track_visibility") == 0 ? "visibility"
                          : strcmp(f, "visibility") == 0       ? "visibility.*"
                          : strcmp(f, "imm") == 0              ? "imm.*"
                                                               : f;
        const char *hint = strcmp(f, "association") == 0 && st == TRK_E_UNSUPPORTED
                               ? " (association = joint needs clutter = parametric and every sensor's "
                                 "clutter_density_per_m2 > 0; or set association = pda)"
                           : strcmp(f, "filter") == 0 && st == TRK_E_UNSUPPORTED
                               ? " (filter = alpha_beta needs a libtrk built with TRK_WITH_ALPHA_BETA=1, "
                                 "process_noise_q > 0 and no IMM)"
                               : "";
        snprintf(err, n, "%s: refused by the tracker (%s): %s%s", key, f, ERRMSG_STATUS(st), hint);
    }
}

int tcfg_check(const struct tcfg *c, char *err, size_t n)
{
    const struct trk_tracker_params *p = &c->params;
    struct trk_tracker_params full;
    const char *field;
    trk_status st;
    /* 0. what two keys say together about a sensor's view (the tracker
     *    refuses the same, naming the field) */
    for (unsigned s = 0; s < p->n_sensors; s++) {
        const struct trk_sensor_params *sp = &p->sensor[s];
        if (sp->coverage.max_range_m > 0 && !(sp->coverage.max_range_m > sp->coverage.min_range_m)) {
            snprintf(err, n, "sensor.%u.coverage.max_range_m = %g must exceed coverage.min_range_m = %g (or be 0: no limit)",
                     s, (double)sp->coverage.max_range_m, (double)sp->coverage.min_range_m);
            return -1;
        }
        if (sp->pd_profile.n > 0 && (c->amp[s].model == TCFG_AMP_K || c->amp[s].table[0])) {
            snprintf(err, n, "sensor.%u.pd_profile with a tabulated amplitude model: only the Rayleigh model "
                             "turns a P_D profile into a target SNR over range "
                             "(set sensor.%u.amplitude = rayleigh, or sensor.%u.pd_profile = none)", s, s, s);
            return -1;
        }
        for (unsigned k = 0; c->amp[s].model == TCFG_AMP_RAYLEIGH && k < sp->pd_profile.n; k++)
            if (!((double)sp->pd_profile.pd[k] > c->amp[s].pfa && sp->pd_profile.pd[k] < 1)) {
                snprintf(err, n, "sensor.%u.pd_profile: P_D %g with the Rayleigh amplitude model must lie in "
                                 "(pfa, 1) = (%g, 1): the target SNR that gives it",
                         s, (double)sp->pd_profile.pd[k], c->amp[s].pfa);
                return -1;
            }
    }
    /* persistent returns live in a Rayleigh model's amplitudes (the tracker
     *    checks them again with the model loaded) */
    for (unsigned s = 0; s < p->n_sensors; s++) {
        const struct trk_sensor_params *sp = &p->sensor[s];
        if (!(sp->persistent_share > 0)) continue;
        if (c->amp[s].model != TCFG_AMP_RAYLEIGH || c->amp[s].table[0]) {
            snprintf(err, n, "sensor.%u.persistent_share needs sensor.%u.amplitude = rayleigh (closed form)", s, s);
            return -1;
        }
        if (!((double)sp->persistent_pd > c->amp[s].pfa && sp->persistent_pd < 1)) {
            snprintf(err, n, "sensor.%u.persistent_pd = %g must lie in (pfa, 1) = (%g, 1)", s,
                     (double)sp->persistent_pd, c->amp[s].pfa);
            return -1;
        }
    }
    /* 1. the tracker (the authority) with the chosen methods: it names the
     *    field it refuses (the amplitude models are not loaded here) */
    tcfg_params(c, &full);
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) full.sensor[s].persistent_share = 0;
    st = trk_tracker_check_params(&full, &field);
    if (st != TRK_OK) {
        explain(c, field, st, err, n);
        return -1;
    }
    /* 2. table files: read and checked by the library's table parser, kind
     *    included (a bad table refuses the start) */
    for (unsigned s = 0; s < p->n_sensors; s++) {
        static const uint32_t amp_kind[] = {TRK_TABLE_KIND_AMP};
        char what[64];
        snprintf(what, sizeof what, "sensor.%u.amp_table", s);
        if (c->amp[s].table[0] && check_table(c->amp[s].table, what, amp_kind, 1, 1, err, n) != 0)
            return -1;
        if (!c->amp[s].table[0] && c->amp[s].model == TCFG_AMP_K) {
            snprintf(err, n, "sensor.%u.amplitude = k needs sensor.%u.amp_table (trk-tablegen amp)",
                     s, s);
            return -1;
        }
        if (!c->amp[s].table[0] && c->amp[s].model == TCFG_AMP_RAYLEIGH) {
            struct trk_amplitude m;
            st = trk_amplitude_init_rayleigh(&m, 1, (trk_real)c->amp[s].snr_db,
                                             (trk_real)c->amp[s].pfa);
            if (st != TRK_OK) {
                snprintf(err, n, "sensor.%u amplitude model (snr_db, pfa): %s", s,
                         ERRMSG_STATUS(st));
                return -1;
            }
        }
    }
    if (c->q2_table[0]) {
        static const uint32_t q2_kinds[] = {TRK_TABLE_KIND_Q2_PDAF, TRK_TABLE_KIND_Q2_PDAFAI};
        if (check_table(c->q2_table, "q2_table", q2_kinds, 2, 0, err, n) != 0) return -1;
    }

    /* 3. the tracker with the amplitude models built from those tables */
    struct tcfg_runtime rt;
    if (tcfg_load(c, &rt, err, n) != 0) return -1;
    struct trk_tracker_params pa;
    tcfg_params_rt(c, &rt, &pa);
    st = trk_tracker_check_params(&pa, &field);
    tcfg_unload(&rt);
    if (st != TRK_OK) {
        snprintf(err, n, "the tracker refuses the sensors' amplitude models: ");
        const size_t k = strlen(err);
        explain(c, field, st, err + k, n - k);
        return -1;
    }
    return 0;
}

int tcfg_load(const struct tcfg *c, struct tcfg_runtime *rt, char *err, size_t n)
{
    memset(rt, 0, sizeof *rt);
    for (unsigned s = 0; s < c->params.n_sensors; s++) {
        const struct tcfg_amp *a = &c->amp[s];
        trk_status st = TRK_OK;
        if (a->table[0]) {
            size_t len;
            struct trk_table t;
            if (trk_table_file_size(a->table, &len) != TRK_OK || len == 0 ||
                !(rt->amp_bytes[s] = malloc(len))) { /* malloc: aligned as trk_table_parse needs */
                snprintf(err, n, "sensor.%u.amp_table '%s': cannot read", s, a->table);
                tcfg_unload(rt);
                return -1;
            }
            st = trk_table_load_file(a->table, rt->amp_bytes[s], len, &t, NULL);
            if (st == TRK_OK) st = trk_amplitude_init_table(&rt->amp[s], &t);
        } else if (a->model == TCFG_AMP_RAYLEIGH) {
            st = trk_amplitude_init_rayleigh(&rt->amp[s], 1, (trk_real)a->snr_db, (trk_real)a->pfa);
        } else if (a->model == TCFG_AMP_K) {
            snprintf(err, n, "sensor.%u.amplitude = k needs sensor.%u.amp_table (trk-tablegen amp)", s, s);
            tcfg_unload(rt);
            return -1;
        } else {
            continue;
        }
        if (st != TRK_OK) {
            snprintf(err, n, "sensor.%u amplitude model: %s", s, ERRMSG_STATUS(st));
            tcfg_unload(rt);
            return -1;
        }
        rt->use_amp[s] = 1;
    }
    return 0;
}

void tcfg_unload(struct tcfg_runtime *rt)
{
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) free(rt->amp_bytes[s]);
    memset(rt, 0, sizeof *rt);
}

void tcfg_params_rt(const struct tcfg *c, const struct tcfg_runtime *rt, struct trk_tracker_params *out)
{
    tcfg_params(c, out);
    for (unsigned s = 0; s < TRK_MAX_SENSORS; s++) {
        out->sensor[s].use_amplitude = rt && rt->use_amp[s];
        if (out->sensor[s].use_amplitude) out->sensor[s].amplitude = rt->amp[s];
    }
}

/* ------------------------------------------------------------------ write, help */

/* Shortest %g that reads back as the same value. */
static void shortest(char *buf, size_t n, double v)
{
    for (int prec = 6; prec <= 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) break;
    }
}

static void put_num(FILE *f, const char *key, double v)
{
    char buf[40];
    shortest(buf, sizeof buf, v);
    fprintf(f, "%s = %s\n", key, buf);
}

void tcfg_write(FILE *f, const struct tcfg *c)
{
    const struct trk_tracker_params *p = &c->params;
    fprintf(f, "# tracker configuration (trk tracker_config keys)\n");
    fprintf(f, "sensors = %u\n", p->n_sensors);
    put_num(f, "process_noise_q", (double)p->process_noise_q);
    put_num(f, "gate_prob", (double)p->gate_prob);
    fprintf(f, "clutter = %s\n", CLUTTER_NAMES[p->clutter == TRK_CLUTTER_NONPARAMETRIC]);
    put_num(f, "init_speed_sigma_mps", (double)p->init_speed_sigma_mps);
    put_num(f, "max_dt_s", (double)p->max_dt_s);
    fprintf(f, "max_tentative_scans = %lu\n", (unsigned long)p->max_tentative_scans);
    fprintf(f, "max_unseen_scans = %lu\n", (unsigned long)p->max_unseen_scans);
    put_num(f, "merge_gate_d2", (double)p->merge_gate_d2);
    put_num(f, "init_exclusion_d2", (double)p->init_exclusion_d2);
    put_num(f, "stationary_d2", (double)p->stationary_d2);
    fprintf(f, "association = %s\n", ASSOC_NAMES[p->association == TRK_ASSOC_JOINT]);
    fprintf(f, "filter = %s\n", FILTER_NAMES[p->filter == TRK_FILTER_ALPHA_BETA]);
    fprintf(f, "init.method = %s\n", INIT_NAMES[p->init.method == TRK_INIT_TWO_POINT]);
    put_num(f, "init.max_speed_mps", (double)p->init.max_speed_mps);
    fprintf(f, "init.max_gap_scans = %lu\n", (unsigned long)p->init.max_gap_scans);
    put_num(f, "init.birth_density_per_m2", (double)p->init.birth_density_per_m2);
    put_num(f, "init.min_existence", (double)p->init.min_existence);
    fprintf(f, "clutter_map.n_range = %u\n", p->clutter_map.n_range);
    fprintf(f, "clutter_map.n_bearing = %u\n", p->clutter_map.n_bearing);
    put_num(f, "clutter_map.time_constant_scans", (double)p->clutter_map.time_constant_scans);
    put_num(f, "clutter_map.prior_count", (double)p->clutter_map.prior_count);
    put_num(f, "clutter_map.min_ratio", (double)p->clutter_map.min_ratio);
    put_num(f, "clutter_map.max_ratio", (double)p->clutter_map.max_ratio);
    fprintf(f, "clutter_map.window_cells = %u\n", p->clutter_map.window_cells);
    fprintf(f, "clutter_map.guard_cells = %u\n", p->clutter_map.guard_cells);
    put_num(f, "clutter_map.edge_alpha", (double)p->clutter_map.edge_alpha);
    put_num(f, "max_pos_sigma_ratio", (double)p->max_pos_sigma_ratio);
    put_num(f, "max_coord_m", (double)p->max_coord_m);
    fprintf(f, "visibility = %d\n", p->track_visibility);
    put_num(f, "visibility.pv0", (double)p->visibility.pv0);
    put_num(f, "visibility.pcv0", (double)p->visibility.pcv0);
    put_num(f, "visibility.delta_stay", (double)p->visibility.delta_stay);
    put_num(f, "visibility.delta_become", (double)p->visibility.delta_become);
    put_num(f, "visibility.omega_c", (double)p->visibility.omega_c);
    put_num(f, "visibility.p_con", (double)p->visibility.p_con);
    put_num(f, "visibility.p_term", (double)p->visibility.p_term);
    fprintf(f, "confirm = %s\n", confirm_name(c->confirm));
    put_num(f, "confirm.existence.p_confirm", (double)c->existence_confirm.p_confirm);
    put_num(f, "confirm.existence.reject_odds_ratio", (double)c->existence_confirm.reject_odds_ratio);
    put_num(f, "confirm.existence.count_alpha", (double)c->existence_confirm.count_alpha);
    fprintf(f, "confirm.mn.m = %d\n", c->mn.m);
    fprintf(f, "confirm.mn.n = %d\n", c->mn.n);
    fprintf(f, "confirm.mn.mode = %s\n", MODE_NAMES[c->mn.mode == TRK_MN_SLIDING]);
    put_num(f, "confirm.sprt.alpha", (double)c->sprt.alpha);
    put_num(f, "confirm.sprt.beta", (double)c->sprt.beta);
    fprintf(f, "confirm.sprt.model = %s\n", SPRT_MODEL_NAMES[c->sprt.model == TRK_SPRT_HMM]);
    put_num(f, "confirm.sprt.pd", (double)c->sprt.pd);
    put_num(f, "confirm.clutter_density.alpha", (double)c->clutter_density.alpha);
    fprintf(f, "confirm.clutter_density.kmax = %u\n", c->clutter_density.kmax);
    put_num(f, "confirm.clutter_amplitude.alpha", (double)c->clutter_amplitude.alpha);
    fprintf(f, "confirm.clutter_amplitude.kmax = %u\n", c->clutter_amplitude.kmax);
    put_num(f, "confirm.clutter_amplitude.a_min_db", (double)c->clutter_amplitude.a_min_db);
    fprintf(f, "term = %s\n", term_name(c->term));
    put_num(f, "term.existence.p_terminate", (double)c->existence_term.p_terminate);
    fprintf(f, "term.kn.k = %d\n", c->kn.k);
    fprintf(f, "term.kn.n = %d\n", c->kn.n);
    put_num(f, "term.page.h", (double)c->page.h);
    put_num(f, "term.shiryaev.beta0", (double)c->shiryaev.beta0);
    put_num(f, "term.shiryaev.rho", (double)c->shiryaev.rho);
    put_num(f, "term.shiryaev.h", (double)c->shiryaev.h);
    put_num(f, "hmm.p_low_high", (double)c->hmm.p_low_high);
    put_num(f, "hmm.q_high_low", (double)c->hmm.q_high_low);
    put_num(f, "hmm.pd_low", (double)c->hmm.pd_low);
    put_num(f, "hmm.pd_high", (double)c->hmm.pd_high);
    if (c->hmm.pi0_high == TRK_HMM_PI0_STATIONARY) fprintf(f, "hmm.pi0_high = stationary\n");
    else put_num(f, "hmm.pi0_high", (double)c->hmm.pi0_high);
    fprintf(f, "hmm.events = %s\n", EVENTS_NAMES[c->hmm_events == TRK_EVENTS_PAPER]);
    if (c->q2_table[0]) fprintf(f, "q2_table = %s\n", c->q2_table);
#if TRK_WITH_IMM
    put_num(f, "imm.turn_rate_dps", c->imm_turn_rate_dps);
    put_num(f, "imm.p_stay", c->imm_p_stay);
    put_num(f, "imm.turn_q", c->imm_turn_q);
#endif
    for (unsigned s = 0; s < p->n_sensors; s++) {
        const struct trk_sensor_params *sp = &p->sensor[s];
        char k[64];
        snprintf(k, sizeof k, "sensor.%u.pd", s);
        put_num(f, k, (double)sp->pd);
        fprintf(f, "sensor.%u.meas_cov_m2 = %.17g, %.17g, %.17g\n", s, (double)sp->meas_cov_m2[0],
                (double)sp->meas_cov_m2[1], (double)sp->meas_cov_m2[2]);
        snprintf(k, sizeof k, "sensor.%u.clutter_density_per_m2", s);
        put_num(f, k, (double)sp->clutter_density_per_m2);
        fprintf(f, "sensor.%u.amplitude = %s\n", s, AMP_NAMES[c->amp[s].model]);
        snprintf(k, sizeof k, "sensor.%u.k_shape", s);
        put_num(f, k, c->amp[s].k_shape);
        snprintf(k, sizeof k, "sensor.%u.snr_db", s);
        put_num(f, k, c->amp[s].snr_db);
        snprintf(k, sizeof k, "sensor.%u.pfa", s);
        put_num(f, k, c->amp[s].pfa);
        if (c->amp[s].table[0]) fprintf(f, "sensor.%u.amp_table = %s\n", s, c->amp[s].table);
        fprintf(f, "sensor.%u.kind = %s\n", s, KIND_NAMES[sp->kind == TRK_SENSOR_POLAR]);
        snprintf(k, sizeof k, "sensor.%u.sigma_range_m", s);
        put_num(f, k, (double)sp->sigma_range_m);
        snprintf(k, sizeof k, "sensor.%u.sigma_bearing_rad", s);
        put_num(f, k, (double)sp->sigma_bearing_rad);
        fprintf(f, "sensor.%u.conversion = %s\n", s, CONVERSION_NAMES[sp->conversion == TRK_POLAR_UNBIASED]);
        snprintf(k, sizeof k, "sensor.%u.pose.x_m", s);
        put_num(f, k, (double)sp->pose.x_m);
        snprintf(k, sizeof k, "sensor.%u.pose.y_m", s);
        put_num(f, k, (double)sp->pose.y_m);
        snprintf(k, sizeof k, "sensor.%u.pose.heading_rad", s);
        put_num(f, k, (double)sp->pose.heading_rad);
        fprintf(f, "sensor.%u.pd_profile = ", s);
        if (sp->pd_profile.n == 0) fputs("none", f);
        for (unsigned i = 0; i < sp->pd_profile.n; i++) {
            char r[40], d[40];
            shortest(r, sizeof r, (double)sp->pd_profile.range_m[i]);
            shortest(d, sizeof d, (double)sp->pd_profile.pd[i]);
            fprintf(f, "%s%s:%s", i ? ", " : "", r, d);
        }
        fputc('\n', f);
        fprintf(f, "sensor.%u.clutter_profile = ", s);
        if (sp->clutter_profile.n == 0) fputs("none", f);
        for (unsigned i = 0; i < sp->clutter_profile.n; i++) {
            char r[40], d[40];
            shortest(r, sizeof r, (double)sp->clutter_profile.range_m[i]);
            shortest(d, sizeof d, (double)sp->clutter_profile.density_per_m2[i]);
            fprintf(f, "%s%s:%s", i ? ", " : "", r, d);
        }
        fputc('\n', f);
        snprintf(k, sizeof k, "sensor.%u.persistent_share", s);
        put_num(f, k, (double)sp->persistent_share);
        snprintf(k, sizeof k, "sensor.%u.persistent_pd", s);
        put_num(f, k, (double)sp->persistent_pd);
        snprintf(k, sizeof k, "sensor.%u.coverage.min_range_m", s);
        put_num(f, k, (double)sp->coverage.min_range_m);
        snprintf(k, sizeof k, "sensor.%u.coverage.max_range_m", s);
        put_num(f, k, (double)sp->coverage.max_range_m);
        snprintf(k, sizeof k, "sensor.%u.coverage.half_width_rad", s);
        put_num(f, k, (double)sp->coverage.half_width_rad);
    }
}

void tcfg_help(FILE *f)
{
    fprintf(f,
            "Tracker settings (config file 'key = value', or on the command line):\n"
            "  sensors = N                       sensors fused, 1..%d (1)\n"
            "  process_noise_q = Q               CV process noise density, m^2/s^3, >= 0 (0.01)\n"
            "  gate_prob = P                     gate probability P_G, (0,1) (0.99)\n"
            "  clutter = parametric|nonparametric  clutter density: configured (parametric) or m/V_G (nonparametric)\n"
            "  init_speed_sigma_mps = S          velocity prior of a new track, per axis, > 0 (5)\n"
            "  max_dt_s = S                      longest accepted gap between scans, [1e-6,1e9] (3600)\n"
            "  max_tentative_scans = N           drop tentative tracks older than N scans, 0 = off (0)\n"
            "  max_unseen_scans = N              end a confirmed track out of the sensor's sight for\n"
            "                                    more than N scans in a row (0)\n"
            "  merge_gate_d2 = G                 merge two tracks whose 4-D states are within d2 <= G, 0 = off (4)\n"
            "  init_exclusion_d2 = G             no new track from a detection within d2 <= G of a confirmed track (18.42)\n"
            "  stationary_d2 = G                 hold a tentative track tentative while its velocity is\n"
            "                                    consistent with standing still, v' P_v^-1 v < G (a\n"
            "                                    persistent return), and a confirmed one back after 3\n"
            "                                    such looks in a row, 0 = off (25)\n"
            "  association = pda|joint           per-track PDA, or joint association (JPDA / JIPDA) (joint)\n"
            "  filter = kalman|alpha_beta        track filter: CV Kalman, or constant gains (TRK_WITH_ALPHA_BETA builds) (kalman)\n"
            "  init.method = two_point|single_point   how tracks start (two_point)\n"
            "    init.max_speed_mps               two-point velocity gate, > 0 (15)\n"
            "    init.max_gap_scans               candidate lifetime in scans, >= 1 (2)\n"
            "    init.birth_density_per_m2        new targets per m^2 per scan: the initial existence,\n"
            "                                     >= 0, 0 = visibility.pv0 (1e-9)\n"
            "    init.min_existence               the least initial existence of a new track; a weaker\n"
            "                                     pair waits for a third point, [0, 1), 0 = off (0.003)\n"
            "  clutter_map.n_range, .n_bearing   each sensor's clutter map: cells over its coverage\n"
            "                                    (range x bearing; needs a maximum range), 0 = none (16, 32)\n"
            "    clutter_map.time_constant_scans  the counts' memory, >= 1 scan (10)\n"
            "    clutter_map.prior_count          pseudo-counts at the configured density, > 0 (2)\n"
            "    clutter_map.min_ratio, .max_ratio   bounds of a position's ratio to it (0.1, 100)\n"
            "    clutter_map.window_cells         a position's ratio from the cells within this many rows\n"
            "                                     and columns of its own, 0-8, 0 = its cell alone (1)\n"
            "    clutter_map.guard_cells          of those, the cells within this many - 1 (1: its own\n"
            "                                     cell) together count one detection per scan less, 0 = none,\n"
            "                                     at most window_cells + 1 (1)\n"
            "    clutter_map.edge_alpha           a quadrant of the window (with the own cell) whose count\n"
            "                                     the window's ratio does not explain (Chernoff bound on\n"
            "                                     its tail < alpha / 4) gives its own ratio (greatest-of\n"
            "                                     at a patch's edge), [0,1), 0 = off (0.2)\n"
            "  max_pos_sigma_ratio = R           end a track whose position sigma exceeds R times the\n"
            "                                    sensor's, 0 = off (20)\n"
            "  max_coord_m = M                   surveillance bound: a detection with |x| or |y| > M\n"
            "                                    is counted and skipped, (0,1e15] (1e8)\n"
            "  visibility = 0|1                  track each track's visibility / existence (1)\n"
            "    visibility.pv0, .pcv0            at initiation (0.5, 0.5)\n"
            "    visibility.delta_stay, .delta_become   Markov visibility model (0.997, 0)\n"
            "    visibility.omega_c               confidence smoothing, [0,1) (0.75)\n"
            "    visibility.p_con, .p_term        confirm at pcv >= p_con, end at pcv < p_term (0.9, 0.1)\n"
            , TRK_MAX_SENSORS);
    fprintf(f,
            "  confirm = existence|mn|sprt|clutter_density|clutter_amplitude|visibility   confirmation test (existence)\n"
            "    confirm.existence.p_confirm, .reject_odds_ratio   confirm at existence >= p, reject when\n"
            "                                     its odds fell below ratio x the initial odds (0.999, 0.01)\n"
            "    confirm.existence.count_alpha    gate-count check: not confirmed while the gates' outer\n"
            "                                     halves (or whole gates, against 3 target highlights) held\n"
            "                                     more detections than lambda V_G and the target explain,\n"
            "                                     P < alpha; [0,1), 0 = off (0.01)\n"
            "    confirm.mn.m, confirm.mn.n       M of N, 1 <= m <= n <= %d (3, 5)\n"
            "    confirm.mn.mode = fixed|sliding  (fixed)\n"
            "    confirm.sprt.alpha, .beta        Wald error probabilities, (0,1), sum < 1 (0.01, 0.1)\n"
            "    confirm.sprt.model = fixed_pd|hmm, confirm.sprt.pd   (fixed_pd, 0.9)\n"
            "    confirm.clutter_density.alpha, .kmax          (0.01, 25)\n"
            "    confirm.clutter_amplitude.alpha, .kmax, .a_min_db   (0.01, 25, 10 dB)\n",
            TRK_MN_MAX_N);
    fprintf(f,
            "  term = existence|kn|page|shiryaev|visibility  termination test (existence)\n"
            "    term.existence.p_terminate       end at existence < p (0.1)\n"
            "    term.kn.k, term.kn.n             K or fewer hits in the last N, 0 <= k < n (0, 5)\n"
            "    term.page.h                      CUSUM threshold, > 0 (5)\n"
            "    term.shiryaev.beta0, .rho, .h    prior, change rate, log-odds threshold (0.01, 0.01, 4.595)\n"
            "  hmm.p_low_high, hmm.q_high_low, hmm.pd_low, hmm.pd_high, hmm.pi0_high\n"
            "                                    fluctuating-SNR model of sprt(hmm)/page/shiryaev\n"
            "                                    (0.1, 0.1, 0.3, 0.9, stationary)\n"
            "  hmm.events = complete|paper       what a detection in the gate means under H1 for\n"
            "                                    sprt (fixed_pd and hmm)/page/shiryaev: target or\n"
            "                                    clutter (complete), or the target alone as in\n"
            "                                    Blanding eq 8 (paper; empty gates of a coasting\n"
            "                                    track then count for it) (complete)\n"
            "  q2_table = FILE                   q2 table (trk-tablegen output)\n"
            "  sensor.N.pd = P                   detection probability, (0,1] (0.9)\n"
            "  sensor.N.meas_cov_m2 = XX, XY, YY measurement covariance, SPD (1, 0, 1)\n"
            "  sensor.N.meas_sigma_m = S         shorthand for meas_cov_m2 = S^2, 0, S^2\n"
            "  sensor.N.clutter_density_per_m2 = L   clutter density, >= 0 (1e-4)\n"
            "  sensor.N.amplitude = none|rayleigh|k  amplitude model of PDAFAI (none)\n"
            "  sensor.N.k_shape, .snr_db, .pfa   K shape, target SNR dB, threshold P_FA (1, 15, 1e-3)\n"
            "  sensor.N.amp_table = FILE         amplitude table (trk-tablegen output)\n"
            "  sensor.N.kind = cartesian|polar   positions, or range and bearing from the pose (cartesian)\n"
            "    sensor.N.sigma_range_m           polar: range noise (1 sigma), (0, 1e6] m (1)\n"
            "    sensor.N.sigma_bearing_rad       polar: bearing noise (1 sigma), (0, 0.5] rad (0.01)\n"
            "    sensor.N.conversion = first_order|unbiased   polar -> Cartesian (first_order)\n"
            "  sensor.N.pose.x_m, .pose.y_m, .pose.heading_rad   the sensor's pose when a scan carries\n"
            "                                    none; heading clockwise from north, [-2pi, 2pi] (0, 0, 0)\n"
            "  sensor.N.pd_profile = none|R:P, ...  P_D over range (m) from the pose, 2..%d points,\n"
            "                                    linear between them; with an amplitude model (Rayleigh\n"
            "                                    only) the target's SNR over range, P_D in (pfa, 1) (none)\n"
            "  sensor.N.persistent_share, .persistent_pd   persistent returns in a Rayleigh model's\n"
            "                                    amplitudes: their share of what is not a target, [0, 1),\n"
            "                                    and their P_D at the threshold, (pfa, 1) (0, 0)\n"
            "  sensor.N.clutter_profile = none|R:D, ...  clutter density (1/m^2) over range from the\n"
            "                                    pose, 2..%d points; parametric clutter only (none)\n"
            "  sensor.N.coverage.min_range_m, .max_range_m, .half_width_rad   where P_D is not 0:\n"
            "                                    ranges (max 0: no limit) and the sector's half width\n"
            "                                    about the heading, [0, pi] (0: all round) (0, 0, 0)\n"
            "Amplitude tables and q2 tables are read and checked at start-up; a bad one\n"
            "stops the program (exit status 2).\n",
            TRK_PD_PROFILE_MAX, TRK_PD_PROFILE_MAX);
#if TRK_WITH_IMM
    fprintf(f, "IMM tracks (this build: TRK_WITH_IMM = 1):\n"
               "  imm.turn_rate_dps = W             CV and coordinated turns at +-W deg/s (trk_tracker_imm_params),\n"
               "                                    [0, 57.29], 0 = CV only (0)\n"
               "    imm.p_stay                       per-scan probability of keeping the model, [0,1] (0.95)\n"
               "    imm.turn_q                       the turn models' q, m^2/s^3, >= 0, 0 = process_noise_q;\n"
               "                                     the CV model's is process_noise_q (0)\n");
#endif
}
