/* amp_sample.c - amplitudes of thresholded detections (amp_sample.h). */
#include "amp_sample.h"
#include "errmsg.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "trk/table_file.h"

int amp_kind_parse(const char *s)
{
    if (strcmp(s, "none") == 0) return AMP_NONE;
    if (strcmp(s, "rayleigh") == 0) return AMP_RAYLEIGH;
    if (strcmp(s, "k") == 0) return AMP_K;
    return -1;
}

const char *amp_kind_name(int kind)
{
    switch (kind) {
    case AMP_NONE: return "none";
    case AMP_RAYLEIGH: return "rayleigh";
    case AMP_K: return "k";
    case AMP_TABLE: return "table";
    default: return "?";
    }
}

int amp_model_init(struct amp_model *m, int kind, double pfa, double nu, char *err, size_t n)
{
    memset(m, 0, sizeof *m);
    m->kind = kind;
    m->pfa = pfa;
    m->nu = nu;
    switch (kind) {
    case AMP_NONE: return 0;
    case AMP_RAYLEIGH:
        if (!(pfa > 0 && pfa < 1)) break;
        if (trk_amplitude_init_rayleigh(&m->lib, 1, 0, (trk_real)pfa) != TRK_OK) break;
        m->t = (double)trk_amplitude_threshold(&m->lib);
        return 0;
    case AMP_K:
        if (!(pfa > 0 && pfa < 1)) break;
        if (kdist_init(&m->k0, nu, 0) != 0) {
            snprintf(err, n, "K shape %g: must be in (0, 1e6]", nu);
            return -1;
        }
        if (kdist_threshold(&m->k0, pfa, &m->t) != 0) {
            snprintf(err, n, "K threshold for pfa %g (shape %g) did not converge", pfa, nu);
            return -1;
        }
        return 0;
    default: snprintf(err, n, "unknown amplitude model %d", kind); return -1;
    }
    snprintf(err, n, "pfa %g: must be in (0, 1)", pfa);
    return -1;
}

int amp_model_init_table(struct amp_model *m, const char *path, char *err, size_t n)
{
    memset(m, 0, sizeof *m);
    size_t len;
    if (trk_table_file_size(path, &len) != TRK_OK || len == 0) {
        snprintf(err, n, "%s: cannot read", path);
        return -1;
    }
    m->table_bytes = malloc(len); /* aligned for double, as the table needs */
    if (!m->table_bytes) {
        snprintf(err, n, "out of memory");
        return -1;
    }
    struct trk_table t;
    trk_status st = trk_table_load_file(path, m->table_bytes, len, &t, NULL);
    if (st == TRK_OK) st = trk_amplitude_init_table(&m->lib, &t);
    if (st != TRK_OK) {
        snprintf(err, n, "%s: not a usable amplitude table: %s", path, ERRMSG_STATUS(st));
        amp_model_free(m);
        return -1;
    }
    m->kind = AMP_TABLE;
    m->pfa = (double)m->lib.pfa;
    m->nu = (double)m->lib.nu;
    m->t = (double)trk_amplitude_threshold(&m->lib);
    return 0;
}

void amp_model_free(struct amp_model *m)
{
    free(m->table_bytes);
    m->table_bytes = NULL;
}

int amp_target_init(const struct amp_model *m, double snr_db, struct amp_target *tg)
{
    memset(tg, 0, sizeof *tg);
    if (!isfinite(snr_db) || snr_db < -50 || snr_db > 80) return -1;
    tg->snr_db = snr_db;
    tg->d = pow(10.0, snr_db / 10);
    switch (m->kind) {
    case AMP_NONE: tg->pd = NAN; return 0;
    case AMP_RAYLEIGH:
        if (trk_amplitude_init_rayleigh(&tg->lib, 1, (trk_real)snr_db, (trk_real)m->pfa) != TRK_OK)
            return -1;
        tg->pd = (double)trk_amplitude_pd(&tg->lib);
        return 0;
    case AMP_TABLE:
        tg->snr_db = (double)m->lib.snr_db;
        tg->d = pow(10.0, tg->snr_db / 10);
        tg->pd = (double)trk_amplitude_pd(&m->lib);
        return 0;
    case AMP_K:
        if (kdist_init(&tg->k1, m->nu, snr_db) != 0) return -1;
        tg->pd = exp(kdist_log_sf(&tg->k1, 1, m->t));
        return isfinite(tg->pd) ? 0 : -1;
    default: return -1;
    }
}

int amp_draw(const struct amp_model *m, const struct amp_target *tg, struct rng *r, double *a)
{
    const double x = rng_exp(r); /* -ln of the truncated survival, Exp(1) */
    switch (m->kind) {
    case AMP_RAYLEIGH: {
        trk_real v;
        if (trk_amplitude_inv_sf(tg ? &tg->lib : &m->lib, tg ? TRK_AMP_TARGET : TRK_AMP_CLUTTER,
                                 (trk_real)x, &v) != TRK_OK)
            return -1;
        *a = (double)v;
        return 0;
    }
    case AMP_TABLE: {
        trk_real v;
        if (trk_amplitude_inv_sf(&m->lib, tg ? TRK_AMP_TARGET : TRK_AMP_CLUTTER, (trk_real)x, &v) !=
            TRK_OK)
            return -1;
        *a = (double)v;
        return 0;
    }
    case AMP_K: {
        double v;
        if (kdist_inv_sf(tg ? &tg->k1 : &m->k0, tg != NULL, m->t, x, &v, NULL) != 0 || !isfinite(v))
            return -1;
        *a = v;
        return 0;
    }
    default: return -1;
    }
}
