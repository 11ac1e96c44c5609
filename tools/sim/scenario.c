/* scenario.c - seeded sonar scenario (scenario.h). */
#include "scenario.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <Random123/philox.h>

#include "trk/kalman.h"

void scen_defaults(struct scen_params *p)
{
    memset(p, 0, sizeof *p);
    p->seed = 1;
    p->sensor_id = 0;
    p->t0_us = 0;
    p->scan_period_s = 2;
    p->x_min_m = 0;
    p->x_max_m = 2000;
    p->y_min_m = 0;
    p->y_max_m = 2000;
    p->clutter_density_per_m2 = 5e-6;
    p->clutter_count = -1;
    p->pd = 0.9;
    p->meas_sigma_m = 3;
    p->attach_cov = 0;
    p->process_noise_q = 0.01;
    p->amp_kind = AMP_RAYLEIGH;
    p->pfa = 1e-3;
    p->k_shape = 1;
    p->snr_db = 15;
    p->n_targets = 3;
    p->targets = NULL;
    p->speed_min_mps = 1;
    p->speed_max_mps = 5;
    p->clutter_around_m = 0;
    p->fluct = 0;
    p->fluct_p = 0.1 / 3;
    p->fluct_q = 0.1;
    p->fluct_pd_low = 0.1;
}

void scen_free(struct scenario *s)
{
    free(s->tg);
    s->tg = NULL;
    s->n_tg = 0;
    free(s->field);
    s->field = NULL;
    amp_model_free(&s->amp);
}

int scen_init(struct scenario *s, const struct scen_params *p, char *err, size_t n)
{
    memset(s, 0, sizeof *s);
    if (!(p->scan_period_s > 0) || !isfinite(p->scan_period_s) || p->t0_us < 0) {
        snprintf(err, n, "scan period must be > 0 and t0 >= 0");
        return -1;
    }
    if (!(p->x_max_m > p->x_min_m) || !(p->y_max_m > p->y_min_m) || !isfinite(p->x_min_m) ||
        !isfinite(p->x_max_m) || !isfinite(p->y_min_m) || !isfinite(p->y_max_m)) {
        snprintf(err, n, "region must have x_min < x_max and y_min < y_max (finite)");
        return -1;
    }
    if (!(p->clutter_density_per_m2 >= 0) || !isfinite(p->clutter_density_per_m2)) {
        snprintf(err, n, "clutter density must be >= 0");
        return -1;
    }
    /* bounded work per scan (a 1e9 m region drew 5e12 clutter points a scan) */
    const double mean_clutter =
        p->clutter_density_per_m2 * (p->x_max_m - p->x_min_m) * (p->y_max_m - p->y_min_m);
    if (p->clutter_count > SCEN_MAX_CLUTTER || (p->clutter_count < 0 && p->clutter_around_m <= 0 &&
                                                !(mean_clutter <= SCEN_MAX_CLUTTER))) {
        snprintf(err, n,
                 "%.6g clutter detections per scan (density x region area) is more than %.0f: "
                 "a smaller region or density",
                 p->clutter_count >= 0 ? (double)p->clutter_count : mean_clutter, (double)SCEN_MAX_CLUTTER);
        return -1;
    }
    if (!(p->meas_sigma_m > 0) || !isfinite(p->meas_sigma_m) || !(p->process_noise_q >= 0) ||
        !isfinite(p->process_noise_q)) {
        snprintf(err, n, "measurement sigma must be > 0 and process noise q >= 0");
        return -1;
    }
    if (p->amp_kind == AMP_NONE && !(p->pd > 0 && p->pd <= 1)) {
        snprintf(err, n, "pd must be in (0, 1]");
        return -1;
    }
    if (!(p->speed_min_mps >= 0) || !(p->speed_max_mps >= p->speed_min_mps) ||
        !isfinite(p->speed_max_mps)) {
        snprintf(err, n, "speed range must be 0 <= min <= max");
        return -1;
    }
    if (p->n_targets > 100000) {
        snprintf(err, n, "too many targets");
        return -1;
    }
    if (!(p->clutter_around_m >= 0) || !isfinite(p->clutter_around_m)) {
        snprintf(err, n, "clutter_around_m must be >= 0");
        return -1;
    }
    if (p->fluct && !(p->fluct_p >= 0 && p->fluct_p <= 1 && p->fluct_q >= 0 && p->fluct_q <= 1 &&
                      p->fluct_p + p->fluct_q > 0 && p->fluct_pd_low >= 0 && p->fluct_pd_low <= 1)) {
        snprintf(err, n, "fluctuation: p, q and pd_low must be in [0, 1] with p + q > 0");
        return -1;
    }
    if (p->amp_kind == AMP_TABLE) {
        if (!p->amp_table || amp_model_init_table(&s->amp, p->amp_table, err, n) != 0) {
            if (!p->amp_table) snprintf(err, n, "amplitude table: no file given");
            return -1;
        }
    } else if (amp_model_init(&s->amp, p->amp_kind, p->pfa, p->k_shape, err, n) != 0) {
        return -1;
    }
    s->p = *p;
    s->p.targets = NULL;
    s->p.amp_table = NULL;
    s->p.target_end_scan = NULL;
    s->n_tg = p->n_targets;
    s->tg = calloc(s->n_tg ? s->n_tg : 1, sizeof *s->tg);
    if (!s->tg) {
        snprintf(err, n, "out of memory");
        amp_model_free(&s->amp);
        return -1;
    }
    rng_init(&s->motion, p->seed, 0);
    for (size_t i = 0; i < s->n_tg; i++) {
        struct scen_target *t = &s->tg[i];
        double snr = p->snr_db;
        if (p->targets) {
            const struct scen_target_init *ti = &p->targets[i];
            t->x[TRK_CV2_X] = ti->x_m;
            t->x[TRK_CV2_VX] = ti->vx_mps;
            t->x[TRK_CV2_Y] = ti->y_m;
            t->x[TRK_CV2_VY] = ti->vy_mps;
            if (!isnan(ti->snr_db)) snr = ti->snr_db;
            for (int k = 0; k < 4; k++)
                if (!isfinite(t->x[k])) {
                    snprintf(err, n, "target %zu: non-finite state", i);
                    scen_free(s);
                    return -1;
                }
        } else {
            const double sp = p->speed_min_mps +
                              (p->speed_max_mps - p->speed_min_mps) * rng_uniform(&s->motion);
            const double hd = 6.283185307179586 * rng_uniform(&s->motion);
            t->x[TRK_CV2_X] = p->x_min_m + (p->x_max_m - p->x_min_m) * rng_uniform(&s->motion);
            t->x[TRK_CV2_Y] = p->y_min_m + (p->y_max_m - p->y_min_m) * rng_uniform(&s->motion);
            t->x[TRK_CV2_VX] = sp * sin(hd);
            t->x[TRK_CV2_VY] = sp * cos(hd);
        }
        if (amp_target_init(&s->amp, snr, &t->amp) != 0) {
            snprintf(err, n, "target %zu: SNR %g dB not usable (must be in [-50, 80])", i, snr);
            scen_free(s);
            return -1;
        }
        t->pd = p->amp_kind == AMP_NONE ? p->pd : t->amp.pd;
        t->high = 1;
        t->end_scan = p->target_end_scan ? p->target_end_scan[i] : 0;
        if (t->end_scan < 0) {
            snprintf(err, n, "target %zu: end scan must be >= 0", i);
            scen_free(s);
            return -1;
        }
        if (p->fluct) t->high = rng_uniform(&s->motion) < p->fluct_p / (p->fluct_p + p->fluct_q);
    }
    if (p->clutter_around_m > 0) {
        s->field = malloc(sizeof *s->field);
        if (!s->field || scen_field_init(s->field, p->seed, p->clutter_density_per_m2, 0) != 0) {
            snprintf(err, n, s->field ? "clutter field: bad density" : "out of memory");
            scen_free(s);
            return -1;
        }
    }
    /* Q per axis from the tracker's model: [[q T^3/3, q T^2/2], [q T^2/2, q T]] */
    trk_real q[16];
    trk_cv2_process_noise((trk_real)p->scan_period_s, (trk_real)p->process_noise_q, q);
    const double q00 = (double)q[0], q01 = (double)q[1], q11 = (double)q[5];
    if (q00 > 0) {
        s->q_chol[0] = sqrt(q00);
        s->q_chol[1] = q01 / s->q_chol[0];
        const double r = q11 - s->q_chol[1] * s->q_chol[1];
        s->q_chol[2] = r > 0 ? sqrt(r) : 0;
    }
    s->k = 0;
    return 0;
}

static void move_targets(struct scenario *s)
{
    const double dt = s->p.scan_period_s;
    for (size_t i = 0; i < s->n_tg; i++) {
        double *x = s->tg[i].x;
        for (int ax = 0; ax < 2; ax++) {
            double *pos = &x[2 * ax], *vel = &x[2 * ax + 1];
            const double z1 = rng_normal(&s->motion), z2 = rng_normal(&s->motion);
            *pos += dt * *vel + s->q_chol[0] * z1;
            *vel += s->q_chol[1] * z1 + s->q_chol[2] * z2;
        }
        if (s->p.fluct) { /* one Markov transition per scan (Blanding eqs 1-2) */
            const double u = rng_uniform(&s->motion);
            s->tg[i].high = s->tg[i].high ? u >= s->p.fluct_q : u < s->p.fluct_p;
        }
    }
}

/* ---------------------------------------------------------------- clutter field */

int scen_field_init(struct scen_field *f, uint64_t seed, double density, double tile_m)
{
    if (!(density >= 0) || !isfinite(density) || !(tile_m >= 0) || !isfinite(tile_m)) return -1;
    f->seed = seed;
    f->density_per_m2 = density;
    f->tile_m = tile_m > 0 ? tile_m : density > 0 ? sqrt(4 / density) : 1;
    if (!(f->tile_m > 0) || !isfinite(f->tile_m)) return -1;
    return 0;
}

/* The random stream of tile (i, j) of (run, scan): see scenario.h. */
static void field_stream(const struct scen_field *f, uint32_t run, uint32_t scan, long i, long j,
                         struct rng *r)
{
    rng_init(r, f->seed ^ SCEN_FIELD_SALT, 0);
    r->ctr[0] = (uint32_t)(uint16_t)(i & 0xFFFF) | (uint32_t)(uint16_t)(j & 0xFFFF) << 16;
    r->ctr[1] = scan;
    r->ctr[2] = 0; /* block counter (rng.c increments ctr[2], carrying into ctr[3]) */
    r->ctr[3] = run;
}

/* Tile (i, j)'s points into pts (inside the window only), counting in *n. */
static void field_tile(const struct scen_field *f, double density, uint32_t run, uint32_t scan, long i,
                       long j, double x_lo, double x_hi, double y_lo, double y_hi,
                       struct scen_field_point *pts, size_t max, size_t *n)
{
    const double l = f->tile_m, x0 = (double)i * l, y0 = (double)j * l;
    struct rng r;
    field_stream(f, run, scan, i, j, &r);
    const unsigned long np = rng_poisson(&r, density * l * l);
    const int inside = x0 >= x_lo && x0 + l <= x_hi && y0 >= y_lo && y0 + l <= y_hi;
    for (unsigned long k = 0; k < np; k++) { /* one philox block per point */
        const double x = x0 + l * (((double)rng_u32(&r) + 0.5) * (1.0 / 4294967296.0));
        const double y = y0 + l * (((double)rng_u32(&r) + 0.5) * (1.0 / 4294967296.0));
        const double u = rng_uniform(&r);
        if (!inside && !(x >= x_lo && x < x_hi && y >= y_lo && y < y_hi)) continue;
        if (*n < max) pts[*n] = (struct scen_field_point){x, y, u};
        ++*n;
    }
}

size_t scen_field_window(const struct scen_field *f, uint32_t run, uint32_t scan, double x_lo,
                         double x_hi, double y_lo, double y_hi, struct scen_field_point *pts,
                         size_t max)
{
    return scen_field_window_at(f, f->density_per_m2, run, scan, x_lo, x_hi, y_lo, y_hi, pts, max);
}

size_t scen_field_window_at(const struct scen_field *f, double density, uint32_t run, uint32_t scan,
                            double x_lo, double x_hi, double y_lo, double y_hi,
                            struct scen_field_point *pts, size_t max)
{
    if (!isfinite(x_lo) || !isfinite(x_hi) || !isfinite(y_lo) || !isfinite(y_hi) || !isfinite(density))
        return SIZE_MAX;
    if (!(x_hi > x_lo) || !(y_hi > y_lo) || !(density > 0)) return 0;
    const double l = f->tile_m;
    const double i0 = floor(x_lo / l), i1 = floor(x_hi / l), j0 = floor(y_lo / l), j1 = floor(y_hi / l);
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > (double)SCEN_FIELD_MAX_TILES || fabs(i0) > 4e18 ||
        fabs(i1) > 4e18 || fabs(j0) > 4e18 || fabs(j1) > 4e18)
        return SIZE_MAX;
    size_t n = 0;
    for (long j = (long)j0; j <= (long)j1; j++)
        for (long i = (long)i0; i <= (long)i1; i++)
            field_tile(f, density, run, scan, i, j, x_lo, x_hi, y_lo, y_hi, pts, max, &n);
    return n;
}

static int cmp_tile(const void *a, const void *b)
{
    const long *x = a, *y = b;
    if (x[1] != y[1]) return x[1] < y[1] ? -1 : 1;
    return x[0] < y[0] ? -1 : x[0] > y[0];
}

/* Clutter of scan s->k in the union of the squares around the targets:
 * every tile touching a square once (sorted, deduplicated), its points kept
 * when inside at least one square. Returns the points (malloc, caller
 * frees) and their number; NULL with *n = 0 when there are none or memory
 * ran out. */
static struct scen_field_point *around_targets(const struct scenario *s, size_t *n_out)
{
    const struct scen_field *f = s->field;
    const double h = s->p.clutter_around_m, l = f->tile_m;
    *n_out = 0;
    if (!(f->density_per_m2 > 0) || s->n_tg == 0) return NULL;
    size_t nt = 0, cap = 0;
    long *tiles = NULL;
    for (size_t t = 0; t < s->n_tg; t++) {
        const double cx = s->tg[t].x[TRK_CV2_X], cy = s->tg[t].x[TRK_CV2_Y];
        const double i0 = floor((cx - h) / l), i1 = floor((cx + h) / l);
        const double j0 = floor((cy - h) / l), j1 = floor((cy + h) / l);
        if (!isfinite(i0) || !isfinite(j1) || (i1 - i0 + 1) * (j1 - j0 + 1) > (double)SCEN_FIELD_MAX_TILES)
            continue; /* a target gone to infinity: no clutter around it */
        for (long j = (long)j0; j <= (long)j1; j++)
            for (long i = (long)i0; i <= (long)i1; i++) {
                if (nt == cap) {
                    cap = cap ? 2 * cap : 64;
                    long *nb = realloc(tiles, 2 * cap * sizeof *nb);
                    if (!nb) {
                        free(tiles);
                        return NULL;
                    }
                    tiles = nb;
                }
                tiles[2 * nt] = i;
                tiles[2 * nt + 1] = j;
                nt++;
            }
    }
    if (nt == 0) {
        free(tiles);
        return NULL;
    }
    qsort(tiles, nt, 2 * sizeof *tiles, cmp_tile);
    size_t m = 0, cap_p = 0;
    struct scen_field_point *pts = NULL;
    for (size_t k = 0; k < nt; k++) {
        if (k > 0 && tiles[2 * k] == tiles[2 * k - 2] && tiles[2 * k + 1] == tiles[2 * k - 1]) continue;
        const double x0 = (double)tiles[2 * k] * l, y0 = (double)tiles[2 * k + 1] * l;
        size_t c = 0; /* count the tile's points, then store them */
        field_tile(f, f->density_per_m2, 0, (uint32_t)s->k, tiles[2 * k], tiles[2 * k + 1], x0, x0 + l, y0,
                   y0 + l, NULL, 0, &c);
        if (c == 0) continue;
        if (m + c > cap_p) {
            cap_p = 2 * (m + c);
            struct scen_field_point *np = realloc(pts, cap_p * sizeof *np);
            if (!np) {
                free(pts);
                free(tiles);
                return NULL;
            }
            pts = np;
        }
        size_t c2 = 0;
        field_tile(f, f->density_per_m2, 0, (uint32_t)s->k, tiles[2 * k], tiles[2 * k + 1], x0, x0 + l, y0,
                   y0 + l, pts + m, c, &c2);
        const size_t base = m;
        for (size_t q = 0; q < c2; q++) { /* keep it when inside any square */
            const struct scen_field_point pt0 = pts[base + q], *pt = &pt0;
            int in = 0;
            for (size_t t = 0; t < s->n_tg && !in; t++)
                in = fabs(pt->x_m - s->tg[t].x[TRK_CV2_X]) <= h && fabs(pt->y_m - s->tg[t].x[TRK_CV2_Y]) <= h;
            if (in) pts[m++] = *pt;
        }
    }
    free(tiles);
    if (m == 0) {
        free(pts);
        return NULL;
    }
    *n_out = m;
    return pts;
}

/* Appends a detection at (x, y) with an amplitude of target tg (NULL:
 * clutter) drawn from r: 1, or 0 when the draw failed (counted) or det[] is
 * full (counted in *dropped). */
static size_t add_detection(struct scenario *s, const struct amp_target *tg, struct rng *r, double x, double y,
                            struct trk_detection *det, size_t max_det, size_t *n, size_t *dropped)
{
    double a = 0;
    const int has_a = s->amp.kind != AMP_NONE;
    if (has_a && amp_draw(&s->amp, tg, r, &a) != 0) {
        s->n_amp_failures++;
        return 0;
    }
    if (*n == max_det) {
        (*dropped)++;
        return 0;
    }
    struct trk_detection *d = &det[(*n)++];
    const double var = s->p.meas_sigma_m * s->p.meas_sigma_m;
    memset(d, 0, sizeof *d);
    d->x_m = (trk_real)x;
    d->y_m = (trk_real)y;
    if (s->p.attach_cov) {
        d->has_cov = 1;
        d->cov_m2[0] = d->cov_m2[2] = (trk_real)var;
        d->cov_m2[1] = 0;
    }
    d->has_amplitude = (uint8_t)has_a;
    d->amplitude = (trk_real)a;
    return 1;
}

void scen_next(struct scenario *s, struct trk_detection *det, size_t max_det, struct trk_scan *scan,
               size_t *n_target_dets, size_t *n_dropped)
{
    if (s->k > 0) move_targets(s);
    struct rng r;
    rng_init(&r, s->p.seed, 1 + s->k);
    size_t n = 0, dropped = 0, nt = 0;
    const double sg = s->p.meas_sigma_m;
    for (size_t i = 0; i < s->n_tg; i++) {
        const struct scen_target *t = &s->tg[i];
        if (!rng_bernoulli(&r, t->high ? t->pd : s->p.fluct_pd_low)) continue;
        if (t->end_scan > 0 && s->k >= (uint64_t)t->end_scan) continue; /* gone */
        const double x = t->x[TRK_CV2_X] + sg * rng_normal(&r), y = t->x[TRK_CV2_Y] + sg * rng_normal(&r);
        nt += add_detection(s, &t->amp, &r, x, y, det, max_det, &n, &dropped);
    }
    const double area = (s->p.x_max_m - s->p.x_min_m) * (s->p.y_max_m - s->p.y_min_m);
    size_t n_around = 0;
    struct scen_field_point *around = s->field ? around_targets(s, &n_around) : NULL;
    const unsigned long nc = s->field ? (unsigned long)n_around
                             : s->p.clutter_count >= 0
                                 ? (unsigned long)s->p.clutter_count
                                 : rng_poisson(&r, s->p.clutter_density_per_m2 * area);
    for (unsigned long c = 0; c < nc; c++) {
        double x, y;
        if (around) {
            x = around[c].x_m;
            y = around[c].y_m;
        } else {
            x = s->p.x_min_m + (s->p.x_max_m - s->p.x_min_m) * rng_uniform(&r);
            y = s->p.y_min_m + (s->p.y_max_m - s->p.y_min_m) * rng_uniform(&r);
        }
        add_detection(s, NULL, &r, x, y, det, max_det, &n, &dropped);
    }
    free(around);
    /* Fisher-Yates shuffle: no target-first order */
    for (size_t i = n; i > 1; i--) {
        const size_t j = (size_t)(rng_uniform(&r) * (double)i);
        const struct trk_detection tmp = det[i - 1];
        det[i - 1] = det[j < i ? j : i - 1];
        det[j < i ? j : i - 1] = tmp;
    }
    /* beyond the tracker's time range: INT64_MAX, which every consumer refuses (no llround overflow) */
    const double t_us = (double)s->p.t0_us + (double)s->k * s->p.scan_period_s * 1e6;
    trk_scan_init(scan,
                  t_us <= (double)TRK_TIME_US_MAX ? s->p.t0_us + (int64_t)llround((double)s->k * s->p.scan_period_s * 1e6)
                                                  : INT64_MAX,
                  s->p.sensor_id, n, det);
    if (n_target_dets) *n_target_dets = nt;
    if (n_dropped) *n_dropped = dropped;
    s->k++;
}
