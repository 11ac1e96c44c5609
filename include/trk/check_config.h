/** @file
 * trk/check_config.h - reject impossible configurations at compile time.
 * Included by config.h after the defaults; each `#error` says how to fix it. */
#ifndef TRK_CHECK_CONFIG_H
#define TRK_CHECK_CONFIG_H

#if TRK_MAX_TRACKS < 1 || TRK_MAX_TRACKS > 65535
#error "TRK_MAX_TRACKS must be in 1..65535 (track slots are indexed by uint16_t); set -DTRK_MAX_TRACKS=64"
#endif
#if TRK_MAX_DETECTIONS < 1 || TRK_MAX_DETECTIONS > 65535
#error "TRK_MAX_DETECTIONS must be in 1..65535 (detections are indexed by uint16_t); set -DTRK_MAX_DETECTIONS=256"
#endif
#if TRK_MAX_CANDIDATES < 1 || TRK_MAX_CANDIDATES > 65535
#error "TRK_MAX_CANDIDATES must be in 1..65535 (initiation candidates are indexed by uint16_t); set -DTRK_MAX_CANDIDATES=256 (default: TRK_MAX_DETECTIONS)"
#endif
#if TRK_MAX_SENSORS < 1 || TRK_MAX_SENSORS > 255
#error "TRK_MAX_SENSORS must be in 1..255 (sensor ids are uint8_t); set -DTRK_MAX_SENSORS=4"
#endif
#if TRK_MAX_STATE < 4
#error "TRK_MAX_STATE must be at least 4: the tracker's 2-D constant-velocity state is [x, vx, y, vy]"
#endif
#if TRK_MAX_MEAS < 2
#error "TRK_MAX_MEAS must be at least 2: the tracker measures [x, y]"
#endif
#if TRK_MAX_MEAS > TRK_MAX_STATE
#error "TRK_MAX_MEAS must not exceed TRK_MAX_STATE"
#endif
#if TRK_MAX_MEAS > 3
#error "TRK_MAX_MEAS above 3 is not supported: gate.h has gamma and volume only for nz = 1, 2, 3"
#endif

#if TRK_WITH_CLUTTER_TESTS != 0 && TRK_WITH_CLUTTER_TESTS != 1
#error "TRK_WITH_CLUTTER_TESTS must be 0 or 1; set -DTRK_WITH_CLUTTER_TESTS=1"
#endif

#endif
