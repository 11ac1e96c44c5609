/* imm.c - interacting multiple model estimator, alone and with PDA
 * (trk/imm.h; docs/conventions.md "Multiple models (IMM)"). */
#include "trk/imm.h"

#include <math.h>
#include <string.h>

#include "internal.h"
#include "pda_impl.h"
#include "trk/gate.h"

#define NX TRK_IMM_NX
#define NZ TRK_IMM_NZ

static int finite_n(const trk_real *v, size_t n);
static void normalise_log(int n, const trk_real *log_w, trk_real *p);
static void spread_add(trk_real w, const trk_real *d, trk_real *p);

/* ------------------------------------------------------------------ parameters, models */

trk_status trk_imm_check_params(const struct trk_imm_params *m)
{
    if (!m || m->n_models < 1 || m->n_models > TRK_MAX_MODELS) return TRK_E_ARG;
    const int n = m->n_models;
    for (int j = 0; j < n; j++) {
        if (!isfinite(m->omega_rad_s[j]) || !isfinite(m->q_m2_per_s3[j])) return TRK_E_NAN;
        if (!(m->q_m2_per_s3[j] >= 0) || !(trk_fabs(m->omega_rad_s[j]) <= 1)) return TRK_E_RANGE;
    }
    for (int i = 0; i < n; i++) {
        trk_real row = 0;
        for (int j = 0; j < n; j++) {
            const trk_real v = m->p_switch[i * n + j];
            if (!isfinite(v)) return TRK_E_NAN;
            if (!(v >= 0 && v <= 1)) return TRK_E_RANGE;
            row += v;
        }
        if (!(trk_fabs(row - 1) <= TRK_REAL_C(1e-6))) return TRK_E_RANGE;
    }
    return TRK_OK;
}

void trk_ct_transition(trk_real dt_s, trk_real omega_rad_s, trk_real f[NX * NX])
{
    const trk_real w = omega_rad_s, wt = w * dt_s;
    const trk_real s = trk_sin(wt), c = trk_cos(wt);
    /* s/w and (1-c)/w = 2 sin^2(wT/2) / w: no cancellation as w -> 0 (in
     * float cos(wT) rounds to 1 below wT ~ 3e-4); exact CV at w = 0 */
    trk_real sw = dt_s, cw = 0;
    if (w != 0) {
        const trk_real h = trk_sin(wt / 2);
        sw = s / w;
        cw = 2 * h * h / w;
    }
    const trk_real fv[NX * NX] = {1, sw, 0, -cw, 0, c, 0, -s, 0, cw, 1, sw, 0, s, 0, c};
    memcpy(f, fv, sizeof fv);
}

/* ------------------------------------------------------------------ mixing and prediction */

trk_status trk_imm_mix(const struct trk_imm_params *m, struct trk_imm_state *s, trk_real mu_pred[TRK_MAX_MODELS])
{
    if (!m || !s || !mu_pred || m->n_models < 1 || m->n_models > TRK_MAX_MODELS) return TRK_E_ARG;
    const int n = m->n_models;
    trk_real total = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(s->mu[i])) return TRK_E_NAN;
        if (!(s->mu[i] >= 0)) return TRK_E_RANGE;
        total += s->mu[i];
    }
    if (!(trk_fabs(total - 1) <= TRK_REAL_C(1e-4))) return TRK_E_RANGE;
    trk_real x0[TRK_MAX_MODELS][NX], p0[TRK_MAX_MODELS][NX * NX], c[TRK_MAX_MODELS];
    for (int j = 0; j < n; j++) {
        c[j] = 0;
        for (int i = 0; i < n; i++) c[j] += m->p_switch[i * n + j] * s->mu[i];
        for (int a = 0; a < NX; a++) x0[j][a] = 0;
        for (int a = 0; a < NX * NX; a++) p0[j][a] = 0;
        if (!(c[j] > 0)) { /* unreachable model: keep its estimate, weight 0 */
            memcpy(x0[j], s->x[j], sizeof x0[j]);
            memcpy(p0[j], s->p[j], sizeof p0[j]);
            continue;
        }
        /* mu_i|j = p_ij mu_i / c_j; x0_j = sum mu_i|j x_i */
        for (int i = 0; i < n; i++) {
            const trk_real wij = m->p_switch[i * n + j] * s->mu[i] / c[j];
            for (int a = 0; a < NX; a++) x0[j][a] += wij * s->x[i][a];
        }
        /* P0_j = sum mu_i|j (P_i + d d'), d = x_i - x0_j */
        for (int i = 0; i < n; i++) {
            const trk_real wij = m->p_switch[i * n + j] * s->mu[i] / c[j];
            trk_real d[NX];
            for (int a = 0; a < NX; a++) d[a] = s->x[i][a] - x0[j][a];
            for (int a = 0; a < NX * NX; a++) p0[j][a] += wij * s->p[i][a];
            spread_add(wij, d, p0[j]);
        }
    }
    for (int j = 0; j < n; j++)
        if (!finite_n(x0[j], NX) || !finite_n(p0[j], NX * NX)) return TRK_E_NAN;
    for (int j = 0; j < n; j++) {
        memcpy(s->x[j], x0[j], sizeof x0[j]);
        memcpy(s->p[j], p0[j], sizeof p0[j]);
        mu_pred[j] = c[j];
    }
    return TRK_OK;
}

trk_status trk_imm_predict(const struct trk_imm_params *m, trk_real dt_s, struct trk_imm_state *s)
{
    if (!m || !s || m->n_models < 1 || m->n_models > TRK_MAX_MODELS) return TRK_E_ARG;
    if (!isfinite(dt_s)) return TRK_E_NAN;
    if (!(dt_s > 0)) return TRK_E_RANGE;
    struct trk_imm_state out = *s;
    for (int j = 0; j < m->n_models; j++) {
        trk_real f[NX * NX], q[NX * NX];
        trk_ct_transition(dt_s, m->omega_rad_s[j], f);
        trk_cv2_process_noise(dt_s, m->q_m2_per_s3[j], q);
        trk_status st = trk_kalman_predict(NX, f, q, out.x[j], out.p[j]);
        if (st != TRK_OK) return st;
    }
    *s = out;
    return TRK_OK;
}

/* ------------------------------------------------------------------ updates */

/* mu_j' ~ Lambda_j c_j, from ln Lambda_j */
static void mode_update(int n, const trk_real *log_lik, const trk_real *mu_pred, trk_real *mu)
{
    trk_real lw[TRK_MAX_MODELS];
    for (int j = 0; j < n; j++) lw[j] = mu_pred[j] > 0 ? log_lik[j] + trk_log(mu_pred[j]) : -(trk_real)INFINITY;
    normalise_log(n, lw, mu);
}

trk_status trk_imm_update(const struct trk_imm_params *m, const trk_real r[NZ * NZ], const trk_real z[NZ],
                          const trk_real mu_pred[TRK_MAX_MODELS], struct trk_imm_state *s, trk_real *log_lik)
{
    if (!m || !r || !z || !mu_pred || !s || m->n_models < 1 || m->n_models > TRK_MAX_MODELS) return TRK_E_ARG;
    if (!finite_n(z, NZ)) return TRK_E_NAN;
    const int n = m->n_models;
    struct trk_imm_state out = *s;
    trk_real ll[TRK_MAX_MODELS];
    for (int j = 0; j < n; j++) {
        struct trk_innovation inn;
        trk_status st = trk_kalman_innovation(NX, NZ, trk_cv2_h, r, out.x[j], out.p[j], &inn);
        if (st != TRK_OK) return st;
        trk_real nu[NZ] = {z[0] - inn.z_pred[TRK_CV2_ZX], z[1] - inn.z_pred[TRK_CV2_ZY]};
        /* ln N(z; H x-, S) = -(nz/2) ln 2pi - (1/2)(ln det S + d2) */
        ll[j] = -TRK_REAL_C(0.5) * ((trk_real)NZ * TRK_LN_2PI + inn.log_det_s + trk_gate_d2(&inn, nu));
        st = trk_kalman_update(NX, NZ, trk_cv2_h, r, z, out.x[j], out.p[j]);
        if (st != TRK_OK) return st;
    }
    mode_update(n, ll, mu_pred, out.mu);
    *s = out;
    if (log_lik)
        for (int j = 0; j < n; j++) log_lik[j] = ll[j];
    return TRK_OK;
}

trk_status trk_imm_pda_update(const struct trk_imm_params *m, const struct trk_pda *pda, const trk_real r[NZ * NZ],
                              size_t n_det, const trk_real *z, const trk_real *log_lr,
                              const trk_real mu_pred[TRK_MAX_MODELS], struct trk_imm_state *s,
                              struct trk_imm_work *w, unsigned char *validated, trk_real *log_lik)
{
    if (!m || !pda || !r || !mu_pred || !s || !w || (n_det > 0 && !z) || m->n_models < 1 ||
        m->n_models > TRK_MAX_MODELS || pda->params.nz != NZ)
        return TRK_E_ARG;
    if (n_det > TRK_MAX_DETECTIONS) return TRK_E_CAPACITY;
    if (pda->params.clutter != TRK_CLUTTER_PARAMETRIC) return TRK_E_UNSUPPORTED;
    if (!finite_n(z, 2 * n_det) || (log_lr && !finite_n(log_lr, n_det))) return TRK_E_NAN;
    const int n = m->n_models;
    struct trk_innovation inn[TRK_MAX_MODELS];
    for (int j = 0; j < n; j++) {
        trk_status st = trk_kalman_innovation(NX, NZ, trk_cv2_h, r, s->x[j], s->p[j], &inn[j]);
        if (st != TRK_OK) return st;
    }
    /* the validated set: inside at least one model's gate, compacted */
    trk_real *zv = w->z, *lrv = w->log_lr;
    size_t nv = 0;
    for (size_t i = 0; i < n_det; i++) {
        int in = 0;
        for (int j = 0; j < n && !in; j++) {
            const trk_real nu[NZ] = {z[2 * i] - inn[j].z_pred[TRK_CV2_ZX], z[2 * i + 1] - inn[j].z_pred[TRK_CV2_ZY]};
            in = trk_gate_d2(&inn[j], nu) <= pda->gamma;
        }
        if (validated) validated[i] = (unsigned char)in;
        if (!in) continue;
        zv[2 * nv] = z[2 * i];
        zv[2 * nv + 1] = z[2 * i + 1];
        lrv[nv] = log_lr ? log_lr[i] : 0;
        nv++;
    }
    /* per model: ln Lambda_j = ln(e_0 + sum_i e_ij), then its PDA over the
     * validated set with no gate of its own */
    struct trk_pda all = *pda;
    all.params.gating = 0;
    struct trk_imm_state out = *s;
    trk_real ll[TRK_MAX_MODELS];
    for (int j = 0; j < n; j++) {
        /* ln e_ij in w->beta first (log-sum-exp), then the PDA's weights */
        const trk_real le0 = trk_i_pda_log_e0(pda, pda->params.clutter_density);
        trk_real mx = le0;
        for (size_t i = 0; i < nv; i++) {
            const trk_real nu[NZ] = {zv[2 * i] - inn[j].z_pred[TRK_CV2_ZX], zv[2 * i + 1] - inn[j].z_pred[TRK_CV2_ZY]};
            w->beta[i] = trk_i_pda_log_e(pda, inn[j].log_det_s, trk_gate_d2(&inn[j], nu), lrv[i]);
            if (w->beta[i] > mx) mx = w->beta[i];
        }
        trk_real sum = mx > -TRK_REAL_MAX ? trk_exp(le0 - mx) : 0;
        for (size_t i = 0; i < nv; i++) sum += trk_exp(w->beta[i] - mx);
        ll[j] = sum > 0 ? mx + trk_log(sum) : -(trk_real)INFINITY;
        trk_status st = trk_pda_update_inn(&all, NX, trk_cv2_h, r, out.x[j], out.p[j], &inn[j], nv, zv,
                                           log_lr ? lrv : NULL, w->beta, NULL, NULL);
        if (st != TRK_OK) return st;
    }
    mode_update(n, ll, mu_pred, out.mu);
    *s = out;
    if (log_lik)
        for (int j = 0; j < n; j++) log_lik[j] = ll[j];
    return TRK_OK;
}

void trk_imm_combine(const struct trk_imm_params *m, const struct trk_imm_state *s, trk_real x[NX],
                     trk_real p[NX * NX])
{
    const int n = m->n_models;
    for (int a = 0; a < NX; a++) {
        x[a] = 0;
        for (int j = 0; j < n; j++) x[a] += s->mu[j] * s->x[j][a];
    }
    for (int a = 0; a < NX * NX; a++) p[a] = 0;
    for (int j = 0; j < n; j++) {
        trk_real d[NX];
        for (int a = 0; a < NX; a++) d[a] = s->x[j][a] - x[a];
        for (int a = 0; a < NX * NX; a++) p[a] += s->mu[j] * s->p[j][a];
        spread_add(s->mu[j], d, p);
    }
}

/* ------------------------------------------------------------------ helpers */

static int finite_n(const trk_real *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

/* p_j = exp(log_w_j) / sum (log-sum-exp; all -inf gives the uniform) */
static void normalise_log(int n, const trk_real *log_w, trk_real *p)
{
    trk_real mx = -(trk_real)INFINITY, sum = 0;
    for (int j = 0; j < n; j++)
        if (log_w[j] > mx) mx = log_w[j];
    if (!(mx > -TRK_REAL_MAX)) {
        for (int j = 0; j < n; j++) p[j] = 1 / (trk_real)n;
        return;
    }
    for (int j = 0; j < n; j++) sum += (p[j] = trk_exp(log_w[j] - mx));
    for (int j = 0; j < n; j++) p[j] /= sum;
}

/* P += w d d' (a positive semi-definite spread term), each product once
 * for both triangles: w d_a d_b and w d_b d_a round differently, and a
 * symmetric P must stay exactly symmetric (found by test_tracker_random's
 * IMM tracks) */
static void spread_add(trk_real w, const trk_real *d, trk_real *p)
{
    for (int a = 0; a < NX; a++)
        for (int b = a; b < NX; b++) {
            const trk_real v = w * d[a] * d[b];
            p[a * NX + b] += v;
            if (b != a) p[b * NX + a] += v;
        }
}
