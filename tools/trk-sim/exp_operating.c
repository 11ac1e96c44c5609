/* exp_operating.c - trk-sim operating-point: the curve a sonar engineer reads
 * before deployment. From the sonar's figures, sweep the detection threshold
 * (its false-alarm probability P_FA) and print per P_FA the detection
 * probability, the PDAF's steady-state position error, the bound, and how
 * long a track is held; and the P_FA the TOC picks.
 *
 * Per P_FA (equally spaced in ln P_FA):
 *   P_D     the ROC of a Swerling I target of --snr-db in Rayleigh or K
 *           clutter (amp_table.h's direct models: the library's closed form
 *           for Rayleigh, kdist.h for K)
 *   lambda  P_FA / --cell-m2 (one false alarm per resolution cell with
 *           probability P_FA)
 *   MRE     the PDAF's steady-state RMSE, sqrt(P11 + P22) (trk/mre.h, Brekke
 *           eqs 27, 35) with q2(P_D, lambda V_G) each step from the library's
 *           quadrature (trk/irf.h; no q2 table needed), from the
 *           two-point-differencing start; "diverges": no steady state
 *   CRLB    Willett eq 37 (trk/crlb.h) with q2 at the MRE's steady-state
 *           lambda V_G (where the MRE diverges: at the clutter-free Kalman
 *           filter's, a looser bound)
 *   life    HYCA's chain over the gated count (trk/hyca.h): mean and median
 *           scans until the gate holds --m-lost or more, the loss per scan,
 *           and the RMSE of the tracks held
 *   TOC     the P_FA minimising the MRE's RMSE (trk_toc_optimise: grid in
 *           ln P_FA, then golden section)
 * The model is 2-D constant velocity with R = r I. A polar sensor is given
 * as --sigma-range-m, --sigma-bearing-deg at --range-m: r = sigma_r (R0
 * sigma_b), the circular R with the same determinant (the same gate area),
 * and so is a Cartesian sensor with --sigma-m (x) and --sigma-y-m (y):
 * r = sigma_x sigma_y; the analysis does not follow the ellipse's shape. Everything here is the
 * PDAF (no amplitude information in the update). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "errmsg.h"
#include "progress.h"
#include "sim.h"
#include "trk/amplitude.h"
#include "trk/crlb.h"
#include "trk/gate.h"
#include "trk/hyca.h"
#include "trk/irf.h"
#include "trk/mre.h"
#include "trk/toc.h"

#define MAX_POINTS 1000

struct op_model {
    int amp_model;
    double nu, snr_db;
    double dt_s, q, r, gamma, cell_m2;
    int m_lost;
    struct trk_irf irf;
};

/* q2 of the PDAF at (P_FA, lambda V_G) for the library's TOC: P_D from the
 * ROC (cached for the P_FA of the current solve), q2 by quadrature. */
struct op_roc_cache {
    double pfa, pd;
    int have;
};
struct op_q2 {
    const struct op_model *m;
    struct op_roc_cache *cache; /* the caller's, written through the const ctx */
};

static int roc_pd(const struct op_model *m, double pfa, double *pd)
{
    struct amp_direct d;
    if (amp_direct_init(&d, m->amp_model, m->nu, 1, m->snr_db, pfa) != 0 || !(d.pd > 0 && d.pd <= 1)) return -1;
    *pd = d.pd;
    return 0;
}

static trk_status op_q2_eval(const void *ctx, trk_real pfa, trk_real lambda_vg, trk_real *q2)
{
    const struct op_q2 *c = ctx;
    struct op_roc_cache *k = c->cache;
    if (!k->have || k->pfa != (double)pfa) {
        if (roc_pd(c->m, (double)pfa, &k->pd) != 0) return TRK_E_RANGE;
        k->pfa = (double)pfa;
        k->have = 1;
    }
    return trk_irf_q2(&c->m->irf, (trk_real)k->pd, lambda_vg, q2);
}

static void mre_params(const struct op_model *m, struct trk_mre_params *p)
{
    memset(p, 0, sizeof *p);
    p->nz = 2;
    p->dt_s = (trk_real)m->dt_s;
    p->q_m2_per_s3 = (trk_real)m->q;
    p->r_m2 = (trk_real)m->r;
    p->gate_gamma = (trk_real)m->gamma;
}

struct op_point {
    double pfa, pd, lambda;
    double mre_rmse, q2, lambda_vg;   /* mre_rmse +inf: diverges */
    double crlb_rmse;
    double life_mean, life_median, loss, hyca_rmse;
};

static int op_point_at(const struct op_model *m, double pfa, struct trk_hyca *h, struct op_point *o)
{
    o->pfa = pfa;
    if (roc_pd(m, pfa, &o->pd) != 0) return -1;
    o->lambda = pfa / m->cell_m2;
    /* MRE with q2 by quadrature */
    struct trk_mre_params mp;
    mre_params(m, &mp);
    mp.clutter_density = (trk_real)o->lambda;
    struct trk_irf_line line = {&m->irf, (trk_real)o->pd};
    mp.q2_fn = trk_irf_line_eval;
    mp.q2_ctx = &line;
    struct trk_mre mre;
    struct trk_mre_result mr;
    if (trk_mre_init(&mre, &mp) != TRK_OK) return -1;
    trk_status st = trk_mre_steady_state(&mre, NULL, &mr);
    double lvg;
    if (st == TRK_OK) {
        o->mre_rmse = (double)mr.rmse_m;
        o->q2 = (double)mr.q2;
        lvg = (double)mr.lambda_vg;
    } else if (st == TRK_E_DIVERGED) {
        o->mre_rmse = INFINITY;
        /* the clutter-free Kalman filter's gate (q2 = 1) */
        mp.q2_fn = NULL;
        mp.q2 = 1;
        if (trk_mre_init(&mre, &mp) != TRK_OK || trk_mre_steady_state(&mre, NULL, &mr) != TRK_OK) return -1;
        lvg = (double)mr.lambda_vg;
        trk_real q;
        if (trk_irf_q2(&m->irf, (trk_real)o->pd, (trk_real)lvg, &q) != TRK_OK) return -1;
        o->q2 = (double)q;
    } else {
        return -1;
    }
    o->lambda_vg = lvg;
    /* CRLB with that q2 */
    struct trk_crlb_params cp;
    memset(&cp, 0, sizeof cp);
    cp.nz = 2;
    cp.dt_s = (trk_real)m->dt_s;
    cp.q_m2_per_s3 = (trk_real)m->q;
    cp.r_m2 = (trk_real)m->r;
    cp.q2 = (trk_real)o->q2;
    struct trk_crlb cr;
    struct trk_crlb_result crr;
    o->crlb_rmse = NAN;
    if (cp.q2 > 0 && trk_crlb_init(&cr, &cp) == TRK_OK && trk_crlb_steady_state(&cr, NULL, &crr) == TRK_OK)
        o->crlb_rmse = (double)crr.pos_rmse_m;
    /* HYCA track life */
    struct trk_hyca_params hp;
    memset(&hp, 0, sizeof hp);
    hp.nz = 2;
    hp.dt_s = (trk_real)m->dt_s;
    hp.q_m2_per_s3 = (trk_real)m->q;
    hp.r_m2 = (trk_real)m->r;
    hp.pd = (trk_real)o->pd;
    hp.gate_gamma = (trk_real)m->gamma;
    hp.clutter_density = (trk_real)o->lambda;
    hp.m_lost = m->m_lost;
    struct trk_hyca_result hr;
    if (trk_hyca_init(h, &hp) != TRK_OK || trk_hyca_run(h, NULL, &hr) != TRK_OK) return -1;
    o->life_mean = (double)hr.mean_life_scans;
    o->life_median = (double)hr.median_life_scans;
    o->loss = (double)hr.loss_per_scan;
    o->hyca_rmse = (double)hr.rmse_m;
    return 0;
}

SIM_EXPERIMENT(operating_point, "operating-point", "sonar operating point: P_D, MRE RMSE, CRLB, track life (HYCA)")
{
    double sigma_m = 0, sigma_y = 0, sigma_r = 0, sigma_b_deg = 0, range_m = 0;
    double dt_s, q, snr_db, nu, cell_m2, gate_g, pfa_min, pfa_max;
    long points, m_lost;
    int clutter;
    static const int clutter_values[2] = {TRK_AMP_RAYLEIGH, TRK_AMP_K};
    const struct sim_opt opts[] = {
        SIM_OPT_DOUBLE("--sigma-m", &sigma_m, "S", NULL, SIM_GT, 0, 0,
                       "measurement noise per Cartesian axis (m; sigma_x with --sigma-y-m);\n"
                       "or the three polar figures below"),
        SIM_OPT_DOUBLE("--sigma-y-m", &sigma_y, "S", NULL, SIM_GT, 0, 0,
                       "y measurement noise (m) when it differs from --sigma-m's x; r = sigma_x sigma_y"),
        SIM_OPT_DOUBLE("--sigma-range-m", &sigma_r, "S", NULL, SIM_GT, 0, 0, "polar sensor: range noise (m)"),
        SIM_OPT_DOUBLE("--sigma-bearing-deg", &sigma_b_deg, "S", NULL, SIM_GT, 0, 0,
                       "polar sensor: bearing noise (degrees)"),
        SIM_OPT_DOUBLE("--range-m", &range_m, "R", NULL, SIM_GT, 0, 0,
                       "polar sensor: the range analysed (m); r = sigma_r R sigma_b"),
        SIM_OPT_DOUBLE("--dt", &dt_s, "T", "4", SIM_GT, 0, 0, "scan interval (s)"),
        SIM_OPT_DOUBLE("--q", &q, "Q", "0.01", SIM_GT, 0, 0, "process noise PSD (m^2/s^3)"),
        SIM_OPT_DOUBLE("--snr-db", &snr_db, "D", "12", SIM_IN, -30, 60, "target SNR (Swerling I), dB"),
        SIM_OPT_CHOICE("--clutter-model", &clutter, "rayleigh|k", clutter_values, "rayleigh",
                       "clutter amplitude law"),
        SIM_OPT_DOUBLE("--k-shape", &nu, "NU", "1", SIM_IN, 0.01, 1e6, "K clutter shape"),
        SIM_OPT_DOUBLE("--cell-m2", &cell_m2, "A", "1000", SIM_GT, 0, 0,
                       "resolution cell area (m^2): lambda = P_FA / A"),
        SIM_OPT_DOUBLE("--gate-g", &gate_g, "G", "4", SIM_GT | SIM_LE, 0, 12, "the gate: d2 <= G^2"),
        SIM_OPT_DOUBLE("--pfa-min", &pfa_min, "P", "1e-6", SIM_OPEN, 0, 1, "smallest P_FA"),
        SIM_OPT_DOUBLE("--pfa-max", &pfa_max, "P", "0.1", SIM_OPEN, 0, 1, "largest P_FA"),
        SIM_OPT_LONG("--points", &points, "N", "20", SIM_IN, 2, MAX_POINTS, "P_FA values, equally spaced in ln"),
        SIM_OPT_LONG("--m-lost", &m_lost, "M", "10", SIM_IN, 2, TRK_HYCA_MAX_STATES,
                     "HYCA: a gate holding M or more measurements is lost"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "operating-point", NULL,
        "The operating point of a sonar: per detection threshold (P_FA), the detection probability,\n"
        "the PDAF's steady-state position RMSE (MRE), the CRLB with q2, the mean track life (HYCA),\n"
        "and the P_FA that minimises the RMSE (TOC). Give --sigma-m, or the polar figures\n"
        "--sigma-range-m, --sigma-bearing-deg and --range-m (or --sigma-m and --sigma-y-m).",
        opts, "operating_point", NULL, SIM_UNUSED_RUNS, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    const int polar = sigma_r > 0 || sigma_b_deg > 0 || range_m > 0;
    if (polar == (sigma_m > 0) || (polar && !(sigma_r > 0 && sigma_b_deg > 0 && range_m > 0)) ||
        (sigma_y > 0 && !(sigma_m > 0))) {
        fprintf(stderr, "trk-sim operating-point: give --sigma-m, or all of --sigma-range-m, --sigma-bearing-deg, --range-m\n");
        return 2;
    }
    if (!(pfa_min < pfa_max)) {
        fprintf(stderr, "trk-sim operating-point: --pfa-min must be below --pfa-max\n");
        return 2;
    }
    static struct op_model m;
    m.amp_model = clutter;
    m.nu = nu;
    m.snr_db = snr_db;
    m.dt_s = dt_s;
    m.q = q;
    m.r = polar ? sigma_r * range_m * sigma_b_deg * (double)TRK_PI / 180 : sigma_m * (sigma_y > 0 ? sigma_y : sigma_m);
    m.gamma = gate_g * gate_g;
    m.cell_m2 = cell_m2;
    m.m_lost = (int)m_lost;
    if (trk_irf_init(&m.irf, 2, (trk_real)m.gamma) != TRK_OK) {
        fprintf(stderr, "trk-sim operating-point: gate g %g is outside the quadrature's range\n", gate_g);
        return 2;
    }
    const double t0 = progress_now_s();
    static struct trk_hyca h;
    static struct op_point pts[MAX_POINTS];
    for (long i = 0; i < points; i++) {
        const double pfa = exp(log(pfa_min) + (log(pfa_max) - log(pfa_min)) * (double)i / (double)(points - 1));
        if (op_point_at(&m, pfa, &h, &pts[i]) != 0) {
            fprintf(stderr, "trk-sim operating-point: no result at P_FA %g (ROC or model refused)\n", pfa);
            return 1;
        }
    }
    /* the TOC optimum */
    struct trk_toc_params tp;
    memset(&tp, 0, sizeof tp);
    mre_params(&m, &tp.mre);
    tp.cells_per_m = (trk_real)(1 / cell_m2);
    tp.pfa_min = (trk_real)pfa_min;
    tp.pfa_max = (trk_real)pfa_max;
    struct op_roc_cache cache = {0, 0, 0};
    const struct op_q2 qc = {&m, &cache};
    tp.q2_fn = op_q2_eval;
    tp.q2_ctx = &qc;
    struct trk_toc_result toc;
    const trk_status tst = trk_toc_optimise(&tp, &toc);
    struct op_point best;
    const int have_best = tst == TRK_OK && op_point_at(&m, (double)toc.pfa, &h, &best) == 0;
    const double secs = progress_now_s() - t0;
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# operating-point: P_D, MRE RMSE, CRLB and HYCA track life along the ROC (PDAF)");
    if (!f) return 1;
    char sensor[160];
    if (polar)
        snprintf(sensor, sizeof sensor, "sigma_r %g m, sigma_b %g deg at %g m (r = %g m^2)", sigma_r, sigma_b_deg,
                 range_m, m.r);
    else
        snprintf(sensor, sizeof sensor, "sigma_x %g m, sigma_y %g m (r = %g m^2)", sigma_m, sigma_y > 0 ? sigma_y : sigma_m,
                 m.r);
    char model[64];
    if (clutter == TRK_AMP_K) snprintf(model, sizeof model, "K clutter, shape %g", nu);
    else snprintf(model, sizeof model, "Rayleigh clutter");
    fprintf(f, "# %s; T %g s, q %g m^2/s^3; SNR %g dB, %s; cell %g m^2; gate g %g; m_lost %ld\n", sensor, dt_s, q,
            snr_db, model, cell_m2, gate_g, m_lost);
    fprintf(f, "pfa,pd,lambda_per_m2,mre_rmse_m,q2,lambda_vg,crlb_rmse_m,life_mean_scans,life_median_scans,"
               "loss_per_scan,hyca_rmse_m\n");
    printf("# operating-point: %s; T %g s, q %g; SNR %g dB, %s; cell %g m^2; gate g %g\n", sensor, dt_s, q, snr_db,
           model, cell_m2, gate_g);
    printf("%10s %6s %10s | %9s %6s %7s | %9s | %11s %11s %9s\n", "P_FA", "P_D", "lambda", "MRE RMSE", "q2",
           "lam V_G", "CRLB", "life mean", "life median", "HYCA RMSE");
    for (long i = 0; i < points; i++) {
        const struct op_point *o = &pts[i];
        char mre[16];
        if (isfinite(o->mre_rmse)) snprintf(mre, sizeof mre, "%9.3f", o->mre_rmse);
        else snprintf(mre, sizeof mre, "%9s", "diverges");
        printf("%10.3g %6.3f %10.3g | %s %6.3f %7.3f | %9.3f | %11.4g %11.4g %9.3f\n", o->pfa, o->pd, o->lambda, mre,
               o->q2, o->lambda_vg, o->crlb_rmse, o->life_mean, o->life_median, o->hyca_rmse);
        fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", o->pfa, o->pd, o->lambda, o->mre_rmse,
                o->q2, o->lambda_vg, o->crlb_rmse, o->life_mean, o->life_median, o->loss, o->hyca_rmse);
    }
    if (have_best) {
        printf("# TOC: P_FA %.4g (P_D %.3f) gives the smallest RMSE, %.3f m; mean track life there %.4g scans\n",
               best.pfa, best.pd, best.mre_rmse, best.life_mean);
        fprintf(f, "# toc_optimum pfa %.6g pd %.6g rmse_m %.6g life_mean_scans %.6g\n", best.pfa, best.pd,
                best.mre_rmse, best.life_mean);
    } else {
        printf("# TOC: no P_FA in [%g, %g] has a steady state (%s)\n", pfa_min, pfa_max, ERRMSG_STATUS(tst));
        fprintf(f, "# toc_optimum none\n");
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("# %ld points in %.2f s\n# file: %s\n", points, secs, path);
    char mark[320] = "";
    if (have_best)
        snprintf(mark, sizeof mark,
                 "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 3 lc rgb 'gray40'\n"
                 "set label 'TOC optimum' at %.6g, graph 0.95 offset 0.5,0 tc rgb 'gray40'\n",
                 best.pfa, best.pfa, best.pfa);
    sim_plotf(&com, "",
              "set datafile separator ','\nset datafile missing 'inf'\nset grid\nset key top left\n"
              "set title \"Operating point: %s, SNR %g dB, %s\"\n"
              "set logscale x\nset format x '10^{%%L}'\nset xlabel 'P_{FA}'\nset ylabel 'position RMSE (m)'\n"
              "set logscale y2\nset format y2 '10^{%%L}'\nset y2label 'mean track life (scans)'\nset y2tics\n"
              "set ytics nomirror\nset yrange [0:*]\n%s"
              "plot '%s' every ::1 using 1:4 with linespoints pt 7 title 'MRE RMSE (PDAF)', \\\n"
              "     '%s' every ::1 using 1:7 with linespoints dt 2 pt 4 title 'CRLB with q2', \\\n"
              "     '%s' every ::1 using 1:8 axes x1y2 with linespoints pt 5 title 'mean track life (HYCA)'\n",
              sensor, snr_db, model, mark, path, path, path);
    return 0;
}
