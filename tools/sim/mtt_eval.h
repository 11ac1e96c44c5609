/* mtt_eval.h - multi-target tracking evaluation: GOSPA per scan and the
 * track-maintenance statistics of the "Tracking Radar" MTT survey (2002,
 * ch. 6.3), accumulated over the scans of one run.
 *
 * Per scan the caller gives the true targets present (id, position) and the
 * tracks to score (id, position; normally the confirmed ones). Each scan is
 * scored on its own optimal GOSPA assignment (gospa.h, p = 2, alpha = 2,
 * cut-off c): a track assigned to a target is that target's track in that
 * scan. From the assignments:
 *   coverage          assigned target-scans / target-scans
 *   scans to confirm  per target: scans from its first scan to its first
 *                     assigned scan (targets never assigned are counted
 *                     apart: n_never)
 *   false track-scans unassigned tracks farther than c from every target
 *   duplicate t.-s.   unassigned tracks within c of a target (a second track
 *                     on a target the assignment gave to another one)
 *   false tracks      track ids whose every scored scan was a false
 *                     track-scan (never near a target)
 *   identity switches a target's assigned track id differs from the id of its
 *                     previous assigned scan
 *   fragmentations    a target assigned, then unassigned while present, then
 *                     assigned again (each gap counts once)
 *   RMSE              position error over the assigned pairs
 * Host code: the state grows on the heap with the ids seen. */
#ifndef TRK_SIM_MTT_EVAL_H
#define TRK_SIM_MTT_EVAL_H

#include <stddef.h>

struct mtt_obj {
    long id;
    double x_m, y_m;
};

struct mtt_target_state; /* per target, internal */
struct mtt_track_state;  /* per track id, internal */

struct mtt_eval {
    double c_m;                 /* GOSPA cut-off */
    size_t n_scans;
    double loc_sum, missed_sum, false_sum; /* the parts of GOSPA^2, summed over scans */
    double gospa_lin_sum;       /* of GOSPA (the metric itself) over scans */
    size_t target_scans, assigned_scans;
    size_t false_track_scans, duplicate_track_scans;
    size_t id_switches, fragmentations;
    double sq_err_sum;          /* over assigned pairs */
    /* internal */
    struct mtt_target_state *targets;
    size_t n_targets, cap_targets;
    struct mtt_track_state *tracks;
    size_t n_tracks, cap_tracks;
};

struct mtt_summary {
    size_t n_scans;
    double gospa_mean_m, loc_mean_m2, missed_mean_m2, false_mean_m2; /* per scan */
    double coverage;
    double scans_to_confirm_mean; /* over targets ever assigned */
    size_t n_targets, n_never;    /* targets seen, never assigned */
    size_t n_false_tracks, n_tracks;
    double false_track_scans_per_100, duplicate_track_scans_per_100; /* per 100 scans */
    size_t id_switches, fragmentations;
    double rmse_m;
};

void mtt_eval_init(struct mtt_eval *e, double c_m);
void mtt_eval_free(struct mtt_eval *e);
/* One scan: n_truth targets, n_est scored tracks (ids must be unique within
 * each list). Returns 0, -1 on bad arguments or no memory. */
int mtt_eval_scan(struct mtt_eval *e, const struct mtt_obj *truth, size_t n_truth, const struct mtt_obj *est,
                  size_t n_est);
/* The same, and assign[i] (n_truth entries; may be NULL) = the index in est
 * of the track assigned to truth[i] in this scan, or -1 (per-target
 * statistics of the caller: coverage in a window, both of a pair held). */
int mtt_eval_scan_assign(struct mtt_eval *e, const struct mtt_obj *truth, size_t n_truth,
                         const struct mtt_obj *est, size_t n_est, long *assign_out);
void mtt_eval_summary(const struct mtt_eval *e, struct mtt_summary *s);
/* Scans from target id's first scan to its first assigned scan (its share
 * of scans_to_confirm_mean); NAN when it was never assigned or never seen. */
double mtt_eval_target_to_confirm(const struct mtt_eval *e, long id);

#endif
