#!/usr/bin/env bash
# Builds ssgraph into build-test/ (or SSG_BUILD_DIR; flags from SSG_CMAKE_FLAGS) and runs the whole test
# suite with ctest. This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${SSG_BUILD_DIR:-build-test}
# The test tooling (a browser, selenium, pytest, ...) comes with the test command, not with
# the README's first: install what is missing of both lists (tools/install-deps.sh --test).
# Off Debian (no dpkg-query) the tests that need a tool say which.
if command -v dpkg-query > /dev/null; then
    missing=$(for p in $(cat tools/debian-packages.txt tools/debian-packages-test.txt); do
        dpkg-query -W -f='${Status}\n' "$p" 2> /dev/null | grep -q '^install ok installed$' ||
            echo "$p"
    done)
    if [ -n "$missing" ]; then
        echo "tools/test.sh: installing what the tests need:" $missing
        bash tools/install-deps.sh --test
    fi
fi
cmake -S . -B "$dir" -DBUILD_TESTING=ON -DSSGRAPH_BUILD_BENCH=ON ${SSG_CMAKE_FLAGS:--DCMAKE_BUILD_TYPE=Release} >/dev/null
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)" --timeout 300
