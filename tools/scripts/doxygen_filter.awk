# doxygen_filter.awk - docs/Doxyfile's input filter (awk -f this FILE): a
# public header as Doxygen should read it, the headers' hand layout kept.
#
# The headers' comments set equations, tables and step lists off by
# indenting them (" *   e_0 = lambda (1 - P_D P_G)    missed detection").
# Doxygen would run such lines together into one paragraph; this filter makes
# each run of them a verbatim block, so the reference shows them as the
# header does. A line of a /** ... */ block comment is preformatted when its
# text starts two or more spaces after the usual " * ". The filter adds the
# word @verbatim at the end of the line before a run and @endverbatim at the
# start of the line after it (or before the closing star-slash), blanks the
# run's comment margin (inside a verbatim block Doxygen would keep the star),
# and never adds or removes a line, so Doxygen's warnings keep the header's
# line numbers. A comment that sets its own @verbatim or @code block is left
# as it is. awk rather than python: Doxygen runs it about twice per header.

# margin(s): length of the comment margin "   *" of line s, 0 when none
function margin(s) { return match(s, /^[ \t]*\*/) ? RLENGTH : 0 }
# text(s): the line after its margin and one optional space
function text(s,   m, t) {
    m = margin(s); t = substr(s, m + 1)
    return substr(t, 1, 1) == " " ? substr(t, 2) : t
}
function preformatted(s,   t) {
    if (!margin(s)) return 0
    t = text(s)
    return substr(t, 1, 2) == "  " && t !~ /^[ \t]*$/ && substr(t, 1, 1) != "/"
}
function blanks(n,   b) { b = ""; while (n-- > 0) b = b " "; return b }

{ line[NR] = $0 }

END {
    n = NR; i = 1
    while (i <= n) {
        s = line[i]; sub(/^[ \t]*/, "", s)
        if (substr(s, 1, 3) == "/**" && substr(s, 1, 4) != "/**<" && index(s, "*/") == 0) {
            j = i
            while (j < n && index(line[j], "*/") == 0) j++
            explicit = 0
            for (k = i; k <= j; k++) if (line[k] ~ /@verbatim|@code/) explicit = 1
            if (!explicit) comment(i, j)
            for (k = i; k <= j; k++) print line[k]
            i = j + 1
        } else {
            print line[i]; i++
        }
    }
}

# comment(a, b): the runs of preformatted lines of the comment on lines a..b
function comment(a, b,   i, j, k, m, c) {
    i = a + 1
    while (i <= b) {
        if (!preformatted(line[i])) { i++; continue }
        j = i
        while (j + 1 <= b && preformatted(line[j + 1])) j++
        line[i - 1] = line[i - 1] " @verbatim"
        for (k = i; k <= j; k++)
            if (index(line[k], "*/") == 0) {
                m = margin(line[k]); line[k] = blanks(m) substr(line[k], m + 1)
            }
        if ((c = index(line[j], "*/")) > 0)
            line[j] = substr(line[j], 1, c - 1) "@endverbatim " substr(line[j], c)
        else if (j + 1 <= b) {
            m = margin(line[j + 1])
            if (m && substr(text(line[j + 1]), 1, 1) != "/")
                line[j + 1] = blanks(m) " @endverbatim " text(line[j + 1])
            else if ((c = index(line[j + 1], "*/")) > 0)
                line[j + 1] = substr(line[j + 1], 1, c - 1) "@endverbatim " substr(line[j + 1], c)
            else
                line[j + 1] = "@endverbatim " line[j + 1]
        }
        i = j + 2
    }
}
