/* table_file.c - read a table file into caller memory (trk/table_file.h). */
#include "trk/table_file.h"

#include <stdio.h>

trk_status trk_table_file_size(const char *path, size_t *size)
{
    if (!path || !size) return TRK_E_ARG;
    FILE *fp = fopen(path, "rb");
    if (!fp) return TRK_E_IO;
    size_t n = 0;
    unsigned char chunk[4096];
    for (;;) {
        size_t got = fread(chunk, 1, sizeof chunk, fp);
        n += got;
        if (n > TRK_TABLE_FILE_MAX_BYTES) { /* bounded: /dev/zero never ends */
            fclose(fp);
            return TRK_E_CAPACITY;
        }
        if (got < sizeof chunk) break;
    }
    const int bad = ferror(fp);
    fclose(fp);
    if (bad) return TRK_E_IO;
    *size = n;
    return TRK_OK;
}

trk_status trk_table_load_file(const char *path, void *buf, size_t cap, struct trk_table *t, size_t *len)
{
    if (!path || !buf || !t) return TRK_E_ARG;
    if ((uintptr_t)buf % TRK_TABLE_ALIGN != 0) return TRK_E_ARG;
    FILE *fp = fopen(path, "rb");
    if (!fp) return TRK_E_IO;
    const size_t n = fread(buf, 1, cap, fp);
    int more = 0;
    if (n == cap) { /* anything left does not fit */
        unsigned char probe;
        more = fread(&probe, 1, 1, fp) == 1;
    }
    const int bad = ferror(fp);
    fclose(fp);
    if (bad) return TRK_E_IO;
    if (more) return TRK_E_CAPACITY;
    struct trk_table v;
    trk_status st = trk_table_parse(&v, buf, n);
    if (st != TRK_OK) return st;
    if (v.info.size != n) return TRK_E_TABLE_CORRUPT;
    *t = v;
    if (len) *len = n;
    return TRK_OK;
}
