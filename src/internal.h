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

/* trk_amplitude.built of a model made by its init functions (amplitude.h). */
#define TRK_I_AMP_BUILT 0x616d706cu /* "ampl" */

struct trk_amplitude;
/* 1/u = ln p / ln pfa of a Swerling I target that a closed-form Rayleigh
 * model m detects at probability p (Brekke eq 8: u = 1 + SNR; ln pfa =
 * -t^2/P, eq 6): the one form behind trk_amplitude_log_lr_at_pd, the
 * tracker's persistent returns and its echoes weighed against theirs. m
 * and p are not checked: p in (pfa, 1) gives 1/u in (0, 1). */
trk_real trk_i_amplitude_inv_u(const struct trk_amplitude *m, trk_real p);
/* The Rayleigh ln l^a of a target with 1 + SNR = u (Brekke eq 19), from
 * inv_u = 1/u = ln P_D / ln pfa and its log: (1 - inv_u)(a^2 - t^2)/P +
 * ln inv_u. The one closed form behind trk_amplitude_log_lr_at_pd, for a
 * caller that holds 1/u (the tracker's persistent returns: per scan). m is
 * a closed-form Rayleigh model (not checked). TRK_E_NAN a not finite,
 * TRK_E_RANGE a < 0, below the threshold, or ln l^a beyond the real type. */
trk_status trk_i_amplitude_log_lr_inv_u(const struct trk_amplitude *m, trk_real inv_u, trk_real ln_inv_u, trk_real a,
                                        trk_real *log_lr);

/* Small kernels in *_impl.h are forced inline unless TRK_SIZE_OPT (config.h:
 * default 1 under -Os) leaves the inlining decision to the compiler. */
#if (defined(__GNUC__) || defined(__clang__)) && !TRK_SIZE_OPT
#define TRK_INLINE static inline __attribute__((always_inline))
#else
#define TRK_INLINE static inline
#endif

/* A stage kept out of its caller, so that the caller's stack frame does not
 * carry the stage's locals on the paths through its other stages (the
 * firmware stack budget of trk_tracker_process_scan, mk/size.mk). */
#if defined(__GNUC__) || defined(__clang__)
#define TRK_NOINLINE __attribute__((noinline))
#else
#define TRK_NOINLINE
#endif

#endif
