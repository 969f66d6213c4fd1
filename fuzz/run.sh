#!/usr/bin/env bash
# fuzz/run.sh [SECONDS] [TARGET...]: builds the libFuzzer targets with clang into
# build-fuzz/ (library and targets instrumented, ASan + UBSan) and runs each TARGET (default:
# graph scene gltf image model) for SECONDS (default 600), one after another, starting from the
# seeds in fuzz/seeds_<target>.txt. Each target keeps its growing corpus in
# build-fuzz/corpus/<target>/ between runs; a crash, leak, timeout (20 s) or out-of-memory
# input is saved in build-fuzz/findings/<target>/ and the script exits 1 at the end; an
# input slower than 10 s is saved there too as slow-unit-*, reported but not failing. Turn each
# finding into a fixture: fix the bug, copy the file into fuzz/corpus/<target>/ (replayed
# by ctest as fuzz_replay_<target>). The last lines of build-fuzz/fuzz_<target>.log give
# the executions (stat::number_of_executed_units) and coverage (cov:).
# Needs: clang (Debian package clang) besides the packages of tools/debian-packages.txt.
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-600}
[ $# -gt 0 ] && shift
targets=${*:-graph scene gltf image model}
cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSSG_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null || exit 1
cmake --build build-fuzz -j"$(nproc)" $(printf -- '--target fuzz_%s ' $targets) > /dev/null || exit 1
found=0
for t in $targets; do
    case $t in graph|scene) max_len=8192 ;; *) max_len=65536 ;; esac
    seeds=build-fuzz/seeds/$t
    rm -rf "$seeds" && mkdir -p "$seeds" build-fuzz/corpus/$t build-fuzz/findings/$t
    while read -r s; do
        [ -d "$s" ] && find "$s" -maxdepth 1 -type f -exec cp {} "$seeds/" \;
        [ -f "$s" ] && cp "$s" "$seeds/"
    done < fuzz/seeds_$t.txt
    echo "fuzz_$t: $secs s"
    # intercept_tls_get_addr=0: see SSG_SANITIZER_ENV in CMakeLists.txt (LeakSanitizer's
    # tracer and the dynamic TLS of the dlopen'd OpenImageIO module).
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0 \
    LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:intercept_tls_get_addr=0 \
        build-fuzz/fuzz_$t -max_total_time="$secs" -timeout=20 -rss_limit_mb=4096 \
        -malloc_limit_mb=4096 -max_len=$max_len -print_final_stats=1 \
        -artifact_prefix=build-fuzz/findings/$t/ build-fuzz/corpus/$t "$seeds" \
        > build-fuzz/fuzz_$t.log 2>&1
    rc=$?
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb|^#[0-9]+.*DONE" build-fuzz/fuzz_$t.log | tail -3
    # crash-, leak-, timeout- and oom- files fail the run; slow-unit- files (over 10 s,
    # under the timeout) are reported to look at.
    n=$(ls build-fuzz/findings/$t | grep -vc '^slow-unit-')
    slow=$(ls build-fuzz/findings/$t | grep -c '^slow-unit-')
    echo "fuzz_$t: exit $rc, $n finding(s), $slow slow unit(s) in build-fuzz/findings/$t/"
    { [ "$rc" -ne 0 ] || [ "$n" -ne 0 ]; } && found=1
done
exit $found
