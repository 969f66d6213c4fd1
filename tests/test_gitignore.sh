#!/usr/bin/env bash
# What the docs have a reader make inside the checkout is ignored by git, so `git status`
# stays clean after following them (issue 46): the README's build folders, `out/`, the
# tutorial's `hello` and `sweep_live`, docs/python.md's `.venv/` and `sweep.png`. Each path
# is also checked to be named by the docs, so a renamed output fails here too. Outside a git
# work tree (a release tarball) there is nothing to check.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_gitignore"

if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    echo "test_gitignore: not a git work tree: nothing to check"
    finish test_gitignore
fi
for made in build/ssgraph build-test/ssgraph out/gi.png hello sweep_live .venv/bin/python3 \
        sweep.png; do
    git check-ignore -q --no-index "$made" || fail "$made (made by following the docs) is not ignored"
done
# where the docs make them
grep -q -- "-o sweep_live" docs/tutorial.md || fail "docs/tutorial.md no longer makes sweep_live"
grep -q -- "--plot sweep.png" docs/python.md || fail "docs/python.md no longer makes sweep.png"
grep -q -- "venv --system-site-packages .venv" docs/python.md ||
    fail "docs/python.md no longer makes .venv"
finish test_gitignore
