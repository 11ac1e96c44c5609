#!/bin/sh
# tests/papers_summary.sh TRK_SIM - the `make test` step papers-summary
# (mk/papers.mk; issue 18 item 5): tools/scripts/papers.sh at its tiny size
# (the machinery of `make papers`), its summary checked:
#   - summary.csv: the header experiment,source,cell,paper,trk,lo95,hi95,
#     agree,rule; 9 fields per row; agree yes or no; paper and trk numbers;
#     lo95 <= hi95 where given; the four experiments with their row counts
#     (brekke-trackloss 24 at one cell area, willett-table1 30, kennedy-null
#     2 per run length 2..6 = 10, blanding-add-arl 2)
#   - brekke-trackloss rows agree exactly when the paper's value lies in
#     [lo95, hi95]
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
bad=$(awk -F, 'NR > 1 && (NF != 9 || ($8 != "yes" && $8 != "no") || $4 !~ /^-?[0-9.e+-]+$/ || $5 !~ /^-?[0-9.e+-]+$/ ||
    ($6 != "" && $6 + 0 > $7 + 0))' "$c" | wc -l)
[ "$bad" = 0 ] || fail "$bad malformed summary.csv rows"
for e in brekke-trackloss:24 willett-table1:30 kennedy-null:10 blanding-add-arl:2; do
    n=$(grep -c "^${e%%:*}," "$c")
    [ "$n" = "${e#*:}" ] || fail "${e%%:*}: $n rows, expected ${e#*:}"
done
wrong=$(awk -F, '$1 == "brekke-trackloss" && (($4 + 0 >= $6 + 0 && $4 + 0 <= $7 + 0) != ($8 == "yes"))' "$c" | wc -l)
[ "$wrong" = 0 ] || fail "$wrong brekke-trackloss rows with an agreement other than paper in [lo95, hi95]"
rows=$(($(wc -l < "$c") - 1))
tl=$(grep -c -E '^\| .* \| (yes|no) \|$' "$m")
[ "$tl" = "$rows" ] || fail "summary.md: $tl table rows for $rows CSV rows"
for e in brekke-trackloss willett-table1 kennedy-null blanding-add-arl; do
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
awk -F, '/^#/ || /^cell_m2/ { next } { s = $6; for (i = 10; i <= 19; i++) s += $i; if (s != 40 || NF != 19) bad++ }
    END { exit bad > 0 }' "$l" || fail "brekke-trackloss_loss.csv: kept + lost per bin is not the runs"
awk -F, 'NR == FNR { if ($0 !~ /^#/ && $1 != "cell_m2") lost[$1 "," $2 "," $3 "," $4 "," $7] = $9; next }
    /^#/ || /^cell_m2/ { next } { k = $1 "," $2 "," $3 "," $4 "," $5; s = 0; for (i = 10; i <= 19; i++) s += $i
    if (!(k in lost) || lost[k] != s) bad++ } END { exit bad > 0 }' "$T/p/brekke-trackloss.csv" "$l" ||
    fail "brekke-trackloss_loss.csv: the loss times do not add up to the lost tracks"
grep -q '^# assumptions: start two-point' "$l" || fail "brekke-trackloss_loss.csv: no assumptions line"
ok "summary.csv: $rows rows of 4 experiments, $(grep -c ',yes,' "$c") agree; summary.md: one table line per row, counts per experiment"
echo "papers-summary: the summary of make papers (tiny size): $rows rows, format checked"
