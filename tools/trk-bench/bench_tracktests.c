/* bench_tracktests.c - cost of the per-track confirmation / termination
 * tests:
 *   tt_<test>          ns per step of one test on one track (Blanding Table 1
 *                      model, 4 sensors looked at in turn, a fixed pseudo-random
 *                      pattern of detections and gate P_FA)
 *   tt_chi2_init       ns per trk_clutter_chi2_model_init (kmax 25: the
 *                      threshold table, built once per tracker; a track start
 *                      is the cheap trk_clutter_chi2_reset)
 *   tt_amp_threshold   ns per on-demand F quantile (window K = 25, 250 others)
 *   tt_table64_all     ns per scan for 64 tracks each stepping every test
 *                      (K/N, Page, Shiryaev, M/N, SPRT, chi2, F) with one
 *                      shared model per test, as the tracker does
 *   tt_sizeof_<test>   bytes of each test's per-track state
 *   tt_sizeof_<test>_model  bytes of its shared model */
#include <stdio.h>
#include <string.h>

#include "bench.h"
#include "trk/clutter_test.h"
#include "trk/confirm_mn.h"
#include "trk/confirm_sprt.h"
#include "trk/term_kn.h"
#include "trk/term_page.h"
#include "trk/term_shiryaev.h"

#define PAT 1024
#define NTRK 64

static struct {
    int det[PAT];
    trk_real pfa[PAT];
    trk_real rho_vg[PAT];
    trk_real a_assoc[PAT];
    trk_real others[PAT + 16];
} pat;

static unsigned ns_bench(void) { return TRK_MAX_SENSORS >= 4 ? 4 : TRK_MAX_SENSORS; }

static void make_pattern(void)
{
    uint64_t s = 12345;
    for (int i = 0; i < PAT; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        const double u = (double)(s >> 11) * (1.0 / 9007199254740992.0);
        pat.det[i] = u < 0.3;
        pat.pfa[i] = (trk_real)(0.05 + 0.05 * u);
        pat.rho_vg[i] = (trk_real)(0.02 + 2 * u);
        pat.a_assoc[i] = (trk_real)(5 + 20 * u);
    }
    for (int i = 0; i < PAT + 16; i++) pat.others[i] = (trk_real)(5 + 3 * ((i * 37) % 11) / 11.0);
}

static struct trk_hmm_params blanding_hmm(void)
{
    const struct trk_hmm_sensor_params sp = {TRK_REAL_C(0.1) / 3, TRK_REAL_C(0.1), TRK_REAL_C(0.1),
                                             TRK_REAL_C(0.9), TRK_HMM_PI0_STATIONARY};
    struct trk_hmm_params hp;
    trk_hmm_params_uniform(&hp, ns_bench(), &sp);
    return hp;
}

/* shared models (one per test, as in the tracker) */
static struct {
    struct trk_page_model page;
    struct trk_shiryaev_model shir;
    struct trk_sprt_model sprt_fixed, sprt_hmm;
    struct trk_kn_model kn;
    struct trk_mn_model mn;
    struct trk_clutter_chi2_model chi2;
    struct trk_clutter_amp_model amp;
    struct trk_hmm_model hmm;
} mod;

/* per-track states */
struct job {
    unsigned i;
    struct trk_page page;
    struct trk_shiryaev shir;
    struct trk_sprt sprt_fixed, sprt_hmm;
    struct trk_kn kn;
    struct trk_mn mn;
    struct trk_clutter_chi2 chi2;
    struct trk_clutter_amp amp;
    struct trk_hmm_state hmm;
};

static int models_init(void)
{
    struct trk_page_params pp;
    pp.hmm = blanding_hmm();
    pp.h = 1e6; /* keep going: a fired test costs the same per step */
    struct trk_shiryaev_params sp;
    sp.hmm = pp.hmm;
    sp.beta0 = TRK_REAL_C(0.5);
    sp.rho = TRK_REAL_C(0.005);
    sp.h = 1e6;
    struct trk_sprt_params fp;
    memset(&fp, 0, sizeof fp);
    fp.alpha = TRK_REAL_C(0.01);
    fp.beta = TRK_REAL_C(0.1);
    fp.model = TRK_SPRT_FIXED_PD;
    fp.pd = TRK_REAL_C(0.8);
    struct trk_sprt_params hp = fp;
    hp.model = TRK_SPRT_HMM;
    hp.hmm = pp.hmm;
    const struct trk_kn_params kp = {3, 20};
    const struct trk_mn_params mp = {3, 5, TRK_MN_SLIDING};
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.01), 25};
    const struct trk_clutter_amp_params ap = {5, TRK_REAL_C(0.01), 25};
    return trk_page_model_init(&mod.page, &pp) || trk_shiryaev_model_init(&mod.shir, &sp) ||
           trk_sprt_model_init(&mod.sprt_fixed, &fp) || trk_sprt_model_init(&mod.sprt_hmm, &hp) ||
           trk_kn_model_init(&mod.kn, &kp) || trk_mn_model_init(&mod.mn, &mp) ||
           trk_clutter_chi2_model_init(&mod.chi2, &cp) ||
           trk_clutter_amp_model_init(&mod.amp, &ap) || trk_hmm_model_init(&mod.hmm, &pp.hmm);
}

static void job_reset(struct job *j)
{
    j->i = 0;
    trk_page_reset(&mod.page, &j->page);
    trk_shiryaev_reset(&mod.shir, &j->shir);
    trk_sprt_reset(&mod.sprt_fixed, &j->sprt_fixed);
    trk_sprt_reset(&mod.sprt_hmm, &j->sprt_hmm);
    trk_kn_reset(&mod.kn, &j->kn);
    trk_mn_reset(&mod.mn, &j->mn);
    trk_clutter_chi2_reset(&mod.chi2, &j->chi2);
    trk_clutter_amp_reset(&mod.amp, &j->amp);
    trk_hmm_state_reset(&mod.hmm, &j->hmm);
}

#define NEXT(j) const unsigned k_ = (j)->i++ & (PAT - 1); const unsigned sensor_ = (j)->i % ns_bench()

static void run_hmm(void *a)
{
    struct job *j = a;
    NEXT(j);
    trk_real lf1;
    trk_status st = trk_hmm_update(&mod.hmm, &j->hmm, sensor_, pat.det[k_], pat.pfa[k_], &lf1);
    bench_sink((double)lf1 + (double)st);
}
static void run_page(void *a)
{
    struct job *j = a;
    NEXT(j);
    enum trk_decision d;
    trk_status st = trk_page_step(&mod.page, &j->page, sensor_, pat.det[k_], pat.pfa[k_], &d);
    bench_sink((double)j->page.stat + (double)st);
}
static void run_shir(void *a)
{
    struct job *j = a;
    NEXT(j);
    enum trk_decision d;
    trk_status st = trk_shiryaev_step(&mod.shir, &j->shir, sensor_, pat.det[k_], pat.pfa[k_], &d);
    bench_sink((double)j->shir.stat + (double)st);
}
static void run_sprt_fixed(void *a)
{
    struct job *j = a;
    NEXT(j);
    enum trk_decision d;
    trk_status st =
        trk_sprt_step(&mod.sprt_fixed, &j->sprt_fixed, sensor_, pat.det[k_], pat.pfa[k_], &d);
    bench_sink((double)j->sprt_fixed.stat + (double)st);
}
static void run_sprt_hmm(void *a)
{
    struct job *j = a;
    NEXT(j);
    enum trk_decision d;
    trk_status st =
        trk_sprt_step(&mod.sprt_hmm, &j->sprt_hmm, sensor_, pat.det[k_], pat.pfa[k_], &d);
    bench_sink((double)j->sprt_hmm.stat + (double)st);
}
static void run_kn(void *a)
{
    struct job *j = a;
    NEXT(j);
    (void)sensor_;
    enum trk_decision d = TRK_DECISION_CONTINUE;
    trk_status st = trk_kn_step(&mod.kn, &j->kn, pat.det[k_], &d);
    bench_sink((double)d + (double)st);
}
static void run_mn(void *a)
{
    struct job *j = a;
    NEXT(j);
    (void)sensor_;
    enum trk_decision d = TRK_DECISION_CONTINUE;
    trk_status st = trk_mn_step(&mod.mn, &j->mn, pat.det[k_], &d);
    bench_sink((double)d + (double)st);
}
static void run_chi2(void *a)
{
    struct job *j = a;
    NEXT(j);
    (void)sensor_;
    enum trk_decision d;
    trk_status st = trk_clutter_chi2_step(&mod.chi2, &j->chi2, pat.rho_vg[k_], &d);
    bench_sink((double)j->chi2.p_value + (double)st);
}
static void run_amp(void *a)
{
    struct job *j = a;
    NEXT(j);
    (void)sensor_;
    enum trk_decision d;
    trk_status st =
        trk_clutter_amp_step(&mod.amp, &j->amp, pat.a_assoc[k_], 10, pat.others + (k_ & 7), &d);
    bench_sink((double)j->amp.p_value + (double)st);
}
static void run_chi2_init(void *a)
{
    (void)a;
    const struct trk_clutter_chi2_params cp = {TRK_REAL_C(0.01), 25};
    trk_status st = trk_clutter_chi2_model_init(&mod.chi2, &cp);
    bench_sink((double)mod.chi2.threshold_tab[24] + (double)st);
}
static void run_amp_thr(void *a)
{
    struct job *j = a;
    trk_real thr = 0;
    trk_status st = trk_clutter_amp_threshold(&mod.amp, &j->amp, &thr);
    bench_sink((double)thr + (double)st);
}

/* the whole table: 64 tracks, every test, one scan */
static struct job table[NTRK];
static unsigned table_scan;
static void run_table(void *a)
{
    (void)a;
    const unsigned sensor = table_scan % ns_bench();
    for (int t = 0; t < NTRK; t++) {
        struct job *j = &table[t];
        const unsigned k = (table_scan * 7u + (unsigned)t * 13u) & (PAT - 1);
        const int det = pat.det[k];
        const trk_real pfa = pat.pfa[k];
        enum trk_decision d[7] = {TRK_DECISION_CONTINUE};
        trk_status st = trk_page_step(&mod.page, &j->page, sensor, det, pfa, &d[0]);
        st |= trk_shiryaev_step(&mod.shir, &j->shir, sensor, det, pfa, &d[1]);
        st |= trk_sprt_step(&mod.sprt_hmm, &j->sprt_hmm, sensor, det, pfa, &d[2]);
        st |= trk_clutter_chi2_step(&mod.chi2, &j->chi2, pat.rho_vg[k], &d[3]);
        st |= trk_clutter_amp_step(&mod.amp, &j->amp, pat.a_assoc[k], 10, pat.others + (k & 7),
                                   &d[4]);
        st |= trk_kn_step(&mod.kn, &j->kn, det, &d[5]);
        st |= trk_mn_step(&mod.mn, &j->mn, det, &d[6]);
        int nd = 0;
        for (int i = 0; i < 7; i++) nd += d[i] != TRK_DECISION_CONTINUE;
        bench_sink((double)j->page.stat + (double)j->amp.p_value + nd + (double)st);
    }
    table_scan++;
}

TRK_BENCH(tracktests)
{
    static struct job j;
    make_pattern();
    if (models_init()) {
        fprintf(stderr, "trk-bench tracktests: init failed\n");
        return;
    }
    job_reset(&j);
    const struct {
        const char *name;
        void (*fn)(void *);
    } steps[] = {
        {"tt_hmm_detect_update", run_hmm}, {"tt_page_step", run_page},
        {"tt_shiryaev_step", run_shir},    {"tt_sprt_step_fixed", run_sprt_fixed},
        {"tt_sprt_step_hmm", run_sprt_hmm}, {"tt_kn_step", run_kn},
        {"tt_mn_step", run_mn},             {"tt_clutter_chi2_step_k25", run_chi2},
        {"tt_clutter_amp_step_k25_n10", run_amp},
    };
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++)
        bench_print(steps[i].name, bench_time_ns(steps[i].fn, &j, 5), "ns");
    bench_print("tt_amp_threshold_k25", bench_time_ns(run_amp_thr, &j, 3), "ns");
    bench_print("tt_chi2_init_k25", bench_time_ns(run_chi2_init, &j, 3), "ns");
    for (int t = 0; t < NTRK; t++) job_reset(&table[t]);
    const double per_scan = bench_time_ns(run_table, NULL, 5);
    bench_print("tt_table64_all_per_scan", per_scan, "ns");
    bench_print("tt_table64_all_per_track", per_scan / NTRK, "ns");
    bench_print("tt_sizeof_page", (double)sizeof(struct trk_page), "B");
    bench_print("tt_sizeof_shiryaev", (double)sizeof(struct trk_shiryaev), "B");
    bench_print("tt_sizeof_sprt", (double)sizeof(struct trk_sprt), "B");
    bench_print("tt_sizeof_clutter_chi2", (double)sizeof(struct trk_clutter_chi2), "B");
    bench_print("tt_sizeof_clutter_amp", (double)sizeof(struct trk_clutter_amp), "B");
    bench_print("tt_sizeof_page_model", (double)sizeof(struct trk_page_model), "B");
    bench_print("tt_sizeof_shiryaev_model", (double)sizeof(struct trk_shiryaev_model), "B");
    bench_print("tt_sizeof_sprt_model", (double)sizeof(struct trk_sprt_model), "B");
    bench_print("tt_sizeof_clutter_chi2_model", (double)sizeof(struct trk_clutter_chi2_model), "B");
    bench_print("tt_sizeof_clutter_amp_model", (double)sizeof(struct trk_clutter_amp_model), "B");
}
