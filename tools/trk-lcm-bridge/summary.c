/* summary.c - trk-lcm-bridge --summarize LOG (summary.h). */
#include "summary.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lcm_log.h"
#include "transport.h"

#define MAX_CHANNELS 32
#define MAX_TRUTH 64

struct chan_count {
    char name[64];          /* the first bytes of the channel (may hold NULs) */
    size_t len;             /* its full length */
    uint64_t n;
};

/* Channels are told apart by their full bytes, NULs included. */
static void count_channel(struct chan_count *cc, int *ncc, const struct lcmlog_event *ev)
{
    const size_t keep = ev->channellen < sizeof cc[0].name ? ev->channellen : sizeof cc[0].name - 1;
    for (int i = 0; i < *ncc; i++)
        if (cc[i].len == ev->channellen && memcmp(cc[i].name, ev->channel, keep) == 0) {
            cc[i].n++;
            return;
        }
    if (*ncc == MAX_CHANNELS) return;
    memcpy(cc[*ncc].name, ev->channel, keep);
    cc[*ncc].name[keep] = 0;
    cc[*ncc].len = ev->channellen;
    cc[*ncc].n = 1;
    (*ncc)++;
}

/* A channel name for the listing: a NUL shows as \0. */
static void print_channel(FILE *f, const struct chan_count *c)
{
    const size_t keep = c->len < sizeof c->name ? c->len : sizeof c->name - 1;
    int w = 0;
    fputs("  ", f);
    for (size_t i = 0; i < keep; i++) {
        if (!c->name[i]) {
            w += fprintf(f, "\\0");
            continue;
        }
        fputc(c->name[i], f);
        w++;
    }
    fprintf(f, "%s%*s %llu\n", keep < c->len ? "..." : "", w < 24 ? 24 - w : 0, "",
            (unsigned long long)c->n);
}

/* Per truth target: is there a confirmed track within 25 m of it? */
static void follow(const trk_track_list_t *m, const trk_track_list_t *truth, uint64_t *ok_n,
                   uint64_t *n)
{
    for (int g = 0; g < truth->n_tracks && g < MAX_TRUTH; g++) {
        const double *tx = truth->tracks[g].x;
        int ok = 0;
        for (int i = 0; i < m->n_tracks && !ok; i++) {
            const trk_track_t *t = &m->tracks[i];
            if (t->status != TRK_TRACK_T_STATUS_CONFIRMED) continue;
            ok = hypot(t->x[TRK_CV2_X] - tx[TRK_CV2_X], t->x[TRK_CV2_Y] - tx[TRK_CV2_Y]) <= 25;
        }
        n[g]++;
        ok_n[g] += (uint64_t)ok;
    }
}

static int decode_list(const struct lcmlog_event *ev, trk_track_list_t *m)
{
    if (!ev->data || ev->datalen > INT32_MAX) return -1;
    int k = trk_track_list_t_decode(ev->data, 0, (int)ev->datalen, m);
    if (k < 0 || (size_t)k != ev->datalen) return -1;
    if (m->n_tracks < 0 || m->n_tracks > TRK_TRACK_LIST_T_MAX_TRACKS) return -1;
    return 0;
}

int bridge_summarize(const char *path, const struct bridge_opts *o, const char *truth_channel,
                     FILE *f)
{
    struct lcmlog_reader r;
    if (lcmlog_open_read(&r, path, 1u << 20) != 0) {
        fprintf(stderr, "trk-lcm-bridge: %s: cannot open: %s\n", path, strerror(errno));
        return -1;
    }
    struct chan_count cc[MAX_CHANNELS];
    int ncc = 0;
    trk_track_list_t *m = malloc(sizeof *m), *truth = calloc(1, sizeof *truth),
                     *last = calloc(1, sizeof *last);
    trk_bridge_status_t status;
    int have_status = 0, have_truth = 0, have_last = 0;
    uint64_t n_lists = 0, max_live = 0, n_bad = 0;
    int64_t evaluated = -1; /* utime of the last (tracks, truth) pair compared */
    /* confirmed ids (bounded list) */
    size_t ids_cap = 4096, n_ids = 0;
    int64_t *ids = malloc(ids_cap * sizeof *ids);
    /* truth following: scans where each target had a confirmed track within
     * 3 sigma-ish (25 m) of it, over lists that match a truth list's time */
    uint64_t follow_ok[MAX_TRUTH] = {0}, follow_n[MAX_TRUTH] = {0};
    if (!m || !truth || !last || !ids) {
        fprintf(stderr, "trk-lcm-bridge: out of memory\n");
        free(m), free(truth), free(last), free(ids);
        lcmlog_close_read(&r);
        return -1;
    }
    struct lcmlog_event ev;
    int got;
    while ((got = lcmlog_read(&r, &ev)) > 0) {
        count_channel(cc, &ncc, &ev);
        if (truth_channel && truth_channel[0] && lcmlog_channel_is(&ev, truth_channel)) {
            if (decode_list(&ev, truth) == 0) {
                have_truth = 1;
                /* truth after the track list of the same time */
                if (have_last && last->utime == truth->utime && evaluated != truth->utime) {
                    follow(last, truth, follow_ok, follow_n);
                    evaluated = truth->utime;
                }
            }
            continue;
        }
        if (o->status_channel[0] && lcmlog_channel_is(&ev, o->status_channel)) {
            int k = ev.data && ev.datalen <= INT32_MAX
                        ? trk_bridge_status_t_decode(ev.data, 0, (int)ev.datalen, &status)
                        : -1;
            if (k >= 0) have_status = 1;
            continue;
        }
        if (!lcmlog_channel_is(&ev, o->track_channel)) continue;
        if (decode_list(&ev, m) != 0) {
            n_bad++;
            continue;
        }
        n_lists++;
        if ((uint64_t)m->n_tracks > max_live) max_live = (uint64_t)m->n_tracks;
        for (int i = 0; i < m->n_tracks; i++) {
            const trk_track_t *t = &m->tracks[i];
            if (t->status != TRK_TRACK_T_STATUS_CONFIRMED) continue;
            size_t j = 0;
            while (j < n_ids && ids[j] != t->id) j++;
            if (j == n_ids && n_ids < ids_cap) ids[n_ids++] = t->id;
        }
        if (have_truth && truth->utime == m->utime && evaluated != m->utime) {
            follow(m, truth, follow_ok, follow_n);
            evaluated = m->utime;
        }
        *last = *m;
        have_last = 1;
    }
    if (got < 0) { /* a directory, a read error, not a log */
        fprintf(stderr, "trk-lcm-bridge: %s: %s\n", path, lcmlog_strerror(&r));
        free(m), free(truth), free(last), free(ids);
        lcmlog_close_read(&r);
        return -1;
    }
    fprintf(f, "log %s: %llu events", path, (unsigned long long)r.n_events);
    if (r.n_corrupt || r.truncated)
        fprintf(f, " (%llu corrupt records skipped%s)", (unsigned long long)r.n_corrupt,
                r.truncated ? ", truncated at the end" : "");
    fputc('\n', f);
    for (int i = 0; i < ncc; i++) print_channel(f, &cc[i]);
    fprintf(f, "track lists: %llu (undecodable %llu), at most %llu tracks in one list\n",
            (unsigned long long)n_lists, (unsigned long long)n_bad, (unsigned long long)max_live);
    fprintf(f, "confirmed track ids (%zu):", n_ids);
    for (size_t j = 0; j < n_ids && j < 40; j++) fprintf(f, " %lld", (long long)ids[j]);
    fprintf(f, "%s\n", n_ids > 40 ? " ..." : "");
    if (have_last) {
        int conf = 0, tent = 0;
        for (int i = 0; i < last->n_tracks; i++) {
            conf += last->tracks[i].status == TRK_TRACK_T_STATUS_CONFIRMED;
            tent += last->tracks[i].status == TRK_TRACK_T_STATUS_TENTATIVE;
        }
        /* confirmed tracks on top of another confirmed track (PDA tracks
         * sharing detections coalesce): within 5 m and 0.5 m/s */
        int dup = 0;
        for (int i = 0; i < last->n_tracks; i++) {
            const trk_track_t *t = &last->tracks[i];
            if (t->status != TRK_TRACK_T_STATUS_CONFIRMED) continue;
            for (int k = 0; k < i; k++) {
                const trk_track_t *u = &last->tracks[k];
                if (u->status == TRK_TRACK_T_STATUS_CONFIRMED &&
                    hypot(t->x[TRK_CV2_X] - u->x[TRK_CV2_X], t->x[TRK_CV2_Y] - u->x[TRK_CV2_Y]) < 5 &&
                    hypot(t->x[TRK_CV2_VX] - u->x[TRK_CV2_VX], t->x[TRK_CV2_VY] - u->x[TRK_CV2_VY]) < 0.5) {
                    dup++;
                    break;
                }
            }
        }
        fprintf(f, "last list (utime %lld, seq %lld): %d confirmed (%d duplicating another), %d tentative\n",
                (long long)last->utime, (long long)last->seq, conf, dup, tent);
        for (int i = 0; i < last->n_tracks; i++) {
            const trk_track_t *t = &last->tracks[i];
            if (t->status != TRK_TRACK_T_STATUS_CONFIRMED) continue;
            fprintf(f, "  track %-6lld x %9.1f m  y %9.1f m  vx %6.2f  vy %6.2f m/s  sd %.1f m  %d updates\n",
                    (long long)t->id, t->x[TRK_CV2_X], t->x[TRK_CV2_Y], t->x[TRK_CV2_VX], t->x[TRK_CV2_VY],
                    sqrt(0.5 * (t->p[TRK_CV2_P(TRK_CV2_X, TRK_CV2_X)] + t->p[TRK_CV2_P(TRK_CV2_Y, TRK_CV2_Y)])), t->n_updates);
        }
    }
    if (have_truth) {
        fprintf(f, "truth (%s): %d targets; scans with a confirmed track within 25 m:\n",
                truth_channel, truth->n_tracks);
        for (int g = 0; g < truth->n_tracks && g < MAX_TRUTH; g++)
            fprintf(f, "  target %d: %llu of %llu scans (%.0f %%)\n", g + 1,
                    (unsigned long long)follow_ok[g], (unsigned long long)follow_n[g],
                    follow_n[g] ? 100.0 * (double)follow_ok[g] / (double)follow_n[g] : 0.0);
    }
    if (have_status) {
        fprintf(f,
                "last bridge status: received %lld, processed %lld, rejected %lld (decode %lld, "
                "count %lld, capacity %lld, field %lld, sensor %lld, time %lld, gap %lld, "
                "other %lld), sequence gaps %lld, jumps %lld\n",
                (long long)status.n_received, (long long)status.n_processed,
                (long long)status.n_rejected, (long long)status.n_rejected_decode,
                (long long)status.n_rejected_count, (long long)status.n_rejected_capacity,
                (long long)status.n_rejected_field, (long long)status.n_rejected_sensor,
                (long long)status.n_rejected_time, (long long)status.n_rejected_gap,
                (long long)status.n_rejected_other, (long long)status.n_seq_gaps,
                (long long)status.n_seq_jumps);
        fprintf(f,
                "  detections dropped %lld (nonfinite %lld, field %lld, covariance %lld, "
                "amplitude %lld), below the amplitude threshold %lld\n",
                (long long)status.n_detections_rejected, (long long)status.n_detections_nonfinite,
                (long long)status.n_detections_field, (long long)status.n_detections_covariance,
                (long long)status.n_detections_amplitude,
                (long long)status.n_detections_below_threshold);
    }
    free(m);
    free(truth);
    free(last);
    free(ids);
    lcmlog_close_read(&r);
    return 0;
}
