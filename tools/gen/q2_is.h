/* q2_is.h - importance-sampling estimator of the information-reduction factor
 * q2 for the offline tools (docs/conventions.md "q2, MRE and CRLB"; Brekke eqs 28-30,
 * 36-38, 50-54; Willett eqs 14-16).
 *
 * Estimator (Brekke eq 38 with eq 28 folded in, docs/conventions.md):
 *   q2 = pd F_{nz+2}(gamma) sum_{n>=0} Poisson(n; lambda_vg) E_n[beta_1],
 *   beta_1 = L_1 / (b + L_1 + sum_{j=2}^{n+1} L_j),  L_i = l^a(a_i) exp(-rho_i^2/2),
 *   b = (2 pi)^(nz/2) lambda_vg (1 - pd pg) / (pd c_nz gamma^(nz/2)),
 * with the target's rho_1^2 ~ chi2(nz+2) truncated to [0, gamma] (the factor
 * F_{nz+2}(gamma) = P(chi2(nz+2) <= gamma) outside; without the truncation q2
 * is ~6 % high at pg = 0.99), n clutter points uniform in the gate
 * (rho_j = sqrt(gamma) U^(1/nz), Brekke eq 53) and amplitudes from the
 * thresholded target / clutter laws (PDAFAI; l^a = 1 for the PDAF).
 * pg = P(chi2(nz) <= gamma) is the gate probability of gamma.
 *
 * Sampling. Stratified by the clutter count n, n = 0 included; strata cover
 * each cell's Poisson(lambda_vg) mass except tail_mass (default 1e-12, the
 * bound on the truncation bias). Allocation, N = `samples`: a pilot round at
 * N/64 (N/1024 with a target se; at least 1024) with proportional allocation (stratum n gets
 * max_k w_n(lambda_k) / w_mode(lambda_k) of the scenes), then Neyman
 * allocation from the pilot's standard deviations s_n: stratum n gets
 * rho_n N scenes, rho_n = max over its cells of w_n s_n / max_m (w_m s_m)
 * (N scenes where a cell's variance comes from), at least a tenth of its
 * proportional share and at least min(N, 256) scenes.
 * Common random numbers: a scene's (L_1, sum_j L_j) does not depend on pd or
 * lambda_vg (they enter only b and the weights), so one sample set per
 * stratum serves every cell of a line; the estimate is a smooth function of
 * the cell's (pd, lambda_vg) and a table of it interpolates smoothly.
 * nz = 2 draws without libm calls on the radial part: exp(-rho_1^2/2) = U1 U2
 * (chi2(4)/2 = E1 + E2) and rejection of U1 U2 < exp(-gamma/2) truncates it.
 *
 * Standard error per cell: se^2 = (pd F)^2 sum_n w_n^2 s_n^2 / N_n, s_n^2 the
 * sample variance of beta_1 in stratum n (block-wise two-pass, merged by
 * Chan's formula: no cancellation).
 *
 * Random numbers: Random123 philox4x32-10, key = seed (64 bits), counter =
 * (word group, sample index, stratum n, line stream). Every output is a
 * fixed function of (seed, stream, the line's cells, samples): work items
 * (line, stratum, chunk of 2^17 samples) are computed independently, in any
 * order and on any thread, into their own slots, and merged in a fixed order
 * afterwards (never an OpenMP floating-point reduction). The result is
 * bit-identical for any thread count and schedule. The items of a round are
 * the work units of tools/par (par.h): on this process's threads, or over
 * the ranks of an MPI job (options.par), with the same bits.
 *
 * Threads: libtrk_tools.a holds the OpenMP build (mk/q2.mk); compiled
 * without -fopenmp the same source runs serially. Both give the same bits.
 */
#ifndef TRK_Q2_IS_H
#define TRK_Q2_IS_H

#include <stddef.h>
#include <stdint.h>

struct par; /* tools/par/par.h */

/* Pluggable amplitude law (PDAFAI; tools/gen/q2_amp.h builds it on the
 * library's amplitude module). log_lr draws n thresholded amplitudes by
 * inverse transform from the uniforms u[i] in (0, 1) (x = -ln u[i] ~ Exp(1)
 * is the negative log truncated survival, docs/conventions.md "Amplitude models") --
 * target != 0: from the target law p1^a; 0: the clutter law p0^a -- and writes
 * out[i] = ln l^a(a_i); returns 0, or -1 when the model refuses a value. It
 * must be a pure function of (ctx, target, u[i]) (called concurrently from
 * several threads). pd is S1(t), the detection probability at the threshold
 * (the ROC value). */
struct q2_amp_sampler {
    const char *name;
    int (*log_lr)(const void *ctx, int target, size_t n, const double *u, double *out);
    const void *ctx;
    double pd;
};

/* One scene law and the output cells that share its samples. */
struct q2_is_line {
    int nz;                            /* 1..3 */
    double gamma;                      /* gate threshold on d2, > 0 */
    const struct q2_amp_sampler *amp;  /* NULL: PDAF; else PDAFAI */
    uint32_t stream;                   /* part of the random counter; lines with the
                                          same stream and law share samples */
    size_t n_cells;                    /* >= 1 */
    const double *pd;                  /* n_cells detection probabilities in (0, 1];
                                          NULL: amp->pd for every cell (PDAFAI) */
    const double *lambda_vg;           /* n_cells, in (0, Q2_IS_MAX_LAMBDA_VG] */
    double *q2;                        /* out: n_cells estimates */
    double *se;                        /* out: n_cells standard errors (may be NULL) */
    /* out: what was drawn for this line */
    uint64_t scenes;                   /* scenes over all strata */
    uint64_t points;                   /* target + clutter points drawn */
    uint64_t samples_mode;             /* N of the last round (< samples when target_se
                                          stopped the line early) */
    int n_strata;
};

#define Q2_IS_MAX_LAMBDA_VG 1000.0
#define Q2_IS_CHUNK 131072u

struct q2_is_progress {
    size_t lines_done, n_lines;
    uint64_t points_done;      /* target + clutter points so far */
    uint64_t points_planned;   /* at most this many (target_se may stop earlier) */
    double elapsed_s;
    int threads;
};

struct q2_is_options {
    uint64_t seed;
    uint64_t samples;          /* N (see the allocation above), 2 .. 2^32-1 */
    double target_se;          /* > 0: a pilot round at N/1024 (>= 1024 scenes),
                                  then 2x, then rounds sized from the largest se
                                  (se ~ 1/sqrt(N): x1.1 the predicted N, growth
                                  1.25 .. 4 per round) up to N; a stratum stops
                                  once every cell it serves has se <= target_se,
                                  a line once all its cells have; 0: the pilot
                                  (N/64), then N */
    double tail_mass;          /* Poisson mass left out per cell; 0: 1e-12 */
    int threads;               /* <= 0: OpenMP default; 1 in the serial build */
    /* called from one thread at most every 0.25 s and once at the end (on
     * rank 0 only, with par: the work of all ranks) */
    void (*progress)(void *ctx, const struct q2_is_progress *p);
    void *progress_ctx;
    /* the work distribution (tools/par/par.h): each round's items are par
     * work units. NULL: this process's threads (an MPI build of a tool
     * passes its ranks) */
    struct par *par;
};

/* Estimate q2 (and se) for every cell of every line. Returns 0, or -1 with a
 * message in err (bad parameters: nz, gamma, pd, lambda_vg, samples, NaN;
 * F_{nz+2}(gamma) < 1e-3; out of memory). */
int q2_is_run(struct q2_is_line *lines, size_t n_lines, const struct q2_is_options *opt,
              char *err, size_t err_len);

/* One cell: PDAF when amp is NULL (pd given), PDAFAI otherwise (pd = amp->pd
 * when pd <= 0). stream 0. Returns 0 or -1 (err). */
int q2_is_cell(int nz, double gamma, double pd, double lambda_vg,
               const struct q2_amp_sampler *amp, const struct q2_is_options *opt, double *q2,
               double *se, char *err, size_t err_len);

/* The PDA constant b of a cell (docs/conventions.md "q2"); pg from gamma. */
double q2_is_b(int nz, double gamma, double pd, double lambda_vg);

/* Threads the parallel build would use for `threads` (<= 0: default); 1 in
 * the serial build. */
int q2_is_threads(int threads);

/* 1 when this object was compiled with OpenMP. */
int q2_is_parallel(void);

#endif
