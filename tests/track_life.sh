#!/bin/sh
# tests/track_life.sh TRK_SIM - the `make test` step track-life (mk/track-life.mk):
# trk-sim operating-point and trk-sim hyca as documented, their CSV checked:
#   operating-point (polar sensor, 20 P_FA): 20 rows; P_FA increasing and
#     equally spaced in ln; P_D increasing (the ROC); lambda = P_FA / cell;
#     the CRLB below the MRE wherever the MRE has a steady state; the mean
#     track life falls as P_FA (the clutter) rises once it is finite; the TOC
#     optimum inside the range with an RMSE at most every row's
#   hyca: the predicted loss and life inside [0, 1] and [1, scans]; the
#     simulated intervals ordered; a longer life at lower clutter (simulated)
#   fading: per test, the faded run length and the vanished delay rise with
#     the threshold (a laxer test keeps tracks longer both ways)
set -u
sim=$1
STEP=track-life
. tests/step_lib.sh
"$sim" operating-point --sigma-range-m 7.5 --sigma-bearing-deg 1.5 --range-m 3000 --cell-m2 1000 --quiet \
    --no-plot --out "$T/op" > "$T/op.txt" 2>&1 || { cat "$T/op.txt"; fail "operating-point failed"; }
c=$T/op.csv
[ "$(grep -c '^[0-9]' "$c")" = 20 ] || fail "operating-point: not 20 rows"
awk -F, '/^#/ || /^pfa,/ { next }
    { n++; lp = log($1)
      if (n > 1 && !($1 > pfa && $2 > pd)) { print "P_FA or P_D not increasing at row " n; bad++ }
      if (n > 2 && (lp - lprev) / step - 1 > 1e-3 || n > 2 && 1 - (lp - lprev) / step > 1e-3) { print "P_FA not equally spaced in ln"; bad++ }
      if (n > 1) step = lp - lprev
      if ($3 / ($1 / 1000) - 1 > 1e-5 || 1 - $3 / ($1 / 1000) > 1e-5) { print "lambda != P_FA / cell at row " n; bad++ }
      if ($4 !~ /inf/ && !($7 < $4)) { print "CRLB not below the MRE at row " n; bad++ }
      if (n > 1 && $8 !~ /inf/ && life !~ /inf/ && !($8 < life)) { print "life not falling at row " n; bad++ }
      if ($4 !~ /inf/ && ($4 < best || best == "")) best = $4
      pfa = $1; pd = $2; lprev = lp; life = $8 }
    END { exit bad > 0 }' "$c" || fail "operating-point: CSV invariants"
opt=$(sed -n 's/^# toc_optimum pfa \([^ ]*\) pd [^ ]* rmse_m \([^ ]*\) .*/\1 \2/p' "$c")
[ -n "$opt" ] || fail "operating-point: no TOC optimum"
awk -F, -v o="$opt" 'BEGIN { split(o, w, " ") } /^#/ || /^pfa,/ { next }
    { if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1; if ($4 !~ /inf/ && $4 < w[2] - 1e-9) bad++ }
    END { exit !(w[1] >= min && w[1] <= max && !bad) }' "$c" || fail "operating-point: TOC optimum outside the range or not the smallest RMSE"
ok "operating-point: 20 P_FA, ROC and life monotone, CRLB below the MRE, TOC optimum at P_FA $(echo $opt | cut -d' ' -f1)"
"$sim" hyca --runs 200 --scans 100 --pd 0.9 --lambda 1e-4,2e-3 --seed 2 --quiet --no-plot --out "$T/hy" > "$T/hy.txt" 2>&1 ||
    { cat "$T/hy.txt"; fail "hyca failed"; }
h=$T/hy.csv
[ "$(grep -c '^0.9,' "$h")" = 2 ] || fail "hyca: not 2 rows"
awk -F, '/^#/ || /^pd,/ { next }
    { n++
      if (!($3 >= 0 && $3 <= 1 && $4 >= 1 && $4 <= 100 + 1e-6)) { print "prediction out of range at row " n; bad++ }
      if (!($11 <= $10 && $10 <= $12 && $15 <= $14 && $14 <= $16)) { print "simulated interval not ordered at row " n; bad++ }
      life[n] = $14 }
    END { if (!(life[1] > life[2])) { print "simulated life not longer at lower clutter"; bad++ } exit bad > 0 }' "$h" ||
    fail "hyca: CSV invariants"
ok "hyca: predictions in range, simulated life falls with clutter"
"$sim" fading --runs 30 --scans 40 --existence 0.1,0.001 --kn 3,6 --page 3,6 --shiryaev -3,0 --seed 2 --quiet --no-plot \
    --out "$T/fd" > "$T/fd.txt" 2>&1 || { cat "$T/fd.txt"; fail "fading failed"; }
awk -F, '/^#/ || /^method,/ { next }
    { n++; if (!($4 >= 0 && $4 <= 40 && $8 >= 0 && $8 <= 40 && $3 > 0)) { print "out of range: " $0; bad++ }
      if ($1 == m && !($4 >= arl && $8 >= add)) { print "ARL/ADD not rising with the threshold: " $0; bad++ }
      m = $1; arl = $4; add = $8 }
    END { if (n != 8) { print n " rows"; bad++ } exit bad > 0 }' "$T/fd.csv" || fail "fading: CSV invariants"
ok "fading: 4 tests x 2 thresholds, run length and delay rise with the threshold"
