#!/usr/bin/env python3
"""plot_track_log.py - plot the confirmed tracks of a trk track log (and the
simulated sonar's truth when the log holds it).

    PYTHONPATH=tools/python python3 tools/python/plot_track_log.py build/demo-lcm/tracks.lcmlog --out tracks

writes tracks_tracks.csv (every confirmed track's states, one block per
track), tracks_truth.csv (the TRK_TRUTH states, if any) and tracks.png: x/y
paths, the truth dashed. The plot is drawn by matplotlib when it is
installed (Debian: python3-matplotlib), else by gnuplot (Debian:
gnuplot-nox) from the CSV files and a .gp script, else only the CSV files
are written (--plotter chooses). Needs numpy and the shipped reader
(lcmlog.py, trklog.py, the lcm-gen -p types in trk/).
"""

import argparse
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from needs import need, run_main  # noqa: E402

need("plot_track_log.py", "numpy")
import trklog  # noqa: E402


def have_matplotlib():
    try:
        import matplotlib  # noqa: F401
        return True
    except ImportError:
        return False


def write_csv(path, header, blocks):
    """blocks: lists of rows; a blank line between blocks (gnuplot breaks
    the line there; trkcsv and pandas skip it)."""
    with open(path, "w") as f:
        f.write(header + "\n")
        for i, rows in enumerate(blocks):
            if i:
                f.write("\n")
            for r in rows:
                f.write(",".join(v if isinstance(v, str) else "%.6g" % v for v in r) + "\n")


def plot_matplotlib(png, title, subtitle, tracks, truth):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 7))
    for g, rows in truth.items():
        ax.plot(rows["x_m"], rows["y_m"], "--", color="0.6", lw=1, label="truth" if g == min(truth) else None)
    for tid, rows in tracks.items():
        ax.plot(rows["x_m"], rows["y_m"], "-", lw=1.5, label="track %d" % tid)
        ax.plot(rows["x_m"][-1:], rows["y_m"][-1:], "o", ms=4, color=ax.lines[-1].get_color())
    ax.set_xlabel("x (m, east)")
    ax.set_ylabel("y (m, north)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, loc="best")
    fig.suptitle(title, fontsize=11)
    ax.set_title(subtitle, fontsize=8)
    fig.savefig(png, dpi=100)
    plt.close(fig)


def plot_gnuplot(prefix, png, title, subtitle, tracks_csv, truth_csv):
    gp = prefix + ".gp"
    with open(gp, "w") as f:
        f.write("set terminal pngcairo size 800,700 noenhanced\n" if _gnuplot_has("pngcairo")
                else "set terminal png size 800,700 noenhanced\n")
        f.write("set output '%s'\n" % png)
        f.write("set datafile separator ','\nset key autotitle columnhead\n")
        f.write("set title \"%s\\n%s\"\n" % (title.replace('"', "'"), subtitle.replace('"', "'")))
        f.write("set xlabel 'x (m, east)'\nset ylabel 'y (m, north)'\nset size ratio -1\nset grid\nset key below\n")
        plots = []
        if truth_csv:
            plots.append("'%s' using 3:4 with lines dt 2 lc rgb 'gray60' title 'truth'" % truth_csv)
        plots.append("'%s' using 4:5:2 with lines lw 1.5 lc variable title 'confirmed tracks'" % tracks_csv)
        f.write("plot " + ", ".join(plots) + "\n")
    r = subprocess.run(["gnuplot", gp], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("gnuplot %s failed: %s" % (gp, r.stderr.strip()))


def _gnuplot_has(term):
    r = subprocess.run(["gnuplot", "-e", "set terminal"], capture_output=True, text=True)
    return term in (r.stdout + r.stderr)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("log", help="LCM log with track lists (trk-lcm-bridge --replay --out, or lcm-logger)")
    ap.add_argument("--out", default=None, help="output prefix (default: the log's name without .lcmlog)")
    ap.add_argument("--channel", default="TRK_TRACKS", help="track channel (TRK_TRACKS)")
    ap.add_argument("--truth", default="TRK_TRUTH", help="truth channel, '' = none (TRK_TRUTH)")
    ap.add_argument("--plotter", choices=("auto", "matplotlib", "gnuplot", "none"), default="auto",
                    help="auto: matplotlib, else gnuplot, else CSV only")
    a = ap.parse_args(argv)
    prefix = a.out or (a.log[:-7] if a.log.endswith(".lcmlog") else a.log)

    lists = trklog.track_lists(a.log, a.channel)
    tr = trklog.tracks_array(lists)
    if not lists:
        print("plot_track_log: %s holds no track list on %s" % (a.log, a.channel), file=sys.stderr)
        return 1
    t0 = min(m.utime for m in lists)
    conf = tr[tr["status"] == trklog.CONFIRMED]
    ids = list(dict.fromkeys(conf["id"].tolist()))  # in order of confirmation
    tracks = {i: conf[conf["id"] == i] for i in ids}
    tracks_csv = prefix + "_tracks.csv"
    write_csv(tracks_csv, "t_s,id,n_updates,x_m,y_m,vx_mps,vy_mps,sd_m",
              [[((r["utime"] - t0) * 1e-6, r["id"], r["n_updates"], r["x_m"], r["y_m"], r["vx_mps"], r["vy_mps"],
                 r["sd_m"]) for r in rows] for rows in tracks.values()])
    truth = {}
    truth_csv = None
    if a.truth:
        tt = trklog.tracks_array(a.log, a.truth)
        if len(tt):
            truth = {g: tt[tt["id"] == g] for g in sorted(set(tt["id"].tolist()))}
            truth_csv = prefix + "_truth.csv"
            write_csv(truth_csv, "t_s,target,x_m,y_m",
                      [[((r["utime"] - t0) * 1e-6, r["id"], r["x_m"], r["y_m"]) for r in rows]
                       for rows in truth.values()])
    title = "trk track log %s: %d confirmed tracks%s" % (
        os.path.basename(a.log), len(ids), ", %d targets" % len(truth) if truth else "")
    subtitle = "%d track lists over %.0f s (%s)%s" % (
        len(lists), (max(m.utime for m in lists) - t0) * 1e-6, a.channel, "; truth dashed (%s)" % a.truth if truth else "")

    plotter = a.plotter
    if plotter == "matplotlib":
        need("plot_track_log.py", "matplotlib")
    if plotter == "auto":
        plotter = "matplotlib" if have_matplotlib() else "gnuplot" if shutil.which("gnuplot") else "none"
    png = prefix + ".png"
    if plotter == "matplotlib":
        plot_matplotlib(png, title, subtitle, tracks, truth)
    elif plotter == "gnuplot":
        plot_gnuplot(prefix, png, title, subtitle, tracks_csv, truth_csv)
    files = [tracks_csv] + ([truth_csv] if truth_csv else []) + ([png] if plotter != "none" else [])
    print("plot_track_log: %d confirmed tracks (ids %s)%s; plotter %s; wrote %s" % (
        len(ids), " ".join(map(str, ids)), ", %d truth targets" % len(truth) if truth else "", plotter,
        ", ".join(files)))
    return 0


if __name__ == "__main__":
    run_main("plot_track_log.py", main, (trklog.lcmlog.LogError, trklog.DecodeError))
