/* registry.c - the table of vector kinds, collected by the build from every
 * TRK_VEC_KIND(name, float_abs, float_rel, speed) line in tools/vec/kind_*.c. */
#include <string.h>

#include "vec.h"

#define TRK_VEC_KIND_ENTRY(kname, fabs_, frel_, speed_) TRK_VEC_KIND(kname, fabs_, frel_, speed_);
#include "vec_kinds.inc"
#undef TRK_VEC_KIND_ENTRY

static const struct vec_kind kinds[] = {
#define TRK_VEC_KIND_ENTRY(kname, fabs_, frel_, speed_) {#kname, trk_vec_kind_##kname, fabs_, frel_, speed_},
#include "vec_kinds.inc"
#undef TRK_VEC_KIND_ENTRY
    {NULL, NULL, 0, 0, VEC_FAST}};

const struct vec_kind *vec_kind_find(const char *name)
{
    for (size_t i = 0; kinds[i].name; i++)
        if (strcmp(kinds[i].name, name) == 0) return &kinds[i];
    return NULL;
}

const struct vec_kind *vec_kinds(size_t *n)
{
    *n = sizeof kinds / sizeof kinds[0] - 1;
    return kinds;
}

int vec_kind_listed(const char *list, const char *name)
{
    const size_t n = strlen(name);
    for (const char *p = list; p && *p;) {
        const char *e = strchr(p, ',');
        const size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0) return 1;
        p = e ? e + 1 : NULL;
    }
    return 0;
}
