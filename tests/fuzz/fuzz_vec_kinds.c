/* fuzz_vec_kinds.c - libFuzzer target: vector cases through the kinds, i.e.
 * hostile numbers into the library. Parses the input like fuzz_vec.c, then
 * runs each case's kind (tools/vec/kind_*.c -> libtrk) and the checker.
 * Finds crashes, undefined behaviour (UBSan), out-of-bounds accesses and
 * hangs (libFuzzer -timeout) in the library's handling of arbitrary finite
 * inputs and in the kinds themselves.
 * Kinds too slow for fuzzing are skipped: q2_pdaf, q2_pdafai (Monte Carlo
 * with millions of samples per case). */
#include <stdint.h>
#include <string.h>

#include "vec.h"

static struct vec_case cs;
static struct vec_out out;

static int slow_kind(const char *k)
{
    return strcmp(k, "q2_pdaf") == 0 || strcmp(k, "q2_pdafai") == 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct vec_file f;
    vec_file_init(&f, (const char *)data, size);
    while (vec_next(&f, &cs) == 1) {
        const struct vec_kind *k = vec_kind_find(cs.kind);
        if (!k || slow_kind(k->name)) continue;
        vec_out_reset(&out);
        if (k->fn(&cs, &out) != 0) continue;
        struct vec_check chk;
        vec_compare(&f, &cs, &out, 0, k->float_abs, k->float_rel, &chk);
        vec_compare(&f, &cs, &out, 1, k->float_abs, k->float_rel, &chk);
    }
    return 0;
}
