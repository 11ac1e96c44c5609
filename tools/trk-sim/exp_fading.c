/* exp_fading.c - trk-sim fading: the termination test's trade between keeping
 * a fading target's track and ending a vanished target's (Blanding et al.
 * 2007, Fig. 2: ADD against ARL), run through the whole tracker.
 *
 * One target in a square region with Poisson clutter, the tracker with the
 * defaults but for the termination test under study. A run starts with
 * --warmup scans at the target's normal P_D (the tracker's sensor P_D), then
 * takes the confirmed track nearest the target (within --near-m; a run
 * without one counts as not acquired) and, on the same random numbers:
 *   fade     the target's P_D drops to --pd-low for up to --scans scans: the
 *            run length is the number of faded scans the track lives through
 *            (its id still live and within --near-m of the target; censored
 *            at --scans): the ARL under a fade, which should be long
 *   vanish   the target is gone: the delay is the number of scans until the
 *            track's id ends (ADD), which should be short
 * Per test and threshold the mean run length and delay with 95 % intervals,
 * and the fraction of tracks that live through the whole fade.
 * Tests (each a threshold sweep): existence (the default method, p_terminate),
 * K/N with K = 0 (N consecutive misses), and the fluctuating-target tests of
 * Blanding 2007 (Page CUSUM and Shiryaev, with the two-state detection HMM of
 * --pd-high / --pd-low and its switching probabilities). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "mc_stats.h"
#include "rng.h"
#include "sim.h"
#include "trk/trk.h"

#define MAX_THRESH 16
#define N_METHODS 4

enum fd_method { FD_EXISTENCE = 0, FD_KN = 1, FD_PAGE = 2, FD_SHIRYAEV = 3 };
static const char *const method_name[N_METHODS] = {"existence", "kn", "page", "shiryaev"};

struct fd_setup {
    double region_m, speed_mps, dt_s, sigma_m, clutter_per_scan, pd_high, pd_low, near_m;
    double hmm_q, hmm_p;              /* HMM: P(high -> low), P(low -> high) per scan */
    long warmup, scans, runs;
    uint64_t seed;
    int n_thresh[N_METHODS];
    double thresh[N_METHODS][MAX_THRESH];
};

/* One unit: (method, threshold, run); both modes on the same numbers. */
struct fd_out {
    int32_t acquired;   /* 1: a confirmed track on the target after the warm-up */
    int32_t run_len;    /* fade: faded scans lived through (censored at scans) */
    int32_t delay;      /* vanish: scans until the track ended (censored at scans) */
};

static void params_for(const struct fd_setup *s, int method, double th, struct trk_tracker_params *p)
{
    trk_tracker_default_params(p);
    const double area = s->region_m * s->region_m;
    p->sensor[0].pd = (trk_real)s->pd_high;
    p->sensor[0].meas_cov_m2[TRK_COV2_XX] = p->sensor[0].meas_cov_m2[TRK_COV2_YY] = (trk_real)(s->sigma_m * s->sigma_m);
    p->sensor[0].clutter_density_per_m2 = (trk_real)(s->clutter_per_scan / area);
    memset(&p->term, 0, sizeof p->term);
    struct trk_hmm_sensor_params hs = {(trk_real)s->hmm_p, (trk_real)s->hmm_q, (trk_real)s->pd_low,
                                       (trk_real)s->pd_high, TRK_HMM_PI0_STATIONARY};
    switch (method) {
    case FD_EXISTENCE:
        p->term.method = TRK_TERM_EXISTENCE;
        p->term.u.existence.p_terminate = (trk_real)th;
        break;
    case FD_KN:
        p->term.method = TRK_TERM_KN;
        p->term.u.kn.k = 0;
        p->term.u.kn.n = (unsigned)th;
        break;
    case FD_PAGE:
        p->term.method = TRK_TERM_PAGE;
        trk_hmm_params_uniform(&p->term.u.page.hmm, 1, &hs);
        p->term.u.page.h = (trk_real)th;
        break;
    default:
        p->term.method = TRK_TERM_SHIRYAEV;
        trk_hmm_params_uniform(&p->term.u.shiryaev.hmm, 1, &hs);
        p->term.u.shiryaev.beta0 = TRK_REAL_C(1e-3);
        p->term.u.shiryaev.rho = TRK_REAL_C(1e-3);
        p->term.u.shiryaev.h = (trk_real)th;
        break;
    }
}

/* The target at scan k (straight through the centre, heading from the run). */
static void target_at(const struct fd_setup *s, double heading, long k, double *x, double *y)
{
    const double t = (double)k * s->dt_s - 0.5 * (double)(s->warmup + s->scans) * s->dt_s;
    *x = 0.5 * s->region_m + s->speed_mps * t * cos(heading);
    *y = 0.5 * s->region_m + s->speed_mps * t * sin(heading);
}

/* One scan: the target's detection with probability pd, Poisson clutter. */
static size_t make_scan(const struct fd_setup *s, struct rng *r, double tx, double ty, double pd,
                        struct trk_detection *d)
{
    size_t n = 0;
    if (rng_uniform(r) < pd) {
        d[n].x_m = (trk_real)(tx + s->sigma_m * rng_normal(r));
        d[n].y_m = (trk_real)(ty + s->sigma_m * rng_normal(r));
        n++;
    }
    for (unsigned long c = rng_poisson(r, s->clutter_per_scan); c > 0 && n < TRK_MAX_DETECTIONS; c--) {
        d[n].x_m = (trk_real)(s->region_m * rng_uniform(r));
        d[n].y_m = (trk_real)(s->region_m * rng_uniform(r));
        n++;
    }
    for (size_t i = 0; i < n; i++) d[i].has_cov = d[i].has_amplitude = 0;
    return n;
}

/* The live track with this id, or NULL. */
static const struct trk_track *find_id(const struct trk_tracker *t, uint32_t id)
{
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(t, i);
        if (tr && tr->id == id && (tr->status == TRK_TRACK_TENTATIVE || tr->status == TRK_TRACK_CONFIRMED))
            return tr;
    }
    return NULL;
}

struct fd_ws {
    struct trk_tracker tracker;
    struct trk_detection det[TRK_MAX_DETECTIONS];
};

struct fd_ctx {
    const struct fd_setup *s;
    size_t n_configs;
    int config_method[N_METHODS * MAX_THRESH];
    double config_thresh[N_METHODS * MAX_THRESH];
};

/* Warm up, then one mode (fade: pd_low, vanish: pd 0) from the same state:
 * the scans the track lives (censored at s->scans). -1: not acquired. */
static int run_mode(const struct fd_setup *s, const struct trk_tracker_params *p, struct fd_ws *w, uint32_t run,
                    int vanish, int32_t *scans_out)
{
    struct rng r;
    rng_init(&r, s->seed, run);
    const double heading = 2 * 3.14159265358979323846 * rng_uniform(&r);
    if (trk_tracker_init(&w->tracker, p) != TRK_OK) return -2;
    uint32_t id = 0;
    for (long k = 0; k < s->warmup + s->scans; k++) {
        double tx, ty;
        target_at(s, heading, k, &tx, &ty);
        const int after = k >= s->warmup;
        struct rng rk; /* the scan's own stream: both modes see the same clutter */
        rng_init(&rk, s->seed ^ 0x5bd1e995u, ((uint64_t)run << 24) | (uint64_t)k);
        const double pd = !after ? s->pd_high : vanish ? 0 : s->pd_low;
        struct trk_scan scan = {(int64_t)llround((double)k * s->dt_s * 1e6), 0, 0, w->det, NULL, 0, {0, 0, 0}, NULL};
        scan.n_detections = make_scan(s, &rk, tx, ty, pd, w->det);
        if (trk_tracker_process_scan(&w->tracker, &scan, NULL) != TRK_OK) return -2;
        if (k + 1 == s->warmup) { /* the confirmed track nearest the target */
            double best = s->near_m;
            for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
                const struct trk_track *tr = trk_tracker_track(&w->tracker, i);
                if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
                const double d = hypot((double)tr->x[TRK_CV2_X] - tx, (double)tr->x[TRK_CV2_Y] - ty);
                if (d <= best) best = d, id = tr->id;
            }
            if (!id) return -1;
        } else if (after) {
            const struct trk_track *tr = find_id(&w->tracker, id);
            const int held = tr && (vanish || hypot((double)tr->x[TRK_CV2_X] - tx,
                                                    (double)tr->x[TRK_CV2_Y] - ty) <= s->near_m);
            if (!held) {
                *scans_out = (int32_t)(k - s->warmup);
                return 0;
            }
        }
    }
    *scans_out = (int32_t)s->scans;
    return 0;
}

static int fd_unit(void *vctx, size_t i, void *res, void **wsp)
{
    const struct fd_ctx *c = vctx;
    const struct fd_setup *s = c->s;
    struct fd_out *o = res;
    if (!*wsp && !(*wsp = malloc(sizeof(struct fd_ws)))) return -1;
    struct fd_ws *w = *wsp;
    const size_t cfg = i / (size_t)s->runs;
    const uint32_t run = (uint32_t)(i % (size_t)s->runs);
    struct trk_tracker_params p;
    params_for(s, c->config_method[cfg], c->config_thresh[cfg], &p);
    int32_t fade = 0, delay = 0;
    int rc = run_mode(s, &p, w, run, 0, &fade);
    if (rc == -2) return -1;
    o->acquired = rc == 0;
    if (rc == 0 && run_mode(s, &p, w, run, 1, &delay) != 0) return -1;
    o->run_len = fade;
    o->delay = delay;
    return 0;
}

static void fd_ws_free(void *ctx, void *ws)
{
    (void)ctx;
    free(ws);
}

SIM_EXPERIMENT(fading, "fading", "Blanding 2007 Fig. 2 through the tracker: a fading target's track life vs delay")
{
    static struct fd_setup s;
    double th_ex[MAX_THRESH], th_kn[MAX_THRESH], th_page[MAX_THRESH], th_shir[MAX_THRESH];
    int n_ex, n_kn, n_page, n_shir;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &s.runs, "N", "200", SIM_GE, 1, 0, "runs per test and threshold"),
        SIM_OPT_LONG("--scans", &s.scans, "N", "100", SIM_IN, 1, 100000, "scans after the warm-up (the censoring)"),
        SIM_OPT_LONG("--warmup", &s.warmup, "N", "30", SIM_IN, 3, 100000, "scans at the normal P_D first"),
        SIM_OPT_DOUBLE("--pd-high", &s.pd_high, "P", "0.9", SIM_IN, 0.01, 0.999,
                       "the target's normal P_D (the tracker's sensor P_D)"),
        SIM_OPT_DOUBLE("--pd-low", &s.pd_low, "P", "0.3", SIM_IN, 0.001, 0.999, "the faded P_D"),
        SIM_OPT_DOUBLE("--clutter", &s.clutter_per_scan, "C", "20", SIM_GE, 0, 200, "clutter per scan in the region"),
        SIM_OPT_DOUBLE("--region-m", &s.region_m, "S", "3000", SIM_GT, 0, 0, "square region side"),
        SIM_OPT_DOUBLE("--sigma-m", &s.sigma_m, "S", "5", SIM_GT, 0, 0, "measurement noise per axis"),
        SIM_OPT_DOUBLE("--speed-mps", &s.speed_mps, "V", "8", SIM_GE, 0, 0, "target speed"),
        SIM_OPT_DOUBLE("--dt", &s.dt_s, "T", "4", SIM_GT, 0, 0, "scan interval (s)"),
        SIM_OPT_DOUBLE("--near-m", &s.near_m, "D", "50", SIM_GT, 0, 0,
                       "a track farther than this from the target is not its track"),
        SIM_OPT_DOUBLE("--hmm-q", &s.hmm_q, "Q", "0.05", SIM_IN, 0, 1, "the HMM tests: P(high -> low) per scan"),
        SIM_OPT_DOUBLE("--hmm-p", &s.hmm_p, "P", "0.2", SIM_IN, 0, 1, "the HMM tests: P(low -> high) per scan"),
        SIM_OPT_LIST("--existence", th_ex, &n_ex, MAX_THRESH, "0.3,0.1,0.03,0.01,0.003,0.001,1e-4,1e-5", SIM_OPEN, 0,
                     1, "existence p_terminate values"),
        SIM_OPT_LIST("--kn", th_kn, &n_kn, MAX_THRESH, "3,4,5,6,8,10,12,16", SIM_IN, 1, 64,
                     "K/N 0/N: N consecutive misses"),
        SIM_OPT_LIST("--page", th_page, &n_page, MAX_THRESH, "1,2,3,4,5,6,8,10", SIM_GT, 0, 0, "Page thresholds h"),
        SIM_OPT_LIST("--shiryaev", th_shir, &n_shir, MAX_THRESH, "-6,-5,-4,-3,-2,-1,0,2", 0, 0, 0,
                     "Shiryaev thresholds h (log-odds)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "fading", NULL,
        "A fading target (P_D --pd-high falling to --pd-low) against a vanished one, through the whole\n"
        "tracker: per termination test and threshold, the faded scans a track lives through (ARL, long\n"
        "is good) and the scans to end a vanished target's track (ADD, short is good).",
        opts, "fading", NULL, 0, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    s.seed = com.seed;
    const double *lists[N_METHODS] = {th_ex, th_kn, th_page, th_shir};
    const int counts[N_METHODS] = {n_ex, n_kn, n_page, n_shir};
    static struct fd_ctx ctx;
    ctx.s = &s;
    ctx.n_configs = 0;
    for (int m = 0; m < N_METHODS; m++)
        for (int j = 0; j < counts[m]; j++) {
            ctx.config_method[ctx.n_configs] = m;
            ctx.config_thresh[ctx.n_configs++] = lists[m][j];
            struct trk_tracker_params p;
            params_for(&s, m, lists[m][j], &p);
            const char *field;
            const trk_status st = trk_tracker_check_params(&p, &field);
            if (st != TRK_OK) {
                fprintf(stderr, "trk-sim fading: %s %g: parameter %s: %s\n", method_name[m], lists[m][j], field,
                        ERRMSG_STATUS(st));
                return 2;
            }
        }
    const size_t n_units = ctx.n_configs * (size_t)s.runs;
    struct fd_out *out = calloc(n_units, sizeof *out);
    double *v = malloc((size_t)s.runs * sizeof *v);
    if (!out || !v) return 1;
    sim_threads(&com);
    double wall;
    size_t failed;
    const int rc = sim_run_units(&com, cli.name, n_units, sizeof *out, 1, fd_unit, fd_ws_free, &ctx, out, &wall,
                                 &failed);
    if (rc != 0) {
        if (rc == 1) fprintf(stderr, "trk-sim fading: unit %zu failed (the tracker refused a scan or ran out of memory)\n", failed);
        return 1;
    }
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# fading: termination tests, faded-target run length (ARL) vs vanished-target delay (ADD)");
    if (!f) return 1;
    fprintf(f, "# P_D %g -> %g, %g clutter per scan in %g m square, sigma %g m, T %g s, %g m/s; warm-up %ld scans, "
               "%ld scans after (censoring); near %g m; HMM q %g p %g; seed %llu, %ld runs\n",
            s.pd_high, s.pd_low, s.clutter_per_scan, s.region_m, s.sigma_m, s.dt_s, s.speed_mps, s.warmup, s.scans,
            s.near_m, s.hmm_q, s.hmm_p, (unsigned long long)com.seed, s.runs);
    fprintf(f, "method,threshold,acquired,arl,arl_lo95,arl_hi95,held_frac,add,add_lo95,add_hi95,add_censored\n");
    printf("# fading: P_D %g -> %g; %g clutter/scan; %ld runs; ARL = faded scans lived (of %ld), ADD = scans to end a "
           "vanished target's track\n",
           s.pd_high, s.pd_low, s.clutter_per_scan, s.runs, s.scans);
    printf("%-10s %9s | %4s | %-22s %6s | %-20s\n", "test", "threshold", "acq", "ARL [95% CI]", "held", "ADD [95% CI]");
    for (size_t c = 0; c < ctx.n_configs; c++) {
        const struct fd_out *o = &out[c * (size_t)s.runs];
        size_t n = 0, held = 0, cens = 0;
        for (long r = 0; r < s.runs; r++)
            if (o[r].acquired) {
                v[n++] = o[r].run_len;
                held += o[r].run_len >= s.scans;
            }
        double arl = NAN, alo = NAN, ahi = NAN, add = NAN, dlo = NAN, dhi = NAN;
        if (n) mc_mean_ci(v, n, 0.95, &arl, &alo, &ahi);
        n = 0;
        for (long r = 0; r < s.runs; r++)
            if (o[r].acquired) {
                v[n++] = o[r].delay;
                cens += o[r].delay >= s.scans;
            }
        if (n) mc_mean_ci(v, n, 0.95, &add, &dlo, &dhi);
        printf("%-10s %9g | %4zu | %6.1f [%6.1f, %6.1f] %6.3f | %5.2f [%5.2f, %5.2f]%s\n",
               method_name[ctx.config_method[c]], ctx.config_thresh[c], n, arl, alo, ahi,
               n ? (double)held / (double)n : NAN, add, dlo, dhi, cens ? " (censored)" : "");
        fprintf(f, "%s,%g,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%zu\n", method_name[ctx.config_method[c]],
                ctx.config_thresh[c], n, arl, alo, ahi, n ? (double)held / (double)n : NAN, add, dlo, dhi, cens);
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("# wall %.1f s\n# file: %s\n", wall, path);
    sim_plotf(&com, "",
              "set datafile separator ','\nset grid\nset key bottom right\n"
              "set title \"Termination: faded-target run length vs vanished-target delay (P_D %g to %g, %g clutter/scan)\"\n"
              "set xlabel 'ADD: scans to end a vanished target''s track'\n"
              "set ylabel 'ARL: faded scans a track lives through (of %ld)'\n"
              "plot for [m in 'existence kn page shiryaev'] '%s' every ::1 using (strcol(1) eq m ? $8 : NaN):4 "
              "with linespoints pt 7 title m\n",
              s.pd_high, s.pd_low, s.clutter_per_scan, s.scans, path);
    free(out);
    free(v);
    return 0;
}
