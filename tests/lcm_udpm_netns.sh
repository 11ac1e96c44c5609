#!/bin/sh
# lcm_udpm_netns.sh BUILD - command-line and multicast tests of the LCM tools
# (make test-lcm-udpm, part of make test). Nothing touches the real network.
#
# Always (no network):
#   - trk-lcm-bridge refuses bad settings and tables with exit status 2 and a
#     message, accepts --help / --print-config
#   - SIGINT and SIGTERM stop a live bridge (memq://) cleanly: exit 0, summary
#   - trk-sonar-sim --log and trk-lcm-bridge --replay are deterministic
#     (same options, byte-identical files), polar scans too; the bridge
#     replays the polar channel; the polar sonar's detections follow its
#     pose, coverage and P_D profile (with a python3 that has numpy)
# In a private network namespace (unshare -rn; skipped with the reason when
# the machine cannot create one):
#   - trk-sonar-sim -> udpm -> trk-lcm-bridge -> udpm -> lcm-logger: the
#     tracks and status reach the logger, malformed messages are counted,
#     SIGTERM stops the bridge with exit 0
# Every program runs under timeout(1) or a watchdog: the test cannot hang.
set -u
BUILD=${1:-build}
B=$BUILD/bin
T=$(mktemp -d "${TMPDIR:-/tmp}/trk-lcm-test.XXXXXX")
trap 'rm -rf "$T"' EXIT INT TERM
fail() { echo "test-lcm-udpm: FAIL: $*"; exit 1; }
ok() { echo "test-lcm-udpm: ok: $*"; }

# --- refusals (exit 2, a message naming the problem)
expect_refusal() { # pattern, args...
    pat=$1; shift
    timeout 20 "$B/trk-lcm-bridge" "$@" --replay /dev/null --out "$T/x.lcmlog" > "$T/o" 2> "$T/e"
    rc=$?
    [ $rc -eq 2 ] || fail "trk-lcm-bridge $* exited $rc, want 2"
    grep -q -- "$pat" "$T/e" || fail "trk-lcm-bridge $*: message lacks '$pat': $(cat "$T/e")"
}
expect_refusal "gate_prob" --gate_prob 2
expect_refusal "unknown setting" --set no-such-setting=1
expect_refusal "confirm.mn" --set confirm=mn --set confirm.mn.m=9
expect_refusal "term = page" --set term=page --set hmm.p_low_high=0 --set hmm.q_high_low=0
expect_refusal "amp_table" --set sensor.0.amplitude=k   # K clutter needs a table
expect_refusal "init_speed_sigma_mps" --set init_speed_sigma_mps=1e160   # its square overflows
expect_refusal "cannot open" --set q2_table="$T/missing.tbl"
head -c 300 /dev/urandom > "$T/junk.tbl"
expect_refusal "TRK_E_TABLE" --set sensor.0.amp_table="$T/junk.tbl"
printf 'gate_prob = 0.9\nbogus line\n' > "$T/bad.conf"
expect_refusal "bad.conf:2" --config "$T/bad.conf"
timeout 20 "$B/trk-lcm-bridge" --help > "$T/help" || fail "--help exited $?"
grep -q "replay" "$T/help" || fail "--help does not document --replay"
printf 'gate_prob = 0.95\ntrack_channel = MY_TRACKS\n' > "$T/good.conf"
timeout 20 "$B/trk-lcm-bridge" --config "$T/good.conf" --print-config > "$T/pc" || fail "--print-config exited $?"
grep -q "^gate_prob = 0.95$" "$T/pc" && grep -q "^track_channel = MY_TRACKS$" "$T/pc" ||
    fail "--print-config does not show the config file's settings"
ok "bad settings and tables are refused with exit status 2"

# --- clean stop on SIGINT / SIGTERM (live, in-process transport). The
# signal goes to the bridge itself, not through timeout(1) (which follows it
# with SIGCONT, racing LeakSanitizer's stop-the-world at exit in ASan builds);
# a watchdog kills it if it does not stop.
for sig in INT TERM; do
    "$B/trk-lcm-bridge" --lcm-url memq:// > "$T/stop.out" 2>&1 &
    pid=$!
    (sleep 30; kill -KILL $pid) > /dev/null 2>&1 &
    wd=$!
    sleep 0.5
    kill -$sig $pid
    wait $pid
    rc=$?
    kill $wd 2> /dev/null
    [ $rc -eq 0 ] || fail "bridge exited $rc after SIG$sig: $(cat "$T/stop.out")"
    grep -q "stopped by SIG$sig" "$T/stop.out" && grep -q "^scans: received 0" "$T/stop.out" ||
        fail "no summary after SIG$sig: $(cat "$T/stop.out")"
done
ok "SIGINT and SIGTERM stop the bridge cleanly with a summary"

# --- inputs that are no log: a clear error, never a spin or "0 events"
timeout -s KILL 20 "$B/trk-lcm-bridge" --summarize "$T" > "$T/o" 2> "$T/e"
rc=$?
[ $rc -eq 1 ] && grep -q "Is a directory" "$T/e" || fail "--summarize DIR exited $rc: $(cat "$T/o" "$T/e")"
timeout -s KILL 60 "$B/trk-lcm-bridge" --replay /dev/zero --out "$T/z.lcmlog" > "$T/o" 2> "$T/e"
rc=$?
[ $rc -eq 1 ] && grep -q "no LCM log record found" "$T/e" ||
    fail "--replay /dev/zero exited $rc: $(cat "$T/o" "$T/e")"
# SIGTERM while the replay resynchronises (zeros trickling through a FIFO)
mkfifo "$T/fifo"
(while :; do head -c 4096 /dev/zero; sleep 0.01; done) > "$T/fifo" 2> /dev/null &
feed=$!
"$B/trk-lcm-bridge" --replay "$T/fifo" --out "$T/z.lcmlog" > "$T/o" 2> "$T/e" &
pid=$!
(sleep 30; kill -KILL $pid) > /dev/null 2>&1 &
wd=$!
sleep 0.5
kill -TERM $pid
wait $pid
rc=$?
kill $wd $feed 2> /dev/null
wait $feed 2> /dev/null
[ $rc -eq 0 ] && grep -q "(interrupted)" "$T/o" || fail "replay exited $rc after SIGTERM: $(cat "$T/o" "$T/e")"
ok "a directory, /dev/zero and SIGTERM during a resync end the bridge with a message"

# --- channels compare by their full length: a NUL inside is no end
printf '\355\241\332\001\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\001\0\0\0\025\0\0\0\001TRK_TRACKS\000hidden1234x' > "$T/nul.lcmlog"
timeout 20 "$B/trk-lcm-bridge" --summarize "$T/nul.lcmlog" > "$T/o" 2> "$T/e" || fail "--summarize exited $?: $(cat "$T/e")"
grep -q 'TRK_TRACKS\\0hidden1234 ' "$T/o" && grep -q "^track lists: 0 (undecodable 0)" "$T/o" ||
    fail "a channel with a NUL was taken for TRK_TRACKS: $(cat "$T/o")"
ok "a channel with a NUL inside is not the track channel"

# --- determinism of the log path
for i in 1 2; do
    timeout 60 "$B/trk-sonar-sim" --out "$T/d$i.lcmlog" --scans 40 --seed 9 --bad-every 7 --quiet > /dev/null ||
        fail "trk-sonar-sim --log exited $?"
    timeout 60 "$B/trk-lcm-bridge" --replay "$T/d$i.lcmlog" --out "$T/t$i.lcmlog" --quiet > "$T/r$i.out" ||
        fail "trk-lcm-bridge --replay exited $?"
done
cmp -s "$T/d1.lcmlog" "$T/d2.lcmlog" || fail "trk-sonar-sim --log is not deterministic"
cmp -s "$T/t1.lcmlog" "$T/t2.lcmlog" || fail "trk-lcm-bridge --replay is not deterministic"
grep -q "processed 40, rejected 5" "$T/r1.out" || fail "replay counts: $(cat "$T/r1.out")"
ok "sonar-sim --log and bridge --replay are byte-identical across runs"

# --- polar scans: deterministic, both channels replayed, and what the
# simulated polar sonar draws (a stationary target inside the coverage is
# detected with the profile's P_D, one outside never; the pose moves as set)
for i in 1 2; do
    timeout 60 "$B/trk-sonar-sim" --polar --platform 1000,1000,0.5,3 --coverage 0,1800,1.2 \
        --pd-profile 0:0.9,1000:0.7,2000:0.3 --out "$T/p$i.lcmlog" --scans 40 --seed 9 --bad-every 7 --quiet > /dev/null ||
        fail "trk-sonar-sim --polar --log exited $?"
done
cmp -s "$T/p1.lcmlog" "$T/p2.lcmlog" || fail "trk-sonar-sim --polar --log is not deterministic"
timeout 60 "$B/trk-lcm-bridge" --set sensor.0.kind=polar --replay "$T/p1.lcmlog" --out "$T/pt.lcmlog" --quiet > "$T/pr.out" ||
    fail "trk-lcm-bridge --replay of polar scans exited $?"
grep -q "45 on TRK_DETECTIONS and TRK_DETECTIONS_POLAR" "$T/pr.out" || fail "polar replay: $(cat "$T/pr.out")"
grep -q "received 45, processed [0-9]*, rejected [0-9]* (decode 1, count 1, field 1, sensor 1" "$T/pr.out" ||
    fail "polar replay counts: $(cat "$T/pr.out")"
ok "sonar-sim --polar --log is byte-identical across runs; the bridge replays the polar channel and counts its bad messages"
PY=
for p in ${PYTHON:-} python3 /usr/bin/python3; do
    if command -v "$p" > /dev/null 2>&1 && "$p" -c 'import numpy' > /dev/null 2>&1; then PY=$p; break; fi
done
if [ -n "$PY" ]; then
    timeout 60 "$B/trk-sonar-sim" --polar --platform 1000,1000,0,4 --coverage 0,2000,1 --pd-profile 0:0.5,3000:0.5 \
        --target 1500,1000,0,0 --target 1000,1800,0,0 --q 0 --clutter-count 0 --clutter-model none \
        --sigma-range-m 3 --sigma-bearing-rad 0.005 --scans 400 --seed 3 --out "$T/pp.lcmlog" --quiet > /dev/null ||
        fail "trk-sonar-sim --polar exited $?"
    PYTHONPATH=tools/python PYTHONDONTWRITEBYTECODE=1 timeout 120 "$PY" - "$T/pp.lcmlog" > "$T/pp.out" 2>&1 <<'PYEOF' ||
import math, sys
import trklog
n_det = n_scans = 0
for ev, m in trklog.messages(sys.argv[1], channels=["TRK_DETECTIONS_POLAR"]):
    k = n_scans
    n_scans += 1
    # the platform: north at 4 m/s, one scan every 2 s, looking north
    assert m.has_pose and m.pose_heading_rad == 0 and m.pose_x_m == 1000, (k, m.pose_x_m)
    assert abs(m.pose_y_m - (1000 + 8 * k)) < 1e-6, (k, m.pose_y_m)
    for d in m.detections[:m.n_detections]:
        # only the target north of the platform (800 m at scan 0), never the one east (bearing pi/2 > 1 rad)
        want_r = 800 - 8 * k if k < 100 else 8 * k - 800
        want_b = 0 if k < 100 else math.pi
        if k >= 100:  # behind the platform: outside the sector, never seen
            raise AssertionError("scan %d: a detection behind the platform" % k)
        assert abs(d.range_m - want_r) < 5 * 3 + 1e-9, (k, d.range_m, want_r)
        assert abs(d.bearing_rad - want_b) < 5 * 0.005 + 1e-9, (k, d.bearing_rad)
        n_det += 1
assert n_scans == 400, n_scans
# 100 scans with the north target in front (P_D 0.5 of the profile, not the
# targets' 0.9): 50 expected, sigma 5
assert 30 <= n_det <= 70, n_det
print("%d scans, %d detections of the target in the sector" % (n_scans, n_det))
PYEOF
        fail "the polar sonar's detections: $(tail -5 "$T/pp.out")"
    ok "sonar-sim --polar: $(cat "$T/pp.out"); poses as set; none outside the coverage"
fi
# detections below the amplitude threshold are counted (they used to be in no counter)
timeout 60 "$B/trk-lcm-bridge" --replay "$T/d1.lcmlog" --out "$T/t3.lcmlog" --quiet \
    --set sensor.0.amplitude=rayleigh --set sensor.0.pfa=1e-9 > "$T/r3.out" || fail "replay exited $?"
grep -q "below the amplitude threshold [1-9]" "$T/r3.out" || fail "below-threshold count: $(cat "$T/r3.out")"
timeout 20 "$B/trk-lcm-bridge" --summarize "$T/t3.lcmlog" > "$T/s3.out" || fail "--summarize exited $?"
grep -q "^  detections dropped 0 .*below the amplitude threshold [1-9]" "$T/s3.out" ||
    fail "the status in the log lacks the below-threshold count: $(cat "$T/s3.out")"
ok "detections below the amplitude threshold are counted in the summary and the status"

# --- UDP multicast in a private network namespace
if ! command -v unshare > /dev/null 2>&1 || ! command -v ip > /dev/null 2>&1; then
    echo "test-lcm-udpm: SKIPPED multicast: unshare or ip (iproute2) not installed"
    exit 0
fi
if ! msg=$(timeout 10 unshare -rn sh -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo' 2>&1); then
    echo "test-lcm-udpm: SKIPPED multicast: cannot create a network namespace with a multicast route (unshare -rn: $msg)"
    exit 0
fi
if ! command -v lcm-logger > /dev/null 2>&1; then
    echo "test-lcm-udpm: SKIPPED multicast: lcm-logger (liblcm-bin) not installed"
    exit 0
fi
export B T
timeout 90 unshare -rn sh -c '
    ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 3
    export LCM_DEFAULT_URL="udpm://239.255.76.67:7667?ttl=0"
    timeout 60 lcm-logger -q -f -c "TRK_TRACKS|TRK_BRIDGE_STATUS" "$T/net.lcmlog" 2> /dev/null &
    L=$!
    "$B/trk-lcm-bridge" --status-period-s 0.2 > "$T/bridge.out" 2> "$T/bridge.err" &
    BR=$!
    (sleep 60; kill -KILL $BR) > /dev/null 2>&1 &
    WD=$!
    sleep 1
    timeout 60 "$B/trk-sonar-sim" --scans 30 --rate-hz 40 --bad-every 10 --seed 5 > "$T/sim.out" 2>&1
    sleep 1
    kill -TERM $BR; wait $BR; rc=$?
    kill $WD 2> /dev/null
    sleep 0.3
    kill -INT $L; wait $L
    exit $rc'
rc=$?
[ $rc -eq 0 ] || fail "multicast run: bridge exited $rc: $(cat "$T/bridge.out" "$T/bridge.err" 2>/dev/null)"
grep -q "stopped by SIGTERM" "$T/bridge.out" || fail "no summary: $(cat "$T/bridge.out")"
processed=$(sed -n 's/.*processed \([0-9]*\).*/\1/p' "$T/bridge.out" | head -1)
[ "${processed:-0}" -ge 25 ] || fail "bridge processed ${processed:-0} of 30 scans: $(cat "$T/bridge.out")"
grep -q "rejected 3 " "$T/bridge.out" || fail "the 3 malformed messages were not counted: $(cat "$T/bridge.out")"
timeout 20 "$B/trk-lcm-bridge" --summarize "$T/net.lcmlog" > "$T/sum.out" || fail "--summarize exited $?"
lists=$(sed -n 's/^track lists: \([0-9]*\).*/\1/p' "$T/sum.out")
[ "${lists:-0}" -ge 25 ] || fail "lcm-logger recorded ${lists:-0} track lists: $(cat "$T/sum.out")"
grep -q "TRK_BRIDGE_STATUS" "$T/sum.out" || fail "no status message reached lcm-logger"
ok "udpm in a network namespace: $processed scans tracked, $lists track lists logged by lcm-logger"
