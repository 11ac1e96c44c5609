/* platform.c - trk-sonar-sim's polar sonar on a moving platform (platform.h). */
#include "platform.h"

#include <math.h>
#include <string.h>

#include "trk/kalman.h"

struct trk_pose polar_pose(const struct polar_platform *pf, uint64_t k, double period_s)
{
    const double t = (double)k * period_s;
    struct trk_pose p;
    p.x_m = (trk_real)(pf->x_m + pf->speed_mps * sin(pf->course_rad) * t);
    p.y_m = (trk_real)(pf->y_m + pf->speed_mps * cos(pf->course_rad) * t);
    p.heading_rad = (trk_real)pf->course_rad;
    return p;
}

/* An angle into (-pi, pi]. */
static double wrap_pi(double a)
{
    const double two_pi = 6.283185307179586;
    a = fmod(a, two_pi);
    if (a > 3.141592653589793) a -= two_pi;
    if (a <= -3.141592653589793) a += two_pi;
    return a;
}

/* Append a detection at range r, bearing b (relative) with an amplitude of
 * tg (NULL: clutter): 1, or 0 when the draw failed or out is full. */
static size_t add(struct scenario *sc, const struct amp_target *tg, struct rng *r, double range_m, double bearing_rad,
                  struct trk_polar_detection *out, size_t max, size_t *n, size_t *dropped)
{
    double a = 0;
    const int has_a = sc->amp.kind != AMP_NONE;
    if (has_a && amp_draw(&sc->amp, tg, r, &a) != 0) {
        sc->n_amp_failures++;
        return 0;
    }
    if (*n == max) {
        (*dropped)++;
        return 0;
    }
    struct trk_polar_detection *d = &out[(*n)++];
    memset(d, 0, sizeof *d);
    d->range_m = (trk_real)range_m;
    d->bearing_rad = (trk_real)bearing_rad;
    d->has_amplitude = (uint8_t)has_a;
    d->amplitude = (trk_real)a;
    return 1;
}

size_t polar_scan(struct scenario *sc, const struct trk_sensor_params *sp, const struct trk_pose *pose, uint64_t k,
                  struct trk_polar_detection *out, size_t max, size_t *n_target, size_t *n_dropped)
{
    struct rng r;
    rng_init(&r, sc->p.seed, POLAR_STREAM + k);
    size_t n = 0, nt = 0, dropped = 0;
    const double px = (double)pose->x_m, py = (double)pose->y_m, h = (double)pose->heading_rad;
    struct trk_sensor_params tsp = *sp; /* a target's P_D: its own where no profile says otherwise */
    tsp.use_amplitude = 0;
    for (size_t i = 0; i < sc->n_tg; i++) {
        const struct scen_target *t = &sc->tg[i];
        const double x = t->x[TRK_CV2_X], y = t->x[TRK_CV2_Y];
        tsp.pd = (trk_real)(t->high ? t->pd : sc->p.fluct_pd_low);
        const double pd = (double)trk_sensor_pd_at(&tsp, pose, (trk_real)x, (trk_real)y);
        if (!rng_bernoulli(&r, pd)) continue;
        if (t->end_scan > 0 && sc->k > (uint64_t)t->end_scan) continue; /* gone (sc->k: scans produced) */
        const double range = hypot(x - px, y - py) + (double)sp->sigma_range_m * rng_normal(&r);
        const double bearing = wrap_pi(atan2(x - px, y - py) - h + (double)sp->sigma_bearing_rad * rng_normal(&r));
        if (!(range > 0)) continue;
        /* with a P_D profile and Rayleigh amplitudes the target's SNR is the
         * one of its P_D there, 1 + SNR = ln pfa / ln P_D (what the library
         * reads a profile with a Rayleigh model as); else its own */
        const struct amp_target *ta = &t->amp;
        struct amp_target at_pd;
        if (sp->pd_profile.n > 0 && sc->amp.kind == AMP_RAYLEIGH && pd > sc->amp.pfa && pd < 1 &&
            amp_target_init(&sc->amp, 10 * log10(log(sc->amp.pfa) / log(pd) - 1), &at_pd) == 0)
            ta = &at_pd;
        nt += add(sc, ta, &r, range, bearing, out, max, &n, &dropped);
    }
    /* clutter over the scenario's region, where the sensor sees */
    struct trk_sensor_params cov = *sp;
    cov.use_amplitude = 0;
    cov.pd = 1;
    cov.pd_profile.n = 0;
    const struct scen_params *p = &sc->p;
    const double area = (p->x_max_m - p->x_min_m) * (p->y_max_m - p->y_min_m);
    const unsigned long nc =
        p->clutter_count >= 0 ? (unsigned long)p->clutter_count : rng_poisson(&r, p->clutter_density_per_m2 * area);
    for (unsigned long c = 0; c < nc; c++) {
        const double x = p->x_min_m + (p->x_max_m - p->x_min_m) * rng_uniform(&r);
        const double y = p->y_min_m + (p->y_max_m - p->y_min_m) * rng_uniform(&r);
        const double range = hypot(x - px, y - py);
        if (!(range > 0) || !(trk_sensor_pd_at(&cov, pose, (trk_real)x, (trk_real)y) > 0)) continue;
        add(sc, NULL, &r, range, wrap_pi(atan2(x - px, y - py) - h), out, max, &n, &dropped);
    }
    for (size_t i = n; i > 1; i--) { /* Fisher-Yates: no target-first order */
        const size_t j = (size_t)(rng_uniform(&r) * (double)i);
        const size_t jj = j < i ? j : i - 1;
        const struct trk_polar_detection tmp = out[i - 1];
        out[i - 1] = out[jj];
        out[jj] = tmp;
    }
    if (n_target) *n_target = nt;
    if (n_dropped) *n_dropped = dropped;
    return n;
}
