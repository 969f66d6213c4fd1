#!/usr/bin/env bash
# Builds ssgraph into build-test/ (flags from SSG_CMAKE_FLAGS) and runs the whole test
# suite with ctest. This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-test ${SSG_CMAKE_FLAGS:--DCMAKE_BUILD_TYPE=Release} >/dev/null
cmake --build build-test -j"$(nproc)"
ctest --test-dir build-test --output-on-failure -j"$(nproc)" --timeout 300
