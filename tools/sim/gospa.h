/* gospa.h - the generalised optimal sub-pattern assignment metric (GOSPA;
 * Rahmathullah, Garcia-Fernandez & Svensson, FUSION 2017) with alpha = 2,
 * and the optimal assignment behind it.
 *
 * For targets X = {x_1..x_n} and estimates Y = {y_1..y_m}, base distance d,
 * cut-off c > 0 and order p >= 1:
 *   GOSPA^p = min over assignments g of  sum_{(i,j) in g} d(x_i, y_j)^p
 *                                        + c^p / 2 (n + m - 2 |g|)
 * where only pairs with d < c may be assigned (a pair at d >= c costs c^p,
 * exactly what leaving both unassigned costs). Its parts (alpha = 2 only):
 *   localisation = sum of d^p over the assigned pairs,
 *   missed       = c^p / 2 * (targets left unassigned),
 *   false        = c^p / 2 * (estimates left unassigned),
 * GOSPA = (localisation + missed + false)^(1/p).
 *
 * The assignment is a rectangular linear assignment on min(d, c)^p solved
 * by the Hungarian method with potentials (Kuhn-Munkres, O(n^2 m) for
 * n <= m), exact. Host code (tools/sim): scratch comes from the heap. */
#ifndef TRK_SIM_GOSPA_H
#define TRK_SIM_GOSPA_H

#include <stddef.h>

struct gospa_result {
    double gospa;        /* (loc + missed + false)^(1/p) */
    double loc, missed, false_; /* the parts, in units of distance^p */
    size_t n_assigned;   /* pairs with d < c */
    size_t n_missed;     /* targets without an estimate */
    size_t n_false;      /* estimates without a target */
};

/* dist: n x m row-major distances (>= 0; +inf allowed: never assigned);
 * assign: n outputs, the estimate assigned to each target or -1 (may be
 * NULL). Returns 0, or -1 for bad arguments (c <= 0, p < 1, a NaN or
 * negative distance, NULL arrays) or no memory. */
int gospa(const double *dist, size_t n, size_t m, double c, double p, long *assign, struct gospa_result *res);

/* The minimum-cost assignment of a rows x cols cost matrix (row-major,
 * finite), rows <= cols: col_of_row gets each row's column. Returns the
 * minimum total cost, or -1 (and nothing written) when out of memory. */
double hungarian(const double *cost, size_t rows, size_t cols, long *col_of_row);

#endif
