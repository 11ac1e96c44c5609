/* trk/hmm_detect.h - predictive likelihood of a detection under the
 * two-state Markov (fluctuating SNR) detection model, per sensor
 * (Blanding et al. 2007 eqs 1-2 and 7-10; Willett II.C eqs 60-64;
 * CONVENTIONS "Track confirmation and termination", HMM f1).
 *
 * Each sensor i has a hidden detection state u in {0 low, 1 high} with
 * detection probabilities pd_low, pd_high and per-look transitions
 * p = P(low -> high), q = P(high -> low). For a look of sensor i:
 *   prior   P(u=1) = pi0_high at the sensor's first look, afterwards
 *           post (1-q) + (1-post) p                 (eq 10: ONE transition per
 *                                                     look of that sensor)
 *   f1      = P(u=1) e_H + (1-P(u=1)) e_L,  e = pd if detected else 1-pd  (eq 8)
 *   post    = P(u=1) e_H / f1                        (eq 9)
 *   f0      = pfa if detected else 1-pfa             (eq 7)
 *   s       = ln f0 - ln f1                          (eq 5, the Page increment)
 * f1 is the paper's literal target-present likelihood (no P_G, no false-alarm
 * term). Fixed P_D is the special case pd_low = pd_high (then f1 = P_D or
 * 1 - P_D whatever the state).
 *
 * Split in two (shared by the Page, Shiryaev and SPRT tests):
 *   struct trk_hmm_model  the validated parameters of every sensor (p, q,
 *                         pd_low, pd_high, resolved pi0_high); built once by
 *                         trk_hmm_model_init and shared by all tracks;
 *   struct trk_hmm_state  what one track carries: per sensor the posterior
 *                         P(u = 1) and the number of looks so far.
 * A state is only meaningful with the model it was reset with. */
#ifndef TRK_HMM_DETECT_H
#define TRK_HMM_DETECT_H

#include "trk/types.h"

/* pi0_high value meaning "the stationary probability p/(p+q)" (eq 2). */
#define TRK_HMM_PI0_STATIONARY TRK_REAL_C(-1.0)

struct trk_hmm_sensor_params {
    trk_real p_low_high;  /* p = P(low -> high) per look of this sensor, [0, 1] */
    trk_real q_high_low;  /* q = P(high -> low) per look, [0, 1] */
    trk_real pd_low;      /* detection probability in the low state, (0, 1) */
    trk_real pd_high;     /* detection probability in the high state, (0, 1) */
    trk_real pi0_high;    /* P(u = 1) at the sensor's first look, [0, 1], or
                             TRK_HMM_PI0_STATIONARY (needs p + q > 0) */
};

struct trk_hmm_params {
    unsigned n_sensors;   /* 1 .. TRK_MAX_SENSORS */
    struct trk_hmm_sensor_params sensor[TRK_MAX_SENSORS];
};

/* Fill params with n_sensors identical sensors (n_sensors is not checked here;
 * trk_hmm_model_init checks it). */
void trk_hmm_params_uniform(struct trk_hmm_params *params, unsigned n_sensors,
                            const struct trk_hmm_sensor_params *each);

/* Shared, read-only after init. */
struct trk_hmm_model {
    unsigned n_sensors;
    struct {
        trk_real p, q;             /* transitions per look */
        trk_real pd_low, pd_high;  /* detection probabilities */
        trk_real pi0_high;         /* resolved prior at the first look (eq 2) */
    } s[TRK_MAX_SENSORS];
};

/* Per track. */
struct trk_hmm_state {
    trk_real post_high[TRK_MAX_SENSORS]; /* P(u = 1 | this sensor's looks so far) */
    uint32_t n_looks[TRK_MAX_SENSORS];   /* looks of this sensor so far (saturates) */
};

/* Validate params and build the model. TRK_E_ARG NULL, TRK_E_CAPACITY
 * n_sensors > TRK_MAX_SENSORS, TRK_E_RANGE n_sensors = 0 or a probability
 * outside its range (also stationary prior with p = q = 0), TRK_E_NAN a
 * non-finite parameter. *m untouched on error. */
TRK_NODISCARD trk_status trk_hmm_model_init(struct trk_hmm_model *m,
                                            const struct trk_hmm_params *params);

/* "No look yet" on every sensor: the start state of a new track. Does
 * nothing when m or st is NULL. */
void trk_hmm_state_reset(const struct trk_hmm_model *m, struct trk_hmm_state *st);

/* P(u = 1) that sensor's next look will use (eq 10 prior); NaN for a bad
 * sensor or a NULL pointer. Pure. */
trk_real trk_hmm_prior_high(const struct trk_hmm_model *m, const struct trk_hmm_state *st,
                            unsigned sensor);

/* One look of `sensor` (detected != 0: a detection in the gate): writes
 * ln f1 (eq 8) and advances that sensor's posterior (eq 9). Other sensors are
 * unchanged. TRK_E_ARG NULL, TRK_E_SENSOR sensor >= n_sensors (state
 * untouched). */
TRK_NODISCARD trk_status trk_hmm_update(const struct trk_hmm_model *m, struct trk_hmm_state *st,
                                        unsigned sensor, int detected, trk_real *log_f1);

/* ln f0 of eq 7: ln pfa if detected, else ln(1 - pfa) (as log1p(-pfa)).
 * TRK_E_ARG NULL, TRK_E_NAN pfa not finite, TRK_E_RANGE pfa outside (0, 1). */
TRK_NODISCARD trk_status trk_hmm_log_f0(int detected, trk_real pfa, trk_real *log_f0);

/* P_FA of a gate of volume V in clutter of density lambda (Blanding eq 4):
 * 1 - exp(-lambda V) computed as -expm1(-lambda V). */
static inline trk_real trk_hmm_gate_pfa(trk_real lambda_v) { return -trk_expm1(-lambda_v); }

#endif
