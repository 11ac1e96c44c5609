/* trk/types.h - the scalar type, its math functions, and status codes.
 *
 * trk_real is double by default; compile everything (library and user code)
 * with -DTRK_REAL_FLOAT for single precision (Cortex-M4F and other FPUs without
 * double support). The float build uses the float libm functions (sqrtf, ...)
 * so no soft-double code is pulled in.
 */
#ifndef TRK_TYPES_H
#define TRK_TYPES_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "trk/config.h"

#ifdef TRK_REAL_FLOAT
typedef float trk_real;
#define TRK_REAL_C(x) x##f
#define TRK_REAL_EPS 1.1920929e-07f
#define TRK_REAL_MAX 3.40282347e+38f
#define TRK_REAL_IS_FLOAT 1
#define trk_sqrt sqrtf
#define trk_exp expf
#define trk_log logf
#define trk_log1p log1pf
#define trk_log10 log10f
#define trk_expm1 expm1f
#define trk_fabs fabsf
#define trk_pow powf
#define trk_floor floorf
#define trk_sin sinf
#define trk_cos cosf
#define trk_atan2 atan2f
#define trk_erfc erfcf
#define trk_lgamma lgammaf
#else
typedef double trk_real;
#define TRK_REAL_C(x) x
#define TRK_REAL_EPS 2.2204460492503131e-16
#define TRK_REAL_MAX 1.7976931348623157e+308
#define TRK_REAL_IS_FLOAT 0
#define trk_sqrt sqrt
#define trk_exp exp
#define trk_log log
#define trk_log1p log1p
#define trk_log10 log10
#define trk_expm1 expm1
#define trk_fabs fabs
#define trk_pow pow
#define trk_floor floor
#define trk_sin sin
#define trk_cos cos
#define trk_atan2 atan2
#define trk_erfc erfc
#define trk_lgamma lgamma
#endif

#define TRK_PI TRK_REAL_C(3.14159265358979323846)
#define TRK_LN_2PI TRK_REAL_C(1.83787706640934548356)

/* Warn when a caller drops a status (libsodium habit). */
#if defined(__GNUC__) || defined(__clang__)
#define TRK_NODISCARD __attribute__((warn_unused_result))
#else
#define TRK_NODISCARD
#endif

/* Status of every fallible call. TRK_OK is 0; everything else is a refusal
 * that left the caller's objects as they were (unless a function says
 * otherwise). trk_status_str() names each one. */
typedef enum trk_status {
    TRK_OK = 0,
    TRK_E_ARG,             /* NULL pointer, bad dimension or enum value */
    TRK_E_NAN,             /* a NaN or infinite input */
    TRK_E_RANGE,           /* a value outside its documented range */
    TRK_E_CAPACITY,        /* more items than the compile-time capacity */
    TRK_E_NOT_SPD,         /* a covariance is not symmetric positive definite */
    TRK_E_SINGULAR,        /* a matrix cannot be inverted */
    TRK_E_TIME,            /* scan time goes backwards */
    TRK_E_SENSOR,          /* unknown sensor id */
    TRK_E_TABLE_TRUNCATED, /* table shorter than its header says */
    TRK_E_TABLE_MAGIC,     /* not a trk table */
    TRK_E_TABLE_VERSION,   /* table format version not supported */
    TRK_E_TABLE_REAL,      /* table real width differs from this build */
    TRK_E_TABLE_CRC,       /* CRC-32 mismatch */
    TRK_E_TABLE_KIND,      /* table of another kind or dimension than asked for */
    TRK_E_TABLE_CORRUPT,   /* inconsistent header, non-finite or non-monotone data */
    TRK_E_DIVERGED,        /* an iteration did not converge */
    TRK_E_UNSUPPORTED,     /* a feature not built into this configuration */
    TRK_E_IO,              /* host helpers only: file could not be read/written */
    TRK_STATUS_COUNT
} trk_status;

/* Short constant name of a status ("TRK_E_NAN"); never NULL. */
const char *trk_status_str(trk_status s);

/* Compile-time capacities as the library was built (libsodium habit: a tool
 * can check at start-up that the library it links matches its headers). */
size_t trk_max_tracks(void);
size_t trk_max_detections(void);
size_t trk_max_sensors(void);
size_t trk_real_size(void);

/* TRK_OK when the library was built with the same capacities and real type as
 * the including translation unit sees; TRK_E_ARG otherwise. */
#define trk_config_check()                                                   \
    ((trk_max_tracks() == TRK_MAX_TRACKS &&                                   \
      trk_max_detections() == TRK_MAX_DETECTIONS &&                           \
      trk_max_sensors() == TRK_MAX_SENSORS &&                                 \
      trk_real_size() == sizeof(trk_real))                                    \
         ? TRK_OK                                                             \
         : TRK_E_ARG)

#endif /* TRK_TYPES_H */
