/* mtt_scenario.c - the multi-target scenario family of trk-sim mtt
 * (mtt_scenario.h). */
#include "mtt_scenario.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "rng.h"
#include "trk/kalman.h"

#define DEG (3.14159265358979323846 / 180.0)

void mtt_scen_defaults(struct mtt_scen_params *p)
{
    memset(p, 0, sizeof *p);
    p->seed = 1;
    p->n_scans = 200;
    p->scan_period_s = 4;
    p->region_m = 3000;
    p->margin_m = 50;
    p->pd = 0.8;
    p->meas_sigma_m = 5;
    p->amplitude = 1;
    p->snr_db = 13;
    p->max_det = TRK_MAX_DETECTIONS;
    p->speed_min_mps = 5;
    p->speed_max_mps = 15;
    p->parallel_sep_m = 60;
    p->turn_deg = 90;
    p->turn_rate_dps = 3;
}

const char *mtt_role_name(int role)
{
    static const char *const names[MTT_N_TARGETS] = {"cross_a", "cross_b", "parallel_a", "parallel_b",
                                                     "birth",   "death",   "turn",       "straight"};
    return role >= 0 && role < MTT_N_TARGETS ? names[role] : "?";
}

void mtt_scen_free(struct mtt_scenario *s) { amp_model_free(&s->amp); }

static double unif(struct rng *r, double lo, double hi) { return lo + (hi - lo) * rng_uniform(r); }

/* The truth of one target at time t (its trajectory, whether present or not). */
static void truth_of(const struct mtt_target *g, double t, double x[4])
{
    const double v = g->speed_mps, h = g->heading_rad;
    double px, py, hd;
    if (g->turn_rad == 0 || g->turn_rate_rps <= 0 || v <= 0 || t <= g->at_s) {
        hd = h;
        px = g->ax_m + v * (t - g->at_s) * cos(h);
        py = g->ay_m + v * (t - g->at_s) * sin(h);
    } else {
        const double w = g->turn_rate_rps, sg = g->turn_rad > 0 ? 1 : -1, tau = fabs(g->turn_rad) / w;
        const double rr = v / w, dt = t < g->at_s + tau ? t - g->at_s : tau;
        /* centre of the arc: left (sg +1) of the heading at the turn start */
        const double ox = g->ax_m + rr * cos(h + sg * 90 * DEG), oy = g->ay_m + rr * sin(h + sg * 90 * DEG);
        hd = h + sg * w * dt;
        px = ox + rr * cos(hd - sg * 90 * DEG);
        py = oy + rr * sin(hd - sg * 90 * DEG);
        if (t > g->at_s + tau) { /* the leg after the turn */
            px += v * (t - g->at_s - tau) * cos(hd);
            py += v * (t - g->at_s - tau) * sin(hd);
        }
    }
    x[TRK_CV2_X] = px;
    x[TRK_CV2_Y] = py;
    x[TRK_CV2_VX] = v * cos(hd);
    x[TRK_CV2_VY] = v * sin(hd);
}

void mtt_scen_truth(const struct mtt_scenario *s, int i, double t_s, double x[4])
{
    truth_of(&s->tg[i], t_s, x);
}

int mtt_scen_present(const struct mtt_scenario *s, int i, long k)
{
    return k >= s->tg[i].birth_scan && k < s->tg[i].death_scan;
}

/* Every scan of the target's life inside [m, S - m]^2 at speed v. */
static int inside_at(const struct mtt_scenario *s, struct mtt_target g, double v)
{
    const double lo = s->p.margin_m, hi = s->p.region_m - s->p.margin_m;
    g.speed_mps = v;
    for (long k = g.birth_scan; k < g.death_scan; k++) {
        double x[4];
        truth_of(&g, (double)k * s->p.scan_period_s, x);
        if (!(x[TRK_CV2_X] >= lo && x[TRK_CV2_X] <= hi && x[TRK_CV2_Y] >= lo && x[TRK_CV2_Y] <= hi)) return 0;
    }
    return 1;
}

/* The largest speed <= v whose path stays in (the path shrinks towards the
 * anchor, inside by construction, as the speed falls: bisection). With a
 * second target b (the pair: one velocity) both must stay in. */
static double fit_speed(const struct mtt_scenario *s, const struct mtt_target *a, const struct mtt_target *b,
                        double v)
{
    if (inside_at(s, *a, v) && (!b || inside_at(s, *b, v))) return v;
    double lo = 0, hi = v;
    for (int it = 0; it < 60; it++) {
        const double mid = 0.5 * (lo + hi);
        if (inside_at(s, *a, mid) && (!b || inside_at(s, *b, mid))) lo = mid;
        else hi = mid;
    }
    return lo;
}

static long clamp_l(long v, long lo, long hi) { return v < lo ? lo : v > hi ? hi : v; }

/* A straight target through a point 300-700 m from the centre at its
 * mid-life, heading tangential +- 30 deg, either way. */
static void straight(struct mtt_target *g, struct rng *r, double cx, double cy, double T)
{
    const double al = unif(r, 0, 360 * DEG), rad = unif(r, 300, 700);
    const double h = al + 90 * DEG + unif(r, -30 * DEG, 30 * DEG) + (rng_uniform(r) < 0.5 ? 180 * DEG : 0);
    g->ax_m = cx + rad * cos(al);
    g->ay_m = cy + rad * sin(al);
    g->at_s = 0.5 * (double)(g->birth_scan + g->death_scan - 1) * T;
    g->heading_rad = h;
}

int mtt_scen_init(struct mtt_scenario *s, const struct mtt_scen_params *p, char *err, size_t n)
{
    memset(s, 0, sizeof *s);
    if (p->n_scans < 10 || p->n_scans > 100000000L) {
        snprintf(err, n, "scans must be in [10, 1e8]");
        return -1;
    }
    if (!(p->scan_period_s > 0) || !isfinite(p->scan_period_s) || !(p->region_m >= 1000) ||
        !isfinite(p->region_m) || !(p->margin_m >= 0 && p->margin_m <= p->region_m / 10)) {
        snprintf(err, n, "scan period must be > 0, region >= 1000 m, margin in [0, region/10]");
        return -1;
    }
    if (!(p->pd > 0 && p->pd < 1) || !(p->meas_sigma_m > 0) || !isfinite(p->meas_sigma_m) ||
        !(p->snr_db >= 0 && p->snr_db <= 40)) {
        snprintf(err, n, "pd must be in (0, 1), sigma > 0, snr_db in [0, 40]");
        return -1;
    }
    if (p->max_det > TRK_MAX_DETECTIONS) {
        snprintf(err, n, "scan capacity %zu exceeds TRK_MAX_DETECTIONS = %d", p->max_det, TRK_MAX_DETECTIONS);
        return -1;
    }
    if (!(p->speed_min_mps > 0) || !(p->speed_max_mps >= p->speed_min_mps) || !isfinite(p->speed_max_mps) ||
        !(p->parallel_sep_m > 0) || !(p->parallel_sep_m < 500) || !(p->turn_deg > 0 && p->turn_deg <= 180) ||
        !(p->turn_rate_dps > 0 && p->turn_rate_dps <= 90)) {
        snprintf(err, n, "speeds must be 0 < min <= max, pair separation in (0, 500) m, turn in (0, 180] deg "
                         "at (0, 90] deg/s");
        return -1;
    }
    s->p = *p;
    if (s->p.max_det == 0) s->p.max_det = TRK_MAX_DETECTIONS;
    /* P_D = pfa^(1 / (1 + SNR)) (Swerling I in Rayleigh): pfa = pd^(1 + SNR) */
    const double d = pow(10.0, p->snr_db / 10);
    s->pfa = pow(p->pd, 1 + d);
    if (amp_model_init(&s->amp, AMP_RAYLEIGH, s->pfa, 1, err, n) != 0) return -1;
    if (amp_target_init(&s->amp, p->snr_db, &s->amp_tg) != 0) {
        snprintf(err, n, "target SNR %g dB not usable", p->snr_db);
        mtt_scen_free(s);
        return -1;
    }
    /* ---- the geometry: stream 0, in this order */
    struct rng r;
    rng_init(&r, p->seed, 0);
    const long ns = p->n_scans;
    const double T = p->scan_period_s, t_end = (double)(ns - 1) * T;
    const double cx = 0.5 * p->region_m, cy = 0.5 * p->region_m;
    for (int i = 0; i < MTT_N_TARGETS; i++) {
        s->tg[i].role = i;
        s->tg[i].birth_scan = 0;
        s->tg[i].death_scan = ns;
    }
    double vdraw[MTT_N_TARGETS];
    /* the X */
    s->cross_x_m = cx + unif(&r, -150, 150);
    s->cross_y_m = cy + unif(&r, -150, 150);
    const double tc = (0.5 + unif(&r, -0.05, 0.05)) * t_end;
    const double ha = 45 * DEG + unif(&r, -10 * DEG, 10 * DEG) + (rng_uniform(&r) < 0.5 ? 180 * DEG : 0);
    const double hb = ha + 90 * DEG + unif(&r, -20 * DEG, 20 * DEG) + (rng_uniform(&r) < 0.5 ? 180 * DEG : 0);
    for (int i = MTT_CROSS_A; i <= MTT_CROSS_B; i++) {
        struct mtt_target *g = &s->tg[i];
        g->ax_m = s->cross_x_m;
        g->ay_m = s->cross_y_m;
        g->at_s = tc;
        g->heading_rad = i == MTT_CROSS_A ? ha : hb;
    }
    s->cross_scan = lround(tc / T);
    /* the pair, along A's line */
    {
        const double hp = ha + unif(&r, -5 * DEG, 5 * DEG) + (rng_uniform(&r) < 0.5 ? 180 * DEG : 0);
        const double side = rng_uniform(&r) < 0.5 ? -1 : 1, off = unif(&r, 300, 500), along = unif(&r, -150, 150);
        const double nx = cos(hp + 90 * DEG), ny = sin(hp + 90 * DEG);
        const double px = cx + side * off * nx + along * cos(hp), py = cy + side * off * ny + along * sin(hp);
        for (int i = MTT_PAR_A; i <= MTT_PAR_B; i++) {
            struct mtt_target *g = &s->tg[i];
            const double o = (i == MTT_PAR_A ? 0.5 : -0.5) * p->parallel_sep_m;
            g->ax_m = px + o * nx;
            g->ay_m = py + o * ny;
            g->at_s = 0.5 * t_end;
            g->heading_rad = hp;
        }
    }
    /* birth and death */
    s->tg[MTT_BIRTH].birth_scan = clamp_l(lround((0.2 + unif(&r, -0.015, 0.015)) * (double)ns), 1, ns - 2);
    straight(&s->tg[MTT_BIRTH], &r, cx, cy, T);
    s->tg[MTT_DEATH].death_scan = clamp_l(lround((0.7 + unif(&r, -0.015, 0.015)) * (double)ns), 2, ns - 1);
    straight(&s->tg[MTT_DEATH], &r, cx, cy, T);
    /* the turn */
    {
        struct mtt_target *g = &s->tg[MTT_TURN];
        const double phi = unif(&r, 0, 360 * DEG), rq = unif(&r, 500, 700);
        const double sg = rng_uniform(&r) < 0.5 ? -1 : 1, dh = unif(&r, -10 * DEG, 10 * DEG);
        const double w = p->turn_rate_dps * DEG * unif(&r, 0.8, 1.2), th = p->turn_deg * DEG;
        const double tau = th / w;
        double ts = 0.5 * t_end - 0.5 * tau + unif(&r, -0.05, 0.05) * t_end;
        if (ts > t_end - tau - T) ts = t_end - tau - T;
        if (ts < T) ts = T;
        g->ax_m = cx + rq * cos(phi);
        g->ay_m = cy + rq * sin(phi);
        g->at_s = ts;
        g->heading_rad = phi + sg * 0.5 * (180 * DEG - th) + dh;
        g->turn_rad = sg * th;
        g->turn_rate_rps = w;
        s->turn_first_scan = (long)ceil(ts / T - 1e-9);
        s->turn_last_scan = (long)floor((ts + tau) / T + 1e-9);
        if (s->turn_last_scan > ns - 1) s->turn_last_scan = ns - 1;
    }
    straight(&s->tg[MTT_STRAIGHT], &r, cx, cy, T);
    for (int i = 0; i < MTT_N_TARGETS; i++) vdraw[i] = unif(&r, p->speed_min_mps, p->speed_max_mps);
    vdraw[MTT_PAR_B] = vdraw[MTT_PAR_A]; /* one velocity */
    /* ---- speeds: the draw, or what keeps the target in */
    for (int i = 0; i < MTT_N_TARGETS; i++) {
        struct mtt_target *g = &s->tg[i];
        g->speed_drawn_mps = vdraw[i];
        if (i == MTT_PAR_B) continue;
        g->speed_mps = fit_speed(s, g, i == MTT_PAR_A ? &s->tg[MTT_PAR_B] : NULL, vdraw[i]);
        if (i == MTT_PAR_A) s->tg[MTT_PAR_B].speed_mps = g->speed_mps;
    }
    return 0;
}

/* One detection. */
static void put(struct trk_detection *d, double x, double y, int has_a, double a)
{
    memset(d, 0, sizeof *d);
    d->x_m = (trk_real)x;
    d->y_m = (trk_real)y;
    d->has_amplitude = (uint8_t)(has_a != 0);
    d->amplitude = has_a ? (trk_real)a : 0;
}

void mtt_scen_scan(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                   size_t max, int *origin, struct trk_scan *scan, struct mtt_scan_info *info)
{
    const size_t cap = s->p.max_det < max ? s->p.max_det : max;
    const double t = (double)k * s->p.scan_period_s, sg = s->p.meas_sigma_m;
    const int has_a = s->p.amplitude;
    size_t nd = 0, nt = 0, nc = 0, capped = 0;
    struct rng r;
    /* targets: four draws each (detected?, two noises, amplitude), always */
    rng_init(&r, s->p.seed, 4 * (uint64_t)k + 1);
    for (int i = 0; i < MTT_N_TARGETS; i++) {
        const double u = rng_uniform(&r), e1 = rng_normal(&r), e2 = rng_normal(&r);
        double a;
        if (amp_draw(&s->amp, &s->amp_tg, &r, &a) != 0) a = s->amp.t;
        if (!mtt_scen_present(s, i, k) || !(u < s->p.pd) || nd == cap) continue;
        double x[4];
        truth_of(&s->tg[i], t, x);
        if (origin) origin[nd] = i;
        put(&det[nd++], x[TRK_CV2_X] + sg * e1, x[TRK_CV2_Y] + sg * e2, has_a, a);
        nt++;
    }
    /* clutter: the first clutter_count points of the scan's clutter stream,
     * as many as the capacity leaves room for */
    rng_init(&r, s->p.seed, 4 * (uint64_t)k + 2);
    const double side = s->p.region_m;
    for (long c = 0; c < clutter_count; c++) {
        if (nd == cap) {
            capped = (size_t)(clutter_count - c);
            break;
        }
        const double x = side * rng_uniform(&r), y = side * rng_uniform(&r);
        double a;
        if (amp_draw(&s->amp, NULL, &r, &a) != 0) a = s->amp.t;
        if (origin) origin[nd] = -1;
        put(&det[nd++], x, y, has_a, a);
        nc++;
    }
    /* Fisher-Yates shuffle: no target-first order */
    rng_init(&r, s->p.seed, 4 * (uint64_t)k + 3);
    for (size_t i = nd; i > 1; i--) {
        size_t j = (size_t)(rng_uniform(&r) * (double)i);
        if (j >= i) j = i - 1;
        const struct trk_detection tmp = det[i - 1];
        det[i - 1] = det[j];
        det[j] = tmp;
        if (origin) {
            const int o = origin[i - 1];
            origin[i - 1] = origin[j];
            origin[j] = o;
        }
    }
    scan->time_us = (int64_t)llround(t * 1e6);
    scan->sensor_id = 0;
    scan->n_detections = nd;
    scan->detections = det;
    if (info) {
        info->n_target = nt;
        info->n_clutter = nc;
        info->n_clutter_capped = capped;
    }
}

void mtt_old_defaults(struct trk_tracker_params *p)
{
    trk_tracker_mn_kn_params(p); /* the library keeps the pre-issue-14 defaults */
}
