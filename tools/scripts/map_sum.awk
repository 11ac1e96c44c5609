# map_sum.awk - bytes a linked image takes from each library, from its GNU ld
# map file (-Wl,-Map=...): input sections kept after --gc-sections, grouped
# by archive (libtrk.a, libm.a, libc*.a, libgcc.a, other objects) and by kind
# (.text, .rodata, .data, .bss).
#   awk -f tools/scripts/map_sum.awk image.map
# Output: "<group> <text> <rodata> <data> <bss>" lines.

function group(file) {
    if (file ~ /libtrk\.a\(/) return "libtrk"
    if (file ~ /libm(_nano)?\.a\(/) return "libm"
    if (file ~ /libc(_nano)?\.a\(/ || file ~ /librdimon/ || file ~ /libnosys/) return "libc"
    if (file ~ /libgcc\.a\(/) return "libgcc"
    return "other"
}
function add(sec, size, file,   g, k) {
    if (size !~ /^0x[0-9a-fA-F]+$/) return
    g = group(file)
    if (sec ~ /^\.text/ || sec ~ /^\.ARM\.ex/) k = "text"
    else if (sec ~ /^\.rodata/) k = "rodata"
    else if (sec ~ /^\.data/) k = "data"
    else if (sec ~ /^\.bss/ || sec ~ /^COMMON/) k = "bss"
    else return
    sum[g, k] += hex(size)
    seen[g] = 1
}
function hex(s,   i, v) {
    s = tolower(substr(s, 3)); v = 0
    for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return v
}
/^Linker script and memory map/ { on = 1; next }
!on { next }
# " .text.name  0xaddr  0xsize  file" on one line
/^ [.A-Z][^ ]* +0x[0-9a-f]+ +0x[0-9a-f]+ / { add($1, $3, $4); pending = ""; next }
# a long section name alone, its address/size/file on the next line
/^ [.A-Z][^ ]*$/ { pending = $1; next }
pending != "" && /^ +0x[0-9a-f]+ +0x[0-9a-f]+ / { add(pending, $2, $3); pending = ""; next }
{ pending = "" }
END {
    n = split("libtrk libm libc libgcc other", G, " ")
    for (i = 1; i <= n; i++)
        if (G[i] in seen) printf "%s %d %d %d %d\n", G[i], sum[G[i], "text"], sum[G[i], "rodata"], sum[G[i], "data"], sum[G[i], "bss"]
}
