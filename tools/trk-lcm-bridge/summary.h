/* summary.h - trk-lcm-bridge --summarize LOG (summary.c): the tool's own,
 * over the bridge's log reader (tools/lcm). */
#ifndef TRK_LCM_BRIDGE_SUMMARY_H
#define TRK_LCM_BRIDGE_SUMMARY_H

#include <stdio.h>

struct bridge_opts;

/* Summarise a log written by the bridge (or any log with its channels):
 * events per channel, track lists, confirmed track ids, the last status,
 * and, when truth lists (track_list_t on truth_channel, as trk-sonar-sim
 * writes them) are present, how well confirmed tracks follow the targets.
 * 0, or -1 when the log cannot be read. */
int bridge_summarize(const char *path, const struct bridge_opts *o, const char *truth_channel,
                     FILE *f);

#endif
