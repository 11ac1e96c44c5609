/** @file
 * trk/layout.h - the shared library's self-description (libtrk.so,
 * libtrk_f.so; src/shared, not in the firmware archive libtrk.a): its
 * version, an ABI check, and the layout of the public structs a binding
 * fills and reads (struct trk_tracker_params, trk_detection, trk_scan,
 * trk_scan_report, trk_track, ...), so that a binding without a C compiler
 * (Python's ctypes, tools/python/trk) takes every offset and size from the
 * library it loaded instead of repeating the headers.
 *
 * A struct is described by rows, one per member (nested members flattened
 * with dots: "confirm.u.mn.m"; union members overlap):
 *   kind  'f' floating point, 'i' signed integer (enums too), 'u' unsigned
 *         integer, 'p' pointer, 's' a struct described under the name sub
 *   size  bytes of one element; count elements (arrays), offset from the
 *         start of the struct
 *   unit, range  the member's unit ("" when none) and accepted values, as the
 *         headers document them ("" when the check is elsewhere)
 */
#ifndef TRK_LAYOUT_H
#define TRK_LAYOUT_H

#include "trk/types.h"

/** The version of the layout protocol below. A binding passes the one it was
 * written for to trk_shared_abi_check; it changes when a function here
 * changes meaning. */
#define TRK_SHARED_ABI 1

/** The library's version ("0.1.0"); never NULL. */
const char *trk_shared_version(void);

/** TRK_OK when the binding's protocol version abi is TRK_SHARED_ABI and the
 * library's objects agree with the headers it was built with
 * (trk_tracker_abi_check); TRK_E_ABI otherwise. */
TRK_NODISCARD trk_status trk_shared_abi_check(unsigned abi);

/** @{ */
/** Described structs: i in 0 .. trk_layout_n_structs() - 1; name ("track"),
 * size (sizeof) and number of rows. TRK_E_RANGE for i out of range. */
size_t trk_layout_n_structs(void);
TRK_NODISCARD trk_status trk_layout_struct(size_t i, const char **name, size_t *size, size_t *n_fields);
/** @} */

/** Row j of struct i (any output pointer may be NULL). TRK_E_RANGE for i or j
 * out of range. */
TRK_NODISCARD trk_status trk_layout_field(size_t i, size_t j, const char **name, char *kind, size_t *size,
                                          size_t *offset, size_t *count, const char **sub, const char **unit,
                                          const char **range);

/** @{ */
/** The build's constants (capacities, options, enum values): i in
 * 0 .. trk_layout_n_constants() - 1. TRK_E_RANGE for i out of range. */
size_t trk_layout_n_constants(void);
TRK_NODISCARD trk_status trk_layout_constant(size_t i, const char **name, long *value);
/** @} */

#endif
