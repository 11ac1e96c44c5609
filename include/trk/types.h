/** @file
 * trk/types.h - the scalar type and its math functions, the status codes,
 * the decision of the per-track tests, and the configuration check.
 *
 * trk_real is double, or float with TRK_REAL_FLOAT (see trk/config.h, where
 * every compile-time knob is documented and checked). The float build uses
 * the float libm functions (sqrtf, ...) so no soft-double code is pulled in.
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
#define TRK_REAL_MIN 1.17549435e-38f /**< smallest normal */
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
/** The scalar type of the library: double, or float with TRK_REAL_FLOAT (trk/config.h). */
typedef double trk_real;
/** A trk_real constant: x, or x with the f suffix in the float build. */
#define TRK_REAL_C(x) x
/** Machine epsilon of trk_real. */
#define TRK_REAL_EPS 2.2204460492503131e-16
/** Largest finite trk_real. */
#define TRK_REAL_MAX 1.7976931348623157e+308
#define TRK_REAL_MIN 2.2250738585072014e-308 /**< smallest normal */
/** 1 in the float build, 0 in the double build. */
#define TRK_REAL_IS_FLOAT 0
/** @{ The libm function of trk_real: sqrt, exp, log, ... in the double build, sqrtf, expf, logf, ... in the float build. */
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
/** @} */
#endif

/** pi as a trk_real. */
#define TRK_PI TRK_REAL_C(3.14159265358979323846)
/** ln(2 pi) as a trk_real. */
#define TRK_LN_2PI TRK_REAL_C(1.83787706640934548356)

/** Warn when a caller drops a status (libsodium habit). */
#if defined(__GNUC__) || defined(__clang__)
#define TRK_NODISCARD __attribute__((warn_unused_result))
#else
#define TRK_NODISCARD
#endif

/** Status of every fallible call. TRK_OK is 0; everything else is a refusal
 * that left the caller's objects as they were (unless a function says
 * otherwise). trk_status_str() names each one, trk_status_message() says it
 * in plain words. */
typedef enum trk_status {
    TRK_OK = 0,
    TRK_E_ARG,             /**< NULL pointer, bad dimension or enum value */
    TRK_E_NAN,             /**< a NaN or infinite input */
    TRK_E_RANGE,           /**< a value outside its documented range */
    TRK_E_CAPACITY,        /**< more items than the compile-time capacity */
    TRK_E_NOT_SPD,         /**< a covariance is not symmetric positive definite */
    TRK_E_SINGULAR,        /**< a matrix cannot be inverted */
    TRK_E_TIME,            /**< scan time goes backwards */
    TRK_E_SENSOR,          /**< unknown sensor id */
    TRK_E_TABLE_TRUNCATED, /**< table shorter than its header says */
    TRK_E_TABLE_MAGIC,     /**< not a trk table */
    TRK_E_TABLE_VERSION,   /**< table format version not supported */
    TRK_E_TABLE_REAL,      /**< table real width differs from this build */
    TRK_E_TABLE_CRC,       /**< CRC-32 mismatch */
    TRK_E_TABLE_KIND,      /**< table of another kind or dimension than asked for */
    TRK_E_TABLE_CORRUPT,   /**< inconsistent header, non-finite or non-monotone data */
    TRK_E_DIVERGED,        /**< an iteration did not converge */
    TRK_E_UNSUPPORTED,     /**< a feature not built into this configuration */
    TRK_E_IO,              /**< host helpers only: file could not be read/written */
    TRK_E_ABI,             /**< the library was built with another configuration
                              (capacities, options, real type) than the caller's
                              headers: trk_config_check(), trk_tracker_abi_check() */
    TRK_STATUS_COUNT
} trk_status;

/** Short constant name of a status ("TRK_E_NAN"); never NULL. */
const char *trk_status_str(trk_status s);

/** One line in plain words saying what went wrong, for a person reading a
 * tool's message ("table checksum does not match its contents (corrupt or
 * truncated copy)"); "success" for TRK_OK, "unknown status code" for a value
 * out of range; never NULL. The words agree with docs/statuses.md. Tools
 * print it with the name: "MESSAGE (TRK_E_TABLE_CRC)". Its text is in an
 * object of its own: a firmware that does not call it links none of it. */
const char *trk_status_message(trk_status s);

/** Decision of a per-track test: the confirmation tests (confirm_mn.h,
 * confirm_sprt.h, clutter_test.h, visibility.h) and the termination tests
 * (term_kn.h, term_page.h, term_shiryaev.h, visibility.h).
 *
 * Why one enum. Each test used to code its decision its own way (an int
 * return of +1/-1/0, a 1/0 field, two flags) and the tracker translated each
 * of them. With one enum every test's step has the same shape,
 *
 * @verbatim
 *   trk_status trk_<test>_step(const struct trk_<test>_model *m,
 *                              struct trk_<test> *s, <the test's per-scan input>,
 *                              enum trk_decision *decision);
 * @endverbatim
 *
 * returning TRK_E_ARG for a NULL pointer (m, s, decision or an input array)
 * and TRK_E_NAN / TRK_E_RANGE / TRK_E_SENSOR / TRK_E_CAPACITY for a bad
 * input, and on error leaving *s and *decision untouched. A caller (the
 * tracker, a simulator, a tool) then handles any test with one switch. The
 * values name what to do with the track, not which hypothesis won: a
 * confirmation test that rejects a tentative track (M/N can no longer reach
 * M, SPRT crosses its lower threshold, visibility falls below p_term) says
 * TRK_DECISION_TERMINATE.
 *
 * Sticky. The first decision a test takes is final: every later step
 * reports it again, and nothing a later scan brings changes it (a test's
 * state keeps the decision in its `decision` member; only trk_<test>_reset
 * starts it afresh). The statistics are not frozen: they keep following
 * their recurrence after the decision, so a display can always show them
 * (trk_track.confirm_stat / term_stat) and the reference vectors check them
 * after decisions (docs/conventions.md "Track confirmation and termination"); they
 * just no longer change the decision. The one change allowed is
 * CONFIRM -> TERMINATE, and only the visibility test makes it: it serves one
 * track in both roles with one state (pcv reaches p_con: confirm; later pcv
 * falls below p_term: terminate). TERMINATE is final for every test.
 *
 * CONTINUE is 0, so a zeroed state is "no decision yet". */
enum trk_decision {
    TRK_DECISION_CONTINUE = 0, /**< no decision yet: keep the track as it is and
                                  step the test again at the next scan */
    TRK_DECISION_CONFIRM = 1,  /**< confirmation test: confirm the tentative track */
    TRK_DECISION_TERMINATE = 2 /**< end the track: a termination test fired, or a
                                  confirmation test rejected a tentative track */
};

/** Short constant name of a decision ("TRK_DECISION_CONFIRM"); never NULL. */
const char *trk_decision_str(enum trk_decision d);

/** @{ */
/** The configuration as the library was built (libsodium habit: a program
 * checks at start-up that the library it links was built like its headers):
 * every value that sets the layout of a public struct. */
size_t trk_max_tracks(void);
size_t trk_max_detections(void);
size_t trk_max_sensors(void);
size_t trk_max_state(void);
size_t trk_max_meas(void);
size_t trk_clutter_kmax(void);
/** @} */
size_t trk_with_clutter_tests(void); /**< TRK_WITH_CLUTTER_TESTS: 0 or 1 */
size_t trk_with_joint(void);         /**< TRK_WITH_JOINT: 0 or 1 */
size_t trk_with_imm(void);           /**< TRK_WITH_IMM: 0 or 1 */
size_t trk_max_models(void);         /**< TRK_MAX_MODELS (struct trk_imm_state) */
size_t trk_jpda_exact_bits(void);    /**< TRK_JPDA_EXACT_BITS (struct trk_jpda_work) */
size_t trk_max_gated_pairs(void);    /**< TRK_MAX_GATED_PAIRS (struct trk_jpda_work, trk_tracker) */
size_t trk_real_size(void);          /**< sizeof(trk_real): TRK_REAL_FLOAT */
size_t trk_enum_size(void);          /**< sizeof of an enum (-fshort-enums changes it,
                                        and every struct that holds one) */

/** TRK_OK when the library was built with the configuration (capacities,
 * TRK_CLUTTER_KMAX, TRK_WITH_CLUTTER_TESTS, real type, enum size) that the
 * including translation unit sees; TRK_E_ABI otherwise. TRK_SIZE_OPT is not
 * compared: it sets no layout. trk_tracker_abi_check() (tracker.h) also
 * compares sizeof(struct trk_tracker). */
#define trk_config_check()                                                   \
    ((trk_max_tracks() == TRK_MAX_TRACKS &&                                   \
      trk_max_detections() == TRK_MAX_DETECTIONS &&                           \
      trk_max_sensors() == TRK_MAX_SENSORS &&                                 \
      trk_max_state() == TRK_MAX_STATE &&                                     \
      trk_max_meas() == TRK_MAX_MEAS &&                                       \
      trk_clutter_kmax() == TRK_CLUTTER_KMAX &&                               \
      trk_with_clutter_tests() == TRK_WITH_CLUTTER_TESTS &&                   \
      trk_with_joint() == TRK_WITH_JOINT &&                                   \
      trk_with_imm() == TRK_WITH_IMM &&                                       \
      trk_max_models() == TRK_MAX_MODELS &&                                   \
      trk_jpda_exact_bits() == TRK_JPDA_EXACT_BITS &&                         \
      trk_max_gated_pairs() == TRK_MAX_GATED_PAIRS &&                         \
      trk_real_size() == sizeof(trk_real) &&                                  \
      trk_enum_size() == sizeof(enum trk_decision))                           \
         ? TRK_OK                                                             \
         : TRK_E_ABI)

#endif /* TRK_TYPES_H */
