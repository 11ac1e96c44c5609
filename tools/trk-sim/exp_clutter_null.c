/* exp_clutter_null.c - trk-sim clutter-null: size of Kennedy's clutter tests
 * under their null hypothesis (Kennedy 2008 sec. 1.2-1.4): a tentative track
 * updated by pure clutter must be confirmed at each update with probability
 * alpha, whatever the window length K.
 *
 * Each scan: a Poisson(mean_peaks) number of clutter peaks, uniform in the
 * validation region around the predicted position (a disc holding mean_peaks
 * peaks on average; for an isotropic S = s I the Mahalanobis ordering is the
 * Euclidean one and V_g = pi D^2 sqrt|S| = pi r^2, so rho V_g = mean_peaks *
 * (r/R)^2 with (r/R)^2 uniform on (0, 1) for a uniform point in the disc);
 * the track is updated with the nearest peak (eqs 4-9). Peak SNRs (dB) are
 * a_min + (theta - a_min) Exp(1) (eq 11); the nearest peak's is a_assoc, the
 * others' are the scan's other peaks (N_k = number of peaks - 1, varying per
 * scan). A scan with no peak at all (probability e^-mean_peaks) is drawn
 * again (counted). The library's trk_clutter_chi2_step / trk_clutter_amp_step
 * run the tests; per update t the raw rejections (not the sticky decision)
 * are counted over the runs and compared with the exact two-sided 99 %
 * acceptance interval of Binomial(runs, alpha). The sticky decision's
 * cumulative rate (the false-track confirmation probability by update t)
 * is reported too: it grows past alpha because every update is a new test. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "rng.h"
#include "sim.h"
#include "trk/clutter_test.h"

#define MAX_SCANS 1000
#define MAX_PEAKS 4096

/* Exact two-sided acceptance interval [lo, hi] of Binomial(n, p) at level
 * 1 - 2 tail: P(X < lo) <= tail, P(X > hi) <= tail. */
static void binom_interval(long n, double p, double tail, long *lo, long *hi)
{
    const double ln1 = lgamma((double)n + 1), lp = log(p), lq = log1p(-p);
    double cdf = 0;
    *lo = 0;
    *hi = n;
    int have_lo = 0;
    for (long k = 0; k <= n; k++) {
        const double pmf =
            exp(ln1 - lgamma((double)k + 1) - lgamma((double)(n - k) + 1) + (double)k * lp +
                (double)(n - k) * lq);
        if (!have_lo && cdf + pmf > tail) { /* P(X < k) <= tail < P(X <= k) */
            *lo = k;
            have_lo = 1;
        }
        cdf += pmf;
        if (cdf >= 1 - tail) { /* P(X > k) <= tail */
            *hi = k;
            return;
        }
    }
}

/* Work units: blocks of CN_BLOCK runs. A block's result: per update t the
 * counts rej_c, rej_a, dec_c, dec_a (scans longs each), then redrawn and
 * overflow: integer sums, the same for any split. */
#define CN_BLOCK 256

struct cn_units {
    const struct trk_clutter_chi2_model *chi_m;
    const struct trk_clutter_amp_model *amp_m;
    long runs, scans;
    uint64_t seed;
    double mean_peaks, a_min, theta;
};

struct cn_ws {
    trk_real others[MAX_PEAKS];
    struct trk_clutter_chi2 chi;
    struct trk_clutter_amp amp;
};

/* 0, or 1 (no memory), 2 (a test refused a step) */
static int cn_unit(void *ctx, size_t blk, void *res, void **wsp)
{
    const struct cn_units *u = ctx;
    struct cn_ws *ws = *wsp;
    if (!ws && !(ws = *wsp = malloc(sizeof *ws))) return 1;
    const long scans = u->scans;
    long *lc = res, *la = lc + scans, *ldc = la + scans, *lda = ldc + scans, *lred = lda + scans,
         *lover = lred + 1;
    memset(res, 0, (4 * (size_t)scans + 2) * sizeof(long));
    const long r0 = (long)blk * CN_BLOCK, r1 = r0 + CN_BLOCK < u->runs ? r0 + CN_BLOCK : u->runs;
    for (long run = r0; run < r1; run++) {
        struct rng r;
        rng_init(&r, u->seed, (uint64_t)run);
        trk_clutter_chi2_reset(u->chi_m, &ws->chi);
        trk_clutter_amp_reset(u->amp_m, &ws->amp);
        for (long t = 0; t < scans; t++) {
            unsigned long n;
            while ((n = rng_poisson(&r, u->mean_peaks)) == 0) ++*lred;
            if (n > MAX_PEAKS - 1) { /* not seen at sane means */
                n = MAX_PEAKS - 1;
                ++*lover;
            }
            if (n - 1 > TRK_MAX_DETECTIONS) {
                n = TRK_MAX_DETECTIONS + 1;
                ++*lover;
            }
            double dmin = 2;
            unsigned long imin = 0;
            for (unsigned long i = 0; i < n; i++) {
                const double d2 = rng_uniform(&r); /* (r/R)^2 of a uniform point */
                ws->others[i] = (trk_real)(u->a_min + (u->theta - u->a_min) * rng_exp(&r));
                if (d2 < dmin) dmin = d2, imin = i;
            }
            const trk_real a_assoc = ws->others[imin];
            ws->others[imin] = ws->others[n - 1];
            enum trk_decision dc, da;
            if (trk_clutter_chi2_step(u->chi_m, &ws->chi, (trk_real)(u->mean_peaks * dmin), &dc) != TRK_OK ||
                trk_clutter_amp_step(u->amp_m, &ws->amp, a_assoc, n - 1, ws->others, &da) != TRK_OK)
                return 2;
            lc[t] += ws->chi.reject;
            la[t] += ws->amp.reject;
            ldc[t] += dc == TRK_DECISION_CONFIRM;
            lda[t] += da == TRK_DECISION_CONFIRM;
        }
    }
    return 0;
}

static void cn_ws_free(void *ctx, void *ws)
{
    (void)ctx;
    free(ws);
}

SIM_EXPERIMENT(clutter_null, "clutter-null", "Kennedy 2008: null rejection rate of the clutter density and amplitude tests")
{
    long runs, scans, kmax;
    double alpha, mean_peaks, a_min, theta;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "100000", SIM_GE, 1, 0, "tracks"),
        SIM_OPT_LONG("--scans", &scans, "N", "40", SIM_IN, 1, MAX_SCANS, "updates per track"),
        SIM_OPT_DOUBLE("--alpha", &alpha, "A", "0.01", SIM_OPEN, 0, 1, "size of both tests"),
        SIM_OPT_LONG("--kmax", &kmax, "K", "25", SIM_IN, 1, TRK_CLUTTER_KMAX, "window, as Kennedy's"),
        SIM_OPT_DOUBLE("--clutter-count", &mean_peaks, "M", "30", SIM_IN, 2, 1000,
                       "expected clutter peaks per scan in the region"),
        SIM_OPT_ALIAS("--mean-peaks", "--clutter-count"),
        SIM_OPT_DOUBLE("--a-min", &a_min, "DB", "5", 0, 0, 0, "detection threshold SNR"),
        SIM_OPT_DOUBLE("--theta", &theta, "DB", "8", 0, 0, 0, "mean clutter SNR above threshold, theta_A"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "clutter-null", NULL,
        "Rejection rate of Kennedy's clutter density (chi-square) and clutter amplitude (F)\n"
        "tests on tracks updated by pure clutter, per update t (window K = min(t, kmax)),\n"
        "against the exact 99% binomial interval of alpha.",
        opts, "clutter_null", NULL, 0, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (!(theta > a_min)) {
        fprintf(stderr, "trk-sim clutter-null: --theta must exceed --a-min\n");
        return 2;
    }
    static struct trk_clutter_chi2_model chi_m;
    static struct trk_clutter_amp_model amp_m;
    const struct trk_clutter_chi2_params cp = {(trk_real)alpha, (unsigned)kmax};
    const struct trk_clutter_amp_params ap = {(trk_real)a_min, (trk_real)alpha, (unsigned)kmax};
    trk_status st = trk_clutter_chi2_model_init(&chi_m, &cp);
    if (st == TRK_OK) st = trk_clutter_amp_model_init(&amp_m, &ap);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim clutter-null: %s\n", ERRMSG_STATUS(st));
        return 2;
    }
    /* counts per update: raw rejections and sticky decisions of both tests */
    static long rej_c[MAX_SCANS], rej_a[MAX_SCANS], dec_c[MAX_SCANS], dec_a[MAX_SCANS];
    long redrawn = 0, overflow = 0;
    const int threads = sim_threads(&com);
    if (!com.quiet)
        fprintf(stderr, "trk-sim clutter-null: %ld tracks x %ld updates, alpha %g, kmax %ld, %g peaks/scan, seed %llu, %d threads\n",
            runs, scans, alpha, kmax, mean_peaks, (unsigned long long)com.seed, threads);
    /* blocks of runs as work units, their counts summed in block order */
    const struct cn_units cu = {&chi_m, &amp_m, runs, scans, com.seed, mean_peaks, a_min, theta};
    const size_t nblk = (size_t)((runs + CN_BLOCK - 1) / CN_BLOCK), bsize = (4 * (size_t)scans + 2) * sizeof(long);
    long *blocks = malloc(nblk * bsize);
    if (!blocks) {
        fprintf(stderr, "trk-sim clutter-null: out of memory\n");
        return 1;
    }
    double wall;
    const int urc = sim_run_units(&com, "clutter-null", nblk, bsize, 1, cn_unit, cn_ws_free, (void *)&cu, blocks,
                                  &wall, NULL);
    if (urc == 1) fprintf(stderr, "trk-sim clutter-null: out of memory, or a clutter test refused a step\n");
    if (urc != 0) {
        free(blocks);
        return 1;
    }
    for (size_t k = 0; k < nblk; k++) {
        const long *b = (const long *)((const unsigned char *)blocks + k * bsize);
        for (long t = 0; t < scans; t++) {
            rej_c[t] += b[t];
            rej_a[t] += b[scans + t];
            dec_c[t] += b[2 * scans + t];
            dec_a[t] += b[3 * scans + t];
        }
        redrawn += b[4 * scans];
        overflow += b[4 * scans + 1];
    }
    free(blocks);
    long lo, hi;
    binom_interval(runs, alpha, 0.005, &lo, &hi);
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# clutter-null: per update t, rejections of H0 (track on clutter) over runs");
    if (!f) return 1;
    fprintf(f, "# runs %ld alpha %g kmax %ld mean_peaks %g a_min %g theta %g seed %llu; 99%% binomial interval [%ld, %ld]\n",
            runs, alpha, kmax, mean_peaks, a_min, theta, (unsigned long long)com.seed, lo, hi);
    fprintf(f, "t,K,chi2_rejects,chi2_rate,amp_rejects,amp_rate,lo_rate,hi_rate,chi2_in,amp_in,chi2_confirmed,amp_confirmed\n");
    int out_c = 0, out_a = 0;
    long sum_c = 0, sum_a = 0;
    for (long t = 0; t < scans; t++) {
        const int in_c = rej_c[t] >= lo && rej_c[t] <= hi, in_a = rej_a[t] >= lo && rej_a[t] <= hi;
        out_c += !in_c;
        out_a += !in_a;
        sum_c += rej_c[t];
        sum_a += rej_a[t];
        fprintf(f, "%ld,%ld,%ld,%.6g,%ld,%.6g,%.6g,%.6g,%d,%d,%.6g,%.6g\n", t + 1,
                t + 1 < kmax ? t + 1 : kmax, rej_c[t], (double)rej_c[t] / (double)runs, rej_a[t],
                (double)rej_a[t] / (double)runs, (double)lo / (double)runs, (double)hi / (double)runs,
                in_c, in_a, (double)dec_c[t] / (double)runs, (double)dec_a[t] / (double)runs);
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("# clutter-null: %ld tracks x %ld updates, alpha %g, kmax %ld, %.1f s wall, %d threads\n", runs,
           scans, alpha, kmax, wall, threads);
    printf("# exact 99%% interval of Binomial(%ld, %g): [%ld, %ld] = rate [%.5f, %.5f]\n", runs, alpha,
           lo, hi, (double)lo / (double)runs, (double)hi / (double)runs);
    printf("%5s %4s %10s %10s %12s %12s\n", "t", "K", "chi2 rate", "F rate", "chi2 conf<=t", "F conf<=t");
    for (long t = 0; t < scans; t++) {
        if (!(t < 5 || t + 1 == 10 || t + 1 == kmax || t + 1 == scans || t + 1 == kmax + 1)) continue;
        printf("%5ld %4ld %10.5f%s %10.5f%s %12.4f %12.4f\n", t + 1, t + 1 < kmax ? t + 1 : kmax,
               (double)rej_c[t] / (double)runs, rej_c[t] >= lo && rej_c[t] <= hi ? " " : "*",
               (double)rej_a[t] / (double)runs, rej_a[t] >= lo && rej_a[t] <= hi ? " " : "*",
               (double)dec_c[t] / (double)runs, (double)dec_a[t] / (double)runs);
    }
    printf("# mean rate over all updates: chi2 %.5f, F %.5f (alpha %g)\n",
           (double)sum_c / (double)runs / (double)scans, (double)sum_a / (double)runs / (double)scans, alpha);
    printf("# updates outside the 99%% interval: chi2 %d of %ld, F %d of %ld (about 1%% expected by chance)\n",
           out_c, scans, out_a, scans);
    if (redrawn || overflow)
        printf("# empty scans redrawn: %ld; scans truncated to capacity: %ld\n", redrawn, overflow);
    printf("# file: %s\n", path);
    sim_plotf(&com, "",
              "set datafile separator ','\n"
              "set title 'Clutter tests under H0 (track on clutter): %ld tracks, alpha %g, Kmax %ld'\n"
              "set xlabel 'update t (window K = min(t, Kmax))'\nset ylabel 'rejection rate of H0'\n"
              "set grid\nset key top left\nset yrange [%g:%g]\n"
              "plot '%s' using 1:7 with lines dt 2 lc rgb '#888888' title '99%% binomial interval', \\\n"
              "     '%s' using 1:8 with lines dt 2 lc rgb '#888888' notitle, \\\n"
              "     '%s' using 1:4 with linespoints pt 7 lc rgb '#1f77b4' title 'density test (chi2)', \\\n"
              "     '%s' using 1:6 with linespoints pt 5 lc rgb '#d62728' title 'amplitude test (F)'\n",
              runs, alpha, kmax, 0.9 * (double)lo / (double)runs, 1.1 * (double)hi / (double)runs,
              path, path, path, path);
    return 0;
}
