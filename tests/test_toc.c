/* test_toc.c - TOC curves and optimum of the tools (tools/sim/toc_curve.h) on
 * small q2 tables from the generator: statuses, the optimum against the
 * curve, the library's MRE at the optimum, tables of the wrong kind, gate or
 * model refused, bad scenarios refused. */
#include "trk_test.h"
#include "q2_table.h"
#include "toc_curve.h"
#include "trk/amplitude.h"
#include "trk/mre.h"
#include "trk/q2.h"

/* A small table: PDAF over pd x lambda_vg, or PDAFAI (Rayleigh or K) over
 * snr {10, 20} x pfa x lambda_vg, gamma 36, few samples (fast, rough). */
static unsigned char *small_table(int pdafai, int model, double nu, double gamma, double lv_max, size_t *len)
{
    static const double pd[6] = {0.5, 0.7, 0.8, 0.9, 0.95, 1.0};
    struct q2_table_spec s;
    memset(&s, 0, sizeof s);
    s.detector = pdafai ? TRK_Q2_PDAFAI : TRK_Q2_PDAF;
    s.nz = 2;
    s.gate_gamma = gamma;
    s.cubic = 1;
    s.lambda_vg = (struct q2_table_axis){8, 1e-6, lv_max, NULL};
    if (pdafai) {
        s.amp_model = model;
        s.nu = nu;
        s.snr_db = (struct q2_table_axis){2, 10, 20, NULL};
        s.pfa = (struct q2_table_axis){5, 1e-5, 0.5, NULL};
        s.amp_size = 32;
    } else {
        s.pd = (struct q2_table_axis){6, 0.5, 1, pd};
    }
    struct q2_table_run r;
    memset(&r, 0, sizeof r);
    r.samples = 3000;
    r.seed = 9;
    r.threads = 1;
    struct q2_table_result res;
    char err[300];
    if (q2_table_build(&s, &r, &res, err, sizeof err)) fail_msg("%s", err);
    *len = res.len;
    unsigned char *b = res.bytes;
    res.bytes = NULL;
    q2_table_result_free(&res);
    return b;
}

static void test_toc_tables(void **state)
{
    (void)state;
    size_t lp, la;
    unsigned char *bp = small_table(0, 0, 0, 36, 30, &lp), *ba = small_table(1, TRK_AMP_RAYLEIGH, 0, 36, 30, &la);
    struct trk_table tp, ta;
    TRK_ASSERT_OK(trk_table_parse(&tp, bp, lp));
    TRK_ASSERT_OK(trk_table_parse(&ta, ba, la));
    struct toc_scenario sc;
    toc_scenario_brekke(&sc, TRK_AMP_RAYLEIGH, 0, 15, 1.0);
    sc.pfa_min = 1e-5;
    struct toc_q2_source src;
    memset(&src, 0, sizeof src);
    src.pdaf = &tp;
    src.pdafai = &ta;
    char err[300];
    struct toc *t = toc_new(&sc, &src, err, sizeof err);
    if (!t) fail_msg("%s", err);

    /* the Rayleigh ROC of the library */
    double pd;
    assert_int_equal(toc_pd(t, 1e-3, &pd, err, sizeof err), 0);
    TRK_ASSERT_NEAR(pd, pow(1e-3, 1 / (1 + pow(10, 1.5))), 0, TRK_TOL(1e-13, 1e-6));

    /* a curve: steady states with q2 in (0, 1); the PDAFAI no worse than the
     * PDAF at low pfa; the PDAF leaves its table (lambda_vg <= 30) at high pfa */
    enum { N = 25 };
    struct toc_point pts[N];
    assert_int_equal(toc_curve(t, N, pts, err, sizeof err), 0);
    TRK_ASSERT_NEAR(pts[0].pfa, 1e-5, 0, 1e-12);
    TRK_ASSERT_NEAR(pts[N - 1].pfa, 0.5, 0, 1e-12);
    int ok = 0, off = 0;
    for (int i = 0; i < N; i++)
        for (int d = 0; d < TOC_N_DETECTORS; d++) {
            if (pts[i].status[d] == TOC_OK) {
                ok++;
                assert_true(pts[i].q2[d] > 0 && pts[i].q2[d] < 1 && pts[i].rmse_m[d] > 0);
                assert_true(isfinite(pts[i].rmse_m[d]) && pts[i].lambda_vg[d] <= 30 * (1 + 1e-9));
            } else {
                off++;
                assert_true(isinf(pts[i].rmse_m[d]));
                if (pts[i].status[d] == TOC_OFF_TABLE) assert_true(pts[i].rmse_bound_m[d] > 0);
            }
        }
    assert_true(ok > N && off > 0);
    assert_int_equal(pts[0].status[TOC_PDAF], TOC_OK);
    assert_int_equal(pts[N - 1].status[TOC_PDAF], TOC_OFF_TABLE);

    /* the optimum: no curve point lower, the library's MRE agrees there */
    for (int d = 0; d < TOC_N_DETECTORS; d++) {
        struct toc_optimum o;
        assert_int_equal(toc_optimum(t, d, &o, err, sizeof err), 0);
        assert_true(o.pfa >= sc.pfa_min * (1 - TRK_TOL(1e-12, 1e-5)) && o.pfa <= sc.pfa_max * (1 + TRK_TOL(1e-12, 1e-5)));
        assert_true(o.pfa_1pct_lo <= o.pfa && o.pfa <= o.pfa_1pct_hi);
        for (int i = 0; i < N; i++)
            if (pts[i].status[d] == TOC_OK) assert_true(o.rmse_m <= pts[i].rmse_m[d] * (1 + 1e-9));
        struct toc_point p;
        assert_int_equal(toc_point_at(t, o.pfa, &p, err, sizeof err), 0);
        TRK_ASSERT_NEAR(p.rmse_m[d], o.rmse_m, 0, TRK_TOL(1e-12, 1e-5));
        TRK_ASSERT_NEAR(p.pd, o.pd, 0, 1e-12);
        double q2;
        assert_int_equal(toc_q2(t, d, o.pfa, o.lambda_vg, &q2, err, sizeof err), 0);
        TRK_ASSERT_NEAR(q2, o.q2, TRK_TOL(1e-9, 1e-5), 0);
    }
    /* a smaller cell: more clutter per pfa, the PDAF's optimum moves down */
    struct toc_optimum o1, o2;
    assert_int_equal(toc_optimum(t, TOC_PDAF, &o1, err, sizeof err), 0);
    assert_int_equal(toc_set_cell_m2(t, 0.1, err, sizeof err), 0);
    assert_int_equal(toc_optimum(t, TOC_PDAF, &o2, err, sizeof err), 0);
    assert_true(o2.pfa < o1.pfa && o2.rmse_m > o1.rmse_m);
    assert_int_equal(toc_set_cell_m2(t, -1, err, sizeof err), -1);
    assert_int_equal(toc_point_at(t, 1.5, &pts[0], err, sizeof err), -1);
    toc_free(t);

    /* tables that do not fit the scenario */
    src.pdafai = &tp; /* a PDAF table as the PDAFAI's */
    assert_null(toc_new(&sc, &src, err, sizeof err));
    assert_non_null(strstr(err, "PDAFAI"));
    src.pdafai = &ta;
    sc.gate_gamma = 25; /* another gate */
    assert_null(toc_new(&sc, &src, err, sizeof err));
    assert_non_null(strstr(err, "gate"));
    sc.gate_gamma = 36;
    sc.amp_model = TRK_AMP_K; /* another clutter model */
    sc.nu = 1;
    assert_null(toc_new(&sc, &src, err, sizeof err));
    assert_non_null(strstr(err, "clutter"));
    toc_scenario_brekke(&sc, TRK_AMP_RAYLEIGH, 0, 25, 1.0); /* SNR outside the table */
    assert_null(toc_new(&sc, &src, err, sizeof err));
    assert_non_null(strstr(err, "snr_db"));
    /* bad scenarios */
    toc_scenario_brekke(&sc, TRK_AMP_RAYLEIGH, 0, 15, 0);
    assert_null(toc_new(&sc, &src, err, sizeof err));
    toc_scenario_brekke(&sc, TRK_AMP_RAYLEIGH, 0, NAN, 1);
    assert_null(toc_new(&sc, &src, err, sizeof err));
    toc_scenario_brekke(&sc, TRK_AMP_RAYLEIGH, 0, 15, 1);
    sc.pfa_min = 0.6;
    assert_null(toc_new(&sc, &src, err, sizeof err));
    free(bp);
    free(ba);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_toc_tables),
    };
    return trk_run_tests("toc", tests, NULL, NULL);
}
