/* test_amplitude.c - amplitude models (trk/amplitude.h): Rayleigh closed
 * forms against amplitude.vec values, K tables built by the generator
 * (tools/gen/amp_table.c) against the direct evaluation (kdist) and the
 * vectors, table tail and extrapolation, Rayleigh and geometric-grid tables,
 * every bad input and every kind of bad amplitude table, Kennedy's dB model.
 * Tables are built small here (the generator is fast at 64..128 points). */
#include "trk_test.h"
#include "amp_table.h"
#include "kdist.h"
#include "table_writer.h"
#include "trk/amplitude.h"
#include "trk/table.h"

static void put32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void fix_crc(unsigned char *b, size_t len) { put32(b + len - 4, trk_crc32(0, b, len - 4)); }

static unsigned char *build(int model, double nu, double snr_db, double pfa, int grid, uint32_t size,
                            uint32_t llr_size, int measure, struct amp_table_result *r)
{
    struct amp_table_opts o;
    amp_table_opts_init(&o, model, nu, snr_db, pfa);
    o.grid = grid;
    o.size = size;
    o.llr_size = llr_size;
    o.measure = measure;
    o.measure_points = 1;
    char err[256];
    if (amp_table_build(&o, r, err, sizeof err) != 0) fail_msg("amp_table_build: %s", err);
    return r->bytes;
}

static void load(const unsigned char *b, size_t len, struct trk_table *t, struct trk_amplitude *m)
{
    TRK_ASSERT_OK(trk_table_parse(t, b, len));
    TRK_ASSERT_OK(trk_amplitude_init_table(m, t));
}

/* amplitude.vec rayleigh_snr5_pfa0.1 and _w0/_w1 of amp_inv_sf */
static void test_rayleigh_closed_form(void **state)
{
    (void)state;
    struct trk_amplitude m;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m, 1, 5, TRK_REAL_C(0.1)));
    const double tol = TRK_TOL(1e-14, 1e-6);
    TRK_ASSERT_NEAR(trk_amplitude_threshold(&m), 1.5174271293851462, 0, tol);
    TRK_ASSERT_NEAR(trk_amplitude_pd(&m), 0.57510471297301957, 0, tol);
    assert_int_equal(m.tabulated, 0);
    const double a[4] = {1.5174271293851462, 2.1618996516303497, 5.2001272565005952, 10.724177447173769};
    const double want[4] = {-1.4260624389053684, 0.37546847538401096, 17.369118022657609, 84.201516415888875};
    for (int i = 0; i < 4; i++) {
        trk_real v;
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)a[i] * (1 + TRK_REAL_EPS), &v));
        TRK_ASSERT_NEAR(v, want[i], TRK_TOL(1e-12, 1e-5), TRK_TOL(1e-12, 2e-6));
    }
    const double x[3] = {0, 0.5, 40}, wc[3] = {1.5174271293851462, 1.6740923191371631, 6.504043749314258},
                 wt[3] = {1.5174271293851462, 2.0937344442593999, 12.992062634536873};
    for (int i = 0; i < 3; i++) {
        trk_real ac, at;
        TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, (trk_real)x[i], &ac));
        TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_TARGET, (trk_real)x[i], &at));
        TRK_ASSERT_NEAR(ac, wc[i], 0, tol);
        TRK_ASSERT_NEAR(at, wt[i], 0, tol);
    }
    /* scaling: clutter power 4 doubles amplitudes, leaves ln l^a(2a) = ln l^a(a) */
    struct trk_amplitude m4;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m4, 4, 5, TRK_REAL_C(0.1)));
    TRK_ASSERT_NEAR(trk_amplitude_threshold(&m4), 2 * 1.5174271293851462, 0, tol);
    trk_real v1, v4;
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m, 3, &v1));
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m4, 6, &v4));
    TRK_ASSERT_NEAR(v4, v1, TRK_TOL(1e-13, 1e-5), 0);
}

/* ln l^a with the SNR that gives P_D pd (a P_D profile's target): the
 * model's own at its P_D, the model of that SNR at another, the density
 * ratio (pfa/P_D) p1(a)/p0(a) of Rayleigh laws, and the refusals. */
static void test_log_lr_at_pd(void **state)
{
    (void)state;
    struct trk_amplitude m;
    const double pfa = 1e-3;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m, 2, 12, (trk_real)pfa));
    const double a[4] = {1.0001 * (double)trk_amplitude_threshold(&m), 4, 6, 9};
    for (int i = 0; i < 4; i++) {
        trk_real own, at;
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)a[i], &own));
        TRK_ASSERT_OK(trk_amplitude_log_lr_at_pd(&m, trk_amplitude_pd(&m), (trk_real)a[i], &at));
        TRK_ASSERT_NEAR(at, own, TRK_TOL(1e-12, 1e-4), TRK_TOL(1e-12, 1e-5));
        /* P_D 0.4: 1 + SNR = ln pfa / ln 0.4 */
        const double pd = 0.4, u = log(pfa) / log(pd), P = 2;
        struct trk_amplitude m2;
        TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m2, 2, (trk_real)(10 * log10(u - 1)), (trk_real)pfa));
        TRK_ASSERT_NEAR(trk_amplitude_pd(&m2), pd, 0, TRK_TOL(1e-13, 1e-5));
        TRK_ASSERT_OK(trk_amplitude_log_lr_at_pd(&m, (trk_real)pd, (trk_real)a[i], &at));
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m2, (trk_real)a[i], &own));
        TRK_ASSERT_NEAR(at, own, TRK_TOL(1e-12, 1e-4), TRK_TOL(1e-11, 1e-5));
        const double p1 = 2 * a[i] / (P * u) * exp(-a[i] * a[i] / (P * u)), p0 = 2 * a[i] / P * exp(-a[i] * a[i] / P);
        TRK_ASSERT_NEAR(at, log(pfa / pd * p1 / p0), TRK_TOL(1e-12, 1e-4), TRK_TOL(1e-11, 1e-5));
    }
    trk_real v = 7;
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, (trk_real)pfa, 5, &v), TRK_E_RANGE); /* no SNR > 0 */
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, 1, 5, &v), TRK_E_RANGE);
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, TRK_REAL_C(0.5), 1, &v), TRK_E_RANGE); /* below t */
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, (trk_real)NAN, 5, &v), TRK_E_NAN);
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, TRK_REAL_C(0.5), (trk_real)INFINITY, &v), TRK_E_NAN);
    assert_int_equal(trk_amplitude_log_lr_at_pd(NULL, TRK_REAL_C(0.5), 5, &v), TRK_E_ARG);
    assert_int_equal(trk_amplitude_log_lr_at_pd(&m, TRK_REAL_C(0.5), 5, NULL), TRK_E_ARG);
    TRK_ASSERT_NEAR(v, 7, 0, 0); /* untouched */
    struct amp_table_result r;
    unsigned char *b = build(TRK_AMP_K, 1, 15, 1e-3, 0, 32, 32, 0, &r);
    struct trk_table t;
    struct trk_amplitude k;
    load(b, r.len, &t, &k);
    assert_int_equal(trk_amplitude_log_lr_at_pd(&k, TRK_REAL_C(0.5), 5, &v), TRK_E_UNSUPPORTED);
    free(b);
}

static void test_bad_input(void **state)
{
    (void)state;
    struct trk_amplitude m, keep;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m, 1, 15, TRK_REAL_C(1e-3)));
    keep = m;
    trk_real v = 123, a = 0;
    const trk_real t = trk_amplitude_threshold(&m);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, (trk_real)NAN, &v), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, (trk_real)INFINITY, &v), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, -(trk_real)INFINITY, &v), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, -1, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, 0, &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, t * (1 - 4 * TRK_REAL_EPS), &v), TRK_E_RANGE); /* just below */
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m, t, &v));                                          /* at t: a detection */
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(NULL, t, &v), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_amplitude_log_lr(&m, t, NULL), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, (trk_real)NAN, &a), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, (trk_real)INFINITY, &a), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, -TRK_REAL_C(1e-9), &a), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_inv_sf(&m, 2, 1, &a), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_amplitude_inv_sf(&m, -1, 1, &a), TRK_E_ARG);
    assert_true(isnan(trk_amplitude_threshold(NULL)) && isnan(trk_amplitude_pd(NULL)));
    /* init: every parameter checked, *m untouched on error */
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, (trk_real)NAN, 15, TRK_REAL_C(1e-3)), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 1, (trk_real)INFINITY, TRK_REAL_C(1e-3)), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 1, 15, (trk_real)NAN), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 0, 15, TRK_REAL_C(1e-3)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, -1, 15, TRK_REAL_C(1e-3)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 1, 15, 0), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 1, 15, 1), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(&m, 1, 101, TRK_REAL_C(0.1)), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_init_rayleigh(NULL, 1, 15, TRK_REAL_C(0.1)), TRK_E_ARG);
    assert_memory_equal(&m, &keep, sizeof m);
}

/* Table lookup against direct evaluation at the vectors' amplitudes and x. */
static void check_k_table(double nu, double snr_db, double pfa)
{
    struct amp_table_result r;
    unsigned char *b = build(TRK_AMP_K, nu, snr_db, pfa, 0, 128, 128, 0, &r);
    struct trk_table t;
    struct trk_amplitude m;
    load(b, r.len, &t, &m);
    assert_int_equal(m.tabulated, 1);
    struct kdist k;
    assert_int_equal(kdist_init(&k, nu, snr_db), 0);
    double tk;
    assert_int_equal(kdist_threshold(&k, pfa, &tk), 0);
    const double pd = exp(kdist_log_sf(&k, 1, tk));
    TRK_ASSERT_NEAR(trk_amplitude_threshold(&m), tk, 0, TRK_TOL(1e-15, 1e-7));
    TRK_ASSERT_NEAR(trk_amplitude_pd(&m), pd, 0, TRK_TOL(1e-15, 1e-7));
    /* ln l^a: 128 nodes uniform in ln a reach ~1e-6 (docs/library.md); float tables
     * carry float rounding of values up to ~|ln l^a| ~ 100 */
    for (int i = 0; i <= 60; i++) {
        const double a = tk * pow(10.0, 1.2 * i / 60); /* t .. 16 t: the tail beyond a_max too */
        const double want = kdist_log_lr(&k, pfa, pd, a, NULL);
        trk_real got;
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)a, &got));
        if (a <= r.a_max)
            TRK_ASSERT_NEAR(got, want, TRK_TOL(5e-6, 1e-4), TRK_TOL(0, 1e-6));
        else /* beyond a_max: between the last node's value and the limit */
            assert_true((got - want) * 0 == 0 && fabs(got) <= fabs(kdist_log_lr_inf(&k, pfa, pd)) + fabs(want) + 1);
    }
    for (int src = 0; src < 2; src++)
        for (int i = 0; i <= 80; i++) {
            const double x = fmin(0.5 * i + 0.123 * (i % 3), 40); /* the table's range */
            double want;
            assert_int_equal(kdist_inv_sf(&k, src, tk, x, &want, NULL), 0);
            trk_real got;
            TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, src, (trk_real)x, &got));
            TRK_ASSERT_NEAR(got, want, 0, TRK_TOL(1e-6, 2e-6));
        }
    trk_real a0;
    TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_TARGET, 0, &a0));
    TRK_ASSERT_NEAR(a0, tk, 0, TRK_TOL(1e-14, 1e-7));
    free(b);
}

static void test_k_tables(void **state)
{
    (void)state;
    check_k_table(1, 15, 1e-3);  /* Brekke's setting */
    check_k_table(0.5, 5, 0.1);  /* nu < 1: l^a not monotone */
    check_k_table(20, 20, 1e-5); /* near Rayleigh, large ln l^a */
    check_k_table(8, 15, 1e-8);  /* tiny pfa */
}

/* Measured errors (stored in the table) bound the error anywhere else. */
static void test_measured_error(void **state)
{
    (void)state;
    struct amp_table_result r;
    unsigned char *b = build(TRK_AMP_K, 1, 15, 1e-4, 0, 64, 64, 1, &r);
    assert_int_equal(r.measured, 1);
    struct trk_table t;
    struct trk_amplitude m;
    load(b, r.len, &t, &m);
    trk_real e1, e2;
    TRK_ASSERT_OK(trk_table_param_real(&t, "err_log_lr", &e1));
    TRK_ASSERT_OK(trk_table_param_real(&t, "err_inv_sf", &e2));
    TRK_ASSERT_NEAR(e1, r.err_log_lr, 0, TRK_TOL(1e-15, 1e-6));
    assert_true(r.err_log_lr > 0 && r.err_log_lr < TRK_TOL(1e-5, 1e-3));
    struct kdist k;
    assert_int_equal(kdist_init(&k, 1, 15), 0);
    for (int i = 0; i < 200; i++) { /* random points: within 2x the measured maximum */
        const double a = r.threshold + (r.a_max - r.threshold) * ((i * 0.618034) - floor(i * 0.618034));
        trk_real got;
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)a, &got));
        TRK_ASSERT_NEAR(got, kdist_log_lr(&k, 1e-4, r.pd, a, NULL), 2 * r.err_log_lr + TRK_TOL(1e-12, 1e-5), 0);
    }
    free(b);
}

static void test_tail(void **state)
{
    (void)state;
    struct amp_table_result r;
    unsigned char *b = build(TRK_AMP_K, 1, 15, 1e-2, 0, 32, 64, 0, &r);
    struct trk_table t;
    struct trk_amplitude m;
    load(b, r.len, &t, &m);
    trk_real lim, l0, l1, lprev;
    TRK_ASSERT_OK(trk_table_param_real(&t, "log_lr_limit", &lim));
    /* continuous at a_max, monotone towards the limit, finite for huge a */
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)r.a_max * (1 - TRK_REAL_C(1e-6)), &l0));
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)r.a_max * (1 + TRK_REAL_C(1e-6)), &l1));
    TRK_ASSERT_NEAR(l1, l0, TRK_TOL(1e-4, 1e-3), 0); /* 2e-6 in ln a times the slope */
    lprev = l1;
    for (double a = r.a_max * 1.5; a < 1e30; a *= 10) {
        trk_real l;
        TRK_ASSERT_OK(trk_amplitude_log_lr(&m, (trk_real)a, &l));
        assert_true(l >= lprev - TRK_TOL(1e-12, 1e-5) && l <= lim + TRK_TOL(1e-12, 1e-4));
        lprev = l;
    }
    TRK_ASSERT_NEAR(lprev, lim, TRK_TOL(1e-6, 1e-4), 0);
    /* a(x) beyond x_max: the tangent of a^2, continuous */
    trk_real a40, a41, a80;
    TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, 40, &a40));
    TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, TRK_REAL_C(40.0001), &a41));
    TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, 80, &a80));
    TRK_ASSERT_NEAR(a41, a40, TRK_TOL(1e-4, 1e-3), 0);
    assert_true(a80 > a40 && isfinite(a80));
    free(b);
}

static void test_rayleigh_and_geometric_tables(void **state)
{
    (void)state;
    struct amp_table_result r;
    unsigned char *b = build(TRK_AMP_RAYLEIGH, 0, 15, 1e-3, 0, 32, 32, 0, &r);
    struct trk_table t;
    struct trk_amplitude m, ref;
    load(b, r.len, &t, &m);
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&ref, 1, 15, TRK_REAL_C(1e-3)));
    assert_int_equal(m.tabulated, 0); /* closed form from the table's parameters */
    assert_int_equal(m.model, TRK_AMP_RAYLEIGH);
    trk_real v1, v2;
    TRK_ASSERT_OK(trk_amplitude_log_lr(&m, 4, &v1));
    TRK_ASSERT_OK(trk_amplitude_log_lr(&ref, 4, &v2));
    assert_true(v1 == v2);
    free(b);

    /* Brekke's geometric grid: piecewise linear a(x), the paper's accuracy */
    b = build(TRK_AMP_K, 1, 15, 1e-3, TRK_AMP_GRID_GEOMETRIC, 64, 64, 0, &r);
    load(b, r.len, &t, &m);
    struct kdist k;
    assert_int_equal(kdist_init(&k, 1, 15), 0);
    for (int src = 0; src < 2; src++)
        for (double x = 0; x <= 40; x += 0.37) {
            double want;
            trk_real got;
            assert_int_equal(kdist_inv_sf(&k, src, r.threshold, x, &want, NULL), 0);
            TRK_ASSERT_OK(trk_amplitude_inv_sf(&m, src, (trk_real)x, &got));
            TRK_ASSERT_NEAR(got, want, 0, 2e-2);
        }
    free(b);
}

/* Rebuild a table with one parameter changed. */
static unsigned char *with_param(int model, const char *skip, const char *name, double value, size_t *len)
{
    struct amp_table_result r;
    unsigned char *src = build(model, model == TRK_AMP_K ? 1 : 0, 15, 1e-3, 0, 16, 16, 0, &r);
    struct trk_table t;
    TRK_ASSERT_OK(trk_table_parse(&t, src, r.len));
    struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, TRK_AMP_TABLE_VERSION, sizeof(trk_real));
    for (uint32_t k = 0; k < t.info.n_params; k++) {
        const unsigned char *p = src + TRK_TABLE_HEADER_SIZE + (size_t)k * TRK_TABLE_PARAM_SIZE;
        const char *pn = (const char *)p;
        if (skip && strcmp(pn, skip) == 0) continue;
        if (get32(p + 32) == TRK_TABLE_PARAM_INT) {
            int64_t iv;
            TRK_ASSERT_OK(trk_table_param_int(&t, pn, &iv));
            if (name && strcmp(pn, name) == 0) iv = (int64_t)value;
            assert_int_equal(tablew_param_int(w, pn, iv), 0);
        } else {
            trk_real rv;
            TRK_ASSERT_OK(trk_table_param_real(&t, pn, &rv));
            assert_int_equal(tablew_param_real(w, pn, name && strcmp(pn, name) == 0 ? value : (double)rv), 0);
        }
    }
    for (uint32_t id = 1; id <= 3; id++) {
        struct trk_table_section s;
        TRK_ASSERT_OK(trk_table_section(&t, id, &s));
        struct tablew_axis ax = {s.axis[0].count, s.axis[0].spacing, s.axis[0].variable, (double)s.axis[0].lo,
                                 (double)s.axis[0].hi, 0, NULL};
        double *d = malloc(s.count * sizeof(double));
        for (size_t i = 0; i < s.count; i++) d[i] = (double)s.data[i];
        assert_int_equal(tablew_section(w, id, 1, &ax, s.ncomp, s.interp, d), 0);
        free(d);
    }
    unsigned char *b;
    assert_int_equal(tablew_finish(w, &b, len), 0);
    tablew_free(w);
    free(src);
    return b;
}

static trk_status init_from(const unsigned char *b, size_t len)
{
    struct trk_table t;
    struct trk_amplitude m;
    memset(&m, 0x5a, sizeof m);
    const struct trk_amplitude keep = m;
    trk_status st = trk_table_parse(&t, b, len);
    if (st != TRK_OK) return st;
    st = trk_amplitude_init_table(&m, &t);
    if (st != TRK_OK) assert_memory_equal(&m, &keep, sizeof m); /* untouched */
    return st;
}

static void test_bad_tables(void **state)
{
    (void)state;
    size_t len;
    unsigned char *b = with_param(TRK_AMP_K, NULL, NULL, 0, &len);
    TRK_ASSERT_OK(init_from(b, len)); /* the copy itself is sound */
    const size_t desc0 = TRK_TABLE_HEADER_SIZE + (size_t)get32(b + 32) * TRK_TABLE_PARAM_SIZE;
    unsigned char *c = malloc(len);
    /* kind and kind version */
    memcpy(c, b, len);
    put32(c + 20, TRK_TABLE_KIND_Q2_PDAF);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_KIND);
    memcpy(c, b, len);
    put32(c + 24, TRK_AMP_TABLE_VERSION + 1);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_VERSION);
    /* a(x) values not increasing: swap two nodes of the clutter curve */
    for (uint32_t id = 2; id <= 3; id++) {
        memcpy(c, b, len);
        const size_t d = desc0 + (id - 1) * TRK_TABLE_SECTION_SIZE, off = get32(c + d + 16);
        trk_real *v = (trk_real *)(void *)(c + off);
        const trk_real tmp = v[2 * 5];
        v[2 * 5] = v[2 * 6];
        v[2 * 6] = tmp;
        fix_crc(c, len);
        TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
        memcpy(c, b, len);
        v = (trk_real *)(void *)(c + off);
        v[2 * 7 + 1] = -v[2 * 7 + 1]; /* a negative slope */
        fix_crc(c, len);
        TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
        memcpy(c, b, len);
        v = (trk_real *)(void *)(c + off);
        v[0] *= TRK_REAL_C(1.01); /* does not start at the threshold */
        fix_crc(c, len);
        TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
    }
    /* finite but absurd node values (lookups would overflow) */
    for (uint32_t id = 1; id <= 3; id++) {
        memcpy(c, b, len);
        trk_real *v = (trk_real *)(void *)(c + get32(c + desc0 + (id - 1) * TRK_TABLE_SECTION_SIZE + 16));
        v[2 * 15 + 1] = TRK_REAL_C(1e30); /* a slope */
        fix_crc(c, len);
        TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
    }
    /* ln l^a axis not starting at ln t; wrong section shapes */
    memcpy(c, b, len);
    put32(c + desc0 + 12, TRK_TABLE_INTERP_LINEAR);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    put32(c + desc0 + 32 + 8, TRK_TABLE_VAR_AMP);
    fix_crc(c, len);
    TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
    memcpy(c, b, len);
    put32(c + desc0 + TRK_TABLE_SECTION_SIZE, 9); /* section 2 renamed: missing */
    fix_crc(c, len);
    TRK_ASSERT_STATUS(init_from(c, len), TRK_E_TABLE_CORRUPT);
    free(c);
    free(b);
    /* parameters: missing, out of range, inconsistent */
    static const struct {
        const char *skip, *name;
        double value;
    } cases[] = {{"pfa", NULL, 0},          {"threshold", NULL, 0},      {"log_lr_limit", NULL, 0},
                 {"model", NULL, 0},        {NULL, "model", 3},          {NULL, "pfa", 1},
                 {NULL, "pfa", 0},          {NULL, "pd", 0},             {NULL, "pd", 1.5},
                 {NULL, "threshold", -1},   {NULL, "threshold", 7},      {NULL, "clutter_power", 0},
                 {NULL, "nu", 0},           {NULL, "snr_db", 200},
                 {NULL, "threshold", 1e30}}; /* far beyond any detection threshold (float-representable) */
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        b = with_param(TRK_AMP_K, cases[i].skip, cases[i].name, cases[i].value, &len);
        trk_status st = init_from(b, len);
        if (st != TRK_E_TABLE_CORRUPT)
            fail_msg("case %zu (%s/%s): %s", i, cases[i].skip ? cases[i].skip : "-",
                     cases[i].name ? cases[i].name : "-", trk_status_str(st));
        free(b);
    }
    /* a Rayleigh table whose threshold disagrees with its closed form */
    b = with_param(TRK_AMP_RAYLEIGH, NULL, "threshold", 2.0, &len);
    TRK_ASSERT_STATUS(init_from(b, len), TRK_E_TABLE_CORRUPT);
    free(b);
    b = with_param(TRK_AMP_RAYLEIGH, NULL, NULL, 0, &len);
    TRK_ASSERT_OK(init_from(b, len));
    free(b);
    struct trk_amplitude m;
    TRK_ASSERT_STATUS(trk_amplitude_init_table(&m, NULL), TRK_E_ARG);
    struct trk_table empty = {0};
    TRK_ASSERT_STATUS(trk_amplitude_init_table(&m, &empty), TRK_E_ARG);
}

/* A K table built by hand whose nodes are consistent with its threshold t
 * (ln l^a axis from ln(t/sqrt P), inverse-survival curves u(x) from t/sqrt P,
 * explicit x nodes, all within the node bounds): only the bound t/sqrt(P) <=
 * TRK_AMP_MAX_NORM_THRESHOLD can refuse it (t = 1e160 passed
 * every check and dropped every detection as below threshold). */
static trk_status consistent_k_table(double thr, double power)
{
    struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, TRK_AMP_TABLE_VERSION, sizeof(trk_real));
    assert_non_null(w);
    const double ut = thr / sqrt(power);
    assert_false(tablew_param_int(w, "model", TRK_AMP_K) || tablew_param_real(w, "nu", 1) ||
                 tablew_param_real(w, "snr_db", 15) || tablew_param_real(w, "pfa", 1e-3) ||
                 tablew_param_real(w, "clutter_power", power) || tablew_param_real(w, "threshold", thr) ||
                 tablew_param_real(w, "pd", 0.5) || tablew_param_real(w, "log_lr_limit", 20));
    const double llr[8] = {1, 1, 2, 1, 3, 1, 4, 1}; /* (L, dL/ds) */
    const struct tablew_axis la = {4, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_LN_AMP, log(ut), log(ut) + 3, 0, NULL};
    static const double xs[4] = {0, 1, 2, 3};
    const double u[4] = {ut, ut * 1.5, ut * 2, ut * 2.5};
    const struct tablew_axis xa = {4, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_X, 0, 3, 0, xs};
    assert_false(tablew_section(w, TRK_AMP_SECTION_LOG_LR, 1, &la, 2, TRK_TABLE_INTERP_HERMITE, llr) ||
                 tablew_section(w, TRK_AMP_SECTION_INV_SF_CLUTTER, 1, &xa, 1, TRK_TABLE_INTERP_LINEAR, u) ||
                 tablew_section(w, TRK_AMP_SECTION_INV_SF_TARGET, 1, &xa, 1, TRK_TABLE_INTERP_LINEAR, u));
    unsigned char *b;
    size_t len;
    if (tablew_finish(w, &b, &len) != 0) fail_msg("tablew: %s", tablew_error(w));
    tablew_free(w);
    const trk_status st = init_from(b, len);
    free(b);
    return st;
}

static void test_threshold_bound(void **state)
{
    (void)state;
    TRK_ASSERT_OK(consistent_k_table(3, 1)); /* the hand-made table is sound */
    TRK_ASSERT_OK(consistent_k_table(9e5, 1));
    TRK_ASSERT_OK(consistent_k_table(0.9 * (double)TRK_AMP_MAX_NORM_THRESHOLD * 1e3, 1e6));
    TRK_ASSERT_STATUS(consistent_k_table(1.1 * (double)TRK_AMP_MAX_NORM_THRESHOLD, 1), TRK_E_TABLE_CORRUPT);
    TRK_ASSERT_STATUS(consistent_k_table(2e6 * 1e3, 1e6), TRK_E_TABLE_CORRUPT);
    if (!TRK_REAL_IS_FLOAT) /* 1e160 is no float */
        TRK_ASSERT_STATUS(consistent_k_table(1e160, 1), TRK_E_TABLE_CORRUPT);
}

/* The tools' texture integrals (kdist) against the half-integer closed forms
 * of K clutter, z = 2 a sqrt(nu) (clutter power 1), from K_{n+1/2}:
 *   nu = 1/2: S0 = e^-z,   nu = 3/2: S0 = (1 + z) e^-z,
 *   nu = 5/2: S0 = (z^2 + 3 z + 3)/3 e^-z,   p0 = -dS0/da,
 * in the log domain out to z ~ 3000 (where K_nu and e^-z underflow). */
static void test_kdist_closed_forms(void **state)
{
    (void)state;
    static const double nus[3] = {0.5, 1.5, 2.5};
    for (int k = 0; k < 3; k++) {
        struct kdist kd;
        assert_int_equal(kdist_init(&kd, nus[k], 10), 0);
        for (double a = 0.01; a < 1000; a *= 1.7) {
            const double z = 2 * a * sqrt(nus[k]), dz = 2 * sqrt(nus[k]);
            double ls, lp;
            if (k == 0) {
                ls = -z;
                lp = log(dz) - z;
            } else if (k == 1) {
                ls = log1p(z) - z;
                lp = log(dz * z) - z; /* d/dz (1+z)e^-z = -z e^-z */
            } else {
                ls = log((z * z + 3 * z + 3) / 3) - z;
                lp = log(dz * z * (z + 1) / 3) - z; /* d/dz: -(z^2 + z)/3 e^-z */
            }
            TRK_ASSERT_NEAR(kdist_log_sf(&kd, 0, a), ls, 1e-13, 1e-13);
            TRK_ASSERT_NEAR(kdist_log_pdf(&kd, 0, a), lp, 1e-13, 1e-13);
        }
        /* thresholds down to P_FA 1e-300: nu = 1/2 has t = -ln(pfa)/(2 sqrt(nu)) */
        if (k == 0)
            for (double pfa = 0.5; pfa > 1e-300; pfa *= 1e-7) {
                double t;
                assert_int_equal(kdist_threshold(&kd, pfa, &t), 0);
                TRK_ASSERT_NEAR(t, -log(pfa) / sqrt(2.0), 0, 1e-13);
            }
    }
    /* nu -> inf is Rayleigh: t^2 -> -ln pfa, P_D -> pfa^(1/(1+SNR)) */
    struct kdist kd;
    assert_int_equal(kdist_init(&kd, 1e6, 15), 0);
    double t;
    assert_int_equal(kdist_threshold(&kd, 1e-4, &t), 0);
    TRK_ASSERT_NEAR(t * t, -log(1e-4), 0, 1e-4);
    TRK_ASSERT_NEAR(exp(kdist_log_sf(&kd, 1, t)), pow(1e-4, 1 / (1 + pow(10, 1.5))), 0, 1e-4);
}

/* amplitude.vec kennedy0 and kennedy4 */
/* trk_amplitude_sample_log_lr = trk_amplitude_log_lr(trk_amplitude_inv_sf(x))
 * up to rounding, for Rayleigh (closed form), a K table (uniform grid) and
 * Brekke's geometric grid; in place; bad input. */
static void check_sample_log_lr(const struct trk_amplitude *m)
{
    enum { N = 100 };
    trk_real x[N], y[N];
    for (int i = 0; i < N; i++) x[i] = (trk_real)(i == 0 ? 0 : 0.05 * i * i / 10.0 + 1e-3 * i); /* 0 .. ~50 */
    for (int src = 0; src < 2; src++) {
        TRK_ASSERT_OK(trk_amplitude_sample_log_lr(m, src, N, x, y));
        for (int i = 0; i < N; i++) {
            trk_real a, l;
            TRK_ASSERT_OK(trk_amplitude_inv_sf(m, src, x[i], &a));
            TRK_ASSERT_OK(trk_amplitude_log_lr(m, a, &l));
            TRK_ASSERT_NEAR(y[i], l, TRK_TOL(1e-11, 2e-4), TRK_TOL(1e-12, 1e-5));
        }
        /* in place */
        trk_real z[N];
        memcpy(z, x, sizeof z);
        TRK_ASSERT_OK(trk_amplitude_sample_log_lr(m, src, N, z, z));
        assert_memory_equal(z, y, sizeof z);
    }
}

static void test_sample_log_lr(void **state)
{
    (void)state;
    struct trk_amplitude m;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&m, 2, 15, TRK_REAL_C(1e-3)));
    check_sample_log_lr(&m);
    struct amp_table_result r;
    struct trk_table t;
    unsigned char *b = build(TRK_AMP_K, 1, 15, 1e-2, 0, 64, 64, 0, &r);
    load(b, r.len, &t, &m);
    check_sample_log_lr(&m);
    free(b);
    b = build(TRK_AMP_K, 8, 10, 1e-1, TRK_AMP_GRID_GEOMETRIC, 64, 64, 0, &r);
    load(b, r.len, &t, &m);
    check_sample_log_lr(&m);
    /* bad input: statuses, nothing written for a bad x */
    trk_real x[3] = {1, NAN, 2}, y[3] = {-7, -7, -7};
    TRK_ASSERT_STATUS(trk_amplitude_sample_log_lr(&m, TRK_AMP_CLUTTER, 3, x, y), TRK_E_NAN);
    x[1] = -1;
    TRK_ASSERT_STATUS(trk_amplitude_sample_log_lr(&m, TRK_AMP_CLUTTER, 3, x, y), TRK_E_RANGE);
    assert_true(y[0] == -7 && y[2] == -7);
    TRK_ASSERT_STATUS(trk_amplitude_sample_log_lr(&m, 2, 3, x, y), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_amplitude_sample_log_lr(NULL, TRK_AMP_CLUTTER, 3, x, y), TRK_E_ARG);
    TRK_ASSERT_STATUS(trk_amplitude_sample_log_lr(&m, TRK_AMP_CLUTTER, 3, NULL, y), TRK_E_ARG);
    TRK_ASSERT_OK(trk_amplitude_sample_log_lr(&m, TRK_AMP_CLUTTER, 0, NULL, NULL));
    free(b);
}

static void test_kennedy(void **state)
{
    (void)state;
    const struct trk_amp_db_params p0 = {5, 10, 10, TRK_REAL_C(35.294468060463664)};
    const struct trk_amp_db_params p4 = {5, 10, 8, 1};
    const double a[3] = {5, 12.5, 45};
    const double w0[3] = {-1.4455268909161931, 0.32009547188410448, -10.445358110135246};
    const double w4[3] = {-3.8095006207705717, -7.9345006207705717, -675.80950062077056};
    for (int i = 0; i < 3; i++) {
        trk_real v;
        TRK_ASSERT_OK(trk_amplitude_db_log_lr(&p0, (trk_real)a[i], &v));
        TRK_ASSERT_NEAR(v, w0[i], TRK_TOL(1e-13, 1e-5), TRK_TOL(1e-12, 1e-6));
        TRK_ASSERT_OK(trk_amplitude_db_log_lr(&p4, (trk_real)a[i], &v));
        TRK_ASSERT_NEAR(v, w4[i], TRK_TOL(1e-13, 1e-5), TRK_TOL(1e-12, 1e-6));
    }
    trk_real v;
    struct trk_amp_db_params bad = p0;
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(&p0, TRK_REAL_C(4.9), &v), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(&p0, (trk_real)NAN, &v), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(NULL, 6, &v), TRK_E_ARG);
    bad.theta_db = bad.a_min_db;
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(&bad, 6, &v), TRK_E_RANGE);
    bad = p0;
    bad.s2_db2 = 0;
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(&bad, 6, &v), TRK_E_RANGE);
    bad.s2_db2 = (trk_real)INFINITY;
    TRK_ASSERT_STATUS(trk_amplitude_db_log_lr(&bad, 6, &v), TRK_E_NAN);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rayleigh_closed_form),
        cmocka_unit_test(test_log_lr_at_pd),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_k_tables),
        cmocka_unit_test(test_measured_error),
        cmocka_unit_test(test_tail),
        cmocka_unit_test(test_rayleigh_and_geometric_tables),
        cmocka_unit_test(test_bad_tables),
        cmocka_unit_test(test_threshold_bound),
        cmocka_unit_test(test_kennedy),
        cmocka_unit_test(test_sample_log_lr),
        cmocka_unit_test(test_kdist_closed_forms),
    };
    return trk_run_tests("amplitude", tests, NULL, NULL);
}
