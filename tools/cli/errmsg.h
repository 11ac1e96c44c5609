/* errmsg.h - the tools' "0, or -1 with a message in err" convention. */
#ifndef TRK_TOOLS_ERRMSG_H
#define TRK_TOOLS_ERRMSG_H

#include <stddef.h>

/* Formats the message into err (when err is not NULL and n > 0) and
 * returns -1: `return errmsg_fail(err, errlen, "bad x %g", x);`. */
int errmsg_fail(char *err, size_t n, const char *fmt, ...);

#endif
