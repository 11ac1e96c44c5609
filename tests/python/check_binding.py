"""The Python binding against the C side (tests/python_binding.sh).

  check_binding.py replay DETECTIONS.csv [--sigma M] [--q Q] [--lambda L]
                   [--pd PD] [--table AMP.tbl]
      the detections through trk.Tracker, every live track of every scan
      printed as build/bin/py-replay-csv prints it (%.17g: equal text is
      equal bits)
  check_binding.py layout      the layout table's invariants and the params
                               API (refusals name the field and the status)
  check_binding.py gospa PY_GOSPA DEMO_DIR
      trk.gospa against trk-sim's C GOSPA (build/bin/py-gospa) on random
      cases and on the demo's truth and confirmed tracks, scan by scan
  check_binding.py polar       a polar sensor on a moving platform through
                               Tracker.process_polar_scan: the same tracks, bit
                               for bit, as process_scan given the library's own
                               conversion (trk_polar_to_cartesian through
                               ctypes); nothing starts outside the coverage; a
                               still object seen from the moving platform stays
                               put; a scan beyond capacity is thinned and its
                               counts add up; clutter_at is the configured
                               density before any scan and the map's after;
                               the caller's densities equal to the map's give
                               the same tracks, bad ones are counted
  check_binding.py udpm        the UDP multicast reassembler on synthetic
                               datagrams (short, fragmented, reordered,
                               superseded, malformed)
"""
import argparse
import ctypes
import math
import sys

import numpy as np

import trk
from trk import recorded


def replay(a):
    p = trk.default_params()
    p.sensor[0].meas_cov_m2 = [a.sigma * a.sigma, 0, a.sigma * a.sigma]
    p.sensor[0].clutter_density_per_m2 = a.lam
    p.sensor[0].pd = a.pd
    p.process_noise_q = a.q
    if a.table:
        p.set_amplitude(0, trk.AmplitudeTable(a.table))
    tk = trk.Tracker(p)
    out = sys.stdout
    g = "%.17g"
    for s in recorded.read_scans(a.csv):
        r, tracks = tk.process_scan(s.time_s, s.xy, amplitude=s.amplitude)
        out.write("scan %d report %d %d %d %d %d %d %d %d %d\n" % (
            s.scan, r["n_detections"], r["n_tracks_updated"], r["n_tracks_hit"], r["n_started"],
            r["n_confirmed"], r["n_terminated"], r["n_merged"], r["n_replaced"], r["n_candidates"]))
        for t in tracks:
            vals = [float(v) for v in t["state"]] + [float(v) for v in t["covariance"].ravel()]
            vals += [float(t["existence"]), float(t["confidence"])]
            out.write("scan %d track %d %d %d %s\n" % (s.scan, t["id"], t["status"], t["end_reason"],
                                                       " ".join(g % v for v in vals)))


def expect_refusal(p, field, status):
    try:
        trk.Tracker(p)
    except trk.ParamError as e:
        assert e.field == field and e.status_name == status, "refusal %s %s, want %s %s" % (
            e.field, e.status_name, field, status)
        assert field in str(e) and status in str(e), str(e)
        return str(e)
    raise AssertionError("%s was not refused" % field)


def layout(_):
    st = trk.binding.ST
    # every member inside its struct, no two non-union members overlapping
    for s in st.values():
        for f in s.fields.values():
            assert f.offset + f.size * f.count <= s.size, (s.name, f.name)
        dt = s.dtype
        assert dt.itemsize == s.size
    # the known layout facts: the detection's first members, the track's id first
    real = trk.REAL.itemsize
    d = st["detection"].fields
    assert d["x_m"].offset == 0 and d["y_m"].offset == real and d["cov_m2"].count == 3
    assert st["track"].fields["id"].offset == 0
    assert st["tracker"].fields["track"].count == trk.MAX_TRACKS
    assert st["tracker_params"].fields["sensor"].count == trk.MAX_SENSORS
    # union members overlap: the confirmation methods' parameters start together
    pf = st["tracker_params"].fields
    assert pf["confirm.u.mn.m"].offset == pf["confirm.u.existence.p_confirm"].offset
    # defaults as the C side sets them (src/tracker_params.c)
    p = trk.default_params()
    assert p.gate_prob == float(np.array(0.99, trk.REAL)) and p.n_sensors == 1
    assert p.confirm.method == trk.CONFIRM_EXISTENCE and p.term.method == trk.TERM_EXISTENCE
    assert p.init.method == trk.INIT_TWO_POINT
    assert list(p.sensor[0].meas_cov_m2) == [1, 0, 1]
    q = trk.mn_kn_params()
    assert q.confirm.method == trk.CONFIRM_MN and q.confirm.u.mn.m == 3 and q.confirm.u.mn.n == 5
    # fields carry units and ranges
    info = {n: (u, r) for n, v, u, r in p.fields()}
    assert info["process_noise_q"] == ("m^2/s^3", ">= 0"), info["process_noise_q"]
    assert info["sensor[0].meas_cov_m2"][0] == "m^2"
    # refusals name the field and the status
    p = trk.default_params()
    p.gate_prob = 1.5
    msg = expect_refusal(p, "gate_prob", "TRK_E_RANGE")
    assert "(0, 1)" in msg, msg
    p = trk.default_params()
    p.sensor[0].meas_cov_m2 = [1, 2, 1]
    expect_refusal(p, "sensor[0].meas_cov_m2", "TRK_E_NOT_SPD")
    p = trk.default_params()
    p.process_noise_q = float("nan")
    expect_refusal(p, "process_noise_q", "TRK_E_NAN")
    p = trk.mn_kn_params()
    p.confirm.u.mn.m = 9
    expect_refusal(p, "confirm.u.mn", "TRK_E_RANGE")
    for bad in (("n_sensors", -1), ("n_sensors", 1.5), ("gate_prob", "x")):
        try:
            setattr(trk.default_params(), *bad)
        except ValueError:
            continue
        raise AssertionError("%s = %r accepted" % bad)
    try:
        trk.default_params().no_such_member = 1
        raise AssertionError("unknown member accepted")
    except AttributeError:
        pass
    # a refused scan raises and leaves the table as it was
    tk = trk.Tracker()
    tk.process_scan(10.0, [[0, 0]])
    try:
        tk.process_scan(5.0, [[0, 0]])
        raise AssertionError("a scan back in time was accepted")
    except trk.TrkError as e:
        assert e.status_name == "TRK_E_TIME", e
    try:
        tk.process_scan(11.0, np.zeros((trk.MAX_SCAN_DETECTIONS + 1, 2)))
        raise AssertionError("an oversized scan was accepted")
    except trk.TrkError as e:
        assert e.status_name == "TRK_E_CAPACITY", e
    # own covariances: a detection with a non-SPD one is counted, not used
    r, _ = tk.process_scan(12.0, [[0, 0], [50, 50]], cov=[[1, 0, 1], [1, 5, 1]])
    assert r["n_rejected_cov"] == 1 and r["n_detections"] == 2, r
    r, _ = tk.process_scan(13.0, [[0, 0]], cov=np.eye(2)[None] * 4)
    assert r["n_rejected_cov"] == 0
    # time conversion rounds half away from zero, as llround
    assert trk.time_us(2.5e-6) == 3 and trk.time_us(-2.5e-6) == -3 and trk.time_us(1.0) == 1000000
    print("layout: %d structs, params API and refusals ok (%s, %s)" % (len(st), trk.library_path, trk.REAL))


def gospa_cases(a):
    import csv
    import subprocess
    from trk.gospa import gospa
    rng = np.random.default_rng(11)
    cases = []
    for k in range(300):
        n, m = int(rng.integers(0, 9)), int(rng.integers(0, 9))
        x = rng.uniform(0, 200, (n, 2))
        y = np.concatenate([x[:min(n, m)] + rng.normal(0, 20, (min(n, m), 2)), rng.uniform(0, 200, (m - min(n, m), 2))])
        if k % 7 == 0 and n and m:
            y[0] = x[0] + [30, 40]  # exactly 50 m: at the cut-off, never assigned
        cases.append((x, y))
    # the demo's targets present and its confirmed tracks, scan by scan
    truth, est = {}, {}
    with open(a.demo + "/truth.csv") as f:
        for r in csv.DictReader(f):
            if int(r["present"]):
                truth.setdefault(int(r["scan"]), []).append((float(r["x_m"]), float(r["y_m"])))
    with open(a.demo + "/tracks.csv") as f:
        for r in csv.DictReader(f):
            if int(r["status"]) == 2:
                est.setdefault(int(r["scan"]), []).append((float(r["x_m"]), float(r["y_m"])))
    for k in sorted(truth):
        cases.append((np.array(truth[k]).reshape(-1, 2), np.array(est.get(k, [])).reshape(-1, 2)))
    c, p = 50.0, 2.0
    path = a.cases
    with open(path, "w") as f:
        f.write("%r %r\n" % (c, p))
        for x, y in cases:
            f.write("%d %d\n" % (len(x), len(y)))
            for v in list(x) + list(y):
                f.write("%r %r\n" % (float(v[0]), float(v[1])))
    out = subprocess.run([a.py_gospa, path], check=True, capture_output=True, text=True).stdout.split("\n")
    worst = 0.0
    for (x, y), line in zip(cases, out):
        want = line.split()
        r = gospa(x, y, c, p)
        assert [r.n_assigned, r.n_missed, r.n_false] == [int(v) for v in want[4:]], (line, r)
        for got, w in zip((r.gospa, r.loc, r.missed, r.false), want[:4]):
            err = abs(got - float(w)) / max(1.0, abs(float(w)))
            worst = max(worst, err)
            assert err <= 1e-12, (line, r)
    assert len([l for l in out if l]) == len(cases)
    print("gospa: %d cases (%d from the demo), Python and C agree (largest relative difference %.1e)" % (
        len(cases), len(cases) - 300, worst))


def udpm(_):
    from trk import lcm_udpm as u
    payload = bytes((i * 13) % 256 for i in range(10000))
    frags = u.fragment("TRK_TRACKS", payload, 5)
    assert len(frags) == 8, len(frags)
    r = u.Reassembler()
    # reordered fragments complete the message once
    got = [r.feed(d, "a") for d in frags[::-1]]
    assert got[:-1] == [None] * 7 and got[-1] == ("TRK_TRACKS", payload), got[-1]
    # a short message
    assert r.feed(u.fragment("S", b"abc", 6)[0], "a") == ("S", b"abc")
    # a message missing a fragment is dropped when the next one begins
    for d in frags[:3]:
        assert r.feed(d, "b") is None
    new = u.fragment("TRK_TRACKS", payload, 6)
    got = [r.feed(d, "b") for d in new]
    assert got[-1] == ("TRK_TRACKS", payload) and r.n_dropped == 1
    # two senders interleaved
    f2 = u.fragment("X", payload[::-1], 1)
    done = [m for pair in zip(frags, f2) for m in (r.feed(pair[0], "c"), r.feed(pair[1], "d")) if m]
    assert sorted(done) == sorted([("TRK_TRACKS", payload), ("X", payload[::-1])])
    # malformed: short, bad magic, no channel end, fragment beyond the payload
    for bad in (b"LC", b"XXXXxxxxchan\0", b"LC02\0\0\0\1nochannelend",
                frags[1][:8] + struct_pack(10000, 9990, 1, 8) + b"x" * 50):
        assert r.feed(bad, "e") is None
    assert r.n_bad == 4, r.n_bad
    assert r.n_short == 1 and r.n_fragmented == 4
    print("udpm: short, fragmented, reordered, interleaved, superseded and malformed datagrams as specified")


def struct_pack(size, offset, no, n):
    import struct
    return struct.pack(">IIHH", size, offset, no, n)


def polar_params(half_width_deg=60.0):
    p = trk.default_params()
    s = p.sensor[0]
    s.kind = trk.constants["SENSOR_POLAR"]
    s.sigma_range_m = 7.5
    s.sigma_bearing_rad = 1.5 * math.pi / 180
    s.pd = 0.9
    s.clutter_density_per_m2 = 1e-7
    s.coverage.max_range_m = 8000
    s.coverage.half_width_rad = half_width_deg * math.pi / 180
    p.stationary_d2 = 0  # the objects here stand still: targets, not persistent returns
    return p


def polar(_):
    B = trk.binding
    conv = B._c.trk_polar_to_cartesian
    conv.restype = ctypes.c_int
    conv.argtypes = [ctypes.c_void_p] * 4
    p = polar_params()
    sp = p._ptr(B.ST["tracker_params"].fields["sensor"].offset)
    rng = np.random.default_rng(5)
    ta, tb, te = trk.Tracker(p), trk.Tracker(p), trk.Tracker(p)
    pose = np.zeros(1, B.ST["pose"].dtype)
    pdet = np.zeros(1, B.ST["polar_detection"].dtype)
    det = np.zeros(1, B.ST["detection"].dtype)
    objects = [(1000.0, 4000.0, 2.0, -3.0), (-2500.0, 3000.0, 4.0, 1.0), (500.0, 6500.0, 0.0, 0.0)]
    n_conf = 0
    for k in range(40):
        t = 8.0 * k
        o = (0.0, 3.0 * t, 0.1 * math.sin(0.05 * k))  # the platform north at 3 m/s, its heading wandering
        r, b = [], []
        for (x0, y0, vx, vy) in objects:
            x, y = x0 + vx * t, y0 + vy * t
            r.append(math.hypot(x - o[0], y - o[1]) + 7.5 * rng.standard_normal())
            b.append(math.atan2(x - o[0], y - o[1]) - o[2] + 0.026 * rng.standard_normal())
        for _ in range(20):  # clutter over the sector
            r.append(500 + 7500 * rng.random())
            b.append((rng.random() - 0.5) * 2 * math.pi / 3)
        ra, rb_ = ta.process_polar_scan(t, r, b, pose=o)
        pose["x_m"], pose["y_m"], pose["heading_rad"] = o
        xy, cov = [], []
        for ri, bi in zip(r, b):
            pdet["range_m"], pdet["bearing_rad"] = ri, bi
            st = conv(sp, ctypes.c_void_p(pose.ctypes.data), ctypes.c_void_p(pdet.ctypes.data),
                      ctypes.c_void_p(det.ctypes.data))
            assert st == 0, st
            xy.append((det["x_m"][0], det["y_m"][0]))
            cov.append(det["cov_m2"][0].copy())
        rb, tb_ = tb.process_scan(t, xy, cov=cov, pose=o)
        assert ra == rb, (k, ra, rb)
        for f in rb_.dtype.names:
            assert np.array_equal(rb_[f], tb_[f]), (k, f, rb_[f], tb_[f])
        # the caller's densities equal to the tracker's own (its map's, before the scan): the same tracks
        lam = [te.clutter_at(x, y, pose=o) for (x, y) in xy]
        re_, te_ = te.process_polar_scan(t, r, b, pose=o, clutter_density=lam)
        assert re_ == ra, (k, re_, ra)
        for f in rb_.dtype.names:
            assert np.array_equal(rb_[f], te_[f]), (k, f, rb_[f], te_[f])
        n_conf = int((rb_["status"] == trk.constants["TRACK_CONFIRMED"]).sum())
    assert n_conf == 3, n_conf
    # the still object (the third) stays put though the platform moved 960 m
    still = [t for t in rb_ if abs(t["state"][0] - 500) < 100 and abs(t["state"][2] - 6500) < 100]
    assert len(still) == 1 and math.hypot(still[0]["state"][1], still[0]["state"][3]) < 0.5, still
    # nothing starts outside the coverage (beyond 8 km, or outside +-60 deg)
    tc = trk.Tracker(polar_params())
    for k in range(10):
        _, tr = tc.process_polar_scan(8.0 * k, [8500, 8500, 3000], [0.0, 0.2, 1.3])
        assert len(tr) == 0, tr
    # beyond capacity: thinned, the counts add up
    n = 2 * trk.MAX_DETECTIONS + 7
    rep, _ = tc.process_polar_scan(100.0, 500 + 7000 * rng.random(n), (rng.random(n) - 0.5) * 2)
    rejected = sum(v for k_, v in rep.items() if k_.startswith("n_rejected") or k_ == "n_below_threshold")
    assert rep["n_detections"] == n and rep["n_kept"] + rep["n_thinned"] + rejected == n, rep
    assert rep["n_kept"] == trk.MAX_DETECTIONS and rep["n_thinned"] > 0, rep
    # clutter_at: the configured density before any scan, the map's after
    td = trk.Tracker(polar_params())
    lam = float(np.asarray(1e-7, dtype=trk.REAL))
    assert td.clutter_at(0, 4000) == lam, td.clutter_at(0, 4000)
    for k in range(30):  # 30 detections per scan in one small patch, 4 km ahead
        td.process_polar_scan(8.0 * k, 4000 + 20 * rng.random(30), 0.002 * rng.random(30))
    hot, cold = td.clutter_at(0, 4010), td.clutter_at(0, 7000, pose=(0, 0, 0))
    assert hot > 10 * lam and 0 < cold < lam, (hot, cold)
    # a bad density rejects its detection only
    rep, _ = td.process_polar_scan(8.0 * 30, [3000, 4000, 5000], [0.0, 0.1, 0.2], clutter_density=[1e-7, np.nan, 0])
    assert rep["n_rejected_density"] == 2 and rep["n_kept"] == 1, rep
    print("polar: process_polar_scan gives the tracks of process_scan with the library's own "
          "conversion, bit for bit, 40 scans from a moving platform (3 confirmed, the still one at rest), and "
          "with the caller's densities equal to its map's; nothing "
          "starts outside the coverage; %d detections thinned to %d; clutter_at %.3g -> %.3g in a hot cell"
          % (n, trk.MAX_DETECTIONS, lam, hot))


def main():
    ap = argparse.ArgumentParser()
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("replay")
    r.add_argument("csv")
    r.add_argument("--sigma", type=float, default=5)
    r.add_argument("--q", type=float, default=1e-3)
    r.add_argument("--lambda", dest="lam", type=float, default=1e-6)
    r.add_argument("--pd", type=float, default=0.9)
    r.add_argument("--table")
    sub.add_parser("layout")
    g = sub.add_parser("gospa")
    g.add_argument("py_gospa")
    g.add_argument("demo")
    g.add_argument("cases")
    sub.add_parser("udpm")
    sub.add_parser("polar")
    a = ap.parse_args()
    {"replay": replay, "layout": layout, "gospa": gospa_cases, "udpm": udpm, "polar": polar}[a.cmd](a)


if __name__ == "__main__":
    main()
