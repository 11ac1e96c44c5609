/* test_tracker_overcap.c - scans beyond the workspace's capacity
 * (trk/tracker.h "Scans beyond capacity"): a scan of 4 x TRK_MAX_DETECTIONS
 * keeps every detection in a live track's gate, its report's counts add up,
 * the raised threshold's P_D and clutter density are the amplitude model's
 * there (and the updates use them when the gates overflow), thinning
 * without amplitudes does not depend on the scan's order and scales lambda
 * and P_D by the kept fraction, and a scan beyond TRK_MAX_SCAN_DETECTIONS is
 * refused with the table untouched. */
#include "trk_test.h"
#include "trk/tracker.h"

static struct trk_tracker tk, tk2; /* static, as in firmware */

#define SEC(k) ((int64_t)(k) * 1000000)
#define K TRK_MAX_DETECTIONS
#define N_OVER (4 * K)
#define N_TGT 4

static struct trk_detection det[N_OVER], det2[N_OVER];
static uint64_t rng_state;
static double urand(void) { return trk_test_urand(&rng_state); }

/* M/N confirmation, single-point initiation (one detection, one track),
 * pd 0.9, lambda 1e-4 per m^2; with amp: a Rayleigh model (P 1, 15 dB,
 * pfa 1e-2). */
static void params(struct trk_tracker_params *p, int amp)
{
    trk_tracker_mn_kn_params(p);
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-4);
    p->process_noise_q = TRK_REAL_C(0.05);
    if (amp) {
        p->sensor[0].use_amplitude = 1;
        TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&p->sensor[0].amplitude, 1, 15, TRK_REAL_C(1e-2)));
    }
}

static void assert_counts_add_up(const struct trk_scan_report *r)
{
    assert_int_equal(r->n_detections, r->n_kept + r->n_thinned + r->n_rejected_nonfinite + r->n_rejected_cov +
                                          r->n_rejected_amplitude + r->n_rejected_region + r->n_below_threshold +
                                          r->n_rejected_density);
    assert_true(r->n_kept <= K);
}

/* Target k's position at scan s: 1 km apart, 1 m/s east. */
static trk_real tgt_x(int k, int s) { return (trk_real)(1000 * (k % 2) + s); }
static trk_real tgt_y(int k) { return (trk_real)(1000 * (k / 2)); }

/* N_TGT tracks from three scans of exact target detections (amplitude
 * just above the threshold thr when thr > 0). */
static void start_targets(struct trk_tracker *t, trk_real thr)
{
    for (int s = 0; s < 3; s++) {
        struct trk_detection d[N_TGT];
        memset(d, 0, sizeof d);
        for (int k = 0; k < N_TGT; k++) {
            d[k].x_m = tgt_x(k, s);
            d[k].y_m = tgt_y(k);
            d[k].has_amplitude = thr > 0;
            d[k].amplitude = TRK_REAL_C(1.01) * thr;
        }
        struct trk_scan scan = {SEC(s), 0, N_TGT, d, NULL, 0, {0, 0, 0}, NULL};
        TRK_ASSERT_OK(trk_tracker_process_scan(t, &scan, NULL));
    }
    assert_int_equal(trk_tracker_live_count(t), N_TGT);
}

/* Scan 3 of the targets: their detections at [0, N_TGT), then clutter far
 * from every track (x in [5, 50] km), stronger than the targets'. */
static void over_scan(trk_real thr)
{
    memset(det, 0, sizeof det);
    for (int i = 0; i < N_OVER; i++) {
        det[i].has_amplitude = thr > 0;
        if (i < N_TGT) {
            det[i].x_m = tgt_x(i, 3);
            det[i].y_m = tgt_y(i);
            det[i].amplitude = TRK_REAL_C(1.01) * thr;
        } else {
            det[i].x_m = (trk_real)(5000 + 45000 * urand());
            det[i].y_m = (trk_real)(45000 * urand());
            det[i].amplitude = thr * (trk_real)(2 + urand());
        }
    }
}

/* A scan of 4 x capacity: each track keeps its detection (its only gated
 * one), with and without amplitudes (the targets' are the weakest). */
static void test_gated_kept(void **state)
{
    (void)state;
    for (int amp = 0; amp <= 1; amp++) {
        struct trk_tracker_params p;
        params(&p, amp);
        TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
        const trk_real thr = amp ? trk_amplitude_threshold(&p.sensor[0].amplitude) : 0;
        rng_state = 11;
        start_targets(&tk, thr);
        over_scan(thr);
        struct trk_scan scan = {SEC(3), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
        assert_int_equal(rep.n_detections, N_OVER);
        assert_int_equal(rep.n_kept, K);
        assert_int_equal(rep.n_thinned, N_OVER - K);
        assert_counts_add_up(&rep);
        assert_int_equal(rep.thin_in_gates, 0);
        assert_int_equal(rep.n_tracks_updated, N_TGT);
        assert_int_equal(rep.n_tracks_hit, N_TGT);
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tk, i);
            if (tr) assert_int_equal(tr->n_gated_last, 1);
        }
    }
}

/* Bad detections of an over-capacity scan are counted as in any scan;
 * kept + thinned + rejected = detections. */
static void test_counts_add_up(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p, 1);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const trk_real thr = trk_amplitude_threshold(&p.sensor[0].amplitude);
    rng_state = 12;
    over_scan(thr);
    /* 40 bad detections, 10 of each kind, every 7th after the targets' (fewer,
     * a multiple of 4, in a build whose 4 x capacity holds fewer) */
    const int n_bad = N_TGT + 7 * 40 <= N_OVER ? 40 : 4 * ((N_OVER - N_TGT) / 28);
    for (int i = 0; i < n_bad; i++) {
        struct trk_detection *d = &det[N_TGT + 7 * i];
        switch (i % 4) {
        case 0: d->x_m = NAN; break;
        case 1: d->has_cov = 1; d->cov_m2[0] = 1; d->cov_m2[1] = 2; d->cov_m2[2] = 1; break;
        case 2: d->amplitude = -1; break;
        default: d->amplitude = TRK_REAL_C(0.5) * thr; break;
        }
    }
    struct trk_scan scan = {SEC(0), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_rejected_nonfinite, n_bad / 4);
    assert_int_equal(rep.n_rejected_cov, n_bad / 4);
    assert_int_equal(rep.n_rejected_amplitude, n_bad / 4);
    assert_int_equal(rep.n_below_threshold, n_bad / 4);
    assert_int_equal(rep.n_kept, K);
    assert_int_equal(rep.n_thinned, N_OVER - n_bad - K);
    assert_counts_add_up(&rep);
    /* within capacity: nothing thinned, the counts still add up */
    scan.time_us = SEC(1);
    scan.n_detections = K;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_thinned, 0);
    assert_true(rep.thin_pd == 0 && rep.thin_clutter_density == 0 && rep.thin_threshold == 0);
    assert_counts_add_up(&rep);
}

static int cmp_desc(const void *a, const void *b)
{
    const trk_real x = *(const trk_real *)a, y = *(const trk_real *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* The K strongest amplitudes of det[0, n) into a (sorted, strongest
 * first). */
static void strongest(size_t n, trk_real *a)
{
    static trk_real all[N_OVER];
    for (size_t i = 0; i < n; i++) all[i] = det[i].amplitude;
    qsort(all, n, sizeof all[0], cmp_desc);
    memcpy(a, all, K * sizeof *a);
}

/* Clutter amplitudes of the model (inverse CDF, Rayleigh), spread far
 * apart, no track: the threshold is raised to the K-th strongest
 * amplitude, and the reported P_D and lambda are the model's there: a
 * Rayleigh model built at pfa' = S0(t') has threshold t' and P_D = thin_pd,
 * and lambda' = lambda pfa' / pfa. */
static void test_raised_threshold_model(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p, 1);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const struct trk_amplitude *m = &p.sensor[0].amplitude;
    rng_state = 13;
    memset(det, 0, sizeof det);
    for (int i = 0; i < N_OVER; i++) {
        det[i].x_m = (trk_real)(100000 * urand());
        det[i].y_m = (trk_real)(100000 * urand());
        det[i].has_amplitude = 1;
        TRK_ASSERT_OK(trk_amplitude_inv_sf(m, TRK_AMP_CLUTTER, (trk_real)-log(1 - urand()), &det[i].amplitude));
    }
    struct trk_scan scan = {SEC(0), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_kept, K);
    assert_int_equal(rep.n_thinned, N_OVER - K);
    assert_int_equal(rep.thin_in_gates, 0);
    static trk_real top[K];
    strongest(N_OVER, top);
    assert_true(rep.thin_threshold == top[K - 1]);
    const trk_real t2 = rep.thin_threshold * rep.thin_threshold;
    const trk_real pfa2 = trk_exp(-t2 / m->clutter_power); /* S0(t') = exp(-t'^2 / P) */
    struct trk_amplitude raised;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&raised, m->clutter_power, m->snr_db, pfa2));
    TRK_ASSERT_NEAR(trk_amplitude_threshold(&raised), rep.thin_threshold, 0, TRK_TOL(1e-13, 1e-5));
    TRK_ASSERT_NEAR(rep.thin_pd, trk_amplitude_pd(&raised), 0, TRK_TOL(1e-13, 1e-5));
    TRK_ASSERT_NEAR(rep.thin_clutter_density, p.sensor[0].clutter_density_per_m2 * pfa2 / m->pfa, 0,
                    TRK_TOL(1e-12, 1e-4));
    assert_true(rep.thin_pd < m->pd);
    /* trk_amplitude_log_sf inverts trk_amplitude_inv_sf */
    for (int src = TRK_AMP_CLUTTER; src <= TRK_AMP_TARGET; src++) {
        trk_real x, a;
        TRK_ASSERT_OK(trk_amplitude_log_sf(m, src, rep.thin_threshold, &x));
        TRK_ASSERT_OK(trk_amplitude_inv_sf(m, src, x, &a));
        TRK_ASSERT_NEAR(a, rep.thin_threshold, 0, TRK_TOL(1e-14, 1e-6));
    }
    trk_real x;
    TRK_ASSERT_STATUS(trk_amplitude_log_sf(m, TRK_AMP_CLUTTER, m->threshold / 2, &x), TRK_E_RANGE);
    TRK_ASSERT_STATUS(trk_amplitude_log_sf(m, TRK_AMP_CLUTTER, NAN, &x), TRK_E_NAN);
    TRK_ASSERT_STATUS(trk_amplitude_log_sf(m, 7, m->threshold, &x), TRK_E_ARG);
}

/* tk with parameters p, one track started by a strong detection at
 * (x0_m, 0) at scan 0 (single-point start): its state and covariance into
 * x and pm, the prior of the next scan's reference update. */
static void start_one_track(const struct trk_tracker_params *p, trk_real x0_m, trk_real x[4], trk_real pm[16])
{
    TRK_ASSERT_OK(trk_tracker_init(&tk, p));
    struct trk_detection d0 = {x0_m, 0, {0, 0, 0}, 2 * p->sensor[0].amplitude.threshold, 0, 1};
    struct trk_scan s0 = {SEC(0), 0, 1, &d0, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s0, NULL));
    const struct trk_track *tr = trk_tracker_track(&tk, 0);
    assert_non_null(tr);
    memcpy(x, tr->x, 4 * sizeof *x);
    memcpy(pm, tr->p, 16 * sizeof *pm);
}

/* More gated detections than the workspace holds: every detection within
 * a metre of one track's prediction. The cut falls in the gates, and the
 * track's update is the PDA with the raised threshold's P_D', lambda' and
 * ln l^a (a Rayleigh model at pfa') over the K strongest detections. */
static void test_gates_overflow(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p, 1);
    const struct trk_amplitude *m = &p.sensor[0].amplitude;
    trk_real x[4], pm[16];
    start_one_track(&p, 0, x, pm);
    const struct trk_track *tr;
    rng_state = 14;
    memset(det, 0, sizeof det);
    for (int i = 0; i < N_OVER; i++) {
        det[i].x_m = (trk_real)(2 * urand() - 1);
        det[i].y_m = (trk_real)(2 * urand() - 1);
        det[i].has_amplitude = 1;
        det[i].amplitude = m->threshold * (trk_real)(1 + 3 * urand());
    }
    struct trk_scan scan = {SEC(1), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_kept, K);
    assert_int_equal(rep.thin_in_gates, 1);
    assert_counts_add_up(&rep);
    static trk_real top[K];
    strongest(N_OVER, top);
    assert_true(rep.thin_threshold == top[K - 1]);
    /* the reference: the public one-track functions at the raised threshold */
    const trk_real pfa2 = trk_exp(-rep.thin_threshold * rep.thin_threshold / m->clutter_power);
    struct trk_amplitude raised;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&raised, m->clutter_power, m->snr_db, pfa2));
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, rep.thin_pd, p.gate_prob, TRK_CLUTTER_PARAMETRIC, rep.thin_clutter_density,
                                      1};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    static trk_real z[2 * K], lr[K], beta[K];
    size_t n = 0;
    for (int i = 0; i < N_OVER; i++)
        if (det[i].amplitude >= rep.thin_threshold) {
            z[2 * n] = det[i].x_m;
            z[2 * n + 1] = det[i].y_m;
            TRK_ASSERT_OK(trk_amplitude_log_lr(&raised, det[i].amplitude, &lr[n]));
            n++;
        }
    assert_int_equal(n, K);
    const trk_real r[4] = {1, 0, 0, 1};
    struct trk_pda_report prep;
    TRK_ASSERT_OK(trk_cv2_predict(1, p.process_noise_q, x, pm));
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, r, x, pm, n, z, lr, beta, NULL, &prep));
    tr = trk_tracker_track(&tk, 0);
    assert_int_equal(tr->n_gated_last, prep.n_gated);
    TRK_ASSERT_NEAR(tr->beta0_last, prep.beta0, TRK_TOL(1e-12, 1e-5), TRK_TOL(1e-9, 1e-3));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(tr->x[i], x[i], TRK_TOL(1e-10, 1e-4), TRK_TOL(1e-9, 1e-3));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(tr->p[i], pm[i], TRK_TOL(1e-10, 1e-4), TRK_TOL(1e-9, 1e-3));
    /* the sensor's own constants are back for the next scan */
    assert_true(tk.pda[0].params.pd == trk_amplitude_pd(m));
    assert_true(tk.pda[0].params.clutter_density == p.sensor[0].clutter_density_per_m2);
}

/* The same with a P_D profile (the target's SNR over range, Rayleigh):
 * at the raised threshold t' every range's P_D is P_D(r)^(t'^2/t^2), the
 * track's at its prediction, and each detection's ln l^a is the one of
 * the profile's P_D' at its own range (trk_amplitude_log_lr_at_pd of the
 * model at pfa'). */
static void gates_overflow_profile(double eta)
{
    struct trk_tracker_params p;
    params(&p, 1);
    struct trk_pd_profile *pr = &p.sensor[0].pd_profile;
    pr->n = 2, pr->range_m[0] = 0, pr->range_m[1] = 2000, pr->pd[0] = TRK_REAL_C(0.95), pr->pd[1] = TRK_REAL_C(0.3);
    const trk_real pd_s = TRK_REAL_C(0.98);
    p.sensor[0].persistent_share = (trk_real)eta;
    p.sensor[0].persistent_pd = pd_s;
    p.sensor[0].clutter_density_per_m2 = 2; /* beta0 near 0.7: P_D counts */
    const struct trk_amplitude *m = &p.sensor[0].amplitude;
    const trk_real x0 = 1000;
    trk_real x[4], pm[16];
    start_one_track(&p, x0, x, pm);
    const struct trk_track *tr;
    rng_state = 15;
    memset(det, 0, sizeof det);
    for (int i = 0; i < N_OVER; i++) {
        det[i].x_m = x0 + (trk_real)(4 * urand() - 2);
        det[i].y_m = (trk_real)(4 * urand() - 2);
        det[i].has_amplitude = 1;
        det[i].amplitude = m->threshold * (trk_real)(1 + TRK_REAL_C(0.2) * urand());
    }
    struct trk_scan scan = {SEC(1), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.thin_in_gates, 1);
    assert_counts_add_up(&rep);
    const trk_real k = rep.thin_threshold * rep.thin_threshold / m->t2; /* t'^2 / t^2 */
    assert_true(k > 1);
    const trk_real pfa2 = trk_exp(-rep.thin_threshold * rep.thin_threshold / m->clutter_power);
    struct trk_amplitude raised;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&raised, m->clutter_power, m->snr_db, pfa2));
    const struct trk_pose origin = {0, 0, 0};
    static trk_real z[2 * K], lr[K], beta[K];
    size_t n = 0;
    for (int i = 0; i < N_OVER; i++)
        if (det[i].amplitude >= rep.thin_threshold) {
            z[2 * n] = det[i].x_m;
            z[2 * n + 1] = det[i].y_m;
            const trk_real pd = trk_sensor_pd_at(&p.sensor[0], &origin, det[i].x_m, det[i].y_m);
            TRK_ASSERT_OK(trk_amplitude_log_lr_at_pd(&raised, trk_pow(pd, k), det[i].amplitude, &lr[n]));
            if (eta > 0) { /* over clutter and persistent returns, their share at the raised threshold */
                trk_real ls;
                TRK_ASSERT_OK(trk_amplitude_log_lr_at_pd(&raised, trk_pow(pd_s, k), det[i].amplitude, &ls));
                const double ps_ratio = pow((double)pd_s, (double)k - 1), pfa_ratio = (double)pfa2 / (double)m->pfa;
                const double eta2 = eta * ps_ratio / ((1 - eta) * pfa_ratio + eta * ps_ratio);
                lr[n] -= (trk_real)log((1 - eta2) + eta2 * exp((double)ls));
            }
            n++;
        }
    assert_int_equal(n, K);
    TRK_ASSERT_OK(trk_cv2_predict(1, p.process_noise_q, x, pm));
    const trk_real pd_track = trk_pow(trk_sensor_pd_at(&p.sensor[0], &origin, x[TRK_CV2_X], x[TRK_CV2_Y]), k);
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, pd_track, p.gate_prob, TRK_CLUTTER_PARAMETRIC, rep.thin_clutter_density, 1};
    TRK_ASSERT_OK(trk_pda_init(&pda, &pp));
    const trk_real r[4] = {1, 0, 0, 1};
    struct trk_pda_report prep;
    TRK_ASSERT_OK(trk_pda_update(&pda, 4, trk_cv2_h, r, x, pm, n, z, lr, beta, NULL, &prep));
    tr = trk_tracker_track(&tk, 0);
    assert_int_equal(tr->n_gated_last, prep.n_gated);
    assert_true(prep.beta0 > TRK_REAL_C(1e-3) && prep.beta0 < TRK_REAL_C(0.999)); /* P_D counts */
    TRK_ASSERT_NEAR(tr->beta0_last, prep.beta0, TRK_TOL(1e-12, 1e-5), TRK_TOL(1e-9, 1e-3));
    for (int i = 0; i < 4; i++) TRK_ASSERT_NEAR(tr->x[i], x[i], TRK_TOL(1e-10, 1e-4), TRK_TOL(1e-9, 1e-3));
    for (int i = 0; i < 16; i++) TRK_ASSERT_NEAR(tr->p[i], pm[i], TRK_TOL(1e-10, 1e-4), TRK_TOL(1e-9, 1e-3));
    /* the profile's P_D holds again for the next scan */
    TRK_ASSERT_NEAR(tk.ws.pd_power, 1, 0, 0);
}

static void test_gates_overflow_profile(void **state)
{
    (void)state;
    gates_overflow_profile(0);
}

/* The same with persistent returns in the amplitudes (struct
 * trk_sensor_params persistent_share): each kept detection's l^a over the
 * clutter-and-scatterer mixture at the raised threshold. */
static void test_gates_overflow_persistent(void **state)
{
    (void)state;
    gates_overflow_profile(0.3);
}

/* The workspace's kept positions, sorted (x then y), into kx, ky. */
static int cmp_xy(const void *a, const void *b)
{
    const trk_real *u = a, *v = b;
    return u[0] < v[0] ? -1 : u[0] > v[0] ? 1 : u[1] < v[1] ? -1 : u[1] > v[1];
}

static size_t kept_positions(const struct trk_tracker *t, trk_real *xy)
{
    for (size_t j = 0; j < t->ws.n_valid; j++) {
        xy[2 * j] = t->ws.x[j];
        xy[2 * j + 1] = t->ws.y[j];
    }
    qsort(xy, t->ws.n_valid, 2 * sizeof *xy, cmp_xy);
    return t->ws.n_valid;
}

/* Without amplitudes: the kept set does not depend on the scan's order
 * (the same detections reversed keep the same positions), and lambda and
 * P_D scale by kept / total of the non-gated detections. */
static void test_no_amplitude_thinning(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p, 0);
    p.init.method = TRK_INIT_TWO_POINT; /* no track from the scan itself: */
    p.init.max_speed_mps = 10;           /* the workspace is read after it */
    p.init.max_gap_scans = 2;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    rng_state = 15;
    over_scan(0);
    for (int i = 0; i < N_OVER; i++) det2[i] = det[N_OVER - 1 - i];
    struct trk_scan s1 = {SEC(0), 0, N_OVER, det, NULL, 0, {0, 0, 0}, NULL}, s2 = {SEC(0), 0, N_OVER, det2, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report r1, r2;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s1, &r1));
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &s2, &r2));
    assert_int_equal(r1.n_kept, K);
    assert_int_equal(r1.n_thinned, N_OVER - K);
    assert_counts_add_up(&r1);
    static trk_real xy1[2 * K], xy2[2 * K];
    assert_int_equal(kept_positions(&tk, xy1), K);
    assert_int_equal(kept_positions(&tk2, xy2), K);
    assert_memory_equal(xy1, xy2, sizeof xy1);
    const trk_real f = (trk_real)K / (trk_real)N_OVER; /* no track: every detection non-gated */
    assert_true(r1.thin_threshold == 0 && r1.thin_in_gates == 0);
    TRK_ASSERT_NEAR(r1.thin_clutter_density, p.sensor[0].clutter_density_per_m2 * f, 0, TRK_TOL(1e-15, 1e-6));
    TRK_ASSERT_NEAR(r1.thin_pd, p.sensor[0].pd * f, 0, TRK_TOL(1e-15, 1e-6));
    assert_true(r1.thin_pd == r2.thin_pd && r1.thin_clutter_density == r2.thin_clutter_density);
    /* again: the same scan keeps the same set */
    TRK_ASSERT_OK(trk_tracker_init(&tk2, &p));
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk2, &s1, &r2));
    assert_int_equal(kept_positions(&tk2, xy2), K);
    assert_memory_equal(xy1, xy2, sizeof xy1);
}

/* TRK_MAX_SCAN_DETECTIONS detections are thinned; one more is refused and
 * leaves the table byte-identical. */
static void test_hard_bound(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p, 0);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    start_targets(&tk, 0);
    const size_t n_max = TRK_MAX_SCAN_DETECTIONS;
    struct trk_detection *big = calloc(n_max + 1, sizeof *big);
    assert_non_null(big);
    rng_state = 16;
    for (size_t i = 0; i <= n_max; i++) {
        big[i].x_m = (trk_real)(5000 + 1e6 * urand());
        big[i].y_m = (trk_real)(1e6 * urand());
    }
    static struct trk_tracker copy;
    memcpy(&copy, &tk, sizeof tk);
    struct trk_scan scan = {SEC(3), 0, n_max + 1, big, NULL, 0, {0, 0, 0}, NULL};
    struct trk_scan_report rep;
    TRK_ASSERT_STATUS(trk_tracker_process_scan(&tk, &scan, &rep), TRK_E_CAPACITY);
    assert_int_equal(rep.n_detections, 0);
    assert_memory_equal(&copy, &tk, offsetof(struct trk_tracker, ws));
    scan.n_detections = n_max;
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &scan, &rep));
    assert_int_equal(rep.n_detections, n_max);
    assert_int_equal(rep.n_kept, K);
    assert_int_equal(rep.n_thinned, n_max - K);
    assert_counts_add_up(&rep);
    free(big);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gated_kept),
        cmocka_unit_test(test_counts_add_up),
        cmocka_unit_test(test_raised_threshold_model),
        cmocka_unit_test(test_gates_overflow),
        cmocka_unit_test(test_gates_overflow_profile),
        cmocka_unit_test(test_gates_overflow_persistent),
        cmocka_unit_test(test_no_amplitude_thinning),
        cmocka_unit_test(test_hard_bound),
    };
    return trk_run_tests("tracker_overcap", tests, NULL, NULL);
}
