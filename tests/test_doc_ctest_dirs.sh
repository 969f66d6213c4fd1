#!/usr/bin/env bash
# Every `ctest --test-dir DIR` the docs tell a reader to run names a build with tests in it:
# the folder tools/test.sh configures with -DBUILD_TESTING=ON (build-test/). The README's
# first command configures build/ with -DBUILD_TESTING=OFF, where ctest finds nothing to run
# and says so without failing (issue 46: docs/adding-a-node.md's command did that).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_doc_ctest_dirs"

tested=$(sed -n 's/^dir=\${SSG_BUILD_DIR:-\([^}]*\)}$/\1/p' tools/test.sh)
[ -n "$tested" ] || fail "tools/test.sh no longer says its build folder (dir=\${SSG_BUILD_DIR:-...})"
grep -q -- '-DBUILD_TESTING=ON' tools/test.sh || fail "tools/test.sh no longer builds the tests"
grep -q -- '-B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF' README.md ||
    fail "the README's first command no longer configures build/ without tests"
while IFS= read -r hit; do
    dir=$(echo "$hit" | sed -n 's/.*ctest --test-dir \([^ `]*\).*/\1/p')
    [ "$dir" = "$tested" ] || fail "$hit: ctest in '$dir', which has no tests (use $tested)"
done < <(grep -n -- 'ctest --test-dir' README.md docs/*.md docs/*/*.md 2>/dev/null)
finish test_doc_ctest_dirs
