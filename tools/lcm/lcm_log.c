/* lcm_log.c - LCM log files (lcm_log.h). */
#include "lcm_log.h"

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

int lcmlog_open_read(struct lcmlog_reader *r, const char *path, size_t max_data)
{
    memset(r, 0, sizeof *r);
    r->f = fopen(path, "rb");
    if (!r->f) return -1;
    r->max_data = max_data;
    r->buf = malloc(max_data ? max_data : 1);
    if (!r->buf) {
        fclose(r->f);
        r->f = NULL;
        return -1;
    }
    return 0;
}

void lcmlog_close_read(struct lcmlog_reader *r)
{
    if (r->f) fclose(r->f);
    free(r->buf);
    r->f = NULL;
    r->buf = NULL;
}

/* Find the next sync word. 1 found, 0 EOF. Counts skipped bytes. */
static int sync_stream(struct lcmlog_reader *r, int *skipped_any)
{
    uint32_t w = 0;
    int n = 0;
    for (;;) {
        int c = fgetc(r->f);
        if (c == EOF) {
            if (n > 0) r->n_bytes_skipped += (uint64_t)n, *skipped_any = 1;
            return 0;
        }
        w = w << 8 | (uint32_t)c;
        n++;
        if (n >= 4 && w == LCMLOG_SYNC) {
            if (n > 4) r->n_bytes_skipped += (uint64_t)(n - 4), *skipped_any = 1;
            return 1;
        }
    }
}

int lcmlog_read(struct lcmlog_reader *r, struct lcmlog_event *ev)
{
    for (;;) {
        int skipped = 0;
        if (!sync_stream(r, &skipped)) {
            if (ferror(r->f)) return -1;
            if (skipped) r->truncated = 1;
            return 0;
        }
        uint8_t h[24];
        if (fread(h, 1, sizeof h, r->f) != sizeof h) {
            if (ferror(r->f)) return -1;
            r->truncated = 1;
            return 0;
        }
        const int32_t chlen = to_i32(get32(h + 16)), dlen = to_i32(get32(h + 20));
        if (chlen <= 0 || chlen > LCMLOG_MAX_CHANNEL || dlen < 0) {
            /* corrupt header: resynchronise just after this sync word */
            r->n_corrupt++;
            if (fseek(r->f, -24, SEEK_CUR) != 0) return -1;
            continue;
        }
        if (fread(r->channel, 1, (size_t)chlen, r->f) != (size_t)chlen) {
            if (ferror(r->f)) return -1;
            r->truncated = 1;
            return 0;
        }
        r->channel[chlen] = 0;
        ev->eventnum = to_i64(get64(h));
        ev->timestamp = to_i64(get64(h + 8));
        ev->channel = r->channel;
        ev->datalen = (size_t)dlen;
        ev->oversize = (size_t)dlen > r->max_data;
        if (ev->oversize) {
            ev->data = NULL;
            /* skip it; past the end means a truncated record */
            long pos = ftell(r->f);
            if (pos < 0 || fseek(r->f, 0, SEEK_END) != 0) return -1;
            long end = ftell(r->f);
            if (end < 0) return -1;
            if (end - pos < (long)dlen) {
                r->truncated = 1;
                return 0;
            }
            if (fseek(r->f, pos + (long)dlen, SEEK_SET) != 0) return -1;
        } else {
            if (fread(r->buf, 1, (size_t)dlen, r->f) != (size_t)dlen) {
                if (ferror(r->f)) return -1;
                r->truncated = 1;
                return 0;
            }
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
    const size_t chlen = strlen(channel);
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
