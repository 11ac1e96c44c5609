/* tracker_config.h - the tracker's configuration for the tools: defaults,
 * "key = value" settings (config file, see kvfile.h, or command line), a
 * check that explains what is wrong, and a printer whose output is a valid
 * config file. Shared by trk-lcm-bridge and trk-sim.
 *
 * Keys (tcfg_help prints them with defaults and ranges):
 *   sensors, process_noise_q, gate_prob, clutter, init_speed_sigma_mps,
 *   max_dt_s, max_tentative_scans, merge_gate_d2, init_exclusion_d2,
 *   init.{method,max_speed_mps,max_gap_scans,birth_density_per_m2,min_existence},
 *   max_pos_sigma_ratio,
 *   visibility (0|1), visibility.{pv0,pcv0,delta_stay,delta_become,omega_c,p_con,p_term},
 *   confirm = existence | mn | sprt | clutter_density | clutter_amplitude | visibility,
 *     confirm.existence.{p_confirm,reject_odds_ratio,count_alpha},
 *     confirm.mn.{m,n,mode}, confirm.sprt.{alpha,beta,model,pd},
 *     confirm.clutter_density.{alpha,kmax},
 *     confirm.clutter_amplitude.{alpha,kmax,a_min_db}
 *   term = existence | kn | page | shiryaev | visibility, term.existence.p_terminate,
 *     term.kn.{k,n}, term.page.h, term.shiryaev.{beta0,rho,h}
 *   hmm.{p_low_high,q_high_low,pd_low,pd_high,pi0_high}  (fluctuating-SNR
 *     detection model of SPRT-hmm / Page / Shiryaev, same for every sensor)
 *   hmm.events = complete | paper  (event model of SPRT (fixed_pd and hmm),
 *     Page, Shiryaev; trk/hmm_detect.h)
 *   q2_table
 *   imm.{turn_rate_dps,p_stay,turn_q}  (TRK_WITH_IMM builds only: IMM tracks on
 *     CV and coordinated turns at +-turn_rate_dps, trk_tracker_imm_params;
 *     turn_rate_dps = 0, the default, is the CV-only tracker; a build without
 *     IMM tracks refuses the keys)
 *   sensor.N.{pd,meas_cov_m2,meas_sigma_m,clutter_density_per_m2,
 *             amplitude,k_shape,snr_db,pfa,amp_table,
 *             kind,sigma_range_m,sigma_bearing_rad,conversion,
 *             pose.{x_m,y_m,heading_rad},pd_profile,
 *             coverage.{min_range_m,max_range_m,half_width_rad}}   N = 0 .. sensors-1
 *
 * Every method's parameters are kept (switching `confirm = ...` back and
 * forth loses nothing); tcfg_params() assembles the tracker's parameters
 * for the chosen methods (the one place to extend when the tracker gains
 * one). tcfg_check() refuses, with a message naming the setting, anything
 * the tracker refuses (trk_tracker_check_params, which names the field) and
 * a bad table. Amplitude tables are read by
 * tcfg_load() into a struct tcfg_runtime that must outlive the tracker
 * (its amplitude models point into the table bytes); tcfg_params_rt() then
 * gives the tracker parameters with the sensors' amplitude models. */
#ifndef TRK_TOOLS_TRACKER_CONFIG_H
#define TRK_TOOLS_TRACKER_CONFIG_H

#include <stddef.h>
#include <stdio.h>

#include "trk/clutter_test.h"
#include "trk/confirm_sprt.h"
#include "trk/hmm_detect.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"
#include "trk/tracker.h"

#define TCFG_PATH_MAX 512


enum tcfg_amp_model { TCFG_AMP_NONE = 0, TCFG_AMP_RAYLEIGH, TCFG_AMP_K };

/* Per-sensor amplitude model of amplitude-aided association (PDAFAI):
 * thresholded Rayleigh or K-distributed clutter, Swerling I target. */
struct tcfg_amp {
    int model;                    /* enum tcfg_amp_model */
    double k_shape;               /* K shape nu > 0 (model k) */
    double snr_db;                /* expected target SNR (dB) */
    double pfa;                   /* detection threshold's P_FA, (0, 1) */
    char table[TCFG_PATH_MAX];    /* amplitude table file ("" = closed form / none) */
};

struct tcfg {
    /* the tracker parameters except confirm and term (see tcfg_params) */
    struct trk_tracker_params params;
    /* chosen methods and every method's parameters */
    enum trk_confirm_method confirm;
    enum trk_term_method term;
    struct trk_mn_params mn;
    struct trk_sprt_params sprt;                  /* .hmm from hmm below */
    struct trk_clutter_chi2_params clutter_density;
    struct trk_clutter_amp_params clutter_amplitude;
    struct trk_kn_params kn;
    struct trk_existence_confirm_params existence_confirm;
    struct trk_existence_term_params existence_term;
    struct trk_page_params page;                  /* .hmm from hmm below */
    struct trk_shiryaev_params shiryaev;          /* .hmm from hmm below */
    struct trk_hmm_sensor_params hmm;             /* same for every sensor */
    enum trk_event_model hmm_events;              /* hmm.events of sprt/page/shiryaev */
    /* amplitude and q2 */
    struct tcfg_amp amp[TRK_MAX_SENSORS];
    char q2_table[TCFG_PATH_MAX];
#if TRK_WITH_IMM
    /* IMM tracks: tcfg_params assembles params.imm from these (whatever
     * params.imm held) */
    double imm_turn_rate_dps;                     /* turn models at +-this; 0 = none, CV only (0) */
    double imm_p_stay;                            /* per-scan probability of keeping the model (0.95) */
    double imm_turn_q;                            /* the turn models' q; 0 = process_noise_q (0);
                                                     the CV model's is process_noise_q */
#endif
};

#if TRK_WITH_IMM
/* p->imm from the imm.* keys' meaning: CV (p->process_noise_q) and turns at
 * +-turn_rate_dps (trk_tracker_imm_params, p_stay), the turns' q turn_q
 * (0: p->process_noise_q). The one mapping, shared by tcfg_params and
 * trk-sim mtt's imm configuration. Statuses of trk_tracker_imm_params. */
trk_status tcfg_imm_models(struct trk_tracker_params *p, double turn_rate_dps, double p_stay, double turn_q);
#endif

/* Defaults: trk_tracker_default_params() for the tracker, every sensor like
 * sensor 0, and the documented defaults of the other methods. */
void tcfg_defaults(struct tcfg *c);

/* Set one key (a kv_setter, ctx = struct tcfg *): 0 ok, 1 unknown key
 * (the nearest known key in err, or ""), -1 bad value (message in err). */
int tcfg_set(void *ctx, const char *key, const char *value, char *err, size_t errlen);
/* The keys tcfg_set knows, NULL-terminated: the general ones (imm.* in every
 * build; a build without IMM tracks refuses their values), and a sensor's,
 * after "sensor.N.". */
const char *const *tcfg_keys(void);
const char *const *tcfg_sensor_keys(void);

/* Whole-configuration check, in this order: the tracker accepts the
 * parameters with the chosen methods (trk_tracker_check_params: the message
 * gives the key of the field it names); every table file parses as a table
 * of the right kind for this build (trk_table_parse; amplitude tables also
 * trk_amplitude_init_table), a Rayleigh model's snr_db/pfa are valid
 * (trk_amplitude_init_rayleigh), K has a table, the tracker accepts the
 * sensors' amplitude models; nothing is configured that this libtrk's
 * tracker cannot run. 0, or -1 with a message. */
int tcfg_check(const struct tcfg *c, char *err, size_t errlen);

/* The tracker parameters (what trk_tracker_init gets): params with the
 * chosen confirmation and termination methods and their parameters (the
 * HMM of sprt/page/shiryaev for params.n_sensors identical sensors). */
void tcfg_params(const struct tcfg *c, struct trk_tracker_params *out);

/* What a run needs besides the parameters: the sensors' amplitude models
 * (Rayleigh closed form, or a table read from its file and kept here). */
struct tcfg_runtime {
    void *amp_bytes[TRK_MAX_SENSORS];           /* table bytes (malloc), or NULL */
    struct trk_amplitude amp[TRK_MAX_SENSORS];
    int use_amp[TRK_MAX_SENSORS];
};

/* Load the tables and build the amplitude models of c: 0, or -1 with a
 * message (rt then holds nothing). Free with tcfg_unload. */
int tcfg_load(const struct tcfg *c, struct tcfg_runtime *rt, char *err, size_t errlen);
void tcfg_unload(struct tcfg_runtime *rt);

/* tcfg_params plus the sensors' amplitude models of rt (rt may be NULL:
 * positions only). */
void tcfg_params_rt(const struct tcfg *c, const struct tcfg_runtime *rt, struct trk_tracker_params *out);

/* Write every key with its current value, in config-file syntax. */
void tcfg_write(FILE *f, const struct tcfg *c);

/* Key reference for --help: one line per key with range and default. */
void tcfg_help(FILE *f);

#endif
