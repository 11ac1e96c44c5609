/* fixed_point_impl.h (private) - stopping rule of the fixed-point iterations
 * of mre.c and crlb.c (Riccati-type maps that contract linearly).
 *
 * With successive changes c_k = max|X_k - X_{k-1}| shrinking at the rate
 * r = c_k / c_{k-1} < 1, the distance to the fixed point is about
 * c_k r / (1 - r): near r = 1 (a slowly contracting map, e.g. Brekke's model
 * at ~0.9 per step) it is many times the last change, so stopping on the
 * change alone leaves 1/(1 - r) times the tolerance. The rule stops when
 *   c_k max(1, r / (1 - r)) <= rel_tol max|X_k|   (r < 1),
 * or when the iteration has reached its rounding floor: c_k <= 1024 eps
 * max|X_k| and no smaller change for 200 steps. */
#ifndef TRK_FIXED_POINT_IMPL_H
#define TRK_FIXED_POINT_IMPL_H

#include "trk/types.h"

struct trk_i_fixed_point {
    trk_real prev_change; /* c_{k-1}; 0 before the first step */
    trk_real best;        /* smallest change below the rounding floor so far */
    int stall;            /* steps without a smaller change at the floor */
};

static inline void trk_i_fixed_point_init(struct trk_i_fixed_point *f)
{
    f->prev_change = 0;
    f->best = TRK_REAL_MAX;
    f->stall = 0;
}

/* 1 when the iteration has converged after a step with change c and scale s. */
static inline int trk_i_fixed_point_done(struct trk_i_fixed_point *f, trk_real c, trk_real s,
                                         trk_real rel_tol)
{
    int done = 0;
    if (c == 0) {
        done = 1;
    } else if (f->prev_change > 0 && c < f->prev_change) {
        const trk_real r = c / f->prev_change;
        const trk_real amp = r / (1 - r);
        done = c * (amp > 1 ? amp : 1) <= rel_tol * s;
    }
    if (!done && c <= 1024 * TRK_REAL_EPS * s) {
        if (c < f->best) {
            f->best = c;
            f->stall = 0;
        } else if (++f->stall >= 200) {
            done = 1;
        }
    }
    f->prev_change = c;
    return done;
}

#endif
