/* test_stationary.c - the hold of tracks that stand still
 * (trk_tracker_params.stationary_d2; docs/tracker.md "Persistent
 * returns"):
 *   - a persistent return (a fixed scatterer detected every scan with
 *     noise) keeps one tentative track, flagged stationary, whose existence
 *     would confirm it; it is never confirmed, its returns start no other
 *     track, and the flag is the closed form v' P_v^-1 v < stationary_d2 of
 *     its published state whenever its existence is past p_confirm;
 *   - once the scatterer moves (6 m/s) a track is confirmed on it within
 *     12 scans (a new one: its still track cannot follow the jump), the
 *     still one never;
 *   - a confirmed target that slows to a stop goes back to held under its
 *     id at its TRK_STILL_LOOKS-th still look, and is confirmed again when
 *     it moves;
 *   - a target moving clearly (8 m/s, sigma 5 m, 4 s) is confirmed at the
 *     same scan with the hold as without it;
 *   - stationary_d2 = 0 confirms the scatterer (the hold off);
 *   - with persistent returns in the amplitudes, each scan's mixture takes
 *     the sensor's share less the returns the held tracks explain (closed
 *     form from the table before the scan; per-track PDA: the sensor's);
 *   - with amplitudes and the persistent-return description, a tentative
 *     track's echoes weighed as its target's against a scatterer's: the sum
 *     over its looks against the closed form (joint association and
 *     per-track PDA, its bounds, an echo whose weight underflows), a still
 *     object echoing as a target never confirmed, and a slow mover held past
 *     stationary_d2 by a scatterer's echoes, the flag its closed form
 *     stationary_d2 - 2 min(S, stationary_d2 / 10) at every look, with the
 *     wait of a track whose echoes are a scatterer's (TRK_SCATTERER_ECHO_LLR);
 *   - every live track updated once a scan, also a confirmed one that goes
 *     back to held (per-track PDA and joint association);
 *   - the parameter check. */
#include "trk_test.h"
#include "trk/tracker.h"

#define SEC(k) ((int64_t)(k) * 4000000)
#define DT_S 4.0

static struct trk_tracker tk;

/* Sigma 5 m, P_D 0.9, clutter 1e-6 per m^2, q 1e-3: the defaults else. */
static void params(struct trk_tracker_params *p)
{
    trk_tracker_default_params(p);
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].meas_cov_m2[TRK_COV2_XX] = p->sensor[0].meas_cov_m2[TRK_COV2_YY] = 25;
    p->sensor[0].meas_cov_m2[TRK_COV2_XY] = 0;
    p->sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-6);
    p->process_noise_q = TRK_REAL_C(1e-3);
}

/* v' P_v^-1 v of track tr. */
static double velocity_d2(const struct trk_track *tr)
{
    const double a = (double)tr->p[TRK_CV2_P(TRK_CV2_VX, TRK_CV2_VX)];
    const double b = (double)tr->p[TRK_CV2_P(TRK_CV2_VX, TRK_CV2_VY)];
    const double c = (double)tr->p[TRK_CV2_P(TRK_CV2_VY, TRK_CV2_VY)];
    const double vx = (double)tr->x[TRK_CV2_VX], vy = (double)tr->x[TRK_CV2_VY];
    return (c * vx * vx - 2 * b * vx * vy + a * vy * vy) / (a * c - b * b);
}

/* The held flag's closed form: v' P_v^-1 v below the bar h - 2 min(S, h/10)
 * (h = stationary_d2, S the track's echo evidence: 0 without amplitudes or
 * a persistent-return description). */
static int held_by_bar(const struct trk_track *tr, double h)
{
    const double s = (double)tr->test.confirm.existence.persist_llr;
    return velocity_d2(tr) < h - 2 * fmin(s, h / 10);
}

/* One scan of the object at (x, y) with noise (every scan). */
static void scan_at(int k, double x, double y, uint64_t *rng, struct trk_scan_report *rep)
{
    struct trk_detection d;
    memset(&d, 0, sizeof d);
    d.x_m = (trk_real)(x + 5 * trk_test_nrand(rng));
    d.y_m = (trk_real)(y + 5 * trk_test_nrand(rng));
    const struct trk_scan s = {SEC(k), 0, 1, &d, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, rep));
}

/* The live tracks: exactly one, returned. */
static const struct trk_track *only_track(void)
{
    const struct trk_track *one = NULL;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        const struct trk_track *tr = trk_tracker_track(&tk, i);
        if (!tr) continue;
        assert_null(one);
        one = tr;
    }
    assert_non_null(one);
    return one;
}

static void test_persistent_return_held_then_handed_over(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    uint64_t rng = 11;
    struct trk_scan_report rep;
    int held = 0;
    uint32_t id = 0;
    for (int k = 0; k < 40; k++) {
        scan_at(k, 1000, 2000, &rng, &rep);
        assert_int_equal(rep.n_confirmed, 0);
        if (k < 1) continue;
        const struct trk_track *tr = only_track();
        if (id == 0) id = tr->id;
        assert_int_equal(tr->id, id); /* one track, never another */
        assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
        if (tr->vis.pv >= p.confirm.u.existence.p_confirm) { /* its test would confirm it */
            assert_int_equal(tr->stationary, velocity_d2(tr) < p.stationary_d2);
            assert_int_equal(tr->stationary, 1);
            assert_int_equal(rep.n_stationary, 1);
            held++;
        }
    }
    assert_true(held >= 30);
    /* it moves away at 6 m/s, a jump its still track cannot follow (24 m a
     * scan against a gate of about 16 m): a new track takes it over and is
     * confirmed, the still one is never confirmed */
    int confirmed_at = -1;
    for (int k = 40; k < 60; k++) {
        const double x = 1000 + 6 * DT_S * (k - 40);
        scan_at(k, x, 2000, &rng, &rep);
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tk, i);
            if (!tr || tr->status != TRK_TRACK_CONFIRMED) continue;
            assert_true(tr->id != id);
            assert_int_equal(tr->stationary, 0);
            assert_true(fabs((double)tr->x[TRK_CV2_X] - x) < 30);
            if (confirmed_at < 0) confirmed_at = k;
        }
    }
    assert_true(confirmed_at > 40 && confirmed_at < 52);
}

/* A target moving at 4 m/s is confirmed; it slows to a stop over 80 s
 * (q 0.05, so that the track follows): once its velocity has been
 * consistent with standing still (the closed form above) for
 * TRK_STILL_LOOKS looks in a row, its track goes back to held (tentative,
 * flagged stationary, counted in n_stationary), under its id, at that look
 * and not before; it speeds up to 2 m/s north: the same track is confirmed
 * again. */
static void confirmed_track_that_stops_is_held(enum trk_assoc_method assoc)
{
    struct trk_tracker_params p;
    params(&p);
    p.association = assoc;
    p.process_noise_q = TRK_REAL_C(0.05);
    /* chi^2_2 at 0.99, below the default's 25: with this q the velocity's
     * sigma stays large, and at 25 the track would be held at 2.2 m/s and
     * not confirmed again at 2 m/s (the default's price, docs/tracker.md) */
    p.stationary_d2 = TRK_REAL_C(9.2103403719761836);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    uint64_t rng = 21;
    struct trk_scan_report rep;
    double x = 0, y = 0;
    uint32_t id = 0;
    int still_in_row = 0, held_at = -1, again_at = -1;
    for (int k = 0; k < 100; k++) {
        const double vx = k < 20 ? 4 : k < 40 ? 4.0 * (40 - k) / 20 : 0, vy = k < 60 ? 0 : k < 70 ? 0.2 * (k - 60) : 2;
        x += vx * DT_S;
        y += vy * DT_S;
        scan_at(k, x, y, &rng, &rep);
        if (k < 2) continue;
        const struct trk_track *tr = only_track();
        /* once a scan, also at the look it goes back to held (tentative after
         * the confirmed tracks' updates: not updated again with the tentative) */
        assert_int_equal(rep.n_tracks_updated, 1);
        if (k == 19) {
            assert_int_equal(tr->status, TRK_TRACK_CONFIRMED);
            id = tr->id;
        }
        if (k < 20) continue;
        assert_int_equal(tr->id, id);
        if (held_at < 0) {
            if (tr->status == TRK_TRACK_CONFIRMED) {
                still_in_row = velocity_d2(tr) < p.stationary_d2 ? still_in_row + 1 : 0;
                assert_true(still_in_row < TRK_STILL_LOOKS);
                assert_int_equal(tr->n_still_in_row, still_in_row);
            } else { /* the look that made it TRK_STILL_LOOKS in a row */
                assert_int_equal(still_in_row + 1, TRK_STILL_LOOKS);
                assert_true(velocity_d2(tr) < p.stationary_d2);
                assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
                assert_int_equal(tr->stationary, 1);
                assert_int_equal(rep.n_stationary, 1);
                held_at = k;
            }
        } else if (k < 60) {
            assert_int_equal(tr->status, TRK_TRACK_TENTATIVE); /* held while it stands */
        } else if (again_at < 0 && tr->status == TRK_TRACK_CONFIRMED) {
            assert_int_equal(tr->stationary, 0);
            again_at = k;
        }
    }
    print_message("%s: held at scan %d, confirmed again at %d\n", assoc == TRK_ASSOC_JOINT ? "joint" : "pda", held_at,
                  again_at);
    assert_true(held_at > 30 && held_at < 50);
    assert_true(again_at > 62 && again_at < 85);
}

static void test_confirmed_track_that_stops_is_held(void **state)
{
    (void)state;
    confirmed_track_that_stops_is_held(TRK_ASSOC_PDA);
#if TRK_WITH_JOINT
    confirmed_track_that_stops_is_held(TRK_ASSOC_JOINT);
#endif
}

/* The scan at which the mover is confirmed (-1: never in 20 scans). */
static int mover_confirmed_at(trk_real stationary_d2)
{
    struct trk_tracker_params p;
    params(&p);
    p.stationary_d2 = stationary_d2;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    uint64_t rng = 5;
    for (int k = 0; k < 20; k++) {
        struct trk_scan_report rep;
        scan_at(k, -500 + 8 * DT_S * k, 300 - 2 * DT_S * k, &rng, &rep);
        if (rep.n_confirmed == 1) return k;
    }
    return -1;
}

static void test_mover_not_delayed(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    trk_tracker_default_params(&p);
    const int with = mover_confirmed_at(p.stationary_d2), without = mover_confirmed_at(0);
    assert_true(without > 0);
    assert_int_equal(with, without);
}

static void test_hold_off_confirms_the_return(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    params(&p);
    p.stationary_d2 = 0;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    uint64_t rng = 11;
    int confirmed = 0;
    for (int k = 0; k < 20; k++) {
        struct trk_scan_report rep;
        scan_at(k, 1000, 2000, &rng, &rep);
        confirmed += (int)rep.n_confirmed;
        assert_int_equal(rep.n_stationary, 0);
    }
    assert_int_equal(confirmed, 1);
}

/* The share of persistent returns a scan's amplitude mixture takes
 * (trk_scan_report persistent_share): with the sensor's eta of the n
 * detections on scatterers, and each tentative track standing still
 * explaining pv P_s of them, n_u = max(eta n - sum pv P_s, P_s) and
 * eta' = n_u / ((1 - eta) n + n_u). A scatterer with a strong return and
 * 9 weak clutter points a scan, 40 scans; joint association, or per-track
 * PDA (there eta stays). */
static int persistent_scans(enum trk_assoc_method assoc)
{
    const double eta = 0.2, p_s = 0.9;
    struct trk_tracker_params p;
    params(&p);
    p.association = assoc;
    p.sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&p.sensor[0].amplitude, 1, 15, TRK_REAL_C(1e-2)));
    p.sensor[0].persistent_share = (trk_real)eta;
    p.sensor[0].persistent_pd = (trk_real)p_s;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const trk_real thr = p.sensor[0].amplitude.threshold;
    uint64_t rng = 5;
    int discounted = 0;
    for (int k = 0; k < 40; k++) {
        double held = 0;
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tk, i);
            if (tr && tr->status == TRK_TRACK_TENTATIVE && held_by_bar(tr, (double)p.stationary_d2))
                held += (double)tr->vis.pv * p_s; /* standing still under the bar its echoes set */
        }
        struct trk_detection d[10];
        memset(d, 0, sizeof d);
        d[0].x_m = (trk_real)(1000 + 5 * trk_test_nrand(&rng));
        d[0].y_m = (trk_real)(2000 + 5 * trk_test_nrand(&rng));
        d[0].amplitude = 3 * thr;
        for (int i = 1; i < 10; i++) {
            d[i].x_m = (trk_real)(20000 * trk_test_urand(&rng) - 10000);
            d[i].y_m = (trk_real)(20000 * trk_test_urand(&rng) - 10000);
            d[i].amplitude = thr * (trk_real)(1 + 0.2 * trk_test_urand(&rng));
        }
        for (int i = 0; i < 10; i++) d[i].has_amplitude = 1;
        const struct trk_scan s = {SEC(k), 0, 10, d, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, &rep));
        const double n_u = fmax(eta * 10 - held, p_s);
        const double want = assoc == TRK_ASSOC_JOINT ? n_u / ((1 - eta) * 10 + n_u) : eta;
        TRK_ASSERT_NEAR((double)rep.persistent_share, want, 0, 1e-5);
        discounted += want < eta - 1e-6;
    }
    return discounted;
}

static void test_held_tracks_explain_persistent_returns(void **state)
{
    (void)state;
    assert_true(persistent_scans(TRK_ASSOC_JOINT) >= 30); /* the scatterer held from its first pings */
    assert_int_equal(persistent_scans(TRK_ASSOC_PDA), 0);
}

/* ---- the evidence of a target against a persistent scatterer */

/* A Rayleigh sensor (clutter power 4, pfa 1e-2) whose targets have SNR 10
 * dB (P_D 0.658) and whose scatterers are detected at P_s 0.95: the
 * tracker's weighing of one echo, ln f_t(a) / f_s(a), and of a miss. */
#define EV_POWER 4.0
#define EV_SNR_DB 10
#define EV_PFA 1e-2
#define EV_PS 0.95

static void evidence_params(struct trk_tracker_params *p, enum trk_assoc_method assoc)
{
    params(p);
    p->association = assoc;
    p->sensor[0].use_amplitude = 1;
    TRK_ASSERT_OK(trk_amplitude_init_rayleigh(&p->sensor[0].amplitude, (trk_real)EV_POWER, EV_SNR_DB, (trk_real)EV_PFA));
    p->sensor[0].persistent_share = TRK_REAL_C(0.05);
    p->sensor[0].persistent_pd = (trk_real)EV_PS;
}

/* 1/u of a source detected at P_D pd: ln pd / ln pfa. */
static double inv_u(double pd) { return log(pd) / log(EV_PFA); }

/* The amplitude whose power is the mean of a source's above the threshold
 * t^2: t^2 + P u. */
static double mean_echo(const struct trk_tracker_params *p, double pd)
{
    return sqrt((double)p->sensor[0].amplitude.t2 + EV_POWER / inv_u(pd));
}

/* ln f_t(a) / f_s(a) of an echo of amplitude a */
static double echo_llr(double pd, double a)
{
    const double it = inv_u(pd), is = inv_u(EV_PS);
    return log(it / is) - a * a / EV_POWER * (it - is);
}

/* The look's ln L_t / L_s with one gated echo of weight 1 - beta0 (a < 0:
 * none gated, beta0 = 1). */
static double look_llr(double pd, double pg, double beta0, double a)
{
    const double r0 = (1 - EV_PS * pg) / (1 - pd * pg);
    if (a < 0) return -log(r0);
    return -log(beta0 * r0 + (1 - beta0) * exp(-echo_llr(pd, a)));
}

/* One scan: one echo of amplitude amp at (x, y) (amp < 0: an empty scan). */
static void echo_at(int k, double x, double y, double amp, struct trk_scan_report *rep)
{
    struct trk_detection d;
    memset(&d, 0, sizeof d);
    d.x_m = (trk_real)x;
    d.y_m = (trk_real)y;
    d.amplitude = (trk_real)amp;
    d.has_amplitude = 1;
    const struct trk_scan s = {SEC(k), 0, amp < 0 ? 0 : 1, &d, NULL, 0, {0, 0, 0}, NULL};
    TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &s, rep));
}


/* The held flag of a tentative track whose existence test confirms it on
 * this look: held by the bar, or moving with echoes a scatterer's (S <
 * -TRK_SCATTERER_ECHO_LLR) on fewer than TRK_STILL_LOOKS looks in a row
 * (*moved: that count, kept by the caller, 0 after any other look). */
static int held_closed_form(const struct trk_track *tr, double h, int *moved)
{
    if (held_by_bar(tr, h)) {
        *moved = 0;
        return 1;
    }
    if (!((double)tr->test.confirm.existence.persist_llr < -TRK_SCATTERER_ECHO_LLR)) return 0;
    return ++*moved < TRK_STILL_LOOKS;
}

/* A still object's held track weighs every look after its start: the
 * running sum of the closed form above (its weight beta0 the track's
 * beta0_last), a miss included, kept within +-stationary_d2 / 2; the held
 * flag is its closed form whenever the existence is past p_confirm. A
 * scatterer's strong echoes drive S to the lower bound; an echo so strong
 * that its weight as the target's underflows to 0 leaves the look without
 * evidence (not a miss's). Joint association and per-track PDA. */
static void evidence_closed_form(enum trk_assoc_method assoc)
{
    struct trk_tracker_params p;
    evidence_params(&p, assoc);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const double pd = (double)p.sensor[0].amplitude.pd, pg = (double)p.gate_prob, h = (double)p.stationary_d2;
    const double weak = mean_echo(&p, pd), strong = mean_echo(&p, EV_PS);
    /* two echoes start the pair; then weak, a miss, weak, then strong ones */
    const double amp[] = {weak, weak, weak, -1, weak, strong, strong, strong, strong, strong, strong, strong, strong,
                          strong, strong, strong, strong};
    const int n = (int)(sizeof amp / sizeof amp[0]);
    double want = 0;
    int bounded = 0, flagged = 0;
    for (int k = 0; k < n; k++) {
        struct trk_scan_report rep;
        echo_at(k, 1000, 2000, amp[k], &rep);
        if (k < 2) continue; /* the pair's own points are not weighed */
        const struct trk_track *tr = only_track();
        assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
        want += look_llr(pd, pg, (double)tr->beta0_last, amp[k]);
        if (want < -h / 2) { /* the bound */
            want = -h / 2;
            bounded++;
        }
        TRK_ASSERT_NEAR((double)tr->test.confirm.existence.persist_llr, want, 1e-9, 1e-4);
        if (k == 4) assert_true(want > 0); /* a target's weak echoes and a miss */
        if (tr->vis.pv >= p.confirm.u.existence.p_confirm) {
            assert_int_equal(tr->stationary, held_by_bar(tr, h));
            flagged += tr->stationary;
        }
    }
    assert_true(bounded >= 2);
    assert_true(flagged >= 8);
    assert_true(echo_llr(pd, weak) > 0 && echo_llr(pd, strong) < 0);
    /* back up from the bound on weak echoes; then one 300 dB above the
     * clutter, whose weight as the target's is 0 (beta0 1): no evidence */
    struct trk_scan_report rep;
    const struct trk_track *tr = NULL;
    for (int k = n; k < n + 3; k++) {
        echo_at(k, 1000, 2000, weak, &rep);
        tr = only_track();
        want += look_llr(pd, pg, (double)tr->beta0_last, weak);
    }
    TRK_ASSERT_NEAR((double)tr->test.confirm.existence.persist_llr, want, 1e-9, 1e-4);
    assert_true(want > -h / 2);
    echo_at(n + 3, 1000, 2000, 1e15, &rep);
    assert_int_equal(rep.n_rejected_amplitude, 0);
    tr = only_track();
    assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
    assert_true(tr->beta0_last == 1);
    TRK_ASSERT_NEAR((double)tr->test.confirm.existence.persist_llr, want, 1e-9, 1e-4);
}

static void test_persistent_evidence_closed_form(void **state)
{
    (void)state;
    evidence_closed_form(TRK_ASSOC_JOINT);
    evidence_closed_form(TRK_ASSOC_PDA);
}

/* A still object echoing as a target does (its weak echoes detected every
 * scan, 40 scans): S climbs to its upper bound, the bar falls by a fifth at
 * most (to 4 stationary_d2 / 5), and it is never confirmed: what stands
 * still is not reported, however it echoes. */
static void test_still_target_echoes_still_held(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    evidence_params(&p, TRK_ASSOC_JOINT);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const double weak = mean_echo(&p, (double)p.sensor[0].amplitude.pd), h = (double)p.stationary_d2;
    uint64_t rng = 3;
    int at_bound = 0;
    for (int k = 0; k < 40; k++) {
        struct trk_scan_report rep;
        echo_at(k, 1000 + 5 * trk_test_nrand(&rng), 2000 + 5 * trk_test_nrand(&rng), weak, &rep);
        assert_int_equal(rep.n_confirmed, 0);
        if (k < 1) continue;
        const struct trk_track *tr = only_track();
        assert_int_equal(tr->status, TRK_TRACK_TENTATIVE);
        const double s = (double)tr->test.confirm.existence.persist_llr;
        assert_true(s <= h / 2);
        at_bound += s == h / 2;
        if (tr->vis.pv >= p.confirm.u.existence.p_confirm) assert_int_equal(tr->stationary, held_by_bar(tr, h));
    }
    assert_true(at_bound >= 10);
}

/* A slow mover (1 m/s, sigma 5 m, 4 s scans), the same positions twice:
 * with a target's weak echoes it is confirmed as soon as its velocity is
 * resolved past its bar (stationary_d2, lowered by a fifth at most); with a
 * scatterer's strong echoes the bar rises (up to 2 stationary_d2), it is
 * held at looks whose motion passes stationary_d2, and once its motion
 * passes its own bar it waits TRK_STILL_LOOKS - 1 looks more (S below
 * -TRK_SCATTERER_ECHO_LLR), then is confirmed (the flag and the count their
 * closed form at every look; at 0.8 m/s, where q keeps v' P_v^-1 v below
 * the bar, never in 120 scans). */
#define SLOW_MPS 1.0

static int slow_mover_confirmed_at(double amp, int *held_past_h, int *waited, int *waited_before, double *d2_confirmed)
{
    struct trk_tracker_params p;
    evidence_params(&p, TRK_ASSOC_JOINT);
    TRK_ASSERT_OK(trk_tracker_init(&tk, &p));
    const double h = (double)p.stationary_d2;
    uint64_t rng = 7;
    int moved = 0;
    *held_past_h = *waited = 0;
    for (int k = 0; k < 120; k++) {
        struct trk_scan_report rep;
        const double x = 1000 + SLOW_MPS * DT_S * k + 5 * trk_test_nrand(&rng), y = 2000 + 5 * trk_test_nrand(&rng);
        echo_at(k, x, y, amp, &rep);
        if (rep.n_confirmed == 1) { /* the looks in a row it waited, and its motion now */
            *waited_before = moved;
            *d2_confirmed = velocity_d2(only_track());
            return k;
        }
        if (k < 1) continue;
        const struct trk_track *tr = only_track();
        if (tr->vis.pv < p.confirm.u.existence.p_confirm) {
            moved = 0;
            continue;
        }
        assert_int_equal(tr->stationary, held_closed_form(tr, h, &moved));
        assert_int_equal(tr->n_still_in_row, moved);
        *held_past_h += tr->stationary && velocity_d2(tr) >= h;
        *waited += tr->stationary && !held_by_bar(tr, h);
    }
    return -1;
}

static void test_scatterer_echoes_raise_the_motion_bar(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    evidence_params(&p, TRK_ASSOC_JOINT);
    int past_t, past_s, waited_t, waited_s, before_t, before_s;
    double d2_t, d2_s;
    const int target =
        slow_mover_confirmed_at(mean_echo(&p, (double)p.sensor[0].amplitude.pd), &past_t, &waited_t, &before_t, &d2_t);
    const int scatterer = slow_mover_confirmed_at(mean_echo(&p, EV_PS), &past_s, &waited_s, &before_s, &d2_s);
    print_message("slow mover confirmed at scan %d with a target's echoes, %d with a scatterer's (held past the "
                  "bar of 25 at %d looks, %d of them past its own bar: moved on fewer than %d looks in a row)\n",
                  target, scatterer, past_s, waited_s, TRK_STILL_LOOKS);
    assert_true(target > 2);
    assert_int_equal(past_t, 0);
    assert_int_equal(waited_t, 0);
    assert_true(scatterer > target + 10);
    assert_true(past_s >= 5);
    assert_int_equal(waited_s, TRK_STILL_LOOKS - 1);
    assert_int_equal(before_s, TRK_STILL_LOOKS - 1); /* those looks in a row, then confirmed */
    assert_int_equal(before_t, 0);
    /* the target's echoes lowered its bar by a fifth: confirmed at a motion
     * below stationary_d2, above 4/5 of it */
    const double h = (double)p.stationary_d2;
    print_message("v' P_v^-1 v at confirmation: %.2f (target's echoes), %.2f (scatterer's)\n", d2_t, d2_s);
    assert_true(d2_t >= 0.8 * h && d2_t < h);
}

static void test_param_check(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    const char *field = NULL;
    params(&p);
    p.stationary_d2 = -1;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_RANGE);
    assert_string_equal(field, "stationary_d2");
    p.stationary_d2 = (trk_real)NAN;
    TRK_ASSERT_STATUS(trk_tracker_check_params(&p, &field), TRK_E_NAN);
    p.stationary_d2 = 0;
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_persistent_return_held_then_handed_over),
        cmocka_unit_test(test_confirmed_track_that_stops_is_held),
        cmocka_unit_test(test_mover_not_delayed),
        cmocka_unit_test(test_hold_off_confirms_the_return),
        cmocka_unit_test(test_held_tracks_explain_persistent_returns),
        cmocka_unit_test(test_persistent_evidence_closed_form),
        cmocka_unit_test(test_still_target_echoes_still_held),
        cmocka_unit_test(test_scatterer_echoes_raise_the_motion_bar),
        cmocka_unit_test(test_param_check),
    };
    return trk_run_tests("stationary", tests, NULL, NULL);
}
