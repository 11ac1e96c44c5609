/* fileio.c - bounded whole-file reading and atomic writing (fileio.h). */
#define _POSIX_C_SOURCE 200809L
#include "fileio.h"

#include <dirent.h>
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void *fileio_read_max(const char *path, size_t max, size_t *len)
{
    *len = 0;
    if (max > SIZE_MAX - 2) max = SIZE_MAX - 2; /* room for the probe byte and the NUL */
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    size_t cap = 1 << 16, n = 0;
    unsigned char *buf = malloc(cap);
    int too_big = 0;
    while (buf) {
        /* read up to max + 1 bytes in all: one more than allowed proves "too long" */
        size_t want = cap - 1 - n; /* one byte kept for the NUL */
        if (want > max + 1 - n) want = max + 1 - n;
        const size_t got = fread(buf + n, 1, want, fp);
        n += got;
        if (n > max) {
            too_big = 1;
            break;
        }
        if (got < want) break; /* end of file or error */
        if (n < cap - 1) continue;
        unsigned char *nb = cap <= SIZE_MAX / 2 ? realloc(buf, cap * 2) : NULL;
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        cap *= 2;
    }
    int err = 0;
    if (!buf) err = ENOMEM;
    else if (too_big) err = EFBIG;
    else if (ferror(fp)) err = EIO;
    fclose(fp);
    if (err) {
        free(buf);
        errno = err;
        return NULL;
    }
    buf[n] = 0;
    *len = n;
    return buf;
}

void *fileio_read(const char *path, size_t *len) { return fileio_read_max(path, SIZE_MAX, len); }

FILE *fileio_create(struct fileio_out *o, const char *path, int binary)
{
    memset(o, 0, sizeof *o);
    const size_t n = strlen(path);
    if (n == 0 || n >= sizeof o->path) {
        errno = n ? ENAMETOOLONG : ENOENT;
        return NULL;
    }
    memcpy(o->path, path, n + 1);
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) { /* a device or FIFO: no rename over it */
        o->in_place = 1;
        o->f = fopen(path, binary ? "wb" : "w");
        return o->f;
    }
    snprintf(o->tmp, sizeof o->tmp, "%s.tmp-XXXXXX", path);
    const int fd = mkstemp(o->tmp);
    if (fd < 0) {
        o->tmp[0] = 0;
        return NULL;
    }
    /* the permissions fopen would give a new file (mkstemp's are 0600) */
    const mode_t um = umask(0);
    umask(um);
    if (fchmod(fd, (mode_t)0666 & ~um) != 0 || !(o->f = fdopen(fd, binary ? "wb" : "w"))) {
        const int e = errno;
        close(fd);
        remove(o->tmp);
        o->tmp[0] = 0;
        errno = e;
        return NULL;
    }
    return o->f;
}

int fileio_put(struct fileio_out *o, const void *bytes, size_t len)
{
    if (o->err || !o->f) {
        errno = o->err ? o->err : EBADF;
        return -1;
    }
    errno = 0;
    if (len && fwrite(bytes, 1, len, o->f) != len) {
        o->err = errno ? errno : EIO; /* write(2)'s reason, e.g. ENOSPC */
        errno = o->err;
        return -1;
    }
    return 0;
}

int fileio_commit(struct fileio_out *o)
{
    if (!o->f) {
        errno = EBADF;
        return -1;
    }
    int err = o->err ? o->err : ferror(o->f) ? EIO : 0;
    if (fflush(o->f) != 0 && !err) err = errno ? errno : EIO;
    if (!o->in_place && !err && fsync(fileno(o->f)) != 0) err = errno;
    if (fclose(o->f) != 0 && !err) err = errno ? errno : EIO;
    o->f = NULL;
    if (!err && !o->in_place && rename(o->tmp, o->path) != 0) err = errno;
    if (err) {
        if (!o->in_place) remove(o->tmp);
        o->tmp[0] = 0;
        errno = err;
        return -1;
    }
    o->tmp[0] = 0;
    return 0;
}

void fileio_discard(struct fileio_out *o)
{
    const int e = errno;
    if (o->f) fclose(o->f);
    o->f = NULL;
    if (!o->in_place && o->tmp[0]) remove(o->tmp);
    o->tmp[0] = 0;
    errno = e;
}

/* name is base + ".tmp-" + 6 letters or digits (fileio_create's pattern) */
static int stale_name(const char *name, const char *base, size_t nb)
{
    if (strncmp(name, base, nb) != 0 || strncmp(name + nb, ".tmp-", 5) != 0) return 0;
    const char *x = name + nb + 5;
    for (int i = 0; i < 6; i++)
        if (!((x[i] >= 'a' && x[i] <= 'z') || (x[i] >= 'A' && x[i] <= 'Z') || (x[i] >= '0' && x[i] <= '9')))
            return 0;
    return x[6] == 0;
}

size_t fileio_remove_stale(const char *path)
{
    char dir[1024] = ".";
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
    const size_t nd = slash ? (size_t)(slash - path) : 0, nb = strlen(base);
    if (nd >= sizeof dir || nb == 0) return 0;
    if (slash && nd == 0) strcpy(dir, "/");
    else if (slash) memcpy(dir, path, nd), dir[nd] = 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    size_t n = 0;
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        char full[1100];
        struct stat st;
        if (!stale_name(e->d_name, base, nb)) continue;
        if (snprintf(full, sizeof full, "%s/%s", dir, e->d_name) >= (int)sizeof full) continue;
        if (lstat(full, &st) == 0 && S_ISREG(st.st_mode) && remove(full) == 0) n++;
    }
    closedir(d);
    return n;
}

int fileio_write(const char *path, const void *bytes, size_t len)
{
    struct fileio_out o;
    if (!fileio_create(&o, path, 1)) return -1;
    (void)fileio_put(&o, bytes, len); /* a failure: fileio_commit reports it */
    return fileio_commit(&o);
}
