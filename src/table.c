/* table.c - validation of lookup tables and in-place views on them
 * (trk/table.h; docs/conventions.md "Lookup tables").
 *
 * Every read is preceded by a bounds check against the total size, which is
 * itself checked against the caller's length first: whatever the bytes, the
 * reader stays inside [bytes, bytes + len). Reals are validated on their bit
 * patterns (finite, ordered) so that a table of either width can be checked
 * by any build without floating-point conversions. */
#include "trk/table.h"

#define HDR TRK_TABLE_HEADER_SIZE
#define PRM TRK_TABLE_PARAM_SIZE
#define SEC TRK_TABLE_SECTION_SIZE
#define AXS TRK_TABLE_AXIS_SIZE

static const unsigned char magic[8] = {'T', 'R', 'K', 'T', 'A', 'B', 'L', 'E'};

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint64_t rd64(const unsigned char *p) { return (uint64_t)rd32(p) | (uint64_t)rd32(p + 4) << 32; }

static int zero_bytes(const unsigned char *p, uint64_t n)
{
    for (uint64_t i = 0; i < n; i++)
        if (p[i]) return 0;
    return 1;
}

/* --- reals as bit patterns of width rs (4 or 8) */
static uint64_t real_bits(const unsigned char *p, uint32_t rs) { return rs == 4 ? rd32(p) : rd64(p); }

static int bits_finite(uint64_t b, uint32_t rs)
{
    return rs == 4 ? ((b >> 23) & 0xffu) != 0xffu : ((b >> 52) & 0x7ffu) != 0x7ffu;
}

/* Order-preserving unsigned key of a finite value. */
static uint64_t bits_key(uint64_t b, uint32_t rs)
{
    const uint64_t sign = rs == 4 ? (uint64_t)0x80000000u : (uint64_t)1 << 63;
    const uint64_t mask = rs == 4 ? (uint64_t)0xffffffffu : ~(uint64_t)0;
    return (b & sign) ? (~b & mask) : (b | sign);
}

static int bits_positive(uint64_t b, uint32_t rs)
{
    const uint64_t sign = rs == 4 ? (uint64_t)0x80000000u : (uint64_t)1 << 63;
    return !(b & sign) && b != 0;
}

static int bits_one(uint64_t b, uint32_t rs)
{
    return rs == 4 ? b == 0x3f800000u : b == ((uint64_t)0x3ff << 52);
}

/* A real slot (8 bytes): finite value, unused bytes zero. */
static int real_slot_ok(const unsigned char *p, uint32_t rs)
{
    return bits_finite(real_bits(p, rs), rs) && (rs == 8 || zero_bytes(p + 4, 4));
}

static uint64_t align8(uint64_t v) { return (v + 7u) & ~(uint64_t)7u; }

/* The next payload array of n reals: starts at the cursor rounded up to 8
 * (padding zero), fits before the trailer, every value finite. */
static trk_status next_array(const unsigned char *b, uint64_t limit, uint64_t *cur, uint64_t n,
                             uint32_t rs, uint64_t *off)
{
    const uint64_t start = align8(*cur);
    if (start > limit || n > (limit - start) >> (rs == 4 ? 2 : 3)) return TRK_E_TABLE_CORRUPT;
    if (!zero_bytes(b + *cur, start - *cur)) return TRK_E_TABLE_CORRUPT;
    for (uint64_t i = 0; i < n; i++)
        if (!bits_finite(real_bits(b + start + i * rs, rs), rs)) return TRK_E_TABLE_CORRUPT;
    *off = start;
    *cur = start + n * rs;
    return TRK_OK;
}

static int name_char(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

static trk_status check_params(const unsigned char *b, uint32_t np, uint32_t rs)
{
    for (uint32_t k = 0; k < np; k++) {
        const unsigned char *p = b + HDR + (uint64_t)k * PRM;
        uint32_t n = 0;
        while (n < TRK_TABLE_NAME_MAX && p[n]) {
            if (!name_char(p[n])) return TRK_E_TABLE_CORRUPT;
            n++;
        }
        if (n == 0 || n == TRK_TABLE_NAME_MAX || !zero_bytes(p + n, TRK_TABLE_NAME_MAX - n))
            return TRK_E_TABLE_CORRUPT;
        for (uint32_t j = 0; j < k; j++) {
            const unsigned char *q = b + HDR + (uint64_t)j * PRM;
            uint32_t c = 0;
            while (c < TRK_TABLE_NAME_MAX && p[c] == q[c]) c++;
            if (c == TRK_TABLE_NAME_MAX) return TRK_E_TABLE_CORRUPT; /* duplicate name */
        }
        const uint32_t type = rd32(p + 32);
        if (rd32(p + 36) != 0) return TRK_E_TABLE_CORRUPT;
        if (type == TRK_TABLE_PARAM_REAL) {
            if (!real_slot_ok(p + 40, rs)) return TRK_E_TABLE_CORRUPT;
        } else if (type != TRK_TABLE_PARAM_INT) {
            return TRK_E_TABLE_CORRUPT;
        }
    }
    return TRK_OK;
}

/* One axis record; explicit values are the next payload array. */
static trk_status check_axis(const unsigned char *b, const unsigned char *ax, uint32_t rs,
                             uint64_t limit, uint64_t *cur, uint64_t *cells)
{
    const uint32_t count = rd32(ax), spacing = rd32(ax + 4), var = rd32(ax + 8), voff = rd32(ax + 12);
    if (count < 2 || count > TRK_TABLE_MAX_COUNT) return TRK_E_TABLE_CORRUPT;
    if (spacing == 0 || spacing >= TRK_TABLE_SPACING_COUNT || var == 0) return TRK_E_TABLE_CORRUPT;
    if (!real_slot_ok(ax + 16, rs) || !real_slot_ok(ax + 24, rs) || !real_slot_ok(ax + 32, rs))
        return TRK_E_TABLE_CORRUPT;
    const uint64_t lo = real_bits(ax + 16, rs), hi = real_bits(ax + 24, rs), ratio = real_bits(ax + 32, rs);
    if (!(bits_key(lo, rs) < bits_key(hi, rs))) return TRK_E_TABLE_CORRUPT;
    if (spacing == TRK_TABLE_SPACING_GEOMETRIC) {
        if (!bits_positive(ratio, rs) || bits_one(ratio, rs)) return TRK_E_TABLE_CORRUPT;
    } else if (ratio != 0) {
        return TRK_E_TABLE_CORRUPT;
    }
    if (spacing == TRK_TABLE_SPACING_LOG && !bits_positive(lo, rs)) return TRK_E_TABLE_CORRUPT;
    if (spacing == TRK_TABLE_SPACING_EXPLICIT) {
        uint64_t off;
        trk_status st = next_array(b, limit, cur, count, rs, &off);
        if (st != TRK_OK) return st;
        if (voff != off) return TRK_E_TABLE_CORRUPT;
        uint64_t prev = real_bits(b + off, rs);
        if (bits_key(prev, rs) != bits_key(lo, rs)) return TRK_E_TABLE_CORRUPT;
        for (uint32_t i = 1; i < count; i++) {
            const uint64_t v = real_bits(b + off + (uint64_t)i * rs, rs);
            if (!(bits_key(prev, rs) < bits_key(v, rs))) return TRK_E_TABLE_CORRUPT;
            prev = v;
        }
        if (bits_key(prev, rs) != bits_key(hi, rs)) return TRK_E_TABLE_CORRUPT;
    } else if (voff != 0) {
        return TRK_E_TABLE_CORRUPT;
    }
    *cells *= count;
    if (*cells > TRK_TABLE_MAX_REALS) return TRK_E_TABLE_CORRUPT;
    return TRK_OK;
}

static trk_status check_sections(const unsigned char *b, const struct trk_table_info *in)
{
    const uint32_t rs = in->real_size, ns = in->n_sections;
    const uint64_t desc0 = HDR + (uint64_t)in->n_params * PRM, limit = (uint64_t)in->size - 4;
    uint64_t cur = desc0 + (uint64_t)ns * SEC;
    for (uint32_t s = 0; s < ns; s++) {
        const unsigned char *d = b + desc0 + (uint64_t)s * SEC;
        const uint32_t id = rd32(d), naxes = rd32(d + 4), ncomp = rd32(d + 8), interp = rd32(d + 12);
        const uint32_t data_off = rd32(d + 16), data_count = rd32(d + 20);
        for (uint32_t j = 0; j < s; j++)
            if (rd32(b + desc0 + (uint64_t)j * SEC) == id) return TRK_E_TABLE_CORRUPT;
        if (naxes < 1 || naxes > TRK_TABLE_MAX_AXES) return TRK_E_TABLE_CORRUPT;
        if (ncomp < 1 || ncomp > TRK_TABLE_MAX_COMP) return TRK_E_TABLE_CORRUPT;
        if (interp >= TRK_TABLE_INTERP_COUNT) return TRK_E_TABLE_CORRUPT;
        if (interp == TRK_TABLE_INTERP_HERMITE && (naxes != 1 || ncomp < 2)) return TRK_E_TABLE_CORRUPT;
        if (!zero_bytes(d + 24, 8)) return TRK_E_TABLE_CORRUPT;
        uint64_t cells = 1;
        for (uint32_t a = 0; a < TRK_TABLE_MAX_AXES; a++) {
            const unsigned char *ax = d + 32 + a * AXS;
            if (a >= naxes) {
                if (!zero_bytes(ax, AXS)) return TRK_E_TABLE_CORRUPT;
                continue;
            }
            trk_status st = check_axis(b, ax, rs, limit, &cur, &cells);
            if (st != TRK_OK) return st;
        }
        const uint64_t n = cells * ncomp;
        if (n > TRK_TABLE_MAX_REALS || n != data_count) return TRK_E_TABLE_CORRUPT;
        uint64_t off;
        trk_status st = next_array(b, limit, &cur, n, rs, &off);
        if (st != TRK_OK) return st;
        if (off != data_off) return TRK_E_TABLE_CORRUPT;
    }
    const uint64_t end = align8(cur);
    if (end != limit || !zero_bytes(b + cur, end - cur)) return TRK_E_TABLE_CORRUPT;
    return TRK_OK;
}

/* A real of this build's width from table bytes (any alignment). */
static trk_real load_real(const unsigned char *p)
{
    trk_real v;
    unsigned char *d = (unsigned char *)&v;
    for (size_t i = 0; i < sizeof v; i++) d[i] = p[i];
    return v;
}

/* Computed axes (linear, log, geometric) of a table of this build's width:
 * every node finite and strictly above the previous one in this build's
 * arithmetic, and the constants of trk_table_axis_locate finite, so that
 * lookups never divide by zero or meet an infinity (e.g. a range wider than
 * the largest real, or a geometric ratio so small that nodes coincide). */
static trk_status check_computed_axes(const unsigned char *b, const struct trk_table_info *in)
{
    const size_t desc0 = HDR + (size_t)in->n_params * PRM;
    for (uint32_t s = 0; s < in->n_sections; s++) {
        const unsigned char *d = b + desc0 + (size_t)s * SEC;
        for (uint32_t a = 0; a < rd32(d + 4); a++) {
            const unsigned char *x = d + 32 + a * AXS;
            struct trk_table_axis ax;
            ax.count = rd32(x);
            ax.spacing = rd32(x + 4);
            ax.variable = rd32(x + 8);
            ax.lo = load_real(x + 16);
            ax.hi = load_real(x + 24);
            ax.ratio = load_real(x + 32);
            ax.values = NULL;
            if (ax.spacing == TRK_TABLE_SPACING_EXPLICIT) continue; /* checked on its bits */
            const trk_real n1 = (trk_real)(ax.count - 1);
            trk_real c1 = ax.hi - ax.lo, c2 = n1 / c1;
            if (ax.spacing == TRK_TABLE_SPACING_LOG) {
                c1 = trk_log(ax.hi / ax.lo);
                c2 = n1 / c1;
            } else if (ax.spacing == TRK_TABLE_SPACING_GEOMETRIC) {
                c1 = (trk_pow(ax.ratio, n1) - 1) / (ax.hi - ax.lo);
                c2 = trk_log(ax.ratio);
            }
            if (!isfinite(c1) || !isfinite(c2) || c1 == 0 || c2 == 0) return TRK_E_TABLE_CORRUPT;
            trk_real prev = trk_table_axis_value(&ax, 0);
            if (!isfinite(prev)) return TRK_E_TABLE_CORRUPT;
            for (uint32_t i = 1; i < ax.count; i++) {
                const trk_real v = trk_table_axis_value(&ax, i);
                if (!isfinite(v) || !(v > prev)) return TRK_E_TABLE_CORRUPT;
                prev = v;
            }
        }
    }
    return TRK_OK;
}

trk_status trk_table_check(const void *bytes, size_t len, struct trk_table_info *info)
{
    if (!bytes) return TRK_E_ARG;
    const unsigned char *b = bytes;
    if (len < HDR) return TRK_E_TABLE_TRUNCATED;
    for (int i = 0; i < 8; i++)
        if (b[i] != magic[i]) return TRK_E_TABLE_MAGIC;
    if (rd32(b + 8) != TRK_TABLE_FORMAT_VERSION) return TRK_E_TABLE_VERSION;
    const uint32_t total = rd32(b + 16);
    if (total > len) return TRK_E_TABLE_TRUNCATED;
    if (rd32(b + 12) != HDR || total < HDR + SEC + 4 || total % 8 != 4) return TRK_E_TABLE_CORRUPT;
    struct trk_table_info in;
    in.size = total;
    in.crc = rd32(b + total - 4);
    if (trk_crc32(0, b, total - 4) != in.crc) return TRK_E_TABLE_CRC;
    in.kind = rd32(b + 20);
    in.kind_version = rd32(b + 24);
    in.real_size = rd32(b + 28);
    in.n_params = rd32(b + 32);
    in.n_sections = rd32(b + 36);
    if (in.kind == 0 || (in.real_size != 4 && in.real_size != 8) || !zero_bytes(b + 40, 24))
        return TRK_E_TABLE_CORRUPT;
    if (in.n_params > TRK_TABLE_MAX_PARAMS || in.n_sections < 1 || in.n_sections > TRK_TABLE_MAX_SECTIONS)
        return TRK_E_TABLE_CORRUPT;
    if (HDR + (uint64_t)in.n_params * PRM + (uint64_t)in.n_sections * SEC > (uint64_t)total - 4)
        return TRK_E_TABLE_CORRUPT;
    trk_status st = check_params(b, in.n_params, in.real_size);
    if (st != TRK_OK) return st;
    st = check_sections(b, &in);
    if (st != TRK_OK) return st;
    if (in.real_size == sizeof(trk_real)) {
        st = check_computed_axes(b, &in);
        if (st != TRK_OK) return st;
    }
    if (info) *info = in;
    return TRK_OK;
}

static int host_little_endian(void)
{
    const union {
        uint32_t u;
        unsigned char c[4];
    } probe = {1u};
    return probe.c[0] == 1;
}

trk_status trk_table_parse(struct trk_table *t, const void *bytes, size_t len)
{
    if (!t || !bytes) return TRK_E_ARG;
    struct trk_table_info in;
    trk_status st = trk_table_check(bytes, len, &in);
    if (st != TRK_OK) return st;
    if (in.real_size != sizeof(trk_real)) return TRK_E_TABLE_REAL;
    if (!host_little_endian()) return TRK_E_UNSUPPORTED;
    if ((uintptr_t)bytes % TRK_TABLE_ALIGN != 0) return TRK_E_ARG;
    t->bytes = bytes;
    t->info = in;
    return TRK_OK;
}


static int valid_view(const struct trk_table *t) { return t && t->bytes; }

static const unsigned char *find_param(const struct trk_table *t, const char *name)
{
    for (uint32_t k = 0; k < t->info.n_params; k++) {
        const unsigned char *p = t->bytes + HDR + (size_t)k * PRM;
        uint32_t c = 0;
        while (c < TRK_TABLE_NAME_MAX && p[c] == (unsigned char)name[c] && name[c]) c++;
        if (c < TRK_TABLE_NAME_MAX && p[c] == 0 && name[c] == 0) return p;
    }
    return NULL;
}

trk_status trk_table_param_real(const struct trk_table *t, const char *name, trk_real *v)
{
    if (!valid_view(t) || !name || !v) return TRK_E_ARG;
    const unsigned char *p = find_param(t, name);
    if (!p || rd32(p + 32) != TRK_TABLE_PARAM_REAL) return TRK_E_TABLE_KIND;
    *v = load_real(p + 40);
    return TRK_OK;
}

trk_status trk_table_param_int(const struct trk_table *t, const char *name, int64_t *v)
{
    if (!valid_view(t) || !name || !v) return TRK_E_ARG;
    const unsigned char *p = find_param(t, name);
    if (!p || rd32(p + 32) != TRK_TABLE_PARAM_INT) return TRK_E_TABLE_KIND;
    const uint64_t u = rd64(p + 40);
    /* two's complement without implementation-defined conversion */
    *v = u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)(~u) - 1;
    return TRK_OK;
}

trk_status trk_table_section(const struct trk_table *t, uint32_t id, struct trk_table_section *s)
{
    if (!valid_view(t) || !s) return TRK_E_ARG;
    const size_t desc0 = HDR + (size_t)t->info.n_params * PRM;
    for (uint32_t k = 0; k < t->info.n_sections; k++) {
        const unsigned char *d = t->bytes + desc0 + (size_t)k * SEC;
        if (rd32(d) != id) continue;
        struct trk_table_section r;
        r.id = id;
        r.naxes = rd32(d + 4);
        r.ncomp = rd32(d + 8);
        r.interp = rd32(d + 12);
        for (uint32_t a = 0; a < TRK_TABLE_MAX_AXES; a++) {
            const unsigned char *ax = d + 32 + a * AXS;
            struct trk_table_axis *o = &r.axis[a];
            o->count = rd32(ax);
            o->spacing = rd32(ax + 4);
            o->variable = rd32(ax + 8);
            o->lo = load_real(ax + 16);
            o->hi = load_real(ax + 24);
            o->ratio = load_real(ax + 32);
            o->values = o->spacing == TRK_TABLE_SPACING_EXPLICIT
                            ? (const trk_real *)(const void *)(t->bytes + rd32(ax + 12))
                            : NULL;
        }
        r.data = (const trk_real *)(const void *)(t->bytes + rd32(d + 16));
        r.count = rd32(d + 20);
        *s = r;
        return TRK_OK;
    }
    return TRK_E_TABLE_KIND;
}

trk_real trk_table_axis_value(const struct trk_table_axis *ax, uint32_t i)
{
    if (!ax || ax->count < 2 || i >= ax->count) return (trk_real)NAN;
    const trk_real n1 = (trk_real)(ax->count - 1), fi = (trk_real)i;
    if (i == ax->count - 1 && ax->spacing != TRK_TABLE_SPACING_EXPLICIT) return ax->hi;
    switch (ax->spacing) {
    case TRK_TABLE_SPACING_LINEAR: return ax->lo + fi * (ax->hi - ax->lo) / n1;
    case TRK_TABLE_SPACING_LOG: return ax->lo * trk_exp(fi / n1 * trk_log(ax->hi / ax->lo));
    case TRK_TABLE_SPACING_GEOMETRIC:
        return ax->lo + (ax->hi - ax->lo) * (trk_pow(ax->ratio, fi) - 1) / (trk_pow(ax->ratio, n1) - 1);
    case TRK_TABLE_SPACING_EXPLICIT: return ax->values ? ax->values[i] : (trk_real)NAN;
    default: return (trk_real)NAN;
    }
}

trk_status trk_table_axis_locate(const struct trk_table_axis *ax, trk_real v, uint32_t *i, trk_real *frac)
{
    if (!ax || !i || !frac || ax->count < 2) return TRK_E_ARG;
    if (!isfinite(v)) return TRK_E_NAN;
    const uint32_t last = ax->count - 2; /* last interval */
    const trk_real n1 = (trk_real)(ax->count - 1);
    trk_real u;
    switch (ax->spacing) {
    case TRK_TABLE_SPACING_LINEAR: u = (v - ax->lo) / (ax->hi - ax->lo) * n1; break;
    case TRK_TABLE_SPACING_LOG:
        if (!(v > 0)) return TRK_E_RANGE;
        u = trk_log(v / ax->lo) / trk_log(ax->hi / ax->lo) * n1;
        break;
    case TRK_TABLE_SPACING_GEOMETRIC: {
        const trk_real arg = 1 + (v - ax->lo) * (trk_pow(ax->ratio, n1) - 1) / (ax->hi - ax->lo);
        if (!(arg > 0)) return TRK_E_RANGE;
        u = trk_log(arg) / trk_log(ax->ratio);
        break;
    }
    case TRK_TABLE_SPACING_EXPLICIT: {
        if (!ax->values) return TRK_E_ARG;
        uint32_t lo = 0, hi = ax->count - 1; /* values[lo] <= v < values[hi] when inside */
        while (hi - lo > 1) {
            const uint32_t mid = lo + (hi - lo) / 2;
            if (ax->values[mid] <= v) lo = mid;
            else hi = mid;
        }
        if (lo > last) lo = last;
        *i = lo;
        *frac = (v - ax->values[lo]) / (ax->values[lo + 1] - ax->values[lo]);
        return TRK_OK;
    }
    default: return TRK_E_ARG;
    }
    if (!isfinite(u)) return TRK_E_RANGE;
    uint32_t k;
    if (u <= 0) k = 0;
    else if (u >= (trk_real)last) k = last;
    else k = (uint32_t)u;
    *i = k;
    *frac = u - (trk_real)k;
    return TRK_OK;
}
