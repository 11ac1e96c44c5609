#!/bin/sh
# tuning_sweep.sh - what each tracker setting changes, measured: `make tuning`.
#
#   sh tools/scripts/tuning_sweep.sh TRK_SIM OUTDIR [SEEDS] [SCANS]
#
# Runs `trk-sim mtt --config new` (the defaults: joint association,
# existence tests, two-point initiation) on the transit family (P_D 0.8,
# sigma 5 m, a scan every 4 s, 6-8 targets in 3 km x 3 km) at two clutter
# levels, 20 and 200 detections per scan (lambda = 2.2e-6 and 2.2e-5 per
# m^2), changing one setting at a time while the sensor stays the same:
#   pd        the P_D the tracker assumes (sensor.0.pd; the truth is 0.8),
#             positions only (--no-amplitude: with amplitudes P_D is the
#             amplitude model's, from its SNR and threshold)
#   snr       the target SNR the amplitude model assumes (sensor.0.snr_db;
#             the truth is 13 dB: P_D 0.8 at the threshold's P_FA)
#   density   the clutter density it assumes, as a factor of the true one
#             (sensor.0.clutter_density_per_m2 = factor x count / 9e6 m^2)
#   gate      gate_prob, P_G
#   confirm   confirm.existence.p_confirm
#   term      term.existence.p_terminate
#   capacity  the clutter count itself, up to 4 x TRK_MAX_DETECTIONS (the
#             tracker thins a scan beyond capacity)
# For each, OUTDIR/tune_<name>.dat (one row per value and clutter level:
# value, clutter, GOSPA mean lo hi, its missed and false parts (m^2), false
# tracks per 1000 scans mean lo hi, scans to confirm, coverage) and
# OUTDIR/tune_<name>.png (gnuplot, when present). Every configuration runs
# on the same scenarios (common random numbers: seeds 1..SEEDS).
set -eu
sim=$1
out=$2
seeds=${3:-20}
scans=${4:-200}
mkdir -p "$out"

# run NAME VALUE CLUTTER_LIST [trk-sim options]: one trk-sim mtt run, its
# rows appended to OUTDIR/tune_NAME.dat
run() {
    name=$1 value=$2 clutter=$3
    shift 3
    "$sim" mtt --config new --seeds "$seeds" --scans "$scans" --clutter-count "$clutter" \
        --no-plot --quiet --threads 2 --out "$out/tune_$name-$value" "$@" >/dev/null
    awk -F, -v v="$value" '
        NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
        { print v, $c["clutter"], $c["gospa_m_mean"], $c["gospa_m_lo"], $c["gospa_m_hi"],
                $c["gospa_missed_m2_mean"], $c["gospa_false_m2_mean"],
                $c["false_tracks_per_1000_scans_mean"], $c["false_tracks_per_1000_scans_lo"],
                $c["false_tracks_per_1000_scans_hi"], $c["scans_to_confirm_mean"], $c["coverage_mean"] }
    ' "$out/tune_$name-$value.csv" >> "$out/tune_$name.dat"
}

# begin NAME: a fresh table with its header
begin() {
    printf '# value clutter gospa_m gospa_lo gospa_hi missed_m2 false_m2 false_tracks_per_1000 ft_lo ft_hi scans_to_confirm coverage\n' \
        > "$out/tune_$1.dat"
}

begin pd
for v in 0.5 0.6 0.7 0.8 0.9 0.95 0.99; do run pd "$v" 20,200 --no-amplitude --set sensor.0.pd="$v"; done

begin snr
for v in 7 10 13 16 19; do run snr "$v" 20,200 --set sensor.0.snr_db="$v"; done

begin density
for f in 0.1 0.3 1 3 10; do
    for n in 20 200; do
        run density "$f" "$n" --set sensor.0.clutter_density_per_m2="$(awk -v f="$f" -v n="$n" 'BEGIN { printf "%.6g", f * n / 9e6 }')"
    done
done

begin gate
for v in 0.9 0.95 0.99 0.999 0.9999; do run gate "$v" 20,200 --set gate_prob="$v"; done

begin confirm
for v in 0.9 0.99 0.999 0.9999 0.99999; do run confirm "$v" 20,200 --set confirm.existence.p_confirm="$v"; done

begin term
for v in 0.01 0.03 0.1 0.3 0.5; do run term "$v" 20,200 --set term.existence.p_terminate="$v"; done

begin capacity
run capacity default 0,64,128,256,384,512,768,1024

command -v gnuplot >/dev/null 2>&1 || { echo "tuning: gnuplot not found, tables only in $out"; exit 0; }

# plot NAME XLABEL: GOSPA, its missed and false parts, false tracks and
# scans to confirm against the value, one line per clutter level (the value
# as a category on x)
plot() {
    name=$1 xlabel=$2
    for n in 20 200; do awk -v n="$n" '!/^#/ && $2 == n' "$out/tune_$name.dat" > "$out/tune_$name-c$n.dat"; done
    a="$out/tune_$name-c20.dat" b="$out/tune_$name-c200.dat"
    gnuplot <<EOF
set terminal pngcairo size 1600,360 font ",10"
set output "$out/tune_$name.png"
set multiplot layout 1,4
set grid
set key top center box opaque
set xlabel "$xlabel"
set offsets 0.3, 0.3, 0, 0
set title "GOSPA (m), mean and 95 % interval"
plot "$a" using 0:3:4:5:xtic(1) with yerrorlines title "20 clutter/scan", \
     "$b" using 0:3:4:5:xtic(1) with yerrorlines title "200 clutter/scan"
set title "GOSPA parts (m^2): missed (solid), false (dashed)"
plot "$a" using 0:6:xtic(1) with linespoints lc 1 title "20", "$b" using 0:6:xtic(1) with linespoints lc 2 title "200", \
     "$a" using 0:7:xtic(1) with linespoints lc 1 dt 2 notitle, "$b" using 0:7:xtic(1) with linespoints lc 2 dt 2 notitle
set title "false tracks per 1000 scans"
set yrange [0:1<*]
plot "$a" using 0:8:9:10:xtic(1) with yerrorlines title "20", "$b" using 0:8:9:10:xtic(1) with yerrorlines title "200"
set title "scans to confirm a new target"
set autoscale y
plot "$a" using 0:11:xtic(1) with linespoints title "20", "$b" using 0:11:xtic(1) with linespoints title "200"
unset multiplot
EOF
}

plot pd "P_D the tracker assumes (true 0.8; positions only)"
plot snr "SNR the amplitude model assumes, dB (true 13)"
plot density "assumed clutter density / true"
plot gate "gate probability P_G"
plot confirm "existence to confirm"
plot term "existence to terminate"

awk '!/^#/' "$out/tune_capacity.dat" > "$out/tune_capacity-all.dat"
gnuplot <<EOF
set terminal pngcairo size 1200,360 font ",10"
set output "$out/tune_capacity.png"
set multiplot layout 1,3
set grid
set key off
set xlabel "clutter detections per scan (capacity 256)"
set title "GOSPA (m), mean and 95 % interval"
plot "$out/tune_capacity-all.dat" using 2:3:4:5 with yerrorlines
set title "false tracks per 1000 scans"
set yrange [0:1<*]
plot "$out/tune_capacity-all.dat" using 2:8:9:10 with yerrorlines
set title "coverage (targets held by a confirmed track)"
set autoscale y
plot "$out/tune_capacity-all.dat" using 2:12 with linespoints
unset multiplot
EOF
echo "tuning: tables and plots in $out"
