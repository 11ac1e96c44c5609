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
        fprintf(stderr, "clutter-null: --theta must exceed --a-min\n");
        return 2;
    }
    static struct trk_clutter_chi2_model chi_m;
    static struct trk_clutter_amp_model amp_m;
    const struct trk_clutter_chi2_params cp = {(trk_real)alpha, (unsigned)kmax};
    const struct trk_clutter_amp_params ap = {(trk_real)a_min, (trk_real)alpha, (unsigned)kmax};
    trk_status st = trk_clutter_chi2_model_init(&chi_m, &cp);
    if (st == TRK_OK) st = trk_clutter_amp_model_init(&amp_m, &ap);
    if (st != TRK_OK) {
        fprintf(stderr, "clutter-null: %s\n", trk_status_str(st));
        return 2;
    }
    /* counts per update: raw rejections and sticky decisions of both tests */
    static long rej_c[MAX_SCANS], rej_a[MAX_SCANS], dec_c[MAX_SCANS], dec_a[MAX_SCANS];
    long redrawn = 0, overflow = 0;
    const int threads = sim_threads(&com);
    if (!com.quiet)
        fprintf(stderr, "clutter-null: %ld tracks x %ld updates, alpha %g, kmax %ld, %g peaks/scan, seed %llu, %d threads\n",
            runs, scans, alpha, kmax, mean_peaks, (unsigned long long)com.seed, threads);
    struct sim_progress pr;
    sim_progress_start(&pr, &com, "clutter-null", runs);
#pragma omp parallel
    {
        long lc[MAX_SCANS] = {0}, la[MAX_SCANS] = {0}, ldc[MAX_SCANS] = {0}, lda[MAX_SCANS] = {0};
        long lred = 0, lover = 0;
        trk_real *others = malloc(sizeof(trk_real) * MAX_PEAKS);
        struct trk_clutter_chi2 *chi = malloc(sizeof *chi);
        struct trk_clutter_amp *amp = malloc(sizeof *amp);
        if (!others || !chi || !amp) abort();
#pragma omp for schedule(dynamic, 256)
        for (long run = 0; run < runs; run++) {
            struct rng r;
            rng_init(&r, com.seed, (uint64_t)run);
            trk_clutter_chi2_reset(&chi_m, chi);
            trk_clutter_amp_reset(&amp_m, amp);
            for (long t = 0; t < scans; t++) {
                unsigned long n;
                while ((n = rng_poisson(&r, mean_peaks)) == 0) lred++;
                if (n > MAX_PEAKS - 1) { /* not seen at sane means */
                    n = MAX_PEAKS - 1;
                    lover++;
                }
                if (n - 1 > TRK_MAX_DETECTIONS) {
                    n = TRK_MAX_DETECTIONS + 1;
                    lover++;
                }
                double dmin = 2;
                unsigned long imin = 0;
                for (unsigned long i = 0; i < n; i++) {
                    const double d2 = rng_uniform(&r); /* (r/R)^2 of a uniform point */
                    others[i] = (trk_real)(a_min + (theta - a_min) * rng_exp(&r));
                    if (d2 < dmin) dmin = d2, imin = i;
                }
                const trk_real a_assoc = others[imin];
                others[imin] = others[n - 1];
                enum trk_decision dc, da;
                if (trk_clutter_chi2_step(&chi_m, chi, (trk_real)(mean_peaks * dmin), &dc) != TRK_OK ||
                    trk_clutter_amp_step(&amp_m, amp, a_assoc, n - 1, others, &da) != TRK_OK)
                    abort();
                lc[t] += chi->reject;
                la[t] += amp->reject;
                ldc[t] += dc == TRK_DECISION_CONFIRM;
                lda[t] += da == TRK_DECISION_CONFIRM;
            }
            sim_progress_add(&pr, 1);
        }
#pragma omp critical(sim_reduce)
        { /* integer sums: the same for any thread count */
            for (long t = 0; t < scans; t++) {
                rej_c[t] += lc[t];
                rej_a[t] += la[t];
                dec_c[t] += ldc[t];
                dec_a[t] += lda[t];
            }
            redrawn += lred;
            overflow += lover;
        }
        free(others);
        free(chi);
        free(amp);
    }
    const double wall = sim_progress_end(&pr);
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
