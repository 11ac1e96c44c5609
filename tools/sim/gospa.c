/* gospa.c - GOSPA (alpha = 2) and its optimal assignment (gospa.h). */
#include "gospa.h"

#include <math.h>
#include <stdlib.h>

/* Hungarian method with row/column potentials u, v (the shortest augmenting
 * path form of Kuhn-Munkres): rows are added one at a time; each addition
 * grows a Dijkstra-like tree over the columns with reduced costs
 * cost - u - v >= 0 until a free column is reached, then augments along it.
 * Index 0 of p/way is the virtual column the new row starts from. */
double hungarian(const double *cost, size_t rows, size_t cols, long *col_of_row)
{
    double *u = calloc(rows + 1, sizeof *u), *v = calloc(cols + 1, sizeof *v);
    double *minv = malloc((cols + 1) * sizeof *minv);
    long *p = calloc(cols + 1, sizeof *p), *way = calloc(cols + 1, sizeof *way);
    char *used = malloc(cols + 1);
    double total = -1;
    if (!u || !v || !minv || !p || !way || !used) goto out;
    for (size_t i = 1; i <= rows; i++) {
        p[0] = (long)i;
        size_t j0 = 0;
        for (size_t j = 0; j <= cols; j++) {
            minv[j] = INFINITY;
            used[j] = 0;
        }
        do {
            used[j0] = 1;
            const size_t i0 = (size_t)p[j0];
            double delta = INFINITY;
            size_t j1 = 0;
            for (size_t j = 1; j <= cols; j++) {
                if (used[j]) continue;
                const double cur = cost[(i0 - 1) * cols + (j - 1)] - u[i0] - v[j];
                if (cur < minv[j]) {
                    minv[j] = cur;
                    way[j] = (long)j0;
                }
                if (minv[j] < delta) {
                    delta = minv[j];
                    j1 = j;
                }
            }
            for (size_t j = 0; j <= cols; j++) {
                if (used[j]) {
                    u[p[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
        } while (p[j0] != 0);
        do { /* augment along the tree back to the virtual column */
            const size_t j1 = (size_t)way[j0];
            p[j0] = p[j1];
            j0 = j1;
        } while (j0);
    }
    total = 0;
    for (size_t j = 1; j <= cols; j++)
        if (p[j] > 0) {
            col_of_row[p[j] - 1] = (long)j - 1;
            total += cost[(size_t)(p[j] - 1) * cols + (j - 1)];
        }
out:
    free(u);
    free(v);
    free(minv);
    free(p);
    free(way);
    free(used);
    return total;
}

int gospa(const double *dist, size_t n, size_t m, double c, double p, long *assign, struct gospa_result *res)
{
    if (!res || (n > 0 && m > 0 && !dist) || !(c > 0) || !(p >= 1) || !isfinite(c) || !isfinite(p)) return -1;
    for (size_t k = 0; k < n * m; k++)
        if (isnan(dist[k]) || dist[k] < 0) return -1;
    const double cp = pow(c, p);
    struct gospa_result r = {0, 0, 0, 0, 0, 0, 0};
    long *row_col = NULL;
    double *cost = NULL;
    /* rows: the smaller side */
    const int transpose = n > m;
    const size_t rows = transpose ? m : n, cols = transpose ? n : m;
    if (rows > 0) {
        cost = malloc(rows * cols * sizeof *cost);
        row_col = malloc(rows * sizeof *row_col);
        if (!cost || !row_col) {
            free(cost);
            free(row_col);
            return -1;
        }
        for (size_t i = 0; i < rows; i++)
            for (size_t j = 0; j < cols; j++) {
                const double d = transpose ? dist[j * m + i] : dist[i * m + j];
                cost[i * cols + j] = d < c ? pow(d, p) : cp;
            }
        if (hungarian(cost, rows, cols, row_col) < 0) {
            free(cost);
            free(row_col);
            return -1;
        }
    }
    if (assign)
        for (size_t i = 0; i < n; i++) assign[i] = -1;
    for (size_t i = 0; i < rows; i++) {
        const size_t t = transpose ? (size_t)row_col[i] : i, e = transpose ? i : (size_t)row_col[i];
        const double d = dist[t * m + e];
        if (!(d < c)) continue; /* costs c^p: the same as leaving both out */
        r.loc += pow(d, p);
        r.n_assigned++;
        if (assign) assign[t] = (long)e;
    }
    r.n_missed = n - r.n_assigned;
    r.n_false = m - r.n_assigned;
    r.missed = cp / 2 * (double)r.n_missed;
    r.false_ = cp / 2 * (double)r.n_false;
    r.gospa = pow(r.loc + r.missed + r.false_, 1 / p);
    free(cost);
    free(row_col);
    *res = r;
    return 0;
}
