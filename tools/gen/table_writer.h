/* table_writer.h - build lookup tables in the trk/table.h format (host tools:
 * trk-tablegen, tests). The layout is the library's (trk/table.h); the CRC is
 * the library's trk_crc32, so writer and reader cannot disagree.
 *
 *   struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, 1, 8);
 *   tablew_param_real(w, "pfa", 1e-3);
 *   struct tablew_axis ax = {n, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, 0, 40, 0, NULL};
 *   tablew_section(w, id, 1, &ax, 2, TRK_TABLE_INTERP_HERMITE, data);   (data copied)
 *   tablew_finish(w, &bytes, &len);    (malloc'd, 8-aligned; free() it)
 *   tablew_free(w);
 * Values are given as doubles and stored in the table's real width (4: each
 * rounded to float; a value that overflows float is an error).
 * Every function returns 0, or -1 with tablew_error(w) saying why. */
#ifndef TRK_TABLE_WRITER_H
#define TRK_TABLE_WRITER_H

#include <stddef.h>
#include <stdint.h>

#include "trk/table.h"

struct tablew;

struct tablew_axis {
    uint32_t count, spacing, variable;
    double lo, hi, ratio;     /* ratio: geometric spacing only */
    const double *values;     /* explicit spacing: count values (copied) */
};

struct tablew *tablew_new(uint32_t kind, uint32_t kind_version, uint32_t real_size);
int tablew_param_real(struct tablew *w, const char *name, double v);
int tablew_param_int(struct tablew *w, const char *name, int64_t v);
int tablew_section(struct tablew *w, uint32_t id, uint32_t naxes, const struct tablew_axis *axes,
                   uint32_t ncomp, uint32_t interp, const double *data);
/* Serialise (and self-check with trk_table_check) into a new buffer. */
int tablew_finish(struct tablew *w, unsigned char **bytes, size_t *len);
const char *tablew_error(const struct tablew *w);
void tablew_free(struct tablew *w);

/* Write bytes to a file (binary), or as C source: a union with a double
 * member (8-byte alignment in C99) named `name`, and NAME_SIZE. `comment`
 * (may be NULL) goes into the file's leading comment. 0 or -1 (errno).
 * Both replace path atomically (fileio.h fileio_create): on a failed write
 * an existing file is left byte-identical (table_write.c). */
int tablew_write_bin(const char *path, const unsigned char *bytes, size_t len);
int tablew_write_c(const char *path, const char *name, const unsigned char *bytes, size_t len,
                   const char *comment);

#endif
