/* exp_brekke_toc.c - trk-sim brekke-toc: Brekke, Hallingstad, Glattetre 2011,
 * Fig. 2 and sec. V.B-C: the tracking operating characteristic (TOC), the
 * steady-state position RMSE along the ROC, of the PDAF and the PDAFAI in K
 * clutter (nu = 1 and 8, SNR 15 dB), simulated (bad tracks removed) against
 * the MRE's prediction (Brekke eq 27, toc.h).
 *
 * Prediction: toc.h (the library's MRE with q2 tables sampled for this
 * scenario: PDAF q2(pd, lambda_vg) along the ROC, PDAFAI q2(pfa, lambda_vg)
 * with the K amplitude law), Brekke's Table I model, lambda = P_FA / cell.
 * Simulation: single_target.h (one target, one track on the library's
 * trk_cv2_predict / trk_pda_update, PDAF and PDAFAI on the same target,
 * detections and clutter), 300 scans, two-point start; a run whose track is
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
#include "plot.h"
#include "progress.h"
#include "sim.h"
#include "single_target.h"
#include "toc.h"
#include "trk/table_file.h"

#define MAXL 32
#define NCURVE 61

/* A q2 table of `make tables` (malloc'd bytes in *buf); 0 or -1. */
static int load_q2_table(const char *dir, const char *name, struct trk_table *t, void **buf)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    size_t n;
    trk_status st = trk_table_file_size(path, &n);
    if (st == TRK_OK) {
        *buf = malloc(n + 8);
        if (!*buf) return -1;
        st = trk_table_load_file(path, *buf, n + 8, t, NULL);
    }
    if (st != TRK_OK) {
        fprintf(stderr, "brekke-toc: %s: %s\n", path, trk_status_str(st));
        return -1;
    }
    return 0;
}

struct tc_out {
    unsigned char lost[2];
    double mse[2];
    int32_t scans[2];
};

static void help(void)
{
    printf("trk-sim brekke-toc [options]\n"
           "  Brekke 2011 Fig. 2: steady-state position RMSE along the ROC (TOC) of the PDAF and the\n"
           "  PDAFAI, simulated (bad tracks removed) against the MRE prediction (toc.h).\n"
           "  --runs N          runs per point and filter (default 1000)\n"
           "  --scans N         scans per run (default 300)\n"
           "  --from K          first scan of the RMSE (default 101)\n"
           "  --nu LIST         K shapes (default 1,8)\n"
           "  --snr-db D        target SNR (default 15)\n"
           "  --cell-m2 A       resolution cell, lambda = P_FA / A (default 1)\n"
           "  --pfa LIST        simulated P_FA (default 1e-6,1e-5,1e-4,1e-3,1e-2,3e-2,0.1,0.2,0.3,0.5)\n"
           "  --texture cell|scan  K texture drawn per detection (default; i.i.d. K amplitudes) or once\n"
           "                    per scan (bursty clutter, see tools/common/single_target.h)\n"
           "  --init twopoint|steady  initial track covariance (default twopoint)\n"
           "  --q2-samples N    importance samples per stratum of the MRE's q2 grids (default toc.h's)\n"
           "  --tables DIR      the MRE's q2 from the tables of `make tables` (q2_pdaf_g6.tbl,\n"
           "                    q2_pdafai_k<nu>_g6.tbl) instead of sampling them here\n"
           "  common: --seed N --out PREFIX (default brekke_toc) --threads N --quiet --no-plot\n"
           "  Writes PREFIX.csv (simulation and MRE at the simulated P_FA), PREFIX_mre.csv (MRE curves),\n"
           "  PREFIX_optimum.csv, PREFIX.gp, PREFIX.png.\n");
}

SIM_EXPERIMENT(brekke_toc, "brekke-toc", "Brekke 2011 Fig. 2: TOC, simulated RMSE vs MRE, PDAF and PDAFAI")
{
    struct sim_common com;
    sim_common_defaults(&com, "brekke_toc");
    long runs = 1000, scans = 300, from = 101, q2_samples = 0;
    double nus[MAXL] = {1, 8}, snr = 15, cell = 1;
    double pfas[MAXL] = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 3e-2, 0.1, 0.2, 0.3, 0.5};
    int nnu = 2, npfa = 10, init = ST_INIT_TWOPOINT, texture = ST_TEXTURE_CELL;
    const char *tables = NULL;
    for (int i = 1; i < argc; i++) {
        const char *v;
        int r;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            help();
            return 0;
        }
        if ((r = sim_common_arg(argc, argv, &i, &com)) != 0) {
            if (r < 0) return 2;
            continue;
        }
        if ((r = sim_arg(argc, argv, &i, "--scans", &v)) != 0) {
            if (r < 0 || sim_parse_long(v, &scans) || scans < 2 || scans > 1000000) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--from", &v)) != 0) {
            if (r < 0 || sim_parse_long(v, &from) || from < 1) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--nu", &v)) != 0) {
            if (r < 0 || (nnu = sim_parse_list(v, nus, MAXL)) < 1) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--snr-db", &v)) != 0) {
            if (r < 0 || sim_parse_double(v, &snr)) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--cell-m2", &v)) != 0) {
            if (r < 0 || sim_parse_double(v, &cell) || !(cell > 0)) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--pfa", &v)) != 0) {
            if (r < 0 || (npfa = sim_parse_list(v, pfas, MAXL)) < 1) goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--texture", &v)) != 0) {
            if (r < 0) goto bad;
            if (!strcmp(v, "cell")) texture = ST_TEXTURE_CELL;
            else if (!strcmp(v, "scan")) texture = ST_TEXTURE_SCAN;
            else goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--init", &v)) != 0) {
            if (r < 0) goto bad;
            if (!strcmp(v, "twopoint")) init = ST_INIT_TWOPOINT;
            else if (!strcmp(v, "steady")) init = ST_INIT_STEADY;
            else goto bad;
        } else if ((r = sim_arg(argc, argv, &i, "--tables", &v)) != 0) {
            if (r < 0) goto bad;
            tables = v;
        } else if ((r = sim_arg(argc, argv, &i, "--q2-samples", &v)) != 0) {
            if (r < 0 || sim_parse_long(v, &q2_samples) || q2_samples < 1000) goto bad;
        } else {
            fprintf(stderr, "brekke-toc: unknown option %s (see --help)\n", argv[i]);
            return 2;
        }
        continue;
    bad:
        fprintf(stderr, "brekke-toc: bad value for %s\n", argv[i]);
        return 2;
    }
    if (com.runs > 0) runs = com.runs;
    if (from > scans) {
        fprintf(stderr, "brekke-toc: --from must be <= --scans\n");
        return 2;
    }
    double pmin = pfas[0], pmax = pfas[0];
    for (int j = 0; j < npfa; j++) {
        if (!(pfas[j] > 0 && pfas[j] < 1)) {
            fprintf(stderr, "brekke-toc: P_FA must be in (0, 1)\n");
            return 2;
        }
        pmin = fmin(pmin, pfas[j]);
        pmax = fmax(pmax, pfas[j]);
    }
    const int threads = sim_threads(&com);
    char err[512];
    /* ---- the MRE (toc.h): one TOC per nu */
    struct toc **toc = calloc((size_t)nnu, sizeof *toc);
    struct toc_point *curve = calloc((size_t)nnu * NCURVE, sizeof *curve);
    struct toc_point *at = calloc((size_t)(nnu * npfa), sizeof *at);
    struct toc_optimum opt[MAXL][2];
    void *tbl_bufs[2 * MAXL] = {NULL};
    if (!toc || !curve || !at) return 1;
    const double t_mre = progress_now_s();
    for (int a = 0; a < nnu; a++) {
        struct toc_scenario ts;
        toc_scenario_brekke(&ts, TRK_AMP_K, nus[a], snr, cell);
        ts.pfa_min = fmin(ts.pfa_min, pmin);
        ts.pfa_max = fmax(ts.pfa_max, pmax);
        struct toc_q2_source src;
        memset(&src, 0, sizeof src);
        struct trk_table tb[2];
        void *tbuf[2] = {NULL, NULL};
        if (tables) {
            char name[64];
            snprintf(name, sizeof name, "q2_pdafai_k%g_g6.tbl", nus[a]);
            if (load_q2_table(tables, "q2_pdaf_g6.tbl", &tb[0], &tbuf[0]) ||
                load_q2_table(tables, name, &tb[1], &tbuf[1]))
                return 1;
            src.pdaf = &tb[0];
            src.pdafai = &tb[1];
        }
        src.samples = (uint64_t)q2_samples;
        src.seed = com.seed;
        src.threads = com.threads;
        src.quiet = com.quiet;
        if (!(toc[a] = toc_new(&ts, &src, err, sizeof err)) || toc_curve(toc[a], NCURVE, curve + a * NCURVE, err, sizeof err) ||
            toc_optimum(toc[a], TOC_PDAF, &opt[a][0], err, sizeof err) ||
            toc_optimum(toc[a], TOC_PDAFAI, &opt[a][1], err, sizeof err)) {
            fprintf(stderr, "brekke-toc: MRE (nu %g): %s\n", nus[a], err);
            return 1;
        }
        tbl_bufs[2 * a] = tbuf[0];
        tbl_bufs[2 * a + 1] = tbuf[1];
        for (int j = 0; j < npfa; j++)
            if (toc_point_at(toc[a], pfas[j], &at[a * npfa + j], err, sizeof err)) {
                fprintf(stderr, "brekke-toc: MRE (nu %g, P_FA %g): %s\n", nus[a], pfas[j], err);
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
    int amp_fail = 0;
#pragma omp parallel for schedule(dynamic, 1)
    for (int m = 0; m < nmod; m++) {
        char e[256];
        if (st_amp_init(&amp[m], TRK_AMP_K, nus[m / npfa], snr, pfas[m % npfa], 0, 0, e, sizeof e)) {
#pragma omp critical(tc_err)
            {
                amp_fail = 1;
                fprintf(stderr, "brekke-toc: %s\n", e);
            }
        }
    }
    if (amp_fail) return 1;
    for (int m = 0; m < nmod; m++) {
        struct st_params sp;
        st_params_brekke(&sp);
        sp.n_scans = scans;
        sp.init = init;
        sp.texture = texture;
        sp.amp = &amp[m].m;
        sp.lambda_per_m2 = pfas[m % npfa] / cell;
        sp.seed = com.seed;
        if (st_model_init(&mod[m], &sp, err, sizeof err)) {
            fprintf(stderr, "brekke-toc: %s\n", err);
            return 1;
        }
    }
    if (!com.quiet)
        fprintf(stderr, "brekke-toc: %d nu x %d P_FA x 2 filters x %ld runs x %ld scans, seed %llu, %d threads (MRE %.1f s)\n",
                nnu, npfa, runs, scans, (unsigned long long)com.seed, threads, mre_s);
    struct progress pr;
    progress_start(&pr, "brekke-toc", (long)nmod * runs, !com.quiet);
    const double t0 = progress_now_s();
#pragma omp parallel
    {
        struct st_ws ws = {NULL, 0, NULL, 0};
        long pending = 0;
#pragma omp for schedule(dynamic, 8)
        for (long it = 0; it < (long)nmod * runs; it++) {
            const long m = it / runs, run = it % runs;
            for (int f = 0; f < 2; f++) {
                struct st_result res;
                st_run(&mod[m], &ws, (uint32_t)run, f, from, NULL, &res);
                out[it].lost[f] = (unsigned char)res.lost;
                out[it].mse[f] = res.n_sse ? res.sse / (double)res.n_sse : NAN;
                out[it].scans[f] = (int32_t)res.scans;
            }
            if (++pending == 64) {
#pragma omp critical(sim_progress)
                progress_add(&pr, pending);
                pending = 0;
            }
        }
#pragma omp critical(sim_progress)
        progress_add(&pr, pending);
        st_ws_free(&ws);
    }
    progress_end(&pr);
    const double wall = progress_now_s() - t0;
    /* ---- reduce in run order, print, write */
    char path[1024];
    snprintf(path, sizeof path, "%s.csv", com.out);
    FILE *f = plot_csv_open(path, "# brekke-toc: Brekke 2011 Fig. 2, TOC: simulated RMSE (bad tracks removed) vs MRE");
    if (!f) return 1;
    fprintf(f, "# Table I model (T 1 s, q 0.0125^2, R I/12, g 6), K clutter, SNR %g dB, cell %g m^2 (lambda = pfa / cell), "
               "%ld scans, RMSE over scans >= %ld of the runs not lost (two-stage rule, c1 5 m, c2 15 m), %s start, "
               "texture %s, seed %llu, runs %ld\n",
            snr, cell, scans, from, init == ST_INIT_TWOPOINT ? "two-point" : "steady-state",
            texture == ST_TEXTURE_CELL ? "per detection" : "per scan", (unsigned long long)com.seed, runs);
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
    fclose(f);
    char mpath[1024], opath[1024];
    snprintf(mpath, sizeof mpath, "%s_mre.csv", com.out);
    snprintf(opath, sizeof opath, "%s_optimum.csv", com.out);
    FILE *fm = plot_csv_open(mpath, "nu,pfa,pd,rmse_pdaf,rmse_pdafai,q2_pdaf,q2_pdafai,lambda_vg_pdaf,lambda_vg_pdafai");
    FILE *fo = plot_csv_open(opath, "nu,filter,pfa,pd,rmse_m,q2,lambda_vg");
    if (!fm || !fo) return 1;
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
    fclose(fm);
    fclose(fo);
    printf("\n# wall %.1f s on %d threads (+ MRE %.1f s); %ld track updates, %.3g updates/s\n", wall, threads, mre_s,
           total_scans, (double)total_scans / wall);
    printf("# files: %s, %s, %s\n", path, mpath, opath);
    if (!com.no_plot) {
        char body[16384];
        int n = snprintf(body, sizeof body,
                         "set datafile separator ','\nset datafile missing 'nan'\nset logscale x\nset format x '10^{%%L}'\n"
                         "set grid\nset key top left font ',9'\nset xlabel 'P_{FA}'\nset ylabel 'position RMSE (m)'\n"
                         "set logscale y\nset yrange [0.15:3]\nset ytics (0.15, 0.2, 0.3, 0.5, 0.7, 1, 2, 3)\nset multiplot layout 1,%d title 'Brekke 2011 Fig. 2: TOC, SNR %g dB, "
                         "cell %g m^2 (MRE lines, simulation points, bad tracks removed)'\n",
                         nnu, snr, cell);
        for (int a = 0; a < nnu && n < (int)sizeof body - 2048; a++)
            n += snprintf(body + n, sizeof body - (size_t)n,
                          "set title 'K clutter, nu = %g'\n"
                          "plot '%s' index %d %s using 2:4 with lines lw 2 lc 1 title 'MRE PDAF', \\\n"
                          "     '%s' index %d %s using 2:5 with lines lw 2 lc 2 title 'MRE PDAFAI', \\\n"
                          "     '%s' every ::1 using ($1==%g && strcol(5) eq 'PDAF' ? $2 : NaN):9:10:11 with yerrorbars "
                          "pt 7 lc 1 title 'sim PDAF', \\\n"
                          "     '%s' every ::1 using ($1==%g && strcol(5) eq 'PDAFAI' ? $2 : NaN):9:10:11 with yerrorbars "
                          "pt 5 lc 2 title 'sim PDAFAI'\n",
                          nus[a], mpath, a, a ? "" : "every ::1", mpath, a, a ? "" : "every ::1", path, nus[a], path,
                          nus[a]);
        snprintf(body + n, sizeof body - (size_t)n, "unset multiplot\n");
        plot_gnuplot(com.out, body);
    }
    for (int a = 0; a < nnu; a++) toc_free(toc[a]);
    for (int a = 0; a < 2 * nnu; a++) free(tbl_bufs[a]);
    for (int m = 0; m < nmod; m++) st_amp_free(&amp[m]);
    free(toc), free(curve), free(at), free(amp), free(mod), free(out);
    return 0;
}
