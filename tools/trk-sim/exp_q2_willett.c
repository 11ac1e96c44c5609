/* exp_q2_willett.c - trk-sim willett-table1: Willett's Table I of the
 * information-reduction factor q2 (Willett, "Issues in Target Tracking",
 * 2010, Sec. I.C) reproduced by importance sampling, beside the paper's
 * values with our standard errors, the rms relative deviation and the mean
 * (bias); and the steady-state CRLB with IRF (Willett eq 37) with the
 * paper's q2 and with ours.
 *
 * Mapping (docs/conventions.md "Willett Table I mapping"): nz = 2, R = I, "V = 400"
 * is a gate of area 400 around the truth: gamma = 400/pi (pi gamma sqrt|R|
 * = 400), P_G = 1 (to 1e-27), lambda_vg = 400 lambda. CRLB: q~ = 1, R = I,
 * T = 1 s (the paper's Table I setting); Willett plots the (1,1) element of
 * J^-1. The MRE with the same q2 is shown for contrast (2-4x the CRLB). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "trk/gate.h"
#include "errmsg.h"
#include "progress.h"
#include "q2_is.h"
#include "sim.h"
#include "trk/mre.h"
#include "willett.h"

#define W_NCURVE 60

struct prog {
    struct progress p;
    uint64_t last;
    int started;
};

static void on_progress(void *ctx, const struct q2_is_progress *pr)
{
    struct prog *c = ctx;
    if (!c->started) {
        progress_start(&c->p, "willett-table1 points", (long)pr->points_planned, 1);
        c->started = 1;
    }
    c->p.total = (long)pr->points_planned;
    progress_add(&c->p, (long)(pr->points_done - c->last));
    c->last = pr->points_done;
}

static int mre_of(double q2, double *p11)
{
    struct trk_mre_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2, p.dt_s = 1, p.q_m2_per_s3 = 1, p.r_m2 = 1, p.q2 = (trk_real)q2;
    p.gate_gamma = (trk_real)(WILLETT_AREA / (double)trk_gate_unit_volume(2));
    struct trk_mre m;
    struct trk_mre_result r;
    trk_status st = trk_mre_init(&m, &p);
    if (st == TRK_OK) st = trk_mre_steady_state(&m, NULL, &r);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim willett-table1: MRE at q2 = %g: %s\n", q2, ERRMSG_STATUS(st));
        return 1;
    }
    *p11 = (double)r.p[0];
    return 0;
}

SIM_EXPERIMENT(q2_willett, "willett-table1", "Willett Table I: q2 by importance sampling vs the paper; CRLB with q2")
{
    long samples;
    double target_se = 0;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--samples", &samples, "N", "1000000", SIM_IN, 2, 4294967295.0,
                     "scenes per clutter-count stratum"),
        SIM_OPT_DOUBLE("--target-se", &target_se, "S", NULL, SIM_OPEN, 0, 1,
                       "stop a cell at this standard error (default: all samples)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "willett-table1", NULL,
        "Willett's Table I: q2 for lambda 1e-4 .. 0.018 per unit area and P_D 0.7, 0.8, 0.9\n"
        "(nz = 2, R = I, a gate of area V = 400: gamma = 400/pi, P_G = 1, lambda_vg = 400 lambda)\n"
        "by importance sampling beside the paper's values, with standard errors, the rms relative\n"
        "deviation and the bias; then the steady-state CRLB with IRF (Willett eq 37; q = 1,\n"
        "R = I, T = 1 s) with both q2, and the MRE (Brekke eq 27) with ours for contrast.",
        opts, "willett_table1", NULL, SIM_UNUSED_RUNS,
        "Writes PREFIX.csv (the table), PREFIX_curve.csv, PREFIX_crlb.csv and PREFIX.png,\n"
        "PREFIX_crlb.png (gnuplot).",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    const int threads = sim_threads(&com);

    /* one line: the table's cells and a fine lambda curve (common random numbers) */
    enum { NT = WILLETT_NL * 3, NC = NT + W_NCURVE * 3 };
    static double pd[NC], lv[NC], q[NC], se[NC], curve_l[W_NCURVE];
    size_t k = 0;
    for (int i = 0; i < WILLETT_NL; i++)
        for (int j = 0; j < 3; j++, k++) pd[k] = willett_pd[j], lv[k] = WILLETT_AREA * willett_lambda[i];
    for (int i = 0; i < W_NCURVE; i++) {
        curve_l[i] = 5e-5 + (0.02 - 5e-5) * i / (W_NCURVE - 1);
        for (int j = 0; j < 3; j++, k++) pd[k] = willett_pd[j], lv[k] = WILLETT_AREA * curve_l[i];
    }
    struct q2_is_line line;
    memset(&line, 0, sizeof line);
    line.nz = 2;
    line.gamma = WILLETT_AREA / (double)trk_gate_unit_volume(2);
    line.n_cells = NC;
    line.pd = pd;
    line.lambda_vg = lv;
    line.q2 = q;
    line.se = se;
    struct q2_is_options opt;
    memset(&opt, 0, sizeof opt);
    opt.seed = com.seed;
    opt.samples = (uint64_t)samples;
    opt.target_se = target_se;
    opt.threads = com.threads;
    opt.par = com.par;
    struct prog pg;
    memset(&pg, 0, sizeof pg);
    if (!com.quiet) {
        opt.progress = on_progress;
        opt.progress_ctx = &pg;
    }
    char err[300];
    const double t0 = progress_now_s();
    const int rc0 = q2_is_run(&line, 1, &opt, err, sizeof err);
    if (pg.started) progress_end(&pg.p);
    if (rc0) {
        fprintf(stderr, "trk-sim willett-table1: %s\n", err);
        return 1;
    }
    const double dt = progress_now_s() - t0;

    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path, "lambda,pd,lambda_vg,q2_paper,q2,se,rel_dev,dev_in_se");
    if (!f) return 1;
    printf("Willett Table I (nz 2, R = I, V = 400: gamma = 400/pi, P_G = 1, lambda_vg = 400 lambda)\n"
           "q2 by importance sampling: %llu scenes, %llu points in %.2f s on %d thread%s; seed %llu\n"
           "rel_dev = paper / ours - 1\n",
           (unsigned long long)line.scenes, (unsigned long long)line.points, dt, threads, threads == 1 ? "" : "s",
           (unsigned long long)com.seed);
    printf("%-8s %5s  %8s %8s %8s %8s\n", "lambda", "P_D", "paper", "ours", "se", "rel_dev");
    double s1[4] = {0}, s2[4] = {0}, maxse = 0;
    for (int i = 0; i < WILLETT_NL; i++)
        for (int j = 0; j < 3; j++) {
            const size_t c = (size_t)(3 * i + j);
            const double d = willett_q2[i][j] / q[c] - 1;
            fprintf(f, "%.4f,%.1f,%.2f,%.4f,%.6f,%.2e,%.5f,%.2f\n", willett_lambda[i], willett_pd[j],
                    WILLETT_AREA * willett_lambda[i], willett_q2[i][j], q[c], se[c], d, (willett_q2[i][j] - q[c]) / se[c]);
            printf("%-8.4f %5.1f  %8.4f %8.4f %8.1e %+8.4f\n", willett_lambda[i], willett_pd[j], willett_q2[i][j], q[c],
                   se[c], d);
            s1[j] += d, s2[j] += d * d, s1[3] += d, s2[3] += d * d;
            if (se[c] > maxse) maxse = se[c];
        }
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("%-6s %10s %24s   (our largest se %.1e: the deviations are the paper's own Monte Carlo scatter)\n",
           "P_D", "rms dev", "mean dev (bias) +- se", maxse);
    for (int j = 0; j < 4; j++) {
        const double n = j < 3 ? WILLETT_NL : 3 * WILLETT_NL, m = s1[j] / n, rms = sqrt(s2[j] / n);
        const double sd = sqrt((s2[j] - n * m * m) / (n - 1));
        printf("%-6s %9.2f%% %+13.2f%% +- %.2f%%\n", j == 0 ? "0.7" : j == 1 ? "0.8" : j == 2 ? "0.9" : "all",
               100 * rms, 100 * m, 100 * sd / sqrt(n));
    }
    f = sim_csv_open(&com, &f_out, "_curve.csv", path, sizeof path, "lambda,q2_pd07,se_pd07,q2_pd08,se_pd08,q2_pd09,se_pd09");
    if (!f) return 1;
    for (int i = 0; i < W_NCURVE; i++) {
        const double *cq = q + NT + 3 * i, *cs = se + NT + 3 * i;
        fprintf(f, "%.6g,%.6f,%.2e,%.6f,%.2e,%.6f,%.2e\n", curve_l[i], cq[0], cs[0], cq[1], cs[1], cq[2], cs[2]);
    }
    if (sim_csv_close(&f_out) != 0) return 1;

    /* CRLB (Willett eq 37) with the paper's q2 and ours; the MRE for contrast */
    f = sim_csv_open(&com, &f_out, "_crlb.csv", path, sizeof path,
                     "lambda,pd,q2_paper,crlb11_paper_m2,q2,crlb11_m2,crlb_pos_rmse_m,mre11_m2");
    if (!f) return 1;
    printf("\nCRLB with IRF (Willett eq 37), q = 1 m^2/s^3, R = I m^2, T = 1 s: (1,1) element of J^-1 (m^2);\n"
           "MRE (Brekke eq 27) P(1,1) with our q2 for contrast\n");
    printf("%-8s %4s  %8s %10s  %8s %10s %10s  %10s\n", "lambda", "P_D", "q2 paper", "CRLB11", "q2 ours", "CRLB11",
           "pos RMSE", "MRE11");
    double max_rel = 0;
    for (int i = 0; i < WILLETT_NL; i++)
        for (int j = 0; j < 3; j++) {
            const size_t c = (size_t)(3 * i + j);
            double jp, rp, jo, ro, mo;
            if (willett_crlb(cli.name, willett_q2[i][j], &jp, &rp) || willett_crlb(cli.name, q[c], &jo, &ro) ||
                mre_of(q[c], &mo)) {
                sim_csv_discard(&f_out);
                return 1;
            }
            if (fabs(jo / jp - 1) > max_rel) max_rel = fabs(jo / jp - 1);
            fprintf(f, "%.4f,%.1f,%.4f,%.6f,%.6f,%.6f,%.6f,%.6f\n", willett_lambda[i], willett_pd[j], willett_q2[i][j],
                    jp, q[c], jo, ro, mo);
            printf("%-8.4f %4.1f  %8.4f %10.5f  %8.4f %10.5f %10.5f  %10.5f\n", willett_lambda[i], willett_pd[j],
                   willett_q2[i][j], jp, q[c], jo, ro, mo);
        }
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("largest relative CRLB difference (paper q2 vs ours): %.2f%%\n", 100 * max_rel);
    printf("files: %s.csv, %s_curve.csv, %s_crlb.csv\n", com.out, com.out, com.out);
    int rc = sim_plotf(&com, "",
                       "set datafile separator ','\n"
                       "set title \"q2, Willett Table I (V = 400, R = I): paper (points) and importance sampling "
                       "(lines)\"\n"
                       "set xlabel 'clutter density lambda (per unit area)'\nset ylabel 'q2'\nset key top right\n"
                       "set grid\n"
                       "plot for [j=0:2] '%s_curve.csv' every ::1 using 1:(column(2+2*j)) with lines lw 2 lc j+1 "
                       "title sprintf('ours, P_D 0.%%d', j+7), \\\n"
                       "     for [j=0:2] '%s.csv' every 3::(1+j) using 1:4 with points pt 7 lc j+1 "
                       "title sprintf('paper, P_D 0.%%d', j+7)\n",
                       com.out, com.out) < 0;
    rc |= sim_plotf(&com, "_crlb",
                    "set datafile separator ','\n"
                    "set title \"CRLB (Willett eq 37), q = 1 m^2/s^3, R = I: with the paper's q2 (points) and ours "
                    "(lines)\"\n"
                    "set xlabel 'clutter density lambda (per unit area)'\n"
                    "set ylabel 'CRLB, (1,1) element of J^{-1} (m^2)'\n"
                    "set key top left\nset grid\n"
                    "plot for [j=0:2] '%s_crlb.csv' every 3::(1+j) using 1:6 with linespoints lw 2 lc j+1 "
                    "title sprintf('ours, P_D 0.%%d', j+7), \\\n"
                    "     for [j=0:2] '%s_crlb.csv' every 3::(1+j) using 1:4 with points pt 7 lc j+1 "
                    "title sprintf('paper q2, P_D 0.%%d', j+7)\n",
                    com.out, com.out) < 0;
    return rc;
}
