/* filter_imm_impl.h (private) - the IMM as a track filter (track_filter_impl.h) (TRK_WITH_IMM,
 * params.imm.n_models >= 1; trk/imm.h, docs/conventions.md "Multiple models (IMM)";
 * docs/library.md "Manoeuvres"). The stages are a CV track's (predict, gate, weights,
 * update, commit, look); at each an IMM track does:
 *   predict  mixing and each model's prediction (trk_imm_mix,
 *            trk_imm_predict), each model's innovation with the sensor's R,
 *            and their combination with the predicted mode probabilities c_m
 *            (moment matching), which the look, the clutter tests and the
 *            gate volume of the PDA's clutter terms use;
 *   gate     the union of the models' gates (docs/conventions.md IMM-PDA: d2_m <=
 *            gamma for at least one model m); the exclusion zone likewise;
 *   weights  per model and gated detection the PDA's ln e_mi with model m's
 *            S (no gate of its own), and the track's weight of the
 *            detection, the mixture e_i = sum_m c_m e_mi;
 *   update   the association weights beta_i, beta0 come from the track's
 *            e_i: the PDA's normalisation (alone), or the joint events'
 *            marginals (TRK_ASSOC_JOINT: the mixture is then the
 *            track-detection likelihood of an IMM track). Given detection i
 *            the mode is m with rho_mi = c_m e_mi / e_i, given no detection
 *            with c_m, so model m's posterior probability is
 *            mu_m = sum_i beta_i rho_mi + beta0 c_m and its PDA update takes
 *            beta_mi = beta_i rho_mi / mu_m, beta_m0 = beta0 c_m / mu_m
 *            (the Gaussian mixture over association events and modes,
 *            collapsed per mode). Alone this is the IMM-PDA of docs/conventions.md
 *            (mu_m ~ c_m Lambda_m, each model's own PDA weights); with
 *            one model the PDA. Then the combination into the track's x, P.
 * Existence (IPDA/JIPDA) takes the mixture weights as a CV track takes its
 * own. A model with mu_m = 0 (it underflowed) keeps its prediction. A
 * model's weight beta_mi below the smallest normal is exactly 0
 * (trk_i_pda_weight: a detection gated by one model but some 38 sigma from
 * another gives that one about 1e-315, whose moments overflow); mu_m itself
 * is left as computed.
 *
 * Included by tracker.c's modules only (tracker_internal.h). */
#ifndef TRK_FILTER_IMM_IMPL_H
#define TRK_FILTER_IMM_IMPL_H

#include <string.h>

#include "track_gate_impl.h"
#include "track_pred_impl.h"

/* A new track (x, P set): every model starts there, with equal mode
 * probabilities (as MATLAB trackingIMM's default). */
static void imm_start(const struct trk_tracker *t, struct trk_track *tr)
{
    const int n = t->params.imm.n_models;
    tr->maneuver_d2 = 0;
    memset(&tr->imm, 0, sizeof tr->imm);
    for (int m = 0; m < n; m++) {
        for (int i = 0; i < NX; i++) tr->imm.x[m][i] = tr->x[i];
        for (int i = 0; i < NX * NX; i++) tr->imm.p[m][i] = tr->p[i];
        tr->imm.mu[m] = 1 / (trk_real)n;
    }
}

/* Model m's prediction as the PDA takes it (the workspace's). */
static struct trk_i_pda_pred imm_model_pred(struct trk_tracker *t, const struct trk_scan *scan, int m)
{
    (void)scan;
    const struct trk_i_pda_pred pp = {NX,
                                      NZ,
                                      trk_cv2_h,
                                      trk_i_cv2_sel(),
                                      t->ws.imm.r[m],
                                      t->ws.imm.s.x[m],
                                      t->ws.imm.s.p[m],
                                      t->ws.imm.pht[m],
                                      &t->ws.imm.inn[m]};
    return pp;
}

/* Mix and predict the models of tr into the workspace (ws.imm), each
 * model's innovation, and their combination with c_m into *pr (with its
 * innovation, as predict()). A gap of 0 (two sensors at one time) neither
 * mixes nor moves: c = mu. A model with c_m = 0 (unreachable from the
 * others this scan, e.g. p_stay = 1) is predicted (trk_imm_predict) but not
 * checked, and gates nothing, weighs nothing and keeps its prediction. */
static trk_status imm_predict(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                              struct pred *pr)
{
    const struct trk_imm_params *mp = &t->params.imm;
    const trk_real dt = (trk_real)(scan->time_us - tr->time_us) * TRK_REAL_C(1e-6);
    struct trk_imm_state *s = &t->ws.imm.s;
    trk_status st = TRK_OK;
    *s = tr->imm;
    if (dt > 0) {
        st = trk_imm_mix(mp, s, t->ws.imm.c);
        if (st == TRK_OK) st = trk_imm_predict(mp, dt, s);
    } else { /* p_ij is per scan interval: over no time, the identity */
        for (int m = 0; m < mp->n_models; m++) t->ws.imm.c[m] = s->mu[m];
    }
    for (int m = 0; m < mp->n_models && st == TRK_OK; m++) {
        t->ws.imm.log_c[m] = t->ws.imm.c[m] > 0 ? trk_log(t->ws.imm.c[m]) : -(trk_real)INFINITY;
        if (!(t->ws.imm.c[m] > 0)) continue; /* unreachable this scan: weight 0, never used */
        st = trk_i_pda_check(NX, s->x[m], s->p[m]);
        if (st == TRK_OK) {
            trk_real *r = t->ws.imm.r[m];
            const trk_real *r_m = sensor_r_at(t, scan, s->x[m][X], s->x[m][Y], r);
            if (r_m != r)
                for (int i = 0; i < NZ * NZ; i++) r[i] = r_m[i];
            st = trk_i_innovation_sel(NX, NZ, trk_cv2_h, trk_i_cv2_sel(), r, s->x[m], s->p[m], t->ws.imm.pht[m],
                                      &t->ws.imm.inn[m]);
            if (st != TRK_OK && !(sensor_pd_at(t, scan, s->x[m][X], s->x[m][Y]) > 0)) {
                /* out of the sensor's sight the conversion's R may not factor
                 * (pred_finish): the model gates nothing there, so the
                 * sensor's own R gives its innovation the form it needs */
                for (int i = 0; i < NZ * NZ; i++) r[i] = t->r[scan->sensor_id][i];
                st = trk_i_innovation_sel(NX, NZ, trk_cv2_h, trk_i_cv2_sel(), r, s->x[m], s->p[m],
                                          t->ws.imm.pht[m], &t->ws.imm.inn[m]);
            }
        }
    }
    if (st != TRK_OK) return st;
    for (int m = 0; m < mp->n_models; m++) s->mu[m] = t->ws.imm.c[m];
    trk_imm_combine(mp, s, pr->x, pr->p);
    return pred_finish(t, scan, pr);
}

/* Model m's d2 of workspace detection j with its own R_j, or +inf when it
 * is outside model m's bounding box of d2 <= g. */
static trk_real imm_d2_own(struct trk_tracker *t, const struct trk_scan *scan, int m, size_t j, trk_real g)
{
    const struct trk_innovation *inn = &t->ws.imm.inn[m];
    const trk_real nu[NZ] = {t->ws.x[j] - inn->z_pred[ZX], t->ws.y[j] - inn->z_pred[ZY]};
    const struct trk_i_pda_pred pp = imm_model_pred(t, scan, m);
    trk_real r_own[NZ * NZ], l_inv[NZ * NZ], log_det;
    if (!own_box(t, scan, &pp, j, g, nu, r_own, l_inv, &log_det)) return (trk_real)INFINITY;
    return trk_i_mahalanobis2(NZ, l_inv, nu);
}

/* The box [lo_x, hi_x] x [lo_y, hi_y] of several boxes: none yet, and one
 * more, of centre (cx, cy) and half-widths (wx, wy). */
struct span {
    trk_real lo_x, hi_x, lo_y, hi_y;
};

static struct span span_empty(void)
{
    const struct span e = {TRK_REAL_MAX, -TRK_REAL_MAX, TRK_REAL_MAX, -TRK_REAL_MAX};
    return e;
}

static void span_add(struct span *b, trk_real cx, trk_real cy, trk_real wx, trk_real wy)
{
    if (cx - wx < b->lo_x) b->lo_x = cx - wx;
    if (cx + wx > b->hi_x) b->hi_x = cx + wx;
    if (cy - wy < b->lo_y) b->lo_y = cy - wy;
    if (cy + wy > b->hi_y) b->hi_y = cy + wy;
}

/* An IMM track's models' gates: per model (of weight > 0) the half-widths
 * of its bounding box of d2 <= g (-1: the model bounds nothing), and the
 * box that bounds them all. */
struct imm_box {
    int n_models, tentative;
    trk_real wx[TRK_MAX_MODELS], wy[TRK_MAX_MODELS];
    struct span all; /* the box of the boxes */
};

/* Workspace detection j into the IMM track's set when some model's
 * ellipse d2 <= gamma holds it (a detection of the shared group only
 * inside the box of all the models' boxes). */
static void imm_gate_one(struct trk_tracker *t, const struct trk_scan *scan, struct gate *gt,
                         const struct imm_box *b, size_t j)
{
    const struct trk_innovation *inn = t->ws.imm.inn;
    const trk_real x = t->ws.x[j], y = t->ws.y[j];
    const int own = j >= t->ws.n_shared;
    if ((b->tentative && t->ws.used[j] == USED_CONFIRMED) ||
        (!own && (x < b->all.lo_x || x > b->all.hi_x || y < b->all.lo_y || y > b->all.hi_y)))
        return;
    trk_real d2 = (trk_real)INFINITY;
    for (int m = 0; m < b->n_models; m++) {
        if (!(b->wx[m] >= 0)) continue;
        const trk_real nu[NZ] = {x - inn[m].z_pred[ZX], y - inn[m].z_pred[ZY]};
        trk_real d2_m = (trk_real)INFINITY;
        if (own) d2_m = imm_d2_own(t, scan, m, j, gt->g);
        else if (trk_fabs(nu[ZX]) <= b->wx[m] && trk_fabs(nu[ZY]) <= b->wy[m])
            d2_m = trk_i_mahalanobis2(NZ, inn[m].s_chol_inv, nu);
        if (d2_m < d2) d2 = d2_m;
    }
    if (!gate_inside(t, gt, j, d2)) return;
    trk_real r_j[NZ * NZ];
    if (own) det_r(t, scan, j, r_j); /* checked at load */
    (void)gate_add(t, gt, j, own ? r_j : NULL);
}

/* gate() for an IMM track: the union of its models' gates, into the set
 * (no weights yet: imm_weights). A detection with the sensor's covariance
 * is tested against the models' ellipses only inside the box that bounds
 * all their bounding boxes of d2 <= g (gating's index), then the ones with
 * their own covariance inside the box of the models' boxes for the largest
 * of those covariances (their index). */
static int imm_gate(struct trk_tracker *t, const struct trk_track *tr, const struct trk_scan *scan,
                    const struct pred *pr, size_t off, struct trk_i_pda_set *set)
{
    struct gate gt = gate_begin(t, tr, pr->pda, off, set);
    const struct trk_innovation *inn = t->ws.imm.inn;
    struct imm_box b = {t->params.imm.n_models, tr->status == TRK_TRACK_TENTATIVE, {0}, {0}, span_empty()};
    for (int m = 0; m < b.n_models; m++) {
        b.wx[m] = b.wy[m] = -1; /* a model of weight 0 bounds nothing */
        if (!(t->ws.imm.c[m] > 0)) continue;
        b.wx[m] = trk_sqrt(gt.g * inn[m].s[S(ZX, ZX)]);
        b.wy[m] = trk_sqrt(gt.g * inn[m].s[S(ZY, ZY)]);
        span_add(&b.all, inn[m].z_pred[ZX], inn[m].z_pred[ZY], b.wx[m], b.wy[m]);
    }
    struct trk_i_grid_box box = ws_box(t, b.all.lo_x, b.all.hi_x, b.all.lo_y, b.all.hi_y);
    size_t j0, j1;
    while (!gt.full && trk_i_grid_next(&box, &j0, &j1)) /* a cut set is dropped: stop at the cut */
        for (size_t j = j0; j < j1 && !gt.full; j++) imm_gate_one(t, scan, &gt, &b, j);
    if (t->ws.n_valid > t->ws.n_shared && !gt.full) { /* the own-covariance group: the box of */
        struct span own = span_empty();
        for (int m = 0; m < b.n_models; m++) { /* the models' own-covariance boxes */
            if (!(b.wx[m] >= 0)) continue;
            trk_real owx, owy;
            own_box_widths(t, t->ws.imm.s.p[m], gt.g, &owx, &owy);
            span_add(&own, inn[m].z_pred[ZX], inn[m].z_pred[ZY], owx, owy);
        }
        struct trk_i_grid_box obox = ws_box_own(t, own.lo_x, own.hi_x, own.lo_y, own.hi_y);
        while (!gt.full && own.lo_x <= own.hi_x && trk_i_grid_next(&obox, &j0, &j1))
            for (size_t j = t->ws.n_shared + j0; j < t->ws.n_shared + j1 && !gt.full; j++)
                imm_gate_one(t, scan, &gt, &b, j);
    }
    set->m_gated = set->n;
    return gt.full;
}

/* The models' weights of the gated set (detections cand[i]): ln e_mi (the
 * PDA's, with model m's S_mi) into ws.imm.rho as rho_mi = c_m e_mi / e_i,
 * and the track's ln e_i = ln sum_m c_m e_mi into w[i] (w may be NULL). An
 * own-covariance S_mi that is not SPD (cannot happen: the gate factored it)
 * gives TRK_E_NOT_SPD. */
static trk_status imm_weights(struct trk_tracker *t, const struct trk_scan *scan, const struct trk_pda *pda,
                              const struct trk_i_pda_set *set, const uint16_t *cand, trk_real *w)
{
    const int n = t->params.imm.n_models;
    for (size_t i = 0; i < set->n; i++) {
        trk_real le[TRK_MAX_MODELS], mx = -(trk_real)INFINITY;
        const trk_real nz_i[NZ] = {set->z[NZ * i + ZX], set->z[NZ * i + ZY]};
        for (int m = 0; m < n; m++) {
            const trk_real c = t->ws.imm.c[m]; /* ln c_m once per track: ws.imm.log_c */
            le[m] = -(trk_real)INFINITY;
            if (!(c > 0)) continue;
            const struct trk_i_pda_pred pp = imm_model_pred(t, scan, m);
            const struct trk_innovation *inn = pp.inn;
            const trk_real nu[NZ] = {nz_i[ZX] - inn->z_pred[ZX], nz_i[ZY] - inn->z_pred[ZY]};
            trk_real l_own[NZ * NZ], log_det = inn->log_det_s;
            const trk_real *l_inv = inn->s_chol_inv;
            if (i >= set->n_shared) {
                trk_real s_own[NZ * NZ];
                trk_i_pda_own_s(&pp, set->r_own + NZ * NZ * (i - set->n_shared), s_own);
                if (trk_i_pda_factor(NZ, s_own, l_own, &log_det) != TRK_OK) return TRK_E_NOT_SPD;
                l_inv = l_own;
            }
            le[m] = t->ws.imm.log_c[m] + trk_i_pda_log_e(pda, log_det, trk_i_mahalanobis2(NZ, l_inv, nu),
                                                 t->ws.log_lr[cand[i]]);
            if (le[m] > mx) mx = le[m];
        }
        trk_real sum = 0;
        for (int m = 0; m < n; m++) sum += (le[m] = mx > -TRK_REAL_MAX ? trk_exp(le[m] - mx) : 0);
        for (int m = 0; m < n; m++) t->ws.imm.rho[m][i] = sum > 0 ? le[m] / sum : 0;
        if (w) w[i] = sum > 0 ? mx + trk_log(sum) : -(trk_real)INFINITY;
    }
    return TRK_OK;
}

/* The models' PDA updates with the track's association weights (set->w =
 * beta_i, beta0; the top of this file), their posterior mode probabilities,
 * and the combination into pr->x, pr->p, checked (TRK_E_NAN, TRK_E_NOT_SPD;
 * the track is then untouched: all of it is workspace). */
static trk_status imm_update(struct trk_tracker *t, const struct trk_scan *scan, const struct trk_i_pda_set *set,
                             trk_real beta0, struct pred *pr)
{
    const struct trk_imm_params *mp = &t->params.imm;
    struct trk_imm_state *s = &t->ws.imm.s;
    trk_real total = 0;
    for (int m = 0; m < mp->n_models; m++) {
        trk_real *b = t->ws.imm.rho[m];
        trk_real mu = beta0 * t->ws.imm.c[m];
        for (size_t i = 0; i < set->n; i++) mu += (b[i] *= set->w[i]);
        s->mu[m] = mu;
        total += mu;
        if (!(mu > 0)) continue; /* keeps its prediction */
        for (size_t i = 0; i < set->n; i++) b[i] = trk_i_pda_weight(b[i] / mu); /* subnormal: 0 */
        struct trk_i_pda_set sm = *set;
        sm.w = b;
        const struct trk_i_pda_pred pp = imm_model_pred(t, scan, m);
        const trk_status st = set->n > 0 ? trk_i_pda_run_beta(&pp, &sm, beta0 * t->ws.imm.c[m] / mu)
                                         : trk_i_spd(NX, s->p[m]);
        if (st != TRK_OK) return st;
    }
    if (!(total > 0)) return TRK_E_NAN;
    for (int m = 0; m < mp->n_models; m++) s->mu[m] /= total;
    trk_imm_combine(mp, s, pr->x, pr->p);
    const trk_status st = trk_i_pda_check(NX, pr->x, pr->p);
    return st != TRK_OK ? st : trk_i_spd(NX, pr->p);
}

/* The PDA's weights of the track's gated set (its mixture e_i), then the
 * models' updates with them: *out, beta_i into set->w, the posterior over
 * pr->x, pr->p (checked). */
static trk_status imm_pda(struct trk_tracker *t, const struct trk_scan *scan, struct pred *pr,
                          struct trk_i_pda_set *set, struct trk_i_pda_out *out)
{
    pda_weights(pr->pda, pr, set, out);
    return imm_update(t, scan, set, out->beta0, pr);
}

#endif
