/* tracker.c - the preallocated track table and the scan (trk/tracker.h).
 *
 * The only module that loops over tracks. Per track it runs the shared PDA
 * stages of pda_impl.h with the constant dimensions of the CV model, so the
 * compiler unrolls the small matrix loops. */
#include "trk/tracker.h"

#include <string.h>

#include "pda_impl.h"
#include "trk/gate.h"
#include "track_tests.h"

#define NX TRK_CV2_NX
#define NZ TRK_CV2_NZ

/* the CV model's H picks x (0) and y (2) */
static const int cv2_sel[NZ] = {0, 2};

void trk_tracker_default_params(struct trk_tracker_params *p)
{
    /* filled in place: a local copy would put ~1 KB on a firmware stack */
    memset(p, 0, sizeof *p);
    p->n_sensors = 1;
    p->sensor[0].pd = TRK_REAL_C(0.9);
    p->sensor[0].meas_cov_m2[0] = 1;
    p->sensor[0].meas_cov_m2[1] = 0;
    p->sensor[0].meas_cov_m2[2] = 1;
    p->sensor[0].clutter_density_per_m2 = TRK_REAL_C(1e-4);
    p->process_noise_q = TRK_REAL_C(0.01);
    p->gate_prob = TRK_REAL_C(0.99);
    p->clutter = TRK_CLUTTER_PARAMETRIC;
    p->init_speed_sigma_mps = 5;
    p->max_dt_s = 3600;
    p->confirm.method = TRK_CONFIRM_MN;
    p->confirm.u.mn.m = 3;
    p->confirm.u.mn.n = 5;
    p->confirm.u.mn.mode = TRK_MN_FIXED;
    p->term.method = TRK_TERM_KN;
    p->term.u.kn.k = 0;
    p->term.u.kn.n = 5;
    p->max_tentative_scans = 0;
    p->merge_gate_d2 = 4;
    p->init_exclusion_d2 = TRK_REAL_C(18.420680743952367); /* -2 ln 1e-4: 99.99 % of a target's
                                                              detections */
    p->track_visibility = 1; /* Kennedy's Table 1 style IPDA parameters */
    p->visibility.pv0 = TRK_REAL_C(0.5);
    p->visibility.pcv0 = TRK_REAL_C(0.5);
    p->visibility.delta_stay = TRK_REAL_C(0.99);
    p->visibility.delta_become = TRK_REAL_C(0.01);
    p->visibility.omega_c = TRK_REAL_C(0.75);
    p->visibility.p_con = TRK_REAL_C(0.9);
    p->visibility.p_term = TRK_REAL_C(0.1);
}

/* [xx, xy, yy] -> 2x2 matrix; TRK_E_NAN / TRK_E_NOT_SPD. */
static trk_status cov2(const trk_real c[3], trk_real r[NZ * NZ])
{
    if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2])) return TRK_E_NAN;
    if (!(c[0] > 0 && c[2] > 0 && c[0] * c[2] - c[1] * c[1] > 0)) return TRK_E_NOT_SPD;
    r[0] = c[0];
    r[1] = r[2] = c[1];
    r[3] = c[2];
    return TRK_OK;
}

trk_status trk_tracker_init(struct trk_tracker *t, const struct trk_tracker_params *p)
{
    struct trk_pda pda[TRK_MAX_SENSORS];
    trk_real r[TRK_MAX_SENSORS][NZ * NZ];
    if (!t || !p) return TRK_E_ARG;
    if (p->n_sensors < 1 || p->n_sensors > TRK_MAX_SENSORS) return TRK_E_RANGE;
    if (p->clutter != TRK_CLUTTER_PARAMETRIC && p->clutter != TRK_CLUTTER_NONPARAMETRIC)
        return TRK_E_ARG;
    if (!isfinite(p->process_noise_q) || !isfinite(p->gate_prob) ||
        !isfinite(p->init_speed_sigma_mps) || !isfinite(p->max_dt_s) || !isfinite(p->merge_gate_d2) ||
        !isfinite(p->init_exclusion_d2))
        return TRK_E_NAN;
    if (!(p->merge_gate_d2 >= 0) || !(p->init_exclusion_d2 >= 0)) return TRK_E_RANGE;
    if (!(p->process_noise_q >= 0) || !(p->init_speed_sigma_mps > 0) || !(p->max_dt_s > 0) ||
        !(p->max_dt_s <= TRK_REAL_C(1e9)))
        return TRK_E_RANGE;
    for (unsigned s = 0; s < p->n_sensors; s++) {
        const struct trk_sensor_params *sp = &p->sensor[s];
        struct trk_pda_params pp;
        pp.nz = NZ;
        if (sp->use_amplitude != 0 && sp->use_amplitude != 1) return TRK_E_ARG;
        if (sp->use_amplitude) {
            /* PDAFAI: P_D at the amplitude threshold (CONVENTIONS "PDA") */
            const trk_real t_a = trk_amplitude_threshold(&sp->amplitude);
            if (!(t_a >= 0 && t_a <= TRK_REAL_MAX)) return TRK_E_ARG; /* not an initialised model */
            pp.pd = trk_amplitude_pd(&sp->amplitude);
        } else {
            pp.pd = sp->pd;
        }
        pp.gate_prob = p->gate_prob;
        pp.clutter = p->clutter;
        pp.clutter_density = sp->clutter_density_per_m2;
        pp.gating = 1;
        trk_status st = trk_pda_init(&pda[s], &pp);
        if (st != TRK_OK) return st;
        st = cov2(sp->meas_cov_m2, r[s]);
        if (st != TRK_OK) return st;
    }
    union trk_confirm_model confirm_model;
    union trk_term_model term_model;
    struct trk_visibility_model vis_model;
    if (p->track_visibility != 0 && p->track_visibility != 1) return TRK_E_ARG;
    if (p->track_visibility) {
        trk_status vst = trk_visibility_model_init(&vis_model, &p->visibility);
        if (vst != TRK_OK) return vst;
    }
    trk_status st = trk_i_tests_init(p, &confirm_model, &term_model);
    if (st != TRK_OK) return st;

    t->params = *p;
    t->confirm_model = confirm_model;
    t->term_model = term_model;
    if (p->track_visibility) t->vis_model = vis_model;
    for (unsigned s = 0; s < p->n_sensors; s++) {
        t->pda[s] = pda[s];
        for (int i = 0; i < NZ * NZ; i++) t->r[s][i] = r[s][i];
    }
    t->last_time_us = 0;
    {   /* seconds (<= 1e9) to microseconds with 32-bit conversions only: a
         * float -> int64 conversion is soft double on Cortex-M (__aeabi_f2lz) */
        const trk_real whole = trk_floor(p->max_dt_s);
        t->max_dt_us = (int64_t)(int32_t)whole * 1000000 +
                       (int64_t)(int32_t)((p->max_dt_s - whole) * TRK_REAL_C(1e6));
    }
    t->has_time = 0;
    t->next_id = 1;
    t->n_live = 0;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        t->track[i].status = TRK_TRACK_FREE;
        t->track[i].id = 0;
    }
    return TRK_OK;
}

const struct trk_track *trk_tracker_track(const struct trk_tracker *t, size_t slot)
{
    if (!t || slot >= TRK_MAX_TRACKS || t->track[slot].status == TRK_TRACK_FREE) return NULL;
    return &t->track[slot];
}

size_t trk_tracker_live_count(const struct trk_tracker *t) { return t ? t->n_live : 0; }

size_t trk_tracker_sizeof(void) { return sizeof(struct trk_tracker); }

/* ------------------------------------------------------------------ scan */

/* TRK_OK for a usable detection, else why not: TRK_E_NAN non-finite
 * position or covariance, TRK_E_NOT_SPD covariance, TRK_E_RANGE amplitude
 * NaN, infinite or negative. */
static trk_status check_detection(const struct trk_detection *d)
{
    trk_real r[NZ * NZ];
    if (!isfinite(d->x_m) || !isfinite(d->y_m)) return TRK_E_NAN;
    if (d->has_amplitude && !(d->amplitude >= 0 && d->amplitude <= TRK_REAL_MAX)) return TRK_E_RANGE;
    return d->has_cov ? cov2(d->cov_m2, r) : TRK_OK;
}

/* Copy the valid detections into the workspace: shared-covariance ones
 * first [0, *n_shared), own-covariance ones after, up to *n_valid, each
 * group in scan order. Rejections are counted in rep. */
static void load_detections(struct trk_tracker *t, const struct trk_scan *scan,
                            struct trk_scan_report *rep, size_t *n_shared, size_t *n_valid)
{
    size_t n = 0;
    int any_own = 0;
    for (size_t i = 0; i < scan->n_detections; i++) {
        const struct trk_detection *d = &scan->detections[i];
        trk_status st = check_detection(d);
        if (st == TRK_E_NAN) rep->n_rejected_nonfinite++;
        else if (st == TRK_E_RANGE) rep->n_rejected_amplitude++;
        else if (st != TRK_OK) rep->n_rejected_cov++;
        else if (d->has_cov) any_own = 1;
        else {
            t->ws.x[n] = d->x_m;
            t->ws.y[n] = d->y_m;
            t->ws.src[n] = (uint16_t)i;
            n++;
        }
    }
    *n_shared = n;
    size_t n_shared_kept = 0;
    for (size_t i = 0; any_own && i < scan->n_detections; i++) {
        const struct trk_detection *d = &scan->detections[i];
        if (!d->has_cov || check_detection(d) != TRK_OK) continue;
        t->ws.x[n] = d->x_m;
        t->ws.y[n] = d->y_m;
        t->ws.src[n] = (uint16_t)i;
        n++;
    }
    size_t n_amp = 0;
    const struct trk_sensor_params *sp = &t->params.sensor[scan->sensor_id];
    /* amplitudes in dB against the mean clutter power for the clutter test */
    const trk_real amp_ref_db = TRK_REAL_C(10.0) * trk_log10(sp->use_amplitude ? sp->amplitude.clutter_power : 1);
    const int want_db = t->params.confirm.method == TRK_CONFIRM_CLUTTER_AMP; /* only its user */
    size_t kept = 0;
    for (size_t k = 0; k < n; k++) {
        const struct trk_detection *d = &scan->detections[t->ws.src[k]];
        trk_real llr = 0; /* positions only: l^a = 1 */
        if (sp->use_amplitude && d->has_amplitude) {
            /* PDAFAI: ln l^a of this detection, once per scan (Brekke eqs 19-20) */
            trk_status st = trk_amplitude_log_lr(&sp->amplitude, d->amplitude, &llr);
            if (st == TRK_E_RANGE) { /* below the detection threshold */
                rep->n_below_threshold++;
                continue;
            }
            if (st != TRK_OK) {
                rep->n_rejected_amplitude++;
                continue;
            }
        }
        t->ws.x[kept] = t->ws.x[k];
        t->ws.y[kept] = t->ws.y[k];
        t->ws.src[kept] = t->ws.src[k];
        t->ws.used[kept] = 0;
        t->ws.log_lr[kept] = llr;
        t->ws.amp_pos[kept] = -1;
        if (want_db && d->has_amplitude && d->amplitude > 0) {
            t->ws.amp_db[n_amp] = TRK_REAL_C(20.0) * trk_log10(d->amplitude) - amp_ref_db;
            t->ws.amp_pos[kept] = (int16_t)n_amp++;
        }
        if (k < *n_shared) n_shared_kept++;
        kept++;
    }
    n = kept;
    *n_shared = n_shared_kept;
    t->ws.n_amp = n_amp;
    *n_valid = n;
}

static void end_track(struct trk_tracker *t, struct trk_track *tr, enum trk_track_end why,
                      struct trk_scan_report *rep)
{
    (void)t;
    tr->status = TRK_TRACK_TERMINATED;
    tr->end_reason = (uint8_t)why;
    rep->n_terminated++;
    if (why == TRK_END_NUMERICAL) rep->n_numerical++;
    if (why == TRK_END_MERGED) rep->n_merged++;
}

/* Predict one track to the scan time and PDA-update it with the detections
 * in its gate. Returns 0, or -1 on a numerical failure (track untouched). */
static int update_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                        trk_real dt, size_t n_shared, size_t n_valid,
                        struct trk_look *look)
{
    const struct trk_pda *pda = &t->pda[scan->sensor_id];
    const trk_real *r = t->r[scan->sensor_id];
    const trk_real gamma = pda->gamma;
    trk_real x[NX], p[NX * NX], pht[NX * NZ];
    struct trk_innovation inn;

    for (int i = 0; i < NX; i++) x[i] = tr->x[i];
    for (int i = 0; i < NX * NX; i++) p[i] = tr->p[i];
    trk_i_cv2_predict(dt, t->params.process_noise_q, x, p);
    if (trk_i_innovation_sel(NX, NZ, trk_cv2_h, cv2_sel, r, x, p, pht, &inn) != TRK_OK) return -1;

    /* gate: bounding box of the ellipse d2 <= gamma, then the ellipse */
    const trk_real zx = inn.z_pred[0], zy = inn.z_pred[1];
    /* a confirmed track also keeps detections within init_exclusion_d2 (but
     * outside its gate) from starting new tracks */
    const trk_real g_excl = tr->status == TRK_TRACK_CONFIRMED && t->params.init_exclusion_d2 > gamma
                                ? t->params.init_exclusion_d2
                                : gamma;
    const trk_real wx = trk_sqrt(g_excl * inn.s[0]), wy = trk_sqrt(g_excl * inn.s[3]);
    size_t n = 0;
    for (size_t j = 0; j < n_shared; j++) {
        trk_real nu[NZ];
        nu[0] = t->ws.x[j] - zx;
        nu[1] = t->ws.y[j] - zy;
        if (trk_fabs(nu[0]) > wx || trk_fabs(nu[1]) > wy) continue;
        trk_real d2 = trk_i_mahalanobis2(NZ, inn.s_chol_inv, nu);
        if (!trk_gate_inside(d2, gamma)) {
            if (d2 <= g_excl) t->ws.used[j] = 1;
            continue;
        }
        t->ws.cand[n] = (uint16_t)j;
        t->ws.w[n] = trk_i_pda_log_e(pda, inn.log_det_s, d2, t->ws.log_lr[j]);
        t->ws.z[2 * n] = t->ws.x[j];
        t->ws.z[2 * n + 1] = t->ws.y[j];
        n++;
    }
    const size_t n_shared_gated = n;
    for (size_t j = n_shared; j < n_valid; j++) {
        /* own covariance: S_j = H P H' + R_j */
        const struct trk_detection *d = &scan->detections[t->ws.src[j]];
        trk_real s[NZ * NZ], l[NZ * NZ], li[NZ * NZ], nu[NZ];
        s[0] = p[0] + d->cov_m2[0];
        s[1] = s[2] = p[2] + d->cov_m2[1];
        s[3] = p[10] + d->cov_m2[2];
        nu[0] = t->ws.x[j] - zx;
        nu[1] = t->ws.y[j] - zy;
        if (trk_fabs(nu[0]) > trk_sqrt(g_excl * s[0]) || trk_fabs(nu[1]) > trk_sqrt(g_excl * s[3]))
            continue;
        if (trk_i_chol(NZ, s, l) != TRK_OK) continue; /* cannot happen: P SPD, R_j SPD */
        trk_i_tril_inverse(NZ, l, li);
        trk_real d2 = trk_i_mahalanobis2(NZ, li, nu);
        if (!trk_gate_inside(d2, gamma)) {
            if (d2 <= g_excl) t->ws.used[j] = 1;
            continue;
        }
        t->ws.cand[n] = (uint16_t)j;
        t->ws.w[n] = trk_i_pda_log_e(pda, trk_i_chol_logdet(NZ, l), d2, t->ws.log_lr[j]);
        t->ws.z[2 * n] = t->ws.x[j];
        t->ws.z[2 * n + 1] = t->ws.y[j];
        for (int i = 0; i < NZ * NZ; i++) t->ws.s_chol_inv[4 * n + i] = li[i];
        n++;
    }

    /* association probabilities (log domain) */
    const trk_real vg = trk_i_pda_gate_volume(pda, &inn);
    const trk_real lambda = pda->params.clutter == TRK_CLUTTER_PARAMETRIC
                                ? pda->params.clutter_density
                                : (trk_real)n / vg;
    trk_real log_sum_e = -(trk_real)INFINITY; /* ln sum_i e_i, for the visibility */
    trk_real beta0 = n ? trk_i_pda_normalise(trk_i_pda_log_e0(pda, lambda), n, t->ws.w, &log_sum_e) : 1;

    /* pc_sum = sum_i beta_i P_c,i (Joseph form) */
    trk_real pc_sum[NX * NX] = {0};
    if (n > 0) {
        trk_real b_shared = 0, k[NX * NZ], pc[NX * NX];
        for (size_t i = 0; i < n_shared_gated; i++) b_shared += t->ws.w[i];
        if (b_shared > 0) {
            trk_i_gain(NX, NZ, pht, inn.s_chol_inv, k);
            trk_i_joseph_sel(NX, NZ, trk_cv2_h, cv2_sel, r, k, p, pht, pc);
            for (int i = 0; i < NX * NX; i++) pc_sum[i] = b_shared * pc[i];
        }
        for (size_t i = n_shared_gated; i < n; i++) {
            if (t->ws.w[i] == 0) continue;
            const struct trk_detection *d = &scan->detections[t->ws.src[t->ws.cand[i]]];
            trk_real ri[NZ * NZ];
            ri[0] = d->cov_m2[0];
            ri[1] = ri[2] = d->cov_m2[1];
            ri[3] = d->cov_m2[2];
            trk_i_gain(NX, NZ, pht, t->ws.s_chol_inv + 4 * i, k);
            trk_i_joseph_sel(NX, NZ, trk_cv2_h, cv2_sel, ri, k, p, pht, pc);
            for (int a = 0; a < NX * NX; a++) pc_sum[a] += t->ws.w[i] * pc[a];
        }
    }
    trk_real xn[NX], pn[NX * NX];
    if (n > 0) {
        const size_t ng = n_shared_gated;
        trk_i_pda_combine(NX, NZ, x, p, pht, inn.z_pred, beta0, ng, t->ws.z, NZ, t->ws.w,
                          inn.s_chol_inv, n - ng, t->ws.z + NZ * ng, t->ws.w + ng,
                          t->ws.s_chol_inv + 4 * ng, pc_sum, xn, pn);
    } else {
        for (int i = 0; i < NX; i++) xn[i] = x[i];
        for (int i = 0; i < NX * NX; i++) pn[i] = p[i];
    }
    for (int i = 0; i < NX; i++)
        if (!isfinite(xn[i])) return -1;
    for (int i = 0; i < NX * NX; i++)
        if (!isfinite(pn[i])) return -1;
    if (!(pn[0] > 0 && pn[5] > 0 && pn[10] > 0 && pn[15] > 0)) return -1;
    struct trk_visibility vis_out = tr->vis;
    if (t->params.track_visibility) {
        /* Kennedy eqs 21-24: ln sum_i (g_D,i / rho) l_i = ln sum_i e_i - ln P_D - ln lambda
         * (e_i = P_D g_D,i l_i are the PDA weights; lambda = 0: +inf, a certain detection) */
        trk_real log_sum = log_sum_e;
        if (n > 0) log_sum = lambda > 0 ? log_sum_e - trk_log(pda->params.pd) - trk_log(lambda) : (trk_real)INFINITY;
        struct trk_visibility v = vis_out;
        if (trk_visibility_update_log(&t->vis_model, &v, pda->params.pd, pda->params.gate_prob, log_sum) != TRK_OK)
            return -1;
        vis_out = v;
    }

    for (size_t i = 0; i < n; i++) t->ws.used[t->ws.cand[i]] = 1;
    tr->vis = vis_out;
    for (int i = 0; i < NX; i++) tr->x[i] = xn[i];
    for (int i = 0; i < NX * NX; i++) tr->p[i] = pn[i];
    tr->time_us = scan->time_us;
    tr->n_gated_last = (uint16_t)n;
    tr->beta0_last = beta0;
    look->has_nearest = 0;
    look->nearest = 0;
    if (tr->status == TRK_TRACK_TENTATIVE && trk_i_confirm_needs_nearest(&t->params) && n_valid > 0) {
        /* Kennedy eqs 5-9: rho V_g with V_g = c_nz D^nz sqrt|S| enclosed by
         * the nearest detection (sensor's S; D^2 = its d2) */
        trk_real best = TRK_REAL_MAX;
        size_t jb = 0;
        for (size_t j = 0; j < n_valid; j++) {
            trk_real nu[NZ];
            nu[0] = t->ws.x[j] - zx;
            nu[1] = t->ws.y[j] - zy;
            trk_real d2 = trk_i_mahalanobis2(NZ, inn.s_chol_inv, nu);
            if (d2 < best) {
                best = d2;
                jb = j;
            }
        }
        look->has_nearest = 1;
        look->nearest = jb;
        look->rho_vg = pda->params.clutter_density * TRK_PI * best * inn.sqrt_det_s;
    }
    look->detected = n > 0;
    look->sensor_id = scan->sensor_id;
    look->n_gated = (int)n;
    look->pfa_gate = -trk_expm1(-lambda * vg);
    look->beta0 = beta0;
    return 0;
}

/* Is track a stronger than b (kept when they merge)? Confirmed over
 * tentative, then more hits, then older (smaller id: ids only grow, except
 * after 2^32 tracks). */
static int stronger(const struct trk_track *a, const struct trk_track *b)
{
    if (a->status != b->status) return a->status == TRK_TRACK_CONFIRMED;
    if (a->n_hits != b->n_hits) return a->n_hits > b->n_hits;
    return a->id < b->id;
}

/* End the weaker of every pair of live tracks whose states are within
 * merge_gate_d2: d2 = dx' (P_a + P_b)^-1 dx over [x, vx, y, vy] (the
 * track-to-track test without the common process-noise cross-covariance,
 * which would only make d2 larger). A cheap test on the positions first:
 * d2 >= dx^2 / (Pa_xx + Pb_xx) for the x (and y) component alone. */
static void merge_duplicates(struct trk_tracker *t, struct trk_scan_report *rep)
{
    const trk_real g = t->params.merge_gate_d2;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        struct trk_track *a = &t->track[i];
        if (a->status != TRK_TRACK_TENTATIVE && a->status != TRK_TRACK_CONFIRMED) continue;
        for (size_t j = i + 1; j < TRK_MAX_TRACKS; j++) {
            struct trk_track *b = &t->track[j];
            if (b->status != TRK_TRACK_TENTATIVE && b->status != TRK_TRACK_CONFIRMED) continue;
            const trk_real ex = a->x[0] - b->x[0], ey = a->x[2] - b->x[2];
            if (ex * ex > g * (a->p[0] + b->p[0]) || ey * ey > g * (a->p[10] + b->p[10])) continue;
            trk_real c[NX * NX], l[NX * NX], li[NX * NX], dx[NX], y[NX], d2 = 0;
            for (int k = 0; k < NX * NX; k++) c[k] = a->p[k] + b->p[k];
            for (int k = 0; k < NX; k++) dx[k] = a->x[k] - b->x[k];
            if (trk_i_chol(NX, c, l) != TRK_OK) continue; /* cannot happen: both SPD */
            trk_i_tril_inverse(NX, l, li);
            trk_i_tril_mul(NX, li, dx, y);
            for (int k = 0; k < NX; k++) d2 += y[k] * y[k];
            if (d2 > g) continue;
            if (stronger(a, b)) {
                end_track(t, b, TRK_END_MERGED, rep);
            } else {
                end_track(t, a, TRK_END_MERGED, rep);
                break; /* a is gone */
            }
        }
    }
}

/* Confirmation step; for the clutter-amplitude test the nearest detection's
 * amplitude is moved to the end of the scan's amplitude list so the others
 * are contiguous, and moved back afterwards. */
static int confirm_step(struct trk_tracker *t, struct trk_track *tr, struct trk_look *look)
{
    look->has_amp = 0;
    look->n_others = 0;
    look->a_others_db = t->ws.amp_db;
    if (!look->has_nearest || t->params.confirm.method != TRK_CONFIRM_CLUTTER_AMP ||
        t->ws.amp_pos[look->nearest] < 0)
        return trk_i_confirm_step(t, tr, look);
    const size_t k = (size_t)t->ws.amp_pos[look->nearest], last = t->ws.n_amp - 1;
    trk_real tmp = t->ws.amp_db[k];
    t->ws.amp_db[k] = t->ws.amp_db[last];
    t->ws.amp_db[last] = tmp;
    look->has_amp = 1;
    look->a_assoc_db = tmp;
    look->n_others = last;
    int d = trk_i_confirm_step(t, tr, look);
    t->ws.amp_db[last] = t->ws.amp_db[k];
    t->ws.amp_db[k] = tmp;
    return d;
}

static void start_track(struct trk_tracker *t, struct trk_track *tr, const struct trk_scan *scan,
                        size_t j)
{
    const struct trk_detection *d = &scan->detections[t->ws.src[j]];
    const trk_real *r = d->has_cov ? NULL : t->r[scan->sensor_id];
    const trk_real vv = t->params.init_speed_sigma_mps * t->params.init_speed_sigma_mps;
    tr->id = t->next_id;
    t->next_id = t->next_id == UINT32_MAX ? 1 : t->next_id + 1;
    tr->status = TRK_TRACK_TENTATIVE;
    tr->end_reason = TRK_END_NONE;
    tr->time_us = scan->time_us;
    tr->x[0] = t->ws.x[j];
    tr->x[1] = 0;
    tr->x[2] = t->ws.y[j];
    tr->x[3] = 0;
    for (int i = 0; i < NX * NX; i++) tr->p[i] = 0;
    tr->p[0] = r ? r[0] : d->cov_m2[0];
    tr->p[2] = tr->p[8] = r ? r[1] : d->cov_m2[1];
    tr->p[10] = r ? r[3] : d->cov_m2[2];
    tr->p[5] = tr->p[15] = vv;
    tr->n_scans = 1;
    tr->n_hits = 1;
    tr->n_misses_in_row = 0;
    tr->n_gated_last = 1;
    tr->beta0_last = 0;
    tr->term_stat = 0;
    if (t->params.track_visibility) trk_visibility_reset(&t->vis_model, &tr->vis);
    else memset(&tr->vis, 0, sizeof tr->vis);
    trk_i_confirm_start(t, tr);
}

trk_status trk_tracker_process_scan(struct trk_tracker *t, const struct trk_scan *scan,
                                    struct trk_scan_report *report)
{
    struct trk_scan_report rep = {0};
    if (report) *report = rep;
    if (!t || !scan) return TRK_E_ARG;
    if (scan->n_detections > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (scan->n_detections > 0 && !scan->detections) return TRK_E_ARG;
    if (scan->sensor_id >= t->params.n_sensors) return TRK_E_SENSOR;
    /* |time| <= 2^62 keeps every difference of two times representable */
    if (scan->time_us > TRK_TIME_US_MAX || scan->time_us < -TRK_TIME_US_MAX) return TRK_E_RANGE;
    if (t->has_time && scan->time_us < t->last_time_us) return TRK_E_TIME;
    if (t->has_time && scan->time_us - t->last_time_us > t->max_dt_us) return TRK_E_RANGE;
    /* --- the scan is accepted: from here on the table changes */
    rep.n_detections = (uint32_t)scan->n_detections;
    for (size_t i = 0; i < TRK_MAX_TRACKS; i++)
        if (t->track[i].status == TRK_TRACK_TERMINATED) {
            t->track[i].status = TRK_TRACK_FREE;
            t->n_live--;
        }

    size_t n_shared, n_valid;
    load_detections(t, scan, &rep, &n_shared, &n_valid);

    for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
        struct trk_track *tr = &t->track[i];
        if (tr->status != TRK_TRACK_TENTATIVE && tr->status != TRK_TRACK_CONFIRMED) continue;
        const trk_real dt = (trk_real)(scan->time_us - tr->time_us) * TRK_REAL_C(1e-6);
        struct trk_look look;
        rep.n_tracks_updated++;
        if (update_track(t, tr, scan, dt, n_shared, n_valid, &look) != 0) {
            end_track(t, tr, TRK_END_NUMERICAL, &rep);
            continue;
        }
        tr->n_scans++;
        if (look.detected) {
            tr->n_hits++;
            tr->n_misses_in_row = 0;
            rep.n_tracks_hit++;
        } else {
            tr->n_misses_in_row++;
        }
        if (tr->status == TRK_TRACK_TENTATIVE) {
            int d = confirm_step(t, tr, &look);
            if (d > 0) {
                tr->status = TRK_TRACK_CONFIRMED;
                trk_i_term_start(t, tr);
                rep.n_confirmed++;
            } else if (d < 0) {
                end_track(t, tr, TRK_END_REJECTED, &rep);
            } else if (t->params.max_tentative_scans && tr->n_scans > t->params.max_tentative_scans) {
                end_track(t, tr, TRK_END_TENTATIVE_AGE, &rep);
            }
        } else if (trk_i_term_step(t, tr, &look)) {
            end_track(t, tr, TRK_END_TERMINATED, &rep);
        }
    }

    if (t->params.merge_gate_d2 > 0) merge_duplicates(t, &rep);

    /* single-point initiation from every valid detection no track gated */
    size_t slot = 0;
    for (size_t j = 0; j < n_valid; j++) {
        if (t->ws.used[j]) continue;
        while (slot < TRK_MAX_TRACKS && t->track[slot].status != TRK_TRACK_FREE) slot++;
        if (slot == TRK_MAX_TRACKS) {
            rep.n_init_refused_full++;
            continue;
        }
        struct trk_track *tr = &t->track[slot];
        start_track(t, tr, scan, j);
        t->n_live++;
        rep.n_started++;
        /* M/N counts the initiating detection as its first scan; the
         * SPRT and the clutter tests start with the first update */
        if (t->params.confirm.method == TRK_CONFIRM_MN) {
            struct trk_look look = {0};
            look.detected = 1;
            look.sensor_id = scan->sensor_id;
            look.n_gated = 1;
            if (trk_i_confirm_step(t, tr, &look) > 0) {
                tr->status = TRK_TRACK_CONFIRMED;
                trk_i_term_start(t, tr);
                rep.n_confirmed++;
            }
        }
    }
    t->last_time_us = scan->time_us;
    t->has_time = 1;
    if (report) *report = rep;
    return TRK_OK;
}

/* ------------------------------------------------------------------ helpers */

trk_status trk_detection_from_polar(trk_real range_m, trk_real bearing_rad, trk_real sigma_range_m,
                                    trk_real sigma_bearing_rad, trk_real sensor_x_m,
                                    trk_real sensor_y_m, struct trk_detection *d)
{
    if (!d) return TRK_E_ARG;
    if (!isfinite(range_m) || !isfinite(bearing_rad) || !isfinite(sigma_range_m) ||
        !isfinite(sigma_bearing_rad) || !isfinite(sensor_x_m) || !isfinite(sensor_y_m))
        return TRK_E_NAN;
    if (!(range_m >= 0) || !(sigma_range_m > 0) || !(sigma_bearing_rad > 0)) return TRK_E_RANGE;
    const trk_real sb = trk_sin(bearing_rad), cb = trk_cos(bearing_rad);
    const trk_real vr = sigma_range_m * sigma_range_m;
    const trk_real vt = range_m * range_m * sigma_bearing_rad * sigma_bearing_rad; /* cross-range */
    /* J = [[sb, r cb], [cb, -r sb]];  C = J diag(vr, sigma_b^2) J' */
    d->x_m = sensor_x_m + range_m * sb;
    d->y_m = sensor_y_m + range_m * cb;
    d->cov_m2[0] = vr * sb * sb + vt * cb * cb;
    d->cov_m2[1] = (vr - vt) * sb * cb;
    d->cov_m2[2] = vr * cb * cb + vt * sb * sb;
    d->has_cov = 1;
    d->has_amplitude = 0;
    d->amplitude = 0;
    if (!(d->cov_m2[0] * d->cov_m2[2] - d->cov_m2[1] * d->cov_m2[1] > 0)) {
        /* range 0: cross-range variance 0, covariance singular */
        return TRK_E_RANGE;
    }
    return TRK_OK;
}
