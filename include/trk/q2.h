/** @file
 * trk/q2.h - lookup of the information-reduction factor q2 on a grid of
 * precomputed values, and receiver operating characteristics (ROC) as inputs
 * of the tracking operating characteristic (TOC, trk/mre.h).
 *
 * q2 (docs/conventions.md "q2, MRE and CRLB"; Brekke eqs 26-30, Willett eqs 14-16, 36)
 * is the scalar with E[nubar nubar'] = q2 S. It has no closed form: the
 * offline tool computes it by importance sampling over a grid and the library
 * interpolates. q2 depends on S only through lambda_vg = lambda V_G, the
 * expected clutter count in the gate.
 *
 * Grids (the axes are fixed by the detector; the last axis is lambda_vg):
 *   TRK_Q2_PDAF    2 axes (pd, lambda_vg), for one nz and gate probability
 *   TRK_Q2_PDAFAI  3 axes (snr_db, pfa, lambda_vg), for one amplitude model
 *                  (Rayleigh, or K with shape nu); pd is the ROC value S1(t)
 *
 * Interpolation scheme. Each axis is interpolated in its own coordinate u:
 * u = ln(x) on a log axis (pfa, lambda_vg: q2 is smooth in ln lambda_vg),
 * u = x otherwise (pd, snr_db). Per axis either
 *   TRK_Q2_LINEAR  linear in u between the two bracketing nodes, or
 *   TRK_Q2_CUBIC   cubic Hermite in u with node slopes from the quadratic
 *                  through each node and its two neighbours (one-sided at the
 *                  ends); exact for quadratics, C1, needs >= 4 nodes (an axis
 *                  with 2 or 3 nodes is interpolated linearly).
 * The multi-dimensional value is the tensor product (2, 4 or 8 nodes linear;
 * up to 64 cubic). Both schemes return the node values exactly at nodes.
 * Truncation error (smooth q2, node spacing h in u): linear <= h^2/8 max|q2''|,
 * cubic O(h^3). Monte Carlo noise of the nodes passes through with gain
 * sum|w| <= 1 (linear) or <= 1.25 per axis (cubic, uniform nodes). On
 * explicit nodes the cubic slopes divide by the neighbouring intervals, and
 * the gain grows with the ratio of neighbouring intervals (2: 1.67, 4: 2.6,
 * 10: 5.5; the default tables' pd axis 1.61, snr_db 1.36): an axis whose
 * gain exceeds TRK_Q2_MAX_AXIS_GAIN anywhere is refused by
 * trk_q2_lookup_init (TRK_E_TABLE_CORRUPT), so values in [0, 1] never
 * interpolate to more than TRK_Q2_MAX_AXIS_GAIN^axes in magnitude (an
 * interval of 1e-12 beside ones of 0.1 had given 5.9e9).
 * Measured with `trk-tablegen q2 --measure-interp` (q2 estimated at the centre
 * of every grid cell with the same random numbers, compared with this
 * lookup; part of the difference is Monte Carlo noise where the cells' se
 * approach 1e-3, so the largest error over the centres with se <= 1e-4 is
 * given too), on the default grids of `make tables` (se <= 1e-3 per cell):
 *   PDAF, P_G 0.99 (30 pd x 57 lambda_vg)   cubic max 1.3e-4, rms 2.1e-5
 *                                           linear max 2.0e-3, rms 4.1e-4
 *   PDAF, gamma 36                          cubic max 2.8e-4, rms 4.0e-5
 *                                           (se <= 1e-4: max 9.5e-5)
 *                                           linear max 1.8e-3, rms 3.9e-4
 *   PDAFAI, gamma 36, 13 snr_db x 22 pfa x 47 lambda_vg, cubic:
 *     Rayleigh                              max 2.0e-3, rms 2.4e-4
 *     K nu = 1                              max 2.8e-3, rms 3.4e-4
 *     K nu = 8                              max 1.9e-3, rms 2.7e-4
 *                                           (se <= 1e-4: max 7.8e-4)
 *   the largest differences are at lambda_vg ~40, where the se are ~1e-3.
 * q2 bends sharply in pd near 1 (b ~ (1 - pd pg)/pd) and in snr_db at low
 * SNR (pd changes fast along the ROC): hence pd nodes 0.01 (0.005) apart
 * above 0.97 and snr_db nodes 1 dB apart below 8 dB; pfa needs <= 0.63 in
 * ln pfa (3.7 per decade), lambda_vg 6-7 per decade. A 5 dB SNR step gives
 * 2.7e-2, 2.5 dB 4e-3, 1.25 dB 1e-3 (Rayleigh, cubic).
 *
 * Out of range: a coordinate outside [first node, last node] of its axis is
 * refused with TRK_E_RANGE (no extrapolation, no clamping). An axis with a
 * single node accepts only that node's coordinate (to within 1e-6 relative).
 *
 * The grid is a view over caller-owned arrays (ROM or RAM, e.g. the payload
 * of a table file): no copy, no heap. A log axis stores ln(node) in its array,
 * so a lookup costs one log per log axis plus a binary search per axis.
 */
#ifndef TRK_Q2_H
#define TRK_Q2_H

#include "trk/table.h"
#include "trk/types.h"

/** Largest number of axes of a q2 grid (PDAFAI: snr_db, pfa, lambda_vg). */
#define TRK_Q2_MAX_AXES 3
/** Largest noise gain sum|w| of one axis's interpolation weights (see above). */
#define TRK_Q2_MAX_AXIS_GAIN TRK_REAL_C(3.0)

/** The detector a q2 grid describes; its axes, in order. */
enum trk_q2_detector {
    TRK_Q2_PDAF = 1,   /**< axes (pd, lambda_vg) */
    TRK_Q2_PDAFAI = 2  /**< axes (snr_db, pfa, lambda_vg) */
};

/** Interpolation along one axis of a q2 grid (see above). */
enum trk_q2_interp {
    TRK_Q2_LINEAR = 0,
    TRK_Q2_CUBIC = 1
};

/** One axis of a grid. Either explicit nodes (`nodes` != NULL, `count`
 * strictly increasing values of u) or a uniform grid in u (`nodes` == NULL:
 * count nodes from u_first to u_last). u = ln(x) when log_spacing is 1. */
struct trk_q2_axis {
    size_t count;            /**< >= 1 */
    const trk_real *nodes;   /**< count values of u, or NULL (uniform) */
    trk_real u_first;        /**< uniform axes only */
    trk_real u_last;         /**< uniform axes only, > u_first when count > 1 */
    int log_spacing;         /**< 1: u = ln(x) (x > 0); 0: u = x */
    int interp;              /**< enum trk_q2_interp */
};

/** The grid: axes in the detector's order, values row-major with the last axis
 * (lambda_vg) fastest: cell (i0, i1[, i2]) is number c = (i0 * count1 + i1) * count2 + i2
 * and its value is values[c * value_stride] (value_stride 0 means 1; a q2
 * table stores (q2, se) pairs: value_stride 2). */
struct trk_q2_grid {
    int detector;                             /**< enum trk_q2_detector */
    struct trk_q2_axis axis[TRK_Q2_MAX_AXES]; /**< 2 (PDAF) or 3 (PDAFAI) used */
    const trk_real *values;                   /**< prod(count) values in [0, 1] */
    size_t value_stride;                      /**< 0 or 1: contiguous; k: every k-th real */
};

/** A validated grid (initialise with trk_q2_lookup_init or
 * trk_q2_lookup_init_table, then read-only; one lookup object may be shared
 * by any number of readers). The documented fields may be read. */
struct trk_q2_lookup {
    struct trk_q2_grid grid;  /**< the grid as given (the table's view for trk_q2_lookup_init_table) */
    int n_axes;  /**< 2 (PDAF) or 3 (PDAFAI) */
    size_t stride[TRK_Q2_MAX_AXES];  /**< in reals, value_stride included */
    /* what the q2 values are for: from a table's parameters
     * (trk_q2_lookup_init_table); 0 when unknown (trk_q2_lookup_init) */
    int nz;                          /**< measurement dimension */
    trk_real gate_gamma;             /**< gate threshold on d2 */
    trk_real gate_prob;              /**< P_G = P(chi2(nz) <= gate_gamma) */
    int amp_model;                   /**< PDAFAI: enum trk_amp_model (trk/amplitude.h) */
    trk_real nu;                     /**< PDAFAI, K clutter: shape (Rayleigh: 0) */
    trk_real max_se;                 /**< largest per-cell standard error of the values */
};

/** Validate *grid and make *q a lookup over it (the arrays are referenced, not
 * copied: they must outlive q). Checks: pointers, detector, counts >= 1,
 * axes finite and strictly increasing (a log axis: u = ln x with x in the
 * axis' domain: pd in (0, 1], pfa in (0, 1), lambda_vg > 0; snr_db finite),
 * every value finite and in [0, 1].
 * TRK_E_ARG NULL pointer / zero count / bad interp or spacing flag,
 * TRK_E_TABLE_KIND unknown detector, TRK_E_TABLE_CORRUPT non-finite or
 * non-monotone axis, node outside the axis' domain, value outside [0, 1] or
 * not finite, total size overflow. *q untouched on error. */
TRK_NODISCARD trk_status trk_q2_lookup_init(struct trk_q2_lookup *q, const struct trk_q2_grid *grid);

/* ---- q2 tables (trk/table.h container; made by `trk-tablegen q2`) ----
 *
 * Q2 TABLE, kinds TRK_TABLE_KIND_Q2_PDAF and TRK_TABLE_KIND_Q2_PDAFAI, kind
 * version TRK_Q2_TABLE_VERSION (1):
 *   parameters (i: integer, r: real)
 *     detector (i)      enum trk_q2_detector, agrees with the kind
 *     nz (i)            measurement dimension 1..3
 *     gate_gamma (r)    gate threshold gamma on d2 (> 0)
 *     gate_prob (r)     P_G = P(chi2(nz) <= gamma), agrees with gamma to 1e-5
 *     model (i), nu (r) PDAFAI only: enum trk_amp_model, K shape (> 0; 0 for
 *                       Rayleigh); clutter power 1, pd = S1(t) per cell
 *     max_se (r)        largest per-cell standard error (>= 0)
 *     written by the generator, not needed by the lookup: samples (i),
 *     target_se (r), seed (i), tail_mass (r), generator_version (i), and for
 *     PDAFAI the amplitude table size and measured errors (amp_size (i),
 *     amp_err_log_lr (r), amp_err_inv_sf (r))
 *   one section, id TRK_Q2_SECTION_VALUES (1), ncomp 2: per cell (q2, se),
 *     se the Monte Carlo standard error of q2; interpolation
 *     TRK_TABLE_INTERP_LINEAR or TRK_TABLE_INTERP_CUBIC (the two schemes
 *     above, on every axis); axes (variable: spacing)
 *       PDAF:    pd: linear or explicit,  lambda_vg: log
 *       PDAFAI:  snr_db: linear or explicit,  pfa: log,  lambda_vg: log
 *     (a log axis is uniform in u = ln x, an explicit one lists x = u).
 * The lookup is a view on the table's bytes (no copy): the table must outlive it.
 */
/** Version of the q2 section layout in a table file; another version is refused. */
#define TRK_Q2_TABLE_VERSION 1u
/** Section id of a q2 table's values. */
#define TRK_Q2_SECTION_VALUES 1u

/** Make *q a lookup over a parsed q2 table (trk_table_parse) of the given
 * detector and measurement dimension nz. Checks, with *q untouched on error:
 * TRK_E_ARG NULL pointer, detector not PDAF/PDAFAI or nz outside 1..3;
 * TRK_E_TABLE_KIND a table of another kind (e.g. an amplitude table, or a
 * PDAFAI table asked for as PDAF), of another measurement dimension nz, or
 * whose section has the wrong number of axes or axis variables;
 * TRK_E_TABLE_VERSION another kind version; TRK_E_TABLE_CORRUPT a missing or
 * inconsistent parameter, a section of the wrong shape, spacing or
 * interpolation, a standard error < 0, and everything trk_q2_lookup_init
 * refuses (values outside [0, 1], axes outside their domain). */
TRK_NODISCARD trk_status trk_q2_lookup_init_table(struct trk_q2_lookup *q, const struct trk_table *t,
                                                  int detector, int nz);

/** q2 at physical coordinates x[0..n_axes) (detector's axis order).
 * TRK_E_ARG NULL, TRK_E_NAN non-finite coordinate, TRK_E_RANGE coordinate
 * outside its axis (or <= 0 on a log axis). *q2 untouched on error. */
TRK_NODISCARD trk_status trk_q2_lookup_eval(const struct trk_q2_lookup *q, const trk_real *x,
                                            trk_real *q2);

/** @{ */
/** Typed entry points: TRK_E_TABLE_KIND when q is a grid of the other detector. */
TRK_NODISCARD trk_status trk_q2_pdaf(const struct trk_q2_lookup *q, trk_real pd,
                                     trk_real lambda_vg, trk_real *q2);
TRK_NODISCARD trk_status trk_q2_pdafai(const struct trk_q2_lookup *q, trk_real snr_db,
                                       trk_real pfa, trk_real lambda_vg, trk_real *q2);
                                       /** @} */

/* ---- q2 as a function of lambda_vg (the MRE's input, trk/mre.h) ---- */

/** q2 at lambda_vg; ctx is the function's own data. Returns a status. */
typedef trk_status (*trk_q2_fn)(const void *ctx, trk_real lambda_vg, trk_real *q2);

/** A grid with every axis but lambda_vg fixed: PDAF at one pd, or PDAFAI at
 * one (snr_db, pfa). Use as the ctx of trk_q2_line_eval. */
struct trk_q2_line {
    const struct trk_q2_lookup *lookup;  /**< the grid, shared */
    trk_real fixed[TRK_Q2_MAX_AXES - 1];  /**< PDAF: {pd}; PDAFAI: {snr_db, pfa} */
};

/** trk_q2_fn over a struct trk_q2_line (ctx). Statuses of trk_q2_lookup_eval. */
TRK_NODISCARD trk_status trk_q2_line_eval(const void *ctx, trk_real lambda_vg, trk_real *q2);

/* ---- ROC and q2 along it (the TOC's input, trk/mre.h) ---- */

/** Detection probability at the threshold with false-alarm probability pfa.
 * The amplitude module provides these for Rayleigh and K clutter; a
 * tabulated ROC is below. */
typedef trk_status (*trk_roc_fn)(const void *ctx, trk_real pfa, trk_real *pd);

/** Tabulated ROC: n >= 2 points, pfa strictly increasing in (0, 1), pd in
 * (0, 1]; interpolated linearly in (ln pfa, ln pd) (exact for Rayleigh
 * clutter, where pd = pfa^(1/(1+SNR))). Outside [pfa[0], pfa[n-1]]:
 * TRK_E_RANGE. The arrays are referenced, not copied. */
struct trk_roc_table {
    size_t n;  /**< points, >= 2 */
    const trk_real *pfa;  /**< n false-alarm probabilities, strictly increasing in (0, 1) */
    const trk_real *pd;  /**< n detection probabilities in (0, 1] */
};

/** trk_roc_fn over a struct trk_roc_table (ctx). TRK_E_ARG NULL or n < 2,
 * TRK_E_NAN non-finite pfa, TRK_E_RANGE pfa outside the table,
 * TRK_E_TABLE_CORRUPT a table entry out of its domain. */
TRK_NODISCARD trk_status trk_roc_table_eval(const void *ctx, trk_real pfa, trk_real *pd);

/** q2 of a detector operated at false-alarm probability pfa, as a function
 * of lambda_vg. ctx is the function's own data. */
typedef trk_status (*trk_q2_pfa_fn)(const void *ctx, trk_real pfa, trk_real lambda_vg,
                                    trk_real *q2);

/** The usual trk_q2_pfa_fn: for a PDAF grid, pd = roc(pfa) then q2(pd,
 * lambda_vg); for a PDAFAI grid, q2(snr_db, pfa, lambda_vg) (the grid's pd
 * already follows the ROC; roc is not used and may be NULL). */
struct trk_q2_roc {
    const struct trk_q2_lookup *lookup;  /**< the grid, shared */
    trk_roc_fn roc;          /**< PDAF only */
    const void *roc_ctx;  /**< the roc's ctx (PDAF only) */
    trk_real snr_db;         /**< PDAFAI only */
};

/** trk_q2_pfa_fn over a struct trk_q2_roc (ctx). TRK_E_ARG NULL (or no roc for
 * a PDAF grid), plus the statuses of the roc and of trk_q2_lookup_eval. */
TRK_NODISCARD trk_status trk_q2_roc_eval(const void *ctx, trk_real pfa, trk_real lambda_vg,
                                         trk_real *q2);

#endif /* TRK_Q2_H */
