/* number.h - the one decimal number syntax of the tools (config values,
 * options, vector files). No stdio: the QEMU vector image
 * compiles it too (mk/qemu.mk). */
#ifndef TRK_TOOLS_NUMBER_H
#define TRK_TOOLS_NUMBER_H

/* One decimal number at the start of s (blanks before it skipped), the
 * number syntax of every tool: strtod's, but no hex ("0x10"); subnormals
 * (4.9e-324) are finite and accepted. *end after it. 0 with *v, or
 * KV_NUM_BAD (no number; *end = s), KV_NUM_NONFINITE (inf, nan) or
 * KV_NUM_RANGE (overflow, or an underflow to 0 such as 1e-400). */
enum { KV_NUM_BAD = -1, KV_NUM_NONFINITE = -2, KV_NUM_RANGE = -3 };
int kv_strtod(const char *s, char **end, double *v);
/* The message of a KV_NUM_ code ("not a finite number", ...). */
const char *kv_num_error(int code);

/* 0 on success, -1 when s is not entirely one finite number (blanks after
 * it allowed). kv_parse_number: the same with the KV_NUM_ code of the
 * failure (for the message, kv_num_error). */
int kv_parse_double(const char *s, double *v);
int kv_parse_number(const char *s, double *v);

#endif
