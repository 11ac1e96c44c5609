#!/bin/sh
# tests/hostile_tools.sh BIN - the `make test` step hostile-tools (mk/hostile.mk):
# hostile input to the tools (hangs, write errors, parsing), each a check that
# failed before the fix:
#   hangs, unbounded reads: `trk-tablegen info /dev/zero` and
#     `trk-vectors /dev/zero` refuse at once (they read until malloc failed);
#     `trk-sonar-sim --region 0,1e9,0,1e9` is refused with a message (it drew
#     5e12 clutter points a scan, forever); a live trk-sonar-sim stops cleanly
#     (exit 0, "stopped by signal") on SIGTERM and on SIGINT
#   write errors, destroyed outputs: with writes failing (a file size
#     limit, as a full disk; /dev/full) trk-tablegen, trk-sim demo-amplitude, trk-sim demo and
#     kennedy-null and trk-sonar-sim exit 1, and a failed regeneration leaves
#     the old table byte-identical, with no temporary file left; demo prints
#     no "files:" line; `trk-sonar-sim --scan-period-s 1e13` is refused (it
#     wrote 1 of 3 scans and exited 0); `trk-sonar-sim --polar` refuses a
#     platform, noise, P_D profile or coverage out of range, naming it
#   unbounded reads also: trk-sim mtt-compare refuses a CSV line longer than its
#     buffer, naming it (the rest was read as a line of its own)
#   parsing: `trk-tablegen amp --clutter-power 1e31 --no-measure`
#     exits 1 without a table (the library refused what it wrote); `info` on a
#     table of unknown kind 99 says DEFECT (it said OK); `kennedy-null --runs
#     2147483648` names the failure (it exited 1 without a word)
set -u
bin=$1
d=$(mktemp -d) || exit 1
trap 'rm -rf "$d"' EXIT
n=0
fail() {
    echo "hostile-tools: FAILED: $*"
    exit 1
}
ok() { n=$((n + 1)); }
# limited BLOCKS CMD...: CMD with writes beyond BLOCKS (ulimit -f units) failing with EFBIG
limited() {
    blocks=$1
    shift
    (ulimit -f "$blocks" && trap '' XFSZ && exec "$@")
}

# ---- hangs, unbounded reads
out=$(timeout -k 1 20 "$bin/trk-tablegen" info /dev/zero 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "tablegen info /dev/zero: exit $rc, want 1 (a defective input) ($out)"
echo "$out" | grep -q 'trk-tablegen info: /dev/zero: more than' || fail "tablegen info /dev/zero: no message ($out)"
ok
out=$(timeout -k 1 20 "$bin/trk-vectors" /dev/zero 2>&1)
rc=$?
[ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $rc -ne 137 ] || fail "trk-vectors /dev/zero: exit $rc ($out)"
ok
out=$(timeout -k 1 20 "$bin/trk-sonar-sim" --region 0,1e9,0,1e9 --out "$d/x.log" --scans 2 --quiet 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "sonar-sim --region 0,1e9,0,1e9: exit $rc, want 2 ($out)"
echo "$out" | grep -q 'clutter detections per scan' || fail "sonar-sim region: message ($out)"
[ ! -e "$d/x.log" ] || fail "sonar-sim region: wrote $d/x.log"
ok
for sig in TERM INT; do
    timeout -k 1 20 "$bin/trk-sonar-sim" --lcm-url memq:// --scans 0 --rate-hz 50 --quiet > "$d/live.out" 2>&1 &
    pid=$!
    sleep 0.5
    kill -$sig $pid
    wait $pid
    rc=$?
    [ $rc -eq 0 ] || fail "sonar-sim live, SIG$sig: exit $rc, want 0 ($(cat "$d/live.out"))"
    grep -q 'stopped by signal' "$d/live.out" || fail "sonar-sim live, SIG$sig: $(cat "$d/live.out")"
    ok
done

# ---- write errors, destroyed outputs
"$bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 15 --pfa 1e-2 --no-measure --out "$d/t.tbl" > /dev/null ||
    fail "tablegen amp: a valid table"
cp "$d/t.tbl" "$d/t.orig"
out=$(limited 4 "$bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 20 --pfa 1e-3 --no-measure \
    --out "$d/t.tbl" 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "tablegen amp, writes failing: exit $rc, want 1 ($out)"
cmp -s "$d/t.tbl" "$d/t.orig" || fail "tablegen amp: a failed regeneration changed the old table"
ls "$d" | grep -q 'tmp-' && fail "tablegen amp: temporary file left: $(ls "$d")"
out=$(limited 4 "$bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 20 --pfa 1e-3 --no-measure \
    --format c --name t --out "$d/t.tbl" 2>&1)
[ $? -eq 1 ] || fail "tablegen amp --format c, writes failing: not exit 1 ($out)"
cmp -s "$d/t.tbl" "$d/t.orig" || fail "tablegen amp --format c: a failed regeneration changed the old table"
ok
out=$("$bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 15 --pfa 1e-2 --no-measure --out /dev/full 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "tablegen amp --out /dev/full: exit $rc, want 1 ($out)"
echo "$out" | grep -q 'No space left' || fail "tablegen amp --out /dev/full: message ($out)"
ok
"$bin/trk-sim" demo-amplitude --amp-table "$d/t.orig" --scans 12 --out "$d/demo" --quiet --no-plot > "$d/demo.out" 2>&1 ||
    fail "trk-sim demo-amplitude: $(cat "$d/demo.out")"
out=$(limited 4 "$bin/trk-sim" demo-amplitude --amp-table "$d/t.orig" --scans 12 --out "$d/demo2" --quiet --no-plot 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "trk-sim demo-amplitude, writes failing: exit $rc, want 1"
echo "$out" | grep -q 'write error' || fail "trk-sim demo-amplitude, writes failing: no 'write error' message"
echo "$out" | grep -q 'files:' && fail "trk-sim demo-amplitude, writes failing: prints its files"
ls "$d/demo2" | grep -q 'tmp-' && fail "trk-sim demo-amplitude: temporary file left: $(ls "$d/demo2")"
ok
out=$(limited 4 "$bin/trk-sim" demo --scans 30 --out "$d/demo3" --no-plot 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "trk-sim demo, writes failing: exit $rc, want 1"
echo "$out" | grep -q 'write error' || fail "trk-sim demo, writes failing: no 'write error' message"
echo "$out" | grep -q 'files:' && fail "trk-sim demo, writes failing: prints its files"
ls "$d/demo3" | grep -q 'tmp-' && fail "trk-sim demo: temporary file left: $(ls "$d/demo3")"
ok
out=$(limited 0 "$bin/trk-sim" kennedy-null --runs 20 --max-scans 5 --quiet --no-plot --out "$d/kn" 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "kennedy-null, writes failing: exit $rc, want 1"
[ ! -e "$d/kn.csv" ] || fail "kennedy-null, writes failing: left a cut kn.csv"
ok
out=$(timeout -k 1 20 "$bin/trk-sonar-sim" --out /dev/full --scans 3 --quiet 2>&1)
[ $? -eq 1 ] || fail "sonar-sim --out /dev/full: not exit 1 ($out)"
out=$(timeout -k 1 20 "$bin/trk-sonar-sim" --scan-period-s 1e13 --out "$d/p.log" --scans 3 --quiet 2>&1)
rc=$?
[ $rc -eq 2 ] || fail "sonar-sim --scan-period-s 1e13: exit $rc, want 2 ($out)"
echo "$out" | grep -q "beyond the tracker's time range" || fail "sonar-sim --scan-period-s 1e13: message ($out)"
ok
# a polar sonar's settings out of range: exit 2 with the reason, no log
for args in "--platform 0,0,0,-1|speed" "--platform nan,0,0,1|" "--platform 0,0,7,1|course" \
    "--sigma-bearing-rad 0.6|(0, 0.5]" "--sigma-range-m 0|(0, 1e+06]" "--pd-profile 0:0.9|RANGE_M:PD" \
    "--pd-profile 5:0.9,4:0.5|increasing" "--coverage 0,1500|MIN_RANGE_M" "--coverage 500,400,1|must exceed"; do
    a=${args%%|*} want=${args#*|}
    # shellcheck disable=SC2086
    out=$(timeout -k 1 20 "$bin/trk-sonar-sim" --polar $a --out "$d/q.log" --scans 2 --quiet 2>&1)
    rc=$?
    [ $rc -eq 2 ] || fail "sonar-sim --polar $a: exit $rc, want 2 ($out)"
    echo "$out" | grep -qF -- "$want" || fail "sonar-sim --polar $a: message lacks '$want' ($out)"
    [ ! -e "$d/q.log" ] || fail "sonar-sim --polar $a: wrote $d/q.log"
done
ok

# ---- parsing
out=$("$bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 15 --pfa 1e-3 --clutter-power 1e31 --no-measure \
    --out "$d/big.tbl" 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "tablegen amp --clutter-power 1e31: exit $rc, want 1 ($out)"
[ ! -e "$d/big.tbl" ] || fail "tablegen amp --clutter-power 1e31: wrote a table"
echo "$out" | grep -q 'library refuses' || fail "tablegen amp --clutter-power 1e31: message ($out)"
ok
out=$("$bin/trk-tablegen" info tests/tables/kind99.tbl 2>&1)
rc=$?
[ $rc -eq 1 ] || fail "tablegen info kind 99: exit $rc, want 1"
echo "$out" | grep -q 'DEFECT: unknown table kind 99' || fail "tablegen info kind 99: $out"
ok
out=$("$bin/trk-sim" kennedy-null --runs 2147483648 --quiet --no-plot --out "$d/kn2" 2>&1)
rc=$?
[ $rc -ne 0 ] || fail "kennedy-null --runs 2147483648: exit 0"
[ -n "$out" ] || fail "kennedy-null --runs 2147483648: exit $rc without a message"
ok
# every line reader refuses a line longer than its buffer (the rest was read as a line of
# its own: here a comment's tail would have been a row); config files: test_lcm_config
{
    echo "capacity,config,clutter,seeds,scans,amplitude,family"
    printf '#'
    head -c 70000 /dev/zero | tr '\0' x
    echo "64,new,0,2,30,1,transit"
} > "$d/long.csv"
out=$("$bin/trk-sim" mtt-compare "$d/long.csv" --out "$d/cmp" 2>&1)
[ $? -ne 0 ] || fail "mtt-compare, a 70 000-byte line: exit 0"
echo "$out" | grep -q 'long.csv:2: line longer than' || fail "mtt-compare, a 70 000-byte line: $out"
ok
echo "hostile-tools: $n checks passed"
