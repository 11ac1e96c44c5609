/* internal.h (private) - helpers shared by the library's source files. */
#ifndef TRK_INTERNAL_H
#define TRK_INTERNAL_H

#include "trk/types.h"

/* A call whose status cannot be an error here because its arguments were
 * validated earlier (e.g. parameters checked at init). SQLite's NEVER(): the
 * status is evaluated and dropped; no abort in firmware. */
#define TRK_CHECKED(call)                 \
    do {                                  \
        trk_status trk_checked_ = (call); \
        (void)trk_checked_;               \
    } while (0)

/* Small kernels in *_impl.h are forced inline so that a caller passing
 * constant dimensions (the 2-D CV model) gets fully unrolled code.
 * TRK_SIZE_OPT=1 (default when the compiler optimises for size, -Os) leaves
 * the inlining decision to the compiler instead: the firmware build then keeps
 * one copy of each kernel per file rather than one per call site (see
 * mk/size.mk: make size-report, make cross-sizeopt). Host builds (-O2) keep
 * the forced inlining that the benchmarks were measured with. */
#ifndef TRK_SIZE_OPT
#ifdef __OPTIMIZE_SIZE__
#define TRK_SIZE_OPT 1
#else
#define TRK_SIZE_OPT 0
#endif
#endif
#if (defined(__GNUC__) || defined(__clang__)) && !TRK_SIZE_OPT
#define TRK_INLINE static inline __attribute__((always_inline))
#else
#define TRK_INLINE static inline
#endif

#endif
