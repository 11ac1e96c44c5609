/* trk_test.h - shared helpers for the cmocka tests.
 *
 * cmocka 1.1.5 (Debian 12) has no assert_double_equal and its
 * assert_float_equal casts to float, so values are checked with
 * TRK_ASSERT_NEAR(got, want, abs, rel): |got - want| <= abs + rel |want|,
 * the rule of the reference vectors. NaN always fails. */
#ifndef TRK_TEST_H
#define TRK_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
/* cmocka.h needs the headers above first */
#include <cmocka.h>

#define TRK_ASSERT_NEAR(got, want, abs_tol, rel_tol)                                            \
    do {                                                                                       \
        double g_ = (double)(got), w_ = (double)(want);                                        \
        double lim_ = (double)(abs_tol) + (double)(rel_tol)*fabs(w_);                          \
        if (!(fabs(g_ - w_) <= lim_))                                                          \
            fail_msg("%s = %.17g, want %.17g (|diff| %.3g > %.3g)", #got, g_, w_, fabs(g_ - w_), \
                     lim_);                                                                    \
    } while (0)

#define TRK_ASSERT_OK(expr)                                                            \
    do {                                                                               \
        trk_status st_ = (expr);                                                       \
        if (st_ != TRK_OK) fail_msg("%s returned %s", #expr, trk_status_str(st_));     \
    } while (0)

#define TRK_ASSERT_STATUS(expr, want)                                                  \
    do {                                                                               \
        trk_status st_ = (expr);                                                       \
        if (st_ != (want))                                                             \
            fail_msg("%s returned %s, want %s", #expr, trk_status_str(st_),            \
                     trk_status_str(want));                                            \
    } while (0)

/* Tolerance scale of the build: tests state double tolerances and widen
 * them in the float build by TRK_TEST_FLOAT_REL (documented per test). */
#ifdef TRK_REAL_FLOAT
#define TRK_TEST_IS_FLOAT 1
#else
#define TRK_TEST_IS_FLOAT 0
#endif
#define TRK_TOL(dbl, flt) (TRK_TEST_IS_FLOAT ? (flt) : (dbl))

/* The tests' small deterministic generator (splitmix64): uniform in
 * [0, 1) and standard normal (Box-Muller), on a state the test owns. */
static inline double trk_test_urand(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}
static inline double trk_test_nrand(uint64_t *state)
{
    double u1 = trk_test_urand(state), u2 = trk_test_urand(state);
    if (u1 < 1e-300) u1 = 1e-300;
    return sqrt(-2 * log(u1)) * cos(6.283185307179586 * u2);
}

/* Every test program's main ends with
 *     return trk_run_tests("name", tests, setup, teardown);
 * which runs the group under cmocka. With TRK_TEST_CASE set in the
 * environment (`make check T=name CASE=pattern`), only the cases whose name
 * matches the pattern run (cmocka_set_test_filter: `*` and `?` wildcards);
 * the runner (tests/run_step.sh) fails the step when the pattern matches none. */
static inline void trk_test_filter_from_env(void)
{
    const char *pattern = getenv("TRK_TEST_CASE");
    if (pattern && *pattern) cmocka_set_test_filter(pattern);
}
#define trk_run_tests(group_name, group_tests, group_setup, group_teardown) \
    (trk_test_filter_from_env(), cmocka_run_group_tests_name(group_name, group_tests, group_setup, group_teardown))

#endif
