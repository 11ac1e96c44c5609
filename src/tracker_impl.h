/* tracker_impl.h (private) - what the tracker's files share:
 *   tracker.c              the scan, stage by stage (trk_tracker_process_scan),
 *                          and trk_tracker_init
 *   tracker_update_impl.h  one track's update: predict, gate, PDA, visibility
 *                          (included by tracker.c)
 *   tracker_params.c       parameters: defaults, the check naming the field
 * The tracker runs the CV model: state [x, vx, y, vy] (TRK_CV2_*), position
 * measurements [x, y]. */
#ifndef TRK_TRACKER_IMPL_H
#define TRK_TRACKER_IMPL_H

#include "pda_impl.h"
#include "track_tests.h"
#include "trk/tracker.h"

/* Short names in the tracker's files: the CV state [x, vx, y, vy], its
 * measurement [x, y], and the row-major indices of P (4 x 4) and S, R (2 x 2). */
#define NX TRK_CV2_NX
#define NZ TRK_CV2_NZ
#define X TRK_CV2_X
#define VX TRK_CV2_VX
#define Y TRK_CV2_Y
#define VY TRK_CV2_VY
#define ZX TRK_CV2_ZX
#define ZY TRK_CV2_ZY
#define P(i, j) TRK_CV2_P(i, j)
#define S(i, j) TRK_CV2_S(i, j)

/* A packed covariance [xx, xy, yy] (TRK_COV2_*) as the 2x2 matrix r
 * (TRK_CV2_S), unchecked: for one trk_i_cov2_unpack accepted before (a
 * detection loaded, a candidate stored). The one place of the layout. */
TRK_INLINE void trk_i_cov2_matrix(const trk_real c[3], trk_real r[NZ * NZ])
{
    r[S(ZX, ZX)] = c[TRK_COV2_XX];
    r[S(ZX, ZY)] = r[S(ZY, ZX)] = c[TRK_COV2_XY];
    r[S(ZY, ZY)] = c[TRK_COV2_YY];
}

/* The same, checked: TRK_E_NAN non-finite, TRK_E_NOT_SPD not positive
 * definite or too ill-conditioned for the arithmetic (TRK_COV2_MIN_REL_DET,
 * trk/tracker.h; xx yy must not overflow): r is then not written. */
TRK_INLINE trk_status trk_i_cov2_unpack(const trk_real c[3], trk_real r[NZ * NZ])
{
    const trk_real xx = c[TRK_COV2_XX], xy = c[TRK_COV2_XY], yy = c[TRK_COV2_YY];
    if (!isfinite(xx) || !isfinite(xy) || !isfinite(yy)) return TRK_E_NAN;
    const trk_real xxyy = xx * yy;
    if (!(xx > 0 && yy > 0 && xxyy <= TRK_REAL_MAX && xxyy - xy * xy > TRK_COV2_MIN_REL_DET * xxyy))
        return TRK_E_NOT_SPD;
    trk_i_cov2_matrix(c, r);
    return TRK_OK;
}

/* What the parameter check builds on its way, for trk_tracker_init to
 * keep: the caller's storage, since the layout of the test models depends on
 * TRK_WITH_CLUTTER_TESTS and tracker.c may be built in the other
 * configuration (tests/test_tracker_noclutter.mk); the check only passes the
 * model pointers on to trk_i_tests_init. */
struct trk_i_tracker_built {
    struct trk_pda *pda;                     /* [TRK_MAX_SENSORS] */
    trk_real (*r)[NZ * NZ];                  /* [TRK_MAX_SENSORS] */
    struct trk_visibility_model *vis;
    union trk_confirm_model *confirm;
    union trk_term_model *term;
};

/* trk_tracker_check_params, building into *b (tracker_params.c). */
trk_status trk_i_tracker_check(const struct trk_tracker_params *p, const char **field,
                               const struct trk_i_tracker_built *b);

#endif
