/* toc_curve.c - TOC curves and optimum (toc_curve.h): the library's MRE (trk/mre.h) on
 * the library's q2 lookups (trk/q2.h), from q2 tables or sampled grids. */
#include "toc_curve.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "errmsg.h"
#include "progress.h"
#include "q2_table.h"
#include "trk/amplitude.h"
#include "trk/mre.h"
#include "trk/toc.h"
#include "trk/q2.h"

struct toc {
    struct toc_scenario sc;
    struct trk_q2_lookup lk[TOC_N_DETECTORS];
    /* sampled grids (NULL with tables) */
    trk_real *vals[TOC_N_DETECTORS];
    trk_real *nodes;
    trk_real p0[TRK_MRE_MAX_NX * TRK_MRE_MAX_NX]; /* the MRE's start (not two-point) */
};

const char *toc_detector_name(int detector) { return detector == TOC_PDAF ? "PDAF" : "PDAFAI"; }

const char *toc_start_name(int start)
{
    return start == TOC_START_ZERO ? "zero" : start == TOC_START_STEADY ? "steady" : "two-point";
}

const char *toc_status_name(int status)
{
    return status == TOC_OK ? "ok" : status == TOC_DIVERGED ? "diverged" : "off_table";
}

void toc_scenario_brekke(struct toc_scenario *sc, int amp_model, double nu, double snr_db, double cell_m2)
{
    memset(sc, 0, sizeof *sc);
    sc->amp_model = amp_model;
    sc->nu = amp_model == TRK_AMP_K ? nu : 0;
    sc->snr_db = snr_db;
    sc->cell_m2 = cell_m2;
    sc->dt_s = 1;
    sc->q_m2_per_s3 = 0.0125 * 0.0125;
    sc->r_m2 = 1.0 / 12;
    sc->gate_gamma = 36;
    sc->pfa_min = 1e-6;
    sc->pfa_max = 0.5;
}

const struct toc_scenario *toc_scenario_of(const struct toc *t) { return &t->sc; }

int toc_set_cell_m2(struct toc *t, double cell_m2, char *err, size_t errlen)
{
    if (!(cell_m2 > 0 && isfinite(cell_m2))) return errmsg_fail(err, errlen, "cell area must be > 0 (got %g)", cell_m2);
    t->sc.cell_m2 = cell_m2;
    return 0;
}

int toc_pd(const struct toc *t, double pfa, double *pd, char *err, size_t errlen)
{
    if (!(pfa > 0 && pfa < 1)) return errmsg_fail(err, errlen, "pfa %g outside (0, 1)", pfa);
    struct amp_direct d;
    if (amp_direct_init(&d, t->sc.amp_model, t->sc.nu, 1, t->sc.snr_db, pfa) != 0 || !(d.pd > 0 && d.pd <= 1))
        return errmsg_fail(err, errlen, "no ROC value at pfa %g", pfa);
    *pd = d.pd;
    return 0;
}

/* q2(pfa, lambda_vg) of one detector for the library's TOC (trk_q2_pfa_fn);
 * the PDAF's pd = ROC(pfa) is cached for the pfa of the current MRE solve. */
struct q2_ctx {
    const struct toc *t;
    int det;
    double pfa, pd;       /* cache */
    int have;
    int clamp;            /* above the table's lambda_vg: q2 at its top */
};

/* The top of a lookup's lambda_vg axis. */
static double lv_top(const struct trk_q2_lookup *q)
{
    const struct trk_q2_axis *a = &q->grid.axis[q->n_axes - 1];
    return exp((double)(a->nodes ? a->nodes[a->count - 1] : a->u_last));
}

static trk_status q2_at(const void *ctx, trk_real pfa, trk_real lambda_vg, trk_real *q2)
{
    struct q2_ctx *c = (struct q2_ctx *)(uintptr_t)ctx; /* our own mutable cache, see above */
    if (c->clamp) {
        /* q2 falls with lambda_vg: q2 at the top is an upper bound beyond it */
        const double top = lv_top(&c->t->lk[c->det]);
        if ((double)lambda_vg > top) lambda_vg = (trk_real)top;
    }
    if (c->det == TOC_PDAFAI) return trk_q2_pdafai(&c->t->lk[TOC_PDAFAI], (trk_real)c->t->sc.snr_db, pfa, lambda_vg, q2);
    if (!c->have || c->pfa != (double)pfa) {
        double pd;
        if (toc_pd(c->t, (double)pfa, &pd, NULL, 0)) return TRK_E_RANGE;
        c->pfa = (double)pfa;
        c->pd = pd;
        c->have = 1;
    }
    return trk_q2_pdaf(&c->t->lk[TOC_PDAF], (trk_real)c->pd, lambda_vg, q2);
}

static void toc_params(const struct toc *t, struct q2_ctx *c, struct trk_toc_params *p)
{
    memset(p, 0, sizeof *p);
    p->mre.nz = 2;
    p->mre.dt_s = (trk_real)t->sc.dt_s;
    p->mre.q_m2_per_s3 = (trk_real)t->sc.q_m2_per_s3;
    p->mre.r_m2 = (trk_real)t->sc.r_m2;
    p->mre.gate_gamma = (trk_real)t->sc.gate_gamma;
    p->mre.gate_prob = (trk_real)q2_gate_prob(2, t->sc.gate_gamma);
    p->cells_per_m = (trk_real)(1 / t->sc.cell_m2);
    p->pfa_min = (trk_real)t->sc.pfa_min;
    p->pfa_max = (trk_real)t->sc.pfa_max;
    p->q2_fn = q2_at;
    p->q2_ctx = c;
    p->p0 = t->sc.mre_start == TOC_START_TWOPOINT ? NULL : t->p0;
}

/* t->p0 for the scenario's start: P = 0, or the MRE's steady state with
 * q2 = 1 (the clutter-free Kalman filter). */
static int start_cov(struct toc *t, char *err, size_t n)
{
    memset(t->p0, 0, sizeof t->p0);
    if (t->sc.mre_start != TOC_START_STEADY) return 0;
    struct q2_ctx c = {t, 0, 0, 0, 0, 0};
    struct trk_toc_params tp;
    toc_params(t, &c, &tp);
    struct trk_mre_params mp = tp.mre;
    mp.clutter_density = 0;
    mp.q2 = 1;
    struct trk_mre m;
    struct trk_mre_result r;
    trk_status st = trk_mre_init(&m, &mp);
    if (st == TRK_OK) st = trk_mre_steady_state(&m, NULL, &r);
    if (st != TRK_OK) return errmsg_fail(err, n, "the clutter-free steady state: %s", ERRMSG_STATUS(st));
    memcpy(t->p0, r.p, sizeof t->p0);
    return 0;
}

/* ---- construction ---- */

static int check_scenario(const struct toc_scenario *sc, char *err, size_t n)
{
    if (sc->amp_model != TRK_AMP_RAYLEIGH && sc->amp_model != TRK_AMP_K)
        return errmsg_fail(err, n, "amplitude model must be Rayleigh or K");
    if (sc->amp_model == TRK_AMP_K && !(sc->nu > 0 && sc->nu <= 1e6))
        return errmsg_fail(err, n, "K shape nu must be in (0, 1e6] (got %g)", sc->nu);
    if (!(sc->snr_db >= -30 && sc->snr_db <= 60))
        return errmsg_fail(err, n, "snr_db must be in [-30, 60] (got %g)", sc->snr_db);
    if (!(sc->cell_m2 > 0 && isfinite(sc->cell_m2)))
        return errmsg_fail(err, n, "cell area must be > 0 (got %g)", sc->cell_m2);
    if (!(sc->dt_s > 0 && isfinite(sc->dt_s)) || !(sc->q_m2_per_s3 > 0 && isfinite(sc->q_m2_per_s3)) ||
        !(sc->r_m2 > 0 && isfinite(sc->r_m2)))
        return errmsg_fail(err, n, "T, q and r must be finite and > 0");
    if (!(sc->gate_gamma > 0 && sc->gate_gamma <= 1000)) return errmsg_fail(err, n, "gate gamma must be in (0, 1000]");
    if (!(sc->pfa_min > 0 && sc->pfa_min < sc->pfa_max && sc->pfa_max < 1))
        return errmsg_fail(err, n, "need 0 < pfa_min < pfa_max < 1 (got %g, %g)", sc->pfa_min, sc->pfa_max);
    if (sc->mre_start != TOC_START_TWOPOINT && sc->mre_start != TOC_START_ZERO && sc->mre_start != TOC_START_STEADY)
        return errmsg_fail(err, n, "unknown MRE start %d", sc->mre_start);
    return 0;
}

static int same(double a, double b) { return fabs(a - b) <= 1e-6 * fabs(b); }

/* A q2 table for the scenario: kind, nz, gate and model must match. */
static int use_table(struct toc *t, int det, const struct trk_table *tb, char *err, size_t n)
{
    const int qd = det == TOC_PDAF ? TRK_Q2_PDAF : TRK_Q2_PDAFAI;
    trk_status st = trk_q2_lookup_init_table(&t->lk[det], tb, qd, 2);
    if (st != TRK_OK)
        return errmsg_fail(err, n, "%s q2 table refused: %s", toc_detector_name(det), ERRMSG_STATUS(st));
    const struct trk_q2_lookup *q = &t->lk[det];
    if (!same((double)q->gate_gamma, t->sc.gate_gamma))
        return errmsg_fail(err, n, "%s q2 table is for gate gamma %g, the scenario has %g", toc_detector_name(det),
                           (double)q->gate_gamma, t->sc.gate_gamma);
    if (det == TOC_PDAFAI) {
        if (q->amp_model != t->sc.amp_model || (q->amp_model == TRK_AMP_K && !same((double)q->nu, t->sc.nu)))
            return errmsg_fail(err, n, "PDAFAI q2 table is for %s clutter (nu %g), the scenario has %s (nu %g)",
                               q->amp_model == TRK_AMP_K ? "K" : "Rayleigh", (double)q->nu,
                               t->sc.amp_model == TRK_AMP_K ? "K" : "Rayleigh", t->sc.nu);
        const struct trk_q2_axis *a = &q->grid.axis[0];
        const double lo = a->nodes ? (double)a->nodes[0] : (double)a->u_first;
        const double hi = a->nodes ? (double)a->nodes[a->count - 1] : (double)a->u_last;
        if (!(t->sc.snr_db >= lo - 1e-9 && t->sc.snr_db <= hi + 1e-9))
            return errmsg_fail(err, n, "PDAFAI q2 table covers snr_db %g .. %g, not %g", lo, hi, t->sc.snr_db);
    }
    return 0;
}

struct sampler_prog {
    struct progress p;
    uint64_t last;
    int started;
    const char *label;
};

static void on_progress(void *ctx, const struct q2_is_progress *pr)
{
    struct sampler_prog *c = ctx;
    if (!c->started) {
        progress_start(&c->p, c->label, (long)pr->points_planned, 1);
        c->started = 1;
    }
    c->p.total = (long)pr->points_planned;
    progress_add(&c->p, (long)(pr->points_done - c->last));
    c->last = pr->points_done;
}

/* Sample the q2 grid of one detector for the scenario (defaults of the
 * tables; PDAF pd from the node below the ROC's lowest pd up to 1; PDAFAI at
 * the one snr_db, pfa over [pfa_min, pfa_max] at the default density). */
static int sample_grid(struct toc *t, int det, const struct toc_q2_source *src, char *err, size_t n)
{
    static double pd_all[Q2_TABLE_MAX_NODES];
    struct q2_table_spec s;
    memset(&s, 0, sizeof s);
    s.detector = det == TOC_PDAF ? TRK_Q2_PDAF : TRK_Q2_PDAFAI;
    s.nz = 2;
    s.gate_gamma = t->sc.gate_gamma;
    s.cubic = 1;
    if (q2_table_parse_log(det == TOC_PDAF ? Q2_TABLE_DEFAULT_LAMBDA_VG_PDAF : Q2_TABLE_DEFAULT_LAMBDA_VG_PDAFAI,
                           &s.lambda_vg))
        return errmsg_fail(err, n, "bad default lambda_vg grid");
    if (src->lambda_vg_max > 0) {
        /* same density in ln lambda_vg, new top */
        const double per = (double)(s.lambda_vg.n - 1) / log(s.lambda_vg.hi / s.lambda_vg.lo);
        if (!(src->lambda_vg_max > s.lambda_vg.lo && src->lambda_vg_max <= Q2_IS_MAX_LAMBDA_VG))
            return errmsg_fail(err, n, "lambda_vg_max must be in (%g, %g]", s.lambda_vg.lo, Q2_IS_MAX_LAMBDA_VG);
        s.lambda_vg.hi = src->lambda_vg_max;
        s.lambda_vg.n = (size_t)ceil(per * log(s.lambda_vg.hi / s.lambda_vg.lo)) + 1;
    }
    double pd_lo = 1;
    if (det == TOC_PDAF) {
        const int np = q2_table_parse_list(Q2_TABLE_DEFAULT_PD, pd_all, (int)Q2_TABLE_MAX_NODES);
        if (np < 2) return errmsg_fail(err, n, "bad default pd grid");
        for (int k = 0; k < 2; k++) {
            double pd = 1;
            if (toc_pd(t, k ? t->sc.pfa_max : t->sc.pfa_min, &pd, err, n)) return -1;
            if (pd < pd_lo) pd_lo = pd;
        }
        int first = 0;
        while (first + 2 < np && pd_all[first + 1] <= pd_lo) first++;
        q2_table_list_axis(pd_all + first, np - first, &s.pd);
    } else {
        s.amp_model = t->sc.amp_model;
        s.nu = t->sc.nu;
        s.snr_db.n = 1;
        s.snr_db.lo = s.snr_db.hi = t->sc.snr_db;
        struct q2_table_axis dflt;
        if (q2_table_parse_log(Q2_TABLE_DEFAULT_PFA, &dflt)) return errmsg_fail(err, n, "bad default pfa grid");
        const double step = log(dflt.hi / dflt.lo) / (double)(dflt.n - 1);
        s.pfa.lo = t->sc.pfa_min;
        s.pfa.hi = t->sc.pfa_max;
        s.pfa.n = (size_t)ceil(log(s.pfa.hi / s.pfa.lo) / step) + 1;
        if (s.pfa.n < 4) s.pfa.n = 4;
    }
    struct q2_table_run r;
    memset(&r, 0, sizeof r);
    r.samples = src->samples ? src->samples : Q2_TABLE_DEFAULT_SAMPLES;
    r.target_se = src->target_se > 0 ? src->target_se : Q2_TABLE_DEFAULT_TARGET_SE;
    r.seed = src->seed ? src->seed : 1;
    r.threads = src->threads;
    r.par = src->par;
    struct sampler_prog pg;
    memset(&pg, 0, sizeof pg);
    pg.label = det == TOC_PDAF ? "q2 grid PDAF, points" : "q2 grid PDAFAI, points";
    if (!src->quiet) {
        r.progress = on_progress;
        r.progress_ctx = &pg;
    }
    struct q2_table_result res;
    char e2[512];
    const int rc = q2_table_build(&s, &r, &res, e2, sizeof e2);
    if (pg.started) progress_end(&pg.p);
    if (rc) return errmsg_fail(err, n, "%s q2 grid: %s", toc_detector_name(det), e2);
    /* a lookup over a trk_real copy of the values (the PDAFAI grid has one
     * snr node: no table file, the lookup takes plain arrays) */
    const size_t nc = res.n_cells;
    t->vals[det] = malloc(nc * sizeof *t->vals[det]);
    if (det == TOC_PDAF && s.pd.nodes) t->nodes = malloc(s.pd.n * sizeof *t->nodes);
    if (!t->vals[det] || (det == TOC_PDAF && s.pd.nodes && !t->nodes)) {
        q2_table_result_free(&res);
        return errmsg_fail(err, n, "out of memory");
    }
    for (size_t c = 0; c < nc; c++) t->vals[det][c] = (trk_real)res.values[2 * c];
    struct trk_q2_grid g;
    memset(&g, 0, sizeof g);
    g.detector = s.detector;
    g.values = t->vals[det];
    const struct trk_q2_axis lva = {s.lambda_vg.n, NULL, (trk_real)log(s.lambda_vg.lo), (trk_real)log(s.lambda_vg.hi),
                                    1, TRK_Q2_CUBIC};
    if (det == TOC_PDAF) {
        g.axis[0] = (struct trk_q2_axis){s.pd.n, NULL, (trk_real)s.pd.lo, (trk_real)s.pd.hi, 0, TRK_Q2_CUBIC};
        if (s.pd.nodes) {
            for (size_t i = 0; i < s.pd.n; i++) t->nodes[i] = (trk_real)s.pd.nodes[i];
            g.axis[0].nodes = t->nodes;
        }
        g.axis[1] = lva;
    } else {
        g.axis[0] = (struct trk_q2_axis){1, NULL, (trk_real)t->sc.snr_db, (trk_real)t->sc.snr_db, 0, TRK_Q2_LINEAR};
        g.axis[1] = (struct trk_q2_axis){s.pfa.n, NULL, (trk_real)log(s.pfa.lo), (trk_real)log(s.pfa.hi), 1,
                                         TRK_Q2_CUBIC};
        g.axis[2] = lva;
    }
    q2_table_result_free(&res);
    trk_status st = trk_q2_lookup_init(&t->lk[det], &g);
    if (st != TRK_OK)
        return errmsg_fail(err, n, "%s q2 grid refused by the lookup: %s", toc_detector_name(det), ERRMSG_STATUS(st));
    return 0;
}

struct toc *toc_new(const struct toc_scenario *sc, const struct toc_q2_source *src, char *err, size_t errlen)
{
    static const struct toc_q2_source none;
    if (!sc) {
        errmsg_fail(err, errlen, "no scenario");
        return NULL;
    }
    if (!src) src = &none;
    if (check_scenario(sc, err, errlen)) return NULL;
    struct toc *t = calloc(1, sizeof *t);
    if (!t) {
        errmsg_fail(err, errlen, "out of memory");
        return NULL;
    }
    t->sc = *sc;
    if (t->sc.amp_model == TRK_AMP_RAYLEIGH) t->sc.nu = 0;
    if (start_cov(t, err, errlen)) {
        toc_free(t);
        return NULL;
    }
    const struct trk_table *tb[2] = {src->pdaf, src->pdafai};
    for (int d = 0; d < TOC_N_DETECTORS; d++) {
        const int rc = tb[d] ? use_table(t, d, tb[d], err, errlen) : sample_grid(t, d, src, err, errlen);
        if (rc) {
            toc_free(t);
            return NULL;
        }
    }
    return t;
}

void toc_free(struct toc *t)
{
    if (!t) return;
    for (int d = 0; d < TOC_N_DETECTORS; d++) free(t->vals[d]);
    free(t->nodes);
    free(t);
}

int toc_q2(const struct toc *t, int detector, double pfa, double lambda_vg, double *q2, char *err, size_t errlen)
{
    if (detector != TOC_PDAF && detector != TOC_PDAFAI) return errmsg_fail(err, errlen, "bad detector");
    struct q2_ctx c = {t, detector, 0, 0, 0, 0};
    trk_real v;
    trk_status st = q2_at(&c, (trk_real)pfa, (trk_real)lambda_vg, &v);
    if (st != TRK_OK)
        return errmsg_fail(err, errlen, "%s q2 at pfa %g, lambda_vg %g: %s", toc_detector_name(detector), pfa,
                           lambda_vg, ERRMSG_STATUS(st));
    *q2 = (double)v;
    return 0;
}

int toc_point_at(const struct toc *t, double pfa, struct toc_point *p, char *err, size_t errlen)
{
    memset(p, 0, sizeof *p);
    p->pfa = pfa;
    p->lambda_per_m2 = pfa / t->sc.cell_m2;
    if (toc_pd(t, pfa, &p->pd, err, errlen)) return -1;
    for (int d = 0; d < TOC_N_DETECTORS; d++) {
        struct q2_ctx c = {t, d, 0, 0, 0, 0};
        struct trk_toc_params tp;
        toc_params(t, &c, &tp);
        struct trk_mre_result r;
        trk_real e;
        trk_status st = trk_toc_rmse(&tp, (trk_real)pfa, &e, &r);
        if (st == TRK_E_RANGE) {
            /* off the table: again with q2 above the table's lambda_vg held at
             * its top value, an upper bound of q2 (q2 falls with lambda_vg):
             * if the MRE still diverges, the track is lost; otherwise the
             * point is not computable from the table (the RMSE found is a
             * lower bound) */
            c.clamp = 1;
            st = trk_toc_rmse(&tp, (trk_real)pfa, &e, &r);
            if (st == TRK_OK) {
                p->rmse_bound_m[d] = (double)e;
                st = TRK_E_RANGE;
            }
        }
        if (st == TRK_OK) {
            p->status[d] = TOC_OK;
            p->rmse_m[d] = (double)e;
            p->q2[d] = (double)r.q2;
            p->lambda_vg[d] = (double)r.lambda_vg;
            p->iterations[d] = r.iterations;
        } else if (st == TRK_E_DIVERGED || st == TRK_E_RANGE) {
            p->status[d] = st == TRK_E_DIVERGED ? TOC_DIVERGED : TOC_OFF_TABLE;
            p->rmse_m[d] = INFINITY;
            p->q2[d] = p->lambda_vg[d] = NAN;
            p->iterations[d] = r.iterations;
            if (st == TRK_E_DIVERGED) p->rmse_bound_m[d] = INFINITY;
        } else {
            return errmsg_fail(err, errlen, "%s MRE at pfa %g: %s", toc_detector_name(d), pfa, ERRMSG_STATUS(st));
        }
    }
    return 0;
}

int toc_curve(const struct toc *t, size_t n, struct toc_point *pts, char *err, size_t errlen)
{
    if (n < 2) return errmsg_fail(err, errlen, "a curve needs >= 2 points");
    const double l0 = log(t->sc.pfa_min), l1 = log(t->sc.pfa_max);
    for (size_t i = 0; i < n; i++) {
        double pfa = i == n - 1 ? t->sc.pfa_max : exp(l0 + (l1 - l0) * (double)i / (double)(n - 1));
        if (i == 0) pfa = t->sc.pfa_min;
        if (toc_point_at(t, pfa, &pts[i], err, errlen)) return -1;
    }
    return 0;
}

/* Off the table, and possibly better than rmse: its lower bound (q2 held at
 * the table's top) below twice rmse. A bound far above (the PDAF swamped by
 * clutter: several metres) is a lost track whatever the table. */
static int off_table_near(const struct toc_point *p, int d, double rmse)
{
    return p->status[d] == TOC_OFF_TABLE && p->rmse_bound_m[d] < 2 * rmse;
}

int toc_optimum(const struct toc *t, int detector, struct toc_optimum *o, char *err, size_t errlen)
{
    if (detector != TOC_PDAF && detector != TOC_PDAFAI) return errmsg_fail(err, errlen, "bad detector");
    memset(o, 0, sizeof *o);
    struct q2_ctx c = {t, detector, 0, 0, 0, 0};
    struct trk_toc_params tp;
    toc_params(t, &c, &tp);
    struct trk_toc_result r;
    trk_status st = trk_toc_optimise(&tp, &r);
    if (st == TRK_E_DIVERGED)
        return errmsg_fail(err, errlen, "%s: no pfa in [%g, %g] has a steady state", toc_detector_name(detector),
                           t->sc.pfa_min, t->sc.pfa_max);
    if (st != TRK_OK)
        return errmsg_fail(err, errlen, "%s TOC optimum: %s", toc_detector_name(detector), ERRMSG_STATUS(st));
    o->pfa = (double)r.pfa;
    o->rmse_m = (double)r.rmse_m;
    o->q2 = (double)r.q2;
    o->lambda_vg = (double)r.lambda_vg;
    o->n_evals = r.n_evals;
    o->n_diverged = r.n_diverged;
    if (toc_pd(t, o->pfa, &o->pd, err, errlen)) return -1;
    /* where the optimum may lie outside what was searched */
    const double lr = log(t->sc.pfa_max / t->sc.pfa_min);
    o->at_range_end = log(o->pfa / t->sc.pfa_min) < 2e-3 * lr || log(t->sc.pfa_max / o->pfa) < 2e-3 * lr;
    for (int side = -1; side <= 1; side += 2) {
        const double x = o->pfa * exp(0.05 * side);
        struct toc_point p;
        if (x > t->sc.pfa_min && x < t->sc.pfa_max && toc_point_at(t, x, &p, NULL, 0) == 0 &&
            off_table_near(&p, detector, o->rmse_m))
            o->table_limited = 1;
    }
    /* the plateau: the pfa interval around the optimum with RMSE within 1 %
     * (steps of 1/160 of the ln pfa range, walking out from the optimum;
     * q2's Monte Carlo noise can move a flat optimum around inside it) */
    const int np = 161;
    for (int side = -1; side <= 1; side += 2) {
        double x = o->pfa;
        for (;;) {
            const double nx = x * exp(side * lr / (double)(np - 1));
            if (nx < t->sc.pfa_min * (1 - 1e-12) || nx > t->sc.pfa_max * (1 + 1e-12)) break;
            struct toc_point p;
            if (toc_point_at(t, nx, &p, NULL, 0) != 0) break;
            if (off_table_near(&p, detector, o->rmse_m)) o->table_limited = 1;
            if (p.status[detector] != TOC_OK || !(p.rmse_m[detector] <= 1.01 * o->rmse_m)) break;
            x = nx;
        }
        if (side < 0) o->pfa_1pct_lo = x;
        else o->pfa_1pct_hi = x;
    }
    return 0;
}
