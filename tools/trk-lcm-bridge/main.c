/* trk-lcm-bridge - LCM detection scans in, tracks out (see --help).
 *
 *   trk-lcm-bridge [options]                       live: subscribe, track, publish
 *   trk-lcm-bridge --replay IN --out OUT [options] offline: log in, log out
 *   trk-lcm-bridge --summarize LOG                 what a track log contains
 *
 * Exit status: 0 normal end (also after SIGINT/SIGTERM), 1 a runtime failure
 * (LCM cannot be created or fails, a log cannot be read or written), 2 bad
 * usage or configuration (nothing was started). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bridge.h"
#include "cli.h"
#include "kvfile.h"
#include "transport.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: trk-lcm-bridge [options] [--KEY VALUE ...]\n"
            "       trk-lcm-bridge --replay IN.lcmlog --out OUT.lcmlog [options]\n"
            "       trk-lcm-bridge --summarize LOG.lcmlog [--tracks CH] [--status CH] [--truth CH]\n"
            "\n"
            "Subscribes to detection scans (trk.detection_scan_t), runs the trk tracker and\n"
            "publishes the track table (trk.track_list_t) after every accepted scan, plus a\n"
            "status message (trk.bridge_status_t). Bad messages are rejected, counted and\n"
            "logged (once per cause, then at most every log_interval_s); the next scan is\n"
            "processed normally. SIGINT/SIGTERM stop it cleanly with a summary.\n"
            "\n"
            "Options:\n"
            "  --config FILE          settings file, 'key = value' lines (any key below);\n"
            "                         command-line settings override it\n"
            "  --lcm-url URL          LCM provider [lcm_url] (default: $LCM_DEFAULT_URL,\n"
            "                         else LCM's default udpm://239.255.76.67:7667?ttl=0)\n"
            "  --detections CH        detection channel [detection_channel] (TRK_DETECTIONS)\n"
            "  --tracks CH            track channel [track_channel] (TRK_TRACKS)\n"
            "  --status CH            status channel, '' = none [status_channel] (TRK_BRIDGE_STATUS)\n"
            "  --status-period-s S    status every S seconds (log time in replay), 0 = only\n"
            "                         at the end [status_period_s] (1)\n"
            "  --log-interval-s S     at most one message per rejection cause per S seconds\n"
            "                         [log_interval_s] (10)\n"
            "  --max-scans N          live: stop after N accepted scans (0 = until a signal)\n"
            "  --idle-exit-s S        live: stop when nothing arrived for S seconds (0 = never)\n"
            "  --replay IN --out OUT  replay the LCM log IN (lcm-logger format) as fast as\n"
            "                         possible and write the tracks to the log OUT; same input,\n"
            "                         byte-identical output\n"
            "  --keep-input           replay: copy the input events to OUT as well\n"
            "  --summarize LOG        print what a track log holds and exit\n"
            "  --truth CH             summarize: truth channel of trk-sonar-sim (TRK_TRUTH)\n"
            "  --print-config         print the effective settings as a config file and exit\n"
            "  --quiet                no rejection messages (counts are kept)\n"
            "  --KEY VALUE, --KEY=VALUE, --set KEY=VALUE   any setting (bridge or tracker)\n"
            "  --help\n"
            "\n");
    tcfg_help(f);
    fprintf(f,
            "\nThe tracker is built for %d tracks and %d detections per scan; the messages\n"
            "carry at most %d detections and %d tracks.\n",
            TRK_MAX_TRACKS, TRK_MAX_DETECTIONS, TRK_DETECTION_SCAN_T_MAX_DETECTIONS,
            TRK_TRACK_LIST_T_MAX_TRACKS);
}

struct settings {
    struct bridge_opts o;
    struct tcfg cfg;
};

static int set_any(void *ctx, const char *key, const char *value, char *err, size_t n)
{
    struct settings *s = ctx;
    int r = bridge_opts_set(&s->o, key, value, err, n);
    return r <= 0 ? r : tcfg_set(&s->cfg, key, value, err, n);
}

/* --name VALUE or --name=VALUE (cli.h): 1 matched (*val set), -1 missing value, 0 no */
static int opt(int argc, char **argv, int *i, const char *name, const char **val)
{
    return cli_opt(argc, argv, i, name, val, "trk-lcm-bridge");
}

/* The bridge's own flags and the config keys they set. */
static const struct {
    const char *flag, *key;
} BRIDGE_FLAGS[] = {{"--lcm-url", "lcm_url"},
                    {"--detections", "detection_channel"},
                    {"--tracks", "track_channel"},
                    {"--status", "status_channel"},
                    {"--status-period-s", "status_period_s"},
                    {"--log-interval-s", "log_interval_s"}};

static int bridge_flag(int argc, char **argv, int *i, const char **val, const char **key)
{
    for (size_t f = 0; f < sizeof BRIDGE_FLAGS / sizeof BRIDGE_FLAGS[0]; f++) {
        int k = opt(argc, argv, i, BRIDGE_FLAGS[f].flag, val);
        if (k != 0) {
            *key = BRIDGE_FLAGS[f].key;
            return k;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    static struct settings s;
    char err[1024];
    const char *replay_in = NULL, *replay_out = NULL, *summarize = NULL, *v;
    const char *truth_channel = "TRK_TRUTH";
    int keep_input = 0, print_config = 0;
    long max_scans = 0;
    double idle_exit_s = 0;

    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-lcm-bridge: libtrk was built with other capacities or real type\n");
        return 2;
    }
    bridge_opts_defaults(&s.o);
    tcfg_defaults(&s.cfg);

    /* pass 1: help and the config file (command-line settings override it) */
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        }
        int k = opt(argc, argv, &i, "--config", &v);
        if (k < 0) return 2;
        if (k > 0 && kv_parse_file(v, set_any, &s, err, sizeof err) != 0) {
            fprintf(stderr, "trk-lcm-bridge: %s\n", err);
            return 2;
        }
    }
    /* pass 2: everything else, in order */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int k;
        const char *key;
        char kv[KV_MAX_LINE];
#define OPT(name) ((k = opt(argc, argv, &i, name, &v)) != 0)
        if (OPT("--config")) {
            if (k < 0) return 2;
        } else if ((k = bridge_flag(argc, argv, &i, &v, &key)) != 0) {
            if (k < 0) return 2;
            if (bridge_opts_set(&s.o, key, v, err, sizeof err) != 0) {
                fprintf(stderr, "trk-lcm-bridge: %s: %s\n", a, err);
                return 2;
            }
        } else if (OPT("--max-scans")) {
            if (k < 0 || kv_parse_long(v, 0, 2000000000L, &max_scans) != 0) {
                fprintf(stderr, "trk-lcm-bridge: --max-scans needs a count >= 0\n");
                return 2;
            }
        } else if (OPT("--idle-exit-s")) {
            if (k < 0 || kv_parse_double(v, &idle_exit_s) != 0 || idle_exit_s < 0) {
                fprintf(stderr, "trk-lcm-bridge: --idle-exit-s needs seconds >= 0\n");
                return 2;
            }
        } else if (OPT("--replay")) {
            if (k < 0) return 2;
            replay_in = v;
        } else if (OPT("--out")) {
            if (k < 0) return 2;
            replay_out = v;
        } else if (OPT("--summarize")) {
            if (k < 0) return 2;
            summarize = v;
        } else if (OPT("--truth")) {
            if (k < 0) return 2;
            truth_channel = v;
        } else if (OPT("--set")) {
            if (k < 0) return 2;
            if (kv_parse_assignment(v, set_any, &s, err, sizeof err) != 0) {
                fprintf(stderr, "trk-lcm-bridge: --set %s: %s\n", v, err);
                return 2;
            }
        } else if (strcmp(a, "--keep-input") == 0) {
            keep_input = 1;
        } else if (strcmp(a, "--print-config") == 0) {
            print_config = 1;
        } else if (strcmp(a, "--quiet") == 0) {
            s.o.quiet = 1;
        } else if (strncmp(a, "--", 2) == 0 && a[2]) {
            /* --KEY=VALUE or --KEY VALUE for any setting */
            const char *eq = strchr(a + 2, '=');
            if (eq) snprintf(kv, sizeof kv, "%s", a + 2);
            else if (i + 1 < argc) snprintf(kv, sizeof kv, "%s=%s", a + 2, argv[++i]);
            else {
                fprintf(stderr, "trk-lcm-bridge: unknown option %s (see --help)\n", a);
                return 2;
            }
            if (kv_parse_assignment(kv, set_any, &s, err, sizeof err) != 0) {
                fprintf(stderr, "trk-lcm-bridge: %s: %s (see --help)\n", a, err);
                return 2;
            }
        } else {
            fprintf(stderr, "trk-lcm-bridge: unexpected argument '%s' (see --help)\n", a);
            return 2;
        }
#undef OPT
    }

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
        }
        const double el = (double)(bridge_mono_us() - t0) * 1e-6;
        printf("trk-lcm-bridge: replay %s -> %s: %llu events, %llu on %s, %llu written",
               replay_in, replay_out, (unsigned long long)st.events, (unsigned long long)st.scans,
               s.o.detection_channel, (unsigned long long)st.written);
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
            fprintf(stderr, "trk-lcm-bridge: %s -> tracker (%d tracks, %d detections) -> %s%s%s\n",
                    s.o.detection_channel, TRK_MAX_TRACKS, TRK_MAX_DETECTIONS, s.o.track_channel,
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
