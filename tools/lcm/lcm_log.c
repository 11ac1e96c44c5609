/* lcm_log.c - LCM log files (lcm_log.h). */
#include "lcm_log.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

static uint32_t get32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static uint64_t get64(const uint8_t *p) { return (uint64_t)get32(p) << 32 | get32(p + 4); }

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

static void put64(uint8_t *p, uint64_t v)
{
    put32(p, (uint32_t)(v >> 32));
    put32(p + 4, (uint32_t)v);
}

/* two's complement without implementation-defined conversions */
static int64_t to_i64(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(~u) - 1;
}

static int32_t to_i32(uint32_t u)
{
    return u <= (uint32_t)INT32_MAX ? (int32_t)u : -(int32_t)(~u) - 1;
}

int lcmlog_open_stream(struct lcmlog_reader *r, FILE *f, size_t max_data)
{
    memset(r, 0, sizeof *r);
    r->f = f;
    if (!r->f) return -1;
    r->max_data = max_data;
    r->max_resync = LCMLOG_MAX_RESYNC;
    r->buf = malloc(max_data ? max_data : 1);
    if (!r->buf) {
        fclose(r->f);
        r->f = NULL;
        return -1;
    }
    return 0;
}

int lcmlog_open_read(struct lcmlog_reader *r, const char *path, size_t max_data)
{
    return lcmlog_open_stream(r, fopen(path, "rb"), max_data);
}

void lcmlog_close_read(struct lcmlog_reader *r)
{
    if (r->f) fclose(r->f);
    free(r->buf);
    r->f = NULL;
    r->buf = NULL;
}

const char *lcmlog_strerror(const struct lcmlog_reader *r)
{
    switch (r->error) {
    case LCMLOG_OK: return "no error";
    case LCMLOG_E_READ: return r->sys_errno ? strerror(r->sys_errno) : "read error";
    case LCMLOG_E_NO_SYNC: return "no LCM log record found within the resynchronisation bound";
    case LCMLOG_E_NOT_LOG: return "not an LCM log (no complete record)";
    case LCMLOG_E_STOPPED: return "stopped";
    }
    return "unknown error";
}

int lcmlog_channel_is(const struct lcmlog_event *ev, const char *name)
{
    const size_t n = strlen(name);
    return ev->channellen == n && memcmp(ev->channel, name, n) == 0;
}

static int fail(struct lcmlog_reader *r, enum lcmlog_error e)
{
    /* a read interrupted by the stop signal is a stop, not a failure */
    r->error = r->stop && *r->stop ? LCMLOG_E_STOPPED : e;
    r->sys_errno = e == LCMLOG_E_READ ? errno : 0;
    return -1;
}

/* End of file: 0, or -1 when a non-empty file held no complete record. */
static int at_end(struct lcmlog_reader *r)
{
    if (ferror(r->f)) return fail(r, LCMLOG_E_READ);
    if (r->n_events == 0 && r->nonempty) return fail(r, LCMLOG_E_NOT_LOG);
    return 0;
}

/* Find the next sync word: 1 found, 0 end of file, -1 (r->error). *gap
 * counts the bytes read since the last valid record (bounded by
 * max_resync); skipped bytes are counted in n_bytes_skipped. */
static int sync_stream(struct lcmlog_reader *r, uint64_t *gap)
{
    uint32_t w = 0;
    uint64_t n = 0;
    for (;;) {
        const int stop = r->stop && *r->stop;
        if (stop || *gap > r->max_resync) {
            r->n_bytes_skipped += n;
            return fail(r, stop ? LCMLOG_E_STOPPED : LCMLOG_E_NO_SYNC);
        }
        const int c = fgetc(r->f);
        if (c == EOF) {
            if (n > 0) r->n_bytes_skipped += n, r->truncated = 1;
            return 0;
        }
        r->nonempty = 1;
        w = w << 8 | (uint32_t)c;
        n++;
        ++*gap;
        if (n >= 4 && w == LCMLOG_SYNC) {
            r->n_bytes_skipped += n - 4;
            return 1;
        }
    }
}

/* Read exactly n bytes: 1, or 0 at the end of the file (truncated record). */
static int read_exact(struct lcmlog_reader *r, void *dst, size_t n)
{
    if (fread(dst, 1, n, r->f) == n) return 1;
    r->truncated = 1;
    return 0;
}

int lcmlog_read(struct lcmlog_reader *r, struct lcmlog_event *ev)
{
    uint64_t gap = 0;
    r->error = LCMLOG_OK;
    for (;;) {
        const int s = sync_stream(r, &gap);
        if (s <= 0) return s < 0 ? -1 : at_end(r);
        uint8_t h[24];
        if (!read_exact(r, h, sizeof h)) return at_end(r);
        const int32_t chlen = to_i32(get32(h + 16)), dlen = to_i32(get32(h + 20));
        if (chlen <= 0 || chlen > LCMLOG_MAX_CHANNEL || dlen < 0) {
            /* corrupt header: resynchronise just after this sync word */
            r->n_corrupt++;
            if (fseek(r->f, -24, SEEK_CUR) != 0) return fail(r, LCMLOG_E_READ);
            continue;
        }
        if (!read_exact(r, r->channel, (size_t)chlen)) return at_end(r);
        r->channel[chlen] = 0;
        ev->eventnum = to_i64(get64(h));
        ev->timestamp = to_i64(get64(h + 8));
        ev->channel = r->channel;
        ev->channellen = (size_t)chlen;
        ev->datalen = (size_t)dlen;
        ev->oversize = (size_t)dlen > r->max_data;
        if (ev->oversize) {
            ev->data = NULL;
            /* skip it; past the end means a truncated record */
            long pos = ftell(r->f);
            if (pos < 0 || fseek(r->f, 0, SEEK_END) != 0) return fail(r, LCMLOG_E_READ);
            long end = ftell(r->f);
            if (end < 0) return fail(r, LCMLOG_E_READ);
            if (end - pos < (long)dlen) {
                r->truncated = 1;
                return at_end(r);
            }
            if (fseek(r->f, pos + (long)dlen, SEEK_SET) != 0) return fail(r, LCMLOG_E_READ);
        } else {
            if (!read_exact(r, r->buf, (size_t)dlen)) return at_end(r);
            ev->data = r->buf;
        }
        r->n_events++;
        return 1;
    }
}

int lcmlog_open_write(struct lcmlog_writer *w, const char *path)
{
    w->eventnum = 0;
    w->error = 0;
    w->f = fopen(path, "wb");
    return w->f ? 0 : -1;
}

int lcmlog_write(struct lcmlog_writer *w, int64_t timestamp, const char *channel,
                 const void *data, size_t len)
{
    return lcmlog_write_channel(w, timestamp, channel, strlen(channel), data, len);
}

int lcmlog_write_channel(struct lcmlog_writer *w, int64_t timestamp, const char *channel,
                         size_t chlen, const void *data, size_t len)
{
    if (!w->f || chlen == 0 || chlen > LCMLOG_MAX_CHANNEL || len > INT32_MAX) {
        w->error = 1;
        return -1;
    }
    uint8_t h[28];
    put32(h, LCMLOG_SYNC);
    put64(h + 4, (uint64_t)w->eventnum);
    put64(h + 12, (uint64_t)timestamp);
    put32(h + 20, (uint32_t)chlen);
    put32(h + 24, (uint32_t)len);
    if (fwrite(h, 1, sizeof h, w->f) != sizeof h || fwrite(channel, 1, chlen, w->f) != chlen ||
        (len && fwrite(data, 1, len, w->f) != len)) {
        w->error = 1;
        return -1;
    }
    w->eventnum++;
    return 0;
}

int lcmlog_close_write(struct lcmlog_writer *w)
{
    int rc = w->error ? -1 : 0;
    if (w->f && fclose(w->f) != 0) rc = -1;
    w->f = NULL;
    return rc;
}
