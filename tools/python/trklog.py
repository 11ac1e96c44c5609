"""trklog - trk's LCM messages in a log file: decode them with the lcm-gen -p
types (package trk, next to this file) and turn the track lists into numpy
arrays.

    import trklog
    for ev, msg in trklog.messages("tracks.lcmlog"):     # every trk message, decoded
        ...
    tr = trklog.tracks_array("tracks.lcmlog")            # one row per (list, track)
    confirmed = tr[tr["status"] == trklog.CONFIRMED]

Decoding follows trk's C side (tools/lcm/lcm_copy.c, the bridge's summary): a
message must be exactly one message of its type (no trailing bytes) and its
count fields must lie within the fixed arrays; otherwise DecodeError. The
message types are recognised by their LCM fingerprint, whatever the channel.

Standard library and the generated types; numpy for tracks_array only.
"""

import io
import struct

import lcmlog
import trk

__all__ = ["CHANNELS", "TYPES", "TENTATIVE", "CONFIRMED", "TERMINATED", "DecodeError", "decode", "decode_any",
           "messages", "track_lists", "tracks_array", "TRACK_FIELDS", "track_dtype"]

# the channels trk's programs use by default, and their types
CHANNELS = {
    "TRK_DETECTIONS": trk.detection_scan_t,     # trk-sonar-sim -> trk-lcm-bridge
    "TRK_DETECTIONS_POLAR": trk.detection_scan_polar_t,  # trk-sonar-sim --polar: range, bearing, pose
    "TRK_TRUTH": trk.track_list_t,              # trk-sonar-sim: the targets' true states
    "TRK_TRACKS": trk.track_list_t,             # trk-lcm-bridge: the track table after every scan
    "TRK_BRIDGE_STATUS": trk.bridge_status_t,   # trk-lcm-bridge: health counters
}
TYPES = {cls._get_packed_fingerprint(): cls
         for cls in (trk.detection_scan_t, trk.detection_scan_polar_t, trk.track_list_t, trk.bridge_status_t,
                     trk.track_t, trk.detection_t, trk.polar_detection_t)}

TENTATIVE = trk.track_t.STATUS_TENTATIVE
CONFIRMED = trk.track_t.STATUS_CONFIRMED
TERMINATED = trk.track_t.STATUS_TERMINATED


class DecodeError(ValueError):
    """The bytes are not exactly one valid message of the type."""


def _check(msg):
    if isinstance(msg, trk.track_list_t) and not 0 <= msg.n_tracks <= trk.track_list_t.MAX_TRACKS:
        raise DecodeError("n_tracks = %d outside 0 .. %d" % (msg.n_tracks, trk.track_list_t.MAX_TRACKS))
    if isinstance(msg, trk.detection_scan_t) and not 0 <= msg.n_detections <= trk.detection_scan_t.MAX_DETECTIONS:
        raise DecodeError("n_detections = %d outside 0 .. %d" % (msg.n_detections,
                                                                trk.detection_scan_t.MAX_DETECTIONS))
    if isinstance(msg, trk.detection_scan_polar_t) and \
            not 0 <= msg.n_detections <= trk.detection_scan_polar_t.MAX_DETECTIONS:
        raise DecodeError("n_detections = %d outside 0 .. %d" % (msg.n_detections,
                                                                trk.detection_scan_polar_t.MAX_DETECTIONS))
    return msg


def decode(cls, data):
    """cls.decode(data), refusing a wrong fingerprint, truncated data,
    trailing bytes and counts beyond the fixed arrays (DecodeError)."""
    if data is None:
        raise DecodeError("no data (message larger than the reader's max_data)")
    buf = io.BytesIO(data)
    try:
        msg = cls.decode(buf)
    except (ValueError, struct.error) as e:
        raise DecodeError("does not decode as trk.%s (%d bytes): %s" % (cls.__name__, len(data), e)) from None
    if buf.tell() != len(data):
        raise DecodeError("trk.%s with %d trailing bytes" % (cls.__name__, len(data) - buf.tell()))
    return _check(msg)


def decode_any(data):
    """The message of whichever trk type the data's fingerprint names."""
    cls = TYPES.get(bytes(data[:8])) if data is not None else None
    if cls is None:
        raise DecodeError("not a trk message (unknown fingerprint)")
    return decode(cls, data)


def messages(path, channels=None, errors=False):
    """(event, message) for every event of the log on one of `channels` (a
    collection of names; None: every event whose fingerprint is a trk type).
    Undecodable events are left out, or with errors=True given as
    (event, DecodeError)."""
    with lcmlog.LogReader(path) as r:
        for ev in r:
            if channels is not None and ev.channel not in channels:
                continue
            try:
                msg = decode_any(ev.data)
            except DecodeError as e:
                if errors:
                    yield ev, e
                continue
            yield ev, msg


def track_lists(path, channel="TRK_TRACKS"):
    """The decodable trk.track_list_t messages of one channel, in log order."""
    return [m for _, m in messages(path, (channel,)) if isinstance(m, trk.track_list_t)]


TRACK_FIELDS = [
    ("utime", "i8"), ("seq", "i8"), ("id", "i8"), ("status", "i1"), ("end_reason", "i1"),
    ("x_m", "f8"), ("vx_mps", "f8"), ("y_m", "f8"), ("vy_mps", "f8"),
    ("sd_x_m", "f8"), ("sd_y_m", "f8"), ("sd_m", "f8"),
    ("existence_prob", "f8"), ("visibility_prob", "f8"),
    ("n_updates", "i4"), ("n_hits", "i4"), ("n_misses_in_row", "i4"),
]


def track_dtype():
    """The numpy dtype of tracks_array's rows."""
    import numpy as np
    return np.dtype(TRACK_FIELDS)


def tracks_array(path_or_lists, channel="TRK_TRACKS"):
    """One row per (track list, track) of the channel, as a numpy structured
    array (fields TRACK_FIELDS; state [x, vx, y, vy]; sd_m = sqrt((P_xx +
    P_yy) / 2), the bridge summary's "sd"; existence/visibility NaN when the
    message has none). Accepts a log path or a list of track_list_t."""
    import numpy as np
    lists = track_lists(path_or_lists, channel) if isinstance(path_or_lists, (str, bytes)) or hasattr(
        path_or_lists, "__fspath__") else path_or_lists
    rows = []
    nan = float("nan")
    for m in lists:
        for t in m.tracks[:m.n_tracks]:
            pxx, pyy = t.p[0], t.p[10]
            rows.append((m.utime, m.seq, t.id, t.status, t.end_reason, t.x[0], t.x[1], t.x[2], t.x[3],
                         pxx ** 0.5 if pxx >= 0 else nan, pyy ** 0.5 if pyy >= 0 else nan,
                         (0.5 * (pxx + pyy)) ** 0.5 if pxx + pyy >= 0 else nan,
                         t.existence_prob if t.has_existence_prob else nan,
                         t.visibility_prob if t.has_visibility_prob else nan,
                         t.n_updates, t.n_hits, t.n_misses_in_row))
    return np.array(rows, dtype=track_dtype())
