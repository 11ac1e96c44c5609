/* test_clutter_map.c - each sensor's clutter map (trk/tracker.h, struct
 * trk_clutter_map_params; docs/tracker.md "Clutter map"):
 *   - after K scans of the same detections, a cell's density is the
 *     configured one times the Gamma-Poisson ratio (N + a) / (e W + a) with
 *     N and W the closed-form weighted sums and e the cell's exact area
 *     times the density; an empty cell's ratio falls to the floor, a busy
 *     one's rises to the ceiling; outside the coverage the configured
 *     density holds;
 *   - a cell's e integrates the clutter profile (a 1/r density: the
 *     two-point rule is exact);
 *   - the edge rule: a quadrant of the window (with the position's cell)
 *     whose count the window's ratio does not explain (the Chernoff bound
 *     on its Poisson tail below edge_alpha / 4) gives its own ratio, the
 *     greatest such (the estimator computed here from the closed-form
 *     counts; the bound checked against the exact tail), over a sector,
 *     all round, and all round with a window wider than the map; the size
 *     divided among the quadrants; edge_alpha 0 is the window's ratio;
 *   - the detections of a confirmed track's gate are not counted: from the
 *     scan after its confirmation its cell only forgets;
 *   - a polar scan and the same scan as Cartesian detections count alike;
 *   - a scan of twice the capacity, thinned, counts the whole scan (each
 *     kept detection weighted by 1 / the kept share);
 *   - the parameter check names the field; the accessor's refusals;
 *   - Kennedy's clutter-density test weighs rho V_g with the map's density
 *     at the track's prediction (closed form of its window's entry);
 *   - the nonparametric density with detections of their own covariance:
 *     lambda = m_G / V_G with V_G the mean of the gated detections' own
 *     gate volumes (beta0 of a lone track, closed form). */
#include "trk_test.h"
#include "trk_test_sonar.h"
#include "trk/gate.h"
#include "trk/kalman.h"
#include "trk/tracker.h"

#define DEG (3.14159265358979323846 / 180)
#define SCAN_US(k) ((int64_t)(k) * 8000000)

static struct trk_tracker tk, tk2;

/* A polar sensor at the origin facing north, coverage 1-9 km +-60 deg,
 * lambda 1e-7 per m^2; a map of 4 x 4 cells (2 km x 30 deg), tau 10 scans,
 * a = 2, each position's ratio from its own cell alone (no window, so no
 * edge rule);
 * nothing is confirmed in fewer than 64 scans (M of N 64 / 64). */
static void map_params(struct trk_tracker_params *p)
{
    trk_test_polar_params(p, 1e-7);
    struct trk_sensor_params *s = &p->sensor[0];
    s->coverage.min_range_m = 1000;
    s->coverage.max_range_m = 9000;
    s->coverage.half_width_rad = (trk_real)(60 * DEG);
    p->clutter_map.n_range = 4;
    p->clutter_map.n_bearing = 4;
    p->clutter_map.time_constant_scans = 10;
    p->clutter_map.prior_count = 2;
    p->clutter_map.min_ratio = TRK_REAL_C(0.1);
    p->clutter_map.max_ratio = 100;
    p->clutter_map.window_cells = 0;
    p->clutter_map.guard_cells = 0;
    p->clutter_map.edge_alpha = 0;
    p->confirm.method = TRK_CONFIRM_MN;
    p->confirm.u.mn.m = 64;
    p->confirm.u.mn.n = 64;
    p->confirm.u.mn.mode = TRK_MN_FIXED;
    p->term.method = TRK_TERM_KN;
    p->term.u.kn.k = 0;
    p->term.u.kn.n = 64;
}

static double polar_x(double r, double b_deg) { return r * sin(b_deg * DEG); }
static double polar_y(double r, double b_deg) { return r * cos(b_deg * DEG); }

/* W, the map's weighted number of scans after K scans (tau 10). */
static double scans_weight(int K)
{
    double W = 0;
    for (int k = 0; k < K; k++) W = W * (1 - 1.0 / 10) + 1;
    return W;
}

/* The map's ratio after K scans of c detections per scan in a cell of
 * rows [ra, rb] (m), 30 deg wide, lambda 1e-7: (N + a) / (e W + a). */
static double ratio_after(int K, double c, double ra, double rb)
{
    const double W = scans_weight(K);
    const double e = 1e-7 * (30 * DEG) * (rb * rb - ra * ra) / 2;
    return (c * W + 2) / (e * W + 2);
}

static double lambda_at(const struct trk_tracker *t, double x, double y)
{
    trk_real l = 0;
    TRK_ASSERT_OK(trk_tracker_clutter_at(t, 0, NULL, (trk_real)x, (trk_real)y, &l));
    return (double)l;
}

/* K scans of the same n polar detections, none confirmed. */
static void run_fixed_scans(struct trk_tracker *t, const struct trk_polar_detection *d, size_t n, int K)
{
    for (int k = 0; k < K; k++) {
        const struct trk_scan s = {SCAN_US(k), 0, n, NULL, d, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(t, &s, &rep));
        assert_int_equal(rep.n_confirmed, 0);
    }
}

/* Each scan three detections in cell (row 1, column 2) and twelve in
 * cell (0, 0), at fixed spots, and with lone = 1 one in cell (3, 3), as a
 * slow target's (tentative tracks, none confirmed). */
static void run_busy_cells(struct trk_tracker *t, int K, int lone)
{
    struct trk_polar_detection d[16];
    memset(d, 0, sizeof d);
    for (int i = 0; i < 3; i++) d[i].range_m = (trk_real)(3500 + 400 * i), d[i].bearing_rad = (trk_real)((5 + 8 * i) * DEG);
    for (int i = 3; i < 15; i++) d[i].range_m = (trk_real)(1200 + 100 * i), d[i].bearing_rad = (trk_real)(-55 * DEG);
    d[15].range_m = 8000, d[15].bearing_rad = (trk_real)(45 * DEG);
    run_fixed_scans(t, d, (size_t)(15 + lone), K);
}

/* map_params with a window and a guard of one cell, the ratio's bounds
 * wide (0.01, 1000), the edge rule at edge_alpha; all_round: a coverage
 * without a sector (4 x 4 cells of 90 deg). */
/* tk on parameters p and tk2 on q, each through K scans of the busy cells
 * (with the lone one): the same detections, one setting apart. */
static void busy_pair(const struct trk_tracker_params *p, const struct trk_tracker_params *q, int K)
{
    TRK_ASSERT_OK(trk_tracker_init(&tk, p));
    TRK_ASSERT_OK(trk_tracker_init(&tk2, q));
    run_busy_cells(&tk, K, 1);
    run_busy_cells(&tk2, K, 1);
}

static void window_params(struct trk_tracker_params *p, trk_real edge_alpha, int all_round)
{
    map_params(p);
    if (all_round) p->sensor[0].coverage.half_width_rad = 0;
    p->clutter_map.min_ratio = TRK_REAL_C(0.01);
    p->clutter_map.max_ratio = 1000;
    p->clutter_map.window_cells = 1;
    p->clutter_map.guard_cells = 1;
    p->clutter_map.edge_alpha = edge_alpha;
}

/* K scans of three detections at -170 deg, 3.5-4.3 km (row 1). */
static void run_at_minus_170(struct trk_tracker *t, int K)
{
    struct trk_polar_detection d[3];
    memset(d, 0, sizeof d);
    for (int i = 0; i < 3; i++) d[i].range_m = (trk_real)(3500 + 400 * i), d[i].bearing_rad = (trk_real)(-170 * DEG);
    run_fixed_scans(t, d, 3, K);
}

/* Three detections in cell (row 1: 3-5 km, column 2: 0..30 deg) and
 * twelve in cell (row 0, column 0) every scan, at fixed spots (they start
 * tentative tracks, none confirmed). */
static void test_closed_form(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    p.clutter_map.max_ratio = 20;
    p.clutter_map.min_ratio = TRK_REAL_C(0.25);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const int K = 25;
    run_busy_cells(&tk, K, 0);
    const double tol = TRK_TOL(1e-12, 2e-5);
    /* the busy cell, at its centre and at a corner */
    const double want = 1e-7 * ratio_after(K, 3, 3000, 5000);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 15), polar_y(4000, 15)), want, 0, tol);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(3010, 1), polar_y(3010, 1)), want, 0, tol);
    assert_true(want > 3e-7); /* what the test is about: the map rose */
    /* twelve per scan in the smallest cell: the ceiling */
    assert_true(ratio_after(K, 12, 1000, 3000) > 20);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(2000, -45), polar_y(2000, -45)), 1e-7 * 20, 0, tol);
    /* an empty far cell: a / (e W + a), below the floor */
    const double empty = ratio_after(K, 0, 7000, 9000);
    assert_true(empty < 0.25);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(8000, 45), polar_y(8000, 45)), 1e-7 * 0.25, 0, tol);
    /* an empty near cell: above the floor */
    const double near = ratio_after(K, 0, 1000, 3000);
    assert_true(near > 0.25 && near < 1);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(2000, 45), polar_y(2000, 45)), 1e-7 * near, 0, tol);
    /* outside the coverage: the configured density */
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(9500, 0), polar_y(9500, 0)), (double)TRK_REAL_C(1e-7), 0, 0);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 70), polar_y(4000, 70)), (double)TRK_REAL_C(1e-7), 0, 0);
    /* the same position from another pose is another cell (the sensor's frame) */
    const struct trk_pose turned = {0, 0, (trk_real)(-40 * DEG)};
    trk_real l = 0;
    TRK_ASSERT_OK(trk_tracker_clutter_at(&tk, 0, &turned, (trk_real)polar_x(4000, 15), (trk_real)polar_y(4000, 15), &l));
    TRK_ASSERT_NEAR((double)l, 1e-7 * ratio_after(K, 0, 3000, 5000), 0, tol); /* column 3: empty */
}

/* A cell's expected count per scan: row `row` (2 km from 1 km), col_deg
 * degrees wide, lambda 1e-7. */
static double cell_e(int row, double col_deg)
{
    const double ra = 1000 + 2000 * row, rb = ra + 2000;
    return 1e-7 * (col_deg * DEG) * (rb * rb - ra * ra) / 2;
}

/* The pooled ratio (sum N + a) / (sum e W + a) after K scans over training
 * cells holding n detections per scan in all, with cells_in_row[i] cells of row i
 * (rows of 2 km from 1 km, 30 deg wide, lambda 1e-7). */
static double pooled_ratio(int K, double n, const int cells_in_row[4])
{
    const double W = scans_weight(K);
    double e = 0;
    for (int i = 0; i < 4; i++) e += cells_in_row[i] * cell_e(i, 30);
    return (n * W + 2) / (e * W + 2);
}

/* A window of one cell with a guard of one (the defaults): a position's
 * ratio pools the nine cells of its window, cut at the map's edges, its
 * own cell's count less one detection per scan; without the guard, the
 * nine as they are. */
static void test_window_and_guard(void **state)
{
    (void)state;
    struct trk_tracker_params p, q;
    window_params(&p, 0, 0);
    q = p;
    q.clutter_map.guard_cells = 0;
    const int K = 25;
    busy_pair(&p, &q, K);
    const double tol = TRK_TOL(1e-12, 2e-5);
    /* the lone detection's cell (3, 3): its window rows 2-3 x columns 2-3;
     * the guard takes its one per scan away, as a target's */
    const int lone_33[4] = {0, 0, 2, 2};
    const double guarded = pooled_ratio(K, 0, lone_33), open = pooled_ratio(K, 1, lone_33);
    assert_true(guarded < 0.2 && open > 0.3); /* what the guard is about */
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(8000, 45), polar_y(8000, 45)), 1e-7 * guarded, 0, tol);
    TRK_ASSERT_NEAR(lambda_at(&tk2, polar_x(8000, 45), polar_y(8000, 45)), 1e-7 * open, 0, tol);
    /* the busy cell (1, 2), window rows 0-2 x columns 1-3: its three per
     * scan less one still raise it (clutter, not a point target) */
    const int block_12[4] = {3, 3, 3, 0};
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 15), polar_y(4000, 15)), 1e-7 * pooled_ratio(K, 2, block_12), 0, tol);
    TRK_ASSERT_NEAR(lambda_at(&tk2, polar_x(4000, 15), polar_y(4000, 15)), 1e-7 * pooled_ratio(K, 3, block_12), 0, tol);
    assert_true(pooled_ratio(K, 2, block_12) > 2 * pooled_ratio(K, 0, block_12)); /* not taken away */
    /* cell (1, 1) sees both busy cells, (0, 0) and (1, 2); its own empty
     * count stays 0 */
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, -15), polar_y(4000, -15)), 1e-7 * pooled_ratio(K, 15, block_12), 0,
                    tol);
    /* the corner cell (0, 3): its window cut to rows 0-1 x columns 2-3 */
    const int corner_03[4] = {2, 2, 0, 0};
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(2000, 45), polar_y(2000, 45)), 1e-7 * pooled_ratio(K, 3, corner_03), 0, tol);
    /* a map of one cell: its window is the cell, all guard: 16 per scan
     * less one over the whole coverage's expected count */
    window_params(&p, 0, 0);
    p.clutter_map.n_range = p.clutter_map.n_bearing = 1;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    run_busy_cells(&tk, K, 1);
    const int all[4] = {4, 4, 4, 4};
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 15), polar_y(4000, 15)), 1e-7 * pooled_ratio(K, 15, all), 0, tol);
    /* a map all round (no sector; 4 x 4 cells of 90 deg): the window wraps
     * in bearing, so the column at +170 deg pools the one at -170 deg */
    window_params(&p, 0, 1);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    run_at_minus_170(&tk, K);
    const int block_90[4] = {9, 9, 9, 0}; /* rows 0-2, three columns of 90 deg */
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 170), polar_y(4000, 170)), 1e-7 * pooled_ratio(K, 3, block_90), 0,
                    tol);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, -100), polar_y(4000, -100)), 1e-7 * pooled_ratio(K, 2, block_90), 0,
                    tol); /* its own column: three per scan less one */
}

/* P(N >= k) of a Poisson count of mean mu, by its terms (k >= 1). */
static double poisson_tail(double k, double mu)
{
    double below = 0, term = exp(-mu);
    for (int i = 0; i < (int)ceil(k); i++) {
        below += term;
        term *= mu / (i + 1);
    }
    return 1 - below;
}

/* The Chernoff bound on it, exp(n - mu - n ln(n / mu)) for n > mu. */
static double chernoff(double n, double mu) { return exp(n - mu - n * log(n / mu)); }

/* The estimator at cell (r0, b0) of a map of 4 rows (2 km from 1 km) and
 * 4 columns of col_deg degrees (wrap: all round), lambda 1e-7, a = 2, a
 * window of w cells and a guard of one, after K scans of c[r][b]
 * detections per scan in each cell (N = c W): the window's ratio, or the
 * greatest ratio of a quadrant whose count's Poisson tail bound under the
 * window's ratio is below alpha / 4 (alpha 0: the window's). All round
 * with 2 w >= 4 the window holds each column once, offsets -1 .. 2, the
 * opposite column (+2) on both sides. */
static double edge_ratio(int K, const double c[4][4], int r0, int b0, double col_deg, int wrap, int w, double alpha)
{
    const double W = scans_weight(K);
    const int wide = wrap && 2 * w >= 4, db_lo = wide ? -1 : -w, db_hi = wide ? 2 : w;
    double n_tr[5] = {0}, n_gd[5] = {0}, e[5] = {0}; /* [4]: the window, [0..3] the quadrants */
    for (int dr = -w; dr <= w; dr++)
        for (int db = db_lo; db <= db_hi; db++) {
            const int r = r0 + dr;
            int b = b0 + db;
            if (wrap) b = (b + 4) % 4;
            if (r < 0 || r > 3 || b < 0 || b > 3) continue;
            const double e_c = cell_e(r, col_deg), n = c[r][b] * W;
            const int guard = dr == 0 && db == 0, left = db <= 0 || (wide && db == 2);
            for (int q = 0; q < 5; q++) {
                if (q < 4 && !((q & 1 ? dr >= 0 : dr <= 0) && (q & 2 ? db >= 0 : left))) continue;
                *(guard ? &n_gd[q] : &n_tr[q]) += n;
                e[q] += e_c;
            }
        }
    double n_q[5], rho_q[5];
    for (int q = 0; q < 5; q++) {
        n_q[q] = n_tr[q] + (n_gd[q] > W ? n_gd[q] - W : 0);
        rho_q[q] = (n_q[q] + 2) / (e[q] * W + 2);
    }
    double rho = rho_q[4];
    for (int q = 0; q < 4 && alpha > 0; q++) {
        const double mu = rho_q[4] * e[q] * W;
        if (!(rho_q[q] > rho && n_q[q] > mu)) continue;
        assert_true(poisson_tail(n_q[q], mu) <= chernoff(n_q[q], mu)); /* a bound */
        if (chernoff(n_q[q], mu) < alpha / 4) rho = rho_q[q];
    }
    return rho;
}

/* The edge rule (edge_alpha 0.2, window and guard of one cell): where a
 * quadrant of the window holds significantly more than the window's
 * ratio predicts, the position takes the greatest such quadrant's ratio;
 * with edge_alpha 0 the window's. The busy cells of run_busy_cells: three
 * per scan in (1, 2), twelve in (0, 0), one in (3, 3). */
static void test_edge_rule(void **state)
{
    (void)state;
    struct trk_tracker_params p, q;
    window_params(&p, TRK_REAL_C(0.2), 0);
    q = p;
    q.clutter_map.edge_alpha = 0;
    const int K = 25;
    busy_pair(&p, &q, K);
    const double c[4][4] = {{12, 0, 0, 0}, {0, 0, 3, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}};
    const double tol = TRK_TOL(1e-12, 2e-5);
    /* cell (1, 1), between the two busy cells: its quadrant of rows 0-1 x
     * columns 0-1 holds the twelve per scan, far beyond what the window's
     * ratio explains, and gives its ratio: over twice the window's */
    const double win_11 = edge_ratio(K, c, 1, 1, 30, 0, 1, 0), edge_11 = edge_ratio(K, c, 1, 1, 30, 0, 1, 0.2);
    const int quad_11[4] = {2, 2, 0, 0};
    TRK_ASSERT_NEAR(edge_11, pooled_ratio(K, 12, quad_11), 0, 1e-12); /* the estimator here, by hand */
    assert_true(edge_11 > 2 * win_11);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, -15), polar_y(4000, -15)), 1e-7 * edge_11, 0, tol);
    TRK_ASSERT_NEAR(lambda_at(&tk2, polar_x(4000, -15), polar_y(4000, -15)), 1e-7 * win_11, 0, tol);
    /* the busy cell (1, 2) itself: its two per scan (three less the guard's
     * one) in each of its quadrants; the nearer rows' (smaller cells) is
     * the greatest */
    const double edge_12 = edge_ratio(K, c, 1, 2, 30, 0, 1, 0.2);
    assert_true(edge_12 > edge_ratio(K, c, 1, 2, 30, 0, 1, 0));
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 15), polar_y(4000, 15)), 1e-7 * edge_12, 0, tol);
    /* ... and at edge_alpha 1e-3 that quadrant's bound (e^-7.4) is above
     * 1e-3 / 4 (e^-8.3), though below 1e-3: the window's ratio (the size
     * is divided among the four quadrants) */
    p.clutter_map.edge_alpha = TRK_REAL_C(1e-3);
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    run_busy_cells(&tk2, K, 1);
    const double win_12 = edge_ratio(K, c, 1, 2, 30, 0, 1, 0);
    TRK_ASSERT_NEAR(edge_ratio(K, c, 1, 2, 30, 0, 1, 1e-3), win_12, 0, 0);
    assert_true(edge_ratio(K, c, 1, 2, 30, 0, 1, 4e-3) > win_12);
    TRK_ASSERT_NEAR(lambda_at(&tk2, polar_x(4000, 15), polar_y(4000, 15)), 1e-7 * win_12, 0, tol);
    /* the lone detection's cell (3, 3), a target's: the guard takes it, no
     * quadrant stands out, the window's ratio; the same at the empty cell
     * (2, 0) */
    TRK_ASSERT_NEAR(edge_ratio(K, c, 3, 3, 30, 0, 1, 0.2), edge_ratio(K, c, 3, 3, 30, 0, 1, 0), 0, 0);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(8000, 45), polar_y(8000, 45)), 1e-7 * edge_ratio(K, c, 3, 3, 30, 0, 1, 0), 0,
                    tol);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(6000, -45), polar_y(6000, -45)), 1e-7 * edge_ratio(K, c, 2, 0, 30, 0, 1, 0.2),
                    0, tol);
    /* all round (4 columns of 90 deg): three per scan at -170 deg; at +170
     * deg the quadrant of columns +170 and (wrapping) -170 stands out */
    window_params(&p, TRK_REAL_C(0.2), 1);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    run_at_minus_170(&tk, K);
    const double c_round[4][4] = {{0, 0, 0, 0}, {3, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
    const double edge_13 = edge_ratio(K, c_round, 1, 3, 90, 1, 1, 0.2);
    assert_true(edge_13 > edge_ratio(K, c_round, 1, 3, 90, 1, 1, 0));
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 170), polar_y(4000, 170)), 1e-7 * edge_13, 0, tol);
    /* a window of two cells all round: each of the 4 columns once, the one
     * opposite the position's on both sides; at +80 deg (column 2) the
     * busy column 0 is that one, and rows 0-3 are all in */
    window_params(&p, TRK_REAL_C(0.2), 1);
    p.clutter_map.window_cells = 2;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    run_at_minus_170(&tk, K);
    const double edge_wide = edge_ratio(K, c_round, 1, 2, 90, 1, 2, 0.2);
    assert_true(edge_wide > edge_ratio(K, c_round, 1, 2, 90, 1, 2, 0));
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(4000, 80), polar_y(4000, 80)), 1e-7 * edge_wide, 0, tol);
}

/* With a 1/r clutter profile, a cell's expected count is lambda(r) r
 * integrated exactly: one detection per scan in a cell keeps lambda(r) x
 * ratio, ratio with e = c0 dtheta (rb - ra) for lambda = c0 / r. */
static void test_profile_integral(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    struct trk_clutter_profile *cp = &p.sensor[0].clutter_profile;
    const double c0 = 1e-4; /* lambda = c0 / r: 1e-7 at 1 km */
    cp->n = 2;
    cp->range_m[0] = 1000, cp->density_per_m2[0] = (trk_real)(c0 / 1000);
    cp->range_m[1] = 9000, cp->density_per_m2[1] = (trk_real)(c0 / 9000);
    /* linear between the points is not 1/r: compare with the profile's own
     * linear density, integrated exactly (the rule is exact for a cubic) */
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_polar_detection d = {5500, (trk_real)(-20 * DEG), 0, 0};
    const int K = 12;
    for (int k = 0; k < K; k++) {
        const struct trk_scan s = {SCAN_US(k), 0, 1, NULL, &d, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, NULL));
    }
    /* lambda(r) = l0 + s (r - 1000): int over [5000, 7000] of lambda r dr */
    const double l0 = c0 / 1000, sl = (c0 / 9000 - c0 / 1000) / 8000;
    const double ra = 5000, rb = 7000;
    const double I = (l0 - sl * 1000) * (rb * rb - ra * ra) / 2 + sl * (rb * rb * rb - ra * ra * ra) / 3;
    const double e = (30 * DEG) * I;
    const double W = scans_weight(K);
    const double rho = (W + 2) / (e * W + 2);
    const double r = 6000, lam = l0 + sl * (r - 1000);
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(r, -15), polar_y(r, -15)), lam * rho, 0, TRK_TOL(1e-12, 2e-5));
}

/* A target standing at 4 km, 15 deg, detected every scan without noise:
 * its track confirms (the default confirmation); from the scan after that
 * its detections are in a confirmed track's gate and not counted. */
static void test_confirmed_not_counted(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    p.confirm.method = TRK_CONFIRM_MN; /* 3 of 5: confirmed at a known scan */
    p.confirm.u.mn.m = 3;
    p.confirm.u.mn.n = 5;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const struct trk_polar_detection d = {4000, (trk_real)(15 * DEG), 0, 0};
    const int K = 20;
    int kc = -1; /* the scan whose update confirmed the track */
    for (int k = 0; k < K; k++) {
        const struct trk_scan s = {SCAN_US(k), 0, 1, NULL, &d, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
        if (rep.n_confirmed > 0) {
            assert_int_equal(kc, -1);
            kc = k;
        }
    }
    assert_true(kc > 0 && kc < K - 5);
    /* counted: scans 0 .. kc (the detection of scan kc was gated while the
     * track was still tentative); then only forgotten */
    const double keep = 0.9;
    double N = 0, W = 0;
    for (int k = 0; k < K; k++) {
        N = N * keep + (k <= kc ? 1 : 0);
        W = W * keep + 1;
    }
    const double e = 1e-7 * (30 * DEG) * (5000.0 * 5000 - 3000.0 * 3000) / 2;
    TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(3100, 29), polar_y(3100, 29)), 1e-7 * (N + 2) / (e * W + 2), 0,
                    TRK_TOL(1e-12, 2e-5));
}

/* The same detections as a polar scan and as the caller's conversion give
 * the same map (and tables). */
static void test_polar_equals_cartesian(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    uint64_t rng = 7;
    const struct trk_pose o = {0, 0, 0};
    for (int k = 0; k < 10; k++) {
        struct trk_polar_detection d[20];
        struct trk_detection c[20];
        for (int i = 0; i < 20; i++) {
            d[i].range_m = (trk_real)(1000 + 8000 * trk_test_urand(&rng));
            d[i].bearing_rad = (trk_real)((-60 + 120 * trk_test_urand(&rng)) * DEG);
            d[i].has_amplitude = 0;
            d[i].amplitude = 0;
            TRK_ASSERT_OK(trk_polar_to_cartesian(&p.sensor[0], &o, &d[i], &c[i]));
        }
        const struct trk_scan sp = {SCAN_US(k), 0, 20, NULL, d, 0, {0, 0, 0}, NULL};
        const struct trk_scan sc = {SCAN_US(k), 0, 20, c, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &sp, NULL));
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &sc, NULL));
    }
    for (int i = 0; i < 40; i++) {
        const double r = 1000 + 200 * i, b = -58 + 3 * i;
        TRK_ASSERT_NEAR(lambda_at(&tk, polar_x(r, b), polar_y(r, b)), lambda_at(&tk2, polar_x(r, b), polar_y(r, b)),
                        0, TRK_TOL(1e-12, 1e-5));
    }
}

/* A scan of twice the capacity (no amplitudes: the deterministic thinning)
 * counts each kept detection 1 / (its kept share): the cells' counts add up
 * to the whole scan's, N_c = rho_c (e_c W + a) - a with W = 1. */
static void test_thinned_scan_counts_all(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    p.clutter_map.min_ratio = TRK_REAL_C(1e-6);
    p.clutter_map.max_ratio = TRK_REAL_C(1e6);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    enum { N = 2 * TRK_MAX_DETECTIONS };
    static struct trk_polar_detection d[N];
    uint64_t rng = 3;
    for (int i = 0; i < N; i++) {
        d[i].range_m = (trk_real)(1000 + 8000 * trk_test_urand(&rng));
        d[i].bearing_rad = (trk_real)((-59 + 118 * trk_test_urand(&rng)) * DEG);
        d[i].has_amplitude = 0;
        d[i].amplitude = 0;
    }
    const struct trk_scan s = {SCAN_US(0), 0, N, NULL, d, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
    assert_true(rep.n_thinned > 0);
    assert_int_equal(rep.n_kept + rep.n_thinned, N);
    double total = 0;
    for (int ir = 0; ir < 4; ir++)
        for (int ib = 0; ib < 4; ib++) {
            const double ra = 1000 + 2000.0 * ir, rb = ra + 2000, b = -45 + 30 * ib;
            const double e = 1e-7 * (30 * DEG) * (rb * rb - ra * ra) / 2;
            const double rho = lambda_at(&tk, polar_x(ra + 1000, b), polar_y(ra + 1000, b)) / 1e-7;
            total += rho * (e + 2) - 2;
        }
    TRK_ASSERT_NEAR(total, (double)N, 0, TRK_TOL(1e-9, 1e-4));
}

/* The parameter check refuses p with status st, naming field name. */
static void assert_refused(const struct trk_tracker_params *p, trk_status st, const char *name)
{
    const char *field = NULL;
    TRK_ASSERT_STATUS(trk_tracker_check_params(p, &field), st);
    assert_string_equal(field, name);
}

static void test_params_and_refusals(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    map_params(&p);
    p.clutter_map.n_range = TRK_CLUTTER_MAP_CELLS + 1;
    p.clutter_map.n_bearing = 1;
    assert_refused(&p, TRK_E_CAPACITY, "clutter_map.n_range");
    map_params(&p);
    p.clutter_map.n_bearing = 0;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.n_bearing");
    map_params(&p);
    p.clutter_map.time_constant_scans = TRK_REAL_C(0.5);
    assert_refused(&p, TRK_E_RANGE, "clutter_map.time_constant_scans");
    map_params(&p);
    p.clutter_map.prior_count = 0;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.prior_count");
    map_params(&p);
    p.clutter_map.prior_count = TRK_REAL_MIN / 4; /* subnormal */
    assert_refused(&p, TRK_E_RANGE, "clutter_map.prior_count");
    map_params(&p);
    p.clutter_map.min_ratio = (trk_real)NAN;
    assert_refused(&p, TRK_E_NAN, "clutter_map.min_ratio");
    map_params(&p);
    p.clutter_map.min_ratio = TRK_REAL_MIN / 4;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.min_ratio");
    /* the map's floor, density x min_ratio, would underflow: the cell would read 0 */
    map_params(&p);
    p.clutter_map.min_ratio = TRK_REAL_C(1e-3);
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_MIN * 100;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.min_ratio");
    p.clutter_map.min_ratio = TRK_REAL_C(0.1); /* 10 x the smallest normal: a floor that is normal */
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    /* beyond a clutter profile's bound (a cell's expected count would overflow) */
    map_params(&p);
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(2e6);
    assert_refused(&p, TRK_E_RANGE, "sensor[0].clutter_density_per_m2");
    map_params(&p);
    p.clutter_map.max_ratio = TRK_REAL_C(0.5);
    assert_refused(&p, TRK_E_RANGE, "clutter_map.max_ratio");
    map_params(&p);
    p.clutter_map.window_cells = TRK_CLUTTER_MAP_WINDOW_MAX + 1;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.window_cells");
    map_params(&p);
    p.clutter_map.window_cells = 1;
    p.clutter_map.guard_cells = 3;
    assert_refused(&p, TRK_E_RANGE, "clutter_map.guard_cells");
    const trk_real bad_alpha[] = {-TRK_REAL_C(0.1), 1, TRK_REAL_MIN / 4};
    for (size_t i = 0; i < sizeof bad_alpha / sizeof bad_alpha[0]; i++) {
        map_params(&p);
        p.clutter_map.edge_alpha = bad_alpha[i];
        assert_refused(&p, TRK_E_RANGE, "clutter_map.edge_alpha");
    }
    map_params(&p);
    p.clutter_map.edge_alpha = (trk_real)NAN;
    assert_refused(&p, TRK_E_NAN, "clutter_map.edge_alpha");
    map_params(&p); /* no cells: no map, the rest unread */
    p.clutter_map.n_range = p.clutter_map.n_bearing = 0;
    p.clutter_map.prior_count = 0;
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    TRK_ASSERT_NEAR(lambda_at(&tk, 0, 4000), (double)TRK_REAL_C(1e-7), 0, 0);
    trk_real l;
    TRK_ASSERT_STATUS(trk_tracker_clutter_at(NULL, 0, NULL, 0, 0, &l), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_tracker_clutter_at(&tk, 0, NULL, 0, 0, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_tracker_clutter_at(&tk, 1, NULL, 0, 0, &l), TRK_E_SENSOR);
    TRK_ASSERT_STATUS(trk_tracker_clutter_at(&tk, 0, NULL, (trk_real)NAN, 0, &l), TRK_E_NAN);
}

/* A lone track at rest at the origin (own covariance 25 I each scan), then
 * two detections with different own covariances in its gate: beta0 =
 * b / (b + e_1 + e_2), e_j = P_D N(nu_j; 0, S_j), b = lambda (1 - P_D P_G),
 * lambda = 2 / ((V_1 + V_2) / 2), V_j = pi gamma sqrt(det S_j). */
static void test_nonparametric_own_volumes(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_test_sonar_params(&p, 1e-6);
    p.stationary_d2 = 0;
    p.association = TRK_ASSOC_PDA;
    p.clutter = TRK_CLUTTER_NONPARAMETRIC;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    struct trk_detection d[2];
    memset(d, 0, sizeof d);
    d[0].has_cov = 1;
    d[0].cov_m2[TRK_COV2_XX] = d[0].cov_m2[TRK_COV2_YY] = 25;
    for (int k = 0; k < 12; k++) {
        const struct trk_scan s = {SCAN_US(k), 0, 1, d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, NULL));
    }
    const struct trk_track *tr = trk_tracker_track(&tk, 0);
    assert_non_null(tr);
    assert_true(tr->status == TRK_TRACK_TENTATIVE || tr->status == TRK_TRACK_CONFIRMED);
    trk_real x[TRK_CV2_NX], pp[TRK_CV2_NX * TRK_CV2_NX];
    memcpy(x, tr->x, sizeof x);
    memcpy(pp, tr->p, sizeof pp);
    TRK_ASSERT_OK(trk_cv2_predict(8, p.process_noise_q, x, pp));
    const double zx[2] = {3, -2}, zy[2] = {-1, 4}, rxx[2] = {4, 60}, rxy[2] = {1, -10}, ryy[2] = {9, 30};
    for (int j = 0; j < 2; j++) {
        d[j].x_m = (trk_real)zx[j], d[j].y_m = (trk_real)zy[j];
        d[j].has_cov = 1;
        d[j].cov_m2[TRK_COV2_XX] = (trk_real)rxx[j];
        d[j].cov_m2[TRK_COV2_XY] = (trk_real)rxy[j];
        d[j].cov_m2[TRK_COV2_YY] = (trk_real)ryy[j];
    }
    const struct trk_scan s = {SCAN_US(12), 0, 2, d, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
    const double gamma = -2 * log(1 - (double)p.gate_prob), pd = (double)p.sensor[0].pd;
    double vsum = 0, esum = 0;
    for (int j = 0; j < 2; j++) {
        const double sxx = pp[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + rxx[j], sxy = pp[TRK_CV2_P(TRK_CV2_X, TRK_CV2_Y)] + rxy[j];
        const double syy = pp[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)] + ryy[j], det = sxx * syy - sxy * sxy;
        const double nx = zx[j] - x[TRK_CV2_X], ny = zy[j] - x[TRK_CV2_Y];
        const double d2 = (syy * nx * nx - 2 * sxy * nx * ny + sxx * ny * ny) / det;
        assert_true(d2 < gamma); /* both gated */
        vsum += 3.14159265358979323846 * gamma * sqrt(det);
        esum += pd * exp(-0.5 * d2) / (2 * 3.14159265358979323846 * sqrt(det));
    }
    const double lambda = 2 / (vsum / 2), b = lambda * (1 - pd * (double)p.gate_prob);
    TRK_ASSERT_NEAR(tr->beta0_last, b / (b + esum), 0, TRK_TOL(1e-9, 1e-4));
}

#if TRK_WITH_CLUTTER_TESTS
/* A tentative track's clutter-density test (Kennedy eqs 5-9) takes rho V_g
 * with rho the density at the track as its PDA weights do, the map's: each
 * look's window entry is lambda_map(prediction) times the volume of the
 * ellipse through the scan's nearest detection, S = P_pred + R. A
 * Cartesian sensor (R 25 I) with the map's coverage, lambda 1e-5; a
 * target standing at 4 km, 15 deg (sigma 5 m), alone, every scan: its
 * cell's ratio falls to the floor 0.1 by scan 2 (the configured density
 * expects 42 detections a scan there). alpha 1e-12 keeps the first looks
 * tentative. */
static void test_clutter_test_takes_map_density(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    map_params(&p);
    struct trk_sensor_params *sp = &p.sensor[0];
    sp->kind = TRK_SENSOR_CARTESIAN;
    sp->meas_cov_m2[TRK_COV2_XX] = sp->meas_cov_m2[TRK_COV2_YY] = 25;
    sp->meas_cov_m2[TRK_COV2_XY] = 0;
    sp->clutter_density_per_m2 = TRK_REAL_C(1e-5);
    p.confirm.method = TRK_CONFIRM_CLUTTER_CHI2;
    p.confirm.u.chi2.alpha = TRK_REAL_C(1e-12);
    p.confirm.u.chi2.kmax = 25;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const double x0 = polar_x(4000, 15), y0 = polar_y(4000, 15);
    const trk_real h[8] = {1, 0, 0, 0, 0, 0, 1, 0}, r[4] = {25, 0, 0, 25};
    uint64_t rng = 3;
    int checked = 0;
    for (int k = 0; k < 5; k++) {
        /* the target's tentative track before the scan, predicted */
        const struct trk_track *tr = NULL;
        for (size_t i = 0; i < TRK_MAX_TRACKS && !tr; i++) {
            const struct trk_track *c = trk_tracker_track(&tk, i);
            if (c && c->status == TRK_TRACK_TENTATIVE &&
                hypot((double)c->x[TRK_CV2_X] - x0, (double)c->x[TRK_CV2_Y] - y0) < 50)
                tr = c;
        }
        trk_real x[TRK_CV2_NX], pp[TRK_CV2_NX * TRK_CV2_NX];
        double lambda = 0;
        const uint32_t id = tr ? tr->id : 0;
        if (tr) {
            memcpy(x, tr->x, sizeof x);
            memcpy(pp, tr->p, sizeof pp);
            TRK_ASSERT_OK(trk_cv2_predict(8, p.process_noise_q, x, pp));
            lambda = lambda_at(&tk, (double)x[TRK_CV2_X], (double)x[TRK_CV2_Y]);
        }
        struct trk_detection d[1];
        d[0] = trk_test_det_at(x0 + 5 * trk_test_nrand(&rng), y0 + 5 * trk_test_nrand(&rng));
        const struct trk_scan s = {SCAN_US(k), 0, 1, d, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
        if (!tr || tr->id != id || tr->status != TRK_TRACK_TENTATIVE) continue;
        struct trk_innovation inn;
        TRK_ASSERT_OK(trk_kalman_innovation(TRK_CV2_NX, TRK_CV2_NZ, h, r, x, pp, &inn));
        const trk_real nu[2] = {d[0].x_m - inn.z_pred[0], d[0].y_m - inn.z_pred[1]};
        const struct trk_clutter_chi2 *c = &tr->test.confirm.chi2;
        const double got = (double)c->win[(c->head + p.confirm.u.chi2.kmax - 1) % p.confirm.u.chi2.kmax];
        TRK_ASSERT_NEAR(got, lambda * (double)trk_gate_volume_inn(&inn, trk_gate_d2(&inn, nu)), 0, TRK_TOL(1e-9, 1e-3));
        assert_true(lambda < 0.5e-5); /* the map's density, not the configured one */
        checked++;
    }
    assert_true(checked >= 2);
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_form),
        cmocka_unit_test(test_window_and_guard),
        cmocka_unit_test(test_edge_rule),
        cmocka_unit_test(test_profile_integral),
        cmocka_unit_test(test_confirmed_not_counted),
        cmocka_unit_test(test_polar_equals_cartesian),
        cmocka_unit_test(test_thinned_scan_counts_all),
        cmocka_unit_test(test_params_and_refusals),
        cmocka_unit_test(test_nonparametric_own_volumes),
#if TRK_WITH_CLUTTER_TESTS
        cmocka_unit_test(test_clutter_test_takes_map_density),
#endif
    };
    return trk_run_tests("clutter_map", tests, NULL, NULL);
}
