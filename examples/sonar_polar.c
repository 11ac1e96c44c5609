/* sonar_polar.c - firmware with an active sonar on a moving platform: each
 * ping gives range and bearing detections relative to the platform's
 * heading, and the platform's pose at the ping (navigation). The sensor is
 * described once: its noise in range and bearing, its P_D and clutter
 * density over range, the sector it covers; the tracker converts each
 * detection, takes each track's R, P_D and clutter density at its own
 * range, and does not penalise a track for pings that could not see it
 * (docs/tracker.md "Polar sensors, P_D over range, coverage").
 *
 * The "sonar" is a small simulation (two targets, uniform clutter in range
 * x bearing); exit status 0 when both targets are held by confirmed tracks
 * at the end and no confirmed track is false. Static storage only. */
#include <math.h>
#include <stdio.h>

#include "trk/trk.h"

#define PING_S 8.0
#define N_PINGS 60
#define RANGE_MIN_M 500.0
#define RANGE_MAX_M 8000.0
#define HALF_WIDTH_RAD (60 * TRK_PI / 180)
#define N_CLUTTER 20

static struct trk_tracker tracker;
static struct trk_polar_detection pings[TRK_MAX_DETECTIONS];

/* --- a stand-in sonar: xorshift64* random numbers ------------------------- */
static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double urand(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (double)((rng * 0x2545F4914F6CDD1Dull) >> 11) * (1.0 / 9007199254740992.0);
}
static double nrand(void)
{
    double u = urand();
    return sqrt(-2 * log(u > 1e-300 ? u : 1e-300)) * cos(6.283185307179586 * urand());
}

/* two targets [x, y, vx, vy]: one near, one far */
static double target[2][4] = {{-800, 2500, 4, 2}, {1500, 6500, -3, -2}};

/* P_D falling with range, as the sensor's description gives it */
static const double pd_range_m[4] = {500, 2000, 5000, 8000}, pd_value[4] = {0.92, 0.85, 0.6, 0.45};

static double pd_at(double r)
{
    if (r <= pd_range_m[0]) return pd_value[0];
    for (int k = 1; k < 4; k++)
        if (r < pd_range_m[k])
            return pd_value[k - 1] + (r - pd_range_m[k - 1]) / (pd_range_m[k] - pd_range_m[k - 1]) *
                                         (pd_value[k] - pd_value[k - 1]);
    return pd_value[3];
}

/* ping k seen from pose o: the targets' detections and the clutter */
static size_t get_ping(const struct trk_pose *o)
{
    size_t n = 0;
    for (int i = 0; i < 2; i++) {
        target[i][0] += PING_S * target[i][2];
        target[i][1] += PING_S * target[i][3];
        const double dx = target[i][0] - o->x_m, dy = target[i][1] - o->y_m, r = hypot(dx, dy);
        if (urand() < pd_at(r)) {
            pings[n].range_m = (trk_real)(r + 7.5 * nrand());
            pings[n].bearing_rad = (trk_real)(atan2(dx, dy) - o->heading_rad + 0.026 * nrand());
            pings[n++].has_amplitude = 0;
        }
    }
    for (int c = 0; c < N_CLUTTER; c++) {
        pings[n].range_m = (trk_real)(RANGE_MIN_M + (RANGE_MAX_M - RANGE_MIN_M) * urand());
        pings[n].bearing_rad = (trk_real)((2 * urand() - 1) * HALF_WIDTH_RAD);
        pings[n++].has_amplitude = 0;
    }
    return n;
}

int main(void)
{
    if (trk_tracker_abi_check() != TRK_OK) return 2;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    struct trk_sensor_params *s = &p.sensor[0];
    s->kind = TRK_SENSOR_POLAR;
    s->sigma_range_m = TRK_REAL_C(7.5);
    s->sigma_bearing_rad = TRK_REAL_C(0.026); /* 1.5 degrees */
    s->pd_profile.n = 4;
    for (int k = 0; k < 4; k++) s->pd_profile.range_m[k] = (trk_real)pd_range_m[k], s->pd_profile.pd[k] = (trk_real)pd_value[k];
    /* clutter uniform in range x bearing: N / (2 w (r_max - r_min) r) per m^2 */
    s->clutter_density_per_m2 = (trk_real)(N_CLUTTER / (HALF_WIDTH_RAD * (RANGE_MAX_M * RANGE_MAX_M - RANGE_MIN_M * RANGE_MIN_M)));
    s->clutter_profile.n = 2;
    for (int k = 0; k < 2; k++) {
        const double r = k ? RANGE_MAX_M : RANGE_MIN_M;
        s->clutter_profile.range_m[k] = (trk_real)r;
        s->clutter_profile.density_per_m2[k] = (trk_real)(N_CLUTTER / (2 * HALF_WIDTH_RAD * (RANGE_MAX_M - RANGE_MIN_M) * r));
    }
    s->coverage.min_range_m = (trk_real)RANGE_MIN_M;
    s->coverage.max_range_m = (trk_real)RANGE_MAX_M;
    s->coverage.half_width_rad = (trk_real)HALF_WIDTH_RAD;
    p.process_noise_q = TRK_REAL_C(0.001);
    const char *field = NULL;
    if (trk_tracker_check_params(&p, &field) != TRK_OK || trk_tracker_init(&tracker, &p) != TRK_OK) {
        printf("sonar_polar: parameters refused (%s)\n", field ? field : "?");
        return 2;
    }
    for (int k = 0; k < N_PINGS; k++) {
        const struct trk_pose pose = {0, (trk_real)(3.0 * PING_S * k), 0}; /* 3 m/s north, from navigation */
        struct trk_scan scan;
        trk_scan_init_polar(&scan, (int64_t)k * (int64_t)(PING_S * 1e6), 0, get_ping(&pose), pings, &pose);
        struct trk_scan_report rep;
        if (trk_tracker_process_scan(&tracker, &scan, &rep) != TRK_OK) return 2;
    }
    int held[2] = {0, 0}, false_tracks = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *t = trk_tracker_track(&tracker, i);
        if (!t || t->status != TRK_TRACK_CONFIRMED) continue;
        int mine = 0;
        for (int g = 0; g < 2; g++)
            if (hypot(t->x[TRK_CV2_X] - target[g][0], t->x[TRK_CV2_Y] - target[g][1]) < 300) held[g] = mine = 1;
        false_tracks += !mine;
        printf("track %u at (%.0f, %.0f) m, %.1f m/s\n", (unsigned)t->id, (double)t->x[TRK_CV2_X],
               (double)t->x[TRK_CV2_Y], hypot((double)t->x[TRK_CV2_VX], (double)t->x[TRK_CV2_VY]));
    }
    printf("sonar_polar: %d of 2 targets held (near and far), %d false confirmed tracks after %d pings\n",
           held[0] + held[1], false_tracks, N_PINGS);
    return held[0] && held[1] && false_tracks == 0 ? 0 : 1;
}
