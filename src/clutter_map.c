/* clutter_map.c - each sensor's clutter map (trk/tracker.h, struct
 * trk_clutter_map_params; seed survey ch. 5.3, the clutter map that
 * estimates the local density from the detections and feeds it back to the
 * tracker): cells even in range and bearing over the sensor's coverage, in
 * its own frame; per cell an exponentially weighted count N_c of the
 * detections no confirmed track gated, and per sensor the weighted number
 * of scans W; a position's ratio to the configured density is the
 * Gamma-Poisson posterior mean (N + a) / (e W + a) over the window of cells
 * within window_cells rows and columns of its own (a cell-averaging CFAR
 * over the map, survey ch. 5.2), e their expected clutter count per scan
 * from the configured density and N their counts (cut at the map's edges
 * in range, and in bearing unless the map goes all round), where the guard
 * cells (within guard_cells - 1 rows and columns) together count one
 * detection per scan less: what a point target there may have added
 * before its track was confirmed; and where one of the window's four
 * quadrants holds significantly more than that ratio predicts, the
 * greatest such quadrant's ratio (a greatest-of CFAR at a clutter edge,
 * edge_alpha; docs/tracker.md "Clutter map"). */
#include "clutter_map.h"

int trk_i_map_kept(const struct trk_clutter_map_params *mp, const struct trk_sensor_params *sp)
{
    return TRK_CLUTTER_MAP_CELLS > 0 && mp->n_range > 0 && mp->n_bearing > 0 && sp->coverage.max_range_m > 0 &&
           sp->clutter_density_per_m2 > 0;
}

void trk_i_map_view(struct trk_i_view *v, const struct trk_clutter_map_params *mp, const trk_real *count,
                    trk_real scans)
{
    const struct trk_coverage *c = &v->sp->coverage;
    v->map = (uint8_t)trk_i_map_kept(mp, v->sp);
    v->map_params = mp;
    v->map_count = count;
    v->map_scans = scans;
    v->map_half_b = v->sector ? c->half_width_rad : TRK_PI;
    if (v->map) v->clutter_varies = 1;
}

void trk_i_view_polar(const struct trk_i_view *v, trk_real x_m, trk_real y_m, trk_real *r_m, trk_real *b_rad)
{
    const trk_real dx = x_m - v->pose.x_m, dy = y_m - v->pose.y_m;
    const trk_real along = dx * v->sin_h + dy * v->cos_h, across = dx * v->cos_h - dy * v->sin_h;
    *r_m = trk_sqrt(dx * dx + dy * dy);
    *b_rad = trk_atan2(across, along);
}

long trk_i_map_cell(const struct trk_i_view *v, trk_real r_m, trk_real b_rad)
{
    if (!v->map) return -1;
    const struct trk_clutter_map_params *mp = v->map_params;
    const trk_real r0 = v->sp->coverage.min_range_m, r1 = v->sp->coverage.max_range_m, hb = v->map_half_b;
    if (!(r_m >= r0 && r_m <= r1 && b_rad >= -hb && b_rad <= hb)) return -1;
    long ir = (long)((r_m - r0) / (r1 - r0) * (trk_real)mp->n_range);
    long ib = (long)((b_rad + hb) / (2 * hb) * (trk_real)mp->n_bearing);
    if (ir >= (long)mp->n_range) ir = (long)mp->n_range - 1; /* the far edge itself */
    if (ib >= (long)mp->n_bearing) ib = (long)mp->n_bearing - 1;
    return ir * (long)mp->n_bearing + ib;
}

/* e_c: the expected clutter count per scan in a cell of range row ir from
 * the configured density lambda(r): dtheta * int lambda(r) r dr over the
 * row, by two-point Gauss-Legendre (exact for lambda r cubic in r, so for
 * a 1/r density). */
static trk_real expected_count(const struct trk_i_view *v, long ir)
{
    const struct trk_clutter_map_params *mp = v->map_params;
    const trk_real r0 = v->sp->coverage.min_range_m, r1 = v->sp->coverage.max_range_m;
    const trk_real h = (r1 - r0) / (trk_real)mp->n_range / 2; /* the row's half width */
    const trk_real m = r0 + ((trk_real)(2 * ir + 1)) * h;
    const trk_real d = h * TRK_REAL_C(0.57735026918962576); /* h / sqrt(3) */
    const trk_real integral = h * (trk_i_view_clutter_r(v, m - d) * (m - d) + trk_i_view_clutter_r(v, m + d) * (m + d));
    return 2 * v->map_half_b / (trk_real)mp->n_bearing * integral;
}

static long dist(long a, long b) { return a > b ? a - b : b - a; }

/* Counts and expected count per scan over a set of the window's cells:
 * those outside the guard (train) and in it (guard). */
struct cells {
    trk_real n_train, n_guard, e;
};

/* The set's ratio: the Gamma-Poisson posterior mean, its guard counting one
 * detection per scan (W) less, not below 0 (a slow target's own detections
 * do not raise its density; a patch smaller than the guard still does).
 * *n_out: the counts it pooled. */
static trk_real cells_ratio(const struct trk_i_view *v, const struct cells *c, trk_real *n_out)
{
    const struct trk_clutter_map_params *mp = v->map_params;
    trk_real n = c->n_guard;
    if (mp->guard_cells > 0) n = n > v->map_scans ? n - v->map_scans : 0;
    n += c->n_train;
    *n_out = n;
    return (n + mp->prior_count) / (c->e * v->map_scans + mp->prior_count);
}

static void cells_add(struct cells *c, trk_real n, int guard, trk_real e)
{
    if (guard)
        c->n_guard += n;
    else
        c->n_train += n;
    c->e += e;
}

trk_real trk_i_map_lambda_at(const struct trk_i_view *v, trk_real x_m, trk_real y_m)
{
    trk_real r, b;
    trk_i_view_polar(v, x_m, y_m, &r, &b);
    const trk_real lambda = trk_i_view_clutter_r(v, r);
    const long c = trk_i_map_cell(v, r, b);
    if (c < 0) return lambda;
    const struct trk_clutter_map_params *mp = v->map_params;
    const long n_r = (long)mp->n_range, n_b = (long)mp->n_bearing;
    const long w = (long)mp->window_cells, g = (long)mp->guard_cells;
    const long ir0 = c / n_b, ib0 = c % n_b;
    /* an all-round map's window wraps in bearing, each column once: the
     * column offsets db_lo .. db_hi, none farther than n_b / 2 */
    const int wrap = !v->sector, wide = wrap && 2 * w >= n_b;
    const long db_lo = wide ? -((n_b - 1) / 2) : -w, db_hi = wide ? n_b - 1 + db_lo : w;
    /* the window, and its four quadrants: rows on one side of the cell's
     * (with it) times columns on one side of its column (with it); in a
     * window all round of an even number of columns, the column opposite
     * the cell's (db = n_b / 2) is on both sides */
    struct cells win = {0, 0, 0}, quad[4] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (long ir = ir0 - w; ir <= ir0 + w; ir++) {
        if (ir < 0 || ir >= n_r) continue;
        const trk_real e = expected_count(v, ir);
        const long dr = ir - ir0;
        const int guard_row = dist(ir, ir0) < g;
        for (long db = db_lo; db <= db_hi; db++) {
            long ib = ib0 + db;
            if (wrap)
                ib += ib < 0 ? n_b : ib >= n_b ? -n_b : 0;
            else if (ib < 0 || ib >= n_b)
                continue;
            const trk_real n = v->map_count[ir * n_b + ib];
            const int guard = guard_row && dist(db, 0) < g;
            cells_add(&win, n, guard, e);
            const int left = db <= 0 || (wide && 2 * db == n_b);
            for (int q = 0; q < 4; q++)
                if ((q & 1 ? dr >= 0 : dr <= 0) && (q & 2 ? db >= 0 : left)) cells_add(&quad[q], n, guard, e);
        }
    }
    trk_real n_win;
    const trk_real rho_win = cells_ratio(v, &win, &n_win);
    trk_real rho = rho_win;
    /* the edge rule: a quadrant whose count the window's ratio does not
     * explain gives its own ratio (the greatest such): its count n_q above
     * the mean mu_q = rho_win W e_q with a Poisson tail whose Chernoff
     * bound, P(N >= n) <= exp(n - mu - n ln(n / mu)) for n > mu, is below
     * edge_alpha / 4 (one logarithm for the size, ln 4 apart so that a
     * small edge_alpha never makes a subnormal, and one per quadrant that
     * could be taken) */
    if (mp->edge_alpha > 0 && w > 0) {
        const trk_real log_size = trk_log(mp->edge_alpha) - TRK_REAL_C(1.3862943611198906);
        for (int q = 0; q < 4; q++) {
            trk_real n_q;
            const trk_real rho_q = cells_ratio(v, &quad[q], &n_q), mu_q = rho_win * quad[q].e * v->map_scans;
            if (rho_q > rho && n_q > mu_q && mu_q > 0 && n_q - mu_q - n_q * trk_log(n_q / mu_q) < log_size) rho = rho_q;
        }
    }
    /* the estimator's documented bounds (trk_clutter_map_params) */
    if (rho < mp->min_ratio) rho = mp->min_ratio;
    if (rho > mp->max_ratio) rho = mp->max_ratio;
    return lambda * rho;
}

void trk_i_map_forget(const struct trk_clutter_map_params *mp, trk_real *count, trk_real *scans)
{
    const trk_real keep = 1 - 1 / mp->time_constant_scans;
    const size_t n = (size_t)mp->n_range * mp->n_bearing;
    for (size_t c = 0; c < n; c++) count[c] *= keep;
    *scans = *scans * keep + 1;
}
