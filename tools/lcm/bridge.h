/* bridge.h - the core of trk-lcm-bridge, free of any transport: bytes of a
 * detection_scan_t (or of a detection_scan_polar_t, bridge_handle_polar) in,
 * bytes of a track_list_t out, counters and
 * rate-limited logging of rejections. The live LCM loop and the log replay
 * (transport.h) both drive it; so do the tests and trk-bench.
 *
 * One message (bridge_handle):
 *   decode with the fixed-size generated decoder and validate (lcm_copy.h)
 *   -> trk_tracker_process_scan -> track list encoded into an internal buffer
 * Any rejection (the message, or the tracker's refusal of the scan) leaves
 * the tracker untouched, is counted by cause, and is logged: the first time
 * a cause occurs at once, then at most once per log_interval_s with the
 * number suppressed in between. The next message is processed normally.
 * A bad detection drops only itself (counted by reason, logged the same
 * way); the rest of its scan is processed. Detections the tracker drops
 * (non-SPD own covariance, bad amplitude) and those below the amplitude
 * threshold are counted too. */
#ifndef TRK_LCM_BRIDGE_H
#define TRK_LCM_BRIDGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "lcm_copy.h"
#include "tracker_config.h"

#define BRIDGE_DEFAULT_DETECTIONS "TRK_DETECTIONS"
#define BRIDGE_DEFAULT_POLAR_DETECTIONS "TRK_DETECTIONS_POLAR"
#define BRIDGE_DEFAULT_TRACKS "TRK_TRACKS"
#define BRIDGE_DEFAULT_STATUS "TRK_BRIDGE_STATUS"
#define BRIDGE_CHANNEL_MAX 256

/* Rate-limited log slots: one per rejection reason, then these. */
enum { BRIDGE_LOG_PUBLISH = LCMC_N_REASONS, BRIDGE_LOG_DETECTION, BRIDGE_LOG_SLOTS };

/* A forward step of a sensor's seq by more than this many missing scans
 * (hours of pings) is a restart or a corrupt number: one jump, not lost
 * scans. */
#define BRIDGE_SEQ_GAP_MAX 10000

struct bridge_opts {
    char lcm_url[512];                          /* "" = LCM_DEFAULT_URL / LCM default */
    char detection_channel[BRIDGE_CHANNEL_MAX];
    char polar_detection_channel[BRIDGE_CHANNEL_MAX]; /* detection_scan_polar_t; "" = none */
    char track_channel[BRIDGE_CHANNEL_MAX];
    char status_channel[BRIDGE_CHANNEL_MAX];    /* "" = no status messages */
    double status_period_s;                     /* >= 0; 0 = only at exit */
    double log_interval_s;                      /* >= 0 */
    int quiet;                                  /* no rejection messages */
    FILE *log;                                  /* rejection messages (stderr) */
};

/* Defaults: channels TRK_DETECTIONS / TRK_DETECTIONS_POLAR / TRK_TRACKS / TRK_BRIDGE_STATUS,
 * status every 1 s, rejection messages at most every 10 s per cause. */
void bridge_opts_defaults(struct bridge_opts *o);

/* Bridge keys of the config file (a kv_setter, ctx = struct bridge_opts *):
 * lcm_url, detection_channel, polar_detection_channel, track_channel, status_channel,
 * status_period_s, log_interval_s. An unknown key: 1, the nearest of them
 * in err (or ""). */
int bridge_opts_set(void *ctx, const char *key, const char *value, char *err, size_t errlen);
void bridge_opts_write(FILE *f, const struct bridge_opts *o);

struct bridge_counts {
    uint64_t received;                    /* messages handed to bridge_handle */
    uint64_t processed;                   /* scans accepted by the tracker */
    uint64_t rejected;                    /* sum of by_reason[1..] */
    uint64_t by_reason[LCMC_N_REASONS];
    uint64_t seq_gaps;                    /* scans missing by sequence number (steps of
                                             2 .. BRIDGE_SEQ_GAP_MAX + 1) */
    uint64_t seq_jumps;                   /* seq repeated, went back or jumped further */
    uint64_t det_rejected;                /* detections dropped inside accepted scans:
                                             the sum of the four below */
    uint64_t det_nonfinite;               /* NaN/inf or out-of-range used field */
    uint64_t det_field;                   /* boolean not 0/1, negative amplitude, a position
                                             outside the tracker's max_coord_m */
    uint64_t det_cov;                     /* own covariance not SPD (tracker) */
    uint64_t det_amplitude;               /* amplitude refused by the tracker */
    uint64_t det_below_threshold;         /* below the sensor's amplitude threshold */
    uint64_t started, confirmed, terminated, refused_full;
    uint64_t publish_errors;              /* transport: failed publishes / writes */
};

struct bridge {
    struct bridge_opts o;
    struct tcfg cfg;
    struct tcfg_runtime rt;        /* amplitude tables and models of the run */
    struct bridge_counts c;
    int64_t last_seq[TRK_MAX_SENSORS];
    int has_seq[TRK_MAX_SENSORS];
    int64_t last_accepted_seq, last_accepted_utime; /* -1 before the first */
    struct trk_scan_report last_report;
    /* rate-limited log */
    int64_t log_last_us[BRIDGE_LOG_SLOTS];
    uint64_t log_suppressed[BRIDGE_LOG_SLOTS];
    int log_used[BRIDGE_LOG_SLOTS];
    /* buffers (the structs are large: struct bridge lives on the heap) */
    trk_detection_scan_t in;
    trk_detection_scan_polar_t in_polar;
    struct lcmc_scan scan;
    trk_track_list_t out;
    uint8_t *out_buf;
    size_t out_cap;
    trk_bridge_status_t status;
    uint8_t *status_buf;
    size_t status_cap;
    struct trk_tracker tk;
};

/* Check cfg (tcfg_check) and create a bridge with a fresh tracker.
 * NULL with a message on a bad configuration or no memory. */
struct bridge *bridge_new(const struct tcfg *cfg, const struct bridge_opts *o, char *err,
                          size_t errlen);
void bridge_free(struct bridge *b);

/* Handle one message of the detection channel. now_us: the clock of the
 * rate-limited log (monotonic in live mode, log time in replay). On LCMC_OK
 * *out / *out_len is the encoded track_list_t to publish (valid until the
 * next call); otherwise the reason it was rejected. */
enum lcmc_reason bridge_handle(struct bridge *b, const void *data, size_t len, int64_t now_us,
                               const void **out, size_t *out_len);

/* The same for one message of the polar detection channel
 * (detection_scan_polar_t: its sensor must be configured polar). */
enum lcmc_reason bridge_handle_polar(struct bridge *b, const void *data, size_t len, int64_t now_us,
                                     const void **out, size_t *out_len);

/* Encode the status message (utime as given) into an internal buffer. */
void bridge_status(struct bridge *b, int64_t utime, const void **out, size_t *out_len);

/* Log a transport problem (rate-limited like the rejections). */
void bridge_log_publish_error(struct bridge *b, int64_t now_us, const char *what);

/* Print the rejections suppressed since their last message. */
void bridge_log_flush(struct bridge *b);

/* The summary printed at exit (one paragraph). */
void bridge_summary(const struct bridge *b, FILE *f);

#endif
