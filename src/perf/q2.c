/* q2.c - q2 lookup by tensor-product interpolation on a grid, tabulated ROC
 * (trk/q2.h; docs/conventions.md "q2, MRE and CRLB"). */
#include "trk/q2.h"

#include "trk/amplitude.h"
#include "trk/special.h"

/* Axis kinds of each detector, in axis order. */
enum axis_kind { AX_PD, AX_SNR_DB, AX_PFA, AX_LAMBDA_VG };

static int detector_axes(int detector, const enum axis_kind **kinds)
{
    static const enum axis_kind pdaf[2] = {AX_PD, AX_LAMBDA_VG};
    static const enum axis_kind pdafai[3] = {AX_SNR_DB, AX_PFA, AX_LAMBDA_VG};
    switch (detector) {
    case TRK_Q2_PDAF: *kinds = pdaf; return 2;
    case TRK_Q2_PDAFAI: *kinds = pdafai; return 3;
    default: return 0;
    }
}

/* u coordinate of node j. */
static trk_real node_u(const struct trk_q2_axis *a, size_t j)
{
    if (a->nodes) return a->nodes[j];
    if (a->count == 1) return a->u_first;
    if (j == a->count - 1) return a->u_last;
    return a->u_first + (a->u_last - a->u_first) * ((trk_real)j / (trk_real)(a->count - 1));
}

/* Is the physical value x = (log_spacing ? e^u : u) inside the axis kind's domain? */
static int u_in_domain(enum axis_kind k, int log_spacing, trk_real u)
{
    if (!isfinite(u)) return 0;
    switch (k) {
    case AX_PD: return log_spacing ? u <= 0 : (u > 0 && u <= 1);
    case AX_PFA: return log_spacing ? u < 0 : (u > 0 && u < 1);
    case AX_LAMBDA_VG: return log_spacing ? 1 : u > 0;
    case AX_SNR_DB: return 1;
    }
    return 0;
}

static trk_status check_axis(const struct trk_q2_axis *a, enum axis_kind k)
{
    if (a->count < 1) return TRK_E_ARG;
    if (a->log_spacing != 0 && a->log_spacing != 1) return TRK_E_ARG;
    if (a->interp != TRK_Q2_LINEAR && a->interp != TRK_Q2_CUBIC) return TRK_E_ARG;
    if (!a->nodes) {
        if (!isfinite(a->u_first) || !isfinite(a->u_last)) return TRK_E_TABLE_CORRUPT;
        if (a->count > 1 && !(a->u_last > a->u_first)) return TRK_E_TABLE_CORRUPT;
    }
    trk_real prev = 0;
    for (size_t j = 0; j < a->count; j++) {
        trk_real u = node_u(a, j);
        if (!u_in_domain(k, a->log_spacing, u)) return TRK_E_TABLE_CORRUPT;
        if (j > 0 && !(u > prev)) return TRK_E_TABLE_CORRUPT;
        prev = u;
    }
    return TRK_OK;
}

static trk_real axis_max_gain(const struct trk_q2_axis *a);

trk_status trk_q2_lookup_init(struct trk_q2_lookup *q, const struct trk_q2_grid *grid)
{
    const enum axis_kind *kinds;
    if (!q || !grid || !grid->values) return TRK_E_ARG;
    int n_axes = detector_axes(grid->detector, &kinds);
    if (n_axes == 0) return TRK_E_TABLE_KIND;
    size_t total = 1;
    for (int i = 0; i < n_axes; i++) {
        trk_status st = check_axis(&grid->axis[i], kinds[i]);
        if (st != TRK_OK) return st;
        /* the documented bound on the noise gain of the interpolation (q2.h) */
        if (!(axis_max_gain(&grid->axis[i]) <= TRK_Q2_MAX_AXIS_GAIN)) return TRK_E_TABLE_CORRUPT;
        if (grid->axis[i].count > (size_t)-1 / total) return TRK_E_TABLE_CORRUPT;
        total *= grid->axis[i].count;
    }
    const size_t vs = grid->value_stride ? grid->value_stride : 1;
    if (total > ((size_t)-1) / vs) return TRK_E_TABLE_CORRUPT;
    for (size_t j = 0; j < total; j++) {
        trk_real v = grid->values[j * vs];
        if (!(v >= 0 && v <= 1)) return TRK_E_TABLE_CORRUPT; /* also NaN */
    }
    struct trk_q2_lookup r;
    r.grid = *grid;
    r.grid.value_stride = vs;
    r.n_axes = n_axes;
    size_t s = vs;
    for (int i = n_axes - 1; i >= 0; i--) {
        r.stride[i] = s;
        s *= grid->axis[i].count;
    }
    for (int i = n_axes; i < TRK_Q2_MAX_AXES; i++) r.stride[i] = 0;
    r.nz = 0;
    r.gate_gamma = r.gate_prob = 0;
    r.amp_model = 0;
    r.nu = 0;
    r.max_se = 0;
    *q = r;
    return TRK_OK;
}

/* ---- q2 tables ---- */

/* A required parameter: missing (or of the other type) makes the table corrupt. */
static trk_status need_int(const struct trk_table *t, const char *name, int64_t *v)
{
    trk_status st = trk_table_param_int(t, name, v);
    return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
}

static trk_status need_real(const struct trk_table *t, const char *name, trk_real *v)
{
    trk_status st = trk_table_param_real(t, name, v);
    return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
}

/* One table axis as a lookup axis: the expected variable (else the table is
 * of another kind), and a spacing the lookup reads in place (log axes
 * uniform in ln x; linear or explicit axes in x). */
static trk_status table_axis(const struct trk_table_axis *ta, uint32_t var, int log_axis, int interp,
                             struct trk_q2_axis *a)
{
    if (ta->variable != var) return TRK_E_TABLE_KIND;
    a->count = ta->count;
    a->interp = interp;
    a->nodes = NULL;
    a->log_spacing = log_axis;
    if (log_axis) {
        if (ta->spacing != TRK_TABLE_SPACING_LOG || !(ta->lo > 0)) return TRK_E_TABLE_CORRUPT;
        a->u_first = trk_log(ta->lo);
        a->u_last = trk_log(ta->hi);
    } else if (ta->spacing == TRK_TABLE_SPACING_LINEAR) {
        a->u_first = ta->lo;
        a->u_last = ta->hi;
    } else if (ta->spacing == TRK_TABLE_SPACING_EXPLICIT && ta->values) {
        a->nodes = ta->values;
        a->u_first = ta->lo;
        a->u_last = ta->hi;
    } else {
        return TRK_E_TABLE_CORRUPT;
    }
    return TRK_OK;
}

trk_status trk_q2_lookup_init_table(struct trk_q2_lookup *q, const struct trk_table *t, int detector, int nz)
{
    if (!q || !t || !t->bytes) return TRK_E_ARG;
    if (detector != TRK_Q2_PDAF && detector != TRK_Q2_PDAFAI) return TRK_E_ARG;
    if (nz < 1 || nz > 3) return TRK_E_ARG;
    const uint32_t kind = detector == TRK_Q2_PDAF ? TRK_TABLE_KIND_Q2_PDAF : TRK_TABLE_KIND_Q2_PDAFAI;
    if (t->info.kind != kind) return TRK_E_TABLE_KIND;
    if (t->info.kind_version != TRK_Q2_TABLE_VERSION) return TRK_E_TABLE_VERSION;
    int64_t det, tnz, model = 0;
    trk_real gamma, pg, nu = 0, max_se;
    trk_status st;
    if ((st = need_int(t, "detector", &det)) != TRK_OK || (st = need_int(t, "nz", &tnz)) != TRK_OK ||
        (st = need_real(t, "gate_gamma", &gamma)) != TRK_OK || (st = need_real(t, "gate_prob", &pg)) != TRK_OK ||
        (st = need_real(t, "max_se", &max_se)) != TRK_OK)
        return st;
    if (det != detector || tnz < 1 || tnz > 3) return TRK_E_TABLE_CORRUPT;
    if (tnz != nz) return TRK_E_TABLE_KIND; /* a table for another measurement dimension */
    if (!(gamma > 0) || !(pg > 0 && pg <= 1) || !(max_se >= 0 && max_se <= 1)) return TRK_E_TABLE_CORRUPT;
    /* P_G of gamma (nz degrees of freedom) */
    if (!(trk_fabs(trk_chi2_cdf(nz, gamma) - pg) <= TRK_REAL_C(1e-5))) return TRK_E_TABLE_CORRUPT;
    if (detector == TRK_Q2_PDAFAI) {
        if ((st = need_int(t, "model", &model)) != TRK_OK || (st = need_real(t, "nu", &nu)) != TRK_OK) return st;
        if (model == TRK_AMP_RAYLEIGH) {
            if (nu != 0) return TRK_E_TABLE_CORRUPT;
        } else if (model == TRK_AMP_K) {
            if (!(nu > 0)) return TRK_E_TABLE_CORRUPT;
        } else {
            return TRK_E_TABLE_CORRUPT;
        }
    }
    struct trk_table_section sec;
    st = trk_table_section(t, TRK_Q2_SECTION_VALUES, &sec);
    if (st != TRK_OK) return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
    const uint32_t naxes = detector == TRK_Q2_PDAF ? 2u : 3u;
    if (sec.naxes != naxes) return TRK_E_TABLE_KIND;
    if (sec.ncomp != 2) return TRK_E_TABLE_CORRUPT;
    int interp;
    if (sec.interp == TRK_TABLE_INTERP_LINEAR) interp = TRK_Q2_LINEAR;
    else if (sec.interp == TRK_TABLE_INTERP_CUBIC) interp = TRK_Q2_CUBIC;
    else return TRK_E_TABLE_CORRUPT;
    struct trk_q2_grid g;
    g.detector = detector;
    for (int i = 0; i < TRK_Q2_MAX_AXES; i++) {
        g.axis[i].count = 0;
        g.axis[i].nodes = NULL;
        g.axis[i].u_first = g.axis[i].u_last = 0;
        g.axis[i].log_spacing = 0;
        g.axis[i].interp = TRK_Q2_LINEAR;
    }
    static const uint32_t vars_pdaf[2] = {TRK_TABLE_VAR_PD, TRK_TABLE_VAR_LAMBDA_VG};
    static const uint32_t vars_ai[3] = {TRK_TABLE_VAR_SNR_DB, TRK_TABLE_VAR_PFA, TRK_TABLE_VAR_LAMBDA_VG};
    static const int log_pdaf[2] = {0, 1}, log_ai[3] = {0, 1, 1};
    const uint32_t *vars = detector == TRK_Q2_PDAF ? vars_pdaf : vars_ai;
    const int *logs = detector == TRK_Q2_PDAF ? log_pdaf : log_ai;
    for (uint32_t i = 0; i < naxes; i++) {
        st = table_axis(&sec.axis[i], vars[i], logs[i], interp, &g.axis[i]);
        if (st != TRK_OK) return st;
    }
    /* per-cell standard errors: finite (the container) and in [0, max_se] */
    for (size_t c = 1; c < sec.count; c += 2)
        if (!(sec.data[c] >= 0 && sec.data[c] <= max_se)) return TRK_E_TABLE_CORRUPT;
    g.values = sec.data;
    g.value_stride = 2;
    struct trk_q2_lookup r;
    st = trk_q2_lookup_init(&r, &g);
    if (st != TRK_OK) return st;
    r.nz = nz;
    r.gate_gamma = gamma;
    r.gate_prob = pg;
    r.amp_model = (int)model;
    r.nu = nu;
    r.max_se = max_se;
    *q = r;
    return TRK_OK;
}

/* Interpolation weights of one axis at coordinate u: nodes first..first+n-1
 * with weights w[0..n). TRK_E_RANGE outside the axis. */
struct axis_weights {
    size_t first;
    int n;
    trk_real w[4];
};

/* Cubic Hermite slope stencil of node k: m_k = sum c[j] f[s0 + j], j < 3. */
static void slope_stencil(const struct trk_q2_axis *a, size_t k, size_t *s0, trk_real c[3])
{
    const size_t n = a->count;
    if (k == 0) {
        trk_real h0 = node_u(a, 1) - node_u(a, 0), h1 = node_u(a, 2) - node_u(a, 1);
        *s0 = 0;
        c[0] = -(2 * h0 + h1) / (h0 * (h0 + h1));
        c[1] = (h0 + h1) / (h0 * h1);
        c[2] = -h0 / (h1 * (h0 + h1));
    } else if (k == n - 1) {
        trk_real h0 = node_u(a, n - 2) - node_u(a, n - 3), h1 = node_u(a, n - 1) - node_u(a, n - 2);
        *s0 = n - 3;
        c[0] = h1 / (h0 * (h0 + h1));
        c[1] = -(h0 + h1) / (h0 * h1);
        c[2] = (h0 + 2 * h1) / (h1 * (h0 + h1));
    } else {
        trk_real h0 = node_u(a, k) - node_u(a, k - 1), h1 = node_u(a, k + 1) - node_u(a, k);
        *s0 = k - 1;
        c[0] = -h1 / (h0 * (h0 + h1));
        c[1] = (h1 - h0) / (h0 * h1);
        c[2] = h0 / (h1 * (h0 + h1));
    }
}

static trk_status axis_weights(const struct trk_q2_axis *a, trk_real x, struct axis_weights *aw)
{
    if (!isfinite(x)) return TRK_E_NAN;
    trk_real u;
    if (a->log_spacing) {
        if (!(x > 0)) return TRK_E_RANGE;
        u = trk_log(x);
    } else {
        u = x;
    }
    const size_t n = a->count;
    const trk_real lo = node_u(a, 0), hi = node_u(a, n - 1);
    /* rounding slack: a query at an end node computed in another precision */
    const trk_real slack = 8 * TRK_REAL_EPS * (1 + trk_fabs(lo) + trk_fabs(hi));
    if (n == 1) {
        trk_real tol = a->log_spacing ? TRK_REAL_C(1e-6) : TRK_REAL_C(1e-6) * (1 + trk_fabs(lo));
        if (!(trk_fabs(u - lo) <= tol)) return TRK_E_RANGE;
        aw->first = 0;
        aw->n = 1;
        aw->w[0] = 1;
        return TRK_OK;
    }
    if (!(u >= lo - slack && u <= hi + slack)) return TRK_E_RANGE;
    /* bracketing cell i: u_i <= u <= u_{i+1} */
    size_t i;
    if (a->nodes) {
        size_t l = 0, r = n - 1; /* invariant u_l <= u < u_r (or u at the ends) */
        while (r - l > 1) {
            size_t m = l + (r - l) / 2;
            if (a->nodes[m] <= u) l = m;
            else r = m;
        }
        i = l;
    } else {
        trk_real f = (u - lo) / (hi - lo) * (trk_real)(n - 1);
        if (!(f > 0)) f = 0;
        i = (size_t)f;
        if (i > n - 2) i = n - 2;
    }
    const trk_real ui = node_u(a, i), ui1 = node_u(a, i + 1), h = ui1 - ui;
    trk_real t = (u - ui) / h;
    if (t < 0) t = 0; /* only within the rounding slack checked above */
    if (t > 1) t = 1;
    if (a->interp == TRK_Q2_LINEAR || n < 4) {
        aw->first = i;
        aw->n = 2;
        aw->w[0] = 1 - t;
        aw->w[1] = t;
        return TRK_OK;
    }
    const trk_real t2 = t * t, t3 = t2 * t;
    if (!a->nodes && i >= 1 && i + 2 < n) {
        /* uniform interior cell: the slopes are central differences and the
         * weights those of Catmull-Rom (the general formulas below, simplified) */
        aw->first = i - 1;
        aw->n = 4;
        aw->w[0] = TRK_REAL_C(0.5) * (-t3 + 2 * t2 - t);
        aw->w[1] = TRK_REAL_C(0.5) * (3 * t3 - 5 * t2 + 2);
        aw->w[2] = TRK_REAL_C(0.5) * (-3 * t3 + 4 * t2 + t);
        aw->w[3] = TRK_REAL_C(0.5) * (t3 - t2);
        return TRK_OK;
    }
    /* cubic Hermite: p = h00 f_i + h10 h m_i + h01 f_i+1 + h11 h m_i+1 */
    size_t j0 = i >= 1 ? i - 1 : 0;
    if (j0 > n - 4) j0 = n - 4;
    const trk_real h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
    const trk_real h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    aw->first = j0;
    aw->n = 4;
    for (int j = 0; j < 4; j++) aw->w[j] = 0;
    aw->w[i - j0] += h00;
    aw->w[i + 1 - j0] += h01;
    size_t s0;
    trk_real c[3];
    slope_stencil(a, i, &s0, c);
    for (int j = 0; j < 3; j++) aw->w[s0 + (size_t)j - j0] += h10 * h * c[j];
    slope_stencil(a, i + 1, &s0, c);
    for (int j = 0; j < 3; j++) aw->w[s0 + (size_t)j - j0] += h11 * h * c[j];
    return TRK_OK;
}

/* The largest noise gain sum|w| of one axis's interpolation weights, over
 * every cell at TRK_Q2_GAIN_SAMPLES + 1 points (the ends included). Linear
 * weights sum to 1; uniform cubic ones (Catmull-Rom) to at most 1.25; on
 * explicit nodes the slopes divide by the neighbouring intervals, so a short
 * interval next to a long one gives a large gain (pd nodes
 * 0.01 and 1e-12 apart returned 5.9e9 from values in [0, 1]). */
#define TRK_Q2_GAIN_SAMPLES 64
static trk_real axis_max_gain(const struct trk_q2_axis *a)
{
    trk_real g = 1;
    if (a->interp != TRK_Q2_CUBIC || a->count < 4) return g;
    for (size_t i = 0; i + 1 < a->count; i++) {
        const trk_real u0 = node_u(a, i), u1 = node_u(a, i + 1);
        for (int k = 0; k <= TRK_Q2_GAIN_SAMPLES; k++) {
            const trk_real f = (trk_real)k / TRK_Q2_GAIN_SAMPLES;
            const trk_real u = k == TRK_Q2_GAIN_SAMPLES ? u1 : u0 + f * (u1 - u0);
            struct axis_weights aw;
            if (axis_weights(a, a->log_spacing ? trk_exp(u) : u, &aw) != TRK_OK) return (trk_real)INFINITY;
            trk_real s = 0;
            for (int j = 0; j < aw.n; j++) s += trk_fabs(aw.w[j]);
            if (!(s <= g)) g = isnan(s) ? (trk_real)INFINITY : s;
        }
    }
    return g;
}

trk_status trk_q2_lookup_eval(const struct trk_q2_lookup *q, const trk_real *x, trk_real *q2)
{
    struct axis_weights aw[TRK_Q2_MAX_AXES];
    if (!q || !x || !q2) return TRK_E_ARG;
    const int na = q->n_axes;
    if (na < 2 || na > TRK_Q2_MAX_AXES) return TRK_E_ARG;
    for (int i = 0; i < na; i++)
        if (!isfinite(x[i])) return TRK_E_NAN;
    for (int i = 0; i < na; i++) {
        trk_status st = axis_weights(&q->grid.axis[i], x[i], &aw[i]);
        if (st != TRK_OK) return st;
    }
    /* a missing third axis is one node of weight 1 */
    for (int i = na; i < TRK_Q2_MAX_AXES; i++) {
        aw[i].first = 0;
        aw[i].n = 1;
        aw[i].w[0] = 1;
    }
    const trk_real *v = q->grid.values;
    trk_real sum = 0;
    for (int a = 0; a < aw[0].n; a++) {
        size_t o0 = (aw[0].first + (size_t)a) * q->stride[0];
        for (int b = 0; b < aw[1].n; b++) {
            size_t o1 = o0 + (aw[1].first + (size_t)b) * q->stride[1];
            trk_real wab = aw[0].w[a] * aw[1].w[b];
            trk_real inner = 0;
            for (int c = 0; c < aw[2].n; c++)
                inner += aw[2].w[c] * v[o1 + (aw[2].first + (size_t)c) * q->stride[2]];
            sum += wab * inner;
        }
    }
    *q2 = sum;
    return TRK_OK;
}

trk_status trk_q2_pdaf(const struct trk_q2_lookup *q, trk_real pd, trk_real lambda_vg, trk_real *q2)
{
    if (!q || !q2) return TRK_E_ARG;
    if (q->grid.detector != TRK_Q2_PDAF) return TRK_E_TABLE_KIND;
    const trk_real x[2] = {pd, lambda_vg};
    return trk_q2_lookup_eval(q, x, q2);
}

trk_status trk_q2_pdafai(const struct trk_q2_lookup *q, trk_real snr_db, trk_real pfa,
                         trk_real lambda_vg, trk_real *q2)
{
    if (!q || !q2) return TRK_E_ARG;
    if (q->grid.detector != TRK_Q2_PDAFAI) return TRK_E_TABLE_KIND;
    const trk_real x[3] = {snr_db, pfa, lambda_vg};
    return trk_q2_lookup_eval(q, x, q2);
}

trk_status trk_q2_line_eval(const void *ctx, trk_real lambda_vg, trk_real *q2)
{
    const struct trk_q2_line *l = ctx;
    if (!l || !l->lookup || !q2) return TRK_E_ARG;
    switch (l->lookup->grid.detector) {
    case TRK_Q2_PDAF: return trk_q2_pdaf(l->lookup, l->fixed[0], lambda_vg, q2);
    case TRK_Q2_PDAFAI: return trk_q2_pdafai(l->lookup, l->fixed[0], l->fixed[1], lambda_vg, q2);
    default: return TRK_E_TABLE_KIND;
    }
}


trk_status trk_q2_roc_eval(const void *ctx, trk_real pfa, trk_real lambda_vg, trk_real *q2)
{
    const struct trk_q2_roc *r = ctx;
    if (!r || !r->lookup || !q2) return TRK_E_ARG;
    if (!isfinite(pfa) || !isfinite(lambda_vg)) return TRK_E_NAN;
    if (r->lookup->grid.detector == TRK_Q2_PDAF) {
        if (!r->roc) return TRK_E_ARG;
        trk_real pd;
        trk_status st = r->roc(r->roc_ctx, pfa, &pd);
        if (st != TRK_OK) return st;
        return trk_q2_pdaf(r->lookup, pd, lambda_vg, q2);
    }
    return trk_q2_pdafai(r->lookup, r->snr_db, pfa, lambda_vg, q2);
}
