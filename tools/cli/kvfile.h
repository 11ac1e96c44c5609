/* kvfile.h - "key = value" configuration files for the tools.
 *
 * Syntax, one setting per line:
 *     # comment (also after a value: "gate_prob = 0.99   # P_G")
 *     key = value
 * Blank lines are skipped; whitespace around key and value is trimmed; the
 * value is everything after the first '=' up to a '#' or the end of the line
 * (values cannot contain '#'). A key may appear several times: the last one
 * wins, and command-line settings applied after the file override it.
 * Lines are at most KV_MAX_LINE - 2 characters. */
#ifndef TRK_TOOLS_KVFILE_H
#define TRK_TOOLS_KVFILE_H

#include <stddef.h>
#include <stdio.h>

#include "number.h"

#define KV_MAX_LINE 1024

/* Set one key. Return 0 on success, 1 for an unknown key, -1 for a bad value
 * (with a message in err, which has room for errlen bytes). For an unknown
 * key the setter leaves in err the known key nearest to it (cli_near,
 * suggest.h), or "" when none is close: the message then says
 * "unknown setting 'gama'; did you mean 'gamma'?". */
typedef int (*kv_setter)(void *ctx, const char *key, const char *value, char *err,
                         size_t errlen);

/* Read path and call set for every setting, in file order. Returns 0, or -1
 * with "PATH:LINE: message" in err (unreadable file, syntax error, unknown
 * key, bad value, over-long line) at the first problem. */
int kv_parse_file(const char *path, kv_setter set, void *ctx, char *err, size_t errlen);
/* The same on an open stream (read to its end or the first problem; not
 * closed), `name` in the messages instead of PATH. */
int kv_parse_stream(FILE *f, const char *name, kv_setter set, void *ctx, char *err, size_t errlen);

/* Split "key=value" (command-line form) and call set. 0 / -1 with message. */
int kv_parse_assignment(const char *kv, kv_setter set, void *ctx, char *err, size_t errlen);

/* Value parsers (kv_parse_double, kv_parse_number, kv_strtod: number.h):
 * 0 on success, -1 unless s is entirely one integer in [lo, hi]. */
int kv_parse_long(const char *s, long lo, long hi, long *v);
/* Comma- or space-separated list of exactly n finite numbers. */
int kv_parse_doubles(const char *s, double *v, int n);

#endif
