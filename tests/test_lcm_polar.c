/* test_lcm_polar.c - polar detection scans over LCM (detection_scan_polar_t):
 *   - the message round trip is exact (struct -> message -> bytes -> struct,
 *     and the bytes again), its wire size constant
 *   - every header refusal gives its reason and leaves the output untouched
 *     (truncation at every length, trailing bytes, the Cartesian type,
 *     count, utime, sensor unknown or not polar, has_pose, a pose not
 *     finite); a bad detection is dropped alone and counted
 *   - a Cartesian scan copied after a polar one carries no polar part
 *   - the bridge hands the tracker what a direct call gets (scan contents,
 *     pose included) and answers as the tracker does to the direct call;
 *     its replay of a log with both channels and hostile messages counts
 *     each by cause; live, it subscribes to the polar channel (memq://)
 * The scans are built here: targets on straight lines seen from a platform
 * moving north-east, range and bearing exact. */
#define _POSIX_C_SOURCE 200809L /* getpid */
#include <unistd.h>

#include "trk_test.h"

#include <lcm/lcm.h>

#include "bridge.h"
#include "lcm_log.h"
#include "transport.h"

#define N_SCANS 12
#define N_TGT 3

static trk_detection_scan_polar_t msg, msg2, work;
static trk_detection_scan_t cart_msg, cart_work;
static struct lcmc_scan out, out2;
static uint8_t wire[LCMC_POLAR_SCAN_WIRE_SIZE + 16], wire2[LCMC_POLAR_SCAN_WIRE_SIZE + 16];
static uint8_t cart_wire[LCMC_SCAN_WIRE_SIZE];
static struct trk_sensor_params sensors[2]; /* 0 polar, 1 Cartesian */
static struct trk_scan scans[N_SCANS];
static struct trk_polar_detection scan_det[N_SCANS][N_TGT + 2];
static uint8_t scan_bytes[N_SCANS][LCMC_POLAR_SCAN_WIRE_SIZE];
static struct trk_tracker direct;
static struct tcfg cfg;
static struct bridge_opts opts;
static char err[512];

/* A valid message: 3 detections (one with amplitude), a pose. */
static void make_msg(trk_detection_scan_polar_t *m)
{
    memset(m, 0, sizeof *m);
    m->utime = 1700000000123456LL;
    m->sensor_id = 0;
    m->seq = 7;
    m->has_pose = 1;
    m->pose_x_m = 250.5;
    m->pose_y_m = -125.25;
    m->pose_heading_rad = 0.75;
    m->n_detections = 3;
    m->detections[0].range_m = 1000.5;
    m->detections[0].bearing_rad = -0.25;
    m->detections[1].range_m = 12.125;
    m->detections[1].bearing_rad = 3.0;
    m->detections[1].has_amplitude = 1;
    m->detections[1].amplitude = 4.5;
    m->detections[2].range_m = 3e3;
    m->detections[2].bearing_rad = -6.25;
}

static size_t encode(const trk_detection_scan_polar_t *m, uint8_t *buf)
{
    const int n = trk_detection_scan_polar_t_encode(buf, 0, LCMC_POLAR_SCAN_WIRE_SIZE, m);
    assert_int_equal(n, LCMC_POLAR_SCAN_WIRE_SIZE);
    return (size_t)n;
}

/* Decode len bytes from an exactly sized heap copy (ASan sees an over-read). */
static enum lcmc_reason from_bytes(const uint8_t *src, size_t len)
{
    uint8_t *b = malloc(len ? len : 1);
    assert_non_null(b);
    memcpy(b, src, len);
    const enum lcmc_reason r = lcmc_polar_scan_from_bytes(b, len, sensors, 2, &work, &out, NULL, 0);
    free(b);
    return r;
}

static int setup_sensors(void **state)
{
    (void)state;
    memset(sensors, 0, sizeof sensors);
    sensors[0].kind = TRK_SENSOR_POLAR;
    sensors[1].kind = TRK_SENSOR_CARTESIAN;
    return 0;
}

static void test_wire_size(void **state)
{
    (void)state;
    make_msg(&msg);
    assert_int_equal(trk_detection_scan_polar_t_encoded_size(&msg), LCMC_POLAR_SCAN_WIRE_SIZE);
    assert_int_equal(TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS, 256);
    /* its own fingerprint: neither type decodes as the other */
    assert_true(__trk_detection_scan_polar_t_get_hash() != __trk_detection_scan_t_get_hash());
}

static void test_round_trip(void **state)
{
    (void)state;
    make_msg(&msg);
    const size_t n = encode(&msg, wire);
    char detail[128];
    assert_int_equal(lcmc_polar_scan_from_bytes(wire, n, sensors, 2, &work, &out, detail, sizeof detail), LCMC_OK);
    assert_string_equal(detail, "");
    assert_true(out.scan.time_us == 1700000000123456LL);
    assert_int_equal(out.scan.sensor_id, 0);
    assert_true(out.seq == 7);
    assert_int_equal(out.scan.n_detections, 3);
    assert_int_equal(out.n_msg_detections, 3);
    assert_null(out.scan.detections);
    assert_ptr_equal(out.scan.polar, out.polar);
    assert_int_equal(out.scan.has_pose, 1);
    assert_true(out.scan.pose.x_m == TRK_REAL_C(250.5) && out.scan.pose.y_m == TRK_REAL_C(-125.25));
    assert_true(out.scan.pose.heading_rad == TRK_REAL_C(0.75));
    assert_true(out.polar[0].range_m == TRK_REAL_C(1000.5) && out.polar[0].bearing_rad == TRK_REAL_C(-0.25));
    assert_int_equal(out.polar[0].has_amplitude, 0);
    assert_true(out.polar[1].range_m == TRK_REAL_C(12.125) && out.polar[1].bearing_rad == TRK_REAL_C(3.0));
    assert_int_equal(out.polar[1].has_amplitude, 1);
    assert_true(out.polar[1].amplitude == TRK_REAL_C(4.5));
    assert_true(out.polar[2].range_m == TRK_REAL_C(3e3) && out.polar[2].bearing_rad == TRK_REAL_C(-6.25));
    assert_true(out.n_dropped_field == 0 && out.n_dropped_nonfinite == 0);
    /* back: the same message, byte for byte */
    assert_int_equal(lcmc_polar_scan_to_msg(&out.scan, out.seq, &msg2), LCMC_OK);
    encode(&msg2, wire2);
    assert_memory_equal(wire, wire2, LCMC_POLAR_SCAN_WIRE_SIZE);
    /* without a pose: the pose fields are ignored (NaN included) and zero on the way back */
    msg.has_pose = 0;
    msg.pose_x_m = NAN;
    msg.pose_heading_rad = INFINITY;
    encode(&msg, wire);
    assert_int_equal(from_bytes(wire, LCMC_POLAR_SCAN_WIRE_SIZE), LCMC_OK);
    assert_int_equal(out.scan.has_pose, 0);
    assert_true(out.scan.pose.x_m == 0 && out.scan.pose.heading_rad == 0);
    assert_int_equal(lcmc_polar_scan_to_msg(&out.scan, out.seq, &msg2), LCMC_OK);
    assert_true(msg2.has_pose == 0 && msg2.pose_x_m == 0 && msg2.pose_heading_rad == 0);
}

/* A refused message leaves out as it was. */
static void expect_refused(const trk_detection_scan_polar_t *m, enum lcmc_reason want, const char *word)
{
    char detail[160];
    memset(&out, 0x5a, sizeof out);
    memcpy(&out2, &out, sizeof out);
    assert_int_equal(lcmc_polar_scan_from_msg(m, sensors, 2, &out, detail, sizeof detail), want);
    assert_memory_equal(&out, &out2, sizeof out);
    assert_non_null(strstr(detail, word));
}

static void test_header_refusals(void **state)
{
    (void)state;
    make_msg(&msg);
    msg.n_detections = -1;
    expect_refused(&msg, LCMC_COUNT, "n_detections");
    msg.n_detections = 257;
    expect_refused(&msg, LCMC_COUNT, "n_detections");
    make_msg(&msg);
    msg.utime = -1;
    expect_refused(&msg, LCMC_FIELD, "utime");
    msg.utime = TRK_TIME_US_MAX + 1;
    expect_refused(&msg, LCMC_FIELD, "utime");
    make_msg(&msg);
    msg.sensor_id = 2;
    expect_refused(&msg, LCMC_SENSOR, "configured 0 .. 1");
    msg.sensor_id = -1;
    expect_refused(&msg, LCMC_SENSOR, "sensor_id");
    msg.sensor_id = 1; /* configured, but Cartesian */
    expect_refused(&msg, LCMC_SENSOR, "not a polar sensor");
    make_msg(&msg);
    msg.has_pose = 2;
    expect_refused(&msg, LCMC_FIELD, "has_pose");
    make_msg(&msg);
    msg.pose_x_m = NAN;
    expect_refused(&msg, LCMC_FIELD, "pose");
    make_msg(&msg);
    msg.pose_y_m = -INFINITY;
    expect_refused(&msg, LCMC_FIELD, "pose");
    make_msg(&msg);
    msg.pose_heading_rad = NAN;
    expect_refused(&msg, LCMC_FIELD, "pose");
    msg.pose_heading_rad = 1.5e6;
    expect_refused(&msg, LCMC_FIELD, "pose");
    msg.pose_heading_rad = -1e6; /* the limit itself is a heading */
    assert_int_equal(lcmc_polar_scan_from_msg(&msg, sensors, 2, &out, NULL, 0), LCMC_OK);
    if (TRK_REAL_IS_FLOAT) { /* beyond float: not representable */
        make_msg(&msg);
        msg.pose_x_m = 1e39;
        expect_refused(&msg, LCMC_FIELD, "pose");
    }
}

static void test_decode_refusals(void **state)
{
    (void)state;
    make_msg(&msg);
    encode(&msg, wire);
    for (size_t len = 0; len < LCMC_POLAR_SCAN_WIRE_SIZE; len++) assert_int_equal(from_bytes(wire, len), LCMC_DECODE);
    assert_int_equal(from_bytes(wire, LCMC_POLAR_SCAN_WIRE_SIZE + 1), LCMC_DECODE); /* trailing byte */
    wire[3] ^= 1; /* another type's hash */
    assert_int_equal(from_bytes(wire, LCMC_POLAR_SCAN_WIRE_SIZE), LCMC_DECODE);
    /* a Cartesian scan is refused by the polar decoder and the other way round */
    memset(&cart_msg, 0, sizeof cart_msg);
    cart_msg.utime = 5;
    assert_int_equal(trk_detection_scan_t_encode(cart_wire, 0, LCMC_SCAN_WIRE_SIZE, &cart_msg), LCMC_SCAN_WIRE_SIZE);
    assert_int_equal(lcmc_polar_scan_from_bytes(cart_wire, LCMC_POLAR_SCAN_WIRE_SIZE, sensors, 2, &work, &out, NULL, 0),
                     LCMC_DECODE);
    assert_int_equal(from_bytes(cart_wire, LCMC_SCAN_WIRE_SIZE), LCMC_DECODE);
    make_msg(&msg);
    encode(&msg, wire);
    assert_int_equal(lcmc_scan_from_bytes(wire, LCMC_POLAR_SCAN_WIRE_SIZE, 2, &cart_work, &out, NULL, 0), LCMC_DECODE);
    char detail[96];
    assert_int_equal(lcmc_polar_scan_from_bytes(NULL, 0, sensors, 2, &work, &out, detail, sizeof detail), LCMC_DECODE);
    assert_non_null(strstr(detail, "6457"));
}

static void test_bad_detections_dropped_alone(void **state)
{
    (void)state;
    make_msg(&msg);
    msg.n_detections = 10;
    for (int i = 0; i < 10; i++) {
        msg.detections[i].range_m = 100 + i;
        msg.detections[i].bearing_rad = 0.1 * i;
    }
    msg.detections[1].range_m = NAN;             /* nonfinite */
    msg.detections[2].bearing_rad = INFINITY;    /* nonfinite */
    msg.detections[3].range_m = 0;               /* field: range > 0 */
    msg.detections[4].range_m = TRK_REAL_IS_FLOAT ? 1e-300 : -5; /* field: not > 0 as a trk_real */
    msg.detections[5].bearing_rad = 6.3;         /* field: beyond a turn */
    msg.detections[6].has_amplitude = 2;         /* field: boolean */
    msg.detections[7].has_amplitude = 1;         /* field: negative amplitude */
    msg.detections[7].amplitude = -1;
    msg.detections[8].has_amplitude = 1;         /* nonfinite amplitude */
    msg.detections[8].amplitude = NAN;
    msg.detections[9].amplitude = NAN;           /* unused: kept */
    char detail[160];
    assert_int_equal(lcmc_polar_scan_from_msg(&msg, sensors, 2, &out, detail, sizeof detail), LCMC_OK);
    assert_non_null(strstr(detail, "detections[1]")); /* the first dropped one */
    assert_int_equal(out.n_msg_detections, 10);
    assert_int_equal(out.n_dropped_nonfinite, 3);
    assert_int_equal(out.n_dropped_field, 5);
    assert_int_equal(out.scan.n_detections, 2);
    assert_true(out.polar[0].range_m == 100 && out.polar[0].bearing_rad == 0);
    assert_true(out.polar[1].range_m == 109 && out.polar[1].bearing_rad == TRK_REAL_C(0.9) &&
                out.polar[1].amplitude == 0 && out.polar[1].has_amplitude == 0);
    /* the full message, one bad detection among 256: 255 kept in order */
    make_msg(&msg);
    msg.n_detections = 256;
    for (int i = 0; i < 256; i++) {
        msg.detections[i].range_m = 1 + i;
        msg.detections[i].bearing_rad = -1;
    }
    msg.detections[128].bearing_rad = NAN;
    assert_int_equal(lcmc_polar_scan_from_msg(&msg, sensors, 2, &out, NULL, 0), LCMC_OK);
    assert_int_equal(out.scan.n_detections, 255);
    assert_true(out.polar[127].range_m == 128 && out.polar[128].range_m == 130 && out.polar[254].range_m == 256);
}

static void test_to_msg_refusals(void **state)
{
    (void)state;
    struct trk_scan s;
    memset(&s, 0, sizeof s);
    s.n_detections = 257;
    s.polar = scan_det[0];
    assert_int_equal(lcmc_polar_scan_to_msg(&s, 0, &msg), LCMC_COUNT);
    s.n_detections = 1;
    s.time_us = -1;
    assert_int_equal(lcmc_polar_scan_to_msg(&s, 0, &msg), LCMC_FIELD);
    s.time_us = 0;
    s.polar = NULL;
    assert_int_equal(lcmc_polar_scan_to_msg(&s, 0, &msg), LCMC_FIELD);
    s.n_detections = 0; /* an empty scan needs no array */
    assert_int_equal(lcmc_polar_scan_to_msg(&s, 0, &msg), LCMC_OK);
}

static void test_cartesian_after_polar(void **state)
{
    (void)state;
    make_msg(&msg);
    assert_int_equal(lcmc_polar_scan_from_msg(&msg, sensors, 2, &out, NULL, 0), LCMC_OK);
    memset(&cart_msg, 0, sizeof cart_msg);
    cart_msg.utime = 9;
    cart_msg.sensor_id = 1;
    cart_msg.n_detections = 1;
    cart_msg.detections[0].x_m = 3;
    assert_int_equal(lcmc_scan_from_msg(&cart_msg, 2, &out, NULL, 0), LCMC_OK);
    assert_null(out.scan.polar);
    assert_int_equal(out.scan.has_pose, 0);
    assert_ptr_equal(out.scan.detections, out.det);
    assert_true(out.det[0].x_m == 3);
}

/* ------------------------------------------------------------------ the bridge */

/* Scans of sensor 0 (polar): N_TGT targets on straight lines and a clutter
 * detection, from a platform moving north-east at 3 m/s, turning its
 * heading; exact range and bearing, one scan without a pose. */
static void make_scans(void)
{
    for (int k = 0; k < N_SCANS; k++) {
        const double t = 2.0 * k;
        struct trk_scan *s = &scans[k];
        memset(s, 0, sizeof *s);
        s->time_us = 1700000000000000LL + (int64_t)k * 2000000;
        s->sensor_id = 0;
        s->has_pose = k != 5;
        s->pose.x_m = (trk_real)(100 + 2.1 * t);
        s->pose.y_m = (trk_real)(-50 + 2.1 * t);
        s->pose.heading_rad = (trk_real)(0.7 + 0.01 * k);
        if (!s->has_pose) memset(&s->pose, 0, sizeof s->pose);
        /* without a pose the sensor's configured one (make_config) places the scan */
        const double px = s->has_pose ? (double)s->pose.x_m : 100, py = s->has_pose ? (double)s->pose.y_m : -50;
        const double h = s->has_pose ? (double)s->pose.heading_rad : (double)TRK_REAL_C(0.7);
        size_t n = 0;
        for (int i = 0; i < N_TGT; i++) {
            const double x = 400 + 300 * i + 4 * t, y = 600 - 100 * i + 2 * t;
            scan_det[k][n].range_m = (trk_real)hypot(x - px, y - py);
            scan_det[k][n].bearing_rad = (trk_real)(atan2(x - px, y - py) - h);
            scan_det[k][n].has_amplitude = (uint8_t)(i == 1);
            scan_det[k][n].amplitude = (trk_real)(i == 1 ? 3.25 : 0);
            n++;
        }
        scan_det[k][n].range_m = (trk_real)(50 + 37 * k);
        scan_det[k][n].bearing_rad = (trk_real)(-1 + 0.15 * k);
        n++;
        s->n_detections = n;
        s->polar = scan_det[k];
        assert_int_equal(lcmc_polar_scan_to_msg(s, 100 + k, &msg), LCMC_OK);
        assert_int_equal(trk_detection_scan_polar_t_encode(scan_bytes[k], 0, LCMC_POLAR_SCAN_WIRE_SIZE, &msg),
                         LCMC_POLAR_SCAN_WIRE_SIZE);
    }
}

static void make_config(void)
{
    tcfg_defaults(&cfg);
    static const char *const kv[][2] = {{"sensors", "2"},
                                        {"sensor.0.kind", "polar"},
                                        {"sensor.0.sigma_range_m", "2.5"},
                                        {"sensor.0.sigma_bearing_rad", "0.004"},
                                        {"sensor.0.pose.x_m", "100"},
                                        {"sensor.0.pose.y_m", "-50"},
                                        {"sensor.0.pose.heading_rad", "0.7"},
                                        {"sensor.0.pd_profile", "0:0.95, 1500:0.6, 3000:0.2"},
                                        {"sensor.0.coverage.max_range_m", "3000"},
                                        {"sensor.0.clutter_density_per_m2", "1e-6"},
                                        {"sensor.1.clutter_density_per_m2", "1e-6"},
                                        {"confirm", "mn"},
                                        {"confirm.mn.m", "2"},
                                        {"confirm.mn.n", "3"}};
    for (size_t i = 0; i < sizeof kv / sizeof kv[0]; i++)
        assert_int_equal(tcfg_set(&cfg, kv[i][0], kv[i][1], err, sizeof err), 0);
    bridge_opts_defaults(&opts);
    opts.quiet = 1;
}

static int setup_bridge(void **state)
{
    setup_sensors(state);
    make_scans();
    make_config();
    return 0;
}

/* The direct run's parameters: those the bridge gives its tracker. */
static void direct_init(void)
{
    struct trk_tracker_params p;
    tcfg_params_rt(&cfg, NULL, &p);
    assert_int_equal(p.sensor[0].kind, TRK_SENSOR_POLAR);
    assert_true(p.sensor[0].sigma_range_m == TRK_REAL_C(2.5));
    assert_int_equal(p.sensor[0].pd_profile.n, 3);
    assert_true(p.sensor[0].coverage.max_range_m == 3000);
    assert_int_equal(trk_tracker_init(&direct, &p), TRK_OK);
}

/* The scan the bridge handed its tracker is the direct one. */
static void same_scan(const struct trk_scan *got, const struct trk_scan *want)
{
    assert_true(got->time_us == want->time_us);
    assert_int_equal(got->sensor_id, want->sensor_id);
    assert_int_equal(got->n_detections, want->n_detections);
    assert_null(got->detections);
    assert_non_null(got->polar);
    assert_int_equal(got->has_pose, want->has_pose);
    if (want->has_pose) {
        assert_true(got->pose.x_m == want->pose.x_m && got->pose.y_m == want->pose.y_m);
        assert_true(got->pose.heading_rad == want->pose.heading_rad);
    }
    for (size_t i = 0; i < want->n_detections; i++) {
        assert_true(got->polar[i].range_m == want->polar[i].range_m);
        assert_true(got->polar[i].bearing_rad == want->polar[i].bearing_rad);
        assert_int_equal(got->polar[i].has_amplitude, want->polar[i].has_amplitude);
        assert_true(got->polar[i].amplitude == want->polar[i].amplitude);
    }
}

static void test_bridge_matches_direct(void **state)
{
    (void)state;
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    direct_init();
    static trk_track_list_t want;
    static uint8_t want_bytes[1 << 16];
    uint64_t accepted = 0;
    for (int k = 0; k < N_SCANS; k++) {
        const void *o;
        size_t len;
        const enum lcmc_reason r = bridge_handle_polar(b, scan_bytes[k], LCMC_POLAR_SCAN_WIRE_SIZE, k, &o, &len);
        same_scan(&b->scan.scan, &scans[k]);
        assert_true(b->scan.seq == 100 + k);
        struct trk_scan_report rep;
        const trk_status st = trk_tracker_process_scan(&direct, &scans[k], &rep);
        assert_int_equal(r, lcmc_reason_of_status(st)); /* the same answer */
        if (st != TRK_OK) continue;
        accepted++;
        lcmc_tracks_to_msg(&direct, &scans[k], 100 + k, &rep, &want);
        lcmc_count_dropped(&b->scan, &want);
        const int n = trk_track_list_t_encode(want_bytes, 0, (int)sizeof want_bytes, &want);
        assert_int_equal((size_t)n, len);
        assert_memory_equal(o, want_bytes, len);
    }
    assert_true(b->c.received == N_SCANS && b->c.processed == accepted);
    assert_true(b->c.rejected == N_SCANS - accepted);
    bridge_free(b);
}

static void test_bridge_refuses(void **state)
{
    (void)state;
    /* the two channels must differ */
    struct bridge_opts o = opts;
    strcpy(o.polar_detection_channel, o.detection_channel);
    assert_null(bridge_new(&cfg, &o, err, sizeof err));
    assert_non_null(strstr(err, "polar_detection_channel"));
    /* "" turns the polar channel off */
    char e2[128];
    assert_int_equal(bridge_opts_set(&o, "polar_detection_channel", "", e2, sizeof e2), 0);
    assert_string_equal(o.polar_detection_channel, "");
    assert_int_equal(bridge_opts_set(&o, "polar_detection_chanel", "X", e2, sizeof e2), 1);
    assert_string_equal(e2, "polar_detection_channel");
    /* a polar scan of the Cartesian sensor 1, a pose that is not finite */
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    const void *ob;
    size_t len;
    assert_int_equal(trk_detection_scan_polar_t_decode(scan_bytes[0], 0, LCMC_POLAR_SCAN_WIRE_SIZE, &msg),
                     LCMC_POLAR_SCAN_WIRE_SIZE);
    msg.sensor_id = 1;
    encode(&msg, wire);
    assert_int_equal(bridge_handle_polar(b, wire, LCMC_POLAR_SCAN_WIRE_SIZE, 0, &ob, &len), LCMC_SENSOR);
    msg.sensor_id = 0;
    msg.pose_heading_rad = NAN;
    encode(&msg, wire);
    assert_int_equal(bridge_handle_polar(b, wire, LCMC_POLAR_SCAN_WIRE_SIZE, 0, &ob, &len), LCMC_FIELD);
    /* a polar message on the Cartesian path, and the other way round */
    assert_int_equal(bridge_handle(b, scan_bytes[0], LCMC_POLAR_SCAN_WIRE_SIZE, 0, &ob, &len), LCMC_DECODE);
    memset(&cart_msg, 0, sizeof cart_msg);
    assert_int_equal(trk_detection_scan_t_encode(cart_wire, 0, LCMC_SCAN_WIRE_SIZE, &cart_msg), LCMC_SCAN_WIRE_SIZE);
    assert_int_equal(bridge_handle_polar(b, cart_wire, LCMC_SCAN_WIRE_SIZE, 0, &ob, &len), LCMC_DECODE);
    assert_true(b->c.received == 4 && b->c.rejected == 4 && b->c.processed == 0);
    assert_true(b->c.by_reason[LCMC_SENSOR] == 1 && b->c.by_reason[LCMC_FIELD] == 1 &&
                b->c.by_reason[LCMC_DECODE] == 2);
    bridge_free(b);
}

/* Live: the bridge subscribes to the polar channel too (memq://). */
static void test_memq_polar(void **state)
{
    (void)state;
    lcm_t *lc = lcm_create("memq://");
    assert_non_null(lc);
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    struct bridge_live live;
    assert_int_equal(bridge_live_attach(&live, lc, b), 0);
    assert_non_null(live.sub_polar);
    for (int k = 0; k < 3; k++)
        assert_int_equal(lcm_publish(lc, opts.polar_detection_channel, scan_bytes[k], LCMC_POLAR_SCAN_WIRE_SIZE), 0);
    assert_int_equal(lcm_publish(lc, opts.polar_detection_channel, scan_bytes[3], 50), 0); /* truncated */
    while (lcm_handle_timeout(lc, 0) > 0) {
    }
    assert_true(b->c.received == 4 && b->c.by_reason[LCMC_DECODE] == 1);
    same_scan(&b->scan.scan, &scans[2]); /* the last good one */
    bridge_live_detach(&live);
    assert_null(live.sub_polar);
    bridge_free(b);
    /* without the polar channel: no subscription */
    struct bridge_opts o = opts;
    o.polar_detection_channel[0] = 0;
    b = bridge_new(&cfg, &o, err, sizeof err);
    assert_non_null(b);
    assert_int_equal(bridge_live_attach(&live, lc, b), 0);
    assert_null(live.sub_polar);
    assert_int_equal(lcm_publish(lc, opts.polar_detection_channel, scan_bytes[0], LCMC_POLAR_SCAN_WIRE_SIZE), 0);
    while (lcm_handle_timeout(lc, 0) > 0) {
    }
    assert_true(b->c.received == 0);
    bridge_live_detach(&live);
    bridge_free(b);
    lcm_destroy(lc);
}

static const char *tmp_path(const char *name)
{
    static char paths[4][256];
    static int next;
    char *p = paths[next++ % 4];
    const char *dir = getenv("TMPDIR");
    snprintf(p, 256, "%s/trk_test_lcm_polar_%ld_%s", dir ? dir : "/tmp", (long)getpid(), name);
    return p;
}

/* A log with the polar scans on their channel, a Cartesian scan of sensor 1
 * after each, and hostile polar messages: truncated, garbage, a Cartesian
 * type on the polar channel, a scan of the Cartesian sensor. */
static void test_replay(void **state)
{
    (void)state;
    const char *in = tmp_path("in.lcmlog"), *outp = tmp_path("out.lcmlog");
    struct lcmlog_writer w;
    assert_int_equal(lcmlog_open_write(&w, in), 0);
    int n_bad = 0;
    for (int k = 0; k < N_SCANS; k++) {
        const int64_t ts = scans[k].time_us + 100;
        assert_int_equal(lcmlog_write(&w, ts, opts.polar_detection_channel, scan_bytes[k], LCMC_POLAR_SCAN_WIRE_SIZE),
                         0);
        memset(&cart_msg, 0, sizeof cart_msg);
        cart_msg.utime = scans[k].time_us + 1000;
        cart_msg.sensor_id = 1;
        cart_msg.seq = k;
        assert_int_equal(trk_detection_scan_t_encode(cart_wire, 0, LCMC_SCAN_WIRE_SIZE, &cart_msg),
                         LCMC_SCAN_WIRE_SIZE);
        assert_int_equal(lcmlog_write(&w, ts + 1, opts.detection_channel, cart_wire, LCMC_SCAN_WIRE_SIZE), 0);
        if (k % 4 == 1) {
            const uint8_t junk[40] = {1, 2, 3};
            assert_int_equal(lcmlog_write(&w, ts + 2, opts.polar_detection_channel, scan_bytes[k], 100), 0);
            assert_int_equal(lcmlog_write(&w, ts + 2, opts.polar_detection_channel, junk, sizeof junk), 0);
            assert_int_equal(lcmlog_write(&w, ts + 2, opts.polar_detection_channel, cart_wire, LCMC_SCAN_WIRE_SIZE), 0);
            n_bad += 3;
        }
    }
    assert_int_equal(lcmlog_close_write(&w), 0);
    /* what the direct run accepts */
    direct_init();
    uint64_t accepted = 0;
    for (int k = 0; k < N_SCANS; k++) {
        struct trk_scan_report rep;
        accepted += trk_tracker_process_scan(&direct, &scans[k], &rep) == TRK_OK;
    }
    struct bridge *b = bridge_new(&cfg, &opts, err, sizeof err);
    assert_non_null(b);
    struct replay_stats st;
    assert_int_equal(bridge_replay(b, in, outp, 0, NULL, &st, err, sizeof err), 0);
    assert_true(st.scans == (uint64_t)(2 * N_SCANS + n_bad));
    assert_true(b->c.received == st.scans);
    assert_true(b->c.by_reason[LCMC_DECODE] == (uint64_t)n_bad);
    /* the Cartesian sensor's empty scans are all processed, the polar ones as directly */
    assert_true(b->c.processed == N_SCANS + accepted);
    assert_true(b->c.rejected == (uint64_t)n_bad + (N_SCANS - accepted));
    bridge_free(b);
    /* without the polar channel its messages are not scans */
    struct bridge_opts o = opts;
    o.polar_detection_channel[0] = 0;
    b = bridge_new(&cfg, &o, err, sizeof err);
    assert_non_null(b);
    assert_int_equal(bridge_replay(b, in, outp, 0, NULL, &st, err, sizeof err), 0);
    assert_true(st.scans == N_SCANS && b->c.processed == N_SCANS);
    bridge_free(b);
    remove(in);
    remove(outp);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_wire_size, setup_sensors),
        cmocka_unit_test_setup(test_round_trip, setup_sensors),
        cmocka_unit_test_setup(test_header_refusals, setup_sensors),
        cmocka_unit_test_setup(test_decode_refusals, setup_sensors),
        cmocka_unit_test_setup(test_bad_detections_dropped_alone, setup_sensors),
        cmocka_unit_test_setup(test_to_msg_refusals, setup_sensors),
        cmocka_unit_test_setup(test_cartesian_after_polar, setup_sensors),
        cmocka_unit_test_setup(test_bridge_matches_direct, setup_bridge),
        cmocka_unit_test_setup(test_bridge_refuses, setup_bridge),
        cmocka_unit_test_setup(test_memq_polar, setup_bridge),
        cmocka_unit_test_setup(test_replay, setup_bridge),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
