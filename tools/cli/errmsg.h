/* errmsg.h - the tools' "0, or -1 with a message in err" convention. */
#ifndef TRK_TOOLS_ERRMSG_H
#define TRK_TOOLS_ERRMSG_H

#include <stddef.h>

#include "trk/types.h"

/* Formats the message into err (when err is not NULL and n > 0) and
 * returns -1: `return errmsg_fail(err, errlen, "bad x %g", x);`. */
int errmsg_fail(char *err, size_t n, const char *fmt, ...);

/* A library status for a person: "plain words (TRK_E_NAME)"
 * (trk_status_message, trk_status_str) into buf; returns buf. */
const char *errmsg_status(trk_status st, char *buf, size_t n);
/* The same in a buffer of the enclosing block (a compound literal), for a
 * "%s" argument: fprintf(stderr, "trk-x: %s\n", ERRMSG_STATUS(st)). */
#define ERRMSG_STATUS(st) errmsg_status((st), (char[ERRMSG_STATUS_MAX]){0}, ERRMSG_STATUS_MAX)
#define ERRMSG_STATUS_MAX 160

#endif
