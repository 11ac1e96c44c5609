"""Recorded detections for the tracker: trk-sim's detections.csv (columns
scan, time_s, x_m, y_m and optionally amplitude; one row per detection,
scans in order) as a list of scans.

    for s in trk.recorded.read_scans("build/demo-amplitude/detections.csv"):
        report, tracks = tk.process_scan(s.time_s, s.xy, amplitude=s.amplitude)
"""
import csv
from collections import namedtuple

import numpy as np

Scan = namedtuple("Scan", "scan time_s xy amplitude")


def read_scans(path):
    """The scans of the file: Scan(scan, time_s, xy (n x 2), amplitude (n,) or
    None). Scans without a detection have no row and are not in the list."""
    out = []
    with open(path, newline="") as f:
        rows = csv.reader(line for line in f if not line.startswith("#"))
        head = next(rows)
        col = {name: i for i, name in enumerate(head)}
        for need in ("scan", "time_s", "x_m", "y_m"):
            if need not in col:
                raise ValueError("%s: no column %s (columns: %s)" % (path, need, ", ".join(head)))
        ia = col.get("amplitude")
        cur, t, xy, amp = None, 0.0, [], []

        def flush():
            if cur is not None:
                out.append(Scan(cur, t, np.array(xy, dtype=float).reshape(-1, 2),
                                np.array(amp, dtype=float) if ia is not None else None))

        for line, r in enumerate(rows, 2):
            try:
                k = int(r[col["scan"]])
                if k != cur:
                    flush()
                    cur, t, xy, amp = k, float(r[col["time_s"]]), [], []
                xy.append((float(r[col["x_m"]]), float(r[col["y_m"]])))
                if ia is not None:
                    amp.append(float(r[ia]))
            except (ValueError, IndexError) as e:
                raise ValueError("%s:%d: %s" % (path, line, e))
        flush()
    return out
