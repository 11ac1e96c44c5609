/* lcm_copy.c - LCM messages <-> the library's fixed structs (lcm_copy.h). */
#include "lcm_copy.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The wire format is fixed by the .lcm files; keep the C side in step. */
typedef char lcmc_check_max_det[TRK_DETECTION_SCAN_T_MAX_DETECTIONS == 256 ? 1 : -1];
typedef char lcmc_check_max_tracks[TRK_TRACK_LIST_T_MAX_TRACKS == 64 ? 1 : -1];
typedef char lcmc_check_max_polar[TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS == 256 ? 1 : -1];

static const char *const REASON_NAME[LCMC_N_REASONS] = {
    "ok", "decode", "count", "capacity", "nonfinite", "field", "sensor", "time", "gap", "other"};

static const char *const REASON_TEXT[LCMC_N_REASONS] = {
    "accepted",
    "message does not decode as the channel's type (wrong type, truncated or trailing bytes)",
    "n_detections outside 0 .. MAX_DETECTIONS",
    "scan refused by the tracker for its size (beyond TRK_MAX_SCAN_DETECTIONS)",
    "a used field is NaN, infinite or beyond the tracker's real range",
    "invalid field (boolean not 0/1, negative amplitude or utime, bad pose, range or bearing)",
    "sensor_id is not a configured sensor (of the polar kind, for a polar scan)",
    "scan time before the previous accepted scan",
    "gap since the previous accepted scan longer than max_dt_s",
    "scan refused by the tracker",
};

const char *lcmc_reason_name(enum lcmc_reason r)
{
    return (unsigned)r < LCMC_N_REASONS ? REASON_NAME[r] : "unknown";
}

const char *lcmc_reason_text(enum lcmc_reason r)
{
    return (unsigned)r < LCMC_N_REASONS ? REASON_TEXT[r] : "unknown reason";
}

enum lcmc_reason lcmc_reason_of_status(trk_status st)
{
    switch (st) {
    case TRK_OK: return LCMC_OK;
    case TRK_E_TIME: return LCMC_TIME;
    case TRK_E_RANGE: return LCMC_GAP;
    case TRK_E_SENSOR: return LCMC_SENSOR;
    case TRK_E_CAPACITY: return LCMC_CAPACITY;
    default: return LCMC_OTHER;
    }
}

/* Finite and within trk_real's range (converting a larger double to float
 * would be undefined behaviour, C99 6.3.1.5). */
static int representable(double d) { return isfinite(d) && fabs(d) <= (double)TRK_REAL_MAX; }

#define DETAIL(...)                                                                  \
    do {                                                                             \
        if (detail && detail_len) snprintf(detail, detail_len, __VA_ARGS__);         \
    } while (0)

/* One detection: LCMC_OK, LCMC_FIELD (a boolean not 0/1, a negative
 * amplitude) or LCMC_NONFINITE (a used field NaN, infinite or beyond
 * trk_real), with the reason in detail (may be NULL). */
static enum lcmc_reason check_detection(const trk_detection_t *d, size_t i, char *detail,
                                        size_t detail_len)
{
    if ((d->has_cov != 0 && d->has_cov != 1) || (d->has_amplitude != 0 && d->has_amplitude != 1)) {
        DETAIL("detections[%zu]: boolean has_cov = %d, has_amplitude = %d", i, d->has_cov,
               d->has_amplitude);
        return LCMC_FIELD;
    }
    if (!representable(d->x_m) || !representable(d->y_m)) {
        DETAIL("detections[%zu]: position (%g, %g)", i, d->x_m, d->y_m);
        return LCMC_NONFINITE;
    }
    for (int k = 0; d->has_cov && k < 3; k++)
        if (!representable(d->cov_m2[k])) {
            DETAIL("detections[%zu]: cov_m2[%d] = %g", i, k, d->cov_m2[k]);
            return LCMC_NONFINITE;
        }
    if (d->has_amplitude && !representable(d->amplitude)) {
        DETAIL("detections[%zu]: amplitude = %g", i, d->amplitude);
        return LCMC_NONFINITE;
    }
    if (d->has_amplitude && d->amplitude < 0) {
        DETAIL("detections[%zu]: amplitude = %g < 0", i, d->amplitude);
        return LCMC_FIELD;
    }
    return LCMC_OK;
}

enum lcmc_reason lcmc_scan_from_msg(const trk_detection_scan_t *m, unsigned n_sensors,
                                    struct lcmc_scan *out, char *detail, size_t detail_len)
{
    if (detail && detail_len) detail[0] = 0;
    if (m->n_detections < 0 || m->n_detections > TRK_DETECTION_SCAN_T_MAX_DETECTIONS) {
        DETAIL("n_detections = %ld", (long)m->n_detections);
        return LCMC_COUNT;
    }
    if (m->utime < 0 || m->utime > TRK_TIME_US_MAX) { /* the tracker's range, not a gap */
        DETAIL("utime = %lld, outside 0 .. 2^62 - 1", (long long)m->utime);
        return LCMC_FIELD;
    }
    if (m->sensor_id < 0 || (unsigned)m->sensor_id >= n_sensors) {
        DETAIL("sensor_id = %ld, configured 0 .. %u", (long)m->sensor_id, n_sensors - 1);
        return LCMC_SENSOR;
    }
    /* each detection alone: a bad one is dropped and counted, the rest copied
     * in order (every conversion is then exact or rounding only) */
    const size_t n = (size_t)m->n_detections;
    size_t kept = 0;
    out->n_dropped_nonfinite = out->n_dropped_field = 0;
    for (size_t i = 0; i < n; i++) {
        const trk_detection_t *d = &m->detections[i];
        const int first = out->n_dropped_nonfinite + out->n_dropped_field == 0;
        const enum lcmc_reason why = check_detection(d, i, first ? detail : NULL, detail_len);
        if (why == LCMC_NONFINITE) out->n_dropped_nonfinite++;
        if (why == LCMC_FIELD) out->n_dropped_field++;
        if (why != LCMC_OK) continue;
        struct trk_detection *o = &out->det[kept++];
        o->x_m = (trk_real)d->x_m;
        o->y_m = (trk_real)d->y_m;
        o->has_cov = (uint8_t)d->has_cov;
        o->has_amplitude = (uint8_t)d->has_amplitude;
        for (int k = 0; k < 3; k++) o->cov_m2[k] = d->has_cov ? (trk_real)d->cov_m2[k] : 0;
        o->amplitude = d->has_amplitude ? (trk_real)d->amplitude : 0;
    }
    out->n_msg_detections = n;
    trk_scan_init(&out->scan, m->utime, (unsigned)m->sensor_id, kept, out->det);
    out->seq = m->seq;
    return LCMC_OK;
}

enum lcmc_reason lcmc_scan_from_bytes(const void *buf, size_t len, unsigned n_sensors,
                                      trk_detection_scan_t *work, struct lcmc_scan *out,
                                      char *detail, size_t detail_len)
{
    if (detail && detail_len) detail[0] = 0;
    /* the type's wire size is constant: anything else cannot be one */
    if (!buf || len != LCMC_SCAN_WIRE_SIZE) {
        DETAIL("%zu bytes, a detection_scan_t has %d", len, LCMC_SCAN_WIRE_SIZE);
        return LCMC_DECODE;
    }
    int used = trk_detection_scan_t_decode(buf, 0, (int)len, work);
    if (used < 0) {
        DETAIL("wrong type hash");
        return LCMC_DECODE;
    }
    if ((size_t)used != len) {
        DETAIL("decoded %d of %zu bytes", used, len);
        return LCMC_DECODE;
    }
    return lcmc_scan_from_msg(work, n_sensors, out, detail, detail_len);
}

enum lcmc_reason lcmc_scan_to_msg(const struct trk_scan *s, int64_t seq, trk_detection_scan_t *m)
{
    if (s->n_detections > TRK_DETECTION_SCAN_T_MAX_DETECTIONS) return LCMC_COUNT;
    if (s->time_us < 0 || s->sensor_id > INT32_MAX) return LCMC_FIELD;
    memset(m, 0, sizeof *m);
    m->utime = s->time_us;
    m->sensor_id = (int32_t)s->sensor_id;
    m->seq = seq;
    m->n_detections = (int32_t)s->n_detections;
    for (size_t i = 0; i < s->n_detections; i++) {
        const struct trk_detection *d = &s->detections[i];
        trk_detection_t *o = &m->detections[i];
        o->x_m = (double)d->x_m;
        o->y_m = (double)d->y_m;
        o->has_cov = d->has_cov ? 1 : 0;
        if (d->has_cov)
            for (int k = 0; k < 3; k++) o->cov_m2[k] = (double)d->cov_m2[k];
        o->has_amplitude = d->has_amplitude ? 1 : 0;
        if (d->has_amplitude) o->amplitude = (double)d->amplitude;
    }
    return LCMC_OK;
}

/* ------------------------------------------------------------------ polar scans */

/* One polar detection, as check_detection: LCMC_FIELD for a boolean not
 * 0/1, a range <= 0, a bearing beyond a turn or a negative amplitude;
 * LCMC_NONFINITE for a used field NaN, infinite or beyond trk_real. */
static enum lcmc_reason check_polar(const trk_polar_detection_t *d, size_t i, char *detail, size_t detail_len)
{
    if (d->has_amplitude != 0 && d->has_amplitude != 1) {
        DETAIL("detections[%zu]: boolean has_amplitude = %d", i, d->has_amplitude);
        return LCMC_FIELD;
    }
    if (!representable(d->range_m) || !representable(d->bearing_rad)) {
        DETAIL("detections[%zu]: range %g m, bearing %g rad", i, d->range_m, d->bearing_rad);
        return LCMC_NONFINITE;
    }
    /* > 0 as the tracker's real: a float build rounds 1e-300 m to 0 */
    if (!((trk_real)d->range_m > 0) || fabs(d->bearing_rad) > LCMC_BEARING_MAX_RAD) {
        DETAIL("detections[%zu]: range %g m (> 0), bearing %g rad (|b| <= 2 pi)", i, d->range_m, d->bearing_rad);
        return LCMC_FIELD;
    }
    if (d->has_amplitude && !representable(d->amplitude)) {
        DETAIL("detections[%zu]: amplitude = %g", i, d->amplitude);
        return LCMC_NONFINITE;
    }
    if (d->has_amplitude && d->amplitude < 0) {
        DETAIL("detections[%zu]: amplitude = %g < 0", i, d->amplitude);
        return LCMC_FIELD;
    }
    return LCMC_OK;
}

enum lcmc_reason lcmc_polar_scan_from_msg(const trk_detection_scan_polar_t *m,
                                          const struct trk_sensor_params *sensors, unsigned n_sensors,
                                          struct lcmc_scan *out, char *detail, size_t detail_len)
{
    if (detail && detail_len) detail[0] = 0;
    if (m->n_detections < 0 || m->n_detections > TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS) {
        DETAIL("n_detections = %ld", (long)m->n_detections);
        return LCMC_COUNT;
    }
    if (m->utime < 0 || m->utime > TRK_TIME_US_MAX) {
        DETAIL("utime = %lld, outside 0 .. 2^62 - 1", (long long)m->utime);
        return LCMC_FIELD;
    }
    if (m->sensor_id < 0 || (unsigned)m->sensor_id >= n_sensors) {
        DETAIL("sensor_id = %ld, configured 0 .. %u", (long)m->sensor_id, n_sensors - 1);
        return LCMC_SENSOR;
    }
    if (sensors[m->sensor_id].kind != TRK_SENSOR_POLAR) {
        DETAIL("sensor_id = %ld is not a polar sensor (sensor.%ld.kind = cartesian)", (long)m->sensor_id,
               (long)m->sensor_id);
        return LCMC_SENSOR;
    }
    /* the pose places every detection: a bad one rejects the scan */
    if (m->has_pose != 0 && m->has_pose != 1) {
        DETAIL("boolean has_pose = %d", m->has_pose);
        return LCMC_FIELD;
    }
    if (m->has_pose && (!representable(m->pose_x_m) || !representable(m->pose_y_m) ||
                        !(fabs(m->pose_heading_rad) <= LCMC_HEADING_MAX_RAD))) {
        DETAIL("pose (%g m, %g m, heading %g rad)", m->pose_x_m, m->pose_y_m, m->pose_heading_rad);
        return LCMC_FIELD;
    }
    const size_t n = (size_t)m->n_detections;
    size_t kept = 0;
    out->n_dropped_nonfinite = out->n_dropped_field = 0;
    for (size_t i = 0; i < n; i++) {
        const trk_polar_detection_t *d = &m->detections[i];
        const int first = out->n_dropped_nonfinite + out->n_dropped_field == 0;
        const enum lcmc_reason why = check_polar(d, i, first ? detail : NULL, detail_len);
        if (why == LCMC_NONFINITE) out->n_dropped_nonfinite++;
        if (why == LCMC_FIELD) out->n_dropped_field++;
        if (why != LCMC_OK) continue;
        struct trk_polar_detection *o = &out->polar[kept++];
        o->range_m = (trk_real)d->range_m;
        o->bearing_rad = (trk_real)d->bearing_rad;
        o->has_amplitude = (uint8_t)d->has_amplitude;
        o->amplitude = d->has_amplitude ? (trk_real)d->amplitude : 0;
    }
    out->n_msg_detections = n;
    memset(&out->scan, 0, sizeof out->scan);
    out->scan.time_us = m->utime;
    out->scan.sensor_id = (unsigned)m->sensor_id;
    out->scan.n_detections = kept;
    out->scan.detections = NULL;
    out->scan.polar = out->polar;
    out->scan.has_pose = m->has_pose;
    if (m->has_pose) {
        out->scan.pose.x_m = (trk_real)m->pose_x_m;
        out->scan.pose.y_m = (trk_real)m->pose_y_m;
        out->scan.pose.heading_rad = (trk_real)m->pose_heading_rad;
    }
    out->seq = m->seq;
    return LCMC_OK;
}

enum lcmc_reason lcmc_polar_scan_from_bytes(const void *buf, size_t len, const struct trk_sensor_params *sensors,
                                            unsigned n_sensors, trk_detection_scan_polar_t *work,
                                            struct lcmc_scan *out, char *detail, size_t detail_len)
{
    if (detail && detail_len) detail[0] = 0;
    if (!buf || len != LCMC_POLAR_SCAN_WIRE_SIZE) {
        DETAIL("%zu bytes, a detection_scan_polar_t has %d", len, LCMC_POLAR_SCAN_WIRE_SIZE);
        return LCMC_DECODE;
    }
    int used = trk_detection_scan_polar_t_decode(buf, 0, (int)len, work);
    if (used < 0) {
        DETAIL("wrong type hash");
        return LCMC_DECODE;
    }
    if ((size_t)used != len) {
        DETAIL("decoded %d of %zu bytes", used, len);
        return LCMC_DECODE;
    }
    return lcmc_polar_scan_from_msg(work, sensors, n_sensors, out, detail, detail_len);
}

enum lcmc_reason lcmc_polar_scan_to_msg(const struct trk_scan *s, int64_t seq, trk_detection_scan_polar_t *m)
{
    if (s->n_detections > TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS) return LCMC_COUNT;
    if (s->time_us < 0 || s->sensor_id > INT32_MAX || (s->n_detections && !s->polar)) return LCMC_FIELD;
    memset(m, 0, sizeof *m);
    m->utime = s->time_us;
    m->sensor_id = (int32_t)s->sensor_id;
    m->seq = seq;
    m->has_pose = s->has_pose ? 1 : 0;
    if (s->has_pose) {
        m->pose_x_m = (double)s->pose.x_m;
        m->pose_y_m = (double)s->pose.y_m;
        m->pose_heading_rad = (double)s->pose.heading_rad;
    }
    m->n_detections = (int32_t)s->n_detections;
    for (size_t i = 0; i < s->n_detections; i++) {
        const struct trk_polar_detection *d = &s->polar[i];
        trk_polar_detection_t *o = &m->detections[i];
        o->range_m = (double)d->range_m;
        o->bearing_rad = (double)d->bearing_rad;
        o->has_amplitude = d->has_amplitude ? 1 : 0;
        if (d->has_amplitude) o->amplitude = (double)d->amplitude;
    }
    return LCMC_OK;
}

/* ------------------------------------------------------------------ tracks */

static int8_t confirm_code(const struct trk_tracker_params *p)
{
    switch (p->confirm.method) {
    case TRK_CONFIRM_MN: return TRK_TRACK_T_CONFIRM_MN;
    case TRK_CONFIRM_SPRT: return TRK_TRACK_T_CONFIRM_SPRT;
    case TRK_CONFIRM_CLUTTER_CHI2: return TRK_TRACK_T_CONFIRM_CLUTTER_DENSITY;
    case TRK_CONFIRM_CLUTTER_AMP: return TRK_TRACK_T_CONFIRM_CLUTTER_AMPLITUDE;
    case TRK_CONFIRM_VISIBILITY: return TRK_TRACK_T_CONFIRM_VISIBILITY;
    case TRK_CONFIRM_EXISTENCE: return TRK_TRACK_T_CONFIRM_EXISTENCE;
    }
    return 0;
}

static int8_t term_code(const struct trk_tracker_params *p)
{
    switch (p->term.method) {
    case TRK_TERM_KN: return TRK_TRACK_T_TERM_KN;
    case TRK_TERM_PAGE: return TRK_TRACK_T_TERM_PAGE;
    case TRK_TERM_SHIRYAEV: return TRK_TRACK_T_TERM_SHIRYAEV;
    case TRK_TERM_VISIBILITY: return TRK_TRACK_T_TERM_VISIBILITY;
    case TRK_TERM_EXISTENCE: return TRK_TRACK_T_TERM_EXISTENCE;
    }
    return 0;
}

static int32_t clamp32(uint32_t v) { return v > INT32_MAX ? INT32_MAX : (int32_t)v; }

void lcmc_count_dropped(const struct lcmc_scan *s, trk_track_list_t *m)
{
    const uint32_t dropped = s->n_dropped_nonfinite + s->n_dropped_field;
    m->n_detections = clamp32((uint32_t)s->n_msg_detections);
    m->n_detections_rejected = clamp32((uint32_t)m->n_detections_rejected + dropped);
}

void lcmc_track_to_msg(const struct trk_tracker *t, const struct trk_track *tr, trk_track_t *m)
{
    memset(m, 0, sizeof *m);
    m->id = (int64_t)tr->id;
    m->status = (int8_t)tr->status;
    m->end_reason = (int8_t)tr->end_reason;
    m->utime = tr->time_us;
    for (int i = 0; i < 4; i++) m->x[i] = (double)tr->x[i];
    for (int i = 0; i < 16; i++) m->p[i] = (double)tr->p[i];
    /* visibility p_v and its smoothed confidence p_cv (see track_t.lcm) */
    m->has_existence_prob = m->has_visibility_prob = t->params.track_visibility ? 1 : 0;
    m->visibility_prob = t->params.track_visibility ? (double)tr->vis.pv : 0;
    m->existence_prob = t->params.track_visibility ? (double)tr->vis.pcv : 0;
    m->confirm_method = confirm_code(&t->params);
    m->confirm_stat = (double)tr->confirm_stat;
    m->term_method = term_code(&t->params);
    m->term_stat = (double)tr->term_stat;
    m->n_updates = clamp32(tr->n_scans);
    m->n_hits = clamp32(tr->n_hits);
    m->n_misses_in_row = clamp32(tr->n_misses_in_row);
    m->n_gated_last = (int32_t)tr->n_gated_last;
    m->beta0_last = (double)tr->beta0_last;
}

/* Was (or is) the track confirmed? A terminated track ended as confirmed
 * unless it was rejected or aged out while tentative. */
static int is_confirmed(const struct trk_track *tr)
{
    if (tr->status == TRK_TRACK_CONFIRMED) return 1;
    return tr->status == TRK_TRACK_TERMINATED && tr->end_reason != TRK_END_REJECTED &&
           tr->end_reason != TRK_END_TENTATIVE_AGE && tr->end_reason != TRK_END_NONE;
}

void lcmc_tracks_to_msg(const struct trk_tracker *t, const struct trk_scan *scan, int64_t seq,
                        const struct trk_scan_report *rep, trk_track_list_t *m)
{
    memset(m, 0, sizeof *m);
    m->utime = scan->time_us;
    m->sensor_id = scan->sensor_id > INT32_MAX ? INT32_MAX : (int32_t)scan->sensor_id;
    m->seq = seq;
    if (rep) {
        m->n_detections = clamp32(rep->n_detections);
        m->n_detections_rejected =
            clamp32(rep->n_rejected_nonfinite + rep->n_rejected_cov + rep->n_rejected_amplitude +
                    rep->n_rejected_region + rep->n_rejected_density);
        m->n_started = clamp32(rep->n_started);
        m->n_confirmed = clamp32(rep->n_confirmed);
        m->n_terminated = clamp32(rep->n_terminated);
        m->n_init_refused_full = clamp32(rep->n_init_refused_full);
        m->n_below_threshold = clamp32(rep->n_below_threshold);
        m->n_merged = clamp32(rep->n_merged);
    }
    const size_t live = trk_tracker_live_count(t);
    const int all_fit = live <= TRK_TRACK_LIST_T_MAX_TRACKS;
    int32_t n = 0, omitted = 0;
    /* pass 0: everything (all fit) or the confirmed ones; pass 1: the rest */
    for (int pass = 0; pass < (all_fit ? 1 : 2); pass++) {
        for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *tr = trk_tracker_track(t, s);
            if (!tr) continue;
            if (!all_fit && is_confirmed(tr) != (pass == 0)) continue;
            if (n == TRK_TRACK_LIST_T_MAX_TRACKS) {
                omitted++;
                continue;
            }
            lcmc_track_to_msg(t, tr, &m->tracks[n++]);
        }
    }
    m->n_tracks = n;
    m->n_omitted = omitted;
}
