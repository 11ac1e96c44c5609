#!/bin/sh
# lcm_spy.sh BUILD TYPES_JAR CHECK_JAR - lcm-spy with trk's types, headless
# (make test-lcm-spy, part of make test). Skipped with the reason when xvfb,
# libjchart2d-java or a Java runtime with AWT is missing.
#
# A log with trk's four channels (trk-sonar-sim --out -> trk-lcm-bridge
# --replay --keep-input: TRK_DETECTIONS, TRK_TRUTH, TRK_TRACKS,
# TRK_BRIDGE_STATUS) is played to lcm-spy through LCM's file provider, under
# one Xvfb server:
#   1. tools/lcm/java/trk-lcm-spy, as a user starts it: it must still be
#      running after 6 s, having printed no exception;
#   2. the same launcher with TRK_SPY_MAIN=lcm.spy.TrkSpyCheck: lcm-spy's own
#      channel table must list the four channels with trk's types, the message
#      counts of trk-lcm-bridge --summarize and 0 undecodable, its last
#      decoded track list must hold the summary's confirmed tracks, and a
#      screenshot of its window is taken (build/java/lcm-spy.png), and one of
#      its TRK_TRACKS viewer (the decoded fields, lcm-spy-tracks.png).
# Debian's own lcm-spy wrapper is run once too and its refusal reported (not
# a failure: it is what the launcher works around).
set -u
BUILD=$1 TYPES_JAR=$2 CHECK_JAR=$3
B=$BUILD/bin
STEP=test-lcm-spy
. tests/step_lib.sh

command -v xvfb-run > /dev/null 2>&1 && command -v Xvfb > /dev/null 2>&1 || skip "no xvfb-run/Xvfb (apt-get install xvfb xauth)"
command -v xauth > /dev/null 2>&1 || skip "no xauth (apt-get install xauth)"
[ -f "${JCHART2D_JAR:-/usr/share/java/jchart2d.jar}" ] || skip "no jchart2d.jar (apt-get install libjchart2d-java)"
command -v java > /dev/null 2>&1 || skip "no java (apt-get install default-jre)"
jhome=$(dirname "$(dirname "$(readlink -f "$(command -v java)")")")
ls "$jhome"/lib/libawt_xawt.* > /dev/null 2>&1 || skip "the Java runtime in $jhome is headless (apt-get install default-jre)"

# --- a log with the four channels, and what trk's C side counts in it
"$B/trk-sonar-sim" --out "$T/det.lcmlog" --scans 60 --targets 4 --seed 3 --clutter-model k --k-shape 2 --snr-db 16 \
    --quiet > /dev/null || fail "trk-sonar-sim exited $?"
"$B/trk-sonar-sim" --targets 4 --clutter-model k --k-shape 2 --snr-db 16 --print-bridge-config \
    --bridge-amp-table "$T/sonar.amp" > "$T/bridge.conf" || fail "--print-bridge-config exited $?"
"$B/trk-tablegen" amp --clutter-model k --k-shape 2 --snr-db 16 --pfa 0.001 --out "$T/sonar.amp" > /dev/null ||
    fail "trk-tablegen amp exited $?"
"$B/trk-lcm-bridge" --config "$T/bridge.conf" --replay "$T/det.lcmlog" --out "$T/tracks.lcmlog" --keep-input --quiet \
    > /dev/null || fail "trk-lcm-bridge --replay exited $?"
"$B/trk-lcm-bridge" --summarize "$T/tracks.lcmlog" > "$T/summary.txt" || fail "--summarize exited $?"
want=$(awk '/^  TRK_DETECTIONS /{print "TRK_DETECTIONS=detection_scan_t=" $2}
            /^  TRK_TRUTH /{print "TRK_TRUTH=track_list_t=" $2}
            /^  TRK_TRACKS /{print "TRK_TRACKS=track_list_t=" $2}
            /^  TRK_BRIDGE_STATUS /{print "TRK_BRIDGE_STATUS=bridge_status_t=" $2}' "$T/summary.txt")
[ "$(echo "$want" | wc -l)" -eq 4 ] || fail "the log does not hold the four channels: $(cat "$T/summary.txt")"
conf=$(sed -n 's/^last list .*: \([0-9]*\) confirmed .*/\1/p' "$T/summary.txt")
URL="file://$T/tracks.lcmlog?speed=60"

# --- Debian's wrapper (reported, not tested)
if command -v lcm-spy > /dev/null 2>&1; then
    timeout 20 xvfb-run -a lcm-spy -l "$URL" > "$T/debian.out" 2>&1 &
    dp=$!
    sleep 3
    if kill -0 $dp 2> /dev/null; then kill $dp 2> /dev/null; debian="starts"; else
        debian="exits: $(grep -v '^$' "$T/debian.out" | head -1)"; fi
    wait $dp 2> /dev/null
    echo "test-lcm-spy: Debian's lcm-spy wrapper $debian"
fi

SPY=$(pwd)/tools/lcm/java/trk-lcm-spy
export SPY URL TYPES_JAR CHECK_JAR T want
timeout 120 xvfb-run -a -s "-screen 0 1280x1024x24" sh -c '
    # 1. the launcher as a user starts it
    TRK_LCM_JAR=$TYPES_JAR sh "$SPY" -l "$URL" > "$T/spy.out" 2>&1 &
    sp=$!
    sleep 6
    if ! kill -0 $sp 2> /dev/null; then wait $sp; echo "launcher exited $?" > "$T/spy.status"; exit 0; fi
    kill $sp; wait $sp 2> /dev/null
    echo "running after 6 s" > "$T/spy.status"
    # 2. lcm-spy through the same launcher, checked through its channel table
    TRK_LCM_JAR=$TYPES_JAR TRK_SPY_CP=$CHECK_JAR TRK_SPY_MAIN=lcm.spy.TrkSpyCheck \
      sh "$SPY" "$URL" "$T/lcm-spy.png" 60 $want > "$T/check.out" 2>&1
    echo $? > "$T/check.rc"' || fail "xvfb-run exited $?: $(cat "$T"/*.out 2> /dev/null)"
grep -q "running after 6 s" "$T/spy.status" 2> /dev/null ||
    fail "trk-lcm-spy did not stay up: $(cat "$T/spy.status" 2> /dev/null) $(cat "$T/spy.out")"
# (LCM's file provider prints an EOFException with its stack when the log
# ends: that one is not lcm-spy's)
awk '/^java.io.EOFException: EOF$/ { eof = 1; next } eof && /^\tat lcm\./ { next } { eof = 0; print }' "$T/spy.out" |
    grep -E 'Exception|Error|Unrecognized' > "$T/spy.err" && fail "trk-lcm-spy printed: $(cat "$T/spy.err")"
ok "trk-lcm-spy (tools/lcm/java/trk-lcm-spy) up for 6 s under Xvfb, no exception"
sed 's/^/    /' "$T/check.out"
[ "$(cat "$T/check.rc")" = 0 ] && grep -q "^TrkSpyCheck: ok" "$T/check.out" || fail "TrkSpyCheck failed"
grep -q "^last TRK_TRACKS decoded by lcm-spy: .*, $conf confirmed$" "$T/check.out" ||
    fail "lcm-spy's last track list does not hold the summary's $conf confirmed tracks"
mkdir -p "$BUILD/java" && cp "$T/lcm-spy.png" "$T/lcm-spy-tracks.png" "$BUILD/java/"
ok "lcm-spy shows TRK_DETECTIONS, TRK_TRUTH, TRK_TRACKS, TRK_BRIDGE_STATUS decoded with trk's types, the C summary's counts, 0 undecodable, $conf confirmed tracks in the last list; screenshots $BUILD/java/lcm-spy.png, lcm-spy-tracks.png"
