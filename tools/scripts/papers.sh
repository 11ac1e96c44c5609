#!/bin/sh
# tools/scripts/papers.sh TRK_SIM OUTDIR [paper|tiny] - issue 18 item 5: run
# the papers' experiments (trk-sim) into OUTDIR and write OUTDIR/summary.csv
# and OUTDIR/summary.md: per printed value of a paper, the paper's value,
# trk's value with its 95 % interval and whether they agree, by a rule stated
# per experiment:
#   brekke-trackloss  Brekke 2011 Tables II-III, lost tracks per 10000: the
#                     paper's count inside trk's exact 95 % binomial interval
#                     (every cell area, CONVENTIONS asks for all three)
#   willett-table1    Willett 2010 Table I, q2: |paper / trk - 1| <= 3 % (the
#                     printed values are Monte Carlo estimates themselves, of
#                     unknown error; trk's interval is +-1.96 se)
#   kennedy-null      Kennedy 2008 Figs. 2-3, false tracks confirmed on the
#                     last scan: the paper's alpha x runs; trk's count inside
#                     the exact 95 % interval of Binomial(runs, alpha)
#   blanding-add-arl  Blanding 2007 Fig. 2's orderings over ADD 4-15 cycles
#                     (Shiryaev best; Page worse than K/N): at every point
# The plots (PNG, with gnuplot) are the experiments' own, listed in
# summary.md. paper: the experiments' default (paper) sizes (`make papers`);
# tiny: seconds, for the format check of `make test` (papers-summary).
set -u
sim=$1 out=$2 size=${3:-paper}
mkdir -p "$out" || exit 1
log=$out/papers.log
: > "$log"
run() { # run NAME ARGS...: trk-sim NAME ARGS --out OUT/NAME, stdout to OUT/NAME.txt
    n=$1
    shift
    t0=$(date +%s%N)
    "$sim" "$n" "$@" --quiet --out "$out/$n" > "$out/$n.txt" 2>> "$log" || { echo "papers: $n failed (see $log)" >&2; exit 1; }
    ms=$((($(date +%s%N) - t0) / 1000000))
    printf '%s: %d.%d s\n' "$n" $((ms / 1000)) $((ms % 1000 / 100)) >> "$log"
}
if [ "$size" = paper ]; then
    run brekke-trackloss
    run willett-table1
    run kennedy-null
    run blanding-add-arl
elif [ "$size" = tiny ]; then
    run brekke-trackloss --runs 40 --scans 60 --cell-m2 1 --seed 3
    run willett-table1 --samples 2000 --target-se 0.01
    run kennedy-null --runs 100 --max-scans 6 --seed 3
    run blanding-add-arl --runs 150 --max-scans 4000 --seed 5
else
    echo "papers: size must be paper or tiny" >&2
    exit 2
fi
csv=$out/summary.csv md=$out/summary.md
{
    echo "experiment,source,cell,paper,trk,lo95,hi95,agree,rule"
    awk -F, '/^#/ || /^cell_m2,/ { next } $13 >= 0 {
        printf "brekke-trackloss,Brekke 2011 Tables II-III,cell %s m2 nu %s SNR %s dB P_FA %s %s,%s,%s,%s,%s,%s,paper inside the exact 95%% interval (lost per 10000)\n",
            $1, $2, $3, $4, $7, $13, $10, $11, $12, $14 == 1 ? "yes" : "no" }' "$out/brekke-trackloss.csv"
    awk -F, '/^#/ || /^lambda,/ { next } {
        d = $7 < 0 ? -$7 : $7
        printf "willett-table1,Willett 2010 Table I,lambda %s P_D %s,%s,%s,%.6g,%.6g,%s,|paper/trk - 1| <= 3%% (q2)\n",
            $1, $2, $4, $5, $5 - 1.96 * $6, $5 + 1.96 * $6, d <= 0.03 ? "yes" : "no" }' "$out/willett-table1.csv"
    awk -F, '/^#/ || /^scans,/ { next } {
        printf "kennedy-null,Kennedy 2008 Figs. 2-3,density test %s scans,%s,%s,%s,%s,%s,trk inside the 95%% interval of Binomial(runs alpha)\n",
            $1, $3, $6, $4, $5, $8 == 1 ? "yes" : "no"
        printf "kennedy-null,Kennedy 2008 Figs. 2-3,amplitude test %s scans,%s,%s,%s,%s,%s,trk inside the 95%% interval of Binomial(runs alpha)\n",
            $1, $3, $7, $4, $5, $9 == 1 ? "yes" : "no" }' "$out/kennedy-null.csv"
    sed -n 's/^# paper: \(.*\): \([0-9]*\) of \([0-9]*\) points$/\1,\2,\3/p' "$out/blanding-add-arl.txt" |
        awk -F, '{ printf "blanding-add-arl,Blanding 2007 Fig. 2,%s (points),%s,%s,,,%s,the ordering at every point\n",
            $1, $3, $2, $2 == $3 ? "yes" : "no" }'
} > "$csv.tmp" || exit 1
mv "$csv.tmp" "$csv"
rows=$(($(wc -l < "$csv") - 1))
[ "$rows" -gt 0 ] || { echo "papers: no summary rows" >&2; exit 1; }
{
    echo "# trk against the papers ($size size)"
    echo
    echo "Written by \`tools/scripts/papers.sh\` (\`make papers\`) from the experiments' CSV files in this"
    echo "directory; each experiment's assumptions are in its CSV header. Per experiment the rule"
    echo "of agreement is stated; \`summary.csv\` holds the same rows."
    awk -F, 'NR > 1 {
        if ($1 != e) {
            if (e != "") printf "\n%d of %d agree.\n", ny, n
            e = $1; n = 0; ny = 0
            printf "\n## %s (%s)\n\nAgreement: %s.\n\n| cell | paper | trk | 95%% interval | agrees |\n|---|---|---|---|---|\n", $1, $2, $9
        }
        n++; ny += $8 == "yes"
        iv = $6 == "" ? "-" : "[" $6 ", " $7 "]"
        printf "| %s | %s | %s | %s | %s |\n", $3, $4, $5, iv, $8
    } END { printf "\n%d of %d agree.\n", ny, n }' "$csv"
    echo
    echo "## Plots"
    echo
    for p in "$out"/*.png; do [ -e "$p" ] && echo "- \`$(basename "$p")\`"; done
    echo
    echo "Distributions: \`brekke-trackloss_loss.csv\` (when tracks are lost, in 10 bins of the run, and the"
    echo "position RMSE of the tracks kept, per scenario and filter)."
    echo
    echo "## Run times (s)"
    echo
    sed -n 's/^\([a-z0-9-]*\): \([0-9.]*\) s$/- \1: \2/p' "$log"
    echo
    echo "Machine: $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$md.tmp" || exit 1
mv "$md.tmp" "$md"
echo "papers: $rows rows, $(awk -F, 'NR > 1 && $8 == "yes"' "$csv" | wc -l) agree: $csv, $md"
