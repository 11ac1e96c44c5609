/* kind_jpda.c - vector kind jpda_update (tests/vectors/jpda.vec;
 * docs/conventions.md "Joint association (JPDA / JIPDA)"): N tracks on one
 * scan through the library: the CV-2D predict and innovation of each track, its row of
 * weights (trk_jpda_track_weights), the joint marginals
 * (trk_jpda_marginals), the JIPDA existence and conditional weights
 * (trk_jpda_existence) and the PDA update of each track with them
 * (trk_pda_update_weights).
 *
 * Float tolerances (normwise, see vec.h): states and covariances as
 * pda_update (kind_pda.c), 2e-4 relative; the marginals and existences carry
 * the float rounding of d2 and of the exponentials of log-weights spread over
 * tens of nats: abs 1e-4. A detection within 0.1 % of a gate boundary is not
 * resolvable in float (VEC_NOT_APPLICABLE), as in kind_pda.c. */
#include <string.h>

#include "trk/jpda.h"
#include "trk/kalman.h"
#include "trk/pda.h"
#include "vec.h"

#define NX TRK_CV2_NX
#define NZ TRK_CV2_NZ

TRK_VEC_KIND(jpda_update, 1e-4, 2e-4, VEC_FAST)
{
    static struct trk_jpda_work work;
    static trk_real x[TRK_MAX_TRACKS][NX], p[TRK_MAX_TRACKS][NX * NX];
    static struct trk_innovation inn[TRK_MAX_TRACKS];
    static trk_real z[2 * TRK_MAX_DETECTIONS], lr[TRK_MAX_DETECTIONS], d2[TRK_MAX_DETECTIONS];
    static trk_real log_w[TRK_MAX_TRACKS * TRK_MAX_DETECTIONS], log_w0[TRK_MAX_TRACKS];
    static trk_real pa[TRK_MAX_TRACKS * TRK_MAX_DETECTIONS], pm[TRK_MAX_TRACKS];
    static trk_real beta[TRK_MAX_DETECTIONS + 1], ex_post[TRK_MAX_TRACKS];
    double t, q, r, pd, pg, lambda;
    long n, m;
    const double *xd, *pdd, *exd, *zd, *lrd;
    if (vec_in_scalar(c, o, "T", &t) || vec_in_scalar(c, o, "q", &q) || vec_in_scalar(c, o, "r", &r) ||
        vec_in_scalar(c, o, "pd", &pd) || vec_in_scalar(c, o, "pg", &pg) || vec_in_scalar(c, o, "lambda", &lambda) ||
        vec_in_int(c, o, "N", &n) || vec_in_int(c, o, "m", &m))
        return -1;
    if (n < 1 || m < 0) return vec_fail(o, "N < 1 or m < 0");
    if (n > TRK_MAX_TRACKS || m > TRK_MAX_DETECTIONS) {
        vec_fail(o, "%ld tracks / %ld detections above this build's capacities", n, m);
        return VEC_NOT_APPLICABLE;
    }
    const size_t nt = (size_t)n, nd = (size_t)m;
    if (vec_in_array_n(c, o, "x", NX * nt, &xd) || vec_in_array_n(c, o, "P", NX * NX * nt, &pdd) ||
        vec_in_array_n(c, o, "ex", nt, &exd) || vec_in_array_n(c, o, "z", 2 * nd, &zd) ||
        vec_in_array_n(c, o, "log_lr", nd, &lrd))
        return -1;
    struct trk_pda pda;
    const struct trk_pda_params pp = {NZ, (trk_real)pd, (trk_real)pg, TRK_CLUTTER_PARAMETRIC, (trk_real)lambda, 1};
    trk_status st = trk_pda_init(&pda, &pp);
    if (st != TRK_OK) return vec_fail(o, "trk_pda_init: %s", trk_status_str(st));
    trk_real f[NX * NX], qm[NX * NX];
    const trk_real rm[NZ * NZ] = {(trk_real)r, 0, 0, (trk_real)r};
    trk_cv2_transition((trk_real)t, f);
    trk_cv2_process_noise((trk_real)t, (trk_real)q, qm);
    for (size_t i = 0; i < 2 * nd; i++) z[i] = (trk_real)zd[i];
    for (size_t j = 0; j < nd; j++) lr[j] = (trk_real)lrd[j];
    double *xo = vec_put_alloc(o, "x_pred", NX * nt), *po = vec_put_alloc(o, "P_pred", NX * NX * nt);
    double *zo = vec_put_alloc(o, "z_pred", NZ * nt), *so = vec_put_alloc(o, "S", NZ * NZ * nt);
    if (!xo || !po || !zo || !so) return -1;
    for (size_t k = 0; k < nt; k++) {
        for (size_t a = 0; a < NX; a++) x[k][a] = (trk_real)xd[k * NX + a];
        for (size_t a = 0; a < NX * NX; a++) p[k][a] = (trk_real)pdd[k * NX * NX + a];
        st = trk_kalman_predict(NX, f, qm, x[k], p[k]);
        if (st == TRK_OK) st = trk_kalman_innovation(NX, NZ, trk_cv2_h, rm, x[k], p[k], &inn[k]);
        if (st != TRK_OK) return vec_fail(o, "track %zu predict: %s", k, trk_status_str(st));
        st = trk_jpda_track_weights(&pda, (trk_real)exd[k], &inn[k], nd, z, lr, log_w + k * nd, &log_w0[k], d2);
        if (st != TRK_OK) return vec_fail(o, "trk_jpda_track_weights: %s", trk_status_str(st));
        if (TRK_REAL_IS_FLOAT)
            for (size_t j = 0; j < nd; j++)
                if (trk_fabs(d2[j] - pda.gamma) <= TRK_REAL_C(1e-3) * pda.gamma) {
                    vec_fail(o, "detection %zu within 0.1%% of track %zu's gate boundary", j, k);
                    return VEC_NOT_APPLICABLE;
                }
        for (size_t a = 0; a < NX; a++) xo[k * NX + a] = (double)x[k][a];
        for (size_t a = 0; a < NX * NX; a++) po[k * NX * NX + a] = (double)p[k][a];
        for (size_t a = 0; a < NZ; a++) zo[k * NZ + a] = (double)inn[k].z_pred[a];
        for (size_t a = 0; a < NZ * NZ; a++) so[k * NZ * NZ + a] = (double)inn[k].s[a];
    }
    const struct trk_jpda_scan scan = {nt, nd, log_w0, log_w};
    st = trk_jpda_marginals(&scan, &work, pa, pm, NULL);
    if (st != TRK_OK) return vec_fail(o, "trk_jpda_marginals: %s", trk_status_str(st));
    double *go = vec_put_alloc(o, "gated", nt * nd), *bo = vec_put_alloc(o, "beta", nt * (nd + 1));
    double *xpo = vec_put_alloc(o, "x_post", NX * nt), *ppo = vec_put_alloc(o, "P_post", NX * NX * nt);
    if ((nd > 0 && !go) || !bo || !xpo || !ppo || vec_put_real(o, "gamma", &pda.gamma, 1)) return -1;
    for (size_t k = 0; k < nt; k++) {
        st = trk_jpda_existence((trk_real)exd[k], pda.params.pd * pda.params.gate_prob, pa + k * nd, nd, pm[k],
                                &ex_post[k], beta);
        if (st != TRK_OK) return vec_fail(o, "trk_jpda_existence: %s", trk_status_str(st));
        for (size_t j = 0; j < nd; j++) go[k * nd + j] = log_w[k * nd + j] > -TRK_REAL_MAX;
        for (size_t j = 0; j <= nd; j++) bo[k * (nd + 1) + j] = (double)beta[j];
        st = trk_pda_update_weights(NX, trk_cv2_h, rm, x[k], p[k], &inn[k], nd, z, beta);
        if (st != TRK_OK) return vec_fail(o, "trk_pda_update_weights: %s", trk_status_str(st));
        for (size_t a = 0; a < NX; a++) xpo[k * NX + a] = (double)x[k][a];
        for (size_t a = 0; a < NX * NX; a++) ppo[k * NX * NX + a] = (double)p[k][a];
    }
    return vec_put_real(o, "ex_post", ex_post, nt);
}
