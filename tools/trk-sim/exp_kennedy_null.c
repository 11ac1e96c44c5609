/* exp_kennedy_null.c - trk-sim kennedy-null: Kennedy 2008 sec. 4, Figs. 2-3:
 * the false-track confirmation count of the clutter-density and the
 * clutter-amplitude tests in the target-absent scenario with confirmation
 * applied on the last scan only, for runs of 2 .. 50 scans, against
 * alpha x runs (about 0.01 x 1000 = 10 on every scan length).
 *
 * Each run (single_target.h, kn_run): Kennedy's surveillance region
 * (10-20 km x 100-200 km) with exactly N_s = 100 clutter peaks per scan,
 * uniform, SNR a_min + (theta - a_min) Exp(1) dB (a_min 5 dB, theta 10 dB);
 * scan 1 starts a tentative track on a random peak, scans 2..n update it
 * with the library's PDA (gate P_G 0.99 instead of Kennedy's 4 nearest
 * peaks) and run both tests (trk_clutter_chi2_step, trk_clutter_amp_step;
 * K = min(t, 25), alpha 0.01) on the nearest peak; the decision is read at
 * scan n only. Every scan length has its own independent runs, as in the
 * paper. The test statistics are exact under H0 for a homogeneous Poisson
 * field around the track; edge effects (the prediction leaves the region:
 * its nearest peak is farther than the density predicts, the count falls)
 * and a fixed N_s (binomial, not Poisson, peaks) make it approximate, as
 * Kennedy notes (--torus removes the edges). Kennedy's measurement noise
 * factor b = 1/50. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mc_stats.h"
#include "sim.h"
#include "single_target.h"

struct kn_out {
    unsigned char chi2, amp, chi2_ever, amp_ever, outside, failed;
};

struct kn_units {
    const struct kn_model *model;
    long runs;
};

/* unit it: run length 2 + it / runs, run it % runs */
static int kn_unit(void *ctx, size_t it, void *res, void **ws)
{
    const struct kn_units *u = ctx;
    (void)ws;
    const long n = 2 + (long)it / u->runs, run = (long)it % u->runs;
    struct kn_result r;
    kn_run(u->model, n, (uint32_t)n, (uint32_t)run, &r);
    struct kn_out *o = res;
    o->chi2 = (unsigned char)r.chi2_reject;
    o->amp = (unsigned char)r.amp_reject;
    o->chi2_ever = (unsigned char)r.chi2_ever;
    o->amp_ever = (unsigned char)r.amp_ever;
    o->outside = (unsigned char)r.outside;
    o->failed = (unsigned char)r.failed;
    return 0;
}

SIM_EXPERIMENT(kennedy_null, "kennedy-null", "Kennedy 2008 Figs. 2-3: false-track confirmations on the last scan vs alpha")
{
    long runs, max_scans, peaks, kmax;
    double alpha, b;
    int torus = 0;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "1000", SIM_IN, 1, 4294967295.0,
                     "runs per scan length, as in the paper (a 32-bit run index)"),
        SIM_OPT_LONG("--max-scans", &max_scans, "N", "50", SIM_IN, 2, 100000, "run lengths 2 .. N"),
        SIM_OPT_LONG("--clutter-count", &peaks, "N", "100", SIM_GE, 2, 0,
                     "clutter peaks per scan (at most TRK_MAX_DETECTIONS)"),
        SIM_OPT_ALIAS("--peaks", "--clutter-count"),
        SIM_OPT_DOUBLE("--alpha", &alpha, "A", "0.01", SIM_OPEN, 0, 1, "size of both tests"),
        SIM_OPT_LONG("--kmax", &kmax, "K", "25", SIM_IN, 1, TRK_CLUTTER_KMAX, "window"),
        SIM_OPT_DOUBLE("--b", &b, "B", "0.02", SIM_OPEN, 0, 1,
                       "measurement noise factor, sigma = B x region size (Kennedy's 1/50)"),
        SIM_OPT_FLAG("--torus", &torus,
                     "the region wraps around: no edge effects (the density test's size is\n"
                     "then alpha on every length; Kennedy's bounded region loses some at\n"
                     "long runs, as the paper notes)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "kennedy-null", NULL,
        "Kennedy 2008 Figs. 2-3: false tracks confirmed by the clutter density (chi2) and\n"
        "amplitude (F) tests with confirmation on the last scan only, per run length, against\n"
        "alpha x runs and its exact 95% binomial interval.",
        opts, "kennedy_null", NULL, 0, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    struct kn_params kp;
    kn_params_kennedy(&kp);
    kp.n_peaks = peaks;
    kp.alpha = alpha;
    kp.kmax = (unsigned)kmax;
    kp.sigma_x_m = b * (kp.x_max_m - kp.x_min_m);
    kp.sigma_y_m = b * (kp.y_max_m - kp.y_min_m);
    kp.seed = com.seed;
    kp.torus = torus;
    struct kn_model model;
    char err[256];
    if (kn_model_init(&model, &kp, err, sizeof err)) {
        fprintf(stderr, "trk-sim kennedy-null: %s\n", err);
        return 2;
    }
    const int threads = sim_threads(&com);
    const long nlen = max_scans - 1; /* lengths 2 .. max_scans */
    struct kn_out *out = calloc((size_t)(nlen * runs), sizeof *out);
    if (!out) { /* --runs 2147483648 must say why it stops */
        fprintf(stderr, "trk-sim kennedy-null: out of memory for %ld x %ld run results (%.3g GB): fewer --runs or --max-scans\n",
                nlen, runs, (double)nlen * (double)runs * (double)sizeof *out / 1e9);
        return 1;
    }
    if (!com.quiet)
        fprintf(stderr, "trk-sim kennedy-null: %ld run lengths x %ld runs, %ld peaks/scan, alpha %g, seed %llu, %d threads\n",
                nlen, runs, peaks, alpha, (unsigned long long)com.seed, threads);
    /* every run a work unit */
    struct kn_units ku = {&model, runs};
    double wall;
    if (sim_run_units(&com, "kennedy-null", (size_t)(nlen * runs), sizeof *out, 16, kn_unit, NULL, &ku, out, &wall,
                      NULL) != 0) {
        free(out);
        return 1;
    }
    long scans_done = 0; /* n scans of every run of length n */
    for (long n = 2; n <= max_scans; n++) scans_done += n * runs;
    long lo, hi;
    mc_binom_accept(runs, alpha, 0.025, &lo, &hi);
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# kennedy-null: false-track confirmations on the last scan, Kennedy 2008 Figs. 2-3");
    if (!f) return 1;
    fprintf(f, "# region 10-20 km x 100-200 km%s, %ld peaks/scan, b %g (sigma %g m, %g m), T 1 s, b' 1/1000, PDA gate P_G 0.99, "
               "a_min 5 dB, theta 10 dB, alpha %g, kmax %ld, runs %ld per length, seed %llu; exact 95%% interval of "
               "Binomial(runs, alpha): [%ld, %ld]\n",
            torus ? " (wrapping around)" : "", peaks, b, kp.sigma_x_m, kp.sigma_y_m, alpha, kmax, runs, (unsigned long long)com.seed, lo, hi);
    fprintf(f, "scans,K,expected,lo95,hi95,chi2_confirmed,amp_confirmed,chi2_in,amp_in,chi2_confirmed_any_scan,"
               "amp_confirmed_any_scan,left_region,failed,inside_runs,inside_chi2,inside_amp,inside_lo95,inside_hi95,"
               "inside_chi2_rate,inside_amp_rate\n");
    long tot_c = 0, tot_a = 0, out_c = 0, out_a = 0, tot_fail = 0, tot_out = 0, tin = 0, tin_c = 0, tin_a = 0;
    printf("# kennedy-null: %s region, %ld runs per length, %ld peaks/scan, alpha %g: expected %.1f confirmations, exact 95%% "
           "interval [%ld, %ld]\n",
           torus ? "wrapping" : "bounded", runs, peaks, alpha, alpha * (double)runs, lo, hi);
    printf("%6s %4s %8s %8s %14s %14s %8s | %-30s\n", "scans", "K", "density", "amp", "dens any-scan", "amp any-scan",
           "left", "stayed inside: runs dens amp");
    for (long n = 2; n <= max_scans; n++) {
        long c = 0, a = 0, ce = 0, ae = 0, le = 0, fl = 0, ni = 0, ci = 0, ai = 0;
        for (long run = 0; run < runs; run++) {
            const struct kn_out *o = &out[(n - 2) * runs + run];
            c += o->chi2;
            a += o->amp;
            ce += o->chi2_ever;
            ae += o->amp_ever;
            le += o->outside;
            fl += o->failed;
            if (!o->outside && !o->failed) ni++, ci += o->chi2, ai += o->amp;
        }
        long ilo = 0, ihi = 0;
        if (ni > 0) mc_binom_accept(ni, alpha, 0.025, &ilo, &ihi);
        tin += ni, tin_c += ci, tin_a += ai;
        const int in_c = c >= lo && c <= hi, in_a = a >= lo && a <= hi;
        tot_c += c, tot_a += a, out_c += !in_c, out_a += !in_a, tot_fail += fl, tot_out += le;
        const long k = n - 1 < kmax ? n - 1 : kmax;
        fprintf(f, "%ld,%ld,%g,%ld,%ld,%ld,%ld,%d,%d,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%.6g,%.6g\n", n, k,
                alpha * (double)runs, lo, hi, c, a, in_c, in_a, ce, ae, le, fl, ni, ci, ai, ilo, ihi,
                ni ? (double)ci / (double)ni : NAN, ni ? (double)ai / (double)ni : NAN);
        if (n <= 6 || n % 5 == 0 || n == max_scans)
            printf("%6ld %4ld %7ld%s %7ld%s %14ld %14ld %8ld | %6ld %5ld%s %5ld%s\n", n, k, c, in_c ? " " : "*", a,
                   in_a ? " " : "*", ce, ae, le, ni, ci, ci >= ilo && ci <= ihi ? " " : "*", ai,
                   ai >= ilo && ai <= ihi ? " " : "*");
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    const long nl = nlen;
    double plo, phi, alo, ahi;
    mc_binom_ci(tot_c, nl * runs, 0.95, &plo, &phi);
    mc_binom_ci(tot_a, nl * runs, 0.95, &alo, &ahi);
    printf("# pooled over %ld lengths: density %.5f [%.5f, %.5f], amplitude %.5f [%.5f, %.5f] (alpha %g)\n", nl,
           (double)tot_c / (double)(nl * runs), plo, phi, (double)tot_a / (double)(nl * runs), alo, ahi, alpha);
    if (tin > 0) {
        mc_binom_ci(tin_c, tin, 0.95, &plo, &phi);
        mc_binom_ci(tin_a, tin, 0.95, &alo, &ahi);
        printf("# pooled, runs whose track stayed in the region (%ld): density %.5f [%.5f, %.5f], amplitude %.5f "
               "[%.5f, %.5f]\n",
               tin, (double)tin_c / (double)tin, plo, phi, (double)tin_a / (double)tin, alo, ahi);
    }
    printf("# lengths outside the 95%% interval: density %ld, amplitude %ld of %ld (about 5%% expected by chance); "
           "runs whose track left the region: %ld; failed: %ld\n",
           out_c, out_a, nl, tot_out, tot_fail);
    printf("# 'any-scan': sticky confirmation when every scan is tested (Kennedy Table 1, ~100 of 1000 at 50 scans)\n");
    printf("# wall %.1f s on %d threads; %ld track updates, %.3g updates/s\n", wall, threads, scans_done,
           (double)scans_done / wall);
    printf("# file: %s\n", path);
    const int plotted = sim_plotf(&com, "",
              "set datafile separator ','\nset grid\nset key top right\n"
              "set title 'Kennedy 2008 Figs. 2-3: confirmed false tracks, test on the last scan (%ld runs, alpha %g)'\n"
              "set xlabel 'scans per run'\nset ylabel 'confirmed (false) tracks'\nset yrange [0:%g]\n"
              "plot '%s' every ::1 using 1:4 with lines dt 2 lc rgb '#888888' title 'exact 95%% interval', \\\n"
              "     '%s' every ::1 using 1:5 with lines dt 2 lc rgb '#888888' notitle, \\\n"
              "     '%s' every ::1 using 1:3 with lines lw 2 lc rgb 'black' title 'alpha x runs', \\\n"
              "     '%s' every ::1 using 1:6 with linespoints pt 7 lc rgb '#1f77b4' title 'clutter density test', \\\n"
              "     '%s' every ::1 using 1:7 with linespoints pt 5 lc rgb '#d62728' title 'clutter amplitude test'\n",
              runs, alpha, 2.2 * (double)hi, path, path, path, path, path);
    free(out);
    return plotted < 0 ? 1 : 0; /* the .gp script not written */
}
