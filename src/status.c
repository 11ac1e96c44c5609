/* status.c - names of status codes and the build's capacities. */
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
    };
    if ((unsigned)s >= (unsigned)TRK_STATUS_COUNT) return "TRK_E_UNKNOWN";
    return names[s];
}

size_t trk_max_tracks(void) { return TRK_MAX_TRACKS; }
size_t trk_max_detections(void) { return TRK_MAX_DETECTIONS; }
size_t trk_max_sensors(void) { return TRK_MAX_SENSORS; }
size_t trk_real_size(void) { return sizeof(trk_real); }
