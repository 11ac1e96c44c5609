/* test_mtt_scenario.c - the multi-target scenario families of trk-sim mtt
 * (tools/sim/mtt_scenario.h). The transit family (the default): determinism (same seed, same targets and the
 * same detections bit for bit, in any scan order; common random numbers
 * across clutter counts and with or without amplitudes), the targets present
 * per scan (a target present while inside, born when it enters or at its
 * designated birth, dead when it leaves or at its designated death; slots
 * re-used by new targets; at most eight at a time, typically 6-8), the
 * speeds (drawn in [min, max] and kept, at the default 5-15 m/s and at
 * 5-20 m/s), the geometry (the X, the pair 60 m apart present together for
 * 40 scans, the turn, each structure target present where its feature
 * happens), the scan capacity (clutter never makes a scan exceed
 * TRK_MAX_DETECTIONS, the tracker accepts every scan). The fixed family
 * (the first 8-target scenario): what its first implementation produced
 * (seed 1, values kept from it),
 * 8 targets, all alive but BIRTH before its birth and DEATH after its death,
 * speeds drawn in [5, 15] m/s and kept where the path stays inside, else
 * the largest that keeps it in, the X and the pair 60 m apart, determinism,
 * the scan capacity; what the two families share (the structure's draws,
 * the clutter). The manoeuvres: the straight target's
 * acceleration (truth continuous, exact, the speed up by accel x accel_s,
 * the life cut where it leaves; accel 0 the scenario unchanged, bit for
 * bit; nothing else changes with it) and turns up to a full circle. The
 * sonar family (its geometry, sensor, scans and clutter: test_sonar). And the
 * helpers the experiment uses: Student t intervals
 * (mc_stats.h), the per-target assignment of mtt_eval.h, the defaults
 * before two-point initiation. */
#include "trk_test.h"

#include "mc_stats.h"
#include "mtt_eval.h"
#include "mtt_scenario.h"

#define DEG (3.14159265358979323846 / 180.0)

static struct trk_detection det_a[TRK_MAX_DETECTIONS], det_b[TRK_MAX_DETECTIONS];
static long org_a[TRK_MAX_DETECTIONS], org_b[TRK_MAX_DETECTIONS];

static void init_family(struct mtt_scenario *s, int family, uint64_t seed, long scans, double vmin, double vmax)
{
    struct mtt_scen_params p;
    mtt_scen_defaults(&p);
    p.family = family;
    p.seed = seed;
    p.n_scans = scans;
    p.speed_min_mps = vmin;
    p.speed_max_mps = vmax;
    char err[256];
    if (mtt_scen_init(s, &p, err, sizeof err) != 0) fail_msg("mtt_scen_init: %s", err);
}

static void init_speeds(struct mtt_scenario *s, uint64_t seed, long scans, double vmin, double vmax)
{
    init_family(s, MTT_FAMILY_TRANSIT, seed, scans, vmin, vmax);
}

static void init_seed(struct mtt_scenario *s, uint64_t seed, long scans) { init_speeds(s, seed, scans, 5, 15); }

/* Same seed: the same targets and the same scans, bit for bit, whatever
 * the order the scans are asked in; another seed: other ones. */
static void determinism(int family)
{
    struct mtt_scenario a, b, c;
    init_family(&a, family, 7, 200, 5, 15);
    init_family(&b, family, 7, 200, 5, 15);
    init_family(&c, family, 8, 200, 5, 15);
    assert_int_equal(a.n_targets, b.n_targets);
    assert_memory_equal(a.tg, b.tg, a.n_targets * sizeof a.tg[0]);
    assert_memory_equal(a.slot_first, b.slot_first, sizeof a.slot_first);
    assert_memory_equal(a.by_slot, b.by_slot, (size_t)a.slot_first[MTT_N_SLOTS] * sizeof a.by_slot[0]);
    assert_int_equal(a.slot_first[MTT_N_SLOTS], (long)a.n_targets);
    assert_true(memcmp(a.tg, c.tg, MTT_N_SLOTS * sizeof a.tg[0]) != 0);
    static const long ks[] = {199, 0, 17, 99, 140, 41};
    static const long ncl[] = {0, 50, 256};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++)
        for (size_t j = 0; j < sizeof ncl / sizeof ncl[0]; j++) {
            struct trk_scan sa, sb, sc;
            struct mtt_scan_info ia, ib;
            mtt_scen_scan(&a, ks[i], ncl[j], det_a, TRK_MAX_DETECTIONS, org_a, &sa, &ia);
            mtt_scen_scan(&b, ks[i], ncl[j], det_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib);
            assert_int_equal(sa.n_detections, sb.n_detections);
            assert_true(sa.time_us == sb.time_us && sa.time_us == (int64_t)ks[i] * 4000000);
            assert_memory_equal(det_a, det_b, sa.n_detections * sizeof det_a[0]);
            assert_memory_equal(org_a, org_b, sa.n_detections * sizeof org_a[0]);
            assert_memory_equal(&ia, &ib, sizeof ia);
            mtt_scen_scan(&c, ks[i], ncl[j], det_b, TRK_MAX_DETECTIONS, org_b, &sc, NULL);
            assert_true(sc.n_detections != sa.n_detections ||
                        memcmp(det_a, det_b, sa.n_detections * sizeof det_a[0]) != 0);
        }
    mtt_scen_free(&a);
    mtt_scen_free(&b);
    mtt_scen_free(&c);
}

static void test_determinism(void **state)
{
    (void)state;
    determinism(MTT_FAMILY_TRANSIT);
}

/* 1 when detection d's position is among det[0..n) with origin o. */
static int has_pos(const struct trk_detection *d, const struct trk_detection *det, const long *org, size_t n,
                   long o)
{
    for (size_t i = 0; i < n; i++)
        if (org[i] == o && det[i].x_m == d->x_m && det[i].y_m == d->y_m) return 1;
    return 0;
}

/* Common random numbers: the targets' detections are the same at every
 * clutter count, a count's clutter is the first points of a larger one's,
 * and the positions do not depend on the amplitudes being on. */
static void test_common_random_numbers(void **state)
{
    (void)state;
    struct mtt_scenario s, na;
    init_seed(&s, 3, 200);
    struct mtt_scen_params p = s.p;
    p.amplitude = 0;
    char err[256];
    assert_int_equal(mtt_scen_init(&na, &p, err, sizeof err), 0);
    const long lo = TRK_MAX_DETECTIONS / 5, hi = TRK_MAX_DETECTIONS / 2;
    for (long k = 0; k < 200; k += 13) {
        struct trk_scan s1, s2;
        mtt_scen_scan(&s, k, lo, det_a, TRK_MAX_DETECTIONS, org_a, &s1, NULL);
        mtt_scen_scan(&s, k, hi, det_b, TRK_MAX_DETECTIONS, org_b, &s2, NULL);
        for (size_t i = 0; i < s1.n_detections; i++) {
            assert_true(det_a[i].has_amplitude == 1);
            assert_true(has_pos(&det_a[i], det_b, org_b, s2.n_detections, org_a[i]));
        }
        mtt_scen_scan(&na, k, hi, det_a, TRK_MAX_DETECTIONS, org_a, &s1, NULL);
        assert_int_equal(s1.n_detections, s2.n_detections);
        for (size_t i = 0; i < s1.n_detections; i++) {
            assert_true(det_a[i].has_amplitude == 0);
            assert_true(has_pos(&det_a[i], det_b, org_b, s2.n_detections, org_a[i]));
        }
    }
    mtt_scen_free(&s);
    mtt_scen_free(&na);
}

static int inside(const struct mtt_scenario *s, long i, long k)
{
    double x[4];
    mtt_scen_truth(s, i, (double)k * s->p.scan_period_s, x);
    const double lo = s->p.margin_m, hi = s->p.region_m - s->p.margin_m;
    return x[TRK_CV2_X] >= lo && x[TRK_CV2_X] <= hi && x[TRK_CV2_Y] >= lo && x[TRK_CV2_Y] <= hi;
}

/* The targets present, per the rule of mtt_scenario.h, over 20 seeds at
 * 5-15 m/s and 10 at 5-20 m/s:
 *   - every target present while inside the region less the margin, born
 *     where it enters (outside the scan before) unless at the run's start or
 *     the designated birth, dead where it leaves unless at the run's end or
 *     the designated death; the birth at ~20 %, the death at ~70 % of the run
 *   - per slot its targets in time order, one at a time, 1-10 scans apart,
 *     the first born and the last dead within min_life + gap_max scans of
 *     the run's ends; a slot re-used holds a new target (index); the
 *     transit targets present at least min_life_scans scans
 *   - per scan the targets present = those with birth <= k < death, one
 *     per slot at most (mtt_scen_slot_target, mtt_scen_n_present agree), so
 *     at most 8; typically 6-8 (7+ on average, >= 6 in 90 % of the scans)
 *   - target detections from targets present, near them, at the rate P_D */
static void test_presence(void **state)
{
    (void)state;
    long hits = 0, tries = 0, scans = 0, n6 = 0, present_sum = 0, transits = 0;
    for (int run = 0; run < 30; run++) {
        const uint64_t seed = run < 20 ? (uint64_t)run + 1 : (uint64_t)run + 81;
        const double vmax = run < 20 ? 15 : 20;
        struct mtt_scenario s;
        init_speeds(&s, seed, 200, 5, vmax);
        const long ns = 200;
        const struct mtt_target *tb = &s.tg[MTT_BIRTH], *td = &s.tg[MTT_DEATH];
        assert_true(tb->birth_scan >= 37 && tb->birth_scan <= 43 && tb->death_scan > tb->birth_scan + 10);
        assert_true(td->death_scan >= 137 && td->death_scan <= 143 && td->death_scan > td->birth_scan + 10);
        assert_true(inside(&s, MTT_BIRTH, tb->birth_scan) && inside(&s, MTT_BIRTH, tb->birth_scan - 1));
        assert_true(inside(&s, MTT_DEATH, td->death_scan - 1) && inside(&s, MTT_DEATH, td->death_scan));
        assert_true(s.n_targets > MTT_N_SLOTS); /* slots re-used */
        for (size_t i = 0; i < s.n_targets; i++) {
            const struct mtt_target *g = &s.tg[i];
            assert_true(g->slot >= 0 && g->slot < MTT_N_SLOTS);
            assert_int_equal(g->role, i < MTT_N_SLOTS ? (int)i : MTT_TRANSIT);
            if (i < MTT_N_SLOTS) assert_int_equal(g->slot, (int)i);
            assert_true(g->birth_scan >= 0 && g->birth_scan < g->death_scan && g->death_scan <= ns);
            if (g->role == MTT_TRANSIT) {
                assert_true(g->death_scan - g->birth_scan >= s.p.min_life_scans);
                transits++;
            }
            for (long k = g->birth_scan; k < g->death_scan; k++) assert_true(inside(&s, (long)i, k));
            if (g->birth_scan > 0 && !(i == MTT_BIRTH)) assert_false(inside(&s, (long)i, g->birth_scan - 1));
            if (g->death_scan < ns && !(i == MTT_DEATH)) assert_false(inside(&s, (long)i, g->death_scan));
        }
        for (int j = 0; j < MTT_N_SLOTS; j++) {
            int own = 0;
            for (long q = s.slot_first[j]; q < s.slot_first[j + 1]; q++) {
                const long i = s.by_slot[q];
                assert_int_equal(s.tg[i].slot, j);
                own += i == j;
                if (q > s.slot_first[j]) {
                    const long gap = s.tg[i].birth_scan - s.tg[s.by_slot[q - 1]].death_scan;
                    assert_true(gap >= 1 && gap <= s.p.gap_max_scans);
                }
            }
            assert_int_equal(own, 1);
            /* occupied up to fewer than min_life + gap_max scans from either end */
            const long lim = s.p.min_life_scans + s.p.gap_max_scans;
            assert_true(s.tg[s.by_slot[s.slot_first[j]]].birth_scan < lim);
            assert_true(s.tg[s.by_slot[s.slot_first[j + 1] - 1]].death_scan > ns - lim);
        }
        for (long k = 0; k < ns; k++) {
            int n = 0, per_slot[MTT_N_SLOTS] = {0};
            for (size_t i = 0; i < s.n_targets; i++)
                if (mtt_scen_present(&s, (long)i, k)) {
                    n++;
                    per_slot[s.tg[i].slot]++;
                }
            for (int j = 0; j < MTT_N_SLOTS; j++) {
                assert_true(per_slot[j] <= 1);
                const long i = mtt_scen_slot_target(&s, j, k);
                assert_int_equal(i >= 0, per_slot[j]);
                if (i >= 0) assert_true(mtt_scen_present(&s, i, k) && s.tg[i].slot == j);
            }
            assert_int_equal(n, mtt_scen_n_present(&s, k));
            assert_true(n <= MTT_N_SLOTS);
            assert_int_equal(mtt_scen_present(&s, MTT_BIRTH, k), k >= tb->birth_scan && k < tb->death_scan);
            scans++;
            n6 += n >= 6;
            present_sum += n;
            struct trk_scan sc;
            struct mtt_scan_info info;
            mtt_scen_scan(&s, k, 0, det_a, TRK_MAX_DETECTIONS, org_a, &sc, &info);
            assert_int_equal(info.n_target, sc.n_detections);
            assert_true(info.n_target <= (size_t)n);
            long seen[MTT_N_SLOTS];
            size_t n_seen = 0;
            for (size_t j = 0; j < sc.n_detections; j++) {
                const long o = org_a[j];
                assert_true(o >= 0 && o < (long)s.n_targets && mtt_scen_present(&s, o, k));
                for (size_t q = 0; q < n_seen; q++) assert_true(seen[q] != o);
                seen[n_seen++] = o;
                double x[4];
                mtt_scen_truth(&s, o, (double)k * 4, x);
                assert_true(hypot((double)det_a[j].x_m - x[TRK_CV2_X], (double)det_a[j].y_m - x[TRK_CV2_Y]) < 35);
            }
            hits += (long)sc.n_detections;
            tries += n;
        }
        mtt_scen_free(&s);
    }
    /* typically 6-8 present */
    assert_true((double)present_sum / (double)scans >= 7.0);
    assert_true((double)n6 / (double)scans >= 0.9);
    assert_true(transits >= 30 * 10);
    /* ~44 000 target-scans: se of the rate 0.0019 */
    TRK_ASSERT_NEAR((double)hits / (double)tries, 0.8, 0.01, 0);
}

static double ang_diff(double a, double b) /* a - b in (-pi, pi] */
{
    double d = fmod(a - b, 2 * 3.14159265358979323846);
    if (d > 3.14159265358979323846) d -= 2 * 3.14159265358979323846;
    if (d <= -3.14159265358979323846) d += 2 * 3.14159265358979323846;
    return d;
}

/* The X, the pair, the turn and the speeds, over 20 seeds, two run lengths
 * and two speed ranges (5-15, 5-20 m/s). */
static void test_geometry(void **state)
{
    (void)state;
    double v_hi = 0;
    for (int len = 0; len < 2; len++)
        for (int sp = 0; sp < 2; sp++)
            for (uint64_t seed = 1; seed <= 20; seed++) {
                const long ns = len ? 200 : 40;
                const double vmax = sp ? 20 : 15;
                struct mtt_scenario s;
                init_speeds(&s, seed, ns, 5, vmax);
                const struct mtt_target *a = &s.tg[MTT_CROSS_A], *b = &s.tg[MTT_CROSS_B];
                /* the X: both at the crossing point at the same time, near the centre */
                double xa[4], xb[4];
                assert_true(a->at_s == b->at_s);
                mtt_scen_truth(&s, MTT_CROSS_A, a->at_s, xa);
                mtt_scen_truth(&s, MTT_CROSS_B, b->at_s, xb);
                TRK_ASSERT_NEAR(xa[TRK_CV2_X], s.cross_x_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xa[TRK_CV2_Y], s.cross_y_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xb[TRK_CV2_X], s.cross_x_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xb[TRK_CV2_Y], s.cross_y_m, 1e-9, 0);
                assert_true(fabs(s.cross_x_m - 1500) <= 150 && fabs(s.cross_y_m - 1500) <= 150);
                const double cross =
                    fabs(ang_diff(atan2(xb[TRK_CV2_VY], xb[TRK_CV2_VX]), atan2(xa[TRK_CV2_VY], xa[TRK_CV2_VX])));
                const double acute = cross > 90 * DEG ? 180 * DEG - cross : cross;
                assert_true(acute >= 70 * DEG - 1e-9 && acute <= 90 * DEG + 1e-9);
                const long kc = s.cross_scan;
                assert_true(kc > ns / 2 - ns / 20 - 1 && kc < ns / 2 + ns / 20 + 1);
                mtt_scen_truth(&s, MTT_CROSS_A, (double)kc * 4, xa);
                mtt_scen_truth(&s, MTT_CROSS_B, (double)kc * 4, xb);
                assert_true(hypot(xa[TRK_CV2_X] - xb[TRK_CV2_X], xa[TRK_CV2_Y] - xb[TRK_CV2_Y]) <=
                            (a->speed_mps + b->speed_mps) * 2 + 1e-9);
                /* both present well before and after the crossing (from
                 * >= ~1400 m of path either side: 23 scans at 15 m/s, 17 at 20) */
                const long around = ns < 100 ? 15 : sp ? 16 : 22;
                for (long k = kc - around; k <= kc + around; k++)
                    assert_true(mtt_scen_present(&s, MTT_CROSS_A, k) && mtt_scen_present(&s, MTT_CROSS_B, k));
                /* the pair: 60 m apart side by side, one velocity, at every
                 * scan; present together for min(40, n) scans or more */
                long both = 0;
                for (long k = 0; k < ns; k++) {
                    double pa[4], pb[4];
                    mtt_scen_truth(&s, MTT_PAR_A, (double)k * 4, pa);
                    mtt_scen_truth(&s, MTT_PAR_B, (double)k * 4, pb);
                    const double dx = pa[TRK_CV2_X] - pb[TRK_CV2_X], dy = pa[TRK_CV2_Y] - pb[TRK_CV2_Y];
                    TRK_ASSERT_NEAR(hypot(dx, dy), 60, 1e-9, 0);
                    TRK_ASSERT_NEAR(pa[TRK_CV2_VX], pb[TRK_CV2_VX], 1e-12, 0);
                    TRK_ASSERT_NEAR(pa[TRK_CV2_VY], pb[TRK_CV2_VY], 1e-12, 0);
                    TRK_ASSERT_NEAR(dx * pa[TRK_CV2_VX] + dy * pa[TRK_CV2_VY], 0, 1e-9, 0);
                    both += mtt_scen_present(&s, MTT_PAR_A, k) && mtt_scen_present(&s, MTT_PAR_B, k);
                }
                assert_int_equal(both, s.par_scans);
                assert_true(both >= (ns < 40 ? ns : 40));
                /* the turn: 90 deg at 2.4-3.6 deg/s, within the run, speed
                 * kept; present through it and 10 scans either side */
                const struct mtt_target *t = &s.tg[MTT_TURN];
                const double tau = fabs(t->turn_rad) / t->turn_rate_rps;
                TRK_ASSERT_NEAR(fabs(t->turn_rad), 90 * DEG, 1e-12, 0);
                assert_true(t->turn_rate_rps >= 2.4 * DEG - 1e-12 && t->turn_rate_rps <= 3.6 * DEG + 1e-12);
                assert_true(s.turn_first_scan >= 1 && s.turn_first_scan <= s.turn_last_scan &&
                            s.turn_last_scan < ns);
                const long pad = ns < 100 ? 0 : 10;
                for (long k = s.turn_first_scan - pad; k <= s.turn_last_scan + pad; k++)
                    assert_true(mtt_scen_present(&s, MTT_TURN, k));
                double x0[4], x1[4], xm[4];
                mtt_scen_truth(&s, MTT_TURN, t->at_s - 4, x0);
                mtt_scen_truth(&s, MTT_TURN, t->at_s + tau + 4, x1);
                mtt_scen_truth(&s, MTT_TURN, t->at_s + 0.5 * tau, xm);
                TRK_ASSERT_NEAR(
                    ang_diff(atan2(x1[TRK_CV2_VY], x1[TRK_CV2_VX]), atan2(x0[TRK_CV2_VY], x0[TRK_CV2_VX])),
                    t->turn_rad, 1e-9, 0);
                TRK_ASSERT_NEAR(
                    ang_diff(atan2(xm[TRK_CV2_VY], xm[TRK_CV2_VX]), atan2(x0[TRK_CV2_VY], x0[TRK_CV2_VX])),
                    0.5 * t->turn_rad, 1e-9, 0);
                TRK_ASSERT_NEAR(hypot(xm[TRK_CV2_VX], xm[TRK_CV2_VY]), t->speed_mps, 1e-9, 0);
                /* continuity through the turn (no jump at its start or end) */
                double e0[4], e1[4];
                mtt_scen_truth(&s, MTT_TURN, t->at_s + tau - 1e-6, e0);
                mtt_scen_truth(&s, MTT_TURN, t->at_s + tau + 1e-6, e1);
                assert_true(hypot(e0[TRK_CV2_X] - e1[TRK_CV2_X], e0[TRK_CV2_Y] - e1[TRK_CV2_Y]) < 1e-3);
                /* speeds: drawn in [5, vmax] m/s and kept, for every target */
                for (size_t i = 0; i < s.n_targets; i++) {
                    const struct mtt_target *g = &s.tg[i];
                    assert_true(g->speed_drawn_mps >= 5 && g->speed_drawn_mps <= vmax);
                    assert_true(g->speed_mps == g->speed_drawn_mps);
                    mtt_scen_truth(&s, (long)i, 4.0 * (double)g->birth_scan, xm);
                    TRK_ASSERT_NEAR(hypot(xm[TRK_CV2_VX], xm[TRK_CV2_VY]), g->speed_mps, 1e-9, 0);
                    if (g->speed_mps > v_hi) v_hi = g->speed_mps;
                }
                mtt_scen_free(&s);
            }
    assert_true(v_hi > 19.5); /* fast targets occur */
    /* speeds out of order refused; one speed for all accepted and kept */
    struct mtt_scen_params p;
    mtt_scen_defaults(&p);
    p.speed_min_mps = 16;
    struct mtt_scenario s;
    char err[256];
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
    p.speed_min_mps = p.speed_max_mps = 15;
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), 0);
    for (size_t i = 0; i < s.n_targets; i++) assert_true(s.tg[i].speed_mps == 15);
    mtt_scen_free(&s);
}

/* Clutter never makes a scan exceed the capacity: the targets' detections
 * first, then as much clutter as fits (the rest counted); the tracker
 * accepts every scan. */
static void capacity(int family)
{
    struct mtt_scenario s;
    init_family(&s, family, 11, 200, 5, 15);
    static struct trk_tracker tk;
    struct trk_tracker_params tp;
    trk_tracker_default_params(&tp);
    tp.sensor[0].pd = (trk_real)0.8;
    tp.sensor[0].meas_cov_m2[0] = tp.sensor[0].meas_cov_m2[2] = 25;
    tp.sensor[0].meas_cov_m2[1] = 0;
    tp.sensor[0].clutter_density_per_m2 = (trk_real)(TRK_MAX_DETECTIONS / 9e6);
    tp.process_noise_q = (trk_real)1e-3;
    TRK_ASSERT_OK(trk_tracker_init(&tk, &tp));
    static const long counts[] = {0, 7, TRK_MAX_DETECTIONS - 8, TRK_MAX_DETECTIONS, TRK_MAX_DETECTIONS + 44, 5000};
    long capped_scans = 0;
    for (long k = 0; k < 200; k++) {
        struct trk_scan none, sc;
        struct mtt_scan_info i0, info;
        mtt_scen_scan(&s, k, 0, det_b, TRK_MAX_DETECTIONS, org_b, &none, &i0);
        for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
            mtt_scen_scan(&s, k, counts[c], det_a, TRK_MAX_DETECTIONS, org_a, &sc, &info);
            assert_true(sc.n_detections <= TRK_MAX_DETECTIONS);
            assert_int_equal(info.n_target + info.n_clutter, sc.n_detections);
            assert_int_equal(info.n_clutter + info.n_clutter_capped, (size_t)counts[c]);
            assert_int_equal(info.n_target, i0.n_target); /* targets never dropped */
            if (info.n_clutter_capped) {
                assert_int_equal(sc.n_detections, TRK_MAX_DETECTIONS);
                capped_scans++;
            }
            for (size_t j = 0; j < sc.n_detections; j++)
                assert_true(det_a[j].x_m >= 0 && det_a[j].x_m <= 3000 && det_a[j].y_m >= 0 && det_a[j].y_m <= 3000);
        }
        /* the tracker takes the fullest scan (every 10th scan: time) */
        if (k % 10 == 0) {
            mtt_scen_scan(&s, k, 5000, det_a, TRK_MAX_DETECTIONS, NULL, &sc, NULL);
            struct trk_scan_report rep;
            TRK_ASSERT_OK(trk_tracker_process_scan(&tk, &sc, &rep));
            assert_int_equal(rep.n_detections, sc.n_detections);
        }
    }
    assert_true(capped_scans >= 2 * 200); /* the two counts above the capacity, every scan */
    /* a smaller capacity */
    struct mtt_scen_params p = s.p;
    p.max_det = 10;
    struct mtt_scenario small;
    char err[256];
    assert_int_equal(mtt_scen_init(&small, &p, err, sizeof err), 0);
    for (long k = 0; k < 200; k += 7) {
        struct trk_scan sc;
        struct mtt_scan_info info;
        mtt_scen_scan(&small, k, 100, det_a, TRK_MAX_DETECTIONS, NULL, &sc, &info);
        assert_true(sc.n_detections <= 10 && sc.n_detections == info.n_target + info.n_clutter);
    }
    mtt_scen_free(&small);
    p.max_det = (size_t)TRK_MAX_SCAN_DETECTIONS + 1;
    assert_int_equal(mtt_scen_init(&small, &p, err, sizeof err), -1); /* nothing to free */
    mtt_scen_free(&s);
}

static void test_capacity(void **state)
{
    (void)state;
    capacity(MTT_FAMILY_TRANSIT);
}

/* ---------------------------------------------------------------- the fixed family */

/* The fixed family is the first 8-target scenario: seed 1 at the defaults
 * (200 scans) gives the targets its first implementation gave (printed
 * with %.17g) and the
 * same scans (the count, the targets detected in shuffled order, the sums
 * of the positions and amplitudes at 37 clutter). Bit for bit on the
 * machine that took them (x86-64, glibc); the tolerances leave room for
 * another libm. */
static void test_fixed_first_scenario(void **state)
{
    (void)state;
    static const struct {
        long birth, death;
        double speed, drawn, ax, ay, at, heading, turn, rate;
    } want[MTT_N_SLOTS] = {
        {0, 200, 3.962969591802076, 12.641987834629838, 1617.0777518927132, 1525.7177845140409, 360.38519788251267,
         0.68863520737594397, 0, 0},
        {0, 200, 3.749378819894432, 13.138423250430716, 1617.0777518927132, 1525.7177845140409, 360.38519788251267,
         2.0822470663830908, 0, 0},
        {0, 200, 3.8137470397798587, 10.445518197965617, 1811.3219533693755, 1173.7763638589963, 398,
         0.76285409799193393, 0, 0},
        {0, 200, 3.8137470397798587, 10.445518197965617, 1852.7811967317225, 1130.4043551457526, 398,
         0.76285409799193393, 0, 0},
        {39, 200, 4.0586563087250322, 6.1135479245842346, 1244.8175620824793, 1682.792496573913, 476,
         4.4914775782063856, 0, 0},
        {0, 138, 6.0366014557731651, 11.579266922080802, 2005.4490909277479, 1564.2913429663497, 274,
         2.148392055109754, 0, 0},
        {0, 200, 4.2654496809504812, 11.924471679900506, 957.38122272955059, 1282.336074482243, 360.71597419874007,
         2.6944036325946406, -1.5707963267948966, 0.054436753742191923},
        {0, 200, 3.0724902107050251, 11.324829736642595, 1105.3840362882579, 956.01348665694479, 398,
         5.4487721055222025, 0, 0},
    };
    static const struct {
        long k;
        size_t n;
        long targets[8];
        size_t n_targets;
        double sx, sy, sa;
    } scans[] = {
        {0, 42, {6, 1, 5, 2, 0}, 5, 63391.784252330173, 59962.304413524595, 109.93093990631661},
        {57, 43, {3, 7, 2, 1, 6, 0}, 6, 59538.959195981675, 54910.486605861377, 111.51455562627604},
        {150, 42, {2, 0, 3, 7, 4}, 5, 63771.137817185714, 61220.121728936276, 103.99649483551201},
        {199, 41, {0, 2, 1, 4}, 4, 66320.037673180355, 51995.56948966856, 104.37578213044495},
    };
    struct mtt_scenario s;
    init_family(&s, MTT_FAMILY_FIXED, 1, 200, 5, 15);
    assert_int_equal(s.n_targets, MTT_N_SLOTS);
    assert_int_equal(s.cross_scan, 90);
    assert_true(s.turn_first_scan == 91 && s.turn_last_scan == 97);
    for (int i = 0; i < MTT_N_SLOTS; i++) {
        const struct mtt_target *g = &s.tg[i];
        assert_int_equal(g->birth_scan, want[i].birth);
        assert_int_equal(g->death_scan, want[i].death);
        TRK_ASSERT_NEAR(g->speed_mps, want[i].speed, 1e-9, 0);
        TRK_ASSERT_NEAR(g->speed_drawn_mps, want[i].drawn, 1e-12, 0);
        TRK_ASSERT_NEAR(g->ax_m, want[i].ax, 1e-9, 0);
        TRK_ASSERT_NEAR(g->ay_m, want[i].ay, 1e-9, 0);
        TRK_ASSERT_NEAR(g->at_s, want[i].at, 1e-9, 0);
        TRK_ASSERT_NEAR(g->heading_rad, want[i].heading, 1e-12, 0);
        TRK_ASSERT_NEAR(g->turn_rad, want[i].turn, 1e-12, 0);
        TRK_ASSERT_NEAR(g->turn_rate_rps, want[i].rate, 1e-12, 0);
    }
    /* the pinned scans hold up to 45 detections: a smaller build caps them */
    for (size_t q = 0; TRK_MAX_DETECTIONS >= 64 && q < sizeof scans / sizeof scans[0]; q++) {
        struct trk_scan sc;
        mtt_scen_scan(&s, scans[q].k, 37, det_a, TRK_MAX_DETECTIONS, org_a, &sc, NULL);
        assert_int_equal(sc.n_detections, scans[q].n);
        double sx = 0, sy = 0, sa = 0;
        size_t nt = 0;
        for (size_t j = 0; j < sc.n_detections; j++) {
            sx += (double)det_a[j].x_m;
            sy += (double)det_a[j].y_m;
            sa += (double)det_a[j].amplitude;
            if (org_a[j] >= 0) {
                assert_true(nt < scans[q].n_targets);
                assert_int_equal(org_a[j], scans[q].targets[nt]);
                nt++;
            }
        }
        assert_int_equal(nt, scans[q].n_targets);
        /* the detections are trk_real: float builds round each one */
        TRK_ASSERT_NEAR(sx, scans[q].sx, TRK_TOL(1e-6, 0), TRK_TOL(0, 1e-6));
        TRK_ASSERT_NEAR(sy, scans[q].sy, TRK_TOL(1e-6, 0), TRK_TOL(0, 1e-6));
        TRK_ASSERT_NEAR(sa, scans[q].sa, TRK_TOL(1e-9, 0), TRK_TOL(0, 1e-6));
    }
    mtt_scen_free(&s);
}

/* The fixed family's targets over 20 seeds: the eight structure targets
 * alone (slot j holds target j), every one present the whole run but BIRTH
 * before its birth (~20 %) and DEATH from its death (~70 %) on: 7, 8, 7
 * present; inside while present; detections from the targets present, near
 * them, at the rate P_D. */
static void test_fixed_presence(void **state)
{
    (void)state;
    long hits = 0, tries = 0;
    for (uint64_t seed = 1; seed <= 20; seed++) {
        struct mtt_scenario s;
        init_family(&s, MTT_FAMILY_FIXED, seed, 200, 5, 15);
        const long ns = 200, b = s.tg[MTT_BIRTH].birth_scan, d = s.tg[MTT_DEATH].death_scan;
        assert_int_equal(s.n_targets, MTT_N_SLOTS);
        assert_true(b >= 37 && b <= 43);
        assert_true(d >= 137 && d <= 143);
        assert_int_equal(s.par_scans, ns);
        for (int j = 0; j <= MTT_N_SLOTS; j++) assert_int_equal(s.slot_first[j], j);
        for (int i = 0; i < MTT_N_SLOTS; i++) {
            assert_int_equal(s.by_slot[i], i);
            assert_int_equal(s.tg[i].role, i);
            assert_int_equal(s.tg[i].slot, i);
            assert_int_equal(s.tg[i].birth_scan, i == MTT_BIRTH ? b : 0);
            assert_int_equal(s.tg[i].death_scan, i == MTT_DEATH ? d : ns);
        }
        for (long k = 0; k < ns; k++) {
            int n = 0;
            for (int i = 0; i < MTT_N_SLOTS; i++) {
                const int pr = mtt_scen_present(&s, i, k);
                n += pr;
                assert_int_equal(mtt_scen_slot_target(&s, i, k), pr ? i : -1);
                if (pr) assert_true(inside(&s, i, k));
            }
            assert_int_equal(n, k < b || k >= d ? 7 : 8);
            assert_int_equal(mtt_scen_n_present(&s, k), n);
            assert_int_equal(mtt_scen_present(&s, MTT_BIRTH, k), k >= b);
            assert_int_equal(mtt_scen_present(&s, MTT_DEATH, k), k < d);
            struct trk_scan sc;
            struct mtt_scan_info info;
            mtt_scen_scan(&s, k, 0, det_a, TRK_MAX_DETECTIONS, org_a, &sc, &info);
            assert_int_equal(info.n_target, sc.n_detections);
            int seen[MTT_N_SLOTS] = {0};
            for (size_t j = 0; j < sc.n_detections; j++) {
                const long o = org_a[j];
                assert_true(o >= 0 && o < MTT_N_SLOTS && mtt_scen_present(&s, o, k) && !seen[o]);
                seen[o] = 1;
                double x[4];
                mtt_scen_truth(&s, o, (double)k * 4, x);
                assert_true(hypot((double)det_a[j].x_m - x[TRK_CV2_X], (double)det_a[j].y_m - x[TRK_CV2_Y]) < 35);
            }
            hits += (long)sc.n_detections;
            tries += n;
        }
        mtt_scen_free(&s);
    }
    /* 31 000 target-scans: se of the rate 0.0023 */
    TRK_ASSERT_NEAR((double)hits / (double)tries, 0.8, 0.012, 0);
}

/* 1 when target i is inside at every scan of its life at speed v. */
static int life_inside(const struct mtt_scenario *s, long i, double v)
{
    struct mtt_scenario t = *s; /* shallow: the targets are copied below */
    struct mtt_target g = s->tg[i];
    g.speed_mps = v;
    t.tg = &g;
    for (long k = g.birth_scan; k < g.death_scan; k++)
        if (!inside(&t, 0, k)) return 0;
    return 1;
}

/* The fixed family's geometry over 20 seeds, two run lengths and two speed
 * ranges: the X (both at the crossing point together, 70-110 deg), the pair
 * 60 m apart side by side with one velocity at every scan, the turn, and the
 * speeds: drawn in [5, vmax] m/s, kept where the path stays inside over the
 * life (every one in runs of 40 scans), else reduced to the largest that
 * keeps it in (a little faster leaves; every one in runs of 200 scans). */
static void test_fixed_geometry(void **state)
{
    (void)state;
    for (int len = 0; len < 2; len++)
        for (int sp = 0; sp < 2; sp++)
            for (uint64_t seed = 1; seed <= 20; seed++) {
                const long ns = len ? 200 : 40;
                const double vmax = sp ? 20 : 15;
                struct mtt_scenario s;
                init_family(&s, MTT_FAMILY_FIXED, seed, ns, 5, vmax);
                const struct mtt_target *a = &s.tg[MTT_CROSS_A], *b = &s.tg[MTT_CROSS_B];
                double xa[4], xb[4];
                assert_true(a->at_s == b->at_s);
                mtt_scen_truth(&s, MTT_CROSS_A, a->at_s, xa);
                mtt_scen_truth(&s, MTT_CROSS_B, b->at_s, xb);
                TRK_ASSERT_NEAR(xa[TRK_CV2_X], s.cross_x_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xa[TRK_CV2_Y], s.cross_y_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xb[TRK_CV2_X], s.cross_x_m, 1e-9, 0);
                TRK_ASSERT_NEAR(xb[TRK_CV2_Y], s.cross_y_m, 1e-9, 0);
                assert_true(fabs(s.cross_x_m - 1500) <= 150 && fabs(s.cross_y_m - 1500) <= 150);
                const double cross =
                    fabs(ang_diff(atan2(xb[TRK_CV2_VY], xb[TRK_CV2_VX]), atan2(xa[TRK_CV2_VY], xa[TRK_CV2_VX])));
                const double acute = cross > 90 * DEG ? 180 * DEG - cross : cross;
                assert_true(acute >= 70 * DEG - 1e-9 && acute <= 90 * DEG + 1e-9);
                const long kc = s.cross_scan;
                assert_true(kc > ns / 2 - ns / 20 - 1 && kc < ns / 2 + ns / 20 + 1);
                assert_true(mtt_scen_present(&s, MTT_CROSS_A, kc) && mtt_scen_present(&s, MTT_CROSS_B, kc));
                mtt_scen_truth(&s, MTT_CROSS_A, (double)kc * 4, xa);
                mtt_scen_truth(&s, MTT_CROSS_B, (double)kc * 4, xb);
                assert_true(hypot(xa[TRK_CV2_X] - xb[TRK_CV2_X], xa[TRK_CV2_Y] - xb[TRK_CV2_Y]) <=
                            (a->speed_mps + b->speed_mps) * 2 + 1e-9);
                /* the pair: 60 m apart side by side, one velocity, present
                 * together the whole run; its line 300-500 m from the centre */
                for (long k = 0; k < ns; k++) {
                    double pa[4], pb[4];
                    mtt_scen_truth(&s, MTT_PAR_A, (double)k * 4, pa);
                    mtt_scen_truth(&s, MTT_PAR_B, (double)k * 4, pb);
                    const double dx = pa[TRK_CV2_X] - pb[TRK_CV2_X], dy = pa[TRK_CV2_Y] - pb[TRK_CV2_Y];
                    TRK_ASSERT_NEAR(hypot(dx, dy), 60, 1e-9, 0);
                    TRK_ASSERT_NEAR(pa[TRK_CV2_VX], pb[TRK_CV2_VX], 1e-12, 0);
                    TRK_ASSERT_NEAR(pa[TRK_CV2_VY], pb[TRK_CV2_VY], 1e-12, 0);
                    TRK_ASSERT_NEAR(dx * pa[TRK_CV2_VX] + dy * pa[TRK_CV2_VY], 0, 1e-9, 0);
                    assert_true(mtt_scen_present(&s, MTT_PAR_A, k) && mtt_scen_present(&s, MTT_PAR_B, k));
                    if (k == 0) {
                        /* distance of the pair's centre line from the region's centre */
                        const double mx = 0.5 * (pa[TRK_CV2_X] + pb[TRK_CV2_X]) - 1500;
                        const double my = 0.5 * (pa[TRK_CV2_Y] + pb[TRK_CV2_Y]) - 1500;
                        const double off = fabs(mx * dx + my * dy) / 60;
                        assert_true(off >= 300 - 1e-6 && off <= 500 + 1e-6);
                    }
                }
                /* the turn: 90 deg at 2.4-3.6 deg/s within the run, started
                 * 500-700 m from the centre (where drawn) */
                const struct mtt_target *t = &s.tg[MTT_TURN];
                TRK_ASSERT_NEAR(fabs(t->turn_rad), 90 * DEG, 1e-12, 0);
                assert_true(t->turn_rate_rps >= 2.4 * DEG - 1e-12 && t->turn_rate_rps <= 3.6 * DEG + 1e-12);
                assert_true(s.turn_first_scan >= 1 && s.turn_first_scan <= s.turn_last_scan &&
                            s.turn_last_scan < ns);
                const double rq = hypot(t->ax_m - 1500, t->ay_m - 1500);
                assert_true(rq >= 500 - 1e-9 && rq <= 700 + 1e-9);
                /* speeds: drawn in [5, vmax], kept or fitted */
                for (long i = 0; i < MTT_N_SLOTS; i++) {
                    const struct mtt_target *g = &s.tg[i];
                    assert_true(g->speed_drawn_mps >= 5 && g->speed_drawn_mps <= vmax);
                    assert_true(g->speed_mps > 0.5 && g->speed_mps <= g->speed_drawn_mps);
                    assert_true(life_inside(&s, i, g->speed_mps));
                    if (g->speed_mps < g->speed_drawn_mps) /* the largest that stays in */
                        assert_false(life_inside(&s, i, g->speed_mps * (1 + 1e-6)) &&
                                     (i != MTT_PAR_A || life_inside(&s, MTT_PAR_B, g->speed_mps * (1 + 1e-6))) &&
                                     (i != MTT_PAR_B || life_inside(&s, MTT_PAR_A, g->speed_mps * (1 + 1e-6))));
                    if (ns == 40 && !sp) { /* short runs at 5-15 m/s: every draw kept */
                        assert_true(g->speed_mps == g->speed_drawn_mps);
                        assert_true(g->speed_mps >= 5 && g->speed_mps <= 15);
                    }
                    if (ns == 200) assert_true(g->speed_mps < g->speed_drawn_mps); /* 796 s: all fitted */
                    mtt_scen_truth(&s, i, 100, xa);
                    TRK_ASSERT_NEAR(hypot(xa[TRK_CV2_VX], xa[TRK_CV2_VY]), g->speed_mps, 1e-9, 0);
                }
                TRK_ASSERT_NEAR(s.tg[MTT_PAR_A].speed_mps, s.tg[MTT_PAR_B].speed_mps, 0, 0);
                mtt_scen_free(&s);
            }
}

static void test_fixed_determinism(void **state)
{
    (void)state;
    determinism(MTT_FAMILY_FIXED);
}

static void test_fixed_capacity(void **state)
{
    (void)state;
    capacity(MTT_FAMILY_FIXED);
}

/* One code path: the two families of a seed draw the structure alike (the
 * crossing, the headings, the turn, the designated birth and death, the
 * speed draws) and have the same clutter in every scan; they differ in the
 * targets (the fixed family has no transit ones, its speeds are fitted).
 * The family is checked. */
static void test_families_share(void **state)
{
    (void)state;
    for (uint64_t seed = 1; seed <= 10; seed++) {
        struct mtt_scenario tr, fx;
        init_family(&tr, MTT_FAMILY_TRANSIT, seed, 200, 5, 15);
        init_family(&fx, MTT_FAMILY_FIXED, seed, 200, 5, 15);
        assert_true(tr.cross_x_m == fx.cross_x_m && tr.cross_y_m == fx.cross_y_m && tr.cross_scan == fx.cross_scan);
        assert_true(tr.turn_first_scan == fx.turn_first_scan && tr.turn_last_scan == fx.turn_last_scan);
        assert_true(tr.tg[MTT_BIRTH].birth_scan == fx.tg[MTT_BIRTH].birth_scan);
        assert_true(tr.tg[MTT_DEATH].death_scan == fx.tg[MTT_DEATH].death_scan);
        assert_true(tr.n_targets > fx.n_targets && fx.n_targets == MTT_N_SLOTS);
        for (int i = 0; i < MTT_N_SLOTS; i++) {
            assert_true(tr.tg[i].speed_drawn_mps == fx.tg[i].speed_drawn_mps);
            if (i != MTT_PAR_A && i != MTT_PAR_B) assert_true(tr.tg[i].heading_rad == fx.tg[i].heading_rad);
            assert_true(tr.tg[i].turn_rad == fx.tg[i].turn_rad && tr.tg[i].turn_rate_rps == fx.tg[i].turn_rate_rps);
        }
        const long n_clutter = TRK_MAX_DETECTIONS - 8 < 30 ? TRK_MAX_DETECTIONS - 8 : 30; /* never capped */
        for (long k = 0; k < 200; k += 17) {
            struct trk_scan a, b;
            mtt_scen_scan(&tr, k, n_clutter, det_a, TRK_MAX_DETECTIONS, org_a, &a, NULL);
            mtt_scen_scan(&fx, k, n_clutter, det_b, TRK_MAX_DETECTIONS, org_b, &b, NULL);
            size_t nc = 0;
            for (size_t j = 0; j < a.n_detections; j++)
                if (org_a[j] < 0) {
                    nc++;
                    assert_true(has_pos(&det_a[j], det_b, org_b, b.n_detections, -1));
                }
            assert_int_equal(nc, (size_t)n_clutter);
        }
        mtt_scen_free(&tr);
        mtt_scen_free(&fx);
    }
    assert_true(strcmp(mtt_family_name(MTT_FAMILY_TRANSIT), "transit") == 0);
    assert_true(strcmp(mtt_family_name(MTT_FAMILY_FIXED), "fixed") == 0);
    assert_int_equal(mtt_family_parse("fixed"), MTT_FAMILY_FIXED);
    assert_int_equal(mtt_family_parse("transit"), MTT_FAMILY_TRANSIT);
    assert_int_equal(mtt_family_parse("fix"), -1);
    struct mtt_scen_params p;
    mtt_scen_defaults(&p);
    assert_int_equal(p.family, MTT_FAMILY_TRANSIT);
    p.family = MTT_N_FAMILIES;
    struct mtt_scenario s;
    char err[256];
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
}

/* The straight target's acceleration (mtt_scenario.h STRAIGHT), both
 * families, 10 seeds: accel 0 (any duration) gives the default scenario bit
 * for bit (targets, slots, scans); 0.1 m/s^2 for 60 s changes STRAIGHT
 * alone (and the later transit targets of its slot): the same path up to
 * the acceleration's start at its mid-life, continuous position and
 * velocity, the velocity the position's derivative, the speed up by
 * 6 m/s, present while inside and gone where the faster path leaves. */
static void test_accel(void **state)
{
    (void)state;
    static const long ks[] = {0, 63, 99, 100, 131, 199};
    for (int fam = MTT_FAMILY_TRANSIT; fam <= MTT_FAMILY_FIXED; fam++) /* the sonar family has no acceleration */
        for (uint64_t seed = 1; seed <= 10; seed++) {
            struct mtt_scenario base, z, a;
            struct mtt_scen_params p;
            char err[256];
            init_family(&base, fam, seed, 200, 5, 15);
            p = base.p;
            p.accel_mps2 = 0;
            p.accel_s = 123;
            assert_int_equal(mtt_scen_init(&z, &p, err, sizeof err), 0);
            assert_int_equal(z.n_targets, base.n_targets);
            assert_memory_equal(z.tg, base.tg, base.n_targets * sizeof base.tg[0]);
            assert_memory_equal(z.slot_first, base.slot_first, sizeof base.slot_first);
            assert_memory_equal(z.by_slot, base.by_slot, base.n_targets * sizeof base.by_slot[0]);
            assert_true(z.accel_first_scan > z.accel_last_scan);
            for (size_t q = 0; q < sizeof ks / sizeof ks[0]; q++) {
                struct trk_scan s1, s2;
                mtt_scen_scan(&base, ks[q], 40, det_a, TRK_MAX_DETECTIONS, org_a, &s1, NULL);
                mtt_scen_scan(&z, ks[q], 40, det_b, TRK_MAX_DETECTIONS, org_b, &s2, NULL);
                assert_int_equal(s1.n_detections, s2.n_detections);
                assert_memory_equal(det_a, det_b, s1.n_detections * sizeof det_a[0]);
            }
            p.accel_mps2 = 0.1;
            p.accel_s = 60;
            assert_int_equal(mtt_scen_init(&a, &p, err, sizeof err), 0);
            /* the other slots' targets as before */
            for (int j = 0; j < MTT_N_SLOTS; j++) {
                if (j == MTT_STRAIGHT) continue;
                assert_true(a.slot_first[j + 1] - a.slot_first[j] == base.slot_first[j + 1] - base.slot_first[j]);
                for (long q = a.slot_first[j]; q < a.slot_first[j + 1]; q++) {
                    const long i = a.by_slot[q];
                    assert_int_equal(i, base.by_slot[base.slot_first[j] + (q - a.slot_first[j])]);
                    assert_memory_equal(&a.tg[i], &base.tg[i], sizeof a.tg[i]);
                }
            }
            const struct mtt_target *g = &a.tg[MTT_STRAIGHT], *g0 = &base.tg[MTT_STRAIGHT];
            const double T = 4, v = g->speed_mps, t0 = g->accel_t0_s, D = g->accel_dur_s;
            assert_true(g->birth_scan == g0->birth_scan && g->speed_mps == g0->speed_mps &&
                        g->heading_rad == g0->heading_rad && g->ax_m == g0->ax_m && g->at_s == g0->at_s);
            assert_true(g->accel_mps2 == 0.1 && D == 60);
            TRK_ASSERT_NEAR(t0, 0.5 * (double)(g0->birth_scan + g0->death_scan - 1) * T, 1e-12, 0);
            assert_true(g->death_scan <= g0->death_scan && g->death_scan > (long)(t0 / T));
            assert_int_equal(a.accel_first_scan, (long)ceil(t0 / T - 1e-9));
            const long last = (long)floor((t0 + D) / T + 1e-9);
            assert_int_equal(a.accel_last_scan, last < 199 ? last : 199);
            /* the path up to t0 unchanged */
            for (double t = (double)g->birth_scan * T; t <= t0; t += 3.7) {
                double x[4], x0[4];
                mtt_scen_truth(&a, MTT_STRAIGHT, t, x);
                mtt_scen_truth(&base, MTT_STRAIGHT, t, x0);
                assert_memory_equal(x, x0, sizeof x);
            }
            /* continuous at the start and the end, the velocity the
             * derivative (central differences of a quadratic: exact but
             * for rounding), the speed v, v + a (t - t0), v + a D */
            const double tt[] = {t0, t0 + D, t0 + 0.3 * D, t0 + 2 * D, t0 - 10};
            for (size_t q = 0; q < sizeof tt / sizeof tt[0]; q++) {
                const double h = 1e-3;
                double xm[4], xp[4], x[4];
                mtt_scen_truth(&a, MTT_STRAIGHT, tt[q] - h, xm);
                mtt_scen_truth(&a, MTT_STRAIGHT, tt[q] + h, xp);
                mtt_scen_truth(&a, MTT_STRAIGHT, tt[q], x);
                const double u = tt[q] - t0, want = v + 0.1 * (u < 0 ? 0 : u > D ? D : u);
                assert_true(hypot(xp[TRK_CV2_X] - xm[TRK_CV2_X], xp[TRK_CV2_Y] - xm[TRK_CV2_Y]) <= 2 * h * (v + 6.1));
                TRK_ASSERT_NEAR(hypot(x[TRK_CV2_VX], x[TRK_CV2_VY]), want, 1e-9, 0);
                TRK_ASSERT_NEAR(hypot(xp[TRK_CV2_VX] - xm[TRK_CV2_VX], xp[TRK_CV2_VY] - xm[TRK_CV2_VY]), 0,
                                2 * h * 0.1 + 1e-9, 0);
                if (q >= 2) { /* away from the kinks */
                    TRK_ASSERT_NEAR((xp[TRK_CV2_X] - xm[TRK_CV2_X]) / (2 * h), x[TRK_CV2_VX], 1e-5, 0);
                    TRK_ASSERT_NEAR((xp[TRK_CV2_Y] - xm[TRK_CV2_Y]) / (2 * h), x[TRK_CV2_VY], 1e-5, 0);
                }
            }
            {
                /* the distance over the acceleration: v D + a D^2 / 2; the heading kept */
                double x1[4], x2[4];
                mtt_scen_truth(&a, MTT_STRAIGHT, t0, x1);
                mtt_scen_truth(&a, MTT_STRAIGHT, t0 + D, x2);
                TRK_ASSERT_NEAR(hypot(x2[TRK_CV2_X] - x1[TRK_CV2_X], x2[TRK_CV2_Y] - x1[TRK_CV2_Y]),
                                v * D + 0.05 * D * D, 1e-8, 0);
                TRK_ASSERT_NEAR(atan2(x2[TRK_CV2_VY], x2[TRK_CV2_VX]), atan2(x1[TRK_CV2_VY], x1[TRK_CV2_VX]), 1e-12,
                                0);
                TRK_ASSERT_NEAR(hypot(x2[TRK_CV2_VX], x2[TRK_CV2_VY]) - hypot(x1[TRK_CV2_VX], x1[TRK_CV2_VY]),
                                0.1 * 60, 1e-9, 0);
            }
            /* present while inside, gone where it left */
            for (long k = g->birth_scan; k < g->death_scan; k++) assert_true(inside(&a, MTT_STRAIGHT, k));
            if (g->death_scan < 200) assert_false(inside(&a, MTT_STRAIGHT, g->death_scan));
            mtt_scen_free(&base);
            mtt_scen_free(&z);
            mtt_scen_free(&a);
        }
    /* refused: a deceleration, a duration of 0 */
    struct mtt_scen_params p;
    struct mtt_scenario s;
    char err[256];
    mtt_scen_defaults(&p);
    p.accel_mps2 = -0.1;
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
    mtt_scen_defaults(&p);
    p.accel_mps2 = 0.1;
    p.accel_s = 0;
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
}

/* Turns of 120-360 deg (30 scans at 1-3 deg/s): the turning target present
 * over the whole turn, at its speed, its heading turned by turn_deg, the
 * turn's scans those of its duration. */
static void test_long_turns(void **state)
{
    (void)state;
    for (int r = 1; r <= 3; r++)
        for (uint64_t seed = 1; seed <= 10; seed++) {
            struct mtt_scen_params p;
            struct mtt_scenario s;
            char err[256];
            mtt_scen_defaults(&p);
            p.seed = seed;
            p.turn_rate_dps = r;
            p.turn_deg = 120 * r;
            assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), 0);
            const struct mtt_target *g = &s.tg[MTT_TURN];
            const double tau = fabs(g->turn_rad) / g->turn_rate_rps;
            TRK_ASSERT_NEAR(fabs(g->turn_rad), 120 * r * DEG, 1e-12, 0);
            assert_true(g->turn_rate_rps >= 0.8 * r * DEG - 1e-12 && g->turn_rate_rps <= 1.2 * r * DEG + 1e-12);
            const long n = s.turn_last_scan - s.turn_first_scan + 1;
            assert_true(n >= 25 && n <= 38);
            TRK_ASSERT_NEAR((double)n, tau / 4, 1.01, 0);
            for (long k = s.turn_first_scan - 1; k <= s.turn_last_scan + 1; k++)
                assert_true(mtt_scen_present(&s, MTT_TURN, k));
            double x0[4], x1[4];
            mtt_scen_truth(&s, MTT_TURN, g->at_s, x0);
            mtt_scen_truth(&s, MTT_TURN, g->at_s + tau, x1);
            const double turned = ang_diff(atan2(x1[TRK_CV2_VY], x1[TRK_CV2_VX]), atan2(x0[TRK_CV2_VY], x0[TRK_CV2_VX]));
            TRK_ASSERT_NEAR(turned, ang_diff(g->turn_rad, 0), 1e-9, 0);
            TRK_ASSERT_NEAR(hypot(x1[TRK_CV2_VX], x1[TRK_CV2_VY]), g->speed_mps, 1e-9, 0);
            mtt_scen_free(&s);
        }
    struct mtt_scen_params p;
    struct mtt_scenario s;
    char err[256];
    mtt_scen_defaults(&p);
    p.turn_deg = 361;
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
}


/* The sonar family (mtt_scenario.h "The sonar family"), 8 seeds: eight
 * targets, each present only while inside the sector less its margins and
 * for at least 25 scans; speeds in [3, 10] m/s; the platform's pose; the
 * pair on one bearing 100 m apart in range; the crossing shallow; the far
 * target near 7 km; the turn inside its life; the sensor (polar, the
 * profile falling with range, the coverage); the patches 3 % of the area.
 * Scans: determinism, the Cartesian view = the library's conversion of the
 * polar one, mtt_scen_scan = mtt_scen_scan_polar's det[], clutter inside
 * the sector and its counts, the persistent returns (origin -2) switchable
 * without changing the rest, and over the run the targets' detection rate
 * = the library's P_D at their positions (within 4 sigma), the clutter
 * denser near the sonar and in the patches. */
static void test_sonar(void **state)
{
    (void)state;
    static struct trk_polar_detection pol_a[TRK_MAX_DETECTIONS], pol_b[TRK_MAX_DETECTIONS];
    for (uint64_t seed = 1; seed <= 8; seed++) {
        struct mtt_scenario s, s2, np;
        struct mtt_scen_params p;
        char err[256];
        mtt_scen_sonar_defaults(&p);
        p.seed = seed;
        assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), 0);
        assert_int_equal(mtt_scen_init(&s2, &p, err, sizeof err), 0);
        p.persistent = 0;
        assert_int_equal(mtt_scen_init(&np, &p, err, sizeof err), 0);
        assert_memory_equal(s.tg, s2.tg, s.n_targets * sizeof s.tg[0]);
        assert_memory_equal(s.tg, np.tg, s.n_targets * sizeof s.tg[0]);
        assert_int_equal(s.n_targets, 8);
        const double T = 8, hw = 60 * DEG;
        /* the sensor */
        const struct trk_sensor_params *sp = &s.sonar;
        assert_int_equal(sp->kind, TRK_SENSOR_POLAR);
        assert_int_equal(sp->pd_profile.n, MTT_SONAR_PD_POINTS);
        assert_true(sp->pd_profile.pd[0] > 0.85 && sp->pd_profile.pd[0] < 0.95);
        assert_true(sp->pd_profile.pd[MTT_SONAR_PD_POINTS - 1] < 0.5);
        for (int k = 1; k < MTT_SONAR_PD_POINTS; k++) assert_true(sp->pd_profile.pd[k] < sp->pd_profile.pd[k - 1]);
        assert_true(fabs(sp->coverage.max_range_m - 8000) < 1e-3 && fabs(sp->coverage.min_range_m - 500) < 1e-3);
        assert_true(s.sonar_pd_mean > 0.45 && s.sonar_pd_mean < 0.65);
        assert_true(fabs(s.area_m2 - hw * (8000.0 * 8000 - 500.0 * 500)) < 1);
        double pa = 0;
        for (int j = 0; j < MTT_SONAR_PATCHES; j++) pa += 180 * DEG * s.patch[j].r_m * s.patch[j].r_m;
        assert_true(fabs(pa / s.area_m2 - 0.03) < 1e-9);
        /* the targets: present while inside, long enough, speeds */
        for (size_t i = 0; i < s.n_targets; i++) {
            const struct mtt_target *g = &s.tg[i];
            assert_true(g->death_scan - g->birth_scan >= 25);
            assert_true(g->speed_mps >= 3 - 1e-9 && g->speed_mps <= 10 + 1e-9);
            for (long k = g->birth_scan; k < g->death_scan; k++) {
                double x[4];
                struct trk_pose ps;
                mtt_scen_truth(&s, (long)i, (double)k * T, x);
                mtt_scen_pose(&s, k, &ps);
                assert_true(ps.x_m == 0 && ps.heading_rad == 0 && fabs(ps.y_m - 3.0 * T * (double)k) < 1e-3);
                const double dx = x[TRK_CV2_X] - ps.x_m, dy = x[TRK_CV2_Y] - ps.y_m, r = hypot(dx, dy);
                assert_true(r >= 550 - 1e-6 && r <= 7950 + 1e-6 && fabs(atan2(dx, dy)) <= hw - 1 * DEG + 1e-9);
                assert_true(trk_sensor_pd_at(sp, &ps, (trk_real)x[TRK_CV2_X], (trk_real)x[TRK_CV2_Y]) > 0);
            }
        }
        {
            /* the pair at mid-run: one bearing, 100 m apart in range */
            const double tm = 0.5 * 149 * T;
            double a[4], b[4];
            mtt_scen_truth(&s, MTT_PAR_A, tm, a);
            mtt_scen_truth(&s, MTT_PAR_B, tm, b);
            const double py = 3 * tm;
            const double ra = hypot(a[TRK_CV2_X], a[TRK_CV2_Y] - py), rb = hypot(b[TRK_CV2_X], b[TRK_CV2_Y] - py);
            assert_true(fabs(rb - ra - 100) < 1e-6);
            assert_true(fabs(atan2(b[TRK_CV2_X], b[TRK_CV2_Y] - py) - atan2(a[TRK_CV2_X], a[TRK_CV2_Y] - py)) < 1e-9);
            assert_true(s.par_scans >= 40);
            /* the far target near 7 km */
            double f[4];
            mtt_scen_truth(&s, MTT_STRAIGHT, tm, f);
            const double rf = hypot(f[TRK_CV2_X], f[TRK_CV2_Y] - py);
            assert_true(rf >= 6500 - 1e-6 && rf <= 7500 + 1e-6);
            /* the crossing: both at its point, 20-35 deg apart */
            const struct mtt_target *ca = &s.tg[MTT_CROSS_A], *cb = &s.tg[MTT_CROSS_B];
            assert_true(ca->at_s == cb->at_s && ca->ax_m == s.cross_x_m && cb->ay_m == s.cross_y_m);
            const double dh = fabs(remainder(ca->heading_rad - cb->heading_rad, 2 * 180 * DEG));
            assert_true(dh >= 20 * DEG - 1e-9 && dh <= 35 * DEG + 1e-9);
            assert_true(mtt_scen_present(&s, MTT_CROSS_A, s.cross_scan) &&
                        mtt_scen_present(&s, MTT_CROSS_B, s.cross_scan));
            /* the turn within its life */
            assert_true(s.turn_first_scan <= s.turn_last_scan);
            assert_true(mtt_scen_present(&s, MTT_TURN, s.turn_first_scan) &&
                        mtt_scen_present(&s, MTT_TURN, s.turn_last_scan));
        }
        /* the scans */
        const long ncl = TRK_MAX_DETECTIONS - 30 < 150 ? TRK_MAX_DETECTIONS - 30 : 150, nsm = ncl / 2;
        double pd_sum = 0, det_sum = 0, n_tgt = 0, n_cl = 0, n_patch = 0, n_near = 0, n_far = 0, amp_x = 0;
        for (long k = 0; k < 150; k++) {
            struct trk_scan sa, sb;
            struct mtt_scan_info ia, ib;
            struct trk_pose ps;
            mtt_scen_pose(&s, k, &ps);
            assert_int_equal(mtt_scen_scan_polar(&s, k, ncl, det_a, pol_a, TRK_MAX_DETECTIONS, org_a, &sa, &ia), 0);
            assert_true(sa.detections == det_a && sa.polar == NULL && !sa.has_pose);
            assert_int_equal(ia.n_clutter, (size_t)ncl);
            assert_int_equal(sa.n_detections, ia.n_target + ia.n_persist + ia.n_clutter);
            assert_true(ia.n_persist <= MTT_SONAR_PERSIST);
            for (size_t i = 0; i < sa.n_detections; i++) {
                struct trk_detection d;
                memset(&d, 0, sizeof d); /* the padding too, as the scenario's */
                assert_int_equal(trk_polar_to_cartesian(sp, &ps, &pol_a[i], &d), TRK_OK);
                assert_memory_equal(&d, &det_a[i], sizeof d);
                /* amplitudes at the P_D law's threshold t^2 = -ln 0.01 (clutter power 1) */
                assert_true(det_a[i].has_cov && det_a[i].has_amplitude);
                assert_true((double)det_a[i].amplitude * (double)det_a[i].amplitude >= -log(0.01) * (1 - 1e-6));
                if (org_a[i] == -1) {
                    amp_x += (double)det_a[i].amplitude * (double)det_a[i].amplitude + log(0.01); /* ~ Exp(1) */
                    assert_true(pol_a[i].range_m >= 500 - 1e-3 && pol_a[i].range_m <= 8000 + 1e-3);
                    assert_true(fabs(pol_a[i].bearing_rad) <= hw + 1e-6);
                    n_cl++;
                    n_patch += mtt_scen_in_patch(&s, det_a[i].x_m, det_a[i].y_m);
                    n_near += pol_a[i].range_m < 1000;
                    n_far += pol_a[i].range_m > 4000;
                }
                assert_true(org_a[i] >= -2 && org_a[i] < 8);
            }
            for (int j = 0; j < MTT_N_SLOTS; j++) { /* the detection rate against the library's P_D */
                const long i = mtt_scen_slot_target(&s, j, k);
                if (i < 0) continue;
                double x[4];
                mtt_scen_truth(&s, i, (double)k * T, x);
                pd_sum += trk_sensor_pd_at(sp, &ps, (trk_real)x[TRK_CV2_X], (trk_real)x[TRK_CV2_Y]);
                n_tgt++;
            }
            det_sum += (double)ia.n_target;
            if (k % 37 != 0) continue;
            /* determinism; mtt_scen_scan the same det[]; fewer clutter points the first ones */
            mtt_scen_scan_polar(&s2, k, ncl, det_b, pol_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib);
            assert_int_equal(sa.n_detections, sb.n_detections);
            assert_memory_equal(det_a, det_b, sa.n_detections * sizeof det_a[0]);
            assert_memory_equal(pol_a, pol_b, sa.n_detections * sizeof pol_a[0]);
            mtt_scen_scan(&s2, k, ncl, det_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib);
            assert_int_equal(sa.n_detections, sb.n_detections);
            assert_memory_equal(det_a, det_b, sa.n_detections * sizeof det_a[0]);
            mtt_scen_scan(&s2, k, nsm, det_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib);
            for (size_t i = 0; i < sb.n_detections; i++)
                assert_true(has_pos(&det_b[i], det_a, org_a, sa.n_detections, org_b[i]));
            /* without the persistent scatterers: the same but for them */
            mtt_scen_scan(&np, k, ncl, det_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib);
            assert_int_equal(ib.n_persist, 0);
            assert_int_equal(sb.n_detections, sa.n_detections - ia.n_persist);
            for (size_t i = 0; i < sa.n_detections; i++)
                if (org_a[i] != -2) assert_true(has_pos(&det_a[i], det_b, org_b, sb.n_detections, org_a[i]));
        }
        const double pd_mean = pd_sum / n_tgt, sd = sqrt(pd_mean * (1 - pd_mean) / n_tgt);
        assert_true(fabs(det_sum / n_tgt - pd_mean) < 4 * sd);
        /* clutter: ~30 % in the patches (3 % of the area), denser near the
         * sonar per m^2 (r < 1 km against 4-8 km) */
        assert_true(fabs(amp_x / n_cl - 1) < 4 / sqrt(n_cl)); /* the clutter law above the threshold: x ~ Exp(1), 4 sigma */
        assert_true(n_patch / n_cl > 0.2 && n_patch / n_cl < 0.45);
        const double a_near = hw * (1000.0 * 1000 - 500.0 * 500), a_far = hw * (8000.0 * 8000 - 4000.0 * 4000);
        assert_true((n_near / a_near) > 5 * (n_far / a_far));
        mtt_scen_free(&s);
        mtt_scen_free(&s2);
        mtt_scen_free(&np);
    }
    /* without amplitudes the same positions (the amplitudes have a stream of their own) */
    struct mtt_scen_params p;
    struct mtt_scenario s, s0;
    char err[256];
    mtt_scen_sonar_defaults(&p);
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), 0);
    p.amplitude = 0;
    assert_int_equal(mtt_scen_init(&s0, &p, err, sizeof err), 0);
    for (long k = 0; k < 5; k++) {
        struct trk_scan sa, sb;
        struct mtt_scan_info ia, ib;
        assert_int_equal(mtt_scen_scan_polar(&s, k, 50, det_a, pol_a, TRK_MAX_DETECTIONS, org_a, &sa, &ia), 0);
        assert_int_equal(mtt_scen_scan_polar(&s0, k, 50, det_b, pol_b, TRK_MAX_DETECTIONS, org_b, &sb, &ib), 0);
        assert_int_equal(sa.n_detections, sb.n_detections);
        for (size_t i = 0; i < sa.n_detections; i++) {
            assert_true(det_a[i].x_m == det_b[i].x_m && det_a[i].y_m == det_b[i].y_m && org_a[i] == org_b[i]);
            assert_true(det_a[i].has_amplitude && !det_b[i].has_amplitude);
        }
    }
    mtt_scen_free(&s);
    mtt_scen_free(&s0);
    /* refused: an acceleration */
    mtt_scen_sonar_defaults(&p);
    p.accel_mps2 = 0.1;
    assert_int_equal(mtt_scen_init(&s, &p, err, sizeof err), -1);
    assert_true(strcmp(mtt_family_name(MTT_FAMILY_SONAR), "sonar") == 0);
    assert_int_equal(mtt_family_parse("sonar"), MTT_FAMILY_SONAR);
}

/* Student t quantiles and intervals (R: qt(0.975, df)). */
static void test_student_t(void **state)
{
    (void)state;
    TRK_ASSERT_NEAR(mc_t(0.95, 1), 12.706204736174707, 1e-8, 0);
    TRK_ASSERT_NEAR(mc_t(0.95, 9), 2.2621571627982053, 1e-9, 0);
    TRK_ASSERT_NEAR(mc_t(0.99, 4), 4.6040948713499177, 1e-9, 0);
    TRK_ASSERT_NEAR(mc_t(0.95, 1e7), 1.959963984540054, 1e-5, 0);
    const double x[4] = {1, 2, 3, 4};
    double m, lo, hi;
    mc_mean_ci_t(x, 4, 0.95, &m, &lo, &hi);
    TRK_ASSERT_NEAR(m, 2.5, 1e-15, 0);
    TRK_ASSERT_NEAR(hi - m, 3.1824463052842638 * sqrt(5.0 / 3 / 4), 1e-9, 0);
    TRK_ASSERT_NEAR(m - lo, hi - m, 1e-12, 0);
    mc_mean_ci_t(x, 1, 0.95, &m, &lo, &hi);
    assert_true(m == 1 && lo == 1 && hi == 1);
    mc_mean_ci_t(x, 0, 0.95, &m, &lo, &hi);
    assert_true(isnan(m) && isnan(lo) && isnan(hi));
}

/* mtt_eval's per-target assignment agrees with its counts. */
static void test_eval_assign(void **state)
{
    (void)state;
    struct mtt_eval e;
    mtt_eval_init(&e, 50);
    const struct mtt_obj truth[3] = {{0, 0, 0}, {1, 100, 0}, {2, 1000, 1000}};
    const struct mtt_obj est[3] = {{7, 3, 4}, {9, 130, 0}, {11, 2000, 0}};
    long as[3];
    assert_int_equal(mtt_eval_scan_assign(&e, truth, 3, est, 3, as), 0);
    assert_true(as[0] == 0 && as[1] == 1 && as[2] == -1);
    struct mtt_summary su;
    mtt_eval_summary(&e, &su);
    TRK_ASSERT_NEAR(su.coverage, 2.0 / 3, 1e-12, 0);
    TRK_ASSERT_NEAR(su.loc_mean_m2, 25 + 900, 1e-9, 0);
    assert_int_equal(mtt_eval_scan(&e, truth, 3, est, 0), 0);
    mtt_eval_free(&e);
}

/* The `old` configuration: the defaults before two-point initiation, accepted by the tracker. */
static void test_old_defaults(void **state)
{
    (void)state;
    struct trk_tracker_params p;
    mtt_old_defaults(&p);
    assert_int_equal(p.confirm.method, TRK_CONFIRM_MN);
    assert_true(p.confirm.u.mn.m == 3 && p.confirm.u.mn.n == 5 && p.confirm.u.mn.mode == TRK_MN_FIXED);
    assert_int_equal(p.term.method, TRK_TERM_KN);
    assert_true(p.term.u.kn.k == 0 && p.term.u.kn.n == 5);
    TRK_ASSERT_NEAR(p.merge_gate_d2, 4, 0, 0);
    TRK_ASSERT_NEAR(p.init_exclusion_d2, 18.42068, 1e-4, 0);
    assert_int_equal(p.track_visibility, 1);
    TRK_ASSERT_NEAR(p.visibility.delta_become, 0.01, 1e-7, 0);
    TRK_ASSERT_NEAR(p.visibility.p_con, 0.9, 1e-7, 0);
    const char *field = NULL;
    TRK_ASSERT_OK(trk_tracker_check_params(&p, &field));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_determinism), cmocka_unit_test(test_common_random_numbers),
        cmocka_unit_test(test_presence),    cmocka_unit_test(test_geometry),
        cmocka_unit_test(test_capacity),    cmocka_unit_test(test_fixed_first_scenario),
        cmocka_unit_test(test_fixed_presence), cmocka_unit_test(test_fixed_geometry),
        cmocka_unit_test(test_fixed_determinism), cmocka_unit_test(test_fixed_capacity),
        cmocka_unit_test(test_families_share), cmocka_unit_test(test_student_t),
        cmocka_unit_test(test_eval_assign), cmocka_unit_test(test_old_defaults),
        cmocka_unit_test(test_accel),       cmocka_unit_test(test_long_turns),
        cmocka_unit_test(test_sonar),
    };
    return trk_run_tests("mtt_scenario", tests, NULL, NULL);
}
