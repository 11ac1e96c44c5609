/* scan.c - a scan set up whole (trk_scan_init, trk_scan_init_polar in
 * trk/tracker.h): every member written, so that a scan built field by
 * field in a struct on the stack never carries an indeterminate member. */
#include <string.h>

#include "trk/tracker.h"

void trk_scan_init(struct trk_scan *scan, int64_t time_us, unsigned sensor_id, size_t n_detections,
                   const struct trk_detection *detections)
{
    if (!scan) return;
    memset(scan, 0, sizeof *scan);
    scan->time_us = time_us;
    scan->sensor_id = sensor_id;
    scan->n_detections = n_detections;
    scan->detections = detections;
}

void trk_scan_init_polar(struct trk_scan *scan, int64_t time_us, unsigned sensor_id, size_t n_detections,
                         const struct trk_polar_detection *polar, const struct trk_pose *pose)
{
    if (!scan) return;
    memset(scan, 0, sizeof *scan);
    scan->time_us = time_us;
    scan->sensor_id = sensor_id;
    scan->n_detections = n_detections;
    scan->polar = polar;
    if (pose) {
        scan->has_pose = 1;
        scan->pose = *pose;
    }
}
