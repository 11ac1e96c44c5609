/* test_lcm_bridge.c - trk-lcm-bridge end to end, without a network:
 *   - every accepted scan's track list is byte-identical to the tracker run
 *     directly on the same scans (lcmc_tracks_to_msg of a second tracker)
 *   - malformed, oversized, truncated and refused messages of every category
 *     are counted by cause and leave the tracker untouched (the next scans
 *     still match the direct run)
 *   - rejections are logged once per cause, then rate limited
 *   - memq:// round trip through the live loop (subscribe, publish, status)
 *   - log replay: tracks equal the direct run, the same input gives a
 *     byte-identical output, damaged logs (truncated, corrupt header,
 *     oversize record) are survived, liblcm's log reader/writer agree
 * The scenario is sized to the build (small capacities: 3 targets + 5
 * clutter detections per scan). */
#define _POSIX_C_SOURCE 200809L /* getpid, fileno */
#include <unistd.h>

#include "trk_test.h"

#include <lcm/eventlog.h>
#include <lcm/lcm.h>

#include "bridge.h"
#include "fileio.h"
#include "lcm_log.h"
#include "scenario.h"
#include "transport.h"

#define N_SCANS 30
#define N_DET_MAX 256

static struct trk_scan scans[N_SCANS];
static struct trk_detection scan_det[N_SCANS][N_DET_MAX];
static uint8_t scan_bytes[N_SCANS][LCMC_SCAN_WIRE_SIZE];
static trk_detection_scan_t scan_msg[N_SCANS];
static uint8_t *expect_bytes[N_SCANS]; /* direct tracker's track list per scan */
static size_t expect_len[N_SCANS];
static struct trk_tracker direct;
static trk_track_list_t tl;
static struct tcfg cfg;
static struct bridge_opts opts;
static char err[512];

static void make_scenario(void)
{
    struct scen_params p;
    struct scenario s;
    scen_defaults(&p);
    p.seed = 11;
    p.n_targets = TRK_MAX_TRACKS >= 32 ? 6 : 3;
    p.clutter_count = TRK_MAX_DETECTIONS >= 64 ? 25 : 5;
    assert_int_equal(scen_init(&s, &p, err, sizeof err), 0);
    for (int k = 0; k < N_SCANS; k++) {
        scen_next(&s, scan_det[k], N_DET_MAX, &scans[k], NULL, NULL);
        if (k % 3 == 1 && scans[k].n_detections > 0) { /* some detections with own covariance */
            scan_det[k][0].has_cov = 1;
            scan_det[k][0].cov_m2[0] = 16;
            scan_det[k][0].cov_m2[1] = 2;
            scan_det[k][0].cov_m2[2] = 9;
        }
        assert_true(scans[k].n_detections <= TRK_MAX_DETECTIONS);
        assert_int_equal(lcmc_scan_to_msg(&scans[k], 1000 + k, &scan_msg[k]), LCMC_OK);
        assert_int_equal(trk_detection_scan_t_encode(scan_bytes[k], 0, LCMC_SCAN_WIRE_SIZE, &scan_msg[k]),
                         LCMC_SCAN_WIRE_SIZE);
    }
    scen_free(&s);
}

static void make_config(void)
{
    tcfg_defaults(&cfg);
    assert_int_equal(tcfg_set(&cfg, "sensor.0.meas_sigma_m", "3", err, sizeof err), 0);
    assert_int_equal(tcfg_set(&cfg, "sensor.0.clutter_density_per_m2", "6e-6", err, sizeof err), 0);
    assert_int_equal(tcfg_set(&cfg, "confirm.mn.m", "2", err, sizeof err), 0);
    assert_int_equal(tcfg_set(&cfg, "confirm.mn.n", "3", err, sizeof err), 0);
    bridge_opts_defaults(&opts);
    opts.quiet = 1;
}

/* The direct run: the tracker on the same scans, its lists encoded. */
static void make_expected(void)
{
    struct trk_tracker_params p;
    tcfg_params(&cfg, &p);
    TRK_ASSERT_OK(trk_tracker_init(&direct, &p));
    const int n = trk_track_list_t_encoded_size(&tl);
    for (int k = 0; k < N_SCANS; k++) {
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&direct, &scans[k], &rep));
        lcmc_tracks_to_msg(&direct, &scans[k], 1000 + k, &rep, &tl);
        free(expect_bytes[k]);
        expect_bytes[k] = malloc((size_t)n);
        assert_int_equal(trk_track_list_t_encode(expect_bytes[k], 0, n, &tl), n);
        expect_len[k] = (size_t)n;
    }
    /* the scenario does produce confirmed tracks */
    int conf = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *t = trk_tracker_track(&direct, i);
        conf += t && t->status == TRK_TRACK_CONFIRMED;
    }
    assert_true(conf >= 2);
}

static int setup(void **state)
{
    (void)state;
    make_scenario();
    make_config();
    make_expected();
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    for (int k = 0; k < N_SCANS; k++) free(expect_bytes[k]);
    return 0;
}

static void handle_good(struct bridge *b, int k, int64_t now)
{
    const void *out;
    size_t len;
    assert_int_equal(bridge_handle(b, scan_bytes[k], LCMC_SCAN_WIRE_SIZE, now, &out, &len), LCMC_OK);
    assert_int_equal(len, expect_len[k]);
    assert_memory_equal(out, expect_bytes[k], len);
}

/* The bridge's status message now, decoded. */
static const trk_bridge_status_t *status_now(struct bridge *b, int64_t utime)
{
    static trk_bridge_status_t st;
    const void *sb;
    size_t sl;
    bridge_status(b, utime, &sb, &sl);
    assert_int_equal(trk_bridge_status_t_decode(sb, 0, (int)sl, &st), (int)sl);
    return &st;
}

/* A bridge that logs its rejections into a temporary file. */
static struct bridge *logging_bridge(double log_interval_s, FILE **log)
{
    struct bridge_opts o = opts;
    o.quiet = 0;
    o.log_interval_s = log_interval_s;
    o.log = *log = tmpfile();
    assert_non_null(o.log);
    struct bridge *b = bridge_new(&cfg, &o, err, sizeof err);
    assert_non_null(b);
    return b;
}

/* What was written to f (closed), NUL-terminated. */
static char *text_of(FILE *f)
{
    static char text[8192];
    rewind(f);
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = 0;
    fclose(f);
    return text;
}

static void test_handle_matches_direct(void **state)
{
    (void)state;
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    for (int k = 0; k < N_SCANS; k++) handle_good(b, k, k);
    assert_true(b->c.received == N_SCANS && b->c.processed == N_SCANS && b->c.rejected == 0);
    assert_true(b->c.seq_gaps == 0);
    assert_true(b->last_accepted_seq == 1000 + N_SCANS - 1);
    bridge_free(b);
}

/* One malformed message: bytes and the reason it must get. */
struct bad {
    uint8_t *bytes;
    size_t len;
    enum lcmc_reason want;
    const char *what;
};

static struct bad make_bad(int kind, int k)
{
    static trk_detection_scan_t m;
    struct bad r = {NULL, LCMC_SCAN_WIRE_SIZE, LCMC_OK, ""};
    m = scan_msg[k];
    int encode = 1;
    switch (kind) {
    case 0: r.len = LCMC_SCAN_WIRE_SIZE - 1, r.want = LCMC_DECODE, r.what = "truncated by 1"; break;
    case 1: r.len = 100, r.want = LCMC_DECODE, r.what = "truncated to 100"; break;
    case 2: r.len = 0, r.want = LCMC_DECODE, r.what = "empty"; break;
    case 3: r.len = LCMC_SCAN_WIRE_SIZE + 1, r.want = LCMC_DECODE, r.what = "trailing byte"; break;
    case 4: r.want = LCMC_DECODE, r.what = "wrong hash"; break;
    case 5: m.n_detections = -1, r.want = LCMC_COUNT, r.what = "count -1"; break;
    case 6: m.n_detections = 257, r.want = LCMC_COUNT, r.what = "count 257"; break;
    case 7: m.n_detections = 0x40000001, r.want = LCMC_COUNT, r.what = "count 2^30+1"; break;
    /* a NaN, an infinite amplitude or a flag 2 in one detection no longer
     * rejects the scan: test_bad_detection_dropped_alone */
    case 8: m.utime = INT64_MAX, r.want = LCMC_FIELD, r.what = "utime INT64_MAX"; break;
    case 9: m.n_detections = INT32_MIN, r.want = LCMC_COUNT, r.what = "count INT32_MIN"; break;
    case 10: m.sensor_id = -1, r.want = LCMC_SENSOR, r.what = "sensor -1"; break;
    case 11: m.utime = -5, r.want = LCMC_FIELD, r.what = "negative utime"; break;
    case 12: m.sensor_id = 3, r.want = LCMC_SENSOR, r.what = "sensor 3"; break;
    case 13: /* before the last accepted scan (k - 1) */
        m.utime = scan_msg[k - 1].utime - 1, r.want = LCMC_TIME, r.what = "time backwards";
        break;
    case 14: /* gap longer than max_dt_s (3600 s) */
        m.utime = scan_msg[k - 1].utime + 3601000000LL, r.want = LCMC_GAP, r.what = "gap";
        break;
    case 15: /* above this build's capacity: not bad, the tracker thins the
              * scan (test_lcm_copy's test_capacity) */
        r.want = LCMC_OK; /* marks "skip" */
        encode = 0;
        break;
    default: fail_msg("bad kind %d", kind);
    }
    r.bytes = malloc(LCMC_SCAN_WIRE_SIZE + 8);
    assert_non_null(r.bytes);
    memset(r.bytes, 0, LCMC_SCAN_WIRE_SIZE + 8);
    if (encode) trk_detection_scan_t_encode(r.bytes, 0, LCMC_SCAN_WIRE_SIZE, &m);
    if (kind == 4) r.bytes[3] ^= 1;
    return r;
}
#define N_BAD_KINDS 16

static void test_bad_messages_counted_and_harmless(void **state)
{
    (void)state;
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    uint64_t want[LCMC_N_REASONS] = {0};
    uint64_t n_bad = 0;
    handle_good(b, 0, 0);
    for (int k = 1; k < N_SCANS; k++) {
        /* two bad messages before most good scans, cycling through the kinds */
        for (int j = 0; j < 2; j++) {
            const int kind = (2 * k + j) % N_BAD_KINDS;
            struct bad x = make_bad(kind, k);
            if (x.want != LCMC_OK) {
                /* exactly sized copy: an over-read would be caught */
                uint8_t *exact = malloc(x.len ? x.len : 1);
                memcpy(exact, x.bytes, x.len);
                const void *out;
                size_t len;
                enum lcmc_reason r = bridge_handle(b, exact, x.len, k, &out, &len);
                if (r != x.want)
                    fail_msg("%s: reason %s, want %s", x.what, lcmc_reason_name(r),
                             lcmc_reason_name(x.want));
                free(exact);
                want[x.want]++;
                n_bad++;
            }
            free(x.bytes);
        }
        handle_good(b, k, k); /* the tracker was not touched */
    }
    assert_true(b->c.processed == N_SCANS);
    assert_true(b->c.received == N_SCANS + n_bad);
    assert_true(b->c.rejected == n_bad);
    for (int r = 1; r < LCMC_N_REASONS; r++)
        if (b->c.by_reason[r] != want[r])
            fail_msg("%s: %llu rejections, want %llu", lcmc_reason_name((enum lcmc_reason)r),
                     (unsigned long long)b->c.by_reason[r], (unsigned long long)want[r]);
    /* every scan-level category occurred (NONFINITE is a detection's only) */
    assert_true(want[LCMC_DECODE] && want[LCMC_COUNT] && want[LCMC_FIELD] && want[LCMC_SENSOR] &&
                want[LCMC_TIME] && want[LCMC_GAP]);
    assert_true(want[LCMC_NONFINITE] == 0 && b->c.det_rejected == 0);
    assert_true(want[LCMC_CAPACITY] == 0);
    /* the status message says the same */
    const trk_bridge_status_t st = *status_now(b, 123);
    assert_true(st.utime == 123);
    assert_true(st.n_received == (int64_t)b->c.received && st.n_processed == N_SCANS);
    assert_true(st.n_rejected == (int64_t)n_bad);
    assert_true(st.n_rejected_decode == (int64_t)want[LCMC_DECODE]);
    assert_true(st.n_rejected_count == (int64_t)want[LCMC_COUNT]);
    assert_true(st.n_rejected_capacity == (int64_t)want[LCMC_CAPACITY]);
    assert_true(st.n_rejected_field == (int64_t)want[LCMC_FIELD]);
    assert_true(st.n_rejected_sensor == (int64_t)want[LCMC_SENSOR]);
    assert_true(st.n_rejected_time == (int64_t)want[LCMC_TIME]);
    assert_true(st.n_rejected_gap == (int64_t)want[LCMC_GAP]);
    assert_true(st.last_seq == 1000 + N_SCANS - 1);
    assert_true(st.last_scan_utime == scans[N_SCANS - 1].time_us);
    assert_int_equal(st.n_live_tracks, (int32_t)trk_tracker_live_count(&b->tk));
    bridge_free(b);
}

/* A bad detection is dropped alone and counted; the other detections of its
 * scan are processed: every scan's track list equals the direct run on the
 * scan without it, except the list's two detection counts. */
static void test_bad_detection_dropped_alone(void **state)
{
    (void)state;
    FILE *log;
    struct bridge *b = logging_bridge(1e6, &log);
    static trk_detection_scan_t m;
    static trk_track_list_t want_tl;
    static uint8_t buf[LCMC_SCAN_WIRE_SIZE], want[1 << 15];
    uint64_t n_nonfinite = 0, n_field = 0;
    for (int k = 0; k < N_SCANS; k++) {
        m = scan_msg[k];
        const size_t n = (size_t)m.n_detections;
        if (n + 1 > TRK_MAX_DETECTIONS) { /* no room for one more: unchanged */
            handle_good(b, k, k);
            continue;
        }
        /* insert a bad detection at position p */
        const size_t p = (size_t)k % (n + 1);
        memmove(&m.detections[p + 1], &m.detections[p], (n - p) * sizeof m.detections[0]);
        m.n_detections = (int32_t)(n + 1);
        trk_detection_t *d = &m.detections[p];
        memset(d, 0, sizeof *d);
        d->x_m = 10, d->y_m = 20;
        switch (k % 5) {
        case 0: d->y_m = NAN, n_nonfinite++; break;
        case 1: d->has_amplitude = 1, d->amplitude = INFINITY, n_nonfinite++; break;
        case 2: d->has_cov = 2, n_field++; break;
        case 3: d->has_amplitude = 1, d->amplitude = -1, n_field++; break;
        default: d->has_cov = 1, d->cov_m2[0] = NAN, n_nonfinite++; break;
        }
        assert_int_equal(trk_detection_scan_t_encode(buf, 0, LCMC_SCAN_WIRE_SIZE, &m), LCMC_SCAN_WIRE_SIZE);
        const void *out;
        size_t len;
        assert_int_equal(bridge_handle(b, buf, sizeof buf, k, &out, &len), LCMC_OK);
        /* the direct run's list, with the message's count and the drop */
        assert_int_equal(trk_track_list_t_decode(expect_bytes[k], 0, (int)expect_len[k], &want_tl),
                         (int)expect_len[k]);
        want_tl.n_detections++;
        want_tl.n_detections_rejected++;
        const int wn = trk_track_list_t_encode(want, 0, (int)sizeof want, &want_tl);
        assert_int_equal(len, (size_t)wn);
        assert_memory_equal(out, want, len);
    }
    assert_true(b->c.processed == N_SCANS && b->c.rejected == 0);
    assert_true(b->c.det_nonfinite == n_nonfinite && b->c.det_field == n_field);
    assert_true(b->c.det_rejected == n_nonfinite + n_field && n_nonfinite + n_field > 0);
    assert_true(b->c.det_cov == 0 && b->c.det_amplitude == 0);
    const trk_bridge_status_t st = *status_now(b, 1);
    assert_true(st.n_detections_rejected == (int64_t)(n_nonfinite + n_field));
    assert_true(st.n_detections_nonfinite == (int64_t)n_nonfinite);
    assert_true(st.n_detections_field == (int64_t)n_field);
    assert_true(st.n_rejected == 0 && st.n_processed == N_SCANS);
    /* logged once (naming the detection), the rest counted at the flush */
    bridge_log_flush(b);
    const char *text = text_of(log);
    assert_non_null(strstr(text, "dropped 1 bad detection(s)"));
    assert_non_null(strstr(text, "detections[0]: position (10, nan)"));
    char more[96];
    snprintf(more, sizeof more, "%llu more 'dropped detection' messages not shown",
             (unsigned long long)(n_nonfinite + n_field - 1));
    assert_non_null(strstr(text, more));
    bridge_free(b);
}

/* Sequence numbers: a small forward step counts the missing scans; a repeat,
 * a step back or a step above BRIDGE_SEQ_GAP_MAX + 1 is one jump (seq 2^63-1
 * after 4 used to add 9.2e18 "gaps"). */
static void test_seq_gaps(void **state)
{
    (void)state;
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    static trk_detection_scan_t m;
    static uint8_t buf[LCMC_SCAN_WIRE_SIZE];
    const int64_t seqs[] = {5,         6, 9, 10, 10, 4, INT64_MAX, 0, BRIDGE_SEQ_GAP_MAX + 2,
                            2 * BRIDGE_SEQ_GAP_MAX + 3, INT64_MIN, INT64_MIN + 3};
    const int n = (int)(sizeof seqs / sizeof seqs[0]);
    for (int i = 0; i < n; i++) {
        m = scan_msg[i];
        m.seq = seqs[i];
        trk_detection_scan_t_encode(buf, 0, LCMC_SCAN_WIRE_SIZE, &m);
        const void *out;
        size_t len;
        assert_int_equal(bridge_handle(b, buf, sizeof buf, i, &out, &len), LCMC_OK);
    }
    /* gaps: 7, 8; BRIDGE_SEQ_GAP_MAX between the two large numbers; 2 at the end.
     * jumps: 10 -> 10, 10 -> 4, 4 -> INT64_MAX, INT64_MAX -> 0, 0 -> GAP_MAX + 2
     * (GAP_MAX + 1 missing), 2 GAP_MAX + 3 -> INT64_MIN */
    assert_true(b->c.seq_gaps == 2 + BRIDGE_SEQ_GAP_MAX + 2);
    assert_true(b->c.seq_jumps == 6);
    const trk_bridge_status_t st = *status_now(b, 1);
    assert_true(st.n_seq_gaps == 2 + BRIDGE_SEQ_GAP_MAX + 2 && st.n_seq_jumps == 6);
    bridge_free(b);
}

/* Detections below the amplitude threshold are counted (status, summary):
 * with sensor.0.pfa 1e-9 the demo log lost most detections while the
 * summary said "detections dropped 0". */
static void test_below_threshold_counted(void **state)
{
    (void)state;
    struct tcfg c2 = cfg;
    assert_int_equal(tcfg_set(&c2, "sensor.0.amplitude", "rayleigh", err, sizeof err), 0);
    assert_int_equal(tcfg_set(&c2, "sensor.0.pfa", "1e-3", err, sizeof err), 0); /* t = 2.63 */
    struct bridge *b = bridge_new(&c2, &opts, err, sizeof err);
    assert_non_null(b);
    static trk_detection_scan_t m;
    static uint8_t buf[LCMC_SCAN_WIRE_SIZE];
    memset(&m, 0, sizeof m);
    m.utime = 1000000;
    m.n_detections = 4;
    const double amp[4] = {0.5, 2.5, 3.0, 10.0}; /* two below, two above */
    for (int i = 0; i < 4; i++) {
        m.detections[i].x_m = 100.0 * i;
        m.detections[i].y_m = 50;
        m.detections[i].has_amplitude = 1;
        m.detections[i].amplitude = amp[i];
    }
    trk_detection_scan_t_encode(buf, 0, LCMC_SCAN_WIRE_SIZE, &m);
    const void *out;
    size_t len;
    assert_int_equal(bridge_handle(b, buf, sizeof buf, 0, &out, &len), LCMC_OK);
    m.utime += 1000000;
    trk_detection_scan_t_encode(buf, 0, LCMC_SCAN_WIRE_SIZE, &m);
    assert_int_equal(bridge_handle(b, buf, sizeof buf, 1, &out, &len), LCMC_OK);
    assert_true(b->c.det_below_threshold == 4);
    assert_true(b->c.det_rejected == 0);
    const trk_bridge_status_t st = *status_now(b, 1);
    assert_true(st.n_detections_below_threshold == 4);
    FILE *f = tmpfile();
    assert_non_null(f);
    bridge_summary(b, f);
    assert_non_null(strstr(text_of(f), "below the amplitude threshold 4"));
    bridge_free(b);
}

static void test_rate_limited_log(void **state)
{
    (void)state;
    FILE *log;
    struct bridge *b = logging_bridge(10, &log);
    const void *out;
    size_t len;
    const uint8_t junk[10] = {0};
    /* decode rejections at 0, 1, 2, 3 s: one message; at 11 s: one more, "3 more" */
    for (int i = 0; i < 4; i++)
        assert_int_equal(bridge_handle(b, junk, sizeof junk, (int64_t)i * 1000000, &out, &len), LCMC_DECODE);
    /* another cause is logged at once */
    static trk_detection_scan_t m;
    static uint8_t buf[LCMC_SCAN_WIRE_SIZE];
    m = scan_msg[0];
    m.sensor_id = 9;
    trk_detection_scan_t_encode(buf, 0, LCMC_SCAN_WIRE_SIZE, &m);
    assert_int_equal(bridge_handle(b, buf, sizeof buf, 1500000, &out, &len), LCMC_SENSOR);
    assert_int_equal(bridge_handle(b, junk, sizeof junk, 11000000, &out, &len), LCMC_DECODE);
    assert_int_equal(bridge_handle(b, junk, sizeof junk, 12000000, &out, &len), LCMC_DECODE);
    bridge_log_flush(b);
    char *text = text_of(log);
    int lines = 0, decode_lines = 0;
    for (char *l = strtok(text, "\n"); l; l = strtok(NULL, "\n")) {
        lines++;
        if (strstr(l, "does not decode")) decode_lines++;
        if (lines == 3) assert_non_null(strstr(l, "3 more since the last message"));
        if (lines == 4) assert_non_null(strstr(l, "1 more 'decode' rejections not shown"));
    }
    assert_int_equal(decode_lines, 2);
    assert_int_equal(lines, 4); /* decode, sensor, decode (+3), flush (+1) */
    bridge_free(b);
}

static void test_refuses_bad_config(void **state)
{
    (void)state;
    struct tcfg bad = cfg;
    assert_int_equal(tcfg_set(&bad, "confirm", "mn", err, sizeof err), 0);
    assert_int_equal(tcfg_set(&bad, "confirm.mn.m", "4", err, sizeof err), 0); /* > n = 3 */
    assert_null(bridge_new(&bad, &opts, err, sizeof err));
    assert_non_null(strstr(err, "confirm.mn"));
    bad = cfg;
    assert_int_equal(tcfg_set(&bad, "sensor.0.amplitude", "k", err, sizeof err), 0); /* no table */
    assert_null(bridge_new(&bad, &opts, err, sizeof err));
    assert_non_null(strstr(err, "amp_table"));
    /* its square overflows trk_real: refused at init, the field named
     * (1e160 is beyond float itself, so the float build squares 1e20) */
    bad = cfg;
    assert_int_equal(tcfg_set(&bad, "init_speed_sigma_mps", TRK_TEST_IS_FLOAT ? "1e20" : "1e160", err,
                              sizeof err),
                     0);
    assert_null(bridge_new(&bad, &opts, err, sizeof err));
    assert_non_null(strstr(err, "init_speed_sigma_mps"));
}

/* The other confirmation / termination methods run through the bridge the
 * same as directly, and the track list names them. */
static void test_other_methods(void **state)
{
    (void)state;
    static const char *const sets[][4] = {{"confirm", "sprt", "term", "page"},
                                          {"confirm", "sprt", "term", "shiryaev"},
                                          {"confirm", "clutter_density", "term", "kn"},
                                          {"confirm", "visibility", "term", "visibility"}};
    static const int8_t codes[][2] = {{TRK_TRACK_T_CONFIRM_SPRT, TRK_TRACK_T_TERM_PAGE},
                                      {TRK_TRACK_T_CONFIRM_SPRT, TRK_TRACK_T_TERM_SHIRYAEV},
                                      {TRK_TRACK_T_CONFIRM_CLUTTER_DENSITY, TRK_TRACK_T_TERM_KN},
                                      {TRK_TRACK_T_CONFIRM_VISIBILITY, TRK_TRACK_T_TERM_VISIBILITY}};
    for (int v = 0; v < 4; v++) {
        if (v == 2 && !TRK_WITH_CLUTTER_TESTS) continue;
        struct tcfg c2 = cfg;
        assert_int_equal(tcfg_set(&c2, sets[v][0], sets[v][1], err, sizeof err), 0);
        assert_int_equal(tcfg_set(&c2, sets[v][2], sets[v][3], err, sizeof err), 0);
        if (v == 2) assert_int_equal(tcfg_set(&c2, "max_tentative_scans", "6", err, sizeof err), 0);
        if (v == 3) /* with a Rayleigh amplitude model (PDAFAI; P_D from the model) */
            assert_int_equal(tcfg_set(&c2, "sensor.0.amplitude", "rayleigh", err, sizeof err), 0);
        struct bridge *b = bridge_new(&c2, &opts, err, sizeof err);
        if (!b) fail_msg("%s/%s: %s", sets[v][1], sets[v][3], err);
        struct trk_tracker_params p;
        struct tcfg_runtime rt;
        assert_int_equal(tcfg_load(&c2, &rt, err, sizeof err), 0);
        tcfg_params_rt(&c2, &rt, &p);
        assert_int_equal(p.sensor[0].use_amplitude, v == 3);
        TRK_ASSERT_OK(trk_tracker_init(&direct, &p));
        static uint8_t want[1 << 15];
        int n_tracks_seen = 0;
        for (int k = 0; k < N_SCANS; k++) {
            struct trk_scan_report rep;
            TRK_ASSERT_OK(trk_tracker_process_scan(&direct, &scans[k], &rep));
            lcmc_tracks_to_msg(&direct, &scans[k], 1000 + k, &rep, &tl);
            const int n = trk_track_list_t_encode(want, 0, (int)sizeof want, &tl);
            const void *out;
            size_t len;
            assert_int_equal(bridge_handle(b, scan_bytes[k], LCMC_SCAN_WIRE_SIZE, k, &out, &len), LCMC_OK);
            assert_int_equal(len, (size_t)n);
            assert_memory_equal(out, want, len);
            for (int i = 0; i < tl.n_tracks; i++) {
                assert_int_equal(tl.tracks[i].confirm_method, codes[v][0]);
                assert_int_equal(tl.tracks[i].term_method, codes[v][1]);
                n_tracks_seen++;
            }
        }
        assert_true(n_tracks_seen > 0);
        tcfg_unload(&rt);
        bridge_free(b);
    }
}

/* ------------------------------------------------------------------ memq */

struct collector {
    uint8_t *lists[4 * N_SCANS];
    size_t len[4 * N_SCANS];
    int n;
    int n_status;
    trk_bridge_status_t last_status;
};

static void on_tracks(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    struct collector *c = user;
    (void)channel;
    if (c->n == 4 * N_SCANS) return;
    c->lists[c->n] = malloc(rbuf->data_size);
    memcpy(c->lists[c->n], rbuf->data, rbuf->data_size);
    c->len[c->n++] = rbuf->data_size;
}

static void on_status(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    struct collector *c = user;
    (void)channel;
    if (trk_bridge_status_t_decode(rbuf->data, 0, (int)rbuf->data_size, &c->last_status) > 0)
        c->n_status++;
}

static void test_memq_round_trip(void **state)
{
    (void)state;
    lcm_t *lc = lcm_create("memq://");
    assert_non_null(lc);
    struct bridge_opts o = opts;
    o.status_period_s = 0; /* only at the end */
    struct bridge *b = bridge_new(&cfg, &o, err, sizeof err);
    assert_non_null(b);
    struct bridge_live live;
    assert_int_equal(bridge_live_attach(&live, lc, b), 0);
    static struct collector col;
    memset(&col, 0, sizeof col);
    lcm_subscription_t *s1 = lcm_subscribe(lc, o.track_channel, on_tracks, &col);
    lcm_subscription_t *s2 = lcm_subscribe(lc, o.status_channel, on_status, &col);
    assert_non_null(s1);
    assert_non_null(s2);
    lcm_subscription_set_queue_capacity(s1, 4 * N_SCANS);
    /* a scan and a bad message at a time (queues stay short), the live loop
     * runs until idle */
    int n_bad = 0;
    for (int k = 0; k < N_SCANS; k++) {
        assert_int_equal(lcm_publish(lc, o.detection_channel, scan_bytes[k], LCMC_SCAN_WIRE_SIZE), 0);
        if (k % 5 == 4) {
            assert_int_equal(lcm_publish(lc, o.detection_channel, scan_bytes[k], 99), 0);
            n_bad++;
        }
        if (k % 10 == 9) assert_int_equal(bridge_live_run(&live, NULL, 0, 0.05), 0);
    }
    while (lcm_handle_timeout(lc, 0) > 0) {
    }
    assert_int_equal(col.n, N_SCANS);
    for (int k = 0; k < N_SCANS; k++) {
        assert_int_equal(col.len[k], expect_len[k]);
        assert_memory_equal(col.lists[k], expect_bytes[k], expect_len[k]);
        free(col.lists[k]);
    }
    /* one status per loop end, the last with the totals */
    assert_true(col.n_status >= 3);
    assert_true(col.last_status.n_processed == N_SCANS);
    assert_true(col.last_status.n_rejected_decode == n_bad);
    /* a stop request ends the loop at once (and still sends the status) */
    volatile sig_atomic_t stop = 1;
    const int before = col.n_status;
    assert_int_equal(bridge_live_run(&live, &stop, 0, 0), 0);
    while (lcm_handle_timeout(lc, 0) > 0) {
    }
    assert_int_equal(col.n_status, before + 1);
    lcm_unsubscribe(lc, s1);
    lcm_unsubscribe(lc, s2);
    bridge_live_detach(&live);
    lcm_destroy(lc);
    bridge_free(b);
}

/* ------------------------------------------------------------------ replay */

static const char *tmp_path(const char *name)
{
    static char paths[8][256];
    static int next;
    char *p = paths[next++ % 8];
    const char *dir = getenv("TMPDIR");
    snprintf(p, 256, "%s/trk_test_lcm_bridge_%ld_%s", dir ? dir : "/tmp", (long)getpid(), name);
    return p;
}

static void write_input_log(const char *path, int with_bad)
{
    struct lcmlog_writer w;
    assert_int_equal(lcmlog_open_write(&w, path), 0);
    for (int k = 0; k < N_SCANS; k++) {
        const int64_t ts = scans[k].time_us + 500; /* "receive time" */
        assert_int_equal(lcmlog_write(&w, ts, "OTHER_CHANNEL", "xyz", 3), 0);
        assert_int_equal(lcmlog_write(&w, ts, opts.detection_channel, scan_bytes[k], LCMC_SCAN_WIRE_SIZE), 0);
        if (with_bad && k % 4 == 2)
            assert_int_equal(lcmlog_write(&w, ts, opts.detection_channel, scan_bytes[k], 12), 0);
    }
    assert_int_equal(lcmlog_close_write(&w), 0);
}

static uint8_t *read_file(const char *path, size_t *len)
{
    uint8_t *b = fileio_read(path, len);
    assert_non_null(b);
    return b;
}

/* Check a replay output: track lists equal the direct run, status events. */
static void check_output(const char *path, int keep_input, int n_bad)
{
    struct lcmlog_reader r;
    struct lcmlog_event ev;
    assert_int_equal(lcmlog_open_read(&r, path, 1 << 20), 0);
    int k = 0, n_status = 0, n_in = 0;
    static trk_bridge_status_t st;
    while (lcmlog_read(&r, &ev) > 0) {
        if (strcmp(ev.channel, opts.track_channel) == 0) {
            assert_true(k < N_SCANS);
            assert_int_equal(ev.datalen, expect_len[k]);
            assert_memory_equal(ev.data, expect_bytes[k], ev.datalen);
            assert_true(ev.timestamp == scans[k].time_us + 500); /* the input event's time */
            k++;
        } else if (strcmp(ev.channel, opts.status_channel) == 0) {
            assert_true(trk_bridge_status_t_decode(ev.data, 0, (int)ev.datalen, &st) > 0);
            n_status++;
        } else {
            n_in++;
        }
    }
    assert_int_equal(r.truncated, 0);
    assert_true(r.n_corrupt == 0);
    lcmlog_close_read(&r);
    assert_int_equal(k, N_SCANS);
    /* scans every 2 s of log time, status every 1 s: one per scan after the
     * first, plus the final one */
    assert_int_equal(n_status, N_SCANS);
    assert_true(st.n_processed == N_SCANS && st.n_rejected_decode == n_bad);
    assert_int_equal(n_in, keep_input ? 2 * N_SCANS + n_bad : 0);
}

static void test_replay(void **state)
{
    (void)state;
    const char *in = tmp_path("in.lcmlog"), *out1 = tmp_path("out1.lcmlog"),
               *out2 = tmp_path("out2.lcmlog"), *out3 = tmp_path("out3.lcmlog");
    write_input_log(in, 1);
    const int n_bad = (N_SCANS + 1) / 4; /* k = 2, 6, 10, ... */
    struct replay_stats st;
    for (int run = 0; run < 2; run++) {
        struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
        assert_non_null(b);
        assert_int_equal(bridge_replay(b, in, run ? out2 : out1, 0, NULL, &st, err, sizeof err), 0);
        assert_true(st.events == (uint64_t)(2 * N_SCANS + n_bad));
        assert_true(st.scans == (uint64_t)(N_SCANS + n_bad));
        assert_true(b->c.processed == N_SCANS && b->c.by_reason[LCMC_DECODE] == (uint64_t)n_bad);
        bridge_free(b);
    }
    check_output(out1, 0, n_bad);
    size_t l1, l2;
    uint8_t *f1 = read_file(out1, &l1), *f2 = read_file(out2, &l2);
    assert_int_equal(l1, l2);
    assert_memory_equal(f1, f2, l1); /* byte-identical */
    free(f1);
    free(f2);
    /* --keep-input */
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_int_equal(bridge_replay(b, in, out3, 1, NULL, &st, err, sizeof err), 0);
    bridge_free(b);
    check_output(out3, 1, n_bad);
    /* in == out is refused, a missing input is an error */
    b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_int_equal(bridge_replay(b, in, in, 0, NULL, &st, err, sizeof err), -1);
    assert_non_null(strstr(err, "input"));
    assert_int_equal(bridge_replay(b, "/nonexistent/x.lcmlog", out3, 0, NULL, &st, err, sizeof err), -1);
    bridge_free(b);
    remove(in);
    remove(out1);
    remove(out2);
    remove(out3);
}

static void put_be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24), p[1] = (uint8_t)(v >> 16), p[2] = (uint8_t)(v >> 8), p[3] = (uint8_t)v;
}

/* Damaged input logs: a corrupt record header (resynchronised), an oversize
 * record on the detection channel (skipped, counted as decode), a truncated
 * last record (the rest processed). */
static void test_replay_damaged_log(void **state)
{
    (void)state;
    const char *in = tmp_path("dmg.lcmlog"), *out = tmp_path("dmg_out.lcmlog");
    write_input_log(in, 0);
    size_t len;
    uint8_t *f = read_file(in, &len);
    /* record layout: 28-byte header + channel + data. Records alternate
     * OTHER_CHANNEL (28 + 13 + 3 = 44 bytes) and TRK_DETECTIONS
     * (28 + 14 + 12832 bytes). */
    const size_t rec_other = 44, rec_scan = 28 + 14 + LCMC_SCAN_WIRE_SIZE, pair = rec_other + rec_scan;
    assert_int_equal(len, N_SCANS * pair);
    /* scan 3's record: datalen negative (a corrupt header) */
    put_be32(f + 3 * pair + rec_other + 24, 0xFFFFFFF0u);
    /* the last scan's record claims 1 GiB of data: past the end of the file */
    put_be32(f + (N_SCANS - 1) * pair + rec_other + 24, 0x40000000u);
    FILE *w = fopen(in, "wb");
    assert_int_equal(fwrite(f, 1, len, w), len);
    fclose(w);
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    struct replay_stats st;
    assert_int_equal(bridge_replay(b, in, out, 0, NULL, &st, err, sizeof err), 0);
    /* scan 3 lost (its header is corrupt: resync finds the next record), the
     * last record claims 1 GiB: truncated */
    assert_true(st.corrupt == 1);
    assert_true(st.truncated == 1);
    assert_true(st.bytes_skipped > 0);
    assert_true(b->c.processed == N_SCANS - 2);
    assert_true(b->c.rejected == 0);
    bridge_free(b);
    /* the same (scan 3 still corrupt) truncated in the middle of scan 10's data */
    w = fopen(in, "wb");
    assert_int_equal(fwrite(f, 1, 10 * pair + rec_other + 28 + 14 + 500, w), 10 * pair + rec_other + 28 + 14 + 500);
    fclose(w);
    b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_int_equal(bridge_replay(b, in, out, 0, NULL, &st, err, sizeof err), 0);
    assert_true(st.truncated == 1 && st.corrupt == 1);
    assert_true(b->c.processed == 9);
    bridge_free(b);
    /* an oversize record on the detection channel in the middle */
    write_input_log(in, 0);
    {
        struct lcmlog_writer lw;
        assert_int_equal(lcmlog_open_write(&lw, in), 0);
        static uint8_t big[(1 << 20) + 16];
        for (int k = 0; k < 4; k++) {
            assert_int_equal(lcmlog_write(&lw, scans[k].time_us, opts.detection_channel, scan_bytes[k],
                                          LCMC_SCAN_WIRE_SIZE), 0);
            if (k == 1) assert_int_equal(lcmlog_write(&lw, scans[k].time_us, opts.detection_channel, big, sizeof big), 0);
        }
        assert_int_equal(lcmlog_close_write(&lw), 0);
    }
    b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_int_equal(bridge_replay(b, in, out, 0, NULL, &st, err, sizeof err), 0);
    assert_true(st.oversize == 1 && st.truncated == 0);
    assert_true(b->c.processed == 4 && b->c.by_reason[LCMC_DECODE] == 1);
    bridge_free(b);
    free(f);
    remove(in);
    remove(out);
}

/* One log record written byte by byte (the channel may hold NULs). */
static void raw_record(FILE *f, int64_t ts, const char *ch, size_t chlen, const void *data, size_t len)
{
    uint8_t h[28];
    put_be32(h, LCMLOG_SYNC);
    put_be32(h + 4, 0), put_be32(h + 8, 0);
    put_be32(h + 12, (uint32_t)((uint64_t)ts >> 32)), put_be32(h + 16, (uint32_t)ts);
    put_be32(h + 20, (uint32_t)chlen), put_be32(h + 24, (uint32_t)len);
    assert_int_equal(fwrite(h, 1, sizeof h, f), sizeof h);
    assert_int_equal(fwrite(ch, 1, chlen, f), chlen);
    assert_int_equal(fwrite(data, 1, len, f), len);
}

/* "TRK_DETECTIONS\0hidden" is another channel: channels are compared by
 * their full length; --keep-input copies it exactly.
 * (--summarize: tests/lcm_udpm_netns.sh) */
static void test_replay_channel_full_length(void **state)
{
    (void)state;
    const char *in = tmp_path("nul.lcmlog"), *out = tmp_path("nul_out.lcmlog");
    static const char hidden[] = "TRK_DETECTIONS\0hidden";
    FILE *f = fopen(in, "wb");
    assert_non_null(f);
    raw_record(f, scans[0].time_us, hidden, sizeof hidden - 1, scan_bytes[0], LCMC_SCAN_WIRE_SIZE);
    raw_record(f, scans[1].time_us, "TRK_DETECTIONS", 14, scan_bytes[0], LCMC_SCAN_WIRE_SIZE);
    assert_int_equal(fclose(f), 0);
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    struct replay_stats st;
    assert_int_equal(bridge_replay(b, in, out, 1, NULL, &st, err, sizeof err), 0);
    assert_true(st.events == 2 && st.scans == 1);
    assert_true(b->c.received == 1 && b->c.processed == 1);
    bridge_free(b);
    /* the copy keeps the full channel */
    struct lcmlog_reader r;
    struct lcmlog_event ev;
    assert_int_equal(lcmlog_open_read(&r, out, 1 << 20), 0);
    int n_hidden = 0, n_det = 0;
    while (lcmlog_read(&r, &ev) > 0) {
        n_hidden += ev.channellen == sizeof hidden - 1 && memcmp(ev.channel, hidden, sizeof hidden - 1) == 0;
        n_det += lcmlog_channel_is(&ev, "TRK_DETECTIONS");
    }
    lcmlog_close_read(&r);
    assert_int_equal(n_hidden, 1);
    assert_int_equal(n_det, 1);
    remove(in);
    remove(out);
}

/* Log times near INT64_MAX: the next status time saturates instead of
 * overflowing, so no status is due before the end. */
static void test_replay_time_near_int64_max(void **state)
{
    (void)state;
    const char *in = tmp_path("tmax.lcmlog"), *out = tmp_path("tmax_out.lcmlog");
    FILE *f = fopen(in, "wb");
    assert_non_null(f);
    for (int i = 10; i >= 1; i--) raw_record(f, INT64_MAX - i, "OTHER", 5, "x", 1);
    assert_int_equal(fclose(f), 0);
    struct bridge_opts o = opts;
    o.status_period_s = 1;
    struct bridge *b = bridge_new(&cfg, &o, err, sizeof err);
    struct replay_stats st;
    assert_int_equal(bridge_replay(b, in, out, 0, NULL, &st, err, sizeof err), 0);
    assert_true(st.events == 10);
    assert_true(st.written == 1); /* the final status only */
    bridge_free(b);
    remove(in);
    remove(out);
}

/* Inputs that are no log end with a clear error instead of spinning or
 * "0 events": zeros, a first record cut short, a
 * directory and an empty file (neither leaving an output log); /dev/zero stops at the resynchronisation bound or at once on
 * the stop flag. (--summarize and SIGTERM: tests/lcm_udpm_netns.sh) */
static void test_not_a_log(void **state)
{
    (void)state;
    const char *zeros = tmp_path("zeros.lcmlog"), *cut = tmp_path("cut.lcmlog"),
               *out = tmp_path("na_out.lcmlog");
    FILE *f = fopen(zeros, "wb");
    assert_non_null(f);
    static uint8_t block[1 << 16];
    for (int i = 0; i < 48; i++) assert_int_equal(fwrite(block, 1, sizeof block, f), sizeof block); /* 3 MiB */
    assert_int_equal(fclose(f), 0);
    f = fopen(cut, "wb");
    assert_non_null(f);
    raw_record(f, 1, "TRK_DETECTIONS", 14, scan_bytes[0], LCMC_SCAN_WIRE_SIZE);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(truncate(cut, 28 + 14 + 100), 0); /* the only record cut short */
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    struct replay_stats st;
    const char *not_logs[] = {zeros, cut};
    for (int i = 0; i < 2; i++) {
        assert_int_equal(bridge_replay(b, not_logs[i], out, 0, NULL, &st, err, sizeof err), -1);
        assert_non_null(strstr(err, "not an LCM log"));
        assert_non_null(strstr(err, not_logs[i]));
    }
    /* /dev/zero: the bounded resync ends it */
    assert_int_equal(bridge_replay(b, "/dev/zero", out, 0, NULL, &st, err, sizeof err), -1);
    assert_non_null(strstr(err, "no LCM log record found"));
    assert_true(st.bytes_skipped > LCMLOG_MAX_RESYNC - 4);
    /* a directory is not a log either, and leaves no output log */
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    remove(out);
    assert_int_equal(bridge_replay(b, dir, out, 0, NULL, &st, err, sizeof err), -1);
    assert_non_null(strstr(err, "Is a directory"));
    assert_int_equal(access(out, F_OK), -1);
    /* nor is an empty file (it holds no record): an error, no output */
    f = fopen(cut, "wb");
    assert_non_null(f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(bridge_replay(b, cut, out, 0, NULL, &st, err, sizeof err), -1);
    assert_non_null(strstr(err, "empty"));
    assert_non_null(strstr(err, cut));
    assert_int_equal(access(out, F_OK), -1);
    bridge_free(b);
    /* the reader: a lower bound, and the stop flag checked while skipping */
    struct lcmlog_reader r;
    struct lcmlog_event ev;
    assert_int_equal(lcmlog_open_read(&r, "/dev/zero", 1024), 0);
    r.max_resync = 1000;
    assert_int_equal(lcmlog_read(&r, &ev), -1);
    assert_int_equal(r.error, LCMLOG_E_NO_SYNC);
    assert_true(r.n_events == 0);
    lcmlog_close_read(&r);
    volatile sig_atomic_t stop = 1;
    assert_int_equal(lcmlog_open_read(&r, "/dev/zero", 1024), 0);
    r.stop = &stop;
    assert_int_equal(lcmlog_read(&r, &ev), -1);
    assert_int_equal(r.error, LCMLOG_E_STOPPED);
    lcmlog_close_read(&r);
    /* an empty file is an empty log */
    f = fopen(cut, "wb");
    assert_non_null(f);
    assert_int_equal(fclose(f), 0);
    assert_int_equal(lcmlog_open_read(&r, cut, 1024), 0);
    assert_int_equal(lcmlog_read(&r, &ev), 0);
    lcmlog_close_read(&r);
    remove(zeros);
    remove(cut);
    remove(out);
}

/* Our log files and liblcm's agree in both directions. */
static void test_log_compat_with_liblcm(void **state)
{
    (void)state;
    const char *a = tmp_path("ours.lcmlog"), *c = tmp_path("theirs.lcmlog");
    struct lcmlog_writer w;
    assert_int_equal(lcmlog_open_write(&w, a), 0);
    for (int k = 0; k < 3; k++)
        assert_int_equal(lcmlog_write(&w, 1000 + k, "TRK_DETECTIONS", scan_bytes[k], LCMC_SCAN_WIRE_SIZE), 0);
    assert_int_equal(lcmlog_close_write(&w), 0);
    lcm_eventlog_t *el = lcm_eventlog_create(a, "r");
    assert_non_null(el);
    for (int k = 0; k < 3; k++) {
        lcm_eventlog_event_t *ev = lcm_eventlog_read_next_event(el);
        assert_non_null(ev);
        assert_true(ev->eventnum == k && ev->timestamp == 1000 + k);
        assert_string_equal(ev->channel, "TRK_DETECTIONS");
        assert_int_equal(ev->datalen, LCMC_SCAN_WIRE_SIZE);
        assert_memory_equal(ev->data, scan_bytes[k], LCMC_SCAN_WIRE_SIZE);
        lcm_eventlog_free_event(ev);
    }
    assert_null(lcm_eventlog_read_next_event(el));
    lcm_eventlog_destroy(el);
    el = lcm_eventlog_create(c, "w");
    assert_non_null(el);
    for (int k = 0; k < 3; k++) {
        lcm_eventlog_event_t ev;
        ev.timestamp = 1000 + k;
        ev.channel = (char *)"TRK_DETECTIONS";
        ev.channellen = 14;
        ev.data = scan_bytes[k];
        ev.datalen = LCMC_SCAN_WIRE_SIZE;
        assert_int_equal(lcm_eventlog_write_event(el, &ev), 0);
    }
    lcm_eventlog_destroy(el);
    size_t la, lc2;
    uint8_t *fa = read_file(a, &la), *fc = read_file(c, &lc2);
    assert_int_equal(la, lc2);
    assert_memory_equal(fa, fc, la); /* the same bytes */
    free(fa);
    free(fc);
    remove(a);
    remove(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_handle_matches_direct),
        cmocka_unit_test(test_bad_messages_counted_and_harmless),
        cmocka_unit_test(test_bad_detection_dropped_alone),
        cmocka_unit_test(test_seq_gaps),
        cmocka_unit_test(test_below_threshold_counted),
        cmocka_unit_test(test_rate_limited_log),
        cmocka_unit_test(test_refuses_bad_config),
        cmocka_unit_test(test_other_methods),
        cmocka_unit_test(test_memq_round_trip),
        cmocka_unit_test(test_replay),
        cmocka_unit_test(test_replay_damaged_log),
        cmocka_unit_test(test_replay_channel_full_length),
        cmocka_unit_test(test_replay_time_near_int64_max),
        cmocka_unit_test(test_not_a_log),
        cmocka_unit_test(test_log_compat_with_liblcm),
    };
    return trk_run_tests("lcm_bridge", tests, setup, teardown);
}
