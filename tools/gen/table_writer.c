/* table_writer.c - serialise lookup tables (table_writer.h, trk/table.h). */
#include "errmsg.h"
#include "table_writer.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


struct tw_param {
    char name[TRK_TABLE_NAME_MAX];
    uint32_t type;
    double real;
    int64_t integer;
};

struct tw_section {
    uint32_t id, naxes, ncomp, interp;
    struct tablew_axis axis[TRK_TABLE_MAX_AXES];
    double *values[TRK_TABLE_MAX_AXES];
    double *data;
    size_t count;
};

struct tablew {
    uint32_t kind, kind_version, real_size;
    uint32_t n_params, n_sections;
    struct tw_param params[TRK_TABLE_MAX_PARAMS];
    struct tw_section sections[TRK_TABLE_MAX_SECTIONS];
    char err[200];
};

static int fail(struct tablew *w, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(w->err, sizeof w->err, fmt, ap);
    va_end(ap);
    return -1;
}

const char *tablew_error(const struct tablew *w) { return w ? w->err : "out of memory"; }

struct tablew *tablew_new(uint32_t kind, uint32_t kind_version, uint32_t real_size)
{
    if (kind == 0 || (real_size != 4 && real_size != 8)) return NULL;
    struct tablew *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    w->kind = kind;
    w->kind_version = kind_version;
    w->real_size = real_size;
    return w;
}

void tablew_free(struct tablew *w)
{
    if (!w) return;
    for (uint32_t s = 0; s < w->n_sections; s++) {
        free(w->sections[s].data);
        for (int a = 0; a < (int)TRK_TABLE_MAX_AXES; a++) free(w->sections[s].values[a]);
    }
    free(w);
}

/* Representable in the table's width (finite after rounding). */
static int real_ok(const struct tablew *w, double v)
{
    if (!isfinite(v)) return 0;
    return w->real_size == 8 || isfinite((float)v);
}

static int add_param(struct tablew *w, const char *name, uint32_t type, double r, int64_t i)
{
    size_t n = strlen(name);
    if (n == 0 || n >= TRK_TABLE_NAME_MAX) return fail(w, "parameter name '%s': 1..31 characters", name);
    for (size_t k = 0; k < n; k++)
        if (!(islower((unsigned char)name[k]) || isdigit((unsigned char)name[k]) || name[k] == '_'))
            return fail(w, "parameter name '%s': only [a-z0-9_]", name);
    for (uint32_t k = 0; k < w->n_params; k++)
        if (strcmp(w->params[k].name, name) == 0) return fail(w, "duplicate parameter '%s'", name);
    if (w->n_params >= TRK_TABLE_MAX_PARAMS) return fail(w, "more than %u parameters", TRK_TABLE_MAX_PARAMS);
    if (type == TRK_TABLE_PARAM_REAL && !real_ok(w, r))
        return fail(w, "parameter '%s' = %g is not a finite %s", name, r, w->real_size == 4 ? "float" : "double");
    struct tw_param *p = &w->params[w->n_params++];
    memset(p, 0, sizeof *p);
    memcpy(p->name, name, n);
    p->type = type;
    p->real = r;
    p->integer = i;
    return 0;
}

int tablew_param_real(struct tablew *w, const char *name, double v)
{
    return add_param(w, name, TRK_TABLE_PARAM_REAL, v, 0);
}

int tablew_param_int(struct tablew *w, const char *name, int64_t v)
{
    return add_param(w, name, TRK_TABLE_PARAM_INT, 0, v);
}

int tablew_section(struct tablew *w, uint32_t id, uint32_t naxes, const struct tablew_axis *axes,
                   uint32_t ncomp, uint32_t interp, const double *data)
{
    if (w->n_sections >= TRK_TABLE_MAX_SECTIONS) return fail(w, "more than %u sections", TRK_TABLE_MAX_SECTIONS);
    if (naxes < 1 || naxes > TRK_TABLE_MAX_AXES) return fail(w, "section %u: 1..3 axes", id);
    if (ncomp < 1 || ncomp > TRK_TABLE_MAX_COMP) return fail(w, "section %u: 1..8 components", id);
    for (uint32_t s = 0; s < w->n_sections; s++)
        if (w->sections[s].id == id) return fail(w, "duplicate section id %u", id);
    struct tw_section *sec = &w->sections[w->n_sections];
    memset(sec, 0, sizeof *sec);
    sec->id = id;
    sec->naxes = naxes;
    sec->ncomp = ncomp;
    sec->interp = interp;
    size_t cells = 1;
    for (uint32_t a = 0; a < naxes; a++) {
        const struct tablew_axis *ax = &axes[a];
        if (ax->count < 2 || ax->count > TRK_TABLE_MAX_COUNT) return fail(w, "section %u axis %u: count", id, a);
        if (!real_ok(w, ax->lo) || !real_ok(w, ax->hi) || !real_ok(w, ax->ratio))
            return fail(w, "section %u axis %u: non-finite range", id, a);
        sec->axis[a] = *ax;
        sec->axis[a].values = NULL;
        if (ax->spacing == TRK_TABLE_SPACING_EXPLICIT) {
            if (!ax->values) return fail(w, "section %u axis %u: explicit values missing", id, a);
            sec->values[a] = malloc(ax->count * sizeof(double));
            if (!sec->values[a]) return fail(w, "out of memory");
            memcpy(sec->values[a], ax->values, ax->count * sizeof(double));
        }
        cells *= ax->count;
        if (cells > TRK_TABLE_MAX_REALS) return fail(w, "section %u: too many cells", id);
    }
    sec->count = cells * ncomp;
    if (sec->count > TRK_TABLE_MAX_REALS) return fail(w, "section %u: too many values", id);
    sec->data = malloc(sec->count * sizeof(double));
    if (!sec->data) return fail(w, "out of memory");
    for (size_t i = 0; i < sec->count; i++) {
        if (!real_ok(w, data[i])) {
            w->n_sections++; /* so tablew_free releases it */
            return fail(w, "section %u: value %zu = %g is not finite in the table's width", id, i, data[i]);
        }
        sec->data[i] = data[i];
    }
    w->n_sections++;
    return 0;
}

static void put32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static void put64(unsigned char *p, uint64_t v)
{
    for (int i = 0; i < 8; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static void put_real(unsigned char *p, double v, uint32_t rs)
{
    if (rs == 4) {
        float f = (float)v;
        uint32_t b;
        memcpy(&b, &f, 4);
        put32(p, b);
    } else {
        uint64_t b;
        memcpy(&b, &v, 8);
        put64(p, b);
    }
}

static size_t align8(size_t v) { return (v + 7u) & ~(size_t)7u; }

int tablew_finish(struct tablew *w, unsigned char **bytes, size_t *len)
{
    if (w->n_sections == 0) return fail(w, "a table needs at least one section");
    const uint32_t rs = w->real_size;
    /* layout: header, params, descriptors, then arrays in section order */
    size_t cur = TRK_TABLE_HEADER_SIZE + (size_t)w->n_params * TRK_TABLE_PARAM_SIZE +
                 (size_t)w->n_sections * TRK_TABLE_SECTION_SIZE;
    size_t voff[TRK_TABLE_MAX_SECTIONS][TRK_TABLE_MAX_AXES] = {{0}}, doff[TRK_TABLE_MAX_SECTIONS];
    for (uint32_t s = 0; s < w->n_sections; s++) {
        const struct tw_section *sec = &w->sections[s];
        for (uint32_t a = 0; a < sec->naxes; a++)
            if (sec->values[a]) {
                cur = align8(cur);
                voff[s][a] = cur;
                cur += (size_t)sec->axis[a].count * rs;
            }
        cur = align8(cur);
        doff[s] = cur;
        cur += sec->count * rs;
    }
    const size_t total = align8(cur) + 4;
    if (total > 0xffffffffu) return fail(w, "table larger than 4 GB");
    /* 8-aligned (malloc) and zeroed: padding and reserved bytes are zero */
    unsigned char *b = calloc(1, total);
    if (!b) return fail(w, "out of memory");
    memcpy(b, "TRKTABLE", 8);
    put32(b + 8, TRK_TABLE_FORMAT_VERSION);
    put32(b + 12, TRK_TABLE_HEADER_SIZE);
    put32(b + 16, (uint32_t)total);
    put32(b + 20, w->kind);
    put32(b + 24, w->kind_version);
    put32(b + 28, rs);
    put32(b + 32, w->n_params);
    put32(b + 36, w->n_sections);
    for (uint32_t k = 0; k < w->n_params; k++) {
        unsigned char *p = b + TRK_TABLE_HEADER_SIZE + (size_t)k * TRK_TABLE_PARAM_SIZE;
        const struct tw_param *pr = &w->params[k];
        memcpy(p, pr->name, strlen(pr->name));
        put32(p + 32, pr->type);
        if (pr->type == TRK_TABLE_PARAM_REAL) put_real(p + 40, pr->real, rs);
        else put64(p + 40, (uint64_t)pr->integer);
    }
    const size_t desc0 = TRK_TABLE_HEADER_SIZE + (size_t)w->n_params * TRK_TABLE_PARAM_SIZE;
    for (uint32_t s = 0; s < w->n_sections; s++) {
        const struct tw_section *sec = &w->sections[s];
        unsigned char *d = b + desc0 + (size_t)s * TRK_TABLE_SECTION_SIZE;
        put32(d, sec->id);
        put32(d + 4, sec->naxes);
        put32(d + 8, sec->ncomp);
        put32(d + 12, sec->interp);
        put32(d + 16, (uint32_t)doff[s]);
        put32(d + 20, (uint32_t)sec->count);
        for (uint32_t a = 0; a < sec->naxes; a++) {
            unsigned char *ax = d + 32 + a * TRK_TABLE_AXIS_SIZE;
            const struct tablew_axis *x = &sec->axis[a];
            put32(ax, x->count);
            put32(ax + 4, x->spacing);
            put32(ax + 8, x->variable);
            put32(ax + 12, (uint32_t)voff[s][a]);
            put_real(ax + 16, x->lo, rs);
            put_real(ax + 24, x->hi, rs);
            put_real(ax + 32, x->spacing == TRK_TABLE_SPACING_GEOMETRIC ? x->ratio : 0, rs);
            if (sec->values[a])
                for (uint32_t i = 0; i < x->count; i++) put_real(b + voff[s][a] + (size_t)i * rs, sec->values[a][i], rs);
        }
        for (size_t i = 0; i < sec->count; i++) put_real(b + doff[s] + i * rs, sec->data[i], rs);
    }
    put32(b + total - 4, trk_crc32(0, b, total - 4));
    trk_status st = trk_table_check(b, total, NULL);
    if (st != TRK_OK) {
        free(b);
        return fail(w, "the table does not pass trk_table_check: %s (axis ranges, monotone explicit axes?)",
                    ERRMSG_STATUS(st));
    }
    *bytes = b;
    *len = total;
    return 0;
}
