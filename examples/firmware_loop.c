/* firmware_loop.c - how firmware uses libtrk: a static tracker, a main loop
 * that receives one detection scan at a time and reads the confirmed tracks.
 *
 * The "sonar" here is a small simulation (three targets, Poisson clutter);
 * in firmware, get_scan() would read the signal processor's detection list.
 * Everything lives in static storage; no heap, no libtrk call allocates. */
#include <math.h>
#include <stdio.h>

#include "trk/trk.h"

#define N_TARGETS 3
#define AREA_M 2000.0
#define SCAN_PERIOD_S 2.0
#define N_SCANS 60

/* the CV state [x, vx, y, vy] and its covariance by name (trk/kalman.h) */
#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define P(i, j) TRK_CV2_P(i, j)

static struct trk_tracker tracker;                 /* ~40 KB, .bss */
static struct trk_detection detections[TRK_MAX_DETECTIONS];

/* --- a stand-in sonar: xorshift64* random numbers, three CV targets -------- */
static uint64_t rng = 0x2545F4914F6CDD1Dull;
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
static unsigned poisson(double mean)
{
    double l = exp(-mean), p = 1;
    unsigned k = 0;
    while ((p *= urand()) > l) k++;
    return k;
}

static const double target0[N_TARGETS][4] = { /* [x, vx, y, vy] like the tracks */
    {200, 3.0, 300, 1.0}, {1500, -2.0, 400, 2.5}, {900, 0.5, 1700, -3.0}};
static double target[N_TARGETS][4];

static size_t get_scan(int k, struct trk_scan *scan)
{
    size_t n = 0;
    for (int i = 0; i < N_TARGETS; i++) {
        target[i][X] += SCAN_PERIOD_S * target[i][VX];
        target[i][Y] += SCAN_PERIOD_S * target[i][VY];
        if (urand() < 0.85 && n < TRK_MAX_DETECTIONS) {
            detections[n].x_m = (trk_real)(target[i][X] + 3 * nrand());
            detections[n].y_m = (trk_real)(target[i][Y] + 3 * nrand());
            detections[n].has_cov = detections[n].has_amplitude = 0;
            n++;
        }
    }
    for (unsigned c = poisson(20); c > 0 && n < TRK_MAX_DETECTIONS; c--) {
        detections[n].x_m = (trk_real)(AREA_M * urand());
        detections[n].y_m = (trk_real)(AREA_M * urand());
        detections[n].has_cov = detections[n].has_amplitude = 0;
        n++;
    }
    trk_scan_init(scan, (int64_t)(k * SCAN_PERIOD_S * 1e6), 0, n, detections);
    return n;
}

int main(void)
{
    /* first: a library built with another configuration than these headers
     * (capacities, scalar type) has other struct layouts, so even
     * trk_tracker_default_params would write past `params` */
    if (trk_tracker_abi_check() != TRK_OK) return 2; /* header/library mismatch */
    struct trk_tracker_params params;
    trk_tracker_default_params(&params);
    params.sensor[0].pd = TRK_REAL_C(0.85);
    params.sensor[0].meas_cov_m2[TRK_COV2_XX] = 9; /* 3 m standard deviation */
    params.sensor[0].meas_cov_m2[TRK_COV2_YY] = 9;
    params.sensor[0].clutter_density_per_m2 = (trk_real)(20.0 / (AREA_M * AREA_M));
    params.process_noise_q = TRK_REAL_C(0.01);
    /* the defaults confirm and terminate by existence (IPDA / JIPDA): a track is
     * confirmed when its existence reaches 0.999 and ends below 0.1. Another
     * method is chosen with its method field and its own member of the union,
     * e.g. params.confirm.method = TRK_CONFIRM_MN; params.confirm.u.mn.m = 4; ...
     * (writing another method's member leaves the chosen one's garbage: refused
     * by trk_tracker_check_params). */
    params.confirm.u.existence.p_confirm = TRK_REAL_C(0.999);
    params.term.u.existence.p_terminate = TRK_REAL_C(0.1);

    const char *field;
    trk_status st = trk_tracker_check_params(&params, &field); /* names what it refuses */
    if (st != TRK_OK) {
        printf("tracker parameter %s: %s\n", field, trk_status_str(st));
        return 1;
    }
    st = trk_tracker_init(&tracker, &params);
    if (st != TRK_OK) {
        printf("trk_tracker_init: %s\n", trk_status_str(st));
        return 1;
    }
    for (int i = 0; i < N_TARGETS; i++)
        for (int j = 0; j < 4; j++) target[i][j] = target0[i][j];

    unsigned long n_det = 0, n_started = 0, n_ended = 0;
    for (int k = 0; k < N_SCANS; k++) { /* the firmware main loop */
        struct trk_scan scan;
        struct trk_scan_report rep;
        n_det += get_scan(k, &scan);
        st = trk_tracker_process_scan(&tracker, &scan, &rep);
        if (st != TRK_OK) { /* a refused scan leaves the table as it was */
            printf("scan %d refused: %s\n", k, trk_status_str(st));
            continue;
        }
        n_started += rep.n_started;
        n_ended += rep.n_terminated;
        if ((k + 1) % 15 == 0) {
            printf("t = %5.0f s: %2u detections, %zu live tracks; confirmed:\n", (double)scan.time_us * 1e-6,
                   rep.n_detections, trk_tracker_live_count(&tracker));
            for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
                const struct trk_track *tr = trk_tracker_track(&tracker, s);
                if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
                printf("  id %3u  x %8.1f y %8.1f m  v (%5.2f, %5.2f) m/s  sd %.1f m  hits %u/%u\n",
                       (unsigned)tr->id, (double)tr->x[X], (double)tr->x[Y], (double)tr->x[VX],
                       (double)tr->x[VY], sqrt((double)(tr->p[P(X, X)] + tr->p[P(Y, Y)])), (unsigned)tr->n_hits,
                       (unsigned)tr->n_scans);
            }
        }
    }
    /* score: each target should have one confirmed track within 20 m, and
     * no confirmed track should be farther than that from every target */
    int found = 0, n_false = 0;
    for (int i = 0; i < N_TARGETS; i++)
        for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *tr = trk_tracker_track(&tracker, s);
            if (tr && tr->status == TRK_TRACK_CONFIRMED &&
                hypot((double)tr->x[X] - target[i][X], (double)tr->x[Y] - target[i][Y]) < 20) {
                found++;
                break;
            }
        }
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *tr = trk_tracker_track(&tracker, s);
        int near = 0;
        for (int i = 0; tr && i < N_TARGETS; i++)
            near |= hypot((double)tr->x[X] - target[i][X], (double)tr->x[Y] - target[i][Y]) < 20;
        n_false += tr && tr->status == TRK_TRACK_CONFIRMED && !near;
    }
    printf("%d scans, %lu detections, %lu tracks started, %lu ended; %d of %d targets held, %d false confirmed "
           "tracks\n",
           N_SCANS, n_det, n_started, n_ended, found, N_TARGETS, n_false);
    return found == N_TARGETS && n_false == 0 ? 0 : 1;
}
