#!/bin/sh
# run_step.sh - run one step of `make check` / `make test` quietly.
#
#   CFG=label sh tests/run_step.sh RESULTDIR NAME COMMAND [ARG...]
#
# Runs COMMAND with stdout and stderr in RESULTDIR/NAME.log and prints one
# line: the configuration label, PASS or FAIL, the step, what it counted
# (cmocka: the cases run; otherwise the log's last line, or its last
# DETAIL_LINES lines) and the wall time.
# On failure the whole log follows, indented. The result ("pass"/"fail") goes
# to RESULTDIR/NAME.res for tests/summary.sh. Always exits 0, so that one
# failing step does not stop the others; the summary fails the build.
# With TRK_TEST_CASE set (make check CASE=...), a cmocka program that runs no
# case fails: the pattern matched nothing.
dir=$1 name=$2
shift 2
mkdir -p "$dir"
res=$dir/$name.res log=$dir/$name.log
rm -f "$res"
start=$(date +%s%N)
"$@" > "$log" 2>&1
rc=$?
end=$(date +%s%N)
ms=$(( (end - start) / 1000000 ))
secs=$(printf '%d.%02d' $((ms / 1000)) $((ms % 1000 / 10)))
if grep -q '^\[==========\] Running' "$log"; then
    ran=$(sed -n 's/^\[==========\] \([0-9]*\) test(s) run\..*/\1/p' "$log" | tail -1)
    skipped=$(grep -c '^\[  SKIPPED \]' "$log")
    detail="${ran:-?} cases"
    [ "$skipped" -gt 0 ] && detail="$detail, $skipped skipped"
    if [ "$rc" -eq 0 ] && [ -n "${TRK_TEST_CASE:-}" ] && [ "${ran:-0}" = 0 ]; then
        echo "run_step: no case of $name matches CASE=$TRK_TEST_CASE" >> "$log"
        rc=1
    fi
else
    # the log's last line; DETAIL_LINES=N: its last N lines, joined with "; "
    detail=$(grep -v '^[[:space:]]*$' "$log" | tail -"${DETAIL_LINES:-1}" | sed 's/^vectors: //' |
        awk '{ printf "%s%s", (NR > 1 ? "; " : ""), $0 }' | cut -c1-200)
fi
if [ "$rc" -eq 0 ]; then
    echo pass > "$res"
    printf '%-14s PASS %-24s %8s s  %s\n' "${CFG:-}" "$name" "$secs" "$detail"
else
    echo fail > "$res"
    { printf '%-14s FAIL %-24s %8s s  exit status %d, log %s:\n' "${CFG:-}" "$name" "$secs" "$rc" "$log"
      sed 's/^/    | /' "$log"; } > "$log.shown"
    cat "$log.shown"
    rm -f "$log.shown"
fi
exit 0
