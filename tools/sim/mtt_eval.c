/* mtt_eval.c - GOSPA and track-maintenance statistics (mtt_eval.h). */
#include "mtt_eval.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gospa.h"

struct mtt_target_state {
    long id;
    size_t first_scan;      /* scan index it was first present */
    long first_assigned;    /* scan index of its first assigned scan, -1 none */
    long last_track;        /* id of its last assigned track, or LONG_MIN-like none */
    int have_last;
    int was_assigned;       /* assigned in the last scan it was present */
    int gap_open;           /* unassigned while present since an assignment */
};

struct mtt_track_state {
    long id;
    size_t scans;           /* scored scans */
    size_t false_scans;     /* of which far from every target */
};

void mtt_eval_init(struct mtt_eval *e, double c_m)
{
    memset(e, 0, sizeof *e);
    e->c_m = c_m;
}

void mtt_eval_free(struct mtt_eval *e)
{
    free(e->targets);
    free(e->tracks);
    e->targets = NULL;
    e->tracks = NULL;
}

/* find or add (linear: a run has tens of targets and up to thousands of track ids) */
static struct mtt_target_state *target_of(struct mtt_eval *e, long id, size_t scan)
{
    for (size_t i = 0; i < e->n_targets; i++)
        if (e->targets[i].id == id) return &e->targets[i];
    if (e->n_targets == e->cap_targets) {
        const size_t cap = e->cap_targets ? 2 * e->cap_targets : 16;
        struct mtt_target_state *t = realloc(e->targets, cap * sizeof *t);
        if (!t) return NULL;
        e->targets = t;
        e->cap_targets = cap;
    }
    struct mtt_target_state *t = &e->targets[e->n_targets++];
    memset(t, 0, sizeof *t);
    t->id = id;
    t->first_scan = scan;
    t->first_assigned = -1;
    return t;
}

static struct mtt_track_state *track_of(struct mtt_eval *e, long id)
{
    for (size_t i = e->n_tracks; i-- > 0;) /* recent ids are at the end */
        if (e->tracks[i].id == id) return &e->tracks[i];
    if (e->n_tracks == e->cap_tracks) {
        const size_t cap = e->cap_tracks ? 2 * e->cap_tracks : 64;
        struct mtt_track_state *t = realloc(e->tracks, cap * sizeof *t);
        if (!t) return NULL;
        e->tracks = t;
        e->cap_tracks = cap;
    }
    struct mtt_track_state *t = &e->tracks[e->n_tracks++];
    memset(t, 0, sizeof *t);
    t->id = id;
    return t;
}

int mtt_eval_scan(struct mtt_eval *e, const struct mtt_obj *truth, size_t n_truth, const struct mtt_obj *est,
                  size_t n_est)
{
    return mtt_eval_scan_assign(e, truth, n_truth, est, n_est, NULL);
}

int mtt_eval_scan_assign(struct mtt_eval *e, const struct mtt_obj *truth, size_t n_truth,
                         const struct mtt_obj *est, size_t n_est, long *assign_out)
{
    if (!e || (n_truth && !truth) || (n_est && !est)) return -1;
    double *d = n_truth && n_est ? malloc(n_truth * n_est * sizeof *d) : NULL;
    long *assign = n_truth ? malloc(n_truth * sizeof *assign) : NULL;
    char *est_assigned = n_est ? calloc(n_est, 1) : NULL;
    int rc = -1;
    if ((n_truth && n_est && !d) || (n_truth && !assign) || (n_est && !est_assigned)) goto out;
    for (size_t i = 0; i < n_truth; i++)
        for (size_t j = 0; j < n_est; j++)
            d[i * n_est + j] = hypot(truth[i].x_m - est[j].x_m, truth[i].y_m - est[j].y_m);
    struct gospa_result g;
    if (gospa(d, n_truth, n_est, e->c_m, 2, assign, &g)) goto out;
    const size_t scan = e->n_scans++;
    e->gospa_lin_sum += g.gospa;
    e->loc_sum += g.loc;
    e->missed_sum += g.missed;
    e->false_sum += g.false_;
    /* targets: coverage, first assignment, switches, fragmentation */
    for (size_t i = 0; i < n_truth; i++) {
        struct mtt_target_state *t = target_of(e, truth[i].id, scan);
        if (!t) goto out;
        e->target_scans++;
        if (assign[i] < 0) {
            if (t->was_assigned) t->gap_open = 1;
            t->was_assigned = 0;
            continue;
        }
        const struct mtt_obj *y = &est[assign[i]];
        est_assigned[assign[i]] = 1;
        e->assigned_scans++;
        e->sq_err_sum += d[i * n_est + (size_t)assign[i]] * d[i * n_est + (size_t)assign[i]];
        if (t->first_assigned < 0) t->first_assigned = (long)scan;
        if (t->have_last && t->last_track != y->id) e->id_switches++;
        if (t->gap_open) e->fragmentations++;
        t->gap_open = 0;
        t->last_track = y->id;
        t->have_last = 1;
        t->was_assigned = 1;
    }
    /* tracks: false or duplicate when unassigned */
    for (size_t j = 0; j < n_est; j++) {
        struct mtt_track_state *k = track_of(e, est[j].id);
        if (!k) goto out;
        k->scans++;
        if (est_assigned[j]) continue;
        int near = 0;
        for (size_t i = 0; i < n_truth && !near; i++) near = d[i * n_est + j] < e->c_m;
        if (near) e->duplicate_track_scans++;
        else {
            e->false_track_scans++;
            k->false_scans++;
        }
    }
    if (assign_out)
        for (size_t i = 0; i < n_truth; i++) assign_out[i] = assign[i];
    rc = 0;
out:
    free(d);
    free(assign);
    free(est_assigned);
    return rc;
}

/* Scans from a target's first scan to its first assigned one; NAN never assigned. */
static double to_confirm(const struct mtt_target_state *t)
{
    return t->first_assigned < 0 ? NAN : (double)((size_t)t->first_assigned - t->first_scan);
}

double mtt_eval_target_to_confirm(const struct mtt_eval *e, long id)
{
    for (size_t i = 0; i < e->n_targets; i++)
        if (e->targets[i].id == id) return to_confirm(&e->targets[i]);
    return NAN;
}

void mtt_eval_summary(const struct mtt_eval *e, struct mtt_summary *s)
{
    memset(s, 0, sizeof *s);
    const double n = e->n_scans ? (double)e->n_scans : 1;
    s->n_scans = e->n_scans;
    s->gospa_mean_m = e->gospa_lin_sum / n;
    s->loc_mean_m2 = e->loc_sum / n;
    s->missed_mean_m2 = e->missed_sum / n;
    s->false_mean_m2 = e->false_sum / n;
    s->coverage = e->target_scans ? (double)e->assigned_scans / (double)e->target_scans : 0;
    s->n_targets = e->n_targets;
    double sum = 0;
    size_t k = 0;
    for (size_t i = 0; i < e->n_targets; i++) {
        const double x = to_confirm(&e->targets[i]);
        if (isnan(x)) {
            s->n_never++;
            continue;
        }
        sum += x;
        k++;
    }
    s->scans_to_confirm_mean = k ? sum / (double)k : NAN;
    s->n_tracks = e->n_tracks;
    for (size_t j = 0; j < e->n_tracks; j++)
        if (e->tracks[j].scans > 0 && e->tracks[j].false_scans == e->tracks[j].scans) s->n_false_tracks++;
    s->false_track_scans_per_100 = 100.0 * (double)e->false_track_scans / n;
    s->duplicate_track_scans_per_100 = 100.0 * (double)e->duplicate_track_scans / n;
    s->id_switches = e->id_switches;
    s->fragmentations = e->fragmentations;
    s->rmse_m = e->assigned_scans ? sqrt(e->sq_err_sum / (double)e->assigned_scans) : NAN;
}
