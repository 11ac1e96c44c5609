/* mtt_oracle.c - the known-association bound of trk-sim mtt (mtt_oracle.h). */
#include "mtt_oracle.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* [xx, xy, yy] as a 2 x 2 row-major matrix. */
static void cov_full(const trk_real c[3], trk_real r[TRK_CV2_NZ * TRK_CV2_NZ])
{
    r[TRK_CV2_S(0, 0)] = c[TRK_COV2_XX];
    r[TRK_CV2_S(0, 1)] = r[TRK_CV2_S(1, 0)] = c[TRK_COV2_XY];
    r[TRK_CV2_S(1, 1)] = c[TRK_COV2_YY];
}

int mtt_oracle_init(struct mtt_oracle *o, size_t n_targets, const trk_real cov_m2[3], trk_real q_m2_per_s3)
{
    if (!o || !cov_m2) return -1;
    memset(o, 0, sizeof *o);
    const trk_real xx = cov_m2[TRK_COV2_XX], xy = cov_m2[TRK_COV2_XY], yy = cov_m2[TRK_COV2_YY];
    if (!(xx > 0 && yy > 0 && xx * yy - xy * xy > 0) || !(q_m2_per_s3 >= 0) || !isfinite(q_m2_per_s3)) return -1;
    if (n_targets && !(o->tr = calloc(n_targets, sizeof *o->tr))) return -1;
    cov_full(cov_m2, o->r_m2);
    o->q_m2_per_s3 = q_m2_per_s3;
    o->n_targets = n_targets;
    return 0;
}

void mtt_oracle_free(struct mtt_oracle *o)
{
    free(o->tr);
    o->tr = NULL;
    o->n_targets = 0;
}

int mtt_oracle_scan(struct mtt_oracle *o, const struct trk_scan *scan, const long *origin,
                    struct mtt_oracle_report *rep)
{
    struct mtt_oracle_report r = {0, 0, 0};
    if (!o || !scan || (scan->n_detections && (!scan->detections || !origin))) return -1;
    const double t_s = 1e-6 * (double)scan->time_us;
    /* the running tracks to the scan's time: a target missed keeps its prediction */
    for (size_t i = 0; i < o->n_targets; i++) {
        struct mtt_oracle_track *k = &o->tr[i];
        if (k->state != MTT_ORACLE_TRACK) continue;
        if (t_s < k->t_s) return -1;
        if (t_s > k->t_s && trk_cv2_predict((trk_real)(t_s - k->t_s), o->q_m2_per_s3, k->x, k->p) != TRK_OK)
            return -1;
        k->t_s = t_s;
    }
    for (size_t j = 0; j < scan->n_detections; j++) {
        if (origin[j] < 0) continue; /* clutter */
        if ((size_t)origin[j] >= o->n_targets) return -1;
        struct mtt_oracle_track *k = &o->tr[origin[j]];
        const struct trk_detection *d = &scan->detections[j];
        const trk_real z[TRK_CV2_NZ] = {d->x_m, d->y_m};
        trk_real rd[TRK_CV2_NZ * TRK_CV2_NZ];
        if (d->has_cov) cov_full(d->cov_m2, rd);
        else memcpy(rd, o->r_m2, sizeof rd);
        r.n_target_det++;
        switch (k->state) {
        case MTT_ORACLE_NONE:
            k->state = MTT_ORACLE_ONE;
            k->t0_s = t_s;
            memcpy(k->z0_m, z, sizeof z);
            memcpy(k->r0_m2, rd, sizeof rd);
            break;
        case MTT_ORACLE_ONE:
            if (!(t_s > k->t0_s)) break; /* a second one of the first scan: the first is kept */
            if (trk_cv2_two_point(k->z0_m, k->r0_m2, z, rd, (trk_real)(t_s - k->t0_s), k->x, k->p) != TRK_OK)
                return -1;
            k->state = MTT_ORACLE_TRACK;
            k->t_s = t_s;
            k->start_scan = o->scans;
            r.n_started++;
            break;
        case MTT_ORACLE_TRACK:
            if (trk_kalman_update(TRK_CV2_NX, TRK_CV2_NZ, trk_cv2_h, rd, z, k->x, k->p) != TRK_OK) return -1;
            r.n_updated++;
            break;
        default: /* ended: the target has gone */
            break;
        }
    }
    o->scans++;
    if (rep) *rep = r;
    return 0;
}

int mtt_oracle_end(struct mtt_oracle *o, size_t i)
{
    if (!o || i >= o->n_targets || o->tr[i].state == MTT_ORACLE_ENDED) return 0;
    const int had = o->tr[i].state == MTT_ORACLE_TRACK;
    o->tr[i].state = MTT_ORACLE_ENDED;
    return had;
}

const struct mtt_oracle_track *mtt_oracle_track(const struct mtt_oracle *o, size_t i)
{
    if (!o || i >= o->n_targets || o->tr[i].state != MTT_ORACLE_TRACK) return NULL;
    return &o->tr[i];
}
