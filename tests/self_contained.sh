#!/bin/sh
# self_contained.sh - the repository stands alone: no tracked file names a
# path outside it (a sibling checkout of reference material, a workspace or home
# directory), so that a plain clone builds, tests and reads the same
# anywhere. Its reference material lives in the repository: the vectors in
# tests/vectors, the conventions in docs/conventions.md, the papers cited by
# author, year and equation.
#
#   sh tests/self_contained.sh [DIR]      (DIR: the repository, default .)
#
# Lists the tracked files (git ls-files; every file but build/ and .git when
# DIR is not a git checkout) and fails on each line naming such a path.
# It fails as well on a line that names a tracker issue by number ("issue"
# and a number): code, comments, docs and --help texts say what and why, and
# the history of a change belongs in CHANGELOG.md and the commit messages.
STEP=self-contained
dir=${1:-.}
cd "$dir" || { echo "$STEP: FAIL: no directory $dir"; exit 1; }
# ../NAME of the workspace around a checkout, absolute workspace and home
# directories (written with a bracket so that this file does not match itself)
pat='\.\./(shared|seeds|vectors|CONVENTIONS|DESIGN|TOOLCHAIN|INDEX)[/.]|(^|[^A-Za-z0-9_.~-])/(wor[k]|hom[e]|User[s]|roo[t]|mn[t]|scratc[h])/|~[/]'
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    list() { git ls-files -z; }
else
    list() { find . -path ./.git -prune -o -path './build*' -prune -o -type f -print0; }
fi
n=$(list | tr -cd '\0' | wc -c)
[ "$n" -gt 0 ] || { echo "$STEP: FAIL: no file found in $dir"; exit 1; }
st=0
hits=$(list | xargs -0 grep -nIE -- "$pat")
if [ -n "$hits" ]; then
    echo "$hits"
    echo "$STEP: FAIL: $(echo "$hits" | wc -l) lines above name a path outside the repository (cite docs/ or tests/vectors/ instead)"
    st=1
fi
# ("issue" written with a bracket so that this line does not match itself)
hits=$(list | xargs -0 grep -nIiE -- '(^|[^a-z])issu[e]s? ?#?[0-9]+')
if [ -n "$hits" ]; then
    echo "$hits"
    echo "$STEP: FAIL: $(echo "$hits" | wc -l) lines above name an issue number (say what and why instead)"
    st=1
fi
[ $st = 0 ] || exit 1
echo "$STEP: ok: $n files name no path outside the repository and no issue number"
