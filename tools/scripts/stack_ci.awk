# stack_ci.awk - worst-case stack depth from gcc's -fcallgraph-info=su files.
#
#   awk -v EXTERN=ext.txt -v ROOTS=public -f tools/scripts/stack_ci.awk file.ci...
#
# Each .ci file (VCG text, one per object, written by gcc with
# -fstack-usage -fcallgraph-info=su) lists the functions of one translation
# unit as nodes with their own frame size ("N bytes (static)", the same number
# as the .su file) and the calls that survived optimisation as edges.
# Functions of other objects appear as "ellipse" nodes without a size and are
# resolved by name against the other .ci files (static functions are named
# "file.c:name", so they never clash).
#
# worst(f) = frame(f) + max over callees c of worst(c)
#
# Calls leaving the library (libm, memcpy, compiler helpers) have no .ci node:
# their worst depth is read from EXTERN (lines "name bytes", e.g. produced by
# stack_elf.awk from a linked image with the target's C library); a callee
# found in neither is counted as 0 and flagged "ext:name".
# Limits, all flagged in the output rather than hidden:
#   recursion   a call back into a function on the current path: counted once
#               (the depth of the recursion is not bounded by this analysis);
#   indirect    a call through a function pointer (gcc's __indirect_call):
#               the callee is unknown, counted 0 (the caller-supplied callback's
#               own stack must be added);
#   dynamic     a frame gcc marks "dynamic" (VLA/alloca; banned in trk);
#   ext:NAME    an external callee with no EXTERN entry.
# The interrupt/exception context a preempting handler pushes (Cortex-M: 32 or
# 104 bytes with FP context) is not included.
#
# Output, one line per root, sorted by name:
#   name<TAB>worst_bytes<TAB>own_frame<TAB>flags<TAB>path (a > b > c)
# ROOTS=public (default): global functions named trk_* except the library's
# internal trk_i_* ones; ROOTS=all: every function.

function basename_of(t,   i) {
    i = index(t, ":")
    return i ? substr(t, i + 1) : t
}

function walk(f,   i, n, c, w, best, bestpath, fl) {
    if (f in memo) return memo[f]
    if (onpath[f]) { cyc = cyc " recursion"; return 0 }
    if (!(f in frame)) {
        if (f == "__indirect_call") { cyc = cyc " indirect"; return 0 }
        if (f in ext) { mpath[f] = f "[ext]"; return ext[f] }
        cyc = cyc " ext:" f
        return 0
    }
    onpath[f] = 1
    best = 0; bestpath = ""
    n = ncall[f]
    for (i = 1; i <= n; i++) {
        c = callee[f, i]
        w = walk(c)
        if (w > best || bestpath == "") {
            best = w
            bestpath = (c in mpath) ? mpath[c] : basename_of(c)
        }
    }
    onpath[f] = 0
    if (dyn[f]) cyc = cyc " dynamic"
    memo[f] = frame[f] + best
    mpath[f] = basename_of(f) "(" frame[f] ")" (bestpath != "" ? " > " bestpath : "")
    return memo[f]
}

BEGIN {
    if (ROOTS == "") ROOTS = "public"
    if (EXTERN != "") {
        while ((getline line < EXTERN) > 0) {
            split(line, a, /[ \t]+/)
            if (a[1] != "" && a[1] !~ /^#/ && a[2] ~ /^[0-9]+$/) ext[a[1]] = a[2] + 0
        }
        close(EXTERN)
    }
}

/^node:/ {
    if (!match($0, /title: "[^"]*"/)) next
    t = substr($0, RSTART + 8, RLENGTH - 9)
    if (match($0, /\\n[0-9]+ bytes \([a-z,]*\)/)) {
        s = substr($0, RSTART + 2, RLENGTH - 2)
        split(s, b, " ")
        frame[t] = b[1] + 0
        if (s ~ /dynamic/ && s !~ /bounded/) dyn[t] = 1
    }
    next
}

/^edge:/ {
    if (!match($0, /sourcename: "[^"]*"/)) next
    src = substr($0, RSTART + 13, RLENGTH - 14)
    if (!match($0, /targetname: "[^"]*"/)) next
    dst = substr($0, RSTART + 13, RLENGTH - 14)
    if (seen[src, dst]++) next
    callee[src, ++ncall[src]] = dst
    next
}

END {
    # a clean memo per root, so that each root's flags cover its whole tree
    # (the graph is a few hundred nodes)
    for (f in frame) {
        if (ROOTS == "public" && (index(f, ":") || f !~ /^trk_/ || f ~ /^trk_i_/)) continue
        split("", memo); split("", mpath); split("", onpath)
        cyc = ""
        w = walk(f)
        split("", fseen); flags = ""
        nflag = split(cyc, fl, " ")
        for (i = 1; i <= nflag; i++) if (!(fl[i] in fseen)) { fseen[fl[i]] = 1; flags = flags (flags == "" ? "" : ",") fl[i] }
        printf "%s\t%d\t%d\t%s\t%s\n", f, w, frame[f], (flags == "" ? "-" : flags), mpath[f]
    }
}
