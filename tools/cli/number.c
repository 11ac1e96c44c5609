/* number.c - the one decimal number syntax of the tools (number.h). */
#include "number.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

int kv_strtod(const char *s, char **end, double *v)
{
    *end = (char *)s;
    const char *p = s;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '+' || *p == '-') p++;
    /* decimal only: strtod would also take hex ("0x10") */
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) return KV_NUM_BAD;
    errno = 0;
    const double d = strtod(s, end);
    if (*end == s) return KV_NUM_BAD;
    if (!isfinite(d)) return errno == ERANGE ? KV_NUM_RANGE : KV_NUM_NONFINITE;
    /* ERANGE with a nonzero result: a subnormal (4.9e-324), finite and kept;
     * with 0: the number underflowed entirely (1e-400) */
    if (errno == ERANGE && d == 0) return KV_NUM_RANGE;
    *v = d;
    return 0;
}

int kv_parse_double(const char *s, double *v) { return kv_parse_number(s, v) == 0 ? 0 : -1; }

int kv_parse_number(const char *s, double *v)
{
    char *end;
    double d;
    const int r = kv_strtod(s, &end, &d);
    if (r) return r;
    while (*end == ' ' || *end == '\t') end++;
    if (*end) return KV_NUM_BAD;
    *v = d;
    return 0;
}

const char *kv_num_error(int code)
{
    switch (code) {
    case KV_NUM_NONFINITE: return "not a finite number";
    case KV_NUM_RANGE: return "beyond the range of a double (overflow, or underflow to 0)";
    default: return "not a decimal number";
    }
}
