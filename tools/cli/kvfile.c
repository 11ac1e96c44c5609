/* kvfile.c - "key = value" configuration files (kvfile.h). */
#include "kvfile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "suggest.h"

/* Blanks around keys and values: the same set at both ends (a '\r' before
 * a key was kept, one after it dropped: found by fuzz_kvfile). */
static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

static char *trim(char *s)
{
    while (is_blank(*s)) s++;
    size_t n = strlen(s);
    while (n > 0 && is_blank(s[n - 1])) s[--n] = 0;
    return s;
}

/* Split one line (modified in place). 0 empty/comment, 1 key+value, -1 syntax. */
static int split_line(char *line, char **key, char **value)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = 0;
    char *s = trim(line);
    if (!*s) return 0;
    char *eq = strchr(s, '=');
    if (!eq) return -1;
    *eq = 0;
    *key = trim(s);
    *value = trim(eq + 1);
    return **key ? 1 : -1;
}

static int apply(kv_setter set, void *ctx, const char *key, const char *value, char *err,
                 size_t errlen)
{
    char msg[512] = "";
    int r = set(ctx, key, value, msg, sizeof msg);
    if (r == 0) return 0;
    if (r > 0) { /* msg: the nearest known key, or "" */
        char mean[600];
        cli_did_you_mean(msg[0] ? msg : NULL, mean, sizeof mean);
        snprintf(err, errlen, "unknown setting '%s'%s", key, mean);
    }
    else if (msg[0]) snprintf(err, errlen, "%s = %s: %s", key, value, msg);
    else snprintf(err, errlen, "bad value for %s: '%s'", key, value);
    return -1;
}

/* One line of f into line (at most cap - 2 characters, without its '\n'),
 * byte by byte so that a NUL byte cannot hide the rest of a line: 1 a line,
 * 0 end of file, -1 longer than cap - 2, -2 a NUL byte. */
static int read_line(FILE *f, char *line, size_t cap)
{
    size_t n = 0;
    int c = EOF;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (c == '\0') return -2;
        if (n + 2 > cap) return -1;
        line[n++] = (char)c;
    }
    if (c == EOF && n == 0) return 0;
    line[n] = 0;
    return 1;
}

int kv_parse_stream(FILE *f, const char *name, kv_setter set, void *ctx, char *err, size_t errlen)
{
    char line[KV_MAX_LINE];
    long lineno = 0;
    int rc = 0, got;
    while ((got = read_line(f, line, sizeof line)) != 0) {
        lineno++;
        if (got == -1) {
            snprintf(err, errlen, "%s:%ld: line longer than %d characters", name, lineno, KV_MAX_LINE - 2);
            rc = -1;
            break;
        }
        if (got == -2) {
            snprintf(err, errlen, "%s:%ld: a NUL byte (not a text file?)", name, lineno);
            rc = -1;
            break;
        }
        char *key, *value, msg[640];
        int k = split_line(line, &key, &value);
        if (k == 0) continue;
        if (k < 0) {
            snprintf(err, errlen, "%s:%ld: expected 'key = value'", name, lineno);
            rc = -1;
            break;
        }
        if (apply(set, ctx, key, value, msg, sizeof msg) != 0) {
            snprintf(err, errlen, "%s:%ld: %s", name, lineno, msg);
            rc = -1;
            break;
        }
    }
    if (rc == 0 && ferror(f)) {
        snprintf(err, errlen, "%s: read error", name);
        rc = -1;
    }
    return rc;
}

int kv_parse_file(const char *path, kv_setter set, void *ctx, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    const int rc = kv_parse_stream(f, path, set, ctx, err, errlen);
    fclose(f);
    return rc;
}

int kv_parse_assignment(const char *kv, kv_setter set, void *ctx, char *err, size_t errlen)
{
    char line[KV_MAX_LINE];
    if (strlen(kv) >= sizeof line - 1) {
        snprintf(err, errlen, "setting too long");
        return -1;
    }
    strcpy(line, kv);
    char *eq = strchr(line, '=');
    if (!eq) {
        snprintf(err, errlen, "expected KEY=VALUE, got '%s'", kv);
        return -1;
    }
    *eq = 0;
    char *key = trim(line), *value = trim(eq + 1);
    if (!*key) {
        snprintf(err, errlen, "expected KEY=VALUE, got '%s'", kv);
        return -1;
    }
    return apply(set, ctx, key, value, err, errlen);
}

int kv_parse_long(const char *s, long lo, long hi, long *v)
{
    char *end;
    errno = 0;
    long x = strtol(s, &end, 10);
    while (*end == ' ' || *end == '\t') end++;
    if (errno || end == s || *end || x < lo || x > hi) return -1;
    *v = x;
    return 0;
}

int kv_parse_doubles(const char *s, double *v, int n)
{
    const char *p = s;
    for (int i = 0; i < n; i++) {
        /* separator before every number but the first: spaces, at most one comma */
        while (*p == ' ' || *p == '\t') p++;
        if (i > 0 && *p == ',') p++;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == ',' || *p == 0) return -1;
        char *end;
        double d;
        if (kv_strtod(p, &end, &d) != 0) return -1;
        v[i] = d;
        p = end;
    }
    while (*p == ' ' || *p == '\t') p++;
    return *p ? -1 : 0;
}
