/* fileio.h - whole-file reading and atomic file writing for the tools and
 * tests (every read bounded, every write checked, a
 * failed write never destroys the file it was to replace). */
#ifndef TRK_TOOLS_FILEIO_H
#define TRK_TOOLS_FILEIO_H

#include <stddef.h>
#include <stdio.h>

/* The contents of the file at `path` in one malloc'd buffer (malloc's
 * alignment), *len bytes, followed by a NUL byte that *len does not count
 * (text can be parsed in place as a string). At most `max` bytes are read: a
 * longer file (or an endless one, /dev/zero) gives NULL with errno EFBIG
 * after reading max + 1 bytes. NULL on failure with errno set (fopen's,
 * EFBIG, ENOMEM, or EIO after a read error) and *len = 0. Free with free(). */
void *fileio_read_max(const char *path, size_t max, size_t *len);
/* fileio_read_max without a bound (trusted files only: tests). */
void *fileio_read(const char *path, size_t *len);

/* An output file replaced atomically: written to a temporary file next to
 * it (PATH.tmp-XXXXXX), renamed onto PATH by fileio_commit only after every
 * write, the flush, fsync and close succeeded; on any failure the temporary
 * file is removed and PATH is left as it was (byte-identical). A PATH that
 * exists and is not a regular file (/dev/full, /dev/stdout, a FIFO) is
 * written in place, with the same checks. */
struct fileio_out {
    FILE *f;       /* write through this (fprintf, fwrite, ...) or fileio_put */
    int in_place;  /* 1: PATH is no regular file, written directly */
    int err;       /* errno of the first failed fileio_put (0: none) */
    char path[1024], tmp[1040];
};

/* Open o for path ("wb" when binary, else "w"). o->f, or NULL with errno
 * (ENAMETOOLONG for a path of 1024 bytes or more, or mkstemp's/fopen's). */
FILE *fileio_create(struct fileio_out *o, const char *path, int binary);
/* bytes[len] to o->f, keeping the errno of the first write that fails
 * (write(2)'s: ENOSPC on a full disk), which fileio_commit then reports;
 * after a failure it writes nothing more. 0, or -1 with errno. */
int fileio_put(struct fileio_out *o, const void *bytes, size_t len);
/* Finish o: 0 when every byte reached PATH, else -1 with errno (a failed
 * fileio_put's, EIO after a failed fprintf/fwrite on o->f, else fflush's,
 * fsync's, fclose's or rename's) and PATH untouched. o->f is closed either
 * way. */
int fileio_commit(struct fileio_out *o);
/* Give up o (an error elsewhere): close and remove the temporary file; PATH
 * untouched. Safe on an o whose fileio_create failed or that was committed. */
void fileio_discard(struct fileio_out *o);

/* Remove the temporary files of writes to path that never finished (a
 * process killed between fileio_create and fileio_commit): the regular
 * files PATH.tmp-XXXXXX, X mkstemp's letters and digits, in PATH's
 * directory. Only for a path no other process is writing. Their count. */
size_t fileio_remove_stale(const char *path);

/* bytes[len] into path through fileio_create/fileio_commit: 0, or -1 with errno. */
int fileio_write(const char *path, const void *bytes, size_t len);

#endif
