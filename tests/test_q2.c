/* test_q2.c - q2 lookup (trk/q2.h): exact at nodes, linear and cubic
 * reproduction of polynomials, interpolation error bound, ROC table, bad
 * grids and queries; the importance sampler (tools/gen/q2_is.h): limits
 * with closed forms, a reference value, bad input, and bit-identical output
 * for 1 and 2 threads (this test links the OpenMP object, tests/test_q2.mk);
 * the fast exp/log and the amplitude sampler on the library's amplitude
 * module (Rayleigh closed forms, K table lookup). */
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>

#include "trk_test.h"
#include "fileio.h"
#include "par.h"
#include "q2_amp.h"
#include "q2_fastmath.h"
#include "q2_is.h"
#include "q2_table.h"
#include "table_writer.h"
#include "trk/amplitude.h"
#include "trk/q2.h"
#include "trk/special.h"

/* ---- lookup ---- */

/* A 2-D PDAF grid over pd x ln(lambda_vg) filled from f. */
#define NPD 5
#define NLV 7
static trk_real pd_nodes[NPD] = {TRK_REAL_C(0.5), TRK_REAL_C(0.6), TRK_REAL_C(0.75), TRK_REAL_C(0.9), 1};
static trk_real lv_nodes[NLV]; /* ln lambda_vg, filled in setup */
static trk_real vals[NPD * NLV];

static void fill_pdaf(struct trk_q2_grid *g, double (*f)(double pd, double u), int interp)
{
    for (int j = 0; j < NLV; j++) lv_nodes[j] = (trk_real)(log(0.01) + j * 0.7 + (j == 3 ? 0.1 : 0));
    for (int i = 0; i < NPD; i++)
        for (int j = 0; j < NLV; j++) vals[i * NLV + j] = (trk_real)f(pd_nodes[i], lv_nodes[j]);
    memset(g, 0, sizeof *g);
    g->detector = TRK_Q2_PDAF;
    g->axis[0] = (struct trk_q2_axis){NPD, pd_nodes, 0, 0, 0, interp};
    g->axis[1] = (struct trk_q2_axis){NLV, lv_nodes, 0, 0, 1, interp};
    g->values = vals;
}

static double f_bilinear(double pd, double u) { return 0.3 + 0.5 * pd - 0.02 * u + 0.01 * pd * u; }
static double f_quad(double pd, double u)
{
    return 0.4 + 0.2 * pd - 0.1 * pd * pd - 0.01 * u - 0.002 * u * u + 0.01 * pd * u;
}
static double f_smooth(double pd, double u) { return pd / (1 + exp(u)); } /* q2-like */

static void test_lookup_nodes_and_polynomials(void **state)
{
    (void)state;
    struct trk_q2_grid g;
    struct trk_q2_lookup q;
    trk_real v;
    for (int interp = 0; interp <= 1; interp++) {
        /* exact at every node */
        fill_pdaf(&g, f_smooth, interp);
        TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
        for (int i = 0; i < NPD; i++)
            for (int j = 0; j < NLV; j++) {
                TRK_ASSERT_OK(trk_q2_pdaf(&q, pd_nodes[i], (trk_real)exp((double)lv_nodes[j]), &v));
                TRK_ASSERT_NEAR(v, vals[i * NLV + j], TRK_TOL(1e-14, 2e-6), 0);
            }
        /* bilinear functions are reproduced by both schemes, quadratics by the cubic one */
        fill_pdaf(&g, interp ? f_quad : f_bilinear, interp);
        TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
        for (double pd = 0.5; pd <= 1.0; pd += 0.0371)
            for (double u = (double)lv_nodes[0]; u <= (double)lv_nodes[NLV - 1]; u += 0.113) {
                TRK_ASSERT_OK(trk_q2_pdaf(&q, (trk_real)pd, (trk_real)exp(u), &v));
                double want = interp ? f_quad(pd, u) : f_bilinear(pd, u);
                TRK_ASSERT_NEAR(v, want, TRK_TOL(1e-13, 1e-5), 0);
            }
    }
}

/* Linear interpolation error of a smooth function within h^2/8 max|f''|
 * per axis; the cubic scheme several times smaller. */
static void test_lookup_error_bound(void **state)
{
    (void)state;
    struct trk_q2_grid g;
    struct trk_q2_lookup ql, qc;
    fill_pdaf(&g, f_smooth, TRK_Q2_LINEAR);
    TRK_ASSERT_OK(trk_q2_lookup_init(&ql, &g));
    static trk_real vals_c[NPD * NLV];
    memcpy(vals_c, vals, sizeof vals);
    struct trk_q2_grid gc = g;
    gc.axis[0].interp = gc.axis[1].interp = TRK_Q2_CUBIC;
    gc.values = vals_c;
    TRK_ASSERT_OK(trk_q2_lookup_init(&qc, &gc));
    /* f = pd s(u), s = 1/(1+e^u): f_pd,pd = 0, |s''| <= 1/(6 sqrt 3) ~ 0.0962, h_u <= 0.8 */
    const double bound = 0.8 * 0.8 / 8 * 0.0962 + 1e-6;
    double max_l = 0, max_c = 0;
    for (double pd = 0.5; pd <= 1.0; pd += 0.0173)
        for (double u = (double)lv_nodes[0]; u <= (double)lv_nodes[NLV - 1]; u += 0.0137) {
            trk_real vl, vc;
            TRK_ASSERT_OK(trk_q2_pdaf(&ql, (trk_real)pd, (trk_real)exp(u), &vl));
            TRK_ASSERT_OK(trk_q2_pdaf(&qc, (trk_real)pd, (trk_real)exp(u), &vc));
            double e = fabs((double)vl - f_smooth(pd, u)), ec = fabs((double)vc - f_smooth(pd, u));
            if (e > max_l) max_l = e;
            if (ec > max_c) max_c = ec;
        }
    if (!(max_l <= bound)) fail_msg("linear error %g above bound %g", max_l, bound);
    if (!(max_c <= 0.5 * max_l)) fail_msg("cubic error %g not below half the linear %g", max_c, max_l);
}

/* PDAFAI 3-D grid with uniform axes; the typed entry points check the kind. */
static void test_lookup_3d_uniform(void **state)
{
    (void)state;
    enum { NS = 3, NP = 4, NL = 5 };
    static trk_real v3[NS * NP * NL];
    for (int a = 0; a < NS; a++)
        for (int b = 0; b < NP; b++)
            for (int c = 0; c < NL; c++)
                v3[(a * NP + b) * NL + c] = (trk_real)(0.2 + 0.01 * a + 0.02 * b + 0.05 * c);
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    g.detector = TRK_Q2_PDAFAI;
    g.axis[0] = (struct trk_q2_axis){NS, NULL, 10, 20, 0, TRK_Q2_LINEAR};            /* snr 10,15,20 */
    g.axis[1] = (struct trk_q2_axis){NP, NULL, (trk_real)log(1e-4), (trk_real)log(1e-1), 1, TRK_Q2_LINEAR};
    g.axis[2] = (struct trk_q2_axis){NL, NULL, (trk_real)log(0.01), (trk_real)log(100.0), 1, TRK_Q2_CUBIC};
    g.values = v3;
    struct trk_q2_lookup q;
    TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
    trk_real v;
    /* node (1, 2, 3): snr 15, pfa 1e-2, lambda_vg 10 */
    TRK_ASSERT_OK(trk_q2_pdafai(&q, 15, TRK_REAL_C(1e-2), 10, &v));
    TRK_ASSERT_NEAR(v, 0.2 + 0.01 + 0.04 + 0.15, TRK_TOL(1e-13, 1e-5), 0);
    /* linear in every coordinate: midpoint in snr and ln pfa, lambda between nodes */
    TRK_ASSERT_OK(trk_q2_pdafai(&q, TRK_REAL_C(12.5), (trk_real)sqrt(1e-4 * 1e-3), (trk_real)sqrt(10.0), &v));
    TRK_ASSERT_NEAR(v, 0.2 + 0.005 + 0.01 + 0.125, TRK_TOL(1e-13, 1e-5), 0);
    /* ends of the axes are inside */
    TRK_ASSERT_OK(trk_q2_pdafai(&q, 20, TRK_REAL_C(1e-1), 100, &v));
    TRK_ASSERT_NEAR(v, 0.2 + 0.02 + 0.06 + 0.2, TRK_TOL(1e-13, 1e-5), 0);
    TRK_ASSERT_STATUS(trk_q2_pdaf(&q, TRK_REAL_C(0.9), 1, &v), TRK_E_TABLE_KIND);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 21, TRK_REAL_C(1e-2), 1, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 15, TRK_REAL_C(0.2), 1, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 15, TRK_REAL_C(1e-2), TRK_REAL_C(1e-3), &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 15, TRK_REAL_C(1e-2), 0, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, NAN, TRK_REAL_C(1e-2), 1, &v), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 15, TRK_REAL_C(1e-2), INFINITY, &v), TRK_E_NAN);
    /* line adapter */
    struct trk_q2_line line = {&q, {15, TRK_REAL_C(1e-2)}};
    TRK_ASSERT_OK(trk_q2_line_eval(&line, 10, &v));
    TRK_ASSERT_NEAR(v, 0.4, TRK_TOL(1e-13, 1e-5), 0);
}

/* A uniform axis and the same nodes given explicitly interpolate alike
 * (the uniform cubic path is Catmull-Rom, the general one Hermite with
 * three-point slopes: the same weights on equal spacing). */
static void test_lookup_uniform_equals_explicit(void **state)
{
    (void)state;
    enum { N = 9 };
    static trk_real nodes[N], v[2 * N];
    for (int j = 0; j < N; j++) {
        nodes[j] = (trk_real)(-3.0 + 0.75 * j);
        v[j] = (trk_real)(0.3 / (1 + exp((double)nodes[j])));
        v[N + j] = (trk_real)(0.9 / (1 + exp((double)nodes[j])));
    }
    static const trk_real pd[2] = {TRK_REAL_C(0.3), TRK_REAL_C(0.9)};
    struct trk_q2_grid gu, ge;
    memset(&gu, 0, sizeof gu);
    gu.detector = TRK_Q2_PDAF;
    gu.axis[0] = (struct trk_q2_axis){2, pd, 0, 0, 0, TRK_Q2_LINEAR};
    gu.axis[1] = (struct trk_q2_axis){N, NULL, nodes[0], nodes[N - 1], 1, TRK_Q2_CUBIC};
    gu.values = v;
    ge = gu;
    ge.axis[1].nodes = nodes;
    struct trk_q2_lookup qu, qe;
    TRK_ASSERT_OK(trk_q2_lookup_init(&qu, &gu));
    TRK_ASSERT_OK(trk_q2_lookup_init(&qe, &ge));
    for (double u = -3; u <= 3; u += 0.0371) {
        trk_real a, b;
        TRK_ASSERT_OK(trk_q2_pdaf(&qu, TRK_REAL_C(0.5), (trk_real)exp(u), &a));
        TRK_ASSERT_OK(trk_q2_pdaf(&qe, TRK_REAL_C(0.5), (trk_real)exp(u), &b));
        TRK_ASSERT_NEAR(a, b, TRK_TOL(1e-14, 1e-6), 0);
    }
}

/* A PDAF table that passes every other check (values in
 * [0, 1], pd nodes in (0, 1], CRC) with cubic interpolation and an explicit
 * pd axis holding one short interval returned 1.30, 6.61, 5 927 and 5.9e9:
 * the interpolation gain bound was not enforced for explicit axes. Such a
 * table is refused at load; the default explicit pd axis of trk-tablegen
 * (intervals 0.05 / 0.02 / 0.01 / 0.005 side by side: gain 1.61) loads, and
 * its lookups of values in [0, 1] stay within that gain. */
static trk_status load_explicit_pd(const double *pd, uint32_t npd, const double *node_vals, struct trk_q2_lookup *q,
                                   unsigned char **bytes)
{
    struct tablew *w = tablew_new(TRK_TABLE_KIND_Q2_PDAF, TRK_Q2_TABLE_VERSION, sizeof(trk_real));
    assert_non_null(w);
    const double gamma = -2 * log1p(-0.99);
    assert_false(tablew_param_int(w, "detector", TRK_Q2_PDAF) || tablew_param_int(w, "nz", 2) ||
                 tablew_param_real(w, "gate_gamma", gamma) || tablew_param_real(w, "gate_prob", 0.99) ||
                 tablew_param_real(w, "max_se", 1e-4));
    const struct tablew_axis ax[2] = {
        {npd, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_PD, pd[0], pd[npd - 1], 0, pd},
        {2, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_LAMBDA_VG, 0.1, 10, 0, NULL}};
    static double data[2 * 2 * 64];
    for (uint32_t c = 0; c < 2 * npd; c++) {
        data[2 * c] = node_vals[c / 2];
        data[2 * c + 1] = 1e-5;
    }
    assert_int_equal(tablew_section(w, TRK_Q2_SECTION_VALUES, 2, ax, 2, TRK_TABLE_INTERP_CUBIC, data), 0);
    size_t len;
    if (tablew_finish(w, bytes, &len) != 0) fail_msg("tablew: %s", tablew_error(w));
    tablew_free(w);
    struct trk_table t;
    trk_status st = trk_table_parse(&t, *bytes, len);
    if (st == TRK_OK) st = trk_q2_lookup_init_table(q, &t, TRK_Q2_PDAF, 2);
    return st;
}

static void test_lookup_explicit_gain(void **state)
{
    (void)state;
    struct trk_q2_lookup q;
    unsigned char *b;
    static const double shorts[] = {0.01, 1e-3, 1e-6, 1e-12};
    for (size_t k = 0; k < sizeof shorts / sizeof shorts[0]; k++) {
        /* 0.1 apart, but 0.5 -> 0.5 + short; the values jump across the short interval */
        if (TRK_REAL_IS_FLOAT && shorts[k] < 1e-6) continue; /* no such float interval at 0.5 */
        const double pd[8] = {0.2, 0.3, 0.4, 0.5, 0.5 + shorts[k], 0.6, 0.7, 0.8};
        static const double v[8] = {0, 0, 0, 0, 1, 1, 1, 1};
        TRK_ASSERT_STATUS(load_explicit_pd(pd, 8, v, &q, &b), TRK_E_TABLE_CORRUPT);
        free(b);
    }
    /* the default pd axis (Q2_TABLE_DEFAULT_PD), alternating values 0, 1: the worst noise */
    static const double pd[30] = {0.02, 0.04, 0.06, 0.08, 0.1,  0.15, 0.2,  0.25,  0.3,  0.35,
                                  0.4,  0.45, 0.5,  0.55, 0.6,  0.65, 0.7,  0.75,  0.8,  0.85,
                                  0.87, 0.89, 0.91, 0.93, 0.95, 0.97, 0.98, 0.99, 0.995, 1};
    double v[30];
    for (int i = 0; i < 30; i++) v[i] = i % 2;
    TRK_ASSERT_OK(load_explicit_pd(pd, 30, v, &q, &b));
    trk_real lo = 1, hi = 0;
    for (int i = 0; i + 1 < 30; i++)
        for (int k = 0; k <= 50; k++) {
            trk_real x;
            TRK_ASSERT_OK(trk_q2_pdaf(&q, (trk_real)(pd[i] + (pd[i + 1] - pd[i]) * k / 50.0), 1, &x));
            lo = x < lo ? x : lo;
            hi = x > hi ? x : hi;
        }
    /* at the nodes exactly 0 and 1; between them within the gain 1.61 of the axis */
    assert_true(lo >= TRK_REAL_C(-0.62) && lo < TRK_REAL_C(-0.1));
    assert_true(hi <= TRK_REAL_C(1.62) && hi > TRK_REAL_C(1.1));
    trk_real at;
    TRK_ASSERT_OK(trk_q2_pdaf(&q, TRK_REAL_C(0.97), 1, &at));
    TRK_ASSERT_NEAR(at, 1, TRK_TOL(1e-12, 1e-5), 0);
    free(b);
    /* the grid API refuses the same axis */
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    static trk_real nodes[8] = {TRK_REAL_C(0.2), TRK_REAL_C(0.3), TRK_REAL_C(0.4), TRK_REAL_C(0.5),
                                TRK_REAL_C(0.501), TRK_REAL_C(0.6), TRK_REAL_C(0.7), TRK_REAL_C(0.8)};
    static const trk_real lv[2] = {TRK_REAL_C(0.1), TRK_REAL_C(10.0)};
    static trk_real gvals[16];
    g.detector = TRK_Q2_PDAF;
    g.axis[0] = (struct trk_q2_axis){8, nodes, 0, 0, 0, TRK_Q2_CUBIC};
    g.axis[1] = (struct trk_q2_axis){2, lv, 0, 0, 0, TRK_Q2_LINEAR};
    g.values = gvals;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &g), TRK_E_TABLE_CORRUPT);
    g.axis[0].interp = TRK_Q2_LINEAR; /* linear weights: gain 1 on any nodes */
    TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
}

static void test_lookup_bad_grids(void **state)
{
    (void)state;
    struct trk_q2_grid g;
    struct trk_q2_lookup q;
    fill_pdaf(&g, f_smooth, TRK_Q2_LINEAR);
    TRK_ASSERT_STATUS(trk_q2_lookup_init(NULL, &g), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, NULL), TRK_E_ARG);
    struct trk_q2_grid b = g;
    b.detector = 7;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &b), TRK_E_TABLE_KIND);
    b = g;
    b.values = NULL;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &b), TRK_E_ARG);
    b = g;
    b.axis[1].count = 0;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &b), TRK_E_ARG);
    b = g;
    b.axis[0].interp = 5;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &b), TRK_E_ARG);
    /* non-monotone axis, pd node outside (0, 1], value outside [0, 1], NaN value */
    trk_real save = pd_nodes[2];
    pd_nodes[2] = pd_nodes[1];
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &g), TRK_E_TABLE_CORRUPT);
    pd_nodes[2] = save;
    save = pd_nodes[4];
    pd_nodes[4] = TRK_REAL_C(1.01);
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &g), TRK_E_TABLE_CORRUPT);
    pd_nodes[4] = save;
    save = vals[9];
    vals[9] = TRK_REAL_C(1.5);
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &g), TRK_E_TABLE_CORRUPT);
    vals[9] = NAN;
    TRK_ASSERT_STATUS(trk_q2_lookup_init(&q, &g), TRK_E_TABLE_CORRUPT);
    vals[9] = save;
    /* a PDAF grid refuses PDAFAI queries and out-of-range coordinates */
    TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
    trk_real v = -1;
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 15, TRK_REAL_C(0.01), 1, &v), TRK_E_TABLE_KIND);
    TRK_ASSERT_STATUS(trk_q2_pdaf(&q, TRK_REAL_C(0.4), 1, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdaf(&q, TRK_REAL_C(0.9), 1e6, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdaf(&q, TRK_REAL_C(0.9), -1, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_q2_pdaf(NULL, TRK_REAL_C(0.9), 1, &v), TRK_E_ARG);
    assert_true(v == -1); /* untouched on error */
}

/* ---- q2 tables (trk_q2_lookup_init_table) ---- */

/* What to spoil in a hand-made q2 table. */
enum spoil {
    OK_TABLE, KIND_AMP, VERSION2, NZ3, NO_GAMMA, GATE_MISMATCH, SE_NEGATIVE, VALUE_ABOVE_1, THREE_AXES,
    WRONG_VAR, INTERP_HERMITE_NONE, NCOMP1, LOG_PD, MAX_SE_LOW, DETECTOR_PARAM, PDAFAI_NO_MODEL
};

/* PDAF table, nz 2, gamma 9.21 (P_G 0.99), pd explicit {0.5 .. 1} x lambda_vg
 * log 0.01 .. 10 (5 nodes), values f_smooth, se 1e-4; or PDAFAI (snr 10, 20
 * x pfa 1e-3 .. 1e-1 (3) x lambda_vg) when pdafai. */
static unsigned char *make_table(int pdafai, enum spoil sp, uint32_t real_size, size_t *len)
{
    static const double pd[5] = {0.5, 0.6, 0.75, 0.9, 1};
    const double gamma = -2 * log1p(-0.99);
    struct tablew *w = tablew_new(sp == KIND_AMP ? TRK_TABLE_KIND_AMP
                                  : pdafai      ? TRK_TABLE_KIND_Q2_PDAFAI
                                                : TRK_TABLE_KIND_Q2_PDAF,
                                  sp == VERSION2 ? 2 : TRK_Q2_TABLE_VERSION, real_size);
    assert_non_null(w);
    int bad = tablew_param_int(w, "detector", sp == DETECTOR_PARAM ? 2 - pdafai : 1 + pdafai) ||
              tablew_param_int(w, "nz", sp == NZ3 ? 3 : 2) ||
              (sp != NO_GAMMA && tablew_param_real(w, "gate_gamma", gamma)) ||
              tablew_param_real(w, "gate_prob", sp == GATE_MISMATCH ? 0.95 : 0.99) ||
              tablew_param_real(w, "max_se", sp == MAX_SE_LOW ? 1e-5 : 1e-4) ||
              (pdafai && sp != PDAFAI_NO_MODEL &&
               (tablew_param_int(w, "model", TRK_AMP_K) || tablew_param_real(w, "nu", 2)));
    assert_false(bad);
    struct tablew_axis ax[3];
    const struct tablew_axis lv = {5, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_LAMBDA_VG, 0.01, 10, 0, NULL};
    uint32_t naxes;
    size_t cells;
    if (!pdafai) {
        ax[0] = (struct tablew_axis){5, sp == LOG_PD ? TRK_TABLE_SPACING_LOG : TRK_TABLE_SPACING_EXPLICIT,
                                     sp == WRONG_VAR ? TRK_TABLE_VAR_PFA : TRK_TABLE_VAR_PD, 0.5, 1, 0,
                                     sp == LOG_PD ? NULL : pd};
        ax[1] = lv;
        ax[2] = (struct tablew_axis){3, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_SNR_DB, 0, 1, 0, NULL};
        naxes = sp == THREE_AXES ? 3 : 2;
        cells = 25 * (naxes == 3 ? 3 : 1);
    } else {
        ax[0] = (struct tablew_axis){2, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_SNR_DB, 10, 20, 0, NULL};
        ax[1] = (struct tablew_axis){3, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_PFA, 1e-3, 0.1, 0, NULL};
        ax[2] = lv;
        naxes = 3;
        cells = 30;
    }
    const uint32_t ncomp = sp == NCOMP1 ? 1 : 2;
    double data[2 * 75];
    for (size_t c = 0; c < cells; c++) {
        const size_t j = c % 5;
        const double x0 = pdafai ? 0.7 + 0.01 * (double)(c / 15) + 0.02 * (double)((c / 5) % 3) : pd[(c / 5) % 5];
        const double v = f_smooth(x0, log(0.01) + (double)j * log(1000.0) / 4);
        if (ncomp == 2) {
            data[2 * c] = sp == VALUE_ABOVE_1 && c == 7 ? 1.2 : v;
            data[2 * c + 1] = sp == SE_NEGATIVE && c == 3 ? -1e-5 : 1e-4;
        } else {
            data[c] = v;
        }
    }
    assert_int_equal(tablew_section(w, TRK_Q2_SECTION_VALUES, naxes, ax, ncomp,
                                    sp == INTERP_HERMITE_NONE ? TRK_TABLE_INTERP_NONE : TRK_TABLE_INTERP_CUBIC,
                                    data),
                     0);
    unsigned char *bytes;
    if (tablew_finish(w, &bytes, len) != 0) fail_msg("tablew: %s", tablew_error(w));
    tablew_free(w);
    return bytes;
}

static trk_status load_q2(int pdafai, enum spoil sp, int want_det, int want_nz, struct trk_q2_lookup *q)
{
    size_t len;
    unsigned char *b = make_table(pdafai, sp, sizeof(trk_real), &len);
    struct trk_table t;
    trk_status st = trk_table_parse(&t, b, len);
    if (st == TRK_OK) st = trk_q2_lookup_init_table(q, &t, want_det, want_nz);
    free(b);
    return st;
}

static void test_q2_table(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = make_table(0, OK_TABLE, sizeof(trk_real), &len);
    struct trk_table t;
    TRK_ASSERT_OK(trk_table_parse(&t, b, len));
    struct trk_q2_lookup q;
    TRK_ASSERT_OK(trk_q2_lookup_init_table(&q, &t, TRK_Q2_PDAF, 2));
    assert_int_equal(q.nz, 2);
    TRK_ASSERT_NEAR(q.gate_gamma, -2 * log1p(-0.99), 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(q.max_se, 1e-4, 0, TRK_TOL(1e-15, 1e-6));
    /* in place: the values are the table's bytes */
    struct trk_table_section sec;
    TRK_ASSERT_OK(trk_table_section(&t, TRK_Q2_SECTION_VALUES, &sec));
    assert_ptr_equal(q.grid.values, sec.data);
    /* the same lookup as the plain-array grid of the same nodes and values */
    struct trk_q2_grid g;
    fill_pdaf(&g, f_smooth, TRK_Q2_CUBIC);
    for (int j = 0; j < NLV; j++) lv_nodes[j] = (trk_real)(log(0.01) + j * log(1000.0) / 4);
    for (int i = 0; i < NPD; i++)
        for (int j = 0; j < 5; j++) vals[i * 5 + j] = (trk_real)f_smooth(pd_nodes[i], lv_nodes[j]);
    g.axis[1].count = 5;
    struct trk_q2_lookup qa;
    TRK_ASSERT_OK(trk_q2_lookup_init(&qa, &g));
    for (double pdx = 0.5; pdx <= 1.0; pdx += 0.0625)
        for (double l = 0.01; l <= 10; l *= 1.7) {
            trk_real a, c;
            TRK_ASSERT_OK(trk_q2_pdaf(&q, (trk_real)pdx, (trk_real)l, &a));
            TRK_ASSERT_OK(trk_q2_pdaf(&qa, (trk_real)pdx, (trk_real)l, &c));
            TRK_ASSERT_NEAR(a, c, TRK_TOL(1e-14, 1e-6), 0);
        }
    /* the container's own checks come first: truncation, a flipped bit */
    struct trk_table t2;
    TRK_ASSERT_STATUS(trk_table_parse(&t2, b, len - 1), TRK_E_TABLE_TRUNCATED);
    b[len / 2] ^= 0x10;
    TRK_ASSERT_STATUS(trk_table_parse(&t2, b, len), TRK_E_TABLE_CRC);
    free(b);
    /* a table of the other real width is not used in place */
    b = make_table(0, OK_TABLE, sizeof(trk_real) == 8 ? 4 : 8, &len);
    TRK_ASSERT_STATUS(trk_table_parse(&t2, b, len), TRK_E_TABLE_REAL);
    free(b);

    /* wrong kind or dimension: TRK_E_TABLE_KIND */
    TRK_ASSERT_STATUS(load_q2(0, OK_TABLE, TRK_Q2_PDAFAI, 2, &q), TRK_E_TABLE_KIND); /* PDAF asked as PDAFAI */
    TRK_ASSERT_STATUS(load_q2(1, OK_TABLE, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_KIND);   /* and the reverse */
    TRK_ASSERT_STATUS(load_q2(0, KIND_AMP, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_KIND);   /* an amplitude table */
    TRK_ASSERT_STATUS(load_q2(0, OK_TABLE, TRK_Q2_PDAF, 3, &q), TRK_E_TABLE_KIND);   /* another nz asked */
    TRK_ASSERT_STATUS(load_q2(0, NZ3, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_KIND);        /* a table for nz 3 */
    TRK_ASSERT_STATUS(load_q2(0, THREE_AXES, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_KIND); /* 3 axes for the PDAF */
    TRK_ASSERT_STATUS(load_q2(0, WRONG_VAR, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_KIND);  /* pfa instead of pd */
    /* version, corrupt contents */
    TRK_ASSERT_STATUS(load_q2(0, VERSION2, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_VERSION);
    TRK_ASSERT_STATUS(load_q2(0, NO_GAMMA, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, GATE_MISMATCH, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, SE_NEGATIVE, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, MAX_SE_LOW, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, VALUE_ABOVE_1, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, INTERP_HERMITE_NONE, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, NCOMP1, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, LOG_PD, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(0, DETECTOR_PARAM, TRK_Q2_PDAF, 2, &q), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(load_q2(1, PDAFAI_NO_MODEL, TRK_Q2_PDAFAI, 2, &q), TRK_E_TABLE_CORRUPT);
    /* bad arguments */
    TRK_ASSERT_STATUS(load_q2(0, OK_TABLE, 0, 2, &q), TRK_E_ARG);
    TRK_ASSERT_STATUS(load_q2(0, OK_TABLE, TRK_Q2_PDAF, 0, &q), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_q2_lookup_init_table(&q, NULL, TRK_Q2_PDAF, 2), TRK_E_ARG);
    /* PDAFAI: model and nu, a 3-D lookup (the table outlives the lookup) */
    b = make_table(1, OK_TABLE, sizeof(trk_real), &len);
    TRK_ASSERT_OK(trk_table_parse(&t, b, len));
    TRK_ASSERT_OK(trk_q2_lookup_init_table(&q, &t, TRK_Q2_PDAFAI, 2));
    assert_int_equal(q.amp_model, TRK_AMP_K);
    TRK_ASSERT_NEAR(q.nu, 2, 0, 0);
    trk_real v;
    TRK_ASSERT_OK(trk_q2_pdafai(&q, 15, TRK_REAL_C(0.01), 1, &v));
    assert_true(v > 0 && v < 1);
    TRK_ASSERT_STATUS(trk_q2_pdafai(&q, 25, TRK_REAL_C(0.01), 1, &v), TRK_E_RANGE);
    free(b);
}

/* A table from the generator (q2_table.c) loads through the library, holds
 * the sampler's values at its nodes, and documents itself. */
static void test_q2_table_generated(void **state)
{
    (void)state;
    static const double pdn[4] = {0.6, 0.8, 0.9, 1.0};
    struct q2_table_spec s;
    memset(&s, 0, sizeof s);
    s.detector = TRK_Q2_PDAF;
    s.nz = 2;
    s.gate_gamma = 9.21;
    s.cubic = 1;
    s.pd = (struct q2_table_axis){4, 0.6, 1, pdn};
    s.lambda_vg = (struct q2_table_axis){4, 0.1, 10, NULL};
    s.measure_interp = 1;
    struct q2_table_run r;
    memset(&r, 0, sizeof r);
    r.samples = 4000;
    r.seed = 5;
    r.threads = 1;
    struct q2_table_result res;
    char err[300];
    if (q2_table_build(&s, &r, &res, err, sizeof err)) fail_msg("%s", err);
    assert_int_equal(res.n_cells, 16);
    assert_true(res.interp_measured && res.interp_n == 9);
    struct trk_table t;
    TRK_ASSERT_OK(trk_table_parse(&t, res.bytes, res.len));
    struct trk_q2_lookup q;
    TRK_ASSERT_OK(trk_q2_lookup_init_table(&q, &t, TRK_Q2_PDAF, 2));
    for (int i = 0; i < 4; i++) {
        trk_real v;
        const double l = 0.1 * pow(100.0, 1.0 / 3);
        TRK_ASSERT_OK(trk_q2_pdaf(&q, (trk_real)pdn[i], (trk_real)l, &v));
        TRK_ASSERT_NEAR(v, res.values[2 * (4 * i + 1)], TRK_TOL(1e-12, 1e-6), 0);
    }
    int64_t samples;
    trk_real mse;
    TRK_ASSERT_OK(trk_table_param_int(&t, "samples", &samples));
    assert_int_equal(samples, 4000);
    TRK_ASSERT_OK(trk_table_param_real(&t, "interp_err_max", &mse));
    TRK_ASSERT_NEAR(mse, res.interp_max, 0, TRK_TOL(1e-15, 1e-6));
    q2_table_result_free(&res);
    /* bad specs: a clear message, nothing allocated */
    s.lambda_vg.lo = -1;
    assert_int_equal(q2_table_build(&s, &r, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "lambda_vg"));
    s.lambda_vg.lo = 0.1;
    s.gate_gamma = NAN;
    assert_int_equal(q2_table_build(&s, &r, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "gamma"));
    s.gate_gamma = 9.21;
    r.samples = 0;
    assert_int_equal(q2_table_build(&s, &r, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "samples"));
    r.samples = 4000;
    static const double bad_pd[3] = {0.5, 1.2, 1.3};
    s.pd = (struct q2_table_axis){3, 0.5, 1.3, bad_pd};
    assert_int_equal(q2_table_build(&s, &r, &res, err, sizeof err), -1);
    assert_non_null(strstr(err, "pd axis"));
    assert_null(res.bytes);
}

/* Rayleigh ROC pd = pfa^(1/(1+SNR)): ln pd linear in ln pfa, so the table is exact. */
static void test_roc_table(void **state)
{
    (void)state;
    const double snr = pow(10.0, 1.5);
    static trk_real pfa[6], pd[6];
    for (int i = 0; i < 6; i++) {
        pfa[i] = (trk_real)pow(10.0, -6.0 + i);
        pd[i] = (trk_real)pow((double)pfa[i], 1 / (1 + snr));
    }
    struct trk_roc_table t = {6, pfa, pd};
    trk_real v;
    for (double x = 1e-6; x <= 0.1; x *= 1.37) {
        TRK_ASSERT_OK(trk_roc_table_eval(&t, (trk_real)x, &v));
        TRK_ASSERT_NEAR(v, pow((double)(trk_real)x, 1 / (1 + snr)), 0, TRK_TOL(1e-13, 1e-5));
    }
    TRK_ASSERT_STATUS(trk_roc_table_eval(&t, TRK_REAL_C(0.5), &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_roc_table_eval(&t, NAN, &v), TRK_E_NAN);
    struct trk_roc_table bad = {1, pfa, pd};
    TRK_ASSERT_STATUS(trk_roc_table_eval(&bad, TRK_REAL_C(1e-3), &v), TRK_E_ARG);
    /* q2 along the ROC on a PDAF grid: pd from the table, then the grid */
    struct trk_q2_grid g;
    struct trk_q2_lookup q;
    fill_pdaf(&g, f_bilinear, TRK_Q2_LINEAR);
    TRK_ASSERT_OK(trk_q2_lookup_init(&q, &g));
    struct trk_q2_roc qr = {&q, trk_roc_table_eval, &t, 0};
    TRK_ASSERT_OK(trk_q2_roc_eval(&qr, TRK_REAL_C(1e-2), TRK_REAL_C(0.1), &v));
    TRK_ASSERT_NEAR(v, f_bilinear(pow(1e-2, 1 / (1 + snr)), log(0.1)), TRK_TOL(1e-12, 1e-5), 0);
    qr.roc = NULL;
    TRK_ASSERT_STATUS(trk_q2_roc_eval(&qr, TRK_REAL_C(1e-2), TRK_REAL_C(0.1), &v), TRK_E_ARG);
}

/* ---- sampler ---- */

static void test_fastmath(void **state)
{
    (void)state;
    double worst_e = 0, worst_l = 0;
    for (double x = -708; x <= 709; x += 0.0917) {
        double a = q2_exp(x), b = exp(x);
        double e = fabs(a - b) / (nextafter(b, INFINITY) - b);
        if (e > worst_e) worst_e = e;
    }
    for (double x = 1e-12; x < 4; x = x * 1.0013 + 1e-15) {
        double a = q2_log(x), b = log(x);
        double e = fabs(a - b) / (nextafter(fabs(b), INFINITY) - fabs(b));
        if (b != 0 && e > worst_l) worst_l = e;
    }
    if (!(worst_e <= 2)) fail_msg("q2_exp error %g ulp", worst_e);
    if (!(worst_l <= 3)) fail_msg("q2_log error %g ulp", worst_l);
    assert_true(q2_exp(-709) == 0 && q2_exp(0) == 1);
}

/* The sampler is the library's inv_sf then log_lr at x = -ln u, for both
 * laws; the ROC values of q2.vec (ai_01 Rayleigh, ai_03 K nu 1). */
static void check_sampler(const struct q2_amp *a)
{
    const double u[5] = {0.9, 0.5, 1e-3, 1e-9, 1.0};
    double out[5];
    struct q2_amp_sampler s = q2_amp_sampler_of(a);
    assert_true(s.pd == a->pd);
    for (int target = 0; target <= 1; target++) {
        assert_int_equal(s.log_lr(s.ctx, target, 5, u, out), 0);
        for (int i = 0; i < 5; i++) {
            trk_real amp, l;
            TRK_ASSERT_OK(trk_amplitude_inv_sf(&a->m, target ? TRK_AMP_TARGET : TRK_AMP_CLUTTER,
                                               (trk_real)-log(u[i]), &amp));
            TRK_ASSERT_OK(trk_amplitude_log_lr(&a->m, amp, &l));
            TRK_ASSERT_NEAR(out[i], (double)l, TRK_TOL(1e-12, 2e-5), TRK_TOL(1e-12, 1e-6));
        }
    }
}

static void test_amp_sampler(void **state)
{
    (void)state;
    struct q2_amp a;
    char err[256];
    assert_int_equal(q2_amp_init(&a, TRK_AMP_RAYLEIGH, 0, 15, 1e-3, 0, 0, err, sizeof err), 0);
    TRK_ASSERT_NEAR(a.pd, 0.8091698825961493, 0, TRK_TOL(1e-14, 1e-6));
    check_sampler(&a);
    /* at the threshold: l^a(t) = (pfa/pd) p1(t)/p0(t) = 1/(1 + SNR) (u = 1: x = 0) */
    {
        const double u1 = 1;
        double l;
        struct q2_amp_sampler s = q2_amp_sampler_of(&a);
        assert_int_equal(s.log_lr(s.ctx, 0, 1, &u1, &l), 0);
        TRK_ASSERT_NEAR(l, -log1p(pow(10, 1.5)), TRK_TOL(1e-12, 1e-5), 0);
    }
    q2_amp_free(&a);
    /* K, nu 1, 15 dB, pfa 0.01, the table measured against the direct model */
    assert_int_equal(q2_amp_init(&a, TRK_AMP_K, 1, 15, 0.01, 0, 1, err, sizeof err), 0);
    assert_non_null(a.table);
    TRK_ASSERT_NEAR(a.pd, 0.77485305481652278, 0, 1e-9);
    if (!TRK_REAL_IS_FLOAT) {
        assert_true(a.measured);
        if (!(a.err_log_lr < 1e-5 && a.err_inv_sf < 1e-5))
            fail_msg("K table errors ln l^a %g, a(x) %g", a.err_log_lr, a.err_inv_sf);
    }
    check_sampler(&a);
    q2_amp_free(&a);
    /* bad input */
    assert_int_equal(q2_amp_init(&a, TRK_AMP_RAYLEIGH, 0, 15, 0, 0, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "pfa"));
    assert_int_equal(q2_amp_init(&a, TRK_AMP_RAYLEIGH, 0, NAN, 0.1, 0, 0, err, sizeof err), -1);
    assert_int_equal(q2_amp_init(&a, TRK_AMP_K, 0, 15, 0.1, 0, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "nu"));
    assert_int_equal(q2_amp_init(&a, 7, 1, 15, 0.1, 0, 0, err, sizeof err), -1);
    assert_int_equal(q2_amp_model_parse("k"), TRK_AMP_K);
    assert_int_equal(q2_amp_model_parse("x"), 0);
}

static struct q2_is_options opts(uint64_t samples, int threads)
{
    struct q2_is_options o;
    memset(&o, 0, sizeof o);
    o.seed = 20240611;
    o.samples = samples;
    o.threads = threads;
    return o;
}

/* lambda_vg -> 0: only n = 0, b -> 0, beta_1 -> 1: q2 -> pd F_4(gamma). */
static void test_is_limits(void **state)
{
    (void)state;
    const double gamma = -2 * log1p(-0.99), F = 1 - exp(-gamma / 2) * (1 + gamma / 2);
    struct q2_is_options o = opts(20000, 1);
    double q2, se;
    char err[200];
    assert_int_equal(q2_is_cell(2, gamma, 0.8, 1e-7, NULL, &o, &q2, &se, err, sizeof err), 0);
    TRK_ASSERT_NEAR(q2, 0.8 * F, 1e-5, 0);
    assert_true(se < 1e-5);
    /* nz = 1 and 3 run through the generic (libm) path: same limit */
    for (int nz = 1; nz <= 3; nz += 2) {
        const double g = 9.0;
        double Fn = (double)trk_chi2_cdf(nz + 2, (trk_real)g);
        assert_int_equal(q2_is_cell(nz, g, 0.9, 1e-7, NULL, &o, &q2, &se, err, sizeof err), 0);
        TRK_ASSERT_NEAR(q2, 0.9 * Fn, 2e-5, 0);
    }
    /* b of the docs/conventions.md formula: nz = 2, pd = 1: b = 2 lambda_vg (1 - pg) / gamma */
    TRK_ASSERT_NEAR(q2_is_b(2, gamma, 1.0, 3.0), 2 * 3.0 * 0.01 / gamma, 0, 1e-6);
}

/* A reference value (q2.vec pdaf_02: 0.50360341306552991, se 5.34e-5) with
 * few scenes: within 4.5 of our standard errors. */
static void test_is_reference(void **state)
{
    (void)state;
    struct q2_is_options o = opts(40000, 2);
    double q2, se;
    char err[200];
    assert_int_equal(q2_is_cell(2, -2 * log1p(-0.99), 0.9, 1.0, NULL, &o, &q2, &se, err, sizeof err), 0);
    assert_true(se > 1e-4 && se < 2e-3);
    TRK_ASSERT_NEAR(q2, 0.50360341306552991, 4.5 * sqrt(se * se + 5.34e-5 * 5.34e-5), 0);
    /* PDAFAI, Rayleigh (q2.vec ai_01: 0.77937236522566689, se 6.21e-5) */
    struct q2_amp r;
    assert_int_equal(q2_amp_init(&r, TRK_AMP_RAYLEIGH, 0, 15, 1e-3, 0, 0, err, sizeof err), 0);
    struct q2_amp_sampler amp = q2_amp_sampler_of(&r);
    assert_int_equal(q2_is_cell(2, 36.0, 0, 0.5, &amp, &o, &q2, &se, err, sizeof err), 0);
    TRK_ASSERT_NEAR(q2, 0.77937236522566689, 4.5 * sqrt(se * se + 6.21e-5 * 6.21e-5), 0);
    q2_amp_free(&r);
    /* PDAFAI, K nu 1 (q2.vec ai_04: 0.59473034452134488, se 8.48e-5) */
    assert_int_equal(q2_amp_init(&r, TRK_AMP_K, 1, 15, 0.01, 0, 0, err, sizeof err), 0);
    amp = q2_amp_sampler_of(&r);
    assert_int_equal(q2_is_cell(2, 36.0, 0, 4.0, &amp, &o, &q2, &se, err, sizeof err), 0);
    TRK_ASSERT_NEAR(q2, 0.59473034452134488, 4.5 * sqrt(se * se + 8.48e-5 * 8.48e-5), 0);
    q2_amp_free(&r);
}

/* Two lines (PDAF over 2 pd x 3 lambda; PDAFAI over 3 lambda) with 1 and 2
 * threads, with and without a target se: identical bits. */
static void run_lines(int threads, double target_se, double *out)
{
    static const double pd[6] = {0.6, 0.6, 0.6, 0.95, 0.95, 0.95};
    static const double lv[6] = {0.05, 1.0, 6.0, 0.05, 1.0, 6.0};
    static struct q2_amp r;
    char e0[256];
    assert_int_equal(q2_amp_init(&r, TRK_AMP_RAYLEIGH, 0, 12, 1e-2, 0, 0, e0, sizeof e0), 0);
    static struct q2_amp_sampler amp;
    amp = q2_amp_sampler_of(&r);
    struct q2_is_line lines[2];
    memset(lines, 0, sizeof lines);
    lines[0] = (struct q2_is_line){.nz = 2, .gamma = 9.21, .stream = 1, .n_cells = 6, .pd = pd,
                                   .lambda_vg = lv, .q2 = out, .se = out + 6};
    lines[1] = (struct q2_is_line){.nz = 2, .gamma = 16, .amp = &amp, .stream = 2, .n_cells = 3,
                                   .lambda_vg = lv + 3, .q2 = out + 12, .se = out + 15};
    struct q2_is_options o = opts(6000, threads);
    o.target_se = target_se;
    char err[200];
    assert_int_equal(q2_is_run(lines, 2, &o, err, sizeof err), 0);
    out[18] = (double)lines[0].scenes;
    out[19] = (double)lines[1].points;
}

static void test_is_bit_identical_threads(void **state)
{
    (void)state;
    double a[20], b[20];
    for (int pass = 0; pass < 2; pass++) {
        double tse = pass ? 0.01 : 0;
        run_lines(1, tse, a);
        run_lines(2, tse, b);
        if (memcmp(a, b, sizeof a) != 0)
            for (int i = 0; i < 20; i++)
                if (memcmp(&a[i], &b[i], sizeof a[i]) != 0)
                    fail_msg("target_se %g: output %d differs: %.17g (1 thread) vs %.17g (2 threads)", tse,
                             i, a[i], b[i]);
        /* and it is an estimate: q2 in (0, 1), se > 0 */
        for (int i = 0; i < 9; i++) assert_true(a[i < 6 ? i : i + 6] > 0 && a[i < 6 ? i : i + 6] < 1);
    }
    /* q2 falls with lambda_vg and rises with pd (same samples: exact ordering) */
    assert_true(a[0] > a[1] && a[1] > a[2] && a[3] > a[0]);
}

static void test_is_bad_input(void **state)
{
    (void)state;
    double q2 = -1, se;
    char err[200];
    struct q2_is_options o = opts(1000, 1);
    const double g = 9.21;
    assert_int_equal(q2_is_cell(2, g, 0.9, NAN, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_non_null(strstr(err, "lambda_vg"));
    assert_int_equal(q2_is_cell(2, g, 0.9, 2000, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(2, g, 0.9, 0, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(2, g, NAN, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(2, g, 1.5, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(2, NAN, 0.9, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(4, g, 0.9, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_int_equal(q2_is_cell(2, 0.01, 0.9, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_non_null(strstr(err, "gate too small"));
    o.samples = 0;
    assert_int_equal(q2_is_cell(2, g, 0.9, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_non_null(strstr(err, "samples"));
    o.samples = 1000;
    o.target_se = NAN;
    assert_int_equal(q2_is_cell(2, g, 0.9, 1, NULL, &o, &q2, &se, err, sizeof err), -1);
    assert_true(q2 == -1);
}

/* FNV-1a 64 of a checkpoint file's bytes (tools/par/par.c's checksum) */
static uint64_t fnv1a(const unsigned char *b, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

/* A checkpoint with a valid checksum whose results were forged: the first
 * amplitude model's slot says "refused" with no reason. The build fails
 * with a message that names the model and the damage (it printed an empty
 * one). */
static void test_q2_forged_checkpoint(void **state)
{
    (void)state;
    char path[128], err[1600];
    snprintf(path, sizeof path, "%.60s/trk_test_q2_%ld.ckpt", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp",
             (long)getpid());
    remove(path);
    struct q2_table_spec s;
    memset(&s, 0, sizeof s);
    s.detector = TRK_Q2_PDAFAI;
    s.nz = 2;
    s.gate_gamma = 9.21;
    s.amp_model = TRK_AMP_RAYLEIGH;
    s.snr_db = (struct q2_table_axis){2, 10, 15, NULL};
    s.pfa = (struct q2_table_axis){2, 1e-3, 1e-2, NULL};
    s.lambda_vg = (struct q2_table_axis){2, 0.1, 10, NULL};
    struct q2_table_run r;
    memset(&r, 0, sizeof r);
    r.samples = 200;
    r.seed = 5;
    r.threads = 1;
    struct par p;
    par_init(&p, "test_q2");
    p.quiet = 1;
    assert_int_equal(par_checkpoint(&p, path, 0, "forged", err, sizeof err), 0);
    r.par = &p;
    struct q2_table_result res;
    if (q2_table_build(&s, &r, &res, err, sizeof err)) fail_msg("%s", err);
    q2_table_result_free(&res);
    assert_int_equal(par_finish(&p, 0), 0); /* kept: every batch in the file */
    size_t len;
    unsigned char *b = fileio_read(path, &len);
    assert_non_null(b);
    /* magic, version, key, records (6 u64 and the data): batch 0 is the models' */
    uint64_t klen, n, h[6];
    memcpy(&klen, b + 16, 8);
    size_t at = 24 + (size_t)klen;
    memcpy(&n, b + at, 8);
    at += 8;
    int forged = 0;
    for (uint64_t i = 0; i < n && !forged; i++) {
        memcpy(h, b + at, sizeof h);
        at += sizeof h;
        if (h[0] == 0 && h[3] == 0) {
            const int32_t refused = 1;
            memcpy(b + at, &refused, sizeof refused);
            memset(b + at + 8, 0, 256); /* no reason */
            forged = 1;
        }
        at += (size_t)h[5];
    }
    assert_true(forged);
    const uint64_t sum = fnv1a(b, len - 8);
    memcpy(b + len - 8, &sum, 8);
    assert_int_equal(fileio_write(path, b, len), 0);
    free(b);
    par_init(&p, "test_q2");
    p.quiet = 1;
    assert_int_equal(par_checkpoint(&p, path, 0, "forged", err, sizeof err), 0);
    err[0] = 0;
    assert_int_equal(q2_table_build(&s, &r, &res, err, sizeof err), -1);
    print_message("forged: %s\n", err);
    assert_non_null(strstr(err, "amplitude model 0"));
    assert_non_null(strstr(err, "damaged"));
    assert_int_equal(par_finish(&p, 0), 0);
    remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lookup_nodes_and_polynomials),
        cmocka_unit_test(test_lookup_error_bound),
        cmocka_unit_test(test_lookup_3d_uniform),
        cmocka_unit_test(test_lookup_uniform_equals_explicit),
        cmocka_unit_test(test_lookup_explicit_gain),
        cmocka_unit_test(test_lookup_bad_grids),
        cmocka_unit_test(test_roc_table),
        cmocka_unit_test(test_q2_table),
        cmocka_unit_test(test_q2_table_generated),
        cmocka_unit_test(test_q2_forged_checkpoint),
        cmocka_unit_test(test_fastmath),
        cmocka_unit_test(test_amp_sampler),
        cmocka_unit_test(test_is_limits),
        cmocka_unit_test(test_is_reference),
        cmocka_unit_test(test_is_bit_identical_threads),
        cmocka_unit_test(test_is_bad_input),
    };
    return trk_run_tests("q2", tests, NULL, NULL);
}
