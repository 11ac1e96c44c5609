/* test_cli.c - the one option parser of the tools (tools/cli/cli.h): every
 * option form (--name value, --name=value, flags, typed values with ranges,
 * lists, repeated options, calls, choices), old spellings (accepted, one
 * deprecation note each), refused values (blank, empty, trailing garbage,
 * out of range), --help (exit status 0, the generated text), usage errors
 * (one line naming the option, exit status 2), operands, --set into the
 * tracker configuration, the subcommand dispatcher, the suggestion after a
 * misspelled option, key or command (suggest.h); and the stop flag set by
 * SIGINT/SIGTERM after cli_catch_stop_signals. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <unistd.h>

#include "cli.h"
#include "kvfile.h"
#include "suggest.h"
#include "tracker_config.h"
#include "trk_test.h"

/* ---------------------------------------------------------------- capture of stdout / stderr */

struct capture {
    int fd, saved;
    FILE *tmp;
    char text[16384];
};

static void capture_begin(struct capture *c, int fd)
{
    fflush(stdout);
    fflush(stderr);
    c->fd = fd;
    c->tmp = tmpfile();
    assert_non_null(c->tmp);
    c->saved = dup(fd);
    assert_true(c->saved >= 0);
    assert_true(dup2(fileno(c->tmp), fd) >= 0);
}

static const char *capture_end(struct capture *c)
{
    fflush(stdout);
    fflush(stderr);
    assert_true(dup2(c->saved, c->fd) >= 0);
    close(c->saved);
    rewind(c->tmp);
    const size_t n = fread(c->text, 1, sizeof c->text - 1, c->tmp);
    c->text[n] = 0;
    fclose(c->tmp);
    return c->text;
}

static int count_lines(const char *s)
{
    int n = 0;
    for (; *s; s++) n += *s == '\n';
    return n;
}

static int count_of(const char *s, const char *sub)
{
    int n = 0;
    for (const char *p = strstr(s, sub); p; p = strstr(p + 1, sub)) n++;
    return n;
}

/* ---------------------------------------------------------------- a tool's table */

struct opts {
    long scans;
    double snr, nu;
    double list[8];
    int n_list;
    double pair[2];
    int model, quiet, fmt;
    const char *out, *channel;
    const char *sets[4];
    int n_sets;
    unsigned seed;
    int calls;
    char last_call[64];
    const char *operands[4];
    int n_operands;
};

static int parse_seed(const char *s, void *dst)
{
    long l;
    if (cli_parse_long(s, &l) != 0 || l < 0 || l > 1000) return -1;
    *(unsigned *)dst = (unsigned)l;
    return 0;
}

static int on_call(void *ctx, const char *v, char *err, size_t errlen)
{
    struct opts *o = ctx;
    if (strcmp(v, "bad") == 0) {
        snprintf(err, errlen, "refused by the call");
        return -1;
    }
    o->calls++;
    snprintf(o->last_call, sizeof o->last_call, "%s", v);
    return 0;
}

/* file names, and the old form OLD=VALUE (with a note) */
static int on_operand(void *ctx, const char *arg, const char *next, char *err, size_t errlen)
{
    struct opts *o = ctx;
    if (strcmp(arg, "--pair-old") == 0) { /* an old two-argument form */
        if (!next) return 0;
        cli_note_deprecated("t", "--pair-old X", "--pair X");
        return 2;
    }
    if (arg[0] == '-') return 0;
    if (strcmp(arg, "refuse") == 0) {
        snprintf(err, errlen, "operand 'refuse' refused");
        return -1;
    }
    if (o->n_operands == 4) return 0;
    o->operands[o->n_operands++] = arg;
    return 1;
}

static const int model_values[] = {10, 20, 30};

static int run_parse(struct opts *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    o->channel = "TRK_X";
    const struct cli_opt opts[] = {
        CLI_OPT_HEADING("Run:"),
        CLI_OPT_LONG("--scans", &o->scans, "N", "300", CLI_IN, 1, 1000000, "scans per run"),
        CLI_OPT_DOUBLE("--snr-db", &o->snr, "D", "15", CLI_IN, -30, 60, "target SNR"),
        CLI_OPT_DOUBLE("--k-shape", &o->nu, "NU", "1", CLI_GT, 0, 0, "K shape"),
        CLI_OPT_LIST("--pfa", o->list, &o->n_list, 8, "1e-3", CLI_OPEN, 0, 1, "false-alarm probabilities"),
        CLI_OPT_NUMBERS("--pair", o->pair, 2, "A,B", "two numbers"),
        CLI_OPT_CHOICE("--clutter-model", &o->model, "none|rayleigh|k", model_values, "rayleigh", "clutter law"),
        CLI_OPT_CHOICE("--format", &o->fmt, "bin|c", NULL, NULL, "format"),
        CLI_OPT_FLAG("--quiet", &o->quiet, "no progress"),
        CLI_OPT_SHORT("-q", "--quiet"),
        CLI_OPT_REQUIRED_STRING("--out", &o->out, "FILE", "output file"),
        {.name = "--channel", .type = CLI_STRING, .dst = &o->channel, .arg = "CH", .flags = CLI_EMPTY_OK,
         .help = "channel, '' = none"},
        CLI_OPT_STRINGS("--set", o->sets, &o->n_sets, 4, "KEY=VALUE", "a setting; repeat"),
        CLI_OPT_CUSTOM("--seed", &o->seed, parse_seed, "N", "1", "seed"),
        CLI_OPT_CALL("--call", o, on_call, "V", "called at every occurrence"),
        {.name = "--secret", .type = CLI_FLAG, .dst = &o->quiet, .flags = CLI_HIDDEN, .help = "hidden"},
        CLI_OPT_ALIAS("--nu", "--k-shape"),
        CLI_OPT_ALIAS("-o", "--out"),
        CLI_OPT_ALIAS("--model", "--clutter-model"),
        CLI_OPT_END};
    const struct cli cli = {.prog = "t",
                            .usage = "[options] FILE...",
                            .about = "A test tool.",
                            .opts = opts,
                            .after = "Writes FILE.",
                            .operand = on_operand,
                            .ctx = o};
    return cli_parse(&cli, argc, argv);
}

#define ARGC(a) ((int)(sizeof(a) / sizeof(a)[0]) - 1)

/* The parse of argv with stderr captured: returns the status, *err the text. */
static int parse_err(struct opts *o, int argc, char **argv, struct capture *c, const char **err)
{
    capture_begin(c, 2);
    const int rc = run_parse(o, argc, argv);
    *err = capture_end(c);
    return rc;
}

/* ---------------------------------------------------------------- option forms */

static void test_defaults(void **state)
{
    (void)state;
    struct opts o;
    char *argv[] = {"t", "--out", "x", NULL};
    assert_int_equal(run_parse(&o, ARGC(argv), argv), CLI_RUN);
    assert_int_equal(o.scans, 300);
    TRK_ASSERT_NEAR(o.snr, 15, 0, 0);
    TRK_ASSERT_NEAR(o.nu, 1, 0, 0);
    assert_int_equal(o.n_list, 1);
    TRK_ASSERT_NEAR(o.list[0], 1e-3, 0, 0);
    assert_int_equal(o.model, 20);
    assert_int_equal(o.fmt, 0);
    assert_int_equal(o.quiet, 0);
    assert_int_equal(o.seed, 1);
    assert_string_equal(o.channel, "TRK_X");
    assert_string_equal(o.out, "x");
    assert_int_equal(o.n_sets, 0);
}

static void test_forms(void **state)
{
    (void)state;
    struct opts o;
    char *argv[] = {"t", "--scans", "12", "--snr-db=-3.5", "--k-shape", "2", "--pfa", "1e-3,0.01,0.1",
                    "--pair", "1, 2", "--clutter-model", "k", "--format=c", "--quiet", "--out=a.tbl",
                    "--channel=", "--set", "a=1", "--set=b = 2", "--seed", "7", "--call", "x", "--call=y",
                    "f1", "f2", NULL};
    assert_int_equal(run_parse(&o, ARGC(argv), argv), CLI_RUN);
    assert_int_equal(o.scans, 12);
    TRK_ASSERT_NEAR(o.snr, -3.5, 0, 0);
    TRK_ASSERT_NEAR(o.nu, 2, 0, 0);
    assert_int_equal(o.n_list, 3);
    TRK_ASSERT_NEAR(o.list[2], 0.1, 0, 0);
    TRK_ASSERT_NEAR(o.pair[0], 1, 0, 0);
    TRK_ASSERT_NEAR(o.pair[1], 2, 0, 0);
    assert_int_equal(o.model, 30);
    assert_int_equal(o.fmt, 1);
    assert_int_equal(o.quiet, 1);
    assert_string_equal(o.out, "a.tbl");
    assert_string_equal(o.channel, ""); /* CLI_EMPTY_OK */
    assert_int_equal(o.n_sets, 2);      /* repeated, in order */
    assert_string_equal(o.sets[0], "a=1");
    assert_string_equal(o.sets[1], "b = 2");
    assert_int_equal(o.seed, 7);
    assert_int_equal(o.calls, 2); /* every occurrence, in order */
    assert_string_equal(o.last_call, "y");
    assert_int_equal(o.n_operands, 2);
    assert_string_equal(o.operands[0], "f1");
    assert_string_equal(o.operands[1], "f2");
    /* a range list, an integer in exponent form, the last value wins */
    char *argv2[] = {"t", "--pfa", "0.1:0.5:0.1", "--scans", "1e4", "--scans", "20", "-q", "--out", "o", NULL};
    assert_int_equal(run_parse(&o, ARGC(argv2), argv2), CLI_RUN);
    assert_int_equal(o.n_list, 5);
    TRK_ASSERT_NEAR(o.list[4], 0.5, 1e-12, 0);
    assert_int_equal(o.scans, 20);
    assert_int_equal(o.quiet, 1); /* -q: a second spelling, no note */
    /* a value may look like an option (negative numbers) */
    char *argv3[] = {"t", "--snr-db", "-10", "--out", "-", NULL};
    assert_int_equal(run_parse(&o, ARGC(argv3), argv3), CLI_RUN);
    TRK_ASSERT_NEAR(o.snr, -10, 0, 0);
    assert_string_equal(o.out, "-");
    /* an operand hook taking two arguments */
    char *argv4[] = {"t", "--out", "x", "--pair-old", "3", "f", NULL};
    struct capture c;
    const char *err;
    assert_int_equal(parse_err(&o, ARGC(argv4), argv4, &c, &err), CLI_RUN);
    assert_int_equal(o.n_operands, 1);
    assert_string_equal(o.operands[0], "f");
    assert_non_null(strstr(err, "t: note: --pair-old X is deprecated"));
    assert_non_null(strstr(err, "use --pair X"));
}

static void test_value_parsers(void **state)
{
    (void)state;
    long l;
    double d, v[8];
    assert_int_equal(cli_parse_long("9007199254740993", &l), 0); /* exact beyond 2^53 */
    assert_true(l == 9007199254740993L);
    assert_int_equal(cli_parse_long("-12", &l), 0);
    assert_int_equal(l, -12);
    assert_int_equal(cli_parse_long("2.5e3", &l), 0);
    assert_int_equal(l, 2500);
    assert_int_equal(cli_parse_long("1.5", &l), -1);
    assert_int_equal(cli_parse_long("1e300", &l), -1);
    assert_int_equal(cli_parse_long("12x", &l), -1);
    assert_int_equal(cli_parse_long(" 12", &l), -1);
    assert_int_equal(cli_parse_long("12 ", &l), -1);
    assert_int_equal(cli_parse_long("", &l), -1);
    assert_int_equal(cli_parse_double("1e-3", &d), 0);
    TRK_ASSERT_NEAR(d, 1e-3, 0, 0);
    assert_int_equal(cli_parse_double("nan", &d), -1);
    assert_int_equal(cli_parse_double("inf", &d), -1);
    assert_int_equal(cli_parse_double("1e999", &d), -1);
    assert_int_equal(cli_parse_double("0.5 ", &d), -1);
    assert_int_equal(cli_parse_double("0.5,", &d), -1);
    assert_int_equal(cli_parse_list("1,2,3", v, 8), 3);
    assert_int_equal(cli_parse_list("1:2:0.5", v, 8), 3);
    assert_int_equal(cli_parse_list("1:100:1", v, 8), -1); /* more than max: refused, never cut */
    assert_int_equal(cli_parse_list("1,2,", v, 8), -1);
    assert_int_equal(cli_parse_list("1, 2", v, 8), -1);
    assert_int_equal(cli_parse_list("2:1:1", v, 8), -1);
    assert_int_equal(cli_parse_list("", v, 8), -1);
    assert_true(cli_blank(""));
    assert_true(cli_blank(" \t"));
    assert_false(cli_blank(" x "));
}

/* ---------------------------------------------------------------- aliases */

static void test_aliases(void **state)
{
    (void)state;
    struct opts o;
    struct capture c;
    const char *err;
    char *argv[] = {"t", "--nu", "3", "-o", "f.tbl", "--model=none", "--nu=4", NULL};
    assert_int_equal(parse_err(&o, ARGC(argv), argv, &c, &err), CLI_RUN);
    TRK_ASSERT_NEAR(o.nu, 4, 0, 0); /* an alias sets its option */
    assert_string_equal(o.out, "f.tbl");
    assert_int_equal(o.model, 10);
    /* one note per old spelling (--nu twice: once), each naming the new one */
    assert_int_equal(count_lines(err), 3);
    assert_int_equal(count_of(err, "t: note: --nu is deprecated"), 1);
    assert_non_null(strstr(err, "use --k-shape"));
    assert_non_null(strstr(err, "t: note: -o is deprecated"));
    assert_non_null(strstr(err, "use --out"));
    assert_non_null(strstr(err, "t: note: --model is deprecated"));
    assert_non_null(strstr(err, "use --clutter-model"));
    /* the new spellings: no note */
    char *argv2[] = {"t", "--k-shape", "3", "--out", "f.tbl", "--clutter-model", "none", "-q", NULL};
    assert_int_equal(parse_err(&o, ARGC(argv2), argv2, &c, &err), CLI_RUN);
    assert_string_equal(err, "");
    /* an alias's bad value names the spelling given */
    char *argv3[] = {"t", "--out", "x", "--nu", "abc", NULL};
    assert_int_equal(parse_err(&o, ARGC(argv3), argv3, &c, &err), 2);
    assert_non_null(strstr(err, "t: bad value for --nu: 'abc'"));
}

/* ---------------------------------------------------------------- refusals */

/* argv must give status 2 with one line on stderr holding `want` (after
 * the deprecation notes, if any). */
static void expect_usage_error(char **argv, int argc, const char *want)
{
    struct opts o;
    struct capture c;
    const char *err;
    const int rc = parse_err(&o, argc, argv, &c, &err);
    if (rc != 2 || !strstr(err, want) || count_lines(err) - count_of(err, ": note: ") != 1)
        fail_msg("%s ...: status %d, stderr '%s'; want 2 and one line with '%s'", argv[1], rc, err, want);
}

#define EXPECT_USAGE_ERROR(want, ...)                                  \
    do {                                                               \
        char *argv_[] = {"t", __VA_ARGS__, NULL};                      \
        expect_usage_error(argv_, ARGC(argv_), want);                  \
    } while (0)

static void test_refused_values(void **state)
{
    (void)state;
    /* blanks and empty values */
    EXPECT_USAGE_ERROR("t: bad value for --out: ' ' (blank)", "--out", " ");
    EXPECT_USAGE_ERROR("t: bad value for --out: '' (empty)", "--out=");
    EXPECT_USAGE_ERROR("t: bad value for --channel: '\t' (blank)", "--out", "x", "--channel", "\t");
    EXPECT_USAGE_ERROR("t: bad value for --set: '  ' (blank)", "--out", "x", "--set", "  ");
    EXPECT_USAGE_ERROR("(blank)", "--out", "x", "--scans", " ");
    EXPECT_USAGE_ERROR("(blank)", "--out", "x", "--pair", " ");
    /* trailing garbage, blanks around numbers */
    EXPECT_USAGE_ERROR("t: bad value for --scans: '12x' (an integer in [1, 1000000])", "--out", "x", "--scans", "12x");
    EXPECT_USAGE_ERROR("t: bad value for --snr-db: '3 '", "--out", "x", "--snr-db", "3 ");
    EXPECT_USAGE_ERROR("t: bad value for --snr-db: ' 3'", "--out", "x", "--snr-db", " 3");
    EXPECT_USAGE_ERROR("t: bad value for --pfa: '0.1,0.2x'", "--out", "x", "--pfa", "0.1,0.2x");
    EXPECT_USAGE_ERROR("(2 numbers A,B)", "--out", "x", "--pair", "1,2,3");
    EXPECT_USAGE_ERROR("t: bad value for --seed: '5.5'", "--out", "x", "--seed", "5.5");
    /* ranges, words, non-finite */
    EXPECT_USAGE_ERROR("t: bad value for --scans: '0' (an integer in [1, 1000000])", "--out", "x", "--scans", "0");
    EXPECT_USAGE_ERROR("(a number in [-30, 60])", "--out", "x", "--snr-db", "61");
    EXPECT_USAGE_ERROR("(a number > 0)", "--out", "x", "--k-shape", "0");
    EXPECT_USAGE_ERROR("each in (0, 1)", "--out", "x", "--pfa", "0.1,1");
    EXPECT_USAGE_ERROR("t: bad value for --clutter-model: 'K' (one of none|rayleigh|k)", "--out", "x",
                       "--clutter-model", "K");
    EXPECT_USAGE_ERROR("t: bad value for --snr-db: 'nan'", "--out", "x", "--snr-db", "nan");
    /* a call's own message */
    EXPECT_USAGE_ERROR("t: --call bad: refused by the call", "--out", "x", "--call", "bad");
    /* a repeated option past its capacity */
    EXPECT_USAGE_ERROR("--set e=5: given more than 4 times", "--out", "x", "--set", "a=1", "--set", "b=2", "--set",
                       "c=3", "--set", "d=4", "--set", "e=5");
}

static void test_usage_errors(void **state)
{
    (void)state;
    EXPECT_USAGE_ERROR("t: unknown option --bogus (see --help)", "--out", "x", "--bogus");
    /* a misspelled option: the nearest listed spelling (never a deprecated one) */
    EXPECT_USAGE_ERROR("t: unknown option --scan; did you mean '--scans'? (see --help)", "--out", "x", "--scan", "3");
    EXPECT_USAGE_ERROR("t: unknown option --sacns=3; did you mean '--scans'? (see --help)", "--out", "x", "--sacns=3");
    EXPECT_USAGE_ERROR("t: unknown option --modle (see --help)", "--out", "x", "--modle", "k"); /* --model: old */
    EXPECT_USAGE_ERROR("t: unknown option -z (see --help)", "--out", "x", "-z");                /* -q: 1 of 2 */
    EXPECT_USAGE_ERROR("t: unknown option --k-shap; did you mean '--k-shape'? (see --help)", "--out", "x", "--k-shap",
                       "2");
    EXPECT_USAGE_ERROR("t: --scans needs a value (see --help)", "--out", "x", "--scans");
    EXPECT_USAGE_ERROR("t: --nu needs a value", "--out", "x", "--nu");
    EXPECT_USAGE_ERROR("t: --quiet takes no value (see --help)", "--out", "x", "--quiet=1");
    EXPECT_USAGE_ERROR("t: --out is required (see --help)", "--scans", "3");
    EXPECT_USAGE_ERROR("t: operand 'refuse' refused", "--out", "x", "refuse");
    EXPECT_USAGE_ERROR("t: unexpected argument 'f5' (see --help)", "--out", "x", "f1", "f2", "f3", "f4", "f5");
    EXPECT_USAGE_ERROR("t: unknown option --pair-old (see --help)", "--out", "x", "--pair-old");
}

/* ---------------------------------------------------------------- help */

static void test_help(void **state)
{
    (void)state;
    struct opts o;
    struct capture c;
    const char *const forms[] = {"--help", "-h"};
    for (int k = 0; k < 2; k++) {
        /* anywhere, even after a bad option, and before the required ones */
        char *argv[] = {"t", "--scans", "0", (char *)forms[k], NULL};
        capture_begin(&c, 1);
        const int rc = run_parse(&o, ARGC(argv), argv);
        const char *out = capture_end(&c);
        assert_int_equal(rc, 0);
        assert_non_null(strstr(out, "usage: t [options] FILE...\nA test tool.\nRun:\n"));
        assert_non_null(strstr(out, "  --scans N           scans per run (default 300)\n"));
        assert_non_null(strstr(out, "  --quiet, -q         no progress\n"));
        assert_non_null(strstr(out, "  --out FILE          output file (required)\n"));
        assert_non_null(strstr(out, "  --clutter-model none|rayleigh|k  clutter law (default rayleigh)\n"));
        assert_non_null(strstr(out, "(LIST: values a,b,c or a range from:to:step)"));
        assert_non_null(strstr(out, "deprecated spellings"));
        assert_non_null(strstr(out, "  --nu                use --k-shape\n"));
        assert_non_null(strstr(out, "  -o                  use --out\n"));
        assert_non_null(strstr(out, "Writes FILE.\n"));
        assert_null(strstr(out, "--secret")); /* CLI_HIDDEN */
    }
}

/* A second table (trk-sim's common options): shadowed by the tool's own. */
static void test_common_table(void **state)
{
    (void)state;
    long runs = 0, own_runs = 0, threads = 0;
    const struct cli_opt common[] = {
        CLI_OPT_LONG("--runs", &runs, "N", "5", CLI_GE, 1, 0, "Monte Carlo runs"),
        CLI_OPT_LONG("--threads", &threads, "N", NULL, CLI_IN, 1, 1024, "threads"),
        CLI_OPT_END};
    const struct cli_opt opts[] = {CLI_OPT_LONG("--runs", &own_runs, "N", "10", CLI_GE, 1, 0, "runs per point"),
                                   CLI_OPT_END};
    const struct cli cli = {.prog = "e", .opts = opts, .common = common};
    char *argv[] = {"e", "--runs", "7", "--threads=2", NULL};
    assert_int_equal(cli_parse(&cli, ARGC(argv), argv), CLI_RUN);
    assert_int_equal(own_runs, 7);
    assert_int_equal(runs, 5);
    assert_int_equal(threads, 2);
    struct capture c;
    capture_begin(&c, 1);
    cli_usage(&cli, stdout);
    const char *out = capture_end(&c);
    assert_non_null(strstr(out, "options:\n  --runs N            runs per point (default 10)\n"));
    assert_non_null(strstr(out, "common options:\n  --threads N         threads\n"));
    assert_int_equal(count_of(out, "--runs"), 1);
}

/* ---------------------------------------------------------------- --set */

/* --set KEY=VALUE: the tracker_config.h keys, as in a config file. */
static void test_set(void **state)
{
    (void)state;
    static struct tcfg cfg;
    const char *sets[8];
    int n_sets = 0;
    const struct cli_opt opts[] = {CLI_OPT_STRINGS("--set", sets, &n_sets, 8, "KEY=VALUE", "tracker setting"),
                                   CLI_OPT_END};
    const struct cli cli = {.prog = "s", .opts = opts};
    char *argv[] = {"s", "--set", "term=page", "--set=gate_prob = 0.95", "--set", "sensor.0.k_shape=2", NULL};
    assert_int_equal(cli_parse(&cli, ARGC(argv), argv), CLI_RUN);
    assert_int_equal(n_sets, 3);
    tcfg_defaults(&cfg);
    char err[512];
    for (int i = 0; i < n_sets; i++) assert_int_equal(kv_parse_assignment(sets[i], tcfg_set, &cfg, err, sizeof err), 0);
    assert_int_equal(cfg.term, TRK_TERM_PAGE);
    TRK_ASSERT_NEAR(cfg.params.gate_prob, 0.95, 1e-7, 0);
    TRK_ASSERT_NEAR(cfg.amp[0].k_shape, 2, 0, 0);
    assert_int_equal(kv_parse_assignment("no_such_key=1", tcfg_set, &cfg, err, sizeof err), -1);
    assert_non_null(strstr(err, "unknown setting 'no_such_key'"));
    assert_string_equal(err, "unknown setting 'no_such_key'");
    /* a misspelled key: the nearest known one */
    assert_int_equal(kv_parse_assignment("gate_prb=0.9", tcfg_set, &cfg, err, sizeof err), -1);
    assert_string_equal(err, "unknown setting 'gate_prb'; did you mean 'gate_prob'?");
    assert_int_equal(kv_parse_assignment("sensor.1.pdd=0.9", tcfg_set, &cfg, err, sizeof err), -1);
    assert_string_equal(err, "unknown setting 'sensor.1.pdd'; did you mean 'sensor.1.pd'?");
    assert_int_equal(kv_parse_assignment("sesnor.0.snr_db=9", tcfg_set, &cfg, err, sizeof err), -1);
    assert_string_equal(err, "unknown setting 'sesnor.0.snr_db'; did you mean 'sensor.0.snr_db'?");
    assert_int_equal(kv_parse_assignment("trem.page.h=3", tcfg_set, &cfg, err, sizeof err), -1);
    assert_string_equal(err, "unknown setting 'trem.page.h'; did you mean 'term.page.h'?");
    assert_int_equal(kv_parse_assignment("gate_prob=2", tcfg_set, &cfg, err, sizeof err), -1);
    assert_non_null(strstr(err, "gate_prob"));
    assert_int_equal(kv_parse_assignment("gate_prob= ", tcfg_set, &cfg, err, sizeof err), -1);
}

/* One number syntax everywhere (kv_strtod): decimal only
 * (strtod took "0x10" as 16), subnormals are finite and accepted (4.9e-324
 * was "not a finite number"), overflow and total underflow named as such;
 * blank values refused; "sensor.-1" named as a negative index (it was
 * "sensor index 18446744073709551615"). */
static void test_numbers_one_syntax(void **state)
{
    (void)state;
    double d, v[4];
    long l;
    char *end;
    assert_int_equal(cli_parse_double("4.9e-324", &d), 0);
    assert_true(d > 0 && d < 1e-323);
    assert_int_equal(kv_parse_double("2.2e-310", &d), 0);
    TRK_ASSERT_NEAR(d, 2.2e-310, 0, 1e-9);
    assert_int_equal(kv_parse_number("1e-400", &d), KV_NUM_RANGE);
    assert_int_equal(kv_parse_number("1e400", &d), KV_NUM_RANGE);
    assert_int_equal(kv_parse_number("-inf", &d), KV_NUM_NONFINITE);
    assert_int_equal(kv_parse_number("0x10", &d), KV_NUM_BAD);
    assert_int_equal(kv_parse_number("-0X1p3", &d), KV_NUM_BAD);
    assert_int_equal(kv_parse_number(" ", &d), KV_NUM_BAD);
    assert_int_equal(kv_strtod("0x10", &end, &d), KV_NUM_BAD);
    assert_int_equal(cli_parse_double("0x10", &d), -1);
    assert_int_equal(cli_parse_long("0x10", &l), -1);
    assert_int_equal(cli_parse_list("1,0x2", v, 4), -1);
    assert_int_equal(kv_parse_doubles("1 0x2", v, 2), -1);
    assert_int_equal(kv_parse_doubles("1 4.9e-324", v, 2), 0);
    assert_true(v[1] > 0);
    assert_string_equal(kv_num_error(KV_NUM_RANGE), "beyond the range of a double (overflow, or underflow to 0)");

    static struct tcfg cfg;
    char err[512];
    tcfg_defaults(&cfg);
    assert_int_equal(kv_parse_assignment("sensor.-1.pd=0.5", tcfg_set, &cfg, err, sizeof err), -1);
    assert_non_null(strstr(err, "sensor index '-1': must be an integer >= 0"));
    assert_null(strstr(err, "18446744073709551615"));
    assert_int_equal(kv_parse_assignment("sensor.+0.pd=0.5", tcfg_set, &cfg, err, sizeof err), -1);
    const int sub = kv_parse_assignment("process_noise_q=4.9e-324", tcfg_set, &cfg, err, sizeof err);
    if (TRK_REAL_IS_FLOAT) { /* no float holds it: refused, not silently 0 */
        assert_int_equal(sub, -1);
        if (!strstr(err, "outside the float range of this build")) fail_msg("message: %s", err);
    } else {
        if (sub != 0) fail_msg("4.9e-324 refused: %s", err);
    }
    assert_int_equal(kv_parse_assignment("process_noise_q=1e-400", tcfg_set, &cfg, err, sizeof err), -1);
    assert_non_null(strstr(err, "beyond the range of a double"));
    assert_int_equal(kv_parse_assignment("gate_prob=0x1p-1", tcfg_set, &cfg, err, sizeof err), -1);
    assert_non_null(strstr(err, "not a decimal number"));
    /* fuzz_kvfile: meas_sigma_m squared skipped the covariance check of meas_cov_m2 (8.9e118^2:
     * xx yy overflows), and the configuration written back was refused */
    assert_int_equal(kv_parse_assignment(TRK_REAL_IS_FLOAT ? "sensor.0.meas_sigma_m=1e19" : "sensor.0.meas_sigma_m=8.9e118",
                                         tcfg_set, &cfg, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "TRK_E_NOT_SPD"));
    assert_int_equal(kv_parse_assignment("sensor.0.meas_sigma_m=1e200", tcfg_set, &cfg, err, sizeof err), -1);
    assert_int_equal(kv_parse_assignment("sensor.0.meas_sigma_m=3", tcfg_set, &cfg, err, sizeof err), 0);
    TRK_ASSERT_NEAR(cfg.params.sensor[0].meas_cov_m2[0], 9, 0, 0);
    TRK_ASSERT_NEAR(cfg.params.sensor[0].meas_cov_m2[1], 0, 0, 0);
    TRK_ASSERT_NEAR(cfg.params.sensor[0].meas_cov_m2[2], 9, 0, 0);

    /* blank values through the option table: refused, never 0 */
    long scans = 7;
    double snr = 3;
    const struct cli_opt opts[] = {CLI_OPT_LONG("--max-scans", &scans, "N", NULL, CLI_GE, 0, 0, "scans"),
                                   CLI_OPT_DOUBLE("--snr-db", &snr, "D", NULL, 0, 0, 0, "snr"), CLI_OPT_END};
    const struct cli cli = {.prog = "t", .opts = opts};
    char *a1[] = {"t", "--max-scans", " ", NULL}, *a2[] = {"t", "--snr-db= ", NULL}, *a3[] = {"t", "--snr-db", "1e-400", NULL};
    struct capture c;
    capture_begin(&c, 2);
    const int r1 = cli_parse(&cli, ARGC(a1), a1), r2 = cli_parse(&cli, ARGC(a2), a2), r3 = cli_parse(&cli, ARGC(a3), a3);
    capture_end(&c);
    assert_int_equal(r1, 2);
    assert_int_equal(r2, 2);
    assert_int_equal(r3, 2);
    assert_int_equal(scans, 7);
    TRK_ASSERT_NEAR(snr, 3, 0, 0);
    assert_non_null(strstr(c.text, "'1e-400' (beyond the range of a double"));
}

/* ---------------------------------------------------------------- subcommands */

static int cmd_a(int argc, char **argv)
{
    return argc == 2 && strcmp(argv[0], "a") == 0 && strcmp(argv[1], "x") == 0 ? 42 : 1;
}

static void more_text(FILE *f) { fprintf(f, "more text\n"); }

static void test_dispatch(void **state)
{
    (void)state;
    const struct cli_cmd cmds[] = {{"a", "the a command", cmd_a}, {NULL, NULL, NULL}};
    struct capture c;
    char *run[] = {"p", "a", "x", NULL};
    assert_int_equal(cli_dispatch("p", "command", "usage: p CMD\n", cmds, more_text, 3, run), 42);
    const char *const helps[] = {"--help", "-h", "help"};
    for (int k = 0; k < 3; k++) {
        char *argv[] = {"p", (char *)helps[k], NULL};
        capture_begin(&c, 1);
        assert_int_equal(cli_dispatch("p", "command", "usage: p CMD\n", cmds, more_text, 2, argv), 0);
        const char *out = capture_end(&c);
        assert_non_null(strstr(out, "usage: p CMD\n  a                    the a command\nmore text\n"));
    }
    char *none[] = {"p", NULL};
    capture_begin(&c, 2);
    assert_int_equal(cli_dispatch("p", "experiment", "", cmds, NULL, 1, none), 2);
    assert_string_equal(capture_end(&c), "p: no experiment given (see p --help)\n");
    char *bad[] = {"p", "zz", NULL};
    capture_begin(&c, 2);
    assert_int_equal(cli_dispatch("p", "command", "", cmds, NULL, 2, bad), 2);
    assert_string_equal(capture_end(&c), "p: unknown command 'zz' (see p --help)\n");
    const struct cli_cmd two[] = {{"info", "", cmd_a}, {"amp", "", cmd_a}, {NULL, NULL, NULL}};
    char *near[] = {"p", "inof", NULL};
    capture_begin(&c, 2);
    assert_int_equal(cli_dispatch("p", "command", "", two, NULL, 2, near), 2);
    assert_string_equal(capture_end(&c), "p: unknown command 'inof'; did you mean 'info'? (see p --help)\n");
}

/* ---------------------------------------------------------------- suggestions */

static void test_suggest(void **state)
{
    (void)state;
    /* optimal string alignment: an insertion, a deletion, a substitution, an
     * adjacent swap each count 1 */
    assert_int_equal(cli_edit_distance("gamma", "gamma"), 0);
    assert_int_equal(cli_edit_distance("gama", "gamma"), 1);
    assert_int_equal(cli_edit_distance("gammma", "gamma"), 1);
    assert_int_equal(cli_edit_distance("gamna", "gamma"), 1);
    assert_int_equal(cli_edit_distance("gmama", "gamma"), 1);
    assert_int_equal(cli_edit_distance("agmma", "gamam"), 2);
    assert_int_equal(cli_edit_distance("", "ab"), 2);
    assert_true(cli_edit_distance("abcdef", "uvwxyz") > 2);
    assert_true(cli_edit_distance("a", "abcd") > 2); /* lengths 3 apart */
    /* close: at most 2 edits and fewer than half the word's characters */
    const char *const names[] = {"gamma", "gate_prob", "term", "pd", NULL};
    assert_string_equal(cli_suggest("gama", names), "gamma");
    assert_string_equal(cli_suggest("gate_porb", names), "gate_prob");
    assert_string_equal(cli_suggest("trem", names), "term"); /* 1 edit of 4 */
    assert_null(cli_suggest("pf", names));                   /* 1 edit of 2: not less than half */
    assert_null(cli_suggest("tx", names));
    assert_null(cli_suggest("gate_pxyzb", names));           /* 3 edits */
    assert_null(cli_suggest("anything", NULL));
    /* the nearest wins; on a tie the first listed */
    const char *const tie[] = {"abcd", "abce", "abcx", NULL};
    assert_string_equal(cli_suggest("abcf", tie), "abcd");
    assert_string_equal(cli_suggest("abcxy", tie), "abcx");
    struct cli_near near;
    cli_near_init(&near, "sensors");
    cli_near_add(&near, NULL);
    cli_near_add(&near, "");
    assert_null(near.best);
    cli_near_add(&near, "sensor");
    assert_string_equal(near.best, "sensor");
    assert_int_equal(near.dist, 1);
    char buf[64];
    cli_did_you_mean("gamma", buf, sizeof buf);
    assert_string_equal(buf, "; did you mean 'gamma'?");
    cli_did_you_mean(NULL, buf, sizeof buf);
    assert_string_equal(buf, "");
}

static void test_internal_errors(void **state)
{
    (void)state;
    long x;
    const struct cli_opt bad_default[] = {CLI_OPT_LONG("--x", &x, "N", "abc", 0, 0, 0, "x"), CLI_OPT_END};
    const struct cli c1 = {.prog = "i", .opts = bad_default};
    char *argv[] = {"i", NULL};
    struct capture c;
    capture_begin(&c, 2);
    assert_int_equal(cli_parse(&c1, 1, argv), 1);
    assert_non_null(strstr(capture_end(&c), "internal error: bad default 'abc' of --x"));
    const struct cli_opt dangling[] = {CLI_OPT_ALIAS("--old", "--missing"), CLI_OPT_END};
    const struct cli c2 = {.prog = "i", .opts = dangling};
    char *argv2[] = {"i", "--old", NULL};
    capture_begin(&c, 2);
    assert_int_equal(cli_parse(&c2, 2, argv2), 1);
    assert_non_null(strstr(capture_end(&c), "internal error: --old names no option --missing"));
}

/* ---------------------------------------------------------------- signals */

static void test_stop_signals(void **state)
{
    (void)state;
    cli_catch_stop_signals();
    assert_int_equal(cli_stop_flag, 0);
    assert_int_equal(raise(SIGTERM), 0);
    assert_int_equal(cli_stop_flag, 1);
    assert_int_equal(cli_stop_signal, SIGTERM);
    cli_stop_flag = 0;
    assert_int_equal(raise(SIGINT), 0);
    assert_int_equal(cli_stop_flag, 1);
    assert_int_equal(cli_stop_signal, SIGINT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults),     cmocka_unit_test(test_forms),
        cmocka_unit_test(test_value_parsers), cmocka_unit_test(test_aliases),
        cmocka_unit_test(test_refused_values), cmocka_unit_test(test_usage_errors),
        cmocka_unit_test(test_help),         cmocka_unit_test(test_common_table),
        cmocka_unit_test(test_set),
        cmocka_unit_test(test_numbers_one_syntax),       cmocka_unit_test(test_dispatch),
        cmocka_unit_test(test_suggest),
        cmocka_unit_test(test_internal_errors), cmocka_unit_test(test_stop_signals),
    };
    return trk_run_tests("cli", tests, NULL, NULL);
}
