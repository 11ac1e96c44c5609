/* vec.h - reader, checker and kind registry for the reference-vector format
 * (tests/vectors/FORMAT.md). Fixed buffers only; shared by trk-vectors,
 * the tests and the fuzz target.
 *
 * Adding a kind: create tools/vec/kind_<family>.c and write
 *     TRK_VEC_KIND(my_kind, float_abs, float_rel, VEC_FAST) { ... }
 * The build collects every TRK_VEC_KIND line into the registry
 * (build/gen/vec_kinds.inc); nothing else to edit. float_abs/float_rel are the
 * tolerances used by the float build (normwise: |got-want| <= abs + rel*max|want|
 * over the output array), justified in the kind's file. The last argument is
 * VEC_FAST, or VEC_SLOW for a kind whose cases take seconds (Monte Carlo
 * estimators): `trk-vectors --skip-slow` leaves those out (counted and named),
 * `make check` passes it, `make test` runs them in one configuration, and the
 * firmware image (mk/qemu.mk) neither registers nor embeds them.
 */
#ifndef TRK_VEC_H
#define TRK_VEC_H

#include <stddef.h>

#include "trk/types.h"

#define VEC_MAX_LINE 65536
#define VEC_MAX_FILE_BYTES (256u << 20) /* a vector file read by trk-vectors: at most 256 MiB */
#define VEC_MAX_NAME 32      /* names are at most 31 characters */
#define VEC_MAX_ID 64
#define VEC_MAX_ARRAY 1024   /* values on one line */
/* The two capacities below may be lowered with -D for a small-memory build
 * (the QEMU firmware image of tests/qemu/, mk/qemu.mk): a case that does not
 * fit is then a parse error ("case too large"), never silently cut. */
#ifndef VEC_MAX_ENTRIES
#define VEC_MAX_ENTRIES 512  /* in/out/tol lines of one case */
#endif
#ifndef VEC_POOL
#define VEC_POOL (1u << 18)  /* values of one case, all lines together */
#endif

struct vec_entry {
    char name[VEC_MAX_NAME];
    char word[VEC_MAX_NAME]; /* bare-word value (e.g. a model name), "" if numeric */
    size_t off, n;           /* values in the pool */
};

struct vec_tol {
    char name[VEC_MAX_NAME]; /* "*" = default */
    double abs, rel;
};

struct vec_case {
    char kind[VEC_MAX_NAME];
    char id[VEC_MAX_ID];
    long line;               /* line of the 'case' record */
    size_t n_in, n_out, n_tol;
    struct vec_entry in[VEC_MAX_ENTRIES];
    struct vec_entry out[VEC_MAX_ENTRIES];
    struct vec_tol tol[VEC_MAX_ENTRIES];
    size_t pool_used;
    double pool[VEC_POOL];
};

/* File-level state: tolerances given outside any case apply to later cases. */
struct vec_file {
    const char *buf;
    size_t len, pos;
    long line;
    size_t n_tol;
    struct vec_tol tol[64];
    char err[160];
};

void vec_file_init(struct vec_file *f, const char *buf, size_t len);

/* Next case: 1 = a case was read into *c, 0 = end of input, -1 = malformed
 * input (f->err says what and where; reading cannot continue). */
int vec_next(struct vec_file *f, struct vec_case *c);

/* Tolerance of output `name`: the case's own entry for the name, else the
 * case's "*", else the file's entry for the name, else the file's "*", else 0 0. */
void vec_tolerance(const struct vec_file *f, const struct vec_case *c, const char *name,
                   double *abs, double *rel);

/* --- inputs, for kind implementations. Each returns 0, or -1 with
 * o->err set ("missing input 'x'"), so a kind can write
 *     if (vec_in_scalar(c, o, "T", &t)) return -1;                        --- */
struct vec_out;
int vec_in_array(const struct vec_case *c, struct vec_out *o, const char *name, const double **v,
                 size_t *n);
int vec_in_array_n(const struct vec_case *c, struct vec_out *o, const char *name, size_t n,
                   const double **v); /* exactly n values */
int vec_in_scalar(const struct vec_case *c, struct vec_out *o, const char *name, double *v);
int vec_in_int(const struct vec_case *c, struct vec_out *o, const char *name, long *v);
int vec_in_word(const struct vec_case *c, struct vec_out *o, const char *name, const char **w);
int vec_has_in(const struct vec_case *c, const char *name);

/* --- outputs computed by a kind --- */
struct vec_out {
    size_t n;
    struct vec_entry e[VEC_MAX_ENTRIES];
    size_t pool_used;
    double pool[VEC_POOL];
    char err[160];
};
void vec_out_reset(struct vec_out *o);
/* Append an output array (copied). -1 (with o->err) when full. */
int vec_put(struct vec_out *o, const char *name, const double *v, size_t n);
int vec_put1(struct vec_out *o, const char *name, double v);
/* The same for library values (trk_real, widened to double). */
int vec_put_real(struct vec_out *o, const char *name, const trk_real *v, size_t n);
/* Reserve n values for output `name` and return them to be filled (NULL when full). */
double *vec_put_alloc(struct vec_out *o, const char *name, size_t n);
int vec_fail(struct vec_out *o, const char *fmt, ...);
const struct vec_entry *vec_out_find(const struct vec_out *o, const char *name);

/* --- kinds ---
 * A kind returns 0 (outputs computed), -1 (error: o->err says why), or
 * VEC_NOT_APPLICABLE when this build cannot answer the case meaningfully:
 * a float build whose answer jumps within float rounding (e.g. a detection on
 * the gate boundary), or a case larger than this build's compile-time
 * capacities. o->err says why; the runner counts such cases apart and prints
 * them (they never occur in the default double build). */
#define VEC_NOT_APPLICABLE 1
#define VEC_FLOAT_UNRESOLVABLE VEC_NOT_APPLICABLE /* older name */
typedef int (*vec_kind_fn)(const struct vec_case *c, struct vec_out *o);
enum vec_kind_speed { VEC_FAST = 0, VEC_SLOW = 1 };
struct vec_kind {
    const char *name;
    vec_kind_fn fn;
    double float_abs, float_rel;
    enum vec_kind_speed speed;
};
#define TRK_VEC_KIND(kname, fabs_, frel_, speed_) \
    int trk_vec_kind_##kname(const struct vec_case *c, struct vec_out *o)

const struct vec_kind *vec_kind_find(const char *name);

/* Is kind `name` in the comma-separated list? */
int vec_kind_listed(const char *list, const char *name);
const struct vec_kind *vec_kinds(size_t *n);

/* --- comparison --- */
struct vec_check {
    int ok;               /* 1 when every expected output matched */
    char first_fail[256]; /* "<name>[<index>] got want" of the first mismatch */
    size_t n_fail_names;
    double max_abs_err;   /* over all real outputs of the case */
    double max_rel_err;
    double max_tol_use;   /* max |got-want| / (abs + rel |want|); > 1 fails */
};
/* Compare computed outputs with the case's expected ones using its tolerances;
 * with normwise != 0 (float builds) rel is taken against max|want| of each
 * array and (abs, rel) are widened to at least (float_abs, float_rel). */
void vec_compare(const struct vec_file *f, const struct vec_case *c, const struct vec_out *o,
                 int normwise, double float_abs, double float_rel, struct vec_check *chk);

#endif
