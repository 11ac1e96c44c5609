/* bench_q2.c - q2 importance sampler (tools/gen/q2_is.c) and the q2 /
 * MRE / CRLB library functions.
 *
 *   q2_is_*_points_per_s   target + clutter points drawn per second on ONE
 *                          thread (the numpy reference draws ~4e6/s/core);
 *                          pdaf, pdafai (Rayleigh), pdafai_k (K nu = 1)
 *   q2_is_*_scenes_per_s   scenes (one target + n clutter points) per second
 *   q2_is_parallel_eff     rate on 2 threads / (2 x rate on 1 thread)
 *   q2_is_bitident         1 when 1- and 2-thread outputs are bit-identical
 *   q2_table_*_s, q2_default_tables_*   wall and CPU time of the default
 *                          tables of `make tables` on all threads at se <= 1e-3
 *                          per cell (see below; ~80 s CPU)
 *   q2_lookup_*_ns         lookups on plain arrays and on a q2 table (in place)
 *   mre_*_ns, crlb_*_ns    library calls; mre_steady_lookup_vs_const the
 *                          q2-lookup MRE against the constant-q2 one (baseline)
 * Wall-clock timings: the machine is shared, so run it on a quiet machine. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "q2_amp.h"
#include "q2_is.h"
#include "q2_table.h"
#include "table_writer.h"
#include "trk/amplitude.h"
#include "trk/crlb.h"
#include "trk/mre.h"
#include "trk/q2.h"

#include <time.h>

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double last_cpu_s; /* process CPU time of the last run */

static int run(struct q2_is_line *l, size_t n, uint64_t samples, double target_se, int threads, double *sec)
{
    struct q2_is_options o;
    memset(&o, 0, sizeof o);
    o.seed = 7;
    o.samples = samples;
    o.target_se = target_se;
    o.threads = threads;
    char err[200];
    double t0 = bench_now_ns(), c0 = cpu_s();
    int rc = q2_is_run(l, n, &o, err, sizeof err);
    *sec = (bench_now_ns() - t0) * 1e-9;
    last_cpu_s = cpu_s() - c0;
    if (rc) fprintf(stderr, "trk-bench q2: %s\n", err);
    return rc;
}

/* One cell: PDAF pd 0.9, pg 0.99, lambda_vg 3 (q2.vec pdaf_03), or PDAFAI
 * 15 dB, gamma 36, lambda_vg 3: Rayleigh at pfa 1e-3 (ai_02), K nu 1 at pfa
 * 1e-2 (ai_04). det: 0 PDAF, 1 PDAFAI Rayleigh, 2 PDAFAI K. */
static int cell_rate(int det, int threads, double *pts_s, double *scenes_s, double *q2, double *pts_cpu_s)
{
    static struct q2_amp r[3];
    static struct q2_amp_sampler amp[3];
    static int ready;
    char err[256];
    if (!ready) {
        if (q2_amp_init(&r[1], TRK_AMP_RAYLEIGH, 0, 15, 1e-3, 0, 0, err, sizeof err) ||
            q2_amp_init(&r[2], TRK_AMP_K, 1, 15, 1e-2, 0, 0, err, sizeof err)) {
            fprintf(stderr, "trk-bench q2: %s\n", err);
            return -1;
        }
        amp[1] = q2_amp_sampler_of(&r[1]);
        amp[2] = q2_amp_sampler_of(&r[2]);
        ready = 1;
    }
    double pd = det ? r[det].pd : 0.9, lv = 3, se, sec;
    struct q2_is_line l;
    memset(&l, 0, sizeof l);
    l.nz = 2, l.gamma = det ? 36 : -2 * log1p(-0.99), l.amp = det ? &amp[det] : NULL;
    l.n_cells = 1, l.pd = &pd, l.lambda_vg = &lv, l.q2 = q2, l.se = &se;
    if (run(&l, 1, det ? 1500000 : 4000000, 0, threads, &sec)) return -1;
    *pts_s = (double)l.points / sec;
    *scenes_s = (double)l.scenes / sec;
    *pts_cpu_s = (double)l.points / last_cpu_s;
    return 0;
}

TRK_BENCH(q2_is)
{
    const char *name[3] = {"pdaf", "pdafai", "pdafai_k"};
    for (int ai = 0; ai < 3; ai++) {
        double p1, s1, p2, s2, q1, q2v, c1, c2, best_p = 0, best_s = 0, best_c1 = 0, best_c2 = 0;
        for (int rep = 0; rep < 3; rep++) { /* best of 3: the machine is shared */
            if (cell_rate(ai, 1, &p1, &s1, &q1, &c1)) return;
            if (p1 > best_p) best_p = p1, best_s = s1;
            if (c1 > best_c1) best_c1 = c1;
        }
        char b[64];
        snprintf(b, sizeof b, "q2_is_%s_points_per_s", name[ai]);
        bench_print(b, best_p, "points/s/core");
        snprintf(b, sizeof b, "q2_is_%s_scenes_per_s", name[ai]);
        bench_print(b, best_s, "scenes/s/core");
        double best2 = 0;
        for (int rep = 0; rep < 3; rep++) {
            if (cell_rate(ai, 2, &p2, &s2, &q2v, &c2)) return;
            if (p2 > best2) best2 = p2;
            if (c2 > best_c2) best_c2 = c2;
        }
        snprintf(b, sizeof b, "q2_is_%s_parallel_eff", name[ai]);
        bench_print(b, q2_is_parallel() ? best2 / (2 * best_p) : 0, "(2 threads vs 1, wall)");
        /* points per CPU second, 2 threads vs 1: the parallel overhead alone,
         * meaningful on a busy machine where the wall-clock ratio is not */
        snprintf(b, sizeof b, "q2_is_%s_parallel_cpu_eff", name[ai]);
        bench_print(b, q2_is_parallel() ? best_c2 / best_c1 : 0, "(2 threads vs 1, CPU time)");
        snprintf(b, sizeof b, "q2_is_%s_bitident", name[ai]);
        bench_print(b, memcmp(&q1, &q2v, sizeof q1) == 0, "bool");
    }
}

/* The default tables of `make tables` (mk/q2tables.mk; grids q2_table.h) at
 * se <= 1e-3 per cell on all threads: wall and CPU time, points, largest se.
 * A long run (~80 s CPU): the machine should be quiet. */
static int default_spec(int k, struct q2_table_spec *s)
{
    static double pd[Q2_TABLE_MAX_NODES], snr[Q2_TABLE_MAX_NODES];
    memset(s, 0, sizeof *s);
    s->nz = 2;
    s->cubic = 1;
    s->gate_gamma = k == 0 ? -2 * log1p(-0.99) : 36;
    if (k < 2) {
        s->detector = TRK_Q2_PDAF;
        int n = q2_table_parse_list(Q2_TABLE_DEFAULT_PD, pd, (int)Q2_TABLE_MAX_NODES);
        if (n < 2) return -1;
        q2_table_list_axis(pd, n, &s->pd);
        return q2_table_parse_log(Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF, &s->lambda_vg);
    }
    s->detector = TRK_Q2_PDAFAI;
    s->amp_model = k == 2 ? TRK_AMP_RAYLEIGH : TRK_AMP_K;
    s->nu = k == 3 ? 1 : k == 4 ? 8 : 0;
    int n = q2_table_parse_list(Q2_TABLE_DEFAULT_SNR_DB, snr, (int)Q2_TABLE_MAX_NODES);
    if (n < 2) return -1;
    q2_table_list_axis(snr, n, &s->snr_db);
    return q2_table_parse_log(Q2_TABLE_DEFAULT_PFA, &s->pfa) ||
           q2_table_parse_log(Q2_TABLE_DEFAULT_LAMBDA_VG_PDAFAI, &s->lambda_vg);
}

TRK_BENCH(q2_default_tables)
{
    static const char *const name[5] = {"pdaf_pg099", "pdaf_g6", "pdafai_rayleigh_g6", "pdafai_k1_g6",
                                        "pdafai_k8_g6"};
    double wall = 0, cpu = 0, pts = 0, mx = 0;
    for (int k = 0; k < 5; k++) {
        struct q2_table_spec s;
        if (default_spec(k, &s)) return;
        struct q2_table_run r;
        memset(&r, 0, sizeof r);
        r.samples = Q2_TABLE_DEFAULT_SAMPLES;
        r.target_se = Q2_TABLE_DEFAULT_TARGET_SE;
        r.seed = 1;
        struct q2_table_result res;
        char err[300];
        const double t0 = bench_now_ns(), c0 = cpu_s();
        if (q2_table_build(&s, &r, &res, err, sizeof err)) {
            fprintf(stderr, "trk-bench q2: %s: %s\n", name[k], err);
            return;
        }
        const double dt = (bench_now_ns() - t0) * 1e-9, dc = cpu_s() - c0;
        char b[96];
        snprintf(b, sizeof b, "q2_table_%s_wall_s", name[k]);
        bench_print(b, dt, "s");
        snprintf(b, sizeof b, "q2_table_%s_cpu_s", name[k]);
        bench_print(b, dc, "s");
        wall += dt, cpu += dc, pts += (double)res.points;
        if (res.max_se > mx) mx = res.max_se;
        q2_table_result_free(&res);
    }
    bench_print("q2_default_tables_wall_s", wall, "s");
    bench_print("q2_default_tables_cpu_s", cpu, "s (process CPU time, all threads)");
    bench_print("q2_default_tables_points", pts, "points");
    bench_print("q2_default_tables_max_se", mx, "");
    bench_print("q2_default_tables_threads", q2_is_threads(0), "threads");
}

/* ---- library ---- */

static struct trk_q2_lookup lk2l, lk2c, lk3c;
static trk_real v2[21 * 49], v3[5 * 24 * 49];

static void setup_grids(void)
{
    for (int i = 0; i < 21; i++)
        for (int j = 0; j < 49; j++) v2[i * 49 + j] = (trk_real)((0.5 + 0.025 * i) / (1 + pow(10.0, -4 + j / 8.0)));
    for (int k = 0; k < 5 * 24 * 49; k++) v3[k] = (trk_real)(0.5 + 0.4 * sin(0.001 * k));
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    g.detector = TRK_Q2_PDAF;
    g.axis[0] = (struct trk_q2_axis){21, NULL, TRK_REAL_C(0.5), 1, 0, TRK_Q2_LINEAR};
    g.axis[1] = (struct trk_q2_axis){49, NULL, (trk_real)log(1e-4), (trk_real)log(100.0), 1, TRK_Q2_LINEAR};
    g.values = v2;
    if (trk_q2_lookup_init(&lk2l, &g) != TRK_OK) fprintf(stderr, "trk-bench q2: grid\n");
    g.axis[0].interp = g.axis[1].interp = TRK_Q2_CUBIC;
    if (trk_q2_lookup_init(&lk2c, &g) != TRK_OK) fprintf(stderr, "trk-bench q2: grid\n");
    struct trk_q2_grid h;
    memset(&h, 0, sizeof h);
    h.detector = TRK_Q2_PDAFAI;
    h.axis[0] = (struct trk_q2_axis){5, NULL, 5, 25, 0, TRK_Q2_CUBIC};
    h.axis[1] = (struct trk_q2_axis){24, NULL, (trk_real)log(1e-6), (trk_real)log(0.5), 1, TRK_Q2_CUBIC};
    h.axis[2] = (struct trk_q2_axis){49, NULL, (trk_real)log(1e-4), (trk_real)log(100.0), 1, TRK_Q2_CUBIC};
    h.values = v3;
    if (trk_q2_lookup_init(&lk3c, &h) != TRK_OK) fprintf(stderr, "trk-bench q2: grid\n");
}

static unsigned lk_i;
static void lk2(void *a)
{
    trk_real v;
    lk_i = lk_i * 1103515245u + 12345u;
    trk_real pd = TRK_REAL_C(0.5) + (trk_real)(lk_i >> 16 & 1023) * TRK_REAL_C(0.00048);
    trk_real lv = TRK_REAL_C(0.001) + (trk_real)(lk_i >> 8 & 1023) * TRK_REAL_C(0.05);
    if (trk_q2_pdaf(a, pd, lv, &v) == TRK_OK) bench_sink((double)v);
}
static void lk3(void *a)
{
    trk_real v;
    lk_i = lk_i * 1103515245u + 12345u;
    trk_real pfa = TRK_REAL_C(1e-5) + (trk_real)(lk_i >> 16 & 1023) * TRK_REAL_C(4e-4);
    trk_real lv = TRK_REAL_C(0.001) + (trk_real)(lk_i >> 8 & 1023) * TRK_REAL_C(0.05);
    if (trk_q2_pdafai(a, TRK_REAL_C(12.3), pfa, lv, &v) == TRK_OK) bench_sink((double)v);
}

/* The same 3-D cubic grid as a q2 table (the file format, used in place). */
static struct trk_q2_lookup lk_tab;
static unsigned char *tab_bytes;

static int setup_table(void)
{
    struct tablew *w = tablew_new(TRK_TABLE_KIND_Q2_PDAFAI, TRK_Q2_TABLE_VERSION, (uint32_t)sizeof(trk_real));
    static double data[2 * 5 * 24 * 49];
    for (int k = 0; k < 5 * 24 * 49; k++) data[2 * k] = (double)v3[k], data[2 * k + 1] = 1e-3;
    const struct tablew_axis ax[3] = {{5, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_SNR_DB, 5, 25, 0, NULL},
                                      {24, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_PFA, 1e-6, 0.5, 0, NULL},
                                      {49, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_LAMBDA_VG, 1e-4, 100, 0, NULL}};
    size_t len;
    struct trk_table t;
    if (!w || tablew_param_int(w, "detector", TRK_Q2_PDAFAI) || tablew_param_int(w, "nz", 2) ||
        tablew_param_real(w, "gate_gamma", 36) || tablew_param_real(w, "gate_prob", -expm1(-18.0)) ||
        tablew_param_real(w, "max_se", 1e-3) || tablew_param_int(w, "model", TRK_AMP_RAYLEIGH) ||
        tablew_param_real(w, "nu", 0) ||
        tablew_section(w, TRK_Q2_SECTION_VALUES, 3, ax, 2, TRK_TABLE_INTERP_CUBIC, data) ||
        tablew_finish(w, &tab_bytes, &len) || trk_table_parse(&t, tab_bytes, len) != TRK_OK ||
        trk_q2_lookup_init_table(&lk_tab, &t, TRK_Q2_PDAFAI, 2) != TRK_OK) {
        fprintf(stderr, "trk-bench q2: q2 table\n");
        tablew_free(w);
        return -1;
    }
    tablew_free(w);
    return 0;
}

TRK_BENCH(q2_lookup)
{
    setup_grids();
    bench_print("q2_lookup_pdaf_linear_ns", bench_time_ns(lk2, &lk2l, 5), "ns");
    bench_print("q2_lookup_pdaf_cubic_ns", bench_time_ns(lk2, &lk2c, 5), "ns");
    bench_print("q2_lookup_pdafai_cubic_ns", bench_time_ns(lk3, &lk3c, 5), "ns");
    if (setup_table() == 0) bench_print("q2_lookup_pdafai_cubic_table_ns", bench_time_ns(lk3, &lk_tab, 5), "ns");
    free(tab_bytes);
    tab_bytes = NULL;
}

/* MRE steady state, Brekke's Table I model (T 1 s, q 0.0125^2, R I/12, g 6):
 * constant q2 0.88 (q2.vec mre_01), and q2 looked up each step on the cubic
 * PDAF grid above at pd 0.9, lambda 0.01 per m^2. */
static struct trk_mre mre_const, mre_lookup;
static struct trk_q2_line mre_line;
static void mre_solve(void *a)
{
    struct trk_mre_result r;
    if (trk_mre_steady_state(a, NULL, &r) == TRK_OK) bench_sink((double)r.rmse_m + r.iterations);
}
static struct trk_crlb crlb_b;
static void crlb_solve(void *a)
{
    struct trk_crlb_result r;
    if (trk_crlb_steady_state(a, NULL, &r) == TRK_OK) bench_sink((double)r.pos_rmse_m);
}

TRK_BENCH(mre)
{
    setup_grids();
    struct trk_mre_params p;
    memset(&p, 0, sizeof p);
    p.nz = 2, p.dt_s = 1, p.q_m2_per_s3 = TRK_REAL_C(0.00015625), p.r_m2 = TRK_REAL_C(1.0) / 12;
    p.gate_gamma = 36, p.clutter_density = TRK_REAL_C(0.001), p.q2 = TRK_REAL_C(0.88);
    if (trk_mre_init(&mre_const, &p) != TRK_OK) return;
    struct trk_mre_result r;
    if (trk_mre_steady_state(&mre_const, NULL, &r) != TRK_OK) return;
    bench_print("mre_steady_const_iterations", r.iterations, "steps");
    bench_print("mre_steady_const_ns", bench_time_ns(mre_solve, &mre_const, 5), "ns");
    mre_line.lookup = &lk2c;
    mre_line.fixed[0] = TRK_REAL_C(0.9);
    p.q2_fn = trk_q2_line_eval, p.q2_ctx = &mre_line, p.clutter_density = TRK_REAL_C(0.01);
    if (trk_mre_init(&mre_lookup, &p) != TRK_OK) return;
    if (trk_mre_steady_state(&mre_lookup, NULL, &r) != TRK_OK) return;
    bench_print("mre_steady_lookup_iterations", r.iterations, "steps");
    const double t_lookup = bench_time_ns(mre_solve, &mre_lookup, 5);
    bench_print("mre_steady_lookup_ns", t_lookup, "ns");
    bench_print("mre_steady_lookup_vs_const", t_lookup / bench_time_ns(mre_solve, &mre_const, 5), "x");
    struct trk_crlb_params c;
    memset(&c, 0, sizeof c);
    c.nz = 2, c.dt_s = 1, c.q_m2_per_s3 = 1, c.r_m2 = 1, c.q2 = TRK_REAL_C(0.7457);
    if (trk_crlb_init(&crlb_b, &c) != TRK_OK) return;
    bench_print("crlb_steady_ns", bench_time_ns(crlb_solve, &crlb_b, 5), "ns");
}
