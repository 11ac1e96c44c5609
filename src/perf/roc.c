/* roc.c - a tabulated receiver operating characteristic, pd(pfa)
 * interpolated linearly in (ln pfa, ln pd): the ROC input of the TOC
 * (trk/toc.h). Declared with the q2 interfaces in trk/q2.h. */
#include "trk/q2.h"

#include <math.h>

#include "internal.h"

trk_status trk_roc_table_eval(const void *ctx, trk_real pfa, trk_real *pd)
{
    const struct trk_roc_table *t = ctx;
    if (!t || !t->pfa || !t->pd || !pd || t->n < 2) return TRK_E_ARG;
    if (!isfinite(pfa)) return TRK_E_NAN;
    const size_t n = t->n;
    if (!(pfa >= t->pfa[0] && pfa <= t->pfa[n - 1])) return TRK_E_RANGE;
    size_t l = 0, r = n - 1;
    while (r - l > 1) {
        size_t m = l + (r - l) / 2;
        if (t->pfa[m] <= pfa) l = m;
        else r = m;
    }
    const trk_real f0 = t->pfa[l], f1 = t->pfa[l + 1], d0 = t->pd[l], d1 = t->pd[l + 1];
    if (!(f0 > 0 && f1 > f0 && f1 < 1 && d0 > 0 && d0 <= 1 && d1 > 0 && d1 <= 1))
        return TRK_E_TABLE_CORRUPT;
    /* ln pd linear in ln pfa */
    trk_real s = (trk_log(pfa) - trk_log(f0)) / (trk_log(f1) - trk_log(f0));
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    trk_real lpd = (1 - s) * trk_log(d0) + s * trk_log(d1);
    *pd = trk_exp(lpd);
    return TRK_OK;
}
