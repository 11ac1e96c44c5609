/* kind_pda.c - vector kinds pda_update, pda_track, pdafai_update
 * (tests/vectors/pda.vec, pdafai.vec): the library's CV-2D predict followed
 * by trk_pda_update (pda_track) or, with the innovation that the single-step
 * kinds output, trk_pda_update_inn.
 *
 * Float tolerances (normwise, see vec.h): states of a few thousand metres carry
 * float rounding of ~4e3 * 6e-8 = 2.4e-4 m per operation; covariances are
 * formed from products of such numbers. Measured worst case (trk-vectors
 * --report-error in the float build) is below 3e-5 normwise; the tolerance
 * 2e-4 normwise relative (plus abs 1e-6 for probabilities near 0) leaves
 * a factor of ~6. The pda_track case accumulates 50 scans: same tolerance.
 *
 * Gate boundary: d2 of an innovation of a few metres next to positions of
 * thousands of metres carries a float error of ~1e-4 relative, so a detection
 * within 0.1 % of gamma may fall on either side; its beta is then 0 or not and
 * no tolerance can cover the jump. The float build reports such cases as not
 * resolvable in float (VEC_NOT_APPLICABLE) instead of comparing them. */
#include <stdio.h>
#include <string.h>

#include "trk/kalman.h"
#include "trk/pda.h"
#include "vec.h"

#define NX TRK_CV2_NX
#define NZ TRK_CV2_NZ

struct pda_setup {
    struct trk_pda pda;
    trk_real f[NX * NX], q[NX * NX], r[NZ * NZ];
    trk_real x[NX], p[NX * NX];
    double dt;
};

static void to_real(const double *d, trk_real *r, size_t n)
{
    for (size_t i = 0; i < n; i++) r[i] = (trk_real)d[i];
}

static int setup(const struct vec_case *c, struct vec_out *o, struct pda_setup *s)
{
    double t, q, r, pd, pg, lambda = 0;
    const char *clutter, *gating;
    const double *x, *p;
    if (vec_in_scalar(c, o, "T", &t) || vec_in_scalar(c, o, "q", &q) || vec_in_scalar(c, o, "r", &r) ||
        vec_in_scalar(c, o, "pd", &pd) || vec_in_scalar(c, o, "pg", &pg) ||
        vec_in_word(c, o, "clutter", &clutter) || vec_in_word(c, o, "gating", &gating) ||
        vec_in_array_n(c, o, "x", NX, &x) || vec_in_array_n(c, o, "P", NX * NX, &p))
        return -1;
    struct trk_pda_params pp = {0};
    pp.nz = NZ;
    pp.pd = (trk_real)pd;
    pp.gate_prob = (trk_real)pg;
    if (strcmp(clutter, "parametric") == 0) {
        if (vec_in_scalar(c, o, "lambda", &lambda)) return -1;
        pp.clutter = TRK_CLUTTER_PARAMETRIC;
        pp.clutter_density = (trk_real)lambda;
    } else if (strcmp(clutter, "nonparametric") == 0) {
        pp.clutter = TRK_CLUTTER_NONPARAMETRIC;
    } else {
        return vec_fail(o, "clutter must be parametric|nonparametric");
    }
    if (strcmp(gating, "on") == 0) pp.gating = 1;
    else if (strcmp(gating, "off") == 0) pp.gating = 0;
    else return vec_fail(o, "gating must be on|off");
    trk_status st = trk_pda_init(&s->pda, &pp);
    if (st != TRK_OK) return vec_fail(o, "trk_pda_init: %s", trk_status_str(st));
    trk_cv2_transition((trk_real)t, s->f);
    trk_cv2_process_noise((trk_real)t, (trk_real)q, s->q);
    s->r[TRK_CV2_S(TRK_CV2_ZX, TRK_CV2_ZX)] = s->r[TRK_CV2_S(TRK_CV2_ZY, TRK_CV2_ZY)] = (trk_real)r;
    s->r[TRK_CV2_S(TRK_CV2_ZX, TRK_CV2_ZY)] = s->r[TRK_CV2_S(TRK_CV2_ZY, TRK_CV2_ZX)] = 0;
    to_real(x, s->x, NX);
    to_real(p, s->p, NX * NX);
    s->dt = t;
    return 0;
}


/* One predict + PDA update; with full != 0 also the intermediate outputs. */
static int step(struct vec_out *o, struct pda_setup *s, size_t m, const double *zd,
                const double *lrd, int full)
{
    static trk_real z[2 * TRK_MAX_DETECTIONS], lr[TRK_MAX_DETECTIONS];
    static trk_real beta[TRK_MAX_DETECTIONS], d2[TRK_MAX_DETECTIONS];
    if (m > TRK_MAX_DETECTIONS) {
        vec_fail(o, "%zu detections above this build's TRK_MAX_DETECTIONS", m);
        return VEC_NOT_APPLICABLE;
    }
    to_real(zd, z, 2 * m);
    if (lrd) to_real(lrd, lr, m);
    trk_status st = trk_kalman_predict(NX, s->f, s->q, s->x, s->p);
    if (st != TRK_OK) return vec_fail(o, "predict: %s", trk_status_str(st));
    struct trk_pda_report rep;
    if (full) { /* the innovation is an output too: the update takes it as given */
        struct trk_innovation inn;
        st = trk_kalman_innovation(NX, NZ, trk_cv2_h, s->r, s->x, s->p, &inn);
        if (st != TRK_OK) return vec_fail(o, "innovation: %s", trk_status_str(st));
        if (vec_put_real(o, "x_pred", s->x, NX) || vec_put_real(o, "P_pred", s->p, NX * NX) ||
            vec_put_real(o, "z_pred", inn.z_pred, NZ) || vec_put_real(o, "S", inn.s, NZ * NZ) ||
            vec_put_real(o, "gamma", &s->pda.gamma, 1))
            return -1;
        st = trk_pda_update_inn(&s->pda, NX, trk_cv2_h, s->r, s->x, s->p, &inn, m, z, lrd ? lr : NULL, beta,
                                d2, &rep);
    } else {
        st = trk_pda_update(&s->pda, NX, trk_cv2_h, s->r, s->x, s->p, m, z, lrd ? lr : NULL, beta, d2, &rep);
    }
    if (st != TRK_OK) return vec_fail(o, "trk_pda_update: %s", trk_status_str(st));
    if (TRK_REAL_IS_FLOAT)
        for (size_t i = 0; i < m; i++)
            if (trk_fabs(d2[i] - s->pda.gamma) <= TRK_REAL_C(1e-3) * s->pda.gamma) {
                vec_fail(o, "detection %zu within 0.1%% of the gate boundary (d2 %g, gamma %g)", i,
                         (double)d2[i], (double)s->pda.gamma);
                return VEC_NOT_APPLICABLE;
            }
    if (full) {
        double *g = vec_put_alloc(o, "gated", m);
        if (!g || vec_put_real(o, "d2", d2, m)) return -1;
        for (size_t i = 0; i < m; i++) g[i] = d2[i] <= s->pda.gamma;
        if (vec_put_real(o, "beta0", &rep.beta0, 1) || vec_put_real(o, "beta", beta, m) ||
            vec_put_real(o, "x_post", s->x, NX) || vec_put_real(o, "P_post", s->p, NX * NX))
            return -1;
    }
    return 0;
}

static int single(const struct vec_case *c, struct vec_out *o, int with_lr)
{
    static struct pda_setup s;
    const double *z, *lr = NULL;
    long m;
    if (setup(c, o, &s) || vec_in_int(c, o, "m", &m)) return -1;
    if (m < 0) return vec_fail(o, "m < 0");
    if (vec_in_array_n(c, o, "z", 2 * (size_t)m, &z)) return -1;
    if (with_lr && vec_in_array_n(c, o, "log_lr", (size_t)m, &lr)) return -1;
    return step(o, &s, (size_t)m, z, lr, 1);
}

TRK_VEC_KIND(pda_update, 1e-6, 2e-4, VEC_FAST) { return single(c, o, 0); }

TRK_VEC_KIND(pdafai_update, 1e-6, 2e-4, VEC_FAST) { return single(c, o, 1); }

TRK_VEC_KIND(pda_track, 1e-6, 2e-4, VEC_FAST)
{
    static struct pda_setup s;
    long n;
    if (setup(c, o, &s) || vec_in_int(c, o, "n_scans", &n)) return -1;
    if (n < 0 || n > 100000) return vec_fail(o, "n_scans out of range");
    for (long k = 1; k <= n; k++) {
        char name[VEC_MAX_NAME];
        const double *z;
        size_t nz;
        snprintf(name, sizeof name, "z%ld", k);
        if (vec_in_array(c, o, name, &z, &nz)) return -1;
        if (nz % 2) return vec_fail(o, "%s has an odd number of values", name);
        int rc = step(o, &s, nz / 2, z, NULL, 0);
        if (rc) return rc;
        snprintf(name, sizeof name, "x%ld", k);
        if (vec_put_real(o, name, s.x, NX)) return -1;
        snprintf(name, sizeof name, "P%ld", k);
        if (vec_put_real(o, name, s.p, NX * NX)) return -1;
    }
    return 0;
}
