#!/bin/sh
# size_report.sh - print libtrk's footprint tables (make size-report).
#
#   sh tools/scripts/size_report.sh CROSSDIR TARGET...
#
# Reads, per target, the files mk/size.mk leaves in CROSSDIR/TARGET/:
#   size-A.txt           `size -A libtrk.a` (sections of every object = module)
#   sizeof-default.txt   `nm -S` of sizeof_probe.o at the default capacities
#   sizeof-small.txt     the same at TRK_MAX_TRACKS=8 TRK_MAX_DETECTIONS=32 TRK_MAX_SENSORS=2
#   stack.txt            stack_ci.awk output (public functions, libm included
#                        where stack-extern.txt could be made from a linked image)
# POSIX sh + awk only (mawk on Debian).
# Goals checked: .text <= 32 KB on cortex-m4f; RAM for 64 tracks x
# 256 detections <= 64 KB; worst stack of trk_tracker_process_scan <= 2 KB.
# Exit status 0; size-check (mk/size.mk) turns goal misses into failures.
set -eu
dir=$1
shift
targets="$*"

# --- sections per module and target: module target text rodata data bss
for t in $targets; do
    awk -v tgt="$t" '
        /^[^ ]+\.o +\(ex / { mod = $1; sub(/\.o$/, "", mod); mods[mod] = 1; next }
        NF >= 2 && $2 ~ /^[0-9]+$/ && mod != "" {
            s = $1; n = $2 + 0
            if (s ~ /^\.text/ || s ~ /^\.ARM\.ex/) text[mod] += n
            else if (s ~ /^\.s?rodata/) ro[mod] += n
            else if (s ~ /^\.s?data/) data[mod] += n
            else if (s ~ /^\.s?bss/ || s == "COMMON") bss[mod] += n
        }
        END { for (m in mods) printf "%s %s %d %d %d %d\n", m, tgt, text[m], ro[m], data[m], bss[m] }
    ' "$dir/$t/size-A.txt"
done > "$dir/size-modules.txt"

echo
echo "== libtrk footprint per module (bytes; text = .text, ro = .rodata; every module has .data = .bss = 0 unless listed below)"
awk -v targets="$targets" '
    BEGIN { nt = split(targets, T, " ") }
    { k = $1 SUBSEP $2; text[k] = $3; ro[k] = $4; data[$2] += $5; bss[$2] += $6
      if ($5 + $6 > 0) mut[$1 " (" $2 ")"] = $5 "/" $6
      mods[$1] = 1; tt[$2] += $3; tr[$2] += $4 }
    END {
        printf "%-16s", "module"
        for (i = 1; i <= nt; i++) printf " %15s", T[i]
        printf "\n%-16s", ""
        for (i = 1; i <= nt; i++) printf " %9s %5s", "text", "ro"
        printf "\n"
        n = 0
        for (m in mods) M[++n] = m
        for (i = 2; i <= n; i++) { v = M[i]; for (j = i - 1; j >= 1 && M[j] > v; j--) M[j + 1] = M[j]; M[j + 1] = v }
        for (j = 1; j <= n; j++) {
            printf "%-16s", M[j]
            for (i = 1; i <= nt; i++) { k = M[j] SUBSEP T[i]; printf " %9d %5d", text[k], ro[k] }
            printf "\n"
        }
        printf "%-16s", "TOTAL"
        for (i = 1; i <= nt; i++) printf " %9d %5d", tt[T[i]], tr[T[i]]
        printf "\n%-16s", "  .data / .bss"
        for (i = 1; i <= nt; i++) printf " %15s", data[T[i]] "/" bss[T[i]]
        printf "\n"
        for (m in mut) printf "  module with static data (.data/.bss): %s %s\n", m, mut[m]
    }' "$dir/size-modules.txt"

# --- a typical firmware image (linked with --gc-sections)
echo
echo "== typical firmware image (tools/scripts/fw_footprint.c: tracker + amplitude table lookup,"
echo "   linked with --gc-sections, newlib-nano): bytes taken from each library (text / rodata / data / bss)"
printf "%-16s %22s %22s %22s %22s\n" target libtrk libm libc libgcc
for t in $targets; do
    [ -s "$dir/$t/fw-footprint.txt" ] || continue
    awk -v tgt="$t" '{ v[$1] = $2 " / " $3 " / " $4 " / " $5 }
        END { printf "%-16s %22s %22s %22s %22s\n", tgt, v["libtrk"], v["libm"], v["libc"], v["libgcc"] }' "$dir/$t/fw-footprint.txt"
done

# --- sizeof at default and small capacities
hexsize() { # nm -S lines -> "symbol decimal-size"
    awk 'function hex(s,   i, c, v) { v = 0; s = tolower(s)
             for (i = 1; i <= length(s); i++) { c = index("0123456789abcdef", substr(s, i, 1)) - 1; v = v * 16 + c }
             return v }
         NF == 4 { print $4, hex($2) }' "$1"
}
echo
echo "== sizeof (bytes): default capacities (64 tracks, 256 detections, 4 sensors) / small (8, 32, 2)"
printf "%-16s %14s %14s %12s %12s %14s\n" target tracker tracker.ws track detection "scan[MAX_DET]"
for t in $targets; do
    [ -f "$dir/$t/sizeof-default.txt" ] || continue
    d=$(hexsize "$dir/$t/sizeof-default.txt" | sort)
    s=$(hexsize "$dir/$t/sizeof-small.txt" | sort)
    printf '%s\n%s\n' "$d" "$s" | awk -v tgt="$t" '
        { n[$1]++; v[$1, n[$1]] = $2 }
        END {
            printf "%-16s %14s %14s %12s %12s %14s\n", tgt,
                v["trk_sizeof_tracker", 1] " / " v["trk_sizeof_tracker", 2],
                v["trk_sizeof_tracker_ws", 1] " / " v["trk_sizeof_tracker_ws", 2],
                v["trk_sizeof_track", 1], v["trk_sizeof_detection", 1],
                v["trk_sizeof_scan_detections", 1] " / " v["trk_sizeof_scan_detections", 2] }'
done

# --- worst stack per public function
echo
echo "== worst-case stack depth (bytes) per public function: own frame + deepest call path,"
echo "   from -fstack-usage/-fcallgraph-info (stack_ci.awk), libm/libc/libgcc callees from the"
echo "   linked image's disassembly (stack_elf.awk); riscv: libtrk only (no C library to link)."
echo "   flags: indirect = calls a caller-supplied function pointer (add its stack),"
echo "   recursion/dynamic/ext:NAME = see stack_ci.awk (none expected)."
for t in $targets; do
    [ -f "$dir/$t/stack.txt" ] && awk -v tgt="$t" -F '\t' '{ print $1 "\t" tgt "\t" $2 "\t" $4 }' "$dir/$t/stack.txt"
done | awk -F '\t' -v targets="$targets" '
    BEGIN { nt = split(targets, T, " ") }
    { w[$1, $2] = $3; fns[$1] = 1
      if ($4 != "-" && !($2 == "riscv")) {       # riscv: libm not linked, ext: expected
          n = split($4, fa, ",")
          for (i = 1; i <= n; i++) if (!(($1, fa[i]) in fseen)) { fseen[$1, fa[i]] = 1; fl[$1] = fl[$1] (fl[$1] == "" ? "" : ",") fa[i] } } }
    END {
        printf "%-32s", "function"
        for (i = 1; i <= nt; i++) printf " %14s", T[i]
        printf "  flags\n"
        n = 0
        for (f in fns) F[++n] = f
        for (i = 2; i <= n; i++) { v = F[i]; for (j = i - 1; j >= 1 && F[j] > v; j--) F[j + 1] = F[j]; F[j + 1] = v }
        for (j = 1; j <= n; j++) {
            printf "%-32s", F[j]
            for (i = 1; i <= nt; i++) printf " %14s", ((F[j], T[i]) in w) ? w[F[j], T[i]] : "-"
            printf "  %s\n", fl[F[j]]
        }
    }'
for t in $targets; do
    [ -f "$dir/$t/stack.txt" ] || continue
    awk -F '\t' -v tgt="$t" '$1 == "trk_tracker_process_scan" { printf "   %s worst path: %s\n", tgt, $5 }' "$dir/$t/stack.txt"
done

# cross-check: the disassembly of the linked image (stack_elf.awk) against
# the call-graph numbers for libtrk's own public functions
for t in $targets; do
    [ -s "$dir/$t/stack-extern.txt" ] || continue
    awk -F '\t' -v tgt="$t" 'FILENAME ~ /stack.txt$/ { ci[$1] = $2; next }
        ($1 in ci) { n++; if (ci[$1] != $2) { d++; if (d <= 3) diff = diff " " $1 "(" ci[$1] " vs " $2 ")" } }
        END { printf "   %s cross-check: %d public functions, %d differ between call graph and disassembly%s\n",
                tgt, n, d, diff }' "$dir/$t/stack.txt" "$dir/$t/stack-extern.txt"
done

# --- goals
echo
echo "== goals"
m4=cortex-m4f
if [ -f "$dir/$m4/size-A.txt" ]; then
    awk -v dir="$dir" '
        $2 == "cortex-m4f" { text += $3; ro += $4; data += $5; bss += $6 }
        END {
            printf "   .text cortex-m4f (whole library)       %6d B  (goal <= 32768: %s); .rodata %d, .data %d, .bss %d\n",
                text, text <= 32768 ? "met" : "NOT MET", ro, data, bss }' "$dir/size-modules.txt"
    awk -v an="${ANALYSIS_MODULES:-mre crlb q2}" '
        BEGIN { n = split(an, a, " "); for (i = 1; i <= n; i++) skip[a[i]] = 1 }
        $2 == "cortex-m4f" && !($1 in skip) { text += $3 }
        END { printf "   .text cortex-m4f without [%s]  %6d B  (goal <= 32768: %s): the run-time library without\n", an, text,
                text <= 32768 ? "met" : "NOT MET"
              printf "                                                  its design-time analysis modules\n" }' "$dir/size-modules.txt"
    [ -s "$dir/$m4/fw-footprint.txt" ] && awk '$1 == "libtrk" {
            printf "   .text cortex-m4f (typical image)        %6d B  (goal <= 32768: %s): libtrk code linked by fw_footprint.c\n",
                $2, $2 <= 32768 ? "met" : "NOT MET" }' "$dir/$m4/fw-footprint.txt"
    [ -s "$dir/$m4-nojoint/fw-footprint.txt" ] && awk '$1 == "libtrk" {
            printf "   .text cortex-m4f (typical image, TRK_WITH_JOINT=0) %6d B  (goal <= 32768: %s): without joint association\n",
                $2, $2 <= 32768 ? "met" : "NOT MET" }' "$dir/$m4-nojoint/fw-footprint.txt"
    tr=$(hexsize "$dir/$m4/sizeof-default.txt" | awk '$1 == "trk_sizeof_tracker" { print $2 }')
    sd=$(hexsize "$dir/$m4/sizeof-default.txt" | awk '$1 == "trk_sizeof_scan_detections" { print $2 }')
    st=$(awk -F '\t' '$1 == "trk_tracker_process_scan" { print $2 }' "$dir/$m4/stack.txt")
    awk -v tr="$tr" -v sd="$sd" -v st="$st" 'BEGIN {
        ram = tr + sd + st
        printf "   RAM cortex-m4f, 64 tracks x 256 dets    %6d B  (goal <= 65536: %s) = struct trk_tracker %d + scan detections %d + stack %d\n",
            ram, ram <= 65536 ? "met" : "NOT MET", tr, sd, st
        printf "   stack trk_tracker_process_scan m4f      %6d B  (goal <= 2048: %s), libm included\n",
            st, st <= 2048 ? "met" : "NOT MET" }'
fi
