#!/usr/bin/env python3
"""structure.py - which source file uses which, and the circles among them.

    python3 tools/scripts/structure.py [--check] [--dot FILE] [ROOT]

Nodes are the C files of src/ (with src/perf, src/host, src/shared), include/trk/
and tools/: foo.c and foo.h of one folder are one node. A public header
include/trk/NAME.h is a node of its own, below src/**/NAME.c: it is the module's
face, which the implementation and its private helpers (NAME_impl.h) include.
"A uses B" when A has `#include "B"` (resolved as the Makefile's -I options do),
or when A names something defined in B that A's translation unit can see: a
function, macro, type, enum constant or variable defined in a file of the same
translation unit (a .c and every header it includes), or an extern function or
variable defined in another .c file (one of the same link: a tool's own folder
or the library layers). Comments and string literals are stripped first;
member names (after `.` or `->`) are not uses; `main` is never one; a name a
header declares itself (a macro of it calling its own prototype) is not a use,
nor is testing whether a name is defined (#ifdef, defined(X): a switch the
includer may set).

Circles are the strongly connected components (Tarjan) of more than one node;
each is printed with, for every edge inside it, one include or identifier that
creates it. The scan's modules have two rules more (STAGES below): no stage
uses another, and only the track filter interface uses a filter. --check exits
1 when a circle exists or a rule is broken. --dot FILE writes a Graphviz drawing (one cluster per folder).
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


def flat(text):
    """Braced blocks out, the innermost first."""
    while re.search(r"\{[^{}]*\}", text):
        text = re.sub(r"\{[^{}]*\}", " ", text)
    return text


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
            elif word in ("if", "elif"):    # whether a name is defined is a switch, not a use
                self.scan_uses(re.sub(r"\bdefined\s*(\(\s*\w+\s*\)|\w+)", " ", rest))
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
        text = flat(text).strip()
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
        if not body and re.match(r"extern\b", text) and "(" not in decl:
            m = re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*$", decl)
            if m:                        # an extern variable's declaration: as a prototype
                self.unuse(m.group(1))
                self.protos.add(m.group(1))
            return
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
            for member in flat(code[m.end():i - 1]).split(";"):
                if re.search(r"\(\s*\*\s*\w+\s*\)\s*\(", member):
                    self.unuse_params(member)
                    continue
                for decl in member.split(",")[1:] + [member.split(",")[0]]:
                    name = re.search(r"(\w+)\s*(\[[^\]]*\]\s*)*(:\s*\w+\s*)?$", decl)
                    if name and len(IDENT.findall(member)) > 1:
                        self.unuse(name.group(1))


def build(root):
    """The files, their nodes, and the edges (node A, node B) -> (file of A, what, file of B)."""
    paths = []
    for top in ("src", "include", "tools"):
        for d, dirs, names in os.walk(os.path.join(root, top)):
            dirs.sort()
            paths += [os.path.relpath(os.path.join(d, f), root) for f in sorted(names)
                      if f.endswith((".c", ".h"))]
    files = {p: Source(root, p) for p in paths}
    node = {p: p[:-2] for p in paths}  # foo.c + foo.h of one folder

    def resolve(frm, inc):
        dirs = INC_SRC if frm.startswith(("src/", "include/")) else INC_TOOLS
        for d in (os.path.dirname(frm),) + dirs:
            p = os.path.normpath(os.path.join(d, inc))
            if p in files:
                return p
        return None

    def unit(start):
        """A translation unit: each file with the root's #include line it came by."""
        seen, stack = {start: 1 << 30}, [(start, None)]
        while stack:
            p, entry = stack.pop()
            for line, inc in reversed(files[p].includes):
                q = resolve(p, inc)
                if q and q not in seen:
                    seen[q] = entry or line
                    stack.append((q, entry or line))
        return seen
    units = {p: unit(p) for p in paths if p.endswith(".c")}
    unit_of = {}
    for c, u in units.items():
        for p in u:
            unit_of.setdefault(p, []).append(c)
    for p in paths:                  # a header no .c includes: a unit of its own
        if p not in unit_of:
            units[p], unit_of[p] = unit(p), [p]
    externs = {}
    for p, f in files.items():
        for name, kind in f.defs.items():
            if p.endswith(".c") and kind == "extern" and name != "main":
                externs.setdefault(name, []).append(p)

    def link(user, defs):
        """The extern definitions a user's link sees: its folder's, else the layers'."""
        own = [d for d in defs if folder(d) == folder(user)]
        return own or [d for d in defs if not is_tool(d)] or defs

    edges = {}

    def add(a, b, why):
        if node[a] != node[b]:
            edges.setdefault((node[a], node[b]), (a, why, b))
    for p, f in files.items():
        for _, inc in f.includes:
            if resolve(p, inc):
                add(p, resolve(p, inc), f'#include "{inc}"')
        visible = {}
        for c in unit_of[p]:         # the root's own definitions only above the include
            for q in units[c]:
                for name, line in files[q].line.items():
                    if q != c or p == c or line < units[c][p]:
                        visible.setdefault(name, q)
        for name in f.uses:
            if name in f.defs or (p.endswith(".h") and name in f.protos):
                continue                 # its own, or what a header declares itself
            if name in visible:
                add(p, visible[name], name)
            for q in link(p, externs[name]) if name not in visible and name in externs else []:
                add(p, q, name)
        for name in f.protos - set(f.defs):  # a layer declaring a tool's function
            for q in externs.get(name, []):
                if is_tool(q) and folder(q) != folder(p):
                    add(p, q, "declares " + name)
    return paths, node, externs, edges


def folder(p):
    return os.path.dirname(p)


def is_tool(p):
    return p.startswith("tools/") and folder(p) not in LIB_DIRS


def tarjan(nodes, out):
    """Strongly connected components, each after the components it reaches."""
    index, low, stack, result = {}, {}, [], []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in out[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = stack[stack.index(v):]
            del stack[stack.index(v):]
            result.append(comp)
    sys.setrecursionlimit(10000)
    for v in nodes:
        if v not in index:
            visit(v)
    return result


def main(argv):
    check = "--check" in argv
    dot = argv[argv.index("--dot") + 1] if "--dot" in argv[:-1] else None
    rest = [a for i, a in enumerate(argv) if not a.startswith("-") and (i == 0 or argv[i - 1] != "--dot")]
    if any(a.startswith("-") and a not in ("--check", "--dot") for a in argv) or len(rest) > 1:
        sys.exit(__doc__)
    paths, node, externs, edges = build(rest[0] if rest else ".")
    members = {}
    for p in paths:
        members.setdefault(node[p], []).append(p)
    label = {n: " + ".join(sorted(fs, key=lambda f: (not f.endswith(".c"), f))) for n, fs in members.items()}
    nodes = sorted(members)
    out = {n: sorted(b for (a, b) in edges if a == n) for n in nodes}
    sccs = tarjan(nodes, out)
    comp = {n: i for i, s in enumerate(sccs) for n in s}
    circles = [sorted(s) for s in sccs if len(s) > 1]
    if dot:
        write_dot(dot, nodes, edges, comp, circles)
    if not check:
        level = {}                   # a component after everything it uses
        for i, s in enumerate(sccs):
            level[i] = max([level[comp[m]] + 1 for n in s for m in out[n] if comp[m] != i] or [0])
        for lv in sorted(set(level.values())):
            print(f"== layer {lv}")
            for n in nodes:
                if level[comp[n]] == lv:
                    print(f"{label[n]}\n    uses: " + (", ".join(label[m].split(" + ")[0] for m in out[n]) or "-"))
    names = {}
    for p in paths:
        names.setdefault(os.path.basename(p), []).append(p)
    for ps in [ps for n, ps in sorted(names.items()) if n != "main.c"] + list(externs.values()):
        if len(ps) > 1:              # two files of one name, a function defined twice
            print(f"warning: namesakes {', '.join(ps)}")
    failing = len(circles)
    for s in circles:
        print(f"\ncircle of {len(s)} nodes:")
        for n in s:
            print(f"  {label[n]}")
        for a in s:
            for b in out[a]:
                if b in s:
                    fa, why, fb = edges[(a, b)]
                    print(f"    {fa} -> {fb}: {why}")
    broken = scan_rules(edges)
    for (a, b), why in broken:
        print(f"rule: {a} -> {b}: {why}")
    failing += len(broken)
    print(f"\nstructure: {len(nodes)} nodes, {len(edges)} edges, {len(circles)} circle(s), "
          f"{len(broken)} broken rule(s) of the scan's modules")
    return 1 if check and failing else 0


# The scan's stages (src/tracker.c includes each; docs/architecture.md): no
# stage uses another (the load stage's thinning is its own part), and a
# track's motion model is reached only through the track filter.
STAGES = ("src/tracker_load_impl.h", "src/tracker_update_impl.h", "src/tracker_joint_impl.h",
          "src/tracker_merge_impl.h", "src/tracker_initiate_impl.h", "src/tracker_thin_impl.h")
PARTS = {("src/tracker_load_impl.h", "src/tracker_thin_impl.h")}


def scan_rules(edges):
    """The edges that break the rules above, each with its reason."""
    broken = []
    for (a, b), (fa, why, fb) in sorted(edges.items()):
        if a + ".h" in STAGES and b + ".h" in STAGES and (a + ".h", b + ".h") not in PARTS:
            broken.append(((fa, fb), f"a stage uses another stage ({why})"))
        if os.path.basename(b).startswith("filter_") and a != "src/track_filter_impl":
            broken.append(((fa, fb), f"a filter reached past the track filter interface ({why})"))
    return broken


def write_dot(path, nodes, edges, comp, circles):
    in_circle = {n for s in circles for n in s}
    with open(path, "w") as f:
        f.write("digraph structure {\n  rankdir=LR;\n  node [shape=box, fontsize=10];\n")
        for i, d in enumerate(sorted({folder(n) for n in nodes})):
            f.write(f'  subgraph cluster_{i} {{\n    label="{d}/";\n')
            for n in nodes:
                if folder(n) == d:
                    red = ", color=red" if n in in_circle else ""
                    f.write(f'    "{n}" [label="{os.path.basename(n)}"{red}];\n')
            f.write("  }\n")
        for (a, b), (fa, why, fb) in sorted(edges.items()):
            red = ", color=red" if comp[a] == comp[b] else ""
            tip = f"{fa} -> {fb}: {why}".replace('"', '\\"')
            f.write(f'  "{a}" -> "{b}" [tooltip="{tip}"{red}];\n')
        f.write("}\n")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
