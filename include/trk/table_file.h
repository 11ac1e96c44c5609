/** @file
 * trk/table_file.h - host helpers (libtrk_host.a, stdio; no heap): read a
 * table file into caller memory and parse it in place (trk/table.h).
 *
 *   size_t n;  trk_table_file_size("k1.tbl", &n);
 *   static uint64_t buf[4096];                     (8-byte aligned storage)
 *   struct trk_table t;
 *   trk_table_load_file("k1.tbl", buf, sizeof buf, &t, &n);
 */
#ifndef TRK_TABLE_FILE_H
#define TRK_TABLE_FILE_H

#include "trk/table.h"

/** Largest table file: one array of TRK_TABLE_MAX_REALS 8-byte reals (the
 * format's own limit, trk/table.h) plus its header and sections. */
#define TRK_TABLE_FILE_MAX_BYTES ((size_t)TRK_TABLE_MAX_REALS * 8u + ((size_t)1 << 20))

/** Bytes in the file, counted up to TRK_TABLE_FILE_MAX_BYTES (a longer file,
 * or an endless one such as /dev/zero, is no table: TRK_E_CAPACITY after
 * reading that much). TRK_E_ARG NULL pointer, TRK_E_IO not readable. */
TRK_NODISCARD trk_status trk_table_file_size(const char *path, size_t *size);

/** Read the whole file into buf (cap bytes, aligned to TRK_TABLE_ALIGN) and
 * trk_table_parse it; *t then views buf. *len (may be NULL) gets the bytes read.
 * TRK_E_ARG NULL pointer or misaligned buf, TRK_E_IO unreadable file,
 * TRK_E_CAPACITY file larger than cap, TRK_E_TABLE_CORRUPT bytes after the
 * table's end, otherwise the status of trk_table_parse. *t untouched on error. */
TRK_NODISCARD trk_status trk_table_load_file(const char *path, void *buf, size_t cap, struct trk_table *t,
                                             size_t *len);

#endif
