/* table_seeds.c - writes the seed corpus of fuzz_table (tests/fuzz/corpus/
 * table/) with the tools' table writer: small valid tables of both real
 * widths covering 1, 2 and 3 axes, every spacing, real and integer
 * parameters, several sections and both interpolation rules, plus a few
 * truncated/corrupted copies. Run by hand (make fuzz-table-seeds) when the
 * format changes; the output is committed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "table_writer.h"

static int emit(const char *dir, const char *name, struct tablew *w, int variants)
{
    unsigned char *b = NULL;
    size_t n = 0;
    if (tablew_finish(w, &b, &n)) {
        fprintf(stderr, "table_seeds: %s: %s\n", name, tablew_error(w));
        tablew_free(w);
        return 1;
    }
    tablew_free(w);
    char path[512];
    snprintf(path, sizeof path, "%s/%s.tbl", dir, name);
    int bad = tablew_write_bin(path, b, n) != 0;
    if (variants) {
        snprintf(path, sizeof path, "%s/%s-truncated.tbl", dir, name);
        bad |= tablew_write_bin(path, b, n / 2) != 0;
        b[n / 3] ^= 0x40;
        snprintf(path, sizeof path, "%s/%s-flipped.tbl", dir, name);
        bad |= tablew_write_bin(path, b, n) != 0;
    }
    free(b);
    return bad;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/fuzz/corpus/table";
    int bad = 0;
    for (unsigned rs = 4; rs <= 8; rs += 4) {
        double d[64];
        for (int i = 0; i < 64; i++) d[i] = 0.25 * i - 3;
        char name[64];
        /* 1 axis, linear, Hermite (value + slope), one real and one int parameter */
        struct tablew *w = tablew_new(TRK_TABLE_KIND_AMP, 1, rs);
        struct tablew_axis lin = {8, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_X, 0, 40, 0, NULL};
        tablew_param_real(w, "pfa", 1e-3);
        tablew_param_int(w, "n", 7);
        tablew_section(w, 1, 1, &lin, 2, TRK_TABLE_INTERP_HERMITE, d);
        snprintf(name, sizeof name, "amp1-r%u", rs);
        bad |= emit(dir, name, w, 1);
        /* 2 axes log x geometric, linear interpolation, 2 sections */
        w = tablew_new(TRK_TABLE_KIND_Q2_PDAF, 1, rs);
        struct tablew_axis a2[2] = {{4, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_LAMBDA_VG, 1e-3, 10, 0, NULL},
                                    {5, TRK_TABLE_SPACING_GEOMETRIC, TRK_TABLE_VAR_PD, 0.1, 0.99, 1.5, NULL}};
        tablew_param_real(w, "gate_prob", 0.99);
        tablew_section(w, 3, 2, a2, 1, TRK_TABLE_INTERP_LINEAR, d);
        tablew_section(w, 4, 2, a2, 2, TRK_TABLE_INTERP_NONE, d + 1);
        snprintf(name, sizeof name, "q2-2axes-r%u", rs);
        bad |= emit(dir, name, w, 1);
        /* 3 axes, one explicit */
        w = tablew_new(TRK_TABLE_KIND_Q2_PDAFAI, 1, rs);
        const double ex[3] = {-1, 0.5, 2};
        struct tablew_axis a3[3] = {{3, TRK_TABLE_SPACING_EXPLICIT, TRK_TABLE_VAR_SNR_DB, -1, 2, 0, ex},
                                    {2, TRK_TABLE_SPACING_LOG, TRK_TABLE_VAR_PFA, 1e-6, 1e-2, 0, NULL},
                                    {3, TRK_TABLE_SPACING_LINEAR, TRK_TABLE_VAR_LAMBDA_VG, 0, 4, 0, NULL}};
        tablew_param_int(w, "model", 2);
        tablew_param_real(w, "nu", 1.5);
        tablew_section(w, 9, 3, a3, 1, TRK_TABLE_INTERP_LINEAR, d);
        snprintf(name, sizeof name, "q2ai-3axes-r%u", rs);
        bad |= emit(dir, name, w, 0);
    }
    return bad;
}
