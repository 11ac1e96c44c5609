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

#define KV_MAX_LINE 1024

/* Set one key. Return 0 on success, 1 for an unknown key, -1 for a bad value
 * (with a message in err, which has room for errlen bytes). */
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

/* One decimal number at the start of s (blanks before it skipped), the
 * number syntax of every tool: strtod's, but no hex ("0x10"); subnormals
 * (4.9e-324) are finite and accepted. *end after it. 0 with *v, or
 * KV_NUM_BAD (no number; *end = s), KV_NUM_NONFINITE (inf, nan) or
 * KV_NUM_RANGE (overflow, or an underflow to 0 such as 1e-400). */
enum { KV_NUM_BAD = -1, KV_NUM_NONFINITE = -2, KV_NUM_RANGE = -3 };
int kv_strtod(const char *s, char **end, double *v);
/* The message of a KV_NUM_ code ("not a finite number", ...). */
const char *kv_num_error(int code);

/* Value parsers: 0 on success, -1 when s is not entirely one finite number
 * (or integer in [lo, hi]). kv_parse_number: the same with the KV_NUM_ code
 * of the failure (for the message, kv_num_error). */
int kv_parse_double(const char *s, double *v);
int kv_parse_number(const char *s, double *v);
int kv_parse_long(const char *s, long lo, long hi, long *v);
/* Comma- or space-separated list of exactly n finite numbers. */
int kv_parse_doubles(const char *s, double *v, int n);

#endif
