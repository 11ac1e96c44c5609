/* kind_imm.c - vector kinds imm_update and imm_pda_update
 * (tests/vectors/imm.vec; docs/conventions.md "Multiple models (IMM)"): one IMM
 * cycle through the library (trk/imm.h): trk_imm_mix, trk_imm_predict, then
 * trk_imm_update (one measurement) or trk_imm_pda_update (a scan with
 * clutter), and trk_imm_combine.
 *
 * Float tolerances (normwise, see vec.h): as pda_update (kind_pda.c) for
 * states and covariances, 2e-4 relative; mode probabilities and log
 * likelihoods carry the float rounding of d2 (~1e-4 relative on innovations
 * of a few metres next to positions of hundreds of metres), abs 1e-3 covers
 * it. Measured worst case in the float build: see trk-vectors --report-error.
 * A case with more models than this build's TRK_MAX_MODELS is not applicable. */
#include <string.h>

#include "trk/gate.h"
#include "trk/imm.h"
#include "vec.h"

#define NX TRK_IMM_NX

struct imm_case {
    struct trk_imm_params m;
    struct trk_imm_state s;
    trk_real r[4];
    double dt;
};

static int load(const struct vec_case *c, struct vec_out *o, struct imm_case *k)
{
    double t, r;
    long n;
    const double *q, *om, *pt, *mu, *x, *p;
    if (vec_in_scalar(c, o, "T", &t) || vec_in_scalar(c, o, "r", &r) || vec_in_int(c, o, "n", &n)) return -1;
    if (n < 1) return vec_fail(o, "n < 1");
    if (n > TRK_MAX_MODELS) {
        vec_fail(o, "%ld models above this build's TRK_MAX_MODELS (%d)", n, TRK_MAX_MODELS);
        return VEC_NOT_APPLICABLE;
    }
    const size_t nm = (size_t)n;
    if (vec_in_array_n(c, o, "q", nm, &q) || vec_in_array_n(c, o, "omega", nm, &om) ||
        vec_in_array_n(c, o, "p_trans", nm * nm, &pt) || vec_in_array_n(c, o, "mu", nm, &mu) ||
        vec_in_array_n(c, o, "x", NX * nm, &x) || vec_in_array_n(c, o, "P", NX * NX * nm, &p))
        return -1;
    memset(k, 0, sizeof *k);
    k->m.n_models = (int)n;
    for (size_t j = 0; j < nm; j++) {
        k->m.q_m2_per_s3[j] = (trk_real)q[j];
        k->m.omega_rad_s[j] = (trk_real)om[j];
        k->s.mu[j] = (trk_real)mu[j];
        for (size_t a = 0; a < NX; a++) k->s.x[j][a] = (trk_real)x[j * NX + a];
        for (size_t a = 0; a < NX * NX; a++) k->s.p[j][a] = (trk_real)p[j * NX * NX + a];
    }
    for (size_t a = 0; a < nm * nm; a++) k->m.p_switch[a] = (trk_real)pt[a];
    trk_status st = trk_imm_check_params(&k->m);
    if (st != TRK_OK) return vec_fail(o, "trk_imm_check_params: %s", trk_status_str(st));
    k->r[0] = k->r[3] = (trk_real)r;
    k->dt = t;
    return 0;
}

/* the per-model arrays of the state as flat outputs */
static int put_models(struct vec_out *o, const char *xname, const char *pname, const struct imm_case *k)
{
    const size_t n = (size_t)k->m.n_models;
    double *xo = vec_put_alloc(o, xname, NX * n), *po = vec_put_alloc(o, pname, NX * NX * n);
    if (!xo || !po) return -1;
    for (size_t j = 0; j < n; j++) {
        for (size_t a = 0; a < NX; a++) xo[j * NX + a] = (double)k->s.x[j][a];
        for (size_t a = 0; a < NX * NX; a++) po[j * NX * NX + a] = (double)k->s.p[j][a];
    }
    return 0;
}

/* mix and predict, with their outputs */
static int mix_predict(struct vec_out *o, struct imm_case *k, trk_real *mu_pred)
{
    trk_status st = trk_imm_mix(&k->m, &k->s, mu_pred);
    if (st != TRK_OK) return vec_fail(o, "trk_imm_mix: %s", trk_status_str(st));
    if (vec_put_real(o, "mu_pred", mu_pred, (size_t)k->m.n_models) || put_models(o, "x_mixed", "P_mixed", k)) return -1;
    st = trk_imm_predict(&k->m, (trk_real)k->dt, &k->s);
    if (st != TRK_OK) return vec_fail(o, "trk_imm_predict: %s", trk_status_str(st));
    return put_models(o, "x_pred", "P_pred", k);
}

static int finish(struct vec_out *o, struct imm_case *k, const trk_real *log_lik)
{
    trk_real x[NX], p[NX * NX];
    trk_imm_combine(&k->m, &k->s, x, p);
    const size_t n = (size_t)k->m.n_models;
    if (vec_put_real(o, "log_lik", log_lik, n) || vec_put_real(o, "mu_post", k->s.mu, n) ||
        put_models(o, "x_post", "P_post", k) || vec_put_real(o, "x", x, NX) || vec_put_real(o, "P", p, NX * NX))
        return -1;
    return 0;
}

TRK_VEC_KIND(imm_update, 1e-3, 2e-4, VEC_FAST)
{
    static struct imm_case k;
    const double *zd;
    long m;
    int rc = load(c, o, &k);
    if (rc) return rc;
    if (vec_in_int(c, o, "m", &m)) return -1;
    if (m != 1) return vec_fail(o, "imm_update takes m = 1");
    if (vec_in_array_n(c, o, "z", 2, &zd)) return -1;
    trk_real mu_pred[TRK_MAX_MODELS], ll[TRK_MAX_MODELS];
    const trk_real z[2] = {(trk_real)zd[0], (trk_real)zd[1]};
    if (mix_predict(o, &k, mu_pred)) return -1;
    trk_status st = trk_imm_update(&k.m, k.r, z, mu_pred, &k.s, ll);
    if (st != TRK_OK) return vec_fail(o, "trk_imm_update: %s", trk_status_str(st));
    return finish(o, &k, ll);
}

TRK_VEC_KIND(imm_pda_update, 1e-3, 2e-4, VEC_FAST)
{
    static struct imm_case k;
    static struct trk_imm_work work;
    static trk_real z[2 * TRK_MAX_DETECTIONS];
    static unsigned char val[TRK_MAX_DETECTIONS];
    const double *zd = NULL;
    double pd, pg, lambda;
    long m;
    int rc = load(c, o, &k);
    if (rc) return rc;
    if (vec_in_scalar(c, o, "pd", &pd) || vec_in_scalar(c, o, "pg", &pg) || vec_in_scalar(c, o, "lambda", &lambda) ||
        vec_in_int(c, o, "m", &m))
        return -1;
    if (m < 0) return vec_fail(o, "m < 0");
    if (m > TRK_MAX_DETECTIONS) {
        vec_fail(o, "%ld detections above this build's TRK_MAX_DETECTIONS", m);
        return VEC_NOT_APPLICABLE;
    }
    if (vec_in_array_n(c, o, "z", 2 * (size_t)m, &zd)) return -1;
    for (size_t i = 0; i < 2 * (size_t)m; i++) z[i] = (trk_real)zd[i];
    struct trk_pda pda;
    const struct trk_pda_params pp = {2, (trk_real)pd, (trk_real)pg, TRK_CLUTTER_PARAMETRIC, (trk_real)lambda, 1};
    trk_status st = trk_pda_init(&pda, &pp);
    if (st != TRK_OK) return vec_fail(o, "trk_pda_init: %s", trk_status_str(st));
    trk_real mu_pred[TRK_MAX_MODELS], ll[TRK_MAX_MODELS];
    if (mix_predict(o, &k, mu_pred)) return -1;
    st = trk_imm_pda_update(&k.m, &pda, k.r, (size_t)m, z, NULL, mu_pred, &k.s, &work, val, ll);
    if (st != TRK_OK) return vec_fail(o, "trk_imm_pda_update: %s", trk_status_str(st));
    /* the mode likelihoods relative to their maximum over the models */
    trk_real mx = ll[0];
    for (int j = 1; j < k.m.n_models; j++)
        if (ll[j] > mx) mx = ll[j];
    for (int j = 0; j < k.m.n_models; j++) ll[j] -= mx;
    double *vo = vec_put_alloc(o, "validated", (size_t)m);
    if ((m > 0 && !vo) || vec_put_real(o, "gamma", &pda.gamma, 1)) return -1;
    for (size_t i = 0; i < (size_t)m; i++) vo[i] = val[i];
    return finish(o, &k, ll);
}
