/* mtt_params.c - the tracker configurations of trk-sim's multi-target
 * experiments (mtt_params.h). */
#include <stdlib.h>
#include <string.h>

#include "errmsg.h"
#include "kvfile.h"
#include "mtt_params.h"
#include "trk/amplitude.h"

const char *const cfg_name[N_CFG_KINDS] = {"new", "pda", "old", "imm", "oracle", "cart", "cfar", "known"};

#if TRK_WITH_IMM
/* p->imm: CV at p->process_noise_q (--q) and turns at +-rate_dps with
 * turn_q (tcfg_imm_models; the defaults MTT_IMM_* and why: above). */
static trk_status imm_models(struct trk_tracker_params *p, const struct imm_opts *im)
{
    return tcfg_imm_models(p, im->rate_dps, im->p_stay, im->turn_q);
}
#endif

/* The tracker parameters of configuration kind at clutter density lambda
 * (the scenario's sensor, then the --set settings). 0, or -1 with a message. */
int mtt_build_params(int kind, const struct mtt_scenario *sc, double lambda, double q, const struct imm_opts *im,
                     const struct mtt_settings *set, struct trk_tracker_params *out, struct tcfg_runtime *rt,
                     char *err, size_t n)
{
    struct trk_tracker_params p;
    if (kind == CFG_OLD) mtt_old_defaults(&p);
    else trk_tracker_default_params(&p); /* new, pda, imm, cart, cfar, known; oracle: its sensor R and q */
    if (kind == CFG_PDA) p.association = TRK_ASSOC_PDA;
#if !TRK_WITH_IMM
    (void)im;
#endif
    const double sg = sc->p.meas_sigma_m;
    p.n_sensors = 1;
    if (sc->p.family == MTT_FAMILY_SONAR) {
        /* the polar sensor as the scenario describes it (kind, sigmas,
         * coverage, P_D profile); cart: the old way, Cartesian detections
         * converted by the caller, one P_D averaged over the sector, no
         * pose, no coverage */
        p.sensor[0] = sc->sonar;
        if (kind == CFG_CART) {
            p.sensor[0].kind = TRK_SENSOR_CARTESIAN;
            memset(&p.sensor[0].pd_profile, 0, sizeof p.sensor[0].pd_profile);
            memset(&p.sensor[0].coverage, 0, sizeof p.sensor[0].coverage);
            p.sensor[0].pd = (trk_real)sc->sonar_pd_mean;
        }
        /* the clutter profile per point, times the points per scan (none at
         * clutter 0, or for cart: the sector's mean lambda everywhere) */
        struct trk_clutter_profile *cp = &p.sensor[0].clutter_profile;
        if (kind == CFG_CART || !(lambda * sc->area_m2 > 0.5)) memset(cp, 0, sizeof *cp);
        for (unsigned k = 0; k < cp->n; k++) cp->density_per_m2[k] *= (trk_real)(lambda * sc->area_m2);
        /* its persistent returns in the amplitudes (not cart's, nor known's,
         * whose scans hold none): their share of what is not a target's (at
         * clutter 0: of one clutter point) and P_D */
        if (kind != CFG_CART && kind != CFG_KNOWN && sc->p.amplitude && sc->p.persistent) {
            const double n_p = MTT_SONAR_PERSIST * MTT_SONAR_PERSIST_PD, n_c = lambda * sc->area_m2;
            p.sensor[0].persistent_share = (trk_real)(n_p / (n_p + (n_c > 1 ? n_c : 1)));
            p.sensor[0].persistent_pd = (trk_real)MTT_SONAR_PERSIST_PD;
        }
    } else {
        p.sensor[0].pd = (trk_real)sc->p.pd;
        p.sensor[0].meas_cov_m2[TRK_COV2_XX] = p.sensor[0].meas_cov_m2[TRK_COV2_YY] = (trk_real)(sg * sg);
        p.sensor[0].meas_cov_m2[TRK_COV2_XY] = 0;
    }
    p.sensor[0].clutter_density_per_m2 = (trk_real)lambda;
    /* the sonar's amplitude model: its threshold, its P_D profile the
     * target's SNR over range (cart: one SNR, the one of its mean P_D) */
    const double snr_db = sc->p.family == MTT_FAMILY_SONAR ? sc->sonar_snr_db : sc->p.snr_db;
    p.sensor[0].use_amplitude = sc->p.amplitude;
    if (sc->p.amplitude &&
        trk_amplitude_init_rayleigh(&p.sensor[0].amplitude, 1, (trk_real)snr_db, (trk_real)sc->pfa) != TRK_OK) {
        snprintf(err, n, "Rayleigh model (SNR %g dB, P_FA %g) refused", snr_db, sc->pfa);
        return -1;
    }
    p.process_noise_q = (trk_real)q;
#if TRK_WITH_IMM
    if (kind == CFG_IMM && imm_models(&p, im) != TRK_OK) {
        snprintf(err, n, "configuration imm needs a build with TRK_MAX_MODELS >= 3");
        return -1;
    }
#endif
    memset(rt, 0, sizeof *rt);
    if (set->n > 0) {
        /* the settings through tools/cli/tracker_config, on a tcfg holding p */
        struct tcfg *c = malloc(sizeof *c);
        if (!c) {
            snprintf(err, n, "out of memory");
            return -1;
        }
        tcfg_defaults(c);
        c->params = p;
        for (unsigned s = 1; s < TRK_MAX_SENSORS; s++) c->params.sensor[s] = p.sensor[0];
        c->confirm = p.confirm.method;
        c->term = p.term.method;
        if (p.confirm.method == TRK_CONFIRM_MN) c->mn = p.confirm.u.mn;
        if (p.term.method == TRK_TERM_KN) c->kn = p.term.u.kn;
        c->amp[0].model = sc->p.amplitude ? TCFG_AMP_RAYLEIGH : TCFG_AMP_NONE;
        c->amp[0].snr_db = snr_db;
        c->amp[0].pfa = sc->pfa;
#if TRK_WITH_IMM
        /* tcfg_params assembles p.imm from these: the configuration's, then --set imm.* */
        c->imm_turn_rate_dps = kind == CFG_IMM ? im->rate_dps : 0;
        c->imm_p_stay = im->p_stay;
        c->imm_turn_q = im->turn_q;
#endif
        int confirm_set = 0, term_set = 0;
        for (int i = 0; i < set->n; i++) {
            const char *kv = set->kv[i];
            if (kv_parse_assignment(kv, tcfg_set, c, err, n) != 0) {
                char e2[512];
                snprintf(e2, sizeof e2, "--set %.200s: %.300s", kv, err);
                snprintf(err, n, "%s", e2);
                free(c);
                return -1;
            }
            confirm_set |= strncmp(kv, "confirm", 7) == 0 || strncmp(kv, "hmm", 3) == 0;
            term_set |= strncmp(kv, "term", 4) == 0 || strncmp(kv, "hmm", 3) == 0;
        }
        /* the clutter floor below, before the check: at clutter 0 joint
         * association refused every --set (a density of 0) */
        const double floor_m2 = 1 / sc->area_m2;
        for (unsigned s = 0; s < TRK_MAX_SENSORS; s++)
            if (c->params.association == TRK_ASSOC_JOINT && c->params.sensor[s].clutter_density_per_m2 < floor_m2 &&
                lambda < floor_m2)
                c->params.sensor[s].clutter_density_per_m2 = (trk_real)floor_m2;
        if (tcfg_check(c, err, n) != 0 || tcfg_load(c, rt, err, n) != 0) {
            free(c);
            return -1;
        }
        struct trk_tracker_params t;
        tcfg_params_rt(c, rt, &t);
        /* the tests the settings did not touch stay the configuration's own */
        if (!confirm_set) t.confirm = p.confirm;
        if (!term_set) t.term = p.term;
        p = t;
        free(c);
    }
    /* joint association weighs events by 1 / lambda: without clutter it
     * assumes one clutter detection per scan in the region */
    const double lambda_floor = 1 / sc->area_m2;
    if (p.association == TRK_ASSOC_JOINT && lambda < lambda_floor)
        p.sensor[0].clutter_density_per_m2 = (trk_real)lambda_floor;
    const char *field = NULL;
    const trk_status st = trk_tracker_check_params(&p, &field);
    if (st != TRK_OK) {
        snprintf(err, n, "the tracker refuses configuration %s: %s: %s", cfg_name[kind], field ? field : "?",
                 ERRMSG_STATUS(st));
        tcfg_unload(rt);
        return -1;
    }
    *out = p;
    return 0;
}

