/* exp_willett_crlb.c - trk-sim willett-crlb: the PDAF's position RMSE against
 * the CRLB with the information-reduction factor (Willett 2010, I.B-I.D:
 * eq 37 with Table I's q2; Figs. 3-5), for a few (P_D, lambda) of Table I.
 *
 * Model (Willett I.B.5, I.C): 2-D constant velocity, T = 1 s, q~ = 1
 * (m^2/s^3), R = I (sigma_w = 1 m), Poisson clutter of density lambda per
 * m^2, detection probability P_D.
 *   CRLB     the library's information recursion (trk/crlb.h, eq 37) to its
 *            steady state, position bound sqrt(Jinv11 + Jinv22), with q2 of
 *            Table I (the paper's) and with q2 from the importance sampler
 *            (q2_is.h) for Table I's mapping (docs/conventions.md: a gate of area
 *            V = 400 around the truth, gamma = 400/pi, P_G = 1,
 *            lambda_vg = 400 lambda).
 *   PDAF     simulated (single_target.h: one target, one track, the
 *            library's trk_cv2_predict / trk_pda_update), gate d2 <= g^2
 *            (--gate-g, default 4), two-point-differencing start (--start); a track is lost
 *            when its position error exceeds 4 sigma_w for 3 scans in a row
 *            (Willett's footnote 5; his PDAF runs in 1-D, here the rule
 *            applies to each coordinate); the RMSE is over the tracks not
 *            lost, scans from --from on (steady state).
 *   MRE      for contrast: the PDAF's own prediction, the MRE (trk/mre.h)
 *            with q2 at its gate, solved as the fixed point q2* =
 *            q2(pd, lambda V_G(S(q2*))) from q2 = 1 down (S(q) the MRE's
 *            steady state with constant q, q2 from the sampler with fixed
 *            random numbers): the largest fixed point, the steady state of a
 *            track that holds. None: no fixed point (the MRE diverges).
 * Willett plots one coordinate ((1,1) of J^-1) and a 1-D PDAF; here both
 * coordinates are tracked (Table I's q2 is 2-D) and every RMSE is the 2-D
 * position RMSE. A 2-D gate holds more clutter than a 1-D one: the 2-D PDAF
 * (and its MRE) breaks down near lambda = 0.002-0.004 at P_D 0.7-0.9, far
 * below Table I's largest lambda, so the default points stay below. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "trk/gate.h"
#include "mc_stats.h"
#include "progress.h"
#include "q2_is.h"
#include "sim.h"
#include "single_target.h"
#include "trk/mre.h"
#include "willett.h"

#define MAXP 32

/* MRE of the PDAF at its gate, as the largest fixed point of q2 (see top). */
static int mre_pdaf(double pd, double lambda, double gamma, const struct q2_is_options *qo, double *rmse,
                    double *q2_out, double *lvg_out)
{
    double q2 = 1;
    *rmse = INFINITY;
    *q2_out = *lvg_out = NAN;
    for (int it = 0; it < 60; it++) {
        struct trk_mre_params mp;
        memset(&mp, 0, sizeof mp);
        mp.nz = 2;
        mp.dt_s = 1;
        mp.q_m2_per_s3 = 1;
        mp.r_m2 = 1;
        mp.gate_gamma = (trk_real)gamma;
        mp.clutter_density = (trk_real)lambda;
        mp.q2 = (trk_real)q2;
        struct trk_mre m;
        struct trk_mre_result res;
        if (trk_mre_init(&m, &mp) != TRK_OK) return -1;
        trk_status st = trk_mre_steady_state(&m, NULL, &res);
        if (st == TRK_E_DIVERGED) return 0;
        if (st != TRK_OK) return -1;
        const double lvg = (double)res.lambda_vg;
        if (!(lvg < Q2_IS_MAX_LAMBDA_VG)) return 0;
        double qn, se;
        char err[256];
        if (lvg > 0) {
            if (q2_is_cell(2, gamma, pd, lvg, NULL, qo, &qn, &se, err, sizeof err) != 0) {
                fprintf(stderr, "trk-sim willett-crlb: q2 sampler: %s\n", err);
                return -1;
            }
        } else { /* no clutter: beta_1 = 1, q2 = pd F_4(gamma) */
            qn = pd * (1 - exp(-gamma / 2) * (1 + gamma / 2));
        }
        if (fabs(qn - q2) < 1e-5) {
            *rmse = (double)res.rmse_m;
            *q2_out = qn;
            *lvg_out = lvg;
            return 0;
        }
        if (qn < 1e-3) return 0;
        q2 = qn;
    }
    return 0;
}

struct wc_out {
    unsigned char lost;
    double mse;   /* mean squared error over the run's scans >= from (not lost) */
    int32_t scans;
};

struct wc_points {
    double pd[MAXP], lambda[MAXP];
    int n;
};

static void keep(void *slot, int ai, const struct st_result *res)
{
    struct wc_out *o = slot;
    (void)ai;
    o->lost = (unsigned char)res->lost;
    o->mse = res->n_sse ? res->sse / (double)res->n_sse : NAN;
    o->scans = (int32_t)res->scans;
}

/* --points: P_D:lambda pairs, "0.9:0.001,0.8:0.0001" */
static int parse_points(const char *v, void *dst)
{
    struct wc_points *p = dst;
    const char *s = v;
    p->n = 0;
    if (strpbrk(v, " \t\n\r\v\f")) return -1; /* no blanks, as every number */
    while (*s && p->n < MAXP) {
        char *end;
        const double pd = strtod(s, &end);
        if (end == s || *end != ':') return -1;
        s = end + 1;
        const double lambda = strtod(s, &end);
        if (end == s || (*end && *end != ',')) return -1;
        if (!(pd > 0 && pd <= 1) || !(lambda >= 0)) return -1;
        p->pd[p->n] = pd;
        p->lambda[p->n++] = lambda;
        s = *end ? end + 1 : end;
    }
    return p->n == 0 || *s ? -1 : 0;
}

SIM_EXPERIMENT(willett_crlb, "willett-crlb", "Willett 2010 I.D: PDAF RMSE against the CRLB with q2 (Table I)")
{
    long runs, scans, from, q2_samples;
    double gate_g;
    int init;
    struct st_gate_cap gate_cap;
    static struct wc_points pts;
    const struct sim_opt opts[] = {
        SIM_OPT_CUSTOM("--points", &pts, parse_points, "LIST",
                       "0.9:0.0001,0.9:0.001,0.9:0.002,0.9:0.004,0.8:0.0001,0.8:0.002,0.7:0.0001",
                       "P_D:lambda pairs\n(Table I's lambdas give the paper's q2)"),
        SIM_OPT_LONG("--runs", &runs, "N", "10000", SIM_GE, 1, 0, "runs per point"),
        SIM_OPT_LONG("--scans", &scans, "N", "100", SIM_IN, 2, 1000000, "scans per run"),
        SIM_OPT_LONG("--from", &from, "K", "21", SIM_GE, 1, 0, "first scan of the RMSE (past the transient)"),
        SIM_OPT_DOUBLE("--gate-g", &gate_g, "G", "4", SIM_GT | SIM_LE, 0, 30,
                       "the PDAF's gate: d2 <= G^2 (4: P_G 0.99966; a gate of P_G 0.99\n"
                       "loses more tracks to gate misses under this strong process noise)"),
        SIM_OPT_LONG("--q2-samples", &q2_samples, "N", "400000", SIM_GE, 1000, 0,
                     "importance samples per stratum for q2"),
        SIM_OPT_START(&init),
        SIM_OPT_GATE_CAP(&gate_cap),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "willett-crlb", NULL,
        "PDAF position RMSE (tracks not lost) against the CRLB with the information-reduction\n"
        "factor q2 (Willett 2010 eq 37, Table I), and the PDAF's MRE. Model: T 1 s, q 1, R = I.",
        opts, "willett_crlb", NULL, 0, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    const double *pds = pts.pd, *lams = pts.lambda;
    const int np = pts.n;
    if (from > scans) {
        fprintf(stderr, "trk-sim willett-crlb: --from must be <= --scans\n");
        return 2;
    }
    const int threads = sim_threads(&com);
    const double gamma = gate_g * gate_g, gate_prob = -expm1(-gamma / 2);
    /* bounds and predictions (deterministic given the seed) */
    double q2p[MAXP], q2o[MAXP], q2o_se[MAXP], crlb_p[MAXP], crlb_o[MAXP], mre[MAXP], mre_q2[MAXP], mre_lvg[MAXP];
    double kf;
    if (willett_crlb(cli.name, 1, NULL, &kf) != 0) return 1;
    struct q2_is_options qo;
    memset(&qo, 0, sizeof qo);
    qo.seed = com.seed;
    qo.samples = (uint64_t)q2_samples;
    qo.target_se = 2e-4;
    qo.threads = com.threads;
    qo.par = com.par;
    const double t_b = progress_now_s();
    for (int k = 0; k < np; k++) {
        char err[256];
        q2p[k] = willett_paper_q2(pds[k], lams[k]);
        if (lams[k] > 0) {
            if (q2_is_cell(2, WILLETT_AREA / (double)trk_gate_unit_volume(2), pds[k], WILLETT_AREA * lams[k], NULL, &qo,
                           &q2o[k], &q2o_se[k], err, sizeof err) != 0) {
                fprintf(stderr, "trk-sim willett-crlb: q2 sampler: %s\n", err);
                return 1;
            }
        } else {
            q2o[k] = pds[k]; /* no clutter: only missed detections */
            q2o_se[k] = 0;
        }
        crlb_p[k] = NAN;
        if (!isnan(q2p[k]) && willett_crlb(cli.name, q2p[k], NULL, &crlb_p[k]) != 0) return 1;
        if (willett_crlb(cli.name, q2o[k], NULL, &crlb_o[k]) != 0) return 1;
        if (mre_pdaf(pds[k], lams[k], gamma, &qo, &mre[k], &mre_q2[k], &mre_lvg[k]) != 0) return 1;
    }
    const double bound_s = progress_now_s() - t_b;
    /* simulation */
    if (np < 1) return 2;
    struct st_model *mod = calloc((size_t)(unsigned)np, sizeof *mod);
    struct wc_out *out = calloc((size_t)np * (size_t)runs, sizeof *out);
    if (!mod || !out) return 1;
    for (int k = 0; k < np; k++) {
        struct st_params sp;
        st_params_brekke(&sp);
        sp.q_m2_per_s3 = 1;
        sp.r_m2 = 1;
        sp.gate_gamma = gamma;
        sp.lambda_per_m2 = lams[k];
        sp.pd = pds[k];
        sp.n_scans = scans;
        sp.loss = ST_LOSS_WILLETT;
        sp.thresh_m = 4;
        sp.count = 3;
        sp.init = init;
        sp.gate_cap = gate_cap;
        sp.seed = com.seed;
        char e[256];
        if (st_model_init(&mod[k], &sp, e, sizeof e)) {
            fprintf(stderr, "trk-sim willett-crlb: %s\n", e);
            return 1;
        }
    }
    if (!com.quiet)
        fprintf(stderr, "trk-sim willett-crlb: %d points x %ld runs x %ld scans, seed %llu, %d threads (bounds %.1f s)\n", np,
                runs, scans, (unsigned long long)com.seed, threads, bound_s);
    int bad_call;
    const double wall = sim_st_runs(&com, cli.name, mod, np, runs, 1, from, keep, out, sizeof *out, &bad_call);
    if (bad_call) return 1;
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# willett-crlb: PDAF position RMSE (tracks not lost) vs CRLB with q2 (Willett eq 37)");
    if (!f) return 1;
    fprintf(f, "# T 1 s, q 1 m^2/s^3, R = I m^2; PDAF gate P_G %.6g (gamma %.6g), %s start, %ld scans, RMSE over "
               "scans >= %ld; lost: |x or y error| > 4 m for 3 scans in a row; q2 for the CRLB: V = 400 (gamma 400/pi, P_G 1, "
               "lambda_vg 400 lambda); seed %llu, runs %ld\n",
            gate_prob, gamma, sim_start_name(init), scans, from, (unsigned long long)com.seed, runs);
    sim_assumptions_csv(f, init, &gate_cap, -1);
    fprintf(f, "# MRE of the PDAF: fixed point of q2 with constant q2 per solve (its steady state does not depend on the "
               "start)\n");
    fprintf(f, "pd,lambda_per_m2,q2_paper,q2_ours,q2_ours_se,crlb_paper_q2_m,crlb_ours_q2_m,crlb_kalman_m,pdaf_rmse_m,"
               "pdaf_rmse_lo95,pdaf_rmse_hi95,pdaf_over_crlb,lost,lost_frac,lost_lo95,lost_hi95,mre_rmse_m,mre_q2,"
               "mre_lambda_vg\n");
    printf("# willett-crlb: T 1 s, q 1, R = I; PDAF gate g %g (P_G %.5f); %ld runs x %ld scans, RMSE over scans >= %ld of the "
           "tracks not lost\n",
           gate_g, gate_prob, runs, scans, from);
    printf("# Kalman filter without clutter and misses (q2 = 1): RMSE bound %.4f m\n", kf);
    printf("%5s %7s | %7s %7s | %8s %8s | %-24s %6s | %-22s | %8s\n", "P_D", "lambda", "q2 pap", "q2 ours", "CRLB pap",
           "CRLB our", "PDAF RMSE [95% CI]", "/CRLB", "lost % [95% CI]", "MRE");
    long total_scans = 0;
    double *mses = malloc((size_t)runs * sizeof *mses);
    if (!mses) return 1;
    for (int k = 0; k < np; k++) {
        long lost = 0;
        size_t n = 0;
        for (long run = 0; run < runs; run++) {
            const struct wc_out *o = &out[(size_t)k * (size_t)runs + (size_t)run];
            total_scans += o->scans;
            if (o->lost) lost++;
            else if (!isnan(o->mse)) mses[n++] = o->mse;
        }
        double m = NAN, lo = NAN, hi = NAN, llo, lhi;
        if (n > 0) mc_mean_ci(mses, n, 0.95, &m, &lo, &hi);
        const double rm = sqrt(m), rlo = sqrt(fmax(lo, 0)), rhi = sqrt(hi);
        mc_binom_ci(lost, runs, 0.95, &llo, &lhi);
        char pq[16], pc[16], mr[16];
        snprintf(pq, sizeof pq, isnan(q2p[k]) ? "-" : "%.4f", q2p[k]);
        snprintf(pc, sizeof pc, isnan(crlb_p[k]) ? "-" : "%.4f", crlb_p[k]);
        snprintf(mr, sizeof mr, isfinite(mre[k]) ? "%.4f" : "diverges", mre[k]);
        printf("%5.2f %7.4f | %7s %7.4f | %8s %8.4f | %7.4f [%7.4f, %7.4f] %6.3f | %6.2f [%6.2f, %6.2f] | %8s\n", pds[k],
               lams[k], pq, q2o[k], pc, crlb_o[k], rm, rlo, rhi, rm / crlb_o[k], 100.0 * (double)lost / (double)runs,
               100 * llo, 100 * lhi, mr);
        fprintf(f, "%g,%g,%.6g,%.6g,%.3g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%ld,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", pds[k],
                lams[k], q2p[k], q2o[k], q2o_se[k], crlb_p[k], crlb_o[k], kf, rm, rlo, rhi, rm / crlb_o[k], lost,
                (double)lost / (double)runs, llo, lhi, mre[k], mre_q2[k], mre_lvg[k]);
    }
    free(mses);
    if (sim_csv_close(&f_out) != 0) return 1;
    printf("# wall %.1f s on %d threads (+ %.1f s q2 and bounds); %ld track updates, %.3g updates/s\n", wall, threads,
           bound_s, total_scans, (double)total_scans / wall);
    printf("# file: %s\n", path);
    char as[160];
    sim_plotf(&com, "",
              "set datafile separator ','\nset datafile missing 'nan'\nset grid\nset key top left\n"
              "set title \"Willett 2010: PDAF RMSE (tracks not lost) vs CRLB with q2 (T 1 s, q 1, R = I)\\n%s\"\n"
              "set xlabel 'clutter density lambda (1/m^2)'\nset ylabel 'steady-state position RMSE (m)'\n"
              "set yrange [0:*]\n"
              "plot for [pd in '0.7 0.8 0.9'] '%s' every ::1 using ($1==pd+0?$2:NaN):9:10:11 with yerrorbars pt 7 "
              "title sprintf('PDAF, P_D %%s', pd), \\\n"
              "     for [pd in '0.7 0.8 0.9'] '%s' every ::1 using ($1==pd+0?$2:NaN):7 with linespoints dt 2 pt 4 "
              "title sprintf('CRLB (our q2), P_D %%s', pd), \\\n"
              "     '%s' every ::1 using 2:6 with points pt 2 ps 1.5 lc rgb 'black' title 'CRLB (paper q2)', \\\n"
              "     '%s' every ::1 using 2:17 with points pt 8 ps 1.3 lc rgb '#888888' title 'MRE of the PDAF'\n",
              sim_assumptions_title(as, sizeof as, init, &gate_cap, -1), path, path, path, path);
    free(mod);
    free(out);
    return 0;
}
