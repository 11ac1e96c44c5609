/* q2_amp.h - the amplitude law of the q2 importance sampler (PDAFAI), built
 * on the library's amplitude module (trk/amplitude.h): the one
 * implementation of the amplitude formulas.
 *
 * docs/conventions.md "Amplitude models" (Brekke eqs 6-9, 19-20, 41-47), clutter
 * power 1: a thresholded amplitude is drawn by inverse CDF from x ~ Exp(1)
 * (x = -ln u, u the sampler's uniform), a = trk_amplitude_inv_sf(x) (target or
 * clutter law), and the sampler needs ln l^a(a) = trk_amplitude_log_lr(a).
 *   Rayleigh  the library's closed forms (trk_amplitude_init_rayleigh)
 *   K         the library's table lookup (trk_amplitude_init_table) on an
 *             amplitude table made in memory by tools/gen/amp_table.c at
 *             exactly this (nu, snr_db, pfa), uniform grid of `amp_size`
 *             points (default Q2_AMP_TABLE_SIZE); the table's own errors can
 *             be measured against the direct K model (kdist.h): ln l^a and
 *             a(x) to ~1e-7 at 256 points (see docs/library.md), negligible against
 *             the Monte Carlo standard errors (>= 1e-5)
 * pd is S1(t), the ROC value: the library's for Rayleigh; for K the
 * generator's double-precision value (kdist.h), which the table stores.
 *
 * Speed: x = -ln u is computed by the vectorised q2_log (q2_fastmath.h) over
 * the whole block, then the two library calls per amplitude (see
 * tools/trk-bench/bench_q2.c for the rates). Deterministic: a pure function
 * of (model, u), whatever the thread. */
#ifndef TRK_Q2_AMP_H
#define TRK_Q2_AMP_H

#include <stddef.h>

#include "q2_is.h"
#include "trk/amplitude.h"

#define Q2_AMP_TABLE_SIZE 64u    /* points of each K amplitude table curve */

struct q2_amp {
    struct trk_amplitude m;   /* the library's model (K: views `table`) */
    unsigned char *table;     /* K: the amplitude table (malloc'd); NULL for Rayleigh */
    size_t table_len;         /* its bytes */
    int model;                /* enum trk_amp_model */
    double nu, snr_db, pfa;
    double pd;                /* S1(t) */
    double threshold;         /* t (clutter power 1) */
    int measured;             /* K with measure: the table's errors below */
    double err_log_lr, err_inv_sf;
};

/* model TRK_AMP_RAYLEIGH (nu ignored) or TRK_AMP_K (0 < nu <= 1e6);
 * snr_db in [-30, 60], pfa in (0, 1). amp_size: points per K table curve
 * (0: Q2_AMP_TABLE_SIZE); measure: measure the K table's errors (slower).
 * 0, or -1 with a message. */
int q2_amp_init(struct q2_amp *a, int model, double nu, double snr_db, double pfa, unsigned amp_size,
                int measure, char *err, size_t errlen);
void q2_amp_free(struct q2_amp *a);

/* A model as bytes, for work units that carry their results as bytes
 * (tools/par: trk-tablegen-mpi builds the models of a PDAFAI table on all
 * its ranks): q2_amp_pack writes *a (its table copied) into buf of
 * q2_amp_packed_size(table_len) bytes (8-aligned); q2_amp_unpack makes the
 * same model from them in *a (the table copied, the library's model on it;
 * free with q2_amp_free). 0, or -1 with a message. */
size_t q2_amp_packed_size(size_t table_len);
size_t q2_amp_table_len(const struct q2_amp *a);
void q2_amp_pack(const struct q2_amp *a, void *buf);
int q2_amp_unpack(struct q2_amp *a, const void *buf, size_t len, char *err, size_t errlen);

/* The sampler over *a (a must outlive it and not move). */
struct q2_amp_sampler q2_amp_sampler_of(const struct q2_amp *a);

/* "rayleigh" / "k" -> enum trk_amp_model, or 0. */
int q2_amp_model_parse(const char *s);
const char *q2_amp_model_name(int model);

#endif
