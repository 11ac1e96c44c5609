/* trk/q2.h - lookup of the information-reduction factor q2 on a grid of
 * precomputed values, and receiver operating characteristics (ROC) as inputs
 * of the tracking operating characteristic (TOC, trk/mre.h).
 *
 * q2 (CONVENTIONS "q2, MRE and CRLB"; Brekke eqs 26-30, Willett eqs 14-16, 36)
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
 * cubic O(h^3). Measured against the direct estimator between the nodes
 * (`trk-q2 interp-error`: PDAF, nz = 2, pg = 0.99, nodes pd 0.5..1 step 0.05
 * x lambda_vg 0.01..100 at 10 per decade, 3600 test points, common random
 * numbers so that the Monte Carlo noise cancels):
 *                 pd < 0.95            0.95 <= pd <= 1
 *   linear   max 1.2e-3 rms 2.7e-4   max 2.0e-3 rms 6.7e-4
 *   cubic    max 1.8e-4 rms 1.7e-5   max 6.7e-4 rms 1.9e-4
 * q2 bends sharply in pd near 1 (b ~ (1 - pd pg)/pd): a table should use
 * cubic interpolation and nodes 0.01 apart or closer above pd 0.9. Monte
 * Carlo noise of the nodes passes through with gain sum|w| <= 1 (linear) or
 * <= 1.25 per axis (cubic).
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

#include "trk/types.h"

#define TRK_Q2_MAX_AXES 3

enum trk_q2_detector {
    TRK_Q2_PDAF = 1,   /* axes (pd, lambda_vg) */
    TRK_Q2_PDAFAI = 2  /* axes (snr_db, pfa, lambda_vg) */
};

enum trk_q2_interp {
    TRK_Q2_LINEAR = 0,
    TRK_Q2_CUBIC = 1
};

/* One axis of a grid. Either explicit nodes (`nodes` != NULL, `count`
 * strictly increasing values of u) or a uniform grid in u (`nodes` == NULL:
 * count nodes from u_first to u_last). u = ln(x) when log_spacing is 1. */
struct trk_q2_axis {
    size_t count;            /* >= 1 */
    const trk_real *nodes;   /* count values of u, or NULL (uniform) */
    trk_real u_first;        /* uniform axes only */
    trk_real u_last;         /* uniform axes only, > u_first when count > 1 */
    int log_spacing;         /* 1: u = ln(x) (x > 0); 0: u = x */
    int interp;              /* enum trk_q2_interp */
};

/* The grid: axes in the detector's order, values row-major with the last axis
 * (lambda_vg) fastest: value(i0, i1[, i2]) = values[(i0 * count1 + i1) * count2 + i2]. */
struct trk_q2_grid {
    int detector;                             /* enum trk_q2_detector */
    struct trk_q2_axis axis[TRK_Q2_MAX_AXES]; /* 2 (PDAF) or 3 (PDAFAI) used */
    const trk_real *values;                   /* prod(count) values in [0, 1] */
};

/* A validated grid (initialise with trk_q2_lookup_init, then read-only; one
 * lookup object may be shared by any number of readers). */
struct trk_q2_lookup {
    struct trk_q2_grid grid;
    int n_axes;
    size_t stride[TRK_Q2_MAX_AXES];
};

/* Validate *grid and make *q a lookup over it (the arrays are referenced, not
 * copied: they must outlive q). Checks: pointers, detector, counts >= 1,
 * axes finite and strictly increasing (a log axis: u = ln x with x in the
 * axis' domain: pd in (0, 1], pfa in (0, 1), lambda_vg > 0; snr_db finite),
 * every value finite and in [0, 1].
 * TRK_E_ARG NULL pointer / zero count / bad interp or spacing flag,
 * TRK_E_TABLE_KIND unknown detector, TRK_E_TABLE_CORRUPT non-finite or
 * non-monotone axis, node outside the axis' domain, value outside [0, 1] or
 * not finite, total size overflow. *q untouched on error. */
TRK_NODISCARD trk_status trk_q2_lookup_init(struct trk_q2_lookup *q, const struct trk_q2_grid *grid);

/* q2 at physical coordinates x[0..n_axes) (detector's axis order).
 * TRK_E_ARG NULL, TRK_E_NAN non-finite coordinate, TRK_E_RANGE coordinate
 * outside its axis (or <= 0 on a log axis). *q2 untouched on error. */
TRK_NODISCARD trk_status trk_q2_lookup_eval(const struct trk_q2_lookup *q, const trk_real *x,
                                            trk_real *q2);

/* Typed entry points: TRK_E_TABLE_KIND when q is a grid of the other detector. */
TRK_NODISCARD trk_status trk_q2_pdaf(const struct trk_q2_lookup *q, trk_real pd,
                                     trk_real lambda_vg, trk_real *q2);
TRK_NODISCARD trk_status trk_q2_pdafai(const struct trk_q2_lookup *q, trk_real snr_db,
                                       trk_real pfa, trk_real lambda_vg, trk_real *q2);

/* ---- q2 as a function of lambda_vg (the MRE's input, trk/mre.h) ---- */

/* q2 at lambda_vg; ctx is the function's own data. Returns a status. */
typedef trk_status (*trk_q2_fn)(const void *ctx, trk_real lambda_vg, trk_real *q2);

/* A grid with every axis but lambda_vg fixed: PDAF at one pd, or PDAFAI at
 * one (snr_db, pfa). Use as the ctx of trk_q2_line_eval. */
struct trk_q2_line {
    const struct trk_q2_lookup *lookup;
    trk_real fixed[TRK_Q2_MAX_AXES - 1];  /* PDAF: {pd}; PDAFAI: {snr_db, pfa} */
};

/* trk_q2_fn over a struct trk_q2_line (ctx). Statuses of trk_q2_lookup_eval. */
TRK_NODISCARD trk_status trk_q2_line_eval(const void *ctx, trk_real lambda_vg, trk_real *q2);

/* ---- ROC and q2 along it (the TOC's input, trk/mre.h) ---- */

/* Detection probability at the threshold with false-alarm probability pfa.
 * The amplitude module provides these for Rayleigh and K clutter; a
 * tabulated ROC is below. */
typedef trk_status (*trk_roc_fn)(const void *ctx, trk_real pfa, trk_real *pd);

/* Tabulated ROC: n >= 2 points, pfa strictly increasing in (0, 1), pd in
 * (0, 1]; interpolated linearly in (ln pfa, ln pd) (exact for Rayleigh
 * clutter, where pd = pfa^(1/(1+SNR))). Outside [pfa[0], pfa[n-1]]:
 * TRK_E_RANGE. The arrays are referenced, not copied. */
struct trk_roc_table {
    size_t n;
    const trk_real *pfa;
    const trk_real *pd;
};

/* trk_roc_fn over a struct trk_roc_table (ctx). TRK_E_ARG NULL or n < 2,
 * TRK_E_NAN non-finite pfa, TRK_E_RANGE pfa outside the table,
 * TRK_E_TABLE_CORRUPT a table entry out of its domain. */
TRK_NODISCARD trk_status trk_roc_table_eval(const void *ctx, trk_real pfa, trk_real *pd);

/* q2 of a detector operated at false-alarm probability pfa, as a function
 * of lambda_vg. ctx is the function's own data. */
typedef trk_status (*trk_q2_pfa_fn)(const void *ctx, trk_real pfa, trk_real lambda_vg,
                                    trk_real *q2);

/* The usual trk_q2_pfa_fn: for a PDAF grid, pd = roc(pfa) then q2(pd,
 * lambda_vg); for a PDAFAI grid, q2(snr_db, pfa, lambda_vg) (the grid's pd
 * already follows the ROC; roc is not used and may be NULL). */
struct trk_q2_roc {
    const struct trk_q2_lookup *lookup;
    trk_roc_fn roc;          /* PDAF only */
    const void *roc_ctx;
    trk_real snr_db;         /* PDAFAI only */
};

/* trk_q2_pfa_fn over a struct trk_q2_roc (ctx). TRK_E_ARG NULL (or no roc for
 * a PDAF grid), plus the statuses of the roc and of trk_q2_lookup_eval. */
TRK_NODISCARD trk_status trk_q2_roc_eval(const void *ctx, trk_real pfa, trk_real lambda_vg,
                                         trk_real *q2);

#endif /* TRK_Q2_H */
