/* trk-q2 - q2, MRE and CRLB reproductions (Willett Table I, the CRLB with
 * q2, Brekke's TOC curves) and q2 values on demand. A preliminary home: the
 * lead will fold these subcommands into trk-tablegen / trk-sim.
 *
 * Every number comes from the library (trk/q2.h, trk/mre.h, trk/crlb.h) and
 * the importance sampler tools/common/q2_is.c; outputs are CSV files and
 * gnuplot PNGs (tools/common/plot.h) in the output directory. See --help. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot.h"
#include "progress.h"
#include "q2_amp_rayleigh.h"
#include "q2_is.h"
#include "trk/crlb.h"
#include "trk/gate.h"
#include "trk/mre.h"
#include "trk/q2.h"
#include "trk/special.h"

static const char usage[] =
    "usage: trk-q2 COMMAND [options]\n"
    "\n"
    "q2 (the information-reduction factor, CONVENTIONS \"q2, MRE and CRLB\") by importance\n"
    "sampling, and what it predicts. Commands:\n"
    "  willett-table1  q2 of Willett's Table I (lambda 1e-4..0.018 per unit area, pd 0.7/0.8/0.9;\n"
    "                  nz = 2, R = I, a gate of area V = 400: gamma = 400/pi, pg = 1,\n"
    "                  lambda_vg = 400 lambda) beside the paper's values, with standard errors,\n"
    "                  the rms relative deviation and the mean bias.\n"
    "  crlb            steady-state CRLB (Willett eq 37) with Table I's q2, the paper's and ours\n"
    "                  (q~ = 1, R = I, T = 1 s; Willett plots the (1,1) element of J^-1), and\n"
    "                  the MRE with the same q2 for contrast.\n"
    "  toc             Brekke Fig. 2: steady-state position RMSE of the MRE (eq 35) along the\n"
    "                  ROC for the PDAF and the PDAFAI, optimal P_FA marked. Brekke's Table I\n"
    "                  model: T = 1 s, q~ = 0.0125^2, R = I/12, gate g = 6 (gamma = 36),\n"
    "                  resolution cell --cell-m2 (not printed in the paper; default 1 m^2, so\n"
    "                  lambda = P_FA per m^2).\n"
    "  interp-error    error of the q2 grid interpolation (linear and cubic) against the direct\n"
    "                  estimator between the nodes (PDAF, nz = 2, pg = 0.99).\n"
    "  cell            one q2 value and its standard error.\n"
    "\n"
    "Options (all commands):\n"
    "  -o DIR            output directory (default .); files q2_<command>*.csv/.gp/.png\n"
    "  --samples N       scenes per stratum where a cell's variance comes from (Neyman\n"
    "                    allocation; default per command)\n"
    "  --target-se S     stop a line of cells once every cell's standard error <= S\n"
    "  --seed N          random seed (default 1); results are bit-identical for any --threads\n"
    "  --threads N       OpenMP threads (default: all cores)\n"
    "  --quiet           no progress bar on stderr\n"
    "  --help            this text\n"
    "toc options:\n"
    "  --model rayleigh|k  clutter amplitude model (k: needs the amplitude module's sampler)\n"
    "  --nu NU           K shape (model k)\n"
    "  --snr-db D        target SNR (default 15)\n"
    "  --cell-m2 A       resolution cell area: lambda = P_FA / A (default 1)\n"
    "  --pfa-min P, --pfa-max P   ROC range (default 1e-6, 0.5)\n"
    "  --lambda-vg-max L largest lambda V_G of the q2 tables (default 100; the MRE beyond it\n"
    "                    counts as diverged)\n"
    "cell options:\n"
    "  --nz N --pd P --pg G --lambda-vg L [--model rayleigh --snr-db D --pfa P]\n"
    "\n"
    "Exit status: 0 success, 1 computation failed, 2 bad usage or input.\n";

struct opts {
    const char *cmd, *outdir, *model;
    unsigned long long samples, seed;
    double target_se, nu, snr_db, cell_m2, pfa_min, pfa_max, lv_max;
    double pd, pg, lv, pfa;
    int nz, threads, quiet;
};

static int bad(const char *fmt, const char *arg)
{
    fprintf(stderr, "trk-q2: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (see trk-q2 --help)\n");
    return 2;
}

static int parse_double(const char *s, double *v)
{
    char *end;
    errno = 0;
    double x = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(x)) return -1;
    *v = x;
    return 0;
}

static int parse_ull(const char *s, unsigned long long *v)
{
    char *end;
    errno = 0;
    if (*s == '-') return -1;
    unsigned long long x = strtoull(s, &end, 0);
    if (end == s || *end || errno) return -1;
    *v = x;
    return 0;
}

static int parse_args(int argc, char **argv, struct opts *o)
{
    memset(o, 0, sizeof *o);
    o->outdir = ".";
    o->model = "rayleigh";
    o->seed = 1;
    o->snr_db = 15;
    o->cell_m2 = 1;
    o->pfa_min = 1e-6;
    o->pfa_max = 0.5;
    o->lv_max = 100;
    o->nz = 2;
    o->pd = NAN, o->pg = NAN, o->lv = NAN, o->pfa = NAN, o->nu = NAN;
    o->target_se = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage, stdout);
            exit(0);
        }
        if (!strcmp(a, "--quiet")) {
            o->quiet = 1;
            continue;
        }
        if (a[0] != '-') {
            if (o->cmd) return bad("unexpected argument '%s'", a);
            o->cmd = a;
            continue;
        }
        if (i + 1 >= argc) return bad("option %s needs a value", a);
        const char *v = argv[++i];
        double d;
        unsigned long long u;
        if (!strcmp(a, "-o")) o->outdir = v;
        else if (!strcmp(a, "--model")) o->model = v;
        else if (!strcmp(a, "--samples")) {
            if (parse_ull(v, &u) || u < 2 || u > 0xffffffffULL) return bad("--samples must be an integer in [2, 4294967295], got '%s'", v);
            o->samples = u;
        } else if (!strcmp(a, "--seed")) {
            if (parse_ull(v, &u)) return bad("--seed must be a non-negative integer, got '%s'", v);
            o->seed = u;
        } else if (!strcmp(a, "--threads")) {
            if (parse_ull(v, &u) || u < 1 || u > 1024) return bad("--threads must be in [1, 1024], got '%s'", v);
            o->threads = (int)u;
        } else if (!strcmp(a, "--nz")) {
            if (parse_ull(v, &u) || u < 1 || u > 3) return bad("--nz must be 1, 2 or 3, got '%s'", v);
            o->nz = (int)u;
        } else {
            if (parse_double(v, &d)) return bad("option needs a finite number, got '%s'", v);
            if (!strcmp(a, "--target-se")) {
                if (!(d > 0 && d < 1)) return bad("--target-se must be in (0, 1), got '%s'", v);
                o->target_se = d;
            } else if (!strcmp(a, "--nu")) {
                if (!(d > 0 && d <= 1e6)) return bad("--nu must be in (0, 1e6], got '%s'", v);
                o->nu = d;
            } else if (!strcmp(a, "--snr-db")) {
                if (!(d >= -30 && d <= 60)) return bad("--snr-db must be in [-30, 60], got '%s'", v);
                o->snr_db = d;
            } else if (!strcmp(a, "--cell-m2")) {
                if (!(d > 0)) return bad("--cell-m2 must be > 0, got '%s'", v);
                o->cell_m2 = d;
            } else if (!strcmp(a, "--pfa-min")) {
                if (!(d > 0 && d < 1)) return bad("--pfa-min must be in (0, 1), got '%s'", v);
                o->pfa_min = d;
            } else if (!strcmp(a, "--pfa-max")) {
                if (!(d > 0 && d < 1)) return bad("--pfa-max must be in (0, 1), got '%s'", v);
                o->pfa_max = d;
            } else if (!strcmp(a, "--lambda-vg-max")) {
                if (!(d >= 1 && d <= Q2_IS_MAX_LAMBDA_VG))
                    return bad("--lambda-vg-max must be in [1, 1000], got '%s'", v);
                o->lv_max = d;
            } else if (!strcmp(a, "--pd")) {
                if (!(d > 0 && d <= 1)) return bad("--pd must be in (0, 1], got '%s'", v);
                o->pd = d;
            } else if (!strcmp(a, "--pg")) {
                if (!(d > 0 && d < 1)) return bad("--pg must be in (0, 1), got '%s'", v);
                o->pg = d;
            } else if (!strcmp(a, "--lambda-vg")) {
                if (!(d > 0 && d <= Q2_IS_MAX_LAMBDA_VG)) return bad("--lambda-vg must be in (0, 1000], got '%s'", v);
                o->lv = d;
            } else if (!strcmp(a, "--pfa")) {
                if (!(d > 0 && d < 1)) return bad("--pfa must be in (0, 1), got '%s'", v);
                o->pfa = d;
            } else {
                return bad("unknown option '%s'", a);
            }
        }
    }
    if (!o->cmd) return bad("%s", "no command given");
    if (!(o->pfa_min < o->pfa_max)) return bad("%s", "--pfa-min must be below --pfa-max");
    return 0;
}

/* ---- running the sampler with a progress bar ---- */

struct prog_ctx {
    struct progress p;
    uint64_t last;
    int started;
};

static void on_progress(void *ctx, const struct q2_is_progress *pr)
{
    struct prog_ctx *c = ctx;
    if (!c->started) {
        progress_start(&c->p, "q2 points", (long)pr->points_planned, 1);
        c->started = 1;
    }
    c->p.total = (long)pr->points_planned; /* the plan follows the allocation */
    progress_add(&c->p, (long)(pr->points_done - c->last));
    c->last = pr->points_done;
}

static int run_lines(const struct opts *o, struct q2_is_line *lines, size_t n, unsigned long long samples,
                     double target_se)
{
    struct q2_is_options opt;
    memset(&opt, 0, sizeof opt);
    opt.seed = o->seed;
    opt.samples = o->samples ? o->samples : samples;
    opt.target_se = o->target_se > 0 ? o->target_se : target_se;
    opt.threads = o->threads;
    struct prog_ctx pc;
    memset(&pc, 0, sizeof pc);
    if (!o->quiet) {
        opt.progress = on_progress;
        opt.progress_ctx = &pc;
    }
    char err[256];
    double t0 = progress_now_s();
    int rc = q2_is_run(lines, n, &opt, err, sizeof err);
    if (pc.started) progress_end(&pc.p);
    if (rc) {
        fprintf(stderr, "trk-q2: %s\n", err);
        return 1;
    }
    uint64_t pts = 0, scenes = 0;
    for (size_t i = 0; i < n; i++) pts += lines[i].points, scenes += lines[i].scenes;
    double dt = progress_now_s() - t0;
    int th = q2_is_threads(o->threads);
    fprintf(stderr, "trk-q2: %llu scenes, %llu points in %.2f s on %d thread%s (%.3g points/s/thread)\n",
            (unsigned long long)scenes, (unsigned long long)pts, dt, th, th == 1 ? "" : "s",
            dt > 0 ? (double)pts / dt / th : 0);
    return 0;
}

static void path_of(char *buf, size_t n, const struct opts *o, const char *name)
{
    snprintf(buf, n, "%s/%s", o->outdir, name);
}

/* ---- Willett Table I ---- */

/* Willett, "Issues in Target Tracking" (2010), Table I: q2 at false-alarm
 * densities lambda and detection probabilities 0.7, 0.8, 0.9 (q~ = 1,
 * sigma_w^2 = 1, V = 400 in two dimensions). Typed from seed 000. */
#define W_NL 10
static const double w_lambda[W_NL] = {0.0001, 0.0020, 0.0040, 0.0060, 0.0080,
                                      0.0100, 0.0120, 0.0140, 0.0160, 0.0180};
static const double w_pd[3] = {0.7, 0.8, 0.9};
static const double w_q2[W_NL][3] = {
    {0.6814, 0.7700, 0.8890}, {0.6341, 0.7472, 0.8491}, {0.5722, 0.6860, 0.8144},
    {0.5460, 0.6498, 0.7727}, {0.5257, 0.6290, 0.7457}, {0.5037, 0.6096, 0.7367},
    {0.4679, 0.5729, 0.6938}, {0.4479, 0.5343, 0.6801}, {0.4356, 0.5330, 0.6590},
    {0.4180, 0.5133, 0.6312},
};
#define W_AREA 400.0
#define W_NCURVE 60

/* Our q2 at the table's cells (q[i][j], se) and on a fine lambda curve. */
static int willett_q2(const struct opts *o, double q[W_NL][3], double se[W_NL][3],
                      double curve_l[W_NCURVE], double curve_q[W_NCURVE][3], double curve_se[W_NCURVE][3])
{
    enum { NC = W_NL * 3 + W_NCURVE * 3 };
    static double pd[NC], lv[NC], q2[NC], s[NC];
    size_t k = 0;
    for (int i = 0; i < W_NL; i++)
        for (int j = 0; j < 3; j++, k++) pd[k] = w_pd[j], lv[k] = W_AREA * w_lambda[i];
    for (int i = 0; i < W_NCURVE; i++) {
        curve_l[i] = 5e-5 + (0.02 - 5e-5) * i / (W_NCURVE - 1);
        for (int j = 0; j < 3; j++, k++) pd[k] = w_pd[j], lv[k] = W_AREA * curve_l[i];
    }
    struct q2_is_line line;
    memset(&line, 0, sizeof line);
    line.nz = 2;
    line.gamma = W_AREA / 3.14159265358979323846; /* pi gamma sqrt(det R) = 400 */
    line.n_cells = NC;
    line.pd = pd;
    line.lambda_vg = lv;
    line.q2 = q2;
    line.se = s;
    if (run_lines(o, &line, 1, 1000000, 0)) return 1;
    k = 0;
    for (int i = 0; i < W_NL; i++)
        for (int j = 0; j < 3; j++, k++) q[i][j] = q2[k], se[i][j] = s[k];
    for (int i = 0; i < W_NCURVE; i++)
        for (int j = 0; j < 3; j++, k++) curve_q[i][j] = q2[k], curve_se[i][j] = s[k];
    return 0;
}

static int cmd_willett(const struct opts *o)
{
    double q[W_NL][3], se[W_NL][3], cl[W_NCURVE], cq[W_NCURVE][3], cse[W_NCURVE][3];
    if (willett_q2(o, q, se, cl, cq, cse)) return 1;
    char path[1024];
    path_of(path, sizeof path, o, "q2_willett_table1.csv");
    FILE *f = plot_csv_open(path, "lambda,pd,lambda_vg,q2_paper,q2,se,rel_dev");
    if (!f) return 1;
    printf("Willett Table I (nz = 2, V = 400: gamma = 400/pi, pg = 1); rel_dev = paper/ours - 1\n");
    printf("%-8s %5s  %8s %8s %8s %8s\n", "lambda", "pd", "paper", "ours", "se", "rel_dev");
    double s1[4] = {0}, s2[4] = {0};
    for (int i = 0; i < W_NL; i++)
        for (int j = 0; j < 3; j++) {
            double d = w_q2[i][j] / q[i][j] - 1;
            fprintf(f, "%.4f,%.1f,%.2f,%.4f,%.6f,%.2e,%.5f\n", w_lambda[i], w_pd[j], W_AREA * w_lambda[i],
                    w_q2[i][j], q[i][j], se[i][j], d);
            printf("%-8.4f %5.1f  %8.4f %8.4f %8.1e %+8.4f\n", w_lambda[i], w_pd[j], w_q2[i][j], q[i][j],
                   se[i][j], d);
            s1[j] += d, s2[j] += d * d, s1[3] += d, s2[3] += d * d;
        }
    fclose(f);
    printf("%-10s %10s %18s\n", "pd", "rms dev", "mean dev (bias)");
    for (int j = 0; j < 4; j++) {
        double n = j < 3 ? W_NL : 3 * W_NL, m = s1[j] / n, rms = sqrt(s2[j] / n);
        double sd = sqrt((s2[j] - n * m * m) / (n - 1));
        printf("%-10s %9.2f%% %+8.2f%% +- %.2f%%\n", j < 3 ? (j == 0 ? "0.7" : j == 1 ? "0.8" : "0.9") : "all",
               100 * rms, 100 * m, 100 * sd / sqrt(n));
    }
    path_of(path, sizeof path, o, "q2_willett_curve.csv");
    f = plot_csv_open(path, "lambda,q2_pd07,se_pd07,q2_pd08,se_pd08,q2_pd09,se_pd09");
    if (!f) return 1;
    for (int i = 0; i < W_NCURVE; i++)
        fprintf(f, "%.6g,%.6f,%.2e,%.6f,%.2e,%.6f,%.2e\n", cl[i], cq[i][0], cse[i][0], cq[i][1], cse[i][1],
                cq[i][2], cse[i][2]);
    fclose(f);
    char base[1024], body[4096];
    path_of(base, sizeof base, o, "q2_willett_table1");
    snprintf(body, sizeof body,
             "set datafile separator ','\n"
             "set title \"q2, Willett Table I (V = 400, R = I): paper (points) and importance sampling (lines)\"\n"
             "set xlabel 'clutter density lambda (per unit area)'\nset ylabel 'q2'\nset key top right\n"
             "set grid\n"
             "plot '%s/q2_willett_curve.csv' every ::1 using 1:2 with lines lw 2 lc 1 title 'ours, Pd 0.7', \\\n"
             "     '%s/q2_willett_curve.csv' every ::1 using 1:4 with lines lw 2 lc 2 title 'ours, Pd 0.8', \\\n"
             "     '%s/q2_willett_curve.csv' every ::1 using 1:6 with lines lw 2 lc 3 title 'ours, Pd 0.9', \\\n"
             "     '%s/q2_willett_table1.csv' every 3::1 using 1:4 with points pt 7 lc 1 title 'paper, Pd 0.7', \\\n"
             "     '%s/q2_willett_table1.csv' every 3::2 using 1:4 with points pt 7 lc 2 title 'paper, Pd 0.8', \\\n"
             "     '%s/q2_willett_table1.csv' every 3::3 using 1:4 with points pt 7 lc 3 title 'paper, Pd 0.9'\n",
             o->outdir, o->outdir, o->outdir, o->outdir, o->outdir, o->outdir);
    return plot_gnuplot(base, body) < 0;
}

/* ---- CRLB with Table I's q2 ---- */

static int crlb_of(double q2, double *j11, double *rmse)
{
    struct trk_crlb_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2, p.dt_s = 1, p.q_m2_per_s3 = 1, p.r_m2 = 1, p.q2 = (trk_real)q2;
    struct trk_crlb c;
    struct trk_crlb_result r;
    trk_status st = trk_crlb_init(&c, &p);
    if (st == TRK_OK) st = trk_crlb_steady_state(&c, NULL, &r);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-q2: CRLB at q2 = %g: %s\n", q2, trk_status_str(st));
        return 1;
    }
    *j11 = (double)r.j_inv[0];
    *rmse = (double)r.pos_rmse_m;
    return 0;
}

static int mre_of(double q2, double lambda, double *p11)
{
    struct trk_mre_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2, p.dt_s = 1, p.q_m2_per_s3 = 1, p.r_m2 = 1, p.q2 = (trk_real)q2;
    p.gate_prob = TRK_REAL_C(0.99), p.clutter_density = (trk_real)lambda;
    struct trk_mre m;
    struct trk_mre_result r;
    trk_status st = trk_mre_init(&m, &p);
    if (st == TRK_OK) st = trk_mre_steady_state(&m, NULL, &r);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-q2: MRE at q2 = %g: %s\n", q2, trk_status_str(st));
        return 1;
    }
    *p11 = (double)r.p[0];
    return 0;
}

static int cmd_crlb(const struct opts *o)
{
    double q[W_NL][3], se[W_NL][3], cl[W_NCURVE], cq[W_NCURVE][3], cse[W_NCURVE][3];
    if (willett_q2(o, q, se, cl, cq, cse)) return 1;
    char path[1024];
    path_of(path, sizeof path, o, "q2_crlb.csv");
    FILE *f = plot_csv_open(path, "lambda,pd,q2_paper,crlb11_paper,q2,crlb11,crlb_rmse,mre11");
    if (!f) return 1;
    printf("CRLB (Willett eq 37), q~ = 1, R = I, T = 1 s: (1,1) element of J^-1 in m^2\n");
    printf("%-8s %4s  %8s %10s  %8s %10s %10s  %10s\n", "lambda", "pd", "q2_paper", "crlb11", "q2_ours",
           "crlb11", "rmse", "mre11");
    for (int i = 0; i < W_NL; i++)
        for (int j = 0; j < 3; j++) {
            double jp, rp, jo, ro, mo;
            if (crlb_of(w_q2[i][j], &jp, &rp) || crlb_of(q[i][j], &jo, &ro) || mre_of(q[i][j], w_lambda[i], &mo)) {
                fclose(f);
                return 1;
            }
            fprintf(f, "%.4f,%.1f,%.4f,%.6f,%.6f,%.6f,%.6f,%.6f\n", w_lambda[i], w_pd[j], w_q2[i][j], jp, q[i][j], jo,
                    ro, mo);
            printf("%-8.4f %4.1f  %8.4f %10.5f  %8.4f %10.5f %10.5f  %10.5f\n", w_lambda[i], w_pd[j], w_q2[i][j], jp,
                   q[i][j], jo, ro, mo);
        }
    fclose(f);
    char base[1024], body[4096];
    path_of(base, sizeof base, o, "q2_crlb");
    snprintf(body, sizeof body,
             "set datafile separator ','\n"
             "set title \"CRLB (Willett eq 37), q = 1 m^2/s^3, R = I: q2 of the paper (points) and ours (lines)\"\n"
             "set xlabel 'clutter density lambda (per unit area)'\nset ylabel 'CRLB, (1,1) element of J^{-1} (m^2)'\n"
             "set key top left\nset grid\n"
             "plot for [j=1:3] '%s/q2_crlb.csv' every 3::j using 1:6 with linespoints lw 2 lc j title sprintf('ours, Pd 0.%%d', j+6), \\\n"
             "     for [j=1:3] '%s/q2_crlb.csv' every 3::j using 1:4 with points pt 7 lc j title sprintf('paper q2, Pd 0.%%d', j+6)\n",
             o->outdir, o->outdir);
    return plot_gnuplot(base, body) < 0;
}

/* ---- TOC (Brekke Fig. 2) ---- */

#define TOC_NCURVE 121

static trk_status rayleigh_roc(const void *ctx, trk_real pfa, trk_real *pd)
{
    const double snr_db = *(const double *)ctx;
    double v = q2_amp_rayleigh_pd(snr_db, (double)pfa);
    if (!(v > 0 && v <= 1)) return TRK_E_RANGE;
    *pd = (trk_real)v;
    return TRK_OK;
}

static int cmd_toc(const struct opts *o)
{
    if (!strcmp(o->model, "k")) {
        fprintf(stderr, "trk-q2: K-distributed amplitude sampler not yet available (model k)\n");
        return 2;
    }
    if (strcmp(o->model, "rayleigh")) return bad("--model must be rayleigh or k, got '%s'", o->model);
    const double gamma = 36; /* Brekke g = 6 */
    const double lv_min = 1e-6, per_dec_lv = 8, per_dec_pfa = 4;
    const size_t nlv = (size_t)lround(log10(o->lv_max / lv_min) * per_dec_lv) + 1;
    const double pd_lo = q2_amp_rayleigh_pd(o->snr_db, o->pfa_min);
    const double pd_step = 0.025, pd_first = floor(pd_lo / pd_step) * pd_step;
    const size_t npd = (size_t)lround((1 - pd_first) / pd_step) + 1;
    const size_t npfa = (size_t)ceil(log10(o->pfa_max / o->pfa_min) * per_dec_pfa) + 1;
    if (!(pd_first > 0)) return bad("%s", "the ROC reaches pd 0 in --pfa-min..--pfa-max");

    double *lv = malloc(nlv * sizeof *lv), *pfa = malloc(npfa * sizeof *pfa);
    double *cell_pd = malloc(npd * nlv * sizeof *cell_pd), *cell_lv = malloc(npd * nlv * sizeof *cell_lv);
    double *q_pdaf = malloc(npd * nlv * sizeof *q_pdaf), *q_ai = malloc(npfa * nlv * sizeof *q_ai);
    trk_real *v_pdaf = malloc(npd * nlv * sizeof *v_pdaf), *v_ai = malloc(npfa * nlv * sizeof *v_ai);
    struct q2_amp_rayleigh *ray = malloc(npfa * sizeof *ray);
    struct q2_amp_sampler *amp = malloc(npfa * sizeof *amp);
    struct q2_is_line *lines = calloc(npfa + 1, sizeof *lines);
    int rc = 1;
    if (!lv || !pfa || !cell_pd || !cell_lv || !q_pdaf || !q_ai || !v_pdaf || !v_ai || !ray || !amp || !lines) {
        fprintf(stderr, "trk-q2: out of memory\n");
        goto out;
    }
    const double ul0 = log(lv_min), ul1 = log(o->lv_max);
    for (size_t j = 0; j < nlv; j++) lv[j] = exp(ul0 + (ul1 - ul0) * (double)j / (double)(nlv - 1));
    lv[nlv - 1] = o->lv_max;
    const double up0 = log(o->pfa_min), up1 = log(o->pfa_max);
    for (size_t i = 0; i < npfa; i++) pfa[i] = exp(up0 + (up1 - up0) * (double)i / (double)(npfa - 1));
    for (size_t i = 0; i < npd; i++)
        for (size_t j = 0; j < nlv; j++) {
            double p = pd_first + pd_step * (double)i;
            cell_pd[i * nlv + j] = p > 1 ? 1 : p;
            cell_lv[i * nlv + j] = lv[j];
        }
    /* PDAF: one line over (pd, lambda_vg); PDAFAI: one line per pfa, the same
     * stream for all (common random numbers along pfa as well) */
    lines[0] = (struct q2_is_line){.nz = 2, .gamma = gamma, .stream = 0, .n_cells = npd * nlv, .pd = cell_pd,
                                   .lambda_vg = cell_lv, .q2 = q_pdaf};
    for (size_t i = 0; i < npfa; i++) {
        if (q2_amp_rayleigh_init(&ray[i], o->snr_db, pfa[i])) {
            fprintf(stderr, "trk-q2: bad pfa %g\n", pfa[i]);
            goto out;
        }
        amp[i] = q2_amp_rayleigh_sampler(&ray[i]);
        lines[i + 1] = (struct q2_is_line){.nz = 2, .gamma = gamma, .amp = &amp[i], .stream = 1,
                                           .n_cells = nlv, .lambda_vg = lv, .q2 = q_ai + i * nlv};
    }
    fprintf(stderr, "trk-q2: q2 tables: PDAF %zu pd x %zu lambda_vg, PDAFAI %zu pfa x %zu lambda_vg\n", npd, nlv,
            npfa, nlv);
    if (run_lines(o, lines, npfa + 1, 100000, 1e-3)) goto out;
    for (size_t k = 0; k < npd * nlv; k++) v_pdaf[k] = (trk_real)q_pdaf[k];
    for (size_t k = 0; k < npfa * nlv; k++) v_ai[k] = (trk_real)q_ai[k];

    /* library views: PDAF (pd, ln lambda_vg), PDAFAI (snr: one node, ln pfa, ln lambda_vg) */
    struct trk_q2_grid gp, ga;
    memset(&gp, 0, sizeof gp);
    memset(&ga, 0, sizeof ga);
    gp.detector = TRK_Q2_PDAF;
    gp.axis[0] = (struct trk_q2_axis){npd, NULL, (trk_real)pd_first, (trk_real)(pd_first + pd_step * (double)(npd - 1)), 0, TRK_Q2_CUBIC};
    gp.axis[1] = (struct trk_q2_axis){nlv, NULL, (trk_real)ul0, (trk_real)ul1, 1, TRK_Q2_CUBIC};
    gp.values = v_pdaf;
    ga.detector = TRK_Q2_PDAFAI;
    ga.axis[0] = (struct trk_q2_axis){1, NULL, (trk_real)o->snr_db, (trk_real)o->snr_db, 0, TRK_Q2_LINEAR};
    ga.axis[1] = (struct trk_q2_axis){npfa, NULL, (trk_real)up0, (trk_real)up1, 1, TRK_Q2_CUBIC};
    ga.axis[2] = (struct trk_q2_axis){nlv, NULL, (trk_real)ul0, (trk_real)ul1, 1, TRK_Q2_CUBIC};
    ga.values = v_ai;
    struct trk_q2_lookup lp, la;
    trk_status st = trk_q2_lookup_init(&lp, &gp);
    if (st == TRK_OK) st = trk_q2_lookup_init(&la, &ga);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-q2: q2 grid rejected: %s\n", trk_status_str(st));
        goto out;
    }
    const double snr_db = o->snr_db;
    struct trk_q2_roc rp = {&lp, rayleigh_roc, &snr_db, 0}, ra = {&la, NULL, NULL, (trk_real)snr_db};

    struct trk_toc_params tp;
    memset(&tp, 0, sizeof tp);
    tp.mre.nz = 2;
    tp.mre.dt_s = 1;
    tp.mre.q_m2_per_s3 = (trk_real)(0.0125 * 0.0125);
    tp.mre.r_m2 = (trk_real)(1.0 / 12);
    tp.mre.gate_gamma = (trk_real)gamma;
    tp.cells_per_m = (trk_real)(1 / o->cell_m2);
    tp.pfa_min = (trk_real)o->pfa_min;
    tp.pfa_max = (trk_real)o->pfa_max;

    char path[1024];
    path_of(path, sizeof path, o, "q2_toc.csv");
    FILE *f = plot_csv_open(path, "pfa,pd,rmse_pdaf,rmse_pdafai,lambda_vg_pdaf,q2_pdaf,lambda_vg_pdafai,q2_pdafai");
    if (!f) goto out;
    for (int i = 0; i < TOC_NCURVE; i++) {
        double x = exp(up0 + (up1 - up0) * i / (TOC_NCURVE - 1));
        trk_real e[2];
        struct trk_mre_result r[2];
        for (int d = 0; d < 2; d++) {
            tp.q2_fn = trk_q2_roc_eval;
            tp.q2_ctx = d ? (const void *)&ra : (const void *)&rp;
            st = trk_toc_rmse(&tp, (trk_real)x, &e[d], &r[d]);
            if (st != TRK_OK && st != TRK_E_DIVERGED && st != TRK_E_RANGE) {
                fprintf(stderr, "trk-q2: MRE at pfa %g: %s\n", x, trk_status_str(st));
                fclose(f);
                goto out;
            }
            if (st != TRK_OK) e[d] = (trk_real)NAN;
        }
        fprintf(f, "%.6g,%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", x, q2_amp_rayleigh_pd(o->snr_db, x), (double)e[0],
                (double)e[1], isnan((double)e[0]) ? NAN : (double)r[0].lambda_vg,
                isnan((double)e[0]) ? NAN : (double)r[0].q2, isnan((double)e[1]) ? NAN : (double)r[1].lambda_vg,
                isnan((double)e[1]) ? NAN : (double)r[1].q2);
    }
    fclose(f);
    struct trk_toc_result best[2];
    const char *name[2] = {"PDAF", "PDAFAI"};
    printf("TOC (Brekke Fig. 2 model): Rayleigh clutter, SNR %.1f dB, cell %.3g m^2 (lambda = P_FA / cell)\n",
           o->snr_db, o->cell_m2);
    for (int d = 0; d < 2; d++) {
        tp.q2_fn = trk_q2_roc_eval;
        tp.q2_ctx = d ? (const void *)&ra : (const void *)&rp;
        st = trk_toc_optimise(&tp, &best[d]);
        if (st != TRK_OK) {
            fprintf(stderr, "trk-q2: %s TOC optimum: %s\n", name[d], trk_status_str(st));
            goto out;
        }
        printf("%-7s optimal P_FA %.3g (P_D %.4f): RMSE %.4f m, lambda V_G %.3g, q2 %.4f (%d MRE solves, %d without "
               "steady state)\n",
               name[d], (double)best[d].pfa, q2_amp_rayleigh_pd(o->snr_db, (double)best[d].pfa),
               (double)best[d].rmse_m, (double)best[d].lambda_vg, (double)best[d].q2, best[d].n_evals,
               best[d].n_diverged);
    }
    path_of(path, sizeof path, o, "q2_toc_optimum.csv");
    f = plot_csv_open(path, "detector,pfa,pd,rmse,lambda_vg,q2");
    if (!f) goto out;
    for (int d = 0; d < 2; d++)
        fprintf(f, "%s,%.6g,%.6f,%.6g,%.6g,%.6g\n", name[d], (double)best[d].pfa,
                q2_amp_rayleigh_pd(o->snr_db, (double)best[d].pfa), (double)best[d].rmse_m,
                (double)best[d].lambda_vg, (double)best[d].q2);
    fclose(f);
    char base[1024], body[4096];
    path_of(base, sizeof base, o, "q2_toc");
    snprintf(body, sizeof body,
             "set datafile separator ','\nset logscale x\nset format x '10^{%%L}'\n"
             "set title \"TOC: MRE steady-state RMSE along the ROC (Rayleigh, SNR %.0f dB, cell %.3g m^2)\"\n"
             "set xlabel 'P_{FA}'\nset ylabel 'steady-state position RMSE (m)'\nset key top left\nset grid\n"
             "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 2 lc 1\n"
             "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 2 lc 2\n"
             "plot '%s/q2_toc.csv' every ::1 using 1:3 with lines lw 2 lc 1 title 'PDAF', \\\n"
             "     '%s/q2_toc.csv' every ::1 using 1:4 with lines lw 2 lc 2 title 'PDAFAI', \\\n"
             "     '%s/q2_toc_optimum.csv' every ::1 using 2:4 with points pt 7 ps 1.5 lc 0 title 'optimum'\n",
             o->snr_db, o->cell_m2, (double)best[0].pfa, (double)best[0].pfa, (double)best[1].pfa,
             (double)best[1].pfa, o->outdir, o->outdir, o->outdir);
    rc = plot_gnuplot(base, body) < 0;
out:
    free(lv), free(pfa), free(cell_pd), free(cell_lv), free(q_pdaf), free(q_ai), free(v_pdaf), free(v_ai);
    free(ray), free(amp), free(lines);
    return rc;
}

/* ---- interpolation error ---- */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int cmd_interp(const struct opts *o)
{
    /* coarse nodes: pd 0.5..1 step 0.05, lambda_vg 1e-2..1e2 with 10 per
     * decade; test points: centres of the thirds of every axis interval. All
     * in one line: common random numbers make the estimator's noise nearly
     * the same at nodes and test points, so the difference measures the
     * interpolation, not the Monte Carlo error. */
    enum { NP = 11, NL = 41, SUB = 3 };
    const double pd0 = 0.5, dpd = 0.05, ul0 = log(1e-2), ul1 = log(1e2);
    const size_t nt = (size_t)(NP - 1) * SUB * (NL - 1) * SUB, nn = NP * NL, nc = nn + nt;
    double *pd = malloc(nc * sizeof *pd), *lv = malloc(nc * sizeof *lv), *q = malloc(nc * sizeof *q);
    double *se = malloc(nc * sizeof *se), *vi = malloc(2 * nt * sizeof *vi), *srt = malloc(nt * sizeof *srt);
    trk_real *nodes = malloc(nn * sizeof *nodes);
    int rc = 1;
    if (!pd || !lv || !q || !se || !vi || !srt || !nodes) {
        fprintf(stderr, "trk-q2: out of memory\n");
        goto out;
    }
    size_t k = 0;
    for (int i = 0; i < NP; i++)
        for (int j = 0; j < NL; j++, k++) pd[k] = pd0 + dpd * i, lv[k] = exp(ul0 + (ul1 - ul0) * j / (NL - 1));
    for (int i = 0; i < (NP - 1) * SUB; i++)
        for (int j = 0; j < (NL - 1) * SUB; j++, k++) {
            pd[k] = pd0 + dpd * (i + 0.5) / SUB;
            lv[k] = exp(ul0 + (ul1 - ul0) * (j + 0.5) / SUB / (NL - 1));
        }
    struct q2_is_line line;
    memset(&line, 0, sizeof line);
    line.nz = 2, line.gamma = -2 * log1p(-0.99), line.n_cells = nc, line.pd = pd, line.lambda_vg = lv;
    line.q2 = q, line.se = se;
    if (run_lines(o, &line, 1, 50000, 0)) goto out;
    for (size_t m = 0; m < nn; m++) nodes[m] = (trk_real)q[m];
    double emax[2] = {0, 0}, e2[2] = {0, 0};
    for (int scheme = 0; scheme < 2; scheme++) {
        struct trk_q2_grid g;
        memset(&g, 0, sizeof g);
        g.detector = TRK_Q2_PDAF;
        g.axis[0] = (struct trk_q2_axis){NP, NULL, (trk_real)pd0, (trk_real)(pd0 + dpd * (NP - 1)), 0, scheme};
        g.axis[1] = (struct trk_q2_axis){NL, NULL, (trk_real)ul0, (trk_real)ul1, 1, scheme};
        g.values = nodes;
        struct trk_q2_lookup lk;
        trk_status st = trk_q2_lookup_init(&lk, &g);
        for (size_t m = 0; m < nt && st == TRK_OK; m++) {
            trk_real v = 0;
            st = trk_q2_pdaf(&lk, (trk_real)pd[nn + m], (trk_real)lv[nn + m], &v);
            vi[scheme * nt + m] = (double)v;
            double e = fabs((double)v - q[nn + m]);
            if (e > emax[scheme]) emax[scheme] = e;
            e2[scheme] += e * e;
        }
        if (st != TRK_OK) {
            fprintf(stderr, "trk-q2: lookup: %s\n", trk_status_str(st));
            goto out;
        }
    }
    memcpy(srt, se + nn, nt * sizeof *srt);
    qsort(srt, nt, sizeof *srt, cmp_double);
    printf("q2 grid interpolation error against the direct estimator between the nodes\n"
           "(PDAF, nz 2, pg 0.99; nodes: pd step 0.05 in [0.5, 1], 10 per decade of lambda_vg in [0.01, 100];\n"
           " %zu test points at the thirds of every cell; common random numbers)\n", nt);
    printf("%-8s %12s %12s   (median se of a value %.1e)\n", "scheme", "max |err|", "rms err", srt[nt / 2]);
    for (int scheme = 0; scheme < 2; scheme++)
        printf("%-8s %12.2e %12.2e\n", scheme ? "cubic" : "linear", emax[scheme], sqrt(e2[scheme] / (double)nt));
    char path[1024];
    path_of(path, sizeof path, o, "q2_interp_error.csv");
    FILE *f = plot_csv_open(path, "pd,lambda_vg,direct,se,linear,cubic");
    if (!f) goto out;
    for (size_t m = 0; m < nt; m++)
        fprintf(f, "%.4f,%.6g,%.7f,%.2e,%.7f,%.7f\n", pd[nn + m], lv[nn + m], q[nn + m], se[nn + m], vi[m],
                vi[nt + m]);
    fclose(f);
    rc = 0;
out:
    free(pd), free(lv), free(q), free(se), free(vi), free(srt), free(nodes);
    return rc;
}

/* ---- one cell ---- */

static int cmd_cell(const struct opts *o)
{
    if (isnan(o->pg) || isnan(o->lv)) return bad("%s", "--pg and --lambda-vg are required");
    double gamma;
    if (o->nz == 2) {
        gamma = -2 * log1p(-o->pg);
    } else {
        trk_real g;
        if (trk_gate_gamma(o->nz, (trk_real)o->pg, &g) != TRK_OK) return bad("%s", "bad --pg");
        gamma = (double)g;
    }
    struct q2_amp_rayleigh ray;
    struct q2_amp_sampler amp;
    const struct q2_amp_sampler *ap = NULL;
    double pd = o->pd;
    if (!isnan(o->pfa)) { /* PDAFAI: pd from the ROC */
        if (strcmp(o->model, "rayleigh")) {
            fprintf(stderr, "trk-q2: K-distributed amplitude sampler not yet available (model %s)\n", o->model);
            return 2;
        }
        if (q2_amp_rayleigh_init(&ray, o->snr_db, o->pfa)) return bad("%s", "bad --snr-db or --pfa");
        amp = q2_amp_rayleigh_sampler(&ray);
        ap = &amp;
        pd = ray.pd;
    } else if (isnan(pd)) {
        return bad("%s", "--pd is required (or --pfa for the PDAFAI)");
    }
    double q2, se;
    struct q2_is_line line;
    memset(&line, 0, sizeof line);
    line.nz = o->nz, line.gamma = gamma, line.amp = ap, line.n_cells = 1, line.pd = &pd, line.lambda_vg = &o->lv;
    line.q2 = &q2, line.se = &se;
    if (run_lines(o, &line, 1, 4000000, 0)) return 1;
    printf("q2 %.8f se %.2e (nz %d, pd %.10g, pg %.10g, lambda_vg %g, %s)\n", q2, se, o->nz, pd, o->pg, o->lv,
           ap ? "PDAFAI Rayleigh" : "PDAF");
    return 0;
}

int main(int argc, char **argv)
{
    struct opts o;
    int rc = parse_args(argc, argv, &o);
    if (rc) return rc;
    if (trk_config_check() != TRK_OK) {
        fprintf(stderr, "trk-q2: libtrk was built with other capacities or real type\n");
        return 2;
    }
    if (!strcmp(o.cmd, "willett-table1")) return cmd_willett(&o);
    if (!strcmp(o.cmd, "crlb")) return cmd_crlb(&o);
    if (!strcmp(o.cmd, "toc")) return cmd_toc(&o);
    if (!strcmp(o.cmd, "interp-error")) return cmd_interp(&o);
    if (!strcmp(o.cmd, "cell")) return cmd_cell(&o);
    return bad("unknown command '%s'", o.cmd);
}
