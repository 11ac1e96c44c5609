/* cli.c - the one command-line interface of the trk tools (cli.h). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kvfile.h"
#include "suggest.h"

/* ---------------------------------------------------------------- value parsers */

static int is_blank_char(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

int cli_blank(const char *s)
{
    for (; *s; s++)
        if (!is_blank_char(*s)) return 0;
    return 1;
}

static int has_blank(const char *s)
{
    for (; *s; s++)
        if (is_blank_char(*s)) return 1;
    return 0;
}

int cli_parse_long(const char *s, long *v)
{
    if (!*s || has_blank(s)) return -1;
    char *end;
    errno = 0;
    const long l = strtol(s, &end, 10);
    if (!*end && errno == 0) { /* exact */
        *v = l;
        return 0;
    }
    double d; /* "1e6"; exact below 2^53 */
    if (kv_strtod(s, &end, &d) != 0 || *end || !(fabs(d) <= 9007199254740992.0) || d < (double)LONG_MIN ||
        d > (double)LONG_MAX || d != floor(d))
        return -1;
    *v = (long)d;
    return 0;
}

int cli_parse_double(const char *s, double *v)
{
    if (!*s || has_blank(s)) return -1;
    char *end;
    double d;
    if (kv_strtod(s, &end, &d) != 0 || *end) return -1;
    *v = d;
    return 0;
}

int cli_parse_list(const char *s, double *v, int max)
{
    if (!*s || has_blank(s)) return -1;
    double a, b, st;
    char tail;
    if (sscanf(s, "%lf:%lf:%lf%c", &a, &b, &st, &tail) == 3) {
        if (!(st > 0) || b < a || !isfinite(a) || !isfinite(b) || !isfinite(st)) return -1;
        int n = 0;
        for (double x = a; x <= b + 1e-9 * st; x = a + st * n) {
            if (n == max) return -1; /* more values than the list holds: refuse, never drop */
            v[n++] = x;
        }
        return n;
    }
    int n = 0;
    const char *p = s;
    while (*p) {
        char *end;
        if (n == max) return -1; /* more values than the list holds */
        if (kv_strtod(p, &end, &v[n]) != 0) return -1;
        n++;
        if (*end == ',' && end[1]) end++;
        else if (*end) return -1;
        p = end;
    }
    return n > 0 ? n : -1;
}

/* ---------------------------------------------------------------- option table */

static int in_range(const struct cli_opt *o, double v)
{
    return (!(o->range & CLI_GE) || v >= o->lo) && (!(o->range & CLI_GT) || v > o->lo) &&
           (!(o->range & CLI_LE) || v <= o->hi) && (!(o->range & CLI_LT) || v < o->hi);
}

/* " in [lo, hi]", " >= lo", ... ("" without a range). */
static void range_text(const struct cli_opt *o, char *buf, size_t n)
{
    const unsigned lo = o->range & (CLI_GE | CLI_GT), hi = o->range & (CLI_LE | CLI_LT);
    if (lo && hi)
        snprintf(buf, n, " in %c%.15g, %.15g%c", lo == CLI_GE ? '[' : '(', o->lo, o->hi, hi == CLI_LE ? ']' : ')');
    else if (lo)
        snprintf(buf, n, " %s %.15g", lo == CLI_GE ? ">=" : ">", o->lo);
    else if (hi)
        snprintf(buf, n, " %s %.15g", hi == CLI_LE ? "<=" : "<", o->hi);
    else
        buf[0] = 0;
}

/* The k-th word of "a|b|c" matching s, or -1. */
static int choice_index(const char *words, const char *s)
{
    const size_t len = strlen(s);
    for (int k = 0; *words; k++) {
        const size_t w = strcspn(words, "|");
        if (w == len && strncmp(words, s, len) == 0) return k;
        words += w;
        if (*words == '|') words++;
    }
    return -1;
}

/* The value into o->dst: 0, or -1 (nothing stored for a scalar; a message
 * of CALL in err). */
static int set_value(const struct cli_opt *o, const char *v, char *err, size_t errlen)
{
    err[0] = 0;
    switch (o->type) {
    case CLI_LONG: {
        long l;
        if (cli_parse_long(v, &l) || !in_range(o, (double)l)) return -1;
        *(long *)o->dst = l;
        return 0;
    }
    case CLI_DOUBLE: {
        double d;
        if (cli_parse_double(v, &d) || !in_range(o, d)) return -1;
        *(double *)o->dst = d;
        return 0;
    }
    case CLI_LIST: {
        double *x = o->dst;
        const int n = cli_parse_list(v, x, o->max);
        if (n < 1) return -1;
        for (int k = 0; k < n; k++)
            if (!in_range(o, x[k])) return -1;
        *o->n = n;
        return 0;
    }
    case CLI_NUMBERS: {
        double x[16];
        if (o->max < 1 || o->max > 16 || is_blank_char(v[0]) || (v[0] && is_blank_char(v[strlen(v) - 1])) ||
            kv_parse_doubles(v, x, o->max) != 0)
            return -1;
        memcpy(o->dst, x, (size_t)o->max * sizeof x[0]);
        return 0;
    }
    case CLI_CHOICE: {
        const int k = choice_index(o->arg, v);
        if (k < 0) return -1;
        *(int *)o->dst = o->values ? o->values[k] : k;
        return 0;
    }
    case CLI_STRING: *(const char **)o->dst = v; return 0;
    case CLI_STRINGS:
        if (*o->n >= o->max) {
            snprintf(err, errlen, "given more than %d times", o->max);
            return -1;
        }
        ((const char **)o->dst)[(*o->n)++] = v;
        return 0;
    case CLI_CUSTOM: return o->parse(v, o->dst) == 0 ? 0 : -1;
    case CLI_CALL: return o->call(o->dst, v, err, errlen) == 0 ? 0 : -1;
    case CLI_FLAG:
    case CLI_ALIAS:
    case CLI_HEADING: break;
    }
    return -1;
}

/* "PROG: bad value for NAME: 'V' (what it must be)" */
static void bad_value(const char *prog, const char *name, const struct cli_opt *o, const char *v, const char *err)
{
    char what[256] = "see --help", r[96];
    range_text(o, r, sizeof r);
    if (err && err[0]) {
        fprintf(stderr, "%s: %s %s: %s\n", prog, name, v, err);
        return;
    }
    if (!v[0]) snprintf(what, sizeof what, "empty");
    else if (cli_blank(v)) snprintf(what, sizeof what, "blank");
    else switch (o->type) {
        case CLI_LONG: snprintf(what, sizeof what, "an integer%s", r); break;
        case CLI_DOUBLE: {
            double d;
            const int e = kv_parse_number(v, &d);
            snprintf(what, sizeof what, "%s%s%s", e ? kv_num_error(e) : "", e ? "; " : "", "a number");
            snprintf(what + strlen(what), sizeof what - strlen(what), "%s", r);
            break;
        }
        case CLI_LIST:
            snprintf(what, sizeof what, "a list a,b,c or from:to:step%s%s", r[0] ? ", each" : "", r);
            break;
        case CLI_NUMBERS: snprintf(what, sizeof what, "%d numbers %s", o->max, o->arg ? o->arg : ""); break;
        case CLI_CHOICE: snprintf(what, sizeof what, "one of %s", o->arg); break;
        default: break;
        }
    fprintf(stderr, "%s: bad value for %s: '%s' (%s)\n", prog, name, v, what);
}

static const struct cli_opt *find_in(const struct cli_opt *t, const char *name)
{
    for (; t && t->name; t++)
        if (t->type != CLI_HEADING && strcmp(t->name, name) == 0) return t;
    return NULL;
}

/* Is argument a the option name (exactly, or "name=value": *joined set)? */
static int matches(const char *a, const char *name, const char **joined)
{
    const size_t n = strlen(name);
    if (strncmp(a, name, n) != 0) return 0;
    if (a[n] == '=') {
        *joined = a + n + 1;
        return 1;
    }
    if (a[n]) return 0;
    *joined = NULL;
    return 1;
}

static int table_len(const struct cli_opt *t)
{
    int n = 0;
    while (t && t[n].name) n++;
    return n;
}

/* The option named name (exactly, or with "=value" when v is not NULL: *v
 * then the joined value or NULL), searched in opts, then common; *k its index
 * over both tables. */
static const struct cli_opt *lookup(const struct cli *c, const char *name, const char **v, int *k)
{
    const int n_opts = table_len(c->opts);
    for (int t = 0; t < 2; t++) {
        const struct cli_opt *tab = t ? c->common : c->opts;
        for (int j = 0; tab && tab[j].name; j++) {
            const struct cli_opt *o = &tab[j];
            if (o->type == CLI_HEADING) continue;
            if (v ? matches(name, o->name, v) : strcmp(name, o->name) == 0) {
                *k = t ? n_opts + j : j;
                return o;
            }
        }
    }
    return NULL;
}

/* ---------------------------------------------------------------- help */

/* The left column of an option: "--name ARG" and its second spellings. */
static void left_text(const struct cli_opt *o, const struct cli_opt *t, char *buf, size_t n)
{
    const char *arg = o->type == CLI_FLAG ? NULL : o->arg;
    size_t k = (size_t)snprintf(buf, n, "%s", o->name);
    for (const struct cli_opt *a = t; a && a->name && k < n; a++)
        if (a->type == CLI_ALIAS && !(a->flags & CLI_DEPRECATED) && strcmp(a->arg, o->name) == 0)
            k += (size_t)snprintf(buf + k, n - k, ", %s", a->name);
    if (arg && k < n) snprintf(buf + k, n - k, " %s", arg);
}

static void help_line(FILE *f, const struct cli_opt *o, const struct cli_opt *t)
{
    char left[128];
    left_text(o, t, left, sizeof left);
    int col = strlen(left) < 19 ? fprintf(f, "  %-19s ", left) : fprintf(f, "  %s  ", left);
    for (const char *h = o->help ? o->help : "";;) {
        const size_t len = strcspn(h, "\n");
        col += fprintf(f, "%.*s", (int)len, h);
        h += len;
        if (!*h) break;
        col = fprintf(f, "\n  %-19s ", "") - 1;
        h++;
    }
    if (o->flags & CLI_REQUIRED) col += fprintf(f, " (required)");
    if (o->def) {
        if (col + 11 + (int)strlen(o->def) > 100) fprintf(f, "\n  %-19s (default %s)\n", "", o->def);
        else fprintf(f, " (default %s)\n", o->def);
    } else {
        fputc('\n', f);
    }
}

void cli_print_options(FILE *f, const struct cli_opt *t, const struct cli_opt *shadow)
{
    for (const struct cli_opt *o = t; o && o->name; o++) {
        if (o->type == CLI_HEADING) {
            fprintf(f, "%s\n", o->help);
            continue;
        }
        if (o->type == CLI_ALIAS || (o->flags & CLI_HIDDEN) || find_in(shadow, o->name)) continue;
        help_line(f, o, t);
    }
}

static int has_type(const struct cli_opt *t, enum cli_type type)
{
    for (; t && t->name; t++)
        if (t->type == type && !(t->flags & CLI_HIDDEN)) return 1;
    return 0;
}

static int has_deprecated(const struct cli_opt *t)
{
    for (; t && t->name; t++)
        if (t->type == CLI_ALIAS && (t->flags & CLI_DEPRECATED)) return 1;
    return 0;
}

static void deprecated_lines(FILE *f, const struct cli_opt *t, const struct cli_opt *shadow)
{
    for (; t && t->name; t++)
        if (t->type == CLI_ALIAS && (t->flags & CLI_DEPRECATED) && !find_in(shadow, t->name))
            fprintf(f, "  %-19s use %s\n", t->name, t->arg);
}

void cli_usage(const struct cli *c, FILE *f)
{
    fprintf(f, "usage: %s %s\n", c->prog, c->usage ? c->usage : "[options]");
    if (c->about) fprintf(f, "%s\n", c->about);
    if (c->opts && c->opts->name) {
        if (c->opts->type != CLI_HEADING) fprintf(f, "options:\n");
        cli_print_options(f, c->opts, NULL);
    }
    if (has_type(c->opts, CLI_LIST) || has_type(c->common, CLI_LIST))
        fprintf(f, "  (LIST: values a,b,c or a range from:to:step)\n");
    if (c->common && c->common->name) {
        fprintf(f, "common options:\n");
        cli_print_options(f, c->common, c->opts);
    }
    if (has_deprecated(c->opts) || has_deprecated(c->common)) {
        fprintf(f, "deprecated spellings (accepted until the next release, with a note on stderr):\n");
        deprecated_lines(f, c->opts, NULL);
        deprecated_lines(f, c->common, c->opts);
    }
    if (c->after) fprintf(f, "%s\n", c->after);
    if (c->more_help) c->more_help(f);
}

void cli_note_deprecated(const char *prog, const char *old_spelling, const char *new_spelling)
{
    fprintf(stderr, "%s: note: %s is deprecated (accepted until the next release), use %s\n", prog, old_spelling,
            new_spelling);
}

/* ---------------------------------------------------------------- parse */

/* Options of both tables, one index each (given, noted). */
#define CLI_MAX_OPTS 256

/* "PROG: unknown option --scan; did you mean '--scans'? (see --help)": the
 * nearest listed spelling of either table (a "=value" joined to the word
 * left out). */
static void unknown_option(const struct cli *c, const char *a)
{
    char word[128], mean[160];
    snprintf(word, sizeof word, "%.*s", (int)strcspn(a, "="), a);
    struct cli_near near;
    cli_near_init(&near, word);
    for (int t = 0; t < 2; t++)
        for (const struct cli_opt *o = t ? c->common : c->opts; o && o->name; o++)
            if (o->type != CLI_HEADING && !(o->flags & (CLI_HIDDEN | CLI_DEPRECATED))) cli_near_add(&near, o->name);
    cli_did_you_mean(near.best, mean, sizeof mean);
    fprintf(stderr, "%s: unknown option %s%s (see --help)\n", c->prog, a, mean);
}

static int set_defaults(const struct cli *c, const struct cli_opt *t)
{
    char err[256];
    for (const struct cli_opt *o = t; o && o->name; o++) {
        if (!o->def || o->type == CLI_FLAG || o->type == CLI_ALIAS || o->type == CLI_HEADING ||
            o->type == CLI_STRINGS || o->type == CLI_CALL)
            continue;
        if (set_value(o, o->def, err, sizeof err) != 0) {
            fprintf(stderr, "%s: internal error: bad default '%s' of %s\n", c->prog, o->def, o->name);
            return -1;
        }
    }
    return 0;
}

int cli_parse(const struct cli *c, int argc, char **argv)
{
    const int n_opts = table_len(c->opts), n_all = n_opts + table_len(c->common);
    unsigned char seen[CLI_MAX_OPTS];
    char err[1024];
    if (n_all > CLI_MAX_OPTS) {
        fprintf(stderr, "%s: internal error: more than %d options\n", c->prog, CLI_MAX_OPTS);
        return 1;
    }
    memset(seen, 0, sizeof seen);
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            cli_usage(c, stdout);
            return 0;
        }
    if (set_defaults(c, c->opts) != 0 || set_defaults(c, c->common) != 0) return 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = NULL;
        int k = 0;
        const struct cli_opt *hit = lookup(c, a, &v, &k);
        if (!hit) {
            err[0] = 0;
            const int r = c->operand ? c->operand(c->ctx, a, i + 1 < argc ? argv[i + 1] : NULL, err, sizeof err)
                                     : 0;
            if (r > 0) {
                i += r - 1;
                continue;
            }
            if (r < 0 && err[0]) fprintf(stderr, "%s: %s\n", c->prog, err);
            else if (a[0] == '-') unknown_option(c, a);
            else fprintf(stderr, "%s: unexpected argument '%s' (see --help)\n", c->prog, a);
            return 2;
        }
        const char *spelling = hit->name;
        if (hit->type == CLI_ALIAS) {
            int kt;
            const struct cli_opt *to = lookup(c, hit->arg, NULL, &kt);
            if (!to || to->type == CLI_ALIAS) {
                fprintf(stderr, "%s: internal error: %s names no option %s\n", c->prog, hit->name, hit->arg);
                return 1;
            }
            if ((hit->flags & CLI_DEPRECATED) && !(seen[k] & 2)) {
                cli_note_deprecated(c->prog, hit->name, to->name);
                seen[k] |= 2;
            }
            hit = to;
            k = kt;
        }
        seen[k] |= 1;
        if (hit->type == CLI_FLAG) {
            if (v) {
                fprintf(stderr, "%s: %s takes no value (see --help)\n", c->prog, spelling);
                return 2;
            }
            *(int *)hit->dst = 1;
            continue;
        }
        if (!v) {
            if (i + 1 >= argc) {
                fprintf(stderr, "%s: %s needs a value (see --help)\n", c->prog, spelling);
                return 2;
            }
            v = argv[++i];
        }
        if ((!v[0] && !(hit->flags & CLI_EMPTY_OK)) || (v[0] && cli_blank(v))) {
            bad_value(c->prog, spelling, hit, v, NULL);
            return 2;
        }
        if (set_value(hit, v, err, sizeof err) != 0) {
            bad_value(c->prog, spelling, hit, v, err);
            return 2;
        }
    }
    for (int t = 0; t < 2; t++) {
        const struct cli_opt *tab = t ? c->common : c->opts;
        for (int j = 0; tab && tab[j].name; j++) {
            const int k = t ? n_opts + j : j;
            if ((tab[j].flags & CLI_REQUIRED) && !(seen[k] & 1) && !(t && find_in(c->opts, tab[j].name))) {
                fprintf(stderr, "%s: %s is required (see --help)\n", c->prog, tab[j].name);
                return 2;
            }
        }
    }
    return CLI_RUN;
}

/* ---------------------------------------------------------------- subcommands */

static void dispatch_usage(FILE *f, const char *head, const struct cli_cmd *cmds, void (*more)(FILE *f))
{
    if (head) fprintf(f, "%s", head);
    for (int i = 0; cmds[i].name; i++) fprintf(f, "  %-20s %s\n", cmds[i].name, cmds[i].summary);
    if (more) more(f);
}

int cli_dispatch(const char *prog, const char *noun, const char *head, const struct cli_cmd *cmds,
                 void (*more)(FILE *f), int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "%s: no %s given (see %s --help)\n", prog, noun, prog);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        dispatch_usage(stdout, head, cmds, more);
        return 0;
    }
    struct cli_near near;
    cli_near_init(&near, argv[1]);
    for (int i = 0; cmds[i].name; i++) {
        if (strcmp(argv[1], cmds[i].name) == 0) return cmds[i].fn(argc - 1, argv + 1);
        cli_near_add(&near, cmds[i].name);
    }
    char mean[160];
    cli_did_you_mean(near.best, mean, sizeof mean);
    fprintf(stderr, "%s: unknown %s '%s'%s (see %s --help)\n", prog, noun, argv[1], mean, prog);
    return 2;
}

/* ---------------------------------------------------------------- signals */

volatile sig_atomic_t cli_stop_flag = 0, cli_stop_signal = 0;

static void on_stop_signal(int sig)
{
    cli_stop_flag = 1;
    cli_stop_signal = sig;
}

void cli_catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}
