/* exp_hyca.c - trk-sim hyca: track life predicted by hybrid conditional
 * averaging (trk/hyca.h; Willett 2010 I.D.2, Fig. 8) against a simulated
 * PDAF with Willett's lost-track rule.
 *
 * Model: 2-D constant velocity, T, q~, R = r I, Poisson clutter of density
 * lambda per m^2, detection probability P_D, the PDAF's gate d2 <= g^2.
 *   HYCA      the chain over the number of gated measurements, m >= m_lost
 *             lost (trk_hyca_run), from the two-point-differencing start,
 *             with the run's length as its horizon: the probability that a
 *             track is lost within the run and E[min(life, scans)].
 *   PDAF      simulated (single_target.h: one target, one track, the
 *             library's prediction, gating and PDA update), the same start,
 *             twice with the same random numbers: lost when its gate holds
 *             m_lost or more detections (HYCA's own event), and lost when
 *             |x error| or |y error| exceeds 4 sqrt(r) for 3 scans in a row
 *             (Willett's footnote 5); a life is the scan of the loss, or the
 *             run's length when the track holds.
 * With --pdafai-snr-db D the PDAFAI runs beside the PDAF on the same random
 * numbers: a Swerling I target of SNR D in Rayleigh clutter, the threshold
 * at the P_FA whose P_D is the point's (pd = pfa^(1/(1+SNR))), the same
 * clutter density; its life shows what amplitude information adds to the
 * PDAF that HYCA models.
 * The gate-count rule is the like-for-like check of the prediction; the
 * error rule is what a user calls lost, and it also loses tracks to runs of
 * missed detections with a small gate, which HYCA's chain does not count.
 * HYCA's RMSE is that of the tracks held (quasi-stationary), the
 * simulation's over the tracks not lost by the error rule, scans from
 * --from on.
 * Settings: willett (T 1 s, q 1, r 1 m^2, Table I's clutter range) and
 * sonar (T 4 s, q 0.01 m^2/s^3, r 56.25 m^2 = (7.5 m)^2, the densities of
 * P_FA 1e-4..1e-2 in resolution cells of about 1000 m^2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "mc_stats.h"
#include "progress.h"
#include "sim.h"
#include "single_target.h"
#include "trk/hyca.h"

#define MAXL 32
#define MAXPD 8

struct hy_out {
    unsigned char lost;
    int32_t life;  /* scan of the loss, or the run's length */
    double mse;    /* over scans >= from of a track not lost */
};

/* One run: the PDAF [0] and, with an amplitude model, the PDAFAI [1]. */
struct hy_slot {
    struct hy_out f[2];
};

static void keep(void *slot, int ai, const struct st_result *res)
{
    struct hy_out *o = &((struct hy_slot *)slot)->f[ai];
    o->lost = (unsigned char)res->lost;
    o->life = (int32_t)(res->lost ? res->lost_scan : res->scans);
    o->mse = res->n_sse ? res->sse / (double)res->n_sse : NAN;
}

struct hy_setting {
    const char *name;
    double dt_s, q, r, gate_g;
    const char *lambdas;
};

static const struct hy_setting settings[] = {
    {"willett", 1, 1, 1, 4, "1e-4,5e-4,1e-3,1.5e-3,2e-3,3e-3,5e-3"},
    {"sonar", 4, 0.01, 56.25, 4, "1e-7,1e-6,3e-6,1e-5,2e-5,3e-5,5e-5"},
};

static int hyca_point(const struct hy_setting *s, double pd, double lambda, int m_lost, long scans,
                      struct trk_hyca *h, struct trk_hyca_result *res)
{
    struct trk_hyca_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2;
    p.dt_s = (trk_real)s->dt_s;
    p.q_m2_per_s3 = (trk_real)s->q;
    p.r_m2 = (trk_real)s->r;
    p.pd = (trk_real)pd;
    p.gate_gamma = (trk_real)(s->gate_g * s->gate_g);
    p.clutter_density = (trk_real)lambda;
    p.m_lost = m_lost;
    p.horizon_scans = (int)scans;
    trk_status st = trk_hyca_init(h, &p);
    if (st == TRK_OK) st = trk_hyca_run(h, NULL, res);
    if (st != TRK_OK) {
        fprintf(stderr, "trk-sim hyca: P_D %g, lambda %g: %s\n", pd, lambda, ERRMSG_STATUS(st));
        return -1;
    }
    return 0;
}

/* Loss and life of one (rule, point, filter) over the runs: the fraction
 * lost with its exact 95 % interval, E[min(L, scans)] with its interval. */
struct hy_stats {
    double lost, lost_lo, lost_hi, life, life_lo, life_hi;
};

static void hy_stats_of(const struct hy_slot *out, long runs, int filter, double *vals, struct hy_stats *st)
{
    long lost = 0;
    for (long run = 0; run < runs; run++) {
        lost += out[run].f[filter].lost;
        vals[run] = out[run].f[filter].life;
    }
    st->lost = (double)lost / (double)runs;
    mc_binom_ci(lost, runs, 0.95, &st->lost_lo, &st->lost_hi);
    mc_mean_ci(vals, (size_t)runs, 0.95, &st->life, &st->life_lo, &st->life_hi);
}

SIM_EXPERIMENT(hyca, "hyca", "Willett 2010 I.D.2: track life by HYCA against a simulated PDAF")
{
    long runs, scans, from, m_lost;
    int setting;
    double dt_o = 0, q_o = 0, r_o = 0, ai_snr_db = NAN;
    double pds[MAXPD], lambdas[MAXL];
    int n_pd, n_lambda;
    static const char *setting_words = "willett|sonar";
    const struct sim_opt opts[] = {
        SIM_OPT_CHOICE("--setting", &setting, setting_words, NULL, "willett",
                       "model: willett (T 1 s, q 1, r 1) or sonar (T 4 s, q 0.01, r 56.25)"),
        SIM_OPT_DOUBLE("--dt", &dt_o, "T", NULL, SIM_GT, 0, 0, "scan interval (s), instead of the setting's"),
        SIM_OPT_DOUBLE("--q", &q_o, "Q", NULL, SIM_GT, 0, 0, "process noise PSD (m^2/s^3), instead of the setting's"),
        SIM_OPT_DOUBLE("--r", &r_o, "R", NULL, SIM_GT, 0, 0, "measurement variance (m^2), instead of the setting's"),
        SIM_OPT_LIST("--pd", pds, &n_pd, MAXPD, "0.7,0.8,0.9", SIM_GT | SIM_LE, 0, 1, "detection probabilities"),
        SIM_OPT_LIST("--lambda", lambdas, &n_lambda, MAXL, NULL, SIM_GE, 0, 0,
                     "clutter densities per m^2 (default: the setting's)"),
        SIM_OPT_LONG("--m-lost", &m_lost, "M", "10", SIM_IN, 2, TRK_HYCA_MAX_STATES,
                     "HYCA: a gate holding M or more measurements is lost (Willett: 10)"),
        SIM_OPT_DOUBLE("--pdafai-snr-db", &ai_snr_db, "D", NULL, SIM_IN, -30, 60,
                       "also run the PDAFAI: Rayleigh clutter, Swerling I target of this SNR"),
        SIM_OPT_LONG("--runs", &runs, "N", "1000", SIM_GE, 1, 0, "runs per point"),
        SIM_OPT_LONG("--scans", &scans, "N", "300", SIM_IN, 2, 1000000, "scans per run (HYCA's horizon)"),
        SIM_OPT_LONG("--from", &from, "K", "21", SIM_GE, 1, 0, "first scan of the simulated RMSE"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "hyca", NULL,
        "Track life predicted by hybrid conditional averaging (HYCA, the chain over the number of\n"
        "gated measurements) against a simulated PDAF with Willett's lost-track rule, over P_D x lambda.",
        opts, "hyca", NULL, 0, "Writes PREFIX.csv, PREFIX.gp, PREFIX.png.", NULL, NULL};
    struct sim_common com;
    n_lambda = 0;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    struct hy_setting set = settings[setting];
    if (dt_o > 0) set.dt_s = dt_o;
    if (q_o > 0) set.q = q_o;
    if (r_o > 0) set.r = r_o;
    const struct hy_setting *s = &set;
    if (n_lambda == 0) {
        const char *v = s->lambdas;
        for (n_lambda = 0; *v && n_lambda < MAXL; n_lambda++) {
            char *end;
            lambdas[n_lambda] = strtod(v, &end);
            v = *end ? end + 1 : end;
        }
    }
    if (from > scans) {
        fprintf(stderr, "trk-sim hyca: --from must be <= --scans\n");
        return 2;
    }
    const int np = n_pd * n_lambda;
    const double gamma = s->gate_g * s->gate_g, thresh = 4 * sqrt(s->r);
    /* predictions */
    static struct trk_hyca h;
    struct trk_hyca_result *pred = calloc((size_t)np, sizeof *pred);
    struct st_model *mod = calloc(2 * (size_t)np, sizeof *mod);
    struct hy_slot *out = calloc(2 * (size_t)np * (size_t)runs, sizeof *out);
    static struct st_amp amps[MAXPD];
    const int with_ai = !isnan(ai_snr_db);
    if (with_ai)
        for (int i = 0; i < n_pd; i++) {
            /* the P_FA whose Rayleigh ROC value is pd: pd = pfa^(1/(1+SNR)) */
            const double snr = pow(10, ai_snr_db / 10), pfa = pow(pds[i], 1 + snr);
            char e[256];
            if (!(pfa > 0) || st_amp_init(&amps[i], TRK_AMP_RAYLEIGH, 0, ai_snr_db, pfa, 0, 0, e, sizeof e)) {
                fprintf(stderr, "trk-sim hyca: PDAFAI at P_D %g, SNR %g dB: %s\n", pds[i], ai_snr_db,
                        pfa > 0 ? e : "P_FA underflows");
                return 1;
            }
        }
    double *vals = malloc((size_t)runs * sizeof *vals);
    if (!pred || !mod || !out || !vals) return 1;
    const double t0 = progress_now_s();
    for (int k = 0; k < np; k++)
        if (hyca_point(s, pds[k / n_lambda], lambdas[k % n_lambda], (int)m_lost, scans, &h, &pred[k])) return 1;
    const double hyca_s = progress_now_s() - t0;
    /* simulation: models 0..np-1 the gate-count rule, np..2np-1 the error rule */
    for (int k = 0; k < 2 * np; k++) {
        const int count_rule = k < np, kp = k % np;
        struct st_params sp;
        st_params_brekke(&sp);
        sp.dt_s = s->dt_s;
        sp.q_m2_per_s3 = s->q;
        sp.r_m2 = s->r;
        sp.gate_gamma = gamma;
        sp.lambda_per_m2 = lambdas[kp % n_lambda];
        sp.pd = pds[kp / n_lambda];
        if (with_ai) sp.amp = &amps[kp / n_lambda].m;
        sp.n_scans = scans;
        sp.loss = ST_LOSS_WILLETT;
        sp.thresh_m = count_rule ? HUGE_VAL : thresh;
        if (count_rule) sp.gate_cap = (struct st_gate_cap){ST_GATE_COUNT, m_lost, 0};
        sp.count = 3;
        sp.init = ST_INIT_TWOPOINT;
        sp.seed = com.seed;
        char e[256];
        if (st_model_init(&mod[k], &sp, e, sizeof e)) {
            fprintf(stderr, "trk-sim hyca: %s\n", e);
            return 1;
        }
    }
    int bad_call;
    const double wall = sim_st_runs(&com, cli.name, mod, 2 * np, runs, with_ai ? 2 : 1, from, keep, out, sizeof *out, &bad_call);
    if (bad_call) return 1;
    char path[1024];
    struct fileio_out f_out;
    FILE *f = sim_csv_open(&com, &f_out, ".csv", path, sizeof path,
                           "# hyca: track life, HYCA (gate runaway, m >= m_lost) vs simulated PDAF (Willett's rule)");
    if (!f) return 1;
    fprintf(f, "# setting %s: T %g s, q %g m^2/s^3, r %g m^2, gate g %g (gamma %g); m_lost %ld; %ld runs x %ld scans, "
               "two-point start; lost: |x or y error| > %g m for 3 scans; seed %llu\n",
            s->name, s->dt_s, s->q, s->r, s->gate_g, gamma, m_lost, runs, scans, thresh,
            (unsigned long long)com.seed);
    fprintf(f, "pd,lambda_per_m2,hyca_lost_frac,hyca_life_horizon,hyca_mean_life,hyca_median_life,hyca_loss_per_scan,"
               "hyca_rmse_m,hyca_mean_gated,cnt_lost_frac,cnt_lost_lo95,cnt_lost_hi95,cnt_lost_in_ci,cnt_life,"
               "cnt_life_lo95,cnt_life_hi95,cnt_life_in_ci,err_lost_frac,err_lost_lo95,err_lost_hi95,err_life,"
               "err_life_lo95,err_life_hi95,sim_rmse_m,sim_rmse_lo95,sim_rmse_hi95,ai_cnt_lost_frac,"
               "ai_cnt_lost_lo95,ai_cnt_lost_hi95,ai_cnt_life,ai_cnt_life_lo95,ai_cnt_life_hi95,ai_err_lost_frac,"
               "ai_err_life\n");
    printf("# hyca (%s): T %g s, q %g, r %g, gate g %g, m_lost %ld; %ld runs x %ld scans; life L = scans until lost, "
           "E[min(L, %ld)]\n",
           s->name, s->dt_s, s->q, s->r, s->gate_g, m_lost, runs, scans, scans);
    printf("# sim gate: lost when the gate holds >= %ld (HYCA's event); sim error: Willett's 4-sigma rule\n", m_lost);
    printf("%5s %8s | %6s %-22s %2s | %7s %-24s %2s | %-22s %-24s | %9s | %6s %-21s\n", "P_D", "lambda", "HYCA %",
           "sim gate lost % [CI]", "in", "HYCA L", "sim gate L [95% CI]", "in", "sim error lost % [CI]",
           "sim error L [95% CI]", "HYCA E[L]", "HYCA", "sim RMSE [95% CI]");
    for (int k = 0; k < np; k++) {
        const struct trk_hyca_result *r = &pred[k];
        const struct hy_slot *cnt = &out[(size_t)k * (size_t)runs], *err = &out[((size_t)np + (size_t)k) * (size_t)runs];
        struct hy_stats sc, se, ac = {NAN, NAN, NAN, NAN, NAN, NAN}, ae = ac;
        hy_stats_of(cnt, runs, 0, vals, &sc);
        hy_stats_of(err, runs, 0, vals, &se);
        if (with_ai) {
            hy_stats_of(cnt, runs, 1, vals, &ac);
            hy_stats_of(err, runs, 1, vals, &ae);
        }
        const double lost_f[2] = {sc.lost, se.lost}, llo[2] = {sc.lost_lo, se.lost_lo}, lhi[2] = {sc.lost_hi, se.lost_hi},
                     life[2] = {sc.life, se.life}, life_lo[2] = {sc.life_lo, se.life_lo},
                     life_hi[2] = {sc.life_hi, se.life_hi};
        size_t n_mse = 0;
        for (long run = 0; run < runs; run++) {
            const struct hy_out *o = &err[run].f[0];
            if (!o->lost && !isnan(o->mse)) vals[n_mse++] = o->mse;
        }
        double m = NAN, mlo = NAN, mhi = NAN;
        if (n_mse > 0) mc_mean_ci(vals, n_mse, 0.95, &m, &mlo, &mhi);
        const double hl = (double)r->lost_by_horizon, hm = (double)r->mean_life_horizon;
        /* inside the interval, up to the rounding of a prediction on its end */
        const double eps = 1e-9;
        const int lost_in = hl >= llo[0] - eps && hl <= lhi[0] + eps,
                  life_in = hm >= life_lo[0] * (1 - eps) && hm <= life_hi[0] * (1 + eps);
        printf("%5.2f %8.2g | %6.2f %6.2f [%6.2f, %6.2f] %2s | %7.1f %7.1f [%6.1f, %6.1f] %2s | %6.2f [%6.2f, %6.2f] "
               "%7.1f [%6.1f, %6.1f] | %9.3g | %6.3f %6.3f [%6.3f, %6.3f]\n",
               pds[k / n_lambda], lambdas[k % n_lambda], 100 * hl, 100 * lost_f[0], 100 * llo[0], 100 * lhi[0],
               lost_in ? "y" : "n", hm, life[0], life_lo[0], life_hi[0], life_in ? "y" : "n", 100 * lost_f[1],
               100 * llo[1], 100 * lhi[1], life[1], life_lo[1], life_hi[1], (double)r->mean_life_scans,
               (double)r->rmse_m, sqrt(m), sqrt(fmax(mlo, 0)), sqrt(mhi));
        if (with_ai)
            printf("%14s | PDAFAI (SNR %g dB): gate rule lost %6.2f %% [%6.2f, %6.2f], life %7.1f [%6.1f, %6.1f]; "
                   "4-sigma rule lost %6.2f %%, life %7.1f\n",
                   "", ai_snr_db, 100 * ac.lost, 100 * ac.lost_lo, 100 * ac.lost_hi, ac.life, ac.life_lo, ac.life_hi,
                   100 * ae.lost, ae.life);
        fprintf(f, "%g,%g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%.6g,"
                   "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                pds[k / n_lambda], lambdas[k % n_lambda], hl, hm, (double)r->mean_life_scans,
                (double)r->median_life_scans, (double)r->loss_per_scan, (double)r->rmse_m, (double)r->mean_gated,
                lost_f[0], llo[0], lhi[0], lost_in, life[0], life_lo[0], life_hi[0], life_in, lost_f[1], llo[1],
                lhi[1], life[1], life_lo[1], life_hi[1], sqrt(m), sqrt(fmax(mlo, 0)), sqrt(mhi), ac.lost, ac.lost_lo,
                ac.lost_hi, ac.life, ac.life_lo, ac.life_hi, ae.lost, ae.life);
    }
    if (sim_csv_close(&f_out) != 0) return 1;
    char pd_words[MAXPD * 24] = "";
    for (int i = 0; i < n_pd; i++)
        snprintf(pd_words + strlen(pd_words), sizeof pd_words - strlen(pd_words), "%s%g", i ? " " : "", pds[i]);
    printf("# wall %.1f s simulation, %.3f s HYCA (%d points)\n", wall, hyca_s, np);
    printf("# file: %s\n", path);
    sim_plotf(&com, "",
              "set datafile separator ','\nset datafile missing 'nan'\nset grid\nset key bottom left\n"
              "set title \"Track life: HYCA (lines) vs simulated PDAF (95%% CI), %s setting, %ld scans\"\n"
              "set xlabel 'clutter density lambda (1/m^2)'\nset ylabel 'E[min(life, %ld)] (scans)'\n"
              "set logscale x\nset yrange [0:*]\n"
              "P = '%s'\n"
              "plot for [i=1:words(P)] '%s' every ::1 using ($1==word(P,i)+0?$2:NaN):14:15:16 with yerrorbars "
              "pt 7 lc i title sprintf('PDAF, gate rule, P_D %%s', word(P,i)), \\\n"
              "     for [i=1:words(P)] '%s' every ::1 using ($1==word(P,i)+0?$2:NaN):21:22:23 with yerrorbars "
              "pt 6 lc i title sprintf('PDAF, 4-sigma rule, P_D %%s', word(P,i)), \\\n"
              "     for [i=1:words(P)] '%s' every ::1 using ($1==word(P,i)+0?$2:NaN):4 with linespoints dt 2 pt 4 "
              "lc i title sprintf('HYCA, P_D %%s', word(P,i))\n",
              s->name, scans, scans, pd_words, path, path, path);
    if (with_ai)
        for (int i = 0; i < n_pd; i++) st_amp_free(&amps[i]);
    free(pred);
    free(mod);
    free(out);
    free(vals);
    return 0;
}
