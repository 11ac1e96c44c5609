/* exp_brekke_errpdf.c - trk-sim brekke-errpdf: Brekke, Hallingstad,
 * Glattetre 2011, Figs. 3-5 (sec. V.B-C): the error pdfs (histograms of the
 * position error sqrt(dx^2 + dy^2)) of the PDAF and the PDAFAI in K clutter
 * at SNR 15 dB, with the MRE's stationary RMSE (eq 35) drawn as a vertical
 * line per filter.
 *
 * The figures. Fig. 5 is nu = 1, P_FA = 1e-1 (its caption). The captions of
 * Figs. 3 and 4 are not in the text; Fig. 2's vertical lines mark their P_FA
 * and the text calls Figs. 4 and 5 "the high-P_FA cases": we take the three
 * P_FA of Tables II-III at nu = 1, Fig. 3 = 1e-4, Fig. 4 = 1e-2, Fig. 5 =
 * 1e-1 (Table I's "P_FA 2 10^-4, 2 10^-2" line is garbled in the seed text
 * and not used). --pfa changes them: figure 3 + i is the i-th value.
 *
 * Simulation: brekke-trackloss's and brekke-toc's runs (sim_brekke_model,
 * single_target.h: one target, one track on the library's trk_cv2_predict /
 * trk_pda_update; the PDAF and the PDAFAI of a run see the same target,
 * detections and clutter), Table I (T 1 s, 300 scans, q 0.0125^2, R I/12,
 * g 6), lambda = P_FA / cell (1 m^2), two-point start (--start), Brekke's
 * two-stage loss rule (c1 5 m, c2 15 m). The histogram takes the error of
 * every scan >= --from (101: past the transient of the two-point start, the
 * scans of brekke-toc's RMSE) of the runs whose track is not lost (--tracks
 * kept: "bad tracks removed", the tracks the MRE describes); --tracks all
 * adds the lost runs' scans before their loss. Bins of equal width over
 * [0, --err-max) (default 4x the larger finite MRE of the figure), the
 * density normalised by all samples (those beyond the range counted as
 * overflow), so it integrates to the fraction inside the range.
 *
 * Prediction: the MRE of brekke-toc (sim_brekke_toc, toc_curve.h: the library's
 * MRE with q2 sampled for this scenario, --mre-start), eq 35's
 * sqrt(P11 + P22) at the steady state, per filter.
 *
 * Statistics per figure and filter: the mean error (the first moment: "the
 * MRE ... corresponds to the first-order moment of the error pdf") and the
 * RMS error with 95 % intervals over runs (ratio estimator: per-run sums
 * over per-run counts), the mode (the fullest bin's centre and edges), the
 * samples; the paper's claim is "a slightly positive (pessimistic) bias of
 * the MRE as compared with the modes" and upper tails (the PDAF at high
 * P_FA). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc_stats.h"
#include "progress.h"
#include "sim.h"
#include "single_target.h"
#include "toc_curve.h"

#define MAXP 8
#define FIG0 3 /* the first figure's number */

enum { TRACKS_KEPT = 0, TRACKS_ALL = 1 };
static const int tracks_values[] = {TRACKS_KEPT, TRACKS_ALL};

/* One run, both filters; followed by the counts uint32_t[2][bins]. */
struct ep_head {
    unsigned char lost[2];
    int32_t scans[2];
    int32_t n[2];        /* samples in the histogram (overflow included) */
    int32_t over[2];     /* samples >= err_max */
    double sum[2], sum2[2];
};

struct ep_ctx {
    long from, bins;
    int tracks;
    const double *width; /* per model: bin width */
};

static size_t slot_size_of(long bins)
{
    const size_t s = sizeof(struct ep_head) + 2 * (size_t)bins * sizeof(uint32_t);
    return (s + 7) / 8 * 8;
}

static uint32_t *counts_of(void *slot, int f, long bins)
{
    return (uint32_t *)((char *)slot + sizeof(struct ep_head)) + (size_t)f * (size_t)bins;
}

static void keep(void *ctx, void *slot, long k, int f, const struct st_result *res, const double *err)
{
    const struct ep_ctx *c = ctx;
    struct ep_head *h = slot;
    const double w = c->width[k];
    uint32_t *cnt = counts_of(slot, f, c->bins);
    h->lost[f] = (unsigned char)res->lost;
    h->scans[f] = (int32_t)res->scans;
    h->n[f] = h->over[f] = 0;
    h->sum[f] = h->sum2[f] = 0;
    for (long b = 0; b < c->bins; b++) cnt[b] = 0;
    if (res->lost && c->tracks == TRACKS_KEPT) return;
    /* a lost run: its scans before the loss */
    const long last = res->lost ? res->lost_scan - 1 : res->scans;
    for (long s = c->from; s <= last; s++) {
        const double e = err[s - 1];
        if (!isfinite(e)) continue;
        const long b = mc_hist_bin(e, 0, w, c->bins);
        if (b < 0) continue;
        if (b < c->bins) cnt[b]++;
        else h->over[f]++;
        h->n[f]++;
        h->sum[f] += e;
        h->sum2[f] += e * e;
    }
}

/* per figure and filter */
struct ep_stat {
    long runs_used, lost;
    double samples, over;
    double mean, mean_lo, mean_hi, rms, rms_lo, rms_hi, mode, mode_lo, mode_hi;
};

SIM_EXPERIMENT(brekke_errpdf, "brekke-errpdf", "Brekke 2011 Figs. 3-5: error pdfs of PDAF and PDAFAI vs the MRE")
{
    long runs, scans, from, bins, q2_samples = 0;
    double nu, snr, cell, pfas[MAXP], err_max;
    int npfa, init, texture, mre_start, tracks;
    struct st_gate_cap gate_cap;
    const char *tables = NULL;
    const struct sim_opt opts[] = {
        SIM_OPT_LONG("--runs", &runs, "N", "10000", SIM_GE, 1, 0, "runs per figure and filter, as in the paper"),
        SIM_OPT_LONG("--scans", &scans, "N", "300", SIM_IN, 2, 1000000, "scans per run"),
        SIM_OPT_LONG("--from", &from, "K", "101", SIM_GE, 1, 0,
                     "first scan in the histogram (past the two-point start's\ntransient; brekke-toc's RMSE scans)"),
        SIM_OPT_CHOICE("--tracks", &tracks, "kept|all", tracks_values, "kept",
                       "the runs in the histogram: those whose track is not lost\n"
                       "(bad tracks removed), or all (a lost run's scans before its loss)"),
        SIM_OPT_DOUBLE("--k-shape", &nu, "NU", "1", SIM_GT, 0, 0, "K shape nu (Figs. 3-5: 1)"),
        SIM_OPT_ALIAS("--nu", "--k-shape"),
        SIM_OPT_DOUBLE("--snr-db", &snr, "D", "15", 0, 0, 0, "target SNR"),
        SIM_OPT_DOUBLE("--cell-m2", &cell, "A", "1", SIM_GT, 0, 0, "resolution cell, lambda = P_FA / A"),
        SIM_OPT_LIST("--pfa", pfas, &npfa, MAXP, "1e-4,1e-2,1e-1", SIM_OPEN, 0, 1,
                     "P_FA of the figures: figure 3 + i is the i-th (Fig. 5: 1e-1, its\n"
                     "caption; Figs. 3-4: Tables II-III's 1e-4 and 1e-2, our reading)"),
        SIM_OPT_LONG("--bins", &bins, "N", "100", SIM_IN, 2, 100000, "histogram bins"),
        SIM_OPT_DOUBLE("--err-max", &err_max, "M", "0", SIM_GE, 0, 0,
                       "histogram range [0, M) m (0: 4x the larger finite MRE of the\n"
                       "figure; c1 = 5 m when neither is finite)"),
        SIM_OPT_TEXTURE(&texture),
        SIM_OPT_START(&init),
        SIM_OPT_GATE_CAP(&gate_cap),
        SIM_OPT_MRE_START(&mre_start),
        SIM_OPT_Q2_SAMPLES(&q2_samples),
        SIM_OPT_TABLES(&tables),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "brekke-errpdf", NULL,
        "Brekke 2011 Figs. 3-5: error pdfs (histograms of the position error) of the PDAF and the\n"
        "PDAFAI in K clutter (nu 1, SNR 15 dB; Table I setting, loss rule c1 5 m / c2 15 m), with\n"
        "the MRE's stationary RMSE (eq 35, brekke-toc's MRE) as a vertical line per filter.\n"
        "Fig. 3 = P_FA 1e-4, Fig. 4 = 1e-2, Fig. 5 = 1e-1 (only Fig. 5's caption is printed;\n"
        "Figs. 3-4 are read as Tables II-III's other two P_FA, the text's \"high-P_FA cases\n"
        "treated in Figs. 4 and 5\"). Histogram: scans >= --from of the runs not lost.",
        opts, "brekke_errpdf", NULL, 0,
        "Writes PREFIX.csv (per figure and filter: MRE, mean, RMS, mode, samples) and per figure N\n"
        "PREFIX_figN.csv (bins, density and counts per filter), PREFIX_figN.gp, PREFIX_figN.png.",
        NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    if (from > scans) {
        fprintf(stderr, "trk-sim brekke-errpdf: --from must be <= --scans\n");
        return 2;
    }
    if (runs > 0xFFFFFFFFL) {
        fprintf(stderr, "trk-sim brekke-errpdf: at most 2^32 runs\n");
        return 2;
    }
    const int threads = sim_threads(&com);
    double pmin = pfas[0], pmax = pfas[0];
    for (int j = 0; j < npfa; j++) pmin = fmin(pmin, pfas[j]), pmax = fmax(pmax, pfas[j]);
    /* ---- the MRE (brekke-toc's) */
    char err[512];
    void *tbuf[2];
    const double t_mre = progress_now_s();
    struct toc *toc = sim_brekke_toc(cli.name, &com, nu, snr, cell, pmin, pmax, mre_start, tables, q2_samples, tbuf);
    if (!toc) return 1;
    struct toc_point at[MAXP];
    double width[MAXP], range[MAXP];
    for (int j = 0; j < npfa; j++) {
        if (toc_point_at(toc, pfas[j], &at[j], err, sizeof err)) {
            fprintf(stderr, "trk-sim brekke-errpdf: MRE (P_FA %g): %s\n", pfas[j], err);
            return 1;
        }
        double top = 0;
        for (int fl = 0; fl < 2; fl++)
            if (isfinite(at[j].rmse_m[fl])) top = fmax(top, at[j].rmse_m[fl]);
        range[j] = err_max > 0 ? err_max : top > 0 ? 4 * top : 5.0;
        width[j] = range[j] / (double)bins;
    }
    toc_free(toc);
    free(tbuf[0]), free(tbuf[1]);
    const double mre_s = progress_now_s() - t_mre;
    /* ---- the runs */
    struct st_amp *amp = calloc((size_t)npfa, sizeof *amp);
    struct st_model *mod = calloc((size_t)npfa, sizeof *mod);
    const size_t ss = slot_size_of(bins);
    char *out = calloc((size_t)npfa * (size_t)runs, ss);
    if (!amp || !mod || !out) {
        fprintf(stderr, "trk-sim brekke-errpdf: out of memory\n");
        return 1;
    }
    if (sim_amp_k_grid(cli.name, amp, &nu, 1, &snr, 1, pfas, npfa, 0, 0)) return 1;
    for (int j = 0; j < npfa; j++)
        if (sim_brekke_model(cli.name, &mod[j], &amp[j], cell, scans, init, texture, &gate_cap, com.seed)) return 1;
    if (!com.quiet)
        fprintf(stderr, "trk-sim brekke-errpdf: %d figures x 2 filters x %ld runs x %ld scans, seed %llu, %d threads (MRE %.1f s)\n",
                npfa, runs, scans, (unsigned long long)com.seed, threads, mre_s);
    struct ep_ctx ctx = {from, bins, tracks, width};
    int bad_call;
    const double wall = sim_st_runs_err(&com, cli.name, mod, npfa, runs, 2, from, keep, &ctx, out, ss, &bad_call);
    if (bad_call) {
        fprintf(stderr, "trk-sim brekke-errpdf: internal error (bad run call)\n");
        return 1;
    }
    /* ---- reduce in run order */
    struct ep_stat st[MAXP][2];
    double *cnt = calloc((size_t)npfa * 2 * (size_t)bins, sizeof *cnt);
    double *num = malloc((size_t)runs * sizeof *num), *num2 = malloc((size_t)runs * sizeof *num2),
           *den = malloc((size_t)runs * sizeof *den);
    if (!cnt || !num || !num2 || !den) {
        fprintf(stderr, "trk-sim brekke-errpdf: out of memory\n");
        return 1;
    }
    long total_scans = 0;
    for (int j = 0; j < npfa; j++)
        for (int fl = 0; fl < 2; fl++) {
            struct ep_stat *s = &st[j][fl];
            double *c = cnt + ((size_t)j * 2 + (size_t)fl) * (size_t)bins;
            size_t nr = 0;
            memset(s, 0, sizeof *s);
            for (long run = 0; run < runs; run++) {
                char *slot = out + ((size_t)j * (size_t)runs + (size_t)run) * ss;
                const struct ep_head *h = (const struct ep_head *)slot;
                const uint32_t *rc = counts_of(slot, fl, bins);
                total_scans += h->scans[fl];
                s->lost += h->lost[fl];
                if (h->n[fl] == 0) continue;
                s->runs_used++;
                for (long b = 0; b < bins; b++) c[b] += rc[b];
                s->samples += h->n[fl];
                s->over += h->over[fl];
                num[nr] = h->sum[fl];
                num2[nr] = h->sum2[fl];
                den[nr++] = h->n[fl];
            }
            double ms;
            mc_ratio_ci(num, den, nr, 0.95, &s->mean, &s->mean_lo, &s->mean_hi);
            mc_ratio_ci(num2, den, nr, 0.95, &ms, &s->rms_lo, &s->rms_hi);
            s->rms = sqrt(ms);
            s->rms_lo = sqrt(fmax(s->rms_lo, 0));
            s->rms_hi = sqrt(s->rms_hi);
            const long m = mc_hist_mode(c, bins);
            s->mode = m < 0 ? NAN : ((double)m + 0.5) * width[j];
            s->mode_lo = m < 0 ? NAN : (double)m * width[j];
            s->mode_hi = m < 0 ? NAN : (double)(m + 1) * width[j];
        }
    free(num), free(num2), free(den);
    /* ---- the summary CSV and table */
    char as[192], path[1024];
    const char *tracks_txt = tracks == TRACKS_KEPT ? "runs not lost (bad tracks removed)" : "all runs (lost ones before their loss)";
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# brekke-errpdf: Brekke 2011 Figs. 3-5, error pdfs of the PDAF and the PDAFAI vs the MRE (eq 35)");
    if (!f) return 1;
    fprintf(f, "# Table I model (T 1 s, q 0.0125^2, R I/12, g 6; used gamma %.6g), K clutter nu %g, SNR %g dB, cell %g m^2 "
               "(lambda = pfa / cell), %ld scans, loss rule c1 5 m / c2 15 m, texture %s, seed %llu, runs %ld\n",
            mod[0].gamma_used, nu, snr, cell, scans, texture == ST_TEXTURE_CELL ? "per detection" : "per scan",
            (unsigned long long)com.seed, runs);
    fprintf(f, "# figures: fig %d + i = the i-th P_FA (default: Fig. 3 1e-4, Fig. 4 1e-2, Fig. 5 1e-1 at nu 1)\n", FIG0);
    sim_assumptions_csv(f, init, &gate_cap, mre_start);
    fprintf(f, "# histogram (--from, --tracks, --bins, --err-max): position error of scans >= %ld of the %s; %ld bins over "
               "[0, err_max); mean and RMS with 95%% intervals over runs; mode = the fullest bin\n",
            from, tracks_txt, bins);
    fprintf(f, "fig,nu,snr_db,cell_m2,pfa,pd,lambda_per_m2,filter,mre_rmse_m,mre_status,runs,runs_used,lost,samples,"
               "overflow,err_max_m,bins,mean_m,mean_lo95,mean_hi95,rms_m,rms_lo95,rms_hi95,mode_m,mode_lo,mode_hi,"
               "mre_over_mode,mre_over_mean,mre_over_rms\n");
    printf("# brekke-errpdf: nu %g, SNR %g dB, cell %g m^2, %ld runs x %ld scans; histogram of scans >= %ld, %s\n", nu, snr,
           cell, runs, scans, from, tracks_txt);
    printf("# %s\n", sim_assumptions_title(as, sizeof as, init, &gate_cap, mre_start));
    printf("%4s %7s %7s %-6s | %7s | %-26s | %-26s | %-17s | %6s %6s | %s\n", "fig", "P_FA", "P_D", "filter", "MRE",
           "mean [95% CI]", "RMS [95% CI]", "mode [bin]", "MRE/md", "MRE/mn", "lost, samples (over)");
    for (int j = 0; j < npfa; j++)
        for (int fl = 0; fl < 2; fl++) {
            const struct ep_stat *s = &st[j][fl];
            const double mre = at[j].rmse_m[fl];
            fprintf(f, "%d,%g,%g,%g,%g,%.6g,%.6g,%s,%.6g,%s,%ld,%ld,%ld,%.0f,%.0f,%.6g,%ld,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,"
                       "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                    FIG0 + j, nu, snr, cell, pfas[j], amp[j].pd, pfas[j] / cell, fl ? "PDAFAI" : "PDAF", mre,
                    toc_status_name(at[j].status[fl]), runs, s->runs_used, s->lost, s->samples, s->over, range[j], bins,
                    s->mean, s->mean_lo, s->mean_hi, s->rms, s->rms_lo, s->rms_hi, s->mode, s->mode_lo, s->mode_hi,
                    mre / s->mode, mre / s->mean, mre / s->rms);
            printf("%4d %7.0e %7.4f %-6s | %7.4f | %7.4f [%7.4f, %7.4f] | %7.4f [%7.4f, %7.4f] | %6.4f [%.3f,%.3f] | "
                   "%6.3f %6.3f | %ld, %.0f (%.0f)\n",
                   FIG0 + j, pfas[j], amp[j].pd, fl ? "PDAFAI" : "PDAF", mre, s->mean, s->mean_lo, s->mean_hi, s->rms,
                   s->rms_lo, s->rms_hi, s->mode, s->mode_lo, s->mode_hi, mre / s->mode, mre / s->mean, s->lost,
                   s->samples, s->over);
        }
    if (sim_csv_close(&f_out) != 0) return 1;
    /* ---- per figure: bins, the .gp and the PNG */
    for (int j = 0; j < npfa; j++) {
        char suf[32], fpath[1024], head[512];
        snprintf(suf, sizeof suf, "_fig%d", FIG0 + j);
        char csuf[40];
        snprintf(csuf, sizeof csuf, "%s.csv", suf);
        snprintf(head, sizeof head,
                 "# brekke-errpdf: Brekke 2011 Fig. %d, error pdf, nu %g, SNR %g dB, P_FA %g (P_D %.6g), cell %g m^2, "
                 "%ld runs x %ld scans, seed %llu",
                 FIG0 + j, nu, snr, pfas[j], amp[j].pd, cell, runs, scans, (unsigned long long)com.seed);
        struct fileio_out b_out;
        FILE *b = sim_csv_open(&com, &b_out, csuf, fpath, sizeof fpath, head);
        if (!b) return 1;
        sim_assumptions_csv(b, init, &gate_cap, mre_start);
        fprintf(b, "# histogram: scans >= %ld of the %s; density = count / (samples x bin width), samples including "
                   "those >= %.6g m (overflow)\n",
                from, tracks_txt, range[j]);
        for (int fl = 0; fl < 2; fl++) {
            const struct ep_stat *s = &st[j][fl];
            fprintf(b, "# %s: MRE %.6g m (%s), mean %.6g m, RMS %.6g m, mode %.6g m, samples %.0f (overflow %.0f), runs "
                       "used %ld, lost %ld\n",
                    fl ? "PDAFAI" : "PDAF", at[j].rmse_m[fl], toc_status_name(at[j].status[fl]), s->mean, s->rms, s->mode,
                    s->samples, s->over, s->runs_used, s->lost);
        }
        fprintf(b, "bin_lo_m,bin_hi_m,bin_mid_m,density_pdaf,density_pdafai,count_pdaf,count_pdafai\n");
        const double *c0 = cnt + (size_t)j * 2 * (size_t)bins, *c1 = c0 + bins;
        for (long k = 0; k < bins; k++) {
            const double lo = (double)k * width[j], hi = (double)(k + 1) * width[j];
            fprintf(b, "%.6g,%.6g,%.6g,%.6g,%.6g,%.0f,%.0f\n", lo, hi, 0.5 * (lo + hi),
                    st[j][0].samples > 0 ? c0[k] / (st[j][0].samples * width[j]) : 0,
                    st[j][1].samples > 0 ? c1[k] / (st[j][1].samples * width[j]) : 0, c0[k], c1[k]);
        }
        if (sim_csv_close(&b_out) != 0) return 1;
        if (com.no_plot) continue;
        struct sim_text t = {NULL, 0, 0, 0};
        sim_text_add(&t,
                     "set datafile separator ','\nset grid\nset key top right font ',9'\n"
                     "set xlabel 'position error sqrt(dx^2 + dy^2) (m)'\nset ylabel 'density (1/m)'\n"
                     "set xrange [0:%.6g]\nset yrange [0:*]\n"
                     "set title \"Brekke 2011 Fig. %d: error pdf, K nu %g, SNR %g dB, P_{FA} %g (P_D %.3f), cell %g m^2\\n"
                     "%s\\nscans >= %ld of %ld runs x %ld scans, %s (kept: PDAF %ld, PDAFAI %ld)\" font ',9'\n",
                     range[j], FIG0 + j, nu, snr, pfas[j], amp[j].pd, cell,
                     sim_assumptions_title(as, sizeof as, init, &gate_cap, mre_start), from, runs, scans,
                     tracks == TRACKS_KEPT ? "tracks not lost" : "all tracks before loss", runs - st[j][0].lost,
                     runs - st[j][1].lost);
        for (int fl = 0; fl < 2; fl++) {
            const double mre = at[j].rmse_m[fl];
            if (isfinite(mre))
                sim_text_add(&t, "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead lw 2 lc %d\n", mre, mre, fl + 1);
            if (isfinite(st[j][fl].mean))
                sim_text_add(&t, "set arrow from %.6g, graph 0 to %.6g, graph 0.6 nohead lw 1 dt 2 lc %d\n",
                             st[j][fl].mean, st[j][fl].mean, fl + 1);
        }
        char key[2][160];
        for (int fl = 0; fl < 2; fl++) {
            const double mre = at[j].rmse_m[fl];
            if (isfinite(mre))
                snprintf(key[fl], sizeof key[fl], "%s (MRE %.3f m: solid line; mean %.3f m: dashed; mode %.3f m)",
                         fl ? "PDAFAI" : "PDAF", mre, st[j][fl].mean, st[j][fl].mode);
            else /* "off_table" without the underscore (a subscript to gnuplot) */
                snprintf(key[fl], sizeof key[fl], "%s (MRE %s: no line; mean %.3f m: dashed; mode %.3f m)",
                         fl ? "PDAFAI" : "PDAF", at[j].status[fl] == TOC_OFF_TABLE ? "off the q2 table" : "diverged",
                         st[j][fl].mean, st[j][fl].mode);
        }
        sim_text_add(&t,
                     "plot '%s' every ::1 using 3:4 with histeps lw 2 lc 1 title '%s', \\\n"
                     "     '%s' every ::1 using 3:5 with histeps lw 2 lc 2 title '%s'\n",
                     fpath, key[0], fpath, key[1]);
        if (!t.failed) sim_plot(&com, suf, t.s);
        sim_text_free(&t);
    }
    printf("# wall %.1f s on %d threads (+ MRE %.1f s); %ld track updates, %.3g updates/s\n", wall, threads, mre_s,
           total_scans, (double)total_scans / wall);
    printf("# files: %s, %s_fig%d..%d.csv (.gp, .png)\n", path, com.out, FIG0, FIG0 + npfa - 1);
    for (int j = 0; j < npfa; j++) st_amp_free(&amp[j]);
    free(amp), free(mod), free(out), free(cnt);
    return 0;
}
