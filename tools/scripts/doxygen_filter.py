#!/usr/bin/env python3
"""doxygen_filter.py FILE - docs/Doxyfile's INPUT_FILTER: a public header as
Doxygen should read it, the headers' hand layout kept.

The headers' comments set equations, tables and step lists off by indenting
them (" *   e_0 = lambda (1 - P_D P_G)    missed detection"). Doxygen would run
such lines together into one paragraph; this filter makes each run of them a
verbatim block, so the reference shows them as the header does. A line of a
/** ... */ block comment is preformatted when its text starts two or more
spaces after the usual " * ". The filter only adds the words @verbatim (at
the end of the line before a run) and @endverbatim (at the start of the line
after it, or before the closing star-slash), blanks the run's comment margin,
and never adds or removes a line, so
Doxygen's warnings keep the header's line numbers; a comment that sets its
own @verbatim or @code block is left as it is. Output on stdout.
"""
import re
import sys

LINE = re.compile(r"^(\s*\*)( ?)(.*)$")


def preformatted(line):
    m = LINE.match(line)
    return bool(m) and not m.group(3).startswith("/") and m.group(3).startswith("  ") \
        and m.group(3).strip() != ""


def filter_comment(lines):
    """lines of one /** block comment (the first opens it, the last closes it)"""
    out = list(lines)
    i = 1
    while i < len(out):
        if preformatted(out[i]):
            j = i
            while j + 1 < len(out) and preformatted(out[j + 1]):
                j += 1
            out[i - 1] = out[i - 1] + " @verbatim"
            # inside a verbatim block Doxygen keeps the star of the comment's
            # margin: the margin becomes blanks
            for k in range(i, j + 1):
                m = LINE.match(out[k])
                if "*/" not in m.group(3):
                    out[k] = " " * len(m.group(1)) + m.group(2) + m.group(3)
            if "*/" in out[j]:
                k = out[j].rindex("*/")
                out[j] = out[j][:k] + "@endverbatim " + out[j][k:]
            elif j + 1 < len(out):
                m = LINE.match(out[j + 1])
                if m and not m.group(3).startswith("/"):
                    out[j + 1] = " " * len(m.group(1)) + " @endverbatim " + m.group(3)
                elif "*/" in out[j + 1]:
                    k = out[j + 1].index("*/")
                    out[j + 1] = out[j + 1][:k] + "@endverbatim " + out[j + 1][k:]
                else:
                    out[j + 1] = "@endverbatim " + out[j + 1]
            i = j + 2
        else:
            i += 1
    return out


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    i = 0
    while i < len(lines):
        s = lines[i].lstrip()
        if s.startswith("/**") and not s.startswith("/**<") and "*/" not in s:
            j = i
            while j + 1 < len(lines) and "*/" not in lines[j]:
                j += 1
            block = lines[i:j + 1]
            explicit = any("@verbatim" in l or "@code" in l for l in block)
            out.extend(block if explicit else filter_comment(block))
            i = j + 1
        else:
            out.append(lines[i])
            i += 1
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main()
