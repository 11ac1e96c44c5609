/* exp_toc.c - trk-sim toc: Brekke's tracking operating characteristic
 * (Brekke et al. 2011, Sec. V-C, Fig. 2): the steady-state position RMSE of
 * the MRE (eq 35) along the ROC for the PDAF and the PDAFAI, Rayleigh and
 * K (nu = 1, 8) clutter, SNR 15 dB, with the optimal P_FA marked; for
 * resolution cell areas 1, 0.25 and 0.1 m^2 (lambda = P_FA / cell: the area
 * is not printed in the paper, docs/conventions.md "Brekke Table I mapping").
 * The curves come from tools/sim/toc_curve.h (the library's MRE, TOC optimiser
 * and q2 lookups) on q2 tables (--tables DIR: `make tables`) or on q2 grids
 * sampled here for exactly this SNR. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "q2_table.h"
#include "sim.h"
#include "toc_curve.h"
#include "trk/amplitude.h"
#include "trk/q2.h"

#define MAX_CELLS 8
#define N_MODELS 3

static const struct {
    const char *name, *label, *table;
    int model;
    double nu;
} models[N_MODELS] = {
    {"rayleigh", "Rayleigh", "q2_pdafai_rayleigh_g6.tbl", TRK_AMP_RAYLEIGH, 0},
    {"k1", "K, nu = 1", "q2_pdafai_k1_g6.tbl", TRK_AMP_K, 1},
    {"k8", "K, nu = 8", "q2_pdafai_k8_g6.tbl", TRK_AMP_K, 8},
};

SIM_EXPERIMENT(toc, "toc", "Brekke Fig. 2: MRE steady-state RMSE along the ROC (PDAF, PDAFAI), optimal P_FA")
{
    double snr_db, pfa_min, pfa_max, target_se = 0, lv_max;
    double cells[MAX_CELLS];
    int n_cells;
    long points, samples = 0;
    const char *tables = NULL;
    int mre_start;
    const struct sim_opt opts[] = {
        SIM_OPT_DOUBLE("--snr-db", &snr_db, "D", "15", SIM_IN, -30, 60, "target SNR"),
        SIM_OPT_LIST("--cells", cells, &n_cells, MAX_CELLS, "1,0.25,0.1", SIM_OPEN, 0, INFINITY,
                     "resolution cell areas in m^2"),
        SIM_OPT_DOUBLE("--pfa-min", &pfa_min, "P", "1e-6", SIM_OPEN, 0, 1, "ROC range: smallest P_FA"),
        SIM_OPT_DOUBLE("--pfa-max", &pfa_max, "P", "0.5", SIM_OPEN, 0, 1, "ROC range: largest P_FA"),
        SIM_OPT_LONG("--points", &points, "N", "121", SIM_IN, 2, 100000,
                     "curve points per (model, cell), equally spaced in ln P_FA"),
        SIM_OPT_STRING("--tables", &tables, "DIR", NULL,
                       "q2 tables of `make tables` (q2_pdaf_g6.tbl, q2_pdafai_<model>_g6.tbl);\n"
                       "default: sample the q2 grids for this SNR here (bit-identical for any\n"
                       "--threads)"),
        SIM_OPT_LONG("--samples", &samples, "N", NULL, SIM_IN, 2, 4294967295.0,
                     "sampler: scenes per clutter-count stratum (default 1e6)"),
        SIM_OPT_DOUBLE("--target-se", &target_se, "S", NULL, SIM_OPEN, 0, 1,
                       "sampler: stop a cell at this standard error (default 1e-3)"),
        SIM_OPT_DOUBLE("--lambda-vg-max", &lv_max, "L", "100", SIM_IN, 1, 1000,
                       "top of the sampled lambda_vg axes (beyond it a point is\n'off_table')"),
        SIM_OPT_MRE_START(&mre_start),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "toc", NULL,
        "Brekke Fig. 2: steady-state position RMSE of the MRE (Brekke eq 35) along the ROC for the\n"
        "PDAF and the PDAFAI, Rayleigh and K (nu = 1, 8) clutter, and the optimal P_FA of each.\n"
        "Brekke's Table I model: T = 1 s, q = 0.0125^2 m^2/s^3, R = I/12 m^2, gate g = 6\n"
        "(gamma = 36); lambda = P_FA / cell area (the cell is not printed in the paper).",
        opts, "toc", NULL, SIM_UNUSED_RUNS,
        "Writes PREFIX.csv (curves), PREFIX_optimum.csv, PREFIX.gp and PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (!(pfa_min < pfa_max)) {
        fprintf(stderr, "trk-sim toc: --pfa-min must be below --pfa-max\n");
        return 2;
    }
    const int threads = sim_threads(&com);
    char err[512];
    int rc = 1;
    struct trk_table pdaf_t, ai_t[N_MODELS];
    void *pdaf_buf = NULL, *ai_buf[N_MODELS] = {NULL, NULL, NULL};
    unsigned char *pdaf_bytes = NULL;
    struct toc *toc[N_MODELS] = {NULL, NULL, NULL};
    struct toc_point *pts = calloc((size_t)points, sizeof *pts);
    struct toc_optimum opt[N_MODELS][MAX_CELLS][TOC_N_DETECTORS];
    FILE *f = NULL, *fo = NULL;
    struct fileio_out f_out, fo_out;
    if (!pts) goto out;
    struct toc_q2_source src;
    memset(&src, 0, sizeof src);
    src.samples = (uint64_t)samples;
    src.target_se = target_se;
    src.seed = com.seed;
    src.threads = com.threads;
    src.quiet = com.quiet;
    src.par = com.par;
    src.lambda_vg_max = lv_max;
    if (tables) {
        if (sim_load_table(cli.name, tables, "q2_pdaf_g6.tbl", &pdaf_t, &pdaf_buf)) goto out;
        src.pdaf = &pdaf_t;
    } else {
        /* one PDAF q2 grid (Brekke's gate) serves every model: q2 depends on
         * the model only through pd */
        struct q2_table_spec s;
        memset(&s, 0, sizeof s);
        static double pd[Q2_TABLE_MAX_NODES];
        const int np = q2_table_parse_list(Q2_TABLE_DEFAULT_PD, pd, (int)Q2_TABLE_MAX_NODES);
        s.detector = TRK_Q2_PDAF;
        s.nz = 2;
        s.gate_gamma = 36;
        s.cubic = 1;
        q2_table_list_axis(pd, np, &s.pd);
        if (q2_table_parse_log(Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF, &s.lambda_vg)) goto out;
        struct q2_table_run r;
        memset(&r, 0, sizeof r);
        r.samples = samples ? (uint64_t)samples : Q2_TABLE_DEFAULT_SAMPLES;
        r.target_se = target_se > 0 ? target_se : Q2_TABLE_DEFAULT_TARGET_SE;
        r.seed = com.seed;
        r.threads = com.threads;
        r.par = com.par;
        struct q2_table_result res;
        if (!com.quiet) fprintf(stderr, "trk-sim toc: sampling the PDAF q2 grid (gate g = 6) ...\n");
        if (q2_table_build(&s, &r, &res, err, sizeof err)) {
            fprintf(stderr, "trk-sim toc: PDAF q2 grid: %s\n", err);
            goto out;
        }
        pdaf_bytes = res.bytes;
        res.bytes = NULL;
        q2_table_result_free(&res);
        if (trk_table_parse(&pdaf_t, pdaf_bytes, res.len) != TRK_OK) {
            fprintf(stderr, "trk-sim toc: the sampled PDAF q2 table does not parse\n");
            goto out;
        }
        src.pdaf = &pdaf_t;
    }
    for (int m = 0; m < N_MODELS; m++) {
        struct toc_scenario sc;
        toc_scenario_brekke(&sc, models[m].model, models[m].nu, snr_db, cells[0]);
        sc.pfa_min = pfa_min;
        sc.pfa_max = pfa_max;
        sc.mre_start = mre_start;
        src.pdafai = NULL;
        if (tables) {
            if (sim_load_table(cli.name, tables, models[m].table, &ai_t[m], &ai_buf[m])) goto out;
            src.pdafai = &ai_t[m];
        } else if (!com.quiet) {
            fprintf(stderr, "trk-sim toc: sampling the PDAFAI q2 grid, %s clutter, SNR %g dB ...\n", models[m].label, snr_db);
        }
        toc[m] = toc_new(&sc, &src, err, sizeof err);
        if (!toc[m]) {
            fprintf(stderr, "trk-sim toc: %s: %s\n", models[m].label, err);
            goto out;
        }
    }
    char path[1024], head[1024];
    const int nh = snprintf(head, sizeof head,
                            "# toc: Brekke Fig. 2 model, SNR %g dB; q2 from %s\n"
                            "# assumptions: MRE start %s (--mre-start: the MRE's start at every P_FA)\n",
                            snr_db, tables ? "the tables in --tables" : "grids sampled for this SNR",
                            toc_start_name(mre_start));
    if (nh < 0 || (size_t)nh >= sizeof head / 2) goto out;
    snprintf(head + nh, sizeof head - (size_t)nh, "%s",
             "model,nu,cell_m2,detector,pfa,pd,rmse_m,q2,lambda_vg,mre_solves,without_steady_state,at_range_end,"
             "table_limited,pfa_rmse_1pct_lo,pfa_rmse_1pct_hi");
    fo = sim_csv_open(&com, &fo_out, "_optimum.csv", path, sizeof path, head);
    snprintf(head + nh, sizeof head - (size_t)nh, "%s",
             "model,nu,cell_m2,pfa,pd,lambda_per_m2,rmse_pdaf_m,status_pdaf,q2_pdaf,lambda_vg_pdaf,"
             "rmse_pdafai_m,status_pdafai,q2_pdafai,lambda_vg_pdafai,rmse_bound_pdaf_m,rmse_bound_pdafai_m");
    f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path, head);
    if (!f || !fo) goto out;
    printf("TOC (Brekke Fig. 2 model): SNR %g dB, T 1 s, q 0.0125^2, R I/12, gamma 36; lambda = P_FA / cell;\n"
           "MRE start %s; q2 from %s; %d thread%s. Curves beyond a P_FA where the MRE diverges (track lost)\n"
           "or settles above the q2 table's lambda_vg are left out (status in the CSV).\n",
           snr_db, toc_start_name(mre_start), tables ? "the tables in --tables" : "grids sampled for this SNR", threads, threads == 1 ? "" : "s");
    printf("%-10s %7s  %-7s %10s %8s %10s %8s %8s  %s\n", "clutter", "cell m2", "filter", "opt P_FA", "P_D",
           "RMSE m", "q2", "lam V_G", "P_FA with RMSE within 1 %");
    for (int m = 0; m < N_MODELS; m++)
        for (int c = 0; c < n_cells; c++) {
            if (toc_set_cell_m2(toc[m], cells[c], err, sizeof err) ||
                toc_curve(toc[m], (size_t)points, pts, err, sizeof err)) {
                fprintf(stderr, "trk-sim toc: %s, cell %g: %s\n", models[m].label, cells[c], err);
                goto out;
            }
            for (long i = 0; i < points; i++) {
                const struct toc_point *p = &pts[i];
                fprintf(f, "%s,%g,%g,%.6g,%.8f,%.6g", models[m].name, models[m].nu, cells[c], p->pfa, p->pd,
                        p->lambda_per_m2);
                for (int d = 0; d < TOC_N_DETECTORS; d++) {
                    if (p->status[d] == TOC_OK)
                        fprintf(f, ",%.6g,%s,%.6g,%.6g", p->rmse_m[d], toc_status_name(p->status[d]), p->q2[d],
                                p->lambda_vg[d]);
                    else
                        fprintf(f, ",,%s,,", toc_status_name(p->status[d]));
                }
                for (int d = 0; d < TOC_N_DETECTORS; d++)
                    if (p->status[d] == TOC_OFF_TABLE) fprintf(f, ",%.6g", p->rmse_bound_m[d]);
                    else fprintf(f, ",");
                fprintf(f, "\n");
            }
            for (int d = 0; d < TOC_N_DETECTORS; d++) {
                struct toc_optimum *o = &opt[m][c][d];
                if (toc_optimum(toc[m], d, o, err, sizeof err)) {
                    fprintf(stderr, "trk-sim toc: %s, cell %g: %s\n", models[m].label, cells[c], err);
                    o->pfa = NAN;
                    printf("%-10s %7g  %-7s %10s\n", models[m].label, cells[c], toc_detector_name(d), "none");
                    continue;
                }
                fprintf(fo, "%s,%g,%g,%s,%.6g,%.8f,%.6g,%.6g,%.6g,%d,%d,%d,%d,%.4g,%.4g\n", models[m].name,
                        models[m].nu, cells[c], toc_detector_name(d), o->pfa, o->pd, o->rmse_m, o->q2, o->lambda_vg,
                        o->n_evals, o->n_diverged, o->at_range_end, o->table_limited, o->pfa_1pct_lo,
                        o->pfa_1pct_hi);
                printf("%-10s %7g  %-7s %10.3g %8.4f %10.4f %8.4f %8.3g  %8.2g..%-8.2g%s%s\n", models[m].label,
                       cells[c], toc_detector_name(d), o->pfa, o->pd, o->rmse_m, o->q2, o->lambda_vg, o->pfa_1pct_lo,
                       o->pfa_1pct_hi,
                       o->at_range_end ? "  (end of the P_FA range)" : "",
                       o->table_limited ? "  (q2 table's edge nearby: --lambda-vg-max)" : "");
            }
        }
    f = fo = NULL;
    const int bad_f = sim_csv_close(&f_out) != 0;
    if (sim_csv_close(&fo_out) != 0 || bad_f) goto out;
    printf("curves: %s.csv, optima: %s_optimum.csv\n", com.out, com.out);
    rc = 0;
    if (!com.no_plot) {
        /* one panel per cell area: 3 models x 2 detectors, optima as points */
        struct sim_text b = {NULL, 0, 0, 0};
        sim_text_add(&b,
                     "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                     "  set terminal pngcairo size %d,620 enhanced font 'sans,10'\n"
                     "} else {\n  set terminal png size %d,620\n}\nset output '%s.png'\n",
                     520 * n_cells, 520 * n_cells, com.out);
        sim_text_add(&b,
                     "set datafile separator ','\nset logscale x\nset format x '10^{%%L}'\n"
                     "set grid\nset key top right font ',8'\n"
                     "set xlabel 'P_{FA}'\nset ylabel 'steady-state position RMSE (m)'\nset yrange [0:1]\n"
                     "set multiplot layout 1,%d title \"TOC (MRE), SNR %g dB, Brekke Table I model\\n"
                     "MRE start %s\"\n",
                     n_cells, snr_db, toc_start_name(mre_start));
        for (int c = 0; c < n_cells; c++) {
            sim_text_add(&b, "set title 'cell %g m^2 (lambda = P_{FA}/%g)'\nplot ", cells[c], cells[c]);
            for (int m = 0; m < N_MODELS; m++)
                for (int d = 0; d < TOC_N_DETECTORS; d++)
                    sim_text_add(&b,
                                 "'%s.csv' using ((strcol(1) eq '%s' && $3 == %g) ? $4 : 1/0):%d with lines lw 2 "
                                 "lc %d dt %d title '%s %s', ",
                                 com.out, models[m].name, cells[c], d ? 11 : 7, m + 1, d ? 1 : 2,
                                 toc_detector_name(d), models[m].label);
            /* off the q2 table: the RMSE's lower bound, marked (columns 15, 16) */
            for (int d = 0; d < TOC_N_DETECTORS; d++)
                sim_text_add(&b,
                             "'%s.csv' using ($3 == %g ? $4 : 1/0):%d with points pt %d ps 0.6 lc rgb '#888888' "
                             "title 'off table, %s: RMSE lower bound (those <= 1 m)', ",
                             com.out, cells[c], 15 + d, d ? 8 : 10, toc_detector_name(d));
            sim_text_add(&b,
                         "'%s_optimum.csv' using ($3 == %g ? $5 : 1/0):7 with points pt 7 ps 1.2 lc 0 "
                         "title 'optimum'\n",
                         com.out, cells[c]);
        }
        sim_text_add(&b, "unset multiplot\n");
        if (b.failed || sim_plot(&com, "", b.s) < 0) rc = 1;
        sim_text_free(&b);
    }
out:
    if (f) sim_csv_discard(&f_out);
    if (fo) sim_csv_discard(&fo_out);
    for (int m = 0; m < N_MODELS; m++) toc_free(toc[m]), free(ai_buf[m]);
    free(pdaf_buf);
    free(pdaf_bytes);
    free(pts);
    return rc;
}
