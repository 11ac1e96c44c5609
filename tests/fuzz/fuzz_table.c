/* fuzz_table.c - libFuzzer target: the table container parser
 * (include/trk/table.h: trk_table_check, trk_table_parse and the accessors)
 * on arbitrary bytes.
 *
 * The input is copied into an 8-byte aligned buffer of exactly its size (the
 * parser requires the alignment; ASan then catches a read past the end). On
 * an accepted table every section is looked up by the ids of its descriptors
 * and its axes are evaluated and searched (ends, middle, outside, NaN);
 * parameters are looked up by the names they hold. Invariants (abort = a
 * finding): check and parse agree on the verdict for this build's real width;
 * an accepted table's arrays lie inside the buffer; axis values are finite
 * and increasing; locate returns an interval inside the axis.
 * To make the CRC no obstacle, a second pass re-computes the CRC trailer of
 * the input (when the header's total size fits) and parses that too, so the
 * fuzzer reaches the layout checks behind the CRC.
 * An accepted amplitude table (kind TRK_TABLE_KIND_AMP) also goes through
 * trk_amplitude_init_table (the kind's own checks); a model it accepts is
 * evaluated (ln l^a and inverse survival at the ends, inside, outside): the
 * results must be finite whenever the status is TRK_OK. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "trk/amplitude.h"
#include "trk/table.h"

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void inside(const void *p, size_t n_bytes, const unsigned char *buf, size_t len)
{
    const unsigned char *c = p;
    if (n_bytes == 0) return;
    if (!c || c < buf || c > buf + len || n_bytes > (size_t)(buf + len - c)) abort();
}

static void exercise(const unsigned char *buf, size_t len)
{
    struct trk_table_info info;
    trk_status chk = trk_table_check(buf, len, &info);
    struct trk_table t;
    trk_status st = trk_table_parse(&t, buf, len);
    if (st == TRK_OK && chk != TRK_OK) abort();
    if (chk == TRK_OK && st != TRK_OK && st != TRK_E_TABLE_REAL && st != TRK_E_UNSUPPORTED) abort();
    if (st != TRK_OK) return;
    if (t.info.size > len || t.info.n_sections > TRK_TABLE_MAX_SECTIONS) abort();
    const size_t sec0 = TRK_TABLE_HEADER_SIZE + (size_t)t.info.n_params * TRK_TABLE_PARAM_SIZE;
    for (uint32_t k = 0; k < t.info.n_params; k++) {
        char name[TRK_TABLE_NAME_MAX];
        memcpy(name, buf + TRK_TABLE_HEADER_SIZE + (size_t)k * TRK_TABLE_PARAM_SIZE, sizeof name);
        name[sizeof name - 1] = '\0';
        trk_real r;
        int64_t i64;
        trk_status a = trk_table_param_real(&t, name, &r);
        trk_status b = trk_table_param_int(&t, name, &i64);
        if ((a == TRK_OK) == (b == TRK_OK)) abort(); /* exactly one type */
        if (a == TRK_OK && !isfinite(r)) abort();
    }
    trk_real dummy;
    if (trk_table_param_real(&t, "NOT A NAME", &dummy) == TRK_OK) abort();
    for (uint32_t k = 0; k < t.info.n_sections; k++) {
        uint32_t id = rd32(buf + sec0 + (size_t)k * TRK_TABLE_SECTION_SIZE);
        struct trk_table_section s;
        if (trk_table_section(&t, id, &s) != TRK_OK) abort();
        if (s.naxes < 1 || s.naxes > TRK_TABLE_MAX_AXES) abort();
        inside(s.data, s.count * sizeof(trk_real), buf, len);
        size_t cells = s.ncomp;
        for (uint32_t a = 0; a < s.naxes; a++) {
            const struct trk_table_axis *ax = &s.axis[a];
            if (ax->count < 2) abort();
            cells *= ax->count;
            if (ax->values) inside(ax->values, ax->count * sizeof(trk_real), buf, len);
            trk_real prev = -(trk_real)INFINITY;
            uint32_t pts[3] = {0, ax->count / 2, ax->count - 1};
            for (int j = 0; j < 3; j++) {
                trk_real v = trk_table_axis_value(ax, pts[j]);
                if (!isfinite(v) || (j > 0 && pts[j] > pts[j - 1] && !(v > prev))) abort();
                prev = v;
            }
            const trk_real probes[6] = {ax->lo, ax->hi, (ax->lo + ax->hi) / 2, ax->lo - 1, ax->hi * 2,
                                        (trk_real)NAN};
            for (int j = 0; j < 6; j++) {
                uint32_t i;
                trk_real frac;
                if (trk_table_axis_locate(ax, probes[j], &i, &frac) == TRK_OK && i > ax->count - 2) abort();
            }
        }
        if (cells != s.count) abort();
    }
    struct trk_table_section none;
    for (uint32_t k = 0; k < t.info.n_sections; k++)
        if (rd32(buf + sec0 + (size_t)k * TRK_TABLE_SECTION_SIZE) == 0xFFFFFFFFu) return;
    if (trk_table_section(&t, 0xFFFFFFFFu, &none) == TRK_OK) abort();

    static struct trk_amplitude m;
    if (t.info.kind != TRK_TABLE_KIND_AMP || trk_amplitude_init_table(&m, &t) != TRK_OK) return;
    const trk_real th = trk_amplitude_threshold(&m);
    if (!isfinite(th) || th < 0) abort();
    const trk_real amps[7] = {th, th * (trk_real)1.0001, th + 1, th * 3, th * 50, th * 1e6f, (trk_real)INFINITY};
    for (int j = 0; j < 7; j++) {
        trk_real llr;
        if (trk_amplitude_log_lr(&m, amps[j], &llr) == TRK_OK && !isfinite(llr)) abort();
    }
    const trk_real xs[6] = {0, (trk_real)1e-6, 1, 10, 39.9f, 1e4f};
    for (int src = 0; src <= 1; src++)
        for (int j = 0; j < 6; j++) {
            trk_real a;
            if (trk_amplitude_inv_sf(&m, src, xs[j], &a) == TRK_OK && (!isfinite(a) || a < th * (trk_real)0.999))
                abort();
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* exactly sized, 8-byte aligned copy (calloc's alignment) */
    unsigned char *buf = calloc(1, size ? size : 1);
    if (!buf) return 0;
    if (size) memcpy(buf, data, size);
    exercise(buf, size);
    /* the same bytes with a correct CRC trailer at the header's total size */
    if (size >= TRK_TABLE_HEADER_SIZE + 4) {
        uint32_t total = rd32(buf + 16);
        if (total >= TRK_TABLE_HEADER_SIZE + 4 && total <= size) {
            uint32_t crc = trk_crc32(0, buf, total - 4);
            for (int i = 0; i < 4; i++) buf[total - 4 + i] = (unsigned char)(crc >> (8 * i));
            exercise(buf, size);
        }
    }
    free(buf);
    return 0;
}
