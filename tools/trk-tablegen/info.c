/* info.c - `trk-tablegen info FILE`: load a table through the library's own
 * loader (trk_table_check, then trk_table_parse and the kind's init when the
 * real width is this build's), print its header, parameters and sections.
 * A defect is reported on stdout with the rest and once more on stderr,
 * "trk-tablegen info: FILE: WHAT" (a library refusal in plain words with the
 * status's name). Exit status 0 when the table is sound, 1 on any defect or
 * an unreadable file, 2 on a usage error. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "errmsg.h"
#include "fileio.h"
#include "tablegen.h"
#include "trk/q2.h"
#include "trk/amplitude.h"
#include "trk/table.h"
#include "trk/table_file.h"

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint64_t rd64(const unsigned char *p) { return (uint64_t)rd32(p) | (uint64_t)rd32(p + 4) << 32; }

/* A real of width rs (the table's), as a double (host tool: either width). */
static double rd_real(const unsigned char *p, uint32_t rs)
{
    if (rs == 4) {
        uint32_t b = rd32(p);
        float f;
        memcpy(&f, &b, 4);
        return f;
    }
    uint64_t b = rd64(p);
    double d;
    memcpy(&d, &b, 8);
    return d;
}

static const char *kind_name(uint32_t k)
{
    switch (k) {
    case TRK_TABLE_KIND_AMP: return "amp";
    case TRK_TABLE_KIND_Q2_PDAF: return "q2_pdaf";
    case TRK_TABLE_KIND_Q2_PDAFAI: return "q2_pdafai";
    default: return "unknown";
    }
}

static const char *spacing_name(uint32_t s)
{
    static const char *const n[] = {"?", "linear", "log", "geometric", "explicit"};
    return s < sizeof n / sizeof n[0] ? n[s] : "?";
}

static const char *var_name(uint32_t v)
{
    static const char *const n[] = {"?", "x", "ln_amp", "amp", "snr_db", "pfa", "pd", "lambda_vg", "gate_prob"};
    return v < sizeof n / sizeof n[0] ? n[v] : "?";
}

static const char *interp_name(uint32_t v)
{
    static const char *const n[] = {"none", "linear", "hermite", "cubic"};
    return v < sizeof n / sizeof n[0] ? n[v] : "?";
}

static const char *section_name(uint32_t kind, uint32_t id)
{
    if (kind == TRK_TABLE_KIND_AMP) switch (id) {
        case TRK_AMP_SECTION_LOG_LR: return "log_lr";
        case TRK_AMP_SECTION_INV_SF_CLUTTER: return "inv_sf_clutter";
        case TRK_AMP_SECTION_INV_SF_TARGET: return "inv_sf_target";
        default: break;
        }
    if ((kind == TRK_TABLE_KIND_Q2_PDAF || kind == TRK_TABLE_KIND_Q2_PDAFAI) && id == TRK_Q2_SECTION_VALUES)
        return "values (q2, se)";
    return "";
}

static void print_table(const unsigned char *b, const struct trk_table_info *in)
{
    const uint32_t rs = in->real_size;
    printf("  format version %u, %zu bytes, CRC-32 0x%08x\n", TRK_TABLE_FORMAT_VERSION, in->size, in->crc);
    printf("  kind %s (%u), kind version %u, reals %u bytes (%s)\n", kind_name(in->kind), in->kind,
           in->kind_version, rs, rs == 4 ? "float" : "double");
    printf("  parameters (%u):\n", in->n_params);
    for (uint32_t k = 0; k < in->n_params; k++) {
        const unsigned char *p = b + TRK_TABLE_HEADER_SIZE + (size_t)k * TRK_TABLE_PARAM_SIZE;
        if (rd32(p + 32) == TRK_TABLE_PARAM_INT)
            printf("    %-20s %lld (int)\n", (const char *)p, (long long)(int64_t)rd64(p + 40));
        else
            printf("    %-20s %.17g\n", (const char *)p, rd_real(p + 40, rs));
    }
    printf("  sections (%u):\n", in->n_sections);
    const size_t desc0 = TRK_TABLE_HEADER_SIZE + (size_t)in->n_params * TRK_TABLE_PARAM_SIZE;
    for (uint32_t s = 0; s < in->n_sections; s++) {
        const unsigned char *d = b + desc0 + (size_t)s * TRK_TABLE_SECTION_SIZE;
        const uint32_t naxes = rd32(d + 4);
        printf("    id %u %s: %u value(s) per cell, interpolation %s, %u reals at offset %u\n", rd32(d),
               section_name(in->kind, rd32(d)), rd32(d + 8), interp_name(rd32(d + 12)), rd32(d + 20),
               rd32(d + 16));
        for (uint32_t a = 0; a < naxes; a++) {
            const unsigned char *ax = d + 32 + a * TRK_TABLE_AXIS_SIZE;
            printf("      axis %u: %s, %u points, %s from %.10g to %.10g", a, var_name(rd32(ax + 8)), rd32(ax),
                   spacing_name(rd32(ax + 4)), rd_real(ax + 16, rs), rd_real(ax + 24, rs));
            if (rd32(ax + 4) == TRK_TABLE_SPACING_GEOMETRIC) printf(", ratio %.10g", rd_real(ax + 32, rs));
            printf("\n");
        }
    }
}

/* A defect: "  DEFECT: what" on stdout, and what into why (the first one
 * only: the stderr line). Returns 1. */
static int defect(char *why, size_t n, const char *what)
{
    printf("  DEFECT: %s\n", what);
    if (!why[0]) snprintf(why, n, "%s", what);
    return 1;
}

/* A library refusal as a defect: "WORDS (NAME)", and on stdout the call
 * that refused. */
static int refused(char *why, size_t n, const char *call, trk_status st)
{
    defect(why, n, ERRMSG_STATUS(st));
    printf("    (refused by the library's %s)\n", call);
    return 1;
}

/* Kind-specific checks through the library (same real width only). */
static int check_kind(const unsigned char *b, size_t len, const struct trk_table_info *in, char *why, size_t wn)
{
    struct trk_table t;
    trk_status st = trk_table_parse(&t, b, len);
    if (st != TRK_OK) return refused(why, wn, "trk_table_parse", st);
    if (in->kind == TRK_TABLE_KIND_Q2_PDAF || in->kind == TRK_TABLE_KIND_Q2_PDAFAI) {
        const int det = in->kind == TRK_TABLE_KIND_Q2_PDAF ? TRK_Q2_PDAF : TRK_Q2_PDAFAI;
        int64_t nz = 0;
        if (trk_table_param_int(&t, "nz", &nz) != TRK_OK) nz = 0;
        struct trk_q2_lookup q;
        st = trk_q2_lookup_init_table(&q, &t, det, (int)nz);
        if (st != TRK_OK) return refused(why, wn, "trk_q2_lookup_init_table", st);
        /* the value at the first and last node, through the lookup */
        trk_real lo[3], hi[3], v_lo, v_hi;
        for (int a = 0; a < q.n_axes; a++) {
            const struct trk_q2_axis *ax = &q.grid.axis[a];
            trk_real u0 = ax->nodes ? ax->nodes[0] : ax->u_first;
            trk_real u1 = ax->nodes ? ax->nodes[ax->count - 1] : ax->u_last;
            lo[a] = ax->log_spacing ? trk_exp(u0) : u0;
            hi[a] = ax->log_spacing ? trk_exp(u1) : u1;
        }
        if (trk_q2_lookup_eval(&q, lo, &v_lo) != TRK_OK || trk_q2_lookup_eval(&q, hi, &v_hi) != TRK_OK)
            return defect(why, wn, "the q2 lookup does not evaluate at the grid's corners");
        printf("  q2 lookup (library): %s, nz %d, gamma %.10g (P_G %.10g)", det == TRK_Q2_PDAF ? "PDAF" : "PDAFAI",
               q.nz, (double)q.gate_gamma, (double)q.gate_prob);
        if (det == TRK_Q2_PDAFAI)
            printf(", %s clutter", q.amp_model == TRK_AMP_K ? "K" : "Rayleigh");
        if (det == TRK_Q2_PDAFAI && q.amp_model == TRK_AMP_K) printf(" nu %.6g", (double)q.nu);
        printf(", max se %.3g\n    q2 at the first corner %.6f, at the last corner %.6f\n", (double)q.max_se,
               (double)v_lo, (double)v_hi);
        return 0;
    }
    if (in->kind != TRK_TABLE_KIND_AMP) return 1; /* unknown kinds are refused by the caller */
    struct trk_amplitude m;
    st = trk_amplitude_init_table(&m, &t);
    if (st != TRK_OK) return refused(why, wn, "trk_amplitude_init_table", st);
    trk_real l_t, l_2t, a1, a2;
    const trk_real thr = trk_amplitude_threshold(&m);
    if (trk_amplitude_log_lr(&m, thr, &l_t) != TRK_OK || trk_amplitude_log_lr(&m, 2 * thr, &l_2t) != TRK_OK ||
        trk_amplitude_inv_sf(&m, TRK_AMP_CLUTTER, 1, &a1) != TRK_OK ||
        trk_amplitude_inv_sf(&m, TRK_AMP_TARGET, 1, &a2) != TRK_OK)
        return defect(why, wn, "the amplitude model does not evaluate");
    printf("  amplitude model (library, %s): threshold %.10g, pd %.10g\n",
           m.tabulated ? "table lookup" : "Rayleigh closed form", (double)thr, (double)trk_amplitude_pd(&m));
    printf("    ln l^a(t) = %.10g, ln l^a(2t) = %.10g; a(x=1): clutter %.10g, target %.10g\n", (double)l_t,
           (double)l_2t, (double)a1, (double)a2);
    return 0;
}

/* How much of FILE to read: the size its header declares (+ 1 MiB, to count
 * bytes after the table's end), 1 MiB when it starts with no table magic
 * (enough for the check's own message), never more than the format's
 * maximum (/dev/zero was read until malloc failed). */
static size_t read_bound(const char *file)
{
    unsigned char h[20];
    size_t bound = (size_t)1 << 20;
    FILE *f = fopen(file, "rb");
    if (!f) return bound;
    if (fread(h, 1, sizeof h, f) == sizeof h && memcmp(h, "TRKTABLE", 8) == 0)
        bound = (size_t)rd32(h + 16) + bound;
    fclose(f);
    return bound < TRK_TABLE_FILE_MAX_BYTES ? bound : TRK_TABLE_FILE_MAX_BYTES;
}

/* The one FILE operand. */
static int take_file(void *ctx, const char *arg, const char *next, char *err, size_t errlen)
{
    const char **file = ctx;
    (void)next;
    if (arg[0] == '-' && arg[1]) return 0; /* an unknown option */
    if (*file) {
        snprintf(err, errlen, "one FILE only, '%s' is a second (see --help)", arg);
        return -1;
    }
    *file = arg;
    return 1;
}

TABLEGEN_CMD(info, "load a table through the library, print header and parameters (exit 1 on a defect)")
{
    const char *file = NULL;
    const struct cli_opt opts[] = {CLI_OPT_END};
    const struct cli cli = {
        .prog = "trk-tablegen info",
        .usage = "FILE",
        .about = "Checks FILE with the library's loader (size, magic, version, CRC, layout, finite and\n"
                 "monotone values; for tables of this build's real width also trk_table_parse and the\n"
                 "kind's own checks, e.g. trk_amplitude_init_table), prints its header, parameters and\n"
                 "sections. A defect is also said on stderr. Exit status 0 sound, 1 a defect or an\n"
                 "unreadable file, 2 a usage error.",
        .opts = opts,
        .operand = take_file,
        .ctx = &file};
    const int parsed = cli_parse(&cli, argc, argv);
    if (parsed != CLI_RUN) return parsed;
    if (!file) {
        fprintf(stderr, "trk-tablegen info: FILE is required (see --help)\n");
        return 2;
    }
    size_t len;
    /* bounded by the format's maximum: /dev/zero is refused, not read forever */
    const size_t bound = read_bound(file);
    unsigned char *b = fileio_read_max(file, bound, &len);
    if (!b) {
        if (errno == EFBIG)
            fprintf(stderr, "trk-tablegen info: %s: more than %zu bytes (%s)\n", file, bound,
                    bound == TRK_TABLE_FILE_MAX_BYTES ? "the largest table" : "its header's size + 1 MiB");
        else
            fprintf(stderr, "trk-tablegen info: %s: cannot read: %s\n", file, strerror(errno));
        return 1;
    }
    struct trk_table_info in;
    char why[512] = "", what[256];
    printf("%s:\n", file);
    trk_status st = trk_table_check(b, len, &in);
    if (st != TRK_OK) {
        refused(why, sizeof why, "trk_table_check", st);
        printf("DEFECT\n");
        fprintf(stderr, "trk-tablegen info: %s: %s\n", file, why);
        free(b);
        return 1;
    }
    print_table(b, &in);
    int bad = 0;
    const int unknown = strcmp(kind_name(in.kind), "unknown") == 0;
    if (unknown) { /* the container is sound, its content unknown */
        snprintf(what, sizeof what, "unknown table kind %u (known: amp %u, q2_pdaf %u, q2_pdafai %u)", in.kind,
                 TRK_TABLE_KIND_AMP, TRK_TABLE_KIND_Q2_PDAF, TRK_TABLE_KIND_Q2_PDAFAI);
        bad = defect(why, sizeof why, what);
    }
    if (in.size != len) {
        snprintf(what, sizeof what, "%zu bytes after the table's end", len - in.size);
        bad = defect(why, sizeof why, what);
    }
    if (!unknown && in.real_size == sizeof(trk_real)) {
        bad |= check_kind(b, len, &in, why, sizeof why);
    } else if (!unknown) {
        printf("  (real width %u: this %s build checks the container only; use a %s build of trk-tablegen\n"
               "   for the kind's checks)\n",
               in.real_size, TRK_REAL_IS_FLOAT ? "float" : "double", in.real_size == 4 ? "float" : "double");
    }
    printf("%s\n", bad ? "DEFECT" : "OK");
    if (bad) fprintf(stderr, "trk-tablegen info: %s: %s\n", file, why);
    free(b);
    return bad;
}
