#!/bin/sh
# tests/mtt_smoke.sh TRK_SIM - the `make test` step mtt-smoke (mk/mtt.mk): a short
# `trk-sim mtt --scans 30 --seeds 2 --clutter-count 0,50` run, with 1 and 2 OpenMP
# threads (the transit family, the default), one with --family fixed (1 thread), and
# their CSVs checked:
#   - the header: the key columns (capacity,config,clutter,seeds,scans,amplitude,family),
#     then <metric>_mean,_lo,_hi for the metrics below
#   - exactly the rows (capacity, config, clutter) = (one capacity) x {new, pda, old, oracle} x {0, 50},
#     seeds 2, scans 30, amplitude 1, family the one asked for
#   - per row and metric lo <= mean <= hi; coverage, turn/pair/cross fractions in [0, 1];
#     GOSPA and its parts >= 0; clutter per scan = the count asked for unless capped;
#     detections counted by the tracker = the scan sizes (30 x (clutter + targets'));
#     targets present per scan in (0, 8] (eight slots), at least 8 targets per run;
#     fixed: exactly 8 targets per run, 7-8 present per scan (7 before the birth and
#     after the death, 8 between)
#   - at clutter 0 the four configurations hold the targets: coverage > 0.3, every
#     target confirmed at some scan
#   - the oracle (known association) does not see the clutter: its GOSPA, parts and
#     coverage the same at 0 and 50; where the targets move as its model says (the
#     turn flattened: --turn-deg 1 --turn-rate 0.01, a run of its own) its GOSPA is
#     not above the default configuration's (new) at the lowest clutter level. (With
#     the 3 deg/s turn and the trackers' q a CV filter lags the turning target beyond
#     the cut-off and, unlike a tracker, never restarts: there it is no bound.)
#   - the manoeuvres: a run with a 120 deg turn at 1 deg/s and the
#     straight target accelerating (--accel 0.1) passes the same checks, its
#     turn_*/accel_* fractions in [0, 1], the acceleration's defined (not nan) and
#     RMSE >= 0; without --accel the accel_* columns are nan; --config imm in a build
#     without IMM tracks is refused (exit 2) with a message naming make mtt-imm
#   - every column but the CPU time identical with 1 and 2 threads
#   - --config known (only the targets' detections): per seed at 50 per scan new's
#     detections less known's are the clutter's (30 x 50), at clutter 0 the same rows as new's
#   - trk-sim mtt-compare merges the transit and the fixed CSV (16 rows: the family is
#     part of the key) and refuses two CSVs of the same family and capacity
set -u
sim=$1
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
fail() {
    echo "mtt-smoke: FAILED: $*"
    exit 1
}
for t in 1 2; do
    "$sim" mtt --scans 30 --seeds 2 --clutter-count 0,50 --seed 3 --threads $t --quiet --no-plot \
        --out "$d/m$t" >"$d/out$t.txt" 2>&1 || { rc=$?; cat "$d/out$t.txt"; fail "trk-sim mtt exited with $rc"; }
done
"$sim" mtt --family fixed --scans 30 --seeds 2 --clutter-count 0,50 --seed 3 --threads 1 --quiet --no-plot \
    --out "$d/f1" >"$d/outf.txt" 2>&1 || { rc=$?; cat "$d/outf.txt"; fail "trk-sim mtt --family fixed exited with $rc"; }
"$sim" mtt --scans 30 --seeds 2 --clutter-count 0,50 --seed 3 --threads 1 --quiet --no-plot --turn-rate 1 \
    --turn-deg 120 --accel 0.1 --accel-s 60 --out "$d/a1" >"$d/outa.txt" 2>&1 ||
    { rc=$?; cat "$d/outa.txt"; fail "trk-sim mtt --accel exited with $rc"; }
"$sim" mtt --scans 30 --seeds 2 --clutter-count 0,50 --seed 3 --threads 1 --quiet --no-plot --turn-rate 0.01 \
    --turn-deg 1 --out "$d/s1" >"$d/outs.txt" 2>&1 || { rc=$?; cat "$d/outs.txt"; fail "trk-sim mtt (no turn) exited with $rc"; }
# check CSV FAMILY [ACCEL [BOUND]] (BOUND 1: the oracle's GOSPA at most new's at the lowest clutter)
check() {
    [ -f "$1" ] || fail "no CSV written ($1)"
    awk -F, -v family="$2" -v accel="${3:-0}" -v bound="${4:-0}" -v want_metrics="turn_rmse_m turn_after_coverage turn_lost accel_coverage accel_rmse_m accel_lost targets_per_run targets_present_per_scan gospa_m gospa_loc_m2 gospa_missed_m2 gospa_false_m2 scans_to_confirm never_confirmed to_confirm_cross to_confirm_pair to_confirm_turn to_confirm_straight to_confirm_birth to_confirm_death coverage turn_coverage parallel_both cross_both false_tracks_per_1000_scans false_track_scans_per_100 duplicate_track_scans_per_100 fragmentations id_switches rmse_m cpu_us_per_scan rep_n_init_refused_full" '
function bad(msg) { print "mtt-smoke: FAILED: " msg; err = 1; exit 1 }
NR == 1 {
    if ($1 != "capacity" || $2 != "config" || $3 != "clutter" || $4 != "seeds" || $5 != "scans" || $6 != "amplitude" ||
        $7 != "family")
        bad("header starts " $1 "," $2 "," $3 "," $4 "," $5 "," $6 "," $7)
    ncol = NF
    for (i = 1; i <= NF; i++) col[$i] = i
    n = split(want_metrics, w, " ")
    for (k = 1; k <= n; k++)
        for (p = 1; p <= 3; p++) {
            c = w[k] (p == 1 ? "_mean" : p == 2 ? "_lo" : "_hi")
            if (!(c in col)) bad("no column " c)
        }
    if ((NF - 7) % 3 != 0) bad("metric columns not in threes: " NF " columns")
    next
}
{
    rows++
    if (NF != ncol) bad("row " NR ": " NF " fields")
    if ($1 !~ /^[0-9]+$/ || $1 < 1) bad("row " NR ": capacity " $1)
    if (cap == "") cap = $1
    if ($1 != cap) bad("two capacities in one run")
    if ($4 != 2 || $5 != 30 || $6 != 1) bad("row " NR ": seeds/scans/amplitude " $4 "/" $5 "/" $6)
    if ($7 != family) bad("row " NR ": family " $7 ", want " family)
    key = $2 "/" $3
    if (key in seen) bad("row " key " twice")
    seen[key] = 1
    for (i = 8; i + 2 <= NF; i += 3) {
        if ($i == "nan" || $i == "-nan") continue
        if (!($(i + 1) <= $i + 1e-9 * (1 + ($i < 0 ? -$i : $i)) && $i <= $(i + 2) + 1e-9 * (1 + ($i < 0 ? -$i : $i))))
            bad("row " key ": column " i " mean " $i " not in [" $(i + 1) ", " $(i + 2) "]")
    }
    split("coverage turn_coverage turn_after_coverage turn_lost accel_coverage accel_after_coverage accel_lost " \
          "parallel_both cross_both", f01, " ")
    for (k in f01) { v = $(col[f01[k] "_mean"]); if (v != "nan" && (v < 0 || v > 1)) bad(key ": " f01[k] " " v) }
    split("gospa_m gospa_loc_m2 gospa_missed_m2 gospa_false_m2 rmse_m turn_rmse_m accel_rmse_m", fpos, " ")
    for (k in fpos) if ($(col[fpos[k] "_mean"]) < 0) bad(key ": " fpos[k] " < 0")
    acc = $(col["accel_coverage_mean"])
    if (accel && (acc == "nan" || acc == "-nan")) bad(key ": accel_coverage undefined with --accel")
    if (!accel && acc != "nan" && acc != "-nan") bad(key ": accel_coverage " acc " without --accel")
    cl = $(col["clutter_per_scan_mean"])
    if ($(col["clutter_capped_scans_mean"]) == 0 && cl != $3) bad(key ": clutter per scan " cl ", asked " $3)
    if (cl > $3) bad(key ": clutter per scan " cl " > " $3)
    dets = $(col["rep_n_detections_mean"])
    if (dets < 30 * cl || dets > 30 * (cl + 8)) bad(key ": " dets " detections in 30 scans at clutter " cl)
    np = $(col["targets_present_per_scan_mean"]); ntg = $(col["targets_per_run_mean"])
    if (!(np > 0 && np <= 8)) bad(key ": targets present per scan " np ", want (0, 8]")
    if (ntg < 8) bad(key ": " ntg " targets per run, want >= 8 (one per slot at least)")
    if (family == "fixed" && (ntg != 8 || np < 7 || np > 8))
        bad(key ": fixed family: " ntg " targets per run, " np " present per scan, want 8 and [7, 8]")
    if ($3 == 0) {
        if ($(col["coverage_mean"]) <= 0.3) bad(key ": coverage " $(col["coverage_mean"]))
        if ($(col["never_confirmed_mean"]) != 0) bad(key ": targets never confirmed " $(col["never_confirmed_mean"]))
    }
    if (family == "fixed" && $(col["never_confirmed_mean"]) == 0) {
        # the eight designated targets alone, all confirmed: the overall mean is the weighted mean by role
        split("cross pair turn straight birth death", rl, " ")
        split("2 2 1 1 1 1", rw, " ")
        sum = 0
        for (k = 1; k <= 6; k++) sum += rw[k] * $(col["to_confirm_" rl[k] "_mean"])
        all = $(col["scans_to_confirm_mean"])
        if ((sum / 8 - all) ^ 2 > 1e-18 * (1 + all * all))
            bad(key ": scans to confirm " all ", its roles give " sum / 8)
    }
    if ($2 == "oracle") {
        acc_o = ""
        split("gospa_m gospa_loc_m2 gospa_missed_m2 gospa_false_m2 coverage", fo, " ")
        for (k = 1; k <= 5; k++) acc_o = acc_o $(col[fo[k] "_mean"]) " "
        if (oracle_acc != "" && acc_o != oracle_acc)
            bad("oracle: clutter " $3 " changes it (GOSPA, parts, coverage " acc_o " against " oracle_acc ")")
        oracle_acc = acc_o
    }
    if ($2 == "new" || $2 == "oracle")
        if (!(($2 "_low") in gospa_low) || $3 < low[$2]) { low[$2] = $3; gospa_low[$2 "_low"] = $(col["gospa_m_mean"]) }
}
END {
    if (err) exit 1
    if (rows != 8) bad(rows " rows, want 8")
    if (!("new/0" in seen) || !("new/50" in seen) || !("pda/0" in seen) || !("pda/50" in seen) ||
        !("old/0" in seen) || !("old/50" in seen) || !("oracle/0" in seen) || !("oracle/50" in seen))
        bad("rows are not {new, pda, oracle, old} x {0, 50}")
    if (bound && !(gospa_low["oracle_low"] <= gospa_low["new_low"]))
        bad("oracle GOSPA " gospa_low["oracle_low"] " m above that of new, " gospa_low["new_low"] " m at clutter " low["new"])
}' "$1" || exit 1
}
check "$d/m1.csv" transit
check "$d/f1.csv" fixed
check "$d/a1.csv" transit 1
check "$d/s1.csv" transit 0 1
grep -q '^-- manoeuvres' "$d/outa.txt" && grep -q 'accel cov' "$d/outa.txt" || fail "no manoeuvre table on stdout"
if "$sim" mtt --config imm --scans 30 --seeds 1 --no-plot --quiet --out "$d/i1" >"$d/outi.txt" 2>&1; then
    grep -q 'imm' "$d/outi.txt" || fail "--config imm ran without an imm configuration"
else
    [ $? -eq 2 ] && grep -q 'make mtt-imm' "$d/outi.txt" || { cat "$d/outi.txt"; fail "--config imm: no clear refusal"; }
fi
# the same with 2 threads, except the CPU time (the columns named cpu_*)
strip() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /^cpu_/ }
             { s = ""; for (i = 1; i <= NF; i++) if (keep[i]) s = s $i ","; print s }' "$1"
}
strip "$d/m1.csv" >"$d/s1" && strip "$d/m2.csv" >"$d/s2" || fail "cannot read the CSV files"
cmp -s "$d/s1" "$d/s2" || fail "the CSV depends on the thread count (cpu_* columns aside)"
grep -q ' transit new  *50 ' "$d/out1.txt" && grep -q ' transit old  *0 ' "$d/out1.txt" &&
    grep -q ' transit oracle  *50 ' "$d/out1.txt" || fail "no table on stdout (with the oracle's rows)"
grep -q '^== trk-sim mtt: family transit,' "$d/out1.txt" || fail "no family in the header line (transit)"
grep -q ' fixed  *new  *50 ' "$d/outf.txt" && grep -q '^== trk-sim mtt: family fixed,' "$d/outf.txt" ||
    fail "no fixed-family table or header line on stdout"
# every run in PREFIX_runs.csv: 4 configurations x 2 levels x 2 seeds, seeds 3 and 4;
# their mean per (config, clutter) is the CSV's mean; the paired table's ratio of
# new over the oracle is the ratio of their sums over the seeds (printed to 3 decimals)
runs="$d/m1_runs.csv"
[ -f "$runs" ] || fail "no per-run CSV ($runs)"
awk -F, -v agg="$d/m1.csv" -v out="$d/out1.txt" '
function bad(msg) { print "mtt-smoke: FAILED: runs CSV: " msg; err = 1; exit 1 }
function abs(x) { return x < 0 ? -x : x }
NR == 1 {
    if ($1 != "capacity" || $2 != "config" || $3 != "clutter" || $4 != "family" || $5 != "seed" || $6 != "gospa_m")
        bad("header starts " $1 "," $2 "," $3 "," $4 "," $5 "," $6)
    next
}
{
    rows++
    if ($4 != "transit" || ($5 != 3 && $5 != 4)) bad("row " NR ": family " $4 ", seed " $5)
    k = $2 "/" $3
    sum[k] += $6
    cnt[k]++
}
END {
    if (err) exit 1
    if (rows != 16) bad(rows " rows, want 16")
    FS = ","
    while ((getline line < agg) > 0) {
        split(line, f, ",")
        if (f[1] == "capacity") { for (i = 1; i in f; i++) if (f[i] == "gospa_m_mean") gc = i; continue }
        k = f[2] "/" f[3]
        if (cnt[k] != 2) bad("(" k ") has " cnt[k] " runs")
        m = sum[k] / 2
        if (abs(m - f[gc]) > 1e-4 * (abs(m) + 1)) bad("(" k ") mean GOSPA " m " against the CSV mean " f[gc])
        checked++
    }
    if (checked != 8) bad(checked " aggregate rows matched, want 8")
    FS = " "
    while ((getline line < out) > 0) {
        n = split(line, f, " ")
        if (n >= 5 && f[2] == "transit" && f[3] == "new" && f[5] ~ /^[0-9.]+$/ && f[6] ~ /^\[/) {
            r = sum["new/" f[4]] / sum["oracle/" f[4]]
            if (abs(r - f[5]) > 6e-4) bad("paired ratio " f[5] " at clutter " f[4] ", runs give " r)
            paired++
        }
    }
    if (paired != 2) bad(paired " paired rows of new found, want 2")
}' "$runs" || exit 1
grep -q '^-- paired against oracle on the same seeds' "$d/out1.txt" || fail "no paired table against the oracle"
"$sim" mtt --scans 30 --seeds 2 --clutter-count 0 --config new,old --paired-base nope --quiet --no-plot \
    --out "$d/pb" >"$d/outpb.txt" 2>&1 && fail "--paired-base nope accepted"
grep -q 'not one of --config' "$d/outpb.txt" || { cat "$d/outpb.txt"; fail "--paired-base: no clear refusal"; }
# known: the scans reduced to the targets' detections
"$sim" mtt --scans 30 --seeds 2 --clutter-count 0,50 --seed 3 --config new,known --threads 1 --quiet --no-plot \
    --out "$d/k" >"$d/outk.txt" 2>&1 || { rc=$?; cat "$d/outk.txt"; fail "trk-sim mtt --config new,known exited with $rc"; }
awk -F, '
function bad(msg) { print "mtt-smoke: FAILED: known: " msg; err = 1; exit 1 }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    det[$2 "/" $3 "/" $5] = $(col["rep_n_detections"])
    r = ""
    for (i = 6; i <= NF; i++) if (i != col["cpu_us_per_scan"]) r = r "," $i
    row[$2 "/" $3 "/" $5] = r
}
END {
    if (err) exit 1
    n = 0
    for (k in det) {
        split(k, f, "/")
        if (f[1] != "known") continue
        n++
        o = "new/" f[2] "/" f[3]
        if (f[2] == 50 && det[o] - det[k] != 30 * 50) bad("seed " f[3] ": new saw " det[o] ", known " det[k])
        if (f[2] == 0 && row[o] != row[k]) bad("seed " f[3] ": at clutter 0 known differs from new")
    }
    if (n != 4) bad(n " runs")
}' "$d/k_runs.csv" || exit 1
# mtt-compare: the family is part of the key
"$sim" mtt-compare "$d/m1.csv" "$d/f1.csv" --no-plot --out "$d/c" >"$d/outc.txt" 2>&1 ||
    { rc=$?; cat "$d/outc.txt"; fail "trk-sim mtt-compare of a transit and a fixed CSV exited with $rc"; }
[ "$(awk -F, 'NR > 1' "$d/c.csv" | wc -l)" -eq 16 ] || fail "mtt-compare: not 16 rows merged"
[ "$(awk -F, 'NR > 1 && $7 == "fixed"' "$d/c.csv" | wc -l)" -eq 8 ] || fail "mtt-compare: not 8 fixed rows"
if "$sim" mtt-compare "$d/m1.csv" "$d/m2.csv" --no-plot --out "$d/c2" >"$d/outc2.txt" 2>&1; then
    fail "mtt-compare merged two CSVs of one family and capacity"
fi
grep -q 'appears twice' "$d/outc2.txt" || { cat "$d/outc2.txt"; fail "mtt-compare: no 'appears twice' message"; }
echo "mtt-smoke: trk-sim mtt: 8 rows (new, pda, old, oracle x clutter 0, 50) checked per family (transit, fixed)" \
    "and with the manoeuvres (turn, acceleration); the oracle blind to clutter and, without the turn, GOSPA <= new's;" \
    "transit identical with 1 and 2 threads; the per-run CSV and the paired table agree with the means;" \
    "known sees its targets alone; mtt-compare keys rows by family"
