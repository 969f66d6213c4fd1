#!/usr/bin/env bash
# The README's first command installs the run-time set (tools/debian-packages.txt) and the
# test tooling comes with the test command (issue 46: the first command installed a browser,
# selenium, pytest and matplotlib before the first image). tools/install-deps.sh runs here
# against a stand-in apt-get that records what it was asked to install; the lists are
# disjoint, the tools only tests use are in the second, CI installs both, and tools/test.sh
# installs the second when any of it is missing.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_deps_lists"

run_list=tools/debian-packages.txt test_list=tools/debian-packages-test.txt
for f in "$run_list" "$test_list"; do [ -s "$f" ] || fail "$f is missing or empty"; done
both=$(sort "$run_list" "$test_list" | uniq -d)
[ -z "$both" ] || fail "in both lists: $both"
for tool in chromium chromium-driver python3-selenium python3-pytest python3-matplotlib \
        glmark2-data; do
    grep -qx "$tool" "$test_list" || fail "$tool (tests only) is not in $test_list"
done
for need in libembree-dev libopenimageio-dev libosmesa6-dev libmicrohttpd-dev graphviz; do
    grep -qx "$need" "$run_list" || fail "$need (building or running ssgraph) is not in $run_list"
done

# a stand-in apt-get (and sudo) that records its arguments
mkdir -p "$TMP/bin"
printf '#!/bin/sh\necho "$@" >> "%s/apt.log"\n' "$TMP" > "$TMP/bin/apt-get"
printf '#!/bin/sh\nexec "$@"\n' > "$TMP/bin/sudo"
chmod +x "$TMP/bin/apt-get" "$TMP/bin/sudo"
installs() { rm -f "$TMP/apt.log"; PATH=$TMP/bin:$PATH bash tools/install-deps.sh "$@" &&
             grep '^install' "$TMP/apt.log"; }
first=$(installs) || fail "tools/install-deps.sh failed"
echo "$first" | grep -qw libembree-dev || fail "the first command does not install libembree-dev"
echo "$first" | grep -qw chromium && fail "the first command installs chromium: $first"
full=$(installs --test) || fail "tools/install-deps.sh --test failed"
echo "$full" | grep -qw chromium && echo "$full" | grep -qw libembree-dev ||
    fail "--test does not install both lists: $full"
expect_exit 2 "usage" env PATH="$TMP/bin:$PATH" bash tools/install-deps.sh --frobnicate

grep -q "debian-packages-test.txt" .ci/run || fail ".ci/run does not install the test list"
grep -q "install-deps.sh --test" tools/test.sh || fail "tools/test.sh does not install the test list"
finish test_deps_lists
