/* trk-vectors - check the library against reference vectors (FORMAT.md).
 *
 *   trk-vectors [--strict] [--emit] [--report-error] [--quiet] [--skip-slow] [--skip K,...] FILE...
 *
 * Prints "FAIL <file> <id> <name>[<index>] got want" per failing case,
 * "UNIMPLEMENTED <file> <id> <kind>" per case of a kind this build does not
 * know, the names of unimplemented and skipped kinds, and finally
 * "vectors: P passed, F failed, U unimplemented".
 * Exit status (docs/statuses.md, "Exit codes"): 1 when F > 0 or P = 0, or
 * U > 0 under --strict, and on an unreadable or malformed file (it also
 * counts as a failure); 2 on a usage error.
 * --emit writes every case back with its out lines replaced by the computed
 * values (17 significant digits) instead of checking.
 * --report-error prints, per kind, the largest absolute and relative error
 * and the largest fraction of its tolerance any value used.
 * In a float build (TRK_REAL_FLOAT) each kind's float tolerance applies
 * normwise (see tools/vec/vec.h and each kind's file), and a case whose answer
 * jumps within float rounding (a detection on the gate boundary) is counted
 * as "not resolvable in float" rather than compared. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fileio.h"
#include "trk/types.h"
#include "vec.h"

static struct vec_case cs;
static struct vec_out out;

struct kind_err {
    const char *name;
    long n;
    double max_abs, max_rel, max_use;
};

static void emit_values(const char *rec, const struct vec_entry *e, const double *pool)
{
    printf("%s %s", rec, e->name);
    if (e->word[0]) printf(" %s", e->word);
    for (size_t i = 0; i < e->n; i++) printf(" %.17g", pool[e->off + i]);
    putchar('\n');
}

static void emit_case(const struct vec_case *c, const struct vec_out *o, int ran)
{
    printf("case %s %s\n", c->kind, c->id);
    for (size_t i = 0; i < c->n_in; i++) emit_values("in", &c->in[i], c->pool);
    for (size_t i = 0; i < c->n_out; i++) {
        const struct vec_entry *g = ran ? vec_out_find(o, c->out[i].name) : NULL;
        if (g && g->n == c->out[i].n) {
            struct vec_entry e = *g;
            emit_values("out", &e, o->pool);
        } else {
            /* left out, never copied from the expected values: a comparer
             * counts the missing output as a failure */
            printf("# not computed: %s: %s\n", c->out[i].name, ran ? "no such output" : o->err);
        }
    }
    for (size_t i = 0; i < c->n_tol; i++)
        printf("tol %s %.17g %.17g\n", c->tol[i].name, c->tol[i].abs, c->tol[i].rel);
    printf("end\n\n");
}

/* The kinds named in the summary (unimplemented, skipped as slow): each name
 * once, copied (a case's kind string is overwritten by the next case); past
 * KIND_NAMES_CAP names the cases are still counted, the names cut with "...". */
#define KIND_NAMES_CAP 32
struct kind_names {
    char name[KIND_NAMES_CAP][VEC_MAX_NAME];
    size_t n;
    int more;
};

static void note_kind(struct kind_names *k, const char *name)
{
    for (size_t i = 0; i < k->n; i++)
        if (strcmp(k->name[i], name) == 0) return;
    if (k->n == KIND_NAMES_CAP) {
        k->more = 1;
        return;
    }
    snprintf(k->name[k->n], sizeof k->name[k->n], "%s", name);
    k->n++;
}

static void print_kinds(const char *what, long count, const struct kind_names *k)
{
    printf("vectors: %ld cases %s:", count, what);
    for (size_t i = 0; i < k->n; i++) printf(" %s", k->name[i]);
    printf("%s\n", k->more ? " ..." : "");
}

/* FILE operands. */
struct files {
    const char **f;
    int n;
};

static int take_file(void *ctx, const char *arg, const char *next, char *err, size_t errlen)
{
    struct files *fl = ctx;
    (void)next, (void)err, (void)errlen;
    if (arg[0] == '-') return 0; /* an unknown option */
    fl->f[fl->n++] = arg;
    return 1;
}

int main(int argc, char **argv)
{
    int strict = 0, emit = 0, report = 0, quiet = 0, bad_file = 0;
    const char *skip = NULL; /* comma-separated kinds not to run */
    int skip_slow = 0;       /* --skip-slow: kinds registered VEC_SLOW */
    long skipped = 0, skipped_slow = 0;
    static struct kind_names unimpl_kinds, slow_kinds;
    long passed = 0, failed = 0, unimpl = 0, not_applicable = 0;
    static struct kind_err errs[128];
    size_t n_errs = 0;

    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-vectors: libtrk was built with other capacities or real type\n");
        return 2;
    }
    struct files fl = {NULL, 0};
    fl.f = malloc((size_t)argc * sizeof *fl.f);
    if (!fl.f) {
        fprintf(stderr, "trk-vectors: out of memory\n");
        return 1;
    }
    const struct cli_opt opts[] = {
        CLI_OPT_FLAG("--strict", &strict, "exit non-zero also when a case's kind is not implemented"),
        CLI_OPT_FLAG("--emit", &emit, "write the cases back with computed out values instead"),
        CLI_OPT_FLAG("--report-error", &report, "per kind: max abs/rel error and max fraction of tolerance used"),
        CLI_OPT_FLAG("--quiet", &quiet, "only the summary line and failures"),
        CLI_OPT_SHORT("-q", "--quiet"),
        CLI_OPT_FLAG("--skip-slow", &skip_slow,
                     "do not run cases of the kinds registered as slow (Monte Carlo,\n"
                     "seconds per case; counted and named; `make check` passes it,\n"
                     "`make test` runs them in one configuration)"),
        CLI_OPT_STRING("--skip", &skip, "K1,K2", NULL, "do not run cases of these kinds (counted as skipped)"),
        CLI_OPT_END};
    char about[96];
    snprintf(about, sizeof about, "  checks each case of each FILE against libtrk (%s build)",
             TRK_REAL_IS_FLOAT ? "float" : "double");
    const struct cli cli = {
        .prog = "trk-vectors",
        .usage = "[--strict] [--emit] [--report-error] [--quiet] [--skip-slow] [--skip K1,K2] FILE...",
        .about = about,
        .opts = opts,
        .operand = take_file,
        .ctx = &fl};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN || fl.n == 0) {
        if (parsed == CLI_RUN) fprintf(stderr, "trk-vectors: no FILE given (see --help)\n");
        free(fl.f);
        return parsed == CLI_RUN ? 2 : parsed;
    }
    for (int fi = 0; fi < fl.n; fi++) {
        const char *path = fl.f[fi];
        size_t len;
        char *buf = fileio_read_max(path, VEC_MAX_FILE_BYTES, &len); /* bounded: /dev/zero */
        if (!buf) {
            fprintf(stderr, "trk-vectors: cannot read %s: %s\n", path,
                    errno == EFBIG ? "larger than 256 MiB (VEC_MAX_FILE_BYTES)" : strerror(errno));
            bad_file = 1;
            failed++;
            continue;
        }
        struct vec_file f;
        vec_file_init(&f, buf, len);
        int r;
        while ((r = vec_next(&f, &cs)) == 1) {
            const struct vec_kind *k = vec_kind_find(cs.kind);
            vec_out_reset(&out);
            if (skip && vec_kind_listed(skip, cs.kind)) {
                skipped++;
                continue;
            }
            if (k && skip_slow && k->speed == VEC_SLOW) {
                skipped_slow++;
                note_kind(&slow_kinds, k->name);
                continue;
            }
            if (!k) {
                if (emit) emit_case(&cs, &out, 0);
                else if (!quiet || strict) printf("UNIMPLEMENTED %s %s %s\n", path, cs.id, cs.kind);
                unimpl++;
                note_kind(&unimpl_kinds, cs.kind);
                continue;
            }
            int rc = k->fn(&cs, &out);
            if (emit) {
                emit_case(&cs, &out, rc == 0);
                continue;
            }
            if (rc == VEC_NOT_APPLICABLE) {
                if (!quiet) printf("NOT-APPLICABLE %s %s %s\n", path, cs.id, out.err);
                not_applicable++;
                continue;
            }
            if (rc != 0) {
                printf("FAIL %s %s %s\n", path, cs.id, out.err[0] ? out.err : "kind failed");
                failed++;
                continue;
            }
            struct vec_check chk;
            vec_compare(&f, &cs, &out, TRK_REAL_IS_FLOAT, k->float_abs, k->float_rel, &chk);
            if (chk.ok) passed++;
            else {
                printf("FAIL %s %s %s\n", path, cs.id, chk.first_fail);
                failed++;
            }
            size_t e;
            for (e = 0; e < n_errs; e++)
                if (errs[e].name == k->name) break;
            if (e == n_errs && n_errs < sizeof errs / sizeof errs[0]) errs[n_errs++].name = k->name;
            if (e < n_errs) {
                errs[e].n++;
                if (chk.max_abs_err > errs[e].max_abs) errs[e].max_abs = chk.max_abs_err;
                if (chk.max_rel_err > errs[e].max_rel) errs[e].max_rel = chk.max_rel_err;
                if (chk.max_tol_use > errs[e].max_use) errs[e].max_use = chk.max_tol_use;
            }
        }
        if (r < 0) {
            fprintf(stderr, "trk-vectors: %s: %s\n", path, f.err);
            printf("FAIL %s malformed: %s\n", path, f.err);
            bad_file = 1;
            failed++;
        }
        free(buf);
    }
    free(fl.f);
    if (emit) return bad_file ? 1 : 0;
    if (report) {
        printf("%-20s %6s %12s %12s %10s   (%s build)\n", "kind", "cases", "max_abs_err", "max_rel_err",
               "tol_used", TRK_REAL_IS_FLOAT ? "float" : "double");
        for (size_t e = 0; e < n_errs; e++)
            printf("%-20s %6ld %12.3g %12.3g %10.3g\n", errs[e].name, errs[e].n, errs[e].max_abs,
                   errs[e].max_rel, errs[e].max_use);
    }
    if (not_applicable)
        printf("vectors: %ld cases not applicable to this build (float resolution or capacity)\n",
               not_applicable);
    if (skipped) printf("vectors: %ld cases skipped (--skip %s)\n", skipped, skip);
    if (skipped_slow) print_kinds("of slow kinds skipped (--skip-slow)", skipped_slow, &slow_kinds);
    if (unimpl) print_kinds("of kinds not implemented yet", unimpl, &unimpl_kinds);
    printf("vectors: %ld passed, %ld failed, %ld unimplemented\n", passed, failed, unimpl);
    if (bad_file) return 1;
    if (failed > 0 || passed == 0 || (strict && unimpl > 0)) return 1;
    return 0;
}
