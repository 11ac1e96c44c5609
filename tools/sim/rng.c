/* rng.c - philox4x32 wrapper (rng.h). */
#include "rng.h"

#include <math.h>
#include <Random123/philox.h>

void rng_init(struct rng *r, uint64_t seed, uint64_t stream)
{
    r->key[0] = (uint32_t)seed;
    r->key[1] = (uint32_t)(seed >> 32);
    r->ctr[0] = (uint32_t)stream;
    r->ctr[1] = (uint32_t)(stream >> 32);
    r->ctr[2] = 0;
    r->ctr[3] = 0;
    r->used = 4;
}

static void refill(struct rng *r)
{
    philox4x32_ctr_t c = {{r->ctr[0], r->ctr[1], r->ctr[2], r->ctr[3]}};
    philox4x32_key_t k = {{r->key[0], r->key[1]}};
    philox4x32_ctr_t o = philox4x32(c, k);
    for (int i = 0; i < 4; i++) r->out[i] = o.v[i];
    if (++r->ctr[2] == 0) ++r->ctr[3];
    r->used = 0;
}

uint32_t rng_u32(struct rng *r)
{
    if (r->used >= 4) refill(r);
    return r->out[r->used++];
}

uint64_t rng_u64(struct rng *r)
{
    uint64_t hi = rng_u32(r);
    return hi << 32 | rng_u32(r);
}

double rng_uniform(struct rng *r)
{
    /* (k + 0.5) / 2^53, k uniform on 53 bits: open interval (0, 1) */
    return ((double)(rng_u64(r) >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double rng_exp(struct rng *r) { return -log(rng_uniform(r)); }

double rng_normal(struct rng *r)
{
    const double u1 = rng_uniform(r), u2 = rng_uniform(r);
    return sqrt(-2 * log(u1)) * cos(6.283185307179586476925 * u2);
}

int rng_bernoulli(struct rng *r, double p) { return rng_uniform(r) < p; }

unsigned long rng_poisson(struct rng *r, double mean)
{
    if (!(mean > 0)) return 0;
    if (mean < 12) { /* inversion by sequential search */
        double u = rng_uniform(r), p = exp(-mean), cdf = p;
        unsigned long k = 0;
        while (u > cdf && k < 1000) {
            k++;
            p *= mean / (double)k;
            cdf += p;
        }
        return k;
    }
    /* PTRS, transformed rejection with squeeze (Hormann 1993) */
    const double slam = sqrt(mean), loglam = log(mean);
    const double b = 0.931 + 2.53 * slam, a = -0.059 + 0.02483 * b;
    const double invalpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2);
    for (;;) {
        const double u = rng_uniform(r) - 0.5, v = rng_uniform(r);
        const double us = 0.5 - fabs(u);
        const double k = floor((2 * a / us + b) * u + mean + 0.43);
        if (us >= 0.07 && v <= vr) return (unsigned long)k;
        if (k < 0 || (us < 0.013 && v > us)) continue;
        if (log(v) + log(invalpha) - log(a / (us * us) + b) <= -mean + k * loglam - lgamma(k + 1))
            return (unsigned long)k;
    }
}
