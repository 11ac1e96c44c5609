#!/bin/sh
# fw_kit.sh MAKE DIR - the firmware kit as a firmware engineer uses it:
# `make install-cross` of the Cortex-M4F target into DIR/prefix, then
# examples/cortex-m4f built from that prefix alone (its Makefile reads
# pkg-config's trk-cortex-m4f.pc; nothing of the build tree) and run under
# qemu-system-arm. The image must print its line and exit 0 (coverage of
# the three targets >= 0.9, no false track); a compilation without the
# kit's flags must be refused by the ABI check (exit 2).
set -eu
mk=$1
dir=$2
for tool in arm-none-eabi-gcc qemu-system-arm pkg-config; do
    command -v "$tool" >/dev/null 2>&1 || { echo "fw-kit: skipped: $tool not found"; exit 0; }
done
rm -rf "$dir"
$mk --no-print-directory install-cross PREFIX="$dir/prefix" INSTALL_CROSS_TARGETS=cortex-m4f >"$dir.install.log" 2>&1 ||
    { cat "$dir.install.log"; echo "fw-kit: make install-cross failed"; exit 1; }
mkdir -p "$dir"
mv "$dir.install.log" "$dir/install.log"
pc=$(PKG_CONFIG_PATH="$dir/prefix/lib/pkgconfig" pkg-config --cflags trk-cortex-m4f)
case "$pc" in
*-DTRK_REAL_FLOAT*-mfloat-abi=hard* | *-mfloat-abi=hard*-DTRK_REAL_FLOAT*) ;;
*) echo "fw-kit: trk-cortex-m4f.pc lacks the archive's flags: $pc"; exit 1 ;;
esac
out=$($mk --no-print-directory -C examples/cortex-m4f TRK_PREFIX="$dir/prefix" O="$dir/example" run 2>&1) || {
    echo "$out"
    echo "fw-kit: the example failed (exit status above)"
    exit 1
}
line=$(echo "$out" | grep '^fw-kit: cortex-m4f') || { echo "$out"; echo "fw-kit: no result line"; exit 1; }
echo "$line" | grep -q ' 0 false;' || { echo "$line"; echo "fw-kit: a false track"; exit 1; }
# the same image compiled without the kit's -DTRK_REAL_FLOAT: refused at start-up
cflags_no_real=$(echo "$pc" | sed 's/-DTRK_REAL_FLOAT//')
set +e
bad=$($mk --no-print-directory -C examples/cortex-m4f TRK_PREFIX="$dir/prefix" O="$dir/example-bad" \
    TRK_CFLAGS="$cflags_no_real" run 2>&1)
rc=$?
set -e
echo "$bad" | grep -q 'TRK_E_ABI' || { echo "$bad"; echo "fw-kit: a build without the kit's flags was not refused"; exit 1; }
size=$(arm-none-eabi-size "$dir/example/tracker.elf" | awk 'NR == 2 { print $1 " B text, " $3 " B bss" }')
echo "fw-kit: ok: install-cross, the example built from the kit alone ($size) and run under QEMU: ${line#fw-kit: }; without the kit's flags refused (TRK_E_ABI, make exit $rc)"
