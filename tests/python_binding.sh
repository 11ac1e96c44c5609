#!/bin/sh
# python_binding.sh BUILD - the Python package trk driving libtrk.so (make
# test-python-binding, part of make test; docs/python.md):
#   - the library's layout table and the parameters API (refusals name the
#     field and the status; units and ranges)
#   - same bytes as C: trk-sim demo-amplitude's detections through the C program
#     (py-replay-csv) and through trk.Tracker, every track of every scan
#     printed exactly and compared (double, and float with libtrk_f.so)
#   - the UDP multicast reassembler on synthetic datagrams, then live in a
#     private network namespace: fragmented messages of the LCM C library,
#     and python3 -m trk.live against trk-lcm-bridge fed by trk-sonar-sim
#     (skipped with the reason when no namespace can be made)
#   - GOSPA: trk.gospa against trk-sim's C GOSPA; the grid example
#   - `pip install` of the source tree into a venv (system numpy), then
#     import trk there and in `make install`'s prefix
set -u
export PYTHONDONTWRITEBYTECODE=1
BUILD=${1:-build}
B=$BUILD/bin
ROOT=$(pwd)
STEP=python-binding
. tests/step_lib.sh
find_python || fail "no python3 with numpy (Debian: apt-get install python3-numpy)"
export PYTHONPATH="$ROOT/tools/python" TRK_LIBRARY="$ROOT/$BUILD/libtrk.so"

# --- the layout and the parameters
$PY tests/python/check_binding.py layout > "$T/layout.out" 2>&1 || fail "layout: $(cat "$T/layout.out")"
ok "$(cat "$T/layout.out")"

# --- a polar sensor through the binding, double and float
$PY tests/python/check_binding.py polar > "$T/polar.out" 2>&1 || fail "polar (double): $(cat "$T/polar.out")"
ok "$(cat "$T/polar.out")"
if [ -e "$BUILD/float/libtrk_f.so" ]; then
    TRK_LIBRARY="$ROOT/$BUILD/float/libtrk_f.so" TRK_REAL=float $PY tests/python/check_binding.py polar \
        > "$T/polar_f.out" 2>&1 || fail "polar (float): $(cat "$T/polar_f.out")"
    ok "float: $(cat "$T/polar_f.out")"
fi

# --- same bytes as C, double and float
"$B/trk-sim" demo-amplitude --tables "$BUILD/tables" --out "$T/demo" --no-plot > "$T/demo.txt" 2>&1 ||
    fail "trk-sim demo-amplitude exited $?: $(tail -5 "$T/demo.txt")"
lam=$(awk -F, '$1 == "clutter_per_scan" { printf "%.17g", $2 / 4e6 }' "$T/demo/summary.csv")
[ -n "$lam" ] || fail "no clutter_per_scan in the demo's summary.csv"
same_bytes() { # label, replay program, library, table
    "$2" "$T/demo/detections.csv" --lambda "$lam" --table "$4" > "$T/c_$1.txt" || fail "$2 exited $?"
    TRK_LIBRARY="$ROOT/$3" TRK_REAL=$1 $PY tests/python/check_binding.py replay "$T/demo/detections.csv" \
        --lambda "$lam" --table "$4" > "$T/py_$1.txt" 2> "$T/py_$1.err" || fail "replay ($1): $(cat "$T/py_$1.err")"
    cmp "$T/c_$1.txt" "$T/py_$1.txt" > "$T/cmp_$1" 2>&1 || fail "$1: Python's tracks differ from C's: $(cat "$T/cmp_$1")
$(diff "$T/c_$1.txt" "$T/py_$1.txt" | head -6)"
    n_scans=$(grep -c ' report ' "$T/c_$1.txt")
    n_tracks=$(grep -c ' track ' "$T/c_$1.txt")
    n_conf=$(grep -c ' track [0-9]* 2 ' "$T/c_$1.txt")
    [ "$n_conf" -gt 500 ] || fail "$1: only $n_conf confirmed track states in the demo's replay"
    ok "same bytes as C ($1): $n_scans scans, $n_tracks track states ($n_conf confirmed), every value equal to the last bit"
}
same_bytes double "$B/py-replay-csv" "$BUILD/libtrk.so" "$BUILD/tables/amp_k1_snr15_pfa1e-2.tbl"
FB=$BUILD/float
if [ -e "$FB/libtrk_f.so" ]; then
    same_bytes float "$FB/bin/py-replay-csv" "$FB/libtrk_f.so" "$FB/tables/amp_k1_snr15_pfa1e-2.tbl"
    TRK_LIBRARY= TRK_REAL=float $PY -c "import trk; assert trk.REAL.itemsize == 4 and trk.library_path.endswith('libtrk_f.so'), trk.library_path" ||
        fail "TRK_REAL=float did not load the source tree's libtrk_f.so"
fi
# a library of another version or ABI is refused at import
$PY -c "
import trk._lib as L
L.SHARED_ABI += 1
try:
    L.load()
except L.AbiError as e:
    assert 'ABI' in str(e), e
else:
    raise SystemExit('a wrong ABI was accepted')
" || fail "the ABI check does not refuse a binding of another ABI"
ok "the ABI check refuses another layout protocol at import"

# --- LCM UDP multicast
$PY tests/python/check_binding.py udpm > "$T/udpm.out" 2>&1 || fail "udpm: $(cat "$T/udpm.out")"
ok "$(cat "$T/udpm.out")"
live_ok=0
if ! command -v unshare > /dev/null 2>&1 || ! command -v ip > /dev/null 2>&1; then
    echo "$STEP: SKIPPED live multicast: unshare or ip (iproute2) not installed"
elif ! msg=$(timeout 10 unshare -rn sh -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo' 2>&1); then
    echo "$STEP: SKIPPED live multicast: cannot create a network namespace with a multicast route (unshare -rn: $msg)"
else
    live_ok=1
fi
if [ $live_ok = 1 ]; then
    export B T PY
    timeout 120 unshare -rn sh -c '
        ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 3
        export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
        # fragmented messages of the LCM C library
        $PY -c "
import sys, trk.lcm_udpm as u
rx = u.Receiver()
open(sys.argv[1], \"w\").close()
n = 0
for ch, p in rx.messages(20, {\"TRK_TEST_BIG\"}):
    if p == b\"done\":
        break
    k = p[0]
    assert len(p) == 200000 and all(p[i] == (i * 7 + k) % 251 for i in range(len(p))), (len(p), k)
    n += 1
print(\"fragmented\", n, rx.asm.n_fragmented, rx.asm.n_short, rx.asm.n_bad)
" "$T/ready" > "$T/big.out" 2>&1 &
        P=$!
        i=0; while [ ! -e "$T/ready" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
        timeout 30 "$B/py-lcm-big" TRK_TEST_BIG 200000 3 || exit 4
        wait $P || exit 5
        # the bridge s tracks live
        rm -f "$T/ready"
        $PY -m trk.live --timeout 6 --all > "$T/live.out" 2> "$T/live.err" &
        P=$!
        "$B/trk-lcm-bridge" --status-period-s 0.5 > "$T/bridge.out" 2>&1 &
        BR=$!
        (sleep 90; kill -KILL $BR) > /dev/null 2>&1 &
        WD=$!
        sleep 1.5
        timeout 60 "$B/trk-sonar-sim" --scans 60 --rate-hz 40 --seed 5 --targets 4 > "$T/sim.out" 2>&1
        sleep 1
        kill -TERM $BR; wait $BR; rc=$?
        kill $WD 2> /dev/null
        wait $P || exit 6
        exit $rc'
    rc=$?
    [ $rc -eq 0 ] || fail "multicast run exited $rc: $(cat "$T/big.out" "$T/live.out" "$T/live.err" "$T/bridge.out" 2>/dev/null | tail -20)"
    grep -q "^fragmented 3 3 1 0$" "$T/big.out" || fail "fragmented messages: $(cat "$T/big.out")"
    ok "3 messages of 200000 bytes from the LCM C library reassembled from their fragments, byte for byte"
    lists=$(sed -n 's/^trk.live: \([0-9]*\) track lists.*/\1/p' "$T/live.out")
    processed=$(sed -n 's/.*processed \([0-9]*\).*/\1/p' "$T/bridge.out" | head -1)
    [ "${lists:-0}" -ge 55 ] && [ "$lists" = "$processed" ] ||
        fail "trk.live printed ${lists:-0} track lists, the bridge processed ${processed:-0}: $(tail -3 "$T/live.out") $(cat "$T/live.err")"
    grep -q "0 undecodable" "$T/live.out" || fail "undecodable messages: $(tail -1 "$T/live.out")"
    grep -q "^status: scans received" "$T/live.out" || fail "no bridge status printed"
    # the last list's tracks as the bridge counted them
    conf_live=$(awk '/^tracks seq/ { c = $9 } END { print c + 0 }' "$T/live.out")
    conf_bridge=$(sed -n 's/.*now [0-9]* live, \([0-9]*\) confirmed.*/\1/p' "$T/bridge.out")
    [ "$conf_live" = "$conf_bridge" ] || fail "trk.live's last list has $conf_live confirmed tracks, the bridge says $conf_bridge"
    ok "python3 -m trk.live: $lists track lists of $processed scans from the bridge over udpm, $conf_live confirmed at the end as the bridge says"
fi

# --- GOSPA and the grid example
$PY tests/python/check_binding.py gospa "$B/py-gospa" "$T/demo" "$T/cases.txt" > "$T/gospa.out" 2>&1 ||
    fail "gospa: $(tail -5 "$T/gospa.out")"
ok "$(cat "$T/gospa.out")"
$PY tools/python/gospa_grid.py "$T/demo" --out "$T/grid" --table "$BUILD/tables/amp_k1_snr15_pfa1e-2.tbl" \
    --x process_noise_q=1e-4,1e-3 --y init.birth_density_per_m2=1e-9,1e-8 > "$T/grid.out" 2>&1 ||
    fail "gospa_grid.py exited $?: $(cat "$T/grid.out")"
[ "$(grep -c '^0' "$T/grid.csv")" = 4 ] || fail "gospa_grid.csv lacks its 4 points: $(cat "$T/grid.csv")"
best=$(sed -n 's/.*best mean GOSPA \([0-9.]*\) m.*/\1/p' "$T/grid.out")
awk -v b="$best" 'BEGIN { exit !(b > 0 && b < 25) }' || fail "best mean GOSPA ${best:-?} m: not the demo's few metres: $(cat "$T/grid.out")"
if $PY -c 'import matplotlib' > /dev/null 2>&1; then
    [ -s "$T/grid.png" ] || fail "matplotlib is installed but gospa_grid.py wrote no PNG"
fi
ok "gospa_grid.py: $(head -1 "$T/grid.out")"

# --- installs: pip into a venv with the system numpy, and make install
if $PY -c 'import venv, ensurepip' > /dev/null 2>&1; then
    $PY -m venv --system-site-packages "$T/venv" > "$T/venv.out" 2>&1 || fail "venv: $(cat "$T/venv.out")"
    "$T/venv/bin/python" -m pip install --no-build-isolation --no-index . > "$T/pip.out" 2>&1 ||
        fail "pip install . exited $?: $(tail -5 "$T/pip.out")"
    (cd "$T" && PYTHONPATH= "$T/venv/bin/python" -c "
import trk, os
assert trk.library_error is None and trk.__file__.startswith(os.environ['T']), (trk.__file__, trk.library_error)
assert hasattr(trk, 'track_list_t') and hasattr(trk, 'Tracker')
tk = trk.Tracker(); r, t = tk.process_scan(0.0, [[0.0, 0.0]]); assert r['n_detections'] == 1
import trk.live, trk.gospa
print(trk.__file__)") > "$T/venv_import.out" 2>&1 || fail "import trk in the venv: $(cat "$T/venv_import.out")"
    ok "pip install . into a venv (system numpy): import trk, a scan, trk.live ($(cat "$T/venv_import.out"))"
else
    echo "$STEP: SKIPPED pip install: python3-venv not installed"
fi
P=$T/prefix
env -u T make --no-print-directory install BUILD="$BUILD" PREFIX="$P" > "$T/install.out" 2>&1 || fail "make install: $(tail -5 "$T/install.out")"
[ -e "$P/lib/libtrk.so.0" ] || fail "make install installed no libtrk.so.0: $(ls "$P/lib")"
[ ! -e "$P/lib/libtrk.so" ] || fail "make install installed the development link libtrk.so: -ltrk would link the shared library"
(cd "$T" && PYTHONPATH="$P/share/trk/python" TRK_LIBRARY= $PY -c "
import trk
assert trk.library_path.startswith('$P/lib/'), trk.library_path
print(trk.library_path, trk.library_version)") > "$T/inst.out" 2>&1 || fail "the installed package: $(cat "$T/inst.out")"
ok "make install: the package in share/trk/python finds its library ($(cat "$T/inst.out"))"
echo "python-binding: the binding's layout, parameters, same bytes as C, live tracks, GOSPA and installs agree with the C side"
