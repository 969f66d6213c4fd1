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
# FUZZ_SEED=N fixes libFuzzer's seed (CI uses 1), so a run from an empty corpus makes the same
# inputs in the same order wherever it runs, and a CI finding can be replayed here.
# FUZZ_VALGRIND=1 builds into build-fuzz-vg/ without ASan and runs each fuzzer under valgrind,
# stopping at the first invalid read or write: the libraries Assimp and OpenImageIO are not
# instrumented, so ASan sees their overruns only later, as a damaged heap in some other
# input's free ("CHECK failed: asan_allocator.cpp"), while valgrind names the input at fault
# (build-fuzz-vg/findings/<target>/valgrind-input, its report in the log). About 100
# executions a second instead of 500.
# Needs: clang (Debian package clang) besides the packages of tools/debian-packages.txt;
# valgrind for FUZZ_VALGRIND=1.
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-600}
[ $# -gt 0 ] && shift
targets=${*:-graph scene gltf image model}
build=build-fuzz
flags=()
runner=()
if [ "${FUZZ_VALGRIND:-0}" = 1 ]; then
    # valgrind reads DWARF 4, not clang's default 5
    build=build-fuzz-vg
    flags=(-DSSG_FUZZ_ASAN=OFF -DCMAKE_C_FLAGS=-gdwarf-4 -DCMAKE_CXX_FLAGS=-gdwarf-4)
    runner=(valgrind -q --exit-on-first-error=yes --error-exitcode=77)
fi
cmake -S . -B $build -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSSG_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "${flags[@]}" > /dev/null || exit 1
cmake --build $build -j"$(nproc)" $(printf -- '--target fuzz_%s ' $targets) > /dev/null || exit 1
seed=()
[ -n "${FUZZ_SEED:-}" ] && seed=(-seed="$FUZZ_SEED")
found=0
for t in $targets; do
    case $t in graph|scene) max_len=8192 ;; *) max_len=65536 ;; esac
    seeds=$build/seeds/$t findings=$build/findings/$t
    rm -rf "$seeds" && mkdir -p "$seeds" $build/corpus/$t "$findings"
    while read -r s; do
        [ -d "$s" ] && find "$s" -maxdepth 1 -type f -exec cp {} "$seeds/" \;
        [ -f "$s" ] && cp "$s" "$seeds/"
    done < fuzz/seeds_$t.txt
    echo "fuzz_$t: $secs s"
    # intercept_tls_get_addr=0: see SSG_SANITIZER_ENV in CMakeLists.txt (LeakSanitizer's
    # tracer and the dynamic TLS of the dlopen'd OpenImageIO module).
    # SSG_FUZZ_LAST (fuzz/fuzz_input.h): the input being run, kept for valgrind's stop.
    ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1:intercept_tls_get_addr=0 \
    LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:intercept_tls_get_addr=0 \
    SSG_FUZZ_LAST=${runner:+$findings/current-input} \
        "${runner[@]}" $build/fuzz_$t "${seed[@]}" -max_total_time="$secs" -timeout=20 \
        -rss_limit_mb=4096 -malloc_limit_mb=4096 -max_len=$max_len -print_final_stats=1 \
        -artifact_prefix="$findings/" $build/corpus/$t "$seeds" > $build/fuzz_$t.log 2>&1
    rc=$?
    [ "$rc" = 77 ] && mv "$findings/current-input" "$findings/valgrind-input"
    rm -f "$findings/current-input"
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb|^#[0-9]+.*DONE" $build/fuzz_$t.log | tail -3
    # crash-, leak-, timeout-, oom- and valgrind- files fail the run; slow-unit- files (over
    # 10 s, under the timeout) are reported to look at.
    n=$(ls "$findings" | grep -vc '^slow-unit-')
    slow=$(ls "$findings" | grep -c '^slow-unit-')
    echo "fuzz_$t: exit $rc, $n finding(s), $slow slow unit(s) in $findings/"
    { [ "$rc" -ne 0 ] || [ "$n" -ne 0 ]; } && found=1
done
exit $found
