/** @file
 * trk/table.h - lookup tables: a self-describing, versioned, CRC-checked
 * container made offline by trk-tablegen and used in place by the library
 * (from a const array in ROM or from a file read into RAM; no copy, no heap).
 *
 * docs/conventions.md "Lookup tables". One container for every kind of table
 * (amplitude models, PDAF / PDAFAI q2, ...): a kind, named numeric parameters
 * and up to TRK_TABLE_MAX_SECTIONS sections, each an array over 1..3 axes with
 * ncomp values per cell.
 *
 * BYTE LAYOUT (format version 1). All integers are unsigned 32-bit
 * little-endian unless noted; "real" is an IEEE 754 value of the table's real
 * width (4 = binary32, 8 = binary64), little-endian, stored in an 8-byte slot
 * whose unused bytes are zero. Every offset is from the first byte.
 *
 *   header, 64 bytes
 *     0  u8[8]  magic "TRKTABLE"
 *     8  u32    format version (1)
 *    12  u32    header size (64)
 *    16  u32    total size in bytes, including the CRC trailer
 *    20  u32    kind (enum trk_table_kind)
 *    24  u32    kind version (layout/semantics of that kind; amp: 1)
 *    28  u32    real width in bytes (4 or 8)
 *    32  u32    number of parameters  (<= TRK_TABLE_MAX_PARAMS)
 *    36  u32    number of sections    (1 .. TRK_TABLE_MAX_SECTIONS)
 *    40  u8[24] reserved, zero
 *   parameters, 48 bytes each, from offset 64
 *     0  char[32] name: 1..31 characters [a-z0-9_], NUL-padded; unique
 *    32  u32    type: 1 real, 2 integer
 *    36  u32    reserved, zero
 *    40  8      value: real slot, or int64 little-endian
 *   section descriptors, 152 bytes each, after the parameters
 *     0  u32    id (meaning defined by the kind; unique in the table)
 *     4  u32    number of axes (1..3)
 *     8  u32    ncomp, values per cell (1..TRK_TABLE_MAX_COMP)
 *    12  u32    interpolation rule (enum trk_table_interp)
 *    16  u32    data offset (multiple of 8)
 *    20  u32    data count in reals = ncomp * product of the axis counts
 *    24  u8[8]  reserved, zero
 *    32  3 axis records of 40 bytes (records beyond the number of axes are zero):
 *         0  u32   count (2 .. TRK_TABLE_MAX_COUNT)
 *         4  u32   spacing (enum trk_table_spacing)
 *         8  u32   variable (enum trk_table_var: what the axis measures)
 *        12  u32   values offset (explicit spacing: count reals, strictly
 *                  increasing, first = lo, last = hi; otherwise 0)
 *        16  real  lo     24 real hi (lo < hi)
 *        32  real  ratio  (geometric spacing: B > 0, B != 1; otherwise 0)
 *   payload, from the end of the descriptors: for each section in order, its
 *     explicit axis values (axis order), then its data; each array starts at
 *     the previous end rounded up to 8 bytes (padding zero). Data are
 *     row-major over the axes (axis 0 slowest), ncomp consecutive values per
 *     cell.
 *   trailer: u32 CRC-32 (IEEE 802.3, reflected 0xEDB88320, init and final
 *     xor 0xFFFFFFFF, as zlib's crc32) of every byte before it, at the end of
 *     the last array rounded up to 8 (padding zero); total size = its offset + 4.
 *
 * Axis spacings (i = 0 .. n-1):
 *   linear     v_i = lo + i (hi - lo)/(n - 1)
 *   log        v_i = lo (hi/lo)^(i/(n - 1)), 0 < lo
 *   geometric  v_i = lo + (hi - lo)(B^i - 1)/(B^(n-1) - 1)  (steps grow by B)
 *   explicit   v_i stored
 *
 * Validation (trk_table_check and trk_table_parse) rejects, with a status and
 * without reading outside [bytes, bytes + len): a buffer shorter than the
 * header or than the total size (TRK_E_TABLE_TRUNCATED), a wrong magic
 * (TRK_E_TABLE_MAGIC), format version (TRK_E_TABLE_VERSION), a CRC mismatch
 * (TRK_E_TABLE_CRC), and any inconsistent header, parameter, axis or layout,
 * non-zero reserved or padding byte, non-finite real, non-increasing explicit
 * axis, and - for a table of this build's real width, in this build's
 * arithmetic - a computed axis whose nodes are not finite and strictly
 * increasing (TRK_E_TABLE_CORRUPT). trk_table_parse additionally requires the real
 * width of this build (TRK_E_TABLE_REAL) and 8-byte alignment of the bytes
 * (TRK_E_ARG) because the values are used in place; on a big-endian target it
 * returns TRK_E_UNSUPPORTED.
 *
 * ALIGNMENT: the first byte must be aligned to TRK_TABLE_ALIGN (8). In C99 a
 * const array gets that alignment inside a union with a double member, which
 * is what `trk-tablegen ... --format c` emits:
 *     static const union { unsigned char bytes[N]; double align; } tbl = {{...}};
 *     trk_table_parse(&t, tbl.bytes, sizeof tbl.bytes);
 * For files use a buffer from malloc or a static array of double / uint64_t.
 */
#ifndef TRK_TABLE_H
#define TRK_TABLE_H

#include "trk/types.h"

/** Container format version (header offset 8). */
#define TRK_TABLE_FORMAT_VERSION 1u
/** Alignment of a table's first byte and of every array in it, in bytes. */
#define TRK_TABLE_ALIGN 8u
/** Header size in bytes (see the byte layout above). */
#define TRK_TABLE_HEADER_SIZE 64u
/** Size of one parameter record in bytes. */
#define TRK_TABLE_PARAM_SIZE 48u
/** Size of one section descriptor in bytes. */
#define TRK_TABLE_SECTION_SIZE 152u
/** Size of one axis record in bytes. */
#define TRK_TABLE_AXIS_SIZE 40u
#define TRK_TABLE_NAME_MAX 32u       /**< bytes of a parameter name incl. NUL */
/** Most parameters in one table. */
#define TRK_TABLE_MAX_PARAMS 64u
/** Most sections in one table. */
#define TRK_TABLE_MAX_SECTIONS 16u
/** Most axes of one section. */
#define TRK_TABLE_MAX_AXES 3u
/** Most values per cell (ncomp). */
#define TRK_TABLE_MAX_COMP 8u
#define TRK_TABLE_MAX_COUNT (1u << 20)  /**< points on one axis */
#define TRK_TABLE_MAX_REALS (1u << 26)  /**< reals in one array */

/** What a table holds; the kind defines its parameters and sections. */
enum trk_table_kind {
    TRK_TABLE_KIND_AMP = 1,        /**< amplitude model (trk/amplitude.h) */
    TRK_TABLE_KIND_Q2_PDAF = 2,    /**< q2 over (pd, lambda_vg) for one (nz, gate_prob) */
    TRK_TABLE_KIND_Q2_PDAFAI = 3,  /**< q2 over (snr_db, pfa, lambda_vg) for one (model, nu) */
    TRK_TABLE_KIND_COUNT
};

/** Node spacing of an axis (formulas above). */
enum trk_table_spacing {
    TRK_TABLE_SPACING_LINEAR = 1,
    TRK_TABLE_SPACING_LOG = 2,
    TRK_TABLE_SPACING_GEOMETRIC = 3,
    TRK_TABLE_SPACING_EXPLICIT = 4,
    TRK_TABLE_SPACING_COUNT
};

/** How a reader interpolates a section (the kind may restrict the choice). */
enum trk_table_interp {
    TRK_TABLE_INTERP_NONE = 0,     /**< cells only (e.g. a Monte Carlo grid with errors) */
    TRK_TABLE_INTERP_LINEAR = 1,   /**< (multi)linear in the axis variables */
    TRK_TABLE_INTERP_HERMITE = 2,  /**< 1 axis, ncomp >= 2: cubic Hermite of comp 0
                                      with comp 1 = d comp0 / d axis variable */
    TRK_TABLE_INTERP_CUBIC = 3,    /**< tensor product of per-axis cubic Hermite with
                                      slopes from the values (3-point differences;
                                      Catmull-Rom on uniform axes): q2 tables, trk/q2.h */
    TRK_TABLE_INTERP_COUNT
};

/** The quantity an axis measures (its values are this quantity). */
enum trk_table_var {
    TRK_TABLE_VAR_X = 1,          /**< x = -ln S^a(a), truncated log-survival (Brekke eq 41) */
    TRK_TABLE_VAR_LN_AMP = 2,     /**< ln(a / sqrt(clutter_power)) */
    TRK_TABLE_VAR_AMP = 3,        /**< a / sqrt(clutter_power) */
    TRK_TABLE_VAR_SNR_DB = 4,
    TRK_TABLE_VAR_PFA = 5,
    TRK_TABLE_VAR_PD = 6,
    TRK_TABLE_VAR_LAMBDA_VG = 7,  /**< expected clutter count in the gate */
    TRK_TABLE_VAR_GATE_PROB = 8,
    TRK_TABLE_VAR_COUNT
};

/** Type of a table parameter's value. */
enum trk_table_param_type {
    TRK_TABLE_PARAM_REAL = 1,
    TRK_TABLE_PARAM_INT = 2
};

/** Header facts of a checked table (any real width). */
struct trk_table_info {
    /** @{ header fields: kind (enum trk_table_kind), kind version, real width in bytes, number of parameters and of sections */
    uint32_t kind, kind_version, real_size, n_params, n_sections;
    /** @} */
    size_t size;            /**< total size in bytes */
    uint32_t crc;  /**< the CRC-32 trailer */
};

/** A parsed table: a view on caller bytes (which must outlive it). */
struct trk_table {
    const unsigned char *bytes;  /**< the table's first byte (caller-owned) */
    struct trk_table_info info;  /**< its header facts */
};

/** One axis of a section, from its axis record (byte layout above). */
struct trk_table_axis {
    /** @{ nodes, spacing (enum trk_table_spacing) and variable (enum trk_table_var) */
    uint32_t count, spacing, variable;
    /** @} */
    /** @{ first and last node, and the ratio B of a geometric axis (else 0) */
    trk_real lo, hi, ratio;
    /** @} */
    const trk_real *values;  /**< explicit spacing, else NULL */
};

/** One section of a parsed table; data and values point into the table. */
struct trk_table_section {
    /** @{ section id, number of axes, values per cell and interpolation rule (enum trk_table_interp) */
    uint32_t id, naxes, ncomp, interp;
    /** @} */
    struct trk_table_axis axis[TRK_TABLE_MAX_AXES];  /**< axes 0 .. naxes - 1 */
    const trk_real *data;  /**< count reals, row-major over the axes, ncomp per cell */
    size_t count;            /**< reals in data */
};

/** CRC-32 (zlib's): crc = trk_crc32(0, p, n); continue with crc = trk_crc32(crc, q, m). */
uint32_t trk_crc32(uint32_t crc, const void *bytes, size_t len);

/** Validate a table of either real width without using it (see the list
 * above); fills *info (may be NULL). TRK_E_ARG for a NULL bytes pointer. */
TRK_NODISCARD trk_status trk_table_check(const void *bytes, size_t len, struct trk_table_info *info);

/** Validate and make *t a view on the bytes for this build (in place). Bytes
 * beyond the table's total size are ignored. *t untouched on error. */
TRK_NODISCARD trk_status trk_table_parse(struct trk_table *t, const void *bytes, size_t len);

/** @{ */
/** Parameters by name. TRK_E_TABLE_KIND when the table has no such
 * parameter or it has the other type; TRK_E_ARG for NULL pointers. */
TRK_NODISCARD trk_status trk_table_param_real(const struct trk_table *t, const char *name, trk_real *v);
TRK_NODISCARD trk_status trk_table_param_int(const struct trk_table *t, const char *name, int64_t *v);
/** @} */

/** Section by id. TRK_E_TABLE_KIND when absent. */
TRK_NODISCARD trk_status trk_table_section(const struct trk_table *t, uint32_t id, struct trk_table_section *s);

/** Value of axis point i (i < count). */
trk_real trk_table_axis_value(const struct trk_table_axis *ax, uint32_t i);

/** Interval of v on the axis: *i in 0..count-2 and *frac = (v - v_i)/(v_{i+1} - v_i)
 * in the axis variable (for log spacing in ln v, for geometric spacing in the
 * step index). Outside [lo, hi] *i is the end interval and *frac < 0 or > 1:
 * the caller extrapolates or refuses. TRK_E_NAN for a NaN v; TRK_E_RANGE for
 * v <= 0 on a log axis. */
TRK_NODISCARD trk_status trk_table_axis_locate(const struct trk_table_axis *ax, trk_real v, uint32_t *i,
                                               trk_real *frac);

/** Cubic Hermite interpolation on [x_i, x_i + h] at x_i + f h (f in [0, 1];
 * outside, the same cubic extrapolates) from values y0, y1 and derivatives
 * d0, d1 (per unit of x). The one implementation used by the library and the
 * tools. */
static inline trk_real trk_table_hermite(trk_real y0, trk_real y1, trk_real d0, trk_real d1,
                                         trk_real h, trk_real f)
{
    /** y0 + f (h d0 + f (3 dy - h (2 d0 + d1) + f (h (d0 + d1) - 2 dy))), dy = y1 - y0 */
    const trk_real dy = y1 - y0, hd0 = h * d0, hd1 = h * d1;
    return y0 + f * (hd0 + f * (3 * dy - 2 * hd0 - hd1 + f * (hd0 + hd1 - 2 * dy)));
}

#endif
