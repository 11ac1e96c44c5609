#!/bin/sh
# tests/mtt_sonar_goals.sh TRK_SIM - the `make test` step mtt-sonar-goals (mk/mtt.mk): the
# sonar family's goals, on `trk-sim mtt --family sonar --config oracle,new --clutter-count
# 20,100 --seeds 120` (seeds 1-120, 150 pings each: what docs/results.md and docs/tuning.md
# report), with the library's defaults and the sensor's description. At 20 and at 100
# clutter detections per ping, `new` against the oracle (known association) of the same
# scenarios, each a mean over the 120 seeds:
#   - coverage beyond 5 km >= 0.9 x the oracle's   (measured 2026-12-08: 0.930 / 0.9004)
#   - coverage in the reverberation patches >= 0.9 x the oracle's   (0.965 / 0.952)
#   - GOSPA <= 1.1 x the oracle's                  (1.035 / 1.074)
#   - false confirmed tracks <= 1 per 1000 pings   (0.17 / 0.00)
# The run is deterministic (seeded scenarios, the same rows with any number of threads), so
# a change that moves a figure below its goal fails here, not in a later measurement. The
# margin beyond 5 km at 100 per ping is 0.0004 on these seeds (other sets of 120 seeds:
# 0.906-0.922, docs/tuning.md): a change that costs the far targets a few pings fails here
# on purpose, and is then measured on more seeds before the goal or the change moves.
#   - no false confirmed track on a persistent scatterer   (0.00 / 0.00; on four other sets
#     of 120 seeds, two runs of the 960 still have one: docs/tracker.md, "Echoes weighed
#     against a scatterer's")
set -u
sim=$1
STEP=mtt-sonar-goals
. tests/step_lib.sh
d=$T
"$sim" mtt --family sonar --config oracle,new --clutter-count 20,100 --seeds 120 --threads 2 \
    --quiet --no-plot --out "$d/g" >"$d/out.txt" 2>&1 || { rc=$?; cat "$d/out.txt"; fail "trk-sim mtt exited with $rc"; }
[ -f "$d/g.csv" ] || fail "no CSV"
awk -F, -v step="$STEP" '
NR == 1 {
    for (i = 1; i <= NF; i++) c[$i] = i
    split("config clutter family seeds scans gospa_m_mean far_coverage_mean patch_coverage_mean false_tracks_per_1000_scans_mean false_tracks_persistent_per_1000_scans_mean", need, " ")
    for (j in need) if (!(need[j] in c)) { printf "%s: FAIL: no column %s in the CSV\n", step, need[j]; dead = 1; exit 2 }
    next
}
{
    rows++
    if ($c["family"] != "sonar" || $c["seeds"] != 120 || $c["scans"] != 150) {
        printf "%s: FAIL: a row of family %s, %s seeds, %s scans (want sonar, 120, 150)\n", step, $c["family"], $c["seeds"], $c["scans"]
        dead = 1; exit 2
    }
    k = $c["config"] " " $c["clutter"]
    gospa[k] = $c["gospa_m_mean"]; far[k] = $c["far_coverage_mean"]; patch[k] = $c["patch_coverage_mean"]
    falsetr[k] = $c["false_tracks_per_1000_scans_mean"]; persist[k] = $c["false_tracks_persistent_per_1000_scans_mean"]
    seen[k] = 1
}
END {
    if (dead) exit 2   # a main rule failed: awk runs END after its exit
    if (rows != 4) { printf "%s: FAIL: %d rows (want oracle and new at 20 and 100)\n", step, rows; exit 2 }
    bad = 0
    for (j = 0; j < 2; j++) {
        lv = j ? 100 : 20; n = "new " lv; o = "oracle " lv
        if (!(n in seen) || !(o in seen)) { printf "%s: FAIL: no rows at %d per ping\n", step, lv; exit 2 }
        # the oracle is the yardstick: it must have covered the far and patch targets
        if (!(far[o] > 0.5 && patch[o] > 0.5 && gospa[o] > 0)) {
            printf "%s: FAIL: the oracle at %d per ping: beyond 5 km %s, in patches %s, GOSPA %s\n", step, lv, far[o], patch[o], gospa[o]
            exit 2
        }
        rf = far[n] / far[o]; rp = patch[n] / patch[o]; rg = gospa[n] / gospa[o]
        printf "%s: %3d per ping: beyond 5 km %.4f x the oracle'\''s, in patches %.4f x, GOSPA %.4f x, false tracks %.2f per 1000 pings (%.2f on persistent returns)\n", \
            step, lv, rf, rp, rg, falsetr[n], persist[n]
        if (!(rf >= 0.9)) { printf "%s: FAIL: beyond 5 km %.4f < 0.9 x the oracle'\''s at %d per ping\n", step, rf, lv; bad = 1 }
        if (!(rp >= 0.9)) { printf "%s: FAIL: in patches %.4f < 0.9 x the oracle'\''s at %d per ping\n", step, rp, lv; bad = 1 }
        if (!(rg <= 1.1)) { printf "%s: FAIL: GOSPA %.4f > 1.1 x the oracle'\''s at %d per ping\n", step, rg, lv; bad = 1 }
        if (!(falsetr[n] <= 1)) { printf "%s: FAIL: %.2f false tracks per 1000 pings at %d per ping\n", step, falsetr[n], lv; bad = 1 }
        if (!(persist[n] == 0)) { printf "%s: FAIL: %.2f false tracks on persistent returns per 1000 pings at %d per ping\n", step, persist[n], lv; bad = 1 }
    }
    exit bad
}' "$d/g.csv"
rc=$?
[ $rc -eq 0 ] || { [ $rc -eq 1 ] || [ $rc -eq 2 ] || fail "the check of $d/g.csv stopped (awk exit $rc)"; exit 1; }
ok "the sonar family meets its goals at 20 and 100 per ping"
