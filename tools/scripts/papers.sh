#!/bin/sh
# tools/scripts/papers.sh TRK_SIM OUTDIR [paper|tiny] - run
# the papers' experiments (trk-sim) into OUTDIR and write OUTDIR/summary.csv
# and OUTDIR/summary.md: per printed value of a paper, the paper's value,
# trk's value with its 95 % interval and whether they agree, by a rule stated
# per experiment:
#   brekke-trackloss  Brekke 2011 Tables II-III, lost tracks per 10000: the
#                     paper's count inside trk's exact 95 % binomial interval
#                     (every cell area, docs/conventions.md asks for all three)
#   willett-table1    Willett 2010 Table I, q2: |paper / trk - 1| <= 3 % (the
#                     printed values are Monte Carlo estimates themselves, of
#                     unknown error; trk's interval is +-1.96 se)
#   kennedy-null      Kennedy 2008 Figs. 2-3, false tracks confirmed on the
#                     last scan: the paper's alpha x runs; trk's count inside
#                     the exact 95 % interval of Binomial(runs, alpha)
#   blanding-add-arl  Blanding 2007 Fig. 2's orderings over ADD 4-15 cycles
#                     (Shiryaev best; Page worse than K/N): at every point
#   brekke-toc        Brekke 2011 Fig. 2 (the paper prints curves, no
#                     values): the MRE's RMSE (trk's MRE, the curve the paper
#                     draws) against the simulated RMSE of the tracks kept:
#                     |sim / MRE - 1| <= 20 % (the paper: "a reasonably good
#                     job in predicting the expected error"); n/a where the
#                     MRE has no steady state or every track was lost
#   willett-crlb      Willett 2010 I.D: the CRLB with trk's q2 against the
#                     CRLB with Table I's printed q2, |trk / paper - 1| <= 3 %
#                     (willett-table1's rule); and the simulated PDAF RMSE
#                     above the bound (its lower 95 % limit; Willett: "all
#                     trackers have significantly higher error than the
#                     CRLB"), the bound with the paper's q2 where printed
#   hyca              Willett 2010 I.D.2 (HYCA, Fig. 8; no printed values):
#                     HYCA's predicted track life against the simulated
#                     PDAF's, both with the gate-count loss of the chain
#                     (lost within the run, and E[min(life, scans)]): the
#                     prediction inside the simulation's 95 % interval
#   brekke-errpdf     Brekke 2011 Figs. 3-5 (histograms, no values): the
#                     histogram's mode below the MRE line ("a slightly
#                     positive (i.e., pessimistic) bias of the MRE as compared
#                     with the modes"), and the histogram's mean within 20 %
#                     of the MRE ("the first-order moment of the error pdf")
# agree is yes, no or n/a (not comparable; counted apart).
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
    run brekke-toc
    run willett-crlb
    run hyca --runs 2000
    run brekke-errpdf
elif [ "$size" = tiny ]; then
    run brekke-trackloss --runs 40 --scans 60 --cell-m2 1 --seed 3
    run willett-table1 --samples 2000 --target-se 0.01
    run kennedy-null --runs 100 --max-scans 6 --seed 3
    run blanding-add-arl --runs 150 --max-scans 4000 --seed 5
    run brekke-toc --runs 40 --k-shape 1 --pfa 1e-4,1e-2,1e-1 --q2-samples 20000 --seed 3
    run willett-crlb --runs 100 --q2-samples 20000 --seed 3
    run hyca --runs 100 --scans 100 --pd 0.9 --lambda 1e-4,1e-3,3e-3 --seed 3
    run brekke-errpdf --runs 40 --scans 150 --from 51 --q2-samples 20000 --seed 3
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
    awk -F, 'function fin(x) { return x != "" && x !~ /inf|nan/ } /^#/ || /^nu,/ { next } {
        a = fin($6) && fin($9) ? ($9 / $6 - 1 <= 0.2 && 1 - $9 / $6 <= 0.2 ? "yes" : "no") : "n/a"
        printf "brekke-toc,Brekke 2011 Fig. 2 (TOC),nu %s P_FA %s %s: simulated RMSE vs the MRE,%s,%s,%s,%s,%s,|sim/MRE - 1| <= 20%% (the MRE is the curve of Fig. 2)\n",
            $1, $2, $5, $6, $9, $10, $11, a }' "$out/brekke-toc.csv"
    awk -F, 'function fin(x) { return x != "" && x !~ /inf|nan/ } /^#/ || /^pd,/ { next } {
        if (fin($6)) {
            d = $7 / $6 - 1; if (d < 0) d = -d
            printf "willett-crlb,Willett 2010 I.B-I.D,P_D %s lambda %s: CRLB with trk q2 vs with the printed q2,%s,%s,,,%s,|trk/paper - 1| <= 3%% (CRLB)\n",
                $1, $2, $6, $7, d <= 0.03 ? "yes" : "no"
        }
        b = fin($6) ? $6 : $7
        printf "willett-crlb,Willett 2010 I.B-I.D,P_D %s lambda %s: PDAF RMSE above the CRLB (%s q2),%s,%s,%s,%s,%s,PDAF RMSE lower 95%% limit above the CRLB\n",
            $1, $2, fin($6) ? "printed" : "trk", b, $9, $10, $11, fin($9) ? ($10 > b ? "yes" : "no") : "n/a" }' "$out/willett-crlb.csv"
    awk -F, '/^#/ || /^pd,/ { next } {
        printf "hyca,Willett 2010 I.D.2 (HYCA),P_D %s lambda %s: lost within the run (fraction),%s,%s,%s,%s,%s,HYCA inside the simulated 95%% interval\n",
            $1, $2, $3, $10, $11, $12, $13 == 1 ? "yes" : "no"
        printf "hyca,Willett 2010 I.D.2 (HYCA),P_D %s lambda %s: E[min(life; scans)],%s,%s,%s,%s,%s,HYCA inside the simulated 95%% interval\n",
            $1, $2, $4, $14, $15, $16, $17 == 1 ? "yes" : "no" }' "$out/hyca.csv"
    awk -F, 'function fin(x) { return x != "" && x !~ /inf|nan/ } /^#/ || /^fig,/ { next } {
        ok = fin($9) && fin($24)
        printf "brekke-errpdf,Brekke 2011 Figs. 3-5,Fig. %s nu %s P_FA %s %s: histogram mode below the MRE,%s,%s,%s,%s,%s,mode < MRE (the paper: MRE pessimistic against the modes)\n",
            $1, $2, $5, $8, $9, $24, $25, $26, ok ? ($24 < $9 ? "yes" : "no") : "n/a"
        ok = fin($9) && fin($18)
        printf "brekke-errpdf,Brekke 2011 Figs. 3-5,Fig. %s nu %s P_FA %s %s: histogram mean vs the MRE,%s,%s,%s,%s,%s,|mean/MRE - 1| <= 20%% (the MRE as the first moment)\n",
            $1, $2, $5, $8, $9, $18, $19, $20, ok ? ($18 / $9 - 1 <= 0.2 && 1 - $18 / $9 <= 0.2 ? "yes" : "no") : "n/a" }' "$out/brekke-errpdf.csv"
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
    awk -F, 'NR == FNR { if (FNR > 1 && index(";" rules[$1] ";", ";" $9 ";") == 0) rules[$1] = rules[$1] (rules[$1] == "" ? "" : ";") $9; next }
    FNR > 1 {
        if ($1 != e) {
            if (e != "") { printf "\n%d of %d agree.\n", ny, n; if (na) printf "%d of them not comparable (n/a).\n", na }
            e = $1; n = 0; ny = 0; na = 0
            r = rules[$1]; gsub(/;/, "; ", r)
            printf "\n## %s (%s)\n\nAgreement: %s.\n\n| cell | paper | trk | 95%% interval | agrees |\n|---|---|---|---|---|\n", $1, $2, r
        }
        n++; ny += $8 == "yes"; na += $8 == "n/a"
        iv = $6 == "" ? "-" : "[" $6 ", " $7 "]"
        printf "| %s | %s | %s | %s | %s |\n", $3, $4, $5, iv, $8
    } END { printf "\n%d of %d agree.\n", ny, n; if (na) printf "%d of them not comparable (n/a).\n", na }' "$csv" "$csv"
    echo
    echo "## Plots"
    echo
    for p in "$out"/*.png; do [ -e "$p" ] && echo "- \`$(basename "$p")\`"; done
    echo
    echo "Distributions: \`brekke-trackloss_loss.csv\` (when tracks are lost, in 10 bins of the run, and the"
    echo "position RMSE of the tracks kept with the quantiles of the per-run RMSE, per scenario and filter;"
    echo "plots \`brekke-trackloss_loss.png\` and \`brekke-trackloss_kept.png\`); Brekke's error pdfs (Figs. 3-5)"
    echo "\`brekke-errpdf_fig3.csv\` .. \`_fig5.csv\` (bins, density per filter; the MRE, mean, RMS and mode in"
    echo "\`brekke-errpdf.csv\`) with their PNGs."
    echo
    echo "## Run times (s)"
    echo
    sed -n 's/^\([a-z0-9-]*\): \([0-9.]*\) s$/- \1: \2/p' "$log"
    echo
    echo "Machine: $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$md.tmp" || exit 1
mv "$md.tmp" "$md"
echo "papers: $rows rows, $(awk -F, 'NR > 1 && $8 == "yes"' "$csv" | wc -l) agree: $csv, $md"
