/* fuzz_kvfile.c - libFuzzer target: the "key = value" configuration reader
 * (tools/cli/kvfile.c) and the tracker settings behind it
 * (tools/cli/tracker_config.c) on arbitrary bytes (config files
 * are hostile input).
 *
 * The input is read as a config file (kv_parse_stream over fmemopen) twice:
 * once with a setter that only checks what the reader hands it, once with
 * the tracker's own setter (tcfg_set). Invariants (abort = a finding):
 *   - every key is non-empty, every key and value trimmed, without '#',
 *     '\n' or '=' in the key, and shorter than a line;
 *   - the value parsers never return a non-finite number;
 *   - a refused file has a message naming the file;
 *   - a configuration the tracker accepted, written back (tcfg_write), is
 *     read again without error and writes back the same text (nothing a
 *     file can set is lost or changed by the round trip).
 * No table is loaded (tcfg_load/tcfg_check open files): paths stay text. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kvfile.h"
#include "tracker_config.h"

static int blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

/* The checking setter: 0 for even-length keys, 1 (unknown) or -1 (bad value) otherwise. */
static int check_setter(void *ctx, const char *key, const char *value, char *err, size_t errlen)
{
    long *n = ctx;
    const size_t kl = strlen(key), vl = strlen(value);
    if (kl == 0 || kl + vl >= KV_MAX_LINE) abort();
    if (strpbrk(key, "#\n=") || strpbrk(value, "#\n")) abort();
    if (blank(key[0]) || blank(key[kl - 1]) || (vl && (blank(value[0]) || blank(value[vl - 1])))) abort();
    double d, v3[3];
    long l;
    if (kv_parse_double(value, &d) == 0 && !isfinite(d)) abort();
    if (kv_parse_doubles(value, v3, 3) == 0 && !(isfinite(v3[0]) && isfinite(v3[1]) && isfinite(v3[2]))) abort();
    if (kv_parse_long(value, -5, 5, &l) == 0 && (l < -5 || l > 5)) abort();
    ++*n;
    if (kl % 2 == 0) return 0;
    if (kl % 3 == 0) return 1;
    snprintf(err, errlen, "odd");
    return -1;
}

/* parse(text) with tcfg_set from the defaults into *c: kv_parse_stream's value. */
static int parse_tcfg(const char *text, size_t len, struct tcfg *c, char *err, size_t errlen)
{
    tcfg_defaults(c);
    FILE *f = fmemopen((void *)text, len, "r");
    if (!f) return -2;
    const int rc = kv_parse_stream(f, "fuzz.conf", tcfg_set, c, err, errlen);
    fclose(f);
    return rc;
}

/* tcfg_write(c) into a malloc'd text (*len bytes). */
static char *write_tcfg(const struct tcfg *c, size_t *len)
{
    char *buf = NULL;
    FILE *f = open_memstream(&buf, len);
    if (!f) abort();
    tcfg_write(f, c);
    if (fclose(f) != 0) abort();
    return buf;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0) return 0; /* fmemopen of 0 bytes is an error in glibc */
    char err[1024];
    long n = 0;
    FILE *f = fmemopen((void *)data, size, "r");
    if (!f) return 0;
    err[0] = 0;
    int rc = kv_parse_stream(f, "fuzz.conf", check_setter, &n, err, sizeof err);
    fclose(f);
    if (rc != 0 && (rc != -1 || strncmp(err, "fuzz.conf", 9) != 0)) abort();

    static struct tcfg c1, c2;
    err[0] = 0;
    rc = parse_tcfg((const char *)data, size, &c1, err, sizeof err);
    if (rc == -1 && strncmp(err, "fuzz.conf:", 10) != 0) abort();
    if (rc != 0) return 0;
    size_t l1, l2;
    char *t1 = write_tcfg(&c1, &l1);
    if (l1 == 0 || parse_tcfg(t1, l1, &c2, err, sizeof err) != 0) {
        fprintf(stderr, "fuzz_kvfile: the written configuration is refused: %s\n%s", err, t1);
        abort();
    }
    char *t2 = write_tcfg(&c2, &l2);
    if (l1 != l2 || memcmp(t1, t2, l1) != 0) {
        fprintf(stderr, "fuzz_kvfile: the round trip changed the configuration:\n%s---\n%s", t1, t2);
        abort();
    }
    free(t1);
    free(t2);
    return 0;
}
