# step_lib.sh - helpers of the shell steps of make test, sourced after
# setting STEP (the name their lines start with):
#     STEP=python-tools; . tests/step_lib.sh
# gives T (a scratch directory, removed at exit unless KEEP is set), fail
# (a FAIL line, exit 1), ok (an ok line), skip (a SKIPPED line, exit 0) and
# find_python (sets PY to the first of $PYTHON, python3, /usr/bin/python3
# that imports numpy; empty when none does).
T=$(mktemp -d "${TMPDIR:-/tmp}/trk-$STEP.XXXXXX") || exit 1
trap '[ -n "${KEEP:-}" ] || rm -rf "$T"' EXIT INT TERM
fail() { echo "$STEP: FAIL: $*"; exit 1; }
ok() { echo "$STEP: ok: $*"; }
skip() { echo "$STEP: SKIPPED: $*"; exit 0; }
find_python() {
    PY=
    for p in ${PYTHON:-} python3 /usr/bin/python3; do
        if command -v "$p" > /dev/null 2>&1 && "$p" -c 'import numpy' > /dev/null 2>&1; then PY=$p; return 0; fi
    done
    return 1
}
