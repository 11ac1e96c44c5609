/* rng.h - counter-based random numbers for the tools (Random123 philox4x32).
 *
 * One generator for every Monte Carlo tool: a stream is keyed by (seed,
 * stream), e.g. stream = run index, and its n-th block depends only on
 * (seed, stream, n). Results therefore do not depend on the number of OpenMP
 * threads or their schedule, provided each run draws from its own stream.
 * Each stream holds 2^64 blocks of four 32-bit words.
 *
 *   struct rng r; rng_init(&r, seed, run);
 *   double u = rng_uniform(&r);      (0, 1), 53 random bits, never 0 or 1
 *   double e = rng_exp(&r);          Exp(1)
 *   double g = rng_normal(&r);       N(0, 1) (Box-Muller, no cached spare)
 *   unsigned long k = rng_poisson(&r, mean);
 */
#ifndef TRK_TOOLS_RNG_H
#define TRK_TOOLS_RNG_H

#include <stdint.h>

struct rng {
    uint32_t key[2];
    uint32_t ctr[4];  /* [stream lo, stream hi, block lo, block hi] */
    uint32_t out[4];  /* current block */
    int used;         /* words of out already consumed (4 = refill) */
};

void rng_init(struct rng *r, uint64_t seed, uint64_t stream);
uint32_t rng_u32(struct rng *r);
uint64_t rng_u64(struct rng *r);
double rng_uniform(struct rng *r);
double rng_exp(struct rng *r);
double rng_normal(struct rng *r);
unsigned long rng_poisson(struct rng *r, double mean);
/* 1 with probability p (p <= 0 never, p >= 1 always). */
int rng_bernoulli(struct rng *r, double p);

#endif
