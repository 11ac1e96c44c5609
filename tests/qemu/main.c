/* main.c - the firmware test image (mk/qemu.mk: make qemu-test).
 *
 * Runs on QEMU's mps2-an386 (Cortex-M4F, trk_real = float) or mps2-an500
 * (Cortex-M7 with double FPU, trk_real = double), output over semihosting:
 *  1. every reference-vector case compiled into the image as C data
 *     (tests/qemu/vec2c.sh) through the host's own parser, kinds and checker
 *     (tools/vec/): per kind the pass/fail counts and the largest errors, as
 *     `trk-vectors --report-error` prints them on the host. Float builds
 *     compare normwise with each kind's float tolerance (tools/vec/kind_*.c);
 *  2. amplitude from lookup tables linked as const arrays (flash): one table
 *     per K-clutter parameter set of the amplitude vectors, generated on the
 *     host in the target's real width (tests/qemu/amp_tables.sh); each is
 *     parsed in place (trk_table_parse, trk_amplitude_init_table) and every
 *     amp_threshold / amp_loglr / amp_inv_sf case of model k is checked by
 *     table lookup against the vector's values (kinds "<kind>/table"), with
 *     the table tolerances of tests/test_amplitude.c. With FW_AMP_K_DIRECT=0
 *     (targets without a double FPU) such cases are answered only by the
 *     table: the kinds' direct K evaluation is tool-side double-precision
 *     quadrature, minutes of soft-double code under emulation;
 *  3. the measured stack of trk_tracker_process_scan and trk_pda_update on a
 *     tracking scenario (stack painted with a pattern before each call, the
 *     deepest overwritten word found after it), to set against the static
 *     bound of make size-report.
 * Exit status 0 when no case failed and at least one passed; 1 otherwise
 * (99 on a fault, from startup.c).
 *
 * Kinds listed in FW_SKIP_KINDS (mk/qemu.mk: those registered VEC_SLOW) are
 * left out of the image's registry and their cases, embedded as case/end
 * lines only, are counted as skipped; cases of kinds no one implements yet
 * are counted as unimplemented and named. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "trk/amplitude.h"
#include "trk/table.h"
#include "trk/trk.h"
#include "vec.h"

#ifndef FW_SKIP_KINDS
#define FW_SKIP_KINDS ""
#endif
#ifndef FW_TARGET
#define FW_TARGET "?"
#endif
#ifndef FW_AMP_K_DIRECT
#define FW_AMP_K_DIRECT 1
#endif

struct fw_vec_blob {
    const char *name;
    const char *text;
    size_t len;
};
extern const struct fw_vec_blob fw_vec_blobs[];
extern const size_t fw_vec_n_blobs;
struct fw_amp_blob {
    const unsigned char *bytes;
    size_t size;
};
extern const struct fw_amp_blob fw_amp_tables[];
extern const size_t fw_amp_n_tables;

static struct vec_case cs;
static struct vec_out out;

struct kind_stat {
    const char *name;
    long passed, failed, not_applicable;
    double max_abs, max_rel, max_use;
    double tol_abs, tol_rel; /* the float tolerance of the kind (or of the table check) */
};
static struct kind_stat stats[64];
static size_t n_stats;

static struct kind_stat *stat_of(const char *name)
{
    for (size_t i = 0; i < n_stats; i++)
        if (strcmp(stats[i].name, name) == 0) return &stats[i];
    if (n_stats == sizeof stats / sizeof stats[0]) return NULL;
    stats[n_stats].name = name;
    return &stats[n_stats++];
}

/* a word of the space-separated FW_SKIP_KINDS list */
static int skipped_kind(const char *kind)
{
    const char *p = FW_SKIP_KINDS;
    size_t n = strlen(kind);
    while (*p) {
        while (*p == ' ') p++;
        const char *q = p;
        while (*q && *q != ' ') q++;
        if ((size_t)(q - p) == n && strncmp(p, kind, n) == 0) return 1;
        p = q;
    }
    return 0;
}

static long passed, failed, unimpl, skipped, not_applicable;

/* ---------------------------------------------------------------- amplitude tables */

#define FW_MAX_AMP 256
static struct trk_table amp_table[FW_MAX_AMP];
static struct trk_amplitude amp_model[FW_MAX_AMP];
static size_t n_amp;
static long amp_beyond; /* vector points beyond a table's range (a_max, x_max) */

/* Tolerances of table lookup against direct evaluation (tests/test_amplitude.c):
 * ln l^a abs 5e-6 (double) / 1e-4 (float) plus rel 1e-6; a(x) rel 1e-6 /
 * 2e-6; threshold and P_D are stored in the table (computed in double by
 * trk-tablegen): rel 1e-9 / 1e-6 (float rounding). */
#define AMP_LLR_ABS (TRK_REAL_IS_FLOAT ? 1e-4 : 5e-6)
#define AMP_LLR_REL 1e-6
#define AMP_INV_REL (TRK_REAL_IS_FLOAT ? 2e-6 : 1e-6)
#define AMP_PAR_REL (TRK_REAL_IS_FLOAT ? 1e-6 : 1e-9)

static int load_amp_tables(void)
{
    int bad = 0;
    for (size_t i = 0; i < fw_amp_n_tables && n_amp < FW_MAX_AMP; i++) {
        trk_status st = trk_table_parse(&amp_table[n_amp], fw_amp_tables[i].bytes, fw_amp_tables[i].size);
        if (st == TRK_OK) st = trk_amplitude_init_table(&amp_model[n_amp], &amp_table[n_amp]);
        if (st != TRK_OK) {
            printf("FAIL amplitude table %u (%u bytes at %p) rejected: %s\n", (unsigned)i,
                   (unsigned)fw_amp_tables[i].size, (const void *)fw_amp_tables[i].bytes, trk_status_str(st));
            bad = 1;
            continue;
        }
        n_amp++;
    }
    return bad;
}

static int near_rel(double a, double b, double rel) { return fabs(a - b) <= rel * fabs(b); }

static const struct trk_amplitude *find_amp(double nu, double power, double snr_db, double pfa)
{
    for (size_t i = 0; i < n_amp; i++) {
        const struct trk_amplitude *m = &amp_model[i];
        if (near_rel((double)m->nu, nu, 1e-6) && near_rel((double)m->clutter_power, power, 1e-6) &&
            fabs((double)m->snr_db - snr_db) <= 1e-6 * (1 + fabs(snr_db)) && near_rel((double)m->pfa, pfa, 1e-6))
            return m;
    }
    return NULL;
}

/* A model-k amplitude case by table lookup: 0 pass, 1 fail (first_fail
 * set), -1 no table / bad case (err set). */
static int amp_table_case(const struct vec_case *c, const char *kind, char *msg, size_t msg_len, double *max_use,
                          double *max_abs, double *max_rel)
{
    double nu, power, snr_db, pfa;
    static struct vec_out o;
    vec_out_reset(&o);
    if (vec_in_scalar(c, &o, "nu", &nu) || vec_in_scalar(c, &o, "clutter_power", &power) ||
        vec_in_scalar(c, &o, "snr_db", &snr_db) || vec_in_scalar(c, &o, "pfa", &pfa)) {
        snprintf(msg, msg_len, "%s", o.err);
        return -1;
    }
    const struct trk_amplitude *m = find_amp(nu, power, snr_db, pfa);
    if (!m) {
        snprintf(msg, msg_len, "no table linked for nu %g, P %g, SNR %g dB, pfa %g", nu, power, snr_db, pfa);
        return -1;
    }
    *max_use = *max_abs = *max_rel = 0;
    const double t = (double)m->threshold;
    if (strcmp(kind, "amp_threshold") == 0) {
        const struct vec_entry *wt = NULL, *wp = NULL;
        for (size_t i = 0; i < c->n_out; i++) {
            if (strcmp(c->out[i].name, "t") == 0) wt = &c->out[i];
            if (strcmp(c->out[i].name, "pd") == 0) wp = &c->out[i];
        }
        if (!wt || !wp || wt->n != 1 || wp->n != 1) {
            snprintf(msg, msg_len, "amp_threshold case without t and pd");
            return -1;
        }
        const double want[2] = {c->pool[wt->off], c->pool[wp->off]}, got[2] = {t, (double)m->pd};
        for (int k = 0; k < 2; k++) {
            const double err = fabs(got[k] - want[k]), use = err / (AMP_PAR_REL * fabs(want[k]));
            if (use > *max_use) *max_use = use;
            if (err > *max_abs) *max_abs = err;
            if (want[k] != 0 && err / fabs(want[k]) > *max_rel) *max_rel = err / fabs(want[k]);
            if (!(use <= 1)) {
                snprintf(msg, msg_len, "%s %.9g %.9g", k ? "pd" : "t", got[k], want[k]);
                return 1;
            }
        }
        return 0;
    }
    const int llr = strcmp(kind, "amp_loglr") == 0;
    const double *in, *want;
    size_t n, nw;
    const char *in_name = llr ? "a" : "x", *out_name = llr ? "log_lr" : "a";
    long which = 0;
    if (vec_in_array(c, &o, in_name, &in, &n) || (!llr && vec_in_int(c, &o, "which", &which))) {
        snprintf(msg, msg_len, "%s", o.err);
        return -1;
    }
    want = NULL;
    nw = 0;
    for (size_t i = 0; i < c->n_out; i++)
        if (strcmp(c->out[i].name, out_name) == 0) {
            want = c->pool + c->out[i].off;
            nw = c->out[i].n;
        }
    if (!want || nw != n) {
        snprintf(msg, msg_len, "no output '%s' of %u values", out_name, (unsigned)n);
        return -1;
    }
    /* ranges covered by the table */
    const double a_max = (double)m->sqrt_p * exp((double)m->llr_hi);
    const double x_max = (double)m->inv[which ? 1 : 0].axis.hi;
    for (size_t i = 0; i < n; i++) {
        trk_real got;
        trk_status st;
        double lim;
        if (llr) {
            /* as the kind: a case point an ulp (float: a rounding) below the threshold is the threshold */
            double a = in[i] < t && in[i] >= t * (1 - (TRK_REAL_IS_FLOAT ? 1e-6 : 1e-12)) ? t : in[i];
            if (a > a_max) {
                amp_beyond++;
                continue;
            }
            trk_real ar = (trk_real)a;
            if (ar < m->threshold) ar = m->threshold;
            st = trk_amplitude_log_lr(m, ar, &got);
            lim = AMP_LLR_ABS + AMP_LLR_REL * fabs(want[i]);
        } else {
            if (in[i] > x_max) {
                amp_beyond++;
                continue;
            }
            st = trk_amplitude_inv_sf(m, (int)which, (trk_real)in[i], &got);
            lim = AMP_INV_REL * fabs(want[i]);
        }
        if (st != TRK_OK) {
            snprintf(msg, msg_len, "%s[%u]: %s", out_name, (unsigned)i, trk_status_str(st));
            return 1;
        }
        const double err = fabs((double)got - want[i]), use = err / lim;
        if (use > *max_use) *max_use = use;
        if (err > *max_abs) *max_abs = err;
        if (want[i] != 0 && err / fabs(want[i]) > *max_rel) *max_rel = err / fabs(want[i]);
        if (!(use <= 1)) {
            snprintf(msg, msg_len, "%s[%u] %.9g %.9g", out_name, (unsigned)i, (double)got, want[i]);
            return 1;
        }
    }
    return 0;
}

static int is_amp_table_kind(const char *kind)
{
    return strcmp(kind, "amp_threshold") == 0 || strcmp(kind, "amp_loglr") == 0 ||
           strcmp(kind, "amp_inv_sf") == 0;
}

static int model_k(const struct vec_case *c)
{
    for (size_t i = 0; i < c->n_in; i++)
        if (strcmp(c->in[i].name, "model") == 0) return strcmp(c->in[i].word, "k") == 0;
    return 0;
}

static void run_amp_table(const char *file, const struct vec_case *c)
{
    static char names[3][VEC_MAX_NAME + 8];
    const char *kind = c->kind;
    int slot = strcmp(kind, "amp_threshold") == 0 ? 0 : strcmp(kind, "amp_loglr") == 0 ? 1 : 2;
    snprintf(names[slot], sizeof names[slot], "%s/table", kind);
    struct kind_stat *s = stat_of(names[slot]);
    if (s) {
        s->tol_abs = slot == 1 ? AMP_LLR_ABS : 0;
        s->tol_rel = slot == 0 ? AMP_PAR_REL : slot == 1 ? AMP_LLR_REL : AMP_INV_REL;
    }
    char msg[160];
    double use = 0, ea = 0, er = 0;
    int r = amp_table_case(c, kind, msg, sizeof msg, &use, &ea, &er);
    if (r == 0) {
        passed++;
        if (s) s->passed++;
    } else {
        printf("FAIL %s %s (table) %s\n", file, c->id, msg);
        failed++;
        if (s) s->failed++;
    }
    if (s) {
        if (use > s->max_use) s->max_use = use;
        if (ea > s->max_abs) s->max_abs = ea;
        if (er > s->max_rel) s->max_rel = er;
    }
}

static void run_blob(const struct fw_vec_blob *b)
{
    static struct vec_file f;
    vec_file_init(&f, b->text, b->len);
    int r;
    while ((r = vec_next(&f, &cs)) == 1) {
        if (is_amp_table_kind(cs.kind) && model_k(&cs)) {
            run_amp_table(b->name, &cs);
            if (!FW_AMP_K_DIRECT) continue;
        }
        const struct vec_kind *k = vec_kind_find(cs.kind);
        if (!k) {
            if (skipped_kind(cs.kind)) skipped++;
            else unimpl++;
            continue;
        }
        struct kind_stat *s = stat_of(k->name);
        if (s) {
            s->tol_abs = k->float_abs;
            s->tol_rel = k->float_rel;
        }
        vec_out_reset(&out);
        int rc = k->fn(&cs, &out);
        if (rc == VEC_NOT_APPLICABLE) {
            printf("NOT-APPLICABLE %s %s %s\n", b->name, cs.id, out.err);
            not_applicable++;
            if (s) s->not_applicable++;
            continue;
        }
        if (rc != 0) {
            printf("FAIL %s %s %s\n", b->name, cs.id, out.err[0] ? out.err : "kind failed");
            failed++;
            if (s) s->failed++;
            continue;
        }
        struct vec_check chk;
        vec_compare(&f, &cs, &out, TRK_REAL_IS_FLOAT, k->float_abs, k->float_rel, &chk);
        if (chk.ok) {
            passed++;
            if (s) s->passed++;
        } else {
            printf("FAIL %s %s %s\n", b->name, cs.id, chk.first_fail);
            failed++;
            if (s) s->failed++;
        }
        if (s) {
            if (chk.max_abs_err > s->max_abs) s->max_abs = chk.max_abs_err;
            if (chk.max_rel_err > s->max_rel) s->max_rel = chk.max_rel_err;
            if (chk.max_tol_use > s->max_use) s->max_use = chk.max_tol_use;
        }
    }
    if (r < 0) {
        printf("FAIL %s malformed: %s\n", b->name, f.err);
        failed++;
    }
}

/* ---------------------------------------------------------------- stack */

#define PAINT_BYTES 16384u
#define PAINT_GUARD 256u /* the painter's own frame lives here */
#define PAINT_WORD 0xC5A5C5A5u

static uintptr_t current_sp(void)
{
    uintptr_t sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

__attribute__((noinline)) static void paint(uintptr_t sp)
{
    volatile uint32_t *p = (volatile uint32_t *)(sp - PAINT_BYTES);
    volatile uint32_t *end = (volatile uint32_t *)(sp - PAINT_GUARD);
    while (p < end) *p++ = PAINT_WORD;
}

static size_t used_below(uintptr_t sp)
{
    const volatile uint32_t *p = (const volatile uint32_t *)(sp - PAINT_BYTES);
    const volatile uint32_t *end = (const volatile uint32_t *)(sp - PAINT_GUARD);
    while (p < end && *p == PAINT_WORD) p++;
    return p == end ? 0 : (size_t)(sp - (uintptr_t)p);
}

/* A deterministic multi-target scene: 3 targets on straight lines, clutter
 * from an LCG, some detections with their own covariance and amplitude. */
static struct trk_tracker tracker;
static struct trk_detection det[TRK_MAX_DETECTIONS];
static uint32_t lcg = 12345u;
static trk_real urand(void)
{
    lcg = lcg * 1664525u + 1013904223u;
    return (trk_real)(lcg >> 8) * (TRK_REAL_C(1.0) / (trk_real)16777216);
}

static size_t max_stack_scan, max_stack_pda;

__attribute__((noinline)) static trk_status measured_scan(const struct trk_scan *scan,
                                                          struct trk_scan_report *rep)
{
    uintptr_t sp = current_sp();
    paint(sp);
    trk_status st = trk_tracker_process_scan(&tracker, scan, rep);
    size_t u = used_below(sp);
    if (u > max_stack_scan) max_stack_scan = u;
    return st;
}

__attribute__((noinline)) static void measured_pda(void)
{
    static trk_real z[2 * 8], beta[8], d2[8], lr[8];
    struct trk_pda pda;
    struct trk_pda_params pp;
    memset(&pp, 0, sizeof pp);
    pp.nz = 2;
    pp.pd = TRK_REAL_C(0.9);
    pp.gate_prob = TRK_REAL_C(0.99);
    pp.clutter = TRK_CLUTTER_PARAMETRIC;
    pp.clutter_density = TRK_REAL_C(1e-4);
    pp.gating = 1;
    if (trk_pda_init(&pda, &pp) != TRK_OK) return;
    trk_real x[4] = {0, 1, 0, 1}, p[16] = {4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1};
    trk_real r[4] = {1, 0, 0, 1};
    for (int i = 0; i < 8; i++) {
        z[2 * i] = urand() * 4 - 2;
        z[2 * i + 1] = urand() * 4 - 2;
        lr[i] = urand();
    }
    uintptr_t sp = current_sp();
    paint(sp);
    trk_status st = trk_pda_update(&pda, 4, trk_cv2_h, r, x, p, 8, z, lr, beta, d2, NULL);
    size_t u = used_below(sp);
    (void)st;
    if (u > max_stack_pda) max_stack_pda = u;
}

static int stack_scenario(void)
{
    struct trk_tracker_params prm;
    trk_tracker_default_params(&prm);
    if (trk_tracker_init(&tracker, &prm) != TRK_OK) {
        printf("stack scenario: trk_tracker_init failed\n");
        return 1;
    }
    long n_conf = 0;
    for (int k = 0; k < 40; k++) {
        size_t n = 0;
        for (int t = 0; t < 3; t++) {
            struct trk_detection *d = &det[n++];
            memset(d, 0, sizeof *d);
            d->x_m = TRK_REAL_C(100.0) * (trk_real)t + TRK_REAL_C(2.0) * (trk_real)k + urand() - TRK_REAL_C(0.5);
            d->y_m = TRK_REAL_C(-50.0) * (trk_real)t + TRK_REAL_C(1.0) * (trk_real)k + urand() - TRK_REAL_C(0.5);
            if (t == 1) {
                d->has_cov = 1;
                d->cov_m2[0] = TRK_REAL_C(2.0);
                d->cov_m2[1] = TRK_REAL_C(0.3);
                d->cov_m2[2] = TRK_REAL_C(1.0);
            }
            d->has_amplitude = 1;
            d->amplitude = TRK_REAL_C(3.0) + urand();
        }
        for (int c = 0; c < 20 && n < TRK_MAX_DETECTIONS; c++) {
            struct trk_detection *d = &det[n++];
            memset(d, 0, sizeof *d);
            d->x_m = urand() * TRK_REAL_C(1000.0) - TRK_REAL_C(300.0);
            d->y_m = urand() * TRK_REAL_C(1000.0) - TRK_REAL_C(500.0);
        }
        struct trk_scan scan = {(int64_t)k * 2000000, 0, n, det, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        if (measured_scan(&scan, &rep) != TRK_OK) {
            printf("stack scenario: scan %d refused\n", k);
            return 1;
        }
        n_conf += rep.n_confirmed;
    }
    for (int i = 0; i < 10; i++) measured_pda();
    printf("stack: trk_tracker_process_scan %u bytes, trk_pda_update %u bytes (measured, 40 scans, "
           "%ld confirmations)\n",
           (unsigned)max_stack_scan, (unsigned)max_stack_pda, n_conf);
    return n_conf > 0 ? 0 : 1;
}

int main(void)
{
    printf("trk-fw: %s, trk_real = %s, %u vector files\n", FW_TARGET,
           TRK_REAL_IS_FLOAT ? "float" : "double", (unsigned)fw_vec_n_blobs);
    if (trk_config_check() != TRK_OK) {
        printf("trk-fw: libtrk was built with other capacities or real type\n");
        return 1;
    }
    int amp_bad = load_amp_tables();
    printf("amplitude tables linked: %u (%u rejected)\n", (unsigned)fw_amp_n_tables,
           (unsigned)(fw_amp_n_tables - n_amp));
    for (size_t i = 0; i < fw_vec_n_blobs; i++) run_blob(&fw_vec_blobs[i]);
    printf("%-20s %6s %6s %6s %12s %12s %10s %9s %9s   (%s build, on target)\n", "kind", "pass", "fail",
           "n/a", "max_abs_err", "max_rel_err", "tol_used", "ftol_abs", "ftol_rel",
           TRK_REAL_IS_FLOAT ? "float" : "double");
    for (size_t i = 0; i < n_stats; i++)
        printf("%-20s %6ld %6ld %6ld %12.3g %12.3g %10.3g %9.2g %9.2g\n", stats[i].name, stats[i].passed,
               stats[i].failed, stats[i].not_applicable, stats[i].max_abs, stats[i].max_rel,
               stats[i].max_use, stats[i].tol_abs, stats[i].tol_rel);
    if (n_amp) printf("amplitude tables: %ld vector points beyond a table's range (a > a_max or x > x_max) not compared; "
                      "model-k cases %s\n", amp_beyond,
                      FW_AMP_K_DIRECT ? "also run by the kinds (direct evaluation)" : "checked by table lookup only");
    if (skipped) printf("skipped on target: %ld cases of kinds [%s] (see mk/qemu.mk)\n", skipped, FW_SKIP_KINDS);
    if (not_applicable)
        printf("vectors: %ld cases not applicable to this build (float resolution or capacity)\n",
               not_applicable);
    printf("vectors: %ld passed, %ld failed, %ld unimplemented\n", passed, failed, unimpl);
    int stack_bad = stack_scenario();
    return (failed > 0 || passed == 0 || stack_bad || amp_bad) ? 1 : 0;
}
