/* amp.c - `trk-tablegen amp`: amplitude model tables (trk/amplitude.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "table_writer.h"
#include "tablegen.h"

static void amp_usage(FILE *fp)
{
    fprintf(fp,
        "usage: trk-tablegen amp --clutter rayleigh|k --nu NU --snr-db S --pfa P\n"
        "                        [--grid geometric|uniform] [--size N] [--llr-size N]\n"
        "                        [--clutter-power P] [--x-max X] [--real float|double]\n"
        "                        [--no-measure] -o FILE [--format bin|c] [--name IDENT]\n"
        "\n"
        "Amplitude table for one (clutter model, nu, SNR, P_FA): threshold t (S0(t) = P_FA),\n"
        "P_D = S1(t), ln l^a over [t, a_max] and the inverse truncated survival a(x),\n"
        "x = -ln(S(a)/S(t)) in [0, x_max], of clutter and of target (Brekke eqs 19-20, 41-47;\n"
        "CONVENTIONS \"Amplitude models\"). Amplitudes in units of sqrt(clutter power).\n"
        "\n"
        "  --clutter rayleigh|k  clutter law: Rayleigh, or K-distributed with shape --nu\n"
        "  --nu NU               K shape, (0, 1e6] (required for k; ignored for rayleigh)\n"
        "  --snr-db S            Swerling I target mean power over clutter power, dB\n"
        "  --pfa P               false-alarm probability of the threshold, (0, 1)\n"
        "  --grid uniform        a(x) tables uniform in x, cubic Hermite of a^2 (default)\n"
        "  --grid geometric      Brekke eqs 43-45: amplitudes t + A (B^p-1)/(B-1), A = 0.25,\n"
        "                        last 100, piecewise linear (the paper's scheme, for comparison)\n"
        "  --size N              points of each a(x) table (default %u uniform, %u geometric)\n"
        "  --llr-size N          points of the ln l^a table, uniform in ln a (default %u)\n"
        "  --clutter-power P     mean clutter power E[a^2] (default 1)\n"
        "  --x-max X             range of x (default %g; a = a(x_max) is the ln l^a range end)\n"
        "  --real float|double   real width of the table (default: this build's, %s)\n"
        "  --no-measure          do not measure the table's errors against direct evaluation\n"
        "                        (measured by default when the width is this build's, and\n"
        "                        stored as parameters err_log_lr and err_inv_sf)\n"
        "  -o FILE               output file\n"
        "  --format bin|c        binary table (default), or C source: a const union\n"
        "                        {bytes, double} named IDENT for in-place use from ROM\n"
        "  --name IDENT          C identifier of --format c (default trk_amp_table)\n",
        AMP_TABLE_DEFAULT_SIZE, AMP_TABLE_DEFAULT_GEOM_SIZE, AMP_TABLE_DEFAULT_LLR_SIZE, AMP_TABLE_X_MAX,
        TRK_REAL_IS_FLOAT ? "float" : "double");
}

TABLEGEN_CMD(amp, "amplitude model table: --clutter rayleigh|k --nu --snr-db --pfa -o FILE")
{
    struct amp_table_opts o;
    memset(&o, 0, sizeof o);
    o.measure = 1;
    const char *out = NULL, *format = "bin", *name = "trk_amp_table";
    int have_nu = 0, have_snr = 0, have_pfa = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        unsigned long u;
        int bad = 0;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            amp_usage(stdout);
            return 0;
        } else if (strcmp(a, "--no-measure") == 0) {
            o.measure = 0;
            continue;
        }
        static const char *const with_value[] = {"--clutter", "--nu", "--snr-db", "--pfa", "--grid",
                                                 "--size", "--llr-size", "--clutter-power", "--x-max",
                                                 "--real", "-o", "--output", "--format", "--name", NULL};
        int known = 0;
        for (int k = 0; with_value[k]; k++) known |= strcmp(a, with_value[k]) == 0;
        if (!known) {
            fprintf(stderr, "trk-tablegen amp: unknown option '%s' (see --help)\n", a);
            return 2;
        }
        if (!v) {
            fprintf(stderr, "trk-tablegen amp: %s needs a value\n", a);
            return 2;
        }
        i++;
        if (strcmp(a, "--clutter") == 0) {
            if (strcmp(v, "rayleigh") == 0) o.model = TRK_AMP_RAYLEIGH;
            else if (strcmp(v, "k") == 0) o.model = TRK_AMP_K;
            else bad = 1;
        } else if (strcmp(a, "--nu") == 0) {
            bad = tablegen_parse_real(v, &o.nu);
            have_nu = 1;
        } else if (strcmp(a, "--snr-db") == 0) {
            bad = tablegen_parse_real(v, &o.snr_db);
            have_snr = 1;
        } else if (strcmp(a, "--pfa") == 0) {
            bad = tablegen_parse_real(v, &o.pfa);
            have_pfa = 1;
        } else if (strcmp(a, "--grid") == 0) {
            if (strcmp(v, "uniform") == 0) o.grid = TRK_AMP_GRID_UNIFORM;
            else if (strcmp(v, "geometric") == 0) o.grid = TRK_AMP_GRID_GEOMETRIC;
            else bad = 1;
        } else if (strcmp(a, "--size") == 0) {
            bad = tablegen_parse_uint(v, 1u << 20, &u) || u < 4;
            o.size = (uint32_t)u;
        } else if (strcmp(a, "--llr-size") == 0) {
            bad = tablegen_parse_uint(v, 1u << 20, &u) || u < 4;
            o.llr_size = (uint32_t)u;
        } else if (strcmp(a, "--clutter-power") == 0) {
            bad = tablegen_parse_real(v, &o.clutter_power) || !(o.clutter_power > 0);
        } else if (strcmp(a, "--x-max") == 0) {
            bad = tablegen_parse_real(v, &o.x_max) || !(o.x_max > 0);
        } else if (strcmp(a, "--real") == 0) {
            if (strcmp(v, "float") == 0) o.real_size = 4;
            else if (strcmp(v, "double") == 0) o.real_size = 8;
            else bad = 1;
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            out = v;
        } else if (strcmp(a, "--format") == 0) {
            format = v;
            bad = strcmp(v, "bin") != 0 && strcmp(v, "c") != 0;
        } else if (strcmp(a, "--name") == 0) {
            name = v;
            bad = !tablegen_valid_ident(v);
        } else {
            fprintf(stderr, "trk-tablegen amp: unknown option '%s' (see --help)\n", a);
            return 2;
        }
        if (bad) {
            fprintf(stderr, "trk-tablegen amp: bad value '%s' for %s\n", v, a);
            return 2;
        }
    }
    if (!o.model || !have_snr || !have_pfa || !out || (o.model == TRK_AMP_K && !have_nu)) {
        fprintf(stderr, "trk-tablegen amp: --clutter, --snr-db, --pfa, -o (and --nu for k) are required\n");
        amp_usage(stderr);
        return 2;
    }
    if (o.model == TRK_AMP_RAYLEIGH) o.nu = 0;
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
    int rc = strcmp(format, "c") == 0 ? tablew_write_c(out, name, r.bytes, r.len, desc)
                                      : tablew_write_bin(out, r.bytes, r.len);
    if (rc != 0) {
        perror(out);
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
