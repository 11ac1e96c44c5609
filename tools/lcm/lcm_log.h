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
 * truncated last record from a clean end. The writer produces byte-identical
 * files for identical input (no wall clock, no padding). */
#ifndef TRK_TOOLS_LCM_LOG_H
#define TRK_TOOLS_LCM_LOG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define LCMLOG_SYNC 0xEDA1DA01u
#define LCMLOG_MAX_CHANNEL 999   /* liblcm's limit for channel names in logs */

struct lcmlog_event {
    int64_t eventnum;
    int64_t timestamp;              /* microseconds (lcm-logger: receive time) */
    const char *channel;            /* NUL-terminated, valid until the next read */
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
};

/* 0, or -1 (cannot open / out of memory; errno-style message via perror-free
 * err text in the caller). */
int lcmlog_open_read(struct lcmlog_reader *r, const char *path, size_t max_data);
/* 1 event read, 0 end of file (clean or truncated: see r->truncated),
 * -1 read error. */
int lcmlog_read(struct lcmlog_reader *r, struct lcmlog_event *ev);
void lcmlog_close_read(struct lcmlog_reader *r);

struct lcmlog_writer {
    FILE *f;
    int64_t eventnum;
    int error;
};

int lcmlog_open_write(struct lcmlog_writer *w, const char *path);
/* 0 or -1 (write error, channel too long, data too large). */
int lcmlog_write(struct lcmlog_writer *w, int64_t timestamp, const char *channel,
                 const void *data, size_t len);
/* 0, or -1 when any write (or the close) failed. */
int lcmlog_close_write(struct lcmlog_writer *w);

#endif
