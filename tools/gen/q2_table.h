/* q2_table.h - q2 tables (trk/q2.h "Q2 TABLE") computed by the importance
 * sampler (q2_is.h) for trk-tablegen q2, the TOC (toc_curve.h), tests and
 * benchmarks.
 *
 * PDAF:   one line of the sampler over all (pd, lambda_vg) cells (common
 *         random numbers over both axes).
 * PDAFAI: one line per (snr_db, pfa) node, each with its amplitude law
 *         (q2_amp.h: the library's Rayleigh closed forms or K table lookup)
 *         and pd = S1(t), all on the same random stream (common random
 *         numbers over every axis).
 * The sampler's lines run in parallel over strata and chunks of samples with
 * a counter-based generator keyed by (seed, stream, stratum, sample), so the
 * table's bytes do not depend on the thread count or the schedule.
 *
 * Interpolation error (measure_interp): extra cells at the centre of every
 * grid cell (PDAF: (pd, lambda_vg) midpoints in the PDAF line; PDAFAI: lines
 * at every (snr_db, pfa) midpoint with lambda_vg midpoints), estimated with
 * the same random numbers, compared with the library's lookup on the new
 * table. The Monte Carlo noise partly cancels in the difference (common
 * random numbers); where the cells' se approach the target se (large
 * lambda_vg) it does not entirely, so the error is also reported over the
 * test points with se <= Q2_TABLE_QUIET_SE (interp_max_quiet). Costs about
 * one more table (PDAFAI) or nothing much (PDAF). */
#ifndef TRK_Q2_TABLE_H
#define TRK_Q2_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "q2_is.h"

#define Q2_TABLE_GENERATOR_VERSION 1
#define Q2_TABLE_MAX_NODES 4096u
#define Q2_TABLE_QUIET_SE 1e-4   /* see interp_max_quiet */

/* Default grids (trk-tablegen q2, `make tables`, the TOC's sampled grids),
 * chosen by the measured interpolation error (docs/library.md "Performance
 * prediction"): LIST and LOG syntax of q2_table_parse_list / _log. */
#define Q2_TABLE_DEFAULT_PD "0.02:0.1:0.02,0.15:0.85:0.05,0.87:0.97:0.02,0.98,0.99,0.995,1"
#define Q2_TABLE_DEFAULT_SNR_DB "5:8:1,9.5:14:1.5,16:20:2,22.5,25"
#define Q2_TABLE_DEFAULT_PFA "1e-6:0.5:22"
#define Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF "1e-6:100:57"
#define Q2_TABLE_DEFAULT_LAMBDA_VG_PDAFAI "1e-6:50:47"
#define Q2_TABLE_DEFAULT_SAMPLES 1000000u
#define Q2_TABLE_DEFAULT_TARGET_SE 1e-3

/* One axis: n nodes, either explicit (nodes != NULL, strictly increasing) or
 * from lo to hi (uniform in x for pd / snr_db, in ln x for pfa / lambda_vg). */
struct q2_table_axis {
    size_t n;
    double lo, hi;
    const double *nodes;
};

struct q2_table_spec {
    int detector;                  /* TRK_Q2_PDAF or TRK_Q2_PDAFAI */
    int nz;                        /* 1..3 */
    double gate_gamma;             /* > 0, with F_{nz+2}(gamma) >= 1e-3 */
    int amp_model;                 /* PDAFAI: TRK_AMP_RAYLEIGH or TRK_AMP_K */
    double nu;                     /* PDAFAI, K: shape */
    struct q2_table_axis pd;       /* PDAF: (0, 1] */
    struct q2_table_axis snr_db;   /* PDAFAI: [-30, 60] */
    struct q2_table_axis pfa;      /* PDAFAI: (0, 1), log spacing */
    struct q2_table_axis lambda_vg;/* (0, 1000], log spacing */
    int cubic;                     /* 1: TRK_TABLE_INTERP_CUBIC, 0: LINEAR */
    uint32_t real_size;            /* 4 or 8; 0: sizeof(trk_real) */
    unsigned amp_size;             /* K amplitude table points (0: default) */
    int amp_measure;               /* measure every K amplitude table's error */
    int measure_interp;            /* measure the interpolation error (above) */
};

struct q2_table_run {
    uint64_t samples;              /* per stratum, see q2_is.h (2 .. 2^32-1) */
    double target_se;              /* stop a cell at this se (0: run all samples) */
    uint64_t seed;
    double tail_mass;              /* 0: q2_is default */
    int threads;                   /* <= 0: OpenMP default */
    void (*progress)(void *ctx, const struct q2_is_progress *p);
    void *progress_ctx;
    struct par *par;               /* q2_is_options.par: NULL this process */
};

struct q2_table_result {
    unsigned char *bytes;          /* the table (malloc'd, 8-aligned); NULL when an
                                      axis has 1 node (the container needs >= 2) */
    size_t len;
    double *values;                /* (q2, se) per cell, row-major as in the table */
    size_t n_cells, n_lines;
    double max_se, mean_se;        /* over the table's cells */
    uint64_t scenes, points;       /* drawn (table and test cells) */
    double setup_s, sample_s;      /* wall time: amplitude models, sampling */
    int amp_measured;
    double amp_err_log_lr, amp_err_inv_sf; /* max over the K amplitude tables */
    int interp_measured;
    size_t interp_n;               /* test points */
    double interp_max, interp_rms; /* |lookup - direct| at the test points */
    double interp_se_median;       /* median se of the direct test values */
    double interp_max_at[3];       /* coordinates of the largest error */
    size_t interp_n_quiet;         /* test points with se <= Q2_TABLE_QUIET_SE */
    double interp_max_quiet;       /* the largest error among them: the
                                      interpolation error with little noise */
};

/* 0, or -1 with a message (bad spec: axis out of range or not increasing,
 * zero samples, NaN parameters, ...; sampler failure; out of memory).
 * Free the result with q2_table_result_free. */
int q2_table_build(const struct q2_table_spec *s, const struct q2_table_run *r, struct q2_table_result *res,
                   char *err, size_t errlen);

/* Free bytes and values. */
void q2_table_result_free(struct q2_table_result *res);

/* LIST: comma-separated values and ranges A:B:STEP, strictly increasing,
 * into v[0..max); returns the count or -1. */
int q2_table_parse_list(const char *s, double *v, int max);
/* LOG: A:B:N, N >= 2 nodes equally spaced in ln x, 0 < A < B. 0 or -1. */
int q2_table_parse_log(const char *s, struct q2_table_axis *a);
/* An axis over v[0..n): a computed (linear) axis when the values are
 * uniform, else explicit (a->nodes = v, which must outlive it). */
void q2_table_list_axis(const double *v, int n, struct q2_table_axis *a);

/* Node i of an axis (explicit, or uniform in x or ln x). */
double q2_table_node(const struct q2_table_axis *a, int log_axis, size_t i);

/* gamma of a gate probability (nz = 2 in closed form, else the library's
 * chi-square inverse) and back. 0 or -1. */
int q2_gate_gamma(int nz, double pg, double *gamma);
double q2_gate_prob(int nz, double gamma);

#endif
