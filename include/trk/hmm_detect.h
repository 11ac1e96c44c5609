/** @file
 * trk/hmm_detect.h - predictive likelihood of a detection under the
 * two-state Markov (fluctuating SNR) detection model, per sensor
 * (Blanding et al. 2007 eqs 1-2 and 7-10; Willett II.C eqs 60-64;
 * docs/conventions.md "Track confirmation and termination", HMM f1 and "Complete
 * detection-event model").
 *
 * Each sensor i has a hidden detection state u in {0 low, 1 high} with
 * detection probabilities pd_low, pd_high and per-look transitions
 * p = P(low -> high), q = P(high -> low). A look is "detected" when the gate
 * holds at least one detection. For a look of sensor i:
 *   prior   P(u=1) = pi0_high at the sensor's first look, afterwards
 *           post (1-q) + (1-post) p                 (eq 10: ONE transition per
 *                                                     look of that sensor)
 *   f1      = P(u=1) e_H + (1-P(u=1)) e_L            (eq 8)
 *   post    = P(u=1) e_H / f1                        (eq 9)
 *   f0      = pfa if detected else 1-pfa             (eq 7)
 *   s       = ln f0 - ln f1                          (eq 5, the Page increment)
 * with e, per state (Pd = pd_low or pd_high, pfa the gate's P_FA, eq 4):
 *   TRK_EVENTS_COMPLETE (the default, docs/conventions.md "Complete detection-event
 *     model"): the gate of a present target may hold clutter too,
 *       hit   e = 1 - (1-Pd)(1-pfa),   miss   e = (1-Pd)(1-pfa),
 *     so ln f1 of a miss = ln(1-pfa) + ln(miss mixture), the posterior of a
 *     miss is the paper's, and a miss always gives s = -ln(miss mixture) > 0
 *     (evidence against the target, however large the gate);
 *   TRK_EVENTS_PAPER (eq 8 literally; the reference vectors, the papers'
 *     experiments): e = Pd if detected else 1-Pd (no P_G, no false-alarm
 *     term). Its misses give s = ln(1-pfa) - ln(miss mixture), which turns
 *     negative as a coasting track's gate grows (ln(1-pfa) = -lambda V): an
 *     empty gate then counts FOR the target and the track is never
 *     terminated. With pfa = 0 the two forms agree.
 * Fixed P_D is the special case pd_low = pd_high (then f1 = P_D or
 * 1 - P_D, paper form, whatever the state).
 *
 * Split in two (shared by the Page, Shiryaev and SPRT tests):
 *   struct trk_hmm_model  the validated parameters of every sensor (p, q,
 *                         pd_low, pd_high, resolved pi0_high) and the event
 *                         model; built once by trk_hmm_model_init and shared
 *                         by all tracks;
 *   struct trk_hmm_state  what one track carries: per sensor the posterior
 *                         P(u = 1) and the number of looks so far.
 * A state is only meaningful with the model it was reset with. */
#ifndef TRK_HMM_DETECT_H
#define TRK_HMM_DETECT_H

#include "trk/types.h"

/** pi0_high value meaning "the stationary probability p/(p+q)" (eq 2). */
#define TRK_HMM_PI0_STATIONARY TRK_REAL_C(-1.0)

/** One sensor's two-state detection model: the transitions and the detection probability of each state. */
struct trk_hmm_sensor_params {
    trk_real p_low_high;  /**< p = P(low -> high) per look of this sensor, [0, 1] */
    trk_real q_high_low;  /**< q = P(high -> low) per look, [0, 1] */
    trk_real pd_low;      /**< detection probability in the low state, (0, 1) */
    trk_real pd_high;     /**< detection probability in the high state, (0, 1) */
    trk_real pi0_high;    /**< P(u = 1) at the sensor's first look, [0, 1], or
                             TRK_HMM_PI0_STATIONARY (needs p + q > 0) */
};

/** What a "detected" look means under H1 (the type of trk_hmm_params.events;
 * see the top of this file). Zero, the default, is the complete model. */
enum trk_event_model {
    TRK_EVENTS_COMPLETE = 0, /**< target or clutter in the gate (docs/conventions.md) */
    TRK_EVENTS_PAPER = 1     /**< Blanding eq 8 as printed: target only */
};

/** Parameters of the detection HMM: one model per sensor and the event model. */
struct trk_hmm_params {
    unsigned n_sensors;   /**< 1 .. TRK_MAX_SENSORS */
    struct trk_hmm_sensor_params sensor[TRK_MAX_SENSORS];  /**< sensor[0 .. n_sensors - 1] */
    enum trk_event_model events; /**< TRK_EVENTS_COMPLETE (0) or TRK_EVENTS_PAPER */
};

/** Fill params with n_sensors identical sensors and events =
 * TRK_EVENTS_COMPLETE (the default; set events afterwards for the paper's
 * form). n_sensors is not checked here; trk_hmm_model_init checks it. */
void trk_hmm_params_uniform(struct trk_hmm_params *params, unsigned n_sensors,
                            const struct trk_hmm_sensor_params *each);

/** Shared, read-only after init. */
struct trk_hmm_model {
    unsigned n_sensors;  /**< sensors (from the parameters) */
    enum trk_event_model events;  /**< event model (from the parameters) */
    struct {
        /** @{ */
        trk_real p, q;             /**< transitions per look */
        /** @} */
        /** @{ */
        trk_real pd_low, pd_high;  /**< detection probabilities */
        /** @} */
        trk_real pi0_high;         /**< resolved prior at the first look (eq 2) */
    } s[TRK_MAX_SENSORS];  /**< per sensor, from the parameters */
};

/** Per track. */
struct trk_hmm_state {
    trk_real post_high[TRK_MAX_SENSORS]; /**< P(u = 1 | this sensor's looks so far) */
    uint32_t n_looks[TRK_MAX_SENSORS];   /**< looks of this sensor so far (saturates) */
};

/** Validate params and build the model. TRK_E_ARG NULL or an unknown
 * events value, TRK_E_CAPACITY
 * n_sensors > TRK_MAX_SENSORS, TRK_E_RANGE n_sensors = 0 or a probability
 * outside its range (also stationary prior with p = q = 0), TRK_E_NAN a
 * non-finite parameter. *m untouched on error. */
TRK_NODISCARD trk_status trk_hmm_model_init(struct trk_hmm_model *m,
                                            const struct trk_hmm_params *params);

/** "No look yet" on every sensor: the start state of a new track. Does
 * nothing when m or st is NULL. */
void trk_hmm_state_reset(const struct trk_hmm_model *m, struct trk_hmm_state *st);

/** P(u = 1) that sensor's next look will use (eq 10 prior); NaN for a bad
 * sensor or a NULL pointer. Pure. */
trk_real trk_hmm_prior_high(const struct trk_hmm_model *m, const struct trk_hmm_state *st,
                            unsigned sensor);

/** One look of `sensor` (detected != 0: a detection in the gate; pfa the
 * gate's false-alarm probability, eq 4): writes ln f1 (eq 8, e of the
 * model's event model) and advances that sensor's posterior (eq 9). Other
 * sensors are unchanged. ln f1 is computed without cancellation (log1p of
 * the complement when f1 > 1/2; a miss's ln(1-pfa) as log1p(-pfa)).
 * TRK_EVENTS_PAPER ignores pfa (any value, NaN included). TRK_E_ARG NULL,
 * TRK_E_SENSOR sensor >= n_sensors, TRK_E_NAN / TRK_E_RANGE (complete model
 * only) pfa not finite / not in [0, 1); state and *log_f1 untouched on
 * error. */
TRK_NODISCARD trk_status trk_hmm_update(const struct trk_hmm_model *m, struct trk_hmm_state *st,
                                        unsigned sensor, int detected, trk_real pfa,
                                        trk_real *log_f1);

/** ln f0 of eq 7 (both event models): ln pfa if detected, else ln(1 - pfa)
 * (as log1p(-pfa)).
 * TRK_E_ARG NULL, TRK_E_NAN pfa not finite, TRK_E_RANGE pfa outside (0, 1). */
TRK_NODISCARD trk_status trk_hmm_log_f0(int detected, trk_real pfa, trk_real *log_f0);

/** P_FA of a gate of volume V in clutter of density lambda (Blanding eq 4):
 * 1 - exp(-lambda V) computed as -expm1(-lambda V). */
static inline trk_real trk_hmm_gate_pfa(trk_real lambda_v) { return -trk_expm1(-lambda_v); }

#endif
