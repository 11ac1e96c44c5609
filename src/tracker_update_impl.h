/* tracker_update_impl.h (private) - one track's update in a scan: predict
 * to the scan time, gate, the PDA over the gated set (pda_impl.h, the same
 * code as trk_pda_update), visibility, commit, and the look for its tests.
 * The PDA is inlined with the CV model's constant dimensions, so its small
 * matrix loops unroll (one shared copy in size-optimised builds).
 *
 * Included by tracker.c only: these functions use struct trk_tracker, whose
 * layout depends on TRK_WITH_CLUTTER_TESTS, TRK_WITH_JOINT and TRK_WITH_IMM
 * (config.h), and tests/test_tracker_noclutter.mk, test_tracker_nojoint.mk
 * and test_tracker_imm.mk rebuild tracker.c in another configuration. An
 * IMM track's stages are tracker_imm_impl.h's, included at the end. */
#ifndef TRK_TRACKER_UPDATE_IMPL_H
#define TRK_TRACKER_UPDATE_IMPL_H

#include "grid_impl.h"
#include "tracker_impl.h"

/* One track's prediction for this scan, and the same as the PDA takes it
 * (pp points into this struct: it is filled in place and never copied). */
struct pred {
    trk_real x[NX], p[NX * NX], pht[NX * NZ];
    struct trk_innovation inn;
    struct trk_i_pda_pred pp;
};

static trk_status track_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                                struct pred *pr);
static int track_gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                      const struct pred *pr, size_t off, struct trk_i_pda_set *set);
static trk_status track_pda(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                            struct trk_i_pda_set *set, struct trk_i_pda_out *out);
static trk_status predict(const struct trk_tracker *t, const struct trk_track *tr,
                          const struct trk_scan *scan, struct pred *pr);
static trk_status pred_finish(const struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr);
static int gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                const struct trk_i_pda_pred *pp, size_t off, struct trk_i_pda_set *set);
static struct trk_i_grid_box ws_box(const struct trk_tracker *t, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                                    trk_real hi_y);
static trk_status update_visibility(const struct trk_tracker *t, const struct trk_pda *pda,
                                    const struct trk_i_pda_set *set, const struct trk_i_pda_out *out,
                                    struct trk_visibility *vis);
static void commit(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                   const struct trk_i_pda_set *set, const uint16_t *cand, const struct pred *pr,
                   const struct trk_visibility *vis, trk_real beta0);
static void build_look(const struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                       const struct trk_innovation *inn, const struct trk_i_pda_out *out, struct trk_look *look);

#if TRK_WITH_IMM
static int imm_on(const struct trk_tracker *t);
static trk_status imm_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                              struct pred *pr);
static int imm_gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan, size_t off,
                    struct trk_i_pda_set *set);
static trk_status imm_weights(struct trk_tracker *t, const struct trk_scan *scan, const struct trk_i_pda_set *set,
                              const uint16_t *cand, trk_real *w);
static trk_status imm_update(struct trk_tracker *t, const struct trk_scan *scan, const struct trk_i_pda_set *set,
                             trk_real beta0, struct pred *pr);
static trk_real maneuver_d2(const struct trk_i_pda_set *set, const struct trk_innovation *inn);
#endif

/* Is the position uncertainty of covariance p over the bound
 * (max_pos_sigma_ratio) of the scan's sensor? */
static int over_covariance_bound(const struct trk_tracker *t, const trk_real *p, unsigned sensor)
{
    const trk_real bound = t->max_pos_var_m2[sensor];
    return bound > 0 && p[P(X, X)] + p[P(Y, Y)] > bound;
}

/* Predict track tr to the scan time, gate the scan's valid detections (the
 * workspace), PDA-update it and mark the detections it used; *look gets what
 * the scan told its tests. 0; 1 when the prediction is already over the
 * covariance bound (the track has lost its target: it is ended without
 * gating, which with so wide a gate would be a pass over most of the scan
 * for a track that the bound ends anyway); -1 on a numerical failure (tr
 * untouched). */
static int track_update(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                        struct trk_look *look)
{
    const struct trk_pda *pda = &t->pda[scan->sensor_id];
    struct pred pr;
    struct trk_i_pda_set set;
    struct trk_i_pda_out out;
    if (track_predict(t, tr, scan, &pr) != TRK_OK) return -1;
    if (over_covariance_bound(t, pr.p, scan->sensor_id)) return 1;
    if (track_gate(t, tr, scan, &pr, 0, &set) < 0) return -1; /* one track's set fits: TRK_I_PAIRS >= TRK_MAX_DETECTIONS */
    if (track_pda(t, scan, &pr, &set, &out) != TRK_OK) return -1; /* pr.x, pr.p: the posterior */
    struct trk_visibility vis = tr->vis;
    if (t->params.track_visibility && update_visibility(t, pda, &set, &out, &vis) != TRK_OK) return -1;
    commit(t, tr, scan, &set, t->ws.cand, &pr, &vis, out.beta0);
    build_look(t, tr, scan, &pr.inn, &out, look);
    return 0;
}

/* The track's prediction: predict(), or an IMM track's imm_predict(). */
static trk_status track_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                                struct pred *pr)
{
#if TRK_WITH_IMM
    if (imm_on(t)) return imm_predict(t, tr, scan, pr);
#endif
    return predict(t, tr, scan, pr);
}

/* Its gated set with ln e_i from pair off on: gate(), or an IMM track's
 * union of gates and mixture weights. 1 when cut (as gate()), -1 on a
 * numerical failure (cannot happen), else 0. */
static int track_gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                      const struct pred *pr, size_t off, struct trk_i_pda_set *set)
{
#if TRK_WITH_IMM
    if (imm_on(t)) {
        const int cut = imm_gate(t, tr, scan, off, set);
        return imm_weights(t, scan, set, t->ws.cand + off, set->w) != TRK_OK ? -1 : cut;
    }
#endif
    return gate(t, tr, scan, &pr->pp, off, set);
}

/* The PDA over the gated set: *out, beta_i into set->w, the posterior over
 * pr->x, pr->p (checked). */
static trk_status track_pda(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                            struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    const struct trk_pda *pda = &t->pda[scan->sensor_id];
#if TRK_WITH_IMM
    if (imm_on(t)) {
        trk_i_pda_clutter(pda, &pr->pp, set, out);
        if (set->m_gated > 0) {
            trk_i_pda_find_w_max(set);
            out->beta0 = trk_i_pda_normalise(trk_i_pda_log_e0(pda, out->lambda), set->n, set->w, set->w_max, out);
        }
        return imm_update(t, scan, set, out->beta0, pr);
    }
#endif
    const trk_status st = trk_i_pda_run(pda, &pr->pp, set, out);
    /* the PDA checked a posterior it formed; with nothing gated it is the
     * prediction: check that one here (one factorisation per track) */
    return st == TRK_OK && set->m_gated == 0 ? trk_i_spd(NX, pr->p) : st;
}


/* CV prediction to the scan time, checked (finite, variances > 0; its
 * positive definiteness is checked once it is known to be the posterior),
 * and its innovation (S = H P H'
 * + R of the scan's sensor; TRK_E_NOT_SPD when S is not positive definite). */
static trk_status predict(const struct trk_tracker *t, const struct trk_track *tr,
                          const struct trk_scan *scan, struct pred *pr)
{
    const trk_real dt = (trk_real)(scan->time_us - tr->time_us) * TRK_REAL_C(1e-6);
    for (int i = 0; i < NX; i++) pr->x[i] = tr->x[i];
    for (int i = 0; i < NX * NX; i++) pr->p[i] = tr->p[i];
    trk_i_cv2_predict(dt, t->params.process_noise_q, pr->x, pr->p);
    return pred_finish(t, scan, pr);
}

/* The prediction pr->x, pr->p checked, its view for the PDA, and its
 * innovation. */
static trk_status pred_finish(const struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr)
{
    const trk_status st = trk_i_pda_check(NX, pr->x, pr->p);
    if (st != TRK_OK) return st;
    const struct trk_i_pda_pred pp = {NX, NZ, trk_cv2_h, trk_i_cv2_sel(), t->r[scan->sensor_id],
                                      pr->x, pr->p, pr->pht, &pr->inn};
    pr->pp = pp;
    return trk_i_innovation_sel(NX, NZ, trk_cv2_h, trk_i_cv2_sel(), t->r[scan->sensor_id], pr->x, pr->p, pr->pht,
                                &pr->inn);
}

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

/* Workspace marks (ws.used) of a detection: no track gated it, a
 * tentative track did or it fell in a confirmed track's exclusion zone (it
 * starts no track), or a confirmed track gated it (no tentative track may
 * use it either). */
enum { USED_NONE = 0, USED_NO_START = 1, USED_CONFIRMED = 2 };

static size_t gate_add(struct trk_tracker *t, struct gate *gt, size_t j, const trk_real *r_j);

/* Is detection j at d2 inside the gate (d2 <= gamma)? If not, and d2 <= g,
 * the exclusion mark: it starts no track. */
static int gate_inside(struct trk_tracker *t, const struct gate *gt, size_t j, trk_real d2)
{
    if (trk_gate_inside(d2, gt->gamma)) return 1;
    if (d2 <= gt->g && t->ws.used[j] == USED_NONE) t->ws.used[j] = USED_NO_START;
    return 0;
}

/* Detection j passed the bounding box: the ellipse d2 <= gamma adds it to
 * the gated set with its ln e_i (and its R_j when it has its own, r_j not
 * NULL); gamma < d2 <= g only marks it, so that it starts no track. */
static void gate_ellipse(struct trk_tracker *t, struct gate *gt, size_t j, const trk_real *nu,
                         const trk_real *l_inv, trk_real log_det, const trk_real *r_j)
{
    const trk_real d2 = trk_i_mahalanobis2(NZ, l_inv, nu);
    if (!gate_inside(t, gt, j, d2)) return;
    const size_t n = gate_add(t, gt, j, r_j);
    if (n < gt->cap) trk_i_pda_set_w(gt->set, n, trk_i_pda_log_e(gt->pda, log_det, d2, t->ws.log_lr[j]));
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

/* A detection with its own covariance: R_j and S_j = H P H' + R_j; 0 when
 * it is outside the bounding box of d2 <= g (or S_j is not SPD: cannot
 * happen), else L_j^-1 and ln det S_j. */
static int own_box(const struct trk_tracker *t, const struct trk_scan *scan, const struct trk_i_pda_pred *pp,
                   size_t j, trk_real g, const trk_real *nu, trk_real *r_j, trk_real *l_inv, trk_real *log_det)
{
    trk_real s[NZ * NZ];
    trk_i_cov2_matrix(scan->detections[t->ws.src[j]].cov_m2, r_j); /* checked at load */
    trk_i_pda_own_s(pp, r_j, s);
    if (trk_fabs(nu[ZX]) > trk_sqrt(g * s[S(ZX, ZX)]) || trk_fabs(nu[ZY]) > trk_sqrt(g * s[S(ZY, ZY)]))
        return 0;
    return trk_i_pda_factor(NZ, s, l_inv, log_det) == TRK_OK;
}

/* An empty gated set for track tr in the workspace pairs from off on, and
 * its gate: gamma, and g = init_exclusion_d2 for a confirmed track. */
static struct gate gate_begin(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                              size_t off, struct trk_i_pda_set *set)
{
    const struct trk_pda *pda = &t->pda[scan->sensor_id];
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

/* Gate the valid detections into the track's gated set (workspace pairs
 * cand, w = ln e_i from pair off on, z and r_own from 0): the bounding box of
 * the ellipse d2 <= g (cheap: the detections with the sensor's covariance
 * share S and its box), then the ellipse (gate_ellipse). g =
 * init_exclusion_d2 for a confirmed track, else gamma. The set holds the
 * shared-covariance detections first (n_shared), then the own-covariance
 * ones, each in workspace order. 1 when the pairs from off on could not hold
 * the whole set (gating then stops: the caller drops a cut set, and the
 * track is gated again alone, which marks the exclusion zone), else 0. */
static int gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                const struct trk_i_pda_pred *pp, size_t off, struct trk_i_pda_set *set)
{
    const struct trk_innovation *inn = pp->inn;
    struct gate gt = gate_begin(t, tr, scan, off, set);
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
                gate_ellipse(t, &gt, j, nu, inn->s_chol_inv, inn->log_det_s, NULL);
            }
        }
    for (size_t j = n_shared; j < n_valid && !gt.full; j++) {
        const trk_real nu[NZ] = {t->ws.x[j] - zx, t->ws.y[j] - zy};
        trk_real r_j[NZ * NZ], l_inv[NZ * NZ], log_det;
        if (tentative && used[j] == USED_CONFIRMED) continue;
        if (own_box(t, scan, pp, j, gt.g, nu, r_j, l_inv, &log_det)) gate_ellipse(t, &gt, j, nu, l_inv, log_det, r_j);
    }
    set->m_gated = set->n;
    return gt.full;
}

/* The box query of the shared group (gating's index ws.grid, grid_impl.h):
 * per column the box overlaps, the points of its rows. */
static struct trk_i_grid_box ws_box(const struct trk_tracker *t, trk_real lo_x, trk_real hi_x, trk_real lo_y,
                                    trk_real hi_y)
{
    return trk_i_grid_box(&t->ws.grid, t->ws.cell_end, lo_x, hi_x, lo_y, hi_y);
}

/* Kennedy eqs 21-24 with the PDA weights: ln sum_i (g_D,i / rho) l_i =
 * ln sum_i e_i - ln P_D - ln lambda (e_i = P_D g_D,i l_i; lambda = 0: +inf,
 * a certain detection). */
static trk_status update_visibility(const struct trk_tracker *t, const struct trk_pda *pda,
                                    const struct trk_i_pda_set *set, const struct trk_i_pda_out *out,
                                    struct trk_visibility *vis)
{
    trk_real log_sum = trk_i_pda_log_sum_e(out);
    if (set->n > 0) {
        /* ln P_D and, for parametric clutter, ln lambda from trk_pda_init's logs */
        const trk_real log_pd = pda->log_pd_norm + TRK_REAL_C(0.5) * (trk_real)pda->params.nz * TRK_LN_2PI;
        const trk_real log_lambda = pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->log_e0_param - pda->log_miss
                                                                                 : trk_log(out->lambda);
        log_sum = out->lambda > 0 ? log_sum - log_pd - log_lambda : (trk_real)INFINITY;
    }
    return trk_visibility_update_log(&t->vis_model, vis, pda->params.pd, pda->params.gate_prob, log_sum);
}

/* The update is accepted: from here on the track changes. The posterior
 * (pr->x, pr->p), its visibility and beta0 into the track; its gated
 * detections (cand) start no track. */
static void commit(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                   const struct trk_i_pda_set *set, const uint16_t *cand, const struct pred *pr,
                   const struct trk_visibility *vis, trk_real beta0)
{
    const uint8_t mark = tr->status == TRK_TRACK_CONFIRMED ? USED_CONFIRMED : USED_NO_START;
    for (size_t i = 0; i < set->n; i++)
        if (t->ws.used[cand[i]] < mark) t->ws.used[cand[i]] = mark;
    for (int i = 0; i < NX; i++) tr->x[i] = pr->x[i];
    for (int i = 0; i < NX * NX; i++) tr->p[i] = pr->p[i];
    tr->vis = *vis;
    tr->beta0_last = beta0;
    tr->time_us = scan->time_us;
    tr->n_gated_last = (uint16_t)set->n;
#if TRK_WITH_IMM
    tr->maneuver_d2 = maneuver_d2(set, &pr->inn);
    if (imm_on(t)) tr->imm = t->ws.imm.s;
#endif
}

/* The clutter tests' inputs (Kennedy eqs 5-9, 13-15): the scan's detection
 * nearest the prediction (smallest d2 with the sensor's S), rho V_g of the
 * ellipse it encloses, and its amplitude (dB) against the scan's others
 * (workspace amp_db holds the amplitudes twice over, so the others of entry
 * k are the n_amp - 1 entries from k + 1). */
static void clutter_look(const struct trk_tracker *t, const struct trk_innovation *inn, trk_real rho,
                         struct trk_look *look)
{
    trk_real best = TRK_REAL_MAX;
    size_t jb = 0;
    for (size_t j = 0; j < t->ws.n_valid; j++) {
        const trk_real nu[NZ] = {t->ws.x[j] - inn->z_pred[ZX], t->ws.y[j] - inn->z_pred[ZY]};
        const trk_real d2 = trk_i_mahalanobis2(NZ, inn->s_chol_inv, nu);
        if (d2 < best || (d2 == best && t->ws.src[j] < t->ws.src[jb])) { /* ties: the first in scan order */
            best = d2;
            jb = j;
        }
    }
    look->has_nearest = 1;
    look->nearest = jb;
    look->rho_vg = rho * trk_gate_volume_inn(inn, best);
    if (t->ws.amp_pos[jb] >= 0) {
        const size_t k = (size_t)t->ws.amp_pos[jb];
        look->has_amp = 1;
        look->a_assoc_db = t->ws.amp_db[k];
        look->n_others = t->ws.n_amp - 1;
        look->a_others_db = t->ws.amp_db + k + 1;
    }
}

/* What this scan told the track's tests: the one place a look is built
 * (the M/N test's first look at initiation apart). */
static void build_look(const struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                       const struct trk_innovation *inn, const struct trk_i_pda_out *out, struct trk_look *look)
{
    look->detected = tr->n_gated_last > 0;
    look->sensor_id = scan->sensor_id;
    look->n_gated = (int)tr->n_gated_last;
    look->pfa_gate = -trk_expm1(-out->lambda * out->gate_volume);
    look->beta0 = out->beta0;
    look->has_nearest = 0;
    look->nearest = 0;
    look->rho_vg = 0;
    look->has_amp = 0;
    look->a_assoc_db = 0;
    look->n_others = 0;
    look->a_others_db = t->ws.amp_db;
    if (tr->status == TRK_TRACK_TENTATIVE && trk_i_confirm_needs_nearest(&t->params) && t->ws.n_valid > 0)
        clutter_look(t, inn, t->pda[scan->sensor_id].params.clutter_density, look);
}

#if TRK_WITH_IMM
#include "tracker_imm_impl.h"
#endif

#endif
