/* kind_window.c - vector kinds kn and mn (tests/vectors/tracktests.vec):
 * K/N termination and M/N confirmation, step by step. Integer outputs only,
 * so the float build uses the same (exact) tolerances.
 *
 * The vector file codes decisions as numbers (docs/conventions.md "Track
 * confirmation and termination"): a confirmation test +1 confirm, -1 reject,
 * 0 pending; a termination test 1 terminate, 0 continue. The library's
 * enum trk_decision is translated here, once, into that coding. */
#include <string.h>

#include "trk/confirm_mn.h"
#include "trk/term_kn.h"
#include "vec.h"

/* enum trk_decision -> the vector file's coding */
static double confirm_code(enum trk_decision d)
{
    return d == TRK_DECISION_CONFIRM ? 1 : d == TRK_DECISION_TERMINATE ? -1 : 0;
}
static double term_code(enum trk_decision d) { return d == TRK_DECISION_TERMINATE ? 1 : 0; }

static int deltas(const struct vec_case *c, struct vec_out *o, const double **d, size_t *n)
{
    if (vec_in_array(c, o, "delta", d, n)) return -1;
    for (size_t i = 0; i < *n; i++)
        if ((*d)[i] != 0 && (*d)[i] != 1) return vec_fail(o, "delta must be 0 or 1");
    return 0;
}

TRK_VEC_KIND(kn, 0, 0, VEC_FAST)
{
    long k, n;
    const double *d;
    size_t len;
    if (vec_in_int(c, o, "k", &k) || vec_in_int(c, o, "n", &n) || deltas(c, o, &d, &len)) return -1;
    struct trk_kn_model m;
    struct trk_kn s;
    struct trk_kn_params p = {(int)k, (int)n};
    trk_status st = trk_kn_model_init(&m, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_kn_model_init: %s", trk_status_str(st));
    trk_kn_reset(&m, &s);
    double *count = vec_put_alloc(o, "count", len), *fire = vec_put_alloc(o, "fire", len),
           *dec = vec_put_alloc(o, "decision", len);
    if (!count || !fire || !dec) return -1;
    for (size_t t = 0; t < len; t++) {
        enum trk_decision dk;
        st = trk_kn_step(&m, &s, d[t] != 0, &dk);
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        dec[t] = term_code(dk);
        count[t] = s.count;
        fire[t] = s.fire;
    }
    return 0;
}

TRK_VEC_KIND(mn, 0, 0, VEC_FAST)
{
    long m, n;
    const char *mode;
    const double *d;
    size_t len;
    if (vec_in_int(c, o, "m", &m) || vec_in_int(c, o, "n", &n) || vec_in_word(c, o, "mode", &mode) ||
        deltas(c, o, &d, &len))
        return -1;
    struct trk_mn_params p = {(int)m, (int)n, TRK_MN_FIXED};
    if (strcmp(mode, "sliding") == 0) p.mode = TRK_MN_SLIDING;
    else if (strcmp(mode, "fixed") != 0) return vec_fail(o, "mode must be fixed|sliding");
    struct trk_mn_model md;
    struct trk_mn s;
    trk_status st = trk_mn_model_init(&md, &p);
    if (st != TRK_OK) return vec_fail(o, "trk_mn_model_init: %s", trk_status_str(st));
    trk_mn_reset(&md, &s);
    double *count = vec_put_alloc(o, "count", len), *dec = vec_put_alloc(o, "decision", len);
    if (!count || !dec) return -1;
    for (size_t t = 0; t < len; t++) {
        enum trk_decision dm;
        st = trk_mn_step(&md, &s, d[t] != 0, &dm);
        if (st != TRK_OK) return vec_fail(o, "scan %zu: %s", t + 1, trk_status_str(st));
        dec[t] = confirm_code(dm);
        count[t] = s.count;
    }
    return 0;
}
