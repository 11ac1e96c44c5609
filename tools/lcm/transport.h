/* transport.h - trk-lcm-bridge's two ways to move bytes: live LCM
 * (subscribe / publish on any provider: udpm://, memq://, file://) and
 * offline log replay (LCM log file in, LCM log file out, deterministic). */
#ifndef TRK_LCM_TRANSPORT_H
#define TRK_LCM_TRANSPORT_H

#include <signal.h>
#include <stdint.h>

#include <lcm/lcm.h>

#include "bridge.h"

/* Monotonic and wall-clock time, microseconds. */
int64_t bridge_mono_us(void);
int64_t bridge_wall_us(void);

/* ------------------------------------------------------------------ live */

struct bridge_live {
    lcm_t *lc;
    lcm_subscription_t *sub;
    lcm_subscription_t *sub_polar;  /* the polar detection channel (NULL: none) */
    struct bridge *b;
    int64_t next_status_us;     /* monotonic time of the next status message */
};

/* Subscribe b to its detection channels (Cartesian, and polar unless "") on lc (the caller owns lc).
 * 0, or -1 when the subscription fails. */
int bridge_live_attach(struct bridge_live *l, lcm_t *lc, struct bridge *b);
void bridge_live_detach(struct bridge_live *l);

/* Handle messages until *stop becomes non-zero (signal handler), max_scans
 * scans were processed (0: no limit), or, with idle_exit_s > 0, nothing
 * arrived for that long. Each accepted scan's track list is published on
 * the track channel; the status on the status channel every
 * status_period_s and once when the loop ends. 0, or -1 on an LCM error. */
int bridge_live_run(struct bridge_live *l, volatile sig_atomic_t *stop, uint64_t max_scans,
                    double idle_exit_s);

/* Publish one status message now (wall-clock utime). */
void bridge_live_publish_status(struct bridge_live *l);

/* ------------------------------------------------------------------ replay */

struct replay_stats {
    uint64_t events;            /* events read from the input log */
    uint64_t scans;             /* ... on the detection channels (Cartesian and polar) */
    uint64_t oversize;          /* ... too large to be a scan (skipped, counted as decode) */
    uint64_t written;           /* events written to the output log */
    uint64_t corrupt;           /* corrupt record headers skipped */
    uint64_t bytes_skipped;     /* bytes skipped while resynchronising */
    int truncated;              /* the input ended inside a record */
};

/* Read the LCM log `in`, run every message of the detection channels (a
 * polar channel's with bridge_handle_polar) through
 * the bridge, write each track list (and the status every status_period_s
 * of log time, and once at the end) to the log `out`. Output events carry
 * the timestamp of the input event that produced them, so the same input
 * gives a byte-identical output. keep_input: also copy every input event
 * (all channels) to the output, before what it produced. *stop (may be
 * NULL) ends the replay early; the output is still a valid log.
 * 0, or -1 with a message (cannot open/read/write, in == out, an input
 * that is no log: empty, a directory, no complete record; then no output
 * log is created). */
int bridge_replay(struct bridge *b, const char *in, const char *out, int keep_input,
                  volatile sig_atomic_t *stop, struct replay_stats *st, char *err, size_t errlen);

#endif
