/* pda_impl.h (private) - one track's PDA update over its gated set, shared
 * by pda.c (the public one-track API) and the tracker (every track of a
 * scan). See trk/pda.h for the formulas (docs/conventions.md "PDA").
 *
 * The caller predicts, computes the innovation and gates; the gated set
 * holds the detections with their unnormalised log weights ln e_i. Detections
 * with the shared innovation covariance S (the sensor's R) and detections
 * with their own R_j (S_j = H P H' + R_j) are one set: the first n_shared
 * share S, the rest carry R_j. trk_i_pda_update_set then does the rest:
 * clutter density, beta, the Joseph-form P_c, the combination into (x, P),
 * the check of the posterior. */
#ifndef TRK_PDA_IMPL_H
#define TRK_PDA_IMPL_H

#include "gate_impl.h"
#include "kalman_impl.h"
#include "trk/gate.h"
#include "trk/pda.h"

/* The prediction of one track, as the PDA needs it. */
struct trk_i_pda_pred {
    int nx, nz;
    const trk_real *h;                /* H (nz x nx) */
    const int *sel;                   /* the state components H selects, or NULL (H general) */
    const trk_real *r;                /* R of the detections that share S */
    trk_real *x, *p;                  /* predicted state and covariance; the update
                                         writes the posterior over them */
    const trk_real *pht;              /* P H' (nx x nz) */
    const struct trk_innovation *inn; /* z_pred and the shared S = H P H' + R */
};

/* One track's gated set. */
struct trk_i_pda_set {
    size_t n;              /* detections: z[0, n) (rows of nz), w[0, n) */
    size_t n_shared;       /* z[0, n_shared) share S; z[n_shared, n) each have an R_j */
    size_t m_gated;        /* m_G, detections in the gate (nonparametric lambda = m_G / V_G) */
    const trk_real *z;
    trk_real *w;           /* in: ln e_i (-inf: weight 0); out: beta_i */
    const trk_real *r_own; /* R_j of detection n_shared + j at r_own + j nz^2 */
    trk_real w_max;        /* the largest ln e_i in w (-inf: none), at w[w_arg]:
                              kept by whoever fills w (trk_i_pda_set_w), so that
                              the normalisation needs no pass of its own */
    size_t w_arg;
};

struct trk_i_pda_out {
    trk_real beta0;       /* P(no detection is the target's) */
    trk_real lambda;      /* clutter density used */
    trk_real gate_volume; /* V_G of the shared S */
    trk_real e_max, e_sum; /* ln sum_i e_i over the set = e_max + ln e_sum
                              (trk_i_pda_log_sum_e: the log only where it is used) */
};

/* ln sum_i e_i over the set (-inf: none, or all weights zero) */
TRK_INLINE trk_real trk_i_pda_log_sum_e(const struct trk_i_pda_out *o)
{
    return o->e_sum > 0 ? o->e_max + trk_log(o->e_sum) : -(trk_real)INFINITY;
}

/* ln e_i = ln P_D - (nz/2) ln 2pi - (1/2) ln det S - d2/2 + ln l^a */
TRK_INLINE trk_real trk_i_pda_log_e(const struct trk_pda *pda, trk_real log_det_s, trk_real d2,
                                    trk_real log_lr)
{
    return pda->log_pd_norm - TRK_REAL_C(0.5) * (log_det_s + d2) + log_lr;
}

/* ln e_0 = ln lambda + ln(1 - P_D P_G); precomputed for parametric clutter */
TRK_INLINE trk_real trk_i_pda_log_e0(const struct trk_pda *pda, trk_real lambda)
{
    return pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->log_e0_param
                                                        : trk_log(lambda) + pda->log_miss;
}

/* s->w_max and s->w_arg from w, for a caller that fills w in one go. */
TRK_INLINE void trk_i_pda_find_w_max(struct trk_i_pda_set *s)
{
    s->w_max = -(trk_real)INFINITY;
    s->w_arg = 0;
    for (size_t i = 0; i < s->n; i++)
        if (s->w[i] > s->w_max) {
            s->w_max = s->w[i];
            s->w_arg = i;
        }
}

/* w[i] = ln e_i into the set, keeping w_max and w_arg (w_max starts at
 * -inf). */
TRK_INLINE void trk_i_pda_set_w(struct trk_i_pda_set *s, size_t i, trk_real log_e)
{
    s->w[i] = log_e;
    if (log_e > s->w_max) {
        s->w_max = log_e;
        s->w_arg = i;
    }
}

/* The rule for association weights (e_i, beta_i, an IMM model's
 * beta_i rho_mi / mu_m): a weight below the smallest normal (a subnormal)
 * is an exactly-zero contribution. Its reciprocal, or that of a sum of
 * such weights (the moments' 1 / B), overflows to inf and the moment match
 * turns to NaN; the detection it weighs lies some 38 sigma (double; 13 in
 * float) from the prediction, so 0 changes the posterior by less than the
 * rounding of the normal weights. Every other value passes unchanged (a NaN
 * stays NaN: no clamping). */
TRK_INLINE trk_real trk_i_pda_weight(trk_real w)
{
    return w > 0 && w < TRK_REAL_MIN ? 0 : w;
}

/* The normalisation's first half: e_i = exp(ln e_i - mx) in place over
 * w[0..n), with the shift mx (o->e_max) and *e0 = exp(ln e_0 - mx). The
 * shift is ln e_0 itself when the largest ln e_i (w_max) lies within 30 of
 * it: e_0 = 1 needs no exponential, and the largest e_i stays in [e^-30,
 * e^30]; else the larger of the two, as usual. 0 (w zeroed, o->e_max and
 * o->e_sum 0) when every weight is zero (e.g. no detection and lambda = 0),
 * else 1. A subnormal e_i is 0 (trk_i_pda_weight). */
TRK_INLINE int trk_i_pda_exp(trk_real log_e0, size_t n, trk_real *w, trk_real w_max, trk_real *e0,
                             struct trk_i_pda_out *o)
{
    const int near = trk_fabs(w_max - log_e0) <= 30; /* (false for an infinite one) */
    const trk_real mx = near || !(w_max > log_e0) ? log_e0 : w_max;
    o->e_max = 0;
    o->e_sum = 0;
    if (!(mx > -TRK_REAL_MAX)) { /* all -inf */
        for (size_t i = 0; i < n; i++) w[i] = 0;
        return 0;
    }
    *e0 = near ? 1 : trk_exp(log_e0 - mx);
    for (size_t i = 0; i < n; i++) w[i] = trk_i_pda_weight(trk_exp(w[i] - mx));
    o->e_max = mx;
    return 1;
}

/* The second half: sum e_i (o->e_sum) given, w[i] = beta_i = e_i / (e_0 +
 * sum e_i); the factor 1 / (e_0 + sum e_i) returned. */
TRK_INLINE trk_real trk_i_pda_exp_scale(trk_real e0, trk_real sum_meas, size_t n, trk_real *w,
                                        struct trk_i_pda_out *o)
{
    o->e_sum = sum_meas;
    const trk_real inv = 1 / (e0 + sum_meas);
    for (size_t i = 0; i < n; i++) w[i] *= inv;
    return inv;
}

/* Normalise in the log domain: log_e0 and log_w[0..n) (in, w_max their
 * largest) -> beta0 (returned) and w[0..n) = beta_i (out, in place). When
 * every weight is zero beta0 = 1. o->e_max, o->e_sum get ln sum_i e_i over
 * the detections (trk_i_pda_log_sum_e). */
TRK_INLINE trk_real trk_i_pda_normalise(trk_real log_e0, size_t n, trk_real *w, trk_real w_max,
                                        struct trk_i_pda_out *o)
{
    trk_real e0, sum_meas = 0;
    if (!trk_i_pda_exp(log_e0, n, w, w_max, &e0, o)) return 1;
    for (size_t i = 0; i < n; i++) sum_meas += w[i];
    return e0 * trk_i_pda_exp_scale(e0, sum_meas, n, w, o);
}

/* S_j = H P H' + R_j of a detection with its own covariance (gating and the
 * update use the same). */
TRK_INLINE void trk_i_pda_own_s(const struct trk_i_pda_pred *pr, const trk_real *r_j, trk_real *s)
{
    const int nz = pr->nz;
    if (pr->sel && nz == 2) { /* the tracker's [x, y]: written out */
        const trk_real *px = pr->pht + pr->sel[0] * 2, *py = pr->pht + pr->sel[1] * 2;
        s[0] = px[0] + r_j[0];
        s[1] = px[1] + r_j[1];
        s[2] = py[0] + r_j[2];
        s[3] = py[1] + r_j[3];
    } else if (pr->sel) {
        for (int j = 0; j < nz; j++)
            for (int k = 0; k < nz; k++) s[j * nz + k] = pr->pht[pr->sel[j] * nz + k] + r_j[j * nz + k];
    } else {
        trk_i_mat_mul(nz, pr->nx, nz, pr->h, pr->pht, s);
        for (int i = 0; i < nz * nz; i++) s[i] += r_j[i];
    }
    trk_i_symmetrize(nz, s);
}

/* L^-1 (S = L L') and ln det S; TRK_E_NOT_SPD when S is not SPD. */
TRK_INLINE trk_status trk_i_pda_factor(int nz, const trk_real *s, trk_real *l_inv, trk_real *log_det)
{
    trk_real l[TRK_MAX_MEAS * TRK_MAX_MEAS];
    trk_status st = trk_i_chol(nz, s, l);
    if (st != TRK_OK) return st;
    trk_i_tril_inverse(nz, l, l_inv);
    *log_det = trk_i_chol_logdet(nz, l);
    return TRK_OK;
}

/* u = P- H' L^-T (nx x nz), so that K = u L^-1 and K nu = u y with the
 * whitened innovation y = L^-1 nu (S = L L'). */
TRK_INLINE void trk_i_pda_u(int nx, int nz, const trk_real *pht, const trk_real *l_inv, trk_real *u)
{
    for (int a = 0; a < nx; a++)
        for (int j = 0; j < nz; j++) {
            trk_real s = 0;
            for (int t = 0; t <= j; t++) s += pht[a * nz + t] * l_inv[j * nz + t];
            u[a * nz + j] = s;
        }
}

/* y = L^-1 (z - z_pred) */
TRK_INLINE void trk_i_pda_whiten(int nz, const trk_real *l_inv, const trk_real *z,
                                 const trk_real *z_pred, trk_real *y)
{
    trk_real nu[TRK_MAX_MEAS];
    for (int t = 0; t < nz; t++) nu[t] = z[t] - z_pred[t];
    trk_i_tril_mul(nz, l_inv, nu, y);
}

/* acc (upper triangle, nx x nx) += w d d' */
TRK_INLINE void trk_i_pda_rank1(int nx, trk_real *acc, trk_real w, const trk_real *d)
{
    for (int a = 0; a < nx; a++) {
        trk_real wd = w * d[a];
        for (int b = a; b < nx; b++) acc[a * nx + b] += wd * d[b];
    }
}

/* Detection i >= n_shared with its own covariance: the move d = K_j nu_j =
 * u_j y_j, and with pc_sum not NULL also pc_sum += beta_j P_c,j (Joseph;
 * the upper triangle). */
TRK_INLINE void trk_i_pda_own_move(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                   size_t i, trk_real *d, trk_real *pc_sum)
{
    const int nx = pr->nx, nz = pr->nz;
    const trk_real *r_j = s->r_own + (i - s->n_shared) * (size_t)(nz * nz);
    trk_real sj[TRK_MAX_MEAS * TRK_MAX_MEAS], li[TRK_MAX_MEAS * TRK_MAX_MEAS], log_det;
    trk_real u[TRK_MAX_STATE * TRK_MAX_MEAS], y[TRK_MAX_MEAS];
    trk_i_pda_own_s(pr, r_j, sj);
    if (trk_i_pda_factor(nz, sj, li, &log_det) != TRK_OK) { /* cannot happen: it was gated */
        for (int a = 0; a < nx; a++) d[a] = 0;
        return;
    }
    if (pc_sum) {
        trk_real k[TRK_MAX_STATE * TRK_MAX_MEAS], pc[TRK_MAX_STATE * TRK_MAX_STATE];
        trk_i_gain(nx, nz, pr->pht, li, k);
        trk_i_joseph_upper(nx, nz, pr->h, pr->sel, r_j, k, pr->p, pr->pht, s->w[i], pc);
        for (int a = 0; a < nx; a++)
            for (int b = a; b < nx; b++) pc_sum[a * nx + b] += pc[a * nx + b]; /* the upper triangle */
    }
    trk_i_pda_u(nx, nz, pr->pht, li, u);
    trk_i_pda_whiten(nz, li, s->z + i * (size_t)nz, pr->inn->z_pred, y);
    trk_i_mat_mul(nx, nz, 1, u, y, d);
}

/* The moments of the shared group (beta_i, i < n_shared) over its whitened
 * innovations y_i = L^-1 nu_i: B = sum beta_i, sy = sum beta_i y_i, and w
 * (nz x nz) = sum beta_i (y_i - ybar)(y_i - ybar)' about ybar = sy / B, in a
 * second pass (centred: a sum of positive semi-definite terms, accurate to
 * rounding of its own size; the one-pass form sum beta_i y_i y_i' - sy sy'/B
 * lost up to all of a float covariance's digits with clustered detections
 * and H P H' >> R). Entries with beta = 0 are skipped (their y may be
 * infinite). pc_sum = B P_c (Joseph form with the shared R; its upper
 * triangle, which is all trk_i_pda_combine reads). */
TRK_INLINE trk_real trk_i_pda_shared_sums(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                          trk_real *sy, trk_real *w, trk_real *pc_sum)
{
    const int nx = pr->nx, nz = pr->nz;
    trk_real bsum = 0, y[TRK_MAX_MEAS], ybar[TRK_MAX_MEAS];
    for (int t = 0; t < nz; t++) sy[t] = 0;
    for (int t = 0; t < nz * nz; t++) w[t] = 0;
    for (size_t i = 0; i < s->n_shared; i++) {
        const trk_real b = s->w[i];
        if (b == 0) continue;
        trk_i_pda_whiten(nz, pr->inn->s_chol_inv, s->z + i * (size_t)nz, pr->inn->z_pred, y);
        bsum += b;
        for (int a = 0; a < nz; a++) sy[a] += b * y[a];
    }
    if (!(bsum > 0)) {
        for (int a = 0; a < nx * nx; a++) pc_sum[a] = 0;
        return bsum;
    }
    for (int t = 0; t < nz; t++) ybar[t] = sy[t] / bsum;
    for (size_t i = 0; i < s->n_shared; i++) {
        const trk_real b = s->w[i];
        if (b == 0) continue;
        trk_i_pda_whiten(nz, pr->inn->s_chol_inv, s->z + i * (size_t)nz, pr->inn->z_pred, y);
        for (int t = 0; t < nz; t++) y[t] -= ybar[t];
        for (int a = 0; a < nz; a++)
            for (int t = a; t < nz; t++) w[a * nz + t] += b * y[a] * y[t];
    }
    for (int a = 0; a < nz; a++)
        for (int t = a + 1; t < nz; t++) w[t * nz + a] = w[a * nz + t];
    trk_real k[TRK_MAX_STATE * TRK_MAX_MEAS];
    trk_i_gain(nx, nz, pr->pht, pr->inn->s_chol_inv, k);
    trk_i_joseph_upper(nx, nz, pr->h, pr->sel, pr->r, k, pr->p, pr->pht, bsum, pc_sum);
    return bsum;
}

/* acc += the spread of the shared group about dxbar, split by the law of
 * total variance: u W u' + B (u ybar - dxbar)(u ybar - dxbar)', with
 * ybar = sy / B and W from trk_i_pda_shared_sums. */
TRK_INLINE void trk_i_pda_shared_spread(const struct trk_i_pda_pred *pr, const trk_real *u, trk_real bsum,
                                        const trk_real *sy, const trk_real *w, const trk_real *dxbar,
                                        trk_real *acc)
{
    const int nx = pr->nx, nz = pr->nz;
    trk_real ybar[TRK_MAX_MEAS], uw[TRK_MAX_STATE * TRK_MAX_MEAS], d[TRK_MAX_STATE];
    for (int t = 0; t < nz; t++) ybar[t] = sy[t] / bsum;
    trk_i_mat_mul(nx, nz, nz, u, w, uw);
    for (int a = 0; a < nx; a++)
        for (int b = a; b < nx; b++) {
            trk_real v = 0;
            for (int t = 0; t < nz; t++) v += uw[a * nz + t] * u[b * nz + t];
            acc[a * nx + b] += v;
        }
    trk_i_mat_mul(nx, nz, 1, u, ybar, d);
    for (int a = 0; a < nx; a++) d[a] -= dxbar[a];
    trk_i_pda_rank1(nx, acc, bsum, d);
}

/* The 2-D CV model (state [x, vx, y, vy], H selecting x and y) with every
 * detection sharing S, the usual case, has a path of its own (the
 * per-track update within 1.25x of a hand-written loop): the same moment
 * match as the general code below, written out over the model's fixed
 * indices, with the weights' moments taken in one pass about a shift (see
 * struct trk_i_cv2_moments) and the weight-free Joseph part formed first.
 * test_pda checks it against the general code (the same track embedded in 5
 * states). Size builds keep the general code alone. */
TRK_INLINE int trk_i_pda_is_cv2(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s)
{
#if TRK_SIZE_OPT
    (void)pr;
    (void)s;
    return 0;
#else
    return pr->nx == TRK_CV2_NX && pr->nz == TRK_CV2_NZ && s->n_shared == s->n && pr->sel &&
           pr->sel[0] == TRK_CV2_X && pr->sel[1] == TRK_CV2_Y;
#endif
}

/* The weights' moments in whitened coordinates y_i = L^-1 nu_i: B = sum
 * beta_i, sy = sum beta_i y_i and W = sum beta_i (y_i - ybar)(y_i - ybar)'
 * about ybar = sy / B, accumulated as sums about a shift c (the whitened
 * innovation of the detection with the largest weight) and corrected at the
 * end: W = sum beta_i (y_i - c)(y_i - c)' - B (ybar - c)(ybar - c)'. With
 * beta_c >= B / n, B |ybar - c|^2 <= n tr W, so the correction cancels at
 * most n times the rounding of W itself (the unshifted one-pass form lost
 * up to all of a float covariance's digits with clustered detections and
 * H P H' >> R; test_pda's clustered cases). */
struct trk_i_cv2_moments {
    trk_real b, y0, y1, w00, w01, w11; /* B, ybar (sums about c while accumulated), W */
};

/* The whitened innovation of detection i: y = L^-1 (z_i - z_pred) */
TRK_INLINE void trk_i_cv2_whiten(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s, size_t i,
                                 trk_real *y0, trk_real *y1)
{
    const trk_real *li = pr->inn->s_chol_inv;
    const trk_real n0 = s->z[2 * i] - pr->inn->z_pred[0], n1 = s->z[2 * i + 1] - pr->inn->z_pred[1];
    *y0 = li[0] * n0;
    *y1 = li[2] * n0 + li[3] * n1;
}

/* acc += e (y - c)(y - c)' and its first moments (upper triangle) */
TRK_INLINE void trk_i_cv2_moments_add(struct trk_i_cv2_moments *acc, trk_real e, trk_real d0, trk_real d1)
{
    const trk_real e0 = e * d0, e1 = e * d1;
    acc->b += e;
    acc->y0 += e0;
    acc->y1 += e1;
    acc->w00 += e0 * d0;
    acc->w01 += e0 * d1;
    acc->w11 += e1 * d1;
}

/* The sums about c of weights e_i, scaled by f (the normalisation), into
 * the moments of beta_i = f e_i (see struct trk_i_cv2_moments; 1 / sum e_i
 * here and f computed side by side, not one after the other). */
TRK_INLINE void trk_i_cv2_moments_end(struct trk_i_cv2_moments *m, trk_real f, trk_real c0, trk_real c1)
{
    const trk_real inv = m->b > 0 ? 1 / m->b : 0, d0 = m->y0 * inv, d1 = m->y1 * inv; /* ybar - c */
    m->w00 = f * (m->w00 - m->y0 * d0);
    m->w01 = f * (m->w01 - m->y0 * d1);
    m->w11 = f * (m->w11 - m->y1 * d1);
    m->b *= f;
    m->y0 = d0 + c0;
    m->y1 = d1 + c1;
}

/* The moments of the weights s->w = beta_i about the shift c = y_k, the
 * whitened innovation of detection k (the one with the largest weight), in
 * one pass (in registers: no call in the loop). Entries with beta = 0 are
 * skipped (outside the gate: their y may be infinite). */
TRK_INLINE void trk_i_pda_moments_cv2(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s, size_t k,
                                      struct trk_i_cv2_moments *m)
{
    trk_real c0 = 0, c1 = 0, y0, y1;
    if (k < s->n && s->w[k] > 0) trk_i_cv2_whiten(pr, s, k, &c0, &c1);
    struct trk_i_cv2_moments acc = {0, 0, 0, 0, 0, 0};
    for (size_t i = 0; i < s->n; i++) {
        const trk_real b = s->w[i];
        if (b == 0) continue;
        trk_i_cv2_whiten(pr, s, i, &y0, &y1);
        trk_i_cv2_moments_add(&acc, b, y0 - c0, y1 - c1);
    }
    trk_i_cv2_moments_end(&acc, 1, c0, c1);
    *m = acc;
}

/* trk_i_pda_normalise with the moments taken on the way: ln e_i (s->w,
 * largest s->w_max at s->w_arg) -> beta_i (in place), beta0 (returned), *m
 * (of the unnormalised e_i, in a loop without calls, then scaled: the
 * division and the moments do not wait for each other), and o->e_max,
 * o->e_sum as trk_i_pda_normalise. */
TRK_INLINE trk_real trk_i_pda_normalise_cv2(trk_real log_e0, const struct trk_i_pda_pred *pr,
                                            const struct trk_i_pda_set *s, struct trk_i_pda_out *o,
                                            struct trk_i_cv2_moments *m)
{
    struct trk_i_cv2_moments acc = {0, 0, 0, 0, 0, 0};
    trk_real e0, c0 = 0, c1 = 0, y0, y1;
    *m = acc;
    if (!trk_i_pda_exp(log_e0, s->n, s->w, s->w_max, &e0, o)) return 1;
    if (s->w_max > -TRK_REAL_MAX) trk_i_cv2_whiten(pr, s, s->w_arg, &c0, &c1);
    for (size_t i = 0; i < s->n; i++) { /* the moments of e_i (sum e_i = acc.b) */
        const trk_real e = s->w[i];
        if (e == 0) continue; /* (outside the gate; its y may be infinite) */
        trk_i_cv2_whiten(pr, s, i, &y0, &y1);
        trk_i_cv2_moments_add(&acc, e, y0 - c0, y1 - c1);
    }
    const trk_real inv = trk_i_pda_exp_scale(e0, acc.b, s->n, s->w, o);
    trk_i_cv2_moments_end(&acc, inv, c0, c1);
    *m = acc;
    return e0 * inv;
}

/* The index of the largest of w[0..n) (0 for none) */
TRK_INLINE size_t trk_i_pda_arg_max(size_t n, const trk_real *w)
{
    size_t k = 0;
    for (size_t i = 1; i < n; i++)
        if (w[i] > w[k]) k = i;
    return k;
}

/* The CV path's weight-free part: u = P H' L^-T, K = u L^-1 and the Joseph
 * form P_c = A - E K' with A = P - K (P H')', E = A H' - K R
 * (trk_i_joseph_upper); formed before the weights, so that it overlaps
 * their chain of exponentials and sums. P H' is read from the rows of x and
 * y (P is symmetric: contiguous, so the float build forms u and K four
 * lanes at a time; 8 ns of 123 at m = 10). */
struct trk_i_cv2_gain {
    trk_real u0[TRK_CV2_NX], u1[TRK_CV2_NX];         /* u (columns) */
    trk_real pc[TRK_CV2_NX * TRK_CV2_NX];             /* P_c (rows; the upper triangle is used) */
};

/* The same for any R and its S = H P H' + R's L^-1 (li: [0] and [2], [3]
 * of the lower triangle). */
TRK_INLINE void trk_i_pda_gain_cv2_r(const trk_real *p, const trk_real *r, const trk_real *li,
                                     struct trk_i_cv2_gain *g)
{
    enum { N = TRK_CV2_NX };
    const trk_real m00 = li[0], m10 = li[2], m11 = li[3]; /* L^-1 */
    trk_real ph0[N], ph1[N], k0[N], k1[N], e0[N], e1[N];
    for (int a = 0; a < N; a++) {
        ph0[a] = p[TRK_CV2_X * N + a]; /* P H' from the rows of P (symmetric) */
        ph1[a] = p[TRK_CV2_Y * N + a];
        g->u0[a] = ph0[a] * m00;
        g->u1[a] = ph0[a] * m10 + ph1[a] * m11;
        k0[a] = g->u0[a] * m00 + g->u1[a] * m10;
        k1[a] = g->u1[a] * m11;
    }
    for (int a = 0; a < N; a++) {
        const trk_real a0 = ph0[a] - (k0[a] * ph0[TRK_CV2_X] + k1[a] * ph1[TRK_CV2_X]);
        const trk_real a2 = ph1[a] - (k0[a] * ph0[TRK_CV2_Y] + k1[a] * ph1[TRK_CV2_Y]);
        e0[a] = a0 - (k0[a] * r[0] + k1[a] * r[2]);
        e1[a] = a2 - (k0[a] * r[1] + k1[a] * r[3]);
    }
    for (int a = 0; a < N; a++) { /* whole rows (they vectorise) */
        const trk_real ka0 = k0[a], ka1 = k1[a], ea0 = e0[a], ea1 = e1[a];
        for (int b = 0; b < N; b++)
            g->pc[a * N + b] = p[a * N + b] - (ka0 * ph0[b] + ka1 * ph1[b]) - (ea0 * k0[b] + ea1 * k1[b]);
    }
}

TRK_INLINE void trk_i_pda_gain_cv2(const struct trk_i_pda_pred *pr, struct trk_i_cv2_gain *g)
{
    trk_i_pda_gain_cv2_r(pr->p, pr->r, pr->inn->s_chol_inv, g);
}

/* trk_i_pda_combine for the CV path, from the gain part *g and the
 * moments *m. */
TRK_INLINE void trk_i_pda_combine_cv2(const struct trk_i_pda_pred *pr, const struct trk_i_cv2_gain *g,
                                      const struct trk_i_cv2_moments *m, trk_real beta0, trk_real *x_new,
                                      trk_real *acc)
{
    enum { N = TRK_CV2_NX };
    const trk_real *p = pr->p;
    const trk_real bsum = m->b, yb0 = m->y0, yb1 = m->y1;
    /* The moves: u ybar, dxbar = B u ybar, and d = u ybar - dxbar; their
     * terms beta0 dxbar dxbar' + B d d' = c (u ybar)(u ybar)' join u W u'
     * as u W' u', W' = W + c ybar ybar' (c >= 0) */
    const trk_real c = bsum * (beta0 * bsum + (1 - bsum) * (1 - bsum));
    const trk_real w00 = m->w00 + c * yb0 * yb0, w01 = m->w01 + c * yb0 * yb1, w11 = m->w11 + c * yb1 * yb1;
    trk_real v0[N], v1[N];
    for (int a = 0; a < N; a++) {
        x_new[a] = pr->x[a] + bsum * (g->u0[a] * yb0 + g->u1[a] * yb1);
        v0[a] = g->u0[a] * w00 + g->u1[a] * w01; /* u W' */
        v1[a] = g->u0[a] * w01 + g->u1[a] * w11;
    }
    /* P = beta0 P- + B P_c + u W' u' (B = 0: W' = 0): whole rows, then the
     * upper triangle mirrored */
    for (int a = 0; a < N; a++) {
        const trk_real va0 = v0[a], va1 = v1[a];
        for (int b = 0; b < N; b++)
            acc[a * N + b] = beta0 * p[a * N + b] + bsum * g->pc[a * N + b] + (va0 * g->u0[b] + va1 * g->u1[b]);
    }
    for (int a = 0; a < N; a++)
        for (int b = a + 1; b < N; b++) acc[b * N + a] = acc[a * N + b];
}

/* The CV layout (as trk_i_pda_is_cv2) whatever the detections' covariances. */
TRK_INLINE int trk_i_pda_is_cv2_layout(const struct trk_i_pda_pred *pr)
{
#if TRK_SIZE_OPT
    (void)pr;
    return 0;
#else
    return pr->nx == TRK_CV2_NX && pr->nz == TRK_CV2_NZ && pr->sel && pr->sel[0] == TRK_CV2_X &&
           pr->sel[1] == TRK_CV2_Y;
#endif
}

/* Own-covariance detection i of the CV path: its gain part (u_j, the
 * Joseph P_c,j with R_j) into *g and its move d = u_j y_j (y_j = L_j^-1
 * nu_j). 0 when S_j does not factor (cannot happen: it was gated). */
TRK_INLINE int trk_i_cv2_own(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s, size_t i,
                             struct trk_i_cv2_gain *g, trk_real *d)
{
    const trk_real *r_j = s->r_own + (i - s->n_shared) * (size_t)(TRK_CV2_NZ * TRK_CV2_NZ);
    trk_real sj[TRK_CV2_NZ * TRK_CV2_NZ], li[TRK_CV2_NZ * TRK_CV2_NZ], log_det;
    trk_i_pda_own_s(pr, r_j, sj);
    if (trk_i_pda_factor(TRK_CV2_NZ, sj, li, &log_det) != TRK_OK) return 0;
    trk_i_pda_gain_cv2_r(pr->p, r_j, li, g);
    const trk_real n0 = s->z[2 * i] - pr->inn->z_pred[0], n1 = s->z[2 * i + 1] - pr->inn->z_pred[1];
    const trk_real y0 = li[0] * n0, y1 = li[2] * n0 + li[3] * n1;
    for (int a = 0; a < TRK_CV2_NX; a++) d[a] = g->u0[a] * y0 + g->u1[a] * y1;
    return 1;
}

/* The moment match over components (weight w, mean move mu) about a shift
 * c: sm = sum w (mu - c), m = sum w (mu - c)(mu - c)' (upper triangle). */
TRK_INLINE void trk_i_cv2_spread_add(trk_real w, const trk_real *mu, const trk_real *c, trk_real *sm, trk_real *m)
{
    trk_real e[TRK_CV2_NX];
    for (int a = 0; a < TRK_CV2_NX; a++) {
        e[a] = mu[a] - c[a];
        sm[a] += w * e[a];
    }
    for (int a = 0; a < TRK_CV2_NX; a++)
        for (int b = a; b < TRK_CV2_NX; b++) m[a * TRK_CV2_NX + b] += w * e[a] * e[b];
}

/* trk_i_pda_combine for the CV path with detections of their own R_j: the
 * mixture as components, each with its weight, mean move and covariance
 * sum: no detection (beta0, 0, beta0 P-), the shared group as one (B, u
 * ybar, B P_c + u W u', W its centred spread), each own-covariance
 * detection (beta_j, d_j, beta_j P_c,j with its own gain). Their spread
 * sum w (mu - mubar)(mu - mubar)' in one pass about the mean of the
 * heaviest component (as struct trk_i_cv2_moments: the correction cancels
 * at most a few times its own rounding), so each detection's gain is formed
 * once (the general code forms it twice). test_pda checks it against the
 * general code. */
TRK_INLINE void trk_i_pda_combine_cv2_own(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                          trk_real beta0, trk_real *x_new, trk_real *acc)
{
    enum { N = TRK_CV2_NX };
    struct trk_i_cv2_gain g;
    const trk_real none[N] = {0, 0, 0, 0}; /* the no-detection hypothesis's move */
    trk_real c[N] = {0, 0, 0, 0}, mu_sh[N] = {0, 0, 0, 0}, d[N], sm[N] = {0, 0, 0, 0}, m[N * N] = {0};
    /* the shared group: its moments and move */
    struct trk_i_pda_set sh = *s;
    sh.n = s->n_shared;
    struct trk_i_cv2_moments ms = {0, 0, 0, 0, 0, 0};
    /* acc = beta0 P- + B P_c + u W u' (upper triangle; a set of own
     * covariances alone, a polar sensor's, has no shared group to form) */
    for (int a = 0; a < N; a++)
        for (int b = a; b < N; b++) acc[a * N + b] = beta0 * pr->p[a * N + b];
    if (sh.n > 0) {
        trk_i_pda_moments_cv2(pr, &sh, trk_i_pda_arg_max(sh.n, sh.w), &ms);
        trk_i_pda_gain_cv2(pr, &g);
        for (int a = 0; a < N; a++) mu_sh[a] = g.u0[a] * ms.y0 + g.u1[a] * ms.y1;
        for (int a = 0; a < N; a++)
            for (int b = a; b < N; b++)
                acc[a * N + b] += ms.b * g.pc[a * N + b] + g.u0[a] * (ms.w00 * g.u0[b] + ms.w01 * g.u1[b]) +
                                  g.u1[a] * (ms.w01 * g.u0[b] + ms.w11 * g.u1[b]);
    }
    /* the shift: the heaviest component's mean */
    size_t k = s->n_shared;
    for (size_t i = s->n_shared + 1; i < s->n; i++)
        if (s->w[i] > s->w[k]) k = i;
    if (s->w[k] > beta0 && s->w[k] > ms.b) {
        if (!trk_i_cv2_own(pr, s, k, &g, c))
            for (int a = 0; a < N; a++) c[a] = 0;
    } else if (ms.b > beta0) {
        for (int a = 0; a < N; a++) c[a] = mu_sh[a];
    }
    trk_real total = beta0 + ms.b;
    trk_i_cv2_spread_add(beta0, none, c, sm, m);
    if (ms.b > 0) trk_i_cv2_spread_add(ms.b, mu_sh, c, sm, m);
    for (size_t i = s->n_shared; i < s->n; i++) {
        const trk_real w = s->w[i];
        if (w == 0 || !trk_i_cv2_own(pr, s, i, &g, d)) continue;
        total += w;
        for (int a = 0; a < N; a++)
            for (int b = a; b < N; b++) acc[a * N + b] += w * g.pc[a * N + b];
        trk_i_cv2_spread_add(w, d, c, sm, m);
    }
    /* mubar = c + sm / total; spread = m - sm sm' / total */
    const trk_real inv = total > 0 ? 1 / total : 0;
    for (int a = 0; a < N; a++) x_new[a] = pr->x[a] + c[a] + sm[a] * inv;
    for (int a = 0; a < N; a++)
        for (int b = a; b < N; b++) acc[a * N + b] += m[a * N + b] - sm[a] * sm[b] * inv;
    for (int a = 0; a < N; a++)
        for (int b = a + 1; b < N; b++) acc[b * N + a] = acc[a * N + b];
}

/* The PDA state and covariance update as the moment match of a Gaussian
 * mixture, written so that every term is positive semi-definite.
 * Hypothesis i (beta_i) moves the state by dx_i = K_i nu_i; hypothesis 0
 * (beta0) by 0:
 *   x = x- + dxbar,  dxbar = sum_i beta_i dx_i
 *   P = beta0 P- + sum_i beta_i P_c,i + sum_i beta_i (dx_i - dxbar)(dx_i - dxbar)'
 *       + beta0 dxbar dxbar'
 * With the shared group alone this is exactly the standard form
 *   P = beta0 P- + (1 - beta0) P_c + K (sum beta_i nu_i nu_i' - nubar nubar') K'.
 * Detections with their own R_j enter one by one (their own K_j). Entries
 * with beta = 0 are skipped. Out: x_new and P (acc, symmetric). */
TRK_INLINE void trk_i_pda_combine(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                  trk_real beta0, trk_real *x_new, trk_real *acc)
{
    const int nx = pr->nx, nz = pr->nz;
    if (trk_i_pda_is_cv2(pr, s)) {
        struct trk_i_cv2_gain g;
        struct trk_i_cv2_moments m;
        trk_i_pda_gain_cv2(pr, &g);
        trk_i_pda_moments_cv2(pr, s, trk_i_pda_arg_max(s->n, s->w), &m);
        trk_i_pda_combine_cv2(pr, &g, &m, beta0, x_new, acc);
        return;
    }
    if (trk_i_pda_is_cv2_layout(pr)) {
        trk_i_pda_combine_cv2_own(pr, s, beta0, x_new, acc);
        return;
    }
    trk_real u[TRK_MAX_STATE * TRK_MAX_MEAS], sy[TRK_MAX_MEAS], w[TRK_MAX_MEAS * TRK_MAX_MEAS];
    trk_real dxbar[TRK_MAX_STATE], d[TRK_MAX_STATE];
    const trk_real bsum = trk_i_pda_shared_sums(pr, s, sy, w, acc); /* acc = pc_sum first */
    trk_i_pda_u(nx, nz, pr->pht, pr->inn->s_chol_inv, u);
    trk_i_mat_mul(nx, nz, 1, u, sy, dxbar);
    for (size_t i = s->n_shared; i < s->n; i++) {
        if (s->w[i] == 0) continue;
        trk_i_pda_own_move(pr, s, i, d, acc);
        for (int a = 0; a < nx; a++) dxbar[a] += s->w[i] * d[a];
    }
    for (int a = 0; a < nx; a++)
        for (int b = a; b < nx; b++)
            acc[a * nx + b] = beta0 * (pr->p[a * nx + b] + dxbar[a] * dxbar[b]) + acc[a * nx + b];
    if (bsum > 0) trk_i_pda_shared_spread(pr, u, bsum, sy, w, dxbar, acc);
    for (size_t i = s->n_shared; i < s->n; i++) {
        if (s->w[i] == 0) continue;
        trk_i_pda_own_move(pr, s, i, d, NULL);
        for (int a = 0; a < nx; a++) d[a] -= dxbar[a];
        trk_i_pda_rank1(nx, acc, s->w[i], d);
    }
    for (int a = 0; a < nx; a++) {
        x_new[a] = pr->x[a] + dxbar[a];
        for (int b = a + 1; b < nx; b++) acc[b * nx + a] = acc[a * nx + b];
    }
}

/* A usable state and covariance: every value finite (else TRK_E_NAN),
 * every variance > 0 (else TRK_E_NOT_SPD). */
TRK_INLINE trk_status trk_i_pda_check(int nx, const trk_real *x, const trk_real *p)
{
    int finite = 1, positive = 1;
    for (int a = 0; a < nx; a++) finite &= isfinite(x[a]) != 0;
    for (int a = 0; a < nx * nx; a++) finite &= isfinite(p[a]) != 0;
    for (int a = 0; a < nx; a++) positive &= p[a * nx + a] > 0;
    return !finite ? TRK_E_NAN : positive ? TRK_OK : TRK_E_NOT_SPD;
}

/* The posterior (x, symmetric P) checked: TRK_OK when x is finite and P
 * positive definite (its LDL' pivots, trk_i_spd_inline: a non-finite entry
 * fails them too), else trk_i_pda_check's status. The factorisation first,
 * the scan over P only for the status of a failure. */
TRK_INLINE trk_status trk_i_pda_check_posterior(int nx, const trk_real *x, const trk_real *p)
{
    int finite = 1;
    for (int a = 0; a < nx; a++) finite &= isfinite(x[a]) != 0;
#if TRK_SIZE_OPT
    const trk_status st = trk_i_spd(nx, p); /* out of line */
#else /* unrolled at the caller's nx; the CV state's 4 x 4 division-free first */
    const trk_status st = (nx == 4 && trk_i_spd4_sure(p)) ? TRK_OK : trk_i_spd_inline(nx, p);
#endif
    if (finite && st == TRK_OK) return TRK_OK;
    const trk_status why = trk_i_pda_check(nx, x, p);
    return why != TRK_OK ? why : TRK_E_NOT_SPD;
}

/* V_G of an update (docs/conventions.md "PDA"): the shared S's; for
 * nonparametric clutter over a set with detections of their own covariance,
 * each gated in its own S_j = H P H' + R_j, the mean of the gated
 * detections' gate volumes (V(S) for a shared one, V(S_j) for an own one),
 * so that lambda = m_G / V_G counts the detections against the gates they
 * were gated in. */
static TRK_NOINLINE trk_real trk_i_pda_own_volume_mean(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                                       const struct trk_i_pda_set *s, trk_real v);

TRK_INLINE trk_real trk_i_pda_gate_volume(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                          const struct trk_i_pda_set *s)
{
    const trk_real v = trk_i_gate_volume(pr->nz, pda->gamma, pr->inn->sqrt_det_s, pr->inn->log_det_s);
    if (pda->params.clutter != TRK_CLUTTER_NONPARAMETRIC || s->n <= s->n_shared) return v;
    return trk_i_pda_own_volume_mean(pda, pr, s, v);
}

/* The mean of trk_i_pda_gate_volume, v the shared S's volume (not inlined:
 * its S_j and factor stay off the update's deepest frame). */
static TRK_NOINLINE trk_real trk_i_pda_own_volume_mean(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                                       const struct trk_i_pda_set *s, trk_real v)
{
    const int nz = pr->nz;
    trk_real sum = v * (trk_real)s->n_shared;
    for (size_t i = s->n_shared; i < s->n; i++) {
        trk_real sj[TRK_MAX_MEAS * TRK_MAX_MEAS], li[TRK_MAX_MEAS * TRK_MAX_MEAS], log_det;
        trk_i_pda_own_s(pr, s->r_own + (i - s->n_shared) * (size_t)(nz * nz), sj);
        /* gated, so S_j factors; were it not, its share is the shared V */
        sum += trk_i_pda_factor(nz, sj, li, &log_det) == TRK_OK
                   ? trk_i_gate_volume(nz, pda->gamma, (trk_real)INFINITY, log_det)
                   : v;
    }
    return sum / (trk_real)s->n;
}

/* V_G (trk_i_pda_gate_volume) and the clutter density (given, or m_G /
 * V_G) into *o, with beta0 = 1 and no detection weight yet. */
TRK_INLINE void trk_i_pda_clutter(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                  const struct trk_i_pda_set *s, struct trk_i_pda_out *o)
{
    o->gate_volume = trk_i_pda_gate_volume(pda, pr, s);
    o->lambda = pda->params.clutter == TRK_CLUTTER_PARAMETRIC ? pda->params.clutter_density
                                                             : (trk_real)s->m_gated / o->gate_volume;
    o->beta0 = 1;
    o->e_max = 0;
    o->e_sum = 0;
}

/* The posterior (x, P) checked (trk_i_pda_check_posterior), then written
 * over the prediction pr->x, pr->p; left untouched on a failure. */
TRK_INLINE trk_status trk_i_pda_commit(const struct trk_i_pda_pred *pr, const trk_real *x, const trk_real *p)
{
    const int nx = pr->nx;
    const trk_status st = trk_i_pda_check_posterior(nx, x, p);
    if (st != TRK_OK) return st;
    for (int a = 0; a < nx; a++) pr->x[a] = x[a];
    for (int a = 0; a < nx * nx; a++) pr->p[a] = p[a];
    return TRK_OK;
}

/* The posterior for given weights (s->w = beta_i, beta0), checked, written
 * over the prediction pr->x, pr->p: TRK_E_NAN / TRK_E_NOT_SPD for a
 * posterior that is not finite or not positive definite (its factorisation
 * fails), pr->x, pr->p then untouched. The PDA's last stage, and the whole
 * of a joint (JPDA) update, whose weights come from the joint events. */
TRK_INLINE trk_status trk_i_pda_update_beta(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                            trk_real beta0)
{
    trk_real x[TRK_MAX_STATE], acc[TRK_MAX_STATE * TRK_MAX_STATE];
    trk_i_pda_combine(pr, s, beta0, x, acc);
    return trk_i_pda_commit(pr, x, acc);
}

/* One track's PDA over its gated set *s (docs/conventions.md "PDA"): lambda (given,
 * or m_G / V_G), beta (into s->w), and the posterior written over the
 * prediction pr->x, pr->p, with *o. With m_G = 0 the prediction is the
 * posterior (left as the caller made it). Statuses as
 * trk_i_pda_update_beta. */
TRK_INLINE trk_status trk_i_pda_update_set(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                           struct trk_i_pda_set *s, struct trk_i_pda_out *o)
{
    trk_i_pda_clutter(pda, pr, s, o);
    if (s->m_gated == 0) { /* nothing to associate (also nonparametric m_G = 0): x, P = prediction */
        for (size_t i = 0; i < s->n; i++) s->w[i] = 0;
        return TRK_OK;
    }
    const trk_real log_e0 = trk_i_pda_log_e0(pda, o->lambda);
    if (trk_i_pda_is_cv2(pr, s)) { /* the Joseph part first, then the weights and their moments */
        struct trk_i_cv2_gain g;
        struct trk_i_cv2_moments m;
        trk_real x[TRK_CV2_NX], acc[TRK_CV2_NX * TRK_CV2_NX];
        trk_i_pda_gain_cv2(pr, &g);
        o->beta0 = trk_i_pda_normalise_cv2(log_e0, pr, s, o, &m);
        trk_i_pda_combine_cv2(pr, &g, &m, o->beta0, x, acc);
        return trk_i_pda_commit(pr, x, acc);
    }
    o->beta0 = trk_i_pda_normalise(log_e0, s->n, s->w, s->w_max, o);
    return trk_i_pda_update_beta(pr, s, o->beta0);
}

/* The same two, out of line with run-time dimensions (pda.c). */
trk_status trk_i_pda_update_set_rt(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                   struct trk_i_pda_set *s, struct trk_i_pda_out *o);
trk_status trk_i_pda_update_beta_rt(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                    trk_real beta0);

/* What callers call: inlined where speed counts (the caller's constant
 * dimensions unroll it), the one out-of-line copy in size-optimised builds
 * (TRK_SIZE_OPT), shared by pda.c and the tracker. */
TRK_INLINE trk_status trk_i_pda_run(const struct trk_pda *pda, const struct trk_i_pda_pred *pr,
                                    struct trk_i_pda_set *s, struct trk_i_pda_out *o)
{
#if TRK_SIZE_OPT
    return trk_i_pda_update_set_rt(pda, pr, s, o);
#else
    return trk_i_pda_update_set(pda, pr, s, o);
#endif
}

TRK_INLINE trk_status trk_i_pda_run_beta(const struct trk_i_pda_pred *pr, const struct trk_i_pda_set *s,
                                         trk_real beta0)
{
#if TRK_SIZE_OPT
    return trk_i_pda_update_beta_rt(pr, s, beta0);
#else
    return trk_i_pda_update_beta(pr, s, beta0);
#endif
}

#endif
