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
#     message; it exited 0), and of a directory leaves no output log;
#   - the messages (docs/statuses.md, "Exit codes"): every error starts with
#     the program's name and gives the documented exit status (1 a failure
#     while running, 2 a usage or configuration error); a misspelled option,
#     command or configuration key gets the nearest known one ("did you mean
#     ..."); a corrupt table is said in plain words with the status's name
#     (trk-tablegen info printed no program name); a replay of a missing file
#     prints no summary (it printed one of zeros); a Python tool without numpy
#     names the package, and one given a missing file names it (they printed
#     a traceback).
# The checkpoint checks need the -mpi builds (MPI=1), the replay ones the
# bridge (LCM); each is skipped, and said, without them.
set -u
bin=$1
STEP=fault-tools
export PYTHONDONTWRITEBYTECODE=1 # no __pycache__ in the checkout
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

# ---- messages: program name, exit status, suggestion, plain words
# expect RC WANT_TEXT CMD...: CMD exits RC and its stderr holds WANT_TEXT (a
# fixed string) and every line of it starts with the program's name (the
# first word of WANT_TEXT)
expect() {
    want_rc=$1 want=$2
    shift 2
    "$@" > "$T/out" 2> "$T/err"
    rc=$?
    [ $rc -eq "$want_rc" ] || fail "$*: exit $rc, want $want_rc: $(cat "$T/err")"
    grep -qF -- "$want" "$T/err" || fail "$*: stderr lacks '$want': $(cat "$T/err")"
    prog=${want%%[: ]*}
    grep -v "^$prog[: ]" "$T/err" > "$T/bad" && fail "$*: a line without '$prog:': $(cat "$T/bad")"
    ran
}
tg="$bin/trk-tablegen"
if [ -x "$tg" ]; then
    expect 2 "trk-tablegen info: unknown option --bogus (see --help)" "$tg" info --bogus x.tbl
    expect 2 "trk-tablegen: unknown command 'inof'; did you mean 'info'?" "$tg" inof x.tbl
    expect 2 "trk-tablegen amp: unknown option --snr-bd; did you mean '--snr-db'?" \
        "$tg" amp --clutter-model k --k-shape 1 --snr-bd 15 --pfa 1e-3 --out "$T/k1.tbl"
    expect 2 "trk-tablegen info: FILE is required" "$tg" info
    expect 1 "trk-tablegen info: $T/none.tbl: cannot read: No such file or directory" "$tg" info "$T/none.tbl"
    # a corrupt table (the command of docs/library.md, one byte changed): plain words and the name
    "$tg" amp --clutter-model k --k-shape 1 --snr-db 15 --pfa 1e-3 --out "$T/k1.tbl" > /dev/null 2>&1 ||
        fail "trk-tablegen amp exited $?"
    cp "$T/k1.tbl" "$T/bad.tbl"
    printf 'U' | dd of="$T/bad.tbl" bs=1 seek=600 conv=notrunc 2> /dev/null
    expect 1 "trk-tablegen info: $T/bad.tbl: table checksum does not match its contents (corrupt or truncated copy) (TRK_E_TABLE_CRC)" \
        "$tg" info "$T/bad.tbl"
    grep -q "DEFECT: table checksum does not match" "$T/out" || fail "info bad.tbl: stdout $(cat "$T/out")"
    "$tg" info "$T/k1.tbl" > "$T/out" 2> "$T/err" || fail "info k1.tbl: exit $?: $(cat "$T/err")"
    [ ! -s "$T/err" ] && tail -1 "$T/out" | grep -qx OK || fail "info k1.tbl: $(cat "$T/out" "$T/err")"
    ran
else
    echo "$STEP: trk-tablegen checks skipped ($tg not built)"
fi
if [ -x "$bridge" ]; then
    printf '# bridge\ntrack_channel = TRK_TRACKS\nsensor.0.pdd = 0.8\n' > "$T/bridge.conf"
    expect 2 "trk-lcm-bridge: $T/bridge.conf:3: unknown setting 'sensor.0.pdd'; did you mean 'sensor.0.pd'?" \
        "$bridge" --config "$T/bridge.conf" --replay "$T/det.lcmlog" --out "$T/o3.lcmlog"
    printf 'track_chanel = T\n' > "$T/bridge.conf"
    expect 2 "trk-lcm-bridge: $T/bridge.conf:1: unknown setting 'track_chanel'; did you mean 'track_channel'?" \
        "$bridge" --config "$T/bridge.conf" --replay "$T/det.lcmlog" --out "$T/o3.lcmlog"
    expect 2 "trk-lcm-bridge: --set gate_prb=0.9: unknown setting 'gate_prb'; did you mean 'gate_prob'?" \
        "$bridge" --set gate_prb=0.9 --replay "$T/det.lcmlog" --out "$T/o3.lcmlog"
    expect 2 "trk-lcm-bridge: unknown option --replya; did you mean '--replay'? (see --help)" \
        "$bridge" --replya "$T/det.lcmlog" --out "$T/o3.lcmlog"
    expect 2 "trk-lcm-bridge: bad value for --max-scans: 'x'" "$bridge" --max-scans x
    expect 2 "trk-lcm-bridge: --replay and --out go together" "$bridge" --replay "$T/det.lcmlog"
    expect 2 "trk-lcm-bridge: $T/none.conf: cannot open: No such file or directory" \
        "$bridge" --config "$T/none.conf" --replay "$T/det.lcmlog" --out "$T/o3.lcmlog"
    # a missing replay file (the command of docs/lcm.md): exit 1, one line, no summary, no output log
    expect 1 "trk-lcm-bridge: $T/none.lcmlog: cannot open: No such file or directory" \
        "$bridge" --replay "$T/none.lcmlog" --out "$T/o3.lcmlog" --keep-input
    [ ! -s "$T/out" ] || fail "replay of a missing file printed a summary: $(cat "$T/out")"
    [ "$(wc -l < "$T/err")" -eq 1 ] || fail "replay of a missing file: more than one line: $(cat "$T/err")"
    [ ! -e "$T/o3.lcmlog" ] || fail "replay of a missing file: wrote an output log"
    expect 1 "trk-lcm-bridge: $T/none.lcmlog: cannot open" "$bridge" --summarize "$T/none.lcmlog"
else
    echo "$STEP: trk-lcm-bridge message checks skipped ($bridge not built)"
fi
if [ -x "$bin/trk-sim" ]; then
    expect 2 "trk-sim: unknown experiment 'kenedy-null'; did you mean 'kennedy-null'?" "$bin/trk-sim" kenedy-null
    expect 2 "trk-sim demo-amplitude: unknown option --scnas; did you mean '--scans'? (see --help)" \
        "$bin/trk-sim" demo-amplitude --scnas 12 --out "$T/demo"
    # a missing input file: exit 1, one line
    expect 1 "trk-sim demo-amplitude: $T/none/amp_k1_snr15_pfa1e-2.tbl: cannot read" "$bin/trk-sim" demo-amplitude --tables "$T/none" \
        --scans 12 --out "$T/demo" --quiet --no-plot
    [ "$(wc -l < "$T/err")" -eq 1 ] || fail "trk-sim demo-amplitude, no table: more than one line: $(cat "$T/err")"
fi
if [ -x "$bin/trk-vectors" ]; then
    expect 1 "trk-vectors: cannot read $T/none.vec: No such file or directory" "$bin/trk-vectors" "$T/none.vec"
    expect 2 "trk-vectors: unknown option --skip-slwo; did you mean '--skip-slow'?" "$bin/trk-vectors" --skip-slwo x.vec
fi
# a Python tool without numpy (python3 -S: no site-packages) names the package, exit 1
if command -v python3 > /dev/null 2>&1; then
    expect 1 "plot_track_log.py: needs the Python package numpy (Debian: apt-get install python3-numpy; pip: pip install numpy)" \
        python3 -S tools/python/plot_track_log.py "$T/none.lcmlog"
    grep -q Traceback "$T/err" && fail "plot_track_log.py without numpy: a traceback: $(cat "$T/err")"
fi
# ... and with numpy, a missing log is one line, exit 1
if find_python; then
    expect 1 "plot_track_log.py: $T/none.lcmlog: No such file or directory" \
        "$PY" tools/python/plot_track_log.py "$T/none.lcmlog"
    [ "$(wc -l < "$T/err")" -eq 1 ] || fail "plot_track_log.py, no log: more than one line: $(cat "$T/err")"
fi
ok "$n checks passed"
