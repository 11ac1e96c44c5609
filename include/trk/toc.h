/** @file
 * trk/toc.h - tracking operating characteristic: the steady-state RMSE of
 * the MRE (trk/mre.h) as a function of the false-alarm probability, and the
 * operating point that minimises it (Brekke sec. 5). Design-time analysis:
 * in libtrk_perf.a (src/perf/toc.c), not in the firmware library. */
#ifndef TRK_TOC_H
#define TRK_TOC_H

#include "trk/mre.h"

/** Parameters of the TOC: the MRE model, the cell density and the detector's q2 along its ROC. */
struct trk_toc_params {
    struct trk_mre_params mre;   /**< model; clutter_density, q2, q2_fn, q2_ctx ignored */
    trk_real cells_per_m;        /**< lambda = pfa * cells_per_m (per m^nz), > 0 */
    /** @{ */
    trk_real pfa_min, pfa_max;   /**< search interval, 0 < pfa_min < pfa_max < 1 */
    /** @} */
    trk_q2_pfa_fn q2_fn;         /**< q2 of the detector at (pfa, lambda_vg) */
    const void *q2_ctx;          /**< e.g. struct trk_q2_roc */
    int n_grid;                  /**< coarse grid points in ln pfa (>= 3; 0: 41) */
    trk_real ln_pfa_tol;         /**< golden-section tolerance in ln pfa (0: 1e-3) */
    const trk_real *p0;          /**< the MRE's start at every pfa (nx x nx, SPD or all
                                    zero; trk_mre_steady_state); NULL: two-point
                                    differencing (trk_mre_initial_cov) */
};

/** Steady-state RMSE at one pfa (the TOC curve). res may be NULL.
 * Statuses of trk_mre_init and trk_mre_steady_state (TRK_E_DIVERGED: the MRE
 * has no steady state there; *rmse_m = +inf), TRK_E_RANGE pfa outside (0, 1). */
TRK_NODISCARD trk_status trk_toc_rmse(const struct trk_toc_params *p, trk_real pfa,
                                      trk_real *rmse_m, struct trk_mre_result *res);

/** The operating point that minimises the steady-state RMSE (trk_toc_optimise). */
struct trk_toc_result {
    trk_real pfa;        /**< optimal false-alarm probability */
    trk_real rmse_m;     /**< steady-state RMSE there */
    trk_real lambda_vg;  /**< lambda V_G there */
    trk_real q2;         /**< q2 there */
    int n_evals;         /**< MRE solves */
    int n_diverged;      /**< of which TRK_E_DIVERGED or off the q2 grid (e = +inf) */
};

/** Minimise e(pfa) over [pfa_min, pfa_max]: n_grid points equally spaced in
 * ln pfa, then golden-section search in ln pfa on the two grid intervals
 * around the best point (to ln_pfa_tol). The grid catches the global minimum
 * of a TOC that is unimodal at the grid's resolution (Brekke Fig. 2).
 * A grid point whose MRE diverges or leaves the q2 grid counts as e = +inf.
 * TRK_E_ARG/NAN/RANGE bad parameters, TRK_E_DIVERGED when no grid point has
 * a finite RMSE, or the first status that is neither OK, DIVERGED nor RANGE. */
TRK_NODISCARD trk_status trk_toc_optimise(const struct trk_toc_params *p,
                                          struct trk_toc_result *res);

#endif /* TRK_TOC_H */
