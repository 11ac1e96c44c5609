/* exp_demo.c - trk-sim demo: trk's main job end to end, the scenario of
 * `make demo`: the sonar's own problem. One run of the sonar family of
 * tools/sim/mtt_scenario.h (a polar sensor, sigma 7.5 m in range and 1.5
 * deg in bearing, on a platform moving north at 3 m/s; its sector 0.5-8 km
 * +-60 deg, a ping every 8 s; P_D falling with range; reverberation patches
 * and a near-field rise; 12 persistent scatterers; eight targets: a shallow
 * crossing, a close pair on one bearing, a 3 deg/s turn, a far target, a
 * birth, a death) through the track table as firmware runs it
 * (trk_tracker_process_scan with each ping as range and bearing and the
 * platform's pose), with the library's defaults and the sensor as the
 * scenario describes it (configuration new of trk-sim mtt, mtt_params.h),
 * next to the known-association oracle (mtt_oracle.h: a CV Kalman filter
 * per target fed with its own detections, what this sensor and motion
 * model allow).
 *
 * Scoring per ping, as trk-sim mtt: the confirmed tracks assigned to the
 * targets present within the GOSPA cut-off c (mtt_eval.h, optimal
 * assignment); a target is covered at a ping when a confirmed track is
 * assigned to it. A confirmed track never assigned nor within c of a target
 * at a ping is false there; a false track is one with a false ping. The
 * oracle's estimate of target i is its own track's. Position errors are
 * reported against the range from the sonar, in bands. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "mtt_eval.h"
#include "mtt_oracle.h"
#include "mtt_params.h"
#include "mtt_scenario.h"
#include "progress.h"
#include "sim.h"
#include "tracker_config.h"
#include "trk/tracker.h"

#define N_BANDS 3
static const double band_lo_m[N_BANDS] = {500, 2500, 5000}, band_hi_m[N_BANDS] = {2500, 5000, 8000};
#define FAR_M 5000.0 /* "beyond 5 km", as trk-sim mtt */

/* Per target: pings present, covered by trk and by the oracle, the first
 * ping present and the first covered by trk; the same beyond 5 km and in a
 * patch. */
struct tgt_stats {
    long present, cov, ocov, first, first_cov;
    long far, far_cov, far_ocov, patch, patch_cov, patch_ocov;
    double r_min, r_max;
};

/* Per range band: squared errors and counts, trk and the oracle. */
struct band_stats {
    double se[2];
    long n[2];
};

/* A confirmed track's id and whether it was false at some ping, where. */
struct false_rec {
    uint32_t id;
    long false_pings, in_patch, on_persist;
};

static int band_of(double r_m)
{
    for (int b = 0; b < N_BANDS; b++)
        if (r_m >= band_lo_m[b] && r_m < band_hi_m[b]) return b;
    return -1;
}

static struct false_rec *false_rec_of(struct false_rec **v, size_t *n, size_t *cap, uint32_t id)
{
    for (size_t i = 0; i < *n; i++)
        if ((*v)[i].id == id) return &(*v)[i];
    if (*n == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        struct false_rec *nv = realloc(*v, *cap * sizeof *nv);
        if (!nv) return NULL;
        *v = nv;
    }
    struct false_rec *r = &(*v)[(*n)++];
    memset(r, 0, sizeof *r);
    r->id = id;
    return r;
}

static double ratio(long a, long b) { return b > 0 ? (double)a / (double)b : NAN; }

static double rmse(double se, long n) { return n > 0 ? sqrt(se / (double)n) : NAN; }

/* The fan plot and the error plot (gnuplot through sim_plot). */
static int demo_plots(const struct sim_common *com, const struct mtt_scenario *sc, long scans, long clutter)
{
    const char *o = com->out;
    const struct trk_coverage *cv = &sc->sonar.coverage;
    struct trk_pose p0, p1;
    mtt_scen_pose(sc, 0, &p0);
    mtt_scen_pose(sc, scans - 1, &p1);
    struct sim_text b = {NULL, 0, 0, 0};
    sim_text_add(&b, "set datafile separator ','\nset size ratio -1\nset key outside bottom center horizontal maxrows 3 font ',9'\n"
                     "set xlabel 'east (m)'\nset ylabel 'north (m)'\nset grid\n"
                     "set title 'trk demo: the sonar, %ld pings, %ld clutter per ping, seed %lu'\n",
                 scans, clutter, (unsigned long)sc->p.seed);
    for (int j = 0; j < MTT_SONAR_PATCHES; j++)
        sim_text_add(&b, "set object %d circle at %.1f,%.1f size %.1f fc rgb '#f0d8c0' fs solid 0.6 noborder behind\n",
                     j + 1, sc->patch[j].x_m, sc->patch[j].y_m, sc->patch[j].r_m);
    /* the sector at the first and the last ping: its outline as a parametric curve */
    const double hb = (double)cv->half_width_rad, r0 = (double)cv->min_range_m, r1 = (double)cv->max_range_m;
    sim_text_add(&b, "set parametric\nset trange [0:1]\nset samples 400\n");
    sim_text_add(&b, "plot ");
    for (int w = 0; w < 2; w++) {
        const struct trk_pose *p = w ? &p1 : &p0;
        const double x = (double)p->x_m, y = (double)p->y_m, h = (double)p->heading_rad;
        /* the outline: out along -hb, the far arc, back along +hb, the near arc */
        sim_text_add(&b,
                     "(t < 0.25 ? %.1f + (%.1f + (%.1f - %.1f) * t * 4) * sin(%.6f) : "
                     "t < 0.5 ? %.1f + %.1f * sin(%.6f + %.6f * (t - 0.25) * 4) : "
                     "t < 0.75 ? %.1f + (%.1f - (%.1f - %.1f) * (t - 0.5) * 4) * sin(%.6f) : "
                     "%.1f + %.1f * sin(%.6f - %.6f * (t - 0.75) * 4)), "
                     "(t < 0.25 ? %.1f + (%.1f + (%.1f - %.1f) * t * 4) * cos(%.6f) : "
                     "t < 0.5 ? %.1f + %.1f * cos(%.6f + %.6f * (t - 0.25) * 4) : "
                     "t < 0.75 ? %.1f + (%.1f - (%.1f - %.1f) * (t - 0.5) * 4) * cos(%.6f) : "
                     "%.1f + %.1f * cos(%.6f - %.6f * (t - 0.75) * 4)) "
                     "with lines lc rgb '%s' dt %d title 'sector, %s ping', ",
                     x, r0, r1, r0, h - hb, x, r1, h - hb, 2 * hb, x, r1, r1, r0, h + hb, x, r0, h + hb, 2 * hb,
                     y, r0, r1, r0, h - hb, y, r1, h - hb, 2 * hb, y, r1, r1, r0, h + hb, y, r0, h + hb, 2 * hb,
                     w ? "#404040" : "#909090", w ? 1 : 2, w ? "last" : "first");
    }
    sim_text_add(&b,
                 "'%s/detections.csv' using 5:6 with dots lc rgb '#b0b0b0' title 'detections (all pings)', "
                 "'%s/pose.csv' using 3:4 with lines lw 2 lc rgb 'black' title 'platform', "
                 "'%s/persistent.csv' using 2:3 with points pt 2 ps 1.2 lc rgb '#8b4513' title 'persistent scatterers', "
                 "'%s/truth.csv' using ($6 > 0 ? $4 : 1/0):5 with points pt 7 ps 0.25 lc rgb '#1f77b4' title 'truth', "
                 "'%s/oracle.csv' using 4:5 with points pt 1 ps 0.4 lc rgb '#2ca02c' title 'oracle (known association)', "
                 "'%s/tracks.csv' using 4:5 with points pt 6 ps 0.5 lc rgb '#d62728' title 'confirmed tracks'\n",
                 o, o, o, o, o, o);
    int rc = b.failed ? -1 : sim_plot(com, "/demo_sonar", b.s);
    sim_text_free(&b);
    struct sim_text e = {NULL, 0, 0, 0};
    sim_text_add(&e, "set datafile separator ','\nset key top left\nset grid\nset logscale y\n"
                     "set xlabel 'range from the sonar (m)'\nset ylabel 'position error (m)'\n"
                     "set title 'trk demo: position error against range (confirmed tracks on a target; the oracle)'\n"
                     "plot '%s/errors.csv' using ($1 == 0 ? $4 : 1/0):5 with points pt 6 ps 0.4 lc rgb '#d62728' "
                     "title 'trk', '' using ($1 == 1 ? $4 : 1/0):5 with points pt 1 ps 0.4 lc rgb '#2ca02c' title "
                     "'oracle', '%s/error_by_range.csv' using 3:4 with linespoints lw 2 pt 7 lc rgb '#d62728' title "
                     "'trk RMSE by band', '' using 3:5 with linespoints lw 2 pt 7 lc rgb '#2ca02c' title 'oracle RMSE "
                     "by band', '' using 3:6 with lines dt 2 lc rgb 'black' title 'cross-range sigma r sigma_b'\n",
                 o, o);
    const int rc2 = e.failed ? -1 : sim_plot(com, "/demo_error_range", e.s);
    sim_text_free(&e);
    return rc < 0 || rc2 < 0 ? -1 : 0;
}

SIM_EXPERIMENT(demo, "demo", "make demo: the sonar's own problem through the track table, against the oracle")
{
    long scans, clutter;
    double c_m;
    struct mtt_settings set = {{NULL}, 0};
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--scans", &scans, "N", "150", SIM_IN, 20, 100000, "pings, one every 8 s"),
        SIM_OPT_LONG("--clutter-count", &clutter, "N", "50", SIM_IN, 0, 4096,
                     "clutter detections per ping (30 % in the patches, 15 % near field,\n"
                     "the rest uniform in range x bearing)"),
        SIM_OPT_DOUBLE("--gospa-c", &c_m, "M", "200", SIM_GT, 0, 0,
                       "a confirmed track is on a target within M m (the GOSPA cut-off of\n"
                       "trk-sim mtt --family sonar)"),
        SIM_OPT_STRINGS("--set", set.kv, &set.n, MTT_MAX_SETTINGS, "KEY=VALUE",
                        "a tracker setting (the keys below; repeat for more)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "demo", "[options] [--set key=value ...]",
        "trk's main job end to end (`make demo`): the sonar's own problem, one run of the sonar\n"
        "family of trk-sim mtt (a polar sensor on a moving platform, P_D falling with range,\n"
        "reverberation patches, persistent scatterers, eight targets) through the track table with\n"
        "the library's defaults and the sensor's description, next to the known-association oracle;\n"
        "prints a summary (coverage per target and beyond 5 km, false tracks, RMSE by range band)\n"
        "and writes CSV files and PNG plots.",
        opts, "demo", "DIR", SIM_UNUSED_RUNS | SIM_UNUSED_THREADS,
        "--set key=value: tracker settings (the keys below), applied after the sensor's.\n"
        "Writes DIR/detections.csv, truth.csv, tracks.csv, oracle.csv, pose.csv, persistent.csv,\n"
        "errors.csv, error_by_range.csv, summary.csv, demo_sonar.png (the sector, detections,\n"
        "truth, tracks and oracle), demo_error_range.png (position error against range).\n",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse_more(&cli, tcfg_help, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    char err[512], path[1200];
    if (sim_mkdir_p(com.out) != 0) {
        fprintf(stderr, "trk-sim demo: cannot create %s\n", com.out);
        return 1;
    }
    /* ---- the scenario and the tracker */
    struct mtt_scen_params sp;
    mtt_scen_sonar_defaults(&sp);
    sp.seed = com.seed;
    sp.n_scans = scans;
    static struct mtt_scenario sc;
    if (mtt_scen_init(&sc, &sp, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim demo: %s\n", err);
        return 1;
    }
    const double lambda = (double)clutter / sc.area_m2;
    static struct trk_tracker_params tp;
    static struct tcfg_runtime rt;
    const struct imm_opts im = {3, 0.95, 1e-2}; /* unused by new */
    /* q 1e-3 m^2/s^3: trk-sim mtt's (--q), the targets' own */
    if (mtt_build_params(CFG_NEW, &sc, lambda, 1e-3, &im, &set, &tp, &rt, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim demo: %s (see trk-sim demo --help)\n", err);
        mtt_scen_free(&sc);
        return 2;
    }
    static struct trk_tracker tk;
    trk_status st = trk_tracker_init(&tk, &tp);
    struct mtt_oracle orc;
    if (st != TRK_OK || mtt_oracle_init(&orc, sc.n_targets, tp.sensor[0].meas_cov_m2, tp.process_noise_q) != 0) {
        fprintf(stderr, "trk-sim demo: trk_tracker_init: %s\n", ERRMSG_STATUS(st));
        return 1;
    }
    struct mtt_eval ev;
    mtt_eval_init(&ev, c_m);
    /* ---- the files */
    struct fileio_out f_out[8];
    static const char *const fname[8] = {"/detections.csv", "/truth.csv", "/tracks.csv", "/oracle.csv",
                                         "/pose.csv", "/errors.csv", "/persistent.csv", "/summary.csv"};
    static const char *const fhead[8] = {
        "ping,time_s,range_m,bearing_rad,x_m,y_m,origin",
        "ping,time_s,target,x_m,y_m,present,range_m,role",
        "ping,time_s,id,x_m,y_m,sd_x_m,sd_y_m,target,err_m,range_m",
        "ping,time_s,target,x_m,y_m,err_m,range_m",
        "ping,time_s,x_m,y_m,heading_rad",
        "who,ping,target,range_m,err_m",
        "scatterer,x_m,y_m",
        "key,value"};
    FILE *f[8];
    int bad = 0;
    for (int i = 0; i < 8; i++) bad |= !(f[i] = sim_csv_open(&com, &f_out[i], fname[i], path, sizeof path, fhead[i]));
    if (bad) {
        for (int i = 0; i < 8; i++)
            if (f[i]) sim_csv_discard(&f_out[i]);
        return 1;
    }
    for (int j = 0; j < MTT_SONAR_PERSIST; j++)
        fprintf(f[6], "%d,%.1f,%.1f\n", j, sc.persist_x_m[j], sc.persist_y_m[j]);
    /* ---- run */
    static struct trk_detection det[TRK_MAX_SCAN_DETECTIONS];
    static struct trk_polar_detection polar[TRK_MAX_SCAN_DETECTIONS];
    static long origin[TRK_MAX_SCAN_DETECTIONS];
    struct tgt_stats *ts = calloc(sc.n_targets, sizeof *ts);
    struct false_rec *fr = NULL;
    size_t n_fr = 0, cap_fr = 0;
    struct band_stats band[N_BANDS];
    memset(band, 0, sizeof band);
    if (!ts) return 1;
    for (size_t i = 0; i < sc.n_targets; i++) ts[i].first = ts[i].first_cov = -1, ts[i].r_min = INFINITY;
    long n_det = 0, held = 0, conf_pings = 0;
    double t_track = 0;
    int rc = 0;
    for (long k = 0; k < scans && rc == 0; k++) {
        struct trk_scan scan;
        struct mtt_scan_info info;
        struct trk_pose pose;
        mtt_scen_pose(&sc, k, &pose);
        if (mtt_scen_scan_polar(&sc, k, clutter, det, polar, TRK_MAX_SCAN_DETECTIONS, origin, &scan, &info) != 0) {
            rc = 1;
            break;
        }
        const double t_s = (double)scan.time_us * 1e-6;
        n_det += (long)scan.n_detections;
        /* the oracle: the detections converted by the scenario, known origin */
        for (size_t i = 0; i < sc.n_targets; i++)
            if (k >= sc.tg[i].death_scan) (void)mtt_oracle_end(&orc, i);
        if (mtt_oracle_scan(&orc, &scan, origin, NULL) != 0) {
            rc = 1;
            break;
        }
        /* the tracker: the ping as range and bearing with the platform's pose */
        struct trk_scan ps = scan;
        ps.detections = NULL;
        ps.polar = polar;
        ps.has_pose = 1;
        ps.pose = pose;
        struct trk_scan_report rep;
        const double t0 = progress_now_s();
        st = trk_tracker_process_scan(&tk, &ps, &rep);
        t_track += progress_now_s() - t0;
        if (st != TRK_OK) {
            fprintf(stderr, "trk-sim demo: ping %ld refused: %s\n", k, ERRMSG_STATUS(st));
            rc = 1;
            break;
        }
        held += rep.n_stationary;
        fprintf(f[4], "%ld,%.1f,%.2f,%.2f,%.6f\n", k, t_s, (double)pose.x_m, (double)pose.y_m,
                (double)pose.heading_rad);
        for (size_t i = 0; i < scan.n_detections; i++)
            fprintf(f[0], "%ld,%.1f,%.2f,%.6f,%.2f,%.2f,%ld\n", k, t_s, (double)polar[i].range_m,
                    (double)polar[i].bearing_rad, (double)det[i].x_m, (double)det[i].y_m, origin[i]);
        /* the targets present and the confirmed tracks, assigned */
        struct mtt_obj truth[MTT_N_SLOTS], est[TRK_MAX_TRACKS];
        long tix[MTT_N_SLOTS], assign[MTT_N_SLOTS];
        const struct trk_track *etr[TRK_MAX_TRACKS];
        size_t nt = 0, ne = 0;
        for (size_t i = 0; i < sc.n_targets; i++) {
            double x[4];
            mtt_scen_truth(&sc, (long)i, t_s, x);
            const int present = mtt_scen_present(&sc, (long)i, k);
            const double r = hypot(x[TRK_CV2_X] - (double)pose.x_m, x[TRK_CV2_Y] - (double)pose.y_m);
            fprintf(f[1], "%ld,%.1f,%zu,%.2f,%.2f,%d,%.1f,%s\n", k, t_s, i, x[TRK_CV2_X], x[TRK_CV2_Y], present, r,
                    mtt_role_name(sc.tg[i].role));
            if (!present || nt == MTT_N_SLOTS) continue;
            tix[nt] = (long)i;
            truth[nt++] = (struct mtt_obj){(long)i, x[TRK_CV2_X], x[TRK_CV2_Y]};
        }
        for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *t = trk_tracker_track(&tk, s);
            if (!t || t->status != TRK_TRACK_CONFIRMED) continue;
            etr[ne] = t;
            est[ne++] = (struct mtt_obj){(long)t->id, (double)t->x[TRK_CV2_X], (double)t->x[TRK_CV2_Y]};
        }
        conf_pings += (long)ne;
        if (mtt_eval_scan_assign(&ev, truth, nt, est, ne, assign) != 0) {
            rc = 1;
            break;
        }
        long est_target[TRK_MAX_TRACKS];
        for (size_t j = 0; j < ne; j++) est_target[j] = -1;
        for (size_t a = 0; a < nt; a++) {
            const long i = tix[a];
            struct tgt_stats *g = &ts[i];
            const double r = hypot(truth[a].x_m - (double)pose.x_m, truth[a].y_m - (double)pose.y_m);
            const int far = r > FAR_M, patch = mtt_scen_in_patch(&sc, truth[a].x_m, truth[a].y_m);
            const struct mtt_oracle_track *ot = mtt_oracle_track(&orc, (size_t)i);
            const double oerr = ot ? hypot((double)ot->x[TRK_CV2_X] - truth[a].x_m,
                                           (double)ot->x[TRK_CV2_Y] - truth[a].y_m)
                                   : INFINITY;
            const int ocov = oerr <= c_m, cov = assign[a] >= 0;
            g->present++;
            if (g->first < 0) g->first = k;
            if (r < g->r_min) g->r_min = r;
            if (r > g->r_max) g->r_max = r;
            g->cov += cov;
            g->ocov += ocov;
            g->far += far, g->far_cov += far && cov, g->far_ocov += far && ocov;
            g->patch += patch, g->patch_cov += patch && cov, g->patch_ocov += patch && ocov;
            if (cov && g->first_cov < 0) g->first_cov = k;
            const int bi = band_of(r);
            if (ot) {
                fprintf(f[3], "%ld,%.1f,%ld,%.2f,%.2f,%.2f,%.1f\n", k, t_s, i, (double)ot->x[TRK_CV2_X],
                        (double)ot->x[TRK_CV2_Y], oerr, r);
                if (ocov) {
                    fprintf(f[5], "1,%ld,%ld,%.1f,%.3f\n", k, i, r, oerr);
                    if (bi >= 0) band[bi].se[1] += oerr * oerr, band[bi].n[1]++;
                }
            }
            if (cov) {
                const size_t j = (size_t)assign[a];
                est_target[j] = i;
                const double e = hypot(est[j].x_m - truth[a].x_m, est[j].y_m - truth[a].y_m);
                fprintf(f[5], "0,%ld,%ld,%.1f,%.3f\n", k, i, r, e);
                if (bi >= 0) band[bi].se[0] += e * e, band[bi].n[0]++;
            }
        }
        for (size_t j = 0; j < ne && rc == 0; j++) {
            const struct trk_track *t = etr[j];
            const double r = hypot(est[j].x_m - (double)pose.x_m, est[j].y_m - (double)pose.y_m);
            double err_m = NAN;
            if (est_target[j] >= 0)
                for (size_t a = 0; a < nt; a++)
                    if (tix[a] == est_target[j]) err_m = hypot(est[j].x_m - truth[a].x_m, est[j].y_m - truth[a].y_m);
            fprintf(f[2], "%ld,%.1f,%u,%.2f,%.2f,%.2f,%.2f,%ld,%.2f,%.1f\n", k, t_s, t->id, est[j].x_m, est[j].y_m,
                    sqrt((double)t->p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)]),
                    sqrt((double)t->p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)]), est_target[j], err_m, r);
            if (est_target[j] >= 0) continue;
            int near = 0;
            for (size_t a = 0; a < nt && !near; a++) near = hypot(truth[a].x_m - est[j].x_m, truth[a].y_m - est[j].y_m) < c_m;
            if (near) continue; /* a duplicate, not false */
            struct false_rec *q = false_rec_of(&fr, &n_fr, &cap_fr, t->id);
            if (!q) {
                rc = 1;
                break;
            }
            q->false_pings++;
            q->in_patch += mtt_scen_in_patch(&sc, est[j].x_m, est[j].y_m);
            q->on_persist += mtt_scen_persist_dist(&sc, est[j].x_m, est[j].y_m) <= c_m;
        }
    }
    if (rc != 0) {
        for (int i = 0; i < 8; i++) sim_csv_discard(&f_out[i]);
        return 1;
    }
    /* ---- the summary */
    struct mtt_summary gs;
    mtt_eval_summary(&ev, &gs);
    long pres = 0, cov = 0, ocov = 0, far = 0, far_cov = 0, far_ocov = 0, patch = 0, patch_cov = 0, patch_ocov = 0;
    long n_confirmed_targets = 0, n_long = 0;
    for (size_t i = 0; i < sc.n_targets; i++) {
        const struct tgt_stats *g = &ts[i];
        pres += g->present, cov += g->cov, ocov += g->ocov;
        far += g->far, far_cov += g->far_cov, far_ocov += g->far_ocov;
        patch += g->patch, patch_cov += g->patch_cov, patch_ocov += g->patch_ocov;
        n_long += g->present >= 25;
        n_confirmed_targets += g->present >= 25 && g->first_cov >= 0;
    }
    long n_false = 0, false_patch = 0, false_persist = 0, false_pings = 0;
    for (size_t i = 0; i < n_fr; i++) {
        n_false++;
        false_pings += fr[i].false_pings;
        false_patch += 2 * fr[i].in_patch > fr[i].false_pings;
        false_persist += 2 * fr[i].on_persist > fr[i].false_pings;
    }
    printf("\n== trk demo: the sonar's own problem, %ld pings (%.0f s), %ld clutter per ping, seed %llu\n", scans,
           (double)scans * sp.scan_period_s, clutter, (unsigned long long)com.seed);
    printf("   sensor: range/bearing (sigma %.1f m, %.1f deg) on a platform at 3 m/s due north, sector %.1f-%.0f km "
           "+-%.0f deg, a ping every %.0f s\n",
           (double)sc.sonar.sigma_range_m, (double)sc.sonar.sigma_bearing_rad * 180 / 3.14159265358979323846,
           (double)sc.sonar.coverage.min_range_m / 1000, (double)sc.sonar.coverage.max_range_m / 1000,
           (double)sc.sonar.coverage.half_width_rad * 180 / 3.14159265358979323846, sp.scan_period_s);
    printf("   P_D %.2f at 0.5 km to %.2f at 8 km (profile); clutter 30 %% in %d patches, 15 %% near field; %d "
           "persistent scatterers\n",
           (double)trk_sensor_pd_at(&sc.sonar, &(struct trk_pose){0, 0, 0}, 0, 500),
           (double)trk_sensor_pd_at(&sc.sonar, &(struct trk_pose){0, 0, 0}, 0, 7999), MTT_SONAR_PATCHES,
           MTT_SONAR_PERSIST);
    printf("   tracker: the library's defaults with the sensor's description (polar scans with the pose, P_D and\n"
           "   clutter profiles, coverage), %d track slots; the oracle: a CV Kalman filter per target fed its own\n"
           "   detections\n", TRK_MAX_TRACKS);
    printf("   detections: %ld (%.1f per ping)\n", n_det, (double)n_det / (double)scans);
    printf("-- targets (coverage: pings with a confirmed track on it, within %.0f m)\n", c_m);
    printf("   target  role        pings  range km     trk   oracle  pings to confirm\n");
    for (size_t i = 0; i < sc.n_targets; i++) {
        const struct tgt_stats *g = &ts[i];
        if (g->present == 0) continue;
        char conf[32];
        if (g->first_cov >= 0) snprintf(conf, sizeof conf, "%ld", g->first_cov - g->first);
        else snprintf(conf, sizeof conf, "never");
        printf("   %6zu  %-10s  %5ld  %3.1f-%-4.1f  %6.2f  %6.2f  %s\n", i, mtt_role_name(sc.tg[i].role), g->present,
               g->r_min / 1000, g->r_max / 1000, ratio(g->cov, g->present), ratio(g->ocov, g->present), conf);
    }
    printf("-- coverage             trk     oracle\n");
    printf("   all targets      %7.3f   %7.3f\n", ratio(cov, pres), ratio(ocov, pres));
    printf("   beyond 5 km      %7.3f   %7.3f\n", ratio(far_cov, far), ratio(far_ocov, far));
    printf("   in the patches   %7.3f   %7.3f\n", ratio(patch_cov, patch), ratio(patch_ocov, patch));
    printf("-- false confirmed tracks: %ld (%ld mostly in a patch, %ld mostly on a persistent scatterer), %ld false "
           "pings;\n   tracks held as standing still (persistent returns): %.1f per ping\n",
           n_false, false_patch, false_persist, false_pings, (double)held / (double)scans);
    printf("-- GOSPA (c %.0f m): %.1f m per ping\n", c_m, gs.gospa_mean_m);
    printf("-- position RMSE by range (m)   trk    oracle   cross-range sigma\n");
    for (int b = 0; b < N_BANDS; b++) {
        const double rm = 0.5 * (band_lo_m[b] + band_hi_m[b]);
        printf("   %3.1f-%.1f km            %7.1f  %7.1f   %7.1f\n", band_lo_m[b] / 1000, band_hi_m[b] / 1000,
               rmse(band[b].se[0], band[b].n[0]), rmse(band[b].se[1], band[b].n[1]),
               rm * (double)sc.sonar.sigma_bearing_rad);
    }
    printf("-- cost: %.1f us of tracker time per ping (this host)\n", 1e6 * t_track / (double)scans);
    /* the summary and the range bands as files */
    fprintf(f[7], "pings,%ld\nclutter_per_ping,%ld\nseed,%llu\ndetections,%ld\ntargets,%zu\n", scans, clutter,
            (unsigned long long)com.seed, n_det, sc.n_targets);
    fprintf(f[7], "targets_present_25,%ld\ntargets_confirmed_25,%ld\n", n_long, n_confirmed_targets);
    fprintf(f[7], "target_pings,%ld\ncoverage,%.6f\noracle_coverage,%.6f\n", pres, ratio(cov, pres),
            ratio(ocov, pres));
    fprintf(f[7], "far_pings,%ld\nfar_coverage,%.6f\noracle_far_coverage,%.6f\n", far, ratio(far_cov, far),
            ratio(far_ocov, far));
    fprintf(f[7], "patch_pings,%ld\npatch_coverage,%.6f\noracle_patch_coverage,%.6f\n", patch,
            ratio(patch_cov, patch), ratio(patch_ocov, patch));
    fprintf(f[7], "false_tracks,%ld\nfalse_tracks_patch,%ld\nfalse_tracks_persistent,%ld\nfalse_pings,%ld\n", n_false,
            false_patch, false_persist, false_pings);
    fprintf(f[7], "confirmed_track_pings,%ld\nheld_per_ping,%.4f\ngospa_m,%.4f\ntracker_us_per_ping,%.2f\n",
            conf_pings, (double)held / (double)scans, gs.gospa_mean_m, 1e6 * t_track / (double)scans);
    for (int b = 0; b < N_BANDS; b++)
        fprintf(f[7], "rmse_%.0f_%.0f_m,%.4f\noracle_rmse_%.0f_%.0f_m,%.4f\n", band_lo_m[b], band_hi_m[b],
                rmse(band[b].se[0], band[b].n[0]), band_lo_m[b], band_hi_m[b], rmse(band[b].se[1], band[b].n[1]));
    for (int i = 0; i < 8; i++)
        if (sim_csv_close(&f_out[i]) != 0) rc = 1;
    struct fileio_out fb_out;
    FILE *fb = sim_csv_open(&com, &fb_out, "/error_by_range.csv", path, sizeof path,
                            "lo_m,hi_m,mid_m,trk_rmse_m,oracle_rmse_m,cross_range_sigma_m,trk_n,oracle_n");
    if (!fb) return 1;
    for (int b = 0; b < N_BANDS; b++) {
        const double rm = 0.5 * (band_lo_m[b] + band_hi_m[b]);
        fprintf(fb, "%.0f,%.0f,%.0f,%.4f,%.4f,%.4f,%ld,%ld\n", band_lo_m[b], band_hi_m[b], rm,
                rmse(band[b].se[0], band[b].n[0]), rmse(band[b].se[1], band[b].n[1]),
                rm * (double)sc.sonar.sigma_bearing_rad, band[b].n[0], band[b].n[1]);
    }
    if (sim_csv_close(&fb_out) != 0) rc = 1;
    if (rc == 0)
        printf("   files: %s/{detections,truth,tracks,oracle,pose,persistent,errors,error_by_range,summary}.csv%s\n",
           com.out, com.no_plot ? "" : ", demo_sonar.png, demo_error_range.png");
    if (rc == 0 && demo_plots(&com, &sc, scans, clutter) != 0) rc = 1;
    tcfg_unload(&rt);
    mtt_oracle_free(&orc);
    mtt_eval_free(&ev);
    mtt_scen_free(&sc);
    free(ts);
    free(fr);
    return rc;
}
