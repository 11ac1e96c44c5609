/* toc_curve.h - tracking operating characteristic (TOC) for the tools: the
 * steady-state position RMSE of the modified Riccati equation (MRE) along a
 * detector's ROC, for the PDAF and the PDAFAI, and the false-alarm
 * probability that minimises it (Brekke Sec. V-C, Fig. 2; docs/conventions.md
 * "q2, MRE and CRLB"). Used by `trk-sim toc`, `trk-sim brekke-toc` and
 * `make demo`.
 *
 * Model. A Swerling I target of snr_db in Rayleigh or K (shape nu) clutter
 * (docs/conventions.md "Amplitude models"); at false-alarm probability pfa the
 * detection probability is the ROC value pd = S1(t), S0(t) = pfa, and the
 * clutter density is lambda = pfa / cell_m2 per m^2 (one false alarm per
 * resolution cell with probability pfa). The MRE (trk/mre.h, Brekke eq 27)
 * runs with q2 looked up each step at lambda_vg = lambda V_G:
 *   PDAF    q2(pd, lambda_vg) from a q2 table of kind TRK_TABLE_KIND_Q2_PDAF
 *           (nz 2, the scenario's gate), pd = ROC(pfa)
 *   PDAFAI  q2(snr_db, pfa, lambda_vg) from a table of kind
 *           TRK_TABLE_KIND_Q2_PDAFAI for the scenario's (model, nu)
 * The library does the lookups (trk_q2_lookup_init_table, trk/q2.h), the MRE
 * and the optimum (trk_toc_rmse, trk_toc_optimise, trk/mre.h). A pfa whose
 * MRE has no steady state (track lost: TRK_E_DIVERGED) or whose lambda_vg
 * leaves the q2 table has rmse_m = +inf (status TOC_DIVERGED / TOC_OFF_TABLE).
 * The MRE starts from the two-point-differencing covariance of a new track
 * (trk_mre_initial_cov; the default), from P = 0 or from the clutter-free
 * Kalman steady state (the MRE with q2 = 1): toc_scenario.mre_start. When an iteration leaves the table it is repeated
 * with q2 above the table's lambda_vg held at the table's top value (an
 * upper bound: q2 falls with lambda_vg): still diverging means the track is
 * lost (TOC_DIVERGED); otherwise TOC_OFF_TABLE (not computable from the
 * table; rmse_bound_m is a lower bound of the RMSE).
 *
 * Brekke's Table I model (toc_scenario_brekke): nz = 2, T = 1 s,
 * q~ = 0.0125^2 m^2/s^3, R = I/12 m^2, gate g = 6 (gamma = 36). The
 * resolution cell is not printed in the paper: 1 m^2 is consistent with
 * R = I/12 (a uniform 1 m cell); docs/conventions.md asks for results at 1, 0.25
 * and 0.1 m^2 -- state the area with every result.
 *
 * q2 source. Either q2 tables made by `trk-tablegen q2` (loaded by the
 * caller, e.g. with trk_table_load_file, and outliving the struct toc), or
 * NULL: the q2 grid is then computed at toc_new by the importance sampler
 * (tools/gen/q2_table.h; OpenMP when the program links the OpenMP object
 * of mk/q2.mk) for exactly this scenario, on the default tables' node
 * densities: PDAF over (pd, lambda_vg) with pd covering the ROC over
 * [pfa_min, pfa_max], PDAFAI over (pfa, lambda_vg) at snr_db (about 1-3 s
 * each on 2 cores). Results are bit-identical for any thread count.
 *
 *   struct toc_scenario sc;
 *   toc_scenario_brekke(&sc, TRK_AMP_K, 1.0, 15.0, 1.0);
 *   struct toc_q2_source src = {0};           (sample; defaults)
 *   struct toc *t = toc_new(&sc, &src, err, sizeof err);
 *   struct toc_point p;  toc_point_at(t, 1e-3, &p);   (both detectors)
 *   struct toc_optimum o; toc_optimum(t, TOC_PDAFAI, &o);
 *   toc_free(t);
 *
 * All functions return 0 on success, or -1 with a message in err (bad
 * scenario, a table of the wrong kind, nz, gate, model, nu or not covering
 * snr_db / the ROC, sampler failure, out of memory). A pfa without a steady
 * state is not an error (rmse_m = +inf).
 */
#ifndef TRK_TOOLS_TOC_CURVE_H
#define TRK_TOOLS_TOC_CURVE_H

#include <stddef.h>
#include <stdint.h>

#include "trk/table.h"

struct par; /* tools/par/par.h */

enum toc_detector { TOC_PDAF = 0, TOC_PDAFAI = 1, TOC_N_DETECTORS = 2 };

struct toc_scenario {
    int amp_model;         /* TRK_AMP_RAYLEIGH or TRK_AMP_K (trk/amplitude.h) */
    double nu;             /* K shape (0 < nu <= 1e6); ignored for Rayleigh */
    double snr_db;         /* Swerling I target SNR, dB */
    double cell_m2;        /* resolution cell area: lambda = pfa / cell_m2 per m^2 */
    double dt_s;           /* MRE model (nz = 2): scan interval T */
    double q_m2_per_s3;    /* process noise PSD q~ */
    double r_m2;           /* R = r I */
    double gate_gamma;     /* gate threshold on d2 (Brekke g^2) */
    double pfa_min, pfa_max; /* the ROC range of curves and of the optimum search */
    int mre_start;         /* enum toc_start: the MRE's start at every pfa */
};

/* The MRE's start: two-point differencing (a new track; 0, the default),
 * P = 0, or the steady state of the clutter-free Kalman filter (P_D = 1: a
 * track held for long; the MRE's fixed point with q2 = 1). A start changes
 * whether the iteration reaches a steady state (or stays on the q2 table),
 * not the steady state it reaches. */
enum toc_start { TOC_START_TWOPOINT = 0, TOC_START_ZERO = 1, TOC_START_STEADY = 2 };
const char *toc_start_name(int start); /* "two-point", "zero", "steady" */

/* Brekke's Table I model, the ROC range 1e-6 .. 0.5, the two-point start. */
void toc_scenario_brekke(struct toc_scenario *sc, int amp_model, double nu, double snr_db,
                         double cell_m2);

struct toc_q2_source {
    const struct trk_table *pdaf;    /* NULL: sample the PDAF q2 grid */
    const struct trk_table *pdafai;  /* NULL: sample the PDAFAI q2 grid */
    /* sampler settings (used only for a NULL table; 0 = default) */
    uint64_t samples;      /* per stratum, default Q2_TABLE_DEFAULT_SAMPLES (1e6) */
    double target_se;      /* per cell, default Q2_TABLE_DEFAULT_TARGET_SE (1e-3) */
    uint64_t seed;         /* default 1 */
    int threads;           /* <= 0: OpenMP default */
    int quiet;             /* no progress bar on stderr */
    double lambda_vg_max;  /* top of the sampled lambda_vg axis; 0: that of the
                              default tables (PDAF 100, PDAFAI 50) */
    struct par *par;       /* the sampler's work distribution (q2_table_run.par) */
};

struct toc; /* opaque: the scenario, the q2 lookups (and sampled grids) */

struct toc *toc_new(const struct toc_scenario *sc, const struct toc_q2_source *src, char *err,
                    size_t errlen);
void toc_free(struct toc *t);

/* The scenario (with defaults applied). */
const struct toc_scenario *toc_scenario_of(const struct toc *t);

/* Another resolution cell area for the same q2 lookups (q2 does not depend
 * on it: only lambda = pfa / cell_m2 does). */
int toc_set_cell_m2(struct toc *t, double cell_m2, char *err, size_t errlen);

/* ROC: pd = S1(t) at false-alarm probability pfa (the library's closed form
 * for Rayleigh, the offline K model kdist.h for K). */
int toc_pd(const struct toc *t, double pfa, double *pd, char *err, size_t errlen);

/* q2 of a detector at (pfa, lambda_vg), as the MRE sees it (table lookup). */
int toc_q2(const struct toc *t, int detector, double pfa, double lambda_vg, double *q2,
           char *err, size_t errlen);

enum toc_status {
    TOC_OK = 0,           /* steady state reached */
    TOC_DIVERGED = 1,     /* the MRE has no steady state (track lost) */
    TOC_OFF_TABLE = 2     /* the iteration left the q2 table (lambda_vg or pd
                             outside its axes): not computed */
};

struct toc_point {
    double pfa, pd;
    double lambda_per_m2;                 /* pfa / cell_m2 */
    double rmse_m[TOC_N_DETECTORS];       /* steady-state sqrt(P11 + P22) (Brekke eq 35);
                                             +inf: no steady state / off the q2 table */
    double q2[TOC_N_DETECTORS];           /* at the steady state (NaN when rmse is inf) */
    double lambda_vg[TOC_N_DETECTORS];    /* at the steady state (NaN when rmse is inf) */
    int iterations[TOC_N_DETECTORS];      /* MRE steps to the steady state */
    int status[TOC_N_DETECTORS];          /* enum toc_status */
    double rmse_bound_m[TOC_N_DETECTORS]; /* TOC_OFF_TABLE: a lower bound of the RMSE
                                             (q2 held at the table's top value);
                                             TOC_DIVERGED: +inf; TOC_OK: 0 */
};

/* Both detectors at one pfa in [pfa_min, pfa_max]. */
int toc_point_at(const struct toc *t, double pfa, struct toc_point *p, char *err, size_t errlen);

/* n >= 2 points equally spaced in ln pfa over [pfa_min, pfa_max]. */
int toc_curve(const struct toc *t, size_t n, struct toc_point *pts, char *err, size_t errlen);

struct toc_optimum {
    double pfa, pd, rmse_m, q2, lambda_vg;
    int n_evals, n_diverged;   /* MRE solves, of which without steady state
                                  (diverged or off the q2 table) */
    int at_range_end;          /* the optimum is pfa_min or pfa_max: the true one
                                  may lie outside the range */
    int table_limited;         /* a neighbouring pfa (x e^+-0.05), or the end of the
                                  1 % interval below, is off the q2 table with an
                                  RMSE bound below twice the optimum's: the true
                                  optimum may lie beyond it (a bound far above is
                                  a lost track, e.g. the PDAF swamped by clutter) */
    double pfa_1pct_lo, pfa_1pct_hi; /* the interval around pfa where the RMSE is
                                  within 1 % of the optimum (a flat TOC: q2's
                                  Monte Carlo noise moves pfa inside it) */
};

/* The pfa minimising the detector's RMSE over [pfa_min, pfa_max]
 * (trk_toc_optimise: 41-point grid in ln pfa, golden section to 1e-3).
 * -1 when no pfa of the range has a steady state. */
int toc_optimum(const struct toc *t, int detector, struct toc_optimum *o, char *err,
                size_t errlen);

const char *toc_detector_name(int detector); /* "PDAF", "PDAFAI" */
const char *toc_status_name(int status);     /* "ok", "diverged", "off_table" */

#endif
