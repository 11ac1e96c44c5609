# stack_elf.awk - worst-case stack depth of every function of a linked
# Arm Thumb (Cortex-M) image, from its disassembly.
#
#   arm-none-eabi-objdump -d --no-show-raw-insn image.elf | awk -f tools/scripts/stack_elf.awk
#
# Used for the code that has no -fcallgraph-info (newlib's libm and libc,
# libgcc): mk/size.mk feeds its numbers for the functions libtrk calls into
# stack_ci.awk as EXTERN. It also serves as an independent cross-check of the
# source-level numbers for libtrk's own functions.
#
# Frame of a function = the sum of every stack-pointer decrement in its body:
#   push {...} / stmdb sp!, {...}       4 bytes per core register
#   vpush {...} / vstmdb sp!, {...}     8 per d register, 4 per s register
#   sub[w] sp, [sp,] #N                 N
#   str/strd ..., [sp, #-N]!            N
# Summing every decrement (not just the prologue's) over-estimates a function
# that pushes on two exclusive paths: safe.
# Calls: bl/blx <sym>, and branches (b, b.w, b<cond>[.w]) to the first
# instruction of another function (tail calls; counted as calls, which again
# over-estimates by the caller's popped frame). Flags:
#   indirect   blx/bx through a register other than lr (function pointer)
#   dynamic    sp decremented by a register amount (alloca/VLA)
#   recursion  a call back into a function on the current path (counted once)
# Output: name<TAB>worst<TAB>frame<TAB>flags<TAB>path

function regcount(list,   n, i, k, a, b, parts, lo, hi) {
    # "{r4, r5, r6, lr}" or "{r4-r7, lr}" or "{d8-d9}" or "{s16-s23}"
    gsub(/[{} ]/, "", list)
    n = split(list, parts, ",")
    k = 0
    for (i = 1; i <= n; i++) {
        if (index(parts[i], "-")) {
            split(parts[i], a, "-")
            lo = a[1]; hi = a[2]
            gsub(/[a-z]/, "", lo); gsub(/[a-z]/, "", hi)
            k += hi - lo + 1
        } else k++
    }
    return k
}

function walk(f,   i, n, c, w, best, bestpath) {
    if (f in memo) return memo[f]
    if (onpath[f]) { cyc = cyc " recursion"; return 0 }
    if (!(f in frame)) { cyc = cyc " unknown:" f; return 0 }
    onpath[f] = 1
    best = 0; bestpath = ""
    n = ncall[f]
    for (i = 1; i <= n; i++) {
        c = callee[f, i]
        w = walk(c)
        if (w > best || bestpath == "") { best = w; bestpath = mpath[c] }
    }
    onpath[f] = 0
    if (ind[f]) cyc = cyc " indirect"
    if (dyn[f]) cyc = cyc " dynamic"
    memo[f] = frame[f] + best
    mpath[f] = name[f] "(" frame[f] ")" (bestpath != "" ? " > " bestpath : "")
    return memo[f]
}

# function header: "0000f86c <expf>:". Functions are keyed by address (static
# functions of different objects share names); calls give the address too.
function hexkey(a) { sub(/^0+/, "", a); return a == "" ? "0" : a }
/^[0-9a-f]+ <[^>]+>:$/ {
    cur = hexkey($1)
    nm = $2
    gsub(/[<>:]/, "", nm)
    name[cur] = nm
    frame[cur] += 0
    next
}

cur != "" && /^ *[0-9a-f]+:\t/ {
    line = $0
    sub(/^ *[0-9a-f]+:\t/, "", line)
    split(line, ins, /[ \t]+/)
    op = ins[1]
    if (op ~ /^(push|push\.w)$/ || (op ~ /^stmdb/ && line ~ /sp!/)) {
        s = line; sub(/^[^{]*/, "", s); sub(/}.*/, "}", s)
        frame[cur] += 4 * regcount(s)
    } else if (op ~ /^vpush/ || (op ~ /^vstmdb/ && line ~ /sp!/)) {
        s = line; sub(/^[^{]*/, "", s); sub(/}.*/, "}", s)
        frame[cur] += (s ~ /d[0-9]/ ? 8 : 4) * regcount(s)
    } else if (op ~ /^subw?(\.w)?$/ && line ~ /^[a-z.]+[ \t]+sp, /) {
        if (match(line, /#[0-9]+/)) frame[cur] += substr(line, RSTART + 1, RLENGTH - 1) + 0
        else dyn[cur] = 1
    } else if (op ~ /^str/ && match(line, /\[sp, #-[0-9]+\]!/)) {
        s = substr(line, RSTART, RLENGTH); gsub(/[^0-9]/, "", s)
        frame[cur] += s + 0
    } else if (op ~ /^blx?(\.w)?$/ || op ~ /^b(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?(\.[nw])?$/) {
        if (match(line, /[0-9a-f]+ <[^>]+>/)) {
            split(substr(line, RSTART, RLENGTH), ta, " ")
            t = hexkey(ta[1])
            # a call, or a branch to the start of another function (tail call)
            if (ta[2] !~ /\+0x/ && (op ~ /^blx?(\.w)?$/ || t != cur))
                if (!seen[cur, t]++) callee[cur, ++ncall[cur]] = t
        } else if (op ~ /^blx/ || (op ~ /^bx/ && line !~ /lr/)) {
            ind[cur] = 1
        }
    } else if (op ~ /^bx/ && line !~ /lr/) {
        ind[cur] = 1
    }
    next
}

END {
    for (f in name) nmcount[name[f]]++
    for (f in frame) {
        split("", memo); split("", mpath); split("", onpath)
        cyc = ""
        w = walk(f)
        split("", fseen); flags = ""
        nflag = split(cyc, fl, " ")
        for (i = 1; i <= nflag; i++) if (!(fl[i] in fseen)) { fseen[fl[i]] = 1; flags = flags (flags == "" ? "" : ",") fl[i] }
        nm = name[f]
        if (nmcount[nm] > 1) nm = nm "@" f
        printf "%s\t%d\t%d\t%s\t%s\n", nm, w, frame[f], (flags == "" ? "-" : flags), mpath[f]
    }
}
