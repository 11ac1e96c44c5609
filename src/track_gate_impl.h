/* track_gate_impl.h (private) - gating into a track's gated set: the
 * set's start (gate_begin), the test of one detection (gate_inside: the
 * gate d2 <= gamma, and the exclusion zone that starts no track), adding it
 * with its own R_j, the box of a detection with its own covariance, and
 * gate(): the whole scan against one Gaussian prediction through gating's
 * 2-D index. A filter with one Gaussian prediction (CV, alpha-beta) gates
 * with gate(); the IMM builds its union of models' gates from the same
 * pieces.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_TRACK_GATE_IMPL_H
#define TRK_TRACK_GATE_IMPL_H

#include "grid_impl.h"
#include "tracker_internal.h"

/* One track's gate while it is built (see gate()). */
struct gate {
    const struct trk_pda *pda;
    trk_real gamma;            /* the gate d2 <= gamma */
    trk_real g;                /* and the exclusion zone d2 <= g */
    struct trk_i_pda_set *set; /* the gated set being filled, */
    uint16_t *cand;            /* its detections' workspace indices */
    size_t cap;                /* room for at most cap of them */
    int full;                  /* one more was gated */
};

/* Is detection j at d2 inside the gate (d2 <= gamma)? If not, and d2 <= g,
 * the exclusion mark: it starts no track. */
static int gate_inside(struct trk_tracker *t, const struct gate *gt, size_t j, trk_real d2)
{
    if (trk_gate_inside(d2, gt->gamma)) return 1;
    if (d2 <= gt->g && t->ws.used[j] == USED_NONE) t->ws.used[j] = USED_NO_START;
    return 0;
}

/* Detection j (its R_j when r_j is not NULL) into the gated set: its index
 * there, or gt->cap when the set is full (gt->full is then set). */
static size_t gate_add(struct trk_tracker *t, struct gate *gt, size_t j, const trk_real *r_j)
{
    struct trk_i_pda_set *set = gt->set;
    if (set->n == gt->cap) {
        gt->full = 1;
        return gt->cap;
    }
    const size_t n = set->n++;
    gt->cand[n] = (uint16_t)j;
    t->ws.u.set.z[NZ * n + ZX] = t->ws.x[j];
    t->ws.u.set.z[NZ * n + ZY] = t->ws.y[j];
    if (r_j)
        for (int i = 0; i < NZ * NZ; i++) t->ws.u.set.r_own[NZ * NZ * (n - set->n_shared) + i] = r_j[i];
    else
        set->n_shared = n + 1;
    return n;
}

/* Detection j passed the bounding box: the ellipse d2 <= gamma adds it to
 * the gated set with its ln e_i (and its R_j when it has its own, r_j not
 * NULL); gamma < d2 <= g only marks it, so that it starts no track. Inline
 * in the loop over the detections that share the sensor's covariance (a
 * call per pair was a quarter of a scan with every detection in every gate);
 * gate_ellipse is the same out of line, for the own-covariance loop whose
 * factorisation per pair dwarfs a call (and the firmware image stays
 * small). */
TRK_INLINE void gate_ellipse_inline(struct trk_tracker *t, struct gate *gt, size_t j, const trk_real *nu,
                                    const trk_real *l_inv, trk_real log_det, const trk_real *r_j)
{
    const trk_real d2 = trk_i_mahalanobis2(NZ, l_inv, nu);
    if (!gate_inside(t, gt, j, d2)) return;
    const size_t n = gate_add(t, gt, j, r_j);
    if (n < gt->cap) trk_i_pda_set_w(gt->set, n, trk_i_pda_log_e(gt->pda, log_det, d2, t->ws.log_lr[j]));
}

static void gate_ellipse(struct trk_tracker *t, struct gate *gt, size_t j, const trk_real *nu, const trk_real *l_inv,
                         trk_real log_det, const trk_real *r_j)
{
    gate_ellipse_inline(t, gt, j, nu, l_inv, log_det, r_j);
}

/* A detection with its own covariance: R_j and S_j = H P H' + R_j; 0 when
 * it is outside the bounding box of d2 <= g (or S_j is not SPD: cannot
 * happen), else L_j^-1 and ln det S_j. */
static int own_box(const struct trk_tracker *t, const struct trk_scan *scan, const struct trk_i_pda_pred *pp,
                   size_t j, trk_real g, const trk_real *nu, trk_real *r_j, trk_real *l_inv, trk_real *log_det)
{
    trk_real s[NZ * NZ];
    det_r(t, scan, j, r_j); /* checked at load */
    trk_i_pda_own_s(pp, r_j, s);
    if (trk_fabs(nu[ZX]) > trk_sqrt(g * s[S(ZX, ZX)]) || trk_fabs(nu[ZY]) > trk_sqrt(g * s[S(ZY, ZY)]))
        return 0;
    return trk_i_pda_factor(NZ, s, l_inv, log_det) == TRK_OK;
}

/* An empty gated set for track tr in the workspace pairs from off on, and
 * its gate: gamma, and g = init_exclusion_d2 for a confirmed track. */
static struct gate gate_begin(struct trk_tracker *t, const struct trk_track *tr, const struct trk_pda *pda,
                              size_t off, struct trk_i_pda_set *set)
{
    const trk_real excl = t->params.init_exclusion_d2;
    struct gate gt = {pda, pda->gamma, tr->status == TRK_TRACK_CONFIRMED && excl > pda->gamma ? excl : pda->gamma,
                      set, t->ws.cand + off, TRK_I_PAIRS - off, 0};
    set->n = set->n_shared = set->m_gated = 0;
    set->w_max = -(trk_real)INFINITY;
    set->w_arg = 0;
    set->z = t->ws.u.set.z;
    set->w = t->ws.w + off;
    set->r_own = t->ws.u.set.r_own;
    return gt;
}

/* The box query of the shared group (gating's index ws.grid, grid_impl.h):
 * per column the box overlaps, the points of its rows. */
static struct trk_i_grid_box ws_box(const struct trk_tracker *t, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                                    trk_real hi_y)
{
    return trk_i_grid_box(&t->ws.grid, t->ws.cell_end, lo_x, hi_x, lo_y, hi_y);
}

/* The box query of the own-covariance group (ws.grid_own): its points'
 * positions count from n_shared. */
static struct trk_i_grid_box ws_box_own(const struct trk_tracker *t, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                                        trk_real hi_y)
{
    return trk_i_grid_box(&t->ws.grid_own, t->ws.cell_end_own, lo_x, hi_x, lo_y, hi_y);
}

/* The half-widths of the box that holds d2 <= g of every own-covariance
 * detection for a prediction of covariance p: S_j = H P H' + R_j, so per
 * axis P's variance plus the group's largest variance, a little wider for
 * the rounding (own_box then tests each exactly). P itself, not S - R: that
 * difference loses P when the sensor's R is far larger (by half an ulp of
 * R, which a relative pad does not cover). */
static void own_box_widths(const struct trk_tracker *t, const trk_real *p, trk_real g, trk_real *wx, trk_real *wy)
{
    const trk_real pad = 1 + 16 * TRK_REAL_EPS;
    *wx = trk_sqrt(g * (p[P(X, X)] + t->ws.own_var_max_m2[0])) * pad;
    *wy = trk_sqrt(g * (p[P(Y, Y)] + t->ws.own_var_max_m2[1])) * pad;
}

/* Gate the valid detections into the track's gated set (workspace pairs
 * cand, w = ln e_i from pair off on, z and r_own from 0): the bounding box of
 * the ellipse d2 <= g (cheap: the detections with the sensor's covariance
 * share S and its box), then the ellipse (gate_ellipse). g =
 * init_exclusion_d2 for a confirmed track, else gamma. The set holds the
 * shared-covariance detections first (n_shared), then the own-covariance
 * ones (through their own index, in a box wide enough for the largest of
 * their covariances), each in workspace order. 1 when the pairs from off on could not hold
 * the whole set (gating then stops: the caller drops a cut set, and the
 * track is gated again alone, which marks the exclusion zone), else 0. */
static int gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                const struct pred *pr, size_t off, struct trk_i_pda_set *set)
{
    const struct trk_i_pda_pred *pp = &pr->pp;
    const struct trk_innovation *inn = pp->inn;
    struct gate gt = gate_begin(t, tr, pr->pda, off, set);
    const trk_real wx = trk_sqrt(gt.g * inn->s[S(ZX, ZX)]), wy = trk_sqrt(gt.g * inn->s[S(ZY, ZY)]);
    const trk_real zx = inn->z_pred[ZX], zy = inn->z_pred[ZY];
    const size_t n_shared = t->ws.n_shared, n_valid = t->ws.n_valid;
    const uint8_t *used = t->ws.used;
    const int tentative = tr->status == TRK_TRACK_TENTATIVE;
    struct trk_i_grid_box box = ws_box(t, zx - wx, zx + wx, zy - wy, zy + wy);
    size_t j0, j1;
    while (!gt.full && trk_i_grid_next(&box, &j0, &j1)) /* a cut set is dropped: stop at the cut */
        for (size_t j = j0; j < j1 && !gt.full; j++) {
            const trk_real dx = t->ws.x[j] - zx, dy = t->ws.y[j] - zy;
            if (trk_fabs(dx) <= wx && trk_fabs(dy) <= wy && !(tentative && used[j] == USED_CONFIRMED)) {
                const trk_real nu[NZ] = {dx, dy}; /* formed in the box only (measured: 2 % of the scan) */
                gate_ellipse_inline(t, &gt, j, nu, inn->s_chol_inv, inn->log_det_s, NULL);
            }
        }
    if (n_valid > n_shared && !gt.full) { /* the own-covariance group through its index */
        trk_real owx, owy;
        own_box_widths(t, pp->p, gt.g, &owx, &owy);
        struct trk_i_grid_box obox = ws_box_own(t, zx - owx, zx + owx, zy - owy, zy + owy);
        while (!gt.full && trk_i_grid_next(&obox, &j0, &j1))
            for (size_t j = n_shared + j0; j < n_shared + j1 && !gt.full; j++) {
                const trk_real nu[NZ] = {t->ws.x[j] - zx, t->ws.y[j] - zy};
                trk_real r_j[NZ * NZ], l_inv[NZ * NZ], log_det;
                if (tentative && used[j] == USED_CONFIRMED) continue;
                if (own_box(t, scan, pp, j, gt.g, nu, r_j, l_inv, &log_det))
                    gate_ellipse(t, &gt, j, nu, l_inv, log_det, r_j);
            }
    }
    set->m_gated = set->n;
    return gt.full;
}

#endif
