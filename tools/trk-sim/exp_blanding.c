/* exp_blanding.c - trk-sim blanding-add-arl: operating characteristics of the
 * track terminators K/N, Page and Shiryaev under the fluctuating-SNR detection
 * model (Blanding, Willett, Bar-Shalom, ICASSP 2007, sec. 3.3, Table 1, Fig. 2;
 * Willett lecture notes II.C.3, Table II, Fig. 10).
 *
 * Model (the detection process alone, as the paper's "model-based results"):
 *   Ns = 4 sensors looked at in turn, one scan every T/Ns = 15 s (scan cycle
 *   T = 60 s; Willett: "measurements arrive sequentially at an interval of
 *   T/Ns"). Each sensor has its own two-state Markov detection state (p = 1/30
 *   low->high, q = 0.1 high->low per look, P_D 0.1 / 0.9), drawn from the
 *   stationary law at its first look.
 *   The gate's P_FA follows the track covariance: per axis a CV Kalman filter
 *   (q~ = 1e-4 m^2/s^3, R = (243.2 m)^2), started from single-point
 *   initiation P = diag(R, (1 m/s)^2) (Willett Table II's prior velocity
 *   uncertainty), predicted 15 s to each look, updated on each detection;
 *   V = gamma pi sqrt|S|, gamma = -2 ln(1 - P_G), P_G = 0.99; P_FA = 1 -
 *   exp(-lambda V), lambda = 3.14e-8 m^-2 (Blanding eqs 3-4). This model
 *   reproduces the P_FA columns of the 4-sensor cases of tracktests.vec to
 *   5e-16.
 *   H1 (true track): a look detects with P_D of the sensor's current state
 *   (the paper's f1: no false alarm under H1). H0 (false track): a look
 *   detects with the gate's P_FA. The tests run the paper's event model too
 *   (hmm.events = TRK_EVENTS_PAPER, Blanding eq 8 as printed; the library's
 *   default is the complete model, docs/conventions.md "Complete detection-event
 *   model"), so that the paper's figures are reproduced.
 *   Every test starts with its initial statistic at the first look after
 *   initiation (Page c_0 = 0, Shiryaev g_0 = logit beta0 with beta0 = 0.5,
 *   rho = 0.005, K/N empty window) and runs on the same detection sequence
 *   (common random numbers). As in the paper, runs under H0 give the false
 *   track life (ADD), runs under H1 the true track life (ARL), both from the
 *   first look. A run is stopped at --max-scans; a test that has not fired by
 *   then is censored (counted at the cap: its mean is a lower bound and the
 *   CSV says how many runs were censored).
 *   One run evaluates every threshold of a test at once: the statistics do
 *   not depend on the threshold, and the first passage over a larger
 *   threshold is never earlier.
 * The library's own step functions run the tests (trk_page_step,
 * trk_shiryaev_step, trk_kn_step) and the covariance (trk_kalman_predict /
 * trk_kalman_update on one axis: R and P are isotropic, so the 2-D S is
 * s I and sqrt|S| = s). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "trk/gate.h"
#include "errmsg.h"
#include "rng.h"
#include "sim.h"
#include "trk/hmm_detect.h"
#include "trk/kalman.h"
#include "trk/term_kn.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"

#define MAX_H 128
#define MAX_KN 2048 /* --kn-k full over the default windows: 1054 rules */

struct bl_cfg {
    /* Table 1 */
    int ns;
    double dt_s, p, q, pd_low, pd_high, lambda, r_m2, q_psd, pg, pv0, beta0, rho;
    double gamma;
    long max_scans;
    /* tests */
    int n_page, n_shir, n_kn;
    double h_page[MAX_H], h_shir[MAX_H];
    int kn_k[MAX_KN], kn_n[MAX_KN];
    struct trk_page_model page_m;     /* shared models; each run resets its states */
    struct trk_shiryaev_model shir_m;
    struct trk_kn_model kn_m[MAX_KN];
};

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

struct bl_units {
    const struct bl_cfg *c;
    long runs;
    uint64_t seed;
};

static void run_one(const struct bl_cfg *c, int h1, uint64_t seed, uint64_t stream, uint32_t *out);

/* unit i < runs: H1 run i; i >= runs: H0 run i - runs. Stream = (hypothesis, run). */
static int bl_unit(void *ctx, size_t i, void *res, void **ws)
{
    const struct bl_units *u = ctx;
    (void)ws;
    const int h1 = (long)i < u->runs;
    const uint64_t run = (uint64_t)(h1 ? (long)i : (long)i - u->runs);
    run_one(u->c, h1, u->seed, (h1 ? 0x100000000ull : 0x200000000ull) | run, res);
    return 0;
}

/* One run under H0 (h1 = 0) or H1: first-passage look of every threshold
 * (0 = censored). */
static void run_one(const struct bl_cfg *c, int h1, uint64_t seed, uint64_t stream, uint32_t *out)
{
    struct rng r;
    rng_init(&r, seed, stream);
    uint32_t *o_page = out, *o_shir = out + c->n_page, *o_kn = out + c->n_page + c->n_shir;
    memset(out, 0, sizeof *out * (size_t)(c->n_page + c->n_shir + c->n_kn));
    /* one axis of the CV filter: state [x, vx], measurement x */
    const trk_real dt = (trk_real)c->dt_s;
    const trk_real f[4] = {1, dt, 0, 1};
    const trk_real qm[4] = {(trk_real)(c->q_psd * c->dt_s * c->dt_s * c->dt_s / 3),
                            (trk_real)(c->q_psd * c->dt_s * c->dt_s / 2),
                            (trk_real)(c->q_psd * c->dt_s * c->dt_s / 2),
                            (trk_real)(c->q_psd * c->dt_s)};
    const trk_real hm[2] = {1, 0}, rm[1] = {(trk_real)c->r_m2}, z[1] = {0};
    trk_real x[2] = {0, 0}, pm[4] = {(trk_real)c->r_m2, 0, 0, (trk_real)c->pv0};
    struct trk_page pg;
    struct trk_shiryaev sh;
    struct trk_kn kn[MAX_KN];
    trk_page_reset(&c->page_m, &pg);
    trk_shiryaev_reset(&c->shir_m, &sh);
    for (int j = 0; j < c->n_kn; j++) trk_kn_reset(&c->kn_m[j], &kn[j]);
    int u[16], seen[16] = {0};
    const double pi_high = c->p / (c->p + c->q);
    for (int i = 0; i < c->ns; i++) u[i] = rng_uniform(&r) < pi_high;
    int next_p = 0, next_s = 0, kn_left = c->n_kn;
    for (long t = 1; t <= c->max_scans; t++) {
        const int sensor = (int)((t - 1) % c->ns);
        if (trk_kalman_predict(2, f, qm, x, pm) != TRK_OK) abort();
        const trk_real s = pm[0] + rm[0];                       /* S per axis */
        const trk_real v = trk_gate_volume(2, (trk_real)c->gamma, 2 * trk_log(s)); /* eq 3: sqrt|S| = s */
        const trk_real pfa = trk_hmm_gate_pfa((trk_real)c->lambda * v); /* eq 4 */
        int det;
        if (h1) {
            if (seen[sensor]) { /* one Markov transition per look of this sensor */
                const double up = rng_uniform(&r);
                u[sensor] = u[sensor] ? up >= c->q : up < c->p;
            }
            seen[sensor] = 1;
            det = rng_uniform(&r) < (u[sensor] ? c->pd_high : c->pd_low);
        } else {
            det = rng_uniform(&r) < (double)pfa;
        }
        if (det && trk_kalman_update(2, 1, hm, rm, z, x, pm) != TRK_OK) abort();
        /* Page and Shiryaev are read against several thresholds through their
         * statistics; their own decisions (at the model's h) are not used */
        enum trk_decision dp, ds;
        if (trk_page_step(&c->page_m, &pg, (unsigned)sensor, det, pfa, &dp) != TRK_OK ||
            trk_shiryaev_step(&c->shir_m, &sh, (unsigned)sensor, det, pfa, &ds) != TRK_OK)
            abort();
        while (next_p < c->n_page && pg.stat > (trk_real)c->h_page[next_p]) o_page[next_p++] = (uint32_t)t;
        while (next_s < c->n_shir && sh.stat > (trk_real)c->h_shir[next_s]) o_shir[next_s++] = (uint32_t)t;
        for (int j = 0; j < c->n_kn; j++) {
            if (o_kn[j]) continue;
            enum trk_decision dk;
            if (trk_kn_step(&c->kn_m[j], &kn[j], det, &dk) != TRK_OK) abort();
            if (dk == TRK_DECISION_TERMINATE) {
                o_kn[j] = (uint32_t)t;
                kn_left--;
            }
        }
        if (next_p == c->n_page && next_s == c->n_shir && kn_left == 0) break;
    }
}

struct bl_point {
    double add, add_se, arl, arl_se; /* scan cycles */
    long cens0, cens1;
};

static void summarize(const uint32_t *res, long runs, int nt, int j, double cap, double ns,
                      struct bl_point *pt)
{
    double s[2] = {0, 0}, s2[2] = {0, 0};
    long cens[2] = {0, 0};
    for (int hyp = 0; hyp < 2; hyp++)
        for (long i = 0; i < runs; i++) { /* fixed order: thread-count independent */
            uint32_t v = res[((size_t)hyp * (size_t)runs + (size_t)i) * (size_t)nt + (size_t)j];
            double x = v ? (double)v : cap;
            if (!v) cens[hyp]++;
            s[hyp] += x;
            s2[hyp] += x * x;
        }
    double m[2], se[2];
    for (int hyp = 0; hyp < 2; hyp++) {
        m[hyp] = s[hyp] / (double)runs;
        double var = runs > 1 ? (s2[hyp] - (double)runs * m[hyp] * m[hyp]) / (double)(runs - 1) : 0;
        se[hyp] = sqrt(var > 0 ? var : 0) / sqrt((double)runs);
    }
    /* hyp 0 = H1 (ARL), hyp 1 = H0 (ADD) */
    pt->arl = m[0] / ns;
    pt->arl_se = se[0] / ns;
    pt->add = m[1] / ns;
    pt->add_se = se[1] / ns;
    pt->cens1 = cens[0];
    pt->cens0 = cens[1];
}

/* ARL at a given ADD by linear interpolation of ln ARL in ADD along a curve
 * sorted by ADD; NAN outside its range. */
static double arl_at(const double *add, const double *arl, int n, double a)
{
    for (int i = 0; i + 1 < n; i++)
        if (add[i] <= a && a <= add[i + 1] && add[i + 1] > add[i]) {
            double w = (a - add[i]) / (add[i + 1] - add[i]);
            return exp((1 - w) * log(arl[i]) + w * log(arl[i + 1]));
        }
    return NAN;
}

SIM_EXPERIMENT(blanding_add_arl, "blanding-add-arl", "Blanding 2007 Fig. 2: ADD vs ARL of K/N, Page, Shiryaev termination")
{
    static struct bl_cfg c;
    c.ns = 4;
    c.dt_s = 60.0 / 4;
    c.p = 0.1 / 3;
    c.q = 0.1;
    c.pd_low = 0.1;
    c.pd_high = 0.9;
    c.lambda = 3.14e-8;
    c.r_m2 = 243.2 * 243.2;
    c.q_psd = 1e-4;
    c.pg = 0.99;
    c.pv0 = 1.0;
    long runs;
    double kn_ns[64];
    static const int kn_k_values[] = {0, 1};
    int kn_k_full = 0;
    int n_kn_n, paper = 0; /* --paper: the default size (a --runs still wins): nothing to set */
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "10000", SIM_GE, 1, 0, "runs per hypothesis, as in the paper"),
        SIM_OPT_FLAG("--paper", &paper, "10000 runs per hypothesis (the default)"),
        SIM_OPT_LONG("--max-scans", &c.max_scans, "N", "20000", SIM_IN, 1, 100000000,
                     "censor a run after N looks (N/4 scan cycles)"),
        SIM_OPT_LIST("--page-h", c.h_page, &c.n_page, MAX_H, "0.5:6:0.25", 0, 0, 0, "Page thresholds"),
        SIM_OPT_LIST("--shir-h", c.h_shir, &c.n_shir, MAX_H, "-1:5:0.25", 0, 0, 0,
                     "Shiryaev thresholds on the log-odds"),
        SIM_OPT_LIST("--kn-n", kn_ns, &n_kn_n, 64, "4:64:2", 0, 0, 0, "K/N window lengths in scans"),
        SIM_OPT_CHOICE("--kn-k", &kn_k_full, "trimmed|full", kn_k_values, "trimmed",
                       "K of each window: N/16..N/3 (trimmed: smaller K give false-track\n"
                       "lives far beyond the plot and most of the run time), or 0..N-1"),
        SIM_OPT_DOUBLE("--beta0", &c.beta0, "B", "0.5", 0, 0, 0, "Shiryaev prior: P(change before the first look)"),
        SIM_OPT_DOUBLE("--rho", &c.rho, "R", "0.005", 0, 0, 0, "Shiryaev prior: per-look change probability"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "blanding-add-arl", NULL,
        "ADD (false-track life, H0) and ARL (true-track life, H1) in scan cycles of the\n"
        "K/N, Page and Shiryaev terminators, Blanding 2007 Table 1 (Ns = 4, T = 60 s,\n"
        "p = 1/30, q = 0.1, P_D 0.1/0.9, lambda 3.14e-8, R = 243.2^2, q = 1e-4, P_G 0.99).",
        opts, "blanding", NULL, 0,
        "Writes PREFIX.csv (every test point), PREFIX_front.csv (K/N upper envelope),\n"
        "PREFIX.gp and PREFIX.png (ADD vs ARL, log ARL).",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (c.ns > TRK_MAX_SENSORS) {
        fprintf(stderr, "trk-sim blanding-add-arl: needs %d sensors, this build has TRK_MAX_SENSORS %d\n",
                c.ns, TRK_MAX_SENSORS);
        return 2;
    }
    qsort(c.h_page, (size_t)c.n_page, sizeof(double), cmp_double);
    qsort(c.h_shir, (size_t)c.n_shir, sizeof(double), cmp_double);
    c.n_kn = 0;
    /* trimmed: K below N/16 only gives false-track lives far beyond the range
     * of interest (0/64 lives ~3000 cycles under H0) and would dominate the
     * run time; K above N/3 only true-track lives below the plot's */
    const char *kn_range = kn_k_full ? "K = 0..N-1" : "K = N/16..N/3";
    for (int a = 0; a < n_kn_n; a++) {
        int n = (int)kn_ns[a];
        const int k_lo = kn_k_full ? 0 : n / 16, k_hi = kn_k_full ? n - 1 : n / 3;
        for (int k = k_lo; k <= k_hi; k++) {
            if (c.n_kn == MAX_KN) {
                fprintf(stderr, "trk-sim blanding-add-arl: more than %d K/N rules (%s over --kn-n): fewer windows\n",
                        MAX_KN, kn_range);
                return 2;
            }
            c.kn_k[c.n_kn] = k;
            c.kn_n[c.n_kn] = n;
            c.n_kn++;
        }
    }
    c.gamma = -2 * log(1 - c.pg);
    /* test models (validated once; each run resets its own states) */
    struct trk_hmm_sensor_params sp = {(trk_real)c.p, (trk_real)c.q, (trk_real)c.pd_low,
                                       (trk_real)c.pd_high, TRK_HMM_PI0_STATIONARY};
    struct trk_page_params pp;
    trk_hmm_params_uniform(&pp.hmm, (unsigned)c.ns, &sp);
    pp.hmm.events = TRK_EVENTS_PAPER; /* the paper's eq 8, as reproduced here */
    pp.h = (trk_real)c.h_page[c.n_page - 1];
    struct trk_shiryaev_params shp;
    shp.hmm = pp.hmm;
    shp.beta0 = (trk_real)c.beta0;
    shp.rho = (trk_real)c.rho;
    shp.h = (trk_real)c.h_shir[c.n_shir - 1];
    trk_status st = trk_page_model_init(&c.page_m, &pp);
    if (st == TRK_OK) st = trk_shiryaev_model_init(&c.shir_m, &shp);
    for (int j = 0; j < c.n_kn && st == TRK_OK; j++) {
        struct trk_kn_params kp = {c.kn_k[j], c.kn_n[j]};
        st = trk_kn_model_init(&c.kn_m[j], &kp);
    }
    if (st != TRK_OK || !(c.h_page[0] > 0)) {
        fprintf(stderr, "trk-sim blanding-add-arl: invalid test parameters (%s)\n", ERRMSG_STATUS(st));
        return 2;
    }
    const int nt = c.n_page + c.n_shir + c.n_kn;
    uint32_t *res = malloc(sizeof *res * (size_t)nt * 2 * (size_t)runs);
    if (!res) {
        fprintf(stderr, "trk-sim blanding-add-arl: out of memory\n");
        return 1;
    }
    const int threads = sim_threads(&com);
    if (!com.quiet)
        fprintf(stderr,
            "blanding-add-arl: %ld runs per hypothesis, %d Page + %d Shiryaev thresholds, %d K/N "
            "rules (%s), cap %ld looks, seed %llu, %d threads\n",
            runs, c.n_page, c.n_shir, c.n_kn, kn_range, c.max_scans, (unsigned long long)com.seed, threads);
    /* every run a work unit (its nt first-passage looks in its slot) */
    struct bl_units bu = {&c, runs, com.seed};
    double wall;
    if (sim_run_units(&com, "blanding-add-arl", (size_t)(2 * runs), sizeof *res * (size_t)nt, 8, bl_unit, NULL,
                      &bu, res, &wall, NULL) != 0) {
        free(res);
        return 1;
    }

    /* ---------------------------------------------------------------- results */
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# blanding-add-arl: ADD (H0) and ARL (H1) in scan cycles of 4 looks; "
                           "censored = runs not terminated within max_scans (counted at the cap)");
    if (!f) return 1;
    fprintf(f, "# runs %ld seed %llu max_scans %ld beta0 %g rho %g\n", runs,
            (unsigned long long)com.seed, c.max_scans, c.beta0, c.rho);
    fprintf(f, "# K/N rules: %s (--kn-k %s) for each window N of --kn-n\n", kn_range,
            kn_k_full ? "full" : "trimmed");
    fprintf(f, "test,k,n,h,add_cycles,add_se,arl_cycles,arl_se,censored_h0,censored_h1\n");
    static struct bl_point pts[2 * MAX_H + MAX_KN];
    for (int j = 0; j < nt; j++)
        summarize(res, runs, nt, j, (double)c.max_scans, (double)c.ns, &pts[j]);
    for (int j = 0; j < nt; j++) {
        const struct bl_point *p = &pts[j];
        if (j < c.n_page)
            fprintf(f, "page,,,%.6g", c.h_page[j]);
        else if (j < c.n_page + c.n_shir)
            fprintf(f, "shiryaev,,,%.6g", c.h_shir[j - c.n_page]);
        else
            fprintf(f, "kn,%d,%d,", c.kn_k[j - c.n_page - c.n_shir], c.kn_n[j - c.n_page - c.n_shir]);
        fprintf(f, ",%.6g,%.3g,%.6g,%.3g,%ld,%ld\n", p->add, p->add_se, p->arl, p->arl_se, p->cens0,
                p->cens1);
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    /* K/N upper envelope: best ARL for an ADD no larger */
    static int order[MAX_KN];
    const struct bl_point *kp = pts + c.n_page + c.n_shir;
    for (int j = 0; j < c.n_kn; j++) order[j] = j;
    for (int a = 1; a < c.n_kn; a++) /* insertion sort by ADD */
        for (int b = a; b > 0 && kp[order[b]].add < kp[order[b - 1]].add; b--) {
            int tmp = order[b];
            order[b] = order[b - 1];
            order[b - 1] = tmp;
        }
    static double fr_add[MAX_KN], fr_arl[MAX_KN];
    static int fr_j[MAX_KN];
    int nfr = 0;
    double best = 0;
    for (int a = 0; a < c.n_kn; a++) {
        const struct bl_point *p = &kp[order[a]];
        if (p->arl > best) {
            best = p->arl;
            fr_add[nfr] = p->add;
            fr_arl[nfr] = p->arl;
            fr_j[nfr] = order[a];
            nfr++;
        }
    }
    f = sim_csv_open(&com, &f_out, "_front.csv", path, sizeof path, "k,n,add_cycles,arl_cycles");
    if (!f) return 1;
    for (int a = 0; a < nfr; a++)
        fprintf(f, "%d,%d,%.6g,%.6g\n", c.kn_k[fr_j[a]], c.kn_n[fr_j[a]], fr_add[a], fr_arl[a]);
    if (sim_csv_close(&f_out) != 0) return 1;

    /* stdout summary */
    printf("# blanding-add-arl: %ld runs per hypothesis, seed %llu, %.1f s wall, %d threads\n", runs,
           (unsigned long long)com.seed, wall, threads);
    printf("# ADD = mean false-track life (H0), ARL = mean true-track life (H1), scan cycles (4 looks)\n");
    printf("%-9s %10s %9s %8s %12s %10s %6s\n", "test", "param", "ADD", "+-", "ARL", "+-", "cens");
    for (int j = 0; j < c.n_page + c.n_shir; j++) {
        const struct bl_point *p = &pts[j];
        const int page = j < c.n_page;
        printf("%-9s h=%8.3g %9.3f %8.3f %12.1f %10.1f %6ld\n", page ? "page" : "shiryaev",
               page ? c.h_page[j] : c.h_shir[j - c.n_page], p->add, p->add_se, p->arl, p->arl_se,
               p->cens1);
    }
    for (int a = 0; a < nfr; a++) {
        const struct bl_point *p = &kp[fr_j[a]];
        printf("%-9s %4d/%-5d %9.3f %8.3f %12.1f %10.1f %6ld\n", "kn-front", c.kn_k[fr_j[a]],
               c.kn_n[fr_j[a]], p->add, p->add_se, p->arl, p->arl_se, p->cens1);
    }
    static double pa[MAX_H], pr_[MAX_H], sa[MAX_H], sr[MAX_H];
    for (int j = 0; j < c.n_page; j++) pa[j] = pts[j].add, pr_[j] = pts[j].arl;
    for (int j = 0; j < c.n_shir; j++) sa[j] = pts[c.n_page + j].add, sr[j] = pts[c.n_page + j].arl;
    printf("# ARL (scan cycles) at equal ADD (log-linear interpolation along each curve)\n");
    printf("%8s %12s %12s %12s\n", "ADD", "K/N front", "Page", "Shiryaev");
    const double adds[] = {2, 3, 4, 6, 8, 10, 12, 15, 20};
    int kn_beats_page = 0, kn_vs_page = 0, shir_best = 0, shir_cmp = 0;
    for (size_t a = 0; a < sizeof adds / sizeof adds[0]; a++) {
        double k = arl_at(fr_add, fr_arl, nfr, adds[a]);
        double p = arl_at(pa, pr_, c.n_page, adds[a]);
        double s = arl_at(sa, sr, c.n_shir, adds[a]);
        printf("%8.1f %12.1f %12.1f %12.1f\n", adds[a], k, p, s);
        if (adds[a] >= 4 && adds[a] <= 15) {
            if (!isnan(k) && !isnan(p)) kn_vs_page++, kn_beats_page += k > p;
            if (!isnan(k) && !isnan(p) && !isnan(s)) shir_cmp++, shir_best += s > k && s > p;
        }
    }
    printf("# paper: Shiryaev best over ADD 4-15 cycles: %d of %d points\n", shir_best, shir_cmp);
    printf("# paper: Page worse than K/N over ADD 4-15 cycles: %d of %d points\n", kn_beats_page,
           kn_vs_page);
    printf("# files: %s.csv %s_front.csv\n", com.out, com.out);

    sim_plotf(&com, "",
              "set datafile separator ','\n"
              "set title 'Track termination, Blanding 2007 Table 1 (%ld runs per hypothesis; K/N: %s)'\n"
              "set xlabel 'ADD: mean false-track life (scan cycles)'\n"
              "set ylabel 'ARL: mean true-track life (scan cycles)'\n"
              "set logscale y\nset grid\nset key left top\nset xrange [0:40]\n"
              "plot '%s.csv' using (strcol(1) eq 'kn' ? $5 : 1/0):7 with points pt 1 lc rgb '#bbbbbb' title 'K/N (%s)', \\\n"
              "     '%s_front.csv' using 3:4 with linespoints pt 7 lc rgb '#1f77b4' title 'K/N upper envelope', \\\n"
              "     '%s.csv' using (strcol(1) eq 'page' ? $5 : 1/0):7 with linespoints pt 5 lc rgb '#d62728' title 'Page', \\\n"
              "     '%s.csv' using (strcol(1) eq 'shiryaev' ? $5 : 1/0):7 with linespoints pt 9 lc rgb '#2ca02c' title 'Shiryaev (beta0 %g, rho %g)', \\\n"
              /* a point with censored runs is a lower bound (counted at the cap) */
              "     '%s.csv' using ($9 + $10 > 0 ? $5 : 1/0):7 with points pt 8 ps 2.2 lc rgb 'black' "
              "title 'censored runs: ADD/ARL a lower bound'\n",
              runs, kn_range, com.out, kn_range, com.out, com.out, com.out, c.beta0, c.rho, com.out);
    free(res);
    return 0;
}
