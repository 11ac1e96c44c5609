#!/usr/bin/env python3
"""gospa_grid.py - tune trk over a grid of two parameters on recorded
detections and plot the mean GOSPA against them (docs/python.md).

    python3 tools/python/gospa_grid.py DIR [--out PREFIX] [--c 50] [--p 2]
        [--x process_noise_q=1e-4,1e-3,1e-2] [--y init.birth_density_per_m2=1e-10,1e-9,1e-8]
        [--table AMP.tbl] [--sigma 5] [--lambda L] [--plotter auto|matplotlib|none]

DIR holds trk-sim demo-amplitude's files: detections.csv (scan, time_s, x_m, y_m,
amplitude) and truth.csv (scan, target, x_m, y_m, present); lambda defaults
to the demo's clutter_per_scan / 2000 m x 2000 m (summary.csv). Every grid
point runs the whole recording through trk.Tracker (defaults, the sensor of
the options, the two parameters set by their member names) and scores each
scan's confirmed tracks against the targets present (trk.gospa, the metric
of trk-sim); the mean over the scans goes to PREFIX.csv, and a heat map to
PREFIX.png when matplotlib is installed. Prints the best point.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from needs import need, run_main  # noqa: E402

np = need("gospa_grid.py", "numpy")
import trk  # noqa: E402
from trk import recorded  # noqa: E402
from trk.gospa import gospa  # noqa: E402


def axis(text):
    name, _, values = text.partition("=")
    return name, [float(v) for v in values.split(",") if v]


def set_member(p, name, value):
    obj = p
    parts = name.split(".")
    for part in parts[:-1]:
        obj = getattr(obj, part)
    setattr(obj, parts[-1], value)


def read_truth(path):
    truth = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            if int(r["present"]):
                truth.setdefault(int(r["scan"]), []).append((float(r["x_m"]), float(r["y_m"])))
    return truth


def run(scans, truth, params, c, p):
    tk = trk.Tracker(params)
    total = 0.0
    for s in scans:
        _, tracks = tk.process_scan(s.time_s, s.xy, amplitude=s.amplitude)
        conf = tracks[tracks["status"] == trk.TRACK_CONFIRMED]
        total += gospa(truth.get(s.scan, []), conf["state"][:, [0, 2]], c, p).gospa
    return total / max(1, len(scans))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("dir")
    ap.add_argument("--out", default="gospa_grid")
    ap.add_argument("--c", type=float, default=50.0, help="GOSPA cut-off (m)")
    ap.add_argument("--p", type=float, default=2.0, help="GOSPA order")
    ap.add_argument("--x", type=axis, default=axis("process_noise_q=1e-4,1e-3,1e-2"))
    ap.add_argument("--y", type=axis, default=axis("init.birth_density_per_m2=1e-10,1e-9,1e-8"))
    ap.add_argument("--table", help="amplitude table (PDAFAI); default: positions only")
    ap.add_argument("--sigma", type=float, default=5.0, help="measurement sigma (m)")
    ap.add_argument("--lambda", dest="lam", type=float, help="clutter density (1/m^2)")
    ap.add_argument("--plotter", choices=("auto", "matplotlib", "none"), default="auto")
    a = ap.parse_args()
    if trk.library_error:
        sys.exit("gospa_grid: %s" % trk.library_error)
    scans = recorded.read_scans(os.path.join(a.dir, "detections.csv"))
    truth = read_truth(os.path.join(a.dir, "truth.csv"))
    lam = a.lam
    if lam is None:
        with open(os.path.join(a.dir, "summary.csv")) as f:
            kv = dict(line.strip().split(",", 1) for line in f if "," in line)
        lam = float(kv["clutter_per_scan"]) / (2000.0 * 2000.0)
    base = trk.default_params()
    base.sensor[0].meas_cov_m2 = [a.sigma ** 2, 0, a.sigma ** 2]
    base.sensor[0].clutter_density_per_m2 = lam
    if a.table:
        base.set_amplitude(0, trk.AmplitudeTable(a.table))
    (xn, xs), (yn, ys) = a.x, a.y
    g = np.zeros((len(ys), len(xs)))
    with open(a.out + ".csv", "w") as f:
        f.write("%s,%s,mean_gospa_m\n" % (xn, yn))
        for i, yv in enumerate(ys):
            for j, xv in enumerate(xs):
                p = base.copy()
                set_member(p, xn, xv)
                set_member(p, yn, yv)
                g[i, j] = run(scans, truth, p, a.c, a.p)
                f.write("%.6g,%.6g,%.6f\n" % (xv, yv, g[i, j]))
    i, j = np.unravel_index(np.argmin(g), g.shape)
    print("gospa_grid: %d x %d runs of %d scans; best mean GOSPA %.3f m at %s = %g, %s = %g; worst %.3f m" % (
        len(xs), len(ys), len(scans), g[i, j], xn, xs[j], yn, ys[i], g.max()))
    plotted = False
    if a.plotter != "none":
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            if a.plotter == "matplotlib":
                need("gospa_grid.py", "matplotlib")  # says which package, exits 1
        else:
            fig, ax = plt.subplots()
            im = ax.imshow(g, origin="lower", cmap="viridis")
            ax.set_xticks(range(len(xs)), ["%g" % v for v in xs])
            ax.set_yticks(range(len(ys)), ["%g" % v for v in ys])
            ax.set_xlabel(xn)
            ax.set_ylabel(yn)
            fig.colorbar(im, label="mean GOSPA (m), c = %g, p = %g" % (a.c, a.p))
            fig.savefig(a.out + ".png", dpi=100)
            plotted = True
    print("gospa_grid: %s.csv%s" % (a.out, " and %s.png" % a.out if plotted else " (no plot: matplotlib not installed)"))


if __name__ == "__main__":
    run_main("gospa_grid.py", main)
