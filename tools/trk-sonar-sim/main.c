/* trk-sonar-sim - a simulated sonar: publishes a seeded scenario
 * (tools/sim/scenario.h) as trk.detection_scan_t messages over LCM (or,
 * with --polar, as trk.detection_scan_polar_t from a moving platform:
 * platform.h), or
 * writes them to an LCM log file (--out), so the whole chain sonar -> trk-lcm-bridge
 * -> consumers can run without hardware. See --help.
 *
 * Exit status: 0 done (also after SIGINT/SIGTERM), 1 LCM or file failure,
 * 2 bad usage. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <time.h>

#include <lcm/lcm.h>

#include "cli.h"
#include "kvfile.h"
#include "lcm_copy.h"
#include "lcm_log.h"
#include "platform.h"
#include "scenario.h"
#include "tracker_config.h"

#define MAX_TARGETS_CLI 256

static int64_t wall_us(void)
{
    struct timeval tv;
    gettimeofday(&tv, NULL);
    return (int64_t)tv.tv_sec * 1000000 + tv.tv_usec;
}

/* One output: LCM or log file. */
struct sink {
    lcm_t *lc;
    struct lcmlog_writer w;
    int is_log;
    uint64_t errors;
};

static int sink_send(struct sink *k, int64_t ts, const char *ch, const void *buf, size_t len)
{
    int rc = k->is_log ? lcmlog_write(&k->w, ts, ch, buf, len)
                       : lcm_publish(k->lc, ch, buf, (unsigned)len);
    if (rc != 0) k->errors++;
    return rc;
}

/* Encode a (possibly corrupted) scan message; returns its length. */
static size_t encode_scan(const trk_detection_scan_t *m, uint8_t *buf, size_t cap)
{
    int n = trk_detection_scan_t_encode(buf, 0, (int)cap, m);
    return n > 0 ? (size_t)n : 0;
}

static size_t encode_polar(const trk_detection_scan_polar_t *m, uint8_t *buf, size_t cap)
{
    int n = trk_detection_scan_polar_t_encode(buf, 0, (int)cap, m);
    return n > 0 ? (size_t)n : 0;
}

/* The k-th malformed polar message: the causes of make_bad, then a pose
 * that is not finite and a detection at range 0 (dropped alone). */
static size_t make_bad_polar(unsigned k, const trk_detection_scan_polar_t *good, trk_detection_scan_polar_t *m,
                             uint8_t *buf, size_t cap, struct rng *r)
{
    *m = *good;
    switch (k % 8) {
    case 0: return encode_polar(m, buf, cap) - 100;
    case 1: m->n_detections = 100000; break;
    case 2: m->utime = INT64_MAX; break;
    case 3: m->utime = good->utime - 1000000; break;
    case 4: m->sensor_id = 99; break;
    case 5:
        m->has_pose = 1;
        m->pose_heading_rad = NAN;
        break;
    case 6: /* a later scan with one bad detection among good ones */
        m->utime = good->utime + 1;
        m->n_detections = 1;
        memset(&m->detections[0], 0, sizeof m->detections[0]);
        break;
    default:
        for (size_t i = 0; i < 64; i++) buf[i] = (uint8_t)rng_u32(r);
        return 64;
    }
    return encode_polar(m, buf, cap);
}

/* The k-th malformed message (k cycles through the causes). */
static size_t make_bad(unsigned k, const trk_detection_scan_t *good, trk_detection_scan_t *m,
                       uint8_t *buf, size_t cap, struct rng *r)
{
    *m = *good;
    switch (k % 6) {
    case 0: return encode_scan(m, buf, cap) - 100; /* truncated */
    case 1: m->n_detections = 100000; break;       /* count above the maximum */
    case 2: m->utime = INT64_MAX; break;             /* beyond the time range (a NaN
                                                        detection would drop alone) */
    case 3: m->utime = good->utime - 1000000; break; /* before the scan just sent */
    case 4: m->sensor_id = 99; break;                /* unknown sensor */
    default:                                         /* garbage */
        for (size_t i = 0; i < 64; i++) buf[i] = (uint8_t)rng_u32(r);
        return 64;
    }
    return encode_scan(m, buf, cap);
}

static void truth_msg(const struct scenario *sc, int64_t utime, int64_t seq, trk_track_list_t *m)
{
    memset(m, 0, sizeof *m);
    m->utime = utime;
    m->sensor_id = (int32_t)sc->p.sensor_id;
    m->seq = seq;
    size_t n = sc->n_tg < TRK_TRACK_LIST_T_MAX_TRACKS ? sc->n_tg : TRK_TRACK_LIST_T_MAX_TRACKS;
    for (size_t i = 0; i < n; i++) {
        trk_track_t *t = &m->tracks[i];
        t->id = (int64_t)i + 1;
        t->status = TRK_TRACK_T_STATUS_CONFIRMED;
        t->utime = utime;
        for (int k = 0; k < 4; k++) t->x[k] = sc->tg[i].x[k];
    }
    m->n_tracks = (int32_t)n;
    m->n_omitted = (int32_t)(sc->n_tg - n);
}

static void print_amplitude_config(const struct scenario *sc, int profile, const char *k_table, FILE *f);

/* --print-bridge-config: the trk-lcm-bridge settings that match this
 * scenario (a config file for `trk-lcm-bridge --config`): the sensor's P_D
 * (the amplitude model's at the threshold, or --pd), its position noise, the
 * clutter density it produces and the targets' process noise. A bridge left
 * at its own defaults (P_D 0.9, 1 m, 1e-4 per m^2) tracks this sonar's
 * detections with the wrong model. */
static void print_bridge_config(const struct scenario *sc, int polar, int profile, const char *k_table, FILE *f)
{
    const struct scen_params *p = &sc->p;
    const double area = (p->x_max_m - p->x_min_m) * (p->y_max_m - p->y_min_m);
    const double density = p->clutter_count >= 0 ? (double)p->clutter_count / area : p->clutter_density_per_m2;
    double pd_sum = 0, pd_min = 1, pd_max = 0;
    for (size_t i = 0; i < sc->n_tg; i++) {
        pd_sum += sc->tg[i].pd;
        pd_min = fmin(pd_min, sc->tg[i].pd);
        pd_max = fmax(pd_max, sc->tg[i].pd);
    }
    const double pd = sc->n_tg ? pd_sum / (double)sc->n_tg : p->pd;
    const unsigned s = p->sensor_id;
    fprintf(f, "# trk-lcm-bridge settings matching trk-sonar-sim's scenario (trk-sonar-sim\n"
               "# --print-bridge-config with the same scenario options)\n");
    if (s > 0) fprintf(f, "sensors = %u\n", s + 1);
    fprintf(f, "process_noise_q = %.9g\n", p->process_noise_q);
    if (sc->n_tg && pd_min != pd_max)
        fprintf(f, "# the targets' P_D range from %.6g to %.6g: their mean\n", pd_min, pd_max);
    if (p->amp_kind != AMP_NONE)
        fprintf(f, "# P_D of the %s amplitude model at the threshold (pfa %g)\n", amp_kind_name(p->amp_kind),
                p->pfa);
    fprintf(f, "sensor.%u.pd = %.6g\n", s, pd);
    if (!polar) fprintf(f, "sensor.%u.meas_sigma_m = %.9g\n", s, p->meas_sigma_m); /* polar: sigma_* below */
    fprintf(f, "# clutter: %s over the region %g..%g x %g..%g m\n",
            p->clutter_count >= 0 ? "a fixed count per scan" : "Poisson", p->x_min_m, p->x_max_m, p->y_min_m,
            p->y_max_m);
    fprintf(f, "sensor.%u.clutter_density_per_m2 = %.9g\n", s, density);
    print_amplitude_config(sc, profile, k_table, f);
}

/* The amplitude part of --print-bridge-config: the model the detections
 * carry, so that the bridge runs the amplitude-aided update (PDAFAI) with
 * it: Rayleigh in closed form (pfa, the targets' SNR; with a P_D profile
 * the library reads the profile as the SNR over range, and the simulator
 * draws each target's amplitude at the SNR of its P_D there); K through a
 * table the bridge reads (amp_table FILE, made once by trk-tablegen amp with
 * the command the comment gives); the simulator's own table as it is. A
 * table with a P_D profile has no SNR over range in the library: positions
 * only, said in a comment. */
static void print_amplitude_config(const struct scenario *sc, int profile, const char *k_table, FILE *f)
{
    const struct scen_params *p = &sc->p;
    const unsigned s = p->sensor_id;
    if (p->amp_kind == AMP_NONE) return;
    if (profile && p->amp_kind != AMP_RAYLEIGH) {
        fprintf(f, "# the detections carry %s amplitudes, but with a P_D profile only a Rayleigh\n"
                   "# model has an SNR over range in the library: positions only\n",
                p->amp_kind == AMP_K ? "K" : "table");
        return;
    }
    int same = 1;
    for (size_t i = 1; i < sc->n_tg; i++) same &= sc->tg[i].amp.snr_db == sc->tg[0].amp.snr_db;
    if (!same && p->amp_kind != AMP_TABLE)
        fprintf(f, "# the targets' SNR differ: the bridge takes the scenario's %g dB for all\n", p->snr_db);
    switch (p->amp_kind) {
    case AMP_RAYLEIGH:
        fprintf(f, "# the detections carry Rayleigh amplitudes: the amplitude-aided update%s\n",
                profile ? " (the targets'\n# SNR over range: the P_D profile's)" : "");
        fprintf(f, "sensor.%u.amplitude = rayleigh\n", s);
        fprintf(f, "sensor.%u.snr_db = %.9g\n", s, p->snr_db);
        fprintf(f, "sensor.%u.pfa = %.9g\n", s, p->pfa);
        break;
    case AMP_K:
        fprintf(f, "# the detections carry K amplitudes: the amplitude-aided update reads their\n"
                   "# table, made once with\n"
                   "#   trk-tablegen amp --clutter-model k --k-shape %.9g --snr-db %.9g --pfa %.9g --out %s\n",
                p->k_shape, p->snr_db, p->pfa, k_table);
        fprintf(f, "sensor.%u.amp_table = %s\n", s, k_table);
        break;
    default: /* AMP_TABLE */
        fprintf(f, "# the detections' amplitudes come from this table: the bridge reads the same\n");
        fprintf(f, "sensor.%u.amp_table = %s\n", s, p->amp_table);
        break;
    }
}

/* --print-bridge-config --polar: the same for a polar sensor: its kind and
 * noise, P_D (flat, or the profile the simulator draws with), coverage and
 * the clutter density inside it. The pose comes with every scan. */
static void print_polar_bridge_config(const struct scenario *sc, const struct trk_sensor_params *sp,
                                      const struct polar_platform *pf, const char *k_table, FILE *f)
{
    const unsigned s = sc->p.sensor_id;
    print_bridge_config(sc, 1, sp->pd_profile.n > 0, k_table, f);
    fprintf(f, "# polar: range and bearing from the platform's pose, which every scan carries\n"
               "# (start %g, %g m, course %g rad, %g m/s); clutter at the density above inside\n"
               "# the coverage\n",
            pf->x_m, pf->y_m, pf->course_rad, pf->speed_mps);
    fprintf(f, "sensor.%u.kind = polar\n", s);
    fprintf(f, "sensor.%u.sigma_range_m = %.9g\n", s, (double)sp->sigma_range_m);
    fprintf(f, "sensor.%u.sigma_bearing_rad = %.9g\n", s, (double)sp->sigma_bearing_rad);
    fprintf(f, "sensor.%u.conversion = first_order\n", s);
    if (sp->pd_profile.n) {
        fprintf(f, "sensor.%u.pd_profile = ", s);
        for (unsigned i = 0; i < sp->pd_profile.n; i++)
            fprintf(f, "%s%.9g:%.9g", i ? ", " : "", (double)sp->pd_profile.range_m[i], (double)sp->pd_profile.pd[i]);
        fputc('\n', f);
    }
    fprintf(f, "sensor.%u.coverage.min_range_m = %.9g\n", s, (double)sp->coverage.min_range_m);
    fprintf(f, "sensor.%u.coverage.max_range_m = %.9g\n", s, (double)sp->coverage.max_range_m);
    fprintf(f, "sensor.%u.coverage.half_width_rad = %.9g\n", s, (double)sp->coverage.half_width_rad);
}

/* A polar sensor's option through the tracker configuration's key (one
 * parser and one set of range checks for the simulator and the bridge). */
struct sensor_opt {
    struct tcfg *cfg;
    const char *key;        /* after "sensor.0." */
};

static int set_sensor_opt(void *ctx, const char *v, char *err, size_t errlen)
{
    const struct sensor_opt *o = ctx;
    char key[64];
    snprintf(key, sizeof key, "sensor.0.%s", o->key);
    return tcfg_set(o->cfg, key, v, err, errlen) == 0 ? 0 : -1;
}

/* --coverage MIN_M,MAX_M,HALF_WIDTH_RAD: the three coverage keys. */
static int set_coverage(void *ctx, const char *v, char *err, size_t errlen)
{
    struct tcfg *c = ctx;
    static const char *const keys[3] = {"sensor.0.coverage.min_range_m", "sensor.0.coverage.max_range_m",
                                        "sensor.0.coverage.half_width_rad"};
    double d[3];
    if (kv_parse_doubles(v, d, 3) != 0) {
        snprintf(err, errlen, "needs MIN_RANGE_M,MAX_RANGE_M,HALF_WIDTH_RAD");
        return -1;
    }
    for (int i = 0; i < 3; i++) {
        char num[40];
        snprintf(num, sizeof num, "%.17g", d[i]);
        if (tcfg_set(c, keys[i], num, err, errlen) != 0) return -1;
    }
    return 0;
}

/* --target X,Y,VX,VY[,SNR_DB], repeated. */
struct targets {
    struct scen_target_init t[MAX_TARGETS_CLI];
    size_t n;
};

static int add_target(void *ctx, const char *v, char *err, size_t errlen)
{
    struct targets *tg = ctx;
    double d[5];
    if (tg->n == MAX_TARGETS_CLI) {
        snprintf(err, errlen, "more than %d targets", MAX_TARGETS_CLI);
        return -1;
    }
    d[4] = NAN;
    if (cli_blank(v) || (kv_parse_doubles(v, d, 4) != 0 && kv_parse_doubles(v, d, 5) != 0)) {
        snprintf(err, errlen, "needs X,Y,VX,VY[,SNR_DB]");
        return -1;
    }
    struct scen_target_init t = {d[0], d[1], d[2], d[3], d[4]};
    tg->t[tg->n++] = t;
    return 0;
}

/* --amp-table FILE: amplitudes from a table (replaces --clutter-model). */
struct amp_table_opt {
    struct scen_params *p;
};

static int set_amp_table(void *ctx, const char *v, char *err, size_t errlen)
{
    struct amp_table_opt *a = ctx;
    (void)err, (void)errlen;
    a->p->amp_table = v;
    a->p->amp_kind = AMP_TABLE;
    return 0;
}

int main(int argc, char **argv)
{
    struct scen_params p;
    static struct targets tgt;
    const char *url = NULL, *log_path = NULL, *channel = "TRK_DETECTIONS", *truth_channel = "TRK_TRUTH";
    const char *bridge_amp_table = "sonar.amp";
    double rate_hz = -1, pd = NAN, speed[2], region[4];
    long scans = -1, bad_every = 0, seed, sensor_id, n_targets;
    long start_utime_l = -1;
    int quiet = 0, have_pd = 0, print_config = 0, polar = 0;
    const char *polar_channel = "TRK_DETECTIONS_POLAR";
    double platform[4] = {1000, 1000, 0, 0};
    static struct tcfg pcfg; /* the polar sensor's keys (sensor 0 of it) */
    char err[512];

    scen_defaults(&p);
    tcfg_defaults(&pcfg);
    pcfg.params.sensor[0].kind = TRK_SENSOR_POLAR;
    pcfg.params.sensor[0].sigma_range_m = 3;
    pcfg.params.sensor[0].sigma_bearing_rad = TRK_REAL_C(0.005);
    struct sensor_opt so_sr = {&pcfg, "sigma_range_m"}, so_sb = {&pcfg, "sigma_bearing_rad"},
                      so_prof = {&pcfg, "pd_profile"};
    seed = (long)p.seed;
    sensor_id = (long)p.sensor_id;
    n_targets = (long)p.n_targets;
    speed[0] = p.speed_min_mps, speed[1] = p.speed_max_mps;
    region[0] = p.x_min_m, region[1] = p.x_max_m, region[2] = p.y_min_m, region[3] = p.y_max_m;
    struct amp_table_opt amp_table = {&p};
    static const int amp_kinds[] = {AMP_NONE, AMP_RAYLEIGH, AMP_K};
    const struct cli_opt opts[] = {
        CLI_OPT_HEADING("Output:"),
        CLI_OPT_STRING("--lcm-url", &url, "URL", NULL, "LCM provider (default: $LCM_DEFAULT_URL, else LCM's default)"),
        CLI_OPT_STRING("--out", &log_path, "FILE",
                       NULL, "write an LCM log file instead of publishing (event time =\n"
                             "scan time; byte-identical for the same options)"),
        CLI_OPT_STRING("--channel", &channel, "CH", NULL, "detection channel (TRK_DETECTIONS)"),
        {.name = "--truth-channel", .type = CLI_STRING, .dst = &truth_channel, .arg = "CH", .flags = CLI_EMPTY_OK,
         .help = "truth channel, '' = none (TRK_TRUTH)"},
        CLI_OPT_DOUBLE("--rate-hz", &rate_hz, "R", NULL, CLI_GE, 0, 0,
                       "live: scans per second of wall clock (default 1/scan period;\n0 = as fast as possible)"),
        CLI_OPT_LONG("--scans", &scans, "N", NULL, CLI_IN, 0, 2000000000.0,
                     "number of scans, 0 = until SIGINT (live default 0, --out 100)"),
        CLI_OPT_LONG("--start-utime", &start_utime_l, "US", NULL, CLI_IN, 0, 9e18,
                     "time of the first scan (live: now; --out: 1700000000000000)"),
        CLI_OPT_LONG("--bad-every", &bad_every, "N", NULL, CLI_IN, 0, 2000000000.0,
                     "after every N-th scan also send one malformed message,\n"
                     "cycling: truncated, count too large, utime out of range,\n"
                     "time going backwards, unknown sensor, garbage (0 = never)"),
        CLI_OPT_FLAG("--quiet", &quiet, "no start-up line on stderr"),
        CLI_OPT_FLAG("--print-bridge-config", &print_config,
                     "print the trk-lcm-bridge settings that match this scenario\n"
                     "(P_D, position noise, clutter density, q, the amplitude\n"
                     "model; a file for trk-lcm-bridge --config) and exit"),
        CLI_OPT_STRING("--bridge-amp-table", &bridge_amp_table, "FILE", NULL,
                       "with K amplitudes: the table file the printed settings\n"
                       "name (made by trk-tablegen amp as their comment says) (sonar.amp)"),
        CLI_OPT_HEADING("Polar sensor on a moving platform:"),
        CLI_OPT_FLAG("--polar", &polar,
                     "publish range and bearing from the platform's pose\n"
                     "(trk.detection_scan_polar_t on --polar-channel) instead of\n"
                     "positions (trk.detection_scan_t on --channel)"),
        CLI_OPT_STRING("--polar-channel", &polar_channel, "CH", NULL,
                       "polar detection channel (TRK_DETECTIONS_POLAR)"),
        CLI_OPT_NUMBERS("--platform", platform, 4, "X,Y,COURSE_RAD,SPEED_MPS",
                        "platform at the first scan (m), its course clockwise from\n"
                        "north, which the sensor looks along, and speed (1000,1000,0,0)"),
        CLI_OPT_CALL("--sigma-range-m", &so_sr, set_sensor_opt, "S", "range noise, 1 sigma, (0, 1e6] (3)"),
        CLI_OPT_CALL("--sigma-bearing-rad", &so_sb, set_sensor_opt, "S", "bearing noise, 1 sigma, (0, 0.5] (0.005)"),
        CLI_OPT_CALL("--pd-profile", &so_prof, set_sensor_opt, "R:P,...",
                     "P_D over range from the platform (m : P_D, 2..16 points,\n"
                     "linear between; replaces the targets' P_D) (none)"),
        CLI_OPT_CALL("--coverage", &pcfg, set_coverage, "MIN_M,MAX_M,HALF_WIDTH_RAD",
                     "where the sensor sees: ranges (max 0: no limit) and the\n"
                     "sector's half width about the heading (0: all round) (0,0,0)"),
        CLI_OPT_HEADING("Scenario:"),
        CLI_OPT_LONG("--seed", &seed, "N", NULL, CLI_IN, 0, 9e18, "(1)"),
        CLI_OPT_LONG("--sensor-id", &sensor_id, "N", NULL, CLI_IN, 0, 2147483647.0, "(0)"),
        CLI_OPT_DOUBLE("--scan-period-s", &p.scan_period_s, "S", NULL, CLI_GT, 0, 0, "simulated time between scans (2)"),
        CLI_OPT_LONG("--targets", &n_targets, "N", NULL, CLI_IN, 0, 100000, "random targets in the region (3)"),
        CLI_OPT_CALL("--target", &tgt, add_target, "X,Y,VX,VY[,SNR_DB]",
                     "a target (m, m/s); repeat for more; replaces --targets"),
        CLI_OPT_NUMBERS("--speed", speed, 2, "MIN,MAX", "random targets' speed range, m/s (1,5)"),
        CLI_OPT_NUMBERS("--region", region, 4, "X0,X1,Y0,Y1", "clutter region (and random targets), m (0,2000,0,2000)"),
        CLI_OPT_DOUBLE("--clutter-density", &p.clutter_density_per_m2, "L", NULL, 0, 0, 0,
                       "Poisson clutter per m^2 per scan (5e-6)"),
        CLI_OPT_LONG("--clutter-count", &p.clutter_count, "N", NULL, CLI_IN, 0, 1000000,
                     "exactly N clutter detections per scan instead"),
        CLI_OPT_DOUBLE("--meas-sigma-m", &p.meas_sigma_m, "S", NULL, 0, 0, 0, "position noise per axis (3)"),
        CLI_OPT_FLAG("--with-cov", &p.attach_cov, "detections carry their covariance (S^2 I)"),
        CLI_OPT_DOUBLE("--q", &p.process_noise_q, "Q", NULL, 0, 0, 0, "target process noise density, m^2/s^3 (0.01)"),
        CLI_OPT_CHOICE("--clutter-model", &p.amp_kind, "none|rayleigh|k", amp_kinds, NULL,
                       "clutter amplitude law, Swerling I targets (rayleigh)"),
        CLI_OPT_DOUBLE("--pfa", &p.pfa, "P", NULL, 0, 0, 0, "detection threshold's false-alarm probability (1e-3)"),
        CLI_OPT_DOUBLE("--snr-db", &p.snr_db, "D", NULL, 0, 0, 0,
                       "target SNR (15); P_D = S1(threshold) (Rayleigh: pfa^(1/(1+SNR)))"),
        CLI_OPT_DOUBLE("--k-shape", &p.k_shape, "NU", NULL, 0, 0, 0, "K-distribution shape (1)"),
        CLI_OPT_CALL("--amp-table", &amp_table, set_amp_table, "FILE",
                     "amplitudes from an amplitude table (trk-tablegen amp; any\n"
                     "model, e.g. K): the library's sampler; the table fixes pfa\n"
                     "and the SNR of every target"),
        CLI_OPT_DOUBLE("--pd", &pd, "P", NULL, 0, 0, 0, "detection probability without amplitude model (0.9)"),
        CLI_OPT_ALIAS("--log", "--out"),
        CLI_OPT_ALIAS("--amplitude", "--clutter-model"),
        CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-sonar-sim",
        .about = "\n"
                 "Publishes a simulated sonar's detection scans (trk.detection_scan_t) on LCM, at a\n"
                 "chosen rate, or writes them to an LCM log file (--out). Constant-velocity targets with\n"
                 "process noise, detection probability from the amplitude model (or --pd), Poisson\n"
                 "clutter over a region, thresholded Rayleigh or K-distributed amplitudes. The\n"
                 "targets' true states go out as trk.track_list_t on the truth channel.\n"
                 "Same --seed, same scans.\n",
        .opts = opts};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN) return parsed;
    p.seed = (uint64_t)seed;
    p.sensor_id = (unsigned)sensor_id;
    p.n_targets = (size_t)n_targets;
    p.speed_min_mps = speed[0], p.speed_max_mps = speed[1];
    p.x_min_m = region[0], p.x_max_m = region[1], p.y_min_m = region[2], p.y_max_m = region[3];
    if (!isnan(pd)) {
        p.pd = pd;
        have_pd = 1;
    }
    int64_t start_utime = start_utime_l;
    const size_t n_tgt = tgt.n;
    const struct scen_target_init *targets = tgt.t;
    if (have_pd && p.amp_kind != AMP_NONE) {
        fprintf(stderr, "trk-sonar-sim: --pd needs --clutter-model none (with an amplitude model "
                        "P_D follows from --pfa and --snr-db)\n");
        return 2;
    }
    if (n_tgt) {
        p.targets = targets;
        p.n_targets = n_tgt;
    }
    if (scans < 0) scans = log_path ? 100 : 0;
    if (log_path && scans == 0) {
        fprintf(stderr, "trk-sonar-sim: --out needs --scans N > 0\n");
        return 2;
    }
    if (start_utime < 0) start_utime = log_path ? 1700000000000000LL : wall_us();
    /* every scan's time in the tracker's range (--scan-period-s 1e13 wrote
     * 1 of 3 scans and exited 0) */
    const double last_us = (double)start_utime + (double)(scans > 0 ? scans - 1 : 0) * p.scan_period_s * 1e6;
    if (!(last_us <= (double)TRK_TIME_US_MAX)) {
        fprintf(stderr,
                "trk-sonar-sim: scan %ld would be at %.6g us, beyond the tracker's time range (%.6g us): "
                "a shorter --scan-period-s or fewer --scans\n",
                scans > 0 ? scans - 1 : 0L, last_us, (double)TRK_TIME_US_MAX);
        return 2;
    }
    if (rate_hz < 0) rate_hz = 1.0 / p.scan_period_s;
    p.t0_us = start_utime;

    struct scenario sc;
    if (scen_init(&sc, &p, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sonar-sim: %s\n", err);
        return 2;
    }

    const struct polar_platform pf = {platform[0], platform[1], platform[2], platform[3]};
    struct trk_sensor_params *psp = &pcfg.params.sensor[0];
    if (polar) {
        char perr[256];
        if (!isfinite(pf.x_m) || !isfinite(pf.y_m) || !(fabs(pf.course_rad) <= 6.283185307179586) ||
            !(pf.speed_mps >= 0 && pf.speed_mps <= 1e4)) {
            fprintf(stderr, "trk-sonar-sim: --platform: finite position, course in [-2 pi, 2 pi], speed in [0, 1e4] m/s\n");
            scen_free(&sc);
            return 2;
        }
        if (tcfg_check(&pcfg, perr, sizeof perr) != 0) {
            fprintf(stderr, "trk-sonar-sim: polar sensor: %s\n", perr);
            scen_free(&sc);
            return 2;
        }
    }
    if (print_config) {
        if (polar) print_polar_bridge_config(&sc, psp, &pf, bridge_amp_table, stdout);
        else print_bridge_config(&sc, 0, 0, bridge_amp_table, stdout);
        scen_free(&sc);
        return fflush(stdout) == 0 && !ferror(stdout) ? 0 : 1;
    }

    struct sink sink = {0};
    if (log_path) {
        sink.is_log = 1;
        if (lcmlog_open_write(&sink.w, log_path) != 0) {
            fprintf(stderr, "trk-sonar-sim: %s: cannot create: %s\n", log_path, strerror(errno));
            scen_free(&sc);
            return 1;
        }
    } else {
        sink.lc = lcm_create(url);
        if (!sink.lc) {
            fprintf(stderr, "trk-sonar-sim: cannot create LCM for '%s'\n",
                    url ? url : getenv("LCM_DEFAULT_URL") ? getenv("LCM_DEFAULT_URL") : "LCM default");
            scen_free(&sc);
            return 1;
        }
    }
    cli_catch_stop_signals();

    struct trk_detection *det = calloc(TRK_DETECTION_SCAN_T_MAX_DETECTIONS, sizeof *det);
    trk_detection_scan_t *msg = malloc(sizeof *msg), *bad = malloc(sizeof *bad);
    struct trk_polar_detection *pdet = calloc(TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS, sizeof *pdet);
    trk_detection_scan_polar_t *pmsg = malloc(sizeof *pmsg), *pbad = malloc(sizeof *pbad);
    trk_track_list_t *truth = malloc(sizeof *truth);
    uint8_t *buf = malloc(65536);
    if (!det || !msg || !bad || !truth || !buf || !pdet || !pmsg || !pbad) {
        fprintf(stderr, "trk-sonar-sim: out of memory\n");
        return 1;
    }
    struct rng bad_rng;
    rng_init(&bad_rng, p.seed, UINT64_MAX);
    if (!quiet) {
        fprintf(stderr, "trk-sonar-sim: %zu targets, %s amplitudes", sc.n_tg, amp_kind_name(p.amp_kind));
        if (p.amp_kind != AMP_NONE)
            fprintf(stderr, " (pfa %g, threshold %.3f sqrt(P))", p.pfa, sc.amp.t);
        if (sc.n_tg)
            fprintf(stderr, ", target 1 P_D %.3f", sc.tg[0].pd);
        if (polar)
            fprintf(stderr, "; polar from (%g, %g) m, course %g rad, %g m/s", pf.x_m, pf.y_m, pf.course_rad,
                    pf.speed_mps);
        fprintf(stderr, "; %s %s%s\n", log_path ? "writing" : "publishing on",
                log_path ? log_path : polar ? polar_channel : channel, log_path ? "" : " (Ctrl-C to stop)");
    }

    struct timespec next;
    clock_gettime(CLOCK_MONOTONIC, &next);
    uint64_t n_sent = 0, n_bad = 0, n_det = 0, n_tdet = 0, n_drop = 0;
    unsigned bad_kind = 0;
    int encode_failed = 0;
    for (long k = 0; (scans == 0 || k < scans) && !cli_stop_flag; k++) {
        struct trk_scan scan;
        size_t nt, nd;
        scen_next(&sc, det, TRK_DETECTION_SCAN_T_MAX_DETECTIONS, &scan, &nt, &nd);
        if (polar) { /* the same targets and time, seen from the platform */
            const struct trk_pose pose = polar_pose(&pf, (uint64_t)k, p.scan_period_s);
            scan.n_detections = polar_scan(&sc, psp, &pose, (uint64_t)k, pdet,
                                           TRK_DETECTION_SCAN_POLAR_T_MAX_DETECTIONS, &nt, &nd);
            scan.detections = NULL;
            scan.polar = pdet;
            scan.has_pose = 1;
            scan.pose = pose;
        }
        n_det += scan.n_detections;
        n_tdet += nt;
        n_drop += nd;
        if (polar) {
            if (lcmc_polar_scan_to_msg(&scan, (int64_t)k, pmsg) != LCMC_OK) {
                fprintf(stderr, "trk-sonar-sim: scan %ld cannot be encoded (time %lld us)\n", k,
                        (long long)scan.time_us);
                encode_failed = 1;
                break;
            }
            const size_t len = encode_polar(pmsg, buf, 65536);
            if (sink_send(&sink, scan.time_us, polar_channel, buf, len) == 0) n_sent++;
        } else {
            if (lcmc_scan_to_msg(&scan, (int64_t)k, msg) != LCMC_OK) {
                fprintf(stderr, "trk-sonar-sim: scan %ld cannot be encoded (time %lld us)\n", k,
                        (long long)scan.time_us);
                encode_failed = 1;
                break;
            }
            size_t len = encode_scan(msg, buf, 65536);
            if (sink_send(&sink, scan.time_us, channel, buf, len) == 0) n_sent++;
        }
        if (truth_channel[0]) {
            truth_msg(&sc, scan.time_us, (int64_t)k, truth);
            int tl = trk_track_list_t_encode(buf, 0, 65536, truth);
            if (tl > 0) sink_send(&sink, scan.time_us, truth_channel, buf, (size_t)tl);
        }
        if (bad_every > 0 && (k + 1) % bad_every == 0) {
            const size_t bl = polar ? make_bad_polar(bad_kind++, pmsg, pbad, buf, 65536, &bad_rng)
                                    : make_bad(bad_kind++, msg, bad, buf, 65536, &bad_rng);
            if (sink_send(&sink, scan.time_us, polar ? polar_channel : channel, buf, bl) == 0) n_bad++;
        }
        if (!log_path && rate_hz > 0) {
            const double per = 1.0 / rate_hz;
            next.tv_sec += (time_t)per;
            next.tv_nsec += (long)((per - floor(per)) * 1e9);
            if (next.tv_nsec >= 1000000000L) {
                next.tv_sec++;
                next.tv_nsec -= 1000000000L;
            }
            while (!cli_stop_flag && clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL) == EINTR) {
            }
        }
    }
    int rc = encode_failed;
    if (log_path) {
        if (lcmlog_close_write(&sink.w) != 0) {
            fprintf(stderr, "trk-sonar-sim: %s: write error\n", log_path);
            rc = 1;
        }
    } else {
        lcm_destroy(sink.lc);
    }
    if (sink.errors) {
        fprintf(stderr, "trk-sonar-sim: %llu send errors\n", (unsigned long long)sink.errors);
        rc = 1;
    }
    printf("trk-sonar-sim: %llu scans sent (%llu detections: %llu from targets, %llu clutter; "
           "%llu dropped over the message maximum), %llu malformed messages%s\n",
           (unsigned long long)n_sent, (unsigned long long)n_det, (unsigned long long)n_tdet,
           (unsigned long long)(n_det - n_tdet), (unsigned long long)n_drop,
           (unsigned long long)n_bad, cli_stop_flag ? " (stopped by signal)" : "");
    if (sc.n_amp_failures)
        printf("trk-sonar-sim: %llu amplitude draws failed (detections dropped)\n",
               (unsigned long long)sc.n_amp_failures);
    free(det);
    free(pdet);
    free(pmsg);
    free(pbad);
    free(msg);
    free(bad);
    free(truth);
    free(buf);
    scen_free(&sc);
    return rc;
}
