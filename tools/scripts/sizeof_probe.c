/* sizeof_probe.c - compiled (never run) with a cross compiler by mk/size.mk:
 * each array's size, read back with nm -S, is the sizeof of a trk type on
 * that target and configuration. */
#include "trk/trk.h"

char trk_sizeof_tracker[sizeof(struct trk_tracker)];
char trk_sizeof_track[sizeof(struct trk_track)];
char trk_sizeof_tracker_ws[sizeof(((struct trk_tracker *)0)->ws)];
char trk_sizeof_detection[sizeof(struct trk_detection)];
char trk_sizeof_scan_detections[sizeof(struct trk_detection) * TRK_MAX_DETECTIONS];
