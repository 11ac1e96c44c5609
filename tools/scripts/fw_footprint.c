/* fw_footprint.c - a typical sonar firmware's use of libtrk, linked (never
 * run) by mk/size.mk with --gc-sections to measure what such an image pays
 * for libtrk: the tracker (init, scan, track list) with amplitude-aided
 * association from a lookup table in ROM (trk_table_parse,
 * trk_amplitude_init_table, trk_amplitude_log_lr) and the status names.
 * The library's design-time analysis functions (q2, MRE, CRLB, ROC
 * optimisation) are not linked by such an image. */
#include "trk/trk.h"
#include "trk/amplitude.h"
#include "trk/table.h"

static struct trk_tracker tracker;
static struct trk_detection det[TRK_MAX_DETECTIONS];
static struct trk_amplitude amp;
extern const unsigned char *volatile fw_table_bytes; /* supplied by the image */
const unsigned char *volatile fw_table_bytes;
volatile size_t fw_table_len;
volatile trk_real fw_sink;
volatile const char *fw_name;

int main(void);
int main(void)
{
    struct trk_tracker_params p;
    struct trk_table t;
    trk_tracker_default_params(&p);
    if (trk_tracker_init(&tracker, &p) != TRK_OK) return 1;
    if (trk_table_parse(&t, fw_table_bytes, fw_table_len) == TRK_OK &&
        trk_amplitude_init_table(&amp, &t) == TRK_OK) {
        for (size_t i = 0; i < TRK_MAX_DETECTIONS; i++) {
            trk_real llr;
            if (trk_amplitude_log_lr(&amp, det[i].amplitude, &llr) == TRK_OK) fw_sink = llr;
        }
    }
    for (int64_t k = 0;; k++) {
        struct trk_scan scan = {k * 1000000, 0, TRK_MAX_DETECTIONS, det, NULL, 0, {0, 0, 0}, NULL};
        struct trk_scan_report rep;
        trk_status st = trk_tracker_process_scan(&tracker, &scan, &rep);
        fw_name = trk_status_str(st);
        for (size_t i = 0; i < TRK_MAX_TRACKS; i++) {
            const struct trk_track *tr = trk_tracker_track(&tracker, i);
            if (tr) fw_sink = tr->x[TRK_CV2_X];
        }
    }
}
