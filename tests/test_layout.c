/* test_layout.c - the shared library's self-description (trk/layout.h,
 * src/shared/layout.c): every row's offset, size and count against this
 * translation unit's offsetof/sizeof of the same member, the rows inside
 * their structs and in offset order within a member group, the sub-struct
 * names resolvable, the constants against the headers, the ABI check and
 * out-of-range queries refused. */
#include <string.h>

#include "trk_test.h"
#include "trk/layout.h"
#include "trk/table.h"
#include "trk/tracker.h"

static size_t struct_index(const char *name)
{
    for (size_t i = 0; i < trk_layout_n_structs(); i++) {
        const char *n;
        TRK_ASSERT_OK(trk_layout_struct(i, &n, NULL, NULL));
        if (strcmp(n, name) == 0) return i;
    }
    fail_msg("struct %s not described", name);
    return 0;
}

static void get_field(const char *st, const char *name, char *kind, size_t *size, size_t *offset, size_t *count)
{
    const size_t i = struct_index(st);
    size_t nf;
    TRK_ASSERT_OK(trk_layout_struct(i, NULL, NULL, &nf));
    for (size_t j = 0; j < nf; j++) {
        const char *n;
        TRK_ASSERT_OK(trk_layout_field(i, j, &n, kind, size, offset, count, NULL, NULL, NULL));
        if (strcmp(n, name) == 0) return;
    }
    fail_msg("%s.%s not described", st, name);
}

/* one member: the row says what the compiler says here */
#define CHECK(ST, S, M, K, N)                                                            \
    do {                                                                                 \
        char k;                                                                          \
        size_t sz, off, cnt;                                                             \
        get_field(ST, #M, &k, &sz, &off, &cnt);                                          \
        assert_int_equal(k, K);                                                          \
        assert_int_equal(off, offsetof(S, M));                                           \
        assert_int_equal(sz *cnt, sizeof(((S *)0)->M));                                  \
        assert_int_equal(cnt, N);                                                        \
    } while (0)

static void test_members_match_offsetof(void **state)
{
    (void)state;
#define P struct trk_tracker_params
    CHECK("tracker_params", P, n_sensors, 'u', 1);
    CHECK("tracker_params", P, sensor, 's', TRK_MAX_SENSORS);
    CHECK("tracker_params", P, gate_prob, 'f', 1);
    CHECK("tracker_params", P, clutter, 'i', 1);
    CHECK("tracker_params", P, visibility.p_term, 'f', 1);
    CHECK("tracker_params", P, confirm.method, 'i', 1);
    CHECK("tracker_params", P, confirm.u.mn.m, 'i', 1);
    CHECK("tracker_params", P, confirm.u.sprt.hmm, 's', 1);
    CHECK("tracker_params", P, confirm.u.existence.reject_odds_ratio, 'f', 1);
    CHECK("tracker_params", P, confirm.u.existence.count_alpha, 'f', 1);
    CHECK("tracker_params", P, clutter_map.edge_alpha, 'f', 1);
    CHECK("tracker_params", P, term.u.shiryaev.h, 'f', 1);
    CHECK("tracker_params", P, init.max_gap_scans, 'u', 1);
    CHECK("tracker_params", P, association, 'i', 1);
#if TRK_WITH_IMM
    CHECK("tracker_params", P, imm, 's', 1);
#endif
#undef P
    CHECK("sensor_params", struct trk_sensor_params, meas_cov_m2, 'f', 3);
    CHECK("sensor_params", struct trk_sensor_params, amplitude, 's', 1);
    CHECK("detection", struct trk_detection, cov_m2, 'f', 3);
    CHECK("detection", struct trk_detection, has_amplitude, 'u', 1);
    CHECK("scan", struct trk_scan, time_us, 'i', 1);
    CHECK("scan", struct trk_scan, detections, 'p', 1);
    CHECK("scan_report", struct trk_scan_report, n_assoc_overflow, 'u', 1);
    CHECK("track", struct trk_track, x, 'f', TRK_CV2_NX);
    CHECK("track", struct trk_track, p, 'f', TRK_CV2_NX * TRK_CV2_NX);
    CHECK("track", struct trk_track, vis.pv, 'f', 1);
    CHECK("track", struct trk_track, n_gated_last, 'u', 1);
    CHECK("tracker", struct trk_tracker, track, 's', TRK_MAX_TRACKS);
    CHECK("hmm_params", struct trk_hmm_params, sensor, 's', TRK_MAX_SENSORS);
    CHECK("imm_params", struct trk_imm_params, p_switch, 'f', TRK_MAX_MODELS * TRK_MAX_MODELS);
}

static void test_struct_sizes_and_rows(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        size_t size;
    } want[] = {{"tracker_params", sizeof(struct trk_tracker_params)},
                {"sensor_params", sizeof(struct trk_sensor_params)},
                {"amplitude", sizeof(struct trk_amplitude)},
                {"detection", sizeof(struct trk_detection)},
                {"scan", sizeof(struct trk_scan)},
                {"scan_report", sizeof(struct trk_scan_report)},
                {"track", sizeof(struct trk_track)},
                {"tracker", sizeof(struct trk_tracker)},
                {"table", sizeof(struct trk_table)}};
    for (size_t w = 0; w < sizeof want / sizeof want[0]; w++) {
        size_t size;
        TRK_ASSERT_OK(trk_layout_struct(struct_index(want[w].name), NULL, &size, NULL));
        assert_int_equal(size, want[w].size);
    }
    assert_int_equal(trk_tracker_sizeof(), sizeof(struct trk_tracker));
    /* every row inside its struct, of a known kind, its sub-struct described
     * and as large as the row's element; the scan report's members every one described */
    for (size_t i = 0; i < trk_layout_n_structs(); i++) {
        const char *sname;
        size_t ssize, nf, covered = 0;
        TRK_ASSERT_OK(trk_layout_struct(i, &sname, &ssize, &nf));
        for (size_t j = 0; j < nf; j++) {
            const char *name, *sub, *unit, *range;
            char kind;
            size_t size, offset, count;
            TRK_ASSERT_OK(trk_layout_field(i, j, &name, &kind, &size, &offset, &count, &sub, &unit, &range));
            assert_true(strchr("fiups", kind) != NULL);
            assert_true(count >= 1 && size >= 1);
            assert_true(offset + size * count <= ssize);
            assert_non_null(unit);
            assert_non_null(range);
            if (kind == 's') {
                size_t sub_size;
                TRK_ASSERT_OK(trk_layout_struct(struct_index(sub), NULL, &sub_size, NULL));
                assert_int_equal(sub_size, size);
            }
            if (kind == 'f') assert_int_equal(size, sizeof(trk_real));
            covered += size * count;
        }
        /* the report: every member described; at most one alignment gap (the
         * uint32_t counters are followed by trk_real members) */
        if (strcmp(sname, "scan_report") == 0) assert_true(covered <= ssize && ssize - covered < sizeof(trk_real));
    }
}

static void test_constants_and_abi(void **state)
{
    (void)state;
    size_t found = 0;
    for (size_t i = 0; i < trk_layout_n_constants(); i++) {
        const char *name;
        long v;
        TRK_ASSERT_OK(trk_layout_constant(i, &name, &v));
        if (strcmp(name, "TRK_MAX_TRACKS") == 0) assert_int_equal(v, TRK_MAX_TRACKS), found++;
        if (strcmp(name, "TRK_REAL_IS_FLOAT") == 0) assert_int_equal(v, TRK_REAL_IS_FLOAT), found++;
        if (strcmp(name, "TRK_CONFIRM_EXISTENCE") == 0) assert_int_equal(v, TRK_CONFIRM_EXISTENCE), found++;
        if (strcmp(name, "TRK_STATUS_COUNT") == 0) assert_int_equal(v, TRK_STATUS_COUNT), found++;
    }
    assert_int_equal(found, 4);
    TRK_ASSERT_OK(trk_shared_abi_check(TRK_SHARED_ABI));
    TRK_ASSERT_STATUS(trk_shared_abi_check(TRK_SHARED_ABI + 1), TRK_E_ABI);
    assert_non_null(trk_shared_version());
    assert_true(strlen(trk_shared_version()) >= 5);
    const char *name;
    long v;
    TRK_ASSERT_STATUS(trk_layout_constant(trk_layout_n_constants(), &name, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_layout_struct(trk_layout_n_structs(), &name, NULL, NULL), TRK_E_RANGE);
    size_t nf;
    TRK_ASSERT_OK(trk_layout_struct(0, NULL, NULL, &nf));
    TRK_ASSERT_STATUS(trk_layout_field(0, nf, &name, NULL, NULL, NULL, NULL, NULL, NULL, NULL), TRK_E_RANGE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_members_match_offsetof),
        cmocka_unit_test(test_struct_sizes_and_rows),
        cmocka_unit_test(test_constants_and_abi),
    };
    return trk_run_tests("layout", tests, NULL, NULL);
}
