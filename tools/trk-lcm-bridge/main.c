/* trk-lcm-bridge - LCM detection scans in, tracks out (see --help).
 *
 *   trk-lcm-bridge [options] [--set KEY=VALUE ...] live: subscribe, track, publish
 *   trk-lcm-bridge --replay IN --out OUT [options] offline: log in, log out
 *   trk-lcm-bridge --summarize LOG                 what a track log contains
 *
 * Exit status (docs/statuses.md, "Exit codes"): 0 normal end (also after
 * SIGINT/SIGTERM), 1 a runtime failure (LCM cannot be created or fails, a log
 * cannot be read or written; a replay that read no event prints no summary),
 * 2 bad usage or configuration (nothing was started). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bridge.h"
#include "cli.h"
#include "kvfile.h"
#include "suggest.h"
#include "summary.h"
#include "tracker_config.h"
#include "transport.h"

static void more_help(FILE *f)
{
    fprintf(f, "\n");
    tcfg_help(f);
    fprintf(f,
            "\nThe tracker is built for %d tracks and %d detections per scan (a larger scan is\n"
            "thinned to the most useful ones, never refused); the messages carry at most %d\n"
            "detections and %d tracks.\n",
            TRK_MAX_TRACKS, TRK_MAX_DETECTIONS, TRK_DETECTION_SCAN_T_MAX_DETECTIONS,
            TRK_TRACK_LIST_T_MAX_TRACKS);
}

struct settings {
    struct bridge_opts o;
    struct tcfg cfg;
};

/* A key of either table; an unknown one: 1, the nearest key of both in err. */
static int set_any(void *ctx, const char *key, const char *value, char *err, size_t n)
{
    struct settings *s = ctx;
    char near_bridge[256];
    int r = bridge_opts_set(&s->o, key, value, near_bridge, sizeof near_bridge);
    if (r <= 0) {
        snprintf(err, n, "%s", near_bridge);
        return r;
    }
    if ((r = tcfg_set(&s->cfg, key, value, err, n)) <= 0) return r;
    char near_tracker[256];
    snprintf(near_tracker, sizeof near_tracker, "%s", err);
    struct cli_near near;
    cli_near_init(&near, key);
    cli_near_add(&near, near_bridge);
    cli_near_add(&near, near_tracker);
    snprintf(err, n, "%s", near.best ? near.best : "");
    return 1;
}

/* The settings of the command line, applied after parsing: the --config
 * files first (in order), then every other setting in command-line order
 * (so the command line overrides the files). */
enum action_kind {
    A_FLAG,      /* a bridge flag (--tracks CH): bridge_opts_set(key, value) */
    A_SET,       /* --set KEY=VALUE (value) */
    A_OLD_PAIR,  /* old form --KEY VALUE (key, value) */
    A_OLD_JOINED /* old form --KEY=VALUE (value: KEY=VALUE) */
};

struct action {
    enum action_kind kind;
    const char *opt;   /* the option as given ("--tracks", "--set", "--term"): messages */
    const char *key;   /* A_FLAG, A_OLD_PAIR */
    const char *value;
};

struct plan {
    struct action *a;
    int n, cap;
    struct settings scratch; /* to tell known keys of old forms */
};

static int push(struct plan *pl, enum action_kind kind, const char *opt, const char *key, const char *value,
                char *err, size_t n)
{
    if (pl->n == pl->cap) {
        snprintf(err, n, "too many settings");
        return -1;
    }
    struct action ac = {kind, opt, key, value};
    pl->a[pl->n++] = ac;
    return 0;
}

/* The bridge's own flags and the config keys they set. */
struct flag_bind {
    struct plan *pl;
    const char *flag, *key;
};

static int bridge_flag(void *ctx, const char *v, char *err, size_t n)
{
    const struct flag_bind *b = ctx;
    return push(b->pl, A_FLAG, b->flag, b->key, v, err, n);
}

static int set_opt(void *ctx, const char *v, char *err, size_t n)
{
    return push(ctx, A_SET, "--set", NULL, v, err, n);
}

/* The old forms --KEY VALUE and --KEY=VALUE of a setting (deprecated). */
static int old_setting(void *ctx, const char *a, const char *next, char *err, size_t n)
{
    struct plan *pl = ctx;
    char key[KV_MAX_LINE], msg[512], old_s[KV_MAX_LINE + 64], new_s[KV_MAX_LINE + 64];
    if (strncmp(a, "--", 2) != 0 || !a[2]) return 0;
    const char *eq = strchr(a + 2, '=');
    if (!eq && !next) return 0;
    const size_t klen = eq ? (size_t)(eq - (a + 2)) : strlen(a + 2);
    if (klen >= sizeof key) return 0;
    memcpy(key, a + 2, klen);
    key[klen] = 0;
    /* a key of neither table: an unknown option (cli_parse says so, with the
     * nearest option), or a setting misspelled (the nearest key: msg) */
    if (set_any(&pl->scratch, key, eq ? eq + 1 : next, msg, sizeof msg) > 0) {
        if (!msg[0]) return 0;
        snprintf(err, n, "unknown option --%s; did you mean the setting '%s' (--set %s=VALUE)?", key, msg, msg);
        return -1;
    }
    if (eq) {
        snprintf(old_s, sizeof old_s, "%s", a);
        snprintf(new_s, sizeof new_s, "--set %s", a + 2);
    } else {
        snprintf(old_s, sizeof old_s, "%s %s", a, next);
        snprintf(new_s, sizeof new_s, "--set %s=%s", a + 2, next);
    }
    cli_note_deprecated("trk-lcm-bridge", old_s, new_s);
    if (push(pl, eq ? A_OLD_JOINED : A_OLD_PAIR, a, a + 2, eq ? a + 2 : next, err, n) != 0) return -1;
    return eq ? 1 : 2;
}

/* The plan into *s: 0, or -1 after a message. */
static int apply(struct settings *s, const char *const *configs, int n_configs, const struct plan *pl)
{
    char err[1024], kv[KV_MAX_LINE];
    for (int i = 0; i < n_configs; i++)
        if (kv_parse_file(configs[i], set_any, s, err, sizeof err) != 0) {
            fprintf(stderr, "trk-lcm-bridge: %s\n", err);
            return -1;
        }
    for (int i = 0; i < pl->n; i++) {
        const struct action *ac = &pl->a[i];
        int r = 0;
        switch (ac->kind) {
        case A_FLAG:
            if ((r = bridge_opts_set(&s->o, ac->key, ac->value, err, sizeof err)) != 0)
                fprintf(stderr, "trk-lcm-bridge: %s: %s\n", ac->opt, err);
            break;
        case A_SET:
            if ((r = kv_parse_assignment(ac->value, set_any, s, err, sizeof err)) != 0)
                fprintf(stderr, "trk-lcm-bridge: --set %s: %s\n", ac->value, err);
            break;
        case A_OLD_PAIR:
        case A_OLD_JOINED:
            if (ac->kind == A_OLD_PAIR) snprintf(kv, sizeof kv, "%s=%s", ac->key, ac->value);
            else snprintf(kv, sizeof kv, "%s", ac->value);
            if ((r = kv_parse_assignment(kv, set_any, s, err, sizeof err)) != 0)
                fprintf(stderr, "trk-lcm-bridge: %s: %s (see --help)\n", ac->opt, err);
            break;
        }
        if (r != 0) return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static struct settings s;
    static struct plan pl;
    char err[1024];
    const char *replay_in = NULL, *replay_out = NULL, *summarize = NULL;
    const char *truth_channel = "TRK_TRUTH";
    int keep_input = 0, print_config = 0, n_configs = 0;
    long max_scans = 0;
    double idle_exit_s = 0;

    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-lcm-bridge: libtrk was built with other capacities or real type\n");
        return 2;
    }
    bridge_opts_defaults(&s.o);
    tcfg_defaults(&s.cfg);
    bridge_opts_defaults(&pl.scratch.o);
    tcfg_defaults(&pl.scratch.cfg);
    const char **configs = malloc((size_t)argc * sizeof *configs);
    pl.a = malloc((size_t)argc * sizeof *pl.a);
    pl.cap = argc;
    if (!configs || !pl.a) {
        fprintf(stderr, "trk-lcm-bridge: out of memory\n");
        free(configs), free(pl.a);
        return 1;
    }
    struct flag_bind fb[] = {{&pl, "--lcm-url", "lcm_url"},
                             {&pl, "--detections", "detection_channel"},
                             {&pl, "--tracks", "track_channel"},
                             {&pl, "--status", "status_channel"},
                             {&pl, "--status-period-s", "status_period_s"},
                             {&pl, "--log-interval-s", "log_interval_s"},
                             {&pl, "--polar-detections", "polar_detection_channel"}};
    const struct cli_opt opts[] = {
        CLI_OPT_STRINGS("--config", configs, &n_configs, argc, "FILE",
                        "settings file, 'key = value' lines (any key below);\n"
                        "command-line settings override it (repeat for more files)"),
        CLI_OPT_CALL("--set", &pl, set_opt, "KEY=VALUE",
                     "any setting: a bridge key [in brackets] or a tracker key\n(below); repeat for more"),
        {.name = "--lcm-url", .type = CLI_CALL, .dst = &fb[0], .call = bridge_flag, .arg = "URL",
         .flags = CLI_EMPTY_OK,
         .help = "LCM provider [lcm_url] (default: $LCM_DEFAULT_URL,\n"
                 "else LCM's default udpm://239.255.76.67:7667?ttl=0)"},
        CLI_OPT_CALL("--detections", &fb[1], bridge_flag, "CH",
                     "detection channel [detection_channel] (TRK_DETECTIONS)"),
        {.name = "--polar-detections", .type = CLI_CALL, .dst = &fb[6], .call = bridge_flag, .arg = "CH",
         .flags = CLI_EMPTY_OK,
         .help = "polar detection channel (trk.detection_scan_polar_t), '' =\n"
                 "none [polar_detection_channel] (TRK_DETECTIONS_POLAR)"},
        CLI_OPT_CALL("--tracks", &fb[2], bridge_flag, "CH", "track channel [track_channel] (TRK_TRACKS)"),
        {.name = "--status", .type = CLI_CALL, .dst = &fb[3], .call = bridge_flag, .arg = "CH",
         .flags = CLI_EMPTY_OK, .help = "status channel, '' = none [status_channel] (TRK_BRIDGE_STATUS)"},
        CLI_OPT_CALL("--status-period-s", &fb[4], bridge_flag, "S",
                     "status every S seconds (log time in replay), 0 = only\n"
                     "at the end [status_period_s] (1)"),
        CLI_OPT_CALL("--log-interval-s", &fb[5], bridge_flag, "S",
                     "at most one message per rejection cause per S seconds\n[log_interval_s] (10)"),
        CLI_OPT_LONG("--max-scans", &max_scans, "N", NULL, CLI_IN, 0, 2000000000.0,
                     "live: stop after N accepted scans (0 = until a signal)"),
        CLI_OPT_DOUBLE("--idle-exit-s", &idle_exit_s, "S", NULL, CLI_GE, 0, 0,
                       "live: stop when nothing arrived for S seconds (0 = never)"),
        CLI_OPT_STRING("--replay", &replay_in, "IN",
                       NULL, "replay the LCM log IN (lcm-logger format) as fast as\n"
                             "possible and write the tracks to the log --out; same input,\n"
                             "byte-identical output"),
        CLI_OPT_STRING("--out", &replay_out, "OUT", NULL, "replay: the track log written"),
        CLI_OPT_FLAG("--keep-input", &keep_input, "replay: copy the input events to OUT as well"),
        CLI_OPT_STRING("--summarize", &summarize, "LOG", NULL, "print what a track log holds and exit"),
        {.name = "--truth", .type = CLI_STRING, .dst = &truth_channel, .arg = "CH", .flags = CLI_EMPTY_OK,
         .help = "summarize: truth channel of trk-sonar-sim (TRK_TRUTH)"},
        CLI_OPT_FLAG("--print-config", &print_config, "print the effective settings as a config file and exit"),
        CLI_OPT_FLAG("--quiet", &s.o.quiet, "no rejection messages (counts are kept)"),
        CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-lcm-bridge",
        .usage = "[options] [--set KEY=VALUE ...]\n"
                 "       trk-lcm-bridge --replay IN.lcmlog --out OUT.lcmlog [options]\n"
                 "       trk-lcm-bridge --summarize LOG.lcmlog [--tracks CH] [--status CH] [--truth CH]",
        .about = "\n"
                 "Subscribes to detection scans (trk.detection_scan_t, and the range/bearing scans\n"
                 "of polar sensors, trk.detection_scan_polar_t), runs the trk tracker and\n"
                 "publishes the track table (trk.track_list_t) after every accepted scan, plus a\n"
                 "status message (trk.bridge_status_t). Bad messages are rejected, counted and\n"
                 "logged (once per cause, then at most every log_interval_s); the next scan is\n"
                 "processed normally. SIGINT/SIGTERM stop it cleanly with a summary.\n",
        .opts = opts,
        .after = "deprecated spellings (accepted until the next release, with a note on stderr):\n"
                 "  --KEY VALUE, --KEY=VALUE  use --set KEY=VALUE (any setting, e.g. --term page:\n"
                 "                      --set term=page)",
        .more_help = more_help,
        .operand = old_setting,
        .ctx = &pl};
    int parsed = cli_parse(&cli, argc, argv);
    if (parsed == CLI_RUN && apply(&s, configs, n_configs, &pl) != 0) parsed = 2;
    free(configs);
    free(pl.a);
    if (parsed != CLI_RUN) return parsed;

    if (summarize) return bridge_summarize(summarize, &s.o, truth_channel, stdout) == 0 ? 0 : 1;
    if (print_config) {
        bridge_opts_write(stdout, &s.o);
        tcfg_write(stdout, &s.cfg);
        return 0;
    }
    if ((replay_in != NULL) != (replay_out != NULL)) {
        fprintf(stderr, "trk-lcm-bridge: --replay and --out go together\n");
        return 2;
    }

    struct bridge *b = bridge_new(&s.cfg, &s.o, err, sizeof err);
    if (!b) {
        fprintf(stderr, "trk-lcm-bridge: bad configuration: %s\n", err);
        return 2;
    }

    cli_catch_stop_signals();

    int rc = 0;
    const int64_t t0 = bridge_mono_us();
    if (replay_in) {
        struct replay_stats st;
        if (bridge_replay(b, replay_in, replay_out, keep_input, &cli_stop_flag, &st, err, sizeof err) != 0) {
            fprintf(stderr, "trk-lcm-bridge: %s\n", err);
            rc = 1;
            if (st.events == 0) { /* nothing replayed (no input, no log, no output): no summary of nothing */
                bridge_free(b);
                return rc;
            }
        }
        const double el = (double)(bridge_mono_us() - t0) * 1e-6;
        printf("trk-lcm-bridge: replay %s -> %s: %llu events, %llu on %s%s%s, %llu written",
               replay_in, replay_out, (unsigned long long)st.events, (unsigned long long)st.scans,
               s.o.detection_channel, s.o.polar_detection_channel[0] ? " and " : "", s.o.polar_detection_channel,
               (unsigned long long)st.written);
        if (st.corrupt || st.truncated)
            printf(" (input: %llu corrupt records skipped%s)", (unsigned long long)st.corrupt,
                   st.truncated ? ", truncated at the end" : "");
        printf("; %.3f s, %.0f scans/s%s\n", el, el > 0 ? (double)st.scans / el : 0.0,
               cli_stop_flag ? " (interrupted)" : "");
    } else {
        lcm_t *lc = lcm_create(s.o.lcm_url[0] ? s.o.lcm_url : NULL);
        if (!lc) {
            fprintf(stderr,
                    "trk-lcm-bridge: cannot create LCM for '%s' (udpm needs a multicast route, "
                    "e.g. ip route add 224.0.0.0/4 dev lo)\n",
                    s.o.lcm_url[0] ? s.o.lcm_url : getenv("LCM_DEFAULT_URL") ? getenv("LCM_DEFAULT_URL")
                                                                             : "LCM default");
            bridge_free(b);
            return 1;
        }
        struct bridge_live l;
        if (bridge_live_attach(&l, lc, b) != 0) {
            fprintf(stderr, "trk-lcm-bridge: cannot subscribe to %s\n", s.o.detection_channel);
            lcm_destroy(lc);
            bridge_free(b);
            return 1;
        }
        if (!s.o.quiet)
            fprintf(stderr, "trk-lcm-bridge: %s%s%s -> tracker (%d tracks, %d detections) -> %s%s%s\n",
                    s.o.detection_channel, s.o.polar_detection_channel[0] ? ", " : "",
                    s.o.polar_detection_channel, TRK_MAX_TRACKS, TRK_MAX_DETECTIONS, s.o.track_channel,
                    s.o.status_channel[0] ? ", status on " : "", s.o.status_channel);
        if (bridge_live_run(&l, &cli_stop_flag, (uint64_t)max_scans, idle_exit_s) != 0) {
            fprintf(stderr, "trk-lcm-bridge: LCM error while handling messages\n");
            rc = 1;
        }
        bridge_live_detach(&l);
        lcm_destroy(lc);
        const double el = (double)(bridge_mono_us() - t0) * 1e-6;
        printf("trk-lcm-bridge: stopped%s after %.1f s\n",
               cli_stop_signal == SIGINT    ? " by SIGINT"
               : cli_stop_signal == SIGTERM ? " by SIGTERM"
                                        : "",
               el);
    }
    bridge_summary(b, stdout);
    fflush(stdout);
    bridge_free(b);
    return rc;
}
