/* transport.c - live LCM loop and log replay of trk-lcm-bridge (transport.h). */
#define _POSIX_C_SOURCE 200809L
#include "transport.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <time.h>

#include "lcm_log.h"

int64_t bridge_mono_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

int64_t bridge_wall_us(void)
{
    struct timeval tv;
    gettimeofday(&tv, NULL);
    return (int64_t)tv.tv_sec * 1000000 + tv.tv_usec;
}

/* ------------------------------------------------------------------ live */

static void on_scan(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    struct bridge_live *l = user;
    const void *out;
    size_t out_len;
    const int64_t now = bridge_mono_us();
    (void)channel;
    if (bridge_handle(l->b, rbuf->data, rbuf->data_size, now, &out, &out_len) != LCMC_OK) return;
    if (lcm_publish(l->lc, l->b->o.track_channel, out, (unsigned)out_len) != 0)
        bridge_log_publish_error(l->b, now, l->b->o.track_channel);
}

static void on_polar_scan(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    struct bridge_live *l = user;
    const void *out;
    size_t out_len;
    const int64_t now = bridge_mono_us();
    (void)channel;
    if (bridge_handle_polar(l->b, rbuf->data, rbuf->data_size, now, &out, &out_len) != LCMC_OK) return;
    if (lcm_publish(l->lc, l->b->o.track_channel, out, (unsigned)out_len) != 0)
        bridge_log_publish_error(l->b, now, l->b->o.track_channel);
}

int bridge_live_attach(struct bridge_live *l, lcm_t *lc, struct bridge *b)
{
    memset(l, 0, sizeof *l);
    l->lc = lc;
    l->b = b;
    l->sub = lcm_subscribe(lc, b->o.detection_channel, on_scan, l);
    if (!l->sub) return -1;
    /* a burst of scans may queue up while one is processed (udpm) */
    lcm_subscription_set_queue_capacity(l->sub, 100);
    if (b->o.polar_detection_channel[0]) {
        l->sub_polar = lcm_subscribe(lc, b->o.polar_detection_channel, on_polar_scan, l);
        if (!l->sub_polar) {
            bridge_live_detach(l);
            return -1;
        }
        lcm_subscription_set_queue_capacity(l->sub_polar, 100);
    }
    l->next_status_us = bridge_mono_us() + (int64_t)(b->o.status_period_s * 1e6);
    return 0;
}

void bridge_live_detach(struct bridge_live *l)
{
    if (l->sub) lcm_unsubscribe(l->lc, l->sub);
    if (l->sub_polar) lcm_unsubscribe(l->lc, l->sub_polar);
    l->sub = l->sub_polar = NULL;
}

void bridge_live_publish_status(struct bridge_live *l)
{
    const void *buf;
    size_t len;
    if (!l->b->o.status_channel[0]) return;
    bridge_status(l->b, bridge_wall_us(), &buf, &len);
    if (lcm_publish(l->lc, l->b->o.status_channel, buf, (unsigned)len) != 0)
        bridge_log_publish_error(l->b, bridge_mono_us(), l->b->o.status_channel);
}

int bridge_live_run(struct bridge_live *l, volatile sig_atomic_t *stop, uint64_t max_scans,
                    double idle_exit_s)
{
    int rc = 0;
    int64_t last_activity = bridge_mono_us();
    const int64_t period_us = (int64_t)(l->b->o.status_period_s * 1e6);
    while (!(stop && *stop)) {
        if (max_scans && l->b->c.processed >= max_scans) break;
        int h = lcm_handle_timeout(l->lc, 100);
        const int64_t now = bridge_mono_us();
        if (h < 0) {
            if (stop && *stop) break; /* interrupted by the signal */
            if (errno == EINTR) continue;
            rc = -1;
            break;
        }
        if (h > 0) last_activity = now;
        else if (idle_exit_s > 0 && now - last_activity >= (int64_t)(idle_exit_s * 1e6)) break;
        if (period_us > 0 && now >= l->next_status_us) {
            bridge_live_publish_status(l);
            l->next_status_us = now + period_us;
        }
    }
    bridge_live_publish_status(l);
    bridge_log_flush(l->b);
    return rc;
}

/* ------------------------------------------------------------------ replay */

static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return 0;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* t + d (d >= 0) without overflow: log times may be anything up to INT64_MAX. */
static int64_t add_sat(int64_t t, int64_t d) { return t > INT64_MAX - d ? INT64_MAX : t + d; }

/* Largest message the replay reads into memory; larger ones (images, ...)
 * are skipped without being read. A detection scan is 12,832 bytes. */
#define REPLAY_MAX_DATA (1u << 20)

/* What the reader met in the input: corrupt records, skipped bytes, a cut end. */
static void input_stats(struct replay_stats *st, const struct lcmlog_reader *r)
{
    st->corrupt = r->n_corrupt;
    st->bytes_skipped = r->n_bytes_skipped;
    st->truncated = r->truncated;
}

int bridge_replay(struct bridge *b, const char *in, const char *out, int keep_input,
                  volatile sig_atomic_t *stop, struct replay_stats *st, char *err, size_t n)
{
    struct lcmlog_reader r;
    struct lcmlog_writer w;
    memset(st, 0, sizeof *st);
    if (same_file(in, out)) {
        snprintf(err, n, "--out %s is the input log", out);
        return -1;
    }
    if (lcmlog_open_read(&r, in, REPLAY_MAX_DATA) != 0) {
        snprintf(err, n, "%s: cannot open: %s", in, strerror(errno));
        return -1;
    }
    /* the first record before the output is created: an input that is no
     * log (a directory, an empty file: no record) leaves no output log */
    r.stop = stop;
    struct lcmlog_event ev;
    int k = stop && *stop ? 0 : lcmlog_read(&r, &ev);
    if ((k < 0 && r.error != LCMLOG_E_STOPPED) || (k == 0 && !(stop && *stop))) {
        if (k < 0) snprintf(err, n, "%s: %s", in, lcmlog_strerror(&r));
        else snprintf(err, n, "%s: not an LCM log (empty: no record)", in);
        input_stats(st, &r);
        lcmlog_close_read(&r);
        return -1;
    }
    if (lcmlog_open_write(&w, out) != 0) {
        snprintf(err, n, "%s: cannot create: %s", out, strerror(errno));
        lcmlog_close_read(&r);
        return -1;
    }
    const struct bridge_opts *o = &b->o;
    const int64_t period_us = (int64_t)(o->status_period_s * 1e6);
    int have_next = 0, rc = 0;
    int64_t next_status = 0, last_ts = 0;
    for (; k > 0 && !(stop && *stop); k = stop && *stop ? 0 : lcmlog_read(&r, &ev)) {
        st->events++;
        last_ts = ev.timestamp;
        if (keep_input && ev.data) {
            if (lcmlog_write_channel(&w, ev.timestamp, ev.channel, ev.channellen, ev.data, ev.datalen) != 0)
                break;
            st->written++;
        }
        const int polar = o->polar_detection_channel[0] && lcmlog_channel_is(&ev, o->polar_detection_channel);
        if (polar || lcmlog_channel_is(&ev, o->detection_channel)) {
            const void *buf;
            size_t len;
            st->scans++;
            st->oversize += ev.oversize != 0;
            if ((polar ? bridge_handle_polar : bridge_handle)(b, ev.data, ev.datalen, ev.timestamp, &buf, &len) ==
                LCMC_OK) {
                if (lcmlog_write(&w, ev.timestamp, o->track_channel, buf, len) != 0) break;
                st->written++;
            }
        }
        if (o->status_channel[0] && period_us > 0) {
            if (!have_next) {
                next_status = add_sat(ev.timestamp, period_us);
                have_next = 1;
            } else if (ev.timestamp >= next_status) {
                const void *buf;
                size_t len;
                bridge_status(b, ev.timestamp, &buf, &len);
                if (lcmlog_write(&w, ev.timestamp, o->status_channel, buf, len) != 0) break;
                st->written++;
                next_status = add_sat(ev.timestamp, period_us);
            }
        }
    }
    if (k < 0 && r.error != LCMLOG_E_STOPPED) { /* a stop is an interruption, not a failure */
        snprintf(err, n, "%s: %s", in, lcmlog_strerror(&r));
        rc = -1;
    }
    if (o->status_channel[0] && !w.error) {
        const void *buf;
        size_t len;
        bridge_status(b, last_ts, &buf, &len);
        if (lcmlog_write(&w, last_ts, o->status_channel, buf, len) == 0) st->written++;
    }
    input_stats(st, &r);
    lcmlog_close_read(&r);
    if (lcmlog_close_write(&w) != 0 && rc == 0) {
        snprintf(err, n, "%s: write error: %s", out, strerror(errno));
        rc = -1;
    }
    bridge_log_flush(b);
    return rc;
}
