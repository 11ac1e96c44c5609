/* fuzz_lcm_log.c - libFuzzer target: the LCM log reader of trk-lcm-bridge
 * (tools/lcm/lcm_log.c) on arbitrary file contents.
 *
 * Input: byte 0 sets the limits, the rest is the file (read from memory).
 *   bits 0..3  max_data = 16 * value bytes (0 .. 240): larger records are skipped
 *   bits 4..7  max_resync = 64 * value bytes (0: the default bound)
 * Invariants (abort = a finding): the reader ends (0 or -1 with a known
 * error, never more events than the file can hold); every event's channel
 * and data are the file's bytes just before the read position, the channel
 * length is 1 .. LCMLOG_MAX_CHANNEL with a NUL after it, data is NULL
 * exactly when the record is larger than max_data; "not a log" only when no
 * event was read; the skip and corrupt counts stay within the file. */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lcm_log.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2) return 0; /* fmemopen needs a non-empty buffer */
    const size_t max_data = 16u * (data[0] & 15u);
    const uint64_t max_resync = 64u * (uint64_t)(data[0] >> 4);
    const uint8_t *file = data + 1;
    const size_t len = size - 1;
    FILE *f = fmemopen((void *)(uintptr_t)file, len, "rb"); /* read only: not written */
    if (!f) return 0;
    struct lcmlog_reader r;
    if (lcmlog_open_stream(&r, f, max_data) != 0) return 0;
    if (max_resync) r.max_resync = max_resync;
    struct lcmlog_event ev;
    int got;
    uint64_t n = 0;
    while ((got = lcmlog_read(&r, &ev)) > 0) {
        if (++n > len / 28) abort(); /* a record takes at least 28 + 1 bytes */
        const long pos = ftell(r.f);
        if (pos < 0 || (size_t)pos > len) abort();
        if (ev.channellen < 1 || ev.channellen > LCMLOG_MAX_CHANNEL || ev.channel[ev.channellen]) abort();
        if ((ev.datalen > max_data) != (ev.oversize != 0) || (ev.data == NULL) != (ev.oversize != 0))
            abort();
        if (ev.datalen + ev.channellen + 28 > (size_t)pos) abort();
        const size_t data_at = (size_t)pos - ev.datalen, ch_at = data_at - ev.channellen;
        if (ev.data && memcmp(ev.data, file + data_at, ev.datalen) != 0) abort();
        if (memcmp(ev.channel, file + ch_at, ev.channellen) != 0) abort();
        if (!lcmlog_channel_is(&ev, ev.channel) != (memchr(ev.channel, 0, ev.channellen) != NULL)) abort();
    }
    if (got < 0) {
        if (r.error != LCMLOG_E_NO_SYNC && r.error != LCMLOG_E_NOT_LOG) abort();
        if (r.error == LCMLOG_E_NOT_LOG && n != 0) abort();
        if (!strlen(lcmlog_strerror(&r))) abort();
    }
    if (r.n_events != n || r.n_bytes_skipped > len || r.n_corrupt > len / 4) abort();
    lcmlog_close_read(&r);
    return 0;
}
