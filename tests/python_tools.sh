#!/bin/sh
# python_tools.sh BUILD - the Python tools of tools/python (make
# test-python, part of make test): the pure-Python LCM log reader and the
# lcm-gen -p types against trk's C side, the CSV readers against trk-sim's
# files, the plotting example (every plotter this machine has: gnuplot from
# gnuplot-nox, matplotlib when python3-matplotlib is installed; CSV only),
# and the committed types against lcm-gen's output.
# Needs python3 with numpy (Debian: python3-numpy; .ci/run installs it).
set -u
export PYTHONDONTWRITEBYTECODE=1   # no __pycache__ in the checkout
BUILD=${1:-build}
B=$BUILD/bin
STEP=python-tools
. tests/step_lib.sh
# the first python3 with numpy: $PYTHON, python3 on PATH, Debian's own
find_python || fail "no python3 with numpy (Debian: apt-get install python3-numpy)"
ok "$($PY -c 'import sys, numpy; print("python %d.%d.%d, numpy %s" % (sys.version_info[:3] + (numpy.__version__,)))') ($PY)"

# --- the committed types are lcm-gen's output for tools/lcm/types
if command -v lcm-gen > /dev/null 2>&1; then
    mkdir -p "$T/gen" && lcm-gen -p --ppath "$T/gen" tools/lcm/types/*.lcm > /dev/null || fail "lcm-gen -p exited $?"
    # the types' modules are lcm-gen's; the package's own __init__.py (the
    # binding's too) imports every type lcm-gen's __init__.py imports
    n=0
    for f in "$T"/gen/trk/*_t.py; do
        diff "$f" "tools/python/trk/${f##*/}" > "$T/gen.diff" ||
            fail "tools/python/trk/${f##*/} differs from lcm-gen -p tools/lcm/types/*.lcm (make python-types): $(head -20 "$T/gen.diff")"
        n=$((n + 1))
    done
    grep '^from \.' "$T/gen/trk/__init__.py" | while IFS= read -r line; do
        grep -qxF "$line" tools/python/trk/__init__.py || { echo "$line"; exit 1; }
    done > "$T/missing" || fail "tools/python/trk/__init__.py lacks lcm-gen's imports: $(cat "$T/missing")"
    ok "tools/python/trk holds lcm-gen -p's $n type modules for tools/lcm/types and imports each"
fi

# --- inputs made by the project's own tools
"$B/trk-sonar-sim" --out "$T/det.lcmlog" --scans 150 --targets 4 --seed 7 --clutter-model k --k-shape 2 \
    --snr-db 16 --pfa 1e-3 --clutter-density 2.5e-6 --bad-every 25 --quiet > "$T/sonar.txt" || fail "trk-sonar-sim exited $?"
"$B/trk-lcm-bridge" --replay "$T/det.lcmlog" --out "$T/tracks.lcmlog" --keep-input --quiet --set sensor.0.pd=0.7 \
    --set sensor.0.meas_sigma_m=3 --set sensor.0.clutter_density_per_m2=2.5e-6 > "$T/replay.txt" ||
    fail "trk-lcm-bridge --replay exited $?"
"$B/trk-lcm-bridge" --summarize "$T/tracks.lcmlog" > "$T/summary.txt" || fail "--summarize exited $?"
"$B/trk-sim" demo-amplitude --tables "$BUILD/tables" --out "$T/demo" --no-plot > "$T/demo.txt" 2>&1 ||
    fail "trk-sim demo-amplitude exited $?: $(tail -5 "$T/demo.txt")"
"$B/trk-sim" blanding-add-arl --runs 40 --max-scans 1000 --seed 5 --quiet --no-plot --out "$T/bl" > /dev/null ||
    fail "trk-sim blanding-add-arl exited $?"

# --- the readers against the C side
$PY tests/python/check_trk_python.py "$T" || exit 1
"$B/trk-lcm-bridge" --summarize "$T/broken.lcmlog" > "$T/broken.txt" || fail "--summarize broken.lcmlog exited $?"
$PY tests/python/check_trk_python.py "$T" --broken-only || exit 1

# --- the plotting example: every plotter this machine has
png_ok() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] && [ "$(wc -c < "$1")" -gt 10000 ]; }
plotters="none"
command -v gnuplot > /dev/null 2>&1 && plotters="$plotters gnuplot"
$PY -c 'import matplotlib' > /dev/null 2>&1 && plotters="$plotters matplotlib"
want_ids=$(sed -n 's/^confirmed track ids ([0-9]*): *//p' "$T/summary.txt")
for p in $plotters; do
    $PY tools/python/plot_track_log.py "$T/tracks.lcmlog" --out "$T/plot_$p" --plotter $p > "$T/plot_$p.out" 2>&1 ||
        fail "plot_track_log.py --plotter $p exited $?: $(cat "$T/plot_$p.out")"
    grep -q "confirmed tracks (ids $want_ids), 4 truth targets; plotter $p" "$T/plot_$p.out" ||
        fail "plot_track_log.py --plotter $p: $(cat "$T/plot_$p.out"), want ids $want_ids"
    # the CSV holds every confirmed state of the log: as many rows as tracks_array's confirmed ones
    rows=$(grep -c '^[0-9]' "$T/plot_${p}_tracks.csv")
    want=$($PY -c "import sys; sys.path.insert(0, 'tools/python'); import trklog
tr = trklog.tracks_array('$T/tracks.lcmlog'); print(int((tr['status'] == trklog.CONFIRMED).sum()))")
    [ "$rows" = "$want" ] || fail "plot_${p}_tracks.csv has $rows states, the log $want confirmed ones"
    if [ $p != none ]; then
        png_ok "$T/plot_$p.png" || fail "plot_track_log.py --plotter $p wrote no PNG ($(ls -la "$T"/plot_$p*))"
        ok "plot_track_log.py --plotter $p: $rows confirmed states of ids $want_ids, PNG of $(wc -c < "$T/plot_$p.png") bytes"
    else
        [ ! -e "$T/plot_none.png" ] || fail "--plotter none wrote a PNG"
        ok "plot_track_log.py --plotter none: $rows confirmed states in CSV, no PNG"
    fi
done
echo "python-tools: the log reader, the types, the CSV readers and the example (plotters: $plotters) agree with the C side"
