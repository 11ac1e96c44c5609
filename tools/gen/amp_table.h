/* amp_table.h - generation of amplitude tables (trk/amplitude.h "AMPLITUDE
 * TABLE") for trk-tablegen, the tests and the benchmarks.
 *
 * K clutter: every node from the high-accuracy texture integrals of kdist.h;
 * Rayleigh: the library's closed forms (trk_amplitude_init_rayleigh,
 * trk_amplitude_log_lr, trk_amplitude_inv_sf) with their derivatives.
 * Optionally the table is loaded back through the library and its errors
 * measured against the direct evaluation (and stored as parameters). */
#ifndef TRK_AMP_TABLE_H
#define TRK_AMP_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "kdist.h"
#include "trk/amplitude.h"

#define AMP_TABLE_GENERATOR_VERSION 1
#define AMP_TABLE_DEFAULT_SIZE 256u      /* inverse-survival points per curve (uniform grid) */
#define AMP_TABLE_DEFAULT_GEOM_SIZE 256u /* points per curve (geometric grid) */
#define AMP_TABLE_DEFAULT_LLR_SIZE 256u  /* log l^a points */
#define AMP_TABLE_X_MAX 40.0             /* x = -ln S^a range of the tables */
#define AMP_TABLE_GEOM_STEP 0.25         /* Brekke eqs 43-45: A */
#define AMP_TABLE_GEOM_LAST 100.0        /* a^(P), units of sqrt(clutter power) */

/* An executor of the generator's node loops (NULL: this file's OpenMP
 * loops): run(ctx, n, size, fn, fctx, out) calls fn(fctx, i, out + i *
 * size) for every i < n, each once, on any thread or process (par_for_each
 * of tools/par/par.h has this shape: trk-tablegen-mpi spreads the nodes
 * over its ranks), and returns 0, or non-zero when an fn call (non-zero) or
 * the executor failed. A node's values depend on i only: the table's bytes
 * are the same either way. */
struct amp_table_exec {
    int (*run)(void *ctx, size_t n, size_t size, int (*fn)(void *fctx, size_t i, void *res), void *fctx,
               void *out);
    void *ctx;
};

struct amp_table_opts {
    int model;              /* enum trk_amp_model */
    double nu;              /* K shape (ignored for Rayleigh) */
    double snr_db, pfa;
    double clutter_power;   /* 0 = 1 */
    int grid;               /* enum trk_amp_grid; 0 = uniform */
    uint32_t size;          /* inverse-survival points; 0 = default */
    uint32_t llr_size;      /* log l^a points; 0 = default */
    double x_max;           /* 0 = AMP_TABLE_X_MAX */
    uint32_t real_size;     /* 4 or 8; 0 = sizeof(trk_real) */
    int measure;            /* measure errors (K tables of real_size == sizeof(trk_real)) */
    int measure_points;     /* error samples per table interval; 0 = 3 */
    const struct amp_table_exec *exec; /* NULL: OpenMP here */
};

struct amp_table_result {
    unsigned char *bytes;   /* malloc'd, 8-aligned: free() */
    size_t len;
    double threshold, pd;   /* amplitude units */
    double a_max;           /* last log l^a node, amplitude units */
    int measured;           /* 1 when the errors below were measured */
    double err_log_lr;      /* max |table - direct| of ln l^a on [t, a_max] */
    double err_inv_sf;      /* max relative error of a(x) on [0, x_max], both curves */
};

/* *o for the law (model, nu, snr_db, pfa), every other option 0 (its default). */
void amp_table_opts_init(struct amp_table_opts *o, int model, double nu, double snr_db, double pfa);

/* 0, or -1 with a message in err. */
int amp_table_build(const struct amp_table_opts *o, struct amp_table_result *r, char *err, size_t errlen);

/* The library's amplitude model on a table built in memory: amp_table_build
 * per *o, then trk_table_parse and trk_amplitude_init_table into *m, which
 * views r->bytes (free(r->bytes) after the last use of *m). The simulations'
 * K models (q2_amp.h, single_target.h). 0, or -1 with a message in err
 * (nothing left to free). */
int amp_table_model(const struct amp_table_opts *o, struct trk_amplitude *m, struct amp_table_result *r,
                    char *err, size_t errlen);

/* Direct (reference) evaluation in amplitude units, the one the vector kinds
 * use: K from kdist, Rayleigh from the library closed forms. */
struct amp_direct {
    int model;
    double clutter_power, sqrt_p, pfa, snr_db, nu;
    double t, pd;           /* amplitude units */
    struct kdist k;         /* K only */
    struct trk_amplitude ray; /* Rayleigh only */
};
int amp_direct_init(struct amp_direct *d, int model, double nu, double clutter_power, double snr_db,
                    double pfa);
int amp_direct_log_lr(const struct amp_direct *d, double a, double *log_lr);
int amp_direct_inv_sf(const struct amp_direct *d, int source, double x, double *a);

#endif
