#!/usr/bin/env bash
# Builds ssgraph into build-test/ (or SSG_BUILD_DIR; flags from SSG_CMAKE_FLAGS) and runs the whole test
# suite with ctest. This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${SSG_BUILD_DIR:-build-test}
cmake -S . -B "$dir" -DBUILD_TESTING=ON -DSSGRAPH_BUILD_BENCH=ON ${SSG_CMAKE_FLAGS:--DCMAKE_BUILD_TYPE=Release} >/dev/null
cmake --build "$dir" -j"$(nproc)"
ctest --test-dir "$dir" --output-on-failure -j"$(nproc)" --timeout 300
