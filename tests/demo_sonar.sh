#!/bin/sh
# tests/demo_sonar.sh TRK_SIM - the `make test` step demo-sonar-check (mk/demo.mk): `trk-sim
# demo` (make demo's sonar, seed 1, 150 pings, 50 clutter per ping) run with --no-plot and
# its files checked against what it must show; thresholds from the measured run (2026-12-06)
# with a margin, the measured value (2026-12-08) in brackets:
#   - every target present for 25 pings or more gets a confirmed track (8 of 8)
#   - coverage >= 0.75 x the oracle's (0.896 / 0.962 = 0.93), beyond 5 km >= 0.7 x (0.93)
#   - at most 10 false confirmed tracks (5), most not on persistent scatterers (0 of 5)
#   - the position RMSE of each range band at most 1.5 x the oracle's (0.73, 0.99, 1.11)
#   - the files agree with the summary: detections.csv holds `detections` rows,
#     tracks.csv `confirmed_track_pings`, persistent.csv the 12 scatterers, pose.csv a
#     row per ping; error_by_range.csv's bands are the summary's
set -u
sim=$1
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
fail() {
    echo "demo-sonar-check: FAILED: $*"
    exit 1
}
"$sim" demo --no-plot --out "$d/demo" >"$d/out.txt" 2>&1 || { rc=$?; cat "$d/out.txt"; fail "trk-sim demo exited $rc"; }
s="$d/demo/summary.csv"
[ -f "$s" ] || fail "no summary.csv"
v() { awk -F, -v k="$1" '$1 == k { print $2; f = 1 } END { if (!f) print "missing" }' "$s"; }
rows() { echo $(($(wc -l <"$1") - 1)); }
awk -v a="$(v targets_confirmed_25)" -v b="$(v targets_present_25)" 'BEGIN { exit !(b >= 6 && a == b) }' ||
    fail "targets present 25+ pings $(v targets_present_25), confirmed $(v targets_confirmed_25)"
awk -v t="$(v coverage)" -v o="$(v oracle_coverage)" 'BEGIN { exit !(t >= 0.75 * o && o > 0.9) }' ||
    fail "coverage $(v coverage) against the oracle's $(v oracle_coverage)"
awk -v t="$(v far_coverage)" -v o="$(v oracle_far_coverage)" 'BEGIN { exit !(t >= 0.7 * o) }' ||
    fail "beyond 5 km $(v far_coverage) against the oracle's $(v oracle_far_coverage)"
awk -v n="$(v false_tracks)" -v p="$(v false_tracks_persistent)" 'BEGIN { exit !(n <= 10 && 2 * p <= n) }' ||
    fail "false tracks $(v false_tracks), on persistent scatterers $(v false_tracks_persistent)"
for b in 500_2500 2500_5000 5000_8000; do
    awk -v t="$(v rmse_${b}_m)" -v o="$(v oracle_rmse_${b}_m)" 'BEGIN { exit !(t > 0 && t <= 1.5 * o) }' ||
        fail "RMSE $b m: $(v rmse_${b}_m) against the oracle's $(v oracle_rmse_${b}_m)"
done
[ "$(rows "$d/demo/detections.csv")" -eq "$(v detections)" ] || fail "detections.csv rows != detections $(v detections)"
[ "$(rows "$d/demo/tracks.csv")" -eq "$(v confirmed_track_pings)" ] || fail "tracks.csv rows != confirmed track pings"
[ "$(rows "$d/demo/persistent.csv")" -eq 12 ] || fail "persistent.csv: not 12 scatterers"
[ "$(rows "$d/demo/pose.csv")" -eq "$(v pings)" ] || fail "pose.csv: not one row per ping"
awk -F, -v r1="$(v rmse_500_2500_m)" 'NR == 2 { exit !($4 == r1) }' "$d/demo/error_by_range.csv" ||
    fail "error_by_range.csv disagrees with summary.csv"
grep -q '^-- coverage' "$d/out.txt" && grep -q 'beyond 5 km' "$d/out.txt" || fail "no coverage table on stdout"
echo "demo-sonar-check: trk-sim demo: $(v targets_confirmed_25) of $(v targets_present_25) targets confirmed," \
    "coverage $(v coverage) (oracle $(v oracle_coverage)), beyond 5 km $(v far_coverage)," \
    "$(v false_tracks) false tracks; files agree with the summary"
