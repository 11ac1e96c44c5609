#!/bin/sh
# tests/mtt_sonar_goals.sh TRK_SIM - the `make test` step mtt-sonar-goals (mk/mtt.mk): the
# sonar family's goals, on `trk-sim mtt --family sonar --config oracle,new --clutter-count
# 20,100 --seeds 120` (seeds 1-120, 150 pings each: what docs/results.md and docs/tuning.md
# report), with the library's defaults and the sensor's description. At 20 and at 100
# clutter detections per ping, `new` against the oracle (known association) of the same
# scenarios, each a mean over the 120 seeds:
#   - coverage beyond 5 km >= 0.9 x the oracle's   (measured 2026-12-07: 0.930 / 0.9005)
#   - coverage in the reverberation patches >= 0.9 x the oracle's   (0.964 / 0.951)
#   - GOSPA <= 1.1 x the oracle's                  (1.037 / 1.076)
#   - false confirmed tracks <= 1 per 1000 pings   (0.17 / 0.11)
# The run is deterministic (seeded scenarios, the same rows with any number of threads), so
# a change that moves a figure below its goal fails here, not in a later measurement. False
# tracks on persistent scatterers are printed, not checked: one run of the 120 at 20 per
# ping still has one (docs/tracker.md, "Echoes weighed against a scatterer's").
set -u
sim=$1
STEP=mtt-sonar-goals
. tests/step_lib.sh
d=$T
"$sim" mtt --family sonar --config oracle,new --clutter-count 20,100 --seeds 120 --threads 2 \
    --quiet --no-plot --out "$d/g" >"$d/out.txt" 2>&1 || { cat "$d/out.txt"; fail "trk-sim mtt exited with $?"; }
[ -f "$d/g.csv" ] || fail "no CSV"
awk -F, '
NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
{
    k = $c["config"] " " $c["clutter"]
    gospa[k] = $c["gospa_m_mean"]; far[k] = $c["far_coverage_mean"]; patch[k] = $c["patch_coverage_mean"]
    falsetr[k] = $c["false_tracks_per_1000_scans_mean"]; persist[k] = $c["false_tracks_persistent_per_1000_scans_mean"]
    seen[k] = 1
}
END {
    bad = 0
    for (j = 0; j < 2; j++) {
        lv = j ? 100 : 20; n = "new " lv; o = "oracle " lv
        if (!(n in seen) || !(o in seen)) { printf "mtt-sonar-goals: FAIL: no rows at %d per ping\n", lv; exit 1 }
        rf = far[n] / far[o]; rp = patch[n] / patch[o]; rg = gospa[n] / gospa[o]
        printf "mtt-sonar-goals: %3d per ping: beyond 5 km %.4f x the oracle'\''s, in patches %.4f x, GOSPA %.4f x, false tracks %.2f per 1000 pings (%.2f on persistent returns)\n", \
            lv, rf, rp, rg, falsetr[n], persist[n]
        if (!(rf >= 0.9)) { printf "mtt-sonar-goals: FAIL: beyond 5 km %.4f < 0.9 x the oracle'\''s at %d per ping\n", rf, lv; bad = 1 }
        if (!(rp >= 0.9)) { printf "mtt-sonar-goals: FAIL: in patches %.4f < 0.9 x the oracle'\''s at %d per ping\n", rp, lv; bad = 1 }
        if (!(rg <= 1.1)) { printf "mtt-sonar-goals: FAIL: GOSPA %.4f > 1.1 x the oracle'\''s at %d per ping\n", rg, lv; bad = 1 }
        if (!(falsetr[n] <= 1)) { printf "mtt-sonar-goals: FAIL: %.2f false tracks per 1000 pings at %d per ping\n", falsetr[n], lv; bad = 1 }
    }
    exit bad
}' "$d/g.csv" || exit 1
ok "the sonar family meets its goals at 20 and 100 per ping"
