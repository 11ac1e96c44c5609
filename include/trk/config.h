/** @file
 * trk/config.h - every compile-time knob of trk: capacities, options and the
 * scalar type, each with its default and a check that says how to fix an
 * impossible value.
 *
 * A knob is a default that a build may override with -DNAME=value or by
 * pointing TRK_CONFIG_FILE at a header of its own (-DTRK_CONFIG_FILE='"my_trk.h"'),
 * which is included first. The `#error` lines below (those at the end check
 * the capacities together) reject impossible combinations at compile time.
 *
 * The library and the program that links it must agree on every knob that
 * sets a struct layout (all of them except TRK_SIZE_OPT): trk_config_check()
 * (types.h) compares the header's view with the library's and returns
 * TRK_E_ABI on a mismatch; trk_tracker_abi_check() (tracker.h) adds the size
 * of struct trk_tracker.
 */
#ifndef TRK_CONFIG_H
#define TRK_CONFIG_H

#ifdef TRK_CONFIG_FILE
#include TRK_CONFIG_FILE
#endif

/* ---------------------------------------------------------------- scalar type */

/* TRK_REAL_FLOAT: a switch, not a value. Undefined (default): trk_real is
 * double. Defined (-DTRK_REAL_FLOAT, `make REAL=float`): trk_real is float and
 * the float libm functions (sqrtf, ...) are used, so no soft-double code is
 * pulled in (Cortex-M4F and other FPUs without double support). Compile the
 * library and every program that includes trk headers with the same choice
 * (trk_config_check() compares sizeof(trk_real)); tables carry their real
 * width and a table of the other width is refused (TRK_E_TABLE_REAL).
 * types.h defines trk_real, TRK_REAL_C() and trk_sqrt/trk_exp/... from it.
 * It is tested with `#ifdef`, so -DTRK_REAL_FLOAT=0 or =double would select
 * float: refused below. */
#if defined(TRK_REAL_FLOAT) && (0 - TRK_REAL_FLOAT - 1) == -1
#error "TRK_REAL_FLOAT is a switch tested with #ifdef: its value 0 (or a word such as double) would still select float. For double leave it undefined; for float use -DTRK_REAL_FLOAT (make REAL=float)"
#endif

/* ---------------------------------------------------------------- capacities */

/** Live tracks in one trk_tracker (tentative + confirmed). */
#ifndef TRK_MAX_TRACKS
#define TRK_MAX_TRACKS 64
#endif

/** Detections in one scan. A larger scan is refused whole (TRK_E_CAPACITY). */
#ifndef TRK_MAX_DETECTIONS
#define TRK_MAX_DETECTIONS 256
#endif

/** Initiation candidates (trk/tracker.h, two-point initiation): the
 * unexplained detections of recent scans that may pair with a later one to
 * start a track. One full scan's worth by default; each costs 30 bytes in
 * float, 58 in double (with its index entry). A scan's candidates are kept
 * together (one run per scan, contiguous): a scan whose unexplained
 * detections do not fit evicts the oldest scans' candidates first, then
 * counts the rest as dropped (trk_scan_report.n_candidates_dropped). At
 * most 65535. */
#ifndef TRK_MAX_CANDIDATES
#define TRK_MAX_CANDIDATES TRK_MAX_DETECTIONS
#endif
#if TRK_MAX_CANDIDATES < 1 || TRK_MAX_CANDIDATES > 65535
#error "TRK_MAX_CANDIDATES must be in 1..65535 (initiation candidates); set -DTRK_MAX_CANDIDATES=256"
#endif

/** Scans whose candidates the store holds at once: trk_init_params.
 * max_gap_scans is at most TRK_MAX_CANDIDATE_SCANS - 1 (a candidate pairs
 * with the next max_gap_scans scans). */
#ifndef TRK_MAX_CANDIDATE_SCANS
#define TRK_MAX_CANDIDATE_SCANS 8
#endif
#if TRK_MAX_CANDIDATE_SCANS < 2 || TRK_MAX_CANDIDATE_SCANS > 256
#error "TRK_MAX_CANDIDATE_SCANS must be in 2..256 (candidate runs); set -DTRK_MAX_CANDIDATE_SCANS=8"
#endif

/** Sensors (e.g. multistatic receivers) with their own noise and detection
 * parameters that one tracker fuses. */
#ifndef TRK_MAX_SENSORS
#define TRK_MAX_SENSORS 4
#endif

/** Points of a sensor's profiles over range (P_D, trk_pd_profile, and
 * clutter density, trk_clutter_profile; trk/tracker.h): 8 points spaced
 * evenly in log range hold a transmission-loss curve from 0.5 to 8 km to
 * within 0.02 of P_D, and a 1/r clutter density within 4 % (interpolated
 * linearly). Each point costs four trk_real per sensor in the tracker's
 * parameters (the default 4 sensors x 8 points: 512 B in float); 16 points
 * took the default build's RAM past its 64 KB budget. */
#ifndef TRK_PD_PROFILE_MAX
#define TRK_PD_PROFILE_MAX 8
#endif

/** Cells of each sensor's clutter map (trk/tracker.h, struct
 * trk_clutter_map_params: range x bearing cells over the sensor's
 * coverage): the map's n_range x n_bearing is at most this. Each cell costs
 * one trk_real per sensor (the default 4 sensors x 512 cells: 8 KB in
 * float; the default map is 16 x 32 cells from 512, 16 x 16 from 256).
 * 0 compiles the map out (its parameters must then ask for no cells). At
 * most 65535. */
#ifndef TRK_CLUTTER_MAP_CELLS
#define TRK_CLUTTER_MAP_CELLS 512
#endif

/** Largest state and measurement dimension of the general linear-Gaussian
 * functions (kalman.h, gate.h, pda.h). The tracker itself runs the 2-D
 * constant-velocity model (4 states, 2 measurements). */
#ifndef TRK_MAX_STATE
#define TRK_MAX_STATE 6
#endif
#ifndef TRK_MAX_MEAS
/** Largest measurement dimension (see TRK_MAX_STATE). */
#define TRK_MAX_MEAS 3
#endif

/** Largest window (updates) of Kennedy's clutter tests (clutter_test.h): the
 * per-track states struct trk_clutter_chi2 / trk_clutter_amp and the density
 * test's threshold table hold TRK_CLUTTER_KMAX entries each, so their size
 * grows with it (at 25: about 0.45 KB per track in double, 0.28 KB in float).
 * Default 25, Kennedy 2008's window: every track slot pays for the largest
 * window (32 would cost 4.5 KB more at 64 float tracks, which the
 * two-point initiation's candidate store needs). */
#ifndef TRK_CLUTTER_KMAX
#define TRK_CLUTTER_KMAX 25
#endif
#if TRK_CLUTTER_KMAX < 1 || TRK_CLUTTER_KMAX > 1024
#error "TRK_CLUTTER_KMAX must be in 1..1024 (window of the clutter tests; Kennedy 2008 uses 25); set -DTRK_CLUTTER_KMAX=25"
#endif

/** Models of one IMM estimator (imm.h): struct trk_imm_state holds
 * TRK_MAX_MODELS mode-conditioned estimates (20 reals each) and probabilities.
 * Default 4: the largest IMM of the reference vectors (CV, two turns and a
 * high-noise CV), so that the default build computes every case; 3 (CV and a
 * left and a right turn) saves 20 reals per IMM state. */
#ifndef TRK_MAX_MODELS
#define TRK_MAX_MODELS 4
#endif
#if TRK_MAX_MODELS < 1 || TRK_MAX_MODELS > 8
#error "TRK_MAX_MODELS must be in 1..8 (models of one IMM, imm.h); set -DTRK_MAX_MODELS=4"
#endif

/** Joint association (jpda.h): a cluster is solved exactly by a programme over
 * the subsets of its smaller side while that side has at most
 * TRK_JPDA_EXACT_BITS members (struct trk_jpda_work holds 2^bits reals) and
 * the work stays under TRK_JPDA_MAX_WORK operations (about a nanosecond each
 * on a host core); beyond, loopy belief
 * propagation runs at most TRK_JPDA_LBP_MAX_ITER iterations (each costing a
 * few operations per gated pair). */
#ifndef TRK_JPDA_EXACT_BITS
#define TRK_JPDA_EXACT_BITS 9 /**< 2 KB of float workspace in the tracker; 10 doubles it */
#endif
#if TRK_JPDA_EXACT_BITS < 1 || TRK_JPDA_EXACT_BITS > 16
#error "TRK_JPDA_EXACT_BITS must be in 1..16 (the exact method's 2^bits workspace, jpda.h); set -DTRK_JPDA_EXACT_BITS=9"
#endif
#ifndef TRK_JPDA_MAX_WORK
#define TRK_JPDA_MAX_WORK (1L << 18) /**< about 0.1 ms of a host core: so the worst scan stays
                                        within 10x a typical full scan (docs/firmware.md,
                                        "Worst-case scan time"); raise it (and
                                        TRK_JPDA_SCAN_WORK) for exact marginals of larger
                                        clusters at that cost */
#endif
/** ... and all exact programmes of one call (one scan) together at most
 * TRK_JPDA_SCAN_WORK: the clusters beyond take belief propagation, so a
 * scan's exact work is bounded however many large clusters it has. */
#ifndef TRK_JPDA_SCAN_WORK
#define TRK_JPDA_SCAN_WORK (1L << 18)
#endif
#if TRK_JPDA_SCAN_WORK < TRK_JPDA_MAX_WORK
#error "TRK_JPDA_SCAN_WORK must be at least TRK_JPDA_MAX_WORK (jpda.h); set -DTRK_JPDA_SCAN_WORK=262144"
#endif
/** Gated track-detection pairs one scan may hold (the tracker's joint
 * association, and trk_jpda_marginals' sparse copy): at least
 * TRK_MAX_DETECTIONS (one track's gated set), at most 65535. A scan with more
 * is counted in the tracker's report (n_assoc_overflow, trk/tracker.h). */
#ifndef TRK_MAX_GATED_PAIRS
#define TRK_MAX_GATED_PAIRS (2 * TRK_MAX_DETECTIONS < 65535 ? 2 * TRK_MAX_DETECTIONS : 65535)
#endif
#if TRK_MAX_GATED_PAIRS < TRK_MAX_DETECTIONS || TRK_MAX_GATED_PAIRS > 65535
#error "TRK_MAX_GATED_PAIRS must be in TRK_MAX_DETECTIONS..65535 (trk/jpda.h); set -DTRK_MAX_GATED_PAIRS=512"
#endif
#ifndef TRK_JPDA_LBP_MAX_ITER
#define TRK_JPDA_LBP_MAX_ITER 30 /**< the bound on a cluster that does not converge (a
                                     fully shared one); typical clusters converge in fewer */
#endif
#if TRK_JPDA_LBP_MAX_ITER < 1
#error "TRK_JPDA_LBP_MAX_ITER must be at least 1 (jpda.h); set -DTRK_JPDA_LBP_MAX_ITER=30"
#endif

/* ---------------------------------------------------------------- options */

/** Kennedy's clutter tests (clutter_test.h) as confirmation methods of the
 * tracker. Their per-track state carries a window of TRK_CLUTTER_KMAX updates,
 * by far the largest member of union trk_confirm_state (trk/tracker.h), which
 * every track slot holds. 0 leaves the clutter tests' states and models out of
 * the track table (then selecting TRK_CONFIRM_CLUTTER_CHI2 or
 * TRK_CONFIRM_CLUTTER_AMP makes trk_tracker_init return TRK_E_UNSUPPORTED);
 * the clutter_test module itself is always built and usable on its own.
 * 1 (default) keeps them. */
#ifndef TRK_WITH_CLUTTER_TESTS
#define TRK_WITH_CLUTTER_TESTS 1
#endif

/** Joint association (JIPDA) in the track table (trk/tracker.h,
 * TRK_ASSOC_JOINT, the default association). 0 leaves it out of the tracker:
 * its pair store shrinks to one track's gated set and its code (the cluster
 * solver, about 5 KB on a Cortex-M4F) is not linked; the default association
 * is then the per-track PDA, and TRK_ASSOC_JOINT makes trk_tracker_init
 * return TRK_E_UNSUPPORTED. The jpda module itself is always built. 1
 * (default) keeps it. */
#ifndef TRK_WITH_JOINT
#define TRK_WITH_JOINT 1
#endif
#if TRK_WITH_JOINT != 0 && TRK_WITH_JOINT != 1
#error "TRK_WITH_JOINT must be 0 or 1 (joint association in the tracker); set -DTRK_WITH_JOINT=1"
#endif

/** Manoeuvring targets: IMM tracks in the track table (trk/tracker.h,
 * trk_tracker_params.imm; trk/imm.h). 1 gives every track slot its
 * mode-conditioned estimates (TRK_MAX_MODELS x 20 reals and the mode
 * probabilities) and the manoeuvre statistic, and the scan workspace the
 * models' weights; a tracker then runs IMM tracks when imm.n_models >= 1.
 * 0 (default) leaves them out: the table's memory and the scan's code and
 * speed are those of the CV-only tracker (struct trk_tracker_params has no
 * imm member then: code that sets it does not compile, rather than being
 * refused at run time). The imm module itself is always built. */
#ifndef TRK_WITH_IMM
#define TRK_WITH_IMM 0
#endif
#if TRK_WITH_IMM != 0 && TRK_WITH_IMM != 1
#error "TRK_WITH_IMM must be 0 or 1 (IMM tracks in the tracker); set -DTRK_WITH_IMM=1"
#endif

/** The constant-gain (alpha-beta) track filter (trk/tracker.h
 * trk_tracker_params.filter = TRK_FILTER_ALPHA_BETA; trk/kalman.h
 * trk_cv_steady_state): the steady-state gains of the CV Kalman filter
 * instead of its covariance recursion, for a firmware that cannot afford
 * the recursion per track. 1 compiles it into the scan; 0 (default) leaves
 * it out (the table's memory is the same either way), and
 * TRK_FILTER_ALPHA_BETA is then refused (TRK_E_UNSUPPORTED). */
#ifndef TRK_WITH_ALPHA_BETA
#define TRK_WITH_ALPHA_BETA 0
#endif
#if TRK_WITH_ALPHA_BETA != 0 && TRK_WITH_ALPHA_BETA != 1
#error "TRK_WITH_ALPHA_BETA must be 0 or 1 (the alpha-beta track filter); set -DTRK_WITH_ALPHA_BETA=1"
#endif

/** The library's small kernels (the *_impl.h headers of src) are forced
 * inline so that a caller passing constant dimensions (the 2-D CV model) gets
 * fully unrolled code. TRK_SIZE_OPT = 1 leaves the inlining decision to the
 * compiler and drops the CV-specialised copies instead: a firmware build then
 * keeps one copy of each kernel per file rather than one per call site
 * (mk/size.mk: make size-report, make cross-sizeopt). Default: 1 when the
 * compiler optimises for size (-Os, __OPTIMIZE_SIZE__), else 0 (host -O2
 * builds keep the forced inlining the benchmarks were measured with). Code
 * size and speed only: no struct layout depends on it, so a library and a
 * program may differ (it is not part of trk_config_check()). */
#ifndef TRK_SIZE_OPT
#ifdef __OPTIMIZE_SIZE__
#define TRK_SIZE_OPT 1
#else
#define TRK_SIZE_OPT 0
#endif
#endif
#if TRK_SIZE_OPT != 0 && TRK_SIZE_OPT != 1
#error "TRK_SIZE_OPT must be 0 (forced inlining, speed) or 1 (compiler's choice, size); set -DTRK_SIZE_OPT=1 or leave it unset (default: 1 under -Os)"
#endif

/* Impossible combinations of the capacities (each #error says how to fix it). */
#if TRK_MAX_TRACKS < 1 || TRK_MAX_TRACKS > 65535
#error "TRK_MAX_TRACKS must be in 1..65535 (track slots are indexed by uint16_t); set -DTRK_MAX_TRACKS=64"
#endif
#if TRK_MAX_DETECTIONS < 1 || TRK_MAX_DETECTIONS > 65535
#error "TRK_MAX_DETECTIONS must be in 1..65535 (detections are indexed by uint16_t); set -DTRK_MAX_DETECTIONS=256"
#endif
#if TRK_MAX_CANDIDATES < 1 || TRK_MAX_CANDIDATES > 65535
#error "TRK_MAX_CANDIDATES must be in 1..65535 (initiation candidates are indexed by uint16_t); set -DTRK_MAX_CANDIDATES=256 (default: TRK_MAX_DETECTIONS)"
#endif
#if TRK_MAX_SENSORS < 1 || TRK_MAX_SENSORS > 255
#error "TRK_MAX_SENSORS must be in 1..255 (sensor ids are uint8_t); set -DTRK_MAX_SENSORS=4"
#endif
#if TRK_CLUTTER_MAP_CELLS < 0 || TRK_CLUTTER_MAP_CELLS > 65535
#error "TRK_CLUTTER_MAP_CELLS must be in 0..65535 (cells of a sensor's clutter map); set -DTRK_CLUTTER_MAP_CELLS=256"
#endif
#if TRK_PD_PROFILE_MAX < 2 || TRK_PD_PROFILE_MAX > 255
#error "TRK_PD_PROFILE_MAX must be in 2..255 (points of a P_D profile); set -DTRK_PD_PROFILE_MAX=16"
#endif
#if TRK_MAX_STATE < 4
#error "TRK_MAX_STATE must be at least 4: the tracker's 2-D constant-velocity state is [x, vx, y, vy]"
#endif
#if TRK_MAX_MEAS < 2
#error "TRK_MAX_MEAS must be at least 2: the tracker measures [x, y]"
#endif
#if TRK_MAX_MEAS > TRK_MAX_STATE
#error "TRK_MAX_MEAS must not exceed TRK_MAX_STATE"
#endif
#if TRK_MAX_MEAS > 3
#error "TRK_MAX_MEAS above 3 is not supported: gate.h has gamma and volume only for nz = 1, 2, 3"
#endif

#if TRK_WITH_CLUTTER_TESTS != 0 && TRK_WITH_CLUTTER_TESTS != 1
#error "TRK_WITH_CLUTTER_TESTS must be 0 or 1; set -DTRK_WITH_CLUTTER_TESTS=1"
#endif

#endif /* TRK_CONFIG_H */
