#!/bin/sh
# tests/sim_assumptions.sh TRK_SIM - the `make test` step sim-assumptions
# (mk/sim-assumptions.mk): the assumptions that change the
# results are options, named in every CSV header and plot title.
#   (a) the defaults give the numbers of before the options (the data rows of
#       tests/sim_assumptions/*.rows, written by the build before them, gcc
#       -O2 double: the default configuration, the only one running this
#       step): brekke-trackloss (its new last column gate_cap_lost left out),
#       brekke-toc (.csv, _mre.csv, _optimum.csv), willett-crlb, toc
#   (b) the options act in the expected direction, same seed:
#       --start steady loses fewer PDAF tracks than two-point (Brekke, 1 m^2);
#       --mre-start zero and steady give the PDAF at P_FA 0.2 (K nu 1, 1 m^2) a
#       finite MRE RMSE of 0.25-0.275 m (measured 0.261 m) where two-point
#       gives inf, and leave the other points' MRE unchanged;
#       --gate-cap truncate:32 truncates in more runs than the default;
#       --gate-cap lost:20 loses tracks by the cap (gate_cap_lost > 0);
#       bad values are refused (exit 2)
#   (c) the CSV headers and the gnuplot titles name start, gate cap and MRE
#       start (toc: the MRE start); brekke-errpdf also the histogram's scans
#       and tracks, its PDAF line at P_FA 0.2 drawn with --mre-start zero
#       only, --tracks all taking at least the kept runs' samples
set -u
sim=$1
STEP=sim-assumptions
. tests/step_lib.sh
G=tests/sim_assumptions
TL="--runs 40 --scans 60 --cell-m2 0.25,1 --k-shape 1 --snr-db 10 --pfa 1e-2,1e-1 --seed 3 --quiet"
BT="--runs 30 --scans 60 --from 31 --k-shape 1 --pfa 1e-3,1e-1,0.2 --q2-samples 2000 --seed 3 --quiet"
rows() { grep -v '^#' "$1"; }
same() { # same FILE GOLDEN: data rows equal
    rows "$1" | cmp -s - "$2" || fail "$1: the default's numbers differ from $2"
}

# (a) defaults
$sim brekke-trackloss $TL --out "$T/tl" > /dev/null || fail "brekke-trackloss failed"
rows "$T/tl.csv" | sed 's/,[^,]*$//' | cmp -s - $G/tl.rows || fail "brekke-trackloss: the default's numbers changed"
$sim brekke-toc $BT --out "$T/bt" > /dev/null || fail "brekke-toc failed"
same "$T/bt.csv" $G/btoc2.rows
same "$T/bt_mre.csv" $G/btoc2_mre.rows
same "$T/bt_optimum.csv" $G/btoc2_optimum.rows
$sim willett-crlb --runs 200 --scans 40 --from 11 --points 0.9:0.001,0.8:0.0001 --q2-samples 20000 --seed 3 \
    --quiet --out "$T/wc" > /dev/null || fail "willett-crlb failed"
same "$T/wc.csv" $G/wc.rows
$sim toc --samples 2000 --target-se 0.01 --points 5 --cells 1,0.1 --pfa-min 1e-3 --seed 3 --quiet \
    --out "$T/toc" > /dev/null || fail "toc failed"
same "$T/toc.csv" $G/toc2.rows
same "$T/toc_optimum.csv" $G/toc2_optimum.rows
ok "defaults: the numbers of before the options (brekke-trackloss, brekke-toc, willett-crlb, toc)"

# (c) the names, defaults
grep -q '^# assumptions: start two-point (--start: .*gate cap truncate:256 (--gate-cap: ' "$T/tl.csv" ||
    fail "brekke-trackloss CSV: no assumptions line"
grep -q '^cell_m2,.*,only_this_lost,gate_cap_lost$' "$T/tl.csv" || fail "brekke-trackloss CSV: no gate_cap_lost column"
grep -q '^# assumptions: start two-point .*gate cap truncate:256 .*, MRE start two-point (--mre-start)' "$T/bt.csv" ||
    fail "brekke-toc CSV: no assumptions line"
grep -q '^# MRE start two-point' "$T/bt_mre.csv" && grep -q '^# MRE start two-point' "$T/bt_optimum.csv" ||
    fail "brekke-toc _mre/_optimum CSV: no MRE start"
grep -q '^# assumptions: start two-point .*gate cap truncate:256' "$T/wc.csv" || fail "willett-crlb CSV: no assumptions"
grep -q '^# assumptions: MRE start two-point' "$T/toc.csv" && grep -q '^# assumptions: MRE start two-point' \
    "$T/toc_optimum.csv" || fail "toc CSV: no MRE start"
grep -q 'title ".*\\nstart two-point, gate cap truncate:256"' "$T/tl.gp" || fail "brekke-trackloss plot title"
grep -q 'title ".*\\nstart two-point, gate cap truncate:256, MRE start two-point"' "$T/bt.gp" ||
    fail "brekke-toc plot title"
grep -q 'title ".*\\nstart two-point, gate cap truncate:256"' "$T/wc.gp" || fail "willett-crlb plot title"
grep -q 'title ".*\\nMRE start two-point"' "$T/toc.gp" || fail "toc plot title"

# (b) directions
col() { # col FILE FILTER N: column N of FILTER's rows, summed
    awk -F, -v f="$2" -v n="$3" '$0 !~ /^#/ && $7 == f { s += $n } END { print s + 0 }' "$1"
}
L="--runs 200 --scans 300 --cell-m2 1 --k-shape 1 --snr-db 10 --pfa 1e-2,1e-1 --seed 3 --quiet --no-plot"
$sim brekke-trackloss $L --out "$T/s2" > /dev/null && $sim brekke-trackloss $L --start steady --out "$T/ss" > /dev/null ||
    fail "brekke-trackloss --start failed"
l2=$(col "$T/s2.csv" PDAF 9) ls=$(col "$T/ss.csv" PDAF 9)
[ "$ls" -lt "$l2" ] || fail "--start steady lost $ls PDAF tracks, two-point $l2: expected fewer"
grep -q '^# assumptions: start steady (--start: initial covariance the clutter-free Kalman steady state)' "$T/ss.csv" ||
    fail "--start steady: not in the CSV header"
# --init, the old spelling, still works (with a note)
$sim brekke-trackloss $L --init steady --out "$T/si" 2> "$T/si.err" > /dev/null && cmp -s "$T/ss.csv" "$T/si.csv" &&
    grep -q 'deprecated' "$T/si.err" || fail "--init steady is not --start steady"
ok "--start steady: $ls lost PDAF tracks, two-point $l2 (200 runs x 2 P_FA, 1 m^2)"
mre() { # mre FILE PFA FILTER: the MRE RMSE of that row
    awk -F, -v p="$2" -v f="$3" '$0 !~ /^#/ && $2 == p && $5 == f { print $6 }' "$1"
}
[ "$(mre "$T/bt.csv" 0.2 PDAF)" = inf ] || fail "brekke-toc two-point: PDAF at 0.2 no longer inf"
for m in zero steady; do
    $sim brekke-toc $BT --no-plot --mre-start $m --out "$T/bt$m" > /dev/null || fail "brekke-toc --mre-start $m failed"
    v=$(mre "$T/bt$m.csv" 0.2 PDAF)
    awk -v v="$v" 'BEGIN { exit !(v + 0 >= 0.25 && v + 0 <= 0.275) }' || fail "--mre-start $m: PDAF at 0.2: $v m"
    for r in "0.001 PDAF" "0.1 PDAF" "0.001 PDAFAI" "0.1 PDAFAI" "0.2 PDAFAI"; do
        set -- $r
        [ "$(mre "$T/bt$m.csv" $1 $2)" = "$(mre "$T/bt.csv" $1 $2)" ] || fail "--mre-start $m changed the MRE of $2 at $1"
    done
    grep -q "^# assumptions: .*, MRE start $m (--mre-start)" "$T/bt$m.csv" || fail "--mre-start $m: not in the CSV"
    eval "v_$m=$v"
done
ok "--mre-start zero / steady: PDAF at P_FA 0.2 (K nu 1, 1 m^2) $v_zero / $v_steady m (two-point: inf); the finite points unchanged"
G1="--runs 40 --scans 60 --cell-m2 0.25 --k-shape 1 --snr-db 10 --pfa 1e-1 --seed 3 --quiet --no-plot"
$sim brekke-trackloss $G1 --out "$T/g0" > /dev/null && $sim brekke-trackloss $G1 --gate-cap truncate:32 --out "$T/g32" > /dev/null &&
    $sim brekke-trackloss $G1 --gate-cap lost:20 --out "$T/gl" > /dev/null || fail "brekke-trackloss --gate-cap failed"
t0=$(col "$T/g0.csv" PDAFAI 17) t32=$(col "$T/g32.csv" PDAFAI 17) gl=$(col "$T/gl.csv" PDAF 22) g0=$(col "$T/g0.csv" PDAF 22)
[ "$t32" -gt "$t0" ] || fail "--gate-cap truncate:32 truncated in $t32 PDAFAI runs, the default in $t0"
[ "$gl" -gt 0 ] && [ "$g0" = 0 ] || fail "--gate-cap lost:20: $gl runs lost by the cap (default: $g0)"
grep -q '^# assumptions: .*gate cap truncate:32 ' "$T/g32.csv" && grep -q '^# assumptions: .*gate cap lost:20 (--gate-cap: the track is lost when lambda V_G exceeds the cap)' "$T/gl.csv" ||
    fail "--gate-cap: not in the CSV header"
for bad in truncate:0 truncate:257 lost:0 lost:-1 lost:inf keep:3 truncate:; do
    $sim brekke-trackloss $G1 --gate-cap "$bad" --out "$T/bad" > /dev/null 2>&1
    [ $? = 2 ] || fail "--gate-cap $bad was not refused with exit status 2"
done
$sim toc --mre-start none > /dev/null 2>&1
[ $? = 2 ] || fail "toc --mre-start none was not refused"
ok "--gate-cap truncate:32: $t32 PDAFAI runs truncated (default truncate:256: $t0); lost:20: $gl PDAF runs lost by the cap; bad values refused"
# brekke-errpdf: the assumptions named; --mre-start zero draws the PDAF's line at P_FA 0.2 where
# two-point has none (inf); --tracks all takes more samples than kept (the lost runs' scans)
E="--runs 40 --scans 60 --from 21 --pfa 1e-1,0.2 --q2-samples 2000 --seed 3 --quiet"
$sim brekke-errpdf $E --out "$T/ep" > /dev/null &&
    $sim brekke-errpdf $E --start steady --mre-start zero --tracks all --out "$T/epz" > /dev/null || fail "brekke-errpdf failed"
grep -q '^# assumptions: start two-point .*gate cap truncate:256 .*, MRE start two-point (--mre-start)' "$T/ep.csv" &&
    grep -q '^# assumptions: start steady .*, MRE start zero (--mre-start)' "$T/epz.csv" &&
    grep -q '^# assumptions: start steady .*, MRE start zero' "$T/epz_fig4.csv" || fail "brekke-errpdf CSV: assumptions not named"
grep -q 'title ".*\\nstart two-point, gate cap truncate:256, MRE start two-point\\nscans >= 21 of 40 runs x 60 scans, tracks not lost' "$T/ep_fig3.gp" &&
    grep -q 'title ".*\\nstart steady, gate cap truncate:256, MRE start zero\\nscans >= 21 of 40 runs x 60 scans, all tracks before loss' "$T/epz_fig4.gp" ||
    fail "brekke-errpdf plot titles: assumptions not named"
ea=$(grep -c '^set arrow' "$T/ep_fig4.gp") ez=$(grep -c '^set arrow' "$T/epz_fig4.gp")
[ "$ea" = 3 ] && [ "$ez" = 4 ] && grep -q "PDAF (MRE [a-z q2]*: no line" "$T/ep_fig4.gp" ||
    fail "brekke-errpdf P_FA 0.2: $ea lines with the two-point MRE start (expected 3: no PDAF MRE), $ez with zero (4)"
awk -F, 'NR == FNR { if ($1 ~ /^[0-9]/) n[$1 $8] = $14; next } $1 ~ /^[0-9]/ && $14 < n[$1 $8] { bad++ } END { exit bad > 0 }' \
    "$T/ep.csv" "$T/epz.csv" || fail "brekke-errpdf --tracks all: fewer samples than kept"
ok "brekke-errpdf: assumptions in CSV headers and titles; PDAF MRE line at P_FA 0.2 with --mre-start zero only ($ea / $ez lines)"
echo "sim-assumptions: defaults unchanged, the options act, CSV headers and plot titles name them"
