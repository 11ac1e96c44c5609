/* status_message.c - a plain-words sentence for each status code
 * (trk_status_message(), types.h). In a file of its own so that a firmware
 * that never calls it links none of its text. */
#include "trk/types.h"

const char *trk_status_message(trk_status s)
{
    /* the same words as docs/statuses.md's "returned when" column */
    static const char *const messages[TRK_STATUS_COUNT] = {
        "success",
        "invalid argument (a NULL pointer, a bad dimension or an enum value out of range)",
        "a value is NaN or infinite",
        "a value is outside its documented range",
        "more items than this build's compile-time capacity allows",
        "a covariance is not symmetric positive definite",
        "a matrix that must be inverted is singular",
        "a scan's time is before the previous scan's",
        "a scan names a sensor the tracker was not configured with",
        "table is shorter than its header says (truncated copy)",
        "not a trk table (wrong file)",
        "table format version not supported by this library (regenerate it with the matching trk-tablegen)",
        "table's real width (float or double) differs from this build's",
        "table checksum does not match its contents (corrupt or truncated copy)",
        "table of another kind or dimension than asked for",
        "table is corrupt (inconsistent header, non-finite or non-monotone data)",
        "an iteration did not converge (no steady state)",
        "a feature not built into this configuration of the library",
        "a file could not be read or written",
        "the library was built with another configuration (capacities, options, real type) than the program",
    };
    if ((unsigned)s >= (unsigned)TRK_STATUS_COUNT) return "unknown status code";
    return messages[s];
}
