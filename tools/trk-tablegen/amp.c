/* amp.c - `trk-tablegen amp`: amplitude model tables (trk/amplitude.h). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "cli.h"
#include "par.h"
#include "table_writer.h"
#include "tablegen.h"

TABLEGEN_CMD(amp, "amplitude model table: --clutter-model rayleigh|k --k-shape --snr-db --pfa --out FILE")
{
    struct amp_table_opts o;
    memset(&o, 0, sizeof o);
    const char *out = NULL, *name = "trk_amp_table";
    int model = 0, grid = 0, real_size = 0, format = 0, no_measure = 0;
    long size = 0, llr_size = 0;
    const char *ckpt = NULL;
    double ckpt_s = 5;
    struct par *par = tablegen_par();
    double nu = NAN, snr_db = 0, pfa = 0, clutter_power = 0, x_max = 0;
    static const int models[] = {TRK_AMP_RAYLEIGH, TRK_AMP_K};
    static const int grids[] = {TRK_AMP_GRID_UNIFORM, TRK_AMP_GRID_GEOMETRIC};
    static const int reals[] = {4, 8};
    char h_size[160], h_llr[96], h_xmax[128], h_real[96];
    snprintf(h_size, sizeof h_size, "points of each a(x) table (default %u uniform, %u geometric)",
             AMP_TABLE_DEFAULT_SIZE, AMP_TABLE_DEFAULT_GEOM_SIZE);
    snprintf(h_llr, sizeof h_llr, "points of the ln l^a table, uniform in ln a (default %u)",
             AMP_TABLE_DEFAULT_LLR_SIZE);
    snprintf(h_xmax, sizeof h_xmax, "range of x (default %g; a = a(x_max) is the ln l^a range end)",
             AMP_TABLE_X_MAX);
    snprintf(h_real, sizeof h_real, "real width of the table (default: this build's, %s)",
             TRK_REAL_IS_FLOAT ? "float" : "double");
    const struct cli_opt opts[] = {
        {.name = "--clutter-model", .type = CLI_CHOICE, .dst = &model, .arg = "rayleigh|k", .values = models,
         .flags = CLI_REQUIRED, .help = "clutter law: Rayleigh, or K-distributed with shape --k-shape"},
        CLI_OPT_DOUBLE("--k-shape", &nu, "NU", NULL, 0, 0, 0, "K shape, (0, 1e6] (required for k; ignored for rayleigh)"),
        {.name = "--snr-db", .type = CLI_DOUBLE, .dst = &snr_db, .arg = "S", .flags = CLI_REQUIRED,
         .help = "Swerling I target mean power over clutter power, dB"},
        {.name = "--pfa", .type = CLI_DOUBLE, .dst = &pfa, .arg = "P", .flags = CLI_REQUIRED,
         .help = "false-alarm probability of the threshold, (0, 1)"},
        CLI_OPT_CHOICE("--grid", &grid, "uniform|geometric", grids, NULL,
                       "uniform: a(x) tables uniform in x, cubic Hermite of a^2 (default);\n"
                       "geometric: Brekke eqs 43-45, amplitudes t + A (B^p-1)/(B-1), A = 0.25,\n"
                       "last 100, piecewise linear (the paper's scheme, for comparison)"),
        CLI_OPT_LONG("--size", &size, "N", NULL, CLI_IN, 4, 1u << 20, h_size),
        CLI_OPT_LONG("--llr-size", &llr_size, "N", NULL, CLI_IN, 4, 1u << 20, h_llr),
        CLI_OPT_DOUBLE("--clutter-power", &clutter_power, "P", NULL, CLI_GT, 0, 0,
                       "mean clutter power E[a^2] (default 1)"),
        CLI_OPT_DOUBLE("--x-max", &x_max, "X", NULL, CLI_GT, 0, 0, h_xmax),
        CLI_OPT_CHOICE("--real", &real_size, "float|double", reals, NULL, h_real),
        CLI_OPT_FLAG("--no-measure", &no_measure,
                     "do not measure the table's errors against direct evaluation\n"
                     "(measured by default when the width is this build's, and\n"
                     "stored as parameters err_log_lr and err_inv_sf)"),
        CLI_OPT_REQUIRED_STRING("--out", &out, "FILE", "output file (the table)"),
        CLI_OPT_CHOICE("--format", &format, "bin|c", NULL, "bin",
                       "binary table, or C source: a const union\n"
                       "{bytes, double} named IDENT for in-place use from ROM"),
        CLI_OPT_CUSTOM("--name", &name, tablegen_parse_ident, "IDENT", "trk_amp_table",
                       "C identifier of --format c"),
#ifdef TRK_TOOL_MPI
        CLI_OPT_STRING("--checkpoint", &ckpt, "FILE", NULL,
                       "trk-tablegen-mpi: write the finished table nodes to FILE; a run\n"
                       "with the same arguments resumes from it (removed once written)"),
        CLI_OPT_DOUBLE("--checkpoint-interval", &ckpt_s, "S", "5", CLI_GE, 0, 1e6,
                       PAR_CHECKPOINT_INTERVAL_HELP),
#endif
        CLI_OPT_ALIAS("--clutter", "--clutter-model"),
        CLI_OPT_ALIAS("--nu", "--k-shape"),
        CLI_OPT_ALIAS("-o", "--out"),
        CLI_OPT_ALIAS("--output", "--out"),
        CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-tablegen amp",
        .usage = "--clutter-model rayleigh|k [--k-shape NU] --snr-db S --pfa P --out FILE [options]",
        .about = "Amplitude table for one (clutter model, nu, SNR, P_FA): threshold t (S0(t) = P_FA),\n"
                 "P_D = S1(t), ln l^a over [t, a_max] and the inverse truncated survival a(x),\n"
                 "x = -ln(S(a)/S(t)) in [0, x_max], of clutter and of target (Brekke eqs 19-20, 41-47;\n"
                 "docs/conventions.md \"Amplitude models\"). Amplitudes in units of sqrt(clutter power).",
        .opts = opts};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN) return parsed;
    if (model == TRK_AMP_K && isnan(nu)) {
        fprintf(stderr, "trk-tablegen amp: --clutter-model k needs --k-shape (see --help)\n");
        return 2;
    }
    o.model = model;
    o.nu = isnan(nu) ? 0 : nu;
    o.snr_db = snr_db;
    o.pfa = pfa;
    o.grid = grid;
    o.size = (uint32_t)size;
    o.llr_size = (uint32_t)llr_size;
    o.clutter_power = clutter_power;
    o.x_max = x_max;
    o.real_size = (uint32_t)real_size;
    o.measure = !no_measure;
    if (o.model == TRK_AMP_RAYLEIGH) o.nu = 0;
    /* the table's nodes are work units of tools/par: this process's threads,
     * or the ranks of trk-tablegen-mpi */
    const struct amp_table_exec exec = {par_for_each, par};
    o.exec = &exec;
    const int crc = tablegen_checkpoint("amp", ckpt, ckpt_s, argc, argv);
    if (crc) return crc;
    struct amp_table_result r;
    char err[256];
    if (amp_table_build(&o, &r, err, sizeof err) != 0) {
        fprintf(stderr, "trk-tablegen amp: %s\n", err);
        return 1;
    }
    char desc[256];
    snprintf(desc, sizeof desc, "amp table: %s clutter%s%.6g, SNR %.6g dB, P_FA %.6g, %s grid, %zu-byte reals",
             o.model == TRK_AMP_K ? "K" : "Rayleigh", o.model == TRK_AMP_K ? " nu " : "",
             o.model == TRK_AMP_K ? o.nu : 0.0, o.snr_db, o.pfa,
             o.grid == TRK_AMP_GRID_GEOMETRIC ? "geometric" : "uniform",
             (size_t)(o.real_size ? o.real_size : sizeof(trk_real)));
    if (o.model != TRK_AMP_K) {
        /* no " nu 0" in the description */
        snprintf(desc, sizeof desc, "amp table: Rayleigh clutter, SNR %.6g dB, P_FA %.6g, %s grid, %zu-byte reals",
                 o.snr_db, o.pfa, o.grid == TRK_AMP_GRID_GEOMETRIC ? "geometric" : "uniform",
                 (size_t)(o.real_size ? o.real_size : sizeof(trk_real)));
    }
    /* written by rank 0 only, atomically (fileio.h) */
    int rc = !par_is_root(par) ? 0
             : format == 1     ? tablew_write_c(out, name, r.bytes, r.len, desc)
                               : tablew_write_bin(out, r.bytes, r.len);
    if (rc != 0) {
        fprintf(stderr, "trk-tablegen amp: cannot write %s: %s\n", out, strerror(errno));
        free(r.bytes);
        return 1;
    }
    printf("%s: %s\n  %zu bytes, threshold %.10g, pd %.10g, ln l^a table to a_max %.6g", out, desc, r.len,
           r.threshold, r.pd, r.a_max);
    if (o.model == TRK_AMP_RAYLEIGH)
        printf("\n  (the library evaluates a Rayleigh table's model by its closed forms)");
    else if (r.measured)
        printf("\n  measured: max |ln l^a error| %.3g on [t, a_max], max relative a(x) error %.3g on [0, x_max]",
               r.err_log_lr, r.err_inv_sf);
    printf("\n");
    free(r.bytes);
    return 0;
}
