/* baseline.h - BENCHMARK BASELINES, NOT LIBRARY CODE: plain
 * fixed-size loops of the arithmetic a library function does, timed in the
 * same run as the library for trk-bench's "<name>_vs_baseline" ratio lines. */
#ifndef TRK_BENCH_BASELINE_H
#define TRK_BENCH_BASELINE_H

#include <stddef.h>

#include "trk/types.h"

/* One 2-D CV track's predict + gate + parametric PDAF update. */
struct baseline_pda {
    trk_real dt_s, q;  /* scan interval, CV process noise (m^2/s^3) */
    trk_real r[4];     /* R (2 x 2) */
    trk_real pd, pg;   /* P_D, P_G */
    trk_real lambda;   /* clutter density (1/m^2) */
    trk_real gamma;    /* gate threshold on d2 */
};

/* x [x, vx, y, vy] and P (4 x 4) of the last scan in, the posterior out;
 * beta[0, m) the detections' weights (0 outside the gate). */
void baseline_pda_cv2(const struct baseline_pda *b, trk_real x[4], trk_real p[16], size_t m,
                      const trk_real *z, trk_real *beta);
/* The same loop compiled at -O2 -funroll-loops (baseline_pda_o2.c). */
void baseline_pda_cv2_o2(const struct baseline_pda *b, trk_real x[4], trk_real p[16], size_t m,
                         const trk_real *z, trk_real *beta);

#endif
