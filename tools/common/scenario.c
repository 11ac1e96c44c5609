/* scenario.c - seeded sonar scenario (scenario.h). */
#include "scenario.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "trk/kalman.h"

void scen_defaults(struct scen_params *p)
{
    memset(p, 0, sizeof *p);
    p->seed = 1;
    p->sensor_id = 0;
    p->t0_us = 0;
    p->scan_period_s = 2;
    p->x_min_m = 0;
    p->x_max_m = 2000;
    p->y_min_m = 0;
    p->y_max_m = 2000;
    p->clutter_density_per_m2 = 5e-6;
    p->clutter_count = -1;
    p->pd = 0.9;
    p->meas_sigma_m = 3;
    p->attach_cov = 0;
    p->process_noise_q = 0.01;
    p->amp_kind = AMP_RAYLEIGH;
    p->pfa = 1e-3;
    p->k_shape = 1;
    p->snr_db = 15;
    p->n_targets = 3;
    p->targets = NULL;
    p->speed_min_mps = 1;
    p->speed_max_mps = 5;
}

void scen_free(struct scenario *s)
{
    free(s->tg);
    s->tg = NULL;
    s->n_tg = 0;
    amp_model_free(&s->amp);
}

int scen_init(struct scenario *s, const struct scen_params *p, char *err, size_t n)
{
    memset(s, 0, sizeof *s);
    if (!(p->scan_period_s > 0) || !isfinite(p->scan_period_s) || p->t0_us < 0) {
        snprintf(err, n, "scan period must be > 0 and t0 >= 0");
        return -1;
    }
    if (!(p->x_max_m > p->x_min_m) || !(p->y_max_m > p->y_min_m) || !isfinite(p->x_min_m) ||
        !isfinite(p->x_max_m) || !isfinite(p->y_min_m) || !isfinite(p->y_max_m)) {
        snprintf(err, n, "region must have x_min < x_max and y_min < y_max (finite)");
        return -1;
    }
    if (!(p->clutter_density_per_m2 >= 0) || !isfinite(p->clutter_density_per_m2)) {
        snprintf(err, n, "clutter density must be >= 0");
        return -1;
    }
    if (!(p->meas_sigma_m > 0) || !isfinite(p->meas_sigma_m) || !(p->process_noise_q >= 0) ||
        !isfinite(p->process_noise_q)) {
        snprintf(err, n, "measurement sigma must be > 0 and process noise q >= 0");
        return -1;
    }
    if (p->amp_kind == AMP_NONE && !(p->pd > 0 && p->pd <= 1)) {
        snprintf(err, n, "pd must be in (0, 1]");
        return -1;
    }
    if (!(p->speed_min_mps >= 0) || !(p->speed_max_mps >= p->speed_min_mps) ||
        !isfinite(p->speed_max_mps)) {
        snprintf(err, n, "speed range must be 0 <= min <= max");
        return -1;
    }
    if (p->n_targets > 100000) {
        snprintf(err, n, "too many targets");
        return -1;
    }
    if (p->amp_kind == AMP_TABLE) {
        if (!p->amp_table || amp_model_init_table(&s->amp, p->amp_table, err, n) != 0) {
            if (!p->amp_table) snprintf(err, n, "amplitude table: no file given");
            return -1;
        }
    } else if (amp_model_init(&s->amp, p->amp_kind, p->pfa, p->k_shape, err, n) != 0) {
        return -1;
    }
    s->p = *p;
    s->p.targets = NULL;
    s->p.amp_table = NULL;
    s->n_tg = p->n_targets;
    s->tg = calloc(s->n_tg ? s->n_tg : 1, sizeof *s->tg);
    if (!s->tg) {
        snprintf(err, n, "out of memory");
        amp_model_free(&s->amp);
        return -1;
    }
    rng_init(&s->motion, p->seed, 0);
    for (size_t i = 0; i < s->n_tg; i++) {
        struct scen_target *t = &s->tg[i];
        double snr = p->snr_db;
        if (p->targets) {
            const struct scen_target_init *ti = &p->targets[i];
            t->x[0] = ti->x_m;
            t->x[1] = ti->vx_mps;
            t->x[2] = ti->y_m;
            t->x[3] = ti->vy_mps;
            if (!isnan(ti->snr_db)) snr = ti->snr_db;
            for (int k = 0; k < 4; k++)
                if (!isfinite(t->x[k])) {
                    snprintf(err, n, "target %zu: non-finite state", i);
                    scen_free(s);
                    return -1;
                }
        } else {
            const double sp = p->speed_min_mps +
                              (p->speed_max_mps - p->speed_min_mps) * rng_uniform(&s->motion);
            const double hd = 6.283185307179586 * rng_uniform(&s->motion);
            t->x[0] = p->x_min_m + (p->x_max_m - p->x_min_m) * rng_uniform(&s->motion);
            t->x[2] = p->y_min_m + (p->y_max_m - p->y_min_m) * rng_uniform(&s->motion);
            t->x[1] = sp * sin(hd);
            t->x[3] = sp * cos(hd);
        }
        if (amp_target_init(&s->amp, snr, &t->amp) != 0) {
            snprintf(err, n, "target %zu: SNR %g dB not usable (must be in [-50, 80])", i, snr);
            scen_free(s);
            return -1;
        }
        t->pd = p->amp_kind == AMP_NONE ? p->pd : t->amp.pd;
    }
    /* Q per axis from the tracker's model: [[q T^3/3, q T^2/2], [q T^2/2, q T]] */
    trk_real q[16];
    trk_cv2_process_noise((trk_real)p->scan_period_s, (trk_real)p->process_noise_q, q);
    const double q00 = (double)q[0], q01 = (double)q[1], q11 = (double)q[5];
    if (q00 > 0) {
        s->q_chol[0] = sqrt(q00);
        s->q_chol[1] = q01 / s->q_chol[0];
        const double r = q11 - s->q_chol[1] * s->q_chol[1];
        s->q_chol[2] = r > 0 ? sqrt(r) : 0;
    }
    s->k = 0;
    return 0;
}

static void move_targets(struct scenario *s)
{
    const double dt = s->p.scan_period_s;
    for (size_t i = 0; i < s->n_tg; i++) {
        double *x = s->tg[i].x;
        for (int ax = 0; ax < 2; ax++) {
            double *pos = &x[2 * ax], *vel = &x[2 * ax + 1];
            const double z1 = rng_normal(&s->motion), z2 = rng_normal(&s->motion);
            *pos += dt * *vel + s->q_chol[0] * z1;
            *vel += s->q_chol[1] * z1 + s->q_chol[2] * z2;
        }
    }
}

static void fill(const struct scenario *s, struct trk_detection *d, double x, double y)
{
    const double var = s->p.meas_sigma_m * s->p.meas_sigma_m;
    memset(d, 0, sizeof *d);
    d->x_m = (trk_real)x;
    d->y_m = (trk_real)y;
    if (s->p.attach_cov) {
        d->has_cov = 1;
        d->cov_m2[0] = d->cov_m2[2] = (trk_real)var;
        d->cov_m2[1] = 0;
    }
}

void scen_next(struct scenario *s, struct trk_detection *det, size_t max_det, struct trk_scan *scan,
               size_t *n_target_dets, size_t *n_dropped)
{
    if (s->k > 0) move_targets(s);
    struct rng r;
    rng_init(&r, s->p.seed, 1 + s->k);
    size_t n = 0, dropped = 0, nt = 0;
    const double sg = s->p.meas_sigma_m;
    for (size_t i = 0; i < s->n_tg; i++) {
        const struct scen_target *t = &s->tg[i];
        if (!rng_bernoulli(&r, t->pd)) continue;
        const double x = t->x[0] + sg * rng_normal(&r), y = t->x[2] + sg * rng_normal(&r);
        double a = 0;
        int has_a = s->amp.kind != AMP_NONE;
        if (has_a && amp_draw(&s->amp, &t->amp, &r, &a) != 0) {
            s->n_amp_failures++;
            continue;
        }
        if (n == max_det) {
            dropped++;
            continue;
        }
        fill(s, &det[n], x, y);
        det[n].has_amplitude = (uint8_t)has_a;
        det[n].amplitude = (trk_real)a;
        n++;
        nt++;
    }
    const double area = (s->p.x_max_m - s->p.x_min_m) * (s->p.y_max_m - s->p.y_min_m);
    const unsigned long nc = s->p.clutter_count >= 0
                                 ? (unsigned long)s->p.clutter_count
                                 : rng_poisson(&r, s->p.clutter_density_per_m2 * area);
    for (unsigned long c = 0; c < nc; c++) {
        const double x = s->p.x_min_m + (s->p.x_max_m - s->p.x_min_m) * rng_uniform(&r);
        const double y = s->p.y_min_m + (s->p.y_max_m - s->p.y_min_m) * rng_uniform(&r);
        double a = 0;
        int has_a = s->amp.kind != AMP_NONE;
        if (has_a && amp_draw(&s->amp, NULL, &r, &a) != 0) {
            s->n_amp_failures++;
            continue;
        }
        if (n == max_det) {
            dropped++;
            continue;
        }
        fill(s, &det[n], x, y);
        det[n].has_amplitude = (uint8_t)has_a;
        det[n].amplitude = (trk_real)a;
        n++;
    }
    /* Fisher-Yates shuffle: no target-first order */
    for (size_t i = n; i > 1; i--) {
        const size_t j = (size_t)(rng_uniform(&r) * (double)i);
        const struct trk_detection tmp = det[i - 1];
        det[i - 1] = det[j < i ? j : i - 1];
        det[j < i ? j : i - 1] = tmp;
    }
    scan->time_us = s->p.t0_us + (int64_t)llround((double)s->k * s->p.scan_period_s * 1e6);
    scan->sensor_id = s->p.sensor_id;
    scan->n_detections = n;
    scan->detections = det;
    if (n_target_dets) *n_target_dets = nt;
    if (n_dropped) *n_dropped = dropped;
    s->k++;
}
