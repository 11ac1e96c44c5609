/* q2_fastmath.h - exp and log for the q2 sampler's inner loops: branch-free,
 * vectorisable (no libm call), deterministic (the same bits from the scalar
 * and the vector code: plain IEEE operations, compile with
 * -ffp-contract=off), accurate to ~2 ulp (measured in tests/test_q2.c).
 *
 *   q2_exp(x)  x <= 709; x < -708 gives 0 (true value < 2.2e-308, subnormal)
 *   q2_log(x)  x > 0, normal and finite (the sampler's uniforms are >= 2^-33)
 *
 * exp: k = round(x / ln 2) by the 1.5 * 2^52 shift, r = x - k ln 2 in two
 * parts (fdlibm's ln2_hi has 21 trailing zero bits, so k ln2_hi is exact),
 * e^r by its Taylor polynomial of degree 13 (|r| <= 0.347: remainder
 * < 3e-18), times 2^k built in the exponent field.
 * log: x = 2^e m with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(f),
 * f = (m - 1)/(m + 1) (|f| <= 0.1716), series to f^23 (remainder < 1e-18).
 */
#ifndef TRK_Q2_FASTMATH_H
#define TRK_Q2_FASTMATH_H

#include <stdint.h>
#include <string.h>

/* Vectorisable kernels are built for AVX-512, AVX2 and the baseline ISA,
 * chosen at load time; all give the same bits (IEEE operations only, no
 * contraction: -ffp-contract=off, explicit lane sums). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(Q2_IS_NO_CLONES)
#define Q2_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#elif defined(__x86_64__) && defined(__clang__) && !defined(Q2_IS_NO_CLONES)
#define Q2_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define Q2_CLONES
#endif

static inline double q2_exp(double x)
{
    const double shift = 6755399441055744.0; /* 1.5 * 2^52 */
    const double log2e = 1.44269504088896338700e+00;
    const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
    double xc = x < -708.0 ? -708.0 : x;
    double kd = xc * log2e + shift;
    uint64_t ki;
    memcpy(&ki, &kd, sizeof ki);
    kd -= shift;
    double r = (xc - kd * ln2_hi) - kd * ln2_lo;
    double p = 1.0 / 6227020800.0; /* 1/13! */
    p = p * r + 1.0 / 479001600.0;
    p = p * r + 1.0 / 39916800.0;
    p = p * r + 1.0 / 3628800.0;
    p = p * r + 1.0 / 362880.0;
    p = p * r + 1.0 / 40320.0;
    p = p * r + 1.0 / 5040.0;
    p = p * r + 1.0 / 720.0;
    p = p * r + 1.0 / 120.0;
    p = p * r + 1.0 / 24.0;
    p = p * r + 1.0 / 6.0;
    p = p * r + 0.5;
    p = p * r + 1.0;
    p = p * r + 1.0;
    uint64_t eb = (ki + 1023u) << 52;
    double s;
    memcpy(&s, &eb, sizeof s);
    double y = p * s;
    return x < -708.0 ? 0.0 : y;
}

static inline double q2_log(double x)
{
    const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
    const double sqrt2 = 1.41421356237309504880;
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    int32_t e = (int32_t)(uint32_t)(b >> 52) - 1023;
    uint64_t mb = (b & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
    double m;
    memcpy(&m, &mb, sizeof m);
    int big = m > sqrt2;
    m = big ? 0.5 * m : m;
    e += big;
    double f = (m - 1.0) / (m + 1.0), s = f * f;
    double p = 1.0 / 23;
    p = p * s + 1.0 / 21;
    p = p * s + 1.0 / 19;
    p = p * s + 1.0 / 17;
    p = p * s + 1.0 / 15;
    p = p * s + 1.0 / 13;
    p = p * s + 1.0 / 11;
    p = p * s + 1.0 / 9;
    p = p * s + 1.0 / 7;
    p = p * s + 1.0 / 5;
    p = p * s + 1.0 / 3;
    double ed = (double)e;
    /* ln m = 2 f (1 + s/3 + ...) = 2f + 2f s p */
    return ed * ln2_hi + (ed * ln2_lo + (2.0 * f * s * p + 2.0 * f));
}

#endif
