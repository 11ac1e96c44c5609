/* main.c - a bare-metal Cortex-M4F image built from an installed trk kit
 * (make install-cross; this directory's Makefile, docs/firmware.md "Building
 * your own image with the kit").
 *
 * The firmware loop of examples/firmware_loop.c on a target: a static
 * tracker, the ABI check at start-up, one trk_tracker_process_scan call per
 * detection scan, here with amplitude-aided association from a table in
 * ROM. The table (K clutter of shape 1, a Swerling I target at 15 dB, P_FA
 * 1e-3) is a const array that the kit's trk-tablegen wrote in the target's
 * real width (amp_table_data.h, made by the Makefile); trk_table_parse
 * checks it in place and the amplitude model reads it from flash.
 *
 * The "sonar" is a short synthetic scenario: three constant-velocity
 * targets, 3 m position noise, detected with the model's P_D, and Poisson
 * clutter, all above the detection threshold, their amplitudes drawn from
 * the table's own inverse survival functions (target or clutter). The
 * random numbers are a fixed xorshift32 sequence, in float only (the M4F's
 * FPU is single precision), so the run is the same on every machine.
 *
 * One line of output over semihosting:
 *   fw-kit: <target> <scans> scans <n> detections coverage <c> <f> false; tracks x,y x,y ...
 * coverage: the fraction of (scan, target) pairs from scan SCORE_FROM on
 * with a confirmed track within HELD_M of the target; false: confirmed
 * tracks at the last scan farther than that from every target; then every
 * confirmed track's final position (m). Exit status 0 when coverage >=
 * MIN_COVERAGE and no track is false; 1 otherwise; 2 when the
 * headers and the library were built differently (ABI check); 3 when the
 * table or the tracker's parameters are refused. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "amp_table_data.h" /* static const union {bytes, reals} amp_table; AMP_TABLE_SIZE */
#include "trk/amplitude.h"
#include "trk/table.h"
#include "trk/trk.h"

#define N_TARGETS 3
#define N_SCANS 60
#define SCAN_PERIOD_S 2.0f
#define AREA_M 2000.0f
#define CLUTTER_PER_SCAN 20.0f
#define NOISE_M 3.0f
#define HELD_M 20.0f
#define SCORE_FROM 10   /* coverage counted from this scan on (tracks need a few to confirm) */
#define MIN_COVERAGE 0.9f

#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY

/* static storage, as firmware has it: the tracker is ~53 KB of .bss */
static struct trk_tracker tracker;
static struct trk_table table;
static struct trk_detection detections[TRK_MAX_DETECTIONS];

/* [x, vx, y, vy] at t = 0 (m, m/s); the truth at scan k is x + vx k T */
static const float target0[N_TARGETS][4] = {
    {300, 4.0f, 400, 1.5f}, {1600, -3.0f, 500, 2.5f}, {1000, 0.5f, 1600, -3.5f}};

/* --- the stand-in sonar ------------------------------------------------ */
static uint32_t rng = 0x9E3779B9u;
static float urand(void) /* uniform in (0, 1) */
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return ((float)(rng >> 8) + 0.5f) * (1.0f / 16777216.0f);
}
static float nrand(void)
{
    return sqrtf(-2.0f * logf(urand())) * cosf(6.2831853f * urand());
}
static unsigned poisson(float mean)
{
    float l = expf(-mean), p = 1;
    unsigned k = 0;
    while ((p *= urand()) > l) k++;
    return k;
}
/* an amplitude above the threshold from the model's truncated law:
 * x = -ln U ~ Exp(1) through the inverse survival function (Brekke eq 47) */
static trk_real amplitude(const struct trk_amplitude *m, int source)
{
    trk_real a;
    if (trk_amplitude_inv_sf(m, source, -logf(urand()), &a) != TRK_OK) return 0; /* 0: refused, counted */
    return a;
}
static void truth(int i, int k, float *x, float *y)
{
    *x = target0[i][X] + target0[i][VX] * SCAN_PERIOD_S * (float)k;
    *y = target0[i][Y] + target0[i][VY] * SCAN_PERIOD_S * (float)k;
}
static size_t get_scan(int k, const struct trk_amplitude *m, struct trk_scan *scan)
{
    size_t n = 0;
    for (int i = 0; i < N_TARGETS; i++) {
        float x, y;
        truth(i, k, &x, &y);
        if (urand() < m->pd && n < TRK_MAX_DETECTIONS) {
            detections[n].x_m = x + NOISE_M * nrand();
            detections[n].y_m = y + NOISE_M * nrand();
            detections[n].amplitude = amplitude(m, TRK_AMP_TARGET);
            detections[n].has_amplitude = 1;
            detections[n].has_cov = 0;
            n++;
        }
    }
    for (unsigned c = poisson(CLUTTER_PER_SCAN); c > 0 && n < TRK_MAX_DETECTIONS; c--) {
        detections[n].x_m = AREA_M * urand();
        detections[n].y_m = AREA_M * urand();
        detections[n].amplitude = amplitude(m, TRK_AMP_CLUTTER);
        detections[n].has_amplitude = 1;
        detections[n].has_cov = 0;
        n++;
    }
    trk_scan_init(scan, (int64_t)k * (int64_t)(SCAN_PERIOD_S * 1e6f), 0, n, detections);
    return n;
}

static int near_target(const struct trk_track *t, int k, int i)
{
    float x, y;
    truth(i, k, &x, &y);
    return hypotf((float)t->x[X] - x, (float)t->x[Y] - y) < HELD_M;
}

/* the targets with a confirmed track within HELD_M after scan k */
static int targets_held(int k)
{
    int held = 0;
    for (int i = 0; i < N_TARGETS; i++)
        for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
            const struct trk_track *t = trk_tracker_track(&tracker, s);
            if (t && t->status == TRK_TRACK_CONFIRMED && near_target(t, k, i)) {
                held++;
                break;
            }
        }
    return held;
}

int main(void)
{
    /* first: headers compiled with other flags than the library (here: without
     * the kit's -DTRK_REAL_FLOAT) see other struct layouts */
    if (trk_tracker_abi_check() != TRK_OK) {
        puts("fw-kit: headers and libtrk built differently (TRK_E_ABI): use pkg-config --cflags trk-cortex-m4f");
        return 2;
    }
    struct trk_tracker_params params;
    trk_tracker_default_params(&params);
    /* the amplitude model reads the table in place, in flash */
    trk_status st = trk_table_parse(&table, amp_table.bytes, AMP_TABLE_SIZE);
    if (st == TRK_OK) st = trk_amplitude_init_table(&params.sensor[0].amplitude, &table);
    if (st != TRK_OK) {
        printf("fw-kit: amplitude table refused: %s\n", trk_status_str(st));
        return 3;
    }
    params.sensor[0].use_amplitude = 1;
    params.sensor[0].pd = trk_amplitude_pd(&params.sensor[0].amplitude);
    params.sensor[0].meas_cov_m2[TRK_COV2_XX] = NOISE_M * NOISE_M;
    params.sensor[0].meas_cov_m2[TRK_COV2_YY] = NOISE_M * NOISE_M;
    params.sensor[0].clutter_density_per_m2 = CLUTTER_PER_SCAN / (AREA_M * AREA_M);
    params.process_noise_q = TRK_REAL_C(0.01);
    const char *field;
    st = trk_tracker_check_params(&params, &field);
    if (st == TRK_OK) st = trk_tracker_init(&tracker, &params);
    else printf("fw-kit: tracker parameter %s: ", field);
    if (st != TRK_OK) {
        printf("%s\n", trk_status_str(st));
        return 3;
    }

    unsigned long n_det = 0;
    int held = 0;
    for (int k = 0; k < N_SCANS; k++) { /* the firmware main loop */
        struct trk_scan scan;
        struct trk_scan_report rep;
        n_det += get_scan(k, &params.sensor[0].amplitude, &scan);
        if (trk_tracker_process_scan(&tracker, &scan, &rep) != TRK_OK) return 1; /* never refused here */
        if (k >= SCORE_FROM) held += targets_held(k);
    }
    const float coverage = (float)held / (float)(N_TARGETS * (N_SCANS - SCORE_FROM));

    int n_false = 0;
    printf("fw-kit: cortex-m4f %d scans %lu detections", N_SCANS, n_det);
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *t = trk_tracker_track(&tracker, s);
        if (!t || t->status != TRK_TRACK_CONFIRMED) continue;
        int near = 0;
        for (int i = 0; i < N_TARGETS; i++) near |= near_target(t, N_SCANS - 1, i);
        n_false += !near;
    }
    printf(" coverage %.3f %d false; tracks", (double)coverage, n_false);
    for (size_t s = 0; s < TRK_MAX_TRACKS; s++) {
        const struct trk_track *t = trk_tracker_track(&tracker, s);
        if (t && t->status == TRK_TRACK_CONFIRMED) printf(" %.1f,%.1f", (double)t->x[X], (double)t->x[Y]);
    }
    printf("\n");
    return coverage >= MIN_COVERAGE && n_false == 0 ? 0 : 1;
}
