/* exp_brekke_trackloss.c - trk-sim brekke-trackloss: Brekke, Hallingstad,
 * Glattetre 2011, Tables II and III: lost tracks out of 10000 for the PDAF
 * and the PDAFAI in K-distributed clutter (nu = 1 and 8), SNR 10 and 15 dB,
 * P_FA 1e-4, 1e-2 and 1e-1, with the paper's Table I setting (T = 1 s,
 * 300 scans, sigma_v^2 = 0.0125^2, sigma_r^2 = 1/12, g = 6) and its
 * two-stage loss rule (sec. V.B, c1 = 5 m, c2 = 15 m).
 *
 * One run = one target and one track, simulated by single_target.h on the
 * library's one-track functions (trk_cv2_predict, trk_pda_update with
 * ln l^a from trk_amplitude_log_lr; amplitudes drawn by trk_amplitude_inv_sf
 * on an in-memory K amplitude table). The PDAF and the PDAFAI of a run see
 * the same target, detections and clutter field (common random numbers), so
 * their difference is measured pairwise.
 *
 * The paper's unprinted choices, ours (docs/conventions.md "Brekke Table I mapping"):
 *   resolution cell  lambda = P_FA / cell; 1, 0.25 and 0.1 m^2 all reported
 *   initial track    two-point differencing (per axis [[r, r/T],
 *                    [r/T, 2r/T^2]]), estimate drawn from N(truth, P_0)
 *                    (--start steady: the clutter-free Kalman steady state)
 *   target velocity  1 m/s along x (does not change the error statistics:
 *                    the filter is linear and the clutter homogeneous)
 *   texture          drawn independently for every detection (i.i.d.
 *                    amplitudes with the K marginal law: the model the
 *                    PDAFAI assumes)
 *   perfect knowledge the filters use the true P_FA, P_D = S1(t), lambda, nu, SNR
 *   runaway gate     a gate holding more than TRK_MAX_DETECTIONS passes its
 *                    nearest (--gate-cap truncate:N | lost:LAMBDA_VG)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "mc_stats.h"
#include "progress.h"
#include "sim.h"
#include "single_target.h"

#define MAXL 16

/* Brekke Tables II (nu = 1) and III (nu = 8): [nu][snr 10, 15][pfa 1e-4, 1e-2, 1e-1][PDAF, PDAFAI] */
static const int paper_lost[2][2][3][2] = {
    {{{4367, 3789}, {3361, 834}, {9549, 721}}, {{67, 22}, {482, 12}, {6727, 19}}},
    {{{181, 74}, {1401, 51}, {9327, 64}}, {{3, 0}, {275, 1}, {6611, 4}}}};

/* The paper's value for (nu, snr, pfa, filter), or -1. */
static int paper_value(double nu, double snr, double pfa, int f)
{
    int i = nu == 1 ? 0 : nu == 8 ? 1 : -1, j = snr == 10 ? 0 : snr == 15 ? 1 : -1;
    int k = fabs(pfa - 1e-4) < 1e-12 ? 0 : fabs(pfa - 1e-2) < 1e-12 ? 1 : fabs(pfa - 1e-1) < 1e-12 ? 2 : -1;
    if (i < 0 || j < 0 || k < 0) return -1;
    return paper_lost[i][j][k][f];
}

struct tl_out {          /* one run, both filters */
    unsigned char lost[2], hard[2], failed[2], trunc[2], gate_lost[2];
    int32_t scans[2];
    int32_t gated[2];
    int32_t gated_clutter[2];
    int32_t lost_scan[2];     /* 0: kept */
    double mse[2];            /* mean squared position error over the run's scans */
};

static void keep(void *slot, int f, const struct st_result *res)
{
    struct tl_out *o = slot;
    o->lost[f] = (unsigned char)res->lost;
    o->hard[f] = (unsigned char)res->lost_hard;
    o->failed[f] = (unsigned char)res->failed;
    o->trunc[f] = res->truncated > 0;
    o->gate_lost[f] = (unsigned char)res->gate_lost;
    o->lost_scan[f] = res->lost ? (int32_t)res->lost_scan : 0;
    o->mse[f] = res->n_sse ? res->sse / (double)res->n_sse : NAN;
    o->scans[f] = (int32_t)res->scans;
    o->gated[f] = (int32_t)res->gated;
    o->gated_clutter[f] = (int32_t)res->gated_clutter;
}

static const int grid_values[] = {TRK_AMP_GRID_UNIFORM, TRK_AMP_GRID_GEOMETRIC};

/* The distributions of PREFIX_loss.csv (lpath) as plots: PREFIX_loss.png,
 * when the tracks are lost (lost per 10000 runs in each tenth of the run,
 * per scenario; rows: cells, columns: filters; data PREFIX_loss_plot.csv),
 * and PREFIX_kept.png, the per-run position RMSE of the tracks kept (box
 * 25-75 %, whiskers 5-95 %, median; the RMSE over the kept runs with its
 * 95 % interval), one panel per cell. as: the assumptions for the titles.
 * 0, or -1 after a message (a data file not written). */
static int plot_loss(const struct sim_common *com, const char *lpath, const long *lbins, const double *cells,
                     int ncell, const double *nus, int nnu, const double *snrs, int nsnr, const double *pfas, int npfa,
                     long runs, long scans, const char *as)
{
    const int nscen = nnu * nsnr * npfa;
    char dat[1024];
    struct fileio_out d_out;
    FILE *d = sim_csv_open(com, &d_out, "_loss_plot.csv", dat, sizeof dat,
                           "# blocks: cell, filter, scenario (gnuplot index (c * 2 + filter) * scenarios + s)\n"
                           "scan_mid,lost_per_10000");
    if (!d) return -1;
    for (int c = 0; c < ncell; c++)
        for (int fl = 0; fl < 2; fl++)
            for (int s = 0; s < nscen; s++) {
                const long *b = &lbins[(((long)c * nscen + s) * 2 + fl) * 10];
                for (int k = 0; k < 10; k++)
                    fprintf(d, "%.6g,%.6g\n", 0.5 * (double)(scans * k / 10 + 1 + scans * (k + 1) / 10),
                            (double)b[k] * 10000.0 / (double)runs);
                fprintf(d, "\n\n");
            }
    if (sim_csv_close(&d_out) != 0) return -1;
    char base[1040];
    snprintf(base, sizeof base, "%s_loss", com->out);
    struct sim_text t = {NULL, 0, 0, 0};
    sim_text_add(&t,
                 "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                 "  set terminal pngcairo size 1400,%d enhanced font 'sans,10'\n"
                 "} else {\n  set terminal png size 1400,%d\n}\nset output '%s.png'\n",
                 320 * ncell + 90, 320 * ncell + 90, base);
    sim_text_add(&t,
                 "set datafile separator ','\nset grid\nset logscale y\nset key outside right font ',8'\n"
                 "set xtics %ld\n", scans / 5 > 0 ? scans / 5 : 1);
    sim_text_add(&t,
                 "set xlabel 'scan of the loss (tenths of the run)'\nset ylabel 'lost per 10000 in the tenth'\n"
                 "set xrange [0:%ld]\nset yrange [*:*]\n"
                 "set multiplot layout %d,2 title \"Brekke 2011 track losses: when the tracks are lost (%ld runs x %ld "
                 "scans; scenarios without a loss not drawn)\\n%s\" font ',10'\n",
                 scans, ncell, runs, scans, as);
    for (int c = 0; c < ncell; c++)
        for (int fl = 0; fl < 2; fl++) {
            sim_text_add(&t, "set title '%s, cell %g m^2' font ',9'\nplot ", fl ? "PDAFAI" : "PDAF", cells[c]);
            int drawn = 0;
            for (int s = 0; s < nscen; s++) {
                const int a = s / (nsnr * npfa), b = (s / npfa) % nsnr, cc = s % npfa;
                const long *lb = &lbins[(((long)c * nscen + s) * 2 + fl) * 10];
                long tot = 0;
                for (int k = 0; k < 10; k++) tot += lb[k];
                if (tot == 0) continue;
                sim_text_add(&t, "%s'%s' index %d using 1:($2 > 0 ? $2 : NaN) with linespoints pt %d lc %d "
                                 "title 'nu %g %g dB P_{FA} %.0e'",
                             drawn ? ", \\\n     " : "", dat, (c * 2 + fl) * nscen + s, 1 + s % 13, 1 + s,
                             nus[a], snrs[b], pfas[cc]);
                drawn++;
            }
            if (!drawn) sim_text_add(&t, "NaN title 'no track lost'");
            sim_text_add(&t, "\n");
        }
    sim_text_add(&t, "unset multiplot\n");
    if (!t.failed) sim_plot(com, "_loss", t.s);
    sim_text_free(&t);
    /* kept-track RMSE: PREFIX_loss.csv's rows, in the order cell, scenario, filter ($0 - 1 = data row) */
    struct sim_text k = {NULL, 0, 0, 0};
    sim_text_add(&k,
                 "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
                 "  set terminal pngcairo size %d,700 enhanced font 'sans,10'\n"
                 "} else {\n  set terminal png size %d,700\n}\nset output '%s_kept.png'\n",
                 80 + 520 * ncell, 80 + 520 * ncell, com->out);
    sim_text_add(&k,
                 "set datafile separator ','\nset datafile missing 'nan'\nset grid\nset logscale y\n"
                 "set yrange [0.1:50]\n"
                 "set key top right font ',8'\nset ylabel 'position RMSE of a kept run (m)'\n"
                 "set xrange [-0.6:%d.6]\nset boxwidth 0.25\nset xtics rotate by 60 right font ',7' (",
                 nscen - 1);
    for (int s = 0; s < nscen; s++) {
        const int a = s / (nsnr * npfa), b = (s / npfa) % nsnr, cc = s % npfa;
        sim_text_add(&k, "%s\"nu%g %gdB %.0e\" %d", s ? ", " : "", nus[a], snrs[b], pfas[cc], s);
    }
    sim_text_add(&k,
                 ")\nsc(r) = int(r / 2) %% %d\n"
                 "set multiplot layout 1,%d title \"Brekke 2011: position RMSE of the tracks kept (%ld runs x %ld "
                 "scans, all scans of a run)\\nbox 25-75%%, whiskers 5-95%%, bar median; point: the RMSE over the kept "
                 "runs with 95%% CI\\n%s\" font ',9'\n",
                 nscen, ncell, runs, scans, as);
    for (int c = 0; c < ncell; c++) {
        sim_text_add(&k, "set title 'cell %g m^2' font ',9'\nplot ", cells[c]);
        for (int fl = 0; fl < 2; fl++) {
            const char *nm = fl ? "PDAFAI" : "PDAF";
            const double off = fl ? 0.17 : -0.17;
            sim_text_add(&k,
                         "%s'%s' every ::1 using ($1 == %g && strcol(5) eq '%s' ? sc($0 - 1) %+.2f : NaN):21:20:24:23 "
                         "with candlesticks whiskerbars lc %d title '%s', \\\n"
                         "     '%s' every ::1 using ($1 == %g && strcol(5) eq '%s' ? sc($0 - 1) %+.2f : NaN):22:22:22:22 "
                         "with candlesticks lw 2 lc %d notitle, \\\n"
                         "     '%s' every ::1 using ($1 == %g && strcol(5) eq '%s' ? sc($0 - 1) %+.2f : NaN):7:8:9 "
                         "with yerrorbars pt 7 ps 0.6 lc rgb 'black' %s",
                         fl ? ", \\\n     " : "", lpath, cells[c], nm, off, fl + 1, nm, lpath, cells[c], nm, off,
                         fl + 1, lpath, cells[c], nm, off, fl ? "notitle" : "title 'RMSE over kept runs'");
        }
        sim_text_add(&k, "\n");
    }
    sim_text_add(&k, "unset multiplot\n");
    if (!k.failed) sim_plot(com, "_kept", k.s);
    sim_text_free(&k);
    return 0;
}

SIM_EXPERIMENT(brekke_trackloss, "brekke-trackloss", "Brekke 2011 Tables II-III: lost tracks, PDAF vs PDAFAI in K clutter")
{
    long runs, scans, amp_size = 0;
    double cells[MAXL], nus[MAXL], snrs[MAXL], pfas[MAXL];
    int ncell, nnu, nsnr, npfa, init, grid, texture;
    struct st_gate_cap gate_cap;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "10000", SIM_GE, 1, 0, "runs per scenario and filter, as in the paper"),
        SIM_OPT_LONG("--scans", &scans, "N", "300", SIM_IN, 1, 1000000, "scans per run"),
        SIM_OPT_LIST("--cell-m2", cells, &ncell, MAXL, "1,0.25,0.1", SIM_GT, 0, 0,
                     "resolution cell areas, lambda = P_FA / cell\n"
                     "(the paper does not print it; all three are reported)"),
        SIM_OPT_LIST("--k-shape", nus, &nnu, MAXL, "1,8", SIM_GT, 0, 0, "K shapes nu"),
        SIM_OPT_ALIAS("--nu", "--k-shape"),
        SIM_OPT_LIST("--snr-db", snrs, &nsnr, MAXL, "10,15", 0, 0, 0, "target SNRs"),
        SIM_OPT_LIST("--pfa", pfas, &npfa, MAXL, "1e-4,1e-2,1e-1", 0, 0, 0, "false-alarm probabilities"),
        SIM_OPT_TEXTURE(&texture),
        SIM_OPT_START(&init),
        SIM_OPT_ALIAS("--init", "--start"),
        SIM_OPT_GATE_CAP(&gate_cap),
        SIM_OPT_CHOICE("--grid", &grid, "uniform|geometric", grid_values, "uniform",
                       "amplitude table grid (geometric = Brekke\neqs 43-45, piecewise linear)"),
        SIM_OPT_LONG("--amp-size", &amp_size, "N", NULL, SIM_IN, 0, 65536,
                     "points per amplitude-table curve (default: the generator's)"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "brekke-trackloss", NULL,
        "Brekke 2011 Tables II-III: lost tracks of the PDAF and the PDAFAI in K clutter, Table I\n"
        "setting (T 1 s, 300 scans, q 0.0125^2, R I/12, g 6, loss c1 5 m / c2 15 m, sec. V.B).",
        opts, "brekke_trackloss", NULL, 0,
        "Writes PREFIX.csv, PREFIX_loss.csv (loss times, kept-track RMSE), PREFIX.gp, PREFIX.png.\n"
        "Prints each table beside the paper's values (per 10000 runs) with exact 95% intervals;\n"
        "'*' marks a paper value outside ours.",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (runs > 0xFFFFFFFFL) {
        fprintf(stderr, "trk-sim brekke-trackloss: at most 2^32 runs\n");
        return 2;
    }
    const int threads = sim_threads(&com);
    const int nscen = nnu * nsnr * npfa, namp = nscen;
    /* amplitude models: one K table per (nu, snr, pfa), built in parallel */
    struct st_amp *amp = calloc((size_t)namp, sizeof *amp);
    if (!amp) return 1;
    const double t_tab = progress_now_s();
    if (sim_amp_k_grid(cli.name, amp, nus, nnu, snrs, nsnr, pfas, npfa, grid, (unsigned)amp_size)) return 1;
    const double tab_s = progress_now_s() - t_tab;
    /* one model per (cell, scenario) */
    const long nmod = (long)ncell * nscen;
    struct st_model *mod = calloc((size_t)nmod, sizeof *mod);
    struct tl_out *out = calloc((size_t)(nmod * runs), sizeof *out);
    if (!mod || !out) {
        fprintf(stderr, "trk-sim brekke-trackloss: out of memory\n");
        return 1;
    }
    for (int c = 0; c < ncell; c++)
        for (int s = 0; s < nscen; s++)
            if (sim_brekke_model(cli.name, &mod[c * nscen + s], &amp[s], cells[c], scans, init, texture, &gate_cap,
                                 com.seed))
                return 1;
    if (!com.quiet)
        fprintf(stderr,
                "brekke-trackloss: %d cells x %d scenarios x 2 filters x %ld runs x %ld scans, seed %llu, %d threads "
                "(amplitude tables %.1f s)\n",
                ncell, nscen, runs, scans, (unsigned long long)com.seed, threads, tab_s);
    int bad_call;
    const double wall = sim_st_runs(&com, cli.name, mod, nmod, runs, 2, 1, keep, out, sizeof *out, &bad_call);
    if (bad_call) {
        fprintf(stderr, "trk-sim brekke-trackloss: internal error (bad run call)\n");
        return 1;
    }
    /* reduce in run order */
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# brekke-trackloss: Brekke 2011 Tables II-III, lost tracks per scenario and filter");
    if (!f) return 1;
    fprintf(f, "# Table I: T 1 s, %ld scans, q 0.0125^2 m^2/s^3, R I/12 m^2, gate g 6 (gamma 36; used %.6g), c1 5 m, c2 15 m\n",
            scans, mod[0].gamma_used);
    fprintf(f, "# choices: lambda = pfa / cell; initial track %s (estimate ~ N(truth, P0)); target 1 m/s along x; "
               "texture %s; amplitude tables %s grid; seed %llu; runs %ld\n",
            init == ST_INIT_TWOPOINT ? "two-point differencing" : "clutter-free Kalman steady state",
            texture == ST_TEXTURE_CELL ? "independent per detection" : "one per scan",
            grid == TRK_AMP_GRID_UNIFORM ? "uniform" : "geometric (eqs 43-45)", (unsigned long long)com.seed, runs);
    sim_assumptions_csv(f, init, &gate_cap, -1);
    fprintf(f, "cell_m2,nu,snr_db,pfa,pd,lambda_per_m2,filter,runs,lost,lost_per_10000,lo95_per_10000,hi95_per_10000,"
               "paper,paper_in_ci,lost_c2,failed,truncated_runs,mean_scans,gated_per_scan,gated_clutter_per_scan,only_this_lost,gate_cap_lost\n");
    long total_scans = 0;
    double *lostv[2], *lov[2], *hiv[2];
    for (int fl = 0; fl < 2; fl++) {
        lostv[fl] = calloc((size_t)nmod, sizeof(double));
        lov[fl] = calloc((size_t)nmod, sizeof(double));
        hiv[fl] = calloc((size_t)nmod, sizeof(double));
        if (!lostv[fl] || !lov[fl] || !hiv[fl]) {
            fprintf(stderr, "trk-sim brekke-trackloss: out of memory\n");
            sim_csv_discard(&f_out);
            return 1;
        }
    }
    int outside_ci = 0, n_cmp = 0;
    for (int c = 0; c < ncell; c++) {
        printf("\n# cell %g m^2 (lambda = P_FA / %g m^2): lost tracks per 10000 runs, paper | ours [exact 95%% CI]\n",
               cells[c], cells[c]);
        printf("%4s %5s %7s %7s %9s | %6s %-22s | %6s %-22s | %s\n", "nu", "SNR", "P_FA", "P_D", "clutter/gate",
               "PDAF", " ours", "PDAFAI", " ours", "pairs AI-only/PDAF-only lost");
        for (int s = 0; s < nscen; s++) {
            const int a = s / (nsnr * npfa), b = (s / npfa) % nsnr, cc = s % npfa;
            const long mi = (long)c * nscen + s;
            long lost[2] = {0, 0}, hard[2] = {0, 0}, failed[2] = {0, 0}, only[2] = {0, 0}, trunc[2] = {0, 0};
            long gl[2] = {0, 0};
            double sc[2] = {0, 0}, gt[2] = {0, 0}, gc[2] = {0, 0};
            for (long run = 0; run < runs; run++) {
                const struct tl_out *o = &out[mi * runs + run];
                for (int fl = 0; fl < 2; fl++) {
                    lost[fl] += o->lost[fl];
                    hard[fl] += o->hard[fl];
                    failed[fl] += o->failed[fl];
                    trunc[fl] += o->trunc[fl];
                    gl[fl] += o->gate_lost[fl];
                    sc[fl] += o->scans[fl];
                    gt[fl] += o->gated[fl];
                    gc[fl] += o->gated_clutter[fl];
                    total_scans += o->scans[fl];
                }
                only[0] += o->lost[0] && !o->lost[1];
                only[1] += o->lost[1] && !o->lost[0];
            }
            char cell_txt[2][64];
            int pv[2];
            for (int fl = 0; fl < 2; fl++) {
                double lo, hi;
                mc_binom_ci(lost[fl], runs, 0.95, &lo, &hi);
                const double scale = 10000.0 / (double)runs;
                pv[fl] = paper_value(nus[a], snrs[b], pfas[cc], fl);
                const int in = pv[fl] < 0 || (pv[fl] / 10000.0 >= lo && pv[fl] / 10000.0 <= hi);
                if (pv[fl] >= 0) {
                    n_cmp++;
                    outside_ci += !in;
                }
                const size_t idx = (size_t)mi;
                lostv[fl][idx] = (double)lost[fl] * scale;
                lov[fl][idx] = lo * 10000;
                hiv[fl][idx] = hi * 10000;
                snprintf(cell_txt[fl], sizeof cell_txt[fl], "%7.1f [%6.1f, %6.1f]%s", (double)lost[fl] * scale,
                         lo * 10000, hi * 10000, in ? " " : "*");
                fprintf(f, "%g,%g,%g,%g,%.6g,%.6g,%s,%ld,%ld,%.6g,%.6g,%.6g,%d,%d,%ld,%ld,%ld,%.6g,%.6g,%.6g,%ld,%ld\n", cells[c],
                        nus[a], snrs[b], pfas[cc], amp[s].pd, mod[mi].p.lambda_per_m2, fl ? "PDAFAI" : "PDAF", runs,
                        lost[fl], (double)lost[fl] * scale, lo * 10000, hi * 10000, pv[fl], in, hard[fl], failed[fl],
                        trunc[fl], sc[fl] / (double)runs, sc[fl] > 0 ? gt[fl] / sc[fl] : 0,
                        sc[fl] > 0 ? gc[fl] / sc[fl] : 0, only[fl], gl[fl]);
            }
            /* mean gated clutter per scan: of the PDAFAI (it stays on the target) */
            const double gate_mean = sc[1] > 0 ? gc[1] / sc[1] : 0;
            char p0[16], p1[16];
            snprintf(p0, sizeof p0, pv[0] >= 0 ? "%d" : "-", pv[0]);
            snprintf(p1, sizeof p1, pv[1] >= 0 ? "%d" : "-", pv[1]);
            printf("%4g %5g %7.0e %7.4f %9.3g | %6s %-22s | %6s %-22s | %ld / %ld\n", nus[a], snrs[b], pfas[cc],
                   amp[s].pd, gate_mean, p0, cell_txt[0], p1, cell_txt[1], only[1], only[0]);
        }
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    /* the distributions behind the counts: when tracks are lost (10 bins of
     * the run length), and the RMSE of the tracks kept */
    char lpath[1024];
    struct fileio_out l_out;
    FILE *fl_ = sim_csv_open(&com, &l_out, "_loss.csv", lpath, sizeof lpath,
                             "# brekke-trackloss: loss times (scan of the loss, 10 bins of the run) and the position RMSE "
                             "of the tracks kept (over all their scans, 95% interval; the quantiles of the per-run RMSE)");
    double *kv = malloc((size_t)runs * sizeof *kv);
    long *lbins = calloc((size_t)nmod * 20, sizeof *lbins); /* [model][filter][bin], for the plot */
    if (!fl_ || !kv || !lbins) {
        if (fl_) sim_csv_discard(&l_out);
        free(kv);
        return 1;
    }
    sim_assumptions_csv(fl_, init, &gate_cap, -1);
    fprintf(fl_, "cell_m2,nu,snr_db,pfa,filter,kept,kept_rmse_m,kept_rmse_lo95,kept_rmse_hi95");
    for (int b = 0; b < 10; b++)
        fprintf(fl_, ",lost_scans_%ld_%ld", scans * b / 10 + 1, scans * (b + 1) / 10);
    fprintf(fl_, ",kept_rmse_q05,kept_rmse_q25,kept_rmse_q50,kept_rmse_q75,kept_rmse_q95\n");
    static const double qp[5] = {0.05, 0.25, 0.5, 0.75, 0.95};
    for (int c = 0; c < ncell; c++)
        for (int s = 0; s < nscen; s++) {
            const int a = s / (nsnr * npfa), b = (s / npfa) % nsnr, cc = s % npfa;
            const long mi = (long)c * nscen + s;
            for (int fl = 0; fl < 2; fl++) {
                long bins[10] = {0};
                size_t nk = 0;
                for (long run = 0; run < runs; run++) {
                    const struct tl_out *o = &out[mi * runs + run];
                    if (o->lost_scan[fl] > 0) {
                        long bi = ((long)o->lost_scan[fl] - 1) * 10 / scans;
                        bins[bi < 0 ? 0 : bi > 9 ? 9 : bi]++;
                    } else if (!isnan(o->mse[fl])) {
                        kv[nk++] = o->mse[fl];
                    }
                }
                double m = NAN, lo = NAN, hi = NAN;
                if (nk > 0) mc_mean_ci(kv, nk, 0.95, &m, &lo, &hi);
                fprintf(fl_, "%g,%g,%g,%g,%s,%zu,%.6g,%.6g,%.6g", cells[c], nus[a], snrs[b], pfas[cc],
                        fl ? "PDAFAI" : "PDAF", nk, sqrt(m), sqrt(fmax(lo, 0)), sqrt(hi));
                for (int k = 0; k < 10; k++) fprintf(fl_, ",%ld", bins[k]), lbins[(mi * 2 + fl) * 10 + k] = bins[k];
                /* the per-run RMSE's distribution (sqrt is monotone: quantiles of the MSE) */
                mc_sort(kv, nk);
                for (int k = 0; k < 5; k++) fprintf(fl_, ",%.6g", sqrt(mc_quantile_sorted(kv, nk, qp[k])));
                fprintf(fl_, "\n");
            }
        }
    free(kv);
    if (sim_csv_close(&l_out) != 0) return 1;
    printf("\n# %d of %d paper values lie outside our 95%% interval (see the notes on the cell area)\n", outside_ci,
           n_cmp);
    printf("# wall %.1f s on %d threads (+ %.1f s amplitude tables); %ld track updates, %.3g updates/s\n", wall,
           threads, tab_s, total_scans, (double)total_scans / wall);
    printf("# files: %s, %s (loss times, kept-track RMSE)\n", path, lpath);
    if (!com.no_plot) {
        /* per cell: ours (points with error bars) and the paper (open symbols), one panel per filter */
        char dat[1024];
        struct fileio_out g_out;
    FILE *g = sim_csv_open(&com, &g_out, "_plot.csv", dat, sizeof dat,
                               "index,label,cell_m2,pdaf,pdaf_lo,pdaf_hi,pdafai,pdafai_lo,pdafai_hi,paper_pdaf,paper_pdafai");
        if (!g) return 1;
        for (int c = 0; c < ncell; c++)
            for (int s = 0; s < nscen; s++) {
                const int a = s / (nsnr * npfa), b = (s / npfa) % nsnr, cc = s % npfa;
                const size_t idx = (size_t)c * (size_t)nscen + (size_t)s;
                const int p0 = paper_value(nus[a], snrs[b], pfas[cc], 0), p1 = paper_value(nus[a], snrs[b], pfas[cc], 1);
                /* zero counts drawn at 0.5 on the log axis */
                fprintf(g, "%d,nu%g %gdB %.0e,%g,%g,%g,%g,%g,%g,%g,%g,%g\n", s, nus[a], snrs[b], pfas[cc], cells[c],
                        fmax(lostv[0][idx], 0.5), fmax(lov[0][idx], 0.5), fmax(hiv[0][idx], 0.5),
                        fmax(lostv[1][idx], 0.5), fmax(lov[1][idx], 0.5), fmax(hiv[1][idx], 0.5),
                        p0 < 0 ? NAN : fmax(p0, 0.5), p1 < 0 ? NAN : fmax(p1, 0.5));
            }
        if (sim_csv_close(&g_out) != 0) return 1;
        struct sim_text t = {NULL, 0, 0, 0};
        char as[160];
        sim_text_add(&t,
                     "set datafile separator ','\nset datafile missing 'nan'\nset logscale y\nset yrange [0.4:20000]\n"
                     "set grid\nset key bottom left font ',8'\nset xtics rotate by 60 right font ',7'\n"
                     "set xrange [-0.5:%d.5]\nset ylabel 'lost tracks per 10000 (0 drawn at 0.5)'\n"
                     "set multiplot layout 1,2 title \"Brekke 2011 Tables II-III: lost tracks (%ld runs x %ld scans)\\n%s\"\n",
                     nscen - 1, runs, scans, sim_assumptions_title(as, sizeof as, init, &gate_cap, -1));
        for (int fl = 0; fl < 2; fl++) {
            sim_text_add(&t,
                         "set title '%s'\nplot '%s' every ::1 using 1:%d:xtic(2) with points pt 6 ps 1.5 "
                         "lc rgb 'black' title 'paper'",
                         fl ? "PDAFAI" : "PDAF", dat, fl ? 11 : 10);
            for (int c = 0; c < ncell; c++)
                sim_text_add(&t,
                             ", \\\n  '%s' every ::%d::%d using ($1+%.2f):%d:%d:%d with yerrorbars pt 7 ps 0.8 lc %d "
                             "title 'ours, cell %g m^2'",
                             dat, 1 + c * nscen, (c + 1) * nscen, 0.12 * (c - (ncell - 1) / 2.0), fl ? 7 : 4,
                             fl ? 8 : 5, fl ? 9 : 6, c + 1, cells[c]);
            sim_text_add(&t, "\n");
        }
        sim_text_add(&t, "unset multiplot\n");
        if (!t.failed) sim_plot(&com, "", t.s);
        sim_text_free(&t);
        if (plot_loss(&com, lpath, lbins, cells, ncell, nus, nnu, snrs, nsnr, pfas, npfa, runs, scans, as)) return 1;
    }
    free(lbins);
    for (int fl = 0; fl < 2; fl++) free(lostv[fl]), free(lov[fl]), free(hiv[fl]);
    for (int s = 0; s < namp; s++) st_amp_free(&amp[s]);
    free(amp);
    free(mod);
    free(out);
    return 0;
}
