#!/bin/sh
# install_check.sh BUILD DIR - the checks of make install-check, after
# `make install` (double) and `make install REAL=float` into DIR/prefix
# (DIR/trk.pc.double: trk.pc as the double install wrote it).
#
# Only pkg-config finds the installed files (PKG_CONFIG_PATH=DIR/prefix/lib/
# pkgconfig), as an external project would; the programs are compiled with
# $CC and, when present, gcc and clang, -std=c99 -Wall -Wextra -Wpedantic
# -Werror:
#   - the float install left the double one as it was (libraries, trk.pc)
#   - trk.pc / trk-float.pc: -ltrk_host, -ltrk_perf, -ltrk (_f), -lm once,
#     -DTRK_REAL_FLOAT in the float Cflags only
#   - tests/install/consumer.c (libtrk, libtrk_host's trk_table_load_file,
#     libtrk_perf's MRE) and examples/firmware_loop.c build and run against
#     each scalar type, on tables the installed trk-tablegen writes
#   - double headers with the float libraries and the reverse link, and are
#     refused at run time (TRK_E_ABI: consumer exit 3, firmware_loop exit 2)
#   - the LCM types: C with publish/subscribe (trk-lcm.pc, a message over
#     memq://), C++ (header-only), Python (share/trk/python reads a log the
#     installed trk-sonar-sim and trk-lcm-bridge wrote), Java (the jar's
#     classes; the installed trk-lcm-spy finds its jars)
#   - tools in bin/ (double only), trk-bench in libexec/trk/ and not in bin/
set -u
BUILD=$1 D=$2
P=$D/prefix
export PKG_CONFIG_PATH=$P/lib/pkgconfig
STEP=install-check
. tests/step_lib.sh
CFLAGS_STRICT="-std=c99 -Wall -Wextra -Wpedantic -Werror"
CCS=${CC:-cc}
for c in gcc clang; do
    command -v $c > /dev/null 2>&1 && [ "$c" != "$CCS" ] && CCS="$CCS $c"
done

# --- side by side: the float install changed none of the double files
cmp -s "$P/lib/libtrk.a" "$BUILD/libtrk.a" && cmp -s "$P/lib/libtrk_perf.a" "$BUILD/libtrk_perf.a" &&
    cmp -s "$P/lib/libtrk_host.a" "$BUILD/libtrk_host.a" || fail "the float install overwrote a double library"
cmp -s "$P/lib/pkgconfig/trk.pc" "$D/trk.pc.double" || fail "the float install overwrote trk.pc"
for f in libtrk_f.a libtrk_perf_f.a libtrk_host_f.a pkgconfig/trk-float.pc pkgconfig/trk-lcm.pc libtrk_lcmtypes.a; do
    [ -f "$P/lib/$f" ] || fail "lib/$f not installed"
done
ok "double and float side by side: libtrk{,_perf,_host}{,_f}.a, trk.pc, trk-float.pc (the float install left the double files as they were)"

# --- the pkg-config files
# (echo: pkg-config ends its line with a space)
libs_d=$(pkg-config --libs trk) && libs_f=$(pkg-config --libs trk-float) || fail "pkg-config trk / trk-float failed"
cf_d=$(pkg-config --cflags trk) && cf_f=$(pkg-config --cflags trk-float) || fail "pkg-config --cflags failed"
libs_d=$(echo $libs_d) libs_f=$(echo $libs_f) cf_d=$(echo $cf_d) cf_f=$(echo $cf_f)
n_lm() { echo " $1 " | tr ' ' '\n' | grep -c '^-lm$'; }
[ "$libs_d" = "-L$P/lib -ltrk_host -ltrk_perf -ltrk -lm" ] && [ "$(n_lm "$libs_d")" = 1 ] ||
    fail "pkg-config --libs trk: '$libs_d'"
[ "$libs_f" = "-L$P/lib -ltrk_host_f -ltrk_perf_f -ltrk_f -lm" ] && [ "$(n_lm "$libs_f")" = 1 ] ||
    fail "pkg-config --libs trk-float: '$libs_f'"
case "$cf_d" in *TRK_REAL_FLOAT*) fail "trk.pc's Cflags select float: $cf_d";; esac
case "$cf_f" in *-DTRK_REAL_FLOAT*) ;; *) fail "trk-float.pc's Cflags lack -DTRK_REAL_FLOAT: $cf_f";; esac
ok "pkg-config --libs trk: $libs_d; trk-float: $libs_f (-lm once each); --cflags trk-float: $cf_f"

# --- tables by the installed trk-tablegen, one per width
for r in double float; do
    "$P/bin/trk-tablegen" amp --clutter-model rayleigh --snr-db 15 --pfa 1e-3 --real $r --out "$D/amp_$r.tbl" \
        > /dev/null || fail "installed trk-tablegen amp --real $r exited $?"
done

# --- each scalar type, every compiler: the consumer and the firmware example
for cc in $CCS; do
    for pc in trk trk-float; do
        r=double
        [ $pc = trk-float ] && r=float
        $cc $CFLAGS_STRICT tests/install/consumer.c $(pkg-config --cflags --libs $pc) -o "$D/consumer_$pc" \
            2> "$D/cc.err" || fail "$cc consumer.c with pkg-config $pc: $(cat "$D/cc.err")"
        $cc $CFLAGS_STRICT examples/firmware_loop.c $(pkg-config --cflags --libs $pc) -o "$D/fw_$pc" \
            2> "$D/cc.err" || fail "$cc firmware_loop.c with pkg-config $pc: $(cat "$D/cc.err")"
        out=$("$D/consumer_$pc" "$D/amp_$r.tbl") || fail "consumer ($cc, $pc) exited $?: $out"
        eval "out_$r=\$out"
        echo "$out" | grep -q "^consumer: trk_real $r; table .*; MRE RMSE [0-9.]* m .*; one scan: 1 detection(s), 1 candidate(s)$" ||
            fail "consumer ($cc, $pc): $out"
        "$D/fw_$pc" > "$D/fw.out" || fail "firmware_loop ($cc, $pc) exited $?: $(tail -3 "$D/fw.out")"
        # the mix: these headers, the other scalar type's libraries
        other=trk-float
        [ $pc = trk-float ] && other=trk
        $cc $CFLAGS_STRICT tests/install/consumer.c $(pkg-config --cflags $pc) $(pkg-config --libs $other) \
            -o "$D/mix" 2> "$D/cc.err" || fail "$cc: $pc headers with $other libraries do not link: $(cat "$D/cc.err")"
        mix=$("$D/mix" "$D/amp_$r.tbl")
        rc=$?
        [ $rc -eq 3 ] && echo "$mix" | grep -q "TRK_E_ABI" || fail "$pc headers with $other libraries: exit $rc, '$mix' (want 3, TRK_E_ABI)"
        $cc $CFLAGS_STRICT examples/firmware_loop.c $(pkg-config --cflags $pc) $(pkg-config --libs $other) -o "$D/mix" \
            2> "$D/cc.err" || fail "$cc: firmware_loop.c, $pc headers with $other libraries: $(cat "$D/cc.err")"
        "$D/mix" > /dev/null
        rc=$?
        [ $rc -eq 2 ] || fail "firmware_loop.c, $pc headers with $other libraries: exit $rc (want 2: ABI refused)"
    done
    ok "$cc: consumer.c and firmware_loop.c build with pkg-config trk and trk-float alone and run"
    for r in double float; do eval "echo \"    \$out_$r\""; done
done
ok "the mix is refused: double headers + float libraries and the reverse link, then trk_config_check gives TRK_E_ABI (consumer exit 3, firmware_loop exit 2)"

# --- the LCM types: C (publish/subscribe), C++
for cc in $CCS; do
    $cc $CFLAGS_STRICT tests/install/lcm_consumer.c $(pkg-config --cflags --libs trk-lcm) -o "$D/lcm_consumer" \
        2> "$D/cc.err" || fail "$cc lcm_consumer.c with pkg-config trk-lcm: $(cat "$D/cc.err")"
    out=$("$D/lcm_consumer") || fail "lcm_consumer ($cc) exited $?: $out"
done
ok "C types (pkg-config trk-lcm: $(pkg-config --libs trk-lcm | tr -s ' ' | cut -c1-60)...): $out"
if command -v c++ > /dev/null 2>&1; then
    c++ -std=c++11 -Wall -Wextra -Werror -I"$(pkg-config --variable=cppincludedir trk-lcm)" tests/install/lcm_consumer.cpp \
        -o "$D/lcm_consumer_cpp" 2> "$D/cc.err" || fail "c++ lcm_consumer.cpp: $(cat "$D/cc.err")"
    out=$("$D/lcm_consumer_cpp") || fail "lcm_consumer.cpp exited $?: $out"
    ok "C++ types (-I\$(pkg-config --variable=cppincludedir trk-lcm)): $out"
fi

# --- the installed tools, and Python reading what they wrote
[ -x "$P/libexec/trk/trk-bench" ] && [ ! -e "$P/bin/trk-bench" ] || fail "trk-bench: not in libexec/trk, or in bin"
tools=$(cd "$P/bin" && ls | tr '\n' ' ')
"$P/bin/trk-sonar-sim" --out "$D/det.lcmlog" --scans 20 --targets 2 --quiet > /dev/null || fail "installed trk-sonar-sim exited $?"
"$P/bin/trk-lcm-bridge" --replay "$D/det.lcmlog" --out "$D/tracks.lcmlog" --keep-input --quiet > /dev/null ||
    fail "installed trk-lcm-bridge exited $?"
if find_python; then
    out=$(cd "$D" && PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$P/share/trk/python" $PY -c '
import lcmlog, trklog, trk
lists = trklog.track_lists("tracks.lcmlog")
n = sum(1 for ev in lcmlog.LogReader("tracks.lcmlog") if ev.channel == "TRK_DETECTIONS")
tr = trklog.tracks_array(lists)
print("%d track lists, %d detection scans, %d track rows" % (len(lists), n, len(tr)))') ||
        fail "the installed Python modules: $out"
    [ "${out%% *}" = 20 ] || fail "the installed Python modules read: $out (want 20 track lists)"
    ok "installed tools in bin/ ($tools), trk-bench in libexec/trk/; share/trk/python reads their log: $out"
else
    ok "installed tools in bin/ ($tools), trk-bench in libexec/trk/ (no python3 with numpy: the Python modules not run)"
fi

# --- Java: the jar and the launcher
if [ -f "$P/share/java/trk_lcm.jar" ]; then
    classes=$(cd "$D" && jar tf "$P/share/java/trk_lcm.jar" 2> /dev/null | grep -c '^trk/.*_t\.class$')
    want=$(ls tools/lcm/types/*.lcm | wc -l) # one class per LCM type
    [ "$classes" = "$want" ] || fail "trk_lcm.jar holds $classes of the $want trk classes"
    msg=$(env -u DISPLAY "$P/bin/trk-lcm-spy" 2>&1)
    rc=$?
    if [ -f /usr/share/java/jchart2d.jar ]; then
        [ $rc -eq 2 ] && echo "$msg" | grep -q 'no \$DISPLAY' ||
            fail "installed trk-lcm-spy without a display: exit $rc, '$msg' (want 2, 'no \$DISPLAY': its jars found)"
    fi
    ok "share/java/trk_lcm.jar ($classes classes); bin/trk-lcm-spy finds it ($msg)"
else
    echo "install-check: no share/java/trk_lcm.jar (no JDK or liblcm-java here): Java not checked"
fi
echo "install-check: double and float installed side by side build and run external programs through pkg-config alone; the mix is refused"
