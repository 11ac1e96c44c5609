/* bridge.c - the transport-free core of trk-lcm-bridge (bridge.h). */
#include "bridge.h"

#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "kvfile.h"
#include "suggest.h"

void bridge_opts_defaults(struct bridge_opts *o)
{
    memset(o, 0, sizeof *o);
    strcpy(o->detection_channel, BRIDGE_DEFAULT_DETECTIONS);
    strcpy(o->polar_detection_channel, BRIDGE_DEFAULT_POLAR_DETECTIONS);
    strcpy(o->track_channel, BRIDGE_DEFAULT_TRACKS);
    strcpy(o->status_channel, BRIDGE_DEFAULT_STATUS);
    o->status_period_s = 1;
    o->log_interval_s = 10;
    o->quiet = 0;
    o->log = stderr;
}

static int set_channel(char *dst, const char *v, int allow_empty, char *err, size_t n)
{
    if (strlen(v) >= BRIDGE_CHANNEL_MAX || (!allow_empty && !*v)) {
        snprintf(err, n, "channel name must be 1 .. %d characters", BRIDGE_CHANNEL_MAX - 1);
        return -1;
    }
    strcpy(dst, v);
    return 0;
}

/* The keys bridge_opts_set knows, for the suggestion after a misspelled one. */
static const char *const BRIDGE_KEYS[] = {"lcm_url",         "detection_channel", "polar_detection_channel",
                                          "track_channel",   "status_channel",    "status_period_s",
                                          "log_interval_s",  NULL};

int bridge_opts_set(void *ctx, const char *key, const char *v, char *err, size_t n)
{
    struct bridge_opts *o = ctx;
    double d;
    if (strcmp(key, "lcm_url") == 0) {
        if (strlen(v) >= sizeof o->lcm_url) {
            snprintf(err, n, "URL too long");
            return -1;
        }
        strcpy(o->lcm_url, v);
        return 0;
    }
    if (strcmp(key, "detection_channel") == 0) return set_channel(o->detection_channel, v, 0, err, n);
    if (strcmp(key, "polar_detection_channel") == 0) return set_channel(o->polar_detection_channel, v, 1, err, n);
    if (strcmp(key, "track_channel") == 0) return set_channel(o->track_channel, v, 0, err, n);
    if (strcmp(key, "status_channel") == 0) return set_channel(o->status_channel, v, 1, err, n);
    if (strcmp(key, "status_period_s") == 0 || strcmp(key, "log_interval_s") == 0) {
        if (kv_parse_double(v, &d) != 0 || d < 0 || d > 1e6) {
            snprintf(err, n, "must be a number of seconds in [0, 1e6]");
            return -1;
        }
        if (key[0] == 's') o->status_period_s = d;
        else o->log_interval_s = d;
        return 0;
    }
    const char *near = cli_suggest(key, BRIDGE_KEYS);
    snprintf(err, n, "%s", near ? near : "");
    return 1;
}

void bridge_opts_write(FILE *f, const struct bridge_opts *o)
{
    fprintf(f, "# bridge\n");
    if (o->lcm_url[0]) fprintf(f, "lcm_url = %s\n", o->lcm_url);
    fprintf(f, "detection_channel = %s\n", o->detection_channel);
    fprintf(f, "polar_detection_channel = %s\n", o->polar_detection_channel);
    fprintf(f, "track_channel = %s\n", o->track_channel);
    fprintf(f, "status_channel = %s\n", o->status_channel);
    fprintf(f, "status_period_s = %g\n", o->status_period_s);
    fprintf(f, "log_interval_s = %g\n", o->log_interval_s);
}

struct bridge *bridge_new(const struct tcfg *cfg, const struct bridge_opts *o, char *err, size_t n)
{
    if (tcfg_check(cfg, err, n) != 0) return NULL;
    if (strcmp(o->polar_detection_channel, o->detection_channel) == 0) { /* one type per channel */
        snprintf(err, n, "polar_detection_channel must differ from detection_channel (%s)", o->detection_channel);
        return NULL;
    }
    struct bridge *b = calloc(1, sizeof *b);
    if (!b) {
        snprintf(err, n, "out of memory");
        return NULL;
    }
    b->o = *o;
    if (!b->o.log) b->o.log = stderr;
    b->cfg = *cfg;
    if (tcfg_load(cfg, &b->rt, err, n) != 0) { /* amplitude tables, kept for the run */
        free(b);
        return NULL;
    }
    struct trk_tracker_params p;
    tcfg_params_rt(cfg, &b->rt, &p);
    const char *field = NULL;
    trk_status st = trk_tracker_check_params(&p, &field); /* names the field it refuses */
    if (st == TRK_OK) st = trk_tracker_init(&b->tk, &p);
    if (st != TRK_OK) {
        snprintf(err, n, "the tracker refuses %s: %s", field ? field : "its parameters", ERRMSG_STATUS(st));
        tcfg_unload(&b->rt);
        free(b);
        return NULL;
    }
    b->last_accepted_seq = -1;
    b->last_accepted_utime = -1;
    b->out_cap = (size_t)trk_track_list_t_encoded_size(&b->out);
    b->status_cap = (size_t)trk_bridge_status_t_encoded_size(&b->status);
    b->out_buf = malloc(b->out_cap);
    b->status_buf = malloc(b->status_cap);
    if (!b->out_buf || !b->status_buf) {
        snprintf(err, n, "out of memory");
        bridge_free(b);
        return NULL;
    }
    return b;
}

void bridge_free(struct bridge *b)
{
    if (!b) return;
    tcfg_unload(&b->rt);
    free(b->out_buf);
    free(b->status_buf);
    free(b);
}

/* ------------------------------------------------------------------ logging */

static void log_event(struct bridge *b, int slot, int64_t now_us, const char *fmt_reason,
                      const char *detail, int64_t seq)
{
    if (b->o.quiet) return;
    const int64_t interval_us = (int64_t)(b->o.log_interval_s * 1e6);
    if (b->log_used[slot]) {
        const int64_t last = b->log_last_us[slot];
        if (now_us < last) b->log_last_us[slot] = now_us; /* clock went back: restart */
        if (now_us < last || (uint64_t)now_us - (uint64_t)last < (uint64_t)interval_us) {
            b->log_suppressed[slot]++;
            return;
        }
    }
    fprintf(b->o.log, "trk-lcm-bridge: %s", fmt_reason);
    if (detail && *detail) fprintf(b->o.log, " (%s)", detail);
    if (seq >= 0) fprintf(b->o.log, " [seq %lld]", (long long)seq);
    if (b->log_suppressed[slot])
        fprintf(b->o.log, "; %llu more since the last message",
                (unsigned long long)b->log_suppressed[slot]);
    fputc('\n', b->o.log);
    fflush(b->o.log);
    b->log_used[slot] = 1;
    b->log_last_us[slot] = now_us;
    b->log_suppressed[slot] = 0;
}

void bridge_log_publish_error(struct bridge *b, int64_t now_us, const char *what)
{
    b->c.publish_errors++;
    log_event(b, BRIDGE_LOG_PUBLISH, now_us, "cannot send", what, -1);
}

void bridge_log_flush(struct bridge *b)
{
    if (b->o.quiet) return;
    for (int s = 0; s < BRIDGE_LOG_SLOTS; s++) {
        if (!b->log_suppressed[s]) continue;
        fprintf(b->o.log, "trk-lcm-bridge: %llu more '%s' %s not shown\n",
                (unsigned long long)b->log_suppressed[s],
                s < LCMC_N_REASONS         ? lcmc_reason_name((enum lcmc_reason)s)
                : s == BRIDGE_LOG_PUBLISH ? "send"
                                          : "dropped detection",
                s < LCMC_N_REASONS ? "rejections" : s == BRIDGE_LOG_PUBLISH ? "errors" : "messages");
        b->log_suppressed[s] = 0;
    }
    fflush(b->o.log);
}

/* ------------------------------------------------------------------ one message */

static enum lcmc_reason reject(struct bridge *b, enum lcmc_reason r, int64_t now_us,
                               const char *detail, int64_t seq)
{
    char what[256];
    b->c.rejected++;
    b->c.by_reason[r]++;
    snprintf(what, sizeof what, "rejected scan: %s", lcmc_reason_text(r));
    log_event(b, (int)r, now_us, what, detail, seq);
    return r;
}

/* Sequence numbers of one sensor, +1 per scan: a forward step of up to
 * BRIDGE_SEQ_GAP_MAX + 1 counts the scans in between as lost; a repeat, a
 * step back or a larger step is one jump. The unsigned difference cannot
 * overflow on any int64 values. */
static void count_seq(struct bridge *b, unsigned s, int64_t seq)
{
    if (b->has_seq[s]) {
        const uint64_t step = (uint64_t)seq - (uint64_t)b->last_seq[s];
        if (seq > b->last_seq[s] && step - 1 <= BRIDGE_SEQ_GAP_MAX) b->c.seq_gaps += step - 1;
        else b->c.seq_jumps++;
    }
    b->last_seq[s] = seq;
    b->has_seq[s] = 1;
}

/* A copied scan (b->scan, either kind) through the tracker; detail holds
 * the copy's note on a dropped detection. */
static enum lcmc_reason process(struct bridge *b, char *detail, size_t detail_len, int64_t now_us,
                                const void **out, size_t *out_len)
{
    struct trk_scan_report rep;
    trk_status st = trk_tracker_process_scan(&b->tk, &b->scan.scan, &rep);
    if (st != TRK_OK) {
        snprintf(detail, detail_len, "%s: utime %lld, previous %lld", ERRMSG_STATUS(st),
                 (long long)b->scan.scan.time_us, (long long)b->last_accepted_utime);
        return reject(b, lcmc_reason_of_status(st), now_us, detail, b->scan.seq);
    }
    /* accepted */
    count_seq(b, b->scan.scan.sensor_id, b->scan.seq);
    b->last_accepted_seq = b->scan.seq;
    b->last_accepted_utime = b->scan.scan.time_us;
    b->last_report = rep;
    b->c.processed++;
    const uint32_t dropped = b->scan.n_dropped_nonfinite + b->scan.n_dropped_field;
    if (dropped) {
        char what[96];
        snprintf(what, sizeof what, "dropped %lu bad detection(s), processed the other %lu",
                 (unsigned long)dropped, (unsigned long)b->scan.scan.n_detections);
        log_event(b, BRIDGE_LOG_DETECTION, now_us, what, detail, b->scan.seq);
    }
    b->c.det_nonfinite += (uint64_t)b->scan.n_dropped_nonfinite + rep.n_rejected_nonfinite;
    b->c.det_field += (uint64_t)b->scan.n_dropped_field + rep.n_rejected_region; /* a position out of bounds */
    b->c.det_cov += rep.n_rejected_cov;
    b->c.det_amplitude += rep.n_rejected_amplitude;
    b->c.det_rejected += (uint64_t)dropped + rep.n_rejected_nonfinite + rep.n_rejected_cov +
                         rep.n_rejected_amplitude + rep.n_rejected_region + rep.n_rejected_density;
    b->c.det_below_threshold += rep.n_below_threshold;
    b->c.started += rep.n_started;
    b->c.confirmed += rep.n_confirmed;
    b->c.terminated += rep.n_terminated;
    b->c.refused_full += rep.n_init_refused_full;

    lcmc_tracks_to_msg(&b->tk, &b->scan.scan, b->scan.seq, &rep, &b->out);
    lcmc_count_dropped(&b->scan, &b->out);
    int n = trk_track_list_t_encode(b->out_buf, 0, (int)b->out_cap, &b->out);
    if (n < 0) { /* cannot happen: constant size */
        return reject(b, LCMC_OTHER, now_us, "track list encoding failed", b->scan.seq);
    }
    *out = b->out_buf;
    *out_len = (size_t)n;
    return LCMC_OK;
}

enum lcmc_reason bridge_handle(struct bridge *b, const void *data, size_t len, int64_t now_us,
                               const void **out, size_t *out_len)
{
    char detail[160];
    b->c.received++;
    const unsigned n_sensors = b->tk.params.n_sensors;
    enum lcmc_reason r =
        lcmc_scan_from_bytes(data, len, n_sensors, &b->in, &b->scan, detail, sizeof detail);
    if (r != LCMC_OK) return reject(b, r, now_us, detail, -1);
    return process(b, detail, sizeof detail, now_us, out, out_len);
}

enum lcmc_reason bridge_handle_polar(struct bridge *b, const void *data, size_t len, int64_t now_us,
                                     const void **out, size_t *out_len)
{
    char detail[160];
    b->c.received++;
    enum lcmc_reason r = lcmc_polar_scan_from_bytes(data, len, b->tk.params.sensor, b->tk.params.n_sensors,
                                                    &b->in_polar, &b->scan, detail, sizeof detail);
    if (r != LCMC_OK) return reject(b, r, now_us, detail, -1);
    return process(b, detail, sizeof detail, now_us, out, out_len);
}

static int64_t sat64(uint64_t v) { return v > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)v; }

void bridge_status(struct bridge *b, int64_t utime, const void **out, size_t *out_len)
{
    trk_bridge_status_t *m = &b->status;
    const struct bridge_counts *c = &b->c;
    memset(m, 0, sizeof *m);
    m->utime = utime;
    m->n_received = sat64(c->received);
    m->n_processed = sat64(c->processed);
    m->n_rejected = sat64(c->rejected);
    m->n_rejected_decode = sat64(c->by_reason[LCMC_DECODE]);
    m->n_rejected_count = sat64(c->by_reason[LCMC_COUNT]);
    m->n_rejected_capacity = sat64(c->by_reason[LCMC_CAPACITY]);
    m->n_rejected_field = sat64(c->by_reason[LCMC_FIELD]);
    m->n_rejected_sensor = sat64(c->by_reason[LCMC_SENSOR]);
    m->n_rejected_time = sat64(c->by_reason[LCMC_TIME]);
    m->n_rejected_gap = sat64(c->by_reason[LCMC_GAP]);
    m->n_rejected_other = sat64(c->by_reason[LCMC_OTHER]);
    m->n_seq_gaps = sat64(c->seq_gaps);
    m->n_seq_jumps = sat64(c->seq_jumps);
    m->n_detections_rejected = sat64(c->det_rejected);
    m->n_detections_nonfinite = sat64(c->det_nonfinite);
    m->n_detections_field = sat64(c->det_field);
    m->n_detections_covariance = sat64(c->det_cov);
    m->n_detections_amplitude = sat64(c->det_amplitude);
    m->n_detections_below_threshold = sat64(c->det_below_threshold);
    m->n_tracks_started = sat64(c->started);
    m->n_tracks_confirmed = sat64(c->confirmed);
    m->n_tracks_terminated = sat64(c->terminated);
    m->n_init_refused_full = sat64(c->refused_full);
    int32_t live = 0, conf = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *t = trk_tracker_track(&b->tk, i);
        if (!t) continue;
        live++;
        conf += t->status == TRK_TRACK_CONFIRMED;
    }
    m->n_live_tracks = live;
    m->n_confirmed_tracks = conf;
    m->last_seq = b->last_accepted_seq;
    m->last_scan_utime = b->last_accepted_utime;
    int n = trk_bridge_status_t_encode(b->status_buf, 0, (int)b->status_cap, m);
    *out = b->status_buf;
    *out_len = n > 0 ? (size_t)n : 0;
}

void bridge_summary(const struct bridge *b, FILE *f)
{
    const struct bridge_counts *c = &b->c;
    int live = 0, conf = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *t = trk_tracker_track(&b->tk, i);
        if (!t) continue;
        live++;
        conf += t->status == TRK_TRACK_CONFIRMED;
    }
    fprintf(f, "scans: received %llu, processed %llu, rejected %llu",
            (unsigned long long)c->received, (unsigned long long)c->processed,
            (unsigned long long)c->rejected);
    if (c->rejected) {
        const char *sep = " (";
        for (int r = 1; r < LCMC_N_REASONS; r++) {
            if (!c->by_reason[r]) continue;
            fprintf(f, "%s%s %llu", sep, lcmc_reason_name((enum lcmc_reason)r),
                    (unsigned long long)c->by_reason[r]);
            sep = ", ";
        }
        fputc(')', f);
    }
    fprintf(f, "; sequence gaps %llu, jumps %llu\n", (unsigned long long)c->seq_gaps,
            (unsigned long long)c->seq_jumps);
    fprintf(f,
            "detections: dropped %llu (nonfinite %llu, field %llu, covariance %llu, amplitude "
            "%llu), below the amplitude threshold %llu\n",
            (unsigned long long)c->det_rejected, (unsigned long long)c->det_nonfinite,
            (unsigned long long)c->det_field, (unsigned long long)c->det_cov,
            (unsigned long long)c->det_amplitude, (unsigned long long)c->det_below_threshold);
    fprintf(f,
            "tracks: started %llu, confirmed %llu, ended %llu, initiations refused (table full) "
            "%llu; now %d live, %d confirmed\n",
            (unsigned long long)c->started, (unsigned long long)c->confirmed,
            (unsigned long long)c->terminated, (unsigned long long)c->refused_full, live, conf);
    if (c->publish_errors)
        fprintf(f, "send errors: %llu\n", (unsigned long long)c->publish_errors);
}
