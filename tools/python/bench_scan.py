#!/usr/bin/env python3
"""bench_scan.py - the cost of a scan through Python against the C call
(make bench-python; docs/python.md).

    python3 tools/python/bench_scan.py --c-replay build/bin/py-replay-csv [--scans 200] [--rounds 3]

The setting of trk-bench's scan_64x256: 64 targets on a grid over
1200 m x 1200 m moving at 1-3 m/s, each detected with P_D 0.9 (sigma 1 m),
and uniform clutter filling each scan to 256 detections; the tracker's
defaults with that sensor (clutter density 192 / 1200^2 per m^2,
q 0.01). The scans are written to a CSV file and run
  - by the C program (py-replay-csv --bench): trk_tracker_process_scan alone,
    timed around the call;
  - through trk.Tracker.process_scan (numpy arrays in, the report and the
    tracks' structured array out), timed around the Python call;
  - through ctypes alone (the scan built once per scan outside the timing:
    the call's own overhead).
The best of --rounds (alternating) of each; prints ns per scan and the ratio Python / C.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from needs import need, run_main  # noqa: E402

np = need("bench_scan.py", "numpy")
import trk  # noqa: E402
from trk import recorded  # noqa: E402

SIDE, NT, ND, SIGMA, Q = 1200.0, 64, 256, 1.0, 0.01


def scenario(n_scans, seed=1):
    rng = np.random.default_rng(seed)
    g = int(np.ceil(np.sqrt(NT)))
    pos = np.array([((i % g + 0.5) * SIDE / g, (i // g + 0.5) * SIDE / g) for i in range(NT)])
    ang = rng.uniform(0, 2 * np.pi, NT)
    vel = rng.uniform(1, 3, NT)[:, None] * np.stack([np.cos(ang), np.sin(ang)], axis=1)
    rows = []
    for k in range(n_scans):
        p = pos + vel * k
        det = p[rng.random(NT) < 0.9]
        det = det + rng.normal(0, SIGMA, det.shape)
        clutter = rng.uniform(0, SIDE, (ND - len(det), 2))
        for x, y in np.concatenate([det, clutter]):
            rows.append("%d,%.1f,%.6f,%.6f\n" % (k, float(k), x, y))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--c-replay", required=True, help="build/bin/py-replay-csv")
    ap.add_argument("--scans", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=5)
    a = ap.parse_args()
    if trk.library_error:
        sys.exit("bench_scan: %s" % trk.library_error)
    lam = (ND - 0.9 * NT) / (SIDE * SIDE)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "scans.csv")
        with open(path, "w") as f:
            f.write("scan,time_s,x_m,y_m\n")
            f.writelines(scenario(a.scans))
        scans = recorded.read_scans(path)
        p = trk.default_params()
        p.sensor[0].meas_cov_m2 = [SIGMA ** 2, 0, SIGMA ** 2]
        p.sensor[0].clutter_density_per_m2 = lam
        p.sensor[0].pd = 0.9
        p.process_noise_q = Q
        c_ns, py_ns, raw_ns, live = [], [], [], 0
        for _ in range(a.rounds):  # the three alternate: a shared machine's load hits each alike
            out = subprocess.run([a.c_replay, path, "--bench", "--sigma", repr(SIGMA), "--q", repr(Q),
                                  "--lambda", repr(lam), "--pd", "0.9"], check=True, capture_output=True,
                                 text=True).stdout.split()
            c_ns.append(float(out[out.index("c_scan_ns") + 1]))
            tk = trk.Tracker(p)
            t = 0.0
            for s in scans:
                t0 = time.perf_counter()
                _, tracks = tk.process_scan(s.time_s, s.xy)
                t += time.perf_counter() - t0
            live = len(tracks)
            py_ns.append(t / len(scans) * 1e9)
            # the bare ctypes call: the detections written outside the timing
            tk = trk.Tracker(p)
            t = 0.0
            for s in scans:
                n = len(s.xy)
                tk._det["x_m"][:n] = s.xy[:, 0]
                tk._det["y_m"][:n] = s.xy[:, 1]
                tk._det["has_cov"][:n] = 0
                tk._det["has_amplitude"][:n] = 0
                tk._scan["time_us"] = trk.time_us(s.time_s)
                tk._scan["n_detections"] = n
                t0 = time.perf_counter()
                st = tk._process(tk._tk, tk._scan_p, tk._report_p)
                t += time.perf_counter() - t0
                assert st == 0
            raw_ns.append(t / len(scans) * 1e9)
    c, py, raw = min(c_ns), min(py_ns), min(raw_ns)
    print("bench python_scan_64x256_c %.0f ns (trk_tracker_process_scan in C, %d scans, %d live tracks at the end, "
          "%s)" % (c, len(scans), live, trk.REAL))
    print("bench python_scan_64x256_ctypes %.0f ns (the same call through ctypes)" % raw)
    print("bench python_scan_64x256_python %.0f ns (trk.Tracker.process_scan: numpy in, report and tracks out)" % py)
    print("bench python_scan_64x256_ratio %.3f x (Python / C)" % (py / c))
    print("bench python_scan_64x256_overhead %.0f ns per scan" % (py - c))


if __name__ == "__main__":
    run_main("bench_scan.py", main)
