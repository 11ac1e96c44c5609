/* vec.c - parser and checker for the reference-vector format (FORMAT.md).
 * Fixed buffers; never reads past buf[len]; rejects what it does not know. */
#include "vec.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "number.h"

void vec_file_init(struct vec_file *f, const char *buf, size_t len)
{
    memset(f, 0, sizeof *f);
    f->buf = buf;
    f->len = len;
}

/* Copy the next line (without newline) into line[]; 0 at end of input,
 * -1 when longer than VEC_MAX_LINE or holding a NUL byte. */
static int read_line(struct vec_file *f, char *line)
{
    if (f->pos >= f->len) return 0;
    size_t n = 0;
    while (f->pos < f->len && f->buf[f->pos] != '\n') {
        char ch = f->buf[f->pos++];
        if (ch == '\0' || n + 1 >= VEC_MAX_LINE) {
            snprintf(f->err, sizeof f->err, "line %ld: %s", f->line + 1,
                     ch == '\0' ? "NUL byte" : "line too long");
            return -1;
        }
        line[n++] = ch;
    }
    if (f->pos < f->len) f->pos++; /* newline */
    if (n > 0 && line[n - 1] == '\r') n--;
    line[n] = '\0';
    f->line++;
    return 1;
}

static int is_space(char ch) { return ch == ' ' || ch == '\t'; }

/* Next whitespace-separated token of *s (advanced), or NULL. */
static char *token(char **s)
{
    char *p = *s;
    while (is_space(*p)) p++;
    if (!*p) return NULL;
    char *t = p;
    while (*p && !is_space(*p)) p++;
    if (*p) *p++ = '\0';
    *s = p;
    return t;
}

static int copy_name(char *dst, size_t cap, const char *src)
{
    size_t n = strlen(src);
    if (n == 0 || n >= cap) return -1;
    memcpy(dst, src, n + 1);
    return 0;
}

static int perr(struct vec_file *f, const char *what)
{
    snprintf(f->err, sizeof f->err, "line %ld: %s", f->line, what);
    return -1;
}

/* Parse "<name> values..." into an entry of c (numbers into the pool, or one
 * bare word). */
static int parse_entry(struct vec_file *f, struct vec_case *c, char *rest, struct vec_entry *e)
{
    char *name = token(&rest);
    if (!name || copy_name(e->name, sizeof e->name, name)) return perr(f, "missing or too long name");
    e->word[0] = '\0';
    e->off = c->pool_used;
    e->n = 0;
    char *t;
    while ((t = token(&rest)) != NULL) {
        char *end;
        double v = 0;
        const int bad = kv_strtod(t, &end, &v); /* decimal only: no hex */
        const char *d = t + (t[0] == '+' || t[0] == '-');
        const int numeric = isdigit((unsigned char)d[0]) || (d[0] == '.' && isdigit((unsigned char)d[1]));
        if (numeric && (bad == KV_NUM_BAD || *end != '\0')) return perr(f, "bad number (decimal numbers only)");
        if (bad == KV_NUM_BAD || *end != '\0') {
            /* a bare word: only as the single value */
            if (e->n > 0 || e->word[0] || token(&rest)) return perr(f, "bad number");
            if (copy_name(e->word, sizeof e->word, t)) return perr(f, "word too long");
            return 0;
        }
        if (bad) return perr(f, bad == KV_NUM_RANGE ? "number beyond the range of a double" : "non-finite number");
        if (e->n >= VEC_MAX_ARRAY) return perr(f, "array longer than 1024 values");
        if (c->pool_used >= VEC_POOL) return perr(f, "case too large");
        c->pool[c->pool_used++] = v;
        e->n++;
    }
    return 0;
}

static int parse_tol(struct vec_file *f, char *rest, struct vec_tol *t)
{
    char *name = token(&rest), *a = token(&rest), *r = token(&rest);
    if (!name || !a || !r || token(&rest)) return perr(f, "tol needs <name> <abs> <rel>");
    if (copy_name(t->name, sizeof t->name, name)) return perr(f, "tol name too long");
    if (kv_parse_double(a, &t->abs) || kv_parse_double(r, &t->rel) || !(t->abs >= 0) || !(t->rel >= 0))
        return perr(f, "bad tolerance");
    return 0;
}

int vec_next(struct vec_file *f, struct vec_case *c)
{
    static char line[VEC_MAX_LINE];
    int in_case = 0;
    for (;;) {
        int r = read_line(f, line);
        if (r < 0) return -1;
        if (r == 0) return in_case ? perr(f, "end of input inside a case") : 0;
        char *rest = line;
        char *rec = token(&rest);
        if (!rec || rec[0] == '#') continue;
        if (strcmp(rec, "case") == 0) {
            if (in_case) return perr(f, "case inside a case");
            char *kind = token(&rest), *id = token(&rest);
            if (!kind || !id || token(&rest)) return perr(f, "case needs <kind> <id>");
            memset(c->kind, 0, sizeof c->kind);
            if (copy_name(c->kind, sizeof c->kind, kind) || copy_name(c->id, sizeof c->id, id))
                return perr(f, "kind or id too long");
            c->line = f->line;
            c->n_in = c->n_out = c->n_tol = 0;
            c->pool_used = 0;
            in_case = 1;
        } else if (strcmp(rec, "in") == 0 || strcmp(rec, "out") == 0) {
            if (!in_case) return perr(f, "in/out outside a case");
            int is_in = rec[0] == 'i';
            size_t *n = is_in ? &c->n_in : &c->n_out;
            if (*n >= VEC_MAX_ENTRIES) return perr(f, "too many entries in a case");
            struct vec_entry *e = (is_in ? c->in : c->out) + *n;
            if (parse_entry(f, c, rest, e)) return -1;
            /* one value per name: a second one would silently win or lose */
            for (size_t j = 0; j < *n; j++)
                if (strcmp((is_in ? c->in : c->out)[j].name, e->name) == 0)
                    return perr(f, is_in ? "duplicate in name" : "duplicate out name");
            (*n)++;
        } else if (strcmp(rec, "tol") == 0) {
            if (in_case) {
                if (c->n_tol >= VEC_MAX_ENTRIES) return perr(f, "too many tol lines");
                if (parse_tol(f, rest, &c->tol[c->n_tol])) return -1;
                c->n_tol++;
            } else {
                struct vec_tol t;
                if (parse_tol(f, rest, &t)) return -1;
                size_t i;
                for (i = 0; i < f->n_tol; i++)
                    if (strcmp(f->tol[i].name, t.name) == 0) break;
                if (i == f->n_tol) {
                    if (f->n_tol >= sizeof f->tol / sizeof f->tol[0])
                        return perr(f, "too many file-level tol lines");
                    f->n_tol++;
                }
                f->tol[i] = t;
            }
        } else if (strcmp(rec, "end") == 0) {
            if (!in_case) return perr(f, "end outside a case");
            if (token(&rest)) return perr(f, "text after end");
            return 1;
        } else {
            return perr(f, "unknown record");
        }
    }
}

static const struct vec_tol *find_tol(const struct vec_tol *t, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(t[i].name, name) == 0) return &t[i];
    return NULL;
}

void vec_tolerance(const struct vec_file *f, const struct vec_case *c, const char *name,
                   double *abs, double *rel)
{
    const struct vec_tol *t = find_tol(c->tol, c->n_tol, name);
    if (!t) t = find_tol(c->tol, c->n_tol, "*");
    if (!t && f) t = find_tol(f->tol, f->n_tol, name);
    if (!t && f) t = find_tol(f->tol, f->n_tol, "*");
    *abs = t ? t->abs : 0;
    *rel = t ? t->rel : 0;
}

/* ---------------------------------------------------------------- inputs */

int vec_fail(struct vec_out *o, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(o->err, sizeof o->err, fmt, ap);
    va_end(ap);
    return -1;
}

static const struct vec_entry *find_in(const struct vec_case *c, const char *name)
{
    for (size_t i = 0; i < c->n_in; i++)
        if (strcmp(c->in[i].name, name) == 0) return &c->in[i];
    return NULL;
}

int vec_has_in(const struct vec_case *c, const char *name) { return find_in(c, name) != NULL; }

int vec_in_array(const struct vec_case *c, struct vec_out *o, const char *name, const double **v,
                 size_t *n)
{
    const struct vec_entry *e = find_in(c, name);
    if (!e) return vec_fail(o, "missing input '%s'", name);
    if (e->word[0]) return vec_fail(o, "input '%s' must be numeric", name);
    *v = c->pool + e->off;
    *n = e->n;
    return 0;
}

int vec_in_array_n(const struct vec_case *c, struct vec_out *o, const char *name, size_t n,
                   const double **v)
{
    size_t got = 0;
    if (vec_in_array(c, o, name, v, &got)) return -1;
    if (got != n) return vec_fail(o, "input '%s' has %zu values, want %zu", name, got, n);
    return 0;
}

int vec_in_scalar(const struct vec_case *c, struct vec_out *o, const char *name, double *v)
{
    const double *p = NULL;
    if (vec_in_array_n(c, o, name, 1, &p)) return -1;
    *v = p[0];
    return 0;
}

int vec_in_int(const struct vec_case *c, struct vec_out *o, const char *name, long *v)
{
    double d;
    if (vec_in_scalar(c, o, name, &d)) return -1;
    if (d != floor(d) || fabs(d) > 1e9) return vec_fail(o, "input '%s' must be an integer", name);
    *v = (long)d;
    return 0;
}

int vec_in_word(const struct vec_case *c, struct vec_out *o, const char *name, const char **w)
{
    const struct vec_entry *e = find_in(c, name);
    if (!e) return vec_fail(o, "missing input '%s'", name);
    if (!e->word[0]) return vec_fail(o, "input '%s' must be a word", name);
    *w = e->word;
    return 0;
}

/* ---------------------------------------------------------------- outputs */

void vec_out_reset(struct vec_out *o)
{
    o->n = 0;
    o->pool_used = 0;
    o->err[0] = '\0';
}

double *vec_put_alloc(struct vec_out *o, const char *name, size_t n)
{
    if (o->n >= VEC_MAX_ENTRIES || n > VEC_POOL - o->pool_used) {
        vec_fail(o, "too many outputs");
        return NULL;
    }
    struct vec_entry *e = &o->e[o->n];
    if (copy_name(e->name, sizeof e->name, name)) {
        vec_fail(o, "bad output name");
        return NULL;
    }
    e->word[0] = '\0';
    e->off = o->pool_used;
    e->n = n;
    o->pool_used += n;
    o->n++;
    return o->pool + e->off;
}

int vec_put(struct vec_out *o, const char *name, const double *v, size_t n)
{
    double *d = vec_put_alloc(o, name, n);
    if (!d) return -1;
    for (size_t i = 0; i < n; i++) d[i] = v[i];
    return 0;
}

int vec_put1(struct vec_out *o, const char *name, double v) { return vec_put(o, name, &v, 1); }

int vec_put_real(struct vec_out *o, const char *name, const trk_real *v, size_t n)
{
    double *d = vec_put_alloc(o, name, n);
    if (!d) return -1;
    for (size_t i = 0; i < n; i++) d[i] = (double)v[i];
    return 0;
}

const struct vec_entry *vec_out_find(const struct vec_out *o, const char *name)
{
    for (size_t i = 0; i < o->n; i++)
        if (strcmp(o->e[i].name, name) == 0) return &o->e[i];
    return NULL;
}

/* ---------------------------------------------------------------- compare */

void vec_compare(const struct vec_file *f, const struct vec_case *c, const struct vec_out *o,
                 int normwise, double float_abs, double float_rel, struct vec_check *chk)
{
    memset(chk, 0, sizeof *chk);
    chk->ok = 1;
    for (size_t k = 0; k < c->n_out; k++) {
        const struct vec_entry *want = &c->out[k];
        const struct vec_entry *got = vec_out_find(o, want->name);
        double abs, rel;
        vec_tolerance(f, c, want->name, &abs, &rel);
        const char *why = NULL; /* a literal: its length bounds the message (gcc -Os -Wformat-truncation) */
        if (!got) why = "not computed";
        else if (want->word[0]) why = "word outputs are not supported";
        const int bad_length = !why && got->n != want->n;
        if (why || bad_length) {
            if (chk->ok || !chk->first_fail[0]) {
                if (bad_length)
                    snprintf(chk->first_fail, sizeof chk->first_fail, "%s length %zu want %zu", want->name, got->n,
                             want->n);
                else
                    snprintf(chk->first_fail, sizeof chk->first_fail, "%s %s", want->name, why);
            }
            chk->ok = 0;
            chk->n_fail_names++;
            continue;
        }
        const double *w = c->pool + want->off, *g = o->pool + got->off;
        double scale = 0;
        if (normwise) {
            for (size_t i = 0; i < want->n; i++)
                if (fabs(w[i]) > scale) scale = fabs(w[i]);
            if (abs < float_abs) abs = float_abs;
            if (rel < float_rel) rel = float_rel;
        }
        int name_failed = 0;
        for (size_t i = 0; i < want->n; i++) {
            double err = fabs(g[i] - w[i]);
            double lim = abs + rel * (normwise ? scale : fabs(w[i]));
            if (!(err <= lim)) { /* NaN fails */
                if (!name_failed && chk->ok)
                    snprintf(chk->first_fail, sizeof chk->first_fail, "%s[%zu] %.17g %.17g",
                             want->name, i, g[i], w[i]);
                if (!name_failed) chk->n_fail_names++;
                name_failed = 1;
                chk->ok = 0;
            }
            if (isnan(err)) err = INFINITY;
            if (err > chk->max_abs_err) chk->max_abs_err = err;
            if (w[i] != 0 && err / fabs(w[i]) > chk->max_rel_err) chk->max_rel_err = err / fabs(w[i]);
            double use = lim > 0 ? err / lim : (err > 0 ? INFINITY : 0);
            if (use > chk->max_tol_use) chk->max_tol_use = use;
        }
    }
}
