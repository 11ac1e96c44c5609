/* q2_amp.c - the q2 sampler's amplitude law on the library's amplitude
 * module (q2_amp.h). */
#include "errmsg.h"
#include "q2_amp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amp_table.h"
#include "q2_fastmath.h"
#include "trk/table.h"

int q2_amp_model_parse(const char *s)
{
    if (!s) return 0;
    if (strcmp(s, "rayleigh") == 0) return TRK_AMP_RAYLEIGH;
    if (strcmp(s, "k") == 0) return TRK_AMP_K;
    return 0;
}

const char *q2_amp_model_name(int model)
{
    return model == TRK_AMP_RAYLEIGH ? "rayleigh" : model == TRK_AMP_K ? "k" : "?";
}

int q2_amp_init(struct q2_amp *a, int model, double nu, double snr_db, double pfa, unsigned amp_size,
                int measure, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    if (!(snr_db >= -30 && snr_db <= 60)) {
        snprintf(err, errlen, "snr_db must be in [-30, 60] (got %g)", snr_db);
        return -1;
    }
    if (!(pfa > 0 && pfa < 1)) {
        snprintf(err, errlen, "pfa must be in (0, 1) (got %g)", pfa);
        return -1;
    }
    a->model = model;
    a->snr_db = snr_db;
    a->pfa = pfa;
    if (model == TRK_AMP_RAYLEIGH) {
        trk_status st = trk_amplitude_init_rayleigh(&a->m, 1, (trk_real)snr_db, (trk_real)pfa);
        if (st != TRK_OK) {
            snprintf(err, errlen, "Rayleigh model (snr_db %g, pfa %g): %s", snr_db, pfa, ERRMSG_STATUS(st));
            return -1;
        }
        a->pd = (double)trk_amplitude_pd(&a->m);
        a->threshold = (double)trk_amplitude_threshold(&a->m);
        return 0;
    }
    if (model != TRK_AMP_K) {
        snprintf(err, errlen, "amplitude model must be rayleigh or k");
        return -1;
    }
    if (!(nu > 0 && nu <= 1e6)) {
        snprintf(err, errlen, "K shape nu must be in (0, 1e6] (got %g)", nu);
        return -1;
    }
    struct amp_table_opts o;
    amp_table_opts_init(&o, TRK_AMP_K, nu, snr_db, pfa);
    o.grid = TRK_AMP_GRID_UNIFORM;
    o.size = o.llr_size = amp_size ? amp_size : Q2_AMP_TABLE_SIZE;
    o.measure = measure;
    struct amp_table_result r;
    if (amp_table_model(&o, &a->m, &r, err, errlen) != 0) return -1;
    a->table = r.bytes;
    a->table_len = r.len;
    a->nu = nu;
    a->pd = r.pd;
    a->threshold = r.threshold;
    a->measured = r.measured;
    a->err_log_lr = r.err_log_lr;
    a->err_inv_sf = r.err_inv_sf;
    return 0;
}

void q2_amp_free(struct q2_amp *a)
{
    free(a->table);
    a->table = NULL;
}

/* The packed form: the struct (its pointers and the library's model left
 * out: made again from the table), then the table's bytes. The ranks of a
 * job run the same program: the struct has the same layout on all. */
#define PACKED_HEAD ((sizeof(struct q2_amp) + 7) / 8 * 8)

size_t q2_amp_packed_size(size_t table_len) { return PACKED_HEAD + (table_len + 7) / 8 * 8; }

size_t q2_amp_table_len(const struct q2_amp *a) { return a->table ? a->table_len : 0; }

void q2_amp_pack(const struct q2_amp *a, void *buf)
{
    struct q2_amp h = *a;
    memset(&h.m, 0, sizeof h.m);
    h.table = NULL;
    h.table_len = q2_amp_table_len(a);
    memset(buf, 0, q2_amp_packed_size(h.table_len));
    memcpy(buf, &h, sizeof h);
    if (h.table_len) memcpy((unsigned char *)buf + PACKED_HEAD, a->table, h.table_len);
}

int q2_amp_unpack(struct q2_amp *a, const void *buf, size_t len, char *err, size_t errlen)
{
    memset(a, 0, sizeof *a);
    if (len < PACKED_HEAD) return snprintf(err, errlen, "amplitude model: %zu bytes, too few", len), -1;
    struct q2_amp h;
    memcpy(&h, buf, sizeof h);
    if (h.table_len > len - PACKED_HEAD) return snprintf(err, errlen, "amplitude model: its table is cut"), -1;
    trk_status st;
    if (h.model == TRK_AMP_RAYLEIGH) {
        h.table_len = 0;
        st = trk_amplitude_init_rayleigh(&h.m, 1, (trk_real)h.snr_db, (trk_real)h.pfa);
    } else if (!(h.table = malloc(h.table_len ? h.table_len : 1))) {
        return snprintf(err, errlen, "out of memory"), -1;
    } else {
        memcpy(h.table, (const unsigned char *)buf + PACKED_HEAD, h.table_len);
        struct trk_table t;
        st = trk_table_parse(&t, h.table, h.table_len);
        if (st == TRK_OK) st = trk_amplitude_init_table(&h.m, &t); /* views h.table, which *a keeps */
    }
    if (st != TRK_OK) {
        free(h.table);
        return snprintf(err, errlen, "amplitude model (snr_db %g, pfa %g) refused: %s", h.snr_db, h.pfa,
                        ERRMSG_STATUS(st)),
               -1;
    }
    *a = h;
    return 0;
}

/* x[i] = -ln u[i] (Exp(1) from the uniforms), vectorised. */
Q2_CLONES
static void neg_log(size_t n, const double *restrict u, double *restrict x)
{
    for (size_t i = 0; i < n; i++) x[i] = -q2_log(u[i]);
}

/* out[i] = ln l^a(a(x_i)), the amplitude drawn from the law of `source`:
 * the library's trk_amplitude_sample_log_lr (trk_amplitude_inv_sf composed
 * with trk_amplitude_log_lr) on the block. */
static int sample(const void *ctx, int target, size_t n, const double *u, double *out)
{
    const struct q2_amp *a = ctx;
    const int source = target ? TRK_AMP_TARGET : TRK_AMP_CLUTTER;
    neg_log(n, u, out);
#if TRK_REAL_IS_FLOAT
    trk_real buf[256];
    for (size_t i0 = 0; i0 < n; i0 += 256) {
        const size_t m = n - i0 < 256 ? n - i0 : 256;
        for (size_t i = 0; i < m; i++) buf[i] = (trk_real)out[i0 + i];
        if (trk_amplitude_sample_log_lr(&a->m, source, m, buf, buf) != TRK_OK) return -1;
        for (size_t i = 0; i < m; i++) out[i0 + i] = (double)buf[i];
    }
    return 0;
#else
    return trk_amplitude_sample_log_lr(&a->m, source, n, out, out) == TRK_OK ? 0 : -1;
#endif
}

struct q2_amp_sampler q2_amp_sampler_of(const struct q2_amp *a)
{
    struct q2_amp_sampler s = {q2_amp_model_name(a->model), sample, a, a->pd};
    return s;
}
