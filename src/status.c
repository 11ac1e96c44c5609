/* status.c - names of status codes and decisions, and the configuration the
 * library was built with (trk_config_check(), types.h). */
#include "trk/types.h"

const char *trk_status_str(trk_status s)
{
    static const char *const names[TRK_STATUS_COUNT] = {
        "TRK_OK",
        "TRK_E_ARG",
        "TRK_E_NAN",
        "TRK_E_RANGE",
        "TRK_E_CAPACITY",
        "TRK_E_NOT_SPD",
        "TRK_E_SINGULAR",
        "TRK_E_TIME",
        "TRK_E_SENSOR",
        "TRK_E_TABLE_TRUNCATED",
        "TRK_E_TABLE_MAGIC",
        "TRK_E_TABLE_VERSION",
        "TRK_E_TABLE_REAL",
        "TRK_E_TABLE_CRC",
        "TRK_E_TABLE_KIND",
        "TRK_E_TABLE_CORRUPT",
        "TRK_E_DIVERGED",
        "TRK_E_UNSUPPORTED",
        "TRK_E_IO",
        "TRK_E_ABI",
    };
    if ((unsigned)s >= (unsigned)TRK_STATUS_COUNT) return "TRK_E_UNKNOWN";
    return names[s];
}

const char *trk_decision_str(enum trk_decision d)
{
    switch (d) {
    case TRK_DECISION_CONTINUE: return "TRK_DECISION_CONTINUE";
    case TRK_DECISION_CONFIRM: return "TRK_DECISION_CONFIRM";
    case TRK_DECISION_TERMINATE: return "TRK_DECISION_TERMINATE";
    }
    return "TRK_DECISION_UNKNOWN";
}

size_t trk_max_tracks(void) { return TRK_MAX_TRACKS; }
size_t trk_max_detections(void) { return TRK_MAX_DETECTIONS; }
size_t trk_max_sensors(void) { return TRK_MAX_SENSORS; }
size_t trk_max_state(void) { return TRK_MAX_STATE; }
size_t trk_max_meas(void) { return TRK_MAX_MEAS; }
size_t trk_clutter_kmax(void) { return TRK_CLUTTER_KMAX; }
size_t trk_with_clutter_tests(void) { return TRK_WITH_CLUTTER_TESTS; }
size_t trk_with_joint(void) { return TRK_WITH_JOINT; }
size_t trk_with_imm(void) { return TRK_WITH_IMM; }
size_t trk_max_models(void) { return TRK_MAX_MODELS; }
size_t trk_jpda_exact_bits(void) { return TRK_JPDA_EXACT_BITS; }
size_t trk_max_gated_pairs(void) { return TRK_MAX_GATED_PAIRS; }
size_t trk_real_size(void) { return sizeof(trk_real); }
size_t trk_enum_size(void) { return sizeof(enum trk_decision); }
