/* amplitude_table.c - an amplitude model from a table made by
 * `trk-tablegen amp` (trk/amplitude.h "AMPLITUDE TABLE"). Every parameter and
 * section is checked before the model is written. */
#include "trk/amplitude.h"
#include "internal.h"

/* Relative agreement of values the tool derived from one another (threshold,
 * first nodes): loose enough for float tables, tight enough to catch a table
 * whose parameters and data do not belong together. */
#define AGREE TRK_REAL_C(1e-5)

/* Bounds that keep every lookup finite whatever a (validated) table holds:
 * node values and slopes (|ln l^a|, u^2, their derivatives), the ln-amplitude
 * axis (|ln u|) and the x range. Real tables are far inside: |ln l^a| and u^2
 * below ~1e5, |ln u| below ~10, x_max 40. */
#define VALUE_MAX TRK_REAL_C(1e12)
#define LN_AMP_MAX TRK_REAL_C(700.0)
#define X_MAX TRK_REAL_C(1e6)

static int bounded(const trk_real *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!(trk_fabs(v[i]) <= VALUE_MAX)) return 0;
    return 1;
}

static int agree(trk_real a, trk_real b)
{
    const trk_real s = trk_fabs(a) > trk_fabs(b) ? trk_fabs(a) : trk_fabs(b);
    return trk_fabs(a - b) <= AGREE * (s > 1 ? s : 1);
}

/* Required real parameter: a missing one makes the amp table corrupt. */
static trk_status need_real(const struct trk_table *t, const char *name, trk_real *v)
{
    trk_status st = trk_table_param_real(t, name, v);
    return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
}

static trk_status need_int(const struct trk_table *t, const char *name, int64_t *v)
{
    trk_status st = trk_table_param_int(t, name, v);
    return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
}

static trk_status need_section(const struct trk_table *t, uint32_t id, struct trk_table_section *s)
{
    trk_status st = trk_table_section(t, id, s);
    return st == TRK_E_TABLE_KIND ? TRK_E_TABLE_CORRUPT : st;
}

/* ln l^a section: 1 linear axis in s = ln(a/sqrt P) from ln(t/sqrt P); cells (L, dL/ds). */
static trk_status load_log_lr(const struct trk_table *t, struct trk_amplitude *r)
{
    struct trk_table_section s;
    trk_status st = need_section(t, TRK_AMP_SECTION_LOG_LR, &s);
    if (st != TRK_OK) return st;
    const struct trk_table_axis *ax = &s.axis[0];
    if (s.naxes != 1 || s.ncomp != 2 || s.interp != TRK_TABLE_INTERP_HERMITE ||
        ax->spacing != TRK_TABLE_SPACING_LINEAR || ax->variable != TRK_TABLE_VAR_LN_AMP)
        return TRK_E_TABLE_CORRUPT;
    if (!(trk_fabs(ax->lo) <= LN_AMP_MAX && trk_fabs(ax->hi) <= LN_AMP_MAX) || !bounded(s.data, s.count))
        return TRK_E_TABLE_CORRUPT;
    if (!agree(ax->lo, trk_log(r->threshold) - r->ln_sqrt_p)) return TRK_E_TABLE_CORRUPT;
    r->llr = s.data;
    r->llr_n = ax->count;
    r->llr_lo = ax->lo;
    r->llr_hi = ax->hi;
    r->llr_h = (ax->hi - ax->lo) / (trk_real)(ax->count - 1);
    r->llr_inv_h = (trk_real)(ax->count - 1) / (ax->hi - ax->lo);
    if (!(r->llr_h > 0) || !isfinite(r->llr_inv_h)) return TRK_E_TABLE_CORRUPT;
    /* tail rate k = L'_N / (L_inf - L_N) when the curve approaches its limit */
    const trk_real *e = s.data + 2 * (size_t)(ax->count - 1);
    const trk_real gap = r->llr_limit - e[0];
    r->llr_tail_rate = gap * e[1] > 0 ? e[1] / gap : 0;
    if (!isfinite(r->llr_tail_rate)) r->llr_tail_rate = 0;
    return TRK_OK;
}

/* One inverse-survival section; u_t = t/sqrt(P). */
static trk_status load_inv(const struct trk_table *t, uint32_t id, trk_real u_t, struct trk_amp_inv_curve *cv)
{
    struct trk_table_section s;
    trk_status st = need_section(t, id, &s);
    if (st != TRK_OK) return st;
    const struct trk_table_axis *ax = &s.axis[0];
    if (s.naxes != 1 || ax->variable != TRK_TABLE_VAR_X || ax->lo != 0 || !(ax->hi <= X_MAX) ||
        !bounded(s.data, s.count))
        return TRK_E_TABLE_CORRUPT;
    const uint32_t n = ax->count;
    if (ax->spacing == TRK_TABLE_SPACING_LINEAR && s.ncomp == 2 && s.interp == TRK_TABLE_INTERP_HERMITE) {
        /* (u^2, du^2/dx): u^2 from t^2, strictly increasing, positive slopes */
        if (!agree(s.data[0], u_t * u_t)) return TRK_E_TABLE_CORRUPT;
        for (uint32_t i = 0; i < n; i++) {
            if (!(s.data[2 * (size_t)i + 1] > 0)) return TRK_E_TABLE_CORRUPT;
            if (i > 0 && !(s.data[2 * (size_t)i] > s.data[2 * (size_t)i - 2])) return TRK_E_TABLE_CORRUPT;
        }
        cv->h = ax->hi / (trk_real)(n - 1);
        cv->inv_h = (trk_real)(n - 1) / ax->hi;
        if (!(cv->h > 0) || !isfinite(cv->inv_h)) return TRK_E_TABLE_CORRUPT;
    } else if (ax->spacing == TRK_TABLE_SPACING_EXPLICIT && s.ncomp == 1 &&
               s.interp == TRK_TABLE_INTERP_LINEAR) {
        /* u at explicit x nodes: from t, strictly increasing */
        if (!agree(s.data[0], u_t)) return TRK_E_TABLE_CORRUPT;
        for (uint32_t i = 1; i < n; i++)
            if (!(s.data[i] > s.data[i - 1])) return TRK_E_TABLE_CORRUPT;
        cv->h = cv->inv_h = 0;
    } else {
        return TRK_E_TABLE_CORRUPT;
    }
    cv->data = s.data;
    cv->axis = *ax;
    return TRK_OK;
}

trk_status trk_amplitude_init_table(struct trk_amplitude *m, const struct trk_table *t)
{
    if (!m || !t || !t->bytes) return TRK_E_ARG;
    if (t->info.kind != TRK_TABLE_KIND_AMP) return TRK_E_TABLE_KIND;
    if (t->info.kind_version != TRK_AMP_TABLE_VERSION) return TRK_E_TABLE_VERSION;
    int64_t model;
    trk_real nu, snr_db, pfa, power, thr, pd, limit = 0;
    trk_status st;
    if ((st = need_int(t, "model", &model)) != TRK_OK || (st = need_real(t, "nu", &nu)) != TRK_OK ||
        (st = need_real(t, "snr_db", &snr_db)) != TRK_OK || (st = need_real(t, "pfa", &pfa)) != TRK_OK ||
        (st = need_real(t, "clutter_power", &power)) != TRK_OK ||
        (st = need_real(t, "threshold", &thr)) != TRK_OK || (st = need_real(t, "pd", &pd)) != TRK_OK)
        return st;
    if (model != TRK_AMP_RAYLEIGH && model != TRK_AMP_K) return TRK_E_TABLE_CORRUPT;
    if (!(power > 0 && power <= TRK_REAL_C(1e30)) || !(pfa > 0 && pfa < 1) || !(thr > 0) || !(pd > 0 && pd <= 1) ||
        !(snr_db >= -100 && snr_db <= 100))
        return TRK_E_TABLE_CORRUPT;
    /* the threshold over the clutter amplitude scale, t / sqrt(P), is at most
     * TRK_AMP_MAX_NORM_THRESHOLD (Rayleigh at P_FA 1e-300: 26): a larger one
     * (whose square may overflow) is not a detection threshold */
    if (!(thr <= TRK_AMP_MAX_NORM_THRESHOLD * trk_sqrt(power))) return TRK_E_TABLE_CORRUPT;
    struct trk_amplitude r;
    if (model == TRK_AMP_RAYLEIGH) {
        /* closed form from the parameters; the table must agree with it */
        if (trk_amplitude_init_rayleigh(&r, power, snr_db, pfa) != TRK_OK) return TRK_E_TABLE_CORRUPT;
        if (!agree(thr, r.threshold) || !agree(pd, r.pd)) return TRK_E_TABLE_CORRUPT;
    } else {
        if (!(nu > 0)) return TRK_E_TABLE_CORRUPT;
        if ((st = need_real(t, "log_lr_limit", &limit)) != TRK_OK) return st;
        if (!(trk_fabs(limit) <= VALUE_MAX)) return TRK_E_TABLE_CORRUPT;
        r = (struct trk_amplitude){0};
        r.model = TRK_AMP_K;
        r.tabulated = 1;
        r.clutter_power = power;
        r.snr_db = snr_db;
        r.pfa = pfa;
        r.nu = nu;
        r.threshold = thr;
        r.t2 = thr * thr;
        r.pd = pd;
        r.snr = trk_pow(10, snr_db / 10);
        r.sqrt_p = trk_sqrt(power);
        r.ln_sqrt_p = TRK_REAL_C(0.5) * trk_log(power);
    }
    r.llr_limit = limit;
    const trk_real u_t = thr / r.sqrt_p;
    /* the sections are validated for every model (a Rayleigh model keeps its
     * closed form: r.tabulated = 0 and the views stay unused) */
    if ((st = load_log_lr(t, &r)) != TRK_OK) return st;
    if ((st = load_inv(t, TRK_AMP_SECTION_INV_SF_CLUTTER, u_t, &r.inv[0])) != TRK_OK) return st;
    if ((st = load_inv(t, TRK_AMP_SECTION_INV_SF_TARGET, u_t, &r.inv[1])) != TRK_OK) return st;
    r.built = TRK_I_AMP_BUILT;
    *m = r;
    return TRK_OK;
}
