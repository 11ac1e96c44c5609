#!/usr/bin/env python3
"""docs_links.py - every relative link of the Markdown files resolves.

    python3 tools/scripts/docs_links.py [--root DIR] FILE.md...

A link [text](target) whose target is not a URL (no scheme) must name a file
or folder of the repository, relative to the linking file; a #fragment must
be the anchor of a heading in the target (or in the same file for a bare
#fragment), as GitHub forms it: the heading's text in lower case, every
character that is not a letter, a digit, a space, '-' or '_' dropped, each
space a '-', and a repeated heading numbered -1, -2, ... in order. Links in
fenced code blocks and inline code are not links. Explicit anchors
(<a name="..."> or id="...") count too.

Prints one line per broken link (FILE:LINE: target: why); exit status 1 when
there is one, 0 otherwise (the last line counts the links checked).
"""
import argparse
import os
import re
import sys

LINK = re.compile(r'(?<!!)\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^()\s]+(?:\([^()]*\))?[^()\s]*)(?:\s+"[^"]*")?\)')
IMAGE = re.compile(r'!\[[^\]]*\]\(([^()\s]+)\)')
HEADING = re.compile(r'^(#{1,6})\s+(.*?)(?:\s+#+)?\s*$')
ANCHOR = re.compile(r'<a\s+(?:name|id)="([^"]+)"|\sid="([^"]+)"')
FENCE = re.compile(r'^\s*(```|~~~)')


def slug(text):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r'`([^`]*)`', r'\1', text)               # inline code: its text
    text = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', text)   # a link: its text
    text = re.sub(r'<[^>]+>', '', text)                    # HTML tags
    text = text.strip().lower()
    out = []
    for ch in text:
        if ch.isalnum() or ch in '-_':
            out.append(ch)
        elif ch == ' ':
            out.append('-')
    return ''.join(out)


def prose_lines(path):
    """(line number, line, line without its inline code) of the lines outside
    fenced code blocks."""
    fenced = False
    with open(path, encoding='utf-8') as f:
        for n, line in enumerate(f, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if not fenced:
                yield n, line, re.sub(r'`[^`]*`', '', line)


def anchors(path, cache={}):
    if path not in cache:
        seen, found = {}, set()
        for _, line, _ in prose_lines(path):
            m = HEADING.match(line)
            if m:
                s = slug(m.group(2))
                k = seen.get(s, 0)
                seen[s] = k + 1
                found.add(s if k == 0 else '%s-%d' % (s, k))
            for a in ANCHOR.findall(line):
                found.update(x for x in a if x)
        cache[path] = found
    return cache[path]


def check(path, root):
    bad, n = [], 0
    for num, _, line in prose_lines(path):
        for target in LINK.findall(line) + IMAGE.findall(line):
            if re.match(r'^[a-zA-Z][a-zA-Z0-9+.-]*:', target):  # http:, https:, mailto:
                continue
            n += 1
            file_part, _, frag = target.partition('#')
            dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part)) if file_part else path
            real_root = os.path.realpath(root)
            if os.path.commonpath([os.path.realpath(dest), real_root]) != real_root:
                bad.append('%s:%d: %s: outside the repository' % (path, num, target))
            elif not os.path.exists(dest):
                bad.append('%s:%d: %s: no such file' % (path, num, target))
            elif frag and dest.endswith('.md') and frag not in anchors(dest):
                bad.append('%s:%d: %s: no heading with anchor #%s in %s' % (path, num, target, frag, dest))
    return bad, n


def main():
    ap = argparse.ArgumentParser(description='check the relative links of Markdown files')
    ap.add_argument('--root', default='.')
    ap.add_argument('files', nargs='+')
    a = ap.parse_args()
    bad, total = [], 0
    for f in a.files:
        if not os.path.isfile(f):  # listed by git, gone from the tree
            bad.append('%s: no such file' % f)
            continue
        b, n = check(f, a.root)
        bad += b
        total += n
    for b in bad:
        print(b)
    print('docs-links: %d relative links in %d files, %d broken' % (total, len(a.files), len(bad)))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
