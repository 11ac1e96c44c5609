/* q2_cmd.c - `trk-tablegen q2`: q2 tables by importance sampling (trk/q2.h
 * "Q2 TABLE"; tools/gen/q2_table.h, q2_is.h). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "par.h"
#include "progress.h"
#include "q2_amp.h"
#include "q2_is.h"
#include "q2_table.h"
#include "table_writer.h"
#include "tablegen.h"
#include "trk/q2.h"

/* Defaults (q2_table.h; docs/library.md "Performance prediction": chosen by the
 * measured interpolation error, `--measure-interp`). */
#define DEF_PD Q2_TABLE_DEFAULT_PD
#define DEF_SNR Q2_TABLE_DEFAULT_SNR_DB
#define DEF_PFA Q2_TABLE_DEFAULT_PFA
#define DEF_LV_PDAF Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF
#define DEF_LV_PDAFAI Q2_TABLE_DEFAULT_LAMBDA_VG_PDAFAI
#define DEF_SAMPLES ((unsigned long long)Q2_TABLE_DEFAULT_SAMPLES)
#define DEF_TARGET_SE Q2_TABLE_DEFAULT_TARGET_SE
#define MAX_LIST Q2_TABLE_MAX_NODES

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

TABLEGEN_CMD(q2, "q2 table by importance sampling: --detector pdaf|pdafai [grid] --out FILE (OpenMP)")
{
    static double pd_v[MAX_LIST], snr_v[MAX_LIST];
    struct q2_table_spec s;
    struct q2_table_run run;
    memset(&s, 0, sizeof s);
    memset(&run, 0, sizeof run);
    double gate_prob = NAN, gate_gamma = NAN, nu = NAN, target_se = DEF_TARGET_SE, tail_mass = 0;
    const char *out = NULL, *name = "trk_q2_table";
    const char *pd_s = DEF_PD, *snr_s = DEF_SNR, *pfa_s = DEF_PFA, *lv_s = NULL;
    int detector = 0, amp_model = 0, cubic = 1, real_size = 0, format = 0, quiet = 0, amp_measure = 0,
        measure_interp = 0;
    long nz = 2, samples = (long)DEF_SAMPLES, seed = 1, threads = 0, amp_size = 0;
    const char *ckpt = NULL;
    double ckpt_s = 5;
    struct par *par = tablegen_par();
    static const int detectors[] = {TRK_Q2_PDAF, TRK_Q2_PDAFAI};
    static const int models[] = {TRK_AMP_RAYLEIGH, TRK_AMP_K};
    static const int interps[] = {1, 0};
    static const int reals[] = {4, 8};
    char h_pd[160], h_snr[160], h_pfa[160], h_lv[160], h_samples[200], h_se[160], h_amp[120], h_real[96];
    snprintf(h_pd, sizeof h_pd, "pdaf: pd nodes in (0, 1] (default %s)", DEF_PD);
    snprintf(h_snr, sizeof h_snr, "pdafai: target SNR nodes, dB, in [-30, 60] (default %s)", DEF_SNR);
    snprintf(h_pfa, sizeof h_pfa, "pdafai: false-alarm probabilities in (0, 1) (default %s)", DEF_PFA);
    snprintf(h_lv, sizeof h_lv, "lambda_vg nodes in (0, 1000] (default pdaf %s,\npdafai %s)", DEF_LV_PDAF,
             DEF_LV_PDAFAI);
    snprintf(h_samples, sizeof h_samples,
             "scenes per clutter-count stratum where a cell's variance comes\n"
             "from (Neyman allocation; default %llu; >= 2)",
             (unsigned long long)DEF_SAMPLES);
    snprintf(h_se, sizeof h_se,
             "stop a cell once its standard error <= S, in [0, 1); 0 runs all\nsamples (default %g)",
             DEF_TARGET_SE);
    snprintf(h_amp, sizeof h_amp, "points per curve of the in-memory K amplitude tables (default %u)",
             Q2_AMP_TABLE_SIZE);
    snprintf(h_real, sizeof h_real, "real width of the table (default: this build's, %s)",
             TRK_REAL_IS_FLOAT ? "float" : "double");
    const struct cli_opt opts[] = {
        CLI_OPT_HEADING("Model:"),
        {.name = "--detector", .type = CLI_CHOICE, .dst = &detector, .arg = "pdaf|pdafai", .values = detectors,
         .flags = CLI_REQUIRED, .help = "the filter"},
        CLI_OPT_LONG("--nz", &nz, "N", "2", CLI_IN, 1, 3, "measurement dimension"),
        CLI_OPT_DOUBLE("--gate-prob", &gate_prob, "P", NULL, CLI_OPEN, 0, 1,
                       "gate probability P_G in (0, 1) (default 0.99), or"),
        CLI_OPT_DOUBLE("--gate-gamma", &gate_gamma, "G", NULL, CLI_GT | CLI_LE, 0, 1000,
                       "the gate threshold on d2 itself, (0, 1000] (e.g. 36: Brekke g = 6)"),
        CLI_OPT_CHOICE("--clutter-model", &amp_model, "rayleigh|k", models, NULL,
                       "pdafai: clutter amplitude model (required)"),
        CLI_OPT_DOUBLE("--k-shape", &nu, "NU", NULL, CLI_GT | CLI_LE, 0, 1e6,
                       "pdafai, k: K shape in (0, 1e6] (required for k)"),
        CLI_OPT_HEADING("Grid (LIST: comma-separated values and ranges A:B:STEP, strictly increasing;\n"
                        "      LOG: A:B:N, N nodes equally spaced in ln x from A to B):"),
        CLI_OPT_STRING("--pd", &pd_s, "LIST", NULL, h_pd),
        CLI_OPT_STRING("--snr-db", &snr_s, "LIST", NULL, h_snr),
        CLI_OPT_STRING("--pfa", &pfa_s, "LOG", NULL, h_pfa),
        CLI_OPT_STRING("--lambda-vg", &lv_s, "LOG", NULL, h_lv),
        CLI_OPT_CHOICE("--interp", &cubic, "cubic|linear", interps, "cubic",
                       "interpolation rule stored in the table"),
        CLI_OPT_HEADING("Sampling:"),
        CLI_OPT_LONG("--samples", &samples, "N", NULL, CLI_IN, 2, 4294967295.0, h_samples),
        CLI_OPT_DOUBLE("--target-se", &target_se, "S", NULL, CLI_GE | CLI_LT, 0, 1, h_se),
        CLI_OPT_LONG("--seed", &seed, "N", "1", CLI_IN, 0, 4294967295.0,
                     "random seed. The file is bit-identical for any\n"
                     "--threads: a counter-based generator keyed by (seed, stratum,\n"
                     "sample), work merged in a fixed order"),
        CLI_OPT_LONG("--threads", &threads, "N", NULL, CLI_IN, 1, 1024, "OpenMP threads (default: all cores)"),
        CLI_OPT_DOUBLE("--tail-mass", &tail_mass, "M", NULL, CLI_GT | CLI_LE, 0, 0.01,
                       "Poisson mass of the clutter count left out per cell, (0, 0.01]\n"
                       "(default 1e-12: the bound on that truncation's bias)"),
        CLI_OPT_LONG("--amp-size", &amp_size, "N", NULL, CLI_IN, 4, 1u << 20, h_amp),
        CLI_OPT_FLAG("--amp-measure", &amp_measure,
                     "measure every K amplitude table against the direct K model and\n"
                     "store the largest errors (amp_err_log_lr, amp_err_inv_sf)"),
        CLI_OPT_FLAG("--measure-interp", &measure_interp,
                     "also estimate q2 at the centre of every grid cell (same random\n"
                     "numbers) and report/store the interpolation error of the table\n"
                     "(interp_err_max, interp_err_rms); pdafai: about twice the time"),
        CLI_OPT_HEADING("Output:"),
        CLI_OPT_REQUIRED_STRING("--out", &out, "FILE", "output file (the table)"),
        CLI_OPT_CHOICE("--real", &real_size, "float|double", reals, NULL, h_real),
        CLI_OPT_CHOICE("--format", &format, "bin|c", NULL, "bin",
                       "binary table, or C source: a const union {bytes,\n"
                       "double} named IDENT for in-place use from ROM"),
        CLI_OPT_CUSTOM("--name", &name, tablegen_parse_ident, "IDENT", "trk_q2_table",
                       "C identifier of --format c"),
        CLI_OPT_FLAG("--quiet", &quiet, "no progress bar on stderr"),
#ifdef TRK_TOOL_MPI
        CLI_OPT_HEADING("Checkpoint (trk-tablegen-mpi):"),
        CLI_OPT_STRING("--checkpoint", &ckpt, "FILE", NULL,
                       "write the finished work units to FILE as they finish; a run\n"
                       "with the same arguments resumes from it (the same bytes); removed\n"
                       "once the table is written"),
        CLI_OPT_DOUBLE("--checkpoint-interval", &ckpt_s, "S", "5", CLI_GE, 0, 1e6,
                       PAR_CHECKPOINT_INTERVAL_HELP),
#endif
        CLI_OPT_ALIAS("--model", "--clutter-model"),
        CLI_OPT_ALIAS("--nu", "--k-shape"),
        CLI_OPT_ALIAS("-o", "--out"),
        CLI_OPT_ALIAS("--output", "--out"),
        CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-tablegen q2",
        .usage = "--detector pdaf|pdafai --out FILE [options]",
        .about = "\n"
                 "q2, the information-reduction factor of the PDAF / PDAFAI (docs/conventions.md\n"
                 "\"q2, MRE and CRLB\"; Brekke eqs 28-30, 38), by importance sampling over a grid,\n"
                 "written with its Monte Carlo standard error per cell as a q2 table (trk/q2.h\n"
                 "\"Q2 TABLE\": versioned, CRC-checked, used in place by trk_q2_lookup_init_table).\n"
                 "  pdaf    2-D table over (pd, lambda_vg) for one measurement dimension and gate\n"
                 "  pdafai  3-D table over (snr_db, pfa, lambda_vg) for one clutter model (Rayleigh, or\n"
                 "          K with shape nu); pd = S1(t) follows from the ROC (library amplitude module)\n"
                 "lambda_vg = lambda V_G is the expected number of clutter points in the gate.\n",
        .opts = opts,
        .after = "\n"
                 "Progress on stderr: lines of cells done, sampled points per second, ETA (an upper bound:\n"
                 "--target-se stops cells early). Exit status 0 success, 1 computation failed, 2 bad\n"
                 "usage or input."};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN) return parsed;
    s.detector = detector;
    s.nz = (int)nz;
    s.amp_model = amp_model;
    s.nu = isnan(nu) ? 0 : nu;
    s.cubic = cubic;
    s.amp_size = (unsigned)amp_size;
    s.amp_measure = amp_measure;
    s.measure_interp = measure_interp;
    s.real_size = (uint32_t)real_size;
    run.samples = (uint64_t)samples;
    run.target_se = target_se;
    run.seed = (uint64_t)seed;
    run.threads = (int)threads;
    run.tail_mass = tail_mass;
    const int have_gp = !isnan(gate_prob), have_gg = !isnan(gate_gamma), have_nu = !isnan(nu);
    if (!have_gp) gate_prob = 0.99;
    const int ai = s.detector == TRK_Q2_PDAFAI;
    if (have_gp && have_gg) {
        fprintf(stderr, "trk-tablegen q2: give --gate-prob or --gate-gamma, not both\n");
        return 2;
    }
    if (ai && !s.amp_model) {
        fprintf(stderr, "trk-tablegen q2: --detector pdafai needs --clutter-model rayleigh|k\n");
        return 2;
    }
    if (ai && s.amp_model == TRK_AMP_K && !have_nu) {
        fprintf(stderr, "trk-tablegen q2: --clutter-model k needs --k-shape\n");
        return 2;
    }
    if (!ai && (s.amp_model || have_nu)) {
        fprintf(stderr, "trk-tablegen q2: --clutter-model and --k-shape are for --detector pdafai\n");
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

    const int crc = tablegen_checkpoint("q2", ckpt, ckpt_s, argc, argv);
    if (crc) return crc;
    run.par = par;
    struct prog pc;
    memset(&pc, 0, sizeof pc);
    pc.quiet = quiet || !par_is_root(par); /* rank 0 reports for all ranks */
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
    /* the table: written by rank 0 only, atomically (fileio.h) */
    int rc = !par_is_root(par) ? 0
             : format == 1     ? tablew_write_c(out, name, r.bytes, r.len, desc)
                               : tablew_write_bin(out, r.bytes, r.len);
    if (rc != 0) {
        fprintf(stderr, "trk-tablegen q2: cannot write %s: %s\n", out, strerror(errno));
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
