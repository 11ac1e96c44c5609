/* test_table.c - the lookup-table container (trk/table.h): CRC, layout of a
 * written table, every prefix rejected as truncated, every flipped byte
 * rejected, wrong magic / version / real width, non-finite values,
 * non-increasing explicit axes, inconsistent headers, alignment, parameters,
 * axes of every spacing, the host file loader. Each buffer handed to the
 * reader is malloc'd at exactly its size so that ASan catches an over-read. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fdopen */
#include "trk_test.h"
#include "table_writer.h"
#include "trk/table.h"
#include "trk/table_file.h"

#define OTHER_REAL (sizeof(trk_real) == 8 ? 4u : 8u)

static void put32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void fix_crc(unsigned char *b, size_t len) { put32(b + len - 4, trk_crc32(0, b, len - 4)); }

/* A small table of real width rs: 3 parameters, a 1-axis Hermite section and
 * a 2-axis section with an explicit and a log axis. */
static unsigned char *make_table(uint32_t rs, size_t *len)
{
    struct tablew *w = tablew_new(TRK_TABLE_KIND_Q2_PDAF, 1, rs);
    assert_non_null(w);
    double d1[2 * 5], d2[3 * 4 * 2];
    for (int i = 0; i < 5; i++) {
        d1[2 * i] = i * i;     /* y = x^2 on x = 0..4 */
        d1[2 * i + 1] = 2 * i; /* dy/dx */
    }
    for (int i = 0; i < 24; i++) d2[i] = 0.5 * i - 3;
    const double xs[3] = {-1, 0.25, 7};
    struct tablew_axis a1 = {5, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, 0, 4, 0, NULL};
    struct tablew_axis a2[2] = {{3, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_PD, -1, 7, 0, xs},
                                {4, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_LAMBDA_VG, 0.01, 10, 0, NULL}};
    assert_int_equal(tablew_param_real(w, "pfa", 1e-3), 0);
    assert_int_equal(tablew_param_int(w, "seed", -1234567890123LL), 0);
    assert_int_equal(tablew_param_real(w, "gate_prob", 0.99), 0);
    assert_int_equal(tablew_section(w, 7, 1, &a1, 2, TRK_TABLE_INTERP_HERMITE, d1), 0);
    assert_int_equal(tablew_section(w, 9, 2, a2, 2, TRK_TABLE_INTERP_NONE, d2), 0);
    unsigned char *b;
    assert_int_equal(tablew_finish(w, &b, len), 0);
    tablew_free(w);
    return b;
}

static unsigned char *copy_exact(const unsigned char *b, size_t n)
{
    unsigned char *c = malloc(n ? n : 1);
    assert_non_null(c);
    if (n) memcpy(c, b, n);
    return c;
}

static trk_status check_copy(const unsigned char *b, size_t n)
{
    unsigned char *c = copy_exact(b, n);
    trk_status st = trk_table_check(c, n, NULL);
    free(c);
    return st;
}

static void test_crc(void **state)
{
    (void)state;
    assert_true(trk_crc32(0, "123456789", 9) == 0xCBF43926u); /* the CRC-32 check value */
    assert_true(trk_crc32(0, "", 0) == 0);
    /* incremental = one shot */
    assert_true(trk_crc32(trk_crc32(0, "12345", 5), "6789", 4) == 0xCBF43926u);
}

static void test_roundtrip(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    assert_true(len % 8 == 4);
    struct trk_table_info in;
    TRK_ASSERT_OK(trk_table_check(b, len, &in));
    assert_int_equal(in.kind, TRK_TABLE_KIND_Q2_PDAF);
    assert_int_equal(in.n_params, 3);
    assert_int_equal(in.n_sections, 2);
    assert_int_equal(in.size, len);
    struct trk_table t;
    TRK_ASSERT_OK(trk_table_parse(&t, b, len));
    trk_real v;
    int64_t iv;
    TRK_ASSERT_OK(trk_table_param_real(&t, "pfa", &v));
    TRK_ASSERT_NEAR(v, 1e-3, 0, TRK_TOL(0, 1e-7));
    TRK_ASSERT_OK(trk_table_param_int(&t, "seed", &iv));
    assert_true(iv == -1234567890123LL);
    TRK_ASSERT_STATUS(trk_table_param_real(&t, "seed", &v), TRK_E_TABLE_KIND); /* wrong type */
    TRK_ASSERT_STATUS(trk_table_param_int(&t, "pfa", &iv), TRK_E_TABLE_KIND);
    TRK_ASSERT_STATUS(trk_table_param_real(&t, "pf", &v), TRK_E_TABLE_KIND);  /* prefix only */
    TRK_ASSERT_STATUS(trk_table_param_real(&t, "pfax", &v), TRK_E_TABLE_KIND);
    TRK_ASSERT_STATUS(trk_table_param_real(NULL, "pfa", &v), TRK_E_ARG);

    struct trk_table_section s;
    TRK_ASSERT_OK(trk_table_section(&t, 7, &s));
    assert_int_equal(s.naxes, 1);
    assert_int_equal(s.ncomp, 2);
    assert_int_equal(s.interp, TRK_TABLE_INTERP_HERMITE);
    assert_int_equal(s.count, 10);
    /* Hermite with exact derivatives reproduces y = x^2 (a cubic) exactly */
    for (int k = 0; k <= 40; k++) {
        const trk_real x = (trk_real)k / 10;
        uint32_t i;
        trk_real f;
        TRK_ASSERT_OK(trk_table_axis_locate(&s.axis[0], x, &i, &f));
        const trk_real *c = s.data + 2 * i;
        TRK_ASSERT_NEAR(trk_table_hermite(c[0], c[2], c[1], c[3], 1, f), x * x, TRK_TOL(1e-14, 1e-5), 0);
    }
    TRK_ASSERT_OK(trk_table_section(&t, 9, &s));
    assert_int_equal(s.naxes, 2);
    assert_int_equal(s.count, 24);
    TRK_ASSERT_NEAR(s.data[23], 8.5, 0, 0);
    assert_non_null(s.axis[0].values);
    TRK_ASSERT_NEAR(s.axis[0].values[1], 0.25, 0, 0);
    TRK_ASSERT_STATUS(trk_table_section(&t, 8, &s), TRK_E_TABLE_KIND);
    /* bytes after the table are ignored by parse */
    unsigned char *longer = calloc(1, len + 16);
    memcpy(longer, b, len);
    TRK_ASSERT_OK(trk_table_parse(&t, longer, len + 16));
    assert_int_equal(t.info.size, len);
    free(longer);
    free(b);
}

static void test_axes(void **state)
{
    (void)state;
    const trk_real xs[4] = {1, 2, 4, 8};
    struct trk_table_axis ax[4] = {
        {5, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, 2, 4, 0, NULL},
        {5, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_PFA, TRK_REAL_C(1e-4), TRK_REAL_C(1.0), 0, NULL},
        {5, TRK_TABLE_SPACING_GEOMETRIC, TRK_TABLE_VAR_AMP, 1, 16, 2, NULL},
        {4, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_SNR_DB, 1, 8, 0, xs}};
    const double want[4][5] = {{2, 2.5, 3, 3.5, 4}, {1e-4, 1e-3, 1e-2, 1e-1, 1}, {1, 2, 4, 8, 16}, {1, 2, 4, 8, 0}};
    /* geometric: lo + (hi-lo)(2^i - 1)/(2^4 - 1) = 1 + i-th partial sums of 1,2,4,8 */
    const double geo[5] = {1, 2, 4, 8, 16};
    for (int k = 0; k < 4; k++) {
        for (uint32_t i = 0; i < ax[k].count; i++) {
            const double w = k == 2 ? geo[i] : want[k][i];
            TRK_ASSERT_NEAR(trk_table_axis_value(&ax[k], i), w, 0, TRK_TOL(1e-14, 1e-6));
            uint32_t j;
            trk_real f;
            TRK_ASSERT_OK(trk_table_axis_locate(&ax[k], trk_table_axis_value(&ax[k], i), &j, &f));
            /* node i is the start of interval i, or the end of the last one */
            if (i + 1 < ax[k].count) {
                assert_int_equal(j, i);
                TRK_ASSERT_NEAR(f, 0, TRK_TOL(1e-12, 1e-5), 0);
            } else {
                assert_int_equal(j, i - 1);
                TRK_ASSERT_NEAR(f, 1, TRK_TOL(1e-12, 1e-5), 0);
            }
        }
        assert_true(isnan(trk_table_axis_value(&ax[k], ax[k].count)));
    }
    uint32_t j;
    trk_real f;
    /* midpoints in the axis variable */
    TRK_ASSERT_OK(trk_table_axis_locate(&ax[0], TRK_REAL_C(2.75), &j, &f));
    assert_int_equal(j, 1);
    TRK_ASSERT_NEAR(f, 0.5, TRK_TOL(1e-14, 1e-6), 0);
    TRK_ASSERT_OK(trk_table_axis_locate(&ax[1], trk_sqrt(TRK_REAL_C(1e-7)), &j, &f)); /* halfway in ln */
    assert_int_equal(j, 0);
    TRK_ASSERT_NEAR(f, 0.5, TRK_TOL(1e-12, 1e-5), 0);
    TRK_ASSERT_OK(trk_table_axis_locate(&ax[3], 3, &j, &f));
    assert_int_equal(j, 1);
    TRK_ASSERT_NEAR(f, 0.5, 0, 0);
    /* outside: end intervals with frac < 0 or > 1 */
    TRK_ASSERT_OK(trk_table_axis_locate(&ax[0], 1, &j, &f));
    assert_int_equal(j, 0);
    TRK_ASSERT_NEAR(f, -2, TRK_TOL(1e-14, 1e-6), 0);
    TRK_ASSERT_OK(trk_table_axis_locate(&ax[3], 10, &j, &f));
    assert_int_equal(j, 2);
    TRK_ASSERT_NEAR(f, 1.5, 0, 0);
    /* bad input */
    TRK_ASSERT_STATUS(trk_table_axis_locate(&ax[0], (trk_real)NAN, &j, &f), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_table_axis_locate(&ax[0], (trk_real)INFINITY, &j, &f), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_table_axis_locate(&ax[1], 0, &j, &f), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_table_axis_locate(&ax[1], -1, &j, &f), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_table_axis_locate(&ax[2], -100, &j, &f), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_table_axis_locate(NULL, 1, &j, &f), TRK_E_ARG);
}

static void test_truncated_every_byte(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    TRK_ASSERT_OK(check_copy(b, len));
    for (size_t n = 0; n < len; n++) {
        trk_status st = check_copy(b, n);
        if (st != TRK_E_TABLE_TRUNCATED) fail_msg("prefix of %zu of %zu bytes: %s", n, len, trk_status_str(st));
        struct trk_table t;
        unsigned char *c = copy_exact(b, n);
        assert_true(trk_table_parse(&t, c, n) == TRK_E_TABLE_TRUNCATED);
        free(c);
    }
    free(b);
}

static void test_flipped_every_byte(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    static const unsigned char masks[3] = {0xff, 0x01, 0x80};
    for (size_t i = 0; i < len; i++)
        for (int k = 0; k < 3; k++) {
            unsigned char *c = copy_exact(b, len);
            c[i] ^= masks[k];
            trk_status st = trk_table_check(c, len, NULL);
            if (st == TRK_OK) fail_msg("byte %zu ^ 0x%02x accepted", i, masks[k]);
            /* the status names the first thing found wrong */
            if (i < 8) assert_int_equal(st, TRK_E_TABLE_MAGIC);
            else if (i < 12) assert_int_equal(st, TRK_E_TABLE_VERSION);
            else if (i >= 20) assert_int_equal(st, TRK_E_TABLE_CRC);
            else /* header and total size */
                assert_true(st == TRK_E_TABLE_TRUNCATED || st == TRK_E_TABLE_CORRUPT || st == TRK_E_TABLE_CRC);
            /* with the CRC made right again the structure checks run on the
             * flipped byte (a flip may also give another valid table, e.g. a
             * data value): never a crash or an over-read (ASan), and a
             * parsed view stays inside the buffer */
            fix_crc(c, len);
            struct trk_table t;
            if (trk_table_parse(&t, c, len) == TRK_OK) {
                for (uint32_t s = 0; s < t.info.n_sections; s++) {
                    const size_t d = TRK_TABLE_HEADER_SIZE + (size_t)t.info.n_params * TRK_TABLE_PARAM_SIZE +
                                     (size_t)s * TRK_TABLE_SECTION_SIZE;
                    struct trk_table_section sec;
                    TRK_ASSERT_OK(trk_table_section(&t, get32(c + d), &sec));
                    const unsigned char *lo = (const unsigned char *)sec.data;
                    assert_true(lo >= c && lo + sec.count * sizeof(trk_real) <= c + len - 4);
                }
            }
            free(c);
        }
    free(b);
}

static void test_magic_version_width(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    struct trk_table t;
    unsigned char *c = copy_exact(b, len);
    c[0] = 'X';
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_MAGIC);
    memcpy(c, b, len);
    put32(c + 8, 2); /* a future format version */
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_VERSION);
    TRK_ASSERT_STATUS(trk_table_parse(&t, c, len), TRK_E_TABLE_VERSION);
    memcpy(c, b, len);
    put32(c + 8, 0);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_VERSION);
    /* real width field not 4 or 8 */
    memcpy(c, b, len);
    put32(c + 28, 2);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* the other width as the field claims: the layout no longer adds up */
    memcpy(c, b, len);
    put32(c + 28, OTHER_REAL);
    fix_crc(c, len);
    assert_true(trk_table_check(c, len, NULL) != TRK_OK);
    /* size field smaller than the table */
    memcpy(c, b, len);
    put32(c + 16, (uint32_t)len - 8);
    put32(c + len - 12, trk_crc32(0, c, len - 12));
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    free(c);

    /* a well-formed table of the other real width: checked, not usable here */
    size_t olen;
    unsigned char *o = make_table(OTHER_REAL, &olen);
    struct trk_table_info in;
    TRK_ASSERT_OK(trk_table_check(o, olen, &in));
    assert_int_equal(in.real_size, OTHER_REAL);
    TRK_ASSERT_STATUS(trk_table_parse(&t, o, olen), TRK_E_TABLE_REAL);
    free(o);

    /* alignment: in-place use needs 8-byte alignment */
    unsigned char *mis = malloc(len + 8);
    memcpy(mis + 1, b, len);
    TRK_ASSERT_OK(trk_table_check(mis + 1, len, NULL));
    TRK_ASSERT_STATUS(trk_table_parse(&t, mis + 1, len), TRK_E_ARG);
    free(mis);
    TRK_ASSERT_STATUS(trk_table_check(NULL, len, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_table_parse(NULL, b, len), TRK_E_ARG);
    free(b);
}

/* Offset of section k's data and of its first axis's explicit values. */
static size_t section_desc(const unsigned char *b, uint32_t k)
{
    (void)b;
    return TRK_TABLE_HEADER_SIZE + 3 * TRK_TABLE_PARAM_SIZE + (size_t)k * TRK_TABLE_SECTION_SIZE;
}

static void put_real_bits(unsigned char *p, int which)
{
    /* which: 0 NaN, 1 +inf, 2 -inf */
    if (sizeof(trk_real) == 8) {
        static const uint64_t bits[3] = {0x7ff8000000000000ull, 0x7ff0000000000000ull, 0xfff0000000000000ull};
        for (int i = 0; i < 8; i++) p[i] = (unsigned char)(bits[which] >> (8 * i));
    } else {
        static const uint32_t bits[3] = {0x7fc00000u, 0x7f800000u, 0xff800000u};
        put32(p, bits[which]);
    }
}

static void test_nonfinite_nonmonotone(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    unsigned char *c = copy_exact(b, len);
    const size_t d0 = section_desc(b, 0), d1 = section_desc(b, 1);
    const size_t data0 = get32(b + d0 + 16), vals1 = get32(b + d1 + 32 + 12), data1 = get32(b + d1 + 16);
    const size_t where[] = {data0 + 3 * sizeof(trk_real), data1, data1 + 23 * sizeof(trk_real),
                            vals1 + sizeof(trk_real), TRK_TABLE_HEADER_SIZE + 40, /* param pfa */
                            d0 + 32 + 16, d0 + 32 + 24,                         /* axis lo, hi */
                            d1 + 32 + TRK_TABLE_AXIS_SIZE + 16};
    for (size_t k = 0; k < sizeof where / sizeof where[0]; k++)
        for (int which = 0; which < 3; which++) {
            memcpy(c, b, len);
            put_real_bits(c + where[k], which);
            fix_crc(c, len);
            trk_status st = trk_table_check(c, len, NULL);
            if (st != TRK_E_TABLE_CORRUPT) fail_msg("non-finite at %zu (%d): %s", where[k], which, trk_status_str(st));
        }
    /* explicit axis values not strictly increasing: swap the first two, or
     * make two equal */
    memcpy(c, b, len);
    memcpy(c + vals1, b + vals1 + sizeof(trk_real), sizeof(trk_real));
    memcpy(c + vals1 + sizeof(trk_real), b + vals1, sizeof(trk_real));
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    memcpy(c + vals1 + 2 * sizeof(trk_real), c + vals1 + sizeof(trk_real), sizeof(trk_real));
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* lo >= hi of a linear axis */
    memcpy(c, b, len);
    memcpy(c + d0 + 32 + 16, b + d0 + 32 + 24, sizeof(trk_real));
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* non-positive lo of a log axis */
    memcpy(c, b, len);
    memset(c + d1 + 32 + TRK_TABLE_AXIS_SIZE + 16, 0, sizeof(trk_real));
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* data count disagreeing with the axes, offsets moved, nonzero padding */
    memcpy(c, b, len);
    put32(c + d0 + 20, get32(b + d0 + 20) - 2);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    put32(c + d1 + 16, get32(b + d1 + 16) + 8);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    c[44] = 1; /* reserved header byte */
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    {   /* padding after an array: a float table's 3 explicit values end at 12 bytes */
        size_t flen;
        unsigned char *f = make_table(4, &flen);
        const size_t fv = get32(f + section_desc(f, 1) + 32 + 12);
        TRK_ASSERT_OK(trk_table_check(f, flen, NULL));
        f[fv + 13] = 1;
        fix_crc(f, flen);
        TRK_ASSERT_STATUS(trk_table_check(f, flen, NULL), TRK_E_TABLE_CORRUPT);
        free(f);
    }
    /* parameter names: bad character, empty, duplicate */
    memcpy(c, b, len);
    c[TRK_TABLE_HEADER_SIZE] = 'P';
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    c[TRK_TABLE_HEADER_SIZE] = 0;
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    memcpy(c + TRK_TABLE_HEADER_SIZE + 2 * TRK_TABLE_PARAM_SIZE, b + TRK_TABLE_HEADER_SIZE, TRK_TABLE_NAME_MAX);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* duplicate section id */
    memcpy(c, b, len);
    put32(c + d1, get32(b + d0));
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    /* too many sections / parameters for the size */
    memcpy(c, b, len);
    put32(c + 36, 17);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    put32(c + 32, 40);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(trk_table_check(c, len, NULL), TRK_E_TABLE_CORRUPT);
    free(c);
    free(b);
}

static void test_writer_refuses(void **state)
{
    (void)state;
    struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, 1, sizeof(trk_real));
    assert_int_equal(tablew_param_real(w, "Bad", 1), -1);
    assert_int_equal(tablew_param_real(w, "nan", NAN), -1);
    assert_int_equal(tablew_param_real(w, "ok", 1), 0);
    assert_int_equal(tablew_param_real(w, "ok", 2), -1);
    const double xs[3] = {0, 2, 1}; /* not increasing: the self-check refuses */
    const double d[3] = {1, 2, 3};
    struct tablew_axis ax = {3, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_X, 0, 1, 0, xs};
    assert_int_equal(tablew_section(w, 1, 1, &ax, 1, TRK_TABLE_INTERP_LINEAR, d), 0);
    unsigned char *b = NULL;
    size_t len;
    assert_int_equal(tablew_finish(w, &b, &len), -1);
    assert_null(b);
    tablew_free(w);
    /* computed axes whose nodes are not finite and increasing in this
     * build's arithmetic: a geometric ratio so small that nodes coincide, a
     * linear range wider than the largest real */
    const double d5[5] = {1, 2, 3, 4, 5};
    const double huge = sizeof(trk_real) == 8 ? 1.7e308 : 3e38;
    struct tablew_axis bad_axes[2] = {
        {5, TRK_TABLE_SPACING_GEOMETRIC, TRK_TABLE_VAR_PD, 0.1, 0.99, 1e-30, NULL},
        {5, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, -huge, huge, 0, NULL}};
    for (int k = 0; k < 2; k++) {
        w = tablew_new(TRK_TABLE_KIND_AMP, 1, sizeof(trk_real));
        assert_int_equal(tablew_section(w, 1, 1, &bad_axes[k], 1, TRK_TABLE_INTERP_LINEAR, d5), 0);
        assert_int_equal(tablew_finish(w, &b, &len), -1);
        tablew_free(w);
    }
    /* a float table cannot hold 1e300 */
    w = tablew_new(TRK_TABLE_KIND_AMP, 1, 4);
    assert_int_equal(tablew_param_real(w, "big", 1e300), -1);
    tablew_free(w);
}

static void test_file(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(sizeof(trk_real), &len);
    char path[] = "/tmp/trk_test_table_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *fp = fdopen(fd, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(b, 1, len, fp), len);
    fclose(fp);
    size_t n;
    TRK_ASSERT_OK(trk_table_file_size(path, &n));
    assert_int_equal(n, len);
    static uint64_t buf[1024];
    struct trk_table t;
    TRK_ASSERT_OK(trk_table_load_file(path, buf, sizeof buf, &t, &n));
    assert_int_equal(n, len);
    assert_true(t.bytes == (const unsigned char *)buf);
    TRK_ASSERT_STATUS(trk_table_load_file(path, buf, len - 1, &t, &n), TRK_E_CAPACITY);
    TRK_ASSERT_STATUS(trk_table_load_file(path, (unsigned char *)buf + 4, sizeof buf - 8, &t, &n), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_table_load_file("/nonexistent/trk.tbl", buf, sizeof buf, &t, &n), TRK_E_IO);
    TRK_ASSERT_STATUS(trk_table_file_size("/nonexistent/trk.tbl", &n), TRK_E_IO);
    /* an endless file is no table: the count stops at the format's bound
     * (/dev/zero never returned) */
    FILE *zero = fopen("/dev/zero", "rb");
    if (zero) {
        fclose(zero);
        TRK_ASSERT_STATUS(trk_table_file_size("/dev/zero", &n), TRK_E_CAPACITY);
    }
    /* trailing bytes in a file are a defect */
    fp = fopen(path, "ab");
    fputs("junk", fp);
    fclose(fp);
    TRK_ASSERT_STATUS(trk_table_load_file(path, buf, sizeof buf, &t, &n), TRK_E_TABLE_CORRUPT);
    /* a truncated file */
    fp = fopen(path, "wb");
    assert_int_equal(fwrite(b, 1, len / 2, fp), len / 2);
    fclose(fp);
    TRK_ASSERT_STATUS(trk_table_load_file(path, buf, sizeof buf, &t, &n), TRK_E_TABLE_TRUNCATED);
    remove(path);
    free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crc),
        cmocka_unit_test(test_roundtrip),
        cmocka_unit_test(test_axes),
        cmocka_unit_test(test_truncated_every_byte),
        cmocka_unit_test(test_flipped_every_byte),
        cmocka_unit_test(test_magic_version_width),
        cmocka_unit_test(test_nonfinite_nonmonotone),
        cmocka_unit_test(test_writer_refuses),
        cmocka_unit_test(test_file),
    };
    return trk_run_tests("table", tests, NULL, NULL);
}
