#!/bin/sh
# docs_run_selftest.sh - tools/scripts/docs_run.py on a page of its own (run
# from the top of the checkout; part of `make docs-run`): a passing block
# passes, a block whose middle command fails fails at its FILE:LINE (the rest
# of the block not run), `long` and `display` blocks are skipped, a fence
# without `run` never runs, a misspelled marker fails, and the exit status
# is 1. So the step cannot pass by running nothing.
set -u
STEP=docs-run-selftest
. tests/step_lib.sh

cat > "$T/page.md" <<'PAGE'
# a page

```sh run
test -d build && test -f Makefile     # the repository root, mirrored
echo written > top_level_file         # vanishes with the block's directory
```

```sh run
true
false
touch "$MARK.after_failure"
```

```sh run long
touch "$MARK.long"
```

```sh run display
touch "$MARK.display"
```

```sh
touch "$MARK.plain"
```

```sh run lnog
true
```
PAGE
MARK=$T/mark; export MARK
python3 tools/scripts/docs_run.py "$T/page.md" > "$T/out.txt" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "exit status $rc, want 1: $(cat "$T/out.txt")"
want() { grep -q "$1" "$T/out.txt" || fail "no line '$1' in: $(cat "$T/out.txt")"; }
want '^PASS .*page\.md:3 '
want '^FAIL .*page\.md:8 .*exit status 1'
want '^SKIP .*page\.md:14 (long)'
want '^SKIP .*page\.md:18 (display)'
want "^FAIL .*page\.md:26: unknown marker 'sh run lnog'"
want '^docs-run: 1 passed, 2 failed, 2 skipped (display 1, long 1)'
for m in after_failure long display plain; do
    [ -e "$MARK.$m" ] && fail "the block that touches $MARK.$m ran"
done
[ -e top_level_file ] && fail "a block's top-level file is in the repository"
ok "a failing block fails at its FILE:LINE; long, display, plain and misspelled blocks do not run"
