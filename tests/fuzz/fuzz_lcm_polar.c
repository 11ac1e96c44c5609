/* fuzz_lcm_polar.c - libFuzzer target: the polar scan copy of
 * trk-lcm-bridge (detection_scan_polar_t -> struct lcmc_scan,
 * tools/lcm/lcm_copy.c) on arbitrary bytes, then the library's conversion
 * of every accepted detection and the tracker on the scan.
 *
 * Input: byte 0 selects the mode, the rest is the message.
 *   bit 0 = 1  raw: the rest is the whole message as received
 *   bit 0 = 0  framed: the correct type hash followed by the rest, zero-padded
 *              to the wire size (bit 1 = 0) or left short (bit 1 = 1)
 *   bits 2..4  number of configured sensors, 1 + value % TRK_MAX_SENSORS
 *   bits 5..7  sensors 1..3 polar (sensor 0 always is); the others Cartesian
 * Invariants (abort = a finding): an accepted scan names a configured polar
 * sensor, has no Cartesian detections, 0/1 flags, a finite pose when it has
 * one, detections with a finite range > 0, |bearing| <= 2 pi and a finite
 * amplitude >= 0, and survives scan -> message -> bytes -> scan unchanged;
 * trk_polar_to_cartesian converts each of its detections; the tracker
 * (fresh table, a polar sensor 0) accepts it (or, while it takes no polar
 * scans, refuses it as an argument it does not use) and its track list
 * encodes and decodes back. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "lcm_copy.h"

static trk_detection_scan_polar_t work, msg2;
static struct lcmc_scan scan, scan2;
static struct trk_tracker tk;
static struct trk_tracker_params params;
static trk_track_list_t tl, tl2;
static uint8_t buf[LCMC_POLAR_SCAN_WIRE_SIZE + 64];
static uint8_t tlbuf[1 << 15];
static int polar_taken = -1; /* does this libtrk's tracker take polar scans (probed once) */

static void make_params(unsigned n_sensors, unsigned mode)
{
    trk_tracker_default_params(&params);
    params.n_sensors = n_sensors;
    for (unsigned s = 1; s < n_sensors; s++) params.sensor[s] = params.sensor[0];
    for (unsigned s = 0; s < n_sensors; s++) {
        struct trk_sensor_params *sp = &params.sensor[s];
        sp->sigma_range_m = 2;
        sp->sigma_bearing_rad = TRK_REAL_C(0.01);
        sp->conversion = s % 2 ? TRK_POLAR_UNBIASED : TRK_POLAR_FIRST_ORDER;
        sp->kind = s == 0 || (s <= 3 && ((mode >> (4 + s)) & 1)) ? TRK_SENSOR_POLAR : TRK_SENSOR_CARTESIAN;
    }
}

/* A one-detection polar scan on a fresh table: TRK_E_ARG means the tracker
 * does not take polar scans yet (it reads only scan.detections). */
static void probe(void)
{
    make_params(1, 0);
    if (trk_tracker_init(&tk, &params) != TRK_OK) abort();
    const struct trk_polar_detection d = {100, TRK_REAL_C(0.5), 0, 0};
    struct trk_scan s;
    memset(&s, 0, sizeof s);
    s.n_detections = 1;
    s.polar = &d;
    struct trk_scan_report rep;
    const trk_status st = trk_tracker_process_scan(&tk, &s, &rep);
    if (st != TRK_OK && st != TRK_E_ARG) abort();
    polar_taken = st == TRK_OK;
}

static void check_scan(const struct lcmc_scan *s, unsigned n_sensors)
{
    const struct trk_scan *c = &s->scan;
    if (c->n_detections > TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS) abort();
    if (c->time_us < 0 || c->time_us > TRK_TIME_US_MAX || c->sensor_id >= n_sensors) abort();
    if (params.sensor[c->sensor_id].kind != TRK_SENSOR_POLAR) abort();
    if (c->detections || c->polar != s->polar) abort();
    if (c->has_pose != 0 && c->has_pose != 1) abort();
    if (c->has_pose && (!isfinite(c->pose.x_m) || !isfinite(c->pose.y_m) || !isfinite(c->pose.heading_rad)))
        abort();
    for (size_t i = 0; i < c->n_detections; i++) {
        const struct trk_polar_detection *d = &s->polar[i];
        if (!isfinite(d->range_m) || !(d->range_m > 0)) abort();
        if (!isfinite(d->bearing_rad) || fabs((double)d->bearing_rad) > LCMC_BEARING_MAX_RAD) abort();
        if (d->has_amplitude > 1 || !isfinite(d->amplitude) || d->amplitude < 0) abort();
    }
}

static void same_scan(const struct lcmc_scan *a, const struct lcmc_scan *b)
{
    if (a->scan.time_us != b->scan.time_us || a->scan.sensor_id != b->scan.sensor_id ||
        a->scan.n_detections != b->scan.n_detections || a->seq != b->seq || a->scan.has_pose != b->scan.has_pose)
        abort();
    if (a->scan.has_pose && memcmp(&a->scan.pose, &b->scan.pose, sizeof a->scan.pose) != 0) abort();
    if (memcmp(a->polar, b->polar, a->scan.n_detections * sizeof a->polar[0]) != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    if (polar_taken < 0) probe();
    const unsigned mode = data[0];
    const unsigned n_sensors = 1 + ((mode >> 2) & 7) % TRK_MAX_SENSORS;
    make_params(n_sensors, mode);
    const uint8_t *msg = data + 1;
    size_t len = size - 1;
    uint8_t *framed = NULL;
    if (!(mode & 1)) {
        /* framed: hash + payload in an exactly sized heap buffer (ASan sees an over-read) */
        const int64_t h = __trk_detection_scan_polar_t_get_hash();
        const size_t body = len;
        const size_t total = (mode & 2) ? 8 + (body < LCMC_POLAR_SCAN_WIRE_SIZE - 8 ? body : LCMC_POLAR_SCAN_WIRE_SIZE - 8)
                                        : LCMC_POLAR_SCAN_WIRE_SIZE;
        framed = calloc(1, total);
        if (!framed) return 0;
        for (int i = 0; i < 8; i++) framed[i] = (uint8_t)((uint64_t)h >> (56 - 8 * i));
        memcpy(framed + 8, msg, body < total - 8 ? body : total - 8);
        msg = framed;
        len = total;
    }
    char detail[160];
    const enum lcmc_reason r =
        lcmc_polar_scan_from_bytes(msg, len, params.sensor, n_sensors, &work, &scan, detail, sizeof detail);
    if ((unsigned)r >= LCMC_N_REASONS) abort();
    if (r == LCMC_OK) {
        check_scan(&scan, n_sensors);
        /* round trip */
        if (lcmc_polar_scan_to_msg(&scan.scan, scan.seq, &msg2) != LCMC_OK) abort();
        int n = trk_detection_scan_polar_t_encode(buf, 0, (int)sizeof buf, &msg2);
        if (n != LCMC_POLAR_SCAN_WIRE_SIZE) abort();
        if (lcmc_polar_scan_from_bytes(buf, (size_t)n, params.sensor, n_sensors, &work, &scan2, NULL, 0) != LCMC_OK)
            abort();
        same_scan(&scan, &scan2);
        /* the library converts every accepted detection */
        const struct trk_sensor_params *sp = &params.sensor[scan.scan.sensor_id];
        const struct trk_pose *pose = scan.scan.has_pose ? &scan.scan.pose : &sp->pose;
        for (size_t i = 0; i < scan.scan.n_detections; i++) {
            struct trk_detection d;
            if (trk_polar_to_cartesian(sp, pose, &scan.polar[i], &d) != TRK_OK) abort();
            if (d.has_cov != 1 || d.has_amplitude != scan.polar[i].has_amplitude) abort();
        }
        /* the tracker on a fresh table */
        if (trk_tracker_init(&tk, &params) != TRK_OK) abort();
        struct trk_scan_report rep;
        const trk_status st = trk_tracker_process_scan(&tk, &scan.scan, &rep);
        if (st != TRK_OK && !(st == TRK_E_ARG && !polar_taken)) abort();
        if (st == TRK_OK) {
            lcmc_tracks_to_msg(&tk, &scan.scan, scan.seq, &rep, &tl);
            if (tl.n_tracks < 0 || tl.n_tracks > TRK_TRACK_LIST_T_MAX_TRACKS) abort();
            n = trk_track_list_t_encode(tlbuf, 0, (int)sizeof tlbuf, &tl);
            if (n <= 0 || trk_track_list_t_decode(tlbuf, 0, n, &tl2) != n) abort();
            if (tl2.n_tracks != tl.n_tracks) abort();
        }
    }
    free(framed);
    return 0;
}
