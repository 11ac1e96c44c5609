/* test_lcm_copy.c - LCM message <-> library struct copy (tools/lcm/lcm_copy.c):
 * round trips are exact, every rejection category gives its reason and leaves
 * the output untouched (truncation at every length, trailing bytes, wrong
 * hash, counts, capacity, utime, sensors), a bad detection (non-finite used
 * field, flag, negative amplitude) is dropped alone and counted, unused
 * fields are ignored, and the track list mirrors the tracker. */
#include "trk_test.h"

#include <limits.h>

#include "lcm_copy.h"

static trk_detection_scan_t msg, work;
static struct lcmc_scan out;
static uint8_t wire[LCMC_SCAN_WIRE_SIZE + 16];
static struct trk_tracker tk;

/* A valid message: 3 detections, one with its own covariance, one with amplitude. */
static void make_msg(trk_detection_scan_t *m)
{
    memset(m, 0, sizeof *m);
    m->utime = 1700000000123456LL;
    m->sensor_id = 1;
    m->seq = 42;
    m->n_detections = 3;
    m->detections[0].x_m = 100.25;
    m->detections[0].y_m = -50.5;
    m->detections[1].x_m = 1e3;
    m->detections[1].y_m = 2e3;
    m->detections[1].has_cov = 1;
    m->detections[1].cov_m2[0] = 4;
    m->detections[1].cov_m2[1] = 0.5;
    m->detections[1].cov_m2[2] = 9;
    m->detections[2].x_m = -7;
    m->detections[2].y_m = 8;
    m->detections[2].has_amplitude = 1;
    m->detections[2].amplitude = 3.5;
}

static size_t encode(const trk_detection_scan_t *m, uint8_t *buf)
{
    int n = trk_detection_scan_t_encode(buf, 0, (int)sizeof wire, m);
    assert_int_equal(n, LCMC_SCAN_WIRE_SIZE);
    return (size_t)n;
}

/* Decode len bytes from an exactly sized heap copy (ASan sees an over-read). */
static enum lcmc_reason from_bytes(const uint8_t *src, size_t len, unsigned n_sensors)
{
    uint8_t *b = malloc(len ? len : 1);
    assert_non_null(b);
    memcpy(b, src, len);
    enum lcmc_reason r = lcmc_scan_from_bytes(b, len, n_sensors, &work, &out, NULL, 0);
    free(b);
    return r;
}

static void test_wire_size(void **state)
{
    (void)state;
    make_msg(&msg);
    assert_int_equal(trk_detection_scan_t_encoded_size(&msg), LCMC_SCAN_WIRE_SIZE);
    assert_int_equal(TRK_DETECTION_SCAN_T_MAX_DETECTIONS, 256);
    assert_int_equal(TRK_TRACK_LIST_T_MAX_TRACKS, 64);
}

static void test_round_trip(void **state)
{
    (void)state;
    make_msg(&msg);
    size_t n = encode(&msg, wire);
    char detail[128];
    assert_int_equal(lcmc_scan_from_bytes(wire, n, 2, &work, &out, detail, sizeof detail), LCMC_OK);
    assert_string_equal(detail, "");
    assert_true(out.scan.time_us == 1700000000123456LL);
    assert_int_equal(out.scan.sensor_id, 1);
    assert_true(out.seq == 42);
    assert_int_equal(out.scan.n_detections, 3);
    assert_ptr_equal(out.scan.detections, out.det);
    assert_true(out.det[0].x_m == TRK_REAL_C(100.25) && out.det[0].y_m == TRK_REAL_C(-50.5));
    assert_int_equal(out.det[0].has_cov, 0);
    assert_int_equal(out.det[0].has_amplitude, 0);
    assert_int_equal(out.det[1].has_cov, 1);
    assert_true(out.det[1].cov_m2[0] == 4 && out.det[1].cov_m2[1] == TRK_REAL_C(0.5) &&
                out.det[1].cov_m2[2] == 9);
    assert_int_equal(out.det[2].has_amplitude, 1);
    assert_true(out.det[2].amplitude == TRK_REAL_C(3.5));
    /* struct -> message -> bytes: the same bytes */
    static trk_detection_scan_t back;
    static uint8_t wire2[sizeof wire];
    assert_int_equal(lcmc_scan_to_msg(&out.scan, out.seq, &back), LCMC_OK);
    encode(&back, wire2);
    assert_memory_equal(wire, wire2, n);
}

/* As many detections as the build and the message hold, at (i, -i). */
static void make_max_msg(trk_detection_scan_t *m)
{
    make_msg(m);
    m->n_detections = TRK_MAX_DETECTIONS < 256 ? TRK_MAX_DETECTIONS : 256;
    for (int i = 0; i < m->n_detections; i++) {
        m->detections[i].x_m = i;
        m->detections[i].y_m = -i;
    }
}

static void test_max_count_accepted(void **state)
{
    (void)state;
    make_max_msg(&msg);
    size_t n = encode(&msg, wire);
    assert_int_equal(from_bytes(wire, n, 2), LCMC_OK);
    assert_int_equal(out.scan.n_detections, (size_t)msg.n_detections);
    assert_true(out.det[msg.n_detections - 1].x_m == (trk_real)(msg.n_detections - 1));
}

/* Rejections never write the output. */
static void expect_reject(const trk_detection_scan_t *m, unsigned n_sensors, enum lcmc_reason want)
{
    char detail[160];
    memset(&out, 0xA5, sizeof out);
    static struct lcmc_scan pattern;
    memset(&pattern, 0xA5, sizeof pattern);
    size_t n = encode(m, wire);
    enum lcmc_reason r = lcmc_scan_from_bytes(wire, n, n_sensors, &work, &out, detail, sizeof detail);
    if (r != want)
        fail_msg("reason %s (%s), want %s", lcmc_reason_name(r), detail, lcmc_reason_name(want));
    assert_true(detail[0] != 0);
    assert_memory_equal(&out, &pattern, sizeof out);
    /* the message-level check gives the same answer */
    assert_int_equal(lcmc_scan_from_msg(m, n_sensors, &out, NULL, 0), want);
}

static void test_truncated_every_length(void **state)
{
    (void)state;
    make_msg(&msg);
    size_t n = encode(&msg, wire);
    for (size_t len = 0; len < n; len++) assert_int_equal(from_bytes(wire, len, 2), LCMC_DECODE);
    /* the generated decoder itself refuses every truncation too */
    for (size_t len = 0; len < n; len += 97)
        assert_true(trk_detection_scan_t_decode(wire, 0, (int)len, &work) < 0);
    /* one trailing byte */
    wire[n] = 0;
    assert_int_equal(from_bytes(wire, n + 1, 2), LCMC_DECODE);
    /* NULL */
    assert_int_equal(lcmc_scan_from_bytes(NULL, n, 2, &work, &out, NULL, 0), LCMC_DECODE);
}

static void test_wrong_type(void **state)
{
    (void)state;
    make_msg(&msg);
    size_t n = encode(&msg, wire);
    for (int i = 0; i < 8; i++) {
        wire[i] ^= 0x10;
        assert_int_equal(from_bytes(wire, n, 2), LCMC_DECODE);
        wire[i] ^= 0x10;
    }
    assert_int_equal(from_bytes(wire, n, 2), LCMC_OK);
    /* a track list is not a scan */
    static trk_track_list_t tl;
    static uint8_t tlb[1 << 15];
    memset(&tl, 0, sizeof tl);
    int k = trk_track_list_t_encode(tlb, 0, (int)sizeof tlb, &tl);
    assert_true(k > 0);
    assert_int_equal(from_bytes(tlb, (size_t)k, 2), LCMC_DECODE);
}

static void test_counts(void **state)
{
    (void)state;
    const int32_t bad[] = {-1, -1073741823, INT32_MIN, 257, 0x40000000, 0x40000001, INT32_MAX};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        make_msg(&msg);
        msg.n_detections = bad[i];
        expect_reject(&msg, 2, LCMC_COUNT);
    }
    make_msg(&msg);
    msg.n_detections = 0;
    assert_int_equal(lcmc_scan_from_msg(&msg, 2, &out, NULL, 0), LCMC_OK);
    assert_int_equal(out.scan.n_detections, 0);
}

static void test_capacity(void **state)
{
    (void)state;
    /* a message above this build's TRK_MAX_DETECTIONS is copied whole: the
     * tracker thins the scan (trk/tracker.h "Scans beyond capacity") */
    const int32_t counts[2] = {TRK_MAX_DETECTIONS < 256 ? TRK_MAX_DETECTIONS + 1 : 255, 256};
    for (int k = 0; k < 2; k++) {
        make_msg(&msg);
        msg.n_detections = counts[k];
        char detail[160];
        const size_t n = encode(&msg, wire);
        const enum lcmc_reason r = lcmc_scan_from_bytes(wire, n, 2, &work, &out, detail, sizeof detail);
        if (r != LCMC_OK) fail_msg("reason %s (%s), want the scan accepted", lcmc_reason_name(r), detail);
        assert_int_equal(out.scan.n_detections, (size_t)counts[k]);
        assert_int_equal(out.n_msg_detections, (size_t)counts[k]);
    }
}

/* A bad detection is dropped alone: the scan is accepted,
 * the other detections are copied in order, the drop is counted by reason
 * and detail names it. */
static void expect_dropped(const trk_detection_scan_t *m, size_t bad, enum lcmc_reason why)
{
    char detail[160], want[32];
    size_t n = encode(m, wire);
    enum lcmc_reason r = lcmc_scan_from_bytes(wire, n, 2, &work, &out, detail, sizeof detail);
    if (r != LCMC_OK) fail_msg("reason %s (%s), want the detection dropped", lcmc_reason_name(r), detail);
    assert_int_equal(out.n_msg_detections, (size_t)m->n_detections);
    assert_int_equal(out.scan.n_detections, (size_t)m->n_detections - 1);
    assert_int_equal(out.n_dropped_nonfinite, why == LCMC_NONFINITE);
    assert_int_equal(out.n_dropped_field, why == LCMC_FIELD);
    snprintf(want, sizeof want, "detections[%zu]", bad);
    assert_non_null(strstr(detail, want));
    for (size_t i = 0, j = 0; i < (size_t)m->n_detections; i++) {
        if (i == bad) continue;
        assert_true(out.det[j].x_m == (trk_real)m->detections[i].x_m);
        assert_true(out.det[j].y_m == (trk_real)m->detections[i].y_m);
        j++;
    }
}

static void test_nonfinite(void **state)
{
    (void)state;
    const double vals[] = {NAN, INFINITY, -INFINITY};
    for (int v = 0; v < 3; v++) {
        make_msg(&msg);
        msg.detections[0].x_m = vals[v];
        expect_dropped(&msg, 0, LCMC_NONFINITE);
        make_msg(&msg);
        msg.detections[2].y_m = vals[v];
        expect_dropped(&msg, 2, LCMC_NONFINITE);
        for (int k = 0; k < 3; k++) {
            make_msg(&msg);
            msg.detections[1].cov_m2[k] = vals[v];
            expect_dropped(&msg, 1, LCMC_NONFINITE);
        }
        make_msg(&msg);
        msg.detections[2].amplitude = vals[v];
        expect_dropped(&msg, 2, LCMC_NONFINITE);
    }
    /* unused fields are ignored (and not copied) */
    make_msg(&msg);
    msg.detections[0].cov_m2[1] = NAN;     /* has_cov = 0 */
    msg.detections[0].amplitude = NAN;     /* has_amplitude = 0 */
    msg.detections[5].x_m = NAN;           /* beyond n_detections */
    assert_int_equal(lcmc_scan_from_msg(&msg, 2, &out, NULL, 0), LCMC_OK);
    assert_true(out.det[0].cov_m2[1] == 0 && out.det[0].amplitude == 0);
    assert_int_equal(out.scan.n_detections, 3);
    assert_int_equal(out.n_dropped_nonfinite + out.n_dropped_field, 0);
    /* beyond trk_real: only the float build drops it */
    make_msg(&msg);
    msg.detections[0].x_m = 1e300;
    if (TRK_REAL_IS_FLOAT) expect_dropped(&msg, 0, LCMC_NONFINITE);
    else assert_int_equal(lcmc_scan_from_msg(&msg, 2, &out, NULL, 0), LCMC_OK);
}

/* One NaN among the most detections a scan can hold loses that one only. */
static void test_one_bad_among_max(void **state)
{
    (void)state;
    make_max_msg(&msg); /* detections 1 and 2 carry a covariance and an amplitude */
    const size_t bad = (size_t)msg.n_detections / 2;
    msg.detections[bad].y_m = NAN;
    expect_dropped(&msg, bad, LCMC_NONFINITE);
    /* and a second bad one of the other kind: both counted, detail names the first */
    msg.detections[0].has_amplitude = 1;
    msg.detections[0].amplitude = -1;
    char detail[160];
    assert_int_equal(lcmc_scan_from_msg(&msg, 2, &out, detail, sizeof detail), LCMC_OK);
    assert_int_equal(out.scan.n_detections, (size_t)msg.n_detections - 2);
    assert_int_equal(out.n_dropped_nonfinite, 1);
    assert_int_equal(out.n_dropped_field, 1);
    assert_non_null(strstr(detail, "detections[0]"));
    assert_true(out.det[0].x_m == 1);
}

static void test_fields(void **state)
{
    (void)state;
    const int8_t flags[] = {2, -1, 127};
    for (int i = 0; i < 3; i++) {
        make_msg(&msg);
        msg.detections[0].has_cov = flags[i];
        expect_dropped(&msg, 0, LCMC_FIELD);
        make_msg(&msg);
        msg.detections[1].has_amplitude = flags[i];
        expect_dropped(&msg, 1, LCMC_FIELD);
    }
    make_msg(&msg);
    msg.detections[2].amplitude = -0.5;
    expect_dropped(&msg, 2, LCMC_FIELD);
    make_msg(&msg);
    msg.utime = -1;
    expect_reject(&msg, 2, LCMC_FIELD);
    make_msg(&msg);
    msg.utime = INT64_MIN;
    expect_reject(&msg, 2, LCMC_FIELD);
    /* beyond the tracker's time range: a field error, not "gap since the
     * previous scan" */
    make_msg(&msg);
    msg.utime = TRK_TIME_US_MAX + 1;
    expect_reject(&msg, 2, LCMC_FIELD);
    make_msg(&msg);
    msg.utime = INT64_MAX;
    expect_reject(&msg, 2, LCMC_FIELD);
    make_msg(&msg);
    msg.utime = TRK_TIME_US_MAX;
    struct lcmc_scan *ok = calloc(1, sizeof *ok);
    assert_non_null(ok);
    assert_int_equal(lcmc_scan_from_msg(&msg, 2, ok, NULL, 0), LCMC_OK);
    free(ok);
}

static void test_sensor(void **state)
{
    (void)state;
    make_msg(&msg);
    msg.sensor_id = -1;
    expect_reject(&msg, 2, LCMC_SENSOR);
    msg.sensor_id = 2;
    expect_reject(&msg, 2, LCMC_SENSOR);
    msg.sensor_id = 1;
    expect_reject(&msg, 1, LCMC_SENSOR);
    msg.sensor_id = INT32_MIN;
    expect_reject(&msg, 2, LCMC_SENSOR);
    msg.sensor_id = 0;
    assert_int_equal(lcmc_scan_from_msg(&msg, 1, &out, NULL, 0), LCMC_OK);
}

static void test_to_msg_refusals(void **state)
{
    (void)state;
    static struct trk_detection det[257];
    struct trk_scan s = {.time_us = 0, .sensor_id = 0, .n_detections = 257, .detections = det};
    assert_int_equal(lcmc_scan_to_msg(&s, 0, &msg), LCMC_COUNT);
    s.n_detections = 1;
    s.time_us = -5;
    assert_int_equal(lcmc_scan_to_msg(&s, 0, &msg), LCMC_FIELD);
}

static void test_reasons(void **state)
{
    (void)state;
    for (int r = 0; r < LCMC_N_REASONS; r++) {
        assert_non_null(lcmc_reason_name((enum lcmc_reason)r));
        assert_true(strlen(lcmc_reason_text((enum lcmc_reason)r)) > 5);
    }
    assert_string_equal(lcmc_reason_name(LCMC_N_REASONS), "unknown");
    assert_int_equal(lcmc_reason_of_status(TRK_OK), LCMC_OK);
    assert_int_equal(lcmc_reason_of_status(TRK_E_TIME), LCMC_TIME);
    assert_int_equal(lcmc_reason_of_status(TRK_E_RANGE), LCMC_GAP);
    assert_int_equal(lcmc_reason_of_status(TRK_E_SENSOR), LCMC_SENSOR);
    assert_int_equal(lcmc_reason_of_status(TRK_E_CAPACITY), LCMC_CAPACITY);
    assert_int_equal(lcmc_reason_of_status(TRK_E_ARG), LCMC_OTHER);
}

static void test_tracks_to_msg(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_mn_kn_params(&p);
    p.confirm.u.mn.m = 2;
    p.confirm.u.mn.n = 3;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    static struct trk_detection det[3];
    memset(det, 0, sizeof det);
    struct trk_scan scan = {.time_us = 0, .sensor_id = 0, .n_detections = 3, .detections = det};
    struct trk_scan_report rep;
    static trk_track_list_t tl;
    for (int k = 0; k < 4; k++) {
        for (int i = 0; i < 3; i++) {
            det[i].x_m = (trk_real)(1000 * i + k);
            det[i].y_m = (trk_real)(500 - k);
        }
        scan.time_us = (int64_t)k * 1000000;
        scan.n_detections = k == 3 ? 2 : 3; /* the third target is missed once */
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    }
    lcmc_tracks_to_msg(&tk, &scan, 77, &rep, &tl);
    assert_true(tl.utime == scan.time_us && tl.seq == 77 && tl.sensor_id == 0);
    assert_int_equal(tl.n_detections, 2);
    assert_int_equal(tl.n_tracks, (int)trk_tracker_live_count(&tk));
    assert_int_equal(tl.n_omitted, 0);
    int j = 0;
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *t = trk_tracker_track(&tk, s);
        if (!t) continue;
        const trk_track_t *m = &tl.tracks[j++];
        assert_true(m->id == (int64_t)t->id);
        assert_int_equal(m->status, t->status);
        assert_int_equal(m->end_reason, t->end_reason);
        assert_true(m->utime == t->time_us);
        for (int i = 0; i < 4; i++) assert_true(m->x[i] == (double)t->x[i]);
        for (int i = 0; i < 16; i++) assert_true(m->p[i] == (double)t->p[i]);
        assert_int_equal(m->n_updates, (int32_t)t->n_scans);
        assert_int_equal(m->n_hits, (int32_t)t->n_hits);
        assert_int_equal(m->n_misses_in_row, (int32_t)t->n_misses_in_row);
        assert_int_equal(m->n_gated_last, t->n_gated_last);
        assert_true(m->confirm_stat == (double)t->confirm_stat);
        assert_true(m->term_stat == (double)t->term_stat);
        assert_int_equal(m->confirm_method, TRK_TRACK_T_CONFIRM_MN);
        assert_int_equal(m->term_method, TRK_TRACK_T_TERM_KN);
        assert_int_equal(m->has_existence_prob, 1);
        assert_int_equal(m->has_visibility_prob, 1);
        assert_true(m->visibility_prob == (double)t->vis.pv);
        assert_true(m->existence_prob == (double)t->vis.pcv);
    }
    /* three confirmed tracks (2 of 3) */
    int conf = 0;
    for (int i = 0; i < tl.n_tracks; i++) conf += tl.tracks[i].status == TRK_TRACK_T_STATUS_CONFIRMED;
    assert_int_equal(conf, TRK_MAX_TRACKS >= 3 ? 3 : (int)TRK_MAX_TRACKS);
    /* unused entries are zero */
    static trk_track_t zero;
    for (int i = tl.n_tracks; i < TRK_TRACK_LIST_T_MAX_TRACKS; i++)
        assert_memory_equal(&tl.tracks[i], &zero, sizeof zero);
    /* and it encodes/decodes to the same list */
    static uint8_t b[1 << 15];
    static trk_track_list_t back;
    int n = trk_track_list_t_encode(b, 0, (int)sizeof b, &tl);
    assert_true(n > 0);
    assert_int_equal(trk_track_list_t_decode(b, 0, n, &back), n);
    assert_int_equal(back.n_tracks, tl.n_tracks);
    assert_true(back.tracks[0].x[0] == tl.tracks[0].x[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wire_size),
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_max_count_accepted),
        cmocka_unit_test(test_truncated_every_length),
        cmocka_unit_test(test_wrong_type),
        cmocka_unit_test(test_counts),
        cmocka_unit_test(test_capacity),
        cmocka_unit_test(test_nonfinite),
        cmocka_unit_test(test_one_bad_among_max),
        cmocka_unit_test(test_fields),
        cmocka_unit_test(test_sensor),
        cmocka_unit_test(test_to_msg_refusals),
        cmocka_unit_test(test_reasons),
        cmocka_unit_test(test_tracks_to_msg),
    };
    return trk_run_tests("lcm_copy", tests, NULL, NULL);
}
