/* cli.h - the one command-line interface of the trk tools: a declarative
 * option parser (every tool's options are a table of struct cli_opt), a
 * subcommand dispatcher, the deprecation notes of old spellings, and a clean
 * stop on SIGINT/SIGTERM.
 *
 * VOCABULARY. The same quantity has one name in every tool; the
 * old spellings stay accepted for one release, each printing one note
 * "PROG: note: OLD is deprecated ..., use NEW" on stderr:
 *
 *   quantity                 new spelling              old spelling (tool)
 *   clutter amplitude law    --clutter-model none|rayleigh|k
 *                                                      --clutter rayleigh|k (trk-tablegen amp)
 *                                                      --model rayleigh|k   (trk-tablegen q2)
 *                                                      --amplitude none|rayleigh|k (trk-sonar-sim)
 *   K shape nu               --k-shape NU              --nu (trk-tablegen amp, q2;
 *                                                            trk-sim brekke-trackloss, brekke-toc: a LIST)
 *                                                      (config key sensor.N.k_shape: unchanged)
 *   clutter detections       --clutter-count N         --clutter N (trk-sim demo: the mean of a
 *     per scan                                                      Poisson count; trk-sonar-sim:
 *                                                                   exactly N, already so named)
 *   output                   --out                     -o, --output (trk-tablegen amp, q2)
 *                                                      --log (trk-sonar-sim)
 *   tracker setting          --set KEY=VALUE           KEY=VALUE operand (trk-sim demo)
 *     (tracker_config.h keys,                          --KEY VALUE, --KEY=VALUE (trk-lcm-bridge,
 *      the config-file keys)                             e.g. --term page, --sensor.0.pd 0.8)
 *
 * One meaning of --out per tool: trk-sim the prefix of the output files
 * (demo: a directory); trk-tablegen amp, q2 the table file; trk-sonar-sim the
 * LCM log file written instead of publishing; trk-lcm-bridge the track log of
 * --replay. trk-bench and trk-vectors write to stdout only.
 *
 * PARSER. A tool describes each option once:
 *     long scans; double nu; const char *out = NULL; int quiet = 0;
 *     const struct cli_opt opts[] = {
 *         CLI_OPT_LONG("--scans", &scans, "N", "300", CLI_IN, 1, 1e6, "scans per run"),
 *         CLI_OPT_DOUBLE("--k-shape", &nu, "NU", "1", CLI_GT, 0, 0, "K shape"),
 *         CLI_OPT_ALIAS("--nu", "--k-shape"),
 *         CLI_OPT_REQUIRED_STRING("--out", &out, "FILE", "output file"),
 *         CLI_OPT_FLAG("--quiet", &quiet, "no progress on stderr"),
 *         CLI_OPT_END};
 *     const struct cli cli = {.prog = "trk-x", .about = "What it does.", .opts = opts};
 *     const int rc = cli_parse(&cli, argc, argv);    argv[0]: the program or command
 *     if (rc != CLI_RUN) return rc;
 * and cli_parse does the rest: the defaults (parsed from their text into
 * the destinations before the command line), `--name value` and
 * `--name=value`, value checks (types, ranges; a value of blanks, an empty
 * value unless CLI_EMPTY_OK, and trailing garbage are refused), aliases,
 * required options, and --help / -h anywhere (the help generated from the
 * table on stdout, exit status 0). A usage error prints one line on stderr,
 * "PROG: ...", naming the option, and gives exit status 2; an unknown option
 * names the nearest listed one ("PROG: unknown option --scan; did you mean
 * '--scans'? (see --help)", suggest.h). Arguments that are no option go to
 * the operand hook (file names, old forms); without one they are a usage
 * error.
 *
 * EXIT STATUS of every tool (docs/statuses.md, "Exit codes"): 0 success, 1 a
 * failure while running (I/O, corrupt input, a library refusal), 2 a usage
 * or configuration error (nothing was started). */
#ifndef TRK_TOOLS_CLI_H
#define TRK_TOOLS_CLI_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

enum cli_type {
    CLI_LONG,    /* long *dst: an integer ("1e6" accepted) within the range */
    CLI_DOUBLE,  /* double *dst: a finite number within the range */
    CLI_LIST,    /* double dst[max], *n = count: "a,b,c" or "from:to:step", each within the range */
    CLI_NUMBERS, /* double dst[max]: exactly max numbers, "a,b" or "a b" */
    CLI_CHOICE,  /* int *dst = values[k] for the k-th word of arg ("none|rayleigh|k"; NULL values: k) */
    CLI_FLAG,    /* int *dst = 1; takes no value */
    CLI_STRING,  /* const char **dst = the value */
    CLI_STRINGS, /* const char *dst[max], *n: every occurrence appended (a repeated option) */
    CLI_CUSTOM,  /* parse(value, dst) == 0 */
    CLI_CALL,    /* call(dst, value, err, errlen) == 0, at every occurrence, in command-line order */
    CLI_ALIAS,   /* another spelling of the option named arg (CLI_DEPRECATED: with a note) */
    CLI_HEADING  /* a heading line (help) in --help; name "" */
};

/* Accepted range of CLI_LONG, CLI_DOUBLE and CLI_LIST values (0: any). */
enum {
    CLI_GE = 1, /* lo <= v */
    CLI_GT = 2, /* lo < v */
    CLI_LE = 4, /* v <= hi */
    CLI_LT = 8, /* v < hi */
    CLI_IN = CLI_GE | CLI_LE,
    CLI_OPEN = CLI_GT | CLI_LT
};

/* Option flags. */
enum {
    CLI_REQUIRED = 1,   /* must be given ("PROG: --out is required") */
    CLI_HIDDEN = 2,     /* accepted, not listed by --help */
    CLI_EMPTY_OK = 4,   /* an empty value '' is accepted (e.g. "'' = none"); blanks never are */
    CLI_DEPRECATED = 8  /* CLI_ALIAS: an old spelling, a note on stderr when used */
};

struct cli_opt {
    const char *name;   /* "--scans"; NULL ends the table */
    enum cli_type type;
    void *dst;
    const char *arg;    /* the value in --help ("N"); CHOICE: the words; ALIAS: the option it names */
    const char *def;    /* the default as text, parsed into dst before the command line and
                         * shown by --help; NULL: dst keeps its value */
    const char *help;   /* one line; '\n' continues it on the next line */
    unsigned range;     /* CLI_GE | ... */
    double lo, hi;
    int max, *n;        /* LIST, STRINGS: capacity of dst and count; NUMBERS: the count */
    const int *values;  /* CHOICE: one per word (NULL: the word's index) */
    int (*parse)(const char *value, void *dst);                       /* CUSTOM: 0 or -1 */
    int (*call)(void *dst, const char *value, char *err, size_t errlen); /* CALL: 0, or -1 with a
                                                                          * message in err (or "") */
    unsigned flags;     /* CLI_REQUIRED | ... */
};

#define CLI_OPT_LONG(name_, dst_, arg_, def_, range_, lo_, hi_, help_)                                  \
    {.name = name_, .type = CLI_LONG, .dst = dst_, .arg = arg_, .def = def_, .help = help_, .range = range_, \
     .lo = lo_, .hi = hi_}
#define CLI_OPT_DOUBLE(name_, dst_, arg_, def_, range_, lo_, hi_, help_)                                  \
    {.name = name_, .type = CLI_DOUBLE, .dst = dst_, .arg = arg_, .def = def_, .help = help_, .range = range_, \
     .lo = lo_, .hi = hi_}
#define CLI_OPT_LIST(name_, dst_, n_, max_, def_, range_, lo_, hi_, help_)                                \
    {.name = name_, .type = CLI_LIST, .dst = dst_, .arg = "LIST", .def = def_, .help = help_, .range = range_, \
     .lo = lo_, .hi = hi_, .max = max_, .n = n_}
#define CLI_OPT_NUMBERS(name_, dst_, count_, arg_, help_) \
    {.name = name_, .type = CLI_NUMBERS, .dst = dst_, .arg = arg_, .help = help_, .max = count_}
#define CLI_OPT_CHOICE(name_, dst_, words_, values_, def_, help_) \
    {.name = name_, .type = CLI_CHOICE, .dst = dst_, .arg = words_, .def = def_, .help = help_, .values = values_}
#define CLI_OPT_FLAG(name_, dst_, help_) {.name = name_, .type = CLI_FLAG, .dst = dst_, .help = help_}
#define CLI_OPT_STRING(name_, dst_, arg_, def_, help_) \
    {.name = name_, .type = CLI_STRING, .dst = dst_, .arg = arg_, .def = def_, .help = help_}
#define CLI_OPT_REQUIRED_STRING(name_, dst_, arg_, help_) \
    {.name = name_, .type = CLI_STRING, .dst = dst_, .arg = arg_, .help = help_, .flags = CLI_REQUIRED}
#define CLI_OPT_STRINGS(name_, dst_, n_, max_, arg_, help_) \
    {.name = name_, .type = CLI_STRINGS, .dst = dst_, .arg = arg_, .help = help_, .max = max_, .n = n_}
#define CLI_OPT_CUSTOM(name_, dst_, parse_, arg_, def_, help_) \
    {.name = name_, .type = CLI_CUSTOM, .dst = dst_, .arg = arg_, .def = def_, .help = help_, .parse = parse_}
#define CLI_OPT_CALL(name_, ctx_, call_, arg_, help_) \
    {.name = name_, .type = CLI_CALL, .dst = ctx_, .arg = arg_, .help = help_, .call = call_}
/* An old spelling: accepted, with a deprecation note naming the new one. */
#define CLI_OPT_ALIAS(old_, new_) {.name = old_, .type = CLI_ALIAS, .arg = new_, .flags = CLI_DEPRECATED}
/* A second spelling that stays (e.g. -q for --quiet); listed beside the option. */
#define CLI_OPT_SHORT(short_, long_) {.name = short_, .type = CLI_ALIAS, .arg = long_}
#define CLI_OPT_HEADING(text_) {.name = "", .type = CLI_HEADING, .help = text_}
#define CLI_OPT_END {.name = NULL}

struct cli {
    const char *prog;   /* "trk-tablegen amp": the usage line and every message */
    const char *usage;  /* after prog in the usage line (NULL: "[options]"); may hold '\n' */
    const char *about;  /* text before the options (NULL: none) */
    const struct cli_opt *opts;
    const struct cli_opt *common; /* a second table ("common options:"; NULL: none); an option
                                   * of opts with the same name shadows it */
    const char *after;  /* text after the options (NULL: none) */
    void (*more_help)(FILE *f); /* more help after `after` (NULL: none) */
    /* An argument that is no option: returns how many arguments it took (1,
     * or 2 with next; next is NULL after the last), 0 when it is not one of
     * the tool's (a usage error), or -1 with a message in err (a usage error). */
    int (*operand)(void *ctx, const char *arg, const char *next, char *err, size_t errlen);
    void *ctx;
};

#define CLI_RUN (-1)
/* Defaults, then argv[1..] into the options (argv[0]: the program or
 * command). CLI_RUN when the tool should run, else its exit status: 0 after
 * --help (-h), 2 after a one-line message on a usage error, 1 on an internal
 * error (a default its option refuses). */
int cli_parse(const struct cli *c, int argc, char **argv);

/* The generated help (what --help prints). */
void cli_usage(const struct cli *c, FILE *f);
/* The help lines of one table (options of `shadow` with the same name and
 * CLI_HIDDEN ones are left out). */
void cli_print_options(FILE *f, const struct cli_opt *t, const struct cli_opt *shadow);

/* "PROG: note: OLD is deprecated (accepted until the next release), use NEW"
 * on stderr: for the old forms operand hooks take. */
void cli_note_deprecated(const char *prog, const char *old_spelling, const char *new_spelling);

/* Value parsers of the table types: 0, or -1 (nothing stored). No blanks
 * around or inside a number; integers exact (strtol) or in exponent form
 * ("1e6"); doubles finite. */
int cli_parse_long(const char *s, long *v);
int cli_parse_double(const char *s, double *v);
/* "a,b,c" or "from:to:step" (step > 0, to >= from): the count (<= max), or
 * -1 for a malformed list or one with more than max values (refused, never
 * cut short). */
int cli_parse_list(const char *s, double *v, int max);
/* A value that is empty or only blanks? */
int cli_blank(const char *s);

/* Subcommands: `PROG COMMAND [options]` runs fn(argc - 1, argv + 1) (argv[0]
 * = the command's name). PROG --help, -h or help: head, the commands with
 * their summaries and more(f) on stdout, exit status 0; no command or an
 * unknown one: one line on stderr naming it (noun: "command", "experiment")
 * and the nearest command ("did you mean 'info'?"), exit status 2. */
struct cli_cmd {
    const char *name, *summary;
    int (*fn)(int argc, char **argv);
};
int cli_dispatch(const char *prog, const char *noun, const char *head, const struct cli_cmd *cmds,
                 void (*more)(FILE *f), int argc, char **argv);

/* After cli_catch_stop_signals(), SIGINT and SIGTERM no longer kill the
 * process: they set cli_stop_flag to 1 and cli_stop_signal to the signal's
 * number, for the main loop to finish cleanly. */
extern volatile sig_atomic_t cli_stop_flag, cli_stop_signal;
void cli_catch_stop_signals(void);

#endif
