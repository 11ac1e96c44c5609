/* amplitude.c - amplitude likelihood ratio and inverse-CDF sampling
 * (trk/amplitude.h): Rayleigh closed forms and table lookup. */
#include "trk/amplitude.h"

#include "internal.h"

trk_status trk_amplitude_init_rayleigh(struct trk_amplitude *m, trk_real clutter_power, trk_real snr_db,
                                       trk_real pfa)
{
    if (!m) return TRK_E_ARG;
    if (!isfinite(clutter_power) || !isfinite(snr_db) || !isfinite(pfa)) return TRK_E_NAN;
    if (!(clutter_power > 0) || !(pfa > 0 && pfa < 1)) return TRK_E_RANGE;
    if (!(snr_db >= -100 && snr_db <= 100)) return TRK_E_RANGE;
    struct trk_amplitude r = {0};
    r.model = TRK_AMP_RAYLEIGH;
    r.tabulated = 0;
    r.clutter_power = clutter_power;
    r.snr_db = snr_db;
    r.pfa = pfa;
    r.nu = 0;
    r.snr = trk_pow(10, snr_db / 10);
    const trk_real ln_pfa = trk_log(pfa), one_d = 1 + r.snr;
    /* S0(t) = exp(-t^2/P) = pfa (Brekke eq 6 with E[a^2] = P) */
    r.t2 = -clutter_power * ln_pfa;
    r.threshold = trk_sqrt(r.t2);
    /* P_D = S1(t) = exp(-t^2/(P+d)) = pfa^(1/(1+SNR)) (eq 8) */
    r.pd = trk_exp(ln_pfa / one_d);
    /* ln l^a = ln(pfa/P_D) + ln(P/(P+d)) + a^2 d/(P(P+d))  (eq 19) */
    r.lr0 = ln_pfa * (r.snr / one_d) - trk_log1p(r.snr);
    r.lr1 = r.snr / (one_d * clutter_power);
    r.sqrt_p = trk_sqrt(clutter_power);
    r.ln_sqrt_p = TRK_REAL_C(0.5) * trk_log(clutter_power);
    if (!isfinite(r.lr0) || !isfinite(r.lr1) || !(r.threshold > 0) || !(r.pd > 0)) return TRK_E_RANGE;
    r.built = TRK_I_AMP_BUILT;
    *m = r;
    return TRK_OK;
}

trk_status trk_amplitude_check(const struct trk_amplitude *m)
{
    if (!m || m->built != TRK_I_AMP_BUILT) return TRK_E_ARG;
    if (m->model != TRK_AMP_RAYLEIGH && m->model != TRK_AMP_K) return TRK_E_ARG;
    if (!(m->threshold > 0 && m->t2 <= TRK_REAL_MAX) || !(m->pd > 0 && m->pd <= 1)) return TRK_E_ARG;
    if (m->tabulated && (!m->llr || m->llr_n < 2)) return TRK_E_ARG;
    return TRK_OK;
}

trk_real trk_amplitude_threshold(const struct trk_amplitude *m)
{
    return m ? m->threshold : (trk_real)NAN;
}

trk_real trk_amplitude_pd(const struct trk_amplitude *m) { return m ? m->pd : (trk_real)NAN; }

/* ln l^a beyond the last node: relaxation to the limit (see the header). */
static trk_real log_lr_tail(const struct trk_amplitude *m, trk_real s)
{
    const trk_real *last = m->llr + 2 * (size_t)(m->llr_n - 1);
    if (!(m->llr_tail_rate > 0)) return last[0];
    return m->llr_limit - (m->llr_limit - last[0]) * trk_exp(-m->llr_tail_rate * (s - m->llr_hi));
}

/* Tabulated ln l^a at s = ln(a/sqrt P): cubic Hermite on a uniform grid in s,
 * the tail relaxation beyond it. */
static trk_real table_log_lr(const struct trk_amplitude *m, trk_real s)
{
    const trk_real u = (s - m->llr_lo) * m->llr_inv_h;
    const trk_real last = (trk_real)(m->llr_n - 1);
    if (u > last) return log_lr_tail(m, s);
    uint32_t i = 0;
    if (u > 0) i = (uint32_t)u;
    if (i > m->llr_n - 2) i = m->llr_n - 2;
    const trk_real f = u - (trk_real)i;
    const trk_real *c = m->llr + 2 * (size_t)i;
    return trk_table_hermite(c[0], c[2], c[1], c[3], m->llr_h, f);
}

trk_status trk_amplitude_log_lr(const struct trk_amplitude *m, trk_real a, trk_real *log_lr)
{
    if (!m || !log_lr) return TRK_E_ARG;
    if (!isfinite(a)) return TRK_E_NAN;
    if (!(a >= 0) || a < m->threshold) return TRK_E_RANGE;
    if (!m->tabulated) {
        const trk_real v = m->lr0 + m->lr1 * (a * a);
        if (!isfinite(v)) return TRK_E_RANGE; /* a^2 overflows the real type */
        *log_lr = v;
        return TRK_OK;
    }
    *log_lr = table_log_lr(m, trk_log(a) - m->ln_sqrt_p);
    return TRK_OK;
}

trk_status trk_i_amplitude_log_lr_inv_u(const struct trk_amplitude *m, trk_real inv_u, trk_real ln_inv_u, trk_real a,
                                        trk_real *log_lr)
{
    if (!isfinite(a)) return TRK_E_NAN;
    if (!(a >= 0) || a < m->threshold) return TRK_E_RANGE;
    const trk_real v = (1 - inv_u) * ((a * a - m->t2) / m->clutter_power) + ln_inv_u; /* eq 19 */
    if (!isfinite(v)) return TRK_E_RANGE; /* a^2 overflows the real type */
    *log_lr = v;
    return TRK_OK;
}

trk_status trk_amplitude_log_lr_at_pd(const struct trk_amplitude *m, trk_real pd, trk_real a, trk_real *log_lr)
{
    if (!m || !log_lr) return TRK_E_ARG;
    if (m->tabulated || m->model != TRK_AMP_RAYLEIGH) return TRK_E_UNSUPPORTED;
    if (!isfinite(a) || !isfinite(pd)) return TRK_E_NAN;
    if (!(pd > m->pfa && pd < 1)) return TRK_E_RANGE;
    const trk_real inv_u = trk_i_amplitude_inv_u(m, pd);
    return trk_i_amplitude_log_lr_inv_u(m, inv_u, trk_log(inv_u), a, log_lr);
}

trk_real trk_i_amplitude_inv_u(const struct trk_amplitude *m, trk_real p)
{
    return trk_log(p) * (-m->clutter_power / m->t2); /* 1/u = ln p / ln pfa (eq 8), ln pfa = -t^2/P (eq 6) */
}

/* Normalised u^2 = a^2/P of a tabulated inverse-survival curve at x >= 0. */
static trk_real inv_curve_u2(const struct trk_amp_inv_curve *cv, trk_real x)
{
    const uint32_t n = cv->axis.count;
    if (cv->axis.spacing == TRK_TABLE_SPACING_LINEAR) { /* uniform: Hermite of u^2 */
        const trk_real u = x * cv->inv_h, last = (trk_real)(n - 1);
        if (u >= last) { /* tangent line beyond x_max */
            const trk_real *e = cv->data + 2 * (size_t)(n - 1);
            return e[0] + e[1] * (x - cv->axis.hi);
        }
        uint32_t i = (uint32_t)u;
        if (i > n - 2) i = n - 2;
        const trk_real *c = cv->data + 2 * (size_t)i;
        return trk_table_hermite(c[0], c[2], c[1], c[3], cv->h, u - (trk_real)i);
    }
    /* geometric grid: explicit x nodes, piecewise linear in u (Brekke's scheme) */
    uint32_t i = 0;
    trk_real f = 0;
    if (trk_table_axis_locate(&cv->axis, x, &i, &f) != TRK_OK) return (trk_real)NAN;
    const trk_real ua = cv->data[i] + f * (cv->data[i + 1] - cv->data[i]);
    return ua * ua;
}

trk_status trk_amplitude_inv_sf(const struct trk_amplitude *m, int source, trk_real x, trk_real *a)
{
    if (!m || !a || (source != TRK_AMP_CLUTTER && source != TRK_AMP_TARGET)) return TRK_E_ARG;
    if (!isfinite(x)) return TRK_E_NAN;
    if (!(x >= 0)) return TRK_E_RANGE;
    trk_real a2;
    if (!m->tabulated) {
        /* S^a(a) = exp(-(a^2 - t^2)/Q), Q = P or P + d (eqs 46-47 for Rayleigh) */
        const trk_real q = source == TRK_AMP_TARGET ? m->clutter_power * (1 + m->snr) : m->clutter_power;
        a2 = m->t2 + q * x;
    } else {
        a2 = inv_curve_u2(&m->inv[source], x) * m->clutter_power;
    }
    if (!isfinite(a2)) return TRK_E_RANGE;
    const trk_real v = trk_sqrt(a2);
    *a = v > m->threshold ? v : m->threshold; /* x = 0 gives t; rounding never below it */
    return TRK_OK;
}

trk_status trk_amplitude_log_sf(const struct trk_amplitude *m, int source, trk_real a, trk_real *x)
{
    if (!m || !x || (source != TRK_AMP_CLUTTER && source != TRK_AMP_TARGET)) return TRK_E_ARG;
    if (!isfinite(a)) return TRK_E_NAN;
    if (!(a >= m->threshold)) return TRK_E_RANGE;
    if (!m->tabulated) { /* a^2 = t^2 + Q x (trk_amplitude_inv_sf) */
        const trk_real q = source == TRK_AMP_TARGET ? m->clutter_power * (1 + m->snr) : m->clutter_power;
        const trk_real v = (a * a - m->t2) / q;
        if (!isfinite(v)) return TRK_E_RANGE;
        *x = v > 0 ? v : 0;
        return TRK_OK;
    }
    /* a(x) increases: bracket [lo, hi] with a(lo) <= a < a(hi), then halve it */
    trk_real lo = 0, hi = 1, ah;
    int k = 0;
    for (; k < 64; k++, lo = hi, hi *= 2)
        if (trk_amplitude_inv_sf(m, source, hi, &ah) != TRK_OK || ah > a) break;
    if (k == 64) return TRK_E_RANGE;
    for (k = 0; k < 64; k++) {
        const trk_real mid = lo + (hi - lo) / 2;
        if (!(mid > lo && mid < hi)) break;
        if (trk_amplitude_inv_sf(m, source, mid, &ah) == TRK_OK && ah <= a) lo = mid;
        else hi = mid;
    }
    *x = lo;
    return TRK_OK;
}

#define SAMPLE_BLOCK 32 /* reals on the stack: 256 bytes in double */

trk_status trk_amplitude_sample_log_lr(const struct trk_amplitude *m, int source, size_t n, const trk_real *x,
                                       trk_real *log_lr)
{
    if (!m || (source != TRK_AMP_CLUTTER && source != TRK_AMP_TARGET)) return TRK_E_ARG;
    if (n > 0 && (!x || !log_lr)) return TRK_E_ARG;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(x[i])) return TRK_E_NAN;
        if (!(x[i] >= 0)) return TRK_E_RANGE;
    }
    if (!m->tabulated) {
        /* ln l^a = lr0 + lr1 a^2 with a^2 = t^2 + Q x (Q = P or P + d): affine in x */
        const trk_real q = source == TRK_AMP_TARGET ? m->clutter_power * (1 + m->snr) : m->clutter_power;
        const trk_real c0 = m->lr0 + m->lr1 * m->t2, c1 = m->lr1 * q;
        for (size_t i = 0; i < n; i++) log_lr[i] = c0 + c1 * x[i];
    } else {
        /* s = ln(a/sqrt P) = ln(u^2)/2, u^2 from the a(x) table (no square
         * root); in blocks of three short passes (table, log, table), which
         * overlap far better in the CPU than one long dependent chain */
        const struct trk_amp_inv_curve *cv = &m->inv[source];
        const trk_real ut2 = m->t2 / m->clutter_power;
        trk_real sb[SAMPLE_BLOCK];
        for (size_t i0 = 0; i0 < n; i0 += SAMPLE_BLOCK) {
            const size_t nb = n - i0 < SAMPLE_BLOCK ? n - i0 : SAMPLE_BLOCK;
            for (size_t i = 0; i < nb; i++) {
                const trk_real u2 = inv_curve_u2(cv, x[i0 + i]);
                sb[i] = u2 < ut2 ? ut2 : u2; /* as trk_amplitude_inv_sf: never below the threshold */
            }
            for (size_t i = 0; i < nb; i++) sb[i] = TRK_REAL_C(0.5) * trk_log(sb[i]);
            for (size_t i = 0; i < nb; i++) log_lr[i0 + i] = table_log_lr(m, sb[i]);
        }
    }
    for (size_t i = 0; i < n; i++)
        if (!isfinite(log_lr[i])) return TRK_E_RANGE;
    return TRK_OK;
}
