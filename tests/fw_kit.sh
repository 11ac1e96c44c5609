#!/bin/sh
# fw_kit.sh MAKE DIR - the firmware kit as a firmware engineer uses it:
# `make install-cross` of the Cortex-M4F target into DIR/prefix, then
# examples/cortex-m4f copied out of the repository (it must stand alone)
# and built from that prefix alone (its Makefile reads pkg-config's
# trk-cortex-m4f.pc; nothing of the build tree), with none of this make's
# variables, and run under qemu-system-arm. The image must exit 0 (coverage
# of the three targets >= 0.9, no false track) and end with one confirmed
# track within 20 m of each target's true final position; the same image
# compiled without the kit's flags must stop at the ABI check.
STEP=fw-kit
. tests/step_lib.sh
set -eu
mk=$1
dir=$2
for tool in arm-none-eabi-gcc qemu-system-arm pkg-config; do
    command -v "$tool" >/dev/null 2>&1 || skip "$tool not found"
done
rm -rf "$dir"
mkdir -p "$dir"
$mk --no-print-directory install-cross PREFIX="$dir/prefix" INSTALL_CROSS_TARGETS=cortex-m4f >"$dir/install.log" 2>&1 ||
    { cat "$dir/install.log"; fail "make install-cross failed"; }
pc=$(PKG_CONFIG_PATH="$dir/prefix/lib/pkgconfig" pkg-config --cflags trk-cortex-m4f)
case "$pc" in
*-DTRK_REAL_FLOAT*-mfloat-abi=hard* | *-mfloat-abi=hard*-DTRK_REAL_FLOAT*) ;;
*) fail "trk-cortex-m4f.pc lacks the archive's flags: $pc" ;;
esac
cp -r examples/cortex-m4f "$T/example"
rm -rf "$T/example/build"
# a fresh make: none of this make's variables or flags reach the example
ex() { env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make --no-print-directory -C "$T/example" TRK_PREFIX="$dir/prefix" "$@"; }
out=$(ex O="$dir/example" run 2>&1) || { echo "$out"; fail "the example failed (exit status above)"; }
line=$(echo "$out" | grep '^fw-kit: cortex-m4f') || { echo "$out"; fail "no result line"; }
echo "$line" | grep -q ' 0 false;' || fail "a false track: $line"
# the truth at the last scan (main.c: target0 + v * 2 s * 59)
echo "${line#*tracks }" | awk '
    BEGIN { tx[1] = 300 + 4.0 * 118; ty[1] = 400 + 1.5 * 118
            tx[2] = 1600 - 3.0 * 118; ty[2] = 500 + 2.5 * 118
            tx[3] = 1000 + 0.5 * 118; ty[3] = 1600 - 3.5 * 118 }
    { for (f = 1; f <= NF; f++) { split($f, p, ","); n++
        for (i = 1; i <= 3; i++) if ((p[1] - tx[i])^2 + (p[2] - ty[i])^2 < 400) held[i]++ } }
    END { if (n != 3) { print "fw-kit: " n " confirmed tracks, not 3"; exit 1 }
          for (i = 1; i <= 3; i++) if (held[i] != 1) { print "fw-kit: target " i " held by " held[i] + 0 " tracks"; exit 1 } }' ||
    fail "final tracks against the truth: $line"
# the same image compiled without the kit's -DTRK_REAL_FLOAT: refused at start-up
cflags_no_real=$(echo "$pc" | sed 's/-DTRK_REAL_FLOAT//')
set +e
bad=$(ex O="$dir/example-bad" TRK_CFLAGS="$cflags_no_real" run 2>&1)
rc=$?
set -e
echo "$bad" | grep -q 'TRK_E_ABI' || { echo "$bad"; fail "a build without the kit's flags was not refused"; }
size=$(arm-none-eabi-size "$dir/example/tracker.elf" | awk 'NR == 2 { print $1 " B text, " $3 " B bss" }')
ok "install-cross, the example copied out and built from the kit alone ($size), run under QEMU: ${line#fw-kit: }; each target's final position held; without the kit's flags refused (TRK_E_ABI, exit $rc)"
