/* bench_amplitude.c - amplitude tables: accuracy against the direct
 * evaluation, bytes against error, lookup speed.
 *
 *   amp_err_*        Brekke's setting (K clutter nu = 1 and 8, SNR 15 dB,
 *                    P_FA 1e-4 .. 1e-1) at the default sizes: max |ln l^a
 *                    error| over [t, a_max] ("abs") and max relative a(x)
 *                    error over x in [0, 40] ("rel"), measured at 5 points per
 *                    table interval (tools/gen/amp_table.c); the largest of
 *                    the eight tables as amp_err_log_lr_max / amp_err_inv_sf_max
 *   amp_geometric_*  the paper's geometric grid (eqs 43-45, A = 0.25, last 100,
 *                    piecewise linear) at the default size, nu = 1, P_FA 1e-3
 *   amp_curve_N*     table bytes and errors against size N (both table kinds
 *                    at N points), nu = 1, SNR 15 dB, P_FA 1e-1 (the hardest
 *                    of the set): the bytes/error curve of this build's width
 *   amp_bytes        bytes of one default table
 *   amp_log_lr_*     ns per ln l^a: table lookup (K), closed form (Rayleigh),
 *                    direct evaluation by quadrature (kdist), and their ratio
 *                    (amp_log_lr_speedup, and amp_log_lr_table_vs_direct =
 *                    table / direct, the ratio against its baseline)
 *   amp_inv_sf_table ns per a(x) lookup (the simulator's amplitude draw) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "bench.h"
#include "kdist.h"
#include "trk/amplitude.h"

static int build(double nu, double pfa, int grid, uint32_t n, uint32_t nllr, int measure,
                 struct amp_table_result *r)
{
    struct amp_table_opts o;
    amp_table_opts_init(&o, TRK_AMP_K, nu, 15, pfa);
    o.grid = grid;
    o.size = n;
    o.llr_size = nllr;
    o.measure = measure;
    o.measure_points = 5;
    char err[256];
    if (amp_table_build(&o, r, err, sizeof err) != 0) {
        fprintf(stderr, "trk-bench amplitude: %s\n", err);
        return -1;
    }
    return 0;
}

TRK_BENCH(amp_error)
{
    static const double nus[2] = {1, 8}, pfas[4] = {1e-4, 1e-3, 1e-2, 1e-1};
    double e_llr = 0, e_inv = 0;
    size_t bytes = 0;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 4; j++) {
            struct amp_table_result r;
            if (build(nus[i], pfas[j], 0, 0, 0, 1, &r)) return;
            char name[64];
            snprintf(name, sizeof name, "amp_err_log_lr_k%g_pfa%g", nus[i], pfas[j]);
            bench_print(name, r.err_log_lr, "abs");
            snprintf(name, sizeof name, "amp_err_inv_sf_k%g_pfa%g", nus[i], pfas[j]);
            bench_print(name, r.err_inv_sf, "rel");
            e_llr = fmax(e_llr, r.err_log_lr);
            e_inv = fmax(e_inv, r.err_inv_sf);
            bytes = r.len;
            free(r.bytes);
        }
    bench_print("amp_err_log_lr_max", e_llr, "abs");
    bench_print("amp_err_inv_sf_max", e_inv, "rel");
    bench_print("amp_bytes", (double)bytes, "bytes");
    struct amp_table_result g;
    if (build(1, 1e-3, TRK_AMP_GRID_GEOMETRIC, 0, 0, 1, &g)) return;
    bench_print("amp_geometric_err_inv_sf", g.err_inv_sf, "rel");
    bench_print("amp_geometric_bytes", (double)g.len, "bytes");
    free(g.bytes);
}

TRK_BENCH(amp_curve)
{
    static const uint32_t sizes[] = {16, 32, 64, 128, 256, 512, 1024};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
        struct amp_table_result r;
        if (build(1, 1e-1, 0, sizes[i], sizes[i], 1, &r)) return;
        char name[64];
        snprintf(name, sizeof name, "amp_curve_N%u_bytes", sizes[i]);
        bench_print(name, (double)r.len, "bytes");
        snprintf(name, sizeof name, "amp_curve_N%u_err_log_lr", sizes[i]);
        bench_print(name, r.err_log_lr, "abs");
        snprintf(name, sizeof name, "amp_curve_N%u_err_inv_sf", sizes[i]);
        bench_print(name, r.err_inv_sf, "rel");
        free(r.bytes);
    }
}

#define NA 1024

struct lookup_job {
    struct trk_amplitude m;
    trk_real a[NA], x[NA];
    struct kdist k;
    double pfa, pd;
    size_t next;
};

static void table_batch(void *arg)
{
    struct lookup_job *j = arg;
    trk_real s = 0;
    for (int i = 0; i < NA; i++) {
        trk_real v;
        trk_status st = trk_amplitude_log_lr(&j->m, j->a[i], &v);
        s += v + (trk_real)st;
    }
    bench_sink((double)s);
}

static void inv_batch(void *arg)
{
    struct lookup_job *j = arg;
    trk_real s = 0;
    for (int i = 0; i < NA; i++) {
        trk_real v;
        trk_status st = trk_amplitude_inv_sf(&j->m, i & 1, j->x[i], &v);
        s += v + (trk_real)st;
    }
    bench_sink((double)s);
}

static void direct_one(void *arg)
{
    struct lookup_job *j = arg;
    const double a = (double)j->a[j->next++ % NA];
    bench_sink(kdist_log_lr(&j->k, j->pfa, j->pd, a, NULL));
}

TRK_BENCH(amp_speed)
{
    static struct lookup_job j;
    struct amp_table_result r;
    if (build(1, 1e-3, 0, 0, 0, 0, &r)) return;
    struct trk_table t;
    if (trk_table_parse(&t, r.bytes, r.len) != TRK_OK || trk_amplitude_init_table(&j.m, &t) != TRK_OK) {
        free(r.bytes);
        return;
    }
    uint64_t s = 7;
    for (int i = 0; i < NA; i++) { /* amplitudes spread over [t, a_max], x over [0, 40] */
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        const double u = (double)(s >> 11) / 9007199254740992.0;
        j.a[i] = (trk_real)(r.threshold * pow(r.a_max / r.threshold, u));
        j.x[i] = (trk_real)(40 * u);
    }
    kdist_init(&j.k, 1, 15);
    j.pfa = 1e-3;
    j.pd = r.pd;
    const double t_table = bench_time_ns(table_batch, &j, 5) / NA;
    const double t_inv = bench_time_ns(inv_batch, &j, 5) / NA;
    const double t_direct = bench_time_ns(direct_one, &j, 3);
    bench_print("amp_log_lr_table", t_table, "ns");
    bench_print("amp_log_lr_direct", t_direct, "ns");
    bench_print("amp_log_lr_speedup", t_direct / t_table, "x");
    bench_print("amp_log_lr_table_vs_direct", t_table / t_direct, "x");
    bench_print("amp_inv_sf_table", t_inv, "ns");
    if (trk_amplitude_init_rayleigh(&j.m, 1, 15, TRK_REAL_C(1e-3)) == TRK_OK)
        bench_print("amp_log_lr_rayleigh", bench_time_ns(table_batch, &j, 5) / NA, "ns");
    free(r.bytes);
}
