#!/bin/sh
# tests/fault_tools.sh BIN - the `make test` step fault-tools (mk/tools-faults.mk):
# the tools' faults found by an adversarial pass, each a check that failed
# before its fix:
#   - a rank killed while writing the checkpoint leaves FILE.tmp-XXXXXX: the
#     next run with --checkpoint FILE removes it (and says so);
#   - a checkpoint path that cannot be written (no such directory) is said
#     at the start, the run goes on, and the end says "not written", never
#     "removed";
#   - a full disk during a checkpoint write says "No space left on device"
#     (it said "Input/output error" when fwrite itself failed): an 8 kB
#     tmpfs in a user and mount namespace (skipped where unshare cannot make
#     one), one thread (the same first writes every time);
#   - trk-lcm-bridge --replay of an empty file is an error (exit 1, a
#     message; it exited 0), and of a directory leaves no output log.
# The checkpoint checks need the -mpi builds (MPI=1), the replay ones the
# bridge (LCM); each is skipped, and said, without them.
set -u
bin=$1
STEP=fault-tools
. tests/step_lib.sh
n=0
ran() { n=$((n + 1)); }
sim="$bin/trk-sim-mpi"
SARGS="kennedy-null --max-scans 10 --seed 3 --quiet --no-plot"
Q2="q2 --detector pdafai --clutter-model k --k-shape 2 --gate-gamma 36 --snr-db 10,15 --pfa 1e-3:0.1:3 \
--lambda-vg 0.01:20:6 --samples 20000 --target-se 2e-3 --seed 3 --quiet"
if [ -x "$sim" ]; then
    # a temporary file of an unfinished write
    : > "$T/ck.tmp-Ab3xYz"
    : > "$T/ck.tmp-keep"
    # shellcheck disable=SC2086
    "$sim" $SARGS --runs 200 --checkpoint "$T/ck" --out "$T/kn" > /dev/null 2> "$T/err" ||
        fail "a run with a stale temporary file: $(cat "$T/err")"
    [ ! -e "$T/ck.tmp-Ab3xYz" ] || fail "the stale FILE.tmp-Ab3xYz was left"
    [ -e "$T/ck.tmp-keep" ] || fail "FILE.tmp-keep (not a temporary file's name) was removed"
    grep -q 'removed 1 temporary file' "$T/err" || fail "no word of the removed temporary file: $(cat "$T/err")"
    ran
    # a path that cannot be written
    # shellcheck disable=SC2086
    "$sim" $SARGS --runs 200 --checkpoint "$T/nodir/ck" --out "$T/kn2" > /dev/null 2> "$T/err"
    rc=$?
    [ $rc -eq 0 ] && [ -s "$T/kn2.csv" ] || fail "unwritable checkpoint: exit $rc (want 0, the run goes on): $(cat "$T/err")"
    grep -q 'nodir/ck: cannot write: No such file or directory' "$T/err" || fail "unwritable checkpoint: no warning: $(cat "$T/err")"
    grep -q 'removed' "$T/err" && fail "unwritable checkpoint: says removed: $(cat "$T/err")"
    ran
    # a full disk: a q2 job, whose first record (the amplitude models) is
    # larger than the stream's buffer, so that fwrite itself fails
    mkdir "$T/full"
    # shellcheck disable=SC2086
    if unshare -rm sh -c "mount -t tmpfs -o size=8k tmpfs '$T/full' && exec \"\$@\"" sh \
        "$bin/trk-tablegen-mpi" $Q2 --threads 1 --checkpoint "$T/full/ck" --checkpoint-interval 0 --out "$T/q2.tbl" \
        > /dev/null 2> "$T/err"; then
        grep -q 'cannot write: No space left on device' "$T/err" || fail "full disk: $(cat "$T/err")"
        grep -q 'Input/output error' "$T/err" && fail "full disk: EIO instead of ENOSPC: $(cat "$T/err")"
        ran
    elif grep -q 'unshare\|mount' "$T/err"; then
        echo "$STEP: full disk: skipped (no tmpfs in a user namespace here: $(head -1 "$T/err"))"
    else
        fail "full disk: the run failed: $(cat "$T/err")"
    fi
else
    echo "$STEP: checkpoint checks skipped ($sim not built: MPI=0)"
fi
bridge="$bin/trk-lcm-bridge"
if [ -x "$bridge" ]; then
    : > "$T/empty.lcmlog"
    "$bridge" --replay "$T/empty.lcmlog" --out "$T/o1.lcmlog" > /dev/null 2> "$T/err"
    rc=$?
    [ $rc -eq 1 ] || fail "replay of an empty file: exit $rc, want 1"
    grep -q 'empty.lcmlog: not an LCM log' "$T/err" || fail "replay of an empty file: $(cat "$T/err")"
    [ ! -e "$T/o1.lcmlog" ] || fail "replay of an empty file: wrote an output log"
    ran
    mkdir "$T/dir.lcmlog"
    "$bridge" --replay "$T/dir.lcmlog" --out "$T/o2.lcmlog" > /dev/null 2> "$T/err"
    rc=$?
    [ $rc -eq 1 ] || fail "replay of a directory: exit $rc, want 1"
    grep -q 'Is a directory' "$T/err" || fail "replay of a directory: $(cat "$T/err")"
    [ ! -e "$T/o2.lcmlog" ] || fail "replay of a directory: wrote an output log"
    ran
else
    echo "$STEP: replay checks skipped ($bridge not built)"
fi
ok "$n checks passed"
