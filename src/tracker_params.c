/* tracker_params.c - the tracker's parameters (trk/tracker.h): defaults and
 * the check that names the refused field (trk_tracker_init in tracker.c
 * runs it). */
#include <string.h>

#include "tracker_internal.h"

void trk_tracker_default_params(struct trk_tracker_params *p)
{
    /* filled in place: a local copy would put 2.0 KB (float) or 3.6 KB (double) on a
     * firmware stack */
    memset(p, 0, sizeof *p);
    p->n_sensors = 1;
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].meas_cov_m2[TRK_COV2_XX] = 1;
    p->sensor[0].meas_cov_m2[TRK_COV2_XY] = 0;
    p->sensor[0].meas_cov_m2[TRK_COV2_YY] = 1;
    p->sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-4);
    p->process_noise_q = TRK_REAL_C(0.01);
    p->gate_prob = TRK_REAL_C(0.99);
    p->clutter = TRK_CLUTTER_PARAMETRIC;
    p->init_speed_sigma_mps = 5;
    p->max_dt_s = 3600;
    /* existence-based confirmation and termination (docs/tracker.md, bullet "Defaults") */
    p->confirm.method = TRK_CONFIRM_EXISTENCE;
    p->confirm.u.existence.p_confirm = TRK_REAL_C(0.999);
    p->confirm.u.existence.reject_odds_ratio = TRK_REAL_C(0.01);
    p->confirm.u.existence.count_alpha = TRK_REAL_C(0.01); /* docs/tracker.md "The gate-count check" */
    p->term.method = TRK_TERM_EXISTENCE;
    p->term.u.existence.p_terminate = TRK_REAL_C(0.1);
    p->max_tentative_scans = 0;
    p->init.method = TRK_INIT_TWO_POINT;
    p->init.max_speed_mps = 15; /* 30 knots */
    p->init.max_gap_scans = 2; /* a target missed once still pairs */
    p->init.birth_density_per_m2 = TRK_REAL_C(1e-9);
    p->init.min_existence = TRK_REAL_C(0.003); /* docs/tuning.md "The least initial existence" */
    p->stationary_d2 = 25; /* motion past 5 sigma: a still object passes at e^-12.5 = 3.7e-6 (chi^2_2),
                              at e^-10 = 4.5e-5 when its echoes are a target's (the bar lowered to 20);
                              docs/tracker.md "Persistent returns" for the measured choice */
    /* a clutter map for a sensor with a coverage: 16 x 32 cells (16 x 16
     * in a build of 256), 10 scans' memory, 2 pseudo-counts, a position's
     * ratio from the 3 x 3 cells about it, its own less one detection per
     * scan (docs/tracker.md "Clutter map" for the measured choice) */
    p->clutter_map.n_range = TRK_CLUTTER_MAP_CELLS >= 256 ? 16 : 0;
    p->clutter_map.n_bearing = TRK_CLUTTER_MAP_CELLS >= 512 ? 32 : TRK_CLUTTER_MAP_CELLS >= 256 ? 16 : 0;
    p->clutter_map.window_cells = 1;
    p->clutter_map.guard_cells = 1;
    p->clutter_map.edge_alpha = TRK_REAL_C(0.2); /* docs/tracker.md "Clutter map" */
    p->clutter_map.time_constant_scans = 10;
    p->clutter_map.prior_count = 2;
    p->clutter_map.min_ratio = TRK_REAL_C(0.1);
    p->clutter_map.max_ratio = 100;
    p->max_pos_sigma_ratio = 20;
    p->max_coord_m = TRK_MAX_COORD_M_DEFAULT;
    p->association = TRK_WITH_JOINT ? TRK_ASSOC_JOINT : TRK_ASSOC_PDA; /* JIPDA: docs/tracker.md,
                                                                              bullet "Association" */
    p->filter = TRK_FILTER_KALMAN;
    p->merge_gate_d2 = 4;
    p->init_exclusion_d2 = TRK_REAL_C(18.420680743952367); /* -2 ln 1e-4: 99.99 % of a target's
                                                              detections */
    /* existence (IPDA, Markov chain one: a target that is gone stays gone) */
    p->track_visibility = 1;
    p->visibility.pv0 = TRK_REAL_C(0.5);
    p->visibility.pcv0 = TRK_REAL_C(0.5);
    p->visibility.delta_stay = TRK_REAL_C(0.997); /* a mean life of 333 scans: docs/tuning.md "Target survival per scan" */
    p->visibility.delta_become = 0;
    p->visibility.omega_c = TRK_REAL_C(0.75);
    p->visibility.p_con = TRK_REAL_C(0.9);
    p->visibility.p_term = TRK_REAL_C(0.1);
}

void trk_tracker_mn_kn_params(struct trk_tracker_params *p)
{
    trk_tracker_default_params(p);
    memset(&p->confirm, 0, sizeof p->confirm);
    memset(&p->term, 0, sizeof p->term);
    p->confirm.method = TRK_CONFIRM_MN;
    p->confirm.u.mn.m = 3;
    p->confirm.u.mn.n = 5;
    p->confirm.u.mn.mode = TRK_MN_FIXED;
    p->term.method = TRK_TERM_KN;
    p->term.u.kn.k = 0;
    p->term.u.kn.n = 5;
    p->init.method = TRK_INIT_SINGLE_POINT;
    p->init.birth_density_per_m2 = 0;
    p->init.min_existence = 0;
    p->stationary_d2 = 0; /* as before the hold of tracks that stand still */
    p->max_pos_sigma_ratio = 0;
    p->visibility.delta_become = TRK_REAL_C(0.01);
    p->association = TRK_ASSOC_PDA;
}

/* ------------------------------------------------------------------ field names */

/* "sensor[i].<member>" for every sensor index of this build, as literals
 * (no stdio to format them): one row per index, rows up to TRK_MAX_SENSORS
 * (in blocks of up to twice the rows needed above 2). */
enum { F_PD, F_COV, F_DENSITY, F_USE_AMP, F_AMP, F_KIND, F_SIGMA_R, F_SIGMA_B, F_CONV, F_POSE, F_PROFILE, F_COVER,
       F_CLUTTER_PROFILE, F_PERSIST, N_SENSOR_FIELDS };
#define ROW(i)                                                                                      \
    {"sensor[" #i "].pd", "sensor[" #i "].meas_cov_m2", "sensor[" #i "].clutter_density_per_m2",       \
     "sensor[" #i "].use_amplitude", "sensor[" #i "].amplitude", "sensor[" #i "].kind",                \
     "sensor[" #i "].sigma_range_m", "sensor[" #i "].sigma_bearing_rad", "sensor[" #i "].conversion",  \
     "sensor[" #i "].pose", "sensor[" #i "].pd_profile", "sensor[" #i "].coverage",                   \
     "sensor[" #i "].clutter_profile", "sensor[" #i "].persistent_share"},
#define ROWS10(d) ROW(d##0) ROW(d##1) ROW(d##2) ROW(d##3) ROW(d##4) ROW(d##5) ROW(d##6) ROW(d##7) ROW(d##8) ROW(d##9)
static const char *const sensor_field[][N_SENSOR_FIELDS] = {
    ROW(0)
#if TRK_MAX_SENSORS > 1
    ROW(1)
#endif
#if TRK_MAX_SENSORS > 2
    ROW(2) ROW(3)
#endif
#if TRK_MAX_SENSORS > 4
    ROW(4) ROW(5) ROW(6) ROW(7)
#endif
#if TRK_MAX_SENSORS > 8
    ROW(8) ROW(9)
#endif
#if TRK_MAX_SENSORS > 10
    ROWS10(1)
#endif
#if TRK_MAX_SENSORS > 20
    ROWS10(2) ROWS10(3)
#endif
#if TRK_MAX_SENSORS > 40
    ROWS10(4) ROWS10(5) ROWS10(6) ROWS10(7)
#endif
#if TRK_MAX_SENSORS > 80
    ROWS10(8) ROWS10(9) ROWS10(10) ROWS10(11) ROWS10(12) ROWS10(13) ROWS10(14) ROWS10(15)
#endif
#if TRK_MAX_SENSORS > 160
    ROWS10(16) ROWS10(17) ROWS10(18) ROWS10(19) ROWS10(20) ROWS10(21) ROWS10(22) ROWS10(23) ROWS10(24)
    ROWS10(25)
#endif
};
#undef ROWS10
#undef ROW
typedef char trk_i_sensor_field_rows_ok[sizeof sensor_field / sizeof sensor_field[0] >= TRK_MAX_SENSORS ? 1 : -1];

static trk_status refuse(const char **field, const char *name, trk_status st)
{
    if (field) *field = name;
    return st;
}

/* ------------------------------------------------------------------ check */

/* A finite v in [lo, hi] (lo_open: (lo, hi]). */
static trk_status check_real(trk_real v, trk_real lo, int lo_open, trk_real hi, const char *name,
                             const char **field)
{
    if (!isfinite(v)) return refuse(field, name, TRK_E_NAN);
    if (!(lo_open ? v > lo : v >= lo) || !(v <= hi)) return refuse(field, name, TRK_E_RANGE);
    return TRK_OK;
}

/* The velocity prior's sigma: its square (the prior variance) must be a
 * positive finite number, so sigma in [sqrt(smallest normal), sqrt(max)]. */
static trk_status check_speed_sigma(trk_real v, const char **field)
{
    const trk_status st = check_real(v, 0, 1, TRK_REAL_MAX, "init_speed_sigma_mps", field);
    if (st != TRK_OK) return st;
    const trk_real vv = v * v;
    return vv <= TRK_REAL_MAX && vv >= 1 / TRK_REAL_MAX ? TRK_OK : refuse(field, "init_speed_sigma_mps", TRK_E_RANGE);
}

/* The clutter maps' cells and estimator (trk_clutter_map_params): no cells
 * is no map (the rest unread). */
static trk_status check_clutter_map(const struct trk_clutter_map_params *mp, const char **field)
{
    trk_status st;
    if (mp->n_range == 0 && mp->n_bearing == 0) return TRK_OK;
    if (mp->n_range == 0) return refuse(field, "clutter_map.n_range", TRK_E_RANGE);
    if (mp->n_bearing == 0) return refuse(field, "clutter_map.n_bearing", TRK_E_RANGE);
    if ((unsigned long)mp->n_range * mp->n_bearing > (unsigned long)TRK_CLUTTER_MAP_CELLS)
        return refuse(field, "clutter_map.n_range", TRK_E_CAPACITY);
    if ((st = check_real(mp->time_constant_scans, 1, 0, TRK_REAL_C(1e6), "clutter_map.time_constant_scans", field)) !=
            TRK_OK ||
        (st = check_real(mp->prior_count, TRK_REAL_MIN, 0, TRK_REAL_C(1e6), "clutter_map.prior_count", field)) !=
            TRK_OK ||
        (st = check_real(mp->min_ratio, TRK_REAL_MIN, 0, 1, "clutter_map.min_ratio", field)) != TRK_OK ||
        (st = check_real(mp->max_ratio, 1, 0, TRK_REAL_C(1e6), "clutter_map.max_ratio", field)) != TRK_OK)
        return st;
    if (mp->window_cells > TRK_CLUTTER_MAP_WINDOW_MAX) return refuse(field, "clutter_map.window_cells", TRK_E_RANGE);
    if (mp->guard_cells > mp->window_cells + 1) return refuse(field, "clutter_map.guard_cells", TRK_E_RANGE);
    /* 0, or a normal number below 1 (a value punned through another type reads as subnormal) */
    if (!isfinite(mp->edge_alpha)) return refuse(field, "clutter_map.edge_alpha", TRK_E_NAN);
    if (!(mp->edge_alpha == 0 || (mp->edge_alpha >= TRK_REAL_MIN && mp->edge_alpha < 1)))
        return refuse(field, "clutter_map.edge_alpha", TRK_E_RANGE);
    return TRK_OK;
}

/* How tracks start (trk_init_params). */
static trk_status check_init(const struct trk_init_params *in, const char **field)
{
    trk_status st;
    if (in->method != TRK_INIT_SINGLE_POINT && in->method != TRK_INIT_TWO_POINT)
        return refuse(field, "init.method", TRK_E_ARG);
    if ((st = check_real(in->birth_density_per_m2, 0, 0, TRK_REAL_MAX, "init.birth_density_per_m2", field)) != TRK_OK)
        return st;
    if ((st = check_real(in->min_existence, 0, 0, 1, "init.min_existence", field)) != TRK_OK) return st;
    if (in->min_existence >= 1) return refuse(field, "init.min_existence", TRK_E_RANGE); /* no pair would start */
    if (in->method == TRK_INIT_SINGLE_POINT) return TRK_OK;
    if ((st = check_real(in->max_speed_mps, 0, 1, TRK_REAL_MAX, "init.max_speed_mps", field)) != TRK_OK) return st;
    return in->max_gap_scans >= 1 && in->max_gap_scans < TRK_MAX_CANDIDATE_SCANS
               ? TRK_OK
               : refuse(field, "init.max_gap_scans", TRK_E_RANGE);
}

/* The alpha-beta filter needs its knob, a process noise (its steady state
 * has none without one), no IMM (whose models are Kalman filters) and no
 * polar sensor (whose R changes with every track's position: constant
 * gains would have to be worked out per track and scan, the cost the
 * filter exists to avoid). */
static trk_status check_filter(const struct trk_tracker_params *p, const char **field)
{
    if (p->filter == TRK_FILTER_KALMAN) return TRK_OK;
    if (p->filter != TRK_FILTER_ALPHA_BETA) return refuse(field, "filter", TRK_E_ARG);
    if (!TRK_WITH_ALPHA_BETA) return refuse(field, "filter", TRK_E_UNSUPPORTED);
#if TRK_WITH_IMM
    if (p->imm.n_models != 0) return refuse(field, "filter", TRK_E_UNSUPPORTED);
#endif
    if (!(p->process_noise_q > 0)) return refuse(field, "filter", TRK_E_UNSUPPORTED);
    for (unsigned s = 0; s < p->n_sensors; s++)
        if (p->sensor[s].kind == TRK_SENSOR_POLAR) return refuse(field, "filter", TRK_E_UNSUPPORTED);
    return TRK_OK;
}

/* Joint association weighs events by 1 / lambda: parametric clutter with a
 * density > 0 at every sensor. */
static trk_status check_association(const struct trk_tracker_params *p, const char **field)
{
    if (p->association == TRK_ASSOC_PDA) return TRK_OK;
    if (p->association != TRK_ASSOC_JOINT) return refuse(field, "association", TRK_E_ARG);
    if (!TRK_WITH_JOINT) return refuse(field, "association", TRK_E_UNSUPPORTED);
    if (p->clutter != TRK_CLUTTER_PARAMETRIC) return refuse(field, "association", TRK_E_UNSUPPORTED);
    for (unsigned s = 0; s < p->n_sensors; s++)
        if (!(p->sensor[s].clutter_density_per_m2 > 0)) return refuse(field, "association", TRK_E_UNSUPPORTED);
    return TRK_OK;
}

/* The scalars (gate_prob with the sensors' PDA). */
static trk_status check_scalars(const struct trk_tracker_params *p, const char **field)
{
    trk_status st;
    if (p->n_sensors < 1 || p->n_sensors > TRK_MAX_SENSORS) return refuse(field, "n_sensors", TRK_E_RANGE);
    if (p->clutter != TRK_CLUTTER_PARAMETRIC && p->clutter != TRK_CLUTTER_NONPARAMETRIC)
        return refuse(field, "clutter", TRK_E_ARG);
    if ((st = check_real(p->process_noise_q, 0, 0, TRK_REAL_MAX, "process_noise_q", field)) != TRK_OK ||
        (st = check_speed_sigma(p->init_speed_sigma_mps, field)) != TRK_OK ||
        (st = check_real(p->max_dt_s, TRK_MAX_DT_S_MIN, 0, TRK_REAL_C(1e9), "max_dt_s", field)) != TRK_OK ||
        (st = check_real(p->merge_gate_d2, 0, 0, TRK_REAL_MAX, "merge_gate_d2", field)) != TRK_OK ||
        (st = check_real(p->init_exclusion_d2, 0, 0, TRK_REAL_MAX, "init_exclusion_d2", field)) != TRK_OK ||
        (st = check_real(p->stationary_d2, 0, 0, TRK_REAL_MAX, "stationary_d2", field)) != TRK_OK)
        return st;
    if (p->track_visibility != 0 && p->track_visibility != 1) return refuse(field, "track_visibility", TRK_E_ARG);
    if ((st = check_real(p->max_pos_sigma_ratio, 0, 0, TRK_REAL_MAX, "max_pos_sigma_ratio", field)) != TRK_OK ||
        (st = check_real(p->max_coord_m, 0, 1, TRK_MAX_COORD_M_LIMIT, "max_coord_m", field)) != TRK_OK)
        return st;
    if ((st = check_clutter_map(&p->clutter_map, field)) != TRK_OK) return st;
    return check_init(&p->init, field);
}

/* A polar sensor's noise and conversion (a Cartesian sensor's are not
 * read). sigma_bearing_rad at most 0.5 rad: beyond it no conversion
 * describes the spread (trk_polar_to_cartesian). */
static trk_status check_polar(const struct trk_sensor_params *sp, const char *const *name, const char **field)
{
    trk_status st;
    if (sp->kind == TRK_SENSOR_CARTESIAN) return TRK_OK;
    if (sp->kind != TRK_SENSOR_POLAR) return refuse(field, name[F_KIND], TRK_E_ARG);
    if (sp->conversion != TRK_POLAR_FIRST_ORDER && sp->conversion != TRK_POLAR_UNBIASED)
        return refuse(field, name[F_CONV], TRK_E_ARG);
    if ((st = check_real(sp->sigma_range_m, 0, 1, TRK_REAL_C(1e6), name[F_SIGMA_R], field)) != TRK_OK ||
        (st = check_real(sp->sigma_bearing_rad, 0, 1, TRK_REAL_C(0.5), name[F_SIGMA_B], field)) != TRK_OK)
        return st;
    /* their squares are the variances: a sigma whose square underflows made
     * every detection's covariance singular (a sensor blind without a word) */
    if (!(sp->sigma_range_m * sp->sigma_range_m >= TRK_REAL_MIN)) return refuse(field, name[F_SIGMA_R], TRK_E_RANGE);
    if (!(sp->sigma_bearing_rad * sp->sigma_bearing_rad >= TRK_REAL_MIN))
        return refuse(field, name[F_SIGMA_B], TRK_E_RANGE);
    return TRK_OK;
}

/* Where the sensor sees: its fixed pose (finite, in the surveillance
 * bound), its P_D profile (points in range order, P_D in [0, 1]; with an
 * amplitude model, a Rayleigh one and P_D in (pfa, 1)), its clutter profile
 * (points in range order, lambda in (0, 1e6] per m^2; parametric clutter
 * only) and its coverage. */
static trk_status check_view(const struct trk_tracker_params *p, const struct trk_sensor_params *sp,
                             const char *const *name, const char **field)
{
    trk_status st;
    const trk_real bound = p->max_coord_m;
    if ((st = check_real(sp->pose.x_m, -bound, 0, bound, name[F_POSE], field)) != TRK_OK ||
        (st = check_real(sp->pose.y_m, -bound, 0, bound, name[F_POSE], field)) != TRK_OK ||
        (st = check_real(sp->pose.heading_rad, -TRK_REAL_C(1e6), 0, TRK_REAL_C(1e6), name[F_POSE], field)) != TRK_OK)
        return st;
    const struct trk_pd_profile *pr = &sp->pd_profile;
    if (pr->n != 0) {
        if (pr->n < 2 || pr->n > TRK_PD_PROFILE_MAX) return refuse(field, name[F_PROFILE], TRK_E_RANGE);
        /* with amplitudes the profile is the target's SNR over range: the
         * Rayleigh closed form (trk_amplitude_log_lr_at_pd), P_D in (pfa, 1) */
        const int snr = sp->use_amplitude;
        if (snr && (sp->amplitude.tabulated || sp->amplitude.model != TRK_AMP_RAYLEIGH))
            return refuse(field, name[F_PROFILE], TRK_E_UNSUPPORTED);
        for (unsigned k = 0; k < pr->n; k++) {
            const trk_real lo = k == 0 ? 0 : pr->range_m[k - 1];
            if ((st = check_real(pr->range_m[k], lo, k > 0, TRK_MAX_COORD_M_LIMIT, name[F_PROFILE], field)) != TRK_OK ||
                (st = check_real(pr->pd[k], 0, 0, 1, name[F_PROFILE], field)) != TRK_OK)
                return st;
            if (snr && !(pr->pd[k] > sp->amplitude.pfa && pr->pd[k] < 1)) return refuse(field, name[F_PROFILE], TRK_E_RANGE);
        }
    }
    /* the density's bound is its profile's; with a map, the map's floor (the
     * configured density times min_ratio) stays a normal number: a cell
     * never goes blind, and no cell's expected count overflows */
    if (sp->clutter_density_per_m2 > TRK_REAL_C(1e6)) return refuse(field, name[F_DENSITY], TRK_E_RANGE);
    const int mapped = trk_i_map_kept(&p->clutter_map, sp);
    if (mapped && sp->clutter_density_per_m2 > 0 && !(sp->clutter_density_per_m2 * p->clutter_map.min_ratio >= TRK_REAL_MIN))
        return refuse(field, "clutter_map.min_ratio", TRK_E_RANGE);
    const struct trk_clutter_profile *cp = &sp->clutter_profile;
    if (cp->n != 0) {
        if (cp->n < 2 || cp->n > TRK_PD_PROFILE_MAX) return refuse(field, name[F_CLUTTER_PROFILE], TRK_E_RANGE);
        if (p->clutter != TRK_CLUTTER_PARAMETRIC) return refuse(field, name[F_CLUTTER_PROFILE], TRK_E_UNSUPPORTED);
        /* the sensor's density stays the reference the profile's odds are taken against */
        if (!(sp->clutter_density_per_m2 > 0)) return refuse(field, name[F_CLUTTER_PROFILE], TRK_E_RANGE);
        for (unsigned k = 0; k < cp->n; k++) {
            const trk_real lo = k == 0 ? 0 : cp->range_m[k - 1];
            if ((st = check_real(cp->range_m[k], lo, k > 0, TRK_MAX_COORD_M_LIMIT, name[F_CLUTTER_PROFILE], field)) !=
                    TRK_OK ||
                (st = check_real(cp->density_per_m2[k], 0, 1, TRK_REAL_C(1e6), name[F_CLUTTER_PROFILE], field)) != TRK_OK)
                return st;
            if (mapped && !(cp->density_per_m2[k] * p->clutter_map.min_ratio >= TRK_REAL_MIN))
                return refuse(field, "clutter_map.min_ratio", TRK_E_RANGE);
        }
    }
    const struct trk_coverage *c = &sp->coverage;
    if ((st = check_real(c->min_range_m, 0, 0, TRK_MAX_COORD_M_LIMIT, name[F_COVER], field)) != TRK_OK ||
        (st = check_real(c->max_range_m, 0, 0, TRK_MAX_COORD_M_LIMIT, name[F_COVER], field)) != TRK_OK ||
        (st = check_real(c->half_width_rad, 0, 0, TRK_PI, name[F_COVER], field)) != TRK_OK)
        return st;
    if (c->max_range_m > 0 && !(c->max_range_m > c->min_range_m)) return refuse(field, name[F_COVER], TRK_E_RANGE);
    return TRK_OK;
}

/* Persistent returns in the amplitudes: eta in [0, 1); with eta > 0 a
 * Rayleigh closed-form model and their P_D in (pfa, 1). */
static trk_status check_persistent(const struct trk_sensor_params *sp, const char *const *name, const char **field)
{
    const trk_real eta = sp->persistent_share;
    if (isnan(eta) || isnan(sp->persistent_pd)) return refuse(field, name[F_PERSIST], TRK_E_NAN);
    if (!(eta >= 0 && eta < 1)) return refuse(field, name[F_PERSIST], TRK_E_RANGE);
    if (eta == 0) return TRK_OK;
    if (!sp->use_amplitude || sp->amplitude.tabulated || sp->amplitude.model != TRK_AMP_RAYLEIGH)
        return refuse(field, name[F_PERSIST], TRK_E_UNSUPPORTED);
    if (!(sp->persistent_pd > sp->amplitude.pfa && sp->persistent_pd < 1)) return refuse(field, name[F_PERSIST], TRK_E_RANGE);
    return TRK_OK;
}

/* A polar sensor's R where the tracker needs one without a position
 * (initiation's reach, the stored defaults): sigma_range_m^2 I, its
 * covariance where the cross-range spread equals the range's. Every gate
 * and update of a polar sensor takes its covariance at the position. */
static void polar_default_r(const struct trk_sensor_params *sp, trk_real r[NZ * NZ])
{
    const trk_real v = sp->sigma_range_m * sp->sigma_range_m;
    r[S(ZX, ZX)] = r[S(ZY, ZY)] = v;
    r[S(ZX, ZY)] = r[S(ZY, ZX)] = 0;
}

/* Sensor s: its kind and view, its PDA (P_D at the amplitude threshold
 * with an amplitude model: docs/conventions.md "PDA") and its covariance
 * (a polar sensor's: polar_default_r). */
static trk_status check_sensor(const struct trk_tracker_params *p, unsigned s, const char **field,
                               const struct trk_i_tracker_built *b)
{
    const struct trk_sensor_params *sp = &p->sensor[s];
    const char *const *name = sensor_field[s];
    if (sp->use_amplitude != 0 && sp->use_amplitude != 1) return refuse(field, name[F_USE_AMP], TRK_E_ARG);
    if (sp->use_amplitude && trk_amplitude_check(&sp->amplitude) != TRK_OK) /* not built by its init */
        return refuse(field, name[F_AMP], TRK_E_ARG);
    trk_status st0;
    if ((st0 = check_polar(sp, name, field)) != TRK_OK || (st0 = check_view(p, sp, name, field)) != TRK_OK ||
        (st0 = check_persistent(sp, name, field)) != TRK_OK)
        return st0;
    const struct trk_pda_params pp = {NZ, sp->use_amplitude ? trk_amplitude_pd(&sp->amplitude) : sp->pd,
                                      p->gate_prob, p->clutter, sp->clutter_density_per_m2, 1};
    const char *pf;
    trk_status st = trk_pda_check_params(&pp, &pf);
    if (st != TRK_OK) {
        const char *f = strcmp(pf, "gate_prob") == 0         ? "gate_prob"
                        : strcmp(pf, "clutter_density") == 0 ? name[F_DENSITY]
                        : sp->use_amplitude                   ? name[F_AMP]
                                                              : name[F_PD];
        return refuse(field, f, st);
    }
    TRK_CHECKED(trk_pda_init(&b->pda[s], &pp));
    if (sp->kind == TRK_SENSOR_POLAR) {
        polar_default_r(sp, b->r[s]);
        return TRK_OK;
    }
    st = trk_i_cov2_unpack(sp->meas_cov_m2, b->r[s]);
    return st == TRK_OK ? TRK_OK : refuse(field, name[F_COV], st);
}

/* Does the confirmation test's model build? (Which of the two tests
 * trk_i_tests_init refused: it checks confirmation first.) */
static int confirm_builds(const struct trk_tracker_params *p)
{
    union trk_confirm_model m;
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN: return trk_mn_model_init(&m.mn, &p->confirm.u.mn) == TRK_OK;
    case TRK_CONFIRM_SPRT: return trk_sprt_model_init(&m.sprt, &p->confirm.u.sprt) == TRK_OK;
#if TRK_WITH_CLUTTER_TESTS
    case TRK_CONFIRM_CLUTTER_CHI2: return trk_clutter_chi2_model_init(&m.chi2, &p->confirm.u.chi2) == TRK_OK;
    case TRK_CONFIRM_CLUTTER_AMP: return trk_clutter_amp_model_init(&m.amp, &p->confirm.u.amp) == TRK_OK;
#endif
    case TRK_CONFIRM_VISIBILITY: return p->track_visibility;
    case TRK_CONFIRM_EXISTENCE: {
        const struct trk_existence_confirm_params *x = &p->confirm.u.existence;
        return p->track_visibility && trk_i_existence_confirm_ok(x);
    }
    default: return 0;
    }
}

/* The field of a refusal st by trk_i_tests_init: the method (unknown, not
 * built in, or a visibility method without track_visibility), its
 * parameters, or its HMM with fewer sensors than the tracker. */
static const char *tests_field(const struct trk_tracker_params *p, trk_status st)
{
    static const char *const confirm[] = {"confirm.u.mn",  "confirm.u.sprt",     "confirm.u.chi2",
                                          "confirm.u.amp", "confirm.method", "confirm.u.existence"};
    static const char *const term[] = {"term.u.kn", "term.u.page", "term.u.shiryaev", "term.method",
                                       "term.u.existence"};
    const unsigned cm = (unsigned)p->confirm.method, tm = (unsigned)p->term.method;
    if (st == TRK_E_SENSOR)
        return p->confirm.method == TRK_CONFIRM_SPRT && p->confirm.u.sprt.model == TRK_SPRT_HMM &&
                       p->confirm.u.sprt.hmm.n_sensors < p->n_sensors
                   ? "confirm.u.sprt.hmm"
                   : tm == TRK_TERM_PAGE ? "term.u.page.hmm" : "term.u.shiryaev.hmm";
    if (st == TRK_E_UNSUPPORTED) return "confirm.method";
    if (!p->track_visibility && (p->confirm.method == TRK_CONFIRM_VISIBILITY || p->confirm.method == TRK_CONFIRM_EXISTENCE))
        return "confirm.method";
    if (!confirm_builds(p)) return cm < sizeof confirm / sizeof *confirm ? confirm[cm] : "confirm.method";
    if (!p->track_visibility && (p->term.method == TRK_TERM_VISIBILITY || p->term.method == TRK_TERM_EXISTENCE))
        return "term.method";
    return tm < sizeof term / sizeof *term ? term[tm] : "term.method";
}

#if TRK_WITH_IMM
trk_status trk_tracker_imm_params(struct trk_tracker_params *p, trk_real omega_rad_s, trk_real p_stay)
{
    if (!p) return TRK_E_ARG;
#if TRK_MAX_MODELS < 3
    (void)omega_rad_s;
    (void)p_stay;
    return TRK_E_CAPACITY;
#else
    struct trk_imm_params *m = &p->imm;
    memset(m, 0, sizeof *m);
    m->n_models = 3;
    const trk_real omega[3] = {0, omega_rad_s, -omega_rad_s};
    for (int i = 0; i < 3; i++) {
        m->omega_rad_s[i] = omega[i];
        m->q_m2_per_s3[i] = p->process_noise_q;
        for (int j = 0; j < 3; j++) m->p_switch[3 * i + j] = i == j ? p_stay : (1 - p_stay) / 2;
    }
    return TRK_OK;
#endif
}
#endif

trk_status trk_i_tracker_check(const struct trk_tracker_params *p, const char **field,
                               const struct trk_i_tracker_built *b)
{
    if (field) *field = NULL;
    if (!p) return refuse(field, "params", TRK_E_ARG);
    trk_status st = check_scalars(p, field);
    if (st != TRK_OK) return st;
    for (unsigned s = 0; s < p->n_sensors; s++)
        if ((st = check_sensor(p, s, field, b)) != TRK_OK) return st;
    if ((st = check_association(p, field)) != TRK_OK) return st;
    if ((st = check_filter(p, field)) != TRK_OK) return st;
#if TRK_WITH_IMM
    if (p->imm.n_models != 0 && (st = trk_imm_check_params(&p->imm)) != TRK_OK) return refuse(field, "imm", st);
#endif
    if (p->track_visibility && (st = trk_visibility_model_init(b->vis, &p->visibility)) != TRK_OK)
        return refuse(field, "visibility", st);
    st = trk_i_tests_init(p, b->confirm, b->term);
    return st == TRK_OK ? TRK_OK : refuse(field, tests_field(p, st), st);
}

trk_status trk_tracker_check_params(const struct trk_tracker_params *p, const char **field)
{
    struct trk_pda pda[TRK_MAX_SENSORS];
    trk_real r[TRK_MAX_SENSORS][NZ * NZ];
    struct trk_visibility_model vis;
    union trk_confirm_model confirm;
    union trk_term_model term;
    const struct trk_i_tracker_built b = {pda, r, &vis, &confirm, &term};
    return trk_i_tracker_check(p, field, &b);
}
