/* exp_demo_amplitude.c - trk-sim demo-amplitude (`make demo-amplitude`):
 * amplitude-aided tracking end to end, the scenario `make demo` ran
 * before the sonar of exp_demo.c. A simulated sonar (tools/sim/scenario.h) with K-distributed
 * (heavy-tailed, nu = 1) clutter amplitudes feeds the track table
 * (trk_tracker_process_scan, the code firmware runs) with amplitude-aided
 * association (PDAFAI: the amplitude table made by `trk-tablegen amp`) and
 * the library's defaults: two-point initiation, confirmation and termination
 * by the track's existence (IPDA, Kennedy eqs 21-24, whose likelihood
 * carries the same amplitude ratios; trk/tracker.h). The tracks are scored
 * against the truth and the position RMSE against the MRE's prediction
 * (toc_curve.h: Brekke eq 27 with q2 of the PDAFAI at this scenario).
 *
 * Scenario: a 2 km x 2 km area, one ping every 2 s, 250 scans; four targets
 * at 1.5-2.6 m/s with process noise q = 1e-3 m^2/s^3 (the tracker's model),
 * one of them gone after scan 150 (its track must be terminated); position
 * noise 5 m; P_D = S1(t) of the table (SNR 15 dB, P_FA 1e-2: 0.775); clutter
 * 150 detections per scan on average (heavy clutter; --clutter-count),
 * uniform (Poisson), amplitudes from the K law. Same seed, same run.
 *
 * Scoring: a confirmed track is on a target at a scan when its position is
 * within --assoc-m of that target's true position; a confirmed track is
 * true when it is on one target for at least half of its confirmed scans
 * (its target), false otherwise. A true track is lost when it ends (or
 * leaves its target for good) while its target is still there; the track of
 * a target that is gone should end, and the delay is reported. The RMSE is
 * over the true tracks' scans on their target from 10 scans after
 * confirmation (steady state). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "errmsg.h"
#include "kvfile.h"
#include "progress.h"
#include "scenario.h"
#include "sim.h"
#include "toc_curve.h"
#include "tracker_config.h"
#include "trk/gate.h"
#include "trk/tracker.h"

#define N_TG 4
#define MAX_SETTINGS 64

struct trk_rec {             /* one track id */
    long start, confirm, end;  /* scans (confirm/end 0 = not) */
    int end_reason;
    long n_conf;               /* confirmed scans */
    long on[N_TG];             /* confirmed scans on each target */
    long last_on;              /* last confirmed scan on its target */
};

struct err_row {
    long scan;
    uint32_t id;
    int target;
    double err;
};

/* Tracker settings, applied after the demo's own, in command-line order:
 * --set key=value, and the old bare key=value operands (deprecated). */
struct demo_settings {
    const char *kv[MAX_SETTINGS];
    int n;
};

static int take_setting(const char *arg, void *ctx)
{
    struct demo_settings *s = ctx;
    if (arg[0] == '-' || !strchr(arg, '=') || s->n >= MAX_SETTINGS) return -1;
    char new_form[600];
    snprintf(new_form, sizeof new_form, "--set %.500s", arg);
    cli_note_deprecated("trk-sim demo-amplitude", arg, new_form);
    s->kv[s->n++] = arg;
    return 0;
}

SIM_EXPERIMENT(demo_amplitude, "demo-amplitude", "make demo-amplitude: amplitude-aided tracking in heavy-tailed clutter, scored")
{
    const char *tables, *amp_table = NULL;
    long scans, mre_samples = 0;
    double clutter_per_scan, assoc_m;
    int fluct = 0;
    struct demo_settings set = {{NULL}, 0};
    const struct sim_opt opts[] = {
        SIM_OPT_STRING("--tables", &tables, "DIR", "build/tables",
                       "amplitude tables of `make tables`; the demo\n"
                       "uses DIR/amp_k1_snr15_pfa1e-2.tbl"),
        SIM_OPT_STRING("--amp-table", &amp_table, "FILE", NULL, "another amplitude table (its model, SNR and P_FA)"),
        SIM_OPT_LONG("--scans", &scans, "N", "250", SIM_IN, 10, 100000, "scans, one every 2 s"),
        SIM_OPT_DOUBLE("--clutter-count", &clutter_per_scan, "N", "150", SIM_IN, 0, 200,
                       "clutter detections per scan over the 2 km x 2 km area\n"
                       "(the mean of a Poisson count)"),
        SIM_OPT_ALIAS("--clutter", "--clutter-count"),
        SIM_OPT_STRINGS("--set", set.kv, &set.n, MAX_SETTINGS, "KEY=VALUE",
                        "a tracker setting (the keys below; repeat for more)"),
        SIM_OPT_FLAG("--fluct", &fluct, "targets fade (Blanding's two-state P_D: p 0.1, q 0.02, P_D low 0.1)"),
        SIM_OPT_DOUBLE("--assoc-m", &assoc_m, "D", "25", SIM_GT, 0, 0, "a track is on a target within D m"),
        SIM_OPT_LONG("--mre-samples", &mre_samples, "N", NULL, SIM_GE, 1000, 0,
                     "importance samples of the MRE's q2 (default: toc.h's)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "demo-amplitude", "[options] [--set key=value ...]",
        "amplitude-aided tracking end to end (`make demo-amplitude`): a simulated sonar with heavy-tailed (K, nu 1)\n"
        "clutter through the track table (PDAFAI, the library's defaults: two-point initiation,\n"
        "existence-based confirmation and termination);\n"
        "prints a summary (tracks confirmed, lost, false; RMSE against the MRE prediction) and\n"
        "writes CSV files and PNG plots.",
        opts, "demo-amplitude", "DIR", SIM_UNUSED_RUNS | SIM_UNUSED_THREADS,
        "--set key=value: tracker settings (the keys below, as in a config file, e.g.\n"
        "--set term=page --set confirm=mn), applied after the demo's own (the scenario's sensor,\n"
        "and its detection model for the HMM tests). (A bare key=value operand still works,\n"
        "with a deprecation note.)\n"
        "Writes DIR/detections.csv, truth.csv, tracks.csv, errors.csv, summary.csv,\n"
        "demo_tracks.png (tracks over detections), demo_error.png (error over time).\n",
        take_setting, &set};
    struct sim_common com;
    const int parsed = sim_parse_more(&cli, tcfg_help, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    const double t_start = progress_now_s();
    char err[512], table_path[1024], path[1200];
    if (amp_table) snprintf(table_path, sizeof table_path, "%s", amp_table);
    else snprintf(table_path, sizeof table_path, "%s/amp_k1_snr15_pfa1e-2.tbl", tables);
    if (sim_mkdir_p(com.out) != 0) {
        fprintf(stderr, "trk-sim demo-amplitude: cannot create %s\n", com.out);
        return 1;
    }
    /* ---- the scenario */
    const double dt = 2, sigma = 5, q = 1e-3, area = 2000.0 * 2000.0;
    static const struct scen_target_init tg[N_TG] = {{200, 300, 2.0, 1.0, NAN},
                                                     {1700, 400, -1.5, 2.0, NAN},
                                                     {1000, 1800, 0.5, -2.5, NAN},
                                                     {300, 1400, 2.0, 0.2, NAN}};
    static const long tg_end_def[N_TG] = {0, 0, 0, 150};
    long tg_end[N_TG]; /* ends within the run (0: present to the end) */
    for (int j = 0; j < N_TG; j++) tg_end[j] = tg_end_def[j] < scans ? tg_end_def[j] : 0;
    struct scen_params sp;
    scen_defaults(&sp);
    sp.seed = com.seed;
    sp.scan_period_s = dt;
    sp.clutter_density_per_m2 = clutter_per_scan / area;
    sp.meas_sigma_m = sigma;
    sp.process_noise_q = q;
    sp.amp_kind = AMP_TABLE;
    sp.amp_table = table_path;
    sp.n_targets = N_TG;
    sp.targets = tg;
    sp.target_end_scan = tg_end;
    sp.fluct = fluct;
    sp.fluct_p = 0.1;
    sp.fluct_q = 0.02;
    sp.fluct_pd_low = 0.1;
    struct scenario sc;
    if (scen_init(&sc, &sp, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim demo-amplitude: %s (run `make tables` first, or give --tables / --amp-table)\n", err);
        return 1;
    }
    const double pd = sc.tg[0].pd, lambda = sp.clutter_density_per_m2;
    /* ---- the tracker: defaults, the demo's settings, then the user's */
    static struct tcfg cfg;
    tcfg_defaults(&cfg);
    /* the library's defaults (existence-based confirmation and termination,
     * two-point initiation) with the scenario's sensor */
    const char *demo_set[] = {"sensor.0.meas_sigma_m", "process_noise_q", "gate_prob",
                              "sensor.0.clutter_density_per_m2", "sensor.0.amp_table", "hmm.pd_high",
                              "hmm.pd_low", "hmm.p_low_high", "hmm.q_high_low"};
    enum { N_DEMO_SET = 9 };
    char demo_val[N_DEMO_SET][1100];
    snprintf(demo_val[0], sizeof demo_val[0], "%g", sigma);
    snprintf(demo_val[1], sizeof demo_val[1], "%g", q);
    snprintf(demo_val[2], sizeof demo_val[2], "0.99");
    snprintf(demo_val[3], sizeof demo_val[3], "%.17g", lambda);
    snprintf(demo_val[4], sizeof demo_val[4], "%s", table_path);
    snprintf(demo_val[5], sizeof demo_val[5], "%.6f", pd);
    /* the detection model of an HMM termination test chosen with --set:
     * the scenario's (fixed P_D: both HMM states alike; fading: Blanding's
     * two states) */
    if (fluct) snprintf(demo_val[6], sizeof demo_val[6], "0.1");
    else snprintf(demo_val[6], sizeof demo_val[6], "%.6f", pd);
    snprintf(demo_val[7], sizeof demo_val[7], "0.1");
    snprintf(demo_val[8], sizeof demo_val[8], "%g", fluct ? 0.02 : 0.1);
    for (int i = 0; i < N_DEMO_SET; i++)
        if (tcfg_set(&cfg, demo_set[i], demo_val[i], err, sizeof err) != 0) {
            fprintf(stderr, "trk-sim demo-amplitude: %s = %s: %s\n", demo_set[i], demo_val[i], err);
            scen_free(&sc);
            return 1;
        }
    for (int i = 0; i < set.n; i++)
        if (kv_parse_assignment(set.kv[i], tcfg_set, &cfg, err, sizeof err) != 0) {
            fprintf(stderr, "trk-sim demo-amplitude: --set %s: %s (see trk-sim demo-amplitude --help)\n", set.kv[i], err);
            scen_free(&sc);
            return 2;
        }
    if (tcfg_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim demo-amplitude: tracker configuration: %s\n", err);
        scen_free(&sc);
        return 2;
    }
    static struct tcfg_runtime rt;
    static struct trk_tracker tk;
    struct trk_tracker_params tp;
    if (tcfg_load(&cfg, &rt, err, sizeof err) != 0) {
        fprintf(stderr, "trk-sim demo-amplitude: %s\n", err);
        scen_free(&sc);
        return 1;
    }
    tcfg_params_rt(&cfg, &rt, &tp);
    trk_status st = trk_tracker_init(&tk, &tp);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim demo-amplitude: trk_tracker_init: %s\n", ERRMSG_STATUS(st));
        return 1;
    }
    /* ---- run */
    struct fileio_out fd_out;
    FILE *fd = sim_csv_open(&com, &fd_out, "/detections.csv", path, sizeof path, "scan,time_s,x_m,y_m,amplitude");
    struct fileio_out ft_out;
    FILE *ft = sim_csv_open(&com, &ft_out, "/truth.csv", path, sizeof path,
                            "scan,time_s,target,x_m,y_m,vx_mps,vy_mps,present,high");
    struct fileio_out fk_out;
    FILE *fk = sim_csv_open(&com, &fk_out, "/tracks.csv", path, sizeof path,
                            "scan,time_s,id,status,x_m,y_m,vx_mps,vy_mps,sd_x_m,sd_y_m,target,err_m");
    if (!fd || !ft || !fk) {
        sim_csv_discard(&fd_out);
        sim_csv_discard(&ft_out);
        sim_csv_discard(&fk_out);
        return 1;
    }
    static struct trk_detection det[TRK_MAX_DETECTIONS];
    struct trk_rec *rec = NULL;
    size_t n_rec = 0, cap_rec = 0;
    struct err_row *er = NULL;
    size_t n_er = 0, cap_er = 0;
    long n_det = 0, n_dropped = 0, n_started = 0, n_refused = 0, n_merged = 0, max_live = 0, updates = 0;
    double t_track = 0;
    for (long k = 0; k < scans; k++) {
        struct trk_scan scan;
        size_t nt, nd;
        scen_next(&sc, det, TRK_MAX_DETECTIONS, &scan, &nt, &nd);
        n_det += (long)scan.n_detections;
        n_dropped += (long)nd;
        struct trk_scan_report rep;
        const double t0 = progress_now_s();
        st = trk_tracker_process_scan(&tk, &scan, &rep);
        t_track += progress_now_s() - t0;
        if (st != TRK_OK) {
            fprintf(stderr, "trk-sim demo-amplitude: scan %ld refused: %s\n", k, ERRMSG_STATUS(st));
            return 1;
        }
        updates += rep.n_tracks_updated;
        n_started += rep.n_started;
        n_refused += rep.n_init_refused_full;
        n_merged += rep.n_merged;
        const double ts = (double)scan.time_us * 1e-6;
        for (size_t i = 0; i < scan.n_detections; i++)
            fprintf(fd, "%ld,%.1f,%.3f,%.3f,%.4g\n", k, ts, (double)det[i].x_m, (double)det[i].y_m,
                    (double)det[i].amplitude);
        int present[N_TG];
        for (int j = 0; j < N_TG; j++) {
            const struct scen_target *t = &sc.tg[j];
            present[j] = !(t->end_scan > 0 && k >= t->end_scan);
            fprintf(ft, "%ld,%.1f,%d,%.3f,%.3f,%.4f,%.4f,%d,%d\n", k, ts, j, t->x[TRK_CV2_X], t->x[TRK_CV2_Y], t->x[TRK_CV2_VX], t->x[TRK_CV2_VY],
                    present[j], t->high);
        }
        long live = 0;
        for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *tr = trk_tracker_track(&tk, s);
            if (!tr) continue;
            live++;
            while (n_rec < tr->id) { /* ids start at 1 and grow */
                if (n_rec == cap_rec) {
                    cap_rec = cap_rec ? 2 * cap_rec : 1024;
                    struct trk_rec *nr = realloc(rec, cap_rec * sizeof *nr);
                    if (!nr) return 1;
                    rec = nr;
                }
                memset(&rec[n_rec], 0, sizeof rec[n_rec]);
                rec[n_rec].start = -1;
                n_rec++;
            }
            struct trk_rec *r = &rec[tr->id - 1];
            if (r->start < 0) r->start = k;
            if (tr->status == TRK_TRACK_TERMINATED) {
                if (!r->end) {
                    r->end = k;
                    r->end_reason = tr->end_reason;
                }
                continue;
            }
            if (tr->status != TRK_TRACK_CONFIRMED) continue;
            if (!r->confirm) r->confirm = k;
            r->n_conf++;
            int best = -1;
            double bd = INFINITY;
            for (int j = 0; j < N_TG; j++) {
                if (!present[j]) continue;
                const double d = hypot((double)tr->x[TRK_CV2_X] - sc.tg[j].x[TRK_CV2_X], (double)tr->x[TRK_CV2_Y] - sc.tg[j].x[TRK_CV2_Y]);
                if (d < bd) bd = d, best = j;
            }
            const int on = best >= 0 && bd <= assoc_m;
            if (on) r->on[best]++;
            fprintf(fk, "%ld,%.1f,%u,%d,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%d,%.4f\n", k, ts, tr->id, tr->status,
                    (double)tr->x[TRK_CV2_X], (double)tr->x[TRK_CV2_Y], (double)tr->x[TRK_CV2_VX], (double)tr->x[TRK_CV2_VY], sqrt((double)tr->p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)]),
                    sqrt((double)tr->p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)]), on ? best : -1, on ? bd : NAN);
            if (on) {
                if (n_er == cap_er) {
                    cap_er = cap_er ? 2 * cap_er : 4096;
                    struct err_row *ne = realloc(er, cap_er * sizeof *ne);
                    if (!ne) return 1;
                    er = ne;
                }
                er[n_er++] = (struct err_row){k, tr->id, best, bd};
            }
        }
        if (live > max_live) max_live = live;
    }
    const int bad_fd = sim_csv_close(&fd_out) != 0, bad_ft = sim_csv_close(&ft_out) != 0;
    if (sim_csv_close(&fk_out) != 0 || bad_fd || bad_ft) return 1;
    /* ---- score */
    long n_conf = 0, n_true = 0, n_false = 0, n_dup = 0, false_scans = 0;
    long first_cover[N_TG], cover[N_TG], n_lost[N_TG], last_end[N_TG];
    for (int j = 0; j < N_TG; j++) first_cover[j] = -1, cover[j] = 0, n_lost[j] = 0, last_end[j] = -1;
    int *major = calloc(n_rec ? n_rec : 1, sizeof *major);
    char *held = calloc((size_t)scans * N_TG, 1);
    if (!major || !held) return 1;
    for (size_t i = 0; i < n_er; i++) held[er[i].scan * N_TG + er[i].target] = 1;
    for (size_t i = 0; i < n_rec; i++) {
        const struct trk_rec *r = &rec[i];
        major[i] = -1;
        if (!r->confirm) continue;
        n_conf++;
        int best = 0;
        for (int j = 1; j < N_TG; j++)
            if (r->on[j] > r->on[best]) best = j;
        if (2 * r->on[best] >= r->n_conf && r->on[best] > 0) {
            major[i] = best;
            n_true++;
            if (first_cover[best] < 0 || r->confirm < first_cover[best]) first_cover[best] = r->confirm;
            /* a duplicate: its target already held by another track when it was confirmed */
            for (size_t e = 0; e < n_er; e++)
                if (er[e].scan == r->confirm && er[e].target == best && er[e].id != i + 1) {
                    n_dup++;
                    break;
                }
            const long last = r->end ? r->end : scans;
            if (last > last_end[best]) last_end[best] = last;
        } else {
            n_false++;
            false_scans += r->n_conf;
        }
    }
    /* per target: scans held (a confirmed track on it), and losses: held -> not
     * held for 3 scans or more while the target is there */
    for (int j = 0; j < N_TG; j++) {
        const long alive = tg_end[j] > 0 ? tg_end[j] : scans; /* tg_end < scans */
        long gap = 0;
        int was = 0;
        for (long k = 0; k < alive; k++) {
            const int h = held[k * N_TG + j];
            cover[j] += h;
            if (h) {
                was = 1;
                gap = 0;
            } else if (was && ++gap == 3) {
                n_lost[j]++;
                was = 0;
            }
        }
    }
    long lost_total = 0;
    for (int j = 0; j < N_TG; j++) lost_total += n_lost[j];
    free(held);
    /* RMSE: true tracks on their target, from 10 scans after confirmation */
    double sse = 0;
    long nse = 0;
    struct fileio_out fe_out;
    FILE *fe = sim_csv_open(&com, &fe_out, "/errors.csv", path, sizeof path, "scan,time_s,id,target,err_m,in_rmse");
    if (!fe) return 1;
    uint32_t prev_id = 0;
    for (size_t i = 0; i < n_er; i++) {
        const struct err_row *e = &er[i];
        if (major[e->id - 1] != e->target) continue;
        const int use = e->scan >= rec[e->id - 1].confirm + 10;
        if (use) sse += e->err * e->err, nse++;
        (void)prev_id;
        fprintf(fe, "%ld,%.1f,%u,%d,%.4f,%d\n", e->scan, (double)e->scan * dt, e->id, e->target, e->err, use);
    }
    if (sim_csv_close(&fe_out) != 0) return 1;
    const double rmse = nse ? sqrt(sse / (double)nse) : NAN;
    /* ---- the MRE's prediction (toc_curve.h: q2 of this scenario by importance sampling) */
    double mre[2] = {NAN, NAN};
    const double t_mre0 = progress_now_s();
    {
        const struct trk_amplitude *am = &rt.amp[0];
        struct toc_scenario ts;
        memset(&ts, 0, sizeof ts);
        toc_scenario_brekke(&ts, am->model, (double)am->nu, (double)am->snr_db, (double)am->pfa / lambda);
        ts.dt_s = dt;
        ts.q_m2_per_s3 = q;
        ts.r_m2 = sigma * sigma;
        ts.gate_gamma = (double)tk.pda[0].gamma;
        ts.pfa_min = (double)am->pfa / 1.5;
        ts.pfa_max = fmin((double)am->pfa * 1.5, 0.9);
        struct toc_q2_source src;
        memset(&src, 0, sizeof src);
        src.samples = (uint64_t)mre_samples;
        src.seed = com.seed;
        src.quiet = 1;
        src.par = com.par;
        struct toc *toc = toc_new(&ts, &src, err, sizeof err);
        struct toc_point pt;
        if (!toc || toc_point_at(toc, (double)am->pfa, &pt, err, sizeof err) != 0)
            fprintf(stderr, "trk-sim demo-amplitude: MRE prediction unavailable: %s\n", err);
        else
            mre[0] = pt.rmse_m[TOC_PDAF], mre[1] = pt.rmse_m[TOC_PDAFAI];
        toc_free(toc);
    }
    const double mre_s = progress_now_s() - t_mre0;
    /* ---- summary */
    struct fileio_out fs_out;
    FILE *fs = sim_csv_open(&com, &fs_out, "/summary.csv", path, sizeof path, "key,value");
    if (!fs) return 1;
    const struct trk_amplitude *am = &rt.amp[0];
    printf("\n== trk demo-amplitude: %ld sonar scans (%.0f s), 2 km x 2 km, seed %llu\n", scans, (double)scans * dt,
           (unsigned long long)com.seed);
    printf("   clutter: %.1f detections/scan, amplitudes %s (nu %g) -- heavy-tailed; threshold P_FA %g\n",
           clutter_per_scan, am->model == TRK_AMP_K ? "K-distributed" : "Rayleigh", (double)am->nu, (double)am->pfa);
    printf("   targets: %d (SNR %.0f dB, P_D %.3f%s)", N_TG, (double)am->snr_db, pd, fluct ? ", fading" : "");
    if (tg_end[3] > 0) printf(", one gone after scan %ld", tg_end[3]);
    printf("; position noise %g m\n", sigma);
    static const char *const conf_name[] = {"M-of-N", "SPRT", "clutter density test", "clutter amplitude test",
                                            "visibility", "existence (amplitude-aided IPDA)"};
    static const char *const term_name[] = {"K-of-N", "Page", "Shiryaev", "visibility", "existence"};
    printf("   tracker: PDAFAI (amplitude table %s), confirm by %s, terminate by %s, P_G %g, %d track slots\n",
           table_path, conf_name[cfg.confirm], term_name[cfg.term], (double)tp.gate_prob, TRK_MAX_TRACKS);
    printf("   detections: %ld (%.1f per scan)%s\n", n_det, (double)n_det / (double)scans,
           n_dropped ? " -- some dropped: more than TRK_MAX_DETECTIONS in a scan" : "");
    printf("-- tracks\n");
    printf("   started %ld tentative tracks, %ld merged duplicates, at most %ld of %d slots live\n", n_started, n_merged,
           max_live, TRK_MAX_TRACKS);
    if (n_refused)
        printf("   %ld initiations refused while the table was full of confirmed tracks or of stronger\n"
               "   tentative ones\n",
               n_refused);
    printf("   confirmed %ld: %ld on targets (%ld of them duplicates of a held target, merged or ended), %ld false "
           "(%ld confirmed scans in all)\n",
           n_conf, n_true, n_dup, n_false, false_scans);
    printf("   lost (a target without a confirmed track for 3+ scans after being held): %ld\n", lost_total);
    for (int j = 0; j < N_TG; j++) {
        const long alive = tg_end[j] > 0 ? tg_end[j] : scans; /* tg_end < scans */
        printf("   target %d: confirmed at scan %ld, held %.0f%% of its %ld scans, lost %ld times", j + 1, first_cover[j],
               100.0 * (double)cover[j] / (double)alive, alive, n_lost[j]);
        if (tg_end[j] > 0) {
            if (last_end[j] >= tg_end[j] && last_end[j] < scans)
                printf("; gone at scan %ld, its track ended %ld scans later", tg_end[j], last_end[j] - tg_end[j]);
            else
                printf("; gone at scan %ld, its track did not end", tg_end[j]);
        }
        printf("\n");
    }
    printf("-- accuracy (true tracks, from 10 scans after confirmation, %ld track-scans)\n", nse);
    printf("   position RMSE %.2f m; MRE prediction (Brekke eq 27): PDAFAI %.2f m, PDAF %.2f m\n", rmse, mre[1],
           mre[0]);
    printf("-- cost: %ld track updates in %.3f s of tracker time (%.3g updates/s); total %.1f s (MRE %.1f s)\n", updates,
           t_track, (double)updates / (t_track > 0 ? t_track : 1e-9), progress_now_s() - t_start, mre_s);
    fprintf(fs, "scans,%ld\nseed,%llu\nclutter_per_scan,%g\npd,%.6f\npfa,%g\nnu,%g\nsnr_db,%g\ntargets,%d\n", scans,
            (unsigned long long)com.seed, clutter_per_scan, pd, (double)am->pfa, (double)am->nu, (double)am->snr_db,
            N_TG);
    fprintf(fs, "detections,%ld\ndropped,%ld\n", n_det, n_dropped);
    fprintf(fs, "started,%ld\nrefused,%ld\nmerged,%ld\nconfirmed,%ld\ntrue,%ld\nduplicates,%ld\nfalse,%ld\nlost,%ld\n",
            n_started, n_refused, n_merged, n_conf, n_true, n_dup, n_false, lost_total);
    for (int j = 0; j < N_TG; j++)
        fprintf(fs, "target%d_confirm_scan,%ld\ntarget%d_held_scans,%ld\n", j + 1, first_cover[j], j + 1, cover[j]);
    fprintf(fs, "target4_end_delay_scans,%ld\nrmse_m,%.6g\nrmse_samples,%ld\nmre_pdafai_m,%.6g\nmre_pdaf_m,%.6g\n",
            tg_end[3] > 0 && last_end[3] >= tg_end[3] && last_end[3] < scans ? last_end[3] - tg_end[3] : -1, rmse, nse,
            mre[1], mre[0]);
    if (sim_csv_close(&fs_out) != 0) return 1;
    printf("   files: %s/{detections,truth,tracks,errors,summary}.csv%s\n", com.out,
           com.no_plot ? "" : ", demo_tracks.png, demo_error.png");
    const int plot_tracks = sim_plotf(&com, "/demo_tracks",
              "set datafile separator ','\nset size ratio -1\nset grid\n"
              "set key bottom right opaque box font ',9'\n"
              "set title 'trk demo: tracks over detections (%ld scans, K clutter nu %g, %.0f per scan)'\n"
              "set xlabel 'x (m)'\nset ylabel 'y (m)'\nset xrange [0:2000]\nset yrange [0:2000]\n"
              "plot '%s/detections.csv' every ::1 using 3:4 with dots lc rgb '#a0a0a0' title 'detections (all scans)', "
              "\\\n"
              "     '%s/truth.csv' every ::1 using ($8==1 ? $4 : NaN):5 with points pt 7 ps 0.9 lc rgb '#c8c8c8' "
              "title 'targets (truth)', \\\n"
              "     '%s/tracks.csv' every ::1 using ($11>=0 ? $5 : NaN):6:($3) with points pt 7 ps 0.25 lc variable "
              "title 'confirmed tracks on targets', \\\n"
              "     '%s/tracks.csv' every ::1 using ($11<0 ? $5 : NaN):6 with points pt 1 ps 0.7 lc rgb 'red' "
              "title 'confirmed, off target'\n",
              scans, (double)am->nu, clutter_per_scan, com.out, com.out, com.out, com.out);
    char mre_line[256] = "";
    if (isfinite(mre[1]))
        snprintf(mre_line, sizeof mre_line,
                 ", \\\n     %.6g with lines lw 2 lc rgb '#d62728' title 'MRE prediction %.2f m (PDAFAI)'", mre[1],
                 mre[1]);
    const int plot_error = sim_plotf(&com, "/demo_error",
              "set datafile separator ','\nset grid\nset key top right opaque box\n"
              "set title 'trk demo: position error of the tracks on targets'\n"
              "set xlabel 'time (s)'\nset ylabel 'position error (m)'\nset yrange [0:*]\n"
              "plot '%s/errors.csv' every ::1 using 2:5:($3) with points pt 7 ps 0.4 lc variable title 'track error', "
              "\\\n"
              "     %.6g with lines lw 2 dt 2 lc rgb 'black' title 'RMSE %.2f m (measured)'%s\n",
              com.out, isnan(rmse) ? 0 : rmse, isnan(rmse) ? 0 : rmse, mre_line);
    free(major);
    free(rec);
    free(er);
    tcfg_unload(&rt);
    scen_free(&sc);
    return plot_tracks < 0 || plot_error < 0 ? 1 : 0; /* a .gp script not written */
}
