/* amplitude_db.c - Kennedy's amplitude likelihood ratio in dB
 * (trk/amplitude.h; Kennedy 2008 eqs 11, 27, 31). */
#include "trk/amplitude.h"

trk_status trk_amplitude_db_log_lr(const struct trk_amp_db_params *p, trk_real a_db, trk_real *log_lr)
{
    if (!p || !log_lr) return TRK_E_ARG;
    if (!isfinite(a_db) || !isfinite(p->a_min_db) || !isfinite(p->theta_db) || !isfinite(p->mu_db) ||
        !isfinite(p->s2_db2))
        return TRK_E_NAN;
    const trk_real span = p->theta_db - p->a_min_db; /* theta_A - a_min */
    if (!(span > 0) || !(p->s2_db2 > 0) || a_db < p->a_min_db) return TRK_E_RANGE;
    const trk_real e = a_db - p->mu_db;
    /* ln g_A = -(ln 2 pi + ln s^2)/2 - e^2/(2 s^2)     (eq 27/31, untruncated)
     * ln f_A = -ln(theta - a_min) - (a - a_min)/(theta - a_min)   (eq 11) */
    *log_lr = -TRK_REAL_C(0.5) * (TRK_LN_2PI + trk_log(p->s2_db2)) - e * e / (2 * p->s2_db2) +
              trk_log(span) + (a_db - p->a_min_db) / span;
    return TRK_OK;
}
