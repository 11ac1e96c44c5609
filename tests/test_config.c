/* test_config.c - the configuration check (types.h, config.h): the library's
 * view of every layout-relevant knob matches this build's headers, a
 * translation unit that sees another value of any one knob gets TRK_E_ABI,
 * and the names of statuses and decisions. */
#include "trk_test.h"
#include "trk/tracker.h"

/* This build's values, captured before the end of the file redefines the
 * knobs one at a time. */
enum {
    TRACKS = TRK_MAX_TRACKS,
    DETECTIONS = TRK_MAX_DETECTIONS,
    SENSORS = TRK_MAX_SENSORS,
    STATE = TRK_MAX_STATE,
    MEAS = TRK_MAX_MEAS,
    KMAX = TRK_CLUTTER_KMAX,
    WITH_CLUTTER = TRK_WITH_CLUTTER_TESTS
};

static void test_matches(void **state)
{
    (void)state;
    TRK_ASSERT_OK(trk_config_check());
    TRK_ASSERT_OK(trk_tracker_abi_check());
    assert_int_equal(trk_max_tracks(), TRK_MAX_TRACKS);
    assert_int_equal(trk_max_detections(), TRK_MAX_DETECTIONS);
    assert_int_equal(trk_max_sensors(), TRK_MAX_SENSORS);
    assert_int_equal(trk_max_state(), TRK_MAX_STATE);
    assert_int_equal(trk_max_meas(), TRK_MAX_MEAS);
    assert_int_equal(trk_clutter_kmax(), TRK_CLUTTER_KMAX);
    assert_int_equal(trk_with_clutter_tests(), TRK_WITH_CLUTTER_TESTS);
    assert_int_equal(trk_real_size(), sizeof(trk_real));
    assert_int_equal(trk_real_size(), TRK_REAL_IS_FLOAT ? sizeof(float) : sizeof(double));
    assert_int_equal(trk_enum_size(), sizeof(enum trk_decision));
    assert_int_equal(trk_tracker_sizeof(), sizeof(struct trk_tracker));
    assert_true(TRK_SIZE_OPT == 0 || TRK_SIZE_OPT == 1); /* not compared: sets no layout */
}

static void test_names(void **state)
{
    (void)state;
    assert_string_equal(trk_status_str(TRK_OK), "TRK_OK");
    assert_string_equal(trk_status_str(TRK_E_ABI), "TRK_E_ABI");
    assert_string_equal(trk_status_str(TRK_E_IO), "TRK_E_IO");
    assert_string_equal(trk_status_str(TRK_STATUS_COUNT), "TRK_E_UNKNOWN");
    assert_string_equal(trk_status_str((trk_status)-1), "TRK_E_UNKNOWN");
    for (int i = 0; i < TRK_STATUS_COUNT; i++) { /* every status named, no two alike */
        const char *a = trk_status_str((trk_status)i);
        assert_true(strncmp(a, "TRK_", 4) == 0 && strcmp(a, "TRK_E_UNKNOWN") != 0);
        for (int j = 0; j < i; j++) assert_true(strcmp(a, trk_status_str((trk_status)j)) != 0);
    }
    /* every status has a plain-words sentence of its own; out of range a defined one */
    assert_string_equal(trk_status_message(TRK_OK), "success");
    assert_string_equal(trk_status_message(TRK_E_TABLE_CRC),
                        "table checksum does not match its contents (corrupt or truncated copy)");
    assert_string_equal(trk_status_message(TRK_STATUS_COUNT), "unknown status code");
    assert_string_equal(trk_status_message((trk_status)-1), "unknown status code");
    for (int i = 0; i < TRK_STATUS_COUNT; i++) {
        const char *a = trk_status_message((trk_status)i);
        assert_non_null(a);
        assert_true(strlen(a) > 0 && strchr(a, '\n') == NULL && strstr(a, "TRK_") == NULL);
        assert_true(strcmp(a, "unknown status code") != 0);
        for (int j = 0; j < i; j++) assert_true(strcmp(a, trk_status_message((trk_status)j)) != 0);
    }
    assert_int_equal(TRK_DECISION_CONTINUE, 0); /* a zeroed state has no decision */
    assert_string_equal(trk_decision_str(TRK_DECISION_CONTINUE), "TRK_DECISION_CONTINUE");
    assert_string_equal(trk_decision_str(TRK_DECISION_CONFIRM), "TRK_DECISION_CONFIRM");
    assert_string_equal(trk_decision_str(TRK_DECISION_TERMINATE), "TRK_DECISION_TERMINATE");
    assert_string_equal(trk_decision_str((enum trk_decision)7), "TRK_DECISION_UNKNOWN");
}

/* A translation unit compiled with one knob changed (the library keeps its
 * own value). trk_config_check() is a macro: it reads the knobs where it is
 * expanded, so each function below sees the redefinition above it. */
#undef TRK_MAX_TRACKS
#define TRK_MAX_TRACKS (TRACKS + 1)
static trk_status other_tracks(void) { return trk_config_check(); }
#undef TRK_MAX_TRACKS
#define TRK_MAX_TRACKS TRACKS

#undef TRK_MAX_DETECTIONS
#define TRK_MAX_DETECTIONS (DETECTIONS - 1)
static trk_status other_detections(void) { return trk_config_check(); }
#undef TRK_MAX_DETECTIONS
#define TRK_MAX_DETECTIONS DETECTIONS

#undef TRK_MAX_SENSORS
#define TRK_MAX_SENSORS (SENSORS + 1)
static trk_status other_sensors(void) { return trk_config_check(); }
#undef TRK_MAX_SENSORS
#define TRK_MAX_SENSORS SENSORS

#undef TRK_MAX_STATE
#define TRK_MAX_STATE (STATE + 1)
static trk_status other_state(void) { return trk_config_check(); }
#undef TRK_MAX_STATE
#define TRK_MAX_STATE STATE

#undef TRK_MAX_MEAS
#define TRK_MAX_MEAS (MEAS - 1)
static trk_status other_meas(void) { return trk_config_check(); }
#undef TRK_MAX_MEAS
#define TRK_MAX_MEAS MEAS

#undef TRK_CLUTTER_KMAX
#define TRK_CLUTTER_KMAX (KMAX + 1)
static trk_status other_kmax(void) { return trk_config_check(); }
static trk_status other_kmax_tracker(void) { return trk_tracker_abi_check(); }
#undef TRK_CLUTTER_KMAX
#define TRK_CLUTTER_KMAX KMAX

#undef TRK_WITH_CLUTTER_TESTS
#define TRK_WITH_CLUTTER_TESTS (1 - WITH_CLUTTER)
static trk_status other_clutter_tests(void) { return trk_config_check(); }
#undef TRK_WITH_CLUTTER_TESTS
#define TRK_WITH_CLUTTER_TESTS WITH_CLUTTER

static trk_status same_again(void) { return trk_config_check(); }

static void test_mismatch(void **state)
{
    (void)state;
    TRK_ASSERT_STATUS(other_tracks(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_detections(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_sensors(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_state(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_meas(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_kmax(), TRK_E_ABI);
    TRK_ASSERT_STATUS(other_clutter_tests(), TRK_E_ABI);
    /* the tracker's check fails too (its status: see trk/tracker.h) */
    assert_true(other_kmax_tracker() != TRK_OK);
    TRK_ASSERT_OK(same_again()); /* restored: the check is the header's view, nothing else */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_matches),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_mismatch),
    };
    return trk_run_tests("config", tests, NULL, NULL);
}
