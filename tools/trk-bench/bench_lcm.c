/* bench_lcm.c - trk-lcm-bridge throughput and added latency, with
 * 64 tracks and 256 detections per scan (64 targets always detected + 192
 * uniform clutter over 1200 m x 1200 m, the setting of scan_64x256):
 *   lcm_direct_64x256         ns per scan: trk_tracker_process_scan alone
 *   lcm_core_64x256           ns per scan: bridge_handle (decode 12.8 kB with
 *                             the fixed-size decoder, validate, copy, track,
 *                             fill and encode the 15 kB track list)
 *   lcm_memq_64x256           ns per scan through LCM memq://: publish the
 *                             scan, the bridge's subscription handles it and
 *                             publishes the track list, a consumer receives
 *                             and decodes it
 *   lcm_memq_64x256_rate      scans per second of the above
 *   lcm_memq_added_latency    lcm_memq - lcm_direct (ns per scan), and the
 *   lcm_core_added_latency    same for the core alone
 *   lcm_memq_64x256_vs_direct lcm_memq / lcm_direct: the baseline is the
 *                             tracker called directly
 *   lcm_replay_64x256_rate    scans per second of bridge_replay: LCM log of
 *                             the scans in, track log out (files in $TMPDIR)
 *   lcm_confirmed_tracks      confirmed tracks after the timed scans
 * Each figure is the best of 5 repetitions over 160 scans after 16 warm-up
 * scans (the replay figure includes its warm-up scans). On a shared machine
 * the differences of whole-scan figures are noisy; the parts the bridge adds
 * are also timed alone (bench_time_ns: batches of >= 20 ms, best of 7):
 *   lcm_part_decode_copy_256  ns: lcmc_scan_from_bytes of a 256-detection scan
 *   lcm_part_fill_encode_64   ns: lcmc_tracks_to_msg + encode, 64 tracks
 *   lcm_part_memq_transport   ns: memq publish + dispatch of one scan and one
 *                             track list (handlers do nothing)
 *   lcm_parts_added_latency   ns: their sum, the added latency per scan */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "transport.h"
#include "bench.h"
#include "lcm_log.h"
#include "scenario.h"

#define NT 64
#define NDET 256
#define WARM 16
#define NSCAN (WARM + 160)
#define REPS 5

struct lcm_job {
    struct trk_scan scan[NSCAN];
    struct trk_detection det[NSCAN][NDET];
    uint8_t bytes[NSCAN][LCMC_SCAN_WIRE_SIZE];
    trk_detection_scan_t msg;
    trk_track_list_t consumed;
    struct trk_tracker tk;
    struct tcfg cfg;
    struct bridge_opts opts;
    long n_consumed;
};

static void on_tracks(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    struct lcm_job *j = user;
    (void)channel;
    if (trk_track_list_t_decode(rbuf->data, 0, (int)rbuf->data_size, &j->consumed) > 0) j->n_consumed++;
}

static int prepare(struct lcm_job *j)
{
    struct scen_params p;
    struct scenario s;
    char err[256];
    scen_defaults(&p);
    p.seed = 42;
    p.n_targets = NT;
    p.clutter_count = NDET - NT;
    p.amp_kind = AMP_NONE;
    p.pd = 1;
    p.x_min_m = -100, p.x_max_m = 1100, p.y_min_m = -100, p.y_max_m = 1100;
    p.speed_min_mps = 1, p.speed_max_mps = 3;
    p.scan_period_s = 1;
    p.meas_sigma_m = 1;
    if (scen_init(&s, &p, err, sizeof err) != 0) return -1;
    for (int k = 0; k < NSCAN; k++) {
        scen_next(&s, j->det[k], NDET, &j->scan[k], NULL, NULL);
        if (lcmc_scan_to_msg(&j->scan[k], k, &j->msg) != LCMC_OK ||
            trk_detection_scan_t_encode(j->bytes[k], 0, LCMC_SCAN_WIRE_SIZE, &j->msg) != LCMC_SCAN_WIRE_SIZE) {
            scen_free(&s);
            return -1;
        }
    }
    scen_free(&s);
    /* the tracker of scan_64x256 */
    tcfg_defaults(&j->cfg);
    const char *set[][2] = {{"sensor.0.pd", "0.9"},
                            {"sensor.0.clutter_density_per_m2", "1.333e-4"},
                            {"process_noise_q", "0.01"},
                            {"confirm.mn.m", "2"},
                            {"confirm.mn.n", "3"}};
    for (size_t i = 0; i < sizeof set / sizeof set[0]; i++)
        if (tcfg_set(&j->cfg, set[i][0], set[i][1], err, sizeof err) != 0) return -1;
    bridge_opts_defaults(&j->opts);
    j->opts.quiet = 1;
    j->opts.status_period_s = 0;
    return 0;
}

static double per_scan(double t0) { return (bench_now_ns() - t0) / (NSCAN - WARM); }

static double run_direct(struct lcm_job *j)
{
    struct trk_tracker_params p;
    tcfg_params(&j->cfg, &p);
    if (trk_tracker_init(&j->tk, &p) != TRK_OK) return -1;
    double t0 = 0;
    for (int k = 0; k < NSCAN; k++) {
        if (k == WARM) t0 = bench_now_ns();
        if (trk_tracker_process_scan(&j->tk, &j->scan[k], NULL) != TRK_OK) return -1;
    }
    return per_scan(t0);
}

static double run_core(struct lcm_job *j)
{
    char err[256];
    struct bridge *b = bridge_new(&j->cfg, &j->opts, err, sizeof err);
    if (!b) return -1;
    double t0 = 0, sink = 0;
    for (int k = 0; k < NSCAN; k++) {
        const void *out;
        size_t len;
        if (k == WARM) t0 = bench_now_ns();
        if (bridge_handle(b, j->bytes[k], LCMC_SCAN_WIRE_SIZE, k, &out, &len) != LCMC_OK) {
            bridge_free(b);
            return -1;
        }
        sink += (double)((const uint8_t *)out)[len / 2];
    }
    const double r = per_scan(t0);
    bench_sink(sink);
    bridge_free(b);
    return r;
}

static double run_memq(struct lcm_job *j, int *n_confirmed)
{
    char err[256];
    lcm_t *lc = lcm_create("memq://");
    if (!lc) return -1;
    struct bridge *b = bridge_new(&j->cfg, &j->opts, err, sizeof err);
    struct bridge_live live;
    if (!b || bridge_live_attach(&live, lc, b) != 0) {
        bridge_free(b);
        lcm_destroy(lc);
        return -1;
    }
    lcm_subscription_t *sub = lcm_subscribe(lc, j->opts.track_channel, on_tracks, j);
    j->n_consumed = 0;
    double t0 = 0;
    int ok = sub != NULL;
    for (int k = 0; k < NSCAN && ok; k++) {
        if (k == WARM) t0 = bench_now_ns();
        ok = lcm_publish(lc, j->opts.detection_channel, j->bytes[k], LCMC_SCAN_WIRE_SIZE) == 0 &&
             lcm_handle_timeout(lc, 1000) > 0 && /* the bridge: scan -> tracks */
             lcm_handle_timeout(lc, 1000) > 0;   /* the consumer: tracks */
    }
    const double r = ok && j->n_consumed == NSCAN ? per_scan(t0) : -1;
    *n_confirmed = 0;
    for (int i = 0; i < j->consumed.n_tracks; i++)
        *n_confirmed += j->consumed.tracks[i].status == TRK_TRACK_T_STATUS_CONFIRMED;
    if (sub) lcm_unsubscribe(lc, sub);
    bridge_live_detach(&live);
    lcm_destroy(lc);
    bridge_free(b);
    return r;
}

static double run_replay(struct lcm_job *j, const char *in, const char *out)
{
    char err[256];
    struct bridge *b = bridge_new(&j->cfg, &j->opts, err, sizeof err);
    if (!b) return -1;
    struct replay_stats st;
    const double t0 = bench_now_ns();
    const int rc = bridge_replay(b, in, out, 0, NULL, &st, err, sizeof err);
    const double dt = bench_now_ns() - t0;
    const int ok = rc == 0 && b->c.processed == NSCAN;
    bridge_free(b);
    return ok ? (double)NSCAN / (dt * 1e-9) : -1;
}

static struct lcm_job *part_job;

static void part_decode(void *arg)
{
    struct lcmc_scan *out = arg;
    if (lcmc_scan_from_bytes(part_job->bytes[NSCAN - 1], LCMC_SCAN_WIRE_SIZE, 1, &part_job->msg, out,
                             NULL, 0) != LCMC_OK)
        bench_sink(1);
    bench_sink((double)out->det[5].x_m);
}

static uint8_t part_buf[1 << 15];
static void part_encode(void *arg)
{
    (void)arg;
    lcmc_tracks_to_msg(&part_job->tk, &part_job->scan[NSCAN - 1], 1, NULL, &part_job->consumed);
    bench_sink((double)trk_track_list_t_encode(part_buf, 0, (int)sizeof part_buf, &part_job->consumed));
}

static void on_nothing(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    (void)channel, (void)user;
    bench_sink((double)rbuf->data_size);
}

static void part_memq(void *arg)
{
    lcm_t *lc = arg;
    if (lcm_publish(lc, "SCAN", part_job->bytes[0], LCMC_SCAN_WIRE_SIZE) != 0 ||
        lcm_handle_timeout(lc, 1000) <= 0 ||
        lcm_publish(lc, "TRACKS", part_buf, (unsigned)trk_track_list_t_encoded_size(&part_job->consumed)) != 0 ||
        lcm_handle_timeout(lc, 1000) <= 0)
        bench_sink(1);
}

static void bench_parts(struct lcm_job *j)
{
    static struct lcmc_scan out;
    part_job = j;
    const double dec = bench_time_ns(part_decode, &out, 7);
    const double enc = bench_time_ns(part_encode, NULL, 7); /* j->tk holds 64 tracks (run_direct) */
    double mq = -1;
    lcm_t *lc = lcm_create("memq://");
    if (lc) {
        lcm_subscription_t *a = lcm_subscribe(lc, "SCAN", on_nothing, NULL);
        lcm_subscription_t *b = lcm_subscribe(lc, "TRACKS", on_nothing, NULL);
        if (a && b) mq = bench_time_ns(part_memq, lc, 7);
        if (a) lcm_unsubscribe(lc, a);
        if (b) lcm_unsubscribe(lc, b);
        lcm_destroy(lc);
    }
    bench_print("lcm_part_decode_copy_256", dec, "ns");
    bench_print("lcm_part_fill_encode_64", enc, "ns");
    bench_print("lcm_part_memq_transport", mq, "ns");
    bench_print("lcm_parts_added_latency", dec + enc + mq, "ns");
}

TRK_BENCH(lcm)
{
    if (TRK_MAX_TRACKS < NT || TRK_MAX_DETECTIONS < NDET) {
        bench_print("lcm_skipped_capacity", 0, "-");
        return;
    }
    struct lcm_job *j = calloc(1, sizeof *j);
    if (!j || prepare(j) != 0) {
        bench_print("lcm_setup_failed", 0, "-");
        free(j);
        return;
    }
    char in[256], out[256];
    const char *dir = getenv("TMPDIR");
    snprintf(in, sizeof in, "%s/trk_bench_lcm_%ld_in.lcmlog", dir ? dir : "/tmp", (long)getpid());
    snprintf(out, sizeof out, "%s/trk_bench_lcm_%ld_out.lcmlog", dir ? dir : "/tmp", (long)getpid());
    struct lcmlog_writer w;
    int log_ok = lcmlog_open_write(&w, in) == 0;
    for (int k = 0; log_ok && k < NSCAN; k++)
        log_ok = lcmlog_write(&w, j->scan[k].time_us, j->opts.detection_channel, j->bytes[k],
                              LCMC_SCAN_WIRE_SIZE) == 0;
    if (lcmlog_close_write(&w) != 0) log_ok = 0;

    double direct = 1e300, core = 1e300, memq = 1e300, replay = 0;
    int n_conf = 0;
    for (int r = 0; r < REPS; r++) {
        double v;
        if ((v = run_direct(j)) >= 0 && v < direct) direct = v;
        if ((v = run_core(j)) >= 0 && v < core) core = v;
        if ((v = run_memq(j, &n_conf)) >= 0 && v < memq) memq = v;
        if (log_ok && (v = run_replay(j, in, out)) > replay) replay = v;
    }
    remove(in);
    remove(out);
    bench_print("lcm_direct_64x256", direct, "ns");
    bench_print("lcm_core_64x256", core, "ns");
    bench_print("lcm_memq_64x256", memq, "ns");
    bench_print("lcm_memq_64x256_rate", 1e9 / memq, "scans/s");
    bench_print("lcm_memq_added_latency", memq - direct, "ns");
    bench_print("lcm_memq_64x256_vs_direct", memq / direct, "x");
    bench_print("lcm_core_added_latency", core - direct, "ns");
    bench_print("lcm_replay_64x256_rate", replay, "scans/s");
    bench_print("lcm_confirmed_tracks", n_conf, "tracks");
    if (run_direct(j) >= 0) bench_parts(j);
    free(j);
}
