/* mtt_scenario.c - the multi-target scenario families of trk-sim mtt
 * (mtt_scenario.h): transit (the default), fixed and sonar. */
#include "mtt_scenario.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rng.h"
#include "trk/kalman.h"

#define DEG (3.14159265358979323846 / 180.0)
#define PAR_SCANS 40       /* the pair present together for at least min(this, n) scans */
#define PAR_OFF_MIN_M 150  /* the pair's line no nearer the centre than this */
#define TRANSIT_TRIES 64   /* draws of a transit target's entry (exit) and heading */
#define TRANSIT_OFF_DEG 60 /* transit heading: up to this off the inward (outward) normal */
#define EDGE_INSET_M 0.01  /* a transit target's entry (exit) point: this far inside */

void mtt_scen_defaults(struct mtt_scen_params *p)
{
    memset(p, 0, sizeof *p);
    p->family = MTT_FAMILY_TRANSIT;
    p->seed = 1;
    p->n_scans = 200;
    p->scan_period_s = 4;
    p->region_m = 3000;
    p->margin_m = 50;
    p->pd = 0.8;
    p->meas_sigma_m = 5;
    p->amplitude = 1;
    p->snr_db = 13;
    p->max_det = TRK_MAX_SCAN_DETECTIONS;
    p->speed_min_mps = 5;
    p->speed_max_mps = 15;
    p->parallel_sep_m = 60;
    p->turn_deg = 90;
    p->turn_rate_dps = 3;
    p->min_life_scans = 25;
    p->gap_max_scans = 10;
    p->accel_mps2 = 0;
    p->accel_s = 60;
    p->platform_speed_mps = 3;
    p->range_min_m = 500;
    p->range_max_m = 8000;
    p->half_width_deg = 60;
    p->sigma_range_m = 7.5;
    p->sigma_bearing_deg = 1.5;
    p->persistent = 1;
}

void mtt_scen_sonar_defaults(struct mtt_scen_params *p)
{
    mtt_scen_defaults(p);
    p->family = MTT_FAMILY_SONAR;
    p->n_scans = 150;
    p->scan_period_s = 8;
    p->speed_min_mps = 3;
    p->speed_max_mps = 10;
    p->parallel_sep_m = 100;
    p->amplitude = 1;
}

const char *mtt_role_name(int role)
{
    static const char *const names[MTT_N_SLOTS + 1] = {"cross_a", "cross_b", "parallel_a", "parallel_b", "birth",
                                                       "death",   "turn",    "straight",   "transit"};
    return role >= 0 && role <= MTT_TRANSIT ? names[role] : "?";
}

const char *mtt_family_name(int family)
{
    static const char *const names[MTT_N_FAMILIES] = {"transit", "fixed", "sonar"};
    return family >= 0 && family < MTT_N_FAMILIES ? names[family] : "?";
}

int mtt_family_parse(const char *name)
{
    for (int f = 0; f < MTT_N_FAMILIES; f++)
        if (strcmp(name, mtt_family_name(f)) == 0) return f;
    return -1;
}

void mtt_scen_free(struct mtt_scenario *s)
{
    amp_model_free(&s->amp);
    free(s->tg);
    free(s->by_slot);
    s->tg = NULL;
    s->by_slot = NULL;
    s->n_targets = 0;
}

static double unif(struct rng *r, double lo, double hi) { return lo + (hi - lo) * rng_uniform(r); }

/* The truth of one target at time t (its trajectory, whether present or not). */
static void truth_of(const struct mtt_target *g, double t, double x[4])
{
    const double v = g->speed_mps, h = g->heading_rad;
    double px, py, hd;
    if (g->accel_mps2 != 0 && t > g->accel_t0_s) {
        /* straight, accelerating from accel_t0_s for accel_dur_s: the
         * distance beyond the constant-speed path, exactly */
        const double a = g->accel_mps2, D = g->accel_dur_s, u = t - g->accel_t0_s;
        const double ds = u < D ? 0.5 * a * u * u : 0.5 * a * D * D + a * D * (u - D);
        const double dv = a * (u < D ? u : D);
        px = g->ax_m + (v * (t - g->at_s) + ds) * cos(h);
        py = g->ay_m + (v * (t - g->at_s) + ds) * sin(h);
        x[TRK_CV2_X] = px;
        x[TRK_CV2_Y] = py;
        x[TRK_CV2_VX] = (v + dv) * cos(h);
        x[TRK_CV2_VY] = (v + dv) * sin(h);
        return;
    }
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

void mtt_scen_truth(const struct mtt_scenario *s, long i, double t_s, double x[4]) { truth_of(&s->tg[i], t_s, x); }

int mtt_scen_present(const struct mtt_scenario *s, long i, long k)
{
    return k >= s->tg[i].birth_scan && k < s->tg[i].death_scan;
}

long mtt_scen_slot_target(const struct mtt_scenario *s, int j, long k)
{
    if (j < 0 || j >= MTT_N_SLOTS) return -1;
    /* the last of the slot's targets born at or before k */
    long lo = s->slot_first[j], hi = s->slot_first[j + 1];
    while (lo < hi) {
        const long mid = lo + (hi - lo) / 2;
        if (s->tg[s->by_slot[mid]].birth_scan <= k) lo = mid + 1;
        else hi = mid;
    }
    if (lo == s->slot_first[j]) return -1;
    const long i = s->by_slot[lo - 1];
    return k < s->tg[i].death_scan ? i : -1;
}

int mtt_scen_n_present(const struct mtt_scenario *s, long k)
{
    int n = 0;
    for (int j = 0; j < MTT_N_SLOTS; j++) n += mtt_scen_slot_target(s, j, k) >= 0;
    return n;
}

/* ---------------------------------------------------------------- lives */

static int inside_xy(const struct mtt_scenario *s, double x, double y)
{
    const double lo = s->p.margin_m, hi = s->p.region_m - s->p.margin_m;
    return x >= lo && x <= hi && y >= lo && y <= hi;
}

static int sonar_inside(const struct mtt_scenario *s, double t, double x, double y);

static int inside_k(const struct mtt_scenario *s, const struct mtt_target *g, long k)
{
    double x[4];
    truth_of(g, (double)k * s->p.scan_period_s, x);
    if (s->p.family == MTT_FAMILY_SONAR)
        return sonar_inside(s, (double)k * s->p.scan_period_s, x[TRK_CV2_X], x[TRK_CV2_Y]);
    return inside_xy(s, x[TRK_CV2_X], x[TRK_CV2_Y]);
}

/* The life of g (mtt_scenario.h): the consecutive scans around its anchor
 * scan inside, within [lo, hi) (its designated birth and death, the run).
 * An anchor outside gives an empty life at the anchor. */
static void set_life(const struct mtt_scenario *s, struct mtt_target *g, long lo, long hi)
{
    const long ns = s->p.n_scans;
    if (lo < 0) lo = 0;
    if (hi > ns) hi = ns;
    long a = lround(g->at_s / s->p.scan_period_s);
    if (a < lo) a = lo;
    if (a > hi - 1) a = hi - 1;
    if (a < lo || !inside_k(s, g, a)) {
        g->birth_scan = g->death_scan = a < 0 ? 0 : a;
        return;
    }
    long b = a, d = a + 1;
    while (b > lo && inside_k(s, g, b - 1)) b--;
    while (d < hi && inside_k(s, g, d)) d++;
    g->birth_scan = b;
    g->death_scan = d;
}

static long overlap(const struct mtt_target *a, const struct mtt_target *b)
{
    const long lo = a->birth_scan > b->birth_scan ? a->birth_scan : b->birth_scan;
    const long hi = a->death_scan < b->death_scan ? a->death_scan : b->death_scan;
    return hi > lo ? hi - lo : 0;
}

static long clamp_l(long v, long lo, long hi) { return v < lo ? lo : v > hi ? hi : v; }

/* ---------------------------------------------------------------- the structure */

/* A straight target through a point 300-700 m from the centre at time
 * at_s, heading tangential +- 30 deg, either way. */
static void straight(struct mtt_target *g, struct rng *r, double cx, double cy, double at_s)
{
    const double al = unif(r, 0, 360 * DEG), rad = unif(r, 300, 700);
    const double h = al + 90 * DEG + unif(r, -30 * DEG, 30 * DEG) + (rng_uniform(r) < 0.5 ? 180 * DEG : 0);
    g->ax_m = cx + rad * cos(al);
    g->ay_m = cy + rad * sin(al);
    g->at_s = at_s;
    g->heading_rad = h;
}

/* The parameter interval [*s0, *s1] of the line (x0, y0) + s (ux, uy) inside
 * (slabs); 0 when it misses. */
static int chord(const struct mtt_scenario *s, double x0, double y0, double ux, double uy, double *s0, double *s1)
{
    const double lo = s->p.margin_m, hi = s->p.region_m - s->p.margin_m;
    double a = -INFINITY, b = INFINITY;
    const double p0[2] = {x0, y0}, u[2] = {ux, uy};
    for (int ax = 0; ax < 2; ax++) {
        if (fabs(u[ax]) < 1e-12) {
            if (p0[ax] < lo || p0[ax] > hi) return 0;
            continue;
        }
        double t0 = (lo - p0[ax]) / u[ax], t1 = (hi - p0[ax]) / u[ax];
        if (t0 > t1) {
            const double t = t0;
            t0 = t1;
            t1 = t;
        }
        if (t0 > a) a = t0;
        if (t1 < b) b = t1;
    }
    *s0 = a;
    *s1 = b;
    return a < b;
}

/* The pair (targets a, b) side by side, heading hp, parallel_sep_m apart
 * about the line through (px, py) + shift (ux, uy) at time at_s: a on the
 * left (+ normal), b on the right. Both families place the pair here; only
 * its point differs (transit: the middle of the chord, fixed: the drawn
 * offset along the line, shift 0). */
static void set_pair(const struct mtt_scenario *s, struct mtt_target *a, struct mtt_target *b, double px, double py,
                     double shift, double hp, double at_s)
{
    const double ux = cos(hp), uy = sin(hp), nx = cos(hp + 90 * DEG), ny = sin(hp + 90 * DEG);
    const double h = 0.5 * s->p.parallel_sep_m;
    for (int i = 0; i < 2; i++) {
        struct mtt_target *g = i ? b : a;
        const double o = i ? -h : h;
        g->ax_m = px + o * nx + shift * ux;
        g->ay_m = py + o * ny + shift * uy;
        g->at_s = at_s;
        g->heading_rad = hp;
    }
}

/* Transit: the pair (targets a, b) on lines off_m from the centre, heading
 * hp, the pair's middle at mid-run along_m from the middle of the part of
 * its lines inside, at speed v; their lives. Returns the scans with both
 * present. */
static long place_pair(const struct mtt_scenario *s, struct mtt_target *a, struct mtt_target *b, double side,
                       double off_m, double hp, double along_m, double v)
{
    const double cx = 0.5 * s->p.region_m, cy = cx, t_mid = 0.5 * (double)(s->p.n_scans - 1) * s->p.scan_period_s;
    const double ux = cos(hp), uy = sin(hp), nx = cos(hp + 90 * DEG), ny = sin(hp + 90 * DEG);
    const double px = cx + side * off_m * nx, py = cy + side * off_m * ny, h = 0.5 * s->p.parallel_sep_m;
    double a0, a1, b0, b1, m = 0;
    if (chord(s, px + h * nx, py + h * ny, ux, uy, &a0, &a1) && chord(s, px - h * nx, py - h * ny, ux, uy, &b0, &b1))
        m = 0.5 * (fmax(a0, b0) + fmin(a1, b1));
    set_pair(s, a, b, px, py, m + along_m, hp, t_mid);
    for (int i = 0; i < 2; i++) {
        struct mtt_target *g = i ? b : a;
        g->speed_mps = v;
        set_life(s, g, 0, s->p.n_scans);
    }
    return overlap(a, b);
}

/* 1 when the turn's arc (and a scan before and after it) is inside. */
static int turn_inside(const struct mtt_scenario *s, const struct mtt_target *g)
{
    const double tau = fabs(g->turn_rad) / g->turn_rate_rps, T = s->p.scan_period_s;
    for (int i = 0; i <= 64; i++) {
        double x[4];
        truth_of(g, g->at_s - T + (tau + 2 * T) * i / 64.0, x);
        if (!inside_xy(s, x[TRK_CV2_X], x[TRK_CV2_Y])) return 0;
    }
    return 1;
}

/* ---------------------------------------------------------------- transit targets */

struct tg_list {
    struct mtt_target *v;
    size_t n, cap;
};

static int tg_push(struct tg_list *l, const struct mtt_target *g)
{
    if (l->n == l->cap) {
        const size_t cap = l->cap ? 2 * l->cap : 64;
        struct mtt_target *v = realloc(l->v, cap * sizeof *v);
        if (!v) return -1;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = *g;
    return 0;
}

/* A transit target of slot j at speed v: forward, entering at scan k and
 * present until it leaves; backward, leaving after scan k (dead at k + 1)
 * and present back to where it entered or scan 0. Position and heading
 * drawn up to TRANSIT_TRIES times until (a) it is present min_life_scans
 * scans and (b) it leaves room for the slot's next target (gap g_next
 * before its birth, or after its death, and min_life_scans), or reaches the
 * run's end; else the best draw ((a) and (b), then (a), then the longest). */
static void transit(const struct mtt_scenario *s, struct rng *r, int j, long k, int forward, double v, long g_next,
                    struct mtt_target *out)
{
    const double m = s->p.margin_m, L = s->p.region_m - 2 * m, T = s->p.scan_period_s;
    const long ns = s->p.n_scans, ml = s->p.min_life_scans;
    struct mtt_target best;
    memset(&best, 0, sizeof best);
    long best_n = -1;
    int best_q = -1;
    for (int it = 0; it < TRANSIT_TRIES; it++) {
        const double u = unif(r, 0, 4 * L), off = unif(r, -TRANSIT_OFF_DEG * DEG, TRANSIT_OFF_DEG * DEG);
        int side = (int)(u / L);
        if (side > 3) side = 3;
        const double w = u - (double)side * L;
        double x, y, nrm; /* the point on the boundary, the inward normal */
        switch (side) {
        case 0: x = m + w, y = m, nrm = 90 * DEG; break;                   /* bottom */
        case 1: x = m + L, y = m + w, nrm = 180 * DEG; break;              /* right */
        case 2: x = m + L - w, y = m + L, nrm = 270 * DEG; break;          /* top */
        default: x = m, y = m + L - w, nrm = 0; break;                      /* left */
        }
        struct mtt_target g;
        memset(&g, 0, sizeof g);
        g.role = MTT_TRANSIT;
        g.slot = j;
        g.speed_mps = g.speed_drawn_mps = v;
        g.ax_m = x + EDGE_INSET_M * cos(nrm);
        g.ay_m = y + EDGE_INSET_M * sin(nrm);
        g.at_s = (double)k * T;
        g.heading_rad = nrm + off + (forward ? 0 : 180 * DEG);
        if (forward) set_life(s, &g, k, s->p.n_scans);
        else set_life(s, &g, 0, k + 1);
        const long n = g.death_scan - g.birth_scan;
        const int room = forward ? g.death_scan == ns || g.death_scan + g_next + ml <= ns
                                 : g.birth_scan == 0 || g.birth_scan - g_next >= ml;
        const int q = n >= ml ? 1 + room : 0;
        if (q > best_q || (q == best_q && n > best_n)) {
            best = g;
            best_n = n;
            best_q = q;
        }
        if (q == 2) break;
    }
    *out = best;
}

static long draw_gap(const struct mtt_scenario *s, struct rng *r)
{
    long g = 1 + (long)(rng_uniform(r) * (double)s->p.gap_max_scans);
    return g > s->p.gap_max_scans ? s->p.gap_max_scans : g;
}

/* ---------------------------------------------------------------- the structure's draws */

/* The structure's random numbers, drawn from stream 0 in this order by both
 * families (a seed gives both the same crossing, headings, offsets, birth
 * and death scans, turn and speed draws; the families differ in what they
 * make of them: place_transit, place_fixed). */
struct structure {
    double tc, ha, hb;                 /* the X: the crossing's time, A's and B's headings */
    double hp, p_side, p_off, p_along; /* the pair: heading, side, offset from the centre, jitter along */
    long kb, kd;                       /* the designated birth scan and death scan */
    double t_phi, t_rq, t_sg, t_dh;    /* the turn: bearing and distance of its start from the centre,
                                          left (+1) or right, the legs' heading jitter */
    double t_w, t_th, tau, ts;         /* its rate, angle, duration and start time */
};

/* The draws (stream 0: the X, the pair, birth, death, turn, straight, the
 * speeds), the X placed, the straight targets (BIRTH, DEATH, STRAIGHT)
 * anchored, every speed drawn (speed_mps = speed_drawn_mps; the pair one
 * velocity). The anchor times of BIRTH and DEATH are the family's: transit
 * its designated birth or last scan, fixed its mid-life. */
static void draw_structure(struct mtt_scenario *s, struct rng *r, struct mtt_target dg[MTT_N_SLOTS],
                           struct structure *st)
{
    const struct mtt_scen_params *p = &s->p;
    const int fixed = p->family == MTT_FAMILY_FIXED;
    const long ns = p->n_scans;
    const double T = p->scan_period_s, t_end = (double)(ns - 1) * T;
    const double cx = 0.5 * p->region_m, cy = 0.5 * p->region_m;
    memset(dg, 0, MTT_N_SLOTS * sizeof *dg);
    memset(st, 0, sizeof *st);
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        dg[i].role = i;
        dg[i].slot = i;
    }
    /* the X */
    s->cross_x_m = cx + unif(r, -150, 150);
    s->cross_y_m = cy + unif(r, -150, 150);
    st->tc = (0.5 + unif(r, -0.05, 0.05)) * t_end;
    st->ha = 45 * DEG + unif(r, -10 * DEG, 10 * DEG) + (rng_uniform(r) < 0.5 ? 180 * DEG : 0);
    st->hb = st->ha + 90 * DEG + unif(r, -20 * DEG, 20 * DEG) + (rng_uniform(r) < 0.5 ? 180 * DEG : 0);
    for (int i = MTT_CROSS_A; i <= MTT_CROSS_B; i++) {
        struct mtt_target *g = &dg[i];
        g->ax_m = s->cross_x_m;
        g->ay_m = s->cross_y_m;
        g->at_s = st->tc;
        g->heading_rad = i == MTT_CROSS_A ? st->ha : st->hb;
    }
    s->cross_scan = lround(st->tc / T);
    /* the pair, along A's line (placed by the family) */
    st->hp = st->ha + unif(r, -5 * DEG, 5 * DEG) + (rng_uniform(r) < 0.5 ? 180 * DEG : 0);
    st->p_side = rng_uniform(r) < 0.5 ? -1 : 1;
    st->p_off = unif(r, 300, 500);
    st->p_along = unif(r, -150, 150);
    /* birth and death */
    st->kb = clamp_l(lround((0.2 + unif(r, -0.015, 0.015)) * (double)ns), 1, ns - 2);
    straight(&dg[MTT_BIRTH], r, cx, cy, fixed ? 0.5 * (double)(st->kb + ns - 1) * T : (double)st->kb * T);
    st->kd = clamp_l(lround((0.7 + unif(r, -0.015, 0.015)) * (double)ns), 2, ns - 1);
    straight(&dg[MTT_DEATH], r, cx, cy, fixed ? 0.5 * (double)(st->kd - 1) * T : (double)(st->kd - 1) * T);
    /* the turn (placed by the family) */
    st->t_phi = unif(r, 0, 360 * DEG);
    st->t_rq = unif(r, 500, 700);
    st->t_sg = rng_uniform(r) < 0.5 ? -1 : 1;
    st->t_dh = unif(r, -10 * DEG, 10 * DEG);
    st->t_w = p->turn_rate_dps * DEG * unif(r, 0.8, 1.2);
    st->t_th = p->turn_deg * DEG;
    st->tau = st->t_th / st->t_w;
    double ts = 0.5 * t_end - 0.5 * st->tau + unif(r, -0.05, 0.05) * t_end;
    if (ts > t_end - st->tau - T) ts = t_end - st->tau - T;
    if (ts < T) ts = T;
    st->ts = ts;
    straight(&dg[MTT_STRAIGHT], r, cx, cy, 0.5 * t_end);
    /* the speeds, drawn */
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        const double v = unif(r, p->speed_min_mps, p->speed_max_mps);
        dg[i].speed_mps = dg[i].speed_drawn_mps = v;
    }
    dg[MTT_PAR_B].speed_mps = dg[MTT_PAR_B].speed_drawn_mps = dg[MTT_PAR_A].speed_mps; /* one velocity */
}

/* The turn target g, its turn starting rq from the centre (bearing t_phi). */
static void set_turn(const struct mtt_scenario *s, struct mtt_target *g, const struct structure *st, double rq)
{
    const double cx = 0.5 * s->p.region_m, cy = 0.5 * s->p.region_m;
    g->ax_m = cx + rq * cos(st->t_phi);
    g->ay_m = cy + rq * sin(st->t_phi);
    g->at_s = st->ts;
    g->heading_rad = st->t_phi + st->t_sg * 0.5 * (180 * DEG - st->t_th) + st->t_dh;
    g->turn_rad = st->t_sg * st->t_th;
    g->turn_rate_rps = st->t_w;
}

/* STRAIGHT's acceleration (p.accel_mps2 > 0; mtt_scenario.h): from g's
 * mid-life (its life without the acceleration) for accel_s, the life then
 * cut at the first scan from that mid-life on where the faster path is
 * outside (the path before the acceleration is unchanged, and a faster one
 * along a line leaves a convex region no later). */
static void set_accel(const struct mtt_scenario *s, struct mtt_target *g)
{
    if (s->p.accel_mps2 == 0 || g->death_scan <= g->birth_scan) return;
    const double T = s->p.scan_period_s;
    g->accel_mps2 = s->p.accel_mps2;
    g->accel_t0_s = 0.5 * (double)(g->birth_scan + g->death_scan - 1) * T;
    g->accel_dur_s = s->p.accel_s;
    long d = (long)floor(g->accel_t0_s / T) + 1; /* scans up to the start: unchanged */
    if (d < g->birth_scan + 1) d = g->birth_scan + 1;
    while (d < g->death_scan && inside_k(s, g, d)) d++;
    g->death_scan = d;
}

/* ---------------------------------------------------------------- transit family */

/* Lives from the path inside, the pair adapted to be present together
 * min(PAR_SCANS, n) scans, the turn's start pulled in until its arc is
 * inside; speeds kept (but the pair's last resort). */
static void place_transit(struct mtt_scenario *s, struct mtt_target dg[MTT_N_SLOTS], const struct structure *st)
{
    const long ns = s->p.n_scans;
    set_life(s, &dg[MTT_CROSS_A], 0, ns);
    set_life(s, &dg[MTT_CROSS_B], 0, ns);
    set_life(s, &dg[MTT_BIRTH], st->kb, ns);
    set_life(s, &dg[MTT_DEATH], 0, st->kd);
    set_life(s, &dg[MTT_STRAIGHT], 0, ns);
    set_accel(s, &dg[MTT_STRAIGHT]);
    {
        /* the pair: present together for min(PAR_SCANS, n) scans, the
         * geometry adapted if need be, then the speed */
        const long need = ns < PAR_SCANS ? ns : PAR_SCANS;
        struct mtt_target *a = &dg[MTT_PAR_A], *b = &dg[MTT_PAR_B];
        const double hp = st->hp, p_off = st->p_off, p_side = st->p_side;
        double v = a->speed_mps, off = p_off, h = hp;
        const double hdiag = 45 * DEG + 90 * DEG * floor((hp - 45 * DEG) / (90 * DEG) + 0.5);
        long got = place_pair(s, a, b, p_side, off, h, st->p_along, v);
        for (int k = 1; k <= 20 && got < need; k++) {
            if (k <= 10) off = p_off - (p_off - PAR_OFF_MIN_M) * k / 10.0;
            else h = hp + (hdiag - hp) * (k - 10) / 10.0;
            got = place_pair(s, a, b, p_side, off, h, 0, v);
        }
        if (got < need) { /* the largest speed that gives it */
            double lo = 0, hi = v;
            for (int it = 0; it < 50; it++) {
                const double mid = 0.5 * (lo + hi);
                if (place_pair(s, a, b, p_side, off, h, 0, mid) >= need) lo = mid;
                else hi = mid;
            }
            v = lo > 0 ? lo : 1e-3;
            got = place_pair(s, a, b, p_side, off, h, 0, v);
        }
        s->par_scans = got;
    }
    {
        struct mtt_target *g = &dg[MTT_TURN];
        double rq = st->t_rq;
        for (int it = 0; it < 40; it++) {
            set_turn(s, g, st, rq);
            if (turn_inside(s, g)) break;
            rq *= 0.9;
        }
        set_life(s, g, 0, ns);
    }
}

/* ---------------------------------------------------------------- fixed family */

/* Every scan of g's life inside at speed v. */
static int life_inside_at(const struct mtt_scenario *s, struct mtt_target g, double v)
{
    g.speed_mps = v;
    for (long k = g.birth_scan; k < g.death_scan; k++)
        if (!inside_k(s, &g, k)) return 0;
    return 1;
}

/* The largest speed <= v whose path stays inside over the life (the path
 * shrinks towards the anchor, inside by construction, as the speed falls:
 * bisection). With a second target b (the pair: one velocity) both must. */
static double fit_speed(const struct mtt_scenario *s, const struct mtt_target *a, const struct mtt_target *b,
                        double v)
{
    if (life_inside_at(s, *a, v) && (!b || life_inside_at(s, *b, v))) return v;
    double lo = 0, hi = v;
    for (int it = 0; it < 60; it++) {
        const double mid = 0.5 * (lo + hi);
        if (life_inside_at(s, *a, mid) && (!b || life_inside_at(s, *b, mid))) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* Lives fixed (the whole run; BIRTH from its birth, DEATH to its death),
 * the pair at its drawn offsets, the turn where drawn, then each speed
 * reduced until the path stays inside over its life (as the first
 * 8-target scenario did). */
static void place_fixed(struct mtt_scenario *s, struct mtt_target dg[MTT_N_SLOTS], const struct structure *st)
{
    const long ns = s->p.n_scans;
    const double cx = 0.5 * s->p.region_m, cy = cx, t_mid = 0.5 * (double)(ns - 1) * s->p.scan_period_s;
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        dg[i].birth_scan = i == MTT_BIRTH ? st->kb : 0;
        dg[i].death_scan = i == MTT_DEATH ? st->kd : ns;
    }
    {
        const double hp = st->hp, off = st->p_off, side = st->p_side;
        const double nx = cos(hp + 90 * DEG), ny = sin(hp + 90 * DEG);
        const double px = cx + side * off * nx + st->p_along * cos(hp);
        const double py = cy + side * off * ny + st->p_along * sin(hp);
        set_pair(s, &dg[MTT_PAR_A], &dg[MTT_PAR_B], px, py, 0, hp, t_mid);
    }
    set_turn(s, &dg[MTT_TURN], st, st->t_rq);
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        struct mtt_target *g = &dg[i];
        if (i == MTT_PAR_B) continue;
        g->speed_mps = fit_speed(s, g, i == MTT_PAR_A ? &dg[MTT_PAR_B] : NULL, g->speed_drawn_mps);
        if (i == MTT_PAR_A) dg[MTT_PAR_B].speed_mps = g->speed_mps;
    }
    s->par_scans = overlap(&dg[MTT_PAR_A], &dg[MTT_PAR_B]);
    set_accel(s, &dg[MTT_STRAIGHT]); /* after the fit: the speed fitted without it */
}

/* ---------------------------------------------------------------- sonar family */

#define SONAR_TRIES 64          /* draws of a target's geometry until its life is long enough */
#define SONAR_MARGIN_DEG 1.0    /* "inside": this far within the sector's edges in bearing */
#define SONAR_PFA 0.01          /* the P_D law's threshold P_FA */
#define SONAR_SRR0_DB 18.0      /* its echo-to-reverberation ratio at range_min_m */
#define SONAR_PATCH_FRAC 0.03   /* the patches' share of the sector's area ... */
#define SONAR_PATCH_SHARE 0.30  /* ... and of the clutter: 10 x the average density */
#define SONAR_NEAR_SHARE 0.15   /* the near-field rise's share of the clutter ... */
#define SONAR_NEAR_SCALE_M 400  /* ... its range beyond range_min_m: Exp(this) */
#define SONAR_PERSIST_PD MTT_SONAR_PERSIST_PD

static double wrap_pi(double a)
{
    const double pi = 180 * DEG;
    while (a > pi) a -= 2 * pi;
    while (a < -pi) a += 2 * pi;
    return a;
}

/* The platform at time t: position, heading clockwise from north (constant). */
static void sonar_platform(const struct mtt_scenario *s, double t, double *px, double *py, double *h)
{
    *px = 0;
    *py = s->p.platform_speed_mps * t;
    *h = 0;
}

/* The point at range r and relative bearing b from the platform at time t. */
static void sonar_point(const struct mtt_scenario *s, double t, double r, double b, double *x, double *y)
{
    double px, py, h;
    sonar_platform(s, t, &px, &py, &h);
    *x = px + r * sin(h + b);
    *y = py + r * cos(h + b);
}

/* Range and relative bearing (-pi, pi] of (x, y) from the platform at time t. */
static void sonar_rb(const struct mtt_scenario *s, double t, double x, double y, double *r, double *b)
{
    double px, py, h;
    sonar_platform(s, t, &px, &py, &h);
    *r = hypot(x - px, y - py);
    *b = wrap_pi(atan2(x - px, y - py) - h);
}

/* Inside the sector less its margins (a target is present there). */
static int sonar_inside(const struct mtt_scenario *s, double t, double x, double y)
{
    double r, b;
    sonar_rb(s, t, x, y, &r, &b);
    return r >= s->p.range_min_m + s->p.margin_m && r <= s->p.range_max_m - s->p.margin_m &&
           fabs(b) <= (s->p.half_width_deg - SONAR_MARGIN_DEG) * DEG;
}

/* Inside the sector itself (the sensor's coverage). */
static int sonar_covered(const struct mtt_scenario *s, double r, double b)
{
    return r >= s->p.range_min_m && r <= s->p.range_max_m && fabs(b) <= s->p.half_width_deg * DEG;
}

/* The P_D law (mtt_scenario.h): a Swerling I target at threshold P_FA
 * SONAR_PFA, P_D = pfa^(1 / (1 + SRR)), its echo-to-reverberation ratio
 * falling as 10 log10 r (boundary-reverberation-limited: Urick, Principles
 * of Underwater Sound, 3rd ed., ch. 9). */
static double sonar_pd_law(const struct mtt_scenario *s, double r_m)
{
    const double srr = pow(10.0, (SONAR_SRR0_DB - 10 * log10(r_m / s->p.range_min_m)) / 10);
    return pow(SONAR_PFA, 1 / (1 + srr));
}

/* g straight from (x, y) at time t at compass heading c (clockwise from
 * north) and speed v. */
static void sonar_set(struct mtt_target *g, double x, double y, double t, double c, double v)
{
    g->ax_m = x;
    g->ay_m = y;
    g->at_s = t;
    g->heading_rad = 90 * DEG - c; /* from +x, counter-clockwise */
    g->speed_mps = g->speed_drawn_mps = v;
    g->turn_rad = g->turn_rate_rps = 0;
}

/* First the draws whose life is long enough, then the longer. */
static int sonar_better(int ok, long len, int best_ok, long best_len)
{
    return ok > best_ok || (ok == best_ok && len > best_len);
}

static long life_of(const struct mtt_target *g) { return g->death_scan - g->birth_scan; }

/* 1 when g is present over scans [a, b] (clamped to the run). */
static int present_over(const struct mtt_scenario *s, const struct mtt_target *g, long a, long b)
{
    a = clamp_l(a, 0, s->p.n_scans - 1);
    b = clamp_l(b, 0, s->p.n_scans - 1);
    return g->birth_scan <= a && g->death_scan > b;
}

/* The sensor (kind polar, sigmas, coverage, the P_D profile) and the
 * sector's area and mean P_D. */
static void sonar_sensor(struct mtt_scenario *s)
{
    const struct mtt_scen_params *p = &s->p;
    struct trk_sensor_params *sp = &s->sonar;
    memset(sp, 0, sizeof *sp);
    sp->kind = TRK_SENSOR_POLAR;
    sp->sigma_range_m = (trk_real)p->sigma_range_m;
    sp->sigma_bearing_rad = (trk_real)(p->sigma_bearing_deg * DEG);
    sp->conversion = TRK_POLAR_FIRST_ORDER;
    sp->coverage.min_range_m = (trk_real)p->range_min_m;
    sp->coverage.max_range_m = (trk_real)p->range_max_m;
    sp->coverage.half_width_rad = (trk_real)(p->half_width_deg * DEG);
    sp->pd_profile.n = MTT_SONAR_PD_POINTS;
    for (int k = 0; k < MTT_SONAR_PD_POINTS; k++) { /* log-spaced: the law is in log r */
        const double r = p->range_min_m * pow(p->range_max_m / p->range_min_m, k / (MTT_SONAR_PD_POINTS - 1.0));
        sp->pd_profile.range_m[k] = (trk_real)r;
        sp->pd_profile.pd[k] = (trk_real)sonar_pd_law(s, r);
    }
    s->area_m2 = p->half_width_deg * DEG * (p->range_max_m * p->range_max_m - p->range_min_m * p->range_min_m);
    /* P_D over the sector's area (weight r dr), from the profile as the
     * tracker reads it (trk_sensor_pd_at straight ahead) */
    const struct trk_pose o = {0, 0, 0};
    const int n = 4000;
    double num = 0, den = 0;
    for (int i = 0; i < n; i++) {
        const double r = p->range_min_m + (p->range_max_m - p->range_min_m) * (i + 0.5) / n;
        num += r * (double)trk_sensor_pd_at(sp, &o, 0, (trk_real)r);
        den += r;
    }
    s->sonar_pd_mean = num / den;
    sp->pd = (trk_real)s->sonar_pd_mean;
    s->sonar_snr_db = 10 * log10(log(SONAR_PFA) / log(s->sonar_pd_mean) - 1);
    /* The clutter's density over range per clutter point per scan, at the
     * P_D profile's ranges (what the sonar's description says of its
     * reverberation; the caller scales it by the points per scan): the
     * uniform share in range x bearing, dN / (2 w r dr); the near-field
     * rise, Exp(SONAR_NEAR_SCALE_M) beyond range_min_m over 2 w r; the
     * patches' share spread over the sector (where they are is the clutter
     * map's to find, not the sensor's description). */
    const double w2 = 2 * p->half_width_deg * DEG;
    sp->clutter_profile.n = MTT_SONAR_PD_POINTS;
    for (int k = 0; k < MTT_SONAR_PD_POINTS; k++) {
        const double r = (double)sp->pd_profile.range_m[k];
        const double uni = (1 - SONAR_PATCH_SHARE - SONAR_NEAR_SHARE) / (w2 * (p->range_max_m - p->range_min_m) * r);
        const double near = SONAR_NEAR_SHARE * exp(-(r - p->range_min_m) / SONAR_NEAR_SCALE_M) / (SONAR_NEAR_SCALE_M * w2 * r);
        sp->clutter_profile.range_m[k] = (trk_real)r;
        sp->clutter_profile.density_per_m2[k] = (trk_real)(uni + near + SONAR_PATCH_SHARE / s->area_m2);
    }
    /* meas_cov_m2 is unused by a polar sensor: the conversion's covariance
     * straight ahead at mid-range as a stand-in (SPD) */
    trk_polar_cov(sp, 0, (trk_real)(0.5 * (p->range_min_m + p->range_max_m)), sp->meas_cov_m2);
}

/* The eight targets, the patches and the scatterers (stream 0;
 * mtt_scenario.h "The sonar family"). */
static void sonar_place(struct mtt_scenario *s, struct rng *r, struct mtt_target dg[MTT_N_SLOTS])
{
    const struct mtt_scen_params *p = &s->p;
    const long ns = p->n_scans;
    const double T = p->scan_period_s, t_end = (double)(ns - 1) * T, t_mid = 0.5 * t_end;
    const double vmin = p->speed_min_mps, vmax = p->speed_max_mps;
    memset(dg, 0, MTT_N_SLOTS * sizeof *dg);
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        dg[i].role = i;
        dg[i].slot = i;
    }
    {
        /* the shallow crossing: both present 10 scans either side */
        struct mtt_target a, b;
        int best_ok = -1;
        long best_len = -1;
        double bx = 0, by = 0, btc = 0;
        for (int it = 0; it < SONAR_TRIES; it++) {
            const double tc = (0.5 + unif(r, -0.05, 0.05)) * t_end;
            const double rc = unif(r, 2500, 4500), bc = unif(r, -30 * DEG, 30 * DEG);
            const double ca = unif(r, -60 * DEG, 60 * DEG);
            const double cb = ca + (rng_uniform(r) < 0.5 ? -1 : 1) * unif(r, 20 * DEG, 35 * DEG);
            const double va = unif(r, vmin, vmax), vb = unif(r, vmin, vmax);
            double x, y;
            sonar_point(s, tc, rc, bc, &x, &y);
            a = dg[MTT_CROSS_A];
            b = dg[MTT_CROSS_B];
            sonar_set(&a, x, y, tc, ca, va);
            sonar_set(&b, x, y, tc, cb, vb);
            set_life(s, &a, 0, ns);
            set_life(s, &b, 0, ns);
            const long kc = lround(tc / T);
            const int ok = present_over(s, &a, kc - 10, kc + 10) && present_over(s, &b, kc - 10, kc + 10);
            const long len = overlap(&a, &b);
            if (sonar_better(ok, len, best_ok, best_len)) {
                dg[MTT_CROSS_A] = a;
                dg[MTT_CROSS_B] = b;
                best_ok = ok;
                best_len = len;
                bx = x;
                by = y;
                btc = tc;
            }
            if (ok) break;
        }
        s->cross_x_m = bx;
        s->cross_y_m = by;
        s->cross_scan = lround(btc / T);
    }
    {
        /* the close pair on one bearing, B parallel_sep_m farther out */
        const long need = ns / 2 < 40 ? ns / 2 : 40;
        int best_ok = -1;
        long best_len = -1;
        for (int it = 0; it < SONAR_TRIES; it++) {
            const double ra = unif(r, 2000, 4500), bp = unif(r, -40 * DEG, 40 * DEG);
            const double cp = unif(r, -60 * DEG, 60 * DEG), v = unif(r, vmin, vmax);
            struct mtt_target a = dg[MTT_PAR_A], b = dg[MTT_PAR_B];
            double x, y;
            sonar_point(s, t_mid, ra, bp, &x, &y);
            sonar_set(&a, x, y, t_mid, cp, v);
            sonar_point(s, t_mid, ra + p->parallel_sep_m, bp, &x, &y);
            sonar_set(&b, x, y, t_mid, cp, v);
            set_life(s, &a, 0, ns);
            set_life(s, &b, 0, ns);
            const long len = overlap(&a, &b);
            const int ok = len >= need;
            if (sonar_better(ok, len, best_ok, best_len)) {
                dg[MTT_PAR_A] = a;
                dg[MTT_PAR_B] = b;
                best_ok = ok;
                best_len = len;
            }
            if (ok) break;
        }
        s->par_scans = overlap(&dg[MTT_PAR_A], &dg[MTT_PAR_B]);
    }
    for (int w = 0; w < 2; w++) {
        /* BIRTH born at its scan, DEATH gone from its scan: 25 scans present */
        const int role = w ? MTT_DEATH : MTT_BIRTH;
        const long kx = w ? clamp_l(lround((0.7 + unif(r, -0.015, 0.015)) * (double)ns), 2, ns - 1)
                          : clamp_l(lround((0.2 + unif(r, -0.015, 0.015)) * (double)ns), 1, ns - 2);
        const long room = w ? kx : ns - kx, need = room < 25 ? room : 25;
        int best_ok = -1;
        long best_len = -1;
        for (int it = 0; it < SONAR_TRIES; it++) {
            const double t = (double)(w ? kx - 1 : kx) * T;
            const double rr = unif(r, 1500, 5000), bb = unif(r, -45 * DEG, 45 * DEG);
            const double c = unif(r, 0, 360 * DEG), v = unif(r, vmin, vmax);
            struct mtt_target g = dg[role];
            double x, y;
            sonar_point(s, t, rr, bb, &x, &y);
            sonar_set(&g, x, y, t, c, v);
            if (w) set_life(s, &g, 0, kx);
            else set_life(s, &g, kx, ns);
            const int ok = life_of(&g) >= need && (w ? g.death_scan == kx : g.birth_scan == kx);
            if (sonar_better(ok, life_of(&g), best_ok, best_len)) {
                dg[role] = g;
                best_ok = ok;
                best_len = life_of(&g);
            }
            if (ok) break;
        }
    }
    {
        /* the turn: present from 5 scans before it to 10 after */
        int best_ok = -1;
        long best_len = -1;
        for (int it = 0; it < SONAR_TRIES; it++) {
            const double tw = p->turn_rate_dps * DEG * unif(r, 0.8, 1.2), th = p->turn_deg * DEG, tau = th / tw;
            double ts = 0.5 * t_end - 0.5 * tau + unif(r, -0.05, 0.05) * t_end;
            if (ts > t_end - tau - T) ts = t_end - tau - T;
            if (ts < T) ts = T;
            const double rr = unif(r, 2000, 4000), bb = unif(r, -40 * DEG, 40 * DEG);
            const double c = unif(r, -60 * DEG, 60 * DEG), v = unif(r, vmin, vmax);
            const double sg = rng_uniform(r) < 0.5 ? -1 : 1;
            struct mtt_target g = dg[MTT_TURN];
            double x, y;
            sonar_point(s, ts, rr, bb, &x, &y);
            sonar_set(&g, x, y, ts, c, v);
            g.turn_rad = sg * th;
            g.turn_rate_rps = tw;
            set_life(s, &g, 0, ns);
            const long k0 = (long)ceil(ts / T - 1e-9), k1 = (long)floor((ts + tau) / T + 1e-9);
            const int ok = present_over(s, &g, k0 - 5, k1 + 10);
            if (sonar_better(ok, life_of(&g), best_ok, best_len)) {
                dg[MTT_TURN] = g;
                best_ok = ok;
                best_len = life_of(&g);
                s->turn_first_scan = k0;
                s->turn_last_scan = k1 > ns - 1 ? ns - 1 : k1;
            }
            if (ok) break;
        }
    }
    {
        /* the far target: across the line of sight with the platform's
         * range rate (v . u = v_platform . u), its range near 7 km */
        const long need = ns < 40 ? ns : 40;
        int best_ok = -1;
        long best_len = -1;
        for (int it = 0; it < SONAR_TRIES; it++) {
            const double rr = unif(r, 6500, 7500), bb = unif(r, -25 * DEG, 25 * DEG);
            const double v = unif(r, vmin, 0.5 * (vmin + vmax)), side = rng_uniform(r) < 0.5 ? -1 : 1;
            double px, py, h, x, y;
            sonar_platform(s, t_mid, &px, &py, &h);
            sonar_point(s, t_mid, rr, bb, &x, &y);
            const double ux = sin(h + bb), uy = cos(h + bb);             /* the line of sight */
            const double vr = p->platform_speed_mps * (sin(h) * ux + cos(h) * uy); /* its range rate */
            const double vt = side * sqrt(fmax(0, v * v - vr * vr));
            const double vx = vr * ux + vt * uy, vy = vr * uy - vt * ux; /* (uy, -ux): across */
            struct mtt_target g = dg[MTT_STRAIGHT];
            sonar_set(&g, x, y, t_mid, atan2(vx, vy), hypot(vx, vy));
            set_life(s, &g, 0, ns);
            const int ok = life_of(&g) >= need;
            if (sonar_better(ok, life_of(&g), best_ok, best_len)) {
                dg[MTT_STRAIGHT] = g;
                best_ok = ok;
                best_len = life_of(&g);
            }
            if (ok) break;
        }
    }
    s->accel_first_scan = 0;
    s->accel_last_scan = -1;
    /* the patches: 3 % of the sector's area in four discs, the first on
     * the crossing, the second on the turn's start, the last two clear of
     * the others */
    const double rp = sqrt(SONAR_PATCH_FRAC * s->area_m2 / (MTT_SONAR_PATCHES * 180 * DEG));
    for (int j = 0; j < MTT_SONAR_PATCHES; j++) {
        struct mtt_disc *d = &s->patch[j];
        d->r_m = rp;
        for (int it = 0; it < SONAR_TRIES; it++) {
            if (j == 0) {
                d->x_m = s->cross_x_m + unif(r, -200, 200);
                d->y_m = s->cross_y_m + unif(r, -200, 200);
            } else if (j == 1) {
                d->x_m = dg[MTT_TURN].ax_m + unif(r, -200, 200);
                d->y_m = dg[MTT_TURN].ay_m + unif(r, -200, 200);
            } else {
                sonar_point(s, t_mid, unif(r, 1500, 6000), unif(r, -45 * DEG, 45 * DEG), &d->x_m, &d->y_m);
            }
            int clear = 1;
            for (int q = 0; q < j; q++)
                clear &= hypot(d->x_m - s->patch[q].x_m, d->y_m - s->patch[q].y_m) >= rp + s->patch[q].r_m;
            if (clear) break;
        }
    }
    /* the persistent scatterers */
    for (int j = 0; j < MTT_SONAR_PERSIST; j++) {
        double x, y;
        if (j < 4) { /* one in each patch */
            const struct mtt_disc *d = &s->patch[j % MTT_SONAR_PATCHES];
            const double rho = d->r_m * sqrt(rng_uniform(r)), phi = unif(r, 0, 360 * DEG);
            x = d->x_m + rho * cos(phi);
            y = d->y_m + rho * sin(phi);
        } else if (j < 8) { /* 250-550 m to the side of a target's path */
            static const int roles[4] = {MTT_CROSS_A, MTT_PAR_A, MTT_TURN, MTT_BIRTH};
            const struct mtt_target *g = &dg[roles[j - 4]];
            const long n = life_of(g) > 0 ? life_of(g) : 1;
            long k = g->birth_scan + (long)(rng_uniform(r) * (double)n);
            if (k >= ns) k = ns - 1;
            double tr[4];
            truth_of(g, (double)k * T, tr);
            const double sp = hypot(tr[TRK_CV2_VX], tr[TRK_CV2_VY]), d = unif(r, 250, 550);
            const double side = rng_uniform(r) < 0.5 ? -1 : 1;
            const double nx = sp > 0 ? -tr[TRK_CV2_VY] / sp : 1, ny = sp > 0 ? tr[TRK_CV2_VX] / sp : 0;
            x = tr[TRK_CV2_X] + side * d * nx;
            y = tr[TRK_CV2_Y] + side * d * ny;
        } else { /* beyond 7 km at a quarter of the run */
            sonar_point(s, 0.25 * t_end, unif(r, 7000, 7800), unif(r, -50 * DEG, 50 * DEG), &x, &y);
        }
        s->persist_x_m[j] = x;
        s->persist_y_m[j] = y;
    }
}

void mtt_scen_pose(const struct mtt_scenario *s, long k, struct trk_pose *pose)
{
    memset(pose, 0, sizeof *pose);
    if (s->p.family != MTT_FAMILY_SONAR) return;
    double px, py, h;
    sonar_platform(s, (double)k * s->p.scan_period_s, &px, &py, &h);
    pose->x_m = (trk_real)px;
    pose->y_m = (trk_real)py;
    pose->heading_rad = (trk_real)h;
}

double mtt_scen_clutter_density(const struct mtt_scenario *s, long k, long clutter_count, double x_m, double y_m)
{
    const struct mtt_scen_params *p = &s->p;
    if (p->family != MTT_FAMILY_SONAR) return 0;
    struct trk_pose pose;
    mtt_scen_pose(s, k, &pose);
    const double dx = x_m - (double)pose.x_m, dy = y_m - (double)pose.y_m, r = hypot(dx, dy);
    const double b = atan2(dx, dy) - (double)pose.heading_rad, bb = atan2(sin(b), cos(b));
    if (!sonar_covered(s, r, bb)) return 0;
    const double w2 = 2 * p->half_width_deg * DEG, n = (double)clutter_count;
    double d = n * (1 - SONAR_PATCH_SHARE - SONAR_NEAR_SHARE) / (w2 * (p->range_max_m - p->range_min_m) * r);
    d += n * SONAR_NEAR_SHARE * exp(-(r - p->range_min_m) / SONAR_NEAR_SCALE_M) / (SONAR_NEAR_SCALE_M * w2 * r);
    for (int j = 0; j < MTT_SONAR_PATCHES; j++)
        if (hypot(x_m - s->patch[j].x_m, y_m - s->patch[j].y_m) <= s->patch[j].r_m)
            d += n * SONAR_PATCH_SHARE / MTT_SONAR_PATCHES / (3.14159265358979323846 * s->patch[j].r_m * s->patch[j].r_m);
    return d;
}

int mtt_scen_in_patch(const struct mtt_scenario *s, double x_m, double y_m)
{
    if (s->p.family != MTT_FAMILY_SONAR) return 0;
    for (int j = 0; j < MTT_SONAR_PATCHES; j++)
        if (hypot(x_m - s->patch[j].x_m, y_m - s->patch[j].y_m) <= s->patch[j].r_m) return 1;
    return 0;
}

double mtt_scen_persist_dist(const struct mtt_scenario *s, double x_m, double y_m)
{
    double d = INFINITY;
    if (s->p.family != MTT_FAMILY_SONAR || !s->p.persistent) return d;
    for (int j = 0; j < MTT_SONAR_PERSIST; j++) d = fmin(d, hypot(x_m - s->persist_x_m[j], y_m - s->persist_y_m[j]));
    return d;
}

/* One polar detection (range rr, relative bearing bb from pose; with
 * amplitudes amplitude a) into det[n] (trk_polar_to_cartesian) and
 * polar[n] (may be NULL). 1 when stored. */
static int sonar_put(const struct mtt_scenario *s, const struct trk_pose *pose, double rr, double bb, double a,
                     struct trk_detection *det, struct trk_polar_detection *polar, size_t n)
{
    struct trk_polar_detection pd;
    memset(&pd, 0, sizeof pd);
    pd.range_m = (trk_real)(rr > 1 ? rr : 1);
    pd.bearing_rad = (trk_real)wrap_pi(bb);
    pd.has_amplitude = (uint8_t)(s->p.amplitude != 0);
    pd.amplitude = s->p.amplitude ? (trk_real)a : 0;
    memset(&det[n], 0, sizeof det[n]);
    if (trk_polar_to_cartesian(&s->sonar, pose, &pd, &det[n]) != TRK_OK) return 0;
    if (polar) polar[n] = pd;
    return 1;
}

/* The amplitudes' own stream of scan k: far from every position stream
 * (0 and 4k + 1 .. 4k + 4), so that amplitudes leave the positions alone. */
#define SONAR_AMP_STREAM(k) ((UINT64_C(1) << 62) + (uint64_t)(k))

/* An amplitude drawn from the stream r: clutter (pd 0), or a target seen
 * with P_D pd at the threshold, 1 + SNR = ln pfa / ln pd (one Exp(1)
 * draw either way). */
static double sonar_amplitude(const struct mtt_scenario *s, struct rng *r, double pd)
{
    const double x = rng_exp(r);
    struct trk_amplitude tg;
    const struct trk_amplitude *m = &s->amp.lib;
    int src = TRK_AMP_CLUTTER;
    if (pd > s->pfa && pd < 1 &&
        trk_amplitude_init_rayleigh(&tg, 1, (trk_real)(10 * log10(log(s->pfa) / log(pd) - 1)), (trk_real)s->pfa) ==
            TRK_OK)
        m = &tg, src = TRK_AMP_TARGET;
    trk_real a;
    return trk_amplitude_inv_sf(m, src, (trk_real)x, &a) == TRK_OK ? (double)a : s->amp.t;
}

/* The sonar family's scan k (mtt_scenario.h "The sonar family"). */
static void sonar_scan(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                       struct trk_polar_detection *polar, size_t max, long *origin, struct trk_scan *scan,
                       struct mtt_scan_info *info)
{
    const struct mtt_scen_params *p = &s->p;
    const size_t cap = p->max_det < max ? p->max_det : max;
    const double t = (double)k * p->scan_period_s, sr = p->sigma_range_m, sb = p->sigma_bearing_deg * DEG;
    const double rmin = p->range_min_m, rmax = p->range_max_m, hw = p->half_width_deg * DEG;
    struct trk_pose pose;
    mtt_scen_pose(s, k, &pose);
    size_t nd = 0, nt = 0, np = 0, nc = 0, capped = 0;
    struct rng r, ra;
    rng_init(&ra, p->seed, SONAR_AMP_STREAM(k)); /* one draw per slot, scatterer and point, always */
    /* targets: four draws per slot (detected?, two noises, one unused), always */
    rng_init(&r, p->seed, 4 * (uint64_t)k + 1);
    for (int j = 0; j < MTT_N_SLOTS; j++) {
        const double u = rng_uniform(&r), e1 = rng_normal(&r), e2 = rng_normal(&r);
        (void)rng_uniform(&r);
        const long i = mtt_scen_slot_target(s, j, k);
        if (i < 0 || nd == cap) continue;
        double x[4], rr, bb;
        truth_of(&s->tg[i], t, x);
        /* the library's P_D at the target's position: the profile, 0 outside the sector */
        const double pd = (double)trk_sensor_pd_at(&s->sonar, &pose, (trk_real)x[TRK_CV2_X], (trk_real)x[TRK_CV2_Y]);
        const double a = sonar_amplitude(s, &ra, pd);
        if (!(u < pd)) continue;
        sonar_rb(s, t, x[TRK_CV2_X], x[TRK_CV2_Y], &rr, &bb);
        if (!sonar_put(s, &pose, rr + sr * e1, bb + sb * e2, a, det, polar, nd)) continue;
        if (origin) origin[nd] = i;
        nd++;
        nt++;
    }
    /* persistent returns: three draws per scatterer, whether on or not */
    rng_init(&r, p->seed, 4 * (uint64_t)k + 4);
    for (int j = 0; j < MTT_SONAR_PERSIST; j++) {
        const double u = rng_uniform(&r), e1 = rng_normal(&r), e2 = rng_normal(&r);
        const double a = sonar_amplitude(s, &ra, SONAR_PERSIST_PD);
        double rr, bb;
        sonar_rb(s, t, s->persist_x_m[j], s->persist_y_m[j], &rr, &bb);
        if (!p->persistent || !sonar_covered(s, rr, bb) || !(u < SONAR_PERSIST_PD) || nd == cap) continue;
        if (!sonar_put(s, &pose, rr + sr * e1, bb + sb * e2, a, det, polar, nd)) continue;
        if (origin) origin[nd] = -2;
        nd++;
        np++;
    }
    /* clutter: six draws per point, whatever its kind */
    rng_init(&r, p->seed, 4 * (uint64_t)k + 2);
    for (long c = 0; c < clutter_count; c++) {
        if (nd == cap) {
            capped = (size_t)(clutter_count - c);
            break;
        }
        const double uk = rng_uniform(&r), us = rng_uniform(&r), u1 = rng_uniform(&r), u2 = rng_uniform(&r);
        const double u3 = rng_uniform(&r), u4 = rng_uniform(&r), a = sonar_amplitude(s, &ra, 0);
        double rr = -1, bb = 0;
        if (uk < SONAR_PATCH_SHARE) { /* in a patch, uniform over its disc */
            int j = (int)(us * MTT_SONAR_PATCHES);
            if (j >= MTT_SONAR_PATCHES) j = MTT_SONAR_PATCHES - 1;
            const struct mtt_disc *d = &s->patch[j];
            const double rho = d->r_m * sqrt(u1), phi = 2 * 180 * DEG * u2;
            sonar_rb(s, t, d->x_m + rho * cos(phi), d->y_m + rho * sin(phi), &rr, &bb);
        } else if (uk < SONAR_PATCH_SHARE + SONAR_NEAR_SHARE) { /* the near-field rise */
            rr = rmin - SONAR_NEAR_SCALE_M * log(u1);
            bb = -hw + 2 * hw * u2;
        }
        if (!sonar_covered(s, rr, bb) || uk >= SONAR_PATCH_SHARE + SONAR_NEAR_SHARE) {
            /* uniform in range x bearing (also in place of a point outside) */
            rr = rmin + (rmax - rmin) * u3;
            bb = -hw + 2 * hw * u4;
        }
        if (!sonar_put(s, &pose, rr, bb, a, det, polar, nd)) continue;
        if (origin) origin[nd] = -1;
        nd++;
        nc++;
    }
    /* Fisher-Yates shuffle, as the other families */
    rng_init(&r, p->seed, 4 * (uint64_t)k + 3);
    for (size_t i = nd; i > 1; i--) {
        size_t j = (size_t)(rng_uniform(&r) * (double)i);
        if (j >= i) j = i - 1;
        const struct trk_detection tmp = det[i - 1];
        det[i - 1] = det[j];
        det[j] = tmp;
        if (polar) {
            const struct trk_polar_detection tp = polar[i - 1];
            polar[i - 1] = polar[j];
            polar[j] = tp;
        }
        if (origin) {
            const long o = origin[i - 1];
            origin[i - 1] = origin[j];
            origin[j] = o;
        }
    }
    memset(scan, 0, sizeof *scan);
    scan->time_us = (int64_t)llround(t * 1e6);
    scan->sensor_id = 0;
    scan->n_detections = nd;
    scan->detections = det;
    if (info) {
        info->n_target = nt;
        info->n_clutter = nc;
        info->n_persist = np;
        info->n_clutter_capped = capped;
    }
}

int mtt_scen_scan_polar(const struct mtt_scenario *s, long k, long clutter_count, struct trk_detection *det,
                        struct trk_polar_detection *polar, size_t max, long *origin, struct trk_scan *scan,
                        struct mtt_scan_info *info)
{
    if (s->p.family != MTT_FAMILY_SONAR) return -1;
    sonar_scan(s, k, clutter_count, det, polar, max, origin, scan, info);
    return 0;
}

/* ---------------------------------------------------------------- init */

int mtt_scen_init(struct mtt_scenario *s, const struct mtt_scen_params *p, char *err, size_t n)
{
    memset(s, 0, sizeof *s);
    if (p->n_scans < 10 || p->n_scans > 1000000L) {
        snprintf(err, n, "scans must be in [10, 1e6]");
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
    if (p->max_det > TRK_MAX_SCAN_DETECTIONS) {
        snprintf(err, n, "scan capacity %zu exceeds TRK_MAX_SCAN_DETECTIONS = %u", p->max_det,
                 TRK_MAX_SCAN_DETECTIONS);
        return -1;
    }
    if (!(p->speed_min_mps > 0) || !(p->speed_max_mps >= p->speed_min_mps) || !(p->speed_max_mps <= 1000) ||
        !(p->parallel_sep_m > 0) || !(p->parallel_sep_m < 500) || !(p->turn_deg > 0 && p->turn_deg <= 360) ||
        !(p->turn_rate_dps > 0 && p->turn_rate_dps <= 90)) {
        snprintf(err, n, "speeds must be 0 < min <= max <= 1000 m/s, pair separation in (0, 500) m, turn in "
                         "(0, 360] deg at (0, 90] deg/s");
        return -1;
    }
    if (!(p->accel_mps2 >= 0 && p->accel_mps2 <= 10) || !(p->accel_s > 0 && p->accel_s <= 1e6)) {
        snprintf(err, n, "the straight target's acceleration must be in [0, 10] m/s^2, its duration in (0, 1e6] s");
        return -1;
    }
    if (p->family != MTT_FAMILY_TRANSIT && p->family != MTT_FAMILY_FIXED && p->family != MTT_FAMILY_SONAR) {
        snprintf(err, n, "family %d is none of transit (%d), fixed (%d), sonar (%d)", p->family, MTT_FAMILY_TRANSIT,
                 MTT_FAMILY_FIXED, MTT_FAMILY_SONAR);
        return -1;
    }
    if (p->family == MTT_FAMILY_SONAR &&
        (!(p->platform_speed_mps >= 0 && p->platform_speed_mps <= 20) || !(p->range_min_m > 0) ||
         !(p->range_max_m > p->range_min_m + 4 * p->margin_m) || !(p->range_max_m <= 1e5) ||
         !(p->half_width_deg > 2 * SONAR_MARGIN_DEG && p->half_width_deg <= 90) || !(p->sigma_range_m > 0) ||
         !isfinite(p->sigma_range_m) || !(p->sigma_bearing_deg > 0 && p->sigma_bearing_deg <= 10))) {
        snprintf(err, n, "sonar: platform speed in [0, 20] m/s, ranges 0 < min < max <= 1e5 m (4 margins apart), "
                         "half width in (2, 90] deg, sigma range > 0, sigma bearing in (0, 10] deg");
        return -1;
    }
    if (p->family == MTT_FAMILY_SONAR && p->accel_mps2 != 0) {
        snprintf(err, n, "sonar: no acceleration");
        return -1;
    }
    if (p->family == MTT_FAMILY_TRANSIT &&
        (p->min_life_scans < 1 || p->gap_max_scans < 1 || p->gap_max_scans > p->n_scans)) {
        snprintf(err, n, "transit targets: min life must be >= 1 scan, gaps 1 .. [1, scans]");
        return -1;
    }
    s->p = *p;
    if (s->p.max_det == 0) s->p.max_det = TRK_MAX_SCAN_DETECTIONS;
    /* P_D = pfa^(1 / (1 + SNR)) (Swerling I in Rayleigh): pfa = pd^(1 + SNR);
     * the sonar's threshold is its P_D law's */
    const double d = pow(10.0, p->snr_db / 10);
    s->pfa = p->family == MTT_FAMILY_SONAR ? SONAR_PFA : pow(p->pd, 1 + d);
    if (amp_model_init(&s->amp, AMP_RAYLEIGH, s->pfa, 1, err, n) != 0) return -1;
    if (amp_target_init(&s->amp, p->snr_db, &s->amp_tg) != 0) {
        snprintf(err, n, "target SNR %g dB not usable", p->snr_db);
        mtt_scen_free(s);
        return -1;
    }
    const long ns = p->n_scans;
    const int transit_on = p->family == MTT_FAMILY_TRANSIT;
    struct mtt_target dg[MTT_N_SLOTS]; /* the designated targets */
    struct structure st;
    struct rng r;
    rng_init(&r, p->seed, 0);
    s->area_m2 = p->region_m * p->region_m;
    if (p->family == MTT_FAMILY_SONAR) {
        sonar_sensor(s);
        sonar_place(s, &r, dg);
    } else {
        draw_structure(s, &r, dg, &st);
        if (p->family == MTT_FAMILY_FIXED) place_fixed(s, dg, &st);
        else place_transit(s, dg, &st);
    }
    if (p->family != MTT_FAMILY_SONAR) {
        const double T = p->scan_period_s;
        s->turn_first_scan = (long)ceil(st.ts / T - 1e-9);
        s->turn_last_scan = (long)floor((st.ts + st.tau) / T + 1e-9);
        if (s->turn_last_scan > ns - 1) s->turn_last_scan = ns - 1;
        const struct mtt_target *g = &dg[MTT_STRAIGHT];
        s->accel_first_scan = 0;
        s->accel_last_scan = -1;
        if (g->accel_mps2 != 0) {
            s->accel_first_scan = (long)ceil(g->accel_t0_s / T - 1e-9);
            s->accel_last_scan = (long)floor((g->accel_t0_s + g->accel_dur_s) / T + 1e-9);
            if (s->accel_last_scan > ns - 1) s->accel_last_scan = ns - 1;
        }
    }
    /* ---- the slots: transit targets before and after the designated one
     * (the transit family; the fixed one has the designated ones alone) */
    struct tg_list all = {NULL, 0, 0}, before = {NULL, 0, 0};
    long *ord = NULL;
    int oom = 0;
    for (int i = 0; i < MTT_N_SLOTS && !oom; i++) oom = tg_push(&all, &dg[i]) != 0;
    size_t n_ord = 0, cap_ord = 0;
    for (int j = 0; j < MTT_N_SLOTS && !oom; j++) {
        before.n = 0;
        long gap = transit_on ? draw_gap(s, &r) : 0;
        for (long kb0 = dg[j].birth_scan; transit_on && !oom;) { /* backwards: the earlier ones, latest first */
            const long x = kb0 - gap;
            if (x < p->min_life_scans) break;
            const double v = unif(&r, p->speed_min_mps, p->speed_max_mps);
            gap = draw_gap(s, &r); /* the one before it */
            struct mtt_target g;
            transit(s, &r, j, x - 1, 0, v, gap, &g);
            oom = tg_push(&before, &g) != 0;
            kb0 = g.birth_scan;
        }
        const size_t first = all.n;
        for (size_t q = before.n; q-- > 0 && !oom;) oom = tg_push(&all, &before.v[q]) != 0;
        const size_t mid = all.n;
        gap = transit_on ? draw_gap(s, &r) : 0;
        for (long kd0 = dg[j].death_scan; transit_on && !oom;) { /* forwards: the later ones */
            const long e = kd0 + gap;
            if (e + p->min_life_scans > ns) break;
            const double v = unif(&r, p->speed_min_mps, p->speed_max_mps);
            gap = draw_gap(s, &r); /* the one after it */
            struct mtt_target g;
            transit(s, &r, j, e, 1, v, gap, &g);
            oom = tg_push(&all, &g) != 0;
            kd0 = g.death_scan;
        }
        /* the slot's order: the earlier ones, the designated one, the later ones */
        const size_t need = n_ord + (all.n - first) + 1;
        if (!oom && need > cap_ord) {
            size_t cap = cap_ord ? cap_ord : 64;
            while (cap < need) cap *= 2;
            long *o = realloc(ord, cap * sizeof *o);
            if (!o) oom = 1;
            else {
                ord = o;
                cap_ord = cap;
            }
        }
        if (oom) break;
        s->slot_first[j] = (long)n_ord;
        for (size_t q = first; q < mid; q++) ord[n_ord++] = (long)q;
        ord[n_ord++] = j;
        for (size_t q = mid; q < all.n; q++) ord[n_ord++] = (long)q;
    }
    free(before.v);
    if (oom) {
        free(all.v);
        free(ord);
        snprintf(err, n, "out of memory");
        mtt_scen_free(s);
        return -1;
    }
    s->slot_first[MTT_N_SLOTS] = (long)n_ord;
    s->tg = all.v;
    s->n_targets = all.n;
    s->by_slot = ord;
    return 0;
}

/* ---------------------------------------------------------------- scans */

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
                   size_t max, long *origin, struct trk_scan *scan, struct mtt_scan_info *info)
{
    if (s->p.family == MTT_FAMILY_SONAR) {
        sonar_scan(s, k, clutter_count, det, NULL, max, origin, scan, info);
        return;
    }
    const size_t cap = s->p.max_det < max ? s->p.max_det : max;
    const double t = (double)k * s->p.scan_period_s, sg = s->p.meas_sigma_m;
    const int has_a = s->p.amplitude;
    size_t nd = 0, nt = 0, nc = 0, capped = 0;
    struct rng r;
    /* targets: four draws per slot (detected?, two noises, amplitude), always */
    rng_init(&r, s->p.seed, 4 * (uint64_t)k + 1);
    for (int j = 0; j < MTT_N_SLOTS; j++) {
        const double u = rng_uniform(&r), e1 = rng_normal(&r), e2 = rng_normal(&r);
        double a;
        if (amp_draw(&s->amp, &s->amp_tg, &r, &a) != 0) a = s->amp.t;
        const long i = mtt_scen_slot_target(s, j, k);
        if (i < 0 || !(u < s->p.pd) || nd == cap) continue;
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
            const long o = origin[i - 1];
            origin[i - 1] = origin[j];
            origin[j] = o;
        }
    }
    trk_scan_init(scan, (int64_t)llround(t * 1e6), 0, nd, det);
    if (info) {
        info->n_target = nt;
        info->n_clutter = nc;
        info->n_persist = 0;
        info->n_clutter_capped = capped;
    }
}

void mtt_old_defaults(struct trk_tracker_params *p)
{
    trk_tracker_mn_kn_params(p); /* the library keeps the defaults before two-point initiation */
}
