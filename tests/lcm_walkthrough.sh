#!/bin/sh
# lcm_walkthrough.sh [PAGE] - the LCM walk-through of docs/lcm.md, run literally
# (make test-lcm-walkthrough, part of make test; run from the top of the
# checkout, after `make`).
#
# The commands below must appear in PAGE (docs/lcm.md) word for word (checked first),
# so the walk-through a reader copies is the one tested. Then, in a scratch
# directory (build/ linked into it):
#   offline: the settings and the amplitude table (trk-tablegen amp), then
#            trk-sonar-sim --out -> trk-lcm-bridge --replay -> --summarize
#   live:    the bridge, lcm-logger and trk-sonar-sim over UDP multicast in a
#            private network namespace (unshare -rn; skipped with the reason
#            when the machine cannot create one)
# and each summary must show as many confirmed tracks as targets (4), none
# duplicating another, each target followed by a confirmed track in >= 90 %
# of the scans. The same check must refuse the walk-through's old settings
# (the bridge's defaults: P_D 0.9, 1 m, 1e-4 per m^2 against the sonar's
# 0.73, 3 m, 5e-6): it confirms 11 tracks for 4 targets.
set -u
README=${1:-docs/lcm.md}
ROOT=$(pwd)
STEP=test-lcm-walkthrough
. tests/step_lib.sh

SONAR='build/bin/trk-sonar-sim --targets 4 --clutter-model k --k-shape 2 --snr-db 16'
C_CONF="$SONAR --print-bridge-config > bridge.conf"
C_TABLE='build/bin/trk-tablegen amp --clutter-model k --k-shape 2 --snr-db 16 --pfa 0.001 --out sonar.amp'
C_BRIDGE='build/bin/trk-lcm-bridge --config bridge.conf --max-scans 150'
C_LOGGER="lcm-logger -f -c 'TRK_.*' tracks.lcmlog"
C_SONAR="$SONAR --scans 150 --rate-hz 25"
C_SUMMARY='build/bin/trk-lcm-bridge --summarize tracks.lcmlog'
C_LOG="$SONAR --scans 150 --out detections.lcmlog"
C_REPLAY='build/bin/trk-lcm-bridge --config bridge.conf --replay detections.lcmlog --out tracks.lcmlog --keep-input'

for c in "$C_CONF" "$C_TABLE" "$C_BRIDGE" "$C_LOGGER" "$C_SONAR" "$C_SUMMARY" "$C_LOG" "$C_REPLAY"; do
    grep -qxF "$c" "$README" || fail "$README lacks the walk-through line: $c"
done
ok "the walk-through's 8 commands are in $README word for word"

ln -s "$ROOT/build" "$T/build"
cd "$T" || exit 1

# check SUMMARY_FILE WHAT: as many confirmed tracks as targets, no duplicate,
# each target followed; prints the reason and returns 1 otherwise
check() {
    s=$1
    n_conf=$(sed -n 's/^confirmed track ids (\([0-9]*\)).*/\1/p' "$s")
    n_tgt=$(sed -n 's/^truth (TRK_TRUTH): \([0-9]*\) targets.*/\1/p' "$s")
    [ -n "$n_conf" ] && [ -n "$n_tgt" ] || { echo "no confirmed/truth line in the summary"; return 1; }
    [ "$n_tgt" -eq 4 ] || { echo "$n_tgt targets in the truth, want 4"; return 1; }
    [ "$n_conf" -eq "$n_tgt" ] || { echo "$n_conf tracks confirmed for $n_tgt targets"; return 1; }
    grep -q "^last list .*: $n_tgt confirmed (0 duplicating another)" "$s" ||
        { echo "the last list does not hold $n_tgt confirmed tracks without duplicates"; return 1; }
    low=$(awk '/^  target [0-9]+: / { p = $7; gsub(/[(%]/, "", p); if (p + 0 < 90) print $2 }' "$s")
    [ -z "$low" ] || { echo "targets followed in < 90 % of the scans: $low"; return 1; }
    return 0
}

# --- offline (deterministic)
sh -c "$C_CONF" || fail "$C_CONF exited $?"
grep -q '^sensor.0.pd = 0.732325$' bridge.conf && grep -q '^sensor.0.meas_sigma_m = 3$' bridge.conf &&
    grep -q '^sensor.0.clutter_density_per_m2 = 5e-06$' bridge.conf ||
    fail "bridge.conf does not hold the sonar's P_D 0.732325, 3 m, 5e-6: $(cat bridge.conf)"
grep -q '^sensor.0.amp_table = sonar.amp$' bridge.conf &&
    grep -qF "#   trk-tablegen amp --clutter-model k --k-shape 2 --snr-db 16 --pfa 0.001 --out sonar.amp" bridge.conf ||
    fail "bridge.conf does not name the sonar's K amplitude table and how to make it: $(cat bridge.conf)"
sh -c "$C_TABLE" > table.out 2>&1 || fail "$C_TABLE exited $?: $(cat table.out)"
sh -c "$C_LOG" > log.out 2>&1 || fail "$C_LOG exited $?: $(cat log.out)"
sh -c "$C_REPLAY" > replay.out 2>&1 || fail "$C_REPLAY exited $?: $(cat replay.out)"
sh -c "$C_SUMMARY" > offline.txt 2>&1 || fail "$C_SUMMARY exited $?"
why=$(check offline.txt) || fail "offline walk-through: $why: $(cat offline.txt)"
ok "offline: $(sed -n 's/^\(confirmed track ids ([0-9]*)\).*/\1/p' offline.txt) for 4 targets, $(grep -c '^  target' offline.txt) followed in >= 90 % of 150 scans"

# --- the settings carry the amplitude model of any sonar: Rayleigh in closed
# form (and, with a P_D profile, the SNR over range from it); K or a table with
# a profile has none in the library: positions only, said
build/bin/trk-sonar-sim --targets 4 --print-bridge-config > ray.conf || fail "--print-bridge-config (Rayleigh) exited $?"
grep -q '^sensor.0.amplitude = rayleigh$' ray.conf && grep -q '^sensor.0.snr_db = 15$' ray.conf &&
    grep -q '^sensor.0.pfa = 0.001$' ray.conf || fail "Rayleigh settings lack the amplitude model: $(cat ray.conf)"
build/bin/trk-lcm-bridge --config ray.conf --print-config > ray.eff 2>&1 || fail "the bridge refuses the Rayleigh settings: $(cat ray.eff)"
build/bin/trk-sonar-sim --polar --pd-profile 0:0.9,2000:0.5 --clutter-model k --k-shape 2 --print-bridge-config > pk.conf ||
    fail "--print-bridge-config (polar, K, profile) exited $?"
if grep -q 'amp_table\|amplitude =' pk.conf || ! grep -q 'positions only' pk.conf; then
    fail "polar K with a P_D profile: $(cat pk.conf)"
fi
build/bin/trk-lcm-bridge --config pk.conf --print-config > pk.eff 2>&1 || fail "the bridge refuses the polar K settings: $(cat pk.eff)"
ok "the settings carry the amplitude model (Rayleigh: closed form; K with a P_D profile: positions only, said)"

# --- the check refuses the old settings (the bridge's defaults)
build/bin/trk-lcm-bridge --set sensor.0.pd=0.8 --replay detections.lcmlog --out old.lcmlog --keep-input > /dev/null 2>&1 ||
    fail "the old settings' replay exited $?"
build/bin/trk-lcm-bridge --summarize old.lcmlog > old.txt 2>&1 || fail "--summarize old.lcmlog exited $?"
if why=$(check old.txt); then fail "the check accepts the old settings: $(cat old.txt)"; fi
ok "the check refuses the old settings (bridge defaults, P_D 0.8): $why"

# --- live over UDP multicast in a private network namespace
if ! command -v unshare > /dev/null 2>&1 || ! command -v ip > /dev/null 2>&1; then
    skip "live: unshare or ip (iproute2) not installed"
fi
if ! msg=$(timeout 10 unshare -rn sh -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo' 2>&1); then
    skip "live: cannot create a network namespace with a multicast route ($msg)"
fi
command -v lcm-logger > /dev/null 2>&1 || skip "live: no lcm-logger"
rm -f tracks.lcmlog
export C_BRIDGE C_LOGGER C_SONAR
timeout 120 unshare -rn sh -c '
    ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 3
    sh -c "exec $C_BRIDGE" > bridge.out 2>&1 &
    BR=$!
    sh -c "exec $C_LOGGER" > logger.out 2>&1 &
    L=$!
    (sleep 100; kill -KILL $BR) > /dev/null 2>&1 &
    WD=$!
    sleep 1
    sh -c "$C_SONAR" > sonar.out 2>&1 || exit 4
    wait $BR; rc=$?
    kill $WD 2> /dev/null
    sleep 0.5
    kill -INT $L; wait $L
    exit $rc'
rc=$?
[ $rc -eq 0 ] || fail "live run exited $rc: $(cat bridge.out sonar.out logger.out 2> /dev/null)"
grep -q "^scans: received 150, processed 150, rejected 0" bridge.out || fail "live bridge: $(cat bridge.out)"
sh -c "$C_SUMMARY" > live.txt 2>&1 || fail "$C_SUMMARY exited $? (live)"
why=$(check live.txt) || fail "live walk-through: $why: $(cat live.txt)"
ok "live (udpm in a network namespace): $(sed -n 's/^\(confirmed track ids ([0-9]*)\).*/\1/p' live.txt) for 4 targets, 150 scans tracked"
