/* layout.c - the shared library's version, ABI check and struct layouts
 * (trk/layout.h). Every offset and size is the compiler's (offsetof,
 * sizeof) in the build of the library itself. */
#include "trk/layout.h"

#include <stddef.h>

#include "trk/table.h"
#include "trk/tracker.h"

#ifndef TRK_VERSION_STRING
#error "TRK_VERSION_STRING must be defined (the Makefile passes TRK_VERSION)"
#endif

const char *trk_shared_version(void) { return TRK_VERSION_STRING; }

trk_status trk_shared_abi_check(unsigned abi)
{
    if (abi != TRK_SHARED_ABI) return TRK_E_ABI;
    return trk_tracker_abi_check();
}

struct layout_row {
    const char *name;
    char kind;
    size_t size, offset, count;
    const char *sub, *unit, *range;
};

struct layout_struct {
    const char *name;
    size_t size;
    const struct layout_row *row;
    size_t n;
};

/* one row: struct S, member M (a designator), its type T */
#define ROW(S, M, K, T, N, SUB, UNIT, RANGE) {#M, K, sizeof(T), offsetof(S, M), N, SUB, UNIT, RANGE}
#define REAL(S, M, N, UNIT, RANGE) ROW(S, M, 'f', trk_real, N, "", UNIT, RANGE)
#define ENUM(S, M, RANGE) ROW(S, M, 'i', enum trk_decision, 1, "", "", RANGE)

#define P struct trk_tracker_params
static const struct layout_row params_rows[] = {
    ROW(P, n_sensors, 'u', unsigned, 1, "", "", "1 .. TRK_MAX_SENSORS"),
    ROW(P, sensor, 's', struct trk_sensor_params, TRK_MAX_SENSORS, "sensor_params", "", "[0, n_sensors) used"),
    REAL(P, process_noise_q, 1, "m^2/s^3", ">= 0"),
    REAL(P, gate_prob, 1, "", "(0, 1)"),
    ENUM(P, clutter, "CLUTTER_PARAMETRIC, CLUTTER_NONPARAMETRIC"),
    REAL(P, init_speed_sigma_mps, 1, "m/s", "> 0"),
    REAL(P, max_dt_s, 1, "s", "(0, 1e9]"),
    ROW(P, track_visibility, 'i', int, 1, "", "", "0, 1"),
    REAL(P, visibility.pv0, 1, "", "(0, 1)"),
    REAL(P, visibility.pcv0, 1, "", "[0, 1]"),
    REAL(P, visibility.delta_stay, 1, "", "[0, 1]"),
    REAL(P, visibility.delta_become, 1, "", "[0, 1]"),
    REAL(P, visibility.omega_c, 1, "", "[0, 1)"),
    REAL(P, visibility.p_con, 1, "", "(0, 1]"),
    REAL(P, visibility.p_term, 1, "", "[0, p_con)"),
    ENUM(P, confirm.method, "CONFIRM_MN, CONFIRM_SPRT, CONFIRM_CLUTTER_CHI2, CONFIRM_CLUTTER_AMP, "
                            "CONFIRM_VISIBILITY, CONFIRM_EXISTENCE"),
    ROW(P, confirm.u.mn.m, 'i', int, 1, "", "scans", "1 .. n"),
    ROW(P, confirm.u.mn.n, 'i', int, 1, "", "scans", "1 .. TRK_MN_MAX_N"),
    ENUM(P, confirm.u.mn.mode, "MN_FIXED, MN_SLIDING"),
    REAL(P, confirm.u.sprt.alpha, 1, "", "(0, 1), alpha + beta < 1"),
    REAL(P, confirm.u.sprt.beta, 1, "", "(0, 1)"),
    ENUM(P, confirm.u.sprt.model, "SPRT_FIXED_PD, SPRT_HMM"),
    REAL(P, confirm.u.sprt.pd, 1, "", "(0, 1)"),
    ROW(P, confirm.u.sprt.hmm, 's', struct trk_hmm_params, 1, "hmm_params", "", ""),
    REAL(P, confirm.u.chi2.alpha, 1, "", "(0, 1)"),
    ROW(P, confirm.u.chi2.kmax, 'u', unsigned, 1, "", "updates", "1 .. TRK_CLUTTER_KMAX"),
    REAL(P, confirm.u.amp.a_min_db, 1, "dB", "finite"),
    REAL(P, confirm.u.amp.alpha, 1, "", "(0, 1)"),
    ROW(P, confirm.u.amp.kmax, 'u', unsigned, 1, "", "updates", "1 .. TRK_CLUTTER_KMAX"),
    REAL(P, confirm.u.existence.p_confirm, 1, "", "[0.5, 1)"),
    REAL(P, confirm.u.existence.reject_odds_ratio, 1, "", "[0, 1)"),
    REAL(P, confirm.u.existence.count_alpha, 1, "", "[0, 1), 0 = off"),
    ENUM(P, term.method, "TERM_KN, TERM_PAGE, TERM_SHIRYAEV, TERM_VISIBILITY, TERM_EXISTENCE"),
    ROW(P, term.u.kn.k, 'i', int, 1, "", "scans", "0 .. n - 1"),
    ROW(P, term.u.kn.n, 'i', int, 1, "", "scans", "1 .. TRK_KN_MAX_N"),
    ROW(P, term.u.page.hmm, 's', struct trk_hmm_params, 1, "hmm_params", "", ""),
    REAL(P, term.u.page.h, 1, "", "> 0"),
    ROW(P, term.u.shiryaev.hmm, 's', struct trk_hmm_params, 1, "hmm_params", "", ""),
    REAL(P, term.u.shiryaev.beta0, 1, "", "(0, 1)"),
    REAL(P, term.u.shiryaev.rho, 1, "", "[0, 1)"),
    REAL(P, term.u.shiryaev.h, 1, "", "finite"),
    REAL(P, term.u.existence.p_terminate, 1, "", "(0, 1), below p_confirm"),
    REAL(P, merge_gate_d2, 1, "", ">= 0 (0: never merge)"),
    REAL(P, init_exclusion_d2, 1, "", ">= 0"),
    REAL(P, stationary_d2, 1, "", ">= 0 (0: off)"),
    ROW(P, max_tentative_scans, 'u', uint32_t, 1, "", "scans", ">= 0 (0: no limit)"),
    ROW(P, max_unseen_scans, 'u', uint32_t, 1, "", "scans", ">= 0 (0: a track leaving the coverage ends; 65535+: never)"),
    ENUM(P, init.method, "INIT_SINGLE_POINT, INIT_TWO_POINT"),
    REAL(P, init.max_speed_mps, 1, "m/s", "> 0"),
    ROW(P, init.max_gap_scans, 'u', uint32_t, 1, "", "scans", "1 .. TRK_MAX_CANDIDATE_SCANS - 1"),
    REAL(P, init.birth_density_per_m2, 1, "1/m^2 per scan", ">= 0 (0: visibility.pv0)"),
    REAL(P, init.min_existence, 1, "", "[0, 1) (0: every pair starts)"),
    ROW(P, clutter_map.n_range, 'u', unsigned, 1, "", "cells", "0 (no map) or n_range x n_bearing <= TRK_CLUTTER_MAP_CELLS"),
    ROW(P, clutter_map.n_bearing, 'u', unsigned, 1, "", "cells", "0 (no map) or n_range x n_bearing <= TRK_CLUTTER_MAP_CELLS"),
    REAL(P, clutter_map.time_constant_scans, 1, "scans", ">= 1"),
    REAL(P, clutter_map.prior_count, 1, "detections", "> 0"),
    REAL(P, clutter_map.min_ratio, 1, "", "(0, 1]"),
    REAL(P, clutter_map.max_ratio, 1, "", ">= 1"),
    ROW(P, clutter_map.window_cells, 'u', unsigned, 1, "", "cells", "0 .. TRK_CLUTTER_MAP_WINDOW_MAX (8)"),
    ROW(P, clutter_map.guard_cells, 'u', unsigned, 1, "", "cells", "0 .. window_cells + 1"),
    REAL(P, clutter_map.edge_alpha, 1, "", "0 (off) or [TRK_REAL_MIN, 1)"),
    REAL(P, max_pos_sigma_ratio, 1, "", ">= 0 (0: no bound)"),
    REAL(P, max_coord_m, 1, "m", "(0, 1e15]"),
    ENUM(P, association, "ASSOC_PDA, ASSOC_JOINT (TRK_WITH_JOINT)"),
    ENUM(P, filter, "FILTER_KALMAN, FILTER_ALPHA_BETA (TRK_WITH_ALPHA_BETA)"),
#if TRK_WITH_IMM
    ROW(P, imm, 's', struct trk_imm_params, 1, "imm_params", "", "n_models 0: CV only"),
#endif
};
#undef P

#define S struct trk_sensor_params
static const struct layout_row sensor_rows[] = {
    REAL(S, pd, 1, "", "(0, 1]"),
    REAL(S, meas_cov_m2, 3, "m^2", "[xx, xy, yy], SPD"),
    REAL(S, clutter_density_per_m2, 1, "1/m^2", ">= 0"),
    ROW(S, use_amplitude, 'i', int, 1, "", "", "0, 1 (1: amplitude set by a model)"),
    ROW(S, amplitude, 's', struct trk_amplitude, 1, "amplitude", "", "set by the amplitude functions"),
    ENUM(S, kind, "SENSOR_CARTESIAN, SENSOR_POLAR"),
    REAL(S, sigma_range_m, 1, "m", "polar: > 0"),
    REAL(S, sigma_bearing_rad, 1, "rad", "polar: (0, 0.5]"),
    ENUM(S, conversion, "POLAR_FIRST_ORDER, POLAR_UNBIASED"),
    ROW(S, pose, 's', struct trk_pose, 1, "pose", "", "the pose of a scan without its own"),
    ROW(S, pd_profile, 's', struct trk_pd_profile, 1, "pd_profile", "", "n 0: pd everywhere"),
    ROW(S, coverage, 's', struct trk_coverage, 1, "coverage", "", "all 0: everywhere"),
    ROW(S, clutter_profile, 's', struct trk_clutter_profile, 1, "clutter_profile", "", "n 0: clutter_density_per_m2 everywhere"),
    REAL(S, persistent_share, 1, "", "[0, 1); > 0 needs a Rayleigh amplitude model"),
    REAL(S, persistent_pd, 1, "", "(pfa, 1) when persistent_share > 0"),
};
#undef S

#define O struct trk_pose
static const struct layout_row pose_rows[] = {
    REAL(O, x_m, 1, "m", "finite, in the surveillance bound"),
    REAL(O, y_m, 1, "m", "finite, in the surveillance bound"),
    REAL(O, heading_rad, 1, "rad", "clockwise from +y, |h| <= 1e6"),
};
#undef O

#define F struct trk_pd_profile
static const struct layout_row pd_profile_rows[] = {
    ROW(F, n, 'u', unsigned, 1, "", "", "0, 2 .. TRK_PD_PROFILE_MAX"),
    REAL(F, range_m, TRK_PD_PROFILE_MAX, "m", "increasing, >= 0"),
    REAL(F, pd, TRK_PD_PROFILE_MAX, "", "[0, 1]"),
};
#undef F

#define L struct trk_clutter_profile
static const struct layout_row clutter_profile_rows[] = {
    ROW(L, n, 'u', unsigned, 1, "", "", "0, 2 .. TRK_PD_PROFILE_MAX"),
    REAL(L, range_m, TRK_PD_PROFILE_MAX, "m", "increasing, >= 0"),
    REAL(L, density_per_m2, TRK_PD_PROFILE_MAX, "1/m^2", "(0, 1e6]"),
};
#undef L

#define V struct trk_coverage
static const struct layout_row coverage_rows[] = {
    REAL(V, min_range_m, 1, "m", ">= 0"),
    REAL(V, max_range_m, 1, "m", "0: none, else > min_range_m"),
    REAL(V, half_width_rad, 1, "rad", "[0, pi]; 0 or pi: all round"),
};
#undef V

#define Q struct trk_polar_detection
static const struct layout_row polar_detection_rows[] = {
    REAL(Q, range_m, 1, "m", "> 0"),
    REAL(Q, bearing_rad, 1, "rad", "clockwise from the pose's heading"),
    REAL(Q, amplitude, 1, "amplitude", ">= 0, used when has_amplitude"),
    ROW(Q, has_amplitude, 'u', uint8_t, 1, "", "", "0, 1"),
};
#undef Q

#define A struct trk_amplitude
static const struct layout_row amplitude_rows[] = {
    ROW(A, model, 'i', int, 1, "", "", "AMP_RAYLEIGH, AMP_K"),
    ROW(A, tabulated, 'i', int, 1, "", "", "0, 1"),
    REAL(A, clutter_power, 1, "amplitude^2", ""),
    REAL(A, snr_db, 1, "dB", ""),
    REAL(A, pfa, 1, "", ""),
    REAL(A, nu, 1, "", ""),
    REAL(A, threshold, 1, "amplitude", ""),
    REAL(A, pd, 1, "", ""),
};
#undef A

#define H struct trk_hmm_params
static const struct layout_row hmm_rows[] = {
    ROW(H, n_sensors, 'u', unsigned, 1, "", "", "1 .. TRK_MAX_SENSORS"),
    ROW(H, sensor, 's', struct trk_hmm_sensor_params, TRK_MAX_SENSORS, "hmm_sensor_params", "", ""),
    ENUM(H, events, "EVENTS_COMPLETE, EVENTS_PAPER"),
};
#undef H

#define H struct trk_hmm_sensor_params
static const struct layout_row hmm_sensor_rows[] = {
    REAL(H, p_low_high, 1, "", "[0, 1]"),
    REAL(H, q_high_low, 1, "", "[0, 1]"),
    REAL(H, pd_low, 1, "", "(0, 1)"),
    REAL(H, pd_high, 1, "", "(0, 1)"),
    REAL(H, pi0_high, 1, "", "[0, 1] or HMM_PI0_STATIONARY"),
};
#undef H

#define I struct trk_imm_params
static const struct layout_row imm_rows[] = {
    ROW(I, n_models, 'i', int, 1, "", "", "0 .. TRK_MAX_MODELS"),
    REAL(I, omega_rad_s, TRK_MAX_MODELS, "rad/s", "|omega| <= 1, 0: CV"),
    REAL(I, q_m2_per_s3, TRK_MAX_MODELS, "m^2/s^3", ">= 0"),
    REAL(I, p_switch, TRK_MAX_MODELS * TRK_MAX_MODELS, "", "rows of n_models sum to 1"),
};
#undef I

#define D struct trk_detection
static const struct layout_row detection_rows[] = {
    REAL(D, x_m, 1, "m", "finite"),
    REAL(D, y_m, 1, "m", "finite"),
    REAL(D, cov_m2, 3, "m^2", "[xx, xy, yy], SPD, used when has_cov"),
    REAL(D, amplitude, 1, "amplitude", ">= 0, used when has_amplitude"),
    ROW(D, has_cov, 'u', uint8_t, 1, "", "", "0, 1"),
    ROW(D, has_amplitude, 'u', uint8_t, 1, "", "", "0, 1"),
};
#undef D

#define C struct trk_scan
static const struct layout_row scan_rows[] = {
    ROW(C, time_us, 'i', int64_t, 1, "", "us", "|t| <= 2^62 - 1, never decreasing"),
    ROW(C, sensor_id, 'u', unsigned, 1, "", "", "0 .. n_sensors - 1"),
    ROW(C, n_detections, 'u', size_t, 1, "", "", "<= TRK_MAX_SCAN_DETECTIONS (beyond TRK_MAX_DETECTIONS: thinned)"),
    ROW(C, detections, 'p', const struct trk_detection *, 1, "", "", ""),
    ROW(C, polar, 'p', const struct trk_polar_detection *, 1, "", "", "a polar sensor's; detections then NULL"),
    ROW(C, has_pose, 'i', int, 1, "", "", "0, 1"),
    ROW(C, pose, 's', struct trk_pose, 1, "pose", "", "used when has_pose"),
    ROW(C, clutter_density_per_m2, 'p', const trk_real *, 1, "", "1/m^2",
        "NULL, or n_detections of them, each finite and > 0"),
};
#undef C

#define R(M) ROW(struct trk_scan_report, M, 'u', uint32_t, 1, "", "", "")
static const struct layout_row report_rows[] = {
    R(n_detections), R(n_rejected_nonfinite), R(n_rejected_cov), R(n_rejected_amplitude),
    R(n_rejected_region), R(n_below_threshold), R(n_rejected_density), R(n_kept), R(n_thinned), R(n_tracks_updated), R(n_tracks_hit), R(n_started), R(n_confirmed), R(n_stationary),
    R(n_terminated), R(n_init_refused_full), R(n_init_deferred), R(n_numerical), R(n_merged), R(n_replaced),
    R(n_covariance), R(n_candidates), R(n_candidates_dropped), R(n_clusters), R(n_clusters_approx),
    R(largest_cluster), R(n_assoc_overflow),
    ROW(struct trk_scan_report, thin_in_gates, 'u', uint32_t, 1, "", "", "0, 1"),
    REAL(struct trk_scan_report, thin_threshold, 1, "", ">= 0 (0: thinned without amplitudes)"),
    REAL(struct trk_scan_report, thin_pd, 1, "", "[0, 1]"),
    REAL(struct trk_scan_report, thin_clutter_density, 1, "1/m^2", ">= 0"),
    REAL(struct trk_scan_report, persistent_share, 1, "", "[0, 1)"),
};
#undef R

#define T struct trk_track
static const struct layout_row track_rows[] = {
    ROW(T, id, 'u', uint32_t, 1, "", "", "> 0"),
    ROW(T, status, 'u', uint8_t, 1, "", "", "TRACK_FREE, TRACK_TENTATIVE, TRACK_CONFIRMED, TRACK_TERMINATED"),
    ROW(T, end_reason, 'u', uint8_t, 1, "", "", "END_*"),
    ROW(T, stationary, 'u', uint8_t, 1, "", "", "1: tentative, held (standing still, or waiting with a scatterer's echoes)"),
    ROW(T, time_us, 'i', int64_t, 1, "", "us", ""),
    REAL(T, x, TRK_CV2_NX, "m, m/s", "[x, vx, y, vy]"),
    REAL(T, p, TRK_CV2_NX * TRK_CV2_NX, "m^2, m^2/s, m^2/s^2", "4 x 4 row-major"),
    ROW(T, n_scans, 'u', uint32_t, 1, "", "scans", ""),
    ROW(T, n_hits, 'u', uint32_t, 1, "", "scans", ""),
    ROW(T, n_misses_in_row, 'u', uint32_t, 1, "", "scans", ""),
    ROW(T, n_gated_last, 'u', uint16_t, 1, "", "", ""),
    REAL(T, beta0_last, 1, "", "[0, 1]"),
    REAL(T, existence0, 1, "", "[0, 1]"),
    REAL(T, vis.pv_pred, 1, "", "[0, 1]"),
    REAL(T, vis.pv, 1, "", "[0, 1]"),
    REAL(T, vis.pcv, 1, "", "[0, 1]"),
    REAL(T, confirm_stat, 1, "", ""),
    REAL(T, term_stat, 1, "", ""),
#if TRK_WITH_IMM
    REAL(T, maneuver_d2, 1, "", ">= 0"),
    REAL(T, imm.mu, TRK_MAX_MODELS, "", "[0, 1]"),
    REAL(T, imm.x, TRK_MAX_MODELS * TRK_IMM_NX, "m, m/s", "per model [x, vx, y, vy]"),
#endif
};
#undef T

static const struct layout_row tracker_rows[] = {
    ROW(struct trk_tracker, track, 's', struct trk_track, TRK_MAX_TRACKS, "track", "", "slots"),
    ROW(struct trk_tracker, n_live, 'u', uint32_t, 1, "", "", ""),
    ROW(struct trk_tracker, next_id, 'u', uint32_t, 1, "", "", ""),
    ROW(struct trk_tracker, scan_no, 'u', uint32_t, 1, "", "", ""),
};

#define N(a) (sizeof a / sizeof a[0])
static const struct layout_struct structs[] = {
    {"tracker_params", sizeof(struct trk_tracker_params), params_rows, N(params_rows)},
    {"sensor_params", sizeof(struct trk_sensor_params), sensor_rows, N(sensor_rows)},
    {"amplitude", sizeof(struct trk_amplitude), amplitude_rows, N(amplitude_rows)},
    {"hmm_params", sizeof(struct trk_hmm_params), hmm_rows, N(hmm_rows)},
    {"hmm_sensor_params", sizeof(struct trk_hmm_sensor_params), hmm_sensor_rows, N(hmm_sensor_rows)},
    {"imm_params", sizeof(struct trk_imm_params), imm_rows, N(imm_rows)},
    {"pose", sizeof(struct trk_pose), pose_rows, N(pose_rows)},
    {"pd_profile", sizeof(struct trk_pd_profile), pd_profile_rows, N(pd_profile_rows)},
    {"coverage", sizeof(struct trk_coverage), coverage_rows, N(coverage_rows)},
    {"clutter_profile", sizeof(struct trk_clutter_profile), clutter_profile_rows, N(clutter_profile_rows)},
    {"polar_detection", sizeof(struct trk_polar_detection), polar_detection_rows, N(polar_detection_rows)},
    {"detection", sizeof(struct trk_detection), detection_rows, N(detection_rows)},
    {"scan", sizeof(struct trk_scan), scan_rows, N(scan_rows)},
    {"scan_report", sizeof(struct trk_scan_report), report_rows, N(report_rows)},
    {"track", sizeof(struct trk_track), track_rows, N(track_rows)},
    {"tracker", sizeof(struct trk_tracker), tracker_rows, N(tracker_rows)},
    {"table", sizeof(struct trk_table), NULL, 0},
};

size_t trk_layout_n_structs(void) { return N(structs); }

trk_status trk_layout_struct(size_t i, const char **name, size_t *size, size_t *n_fields)
{
    if (i >= N(structs)) return TRK_E_RANGE;
    if (name) *name = structs[i].name;
    if (size) *size = structs[i].size;
    if (n_fields) *n_fields = structs[i].n;
    return TRK_OK;
}

trk_status trk_layout_field(size_t i, size_t j, const char **name, char *kind, size_t *size, size_t *offset,
                            size_t *count, const char **sub, const char **unit, const char **range)
{
    if (i >= N(structs) || j >= structs[i].n) return TRK_E_RANGE;
    const struct layout_row *r = &structs[i].row[j];
    if (name) *name = r->name;
    if (kind) *kind = r->kind;
    if (size) *size = r->size;
    if (offset) *offset = r->offset;
    if (count) *count = r->count;
    if (sub) *sub = r->sub;
    if (unit) *unit = r->unit;
    if (range) *range = r->range;
    return TRK_OK;
}

struct layout_const {
    const char *name;
    long value;
};
#define K(c) {#c, (long)(c)}
static const struct layout_const constants[] = {
    K(TRK_MAX_TRACKS), K(TRK_MAX_DETECTIONS), K(TRK_MAX_CANDIDATES), K(TRK_MAX_CANDIDATE_SCANS),
    K(TRK_MAX_SENSORS), K(TRK_MAX_STATE), K(TRK_MAX_MEAS), K(TRK_CLUTTER_KMAX), K(TRK_MAX_MODELS),
    K(TRK_WITH_CLUTTER_TESTS), K(TRK_WITH_JOINT), K(TRK_WITH_IMM), K(TRK_REAL_IS_FLOAT),
    K(TRK_MN_MAX_N), K(TRK_KN_MAX_N), K(TRK_TABLE_ALIGN), K(TRK_CV2_NX), K(TRK_STATUS_COUNT),
    K(TRK_OK), K(TRK_E_ABI), K(TRK_HMM_PI0_STATIONARY),
    K(TRK_CLUTTER_PARAMETRIC), K(TRK_CLUTTER_NONPARAMETRIC),
    K(TRK_CONFIRM_MN), K(TRK_CONFIRM_SPRT), K(TRK_CONFIRM_CLUTTER_CHI2), K(TRK_CONFIRM_CLUTTER_AMP),
    K(TRK_CONFIRM_VISIBILITY), K(TRK_CONFIRM_EXISTENCE),
    K(TRK_TERM_KN), K(TRK_TERM_PAGE), K(TRK_TERM_SHIRYAEV), K(TRK_TERM_VISIBILITY), K(TRK_TERM_EXISTENCE),
    K(TRK_INIT_SINGLE_POINT), K(TRK_INIT_TWO_POINT), K(TRK_ASSOC_PDA), K(TRK_ASSOC_JOINT),
    K(TRK_FILTER_KALMAN), K(TRK_FILTER_ALPHA_BETA), K(TRK_SENSOR_CARTESIAN), K(TRK_SENSOR_POLAR),
    K(TRK_POLAR_FIRST_ORDER), K(TRK_POLAR_UNBIASED), K(TRK_PD_PROFILE_MAX), K(TRK_CLUTTER_MAP_CELLS),
    K(TRK_MAX_SCAN_DETECTIONS),
    K(TRK_MN_FIXED), K(TRK_MN_SLIDING), K(TRK_SPRT_FIXED_PD), K(TRK_SPRT_HMM),
    K(TRK_EVENTS_COMPLETE), K(TRK_EVENTS_PAPER), K(TRK_AMP_RAYLEIGH), K(TRK_AMP_K),
    K(TRK_TRACK_FREE), K(TRK_TRACK_TENTATIVE), K(TRK_TRACK_CONFIRMED), K(TRK_TRACK_TERMINATED),
    K(TRK_END_NONE), K(TRK_END_REJECTED), K(TRK_END_TENTATIVE_AGE), K(TRK_END_TERMINATED),
    K(TRK_END_NUMERICAL), K(TRK_END_MERGED), K(TRK_END_COVARIANCE),
};

size_t trk_layout_n_constants(void) { return N(constants); }

trk_status trk_layout_constant(size_t i, const char **name, long *value)
{
    if (i >= N(constants)) return TRK_E_RANGE;
    if (name) *name = constants[i].name;
    if (value) *value = constants[i].value;
    return TRK_OK;
}
