/* exp_brekke_toc.c - trk-sim brekke-toc: Brekke, Hallingstad, Glattetre 2011,
 * Fig. 2 and sec. V.B-C: the tracking operating characteristic (TOC), the
 * steady-state position RMSE along the ROC, of the PDAF and the PDAFAI in K
 * clutter (nu = 1 and 8, SNR 15 dB), simulated (bad tracks removed) against
 * the MRE's prediction (Brekke eq 27, toc_curve.h).
 *
 * Prediction: toc_curve.h (the library's MRE with q2 tables sampled for this
 * scenario: PDAF q2(pd, lambda_vg) along the ROC, PDAFAI q2(pfa, lambda_vg)
 * with the K amplitude law), Brekke's Table I model, lambda = P_FA / cell.
 * Simulation: single_target.h (one target, one track on the library's
 * trk_cv2_predict / trk_pda_update, PDAF and PDAFAI on the same target,
 * detections and clutter), 300 scans, two-point start (--start); a run whose track is
 * lost by Brekke's two-stage rule (c1 5 m, c2 15 m) is removed ("bad
 * tracks"); the RMSE is sqrt of the mean over the remaining runs of their
 * mean squared position error over scans >= --from (steady state), with a
 * 95 % interval from the spread of the per-run values. Brekke notes that the
 * MRE is slightly pessimistic against the mode of the error and the error
 * pdf has an upper tail (Figs. 3-5): expect agreement to ~10-20 %, and the
 * simulation to degrade where the MRE diverges. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc_stats.h"
#include "progress.h"
#include "sim.h"
#include "single_target.h"
#include "toc_curve.h"

#define MAXL 32
#define NCURVE 61

struct tc_out {
    unsigned char lost[2];
    double mse[2];
    int32_t scans[2];
};

static void keep(void *slot, int f, const struct st_result *res)
{
    struct tc_out *o = slot;
    o->lost[f] = (unsigned char)res->lost;
    o->mse[f] = res->n_sse ? res->sse / (double)res->n_sse : NAN;
    o->scans[f] = (int32_t)res->scans;
}

SIM_EXPERIMENT(brekke_toc, "brekke-toc", "Brekke 2011 Fig. 2: TOC, simulated RMSE vs MRE, PDAF and PDAFAI")
{
    long runs, scans, from, q2_samples = 0;
    double nus[MAXL], snr, cell, pfas[MAXL];
    int nnu, npfa, init, texture, mre_start;
    struct st_gate_cap gate_cap;
    const char *tables = NULL;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "1000", SIM_GE, 1, 0, "runs per point and filter"),
        SIM_OPT_LONG("--scans", &scans, "N", "300", SIM_IN, 2, 1000000, "scans per run"),
        SIM_OPT_LONG("--from", &from, "K", "101", SIM_GE, 1, 0, "first scan of the RMSE"),
        SIM_OPT_LIST("--k-shape", nus, &nnu, MAXL, "1,8", SIM_GT, 0, 0, "K shapes nu"),
        SIM_OPT_ALIAS("--nu", "--k-shape"),
        SIM_OPT_DOUBLE("--snr-db", &snr, "D", "15", 0, 0, 0, "target SNR"),
        SIM_OPT_DOUBLE("--cell-m2", &cell, "A", "1", SIM_GT, 0, 0, "resolution cell, lambda = P_FA / A"),
        SIM_OPT_LIST("--pfa", pfas, &npfa, MAXL, "1e-6,1e-5,1e-4,1e-3,1e-2,3e-2,0.1,0.2,0.3,0.5", SIM_OPEN, 0, 1,
                     "simulated P_FA"),
        SIM_OPT_TEXTURE(&texture),
        SIM_OPT_START(&init),
        SIM_OPT_ALIAS("--init", "--start"),
        SIM_OPT_GATE_CAP(&gate_cap),
        SIM_OPT_MRE_START(&mre_start),
        SIM_OPT_Q2_SAMPLES(&q2_samples),
        SIM_OPT_TABLES(&tables),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "brekke-toc", NULL,
        "Brekke 2011 Fig. 2: steady-state position RMSE along the ROC (TOC) of the PDAF and the\n"
        "PDAFAI, simulated (bad tracks removed) against the MRE prediction (toc.h).",
        opts, "brekke_toc", NULL, 0,
        "Writes PREFIX.csv (simulation and MRE at the simulated P_FA), PREFIX_mre.csv (MRE curves),\n"
        "PREFIX_optimum.csv, PREFIX.gp, PREFIX.png.",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (from > scans) {
        fprintf(stderr, "trk-sim brekke-toc: --from must be <= --scans\n");
        return 2;
    }
    double pmin = pfas[0], pmax = pfas[0];
    for (int j = 0; j < npfa; j++) {
        pmin = fmin(pmin, pfas[j]);
        pmax = fmax(pmax, pfas[j]);
    }
    const int threads = sim_threads(&com);
    char err[512];
    /* ---- the MRE (toc_curve.h): one TOC per nu */
    struct toc **toc = calloc((size_t)nnu, sizeof *toc);
    struct toc_point *curve = calloc((size_t)nnu * NCURVE, sizeof *curve);
    struct toc_point *at = calloc((size_t)(nnu * npfa), sizeof *at);
    struct toc_optimum opt[MAXL][2];
    void *tbl_bufs[2 * MAXL] = {NULL};
    if (!toc || !curve || !at) return 1;
    const double t_mre = progress_now_s();
    for (int a = 0; a < nnu; a++) {
        if (!(toc[a] = sim_brekke_toc(cli.name, &com, nus[a], snr, cell, pmin, pmax, mre_start, tables, q2_samples,
                                      &tbl_bufs[2 * a])))
            return 1;
        if (toc_curve(toc[a], NCURVE, curve + a * NCURVE, err, sizeof err) ||
            toc_optimum(toc[a], TOC_PDAF, &opt[a][0], err, sizeof err) ||
            toc_optimum(toc[a], TOC_PDAFAI, &opt[a][1], err, sizeof err)) {
            fprintf(stderr, "trk-sim brekke-toc: MRE (nu %g): %s\n", nus[a], err);
            return 1;
        }
        for (int j = 0; j < npfa; j++)
            if (toc_point_at(toc[a], pfas[j], &at[a * npfa + j], err, sizeof err)) {
                fprintf(stderr, "trk-sim brekke-toc: MRE (nu %g, P_FA %g): %s\n", nus[a], pfas[j], err);
                return 1;
            }
    }
    const double mre_s = progress_now_s() - t_mre;
    /* ---- the simulation */
    const int nmod = nnu * npfa;
    struct st_amp *amp = calloc((size_t)nmod, sizeof *amp);
    struct st_model *mod = calloc((size_t)nmod, sizeof *mod);
    struct tc_out *out = calloc((size_t)nmod * (size_t)runs, sizeof *out);
    if (!amp || !mod || !out) return 1;
    if (sim_amp_k_grid(cli.name, amp, nus, nnu, &snr, 1, pfas, npfa, 0, 0)) return 1;
    for (int m = 0; m < nmod; m++)
        if (sim_brekke_model(cli.name, &mod[m], &amp[m], cell, scans, init, texture, &gate_cap, com.seed)) return 1;
    if (!com.quiet)
        fprintf(stderr, "trk-sim brekke-toc: %d nu x %d P_FA x 2 filters x %ld runs x %ld scans, seed %llu, %d threads (MRE %.1f s)\n",
                nnu, npfa, runs, scans, (unsigned long long)com.seed, threads, mre_s);
    int bad_call;
    const double wall = sim_st_runs(&com, cli.name, mod, nmod, runs, 2, from, keep, out, sizeof *out, &bad_call);
    if (bad_call) {
        fprintf(stderr, "trk-sim brekke-toc: internal error (bad run call)\n");
        return 1;
    }
    /* ---- reduce in run order, print, write */
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# brekke-toc: Brekke 2011 Fig. 2, TOC: simulated RMSE (bad tracks removed) vs MRE");
    if (!f) return 1;
    fprintf(f, "# Table I model (T 1 s, q 0.0125^2, R I/12, g 6), K clutter, SNR %g dB, cell %g m^2 (lambda = pfa / cell), "
               "%ld scans, RMSE over scans >= %ld of the runs not lost (two-stage rule, c1 5 m, c2 15 m), %s start, "
               "texture %s, seed %llu, runs %ld\n",
            snr, cell, scans, from, init == ST_INIT_TWOPOINT ? "two-point" : "steady-state",
            texture == ST_TEXTURE_CELL ? "per detection" : "per scan", (unsigned long long)com.seed, runs);
    sim_assumptions_csv(f, init, &gate_cap, mre_start);
    fprintf(f, "nu,pfa,pd,lambda_per_m2,filter,mre_rmse_m,mre_q2,mre_lambda_vg,sim_rmse_m,sim_lo95,sim_hi95,sim_over_mre,"
               "kept,lost,lost_frac\n");
    double *v = malloc((size_t)runs * sizeof *v);
    if (!v) return 1;
    long total_scans = 0;
    for (int a = 0; a < nnu; a++) {
        printf("\n# nu %g, SNR %g dB, cell %g m^2: steady-state RMSE (m), MRE | simulated [95%% CI] (lost %%)\n", nus[a],
               snr, cell);
        printf("%8s %7s %9s | %7s %-28s | %7s %-28s\n", "P_FA", "P_D", "lambda", "PDAF", " sim", "PDAFAI", " sim");
        for (int j = 0; j < npfa; j++) {
            const int m = a * npfa + j;
            const struct toc_point *tp = &at[m];
            char cellt[2][96], mt[2][16];
            for (int fl = 0; fl < 2; fl++) {
                size_t n = 0;
                long lost = 0;
                for (long run = 0; run < runs; run++) {
                    const struct tc_out *o = &out[(size_t)m * (size_t)runs + (size_t)run];
                    total_scans += o->scans[fl];
                    if (o->lost[fl]) lost++;
                    else if (!isnan(o->mse[fl])) v[n++] = o->mse[fl];
                }
                double mean = NAN, lo = NAN, hi = NAN;
                if (n > 0) mc_mean_ci(v, n, 0.95, &mean, &lo, &hi);
                const double rm = sqrt(mean), rlo = sqrt(fmax(lo, 0)), rhi = sqrt(hi), mre = tp->rmse_m[fl];
                snprintf(mt[fl], sizeof mt[fl], isfinite(mre) ? "%7.4f" : "  inf  ", mre);
                if (n > 1)
                    snprintf(cellt[fl], sizeof cellt[fl], "%7.4f [%6.4f, %6.4f] %5.1f%%", rm, rlo, rhi,
                             100.0 * (double)lost / (double)runs);
                else
                    snprintf(cellt[fl], sizeof cellt[fl], "   -    (all lost)     %5.1f%%", 100.0 * (double)lost / (double)runs);
                fprintf(f, "%g,%g,%.6g,%.6g,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%zu,%ld,%.6g\n", nus[a], pfas[j],
                        amp[m].pd, pfas[j] / cell, fl ? "PDAFAI" : "PDAF", mre, tp->q2[fl], tp->lambda_vg[fl],
                        n > 1 ? rm : NAN, n > 1 ? rlo : NAN, n > 1 ? rhi : NAN, n > 1 ? rm / mre : NAN, n, lost,
                        (double)lost / (double)runs);
            }
            printf("%8.0e %7.4f %9.3g | %7s %-28s | %7s %-28s\n", pfas[j], amp[m].pd, pfas[j] / cell, mt[0], cellt[0],
                   mt[1], cellt[1]);
        }
        for (int fl = 0; fl < 2; fl++)
            printf("# MRE optimum %-6s: P_FA %.3g (P_D %.4f), RMSE %.4f m\n", fl ? "PDAFAI" : "PDAF", opt[a][fl].pfa,
                   opt[a][fl].pd, opt[a][fl].rmse_m);
    }
    free(v);
    if (sim_csv_close(&f_out) != 0) return 1;
    char mpath[1024], opath[1024];
    struct fileio_out fm_out;
    char mhead[256], ohead[256];
    snprintf(mhead, sizeof mhead, "# MRE start %s (--mre-start)\n%s", toc_start_name(mre_start),
             "nu,pfa,pd,rmse_pdaf,rmse_pdafai,q2_pdaf,q2_pdafai,lambda_vg_pdaf,lambda_vg_pdafai");
    snprintf(ohead, sizeof ohead, "# MRE start %s (--mre-start)\n%s", toc_start_name(mre_start),
             "nu,filter,pfa,pd,rmse_m,q2,lambda_vg");
    FILE *fm = sim_csv_open(&com, &fm_out, "_mre.csv", mpath, sizeof mpath, mhead);
    struct fileio_out fo_out;
    FILE *fo = sim_csv_open(&com, &fo_out, "_optimum.csv", opath, sizeof opath, ohead);
    if (!fm || !fo) {
        sim_csv_discard(&fm_out);
        sim_csv_discard(&fo_out);
        return 1;
    }
    for (int a = 0; a < nnu; a++) {
        for (int i = 0; i < NCURVE; i++) {
            const struct toc_point *c = &curve[a * NCURVE + i];
            fprintf(fm, "%g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", nus[a], c->pfa, c->pd,
                    isfinite(c->rmse_m[0]) ? c->rmse_m[0] : NAN, isfinite(c->rmse_m[1]) ? c->rmse_m[1] : NAN, c->q2[0],
                    c->q2[1], c->lambda_vg[0], c->lambda_vg[1]);
        }
        fprintf(fm, "\n\n"); /* one gnuplot data block per nu */
        for (int fl = 0; fl < 2; fl++)
            fprintf(fo, "%g,%s,%.6g,%.6g,%.6g,%.6g,%.6g\n", nus[a], fl ? "PDAFAI" : "PDAF", opt[a][fl].pfa, opt[a][fl].pd,
                    opt[a][fl].rmse_m, opt[a][fl].q2, opt[a][fl].lambda_vg);
    }
    const int bad_fm = sim_csv_close(&fm_out) != 0;
    if (sim_csv_close(&fo_out) != 0 || bad_fm) return 1;
    printf("\n# wall %.1f s on %d threads (+ MRE %.1f s); %ld track updates, %.3g updates/s\n", wall, threads, mre_s,
           total_scans, (double)total_scans / wall);
    printf("# files: %s, %s, %s\n", path, mpath, opath);
    if (!com.no_plot) {
        struct sim_text b = {NULL, 0, 0, 0};
        char as[160];
        sim_text_add(&b,
                     "set datafile separator ','\nset datafile missing 'nan'\nset logscale x\nset format x '10^{%%L}'\n"
                     "set grid\nset key top left font ',9'\nset xlabel 'P_{FA}'\nset ylabel 'position RMSE (m)'\n"
                     "set logscale y\nset yrange [0.15:3]\nset ytics (0.15, 0.2, 0.3, 0.5, 0.7, 1, 2, 3)\n"
                     "set multiplot layout 1,%d title \"Brekke 2011 Fig. 2: TOC, SNR %g dB, "
                     "cell %g m^2 (MRE lines, simulation points, bad tracks removed)\\n%s\"\n",
                     nnu, snr, cell, sim_assumptions_title(as, sizeof as, init, &gate_cap, mre_start));
        for (int a = 0; a < nnu; a++)
            sim_text_add(&b,
                         "set title 'K clutter, nu = %g'\n"
                         "plot '%s' index %d %s using 2:4 with lines lw 2 lc 1 title 'MRE PDAF', \\\n"
                         "     '%s' index %d %s using 2:5 with lines lw 2 lc 2 title 'MRE PDAFAI', \\\n"
                         "     '%s' every ::1 using ($1==%g && strcol(5) eq 'PDAF' ? $2 : NaN):9:10:11 with yerrorbars "
                         "pt 7 lc 1 title 'sim PDAF', \\\n"
                         "     '%s' every ::1 using ($1==%g && strcol(5) eq 'PDAFAI' ? $2 : NaN):9:10:11 with "
                         "yerrorbars pt 5 lc 2 title 'sim PDAFAI'\n",
                         nus[a], mpath, a, a ? "" : "every ::1", mpath, a, a ? "" : "every ::1", path, nus[a], path,
                         nus[a]);
        sim_text_add(&b, "unset multiplot\n");
        if (!b.failed) sim_plot(&com, "", b.s);
        sim_text_free(&b);
    }
    for (int a = 0; a < nnu; a++) toc_free(toc[a]);
    for (int a = 0; a < 2 * nnu; a++) free(tbl_bufs[a]);
    for (int m = 0; m < nmod; m++) st_amp_free(&amp[m]);
    free(toc), free(curve), free(at), free(amp), free(mod), free(out);
    return 0;
}
