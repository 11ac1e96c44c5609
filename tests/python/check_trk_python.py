"""check_trk_python.py DIR - the Python tools (tools/python) against trk's C
side, on files tests/python_tools.sh made in DIR:

  tracks.lcmlog    trk-sonar-sim --out -> trk-lcm-bridge --replay --keep-input
  summary.txt      trk-lcm-bridge --summarize tracks.lcmlog
  sonar.txt        trk-sonar-sim's output line; replay.txt the bridge's
  broken.lcmlog    written here: garbage, a corrupt header, a cut last record
  broken.txt       trk-lcm-bridge --summarize broken.lcmlog (run by the script
                   after this program's first pass: --broken-only)
  demo/            trk-sim demo-amplitude --no-plot CSV files
  bl.csv           trk-sim blanding-add-arl (strings and empty fields)

Every check compares a value the Python side computes with the value the C
side printed (or the file's own definition), and prints one line.
"""

import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "python"))

import lcmlog  # noqa: E402
import trk  # noqa: E402
import trkcsv  # noqa: E402
import trklog  # noqa: E402

N_CHECKS = 0


def check(cond, what, detail=""):
    global N_CHECKS
    if not cond:
        print("python-tools: FAIL: %s%s" % (what, (": " + detail) if detail else ""))
        sys.exit(1)
    N_CHECKS += 1
    print("python-tools: ok: %s" % what)


def read(path):
    with open(path) as f:
        return f.read()


def write_broken(src, dst):
    """src with 37 garbage bytes after the first record, a corrupt header
    (sync word, channel length 0) after the second, and the last record cut
    by 10 bytes."""
    evs = list(lcmlog.LogReader(src))
    data = open(src, "rb").read()
    # record boundaries from the events (28-byte header + channel + data)
    ends, pos = [], 0
    for ev in evs:
        pos += 28 + len(ev.channel.encode()) + len(ev.data)
        ends.append(pos)
    garbage = bytes((i * 7 + 3) % 251 for i in range(37))
    corrupt = bytes.fromhex("eda1da01") + bytes(24)
    out = data[:ends[0]] + garbage + data[ends[0]:ends[1]] + corrupt + data[ends[1]:len(data) - 10]
    with open(dst, "wb") as f:
        f.write(out)


def main(d, broken_only=False):
    log = os.path.join(d, "tracks.lcmlog")
    if broken_only:
        r = lcmlog.LogReader(os.path.join(d, "broken.lcmlog"))
        n = sum(1 for _ in r)
        c = read(os.path.join(d, "broken.txt"))
        m = re.search(r"^log \S+: (\d+) events \((\d+) corrupt records skipped, truncated at the end\)", c, re.M)
        check(m is not None, "the C summary of the broken log reports corrupt records and the cut end", c[:200])
        check((n, r.n_corrupt, r.truncated) == (int(m.group(1)), int(m.group(2)), True),
              "broken log: %d events, %d corrupt header, truncated, as the C reader counts" % (n, r.n_corrupt),
              "python %r, C %s" % ((n, r.n_corrupt, r.truncated), m.groups()))
        check(r.n_bytes_skipped == 37 + 24, "broken log: the 37 garbage bytes and the corrupt header's 24 "
              "skipped while resynchronising", str(r.n_bytes_skipped))
        return

    summary = read(os.path.join(d, "summary.txt"))
    # --- the log reader: events per channel as trk-lcm-bridge --summarize counts them
    r = lcmlog.LogReader(log)
    evs = list(r)
    m = re.search(r"^log \S+: (\d+) events$", summary, re.M)
    check(m and int(m.group(1)) == len(evs) == r.n_events and not r.truncated and r.n_corrupt == 0,
          "%d events, as the C reader counts" % len(evs))
    c_counts = {k: int(v) for k, v in re.findall(r"^  (TRK_\w+) +(\d+)$", summary, re.M)}
    py_counts = {}
    for ev in evs:
        py_counts[ev.channel] = py_counts.get(ev.channel, 0) + 1
    check(py_counts == c_counts and len(c_counts) == 4, "events per channel equal the C summary's: %s" % (
        ", ".join("%s %d" % kv for kv in sorted(py_counts.items()))), "python %r, C %r" % (py_counts, c_counts))
    # --- round trip: writing the events read gives the same bytes
    copy = os.path.join(d, "copy.lcmlog")
    with lcmlog.LogWriter(copy) as w:
        for ev in evs:
            w.write_event(ev)
    check(open(copy, "rb").read() == open(log, "rb").read(), "LogWriter rewrites the log byte for byte")

    # --- decoding: malformed scans refused as the bridge refuses them
    det = [(ev, msg) for ev, msg in trklog.messages(log, ("TRK_DETECTIONS",), errors=True)]
    bad = [str(msg) for _, msg in det if isinstance(msg, trklog.DecodeError)]
    rep = read(os.path.join(d, "replay.txt"))
    m = re.search(r"rejected (\d+) \(decode (\d+), count (\d+)", rep)
    check(m is not None, "the bridge's replay line names its rejections", rep[:300])
    check(len(bad) == int(m.group(2)) + int(m.group(3)),
          "%d detection messages refused by the decoder (C: decode %s + count %s)" % (len(bad), m.group(2),
                                                                                    m.group(3)), "; ".join(bad))
    lists = trklog.track_lists(log)
    truth = trklog.track_lists(log, "TRK_TRUTH")
    m = re.search(r"^track lists: (\d+) \(undecodable 0\), at most (\d+) tracks in one list", summary, re.M)
    check(m and len(lists) == int(m.group(1)) and max(x.n_tracks for x in lists) == int(m.group(2)),
          "%d track lists decoded, at most %d tracks in one, as in the C summary" % (
              len(lists), max(x.n_tracks for x in lists)))
    sonar = read(os.path.join(d, "sonar.txt"))
    m = re.search(r"(\d+) scans sent \((\d+) detections", sonar)
    check(m and sum(x.n_detections for x in lists) == int(m.group(2)),
          "the track lists' n_detections add up to trk-sonar-sim's %s detections" % (m.group(2) if m else "?"))
    m = re.search(r"tracks: started (\d+), confirmed (\d+), ended (\d+)", rep)
    py = (sum(x.n_started for x in lists), sum(x.n_confirmed for x in lists), sum(x.n_terminated for x in lists))
    check(m and py == tuple(int(v) for v in m.groups()),
          "started/confirmed/ended %d/%d/%d, the bridge's own counts" % py, rep[-300:])

    # --- the track table as numpy: confirmed ids, the last list, following the truth
    tr = trklog.tracks_array(lists)
    conf = tr[tr["status"] == trklog.CONFIRMED]
    ids = list(dict.fromkeys(conf["id"].tolist()))
    m = re.search(r"^confirmed track ids \((\d+)\):((?: \d+)*)", summary, re.M)
    check(m and ids == [int(v) for v in m.group(2).split()],
          "confirmed track ids %s in the order the C summary lists them" % ids)
    last = lists[-1]
    py_lines = ["  track %-6d x %9.1f m  y %9.1f m  vx %6.2f  vy %6.2f m/s  sd %.1f m  %d updates" % (
        t.id, t.x[0], t.x[2], t.x[1], t.x[3], math.sqrt(0.5 * (t.p[0] + t.p[10])), t.n_updates)
        for t in last.tracks[:last.n_tracks] if t.status == trk.track_t.STATUS_CONFIRMED]
    c_lines = re.findall(r"^  track .*updates$", summary, re.M)
    check(py_lines == c_lines and len(py_lines) >= 1,
          "the last list's %d confirmed tracks print as the C summary's lines" % len(py_lines),
          "\npython:\n%s\nC:\n%s" % ("\n".join(py_lines), "\n".join(c_lines)))
    # a target is followed in a scan when a confirmed track is within 25 m of it
    by_time = {x.utime: x for x in lists}
    n_tgt = truth[-1].n_tracks
    ok_n, n = [0] * n_tgt, [0] * n_tgt
    seen = set()
    for tl in truth:
        m_ = by_time.get(tl.utime)
        if m_ is None or tl.utime in seen:
            continue
        seen.add(tl.utime)
        for g in range(min(tl.n_tracks, n_tgt)):
            tx = tl.tracks[g].x
            n[g] += 1
            ok_n[g] += any(t.status == trk.track_t.STATUS_CONFIRMED and
                           math.hypot(t.x[0] - tx[0], t.x[2] - tx[2]) <= 25 for t in m_.tracks[:m_.n_tracks])
    py_follow = ["  target %d: %d of %d scans (%.0f %%)" % (g + 1, ok_n[g], n[g], 100.0 * ok_n[g] / n[g])
                 for g in range(n_tgt)]
    c_follow = re.findall(r"^  target \d+: .*%\)$", summary, re.M)
    check(py_follow == c_follow, "following the truth: %s, as the C summary" % "; ".join(
        s.strip() for s in py_follow), "\npython %r\nC %r" % (py_follow, c_follow))
    st = [msg for _, msg in trklog.messages(log, ("TRK_BRIDGE_STATUS",))][-1]
    py_status = ("last bridge status: received %d, processed %d, rejected %d (decode %d, count %d, capacity %d, "
                 "field %d, sensor %d, time %d, gap %d, other %d), sequence gaps %d, jumps %d" % (
                     st.n_received, st.n_processed, st.n_rejected, st.n_rejected_decode, st.n_rejected_count,
                     st.n_rejected_capacity, st.n_rejected_field, st.n_rejected_sensor, st.n_rejected_time,
                     st.n_rejected_gap, st.n_rejected_other, st.n_seq_gaps, st.n_seq_jumps))
    check(py_status in summary.splitlines(), "the last bridge status decodes to the C summary's line",
          py_status)

    # --- trk-sim CSV files with numpy
    dd = os.path.join(d, "demo")
    s = trkcsv.key_value(os.path.join(dd, "summary.csv"))
    det = trkcsv.read(os.path.join(dd, "detections.csv"))
    check(len(det) == s["detections"] and det["x_m"].dtype.kind == "f",
          "detections.csv: %d rows, summary.csv's detections" % len(det))
    err = trkcsv.read(os.path.join(dd, "errors.csv"))
    used = err.rows(in_rmse=1)
    rmse = math.sqrt(float((used["err_m"] ** 2).mean()))
    check(len(used) == s["rmse_samples"] and abs(rmse - s["rmse_m"]) <= 1e-4 * s["rmse_m"],
          "errors.csv: RMSE of its %d in_rmse rows %.5f m = summary.csv's rmse_m %.5f" % (len(used), rmse,
                                                                                        s["rmse_m"]))
    truth_csv = trkcsv.read(os.path.join(dd, "truth.csv"))
    tracks_csv = trkcsv.read(os.path.join(dd, "tracks.csv"))
    check(len(set(truth_csv["target"].tolist())) == s["targets"] and
          truth_csv["scan"].max() + 1 == s["scans"],
          "truth.csv: %d targets over %d scans, as summary.csv" % (s["targets"], s["scans"]))
    on_target = tracks_csv.rows(status=2)
    on_target = on_target["target"][on_target["target"] >= 0]
    check(len(set(on_target.tolist())) == s["true"],
          "tracks.csv: confirmed tracks on %d distinct targets, summary.csv's true" % s["true"])
    bl = trkcsv.read(os.path.join(d, "bl.csv"))
    kinds = list(dict.fromkeys(bl["test"].tolist()))
    kn = bl.rows(test="kn")
    page = bl.rows(test="page")
    check(bl["test"].dtype.kind == "U" and kinds == ["page", "shiryaev", "kn"] and
          bool((kn["k"] >= 0).all()) and bool((page["k"] != page["k"]).all()) and bl.params.get("runs") == 40,
          "bl.csv: test column str (page, shiryaev, kn), k empty (NaN) for Page, runs 40 from its comment",
          "%r %r %r" % (kinds, bl.params, page["k"][:3]))
    write_broken(log, os.path.join(d, "broken.lcmlog"))
    print("python-tools: %d checks passed" % N_CHECKS)


if __name__ == "__main__":
    main(sys.argv[1], "--broken-only" in sys.argv[2:])
