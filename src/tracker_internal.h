/* tracker_internal.h (private) - the bottom of the tracker: what every
 * module of the scan shares (the short names of the state and measurement,
 * the packed covariance, one track's prediction, the detections' marks) and
 * the parameter check's interface. It includes nothing of the tracker.
 *
 * The scan is one translation unit, tracker.c, built from modules that each
 * include only what is below them (docs/architecture.md "The scan's
 * modules"), bottom up:
 *   tracker_internal.h      this file
 *   tracker_index_impl.h    the 2-D index order and a small sort
 *   track_pred_impl.h       a prediction's view for the PDA, the covariance bound
 *   track_gate_impl.h       gating one Gaussian prediction into a gated set
 *   filter_cv_impl.h        the CV Kalman filter        } the track filters,
 *   filter_imm_impl.h       the IMM (TRK_WITH_IMM)      } one interface:
 *   filter_ab_impl.h        the alpha-beta filter       } track_filter_impl.h
 *   track_filter_impl.h     the interface: the one place a model is chosen
 *   track_commit_impl.h     an accepted update into the track, its look
 *   track_life_impl.h       confirmation and termination of one track
 *   tracker_detection_impl.h  is a detection usable
 *   the stages: tracker_load_impl.h (with tracker_thin_impl.h),
 *     tracker_update_impl.h, tracker_joint_impl.h, tracker_merge_impl.h,
 *     tracker_initiate_impl.h
 *   tracker.c               the scan as the list of its stages
 * tracker_params.c (parameters: defaults, the check naming the field) is a
 * translation unit of its own on this file.
 * The tracker's state is the CV model's [x, vx, y, vy] (TRK_CV2_*) whatever
 * the filter; measurements are positions [x, y]. */
#ifndef TRK_TRACKER_INTERNAL_H
#define TRK_TRACKER_INTERNAL_H

#include "pda_impl.h"
#include "clutter_map.h"
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

/* One track's prediction for this scan, and the same as the PDA takes it
 * (pp points into this struct: it is filled in place and never copied).
 * What the sensor is to this track: its R (a polar sensor's at the
 * predicted position, else the sensor's), its P_D there (0: the sensor
 * cannot see it this scan) with the PDA's constants for it (P_D and lambda
 * at the track), and its covariance bound (0: none). A track's own R and
 * PDA constants live in the workspace (ws.track_r, ws.track_pda: off the
 * firmware's stack), valid until the next track's prediction: one track is
 * predicted and updated at a time. */
struct pred {
    trk_real x[NX], p[NX * NX], pht[NX * NZ];
    struct trk_innovation inn;
    struct trk_i_pda_pred pp;
    const trk_real *r;          /* R: ws.track_r or the sensor's */
    trk_real pd;                /* P_D at the prediction */
    const struct trk_pda *pda;  /* the PDA's constants there: ws.track_pda or the sensor's */
    trk_real bound_m2;          /* the covariance bound on tr P (max_pos_sigma_ratio) */
#if TRK_WITH_ALPHA_BETA
    struct trk_cv_steady ab[2]; /* the alpha-beta filter's steady state per axis (x, y) */
#endif
};

/* 1/u_s of sensor sp's persistent returns: ln persistent_pd / ln pfa
 * (persistent_share > 0 only with a Rayleigh model: checked at init). */
TRK_INLINE trk_real persistent_inv_u(const struct trk_sensor_params *sp)
{
    return trk_i_amplitude_inv_u(&sp->amplitude, sp->persistent_pd);
}

/* Scan detection i's amplitude into *a (its caller's, polar or Cartesian):
 * whether it has one. */
TRK_INLINE int scan_amplitude(const struct trk_scan *scan, size_t i, trk_real *a)
{
    if (scan->polar) {
        *a = scan->polar[i].amplitude;
        return scan->polar[i].has_amplitude;
    }
    *a = scan->detections[i].amplitude;
    return scan->detections[i].has_amplitude;
}

/* ---- The scan's sensor at a position (the view ws.view, set once per
 * scan: sensor_view.h) */

/* Is the scan's sensor polar? */
TRK_INLINE int scan_polar(const struct trk_tracker *t) { return t->ws.view.sp->kind == TRK_SENSOR_POLAR; }

/* P_D of the scan's sensor at (x, y): its profile and coverage
 * (trk_sensor_pd_at), else its PDA's P_D (with an amplitude model, the
 * model's). */
TRK_INLINE trk_real sensor_pd_at(const struct trk_tracker *t, const struct trk_scan *scan, trk_real x, trk_real y)
{
    const trk_real flat = t->pda[scan->sensor_id].params.pd;
    if (!t->ws.view.limited) return flat; /* no call for a sensor that sees everywhere alike */
    const trk_real pd = trk_i_view_pd(&t->ws.view, flat, x, y);
    if (t->ws.view.sp->pd_profile.n == 0) return pd;
    /* a thinned scan's factor, or with amplitudes its power (S1 at the raised threshold) */
    return t->ws.pd_power != 1 ? trk_pow(pd, t->ws.pd_power) : pd * t->ws.pd_scale;
}

/* lambda of the scan's sensor at (x, y): its clutter profile (scaled as
 * the scan's thinning scaled lambda), else its PDA's. */
TRK_INLINE trk_real sensor_lambda_at(const struct trk_tracker *t, const struct trk_scan *scan, trk_real x, trk_real y)
{
    if (!t->ws.view.clutter_varies) return t->pda[scan->sensor_id].params.clutter_density;
    const trk_real lambda = t->ws.view.map ? trk_i_map_lambda_at(&t->ws.view, x, y) : trk_i_view_clutter(&t->ws.view, x, y);
    return lambda * t->ws.lambda_scale;
}

/* ln(lambda(x, y) / lambda_sensor) of the scan's sensor: what a new track's
 * initial odds (init_log_odds, over the sensor's lambda) lose at (x, y). */
TRK_INLINE trk_real sensor_log_lambda_ratio(const struct trk_tracker *t, const struct trk_scan *scan, trk_real x,
                                            trk_real y)
{
    if (!t->ws.view.clutter_varies) return 0;
    return trk_log(sensor_lambda_at(t, scan, x, y)) - trk_log(t->pda[scan->sensor_id].params.clutter_density);
}

/* R of the scan's sensor for a track predicted at (x, y): a polar
 * sensor's conversion covariance there (trk_polar_cov), but sigma_r^2 I
 * nearer than sigma_r / sigma_b (where the cross-range spread falls below
 * the range's and vanishes at the pose: a track's R must stay positive
 * definite); else the sensor's R. Written into r_own, returned. */
TRK_INLINE const trk_real *sensor_r_at(const struct trk_tracker *t, const struct trk_scan *scan, trk_real x,
                                       trk_real y, trk_real r_own[NZ * NZ])
{
    if (!scan_polar(t)) return t->r[scan->sensor_id];
    const struct trk_sensor_params *sp = t->ws.view.sp;
    const trk_real dx = x - t->ws.view.pose.x_m, dy = y - t->ws.view.pose.y_m;
    const trk_real vr = sp->sigma_range_m * sp->sigma_range_m, vb = sp->sigma_bearing_rad * sp->sigma_bearing_rad;
    if ((dx * dx + dy * dy) * vb < vr) return t->r[scan->sensor_id]; /* sigma_r^2 I: tracker_params.c */
    trk_real c[3];
    trk_polar_cov(sp, dx, dy, c);
    trk_i_cov2_matrix(c, r_own);
    return r_own;
}

/* Workspace detection j's own covariance [xx, xy, yy] (the own group,
 * j >= ws.n_shared): a polar sensor's conversion covariance at its position
 * unless the caller gave its own; else the caller's. The same values every
 * time (load checked them). */
TRK_INLINE void det_cov(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real c[3])
{
    if (scan->polar || !scan->detections[t->ws.src[j]].has_cov) {
        trk_polar_cov(t->ws.view.sp, t->ws.x[j] - t->ws.view.pose.x_m, t->ws.y[j] - t->ws.view.pose.y_m, c);
        return;
    }
    const trk_real *d = scan->detections[t->ws.src[j]].cov_m2;
    c[0] = d[0];
    c[1] = d[1];
    c[2] = d[2];
}

/* The same as a 2 x 2 matrix. */
TRK_INLINE void det_r(const struct trk_tracker *t, const struct trk_scan *scan, size_t j, trk_real r[NZ * NZ])
{
    trk_real c[3];
    det_cov(t, scan, j, c);
    trk_i_cov2_matrix(c, r);
}

/* Workspace marks (ws.used) of a detection: no track gated it, a
 * tentative track did or it fell in a confirmed track's exclusion zone (it
 * starts no track), or a confirmed track gated it (no tentative track may
 * use it either). */
enum { USED_NONE = 0, USED_NO_START = 1, USED_CONFIRMED = 2 };

TRK_INLINE int is_live(const struct trk_track *tr)
{
    return tr->status == TRK_TRACK_TENTATIVE || tr->status == TRK_TRACK_CONFIRMED;
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
