/* amp_sample.h - amplitudes of detections that crossed a detection threshold,
 * for simulators (trk-sonar-sim, trk-sim).
 *
 * Convention (docs/conventions.md "Amplitude models"): amplitudes are linear envelope
 * values in units of sqrt(mean clutter power) (P = 1). Given the texture v,
 * clutter is Rayleigh with E[a^2 | v] = v, a Swerling I target with
 * E[a^2 | v] = v + D, D = 10^(snr_db/10):
 *   rayleigh  v = 1:                 S0(a) = exp(-a^2),  S1(a) = exp(-a^2/(1+D))
 *   k         v ~ Gamma(nu, mean 1): S0, S1 from tools/gen/kdist.h
 * The threshold t solves S0(t) = pfa; a target is detected with P_D = S1(t).
 * A detection's amplitude is drawn by inverting its truncated survival
 * function: x ~ Exp(1), a = S^-1(S(t) e^-x) (so a >= t):
 *   rayleigh  the library's closed form (trk/amplitude.h: trk_amplitude_init_rayleigh,
 *             trk_amplitude_inv_sf: a^2 = t^2 + x, target t^2 + (1 + D) x)
 *   k         kdist_inv_sf, the offline high-accuracy model (root of the log
 *             survival, ~1e-12 relative); the library does K only through an
 *             amplitude table (trk_amplitude_init_table), one SNR per table
 *
 *   table     an amplitude table of trk-tablegen (any model, e.g. K), loaded
 *             and checked by the library (trk_table_load_file,
 *             trk_amplitude_init_table) and sampled with trk_amplitude_inv_sf;
 *             the table fixes pfa, SNR (every target gets the table's) and P
 *
 * Adding a model: an enum value, its case in amp_model_init, amp_target_init
 * and amp_draw. */
#ifndef TRK_TOOLS_AMP_SAMPLE_H
#define TRK_TOOLS_AMP_SAMPLE_H

#include <stddef.h>

#include "kdist.h"
#include "rng.h"
#include "trk/amplitude.h"

enum amp_kind { AMP_NONE = 0, AMP_RAYLEIGH = 1, AMP_K = 2, AMP_TABLE = 3 };

struct amp_model {
    int kind;           /* enum amp_kind */
    double pfa;         /* threshold P_FA, (0, 1) */
    double nu;          /* K shape (AMP_K) */
    double t;           /* threshold amplitude, S0(t) = pfa */
    struct kdist k0;    /* AMP_K: the clutter law */
    struct trk_amplitude lib; /* AMP_RAYLEIGH: the clutter law; AMP_TABLE: the table's model */
    void *table_bytes;        /* AMP_TABLE: the table (lib views it) */
};

/* What a target of one SNR needs. */
struct amp_target {
    double snr_db;
    double d;           /* linear SNR */
    double pd;          /* S1(t): detection probability at the threshold */
    struct kdist k1;    /* AMP_K: the target law */
    struct trk_amplitude lib; /* AMP_RAYLEIGH: the library model at this SNR */
};

/* 0, or -1 with a message (pfa not in (0,1), nu not in (0, 1e6], ...).
 * AMP_NONE is valid: no amplitudes, amp_draw must not be called. */
int amp_model_init(struct amp_model *m, int kind, double pfa, double nu, char *err, size_t errlen);

/* An amplitude table file (kind AMP_TABLE). 0, or -1 with a message. */
int amp_model_init_table(struct amp_model *m, const char *path, char *err, size_t errlen);

/* Release a table (any kind; safe to call twice). */
void amp_model_free(struct amp_model *m);

/* 0, or -1 (snr_db outside [-50, 80] or not finite). AMP_NONE: pd = NaN;
 * AMP_TABLE: snr_db is ignored, the table's SNR and P_D are used. */
int amp_target_init(const struct amp_model *m, double snr_db, struct amp_target *tg);

/* Amplitude of a clutter detection (tg == NULL) or of target tg, >= t.
 * 0, or -1 when the K inversion does not converge (*a untouched). */
int amp_draw(const struct amp_model *m, const struct amp_target *tg, struct rng *r, double *a);

/* "none", "rayleigh", "k" -> enum (or -1). */
int amp_kind_parse(const char *s);
const char *amp_kind_name(int kind);

#endif
