/* errmsg.c - error messages of the tools (errmsg.h). */
#include "errmsg.h"

#include <stdarg.h>
#include <stdio.h>

int errmsg_fail(char *err, size_t n, const char *fmt, ...)
{
    if (err && n) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

const char *errmsg_status(trk_status st, char *buf, size_t n)
{
    snprintf(buf, n, "%s (%s)", trk_status_message(st), trk_status_str(st));
    return buf;
}
