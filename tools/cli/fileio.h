/* fileio.h - whole-file reading for the tools and tests. */
#ifndef TRK_TOOLS_FILEIO_H
#define TRK_TOOLS_FILEIO_H

#include <stddef.h>

/* The contents of the file at `path` in one malloc'd buffer (malloc's
 * alignment), *len bytes, followed by a NUL byte that *len does not count
 * (text can be parsed in place as a string). NULL on failure with errno set
 * (fopen's, ENOMEM, or EIO after a read error) and *len = 0. Free with free(). */
void *fileio_read(const char *path, size_t *len);

#endif
