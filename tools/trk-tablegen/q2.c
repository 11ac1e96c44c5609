/* q2.c - `trk-tablegen q2`: q2 tables by importance sampling (trk/q2.h
 * "Q2 TABLE"; tools/gen/q2_table.h, q2_is.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "progress.h"
#include "q2_amp.h"
#include "q2_is.h"
#include "q2_table.h"
#include "table_writer.h"
#include "tablegen.h"
#include "trk/q2.h"

/* Defaults (q2_table.h; README "Performance prediction": chosen by the
 * measured interpolation error, `--measure-interp`). */
#define DEF_PD Q2_TABLE_DEFAULT_PD
#define DEF_SNR Q2_TABLE_DEFAULT_SNR_DB
#define DEF_PFA Q2_TABLE_DEFAULT_PFA
#define DEF_LV_PDAF Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF
#define DEF_LV_PDAFAI Q2_TABLE_DEFAULT_LAMBDA_VG_PDAFAI
#define DEF_SAMPLES ((unsigned long long)Q2_TABLE_DEFAULT_SAMPLES)
#define DEF_TARGET_SE Q2_TABLE_DEFAULT_TARGET_SE
#define MAX_LIST Q2_TABLE_MAX_NODES

static void q2_usage(FILE *fp)
{
    fprintf(fp,
        "usage: trk-tablegen q2 --detector pdaf|pdafai -o FILE [options]\n"
        "\n"
        "q2, the information-reduction factor of the PDAF / PDAFAI (CONVENTIONS \"q2, MRE and\n"
        "CRLB\"; Brekke eqs 28-30, 38), by importance sampling over a grid, written with its\n"
        "Monte Carlo standard error per cell as a q2 table (trk/q2.h \"Q2 TABLE\": versioned,\n"
        "CRC-checked, used in place by trk_q2_lookup_init_table).\n"
        "  pdaf    2-D table over (pd, lambda_vg) for one measurement dimension and gate\n"
        "  pdafai  3-D table over (snr_db, pfa, lambda_vg) for one clutter model (Rayleigh, or\n"
        "          K with shape nu); pd = S1(t) follows from the ROC (library amplitude module)\n"
        "lambda_vg = lambda V_G is the expected number of clutter points in the gate.\n"
        "\n"
        "Model:\n"
        "  --detector pdaf|pdafai  (required)\n"
        "  --nz N                measurement dimension 1..3 (default 2)\n"
        "  --gate-prob P         gate probability P_G in (0, 1) (default 0.99), or\n"
        "  --gate-gamma G        the gate threshold on d2 itself, (0, 1000] (e.g. 36: Brekke g = 6)\n"
        "  --model rayleigh|k    pdafai: clutter amplitude model (required)\n"
        "  --nu NU               pdafai, k: K shape in (0, 1e6] (required for k)\n"
        "Grid (LIST: comma-separated values and ranges A:B:STEP, strictly increasing;\n"
        "      LOG: A:B:N, N nodes equally spaced in ln x from A to B):\n"
        "  --pd LIST             pdaf: pd nodes in (0, 1] (default %s)\n"
        "  --snr-db LIST         pdafai: target SNR nodes, dB, in [-30, 60] (default %s)\n"
        "  --pfa LOG             pdafai: false-alarm probabilities in (0, 1) (default %s)\n"
        "  --lambda-vg LOG       lambda_vg nodes in (0, 1000] (default pdaf %s, pdafai %s)\n"
        "  --interp cubic|linear interpolation rule stored in the table (default cubic)\n"
        "Sampling:\n"
        "  --samples N           scenes per clutter-count stratum where a cell's variance comes\n"
        "                        from (Neyman allocation; default %llu; >= 2)\n"
        "  --target-se S         stop a cell once its standard error <= S, in [0, 1); 0 runs all\n"
        "                        samples (default %g)\n"
        "  --seed N              random seed (default 1). The file is bit-identical for any\n"
        "                        --threads: a counter-based generator keyed by (seed, stratum,\n"
        "                        sample), work merged in a fixed order\n"
        "  --threads N           OpenMP threads (default: all cores)\n"
        "  --tail-mass M         Poisson mass of the clutter count left out per cell, (0, 0.01]\n"
        "                        (default 1e-12: the bound on that truncation's bias)\n"
        "  --amp-size N          points per curve of the in-memory K amplitude tables (default %u)\n"
        "  --amp-measure         measure every K amplitude table against the direct K model and\n"
        "                        store the largest errors (amp_err_log_lr, amp_err_inv_sf)\n"
        "  --measure-interp      also estimate q2 at the centre of every grid cell (same random\n"
        "                        numbers) and report/store the interpolation error of the table\n"
        "                        (interp_err_max, interp_err_rms); pdafai: about twice the time\n"
        "Output:\n"
        "  -o FILE               output file (required)\n"
        "  --real float|double   real width of the table (default: this build's, %s)\n"
        "  --format bin|c        binary table (default), or C source: a const union {bytes,\n"
        "                        double} named IDENT for in-place use from ROM\n"
        "  --name IDENT          C identifier of --format c (default trk_q2_table)\n"
        "  --quiet               no progress bar on stderr\n"
        "\n"
        "Progress on stderr: lines of cells done, sampled points per second, ETA (an upper bound:\n"
        "--target-se stops cells early). Exit status 0 success, 1 computation failed, 2 bad\n"
        "usage or input.\n",
        DEF_PD, DEF_SNR, DEF_PFA, DEF_LV_PDAF, DEF_LV_PDAFAI, (unsigned long long)DEF_SAMPLES, DEF_TARGET_SE,
        Q2_AMP_TABLE_SIZE, TRK_REAL_IS_FLOAT ? "float" : "double");
}

static int real_ok(const char *s, double *v) { return tablegen_parse_real(s, v) == 0 && isfinite(*v); }

struct prog {
    struct progress p;
    char label[96];
    uint64_t last;
    int started, quiet;
    size_t cells_per_line;
};

static void on_progress(void *ctx, const struct q2_is_progress *pr)
{
    struct prog *c = ctx;
    if (c->quiet) return;
    if (!c->started) {
        progress_start(&c->p, c->label, (long)pr->points_planned, 1);
        c->started = 1;
    }
    snprintf(c->label, sizeof c->label, "q2 cells %zu/%zu, points", pr->lines_done * c->cells_per_line,
             pr->n_lines * c->cells_per_line);
    c->p.total = (long)pr->points_planned; /* the plan follows the allocation and --target-se */
    progress_add(&c->p, (long)(pr->points_done - c->last));
    c->last = pr->points_done;
}

TABLEGEN_CMD(q2, "q2 table by importance sampling: --detector pdaf|pdafai [grid] -o FILE (OpenMP)")
{
    static double pd_v[MAX_LIST], snr_v[MAX_LIST];
    struct q2_table_spec s;
    struct q2_table_run run;
    memset(&s, 0, sizeof s);
    memset(&run, 0, sizeof run);
    s.nz = 2;
    s.cubic = 1;
    run.samples = DEF_SAMPLES;
    run.target_se = DEF_TARGET_SE;
    run.seed = 1;
    double gate_prob = 0.99, gate_gamma = 0;
    const char *out = NULL, *format = "bin", *name = "trk_q2_table";
    const char *pd_s = DEF_PD, *snr_s = DEF_SNR, *pfa_s = DEF_PFA, *lv_s = NULL;
    int have_gp = 0, have_gg = 0, have_nu = 0, quiet = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            q2_usage(stdout);
            return 0;
        }
        if (strcmp(a, "--quiet") == 0) {
            quiet = 1;
            continue;
        }
        if (strcmp(a, "--tail-mass") == 0 && i + 1 < argc) {
            if (!real_ok(argv[++i], &run.tail_mass) || !(run.tail_mass > 0 && run.tail_mass <= 1e-2)) {
                fprintf(stderr, "trk-tablegen q2: bad value '%s' for --tail-mass: must be in (0, 0.01]\n", argv[i]);
                return 2;
            }
            continue;
        }
        if (strcmp(a, "--amp-measure") == 0) {
            s.amp_measure = 1;
            continue;
        }
        if (strcmp(a, "--measure-interp") == 0) {
            s.measure_interp = 1;
            continue;
        }
        static const char *const with_value[] = {
            "--detector", "--nz", "--gate-prob", "--gate-gamma", "--model", "--nu", "--pd", "--snr-db", "--pfa",
            "--lambda-vg", "--interp", "--samples", "--target-se", "--seed", "--threads", "--amp-size", "-o",
            "--output", "--real", "--format", "--name", NULL};
        int known = 0;
        for (int k = 0; with_value[k]; k++) known |= strcmp(a, with_value[k]) == 0;
        if (!known) {
            fprintf(stderr, "trk-tablegen q2: unknown option '%s' (see --help)\n", a);
            return 2;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "trk-tablegen q2: %s needs a value\n", a);
            return 2;
        }
        const char *v = argv[++i];
        unsigned long u;
        const char *why = NULL;
        if (strcmp(a, "--detector") == 0) {
            if (strcmp(v, "pdaf") == 0) s.detector = TRK_Q2_PDAF;
            else if (strcmp(v, "pdafai") == 0) s.detector = TRK_Q2_PDAFAI;
            else why = "pdaf or pdafai";
        } else if (strcmp(a, "--nz") == 0) {
            if (tablegen_parse_uint(v, 3, &u) || u < 1) why = "1, 2 or 3";
            else s.nz = (int)u;
        } else if (strcmp(a, "--gate-prob") == 0) {
            if (!real_ok(v, &gate_prob) || !(gate_prob > 0 && gate_prob < 1)) why = "a probability in (0, 1)";
            have_gp = 1;
        } else if (strcmp(a, "--gate-gamma") == 0) {
            if (!real_ok(v, &gate_gamma) || !(gate_gamma > 0 && gate_gamma <= 1000)) why = "a number in (0, 1000]";
            have_gg = 1;
        } else if (strcmp(a, "--model") == 0) {
            if (!(s.amp_model = q2_amp_model_parse(v))) why = "rayleigh or k";
        } else if (strcmp(a, "--nu") == 0) {
            if (!real_ok(v, &s.nu) || !(s.nu > 0 && s.nu <= 1e6)) why = "a K shape in (0, 1e6]";
            have_nu = 1;
        } else if (strcmp(a, "--pd") == 0) {
            pd_s = v;
        } else if (strcmp(a, "--snr-db") == 0) {
            snr_s = v;
        } else if (strcmp(a, "--pfa") == 0) {
            pfa_s = v;
        } else if (strcmp(a, "--lambda-vg") == 0) {
            lv_s = v;
        } else if (strcmp(a, "--interp") == 0) {
            if (strcmp(v, "cubic") == 0) s.cubic = 1;
            else if (strcmp(v, "linear") == 0) s.cubic = 0;
            else why = "cubic or linear";
        } else if (strcmp(a, "--samples") == 0) {
            double d;
            if (!real_ok(v, &d) || !(d >= 2 && d <= 4294967295.0) || d != floor(d))
                why = "an integer in [2, 4294967295] (e.g. 1e6)";
            else run.samples = (uint64_t)d;
        } else if (strcmp(a, "--target-se") == 0) {
            if (!real_ok(v, &run.target_se) || !(run.target_se >= 0 && run.target_se < 1)) why = "a number in [0, 1)";
        } else if (strcmp(a, "--seed") == 0) {
            if (tablegen_parse_uint(v, 0xffffffffUL, &u)) why = "an integer in [0, 4294967295]";
            else run.seed = u;
        } else if (strcmp(a, "--threads") == 0) {
            if (tablegen_parse_uint(v, 1024, &u) || u < 1) why = "an integer in [1, 1024]";
            else run.threads = (int)u;
        } else if (strcmp(a, "--amp-size") == 0) {
            if (tablegen_parse_uint(v, 1u << 20, &u) || u < 4) why = "an integer in [4, 1048576]";
            else s.amp_size = (unsigned)u;
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            out = v;
        } else if (strcmp(a, "--real") == 0) {
            if (strcmp(v, "float") == 0) s.real_size = 4;
            else if (strcmp(v, "double") == 0) s.real_size = 8;
            else why = "float or double";
        } else if (strcmp(a, "--format") == 0) {
            format = v;
            if (strcmp(v, "bin") != 0 && strcmp(v, "c") != 0) why = "bin or c";
        } else if (strcmp(a, "--name") == 0) {
            name = v;
            if (!tablegen_valid_ident(v)) why = "a C identifier";
        }
        if (why) {
            fprintf(stderr, "trk-tablegen q2: bad value '%s' for %s: must be %s\n", v, a, why);
            return 2;
        }
    }
    if (!s.detector || !out) {
        fprintf(stderr, "trk-tablegen q2: --detector and -o are required (see --help)\n");
        return 2;
    }
    const int ai = s.detector == TRK_Q2_PDAFAI;
    if (have_gp && have_gg) {
        fprintf(stderr, "trk-tablegen q2: give --gate-prob or --gate-gamma, not both\n");
        return 2;
    }
    if (ai && !s.amp_model) {
        fprintf(stderr, "trk-tablegen q2: --detector pdafai needs --model rayleigh|k\n");
        return 2;
    }
    if (ai && s.amp_model == TRK_AMP_K && !have_nu) {
        fprintf(stderr, "trk-tablegen q2: --model k needs --nu\n");
        return 2;
    }
    if (!ai && (s.amp_model || have_nu)) {
        fprintf(stderr, "trk-tablegen q2: --model and --nu are for --detector pdafai\n");
        return 2;
    }
    if (s.amp_model == TRK_AMP_RAYLEIGH) s.nu = 0;
    if (have_gg) {
        s.gate_gamma = gate_gamma;
    } else if (q2_gate_gamma(s.nz, gate_prob, &s.gate_gamma)) {
        fprintf(stderr, "trk-tablegen q2: no gate threshold for P_G %g\n", gate_prob);
        return 2;
    }
    if (!lv_s) lv_s = ai ? DEF_LV_PDAFAI : DEF_LV_PDAF;
    if (q2_table_parse_log(lv_s, &s.lambda_vg)) {
        fprintf(stderr, "trk-tablegen q2: bad --lambda-vg '%s': must be A:B:N with 0 < A < B, N >= 2\n", lv_s);
        return 2;
    }
    if (ai) {
        int n = q2_table_parse_list(snr_s, snr_v, MAX_LIST);
        if (n < 2) {
            fprintf(stderr, "trk-tablegen q2: bad --snr-db '%s': needs >= 2 increasing values\n", snr_s);
            return 2;
        }
        q2_table_list_axis(snr_v, n, &s.snr_db);
        if (q2_table_parse_log(pfa_s, &s.pfa)) {
            fprintf(stderr, "trk-tablegen q2: bad --pfa '%s': must be A:B:N with 0 < A < B, N >= 2\n", pfa_s);
            return 2;
        }
    } else {
        int n = q2_table_parse_list(pd_s, pd_v, MAX_LIST);
        if (n < 2) {
            fprintf(stderr, "trk-tablegen q2: bad --pd '%s': needs >= 2 increasing values\n", pd_s);
            return 2;
        }
        q2_table_list_axis(pd_v, n, &s.pd);
    }

    struct prog pc;
    memset(&pc, 0, sizeof pc);
    pc.quiet = quiet;
    pc.cells_per_line = ai ? s.lambda_vg.n : s.pd.n * s.lambda_vg.n;
    snprintf(pc.label, sizeof pc.label, "q2 points");
    run.progress = on_progress;
    run.progress_ctx = &pc;
    struct q2_table_result r;
    char err[512];
    const double t0 = progress_now_s();
    const int brc = q2_table_build(&s, &run, &r, err, sizeof err);
    if (pc.started) progress_end(&pc.p);
    if (brc) {
        fprintf(stderr, "trk-tablegen q2: %s\n", err);
        /* parameters the sampler refuses are bad input; anything else a failure */
        return strstr(err, "axis") || strstr(err, "must be") ? 2 : 1;
    }
    const double wall = progress_now_s() - t0;
    char desc[256];
    if (ai)
        snprintf(desc, sizeof desc, "q2 table: PDAFAI, %s clutter%s%.6g, nz %d, gamma %.6g, %zu-byte reals",
                 s.amp_model == TRK_AMP_K ? "K" : "Rayleigh", s.amp_model == TRK_AMP_K ? " nu " : "",
                 s.amp_model == TRK_AMP_K ? s.nu : 0.0, s.nz, s.gate_gamma,
                 (size_t)(s.real_size ? s.real_size : sizeof(trk_real)));
    else
        snprintf(desc, sizeof desc, "q2 table: PDAF, nz %d, gamma %.6g (P_G %.10g), %zu-byte reals", s.nz,
                 s.gate_gamma, q2_gate_prob(s.nz, s.gate_gamma), (size_t)(s.real_size ? s.real_size : sizeof(trk_real)));
    if (ai && s.amp_model == TRK_AMP_RAYLEIGH) {
        /* no " nu 0" */
        snprintf(desc, sizeof desc, "q2 table: PDAFAI, Rayleigh clutter, nz %d, gamma %.6g, %zu-byte reals", s.nz,
                 s.gate_gamma, (size_t)(s.real_size ? s.real_size : sizeof(trk_real)));
    }
    int rc = strcmp(format, "c") == 0 ? tablew_write_c(out, name, r.bytes, r.len, desc)
                                      : tablew_write_bin(out, r.bytes, r.len);
    if (rc != 0) {
        perror(out);
        q2_table_result_free(&r);
        return 1;
    }
    const int th = q2_is_threads(run.threads);
    printf("%s: %s\n  %zu bytes, %zu cells (%zu lines), se max %.3g mean %.3g (target %g, samples %llu, seed "
           "%llu)\n  %llu scenes, %llu points in %.2f s (setup %.2f s, sampling %.2f s) on %d thread%s: %.3g "
           "points/s/thread\n",
           out, desc, r.len, r.n_cells, r.n_lines, r.max_se, r.mean_se, run.target_se,
           (unsigned long long)run.samples, (unsigned long long)run.seed, (unsigned long long)r.scenes,
           (unsigned long long)r.points, wall, r.setup_s, r.sample_s, th, th == 1 ? "" : "s",
           r.sample_s > 0 ? (double)r.points / r.sample_s / th : 0);
    if (r.amp_measured)
        printf("  K amplitude tables: max |ln l^a error| %.3g, max relative a(x) error %.3g\n", r.amp_err_log_lr,
               r.amp_err_inv_sf);
    if (r.interp_measured) {
        printf("  interpolation error (%s) at %zu cell centres: max %.3g, rms %.3g (median se of a direct value "
               "%.2g); max at ",
               s.cubic ? "cubic" : "linear", r.interp_n, r.interp_max, r.interp_rms, r.interp_se_median);
        if (ai)
            printf("snr_db %.4g, pfa %.4g, lambda_vg %.4g\n", r.interp_max_at[0], r.interp_max_at[1],
                   r.interp_max_at[2]);
        else
            printf("pd %.4g, lambda_vg %.4g\n", r.interp_max_at[0], r.interp_max_at[1]);
        printf("  at the %zu cell centres with se <= %g (little Monte Carlo noise): max %.3g\n", r.interp_n_quiet,
               Q2_TABLE_QUIET_SE, r.interp_max_quiet);
    }
    q2_table_result_free(&r);
    return 0;
}
