/* q2_is.c - importance-sampling estimator of q2 (see q2_is.h for the method,
 * the random-number layout and the determinism argument).
 *
 * Built once, with -fopenmp, into libtrk_tools.a (mk/q2.mk). OpenMP pragmas
 * go through Q2_OMP() so that a build without OpenMP (the firmware image's
 * compiler, a user's) sees none (no -Wunknown-pragmas) and runs serially. */
#define _POSIX_C_SOURCE 199309L
#include "q2_is.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <Random123/philox.h>

#include "errmsg.h"
#include "par.h"
#include "q2_fastmath.h"
#include "trk/gate.h"
#include "trk/special.h"

#ifdef _OPENMP
#include <omp.h>
#define Q2_OMP(x) _Pragma(#x)
#else
#define Q2_OMP(x)
#endif

#define TWO_PI 6.283185307179586476925
#define GROUP_RETRY 0x80000000u  /* counter word 0 of rejected-target retries */
#define GROUP_TARGET_X 0x40000000u /* extra target words (nz = 3 amplitude) */
#define MAX_RETRY (1u << 20)

int q2_is_parallel(void)
{
#ifdef _OPENMP
    return 1;
#else
    return 0;
#endif
}

int q2_is_threads(int threads)
{
#ifdef _OPENMP
    return threads > 0 ? threads : omp_get_max_threads();
#else
    (void)threads;
    return 1;
#endif
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- constants of a cell ---- */

static double gate_sf(int nz, double gamma) { return (double)trk_chi2_sf(nz, (trk_real)gamma); }

double q2_is_b(int nz, double gamma, double pd, double lambda_vg)
{
    /* b = (2 pi)^(nz/2) lambda_vg (1 - pd pg) / (pd c_nz gamma^(nz/2));
     * 1 - pd pg = (1 - pd) + pd (1 - pg): no cancellation when pd pg -> 1 */
    const double one_m = (1 - pd) + pd * gate_sf(nz, gamma);
    /* c_nz gamma^(nz/2): the gate volume at det S = 1 (the library's formula) */
    const double vg1 = (double)trk_gate_volume(nz, (trk_real)gamma, 0);
    return pow(TWO_PI, 0.5 * nz) * lambda_vg * one_m / (pd * vg1);
}

/* ---- the line's strata and cells ---- */

struct stratum {
    int n;             /* clutter count */
    uint64_t n_final;  /* scenes at full N */
    double rho;        /* allocation ratio (scenes / N): proportional, then Neyman */
    double rho_prop;   /* proportional: max_k w_n(lambda_k) / w_mode(lambda_k) */
    size_t rel0, nrel; /* its (cell, b, w) entries */
    uint64_t count;    /* scenes merged so far */
    uint64_t round_to; /* scenes after the current round */
    int frozen;        /* target_se: every cell of this stratum has reached it */
};

struct line_state {
    struct q2_is_line *L;
    double F;          /* F_{nz+2}(gamma) */
    double half_gamma; /* gamma / 2 */
    double ymin;       /* exp(-gamma/2): target in the gate iff y >= ymin */
    uint32_t stream;
    int n_strata;
    struct stratum *st;
    size_t n_rel;
    size_t *rel_cell;  /* cell index */
    double *rel_b;     /* b of the cell */
    double *rel_w;     /* Poisson(n; lambda of the cell) */
    double *rel_prop;  /* proportional ratio w_n(lambda_k) / w_mode(lambda_k) */
    double *rel_rho;   /* allocation ratio of the entry (target_se: per cell) */
    double *cell_n;    /* target_se: the N each cell's strata are drawn at */
    double *mean, *m2; /* per (stratum, cell) accumulators */
    double *pdF;       /* per cell: pd F */
    double *se;        /* per cell: current standard error */
    uint64_t n_round;  /* N of the current round */
    int neyman;        /* allocation updated from the pilot round */
    int done;
};

static void line_free(struct line_state *ls)
{
    free(ls->st);
    free(ls->rel_cell);
    free(ls->rel_b);
    free(ls->rel_w);
    free(ls->rel_prop);
    free(ls->rel_rho);
    free(ls->cell_n);
    free(ls->mean);
    free(ls->m2);
    free(ls->pdF);
    free(ls->se);
    memset(ls, 0, sizeof *ls);
}

static double log_poisson(int n, double lambda)
{
    return (double)n * log(lambda) - lambda - lgamma((double)n + 1);
}

/* Window [lo, hi] of Poisson(lambda) leaving out at most tail/2 on each side. */
static void poisson_window(double lambda, double tail, int *lo, int *hi)
{
    const int jmax = (int)ceil(lambda + 40 * sqrt(lambda) + 60);
    double below = 0;
    int l = 0;
    for (int j = 0; j <= jmax; j++) {
        double w = exp(log_poisson(j, lambda));
        if (below + w > 0.5 * tail) break;
        below += w;
        l = j + 1;
    }
    double above = 0;
    int h = jmax;
    for (int j = jmax; j > l; j--) {
        double w = exp(log_poisson(j, lambda));
        if (above + w > 0.5 * tail) break;
        above += w;
        h = j - 1;
    }
    *lo = l;
    *hi = h;
}

static uint64_t min_scenes(uint64_t samples) { return samples < 256 ? samples : 256; }

static uint64_t alloc_count(double rho, uint64_t nr, uint64_t samples)
{
    double want = ceil(rho * (double)nr);
    uint64_t c = want >= (double)nr ? nr : (uint64_t)want;
    const uint64_t nmin = min_scenes(samples);
    return c > nmin ? c : nmin;
}

static int line_setup(struct line_state *ls, struct q2_is_line *L, const struct q2_is_options *o,
                      double tail, char *err, size_t errlen)
{
    memset(ls, 0, sizeof *ls);
    ls->L = L;
    if (L->nz < 1 || L->nz > 3) return errmsg_fail(err, errlen, "nz must be 1, 2 or 3 (got %d)", L->nz);
    if (!(L->gamma > 0 && L->gamma <= 1000))
        return errmsg_fail(err, errlen, "gamma must be in (0, 1000] (got %g)", L->gamma);
    if (L->n_cells < 1 || !L->lambda_vg || !L->q2)
        return errmsg_fail(err, errlen, "a line needs cells, lambda_vg and q2 arrays");
    if (!L->pd && !L->amp) return errmsg_fail(err, errlen, "a PDAF line needs pd per cell");
    if (L->amp && (!L->amp->log_lr || !(L->amp->pd > 0 && L->amp->pd <= 1)))
        return errmsg_fail(err, errlen, "amplitude sampler without log_lr or with pd outside (0, 1]");
    for (size_t k = 0; k < L->n_cells; k++) {
        double pd = L->pd ? L->pd[k] : L->amp->pd, lv = L->lambda_vg[k];
        if (!(pd > 0 && pd <= 1)) return errmsg_fail(err, errlen, "pd must be in (0, 1] (got %g)", pd);
        if (!(lv > 0 && lv <= Q2_IS_MAX_LAMBDA_VG))
            return errmsg_fail(err, errlen, "lambda_vg must be in (0, %g] (got %g)", Q2_IS_MAX_LAMBDA_VG,
                               lv);
    }
    ls->F = (double)trk_chi2_cdf(L->nz + 2, (trk_real)L->gamma);
    if (!(ls->F >= 1e-3))
        return errmsg_fail(err, errlen, "gate too small: F_%d(gamma = %g) = %g < 1e-3", L->nz + 2,
                           L->gamma, ls->F);
    ls->half_gamma = 0.5 * L->gamma;
    ls->ymin = exp(-0.5 * L->gamma);
    ls->stream = L->stream;

    /* windows, strata, allocation */
    const size_t nc = L->n_cells;
    int *lo = malloc(nc * sizeof *lo), *hi = malloc(nc * sizeof *hi);
    double *lwmode = malloc(nc * sizeof *lwmode);
    ls->pdF = malloc(nc * sizeof *ls->pdF);
    ls->se = calloc(nc, sizeof *ls->se);
    ls->cell_n = calloc(nc, sizeof *ls->cell_n);
    if (!lo || !hi || !lwmode || !ls->pdF || !ls->se || !ls->cell_n) {
        free(lo), free(hi), free(lwmode);
        return errmsg_fail(err, errlen, "out of memory");
    }
    int nmax = 0;
    for (size_t k = 0; k < nc; k++) {
        double lv = L->lambda_vg[k];
        poisson_window(lv, tail, &lo[k], &hi[k]);
        if (hi[k] > nmax) nmax = hi[k];
        int mode = (int)floor(lv);
        lwmode[k] = log_poisson(mode, lv);
        ls->pdF[k] = (L->pd ? L->pd[k] : L->amp->pd) * ls->F;
    }
    int ns = 0;
    size_t nrel = 0;
    for (int n = 0; n <= nmax; n++) {
        int any = 0;
        for (size_t k = 0; k < nc; k++)
            if (n >= lo[k] && n <= hi[k]) any = 1, nrel++;
        ns += any;
    }
    ls->st = calloc((size_t)ns, sizeof *ls->st);
    ls->rel_cell = malloc(nrel * sizeof *ls->rel_cell);
    ls->rel_b = malloc(nrel * sizeof *ls->rel_b);
    ls->rel_w = malloc(nrel * sizeof *ls->rel_w);
    ls->rel_prop = malloc(nrel * sizeof *ls->rel_prop);
    ls->rel_rho = malloc(nrel * sizeof *ls->rel_rho);
    ls->mean = calloc(nrel, sizeof *ls->mean);
    ls->m2 = calloc(nrel, sizeof *ls->m2);
    if (!ls->st || !ls->rel_cell || !ls->rel_b || !ls->rel_w || !ls->rel_prop || !ls->rel_rho || !ls->mean ||
        !ls->m2) {
        free(lo), free(hi), free(lwmode);
        line_free(ls);
        return errmsg_fail(err, errlen, "out of memory");
    }
    size_t r = 0;
    int s = 0;
    for (int n = 0; n <= nmax; n++) {
        size_t r0 = r;
        double rho = 0;
        for (size_t k = 0; k < nc; k++) {
            if (n < lo[k] || n > hi[k]) continue;
            double lw = log_poisson(n, L->lambda_vg[k]);
            double pd = L->pd ? L->pd[k] : L->amp->pd;
            ls->rel_cell[r] = k;
            ls->rel_b[r] = q2_is_b(L->nz, L->gamma, pd, L->lambda_vg[k]);
            ls->rel_w[r] = exp(lw);
            double ratio = exp(lw - lwmode[k]);
            ls->rel_prop[r] = ls->rel_rho[r] = ratio;
            if (ratio > rho) rho = ratio;
            r++;
        }
        if (r == r0) continue;
        struct stratum *t = &ls->st[s++];
        t->n = n;
        t->rho = t->rho_prop = rho;
        t->rel0 = r0;
        t->nrel = r - r0;
        t->n_final = alloc_count(rho, o->samples, o->samples);
    }
    ls->n_strata = ns;
    ls->n_rel = nrel;
    free(lo), free(hi), free(lwmode);
    return 0;
}

/* target_se after the pilot: scenes of stratum t after this round, the
 * largest demand of the cells it serves that have not reached the target
 * (cell k asks for rel_rho N_k, N_k = cell_n[k]); none: no more scenes. */
static uint64_t stratum_demand(const struct line_state *ls, const struct stratum *t, double target,
                               uint64_t samples)
{
    uint64_t c = t->count;
    for (size_t e = t->rel0; e < t->rel0 + t->nrel; e++) {
        const size_t k = ls->rel_cell[e];
        if (ls->se[k] <= target) continue;
        const uint64_t d = alloc_count(ls->rel_rho[e], (uint64_t)ls->cell_n[k], samples);
        if (d > c) c = d;
    }
    return c;
}

/* Scenes of stratum t after the round with N = nr (never fewer than drawn). */
static uint64_t stratum_count(const struct stratum *t, uint64_t nr, uint64_t samples)
{
    uint64_t c = nr >= samples ? t->n_final : alloc_count(t->rho, nr, samples);
    if (c > t->n_final) c = t->n_final;
    return c > t->count ? c : t->count;
}

/* Neyman allocation from the pilot round: the variance of a cell's estimate
 * is sum_n w_n^2 s_n^2 / N_n, smallest for N_n proportional to w_n s_n. Each
 * stratum gets rho_n = max over its cells of w_n s_n / max_m (w_m s_m) (N
 * scenes where a cell's variance comes from), at least a tenth of the
 * proportional share (a guard against a pilot that missed rare events). */
static void neyman_update(struct line_state *ls, uint64_t samples)
{
    const size_t nc = ls->L->n_cells;
    double *best = calloc(nc, sizeof *best);
    if (!best) return; /* keep the proportional allocation */
    for (int s = 0; s < ls->n_strata; s++) {
        const struct stratum *t = &ls->st[s];
        if (t->count < 2) continue;
        for (size_t e = t->rel0; e < t->rel0 + t->nrel; e++) {
            double ws = ls->rel_w[e] * sqrt(ls->m2[e] / (double)(t->count - 1));
            if (ws > best[ls->rel_cell[e]]) best[ls->rel_cell[e]] = ws;
        }
    }
    for (int s = 0; s < ls->n_strata; s++) {
        struct stratum *t = &ls->st[s];
        double rho = 0.1 * t->rho_prop;
        for (size_t e = t->rel0; e < t->rel0 + t->nrel; e++) {
            const size_t k = ls->rel_cell[e];
            double r;
            if (best[k] > 0 && t->count >= 2)
                r = ls->rel_w[e] * sqrt(ls->m2[e] / (double)(t->count - 1)) / best[k];
            else
                r = ls->rel_prop[e]; /* no variance seen for this cell: proportional */
            /* per cell: at least a tenth of its proportional share, at most 1 */
            const double re = r > 0.1 * ls->rel_prop[e] ? r : 0.1 * ls->rel_prop[e];
            ls->rel_rho[e] = re > 1 ? 1 : re;
            if (r > rho) rho = r;
        }
        t->rho = rho > 1 ? 1 : rho;
        t->n_final = alloc_count(t->rho, samples, samples);
        if (t->n_final < t->count) t->n_final = t->count;
    }
    free(best);
}

/* ---- sampling kernel ---- */

/* (w + 1/2) 2^-32 in (0, 1), exactly; through a signed conversion, which
 * every SIMD level has (the unsigned one needs AVX-512). */
static inline double u01(uint32_t w)
{
    return ((double)(int32_t)(w ^ 0x80000000u) + 2147483648.5) * (1.0 / 4294967296.0);
}

/* Per-thread work arrays of one block: scene arrays (cap_b) and point arrays
 * laid out [point j][scene i] (cap_p = cap_b * rows). */
struct scratch {
    size_t cap_b, cap_p;
    double *y, *ua, *la1, *c, *inv, *r, *beta;
    double *urad, *uamp, *e, *lac;
    uint32_t *idx;
};

static void scratch_free(struct scratch *w)
{
    free(w->y), free(w->ua), free(w->la1), free(w->c), free(w->inv), free(w->r), free(w->beta);
    free(w->urad), free(w->uamp), free(w->e), free(w->lac), free(w->idx);
    memset(w, 0, sizeof *w);
}

static int scratch_alloc(struct scratch *w, size_t cap_b, size_t cap_p)
{
    memset(w, 0, sizeof *w);
    w->cap_b = cap_b;
    w->cap_p = cap_p;
    double **b[] = {&w->y, &w->ua, &w->la1, &w->c, &w->inv, &w->r, &w->beta};
    double **p[] = {&w->urad, &w->uamp, &w->e, &w->lac};
    for (size_t i = 0; i < sizeof b / sizeof b[0]; i++)
        if (!(*b[i] = malloc(cap_b * sizeof(double)))) return -1;
    for (size_t i = 0; i < sizeof p / sizeof p[0]; i++)
        if (!(*p[i] = malloc((cap_p ? cap_p : 1) * sizeof(double)))) return -1;
    if (!(w->idx = malloc(cap_b * sizeof *w->idx))) return -1;
    return 0;
}

#define BLOCK_MAX 512u

/* Scenes per block of stratum n: a block's clutter arrays stay ~64 KB. */
static size_t block_size(int n)
{
    size_t b = n > 0 ? 8192 / (size_t)n : BLOCK_MAX;
    if (b < 16) b = 16;
    if (b > BLOCK_MAX) b = BLOCK_MAX;
    return b;
}

/* Rows of the point arrays for n clutter points: whole philox groups. */
static size_t point_rows(int n, int with_amp)
{
    size_t words = (size_t)n * (with_amp ? 2 : 1), groups = (words + 3) / 4;
    return with_amp ? 2 * groups : 4 * groups;
}

/* Largest point array of any stratum n <= max_n. */
static size_t point_cap(int max_n)
{
    size_t cap = 1;
    for (int n = 1; n <= max_n; n++) {
        size_t c = point_rows(n, 0) * block_size(n), c2 = point_rows(n, 1) * block_size(n);
        if (c > cap) cap = c;
        if (c2 > cap) cap = c2;
    }
    return cap;
}

static inline philox4x32_ctr_t draw(uint32_t group, uint32_t sample, uint32_t n, uint32_t stream,
                                    philox4x32_key_t key)
{
    philox4x32_ctr_t c = {{group, sample, n, stream}};
    return philox4x32(c, key);
}

/* The same inside the cloned kernels: Random123's force-inlined philox4x32
 * directly (clang does not inline a plain inline function into a clone built
 * for another target). */
#define DRAW_INTO(r, group, sample, n, stream, key)                    \
    do {                                                               \
        philox4x32_ctr_t c_ = {{(group), (sample), (n), (stream)}};    \
        (r) = philox4x32(c_, (key));                                   \
    } while (0)

/* y = exp(-rho^2/2) of one target draw, rho^2 ~ chi2(nz+2) (untruncated). */
static inline double target_y(int nz, const uint32_t *v)
{
    if (nz == 2) return u01(v[0]) * u01(v[1]); /* chi2(4)/2 = E1 + E2 */
    /* Box-Muller: z^2/2 = -ln(v1) cos^2(2 pi v2), so exp(-z^2/2) = v1^(cos^2) */
    if (nz == 1) { /* chi2(3) = chi2(2) + z^2 */
        double c = cos(TWO_PI * u01(v[2]));
        return u01(v[0]) * pow(u01(v[1]), c * c);
    }
    /* nz == 3: chi2(5) = chi2(4) + z^2 */
    double c = cos(TWO_PI * u01(v[3]));
    return u01(v[0]) * u01(v[1]) * pow(u01(v[2]), c * c);
}

/* Retries a = first, first+1, ... of a rejected target radius (attempt a on
 * counter word GROUP_RETRY | a) until y >= ymin. Returns 0, or -1 after
 * MAX_RETRY attempts. */
static int target_retry(const struct line_state *ls, philox4x32_key_t key, uint32_t sidx,
                        uint32_t n, uint32_t first, double *y)
{
    const int nz = ls->L->nz;
    double yy = -1;
    for (uint32_t a = first; yy < ls->ymin; a++) {
        if (a >= MAX_RETRY) return -1;
        philox4x32_ctr_t r = draw(GROUP_RETRY | a, sidx, n, ls->stream, key);
        yy = target_y(nz, r.v);
    }
    *y = yy;
    return 0;
}

/* One target: y in the gate (rejection of y < ymin, retries on their own
 * counters) and its amplitude uniform. Returns 0, or -1 after MAX_RETRY. */
static int target_draw(const struct line_state *ls, philox4x32_key_t key, uint32_t sidx, uint32_t n,
                       double *y, double *ua)
{
    const int nz = ls->L->nz;
    philox4x32_ctr_t r = draw(0, sidx, n, ls->stream, key);
    double yy = target_y(nz, r.v);
    if (nz == 3) *ua = u01(draw(GROUP_TARGET_X, sidx, n, ls->stream, key).v[0]);
    else *ua = u01(r.v[nz == 2 ? 2 : 3]);
    if (yy < ls->ymin) return target_retry(ls, key, sidx, n, 1, y);
    *y = yy;
    return 0;
}

/* rho^2/2 of a clutter point from its radial uniform: gamma/2 U^(2/nz). */
static inline double clutter_half_rho2(int nz, double half_gamma, double u)
{
    if (nz == 2) return half_gamma * u;
    if (nz == 1) return half_gamma * u * u;
    double c = cbrt(u);
    return half_gamma * c * c;
}

/* ln(sum_j exp(lac[j] - rho_j^2/2)) of one scene's clutter (stride between
 * points), for the rare scene whose plain sum overflows. */
static double clutter_log_sum(int nz, double half_gamma, int n, const double *lac,
                              const double *urad, size_t stride)
{
    double mx = -INFINITY;
    for (int j = 0; j < n; j++) {
        double v = lac[j * stride] - clutter_half_rho2(nz, half_gamma, urad[j * stride]);
        if (v > mx) mx = v;
    }
    double s = 0;
    for (int j = 0; j < n; j++)
        s += exp(lac[j * stride] - clutter_half_rho2(nz, half_gamma, urad[j * stride]) - mx);
    return mx + log(s);
}

/* Sum of v[0..n) in 8 lanes (fixed order whatever the vector width). */
static inline double lane_sum(const double *v, size_t n)
{
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (size_t l = 0; l < 8; l++) acc[l] += v[i + l];
    for (size_t l = 0; i < n; i++, l++) acc[l] += v[i];
    return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

/* Sum of (v[i] - m)^2 in 8 lanes. */
static inline double lane_sum_sq(const double *v, size_t n, double m)
{
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (size_t l = 0; l < 8; l++) {
            double d = v[i + l] - m;
            acc[l] += d * d;
        }
    for (size_t l = 0; i < n; i++, l++) {
        double d = v[i] - m;
        acc[l] += d * d;
    }
    return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}


/* Targets, nz = 2: y = U1 U2 (untruncated; the caller redraws y < ymin) and
 * the amplitude uniform. */
Q2_CLONES
static void block_targets2(philox4x32_key_t key, uint32_t b0, uint32_t n, uint32_t stream, size_t nb,
                           double *restrict y, double *restrict ua)
{
    for (size_t i = 0; i < nb; i++) {
        philox4x32_ctr_t r;
        DRAW_INTO(r, 0u, b0 + (uint32_t)i, n, stream, key);
        y[i] = u01(r.v[0]) * u01(r.v[1]);
        ua[i] = u01(r.v[2]);
    }
}

/* First retry (attempt 1) of the rejected targets idx[0..nr): y_out[k]. */
Q2_CLONES
static void block_retry2(philox4x32_key_t key, uint32_t b0, uint32_t n, uint32_t stream, size_t nr,
                         const uint32_t *restrict idx, double *restrict y_out)
{
    for (size_t k = 0; k < nr; k++) {
        philox4x32_ctr_t r;
        DRAW_INTO(r, GROUP_RETRY | 1u, b0 + idx[k], n, stream, key);
        y_out[k] = u01(r.v[0]) * u01(r.v[1]);
    }
}

/* Clutter uniforms, [point][scene]: group g of scene i holds words 4g..4g+3
 * (PDAF: radii of points 4g..4g+3; PDAFAI: radius, amplitude of point 2g,
 * then of point 2g+1). */
Q2_CLONES
static void block_clutter_words(philox4x32_key_t key, uint32_t b0, uint32_t n, uint32_t stream,
                                size_t nb, size_t groups, int with_amp, double *restrict urad,
                                double *restrict uamp)
{
    for (size_t g = 0; g < groups; g++) {
        if (with_amp) {
            double *r0 = urad + (2 * g) * nb, *r1 = urad + (2 * g + 1) * nb;
            double *a0 = uamp + (2 * g) * nb, *a1 = uamp + (2 * g + 1) * nb;
            for (size_t i = 0; i < nb; i++) {
                philox4x32_ctr_t r;
                DRAW_INTO(r, (uint32_t)g + 1, b0 + (uint32_t)i, n, stream, key);
                r0[i] = u01(r.v[0]);
                a0[i] = u01(r.v[1]);
                r1[i] = u01(r.v[2]);
                a1[i] = u01(r.v[3]);
            }
        } else {
            double *r0 = urad + (4 * g) * nb, *r1 = r0 + nb, *r2 = r1 + nb, *r3 = r2 + nb;
            for (size_t i = 0; i < nb; i++) {
                philox4x32_ctr_t r;
                DRAW_INTO(r, (uint32_t)g + 1, b0 + (uint32_t)i, n, stream, key);
                r0[i] = u01(r.v[0]);
                r1[i] = u01(r.v[1]);
                r2[i] = u01(r.v[2]);
                r3[i] = u01(r.v[3]);
            }
        }
    }
}

/* e[p] = exp(lac[p] - hg urad[p]) (lac NULL: 0), nz = 2. */
Q2_CLONES
static void block_exp2(size_t np, double hg, const double *restrict lac, const double *restrict urad,
                       double *restrict e)
{
    if (lac)
        for (size_t p = 0; p < np; p++) e[p] = q2_exp(lac[p] - hg * urad[p]);
    else
        for (size_t p = 0; p < np; p++) e[p] = q2_exp(-(hg * urad[p]));
}

/* c[i] = sum_j e[j nb + i], j ascending. */
Q2_CLONES
static void block_sums(size_t nb, int n, const double *restrict e, double *restrict c)
{
    for (size_t i = 0; i < nb; i++) c[i] = 0;
    for (int j = 0; j < n; j++) {
        const double *ej = e + (size_t)j * nb;
        for (size_t i = 0; i < nb; i++) c[i] += ej[i];
    }
}

/* PDAFAI target: L_1 = l^a_1 y, inv = 1 / L_1, r = C / L_1 (r = 0 without
 * clutter). L_1 below e^-700 counts as e^-700: beta_1 is then 0 to all
 * digits (or 1 when b = C = 0) either way. */
Q2_CLONES
static void block_target_ai(size_t nb, int has_clutter, const double *restrict la1,
                            const double *restrict y, const double *restrict c,
                            double *restrict inv, double *restrict r)
{
    for (size_t i = 0; i < nb; i++) {
        double lnl1 = la1[i] + q2_log(y[i]);
        lnl1 = lnl1 < -700 ? -700 : lnl1;
        inv[i] = q2_exp(-lnl1);
        r[i] = has_clutter ? c[i] * inv[i] : 0;
    }
}

/* beta_1 for one cell (b = bk) over the block, and its mean and M2. */
Q2_CLONES
static void block_beta(size_t nb, double bk, const double *restrict r, const double *restrict inv,
                       double *restrict beta, double *mean, double *m2)
{
    for (size_t i = 0; i < nb; i++) beta[i] = 1 / (1 + r[i] + bk * inv[i]);
    const double m = lane_sum(beta, nb) / (double)nb;
    *mean = m;
    *m2 = lane_sum_sq(beta, nb, m);
}

/* Scenes [s0, s1) of stratum t of line ls: per relevant cell, the mean and
 * M2 of beta_1 over the scenes (pm, pm2: t->nrel values). Returns the number
 * of points drawn, -1 (target rejection failed) or -2 (the amplitude model
 * refused a sample). */
static int64_t run_item(const struct line_state *ls, const struct stratum *t, uint64_t s0,
                        uint64_t s1, philox4x32_key_t key, struct scratch *w, double *pm,
                        double *pm2)
{
    const int nz = ls->L->nz, n = t->n;
    const struct q2_amp_sampler *amp = ls->L->amp;
    const size_t groups = ((size_t)n * (amp ? 2 : 1) + 3) / 4; /* philox calls per scene */
    const size_t bs = block_size(n);
    const double hg = ls->half_gamma;
    const uint32_t un = (uint32_t)n, stream = ls->stream;
    const double *rb = ls->rel_b + t->rel0;
    uint64_t done = 0;

    for (uint64_t b0 = s0; b0 < s1; b0 += bs) {
        const size_t nb = (size_t)(s1 - b0 < bs ? s1 - b0 : bs);
        const size_t np = nb * (size_t)n;
        const uint32_t ub0 = (uint32_t)b0;
        /* targets: nz = 2 vectorised, then the rejected ones redrawn */
        if (nz == 2) {
            block_targets2(key, ub0, un, stream, nb, w->y, w->ua);
            /* first retry of the rejected ones, compacted and vectorised;
             * later retries (rare: (1 - F)^2) one by one */
            size_t nr = 0;
            for (size_t i = 0; i < nb; i++)
                if (w->y[i] < ls->ymin) w->idx[nr++] = (uint32_t)i;
            if (nr) {
                block_retry2(key, ub0, un, stream, nr, w->idx, w->beta);
                for (size_t k = 0; k < nr; k++) {
                    const uint32_t i = w->idx[k];
                    w->y[i] = w->beta[k];
                    if (w->y[i] < ls->ymin &&
                        target_retry(ls, key, ub0 + i, un, 2, &w->y[i]))
                        return -1;
                }
            }
        } else {
            for (size_t i = 0; i < nb; i++)
                if (target_draw(ls, key, ub0 + (uint32_t)i, un, &w->y[i], &w->ua[i])) return -1;
        }
        /* clutter L_j = l^a_j exp(-rho_j^2/2), [point][scene], summed per scene */
        if (n > 0) {
            block_clutter_words(key, ub0, un, stream, nb, groups, amp != NULL, w->urad, w->uamp);
            if (amp && amp->log_lr(amp->ctx, 0, np, w->uamp, w->lac)) return -2;
            if (nz == 2) {
                block_exp2(np, hg, amp ? w->lac : NULL, w->urad, w->e);
            } else {
                for (size_t p = 0; p < np; p++)
                    w->e[p] = exp((amp ? w->lac[p] : 0) - clutter_half_rho2(nz, hg, w->urad[p]));
            }
        }
        block_sums(nb, n, w->e, w->c);
        /* target L_1 = l^a_1 y: inv = 1 / L_1, r = C / L_1 */
        if (amp) {
            if (amp->log_lr(amp->ctx, 1, nb, w->ua, w->la1)) return -2;
            block_target_ai(nb, n > 0, w->la1, w->y, w->c, w->inv, w->r);
            for (size_t i = 0; i < nb; i++)
                if (n > 0 && !(w->c[i] <= DBL_MAX)) { /* the clutter sum overflowed */
                    double lnl1 = w->la1[i] + q2_log(w->y[i]);
                    if (lnl1 < -700) lnl1 = -700;
                    double lc = clutter_log_sum(nz, hg, n, w->lac + i, w->urad + i, nb);
                    w->r[i] = exp(lc - lnl1);
                }
        } else {
            for (size_t i = 0; i < nb; i++) {
                w->inv[i] = 1 / w->y[i];
                w->r[i] = w->c[i] * w->inv[i];
            }
        }
        /* beta_1 per relevant cell: block mean and M2, merged into the item's
         * accumulators by Chan's formula */
        for (size_t k = 0; k < t->nrel; k++) {
            double mb, m2b;
            block_beta(nb, rb[k], w->r, w->inv, w->beta, &mb, &m2b);
            if (done == 0) {
                pm[k] = mb;
                pm2[k] = m2b;
            } else {
                const double na = (double)done, nbd = (double)nb, nt = na + nbd;
                const double d = mb - pm[k];
                pm[k] += d * (nbd / nt);
                pm2[k] += m2b + d * d * (na * nbd / nt);
            }
        }
        done += nb;
    }
    return (int64_t)((s1 - s0) * (uint64_t)(n + 1));
}

/* ---- driver ---- */

struct item {
    size_t line;
    int stratum;
    uint64_t s0, s1;
};

/* An item's result (its slot of the round's buffer, par.h): the points drawn
 * (int64), then nrel means and nrel M2s (doubles); the slots start at
 * multiples of 8 bytes. */
static size_t item_bytes(size_t nrel) { return sizeof(int64_t) + 2 * nrel * sizeof(double); }

/* The items of a round as par work units. */
struct round {
    const struct line_state *ls;
    const struct item *items;
    philox4x32_key_t key;
    size_t cap_b, cap_p;
    /* progress (rank 0's first thread, par's done hook) */
    const struct q2_is_options *opt;
    uint64_t *points_done;
    size_t lines_done, n_lines;
    uint64_t planned;
    double t_start, *t_last;
    int threads;
};

/* 0, or 1 out of memory, 2 the target rejection failed, 3 the amplitude
 * model refused a sample */
static int round_unit(void *ctx, size_t i, void *res, void **ws)
{
    const struct round *rd = ctx;
    struct scratch *w = *ws;
    if (!w) {
        w = malloc(sizeof *w);
        if (!w) return 1;
        if (scratch_alloc(w, rd->cap_b, rd->cap_p) != 0) {
            scratch_free(w);
            free(w);
            return 1;
        }
        *ws = w;
    }
    const struct item *it = &rd->items[i];
    const struct line_state *L = &rd->ls[it->line];
    const struct stratum *t = &L->st[it->stratum];
    double *pm = (double *)((unsigned char *)res + sizeof(int64_t));
    const int64_t points = run_item(L, t, it->s0, it->s1, rd->key, w, pm, pm + t->nrel);
    memcpy(res, &points, sizeof points);
    return points >= 0 ? 0 : points == -2 ? 3 : 2;
}

static void round_ws_free(void *ctx, void *ws)
{
    (void)ctx;
    scratch_free(ws);
    free(ws);
}

static void round_done(void *ctx, size_t first, size_t count)
{
    const struct round *rd = ctx;
    for (size_t i = first; i < first + count; i++) {
        const struct item *it = &rd->items[i];
        *rd->points_done += (it->s1 - it->s0) * (uint64_t)(rd->ls[it->line].st[it->stratum].n + 1);
    }
    if (!rd->opt->progress) return;
    const double tn = now_s();
    if (tn - *rd->t_last >= 0.25) {
        struct q2_is_progress pr = {rd->lines_done, rd->n_lines, *rd->points_done, rd->planned, tn - rd->t_start,
                                    rd->threads};
        rd->opt->progress(rd->opt->progress_ctx, &pr);
        *rd->t_last = tn;
    }
}

static void line_results(struct line_state *ls, double *max_se)
{
    struct q2_is_line *L = ls->L;
    const size_t nc = L->n_cells;
    double *se = ls->se;
    for (size_t k = 0; k < nc; k++) L->q2[k] = se[k] = 0;
    /* fixed order: strata ascending, cells in entry order */
    for (int s = 0; s < ls->n_strata; s++) {
        const struct stratum *t = &ls->st[s];
        const double cnt = (double)t->count;
        for (size_t e = t->rel0; e < t->rel0 + t->nrel; e++) {
            const size_t k = ls->rel_cell[e];
            L->q2[k] += ls->rel_w[e] * ls->mean[e];
            if (cnt > 1) se[k] += ls->rel_w[e] * ls->rel_w[e] * ls->m2[e] / (cnt * (cnt - 1));
        }
    }
    double mx = 0;
    for (size_t k = 0; k < nc; k++) {
        L->q2[k] *= ls->pdF[k];
        se[k] = ls->pdF[k] * sqrt(se[k]);
        if (se[k] > mx) mx = se[k];
        if (L->se) L->se[k] = se[k];
    }
    *max_se = mx;
}

/* target_se per cell: a stratum stops drawing once every cell it serves has
 * se <= target (cells sharing it with an unfinished cell keep gaining). */
static void freeze_strata(struct line_state *ls, double target)
{
    for (int s = 0; s < ls->n_strata; s++) {
        struct stratum *t = &ls->st[s];
        int all = 1;
        for (size_t e = t->rel0; e < t->rel0 + t->nrel && all; e++)
            if (!(ls->se[ls->rel_cell[e]] <= target)) all = 0;
        t->frozen = all;
    }
}

int q2_is_run(struct q2_is_line *lines, size_t n_lines, const struct q2_is_options *opt, char *err,
              size_t errlen)
{
    if (err && errlen) err[0] = 0;
    if (!lines || !opt || n_lines == 0) return errmsg_fail(err, errlen, "no lines");
    if (opt->samples < 2 || opt->samples > 0xffffffffu)
        return errmsg_fail(err, errlen, "samples must be in [2, 4294967295] (got %llu)",
                           (unsigned long long)opt->samples);
    if (!(opt->target_se >= 0 && opt->target_se < 1))
        return errmsg_fail(err, errlen, "target se must be in [0, 1) (got %g)", opt->target_se);
    if (!(opt->tail_mass >= 0 && opt->tail_mass <= 1e-2))
        return errmsg_fail(err, errlen, "tail mass must be in [0, 0.01] (got %g)", opt->tail_mass);
    const double tail = opt->tail_mass > 0 ? opt->tail_mass : 1e-12;
    const int threads = q2_is_threads(opt->threads);
    philox4x32_key_t key = {{(uint32_t)opt->seed, (uint32_t)(opt->seed >> 32)}};

    struct line_state *ls = calloc(n_lines, sizeof *ls);
    if (!ls) return errmsg_fail(err, errlen, "out of memory");
    int rc = 0;
    int max_n = 0;
    uint64_t planned = 0;
    for (size_t l = 0; l < n_lines && rc == 0; l++) {
        char e2[200];
        if (line_setup(&ls[l], &lines[l], opt, tail, e2, sizeof e2)) {
            rc = errmsg_fail(err, errlen, "line %zu: %s", l, e2);
            break;
        }
        for (int s = 0; s < ls[l].n_strata; s++) {
            const struct stratum *t = &ls[l].st[s];
            if (t->n > max_n) max_n = t->n;
            planned += t->n_final * (uint64_t)(t->n + 1);
        }
        lines[l].scenes = lines[l].points = 0;
        lines[l].n_strata = ls[l].n_strata;
    }
    /* pilot round (proportional allocation) at N/64, at least 1024; with a
     * target se at N/1024 (at least 1024): the later rounds, sized from the
     * se reached, then overshoot the N a cell needs by ~10-25 % */
    const uint64_t div = opt->target_se > 0 ? 1024 : 64;
    const uint64_t n0 = opt->samples / div > 1024 ? opt->samples / div : 1024;
    for (size_t l = 0; l < n_lines && rc == 0; l++) ls[l].n_round = n0 < opt->samples ? n0 : opt->samples;

    struct item *items = NULL;
    unsigned char *part = NULL;
    size_t *offs = NULL;
    double *cost = NULL;
    uint64_t points_done = 0;
    size_t lines_done = 0;
    const double t_start = now_s();
    double t_last = t_start;
    if (rc == 0 && opt->progress) {
        struct q2_is_progress pr = {0, n_lines, 0, planned, 0, threads};
        opt->progress(opt->progress_ctx, &pr);
    }

    while (rc == 0) {
        /* items of this round: per active line and stratum, the new scenes split
         * at absolute multiples of Q2_IS_CHUNK */
        size_t n_items = 0, cap = 0;
        for (size_t l = 0; l < n_lines; l++) {
            if (ls[l].done) continue;
            for (int s = 0; s < ls[l].n_strata; s++) {
                struct stratum *t = &ls[l].st[s];
                if (opt->target_se > 0 && ls[l].neyman)
                    t->round_to = stratum_demand(&ls[l], t, opt->target_se, opt->samples);
                else
                    t->round_to = t->frozen ? t->count : stratum_count(t, ls[l].n_round, opt->samples);
                for (uint64_t a = t->count; a < t->round_to;) {
                    uint64_t b = (a / Q2_IS_CHUNK + 1) * Q2_IS_CHUNK;
                    if (b > t->round_to) b = t->round_to;
                    if (n_items == cap) {
                        cap = cap ? 2 * cap : 256;
                        struct item *ni = realloc(items, cap * sizeof *ni);
                        if (!ni) {
                            rc = errmsg_fail(err, errlen, "out of memory");
                            break;
                        }
                        items = ni;
                    }
                    items[n_items++] = (struct item){l, s, a, b};
                    a = b;
                }
                if (rc) break;
            }
            if (rc) break;
        }
        if (rc || n_items == 0) break;
        /* every item's result in its own slot (par.h): run in any order, on
         * any thread or rank, merged below in creation order, so no bit
         * depends on where or when an item ran. Costliest first (longest
         * processing time first keeps the finishing times close) */
        free(part), free(offs), free(cost);
        offs = malloc((n_items + 1) * sizeof *offs);
        cost = malloc(n_items * sizeof *cost);
        part = NULL;
        if (offs && cost) {
            offs[0] = 0;
            for (size_t i = 0; i < n_items; i++) {
                const struct stratum *t = &ls[items[i].line].st[items[i].stratum];
                offs[i + 1] = offs[i] + item_bytes(t->nrel);
                cost[i] = (double)(items[i].s1 - items[i].s0) * (double)((size_t)t->n + 1 + 2 * t->nrel);
            }
            part = malloc(offs[n_items] ? offs[n_items] : 1);
        }
        if (!offs || !cost || !part) {
            rc = errmsg_fail(err, errlen, "out of memory");
            break;
        }
        struct round rd = {ls, items, key, BLOCK_MAX, point_cap(max_n), opt, &points_done, lines_done, n_lines,
                           planned, t_start, &t_last, threads};
        struct par_batch pb;
        par_batch_init(&pb, n_items, 0, 1, round_unit, &rd);
        pb.offsets = offs;
        pb.cost = cost;
        pb.threads = threads;
        pb.ws_free = round_ws_free;
        pb.done = round_done;
        char e2[256];
        const int prc = par_run(opt->par, &pb, part, e2, sizeof e2);
        if (prc == PAR_E_UNIT) {
            if (pb.failed_code == 2)
                rc = errmsg_fail(err, errlen, "target radius rejection did not accept in %u draws", MAX_RETRY);
            else if (pb.failed_code == 3)
                rc = errmsg_fail(err, errlen, "the amplitude model refused a sample (%s)",
                                 ls[items[pb.failed_unit].line].L->amp ? ls[items[pb.failed_unit].line].L->amp->name
                                                                        : "?");
            else
                rc = errmsg_fail(err, errlen, "out of memory");
            break;
        }
        if (prc != PAR_OK) {
            rc = errmsg_fail(err, errlen, "%s", e2);
            break;
        }
        /* merge in item order (fixed), then decide per line */
        for (size_t i = 0; i < n_items; i++) {
            const struct item *it = &items[i];
            struct line_state *L = &ls[it->line];
            struct stratum *t = &L->st[it->stratum];
            int64_t points;
            memcpy(&points, part + offs[i], sizeof points);
            const double *pm = (const double *)(part + offs[i] + sizeof(int64_t)), *pm2 = pm + t->nrel;
            const double nb = (double)(it->s1 - it->s0);
            for (size_t k = 0; k < t->nrel; k++) {
                double *m = &L->mean[t->rel0 + k], *m2 = &L->m2[t->rel0 + k];
                if (t->count == 0) {
                    *m = pm[k];
                    *m2 = pm2[k];
                } else {
                    const double na = (double)t->count, nt = na + nb, d = pm[k] - *m;
                    *m += d * (nb / nt);
                    *m2 += pm2[k] + d * d * (na * nb / nt);
                }
            }
            t->count = it->s1;
            L->L->scenes += it->s1 - it->s0;
            L->L->points += (uint64_t)points;
        }
        for (size_t l = 0; l < n_lines; l++) {
            if (ls[l].done) continue;
            double max_se;
            line_results(&ls[l], &max_se);
            ls[l].L->samples_mode = ls[l].n_round;
            if (opt->target_se > 0) freeze_strata(&ls[l], opt->target_se);
            if ((opt->target_se > 0 && max_se <= opt->target_se) ||
                (!(opt->target_se > 0) && ls[l].n_round >= opt->samples)) {
                ls[l].done = 1;
                lines_done++;
                for (int st = 0; st < ls[l].n_strata; st++) /* not drawn after all */
                    planned -= (ls[l].st[st].n_final - ls[l].st[st].count) * (uint64_t)(ls[l].st[st].n + 1);
                continue;
            }
            const int after_pilot = !ls[l].neyman;
            if (!ls[l].neyman) {
                /* the plan changes with the allocation */
                for (int st = 0; st < ls[l].n_strata; st++)
                    planned -= ls[l].st[st].n_final * (uint64_t)(ls[l].st[st].n + 1);
                neyman_update(&ls[l], opt->samples);
                for (int st = 0; st < ls[l].n_strata; st++)
                    planned += ls[l].st[st].n_final * (uint64_t)(ls[l].st[st].n + 1);
                ls[l].neyman = 1;
            }
            if (opt->target_se > 0) {
                /* next round, per cell (its strata's scenes rel_rho N_k):
                 * after the pilot N_k = 2 N0 (the pilot's se is that of the
                 * proportional allocation); then the N_k that its se predicts
                 * (se ~ 1/sqrt(N)) with a 10 % margin, growing 1.25 .. 4 x;
                 * cells at the target ask for nothing more */
                const double t = opt->target_se;
                double nmax = 0;
                for (size_t k = 0; k < ls[l].L->n_cells; k++) {
                    double *nk = &ls[l].cell_n[k];
                    if (after_pilot) {
                        *nk = 2 * (double)ls[l].n_round;
                    } else if (ls[l].se[k] > t) {
                        double grow = 1.1 * (ls[l].se[k] / t) * (ls[l].se[k] / t);
                        grow = grow < 1.25 ? 1.25 : grow > 4 ? 4 : grow;
                        *nk = ceil(grow * *nk);
                    }
                    if (*nk > (double)opt->samples) *nk = (double)opt->samples;
                    if (ls[l].se[k] > t && *nk > nmax) nmax = *nk;
                }
                ls[l].n_round = (uint64_t)nmax;
                /* nothing left to draw: every unfinished cell is at N */
                int more = 0;
                for (int st = 0; st < ls[l].n_strata && !more; st++)
                    more = stratum_demand(&ls[l], &ls[l].st[st], t, opt->samples) > ls[l].st[st].count;
                if (!more) {
                    ls[l].done = 1;
                    lines_done++;
                }
            } else
                ls[l].n_round = opt->samples;
        }
    }
    if (rc == 0 && opt->progress) {
        struct q2_is_progress pr = {lines_done, n_lines, points_done, planned, now_s() - t_start, threads};
        opt->progress(opt->progress_ctx, &pr);
    }
    free(items);
    free(part);
    free(offs);
    free(cost);
    for (size_t l = 0; l < n_lines; l++) line_free(&ls[l]);
    free(ls);
    return rc;
}

int q2_is_cell(int nz, double gamma, double pd, double lambda_vg, const struct q2_amp_sampler *amp,
               const struct q2_is_options *opt, double *q2, double *se, char *err, size_t err_len)
{
    double pdv = (amp && !(pd > 0)) ? amp->pd : pd;
    struct q2_is_line line;
    memset(&line, 0, sizeof line);
    line.nz = nz;
    line.gamma = gamma;
    line.amp = amp;
    line.n_cells = 1;
    line.pd = &pdv;
    line.lambda_vg = &lambda_vg;
    line.q2 = q2;
    line.se = se;
    return q2_is_run(&line, 1, opt, err, err_len);
}
