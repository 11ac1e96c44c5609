/* exp_polar.c - `trk-sim polar`: the converted measurement of a polar sensor
 * by range band (docs/conventions.md "Polar detections"): per conversion
 * (the library's trk_polar_to_cartesian, first order and unbiased) and
 * band, the mean error along and across the range (the bias), the RMS error
 * and the NEES e' C^-1 e with the conversion's own covariance C (2 when C is
 * right; the share above the chi-square(2) 95 % point, 0.05 when it is). A
 * sample: a true range uniform in the band, a bearing uniform in +-60
 * degrees, range and bearing with Gaussian noise of sigma_r and sigma_b.
 * The criterion r sigma_b^2 / sigma_r at the band's middle says when the
 * bias matters (it is the bias over sigma_r, doubled). Single-threaded: a
 * band of 10^5 samples takes milliseconds. */
#include <math.h>
#include <stdlib.h>

#include "rng.h"
#include "sim.h"
#include "trk/tracker.h"

#define MAX_BANDS 16

struct band_stat {
    double along, cross, sq, nees, over;
};

/* One band [r0, r1) of n samples of conversion conv (stream per band and
 * conversion: the same draws for both conversions). */
static void band_run(uint64_t seed, int band, double r0, double r1, long n, double sr, double sb_rad, int conv,
                     struct band_stat *st)
{
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    struct trk_sensor_params *s = &p.sensor[0];
    s->kind = TRK_SENSOR_POLAR;
    s->sigma_range_m = (trk_real)sr;
    s->sigma_bearing_rad = (trk_real)sb_rad;
    s->conversion = conv ? TRK_POLAR_UNBIASED : TRK_POLAR_FIRST_ORDER;
    const struct trk_pose o = {0, 0, 0};
    struct rng r;
    rng_init(&r, seed, (uint64_t)band);
    const double chi2_95 = -2 * log(0.05); /* chi-square(2) 95 % point: 5.99 */
    *st = (struct band_stat){0, 0, 0, 0, 0};
    for (long i = 0; i < n; i++) {
        const double rt = r0 + (r1 - r0) * rng_uniform(&r), bt = (rng_uniform(&r) * 2 - 1) * 60 * 3.14159265358979323846 / 180;
        const struct trk_polar_detection pd = {(trk_real)(rt + sr * rng_normal(&r)),
                                               (trk_real)(bt + sb_rad * rng_normal(&r)), 0, 0};
        struct trk_detection d;
        if (trk_polar_to_cartesian(s, &o, &pd, &d) != TRK_OK) continue; /* a range <= 0: not at these bands */
        const double ex = d.x_m - rt * sin(bt), ey = d.y_m - rt * cos(bt);
        const double ua = ex * sin(bt) + ey * cos(bt), uc = ex * cos(bt) - ey * sin(bt);
        const double cxx = d.cov_m2[TRK_COV2_XX], cxy = d.cov_m2[TRK_COV2_XY], cyy = d.cov_m2[TRK_COV2_YY];
        const double det = cxx * cyy - cxy * cxy;
        const double nees = (cyy * ex * ex - 2 * cxy * ex * ey + cxx * ey * ey) / det;
        st->along += ua;
        st->cross += uc;
        st->sq += ex * ex + ey * ey;
        st->nees += nees;
        st->over += nees > chi2_95;
    }
    st->along /= (double)n, st->cross /= (double)n, st->sq = sqrt(st->sq / (double)n);
    st->nees /= (double)n, st->over /= (double)n;
}

SIM_EXPERIMENT(polar, "polar", "a polar sensor's converted measurements: bias and NEES by range band")
{
    double sr, sb_deg, bands[MAX_BANDS];
    long samples;
    int n_bands;
    const struct sim_opt opts[] = {
        SIM_OPT_DOUBLE("--sigma-range-m", &sr, "S", "7.5", SIM_GT, 0, 0, "range noise (m, 1 sigma)"),
        SIM_OPT_DOUBLE("--sigma-bearing-deg", &sb_deg, "S", "1.5", SIM_GT | SIM_LE, 0, 28, "bearing noise (degrees)"),
        SIM_OPT_LIST("--bands", bands, &n_bands, MAX_BANDS, "500,1000,2000,4000,6000,8000", SIM_GT, 0, 0,
                     "band edges (m, increasing)"),
        SIM_OPT_LONG("--samples", &samples, "N", "100000", SIM_IN, 100, 100000000, "samples per band"),
        SIM_OPT_END};
    const struct sim_cli cli = {
        "polar", NULL,
        "A polar sensor's detections converted to positions (trk_polar_to_cartesian) by range band:\n"
        "bias along and across the range, RMS error and NEES with the conversion's own covariance,\n"
        "for the first-order and the unbiased conversion (docs/conventions.md \"Polar detections\").",
        opts, "build/results/polar", NULL, SIM_UNUSED_RUNS | SIM_UNUSED_THREADS,
        "Writes PREFIX.csv: one row per (conversion, band).", NULL, NULL};
    struct sim_common com;
    const int parsed = sim_parse(&cli, &com, argc, argv);
    if (parsed != SIM_RUN) return parsed;
    for (int k = 1; k < n_bands; k++)
        if (!(bands[k] > bands[k - 1])) {
            fprintf(stderr, "trk-sim polar: --bands must increase\n");
            return 2;
        }
    if (n_bands < 2) {
        fprintf(stderr, "trk-sim polar: --bands needs at least two edges\n");
        return 2;
    }
    const double sb = sb_deg * 3.14159265358979323846 / 180;
    struct fileio_out o;
    FILE *f = sim_csv_open(&com, &o, ".csv", NULL, 0,
                           "conversion,r0_m,r1_m,criterion,bias_along_m,bias_cross_m,rms_m,nees,nees_over_95");
    if (!f) return 1;
    printf("== trk-sim polar: sigma_r %g m, sigma_b %g deg, %ld samples per band, bearings +-60 deg\n", sr, sb_deg,
           samples);
    printf("%-12s %13s %9s %10s %10s %9s %6s %7s\n", "conversion", "band (m)", "r sb^2/sr", "bias along", "bias cross",
           "rms", "NEES", ">95%");
    for (int conv = 0; conv <= 1; conv++)
        for (int b = 0; b + 1 < n_bands; b++) {
            struct band_stat st;
            band_run(com.seed, b, bands[b], bands[b + 1], samples, sr, sb, conv, &st);
            const double mid = 0.5 * (bands[b] + bands[b + 1]), crit = mid * sb * sb / sr;
            const char *name = conv ? "unbiased" : "first-order";
            printf("%-12s %6.0f-%-6.0f %9.3f %8.2f m %8.2f m %7.1f m %6.3f %7.4f\n", name, bands[b], bands[b + 1], crit,
                   st.along, st.cross, st.sq, st.nees, st.over);
            fprintf(f, "%s,%g,%g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", name, bands[b], bands[b + 1], crit, st.along,
                    st.cross, st.sq, st.nees, st.over);
        }
    return sim_csv_close(&o) == 0 ? 0 : 1;
}
