/* fuzz_lcm_copy.c - libFuzzer target: the LCM message -> struct copy of
 * trk-lcm-bridge (tools/lcm/lcm_copy.c) on arbitrary bytes, then the
 * tracker on every scan it accepts.
 *
 * Input: byte 0 selects the mode, the rest is the message.
 *   bit 0 = 1  raw: the rest is the whole message as received
 *   bit 0 = 0  framed: the correct type hash followed by the rest, zero-padded
 *              to the wire size (bit 1 = 0) or left short (bit 1 = 1), so the
 *              fuzzer explores field validation instead of the hash check
 *   bits 2..4  number of configured sensors, 1 + value % TRK_MAX_SENSORS
 * Invariants (abort = a finding): an accepted scan has n <= TRK_MAX_DETECTIONS,
 * utime >= 0, a configured sensor, 0/1 flags, finite used fields, and
 * survives scan -> message -> bytes -> scan unchanged; the tracker accepts it
 * (fresh table) and the track list it produces encodes and decodes back. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "lcm_copy.h"

static trk_detection_scan_t work, msg2;
static struct lcmc_scan scan, scan2;
static struct trk_tracker tk;
static trk_track_list_t tl, tl2;
static uint8_t buf[LCMC_SCAN_WIRE_SIZE + 64];
static uint8_t tlbuf[1 << 15];

static void check_scan(const struct lcmc_scan *s, unsigned n_sensors)
{
    if (s->scan.n_detections > TRK_MAX_DETECTIONS) abort();
    if (s->scan.time_us < 0 || s->scan.sensor_id >= n_sensors) abort();
    if (s->scan.detections != s->det) abort();
    for (size_t i = 0; i < s->scan.n_detections; i++) {
        const struct trk_detection *d = &s->det[i];
        if (d->has_cov > 1 || d->has_amplitude > 1) abort();
        if (!isfinite(d->x_m) || !isfinite(d->y_m)) abort();
        for (int k = 0; k < 3; k++)
            if (!isfinite(d->cov_m2[k])) abort();
        if (!isfinite(d->amplitude) || d->amplitude < 0) abort();
    }
}

static void same_scan(const struct lcmc_scan *a, const struct lcmc_scan *b)
{
    if (a->scan.time_us != b->scan.time_us || a->scan.sensor_id != b->scan.sensor_id ||
        a->scan.n_detections != b->scan.n_detections || a->seq != b->seq)
        abort();
    if (memcmp(a->det, b->det, a->scan.n_detections * sizeof a->det[0]) != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const unsigned mode = data[0];
    const unsigned n_sensors = 1 + ((mode >> 2) & 7) % TRK_MAX_SENSORS;
    const uint8_t *msg = data + 1;
    size_t len = size - 1;
    uint8_t *framed = NULL;
    if (!(mode & 1)) {
        /* framed: hash + payload; an exactly sized heap buffer keeps ASan's
         * over-read detection */
        const int64_t h = __trk_detection_scan_t_get_hash();
        size_t body = len;
        size_t total = (mode & 2) ? 8 + (body < LCMC_SCAN_WIRE_SIZE - 8 ? body : LCMC_SCAN_WIRE_SIZE - 8)
                                  : LCMC_SCAN_WIRE_SIZE;
        framed = calloc(1, total);
        if (!framed) return 0;
        for (int i = 0; i < 8; i++) framed[i] = (uint8_t)((uint64_t)h >> (56 - 8 * i));
        memcpy(framed + 8, msg, body < total - 8 ? body : total - 8);
        msg = framed;
        len = total;
    }
    char detail[160];
    enum lcmc_reason r = lcmc_scan_from_bytes(msg, len, n_sensors, &work, &scan, detail, sizeof detail);
    if ((unsigned)r >= LCMC_N_REASONS) abort();
    if (r == LCMC_OK) {
        check_scan(&scan, n_sensors);
        /* round trip */
        if (lcmc_scan_to_msg(&scan.scan, scan.seq, &msg2) != LCMC_OK) abort();
        int n = trk_detection_scan_t_encode(buf, 0, (int)sizeof buf, &msg2);
        if (n != LCMC_SCAN_WIRE_SIZE) abort();
        if (lcmc_scan_from_bytes(buf, (size_t)n, n_sensors, &work, &scan2, NULL, 0) != LCMC_OK) abort();
        same_scan(&scan, &scan2);
        /* the tracker on a fresh table must accept a validated scan */
        struct trk_tracker_params p;
        trk_tracker_default_params(&p);
        p.n_sensors = n_sensors;
        for (unsigned s = 1; s < n_sensors; s++) p.sensor[s] = p.sensor[0];
        if (trk_tracker_init(&tk, &p) != TRK_OK) abort();
        struct trk_scan_report rep;
        if (trk_tracker_process_scan(&tk, &scan.scan, &rep) != TRK_OK) abort();
        lcmc_tracks_to_msg(&tk, &scan.scan, scan.seq, &rep, &tl);
        if (tl.n_tracks < 0 || tl.n_tracks > TRK_TRACK_LIST_T_MAX_TRACKS) abort();
        n = trk_track_list_t_encode(tlbuf, 0, (int)sizeof tlbuf, &tl);
        if (n <= 0 || trk_track_list_t_decode(tlbuf, 0, n, &tl2) != n) abort();
        if (tl2.n_tracks != tl.n_tracks) abort();
    }
    free(framed);
    return 0;
}
