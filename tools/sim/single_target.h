/* single_target.h - one target, one track: the Monte Carlo runs behind the
 * single-target experiments of trk-sim (Brekke track loss and TOC, Willett's
 * PDAF against the CRLB, Kennedy's clutter tests under H0), shared with the
 * tests. One call simulates one run; the experiments run many in parallel
 * and reduce the results in run order (thread-count independent).
 *
 * The track runs on the library's one-track functions, the same code the
 * tracker (trk_tracker_process_scan) runs per track: trk_cv2_predict,
 * trk_kalman_innovation + trk_gate_d2 (gating), trk_pda_update_inn (the
 * library's one PDA over the gated set, with that innovation: PDAF, or
 * PDAFAI with ln l^a from trk_amplitude_log_lr), trk_gate_volume_inn (the
 * gate volume: the clutter tests' rho V_g), amplitudes drawn by
 * trk_amplitude_inv_sf (Brekke eqs 41-47) on the amplitude model (a table
 * for K clutter), the clutter tests trk_clutter_chi2_step /
 * trk_clutter_amp_step. Nothing of the PDA is re-implemented here. The
 * papers' single-target settings have no track management (the track is
 * given at the start and never terminated), so the track table is not used:
 * it would start tentative tracks on clutter and end tracks by its own tests.
 *
 * PDA run (st_run): 2-D constant velocity (docs/conventions.md "State and
 * covariance layout"), R = r I.
 *   truth: x_0 = [0, speed, 0, 0], x_k = F x_{k-1} + w_k, w ~ N(0, Q(T, q))
 *   initial estimate x^_0 = x_0 + e, e ~ N(0, P_0) (a consistent start):
 *     twopoint  P_0 per axis [[r, r/T], [r/T, 2 r/T^2]] (two-point
 *               differencing; the MRE's and CRLB's default start)
 *     steady    P_0 = the steady state of the clutter-free Kalman filter with
 *               P_D = 1 (a track that has been held for long)
 *   scan k = 1..n_scans: the target is detected with P_D (the amplitude
 *   model's S1(t), else pd), at H x_k + N(0, R), with an amplitude from the
 *   truncated target law; clutter is the Poisson field of scenario.h with
 *   density lambda, taken in the bounding box of the track's gate ellipse
 *   (d2 <= gamma) around its prediction: exact, since clutter outside the
 *   gate gets weight 0 (docs/conventions.md "PDA"). Detections in the gate (d2 <=
 *   gamma by trk_gate_d2) go to trk_pda_update_inn with parametric lambda, P_D
 *   and P_G = 1 - exp(-gamma/2).
 *   K texture (the clutter's local power eta ~ Gamma(nu, 1/nu) x P):
 *     cell  drawn independently for every detection: i.i.d. amplitudes with
 *           the K marginal law, P_D = S1(t) fixed, lambda fixed (the model
 *           the PDAFAI assumes)
 *     scan  drawn once per scan for the whole scene (spatially correlated
 *           clutter power): given eta the clutter is Rayleigh of power eta,
 *           so that scan's false-alarm probability is exp(-t^2/eta) (its
 *           clutter density lambda exp(-t^2/eta)/P_FA: bursts of clutter),
 *           the target's P_D exp(-t^2/(eta + d)), and the amplitudes
 *           Rayleigh of power eta (clutter) or eta + d (target), drawn by the
 *           library's Rayleigh inverse survival; over the scans the
 *           marginals are the K model's. The filters still use the K model
 *           (lambda, P_D = S1(t), l^a).
 *   Random streams (common random numbers): the truth, the target's
 *   detections and amplitudes come from philox stream (seed, run << 32 | k),
 *   the clutter from the field keyed by (seed, run, k): a PDAF run and a
 *   PDAFAI run of the same (seed, run) see the same target, detections and
 *   clutter; each filter looks at the clutter around its own prediction.
 *   Track loss:
 *     brekke   (Brekke V.B) error = |position error|; above c1 the track is
 *              tentatively lost, the label is removed when the error comes
 *              back to <= c1; lost if the error exceeds c2 (the run stops
 *              there), or is above c1 at the last scan (lost at the start of
 *              that last excursion)
 *     willett  (Willett I.D, footnote 5, a 1-D criterion applied to each
 *              coordinate) lost when |x error| or |y error| exceeds
 *              thresh_m for count scans in a row (the run stops)
 *   A gate holding more than TRK_MAX_DETECTIONS detections (a track far gone
 *   in dense clutter; or n, p.gate_cap) passes its nearest (smallest d2),
 *   counted per run (truncated), or, with the gate cap's lost rule, the track
 *   is lost once lambda V_G exceeds the cap (struct st_gate_cap); they are found without drawing the whole
 *   gate (a first pass over an ellipse expected to hold twice the capacity,
 *   the whole gate only when that holds fewer: the same result). A library refusal (covariance not SPD) or a
 *   gate window over more than SCEN_FIELD_MAX_TILES clutter tiles ends the
 *   run as lost and is counted apart (failed).
 *
 * Kennedy null run (kn_run): Kennedy 2008 sec. 3 and 4 (Figs. 2-3), target
 * absent. A surveillance rectangle holds exactly n_peaks clutter peaks per
 * scan, uniform, each with an SNR a_min + (theta - a_min) Exp(1) dB (eq 11).
 * Scan 1 starts a tentative track on a random peak (velocity 0 with variance
 * init_speed^2 per axis, position variance R); scans 2..n: Kennedy's CV
 * prediction (trk_kalman_predict with Q = diag((s'T^2/2)^2, (s'T)^2) per
 * axis), the nearest peak (smallest d2 under S) feeds the clutter tests
 * (rho V_g = rho pi d2 sqrt|S| by trk_gate_volume_inn, rho = n_peaks /
 * area; its dB amplitude against the scan's other peaks), and the PDA update
 * (trk_pda_update_inn) uses the peaks in the gate. The tests run their recursion every scan; the decision is read at
 * the last scan only (Kennedy: "track confirmation was only applied on the
 * last scan of the run"). Random stream (seed, tag << 32 | run). With torus
 * the region wraps around, which removes Kennedy's edge effects (a track
 * near an edge has no peaks beyond it, its nearest peak is farther than the
 * density says and the density test confirms less than alpha).
 */
#ifndef TRK_TOOLS_SINGLE_TARGET_H
#define TRK_TOOLS_SINGLE_TARGET_H

#include <stddef.h>
#include <stdint.h>

#include "scenario.h"
#include "trk/amplitude.h"
#include "trk/clutter_test.h"
#include "trk/pda.h"

/* ---------------------------------------------------------------- amplitude model */

/* A Swerling I target of snr_db in Rayleigh (closed form) or K clutter of
 * shape nu (an amplitude table made in memory, tools/gen/amp_table.c),
 * clutter power 1, threshold at pfa. grid: TRK_AMP_GRID_UNIFORM (default,
 * 0) or TRK_AMP_GRID_GEOMETRIC (Brekke eqs 43-45); size: points per
 * inverse-survival curve (0: the generator's default). */
struct st_amp {
    struct trk_amplitude m;   /* the library model */
    unsigned char *table;     /* K: the table bytes (malloc); NULL for Rayleigh */
    int model;                /* enum trk_amp_model */
    double nu, snr_db, pfa, pd, threshold;
};
int st_amp_init(struct st_amp *a, int model, double nu, double snr_db, double pfa, int grid,
                unsigned size, char *err, size_t errlen);
void st_amp_free(struct st_amp *a);

/* ---------------------------------------------------------------- PDA runs */

enum st_init { ST_INIT_TWOPOINT = 0, ST_INIT_STEADY = 1 };
enum st_texture { ST_TEXTURE_CELL = 0, ST_TEXTURE_SCAN = 1 };
enum st_loss { ST_LOSS_BREKKE = 0, ST_LOSS_WILLETT = 1 };

/* The runaway-gate rule (a track far gone in dense clutter): a gate holding
 * more than n detections passes its n nearest (smallest d2; truncate, n in
 * 1..TRK_MAX_DETECTIONS, 0: TRK_MAX_DETECTIONS, the default), or the track is
 * declared lost at the first scan whose predicted gate expects more than
 * lambda_vg clutter detections, lambda V_G > lambda_vg with the filter's
 * lambda and V_G of the prediction (lost; a gate that still holds more than
 * TRK_MAX_DETECTIONS passes its nearest, as the library takes no more). */
/* count: the track is lost at the first scan whose gate holds n or more
 * detections (target and clutter; the lost state of HYCA's chain over the
 * gated count, trk/hyca.h), n in 1..TRK_MAX_DETECTIONS. */
enum st_gate_cap_mode { ST_GATE_TRUNCATE = 0, ST_GATE_LOST = 1, ST_GATE_COUNT = 2 };
struct st_gate_cap {
    int mode;                 /* enum st_gate_cap_mode */
    long n;                   /* truncate: detections passed; count: the lost count */
    double lambda_vg;         /* lost: the cap on lambda V_G, > 0 */
};

struct st_params {
    double dt_s;              /* T > 0 */
    double q_m2_per_s3;       /* process noise PSD (truth and filter) >= 0 */
    double r_m2;              /* R = r I, > 0 */
    double gate_gamma;        /* gate threshold on d2, > 0 (Brekke g^2) */
    double lambda_per_m2;     /* clutter density (truth and filter), >= 0 */
    double pd;                /* P_D without amplitude model, (0, 1] */
    const struct trk_amplitude *amp; /* amplitude model or NULL; with one, P_D = its S1(t) */
    long n_scans;             /* 1 .. 2^31 */
    int init;                 /* enum st_init */
    double speed_mps;         /* truth's initial speed (along x); irrelevant to the
                                 error statistics with a consistent start */
    int loss;                 /* enum st_loss */
    double c1_m, c2_m;        /* brekke thresholds, 0 < c1 <= c2 */
    double thresh_m;          /* willett threshold > 0 */
    int count;                /* willett scans in a row >= 1 */
    double tile_m;            /* clutter field tile (0: auto) */
    int texture;              /* enum st_texture (K amplitude model only) */
    struct st_gate_cap gate_cap; /* runaway-gate rule (zero: truncate to TRK_MAX_DETECTIONS) */
    uint64_t seed;
};

/* Brekke's Table I (T = 1 s, 300 scans, q = 0.0125^2, r = 1/12, g = 6,
 * c1 = 5 m, c2 = 15 m), twopoint start, speed 1 m/s, no clutter, pd 1. */
void st_params_brekke(struct st_params *p);

struct st_model {
    struct st_params p;
    struct trk_pda pda;       /* the filter's PDA (P_D, P_G, lambda) */
    double pd;                /* the target's detection probability */
    double gate_prob;         /* P_G of gate_gamma (as trk_real sees it) */
    double gamma_used;        /* the gate threshold trk_pda_update applies */
    trk_real r[4];            /* R */
    double p0[16];            /* initial covariance */
    double p0_chol[3];        /* per-axis Cholesky factor of its 2x2 block */
    double q_chol[3];         /* per-axis Cholesky factor of the Q block */
    struct scen_field field;
};

/* 0, or -1 with a message (bad parameter; the library refused the PDA). In a
 * float build a gate whose P_G rounds to 1 is narrowed to the largest float
 * P_G below 1 (gamma_used < gate_gamma; reported by the experiments). */
int st_model_init(struct st_model *m, const struct st_params *p, char *err, size_t errlen);

/* Per-thread workspace (heap, grows as needed); start it zeroed. */
struct st_cand {
    double d2, x_m, y_m, x_amp;
    int target;
};
struct st_ws {
    struct scen_field_point *pts;
    size_t cap;
    struct st_cand *cand;
    size_t cand_cap;
};
void st_ws_free(struct st_ws *ws);

struct st_result {
    int lost;                 /* by the loss rule (failed runs count as lost) */
    int lost_hard;            /* brekke: the error exceeded c2 */
    long lost_scan;           /* scan where the loss happened (0: not lost) */
    int failed;               /* the library refused a step (trk_status in status) */
    int status;
    long scans;               /* scans simulated */
    double sse;               /* sum of squared position errors over scans >= from_scan */
    long n_sse;               /* scans in sse */
    double max_err_m;
    long detections;          /* target detections */
    long gated;               /* gated detections over the run (target + clutter) */
    long gated_clutter;       /* of which clutter */
    long truncated;           /* scans with more than the gate cap's n (truncate; lost:
                                 TRK_MAX_DETECTIONS) in the gate: the nearest
                                 (smallest d2) were used */
    int gate_lost;            /* lost by the gate cap (lost: lambda V_G above the cap) */
};

/* One run (run index < 2^32) with the PDAF (ai = 0) or the PDAFAI (ai = 1,
 * needs p.amp). err_by_scan (NULL or n_scans values) receives the position
 * error of each simulated scan (NAN after a stop). from_scan: first scan of
 * sse. Returns 0 (the run's outcome in *res), -1 for a bad call. */
int st_run(const struct st_model *m, struct st_ws *ws, uint32_t run, int ai, long from_scan,
           double *err_by_scan, struct st_result *res);

/* ---------------------------------------------------------------- Kennedy null */

struct kn_params {
    double x_min_m, x_max_m, y_min_m, y_max_m;  /* surveillance region */
    long n_peaks;             /* clutter peaks per scan, 2 .. TRK_MAX_DETECTIONS */
    double dt_s;
    double sigma_x_m, sigma_y_m;        /* measurement noise, R = diag */
    double accel_x, accel_y;            /* Kennedy's sigma'_x, sigma'_y (m/s^2) */
    double init_vx_sigma, init_vy_sigma;/* initial velocity std (m/s) */
    double gate_prob;                   /* PDA gate */
    double a_min_db, theta_db;          /* clutter SNR: a_min + (theta - a_min) Exp(1) */
    double alpha;                       /* size of both tests */
    unsigned kmax;
    int torus;                          /* 1: the region wraps around (no edges: each peak
                                           is taken at its copy nearest the prediction) */
    uint64_t seed;
};

/* Kennedy's setting: 10-20 km x 100-200 km, 100 peaks, T = 1 s, b = 1/50
 * (sigma 200 m, 2 km), b' = 1/1000 (10, 100 m/s^2), initial velocity std
 * (80, 1150) m/s (the mean of the slow and fast targets' velocities), P_G
 * 0.99, a_min 5 dB, theta 10 dB, alpha 0.01, kmax 25. */
void kn_params_kennedy(struct kn_params *p);

struct kn_model {
    struct kn_params p;
    struct trk_pda pda;
    struct trk_clutter_chi2_model chi2;
    struct trk_clutter_amp_model amp;
    double rho;                         /* n_peaks / area */
    trk_real f[16], q[16], r[4];
};

int kn_model_init(struct kn_model *m, const struct kn_params *p, char *err, size_t errlen);

struct kn_result {
    int chi2_reject;          /* density test rejects H0 at the last scan */
    int amp_reject;           /* amplitude test rejects H0 at the last scan */
    int chi2_ever;            /* sticky decision by the last scan (per-scan confirmation) */
    int amp_ever;
    double chi2_p, amp_p;     /* p-values at the last scan */
    int outside;              /* the prediction left the region at some scan */
    int failed;               /* the library refused a step */
    int status;
};

/* One run of n_scans scans (>= 2; the test window is n_scans - 1 updates),
 * stream (tag, run). 0, or -1 for a bad call. */
int kn_run(const struct kn_model *m, long n_scans, uint32_t tag, uint32_t run, struct kn_result *res);

#endif
