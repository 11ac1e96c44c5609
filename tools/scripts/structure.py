#!/usr/bin/env python3
"""structure.py - which source file uses which, and the circles among them.

    python3 tools/scripts/structure.py [--check] [--dot FILE] [ROOT]

Nodes are the C files of src/ (with src/perf, src/host, src/shared) and tools/:
foo.c and foo.h of one folder are one node, and so are src/**/NAME.c and
include/trk/NAME.h (headers of include/trk/ without a .c are nodes of their own).
"A uses B" when A has `#include "B"` (resolved as the Makefile's -I options do),
or when A names something defined in B that A's translation unit can see: a
function, macro, type, enum constant or variable defined in a file of the same
translation unit (a .c and every header it includes), or an extern function or
variable defined in another .c file (one of the same link: a tool's own folder
or the library layers). Comments and string literals are stripped first;
member names (after `.` or `->`) are not uses; `main` is never one.

Circles are the strongly connected components (Tarjan) of more than one node;
each is printed with, for every edge inside it, one include or identifier that
creates it. --check exits 1 when a circle exists; with STRUCTURE_SKIP_SRC=1 in
the environment, circles made only of src/ and include/ files are reported but
do not fail. --dot FILE writes a Graphviz drawing (one cluster per folder).
"""
import os
import re
import sys

LIB_DIRS = ("src", "src/perf", "src/host", "src/shared", "include/trk",
            "tools/lcm", "tools/vec", "tools/sim", "tools/gen", "tools/par",
            "tools/par/mpi", "tools/cli")
# the -I options of the Makefile (and mk/mpi.mk) after the file's own folder
INC_SRC = ("include", "src")
INC_TOOLS = ("include", "tools/lcm", "tools/vec", "tools/sim", "tools/gen",
             "tools/par", "tools/cli", "tools/par/mpi")
KEYWORDS = set("""auto break case char const continue default do double else enum
extern float for goto if inline int long register restrict return short signed
sizeof static struct switch typedef union unsigned void volatile while _Bool
_Complex _Static_assert defined include define undef ifdef ifndef elif endif
pragma error line NULL""".split())
IDENT = re.compile(r"[A-Za-z_]\w*")
STRIP = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)


def strip(text):
    """Comments and literals out, continued lines joined; line numbers kept."""
    def blank(m):
        s = m.group(0)
        return '""' if s[0] in "\"'" else " " + "\n" * s.count("\n")
    lines = STRIP.sub(blank, text).split("\n")
    for i in range(len(lines) - 1):
        if lines[i].endswith("\\"):
            lines[i + 1], lines[i] = lines[i][:-1] + " " + lines[i + 1], ""
    return lines


class Source:
    """One file: its includes, what it defines (and on which line), the names it uses."""

    def __init__(self, root, path):
        self.path = path
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            raw = f.read()
        self.includes = [(raw.count("\n", 0, m.start()) + 1, m.group(1)) for m in
                         re.finditer(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', raw, re.M)]
        code_lines, self.defs, self.line, self.uses, self.protos = [], {}, {}, {}, set()
        for n, line in enumerate(strip(raw), 1):
            m = re.match(r"\s*#\s*(\w+)\s*(.*)", line)
            if not m:
                code_lines.append(line)
                continue
            code_lines.append("")
            word, rest = m.groups()
            if word == "define":
                name = re.match(r"(\w+)(\(([^)]*)\))?", rest)
                if name:
                    self.define(name.group(1), "macro", n)
                    params = set(IDENT.findall(name.group(3) or ""))
                    self.scan_uses(rest[name.end():], params)
            elif word in ("if", "elif", "ifdef", "ifndef"):
                self.scan_uses(rest)
        self.code = "\n".join(code_lines)
        self.scan_uses(self.code)
        self.scan_defs(self.code)
        self.scan_members(self.code)

    def define(self, name, kind, line):
        if name not in KEYWORDS and name not in self.defs:
            self.defs[name], self.line[name] = kind, line

    def scan_uses(self, text, skip=()):
        for m in IDENT.finditer(text):
            name = m.group(0)
            if name in skip:
                continue
            before = text[max(0, m.start() - 2):m.start()].rstrip()
            if name in KEYWORDS or before.endswith(".") or before.endswith("->"):
                continue
            self.uses[name] = self.uses.get(name, 0) + 1

    def unuse(self, name):
        """A name declared here (a prototype, a parameter) is no use of it."""
        if self.uses.get(name, 0) > 1:
            self.uses[name] -= 1
        else:
            self.uses.pop(name, None)

    def scan_defs(self, code):
        """Top-level definitions: functions with a body, types, tags, enum
        constants and variables ("static" or "extern" as their kind)."""
        def line(i):
            return code.count("\n", 0, i) + 1
        for m in re.finditer(r"\b(struct|union|enum)\s+(\w+)\s*\{", code):
            self.define(m.group(2), "type", line(m.start()))
        for m in re.finditer(r"\benum\s+(?:\w+\s*)?\{([^}]*)\}", code):
            for item in m.group(1).split(","):
                name = IDENT.match(item.strip())
                if name:
                    self.define(name.group(0), "type", line(m.start()))
        depth, start, func = 0, 0, False
        for i, c in enumerate(code):
            if c == "{":
                if depth == 0:
                    func = bool(re.search(r"\)\s*$", code[start:i]))
                    if func:
                        self.statement(code[start:i], True, line(i))
                depth += 1
            elif c == "}":
                depth -= 1
                if depth == 0 and func:
                    start = i + 1
            elif c == ";" and depth == 0:
                self.statement(code[start:i], False, line(i))
                start = i + 1

    def statement(self, text, body, line):
        """A top-level statement up to its function body (body) or its `;`."""
        while re.search(r"\{[^{}]*\}", text):
            text = re.sub(r"\{[^{}]*\}", " ", text)
        text = text.strip()
        storage = "static" if re.match(r"(\w+\s+)*static\b", text) else "extern"
        if text.startswith("typedef"):
            m = re.search(r"\(\s*\*\s*(\w+)\s*\)", text) or \
                re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*$", text)
            if m:
                self.define(m.group(1), "type", line)
            return
        m = re.search(r"(\w+)\s*\(((?:[^()]|\([^()]*\))*)\)\s*$", text)
        if m and m.group(1) not in KEYWORDS:
            self.unuse_params(m.group(2))
            if re.search(r"\w\s+\**\s*" + m.group(1) + r"\s*\($", text[:m.end(1) + 1]):
                if body:
                    self.define(m.group(1), storage, line)      # a function
                else:
                    self.unuse(m.group(1))                       # a prototype
                    self.protos.add(m.group(1))
            return
        decl = text.split("=")[0]
        if body or "(" in decl or re.match(r"extern\b|(struct|union|enum)\s+\w+$", text):
            return
        m = re.search(r"\w\s+\**\s*(\w+)\s*(\[[^\]]*\]\s*)*$", decl)
        if m:
            self.define(m.group(1), storage, line)                # a variable

    def unuse_params(self, params):
        depth, start, parts = 0, 0, []
        for i, c in enumerate(params + ","):
            depth += {"(": 1, ")": -1}.get(c, 0)
            if c == "," and depth == 0:
                parts.append(params[start:i])
                start = i + 1
        for param in parts:
            fp = re.search(r"\(\s*\*\s*(\w+)\s*\)\s*\((.*)\)", param)
            if fp:                       # a function pointer: its name and its parameters
                self.unuse(fp.group(1))
                self.unuse_params(fp.group(2))
                continue
            words = IDENT.findall(re.sub(r"\[[^\]]*\]", "", param))
            if len(words) > 1:
                self.unuse(words[-1])

    def scan_members(self, code):
        """Struct and union members are declared, not used."""
        for m in re.finditer(r"\b(struct|union)\s*\w*\s*\{", code):
            depth, i = 1, m.end()
            while depth and i < len(code):
                depth += {"{": 1, "}": -1}.get(code[i], 0)
                i += 1
            body = code[m.end():i - 1]
            while re.search(r"\{[^{}]*\}", body):
                body = re.sub(r"\{[^{}]*\}", " ", body)
            for member in body.split(";"):
                if re.search(r"\(\s*\*\s*\w+\s*\)\s*\(", member):
                    self.unuse_params(member)
                    continue
                for decl in member.split(",")[1:] + [member.split(",")[0]]:
                    name = re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*(:\s*\w+\s*)?$", decl)
                    if name and len(IDENT.findall(member)) > 1:
                        self.unuse(name.group(1))


def main(argv):
    args, check, dot = [], False, None
    it = iter(argv)
    for a in it:
        if a == "--check":
            check = True
        elif a == "--dot":
            dot = next(it, None)
        elif a.startswith("-"):
            sys.exit(__doc__)
        else:
            args.append(a)
    root = args[0] if args else "."
    paths = []
    for top in ("src", "include", "tools"):
        for d, dirs, files in os.walk(os.path.join(root, top)):
            dirs.sort()
            paths += [os.path.relpath(os.path.join(d, f), root) for f in sorted(files)
                      if f.endswith((".c", ".h"))]
    files = {p: Source(root, p) for p in paths}

    # one node: foo.c + foo.h of a folder; src/**/NAME.c + include/trk/NAME.h
    node = {p: p[:-2] for p in paths}
    for p in paths:
        if p.startswith("src/") and p.endswith(".c"):
            h = "include/trk/" + os.path.basename(p)[:-2] + ".h"
            if h in files:
                node[h] = p[:-2]
    members = {}
    for p in paths:
        members.setdefault(node[p], []).append(p)
    label = {n: " + ".join(sorted(fs, key=lambda f: (not f.endswith(".c"), f)))
             for n, fs in members.items()}

    def resolve(frm, inc):
        dirs = INC_SRC if frm.startswith(("src/", "include/")) else INC_TOOLS
        for d in (os.path.dirname(frm),) + dirs:
            p = os.path.normpath(os.path.join(d, inc))
            if p in files:
                return p
        return None

    # translation units: every .c file and what it includes, each file with
    # the line of the root's #include it came in by
    def closure(start):
        seen = {start: 1 << 30}
        stack = [(start, None)]
        while stack:
            p, entry = stack.pop()
            for line, inc in reversed(files[p].includes):
                q = resolve(p, inc)
                if q and q not in seen:
                    seen[q] = entry or line
                    stack.append((q, entry or line))
        return seen
    units = {p: closure(p) for p in paths if p.endswith(".c")}
    unit_of = {}
    for c, unit in units.items():
        for p in unit:
            unit_of.setdefault(p, []).append(c)
    for p in paths:                  # a header no .c includes: a unit of its own
        if p not in unit_of:
            units[p] = closure(p)
            unit_of[p] = [p]

    externs = {}
    for p, f in files.items():
        if p.endswith(".c"):
            for name, kind in f.defs.items():
                if kind == "extern" and name != "main":
                    externs.setdefault(name, []).append(p)

    def folder(p):
        return os.path.dirname(p)

    def is_tool(p):
        return p.startswith("tools/") and folder(p) not in LIB_DIRS

    def link_pick(user, defs):
        """The one extern definition a user's link sees."""
        own = [d for d in defs if folder(d) == folder(user)]
        lib = [d for d in defs if not is_tool(d)]
        return own or lib or defs

    edges = {}                       # (node A, node B) -> reason

    def add(a, b, why):
        na, nb = node[a], node[b]
        if na != nb:
            edges.setdefault((na, nb), f"{a}: {why}" + (f" ({b})" if b != members[nb][0] else ""))

    for p, f in files.items():
        for _, inc in f.includes:
            q = resolve(p, inc)
            if q:
                add(p, q, f'#include "{inc}"')
        visible = {}
        for c in unit_of[p]:         # the root's own definitions only above the include
            for q in units[c]:
                for name, line in files[q].line.items():
                    if q != c or p == c or line < units[c][p]:
                        visible.setdefault(name, q)
        for name in f.uses:
            if name in f.defs:
                continue
            if name in visible:
                add(p, visible[name], name)
            elif name in externs:
                for q in link_pick(p, externs[name]):
                    add(p, q, name)
        for name in f.protos - set(f.defs):  # a layer declaring a tool's function
            for q in externs.get(name, []):
                if is_tool(q) and folder(q) != folder(p):
                    add(p, q, f"declares {name}")

    dups = {n: ps for n, ps in externs.items() if len({folder(p) for p in ps}) < len(ps)
            or len(ps) > 1 and not any(is_tool(p) for p in ps)}
    nodes = sorted(members)
    out = {n: sorted(b for (a, b) in edges if a == n) for n in nodes}
    sccs = tarjan(nodes, out)
    comp = {n: i for i, s in enumerate(sccs) for n in s}
    circles = [sorted(s) for s in sccs if len(s) > 1]

    level = {}
    for s in sccs:                   # Tarjan emits a component after all it uses
        lv = max([level[comp[m]] + 1 for n in s for m in out[n] if comp[m] != comp[n]] or [0])
        level[comp[s[0]]] = lv
    if dot:
        write_dot(dot, nodes, edges, comp, circles)
    if not check:
        for lv in sorted(set(level.values())):
            print(f"== layer {lv}")
            for n in nodes:
                if level[comp[n]] == lv:
                    print(f"{label[n]}\n    uses: " + (", ".join(out[n]) or "-"))
    for name, ps in sorted(dups.items()):
        print(f"warning: {name} defined extern in more than one file of a link: {', '.join(ps)}")
    skip_src = os.environ.get("STRUCTURE_SKIP_SRC") == "1"
    failing = 0
    for s in circles:
        src_only = all(n.startswith(("src/", "include/")) for n in s)
        note = " (src/ only, not failing: STRUCTURE_SKIP_SRC=1)" if src_only and skip_src else ""
        failing += not note
        print(f"\ncircle of {len(s)} nodes{note}:")
        for n in s:
            print(f"  {label[n]}")
        for a in s:
            for b in out[a]:
                if b in s:
                    print(f"    {a} -> {b}: {edges[(a, b)]}")
    print(f"\nstructure: {len(nodes)} nodes, {len(edges)} edges, {len(circles)} circle(s)"
          + (f", {len(circles) - failing} skipped" if skip_src else ""))
    return 1 if check and failing else 0


def tarjan(nodes, out):
    """Strongly connected components, each after the components it reaches."""
    index, low, stack, on, result = {}, {}, [], set(), []
    for start in nodes:
        if start in index:
            continue
        work = [(start, 0)]
        while work:
            v, i = work.pop()
            if i == 0:
                index[v] = low[v] = len(index)
                stack.append(v)
                on.add(v)
            for j in range(i, len(out[v])):
                w = out[v][j]
                if w not in index:
                    work += [(v, j + 1), (w, 0)]
                    break
                if w in on:
                    low[v] = min(low[v], index[w])
            else:
                if low[v] == index[v]:
                    comp = []
                    while True:
                        w = stack.pop()
                        on.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    result.append(comp)
                if work:
                    u = work[-1][0]
                    low[u] = min(low[u], low[v])
    return result


def write_dot(path, nodes, edges, comp, circles):
    in_circle = {n for s in circles for n in s}
    with open(path, "w") as f:
        f.write("digraph structure {\n  rankdir=LR;\n  node [shape=box, fontsize=10];\n")
        for i, d in enumerate(sorted({os.path.dirname(n) for n in nodes})):
            f.write(f'  subgraph cluster_{i} {{\n    label="{d}/";\n')
            for n in nodes:
                if os.path.dirname(n) == d:
                    color = ", color=red" if n in in_circle else ""
                    f.write(f'    "{n}" [label="{os.path.basename(n)}"{color}];\n')
            f.write("  }\n")
        for (a, b) in sorted(edges):
            red = ', color=red' if comp[a] == comp[b] else ""
            f.write(f'  "{a}" -> "{b}" [tooltip="{edges[(a, b)]}"{red}];\n')
        f.write("}\n")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
