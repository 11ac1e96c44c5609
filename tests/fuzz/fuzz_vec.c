/* fuzz_vec.c - libFuzzer target: the reference-vector reader and checker
 * (tools/vec/vec.c) on arbitrary bytes.
 *
 * Parses every case of the input (vec_file_init + vec_next), then, per case,
 * builds an output set from the case's own expected values (vec_put), and
 * runs the tolerance lookup and both comparison modes (vec_compare, plain
 * and normwise), and the input accessors. Invariants checked (abort = a
 * finding): vec_next never reports a case whose entries point outside its
 * pool; comparing a case with its own expected values passes.
 * No kind is run here (fuzz_vec_kinds.c does that). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "vec.h"

static struct vec_case cs;
static struct vec_out out;

static void check_entries(const struct vec_entry *e, size_t n, size_t pool_used)
{
    for (size_t i = 0; i < n; i++) {
        if (e[i].name[0] == '\0' || memchr(e[i].name, 0, sizeof e[i].name) == NULL) abort();
        if (e[i].off > pool_used || e[i].n > pool_used - e[i].off) abort();
        if (e[i].word[0] && e[i].n) abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct vec_file f;
    vec_file_init(&f, (const char *)data, size);
    int r;
    while ((r = vec_next(&f, &cs)) == 1) {
        if (cs.n_in > VEC_MAX_ENTRIES || cs.n_out > VEC_MAX_ENTRIES || cs.pool_used > VEC_POOL) abort();
        check_entries(cs.in, cs.n_in, cs.pool_used);
        check_entries(cs.out, cs.n_out, cs.pool_used);
        vec_out_reset(&out);
        int all_numeric = 1;
        for (size_t i = 0; i < cs.n_out; i++) {
            const struct vec_entry *e = &cs.out[i];
            if (e->word[0]) all_numeric = 0;
            if (!vec_out_find(&out, e->name)) (void)vec_put(&out, e->name, cs.pool + e->off, e->n);
        }
        for (size_t i = 0; i < cs.n_in; i++) {
            const double *v;
            size_t n;
            double x;
            const char *w;
            (void)vec_in_array(&cs, &out, cs.in[i].name, &v, &n);
            (void)vec_in_scalar(&cs, &out, cs.in[i].name, &x);
            long l;
            (void)vec_in_int(&cs, &out, cs.in[i].name, &l);
            (void)vec_in_word(&cs, &out, cs.in[i].name, &w);
        }
        double a, rel;
        vec_tolerance(&f, &cs, "*", &a, &rel);
        struct vec_check chk;
        for (int normwise = 0; normwise <= 1; normwise++) {
            vec_compare(&f, &cs, &out, normwise, 1e-6, 1e-4, &chk);
            /* a case compared with its own values passes, unless an output
             * name repeats (the first copy is compared) or is a word */
            int dup = 0;
            for (size_t i = 0; i < cs.n_out && !dup; i++)
                for (size_t j = 0; j < i; j++)
                    if (strcmp(cs.out[i].name, cs.out[j].name) == 0) dup = 1;
            if (all_numeric && !dup && !chk.ok) abort();
        }
    }
    if (r < 0 && f.err[0] == '\0') abort(); /* an error always says why */
    return 0;
}
