#!/bin/sh
# summary.sh - the closing line of a configuration or of the whole matrix.
#
#   sh tests/summary.sh [--make-status RC] LABEL RESULT.res...
#
# Counts the steps recorded by tests/run_step.sh and prints
#   LABEL: N passed, N failed
# (the plain form CI reads). Files that do not exist are ignored (a shell
# glob that matched nothing). --make-status: the exit status of the make that
# ran the steps; non-zero with no failed step means a build failed before its
# steps ran, which is counted as one failure and said so. Exits 1 when
# anything failed.
status=0
if [ "$1" = --make-status ]; then status=$2; shift 2; fi
label=$1
shift
passed=0 failed=0
for f in "$@"; do
    [ -f "$f" ] || continue
    case $(cat "$f") in
    pass) passed=$((passed + 1)) ;;
    *) failed=$((failed + 1)); cfgdir=${f%/results/*}; failed_names="$failed_names ${cfgdir##*/}/$(basename "$f" .res)" ;;
    esac
done
if [ "$status" -ne 0 ] && [ "$failed" -eq 0 ]; then
    echo "$label: make exited with status $status before all steps ran (a build failed: see above)"
    failed=1
fi
[ -n "${failed_names:-}" ] && echo "$label: failed:$failed_names"
echo "$label: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
