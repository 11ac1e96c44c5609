#!/usr/bin/env python3
"""docs_run.py - run the documentation's runnable code blocks.

    python3 tools/scripts/docs_run.py [--root DIR] [--bin DIR] [--long] [--display]
                                      [--timeout S] [--list] FILE.md...

A fenced block whose info string is a language followed by the word `run` is
runnable (docs/development.md "Docs that run"):

    ```sh run            a shell block: `sh -e -x`, stops at the first failing command
    ```python run        a Python block: a python3 that imports numpy
    ```sh run long       runnable, but skipped unless --long (minutes of CPU)
    ```sh run display    runnable, but skipped unless --display (needs an X display)

Every block runs on its own, in a fresh temporary directory that mirrors the
repository root: each top-level entry of DIR (except .git) is a symbolic link
there, so `build/bin/trk-sim`, `tools/python/...` and `make ...` work as
documented from the root, while a file a block writes at the top level
(`--out op`, `bridge.conf`) goes into the temporary directory, which is removed
afterwards. PATH starts with the --bin directory (default build/bin: the tools
by their bare names, as after `make install`), PYTHONPATH is tools/python, and
make's own variables (MAKEFLAGS, MAKELEVEL) are removed: a block runs as in a
user's fresh shell. After the blocks, a new untracked file in the repository
(`git status`) fails the run: a block must not write into the source tree.

Prints one line per block (PASS / FAIL / SKIP, FILE:LINE of its opening fence,
seconds); a failing block's output follows, indented. The last line counts
them; the exit status is 1 when a block failed, when a runnable block carries
an unknown word, or when no block ran at all.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

FLAGS = ("long", "display")
LANGS = ("sh", "python")


def blocks(path):
    """(line, lang, flags, text) of each runnable fenced block of a Markdown file;
    (line, None, message, None) for a malformed runnable info string."""
    out = []
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        s = lines[i].lstrip(" ")
        if s.startswith("```") or s.startswith("~~~"):
            fence = s[:3]
            words = s[3:].split()
            start = i + 1
            j = i + 1
            while j < len(lines) and not lines[j].lstrip(" ").startswith(fence):
                j += 1
            if len(words) >= 2 and words[1] == "run":
                bad = [w for w in words[2:] if w not in FLAGS]
                if words[0] not in LANGS or bad:
                    out.append((start, None, "unknown marker '%s' (languages %s, flags %s)"
                                % (" ".join(words), "/".join(LANGS), "/".join(FLAGS)), None))
                else:
                    out.append((start, words[0], set(words[2:]), "\n".join(lines[i + 1:j]) + "\n"))
            i = j + 1
            continue
        i += 1
    return out


def find_python():
    """The first of $PYTHON, python3, /usr/bin/python3 that imports numpy (the
    Python tools' one dependency), or None (tests/step_lib.sh's find_python)."""
    for p in [os.environ.get("PYTHON"), "python3", "/usr/bin/python3"]:
        if p and shutil.which(p):
            if subprocess.call([p, "-c", "import numpy"], stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL) == 0:
                return p
    return None


def untracked(root):
    """The repository's untracked files outside the ignored ones, or None
    without git."""
    try:
        r = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=all"],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    except OSError:
        return None
    if r.returncode != 0:
        return None
    return {l[3:] for l in r.stdout.splitlines() if l.startswith("?? ")}


def mirror(root, where):
    """A temporary directory whose top-level entries link to root's."""
    d = tempfile.mkdtemp(prefix="trk-docs-run.", dir=where)
    for name in sorted(os.listdir(root)):
        if name != ".git":
            os.symlink(os.path.join(root, name), os.path.join(d, name))
    return d


def run_block(root, bin_dir, lang, text, python, timeout):
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES", "MAKE_TERMOUT",
                        "MAKE_TERMERR")}
    env["PATH"] = os.path.join(root, bin_dir) + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.join(root, "tools", "python")
    d = mirror(root, os.environ.get("TMPDIR"))
    cmd = ["sh", "-e", "-x", "-c", text] if lang == "sh" else [python, "-c", text]
    t0 = time.time()
    try:
        r = subprocess.run(cmd, cwd=d, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=timeout)
        rc, output = r.returncode, r.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as e:
        rc = "timeout after %g s" % timeout
        output = (e.stdout or b"").decode("utf-8", "replace")
    finally:
        shutil.rmtree(d, ignore_errors=True)
    return rc, output, time.time() - t0


def main():
    ap = argparse.ArgumentParser(description="Run the runnable code blocks of Markdown files.")
    ap.add_argument("files", nargs="+", metavar="FILE.md")
    ap.add_argument("--root", default=".", help="the repository root (default .)")
    ap.add_argument("--bin", default="build/bin", help="tools directory put first on PATH, "
                    "relative to the root (default build/bin)")
    ap.add_argument("--long", action="store_true", help="also the blocks marked long")
    ap.add_argument("--display", action="store_true", help="also the blocks marked display")
    ap.add_argument("--timeout", type=float, default=300, help="seconds per block (default 300)")
    ap.add_argument("--list", action="store_true", help="list the runnable blocks, run none")
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    before = untracked(root)
    python = None
    python_looked = False
    n = {"pass": 0, "fail": 0, "skip": 0}
    why_skipped = {}
    t_all = time.time()
    for path in a.files:
        rel = os.path.relpath(os.path.abspath(path), root)
        for line, lang, flags, text in blocks(path):
            where = "%s:%d" % (rel, line)
            if lang is None:
                print("FAIL %s: %s" % (where, flags))
                n["fail"] += 1
                continue
            if a.list:
                print("%s %s %s" % (where, lang, " ".join(sorted(flags)) or "-"))
                continue
            skip = [f for f in sorted(flags) if not getattr(a, f)]
            if lang == "python" and not skip:
                if not python_looked:
                    python, python_looked = find_python(), True
                if python is None:
                    skip = ["no python3 with numpy"]
            if skip:
                print("SKIP %s (%s)" % (where, ", ".join(skip)))
                n["skip"] += 1
                why_skipped[skip[0]] = why_skipped.get(skip[0], 0) + 1
                continue
            rc, output, secs = run_block(root, a.bin, lang, text, python, a.timeout)
            if rc == 0:
                print("PASS %-28s %6.2f s" % (where, secs))
                n["pass"] += 1
            else:
                print("FAIL %-28s %6.2f s  %s:" % (where, secs, rc if isinstance(rc, str)
                                                    else "exit status %d" % rc))
                for l in output.rstrip("\n").split("\n")[-40:]:
                    print("    | " + l)
                n["fail"] += 1
            sys.stdout.flush()
    if a.list:
        return 0
    after = untracked(root)
    if before is not None and after is not None and after - before:
        print("FAIL: the blocks left untracked files in the repository: "
              + " ".join(sorted(after - before)))
        n["fail"] += 1
    skipped = ", ".join("%s %d" % kv for kv in sorted(why_skipped.items()))
    print("docs-run: %d passed, %d failed, %d skipped%s in %.1f s"
          % (n["pass"], n["fail"], n["skip"], " (%s)" % skipped if skipped else "", time.time() - t_all))
    if n["pass"] == 0 and n["fail"] == 0:
        print("docs-run: FAILED: no runnable block ran")
        return 1
    return 1 if n["fail"] else 0


if __name__ == "__main__":
    sys.exit(main())
