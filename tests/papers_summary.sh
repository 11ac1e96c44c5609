#!/bin/sh
# tests/papers_summary.sh TRK_SIM - the `make test` step papers-summary
# (mk/papers.mk): tools/scripts/papers.sh at its tiny size
# (the machinery of `make papers`), its summary checked:
#   - summary.csv: the header experiment,source,cell,paper,trk,lo95,hi95,
#     agree,rule; 9 fields per row; agree yes, no or n/a; paper and trk
#     numbers (inf / nan only in n/a rows); lo95 <= hi95 where given; the
#     eight experiments with their row counts (brekke-trackloss 24 at one
#     cell area, willett-table1 30, kennedy-null 2 per run length 2..6 = 10,
#     blanding-add-arl 2, brekke-toc 6 (nu 1, three P_FA, two filters),
#     willett-crlb 13 (7 points' RMSE against the bound, 6 with a printed q2),
#     hyca 6 (3 points x lost fraction and life),
#     brekke-errpdf 12 (3 figures x 2 filters x mode and mean))
#   - each experiment's agreement recomputed from the row's numbers:
#     brekke-trackloss paper in [lo95, hi95]; brekke-toc |trk/paper - 1| <=
#     0.2; hyca paper (the prediction) in [lo95, hi95]; willett-crlb |trk/paper - 1| <= 0.03 (CRLB rows), lo95 > paper
#     (RMSE rows); brekke-errpdf mode < MRE, |mean/MRE - 1| <= 0.2
#   - one MRE: brekke-errpdf's MRE lines are brekke-toc's MRE values (same
#     scenario, seed and q2 samples)
#   - brekke-errpdf.csv and _fig3.._fig5.csv: assumptions line; per figure
#     and filter the histogram's counts add up to the samples less the
#     overflow, the densities integrate to that fraction, the mode column is
#     the fullest bin's centre, mean <= RMS, lost + used runs = runs; the
#     plot scripts name the assumptions in their titles
#   - summary.md: a section and a table per experiment, one table line per
#     CSV row, an "N of M agree" line per experiment matching the CSV, the
#     plots and run times listed
set -u
sim=$1
STEP=papers-summary
. tests/step_lib.sh
sh tools/scripts/papers.sh "$sim" "$T/p" tiny > "$T/out" 2>&1 || { cat "$T/out"; fail "papers.sh tiny failed"; }
c=$T/p/summary.csv m=$T/p/summary.md
[ "$(head -1 "$c")" = "experiment,source,cell,paper,trk,lo95,hi95,agree,rule" ] || fail "summary.csv header"
bad=$(awk -F, 'function num(x) { return x ~ /^-?[0-9.e+-]+$/ }
    NR > 1 && (NF != 9 || ($8 != "yes" && $8 != "no" && $8 != "n/a") ||
    ($8 != "n/a" && (!num($4) || !num($5) || ($6 != "" && $6 + 0 > $7 + 0))) ||
    ($8 == "n/a" && ((!num($4) && $4 !~ /^(inf|nan)$/) || (!num($5) && $5 !~ /^(inf|nan)$/))))' "$c" | wc -l)
[ "$bad" = 0 ] || fail "$bad malformed summary.csv rows"
for e in brekke-trackloss:24 willett-table1:30 kennedy-null:10 blanding-add-arl:2 brekke-toc:6 willett-crlb:13 hyca:6 brekke-errpdf:12; do
    n=$(grep -c "^${e%%:*}," "$c")
    [ "$n" = "${e#*:}" ] || fail "${e%%:*}: $n rows, expected ${e#*:}"
done
wrong=$(awk -F, '$1 == "brekke-trackloss" && (($4 + 0 >= $6 + 0 && $4 + 0 <= $7 + 0) != ($8 == "yes"))' "$c" | wc -l)
[ "$wrong" = 0 ] || fail "$wrong brekke-trackloss rows with an agreement other than paper in [lo95, hi95]"
# hyca: the prediction inside the interval, up to the rounding of a prediction on its end
wrong=$(awk -F, '$1 == "hyca" && (($4 + 0 >= ($6 + 0) - 1e-6 * (1 + $6) && $4 + 0 <= ($7 + 0) + 1e-6 * (1 + $7)) != ($8 == "yes"))' "$c" | wc -l)
[ "$wrong" = 0 ] || fail "$wrong hyca rows with an agreement other than the prediction in [lo95, hi95]"
wrong=$(awk -F, 'function ab(x) { return x < 0 ? -x : x } $8 != "n/a" && (0 ||
    ($1 == "brekke-toc" && ((ab($5 / $4 - 1) <= 0.2) != ($8 == "yes"))) ||
    ($1 == "willett-crlb" && $3 ~ /CRLB with trk q2/ && ((ab($5 / $4 - 1) <= 0.03) != ($8 == "yes"))) ||
    ($1 == "willett-crlb" && $3 ~ /RMSE above/ && (($6 + 0 > $4 + 0) != ($8 == "yes"))) ||
    ($1 == "brekke-errpdf" && $3 ~ /mode below/ && (($5 + 0 < $4 + 0) != ($8 == "yes"))) ||
    ($1 == "brekke-errpdf" && $3 ~ /mean vs/ && ((ab($5 / $4 - 1) <= 0.2) != ($8 == "yes"))))' "$c" | wc -l)
[ "$wrong" = 0 ] || fail "$wrong brekke-toc / willett-crlb / brekke-errpdf rows whose agreement is not their rule"
[ "$(grep -c '^willett-crlb,.*CRLB with trk q2' "$c")" = 6 ] || fail "willett-crlb: not 6 CRLB rows"
# one MRE: the error pdfs' lines are brekke-toc's values
miss=$(awk -F, '$1 == "brekke-toc" { split($3, w, " "); mre[w[4] "," w[5]] = $4; next }
    $1 == "brekke-errpdf" { split($3, w, " "); k = w[6] "," w[7]; if (!(k in mre) || mre[k] != $4) bad++ }
    END { print bad + 0 }' "$c")
[ "$miss" = 0 ] || fail "$miss brekke-errpdf rows whose MRE is not brekke-toc's"
e=$T/p/brekke-errpdf.csv
grep -q '^# assumptions: start two-point .* MRE start two-point' "$e" || fail "brekke-errpdf.csv: no assumptions line"
grep -q '^# histogram (--from, --tracks, --bins, --err-max): position error of scans >= 51 of the runs not lost' "$e" ||
    fail "brekke-errpdf.csv: no histogram line"
[ "$(grep -c '^[345],1,15,1,' "$e")" = 6 ] || fail "brekke-errpdf.csv: not 6 rows (3 figures x 2 filters)"
awk -F, '/^#/ || /^fig,/ { next } { if ($11 != 40 || $12 + $13 != 40 || $18 > $21 || $18 <= 0 || $14 <= 0 || $17 != 100) bad++ }
    END { exit bad > 0 }' "$e" || fail "brekke-errpdf.csv: runs, samples, mean <= RMS or bins wrong"
for fig in 3 4 5; do
    b=$T/p/brekke-errpdf_fig$fig.csv
    [ -s "$b" ] && grep -q '^# assumptions: start two-point' "$b" || fail "brekke-errpdf_fig$fig.csv: missing or no assumptions line"
    [ "$(grep -c '^[0-9]' "$b")" = 100 ] || fail "brekke-errpdf_fig$fig.csv: not 100 bins"
    for col in 0 1; do
        awk -F, -v fig=$fig -v col=$col 'NR == FNR { if ($1 == fig && $8 == (col ? "PDAFAI" : "PDAF")) {
                n = $14; over = $15; mode = $24; w = $16 / $17 }; next }
            /^[0-9]/ { c = $(6 + col); s += c; d += $(4 + col) * ($2 - $1); if (c > best) { best = c; m = $3 } }
            END { if (s != n - over) { print "counts " s " != " n - over; exit 1 }
                  if (d < (n - over) / n - 1e-4 || d > (n - over) / n + 1e-4) { print "density integrates to " d; exit 1 }
                  if (m - mode > w * 1e-3 || mode - m > w * 1e-3) { print "mode " mode " != fullest bin " m; exit 1 } }' "$e" "$b" ||
            fail "brekke-errpdf_fig$fig.csv column $col: histogram and summary disagree"
    done
    g=$T/p/brekke-errpdf_fig$fig.gp
    grep -q "Brekke 2011 Fig. $fig: error pdf.*start two-point, gate cap truncate:256, MRE start two-point" "$g" ||
        fail "brekke-errpdf_fig$fig.gp: title without the assumptions"
    [ "$(grep -c '^set arrow' "$g")" = 4 ] || fail "brekke-errpdf_fig$fig.gp: not 4 lines (MRE and mean per filter)"
    if command -v gnuplot > /dev/null; then [ -s "$T/p/brekke-errpdf_fig$fig.png" ] || fail "brekke-errpdf_fig$fig.png missing"; fi
done
for p in loss kept; do
    grep -q 'start two-point, gate cap truncate:256' "$T/p/brekke-trackloss_$p.gp" || fail "brekke-trackloss_$p.gp: no assumptions in the title"
    if command -v gnuplot > /dev/null; then [ -s "$T/p/brekke-trackloss_$p.png" ] || fail "brekke-trackloss_$p.png missing"; fi
done
rows=$(($(wc -l < "$c") - 1))
tl=$(grep -c -E '^\| .* \| (yes|no|n/a) \|$' "$m")
[ "$tl" = "$rows" ] || fail "summary.md: $tl table rows for $rows CSV rows"
for e in brekke-trackloss willett-table1 kennedy-null blanding-add-arl brekke-toc willett-crlb hyca brekke-errpdf; do
    grep -q "^## $e (" "$m" || fail "summary.md: no section $e"
    y=$(awk -F, -v e="$e" '$1 == e && $8 == "yes"' "$c" | wc -l)
    n=$(grep -c "^$e," "$c")
    awk -v e="$e" -v l="$y of $n agree." '/^## / { s = index($0, "## " e " (") == 1 } s && $0 == l { f = 1 } END { exit !f }' "$m" ||
        fail "summary.md: $e has no line '$y of $n agree.'"
done
grep -q '^## Plots' "$m" && grep -q '^## Run times (s)' "$m" && grep -q '^- brekke-trackloss: [0-9]' "$m" ||
    fail "summary.md: plots or run times missing"
# brekke-trackloss_loss.csv: per row, the kept runs and the loss-time bins add up to the runs
# (40), and the losses are brekke-trackloss.csv's
l=$T/p/brekke-trackloss_loss.csv
[ "$(grep -c '^1,' "$l")" = 24 ] || fail "brekke-trackloss_loss.csv: not 24 rows"
awk -F, '/^#/ || /^cell_m2/ { next } { s = $6; for (i = 10; i <= 19; i++) s += $i; if (s != 40 || NF != 24) bad++ }
    END { exit bad > 0 }' "$l" || fail "brekke-trackloss_loss.csv: kept + lost per bin is not the runs"
# the kept runs' RMSE quantiles: ordered, positive where runs were kept, nan where none
awk -F, '/^#/ || /^cell_m2/ { next } $6 > 0 { if (!($20 > 0 && $20 <= $21 && $21 <= $22 && $22 <= $23 && $23 <= $24)) bad++ }
    $6 == 0 { if ($22 != "nan" && $22 != "-nan") bad++ } END { exit bad > 0 }' "$l" ||
    fail "brekke-trackloss_loss.csv: kept-RMSE quantiles not ordered"
# the loss-time plot's data: the lost per 10000 (40 runs: 250 each) add up to the CSV's bins
awk -F, 'NR == FNR { if ($0 !~ /^#/ && $1 != "cell_m2") for (i = 10; i <= 19; i++) want += $i * 250; next }
    /^[0-9]/ { got += $2 } END { exit !(want == got) }' "$l" "$T/p/brekke-trackloss_loss_plot.csv" ||
    fail "brekke-trackloss_loss_plot.csv: its losses are not the CSV's"
[ "$(grep -c '^[0-9]' "$T/p/brekke-trackloss_loss_plot.csv")" = 240 ] || fail "brekke-trackloss_loss_plot.csv: not 12 scenarios x 2 filters x 10 points"
awk -F, 'NR == FNR { if ($0 !~ /^#/ && $1 != "cell_m2") lost[$1 "," $2 "," $3 "," $4 "," $7] = $9; next }
    /^#/ || /^cell_m2/ { next } { k = $1 "," $2 "," $3 "," $4 "," $5; s = 0; for (i = 10; i <= 19; i++) s += $i
    if (!(k in lost) || lost[k] != s) bad++ } END { exit bad > 0 }' "$T/p/brekke-trackloss.csv" "$l" ||
    fail "brekke-trackloss_loss.csv: the loss times do not add up to the lost tracks"
grep -q '^# assumptions: start two-point' "$l" || fail "brekke-trackloss_loss.csv: no assumptions line"
ok "summary.csv: $rows rows of 8 experiments, $(grep -c ',yes,' "$c") agree; summary.md: one table line per row, counts per experiment"
echo "papers-summary: the summary of make papers (tiny size): $rows rows, format checked"
