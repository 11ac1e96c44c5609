/* track_tests.h (private) - the tracker's dispatch to the per-track
 * confirmation and termination tests chosen in its configuration. The
 * tracker holds each chosen test's model once (confirm_model, term_model);
 * every track holds only its state (tr->test.confirm, then tr->test.term).
 * Adding a method: a test with the common step shape and enum trk_decision
 * (types.h), a case in each function of track_tests.c, a member of the state
 * and model unions in trk/tracker.h, and its parameter check. */
#ifndef TRK_TRACK_TESTS_H
#define TRK_TRACK_TESTS_H

#include "trk/tracker.h"

/* What one scan told a track (the tests' per-scan input). */
struct trk_look {
    int seen;            /* the sensor could see the track (P_D > 0): else nothing below is a look */
    int detected;        /* at least one detection in the gate */
    unsigned sensor_id;
    int n_gated;
    trk_real pfa_gate;   /* P(clutter in the gate) = 1 - exp(-lambda V_G) */
    /* the gate-count check's ring, the outer half of the gate's area
     * (gamma / 2 < d2 <= gamma): the detections there, and the count the
     * track's model expects there, lambda V_G / 2 + P_D (sqrt(1 - P_G) - (1 - P_G)) */
    int n_ring;
    trk_real n_ring_expected;
    trk_real n_expected_all; /* lambda V_G + TRK_TARGET_RETURNS_MAX P_D P_G: the whole gate's,
                                for a target of that many highlights */
    trk_real beta0;
    /* ln of the look's likelihood ratio, the track's target against a
     * persistent scatterer there (track_commit_impl.h persist_log_lr; 0:
     * no persistent-return description, or not a tentative track) */
    trk_real persist_llr;
    /* clutter tests: nearest detection of the scan (has_nearest = 0: none) */
    int has_nearest;
    size_t nearest;             /* its workspace index */
    trk_real rho_vg;            /* lambda * volume enclosed by the nearest detection */
    int has_amp;                /* nearest detection has an amplitude */
    trk_real a_assoc_db;        /* its amplitude (dB) */
    size_t n_others;            /* amplitudes of the other detections (dB) */
    const trk_real *a_others_db;
};

/* Existence confirmation's parameters usable (trk/tracker.h): p_confirm
 * in [0.5, 1) (a normal number, so a value punned through another union
 * member is refused), reject_odds_ratio in [0, 1), count_alpha 0 or a
 * normal number below 1. */
static inline int trk_i_existence_confirm_ok(const struct trk_existence_confirm_params *x)
{
    return x->p_confirm >= TRK_REAL_C(0.5) && x->p_confirm < 1 && x->reject_odds_ratio >= 0 &&
           x->reject_odds_ratio < 1 && (x->count_alpha == 0 || (x->count_alpha >= TRK_REAL_MIN && x->count_alpha < 1));
}

/* The gate-count check's tail P(N >= floor(gated)) of a Poisson count of
 * mean expected (trk/tracker.h count_alpha): 1 below one detection. */
trk_real trk_i_gate_count_tail(trk_real gated, trk_real expected);

/* Does the confirmation method need the nearest detection (clutter tests)? */
int trk_i_confirm_needs_nearest(const struct trk_tracker_params *p);

/* Check the methods' parameters and build their shared models (so a track
 * start never re-runs an expensive init). TRK_E_UNSUPPORTED for a clutter
 * test when TRK_WITH_CLUTTER_TESTS is 0. */
trk_status trk_i_tests_init(const struct trk_tracker_params *p, union trk_confirm_model *confirm,
                            union trk_term_model *term);

/* Start the confirmation test of a new tentative track. */
void trk_i_confirm_start(const struct trk_tracker *t, struct trk_track *tr);

/* One scan of a tentative track through its confirmation test: the test's
 * sticky decision (CONTINUE, CONFIRM, or TERMINATE = rejected). Sets
 * tr->confirm_stat. */
enum trk_decision trk_i_confirm_decide(const struct trk_tracker *t, struct trk_track *tr,
                                       const struct trk_look *look);

/* Start the termination test of a newly confirmed track. */
void trk_i_term_start(const struct trk_tracker *t, struct trk_track *tr);

/* One scan of a confirmed track through its termination test: CONTINUE or
 * TERMINATE. Sets tr->term_stat. */
enum trk_decision trk_i_term_decide(const struct trk_tracker *t, struct trk_track *tr,
                                    const struct trk_look *look);

/* The int forms src/tracker.c calls (kept with their prototypes while the
 * tracker is rewritten; new code calls the _decide functions):
 * trk_i_confirm_step: +1 confirm, -1 reject, 0 pending;
 * trk_i_term_step: 1 terminate, 0 continue. */
int trk_i_confirm_step(const struct trk_tracker *t, struct trk_track *tr,
                       const struct trk_look *look);
int trk_i_term_step(const struct trk_tracker *t, struct trk_track *tr,
                    const struct trk_look *look);

#endif
