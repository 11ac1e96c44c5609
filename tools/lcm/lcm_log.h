/* lcm_log.h - read and write LCM log files (the lcm-logger format) without
 * liblcm, with bounded memory on corrupt or hostile files.
 *
 * Format (all integers big-endian), one record per message:
 *   int32 sync 0xEDA1DA01, int64 eventnum, int64 timestamp (us),
 *   int32 channellen, int32 datalen, channel bytes, data bytes.
 * liblcm's own reader (lcm_eventlog_read_next_event) allocates whatever
 * datalen a header claims and reports corrupt data as end of file; this
 * reader keeps one buffer of at most max_data bytes, skips larger messages
 * (returned with data = NULL and `oversize` set), resynchronises on the sync
 * word after a corrupt header (counting the bytes skipped) and tells a
 * truncated last record from a clean end. Every read is bounded: a
 * resynchronisation gives up after max_resync bytes without a valid record
 * (e.g. /dev/zero), a non-empty file without one complete record is not a
 * log, and the caller's stop flag (SIGINT/SIGTERM) is checked on every byte
 * skipped. The writer produces byte-identical files for identical input (no
 * wall clock, no padding). */
#ifndef TRK_TOOLS_LCM_LOG_H
#define TRK_TOOLS_LCM_LOG_H

#include <stddef.h>
#include <stdint.h>
#include <signal.h>
#include <stdio.h>

#define LCMLOG_SYNC 0xEDA1DA01u
#define LCMLOG_MAX_CHANNEL 999   /* liblcm's limit for channel names in logs */
#define LCMLOG_MAX_RESYNC (64u << 20) /* default bound of one resynchronisation (bytes) */

/* Why lcmlog_read returned -1 (lcmlog_strerror gives the text). */
enum lcmlog_error {
    LCMLOG_OK = 0,
    LCMLOG_E_READ,      /* the stream failed (errno in sys_errno) */
    LCMLOG_E_NO_SYNC,   /* max_resync bytes without a valid record */
    LCMLOG_E_NOT_LOG,   /* end of a non-empty file without one complete record */
    LCMLOG_E_STOPPED    /* *stop became non-zero */
};

struct lcmlog_event {
    int64_t eventnum;
    int64_t timestamp;              /* microseconds (lcm-logger: receive time) */
    const char *channel;            /* NUL-terminated, valid until the next read */
    size_t channellen;              /* as in the header: may hold NULs (compare with
                                       lcmlog_channel_is, never strcmp) */
    const uint8_t *data;            /* NULL when oversize */
    size_t datalen;                 /* as in the header */
    int oversize;                   /* datalen > max_data: data skipped */
};

struct lcmlog_reader {
    FILE *f;
    uint8_t *buf;
    size_t max_data;
    char channel[LCMLOG_MAX_CHANNEL + 1];
    uint64_t n_events;
    uint64_t n_corrupt;             /* corrupt headers skipped */
    uint64_t n_bytes_skipped;       /* bytes skipped while resynchronising */
    int truncated;                  /* the file ended inside a record */
    uint64_t max_resync;            /* bound of one resync (LCMLOG_MAX_RESYNC; may be lowered) */
    volatile sig_atomic_t *stop;    /* NULL, or checked while reading (set after open) */
    int nonempty;                   /* at least one byte was read */
    enum lcmlog_error error;        /* of the last -1 */
    int sys_errno;                  /* LCMLOG_E_READ: errno */
};

/* 0, or -1 with errno set (cannot open, out of memory). A directory opens
 * and fails at the first read (LCMLOG_E_READ, EISDIR). */
int lcmlog_open_read(struct lcmlog_reader *r, const char *path, size_t max_data);
/* The same over an open stream (the reader closes it). */
int lcmlog_open_stream(struct lcmlog_reader *r, FILE *f, size_t max_data);
/* 1 event read, 0 end of file (clean or truncated: see r->truncated),
 * -1 with r->error set. */
int lcmlog_read(struct lcmlog_reader *r, struct lcmlog_event *ev);
/* What the last -1 of lcmlog_read means (one line, no path). */
const char *lcmlog_strerror(const struct lcmlog_reader *r);
void lcmlog_close_read(struct lcmlog_reader *r);

/* Is the event on channel `name`? Compares the full length of the header's
 * channel, so "A\0hidden" is not channel "A". */
int lcmlog_channel_is(const struct lcmlog_event *ev, const char *name);

struct lcmlog_writer {
    FILE *f;
    int64_t eventnum;
    int error;
};

int lcmlog_open_write(struct lcmlog_writer *w, const char *path);
/* 0 or -1 (write error, channel too long, data too large). */
int lcmlog_write(struct lcmlog_writer *w, int64_t timestamp, const char *channel,
                 const void *data, size_t len);
/* The same with the channel's length given (it may hold NULs: a read
 * event is copied exactly). */
int lcmlog_write_channel(struct lcmlog_writer *w, int64_t timestamp, const char *channel,
                         size_t chlen, const void *data, size_t len);
/* 0, or -1 when any write (or the close) failed. */
int lcmlog_close_write(struct lcmlog_writer *w);

#endif
