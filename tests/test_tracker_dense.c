/* test_tracker_dense.c - a dense formation: 64 targets on an 8 x 8 lattice
 * moving together, sigma 1 m, P_D 1, no clutter, a scan every 4 s, the
 * default parameters. Measured over spacing x speed (printed: confirmed
 * tracks at scans 10 and 99 for three seeds) and asserted where the table
 * holds the formation: at rest at 8 and 12 m, and at 12 m while the
 * formation moves less than a third of its spacing per scan. Where it moves
 * half its spacing or more, two-point initiation pairs each detection with
 * the wrong neighbour (a lattice moving uniformly looks the same with
 * velocity v and v + spacing / T until its edge), and the tracks it keeps
 * are fewer (docs/tracker.md, "Dense formations"). */
#include "trk_test.h"
#include "trk/tracker.h"
#include "trk_test_sonar.h"

static struct trk_tracker tk; /* static, as in firmware */

static uint64_t rng_state; /* the generator of trk_test.h */

#define N_TGT 64
#define SCAN_S 4.0
#define N_SCANS 100

static size_t count_confirmed(void) { return trk_test_count_confirmed(&tk); }

/* One run: the confirmed tracks after scan 10 (*at10) and after the last. */
static size_t formation_run(double spacing_m, double speed_mps, uint64_t seed, size_t *at10)
{
    static struct trk_detection d[N_TGT];
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    p.sensor[0].pd = 1;
    p.sensor[0].meas_cov_m2[TRK_COV2_XX] = p.sensor[0].meas_cov_m2[TRK_COV2_YY] = 1;
    p.sensor[0].meas_cov_m2[TRK_COV2_XY] = 0;
    p.sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-7); /* joint association needs lambda > 0 */
    p.stationary_d2 = 0; /* the lattice stands still or creeps: targets, not persistent returns */
    p.process_noise_q = TRK_REAL_C(1e-3);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    rng_state = seed;
    for (int k = 0; k < N_SCANS; k++) {
        memset(d, 0, sizeof d);
        for (int i = 0; i < N_TGT; i++) {
            d[i].x_m = (trk_real)(spacing_m * (i % 8) + speed_mps * SCAN_S * k + trk_test_nrand(&rng_state));
            d[i].y_m = (trk_real)(spacing_m * (i / 8) + trk_test_nrand(&rng_state));
        }
        const struct trk_scan scan = {(int64_t)k * 4000000, 0, N_TGT, d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, NULL));
        if (k == 10) *at10 = count_confirmed();
    }
    return count_confirmed();
}

static void test_dense_formation(void **state)
{
    (void)state;
    if (TRK_MAX_TRACKS < N_TGT) {
        skip();
        return;
    }
    static const double spacing[] = {6, 8, 12}, speed[] = {0, 0.5, 1, 2};
    for (size_t a = 0; a < sizeof spacing / sizeof spacing[0]; a++)
        for (size_t b = 0; b < sizeof speed / sizeof speed[0]; b++) {
            char line[160];
            int len = snprintf(line, sizeof line, "spacing %2.0f m, %.1f m/s (%3.0f %% of the spacing per scan):",
                               spacing[a], speed[b], 100 * speed[b] * SCAN_S / spacing[a]);
            size_t worst = N_TGT;
            for (uint64_t seed = 1; seed <= 3; seed++) {
                size_t at10 = 0;
                const size_t end = formation_run(spacing[a], speed[b], seed, &at10);
                if (end < worst) worst = end;
                len += snprintf(line + len, sizeof line - (size_t)len, " %2zu/%2zu", at10, end);
            }
            print_message("%s (confirmed at scan 10 / 99, seeds 1-3)\n", line);
            /* held: at rest from 8 m, and at 12 m below a third of the spacing per scan */
            if (spacing[a] >= 8 && speed[b] * SCAN_S <= spacing[a] / 3) assert_true(worst >= N_TGT - 8);
            if (spacing[a] >= 8 && speed[b] == 0) assert_true(worst >= N_TGT - 1);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dense_formation),
    };
    return trk_run_tests("tracker_dense", tests, NULL, NULL);
}
