#!/usr/bin/env bash
# test_owned_fifo.sh - a FIFO planted where the program names its own files (issue 42,
# item 4b): text outputs stream into a FIFO or device only when the user names it
# (--profile-json, dot -o); a file the program owns (bench.md in --out, the reference
# cache's key, metrics.json, a plot's data) is written through a temporary and a rename and
# a FIFO there is refused without being opened, so nothing waits for a reader. Each command
# runs under `timeout`, and ctest's TIMEOUT bounds the whole: a hang fails.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_owned_fifo"
T="timeout 30"
export SSGRAPH_CACHE="$TMP/cache"
CACHE="$SSGRAPH_CACHE/references"
BENCH=(graphs/ao_error.graph --size 40x28 --frames 1 --sweep k.count=4,8)

# bench.md (and each table) inside --out: refused before the first cell, the FIFO kept.
for f in bench.md bench.csv bench.json; do
    mkdir -p "$TMP/out_$f"
    mkfifo "$TMP/out_$f/$f"
    expect_exit 1 "$f: error: cannot write an output here: it is a FIFO" $T "$BIN" bench \
        "${BENCH[@]}" --out "$TMP/out_$f"
    [ -p "$TMP/out_$f/$f" ] || fail "bench replaced a FIFO at $f"
    [ -e "$TMP/out_$f/cells" ] && fail "bench ran a cell with a FIFO at $f"
done

# The reference cache's key file: the bench goes on without the cache (a warning), the
# FIFO stays; a second bench does too.
"$BIN" bench "${BENCH[@]}" --reference ref.out --image aob.out -q --out "$TMP/first" \
    || fail "the first bench --reference failed"
key=$(ls "$CACHE"/*.key)
rm -f "$key" "${key%.key}.exr"
mkfifo "$key"
for run in second third; do
    expect_exit 0 "warning: the reference was not cached .*it is a FIFO" $T "$BIN" bench \
        "${BENCH[@]}" --reference ref.out --image aob.out --out "$TMP/$run"
    [ -p "$key" ] || fail "bench replaced the FIFO at the cache key"
done
cmp -s <(cut -d, -f1-2,13 "$TMP/first/bench.csv") <(cut -d, -f1-2,13 "$TMP/third/bench.csv") \
    || fail "the metrics changed without the cache"

# metrics.json in --out (a compare node's): refused, the FIFO kept.
mkdir -p "$TMP/metrics"
mkfifo "$TMP/metrics/metrics.json"
expect_exit 1 "metrics.json: error: cannot write an output here: it is a FIFO" $T "$BIN" run \
    graphs/ao_error.graph --size 40x28 --out "$TMP/metrics" -q
[ -p "$TMP/metrics/metrics.json" ] || fail "run replaced a FIFO at metrics.json"

# A file the user names still streams into a FIFO, as before.
mkfifo "$TMP/profile"
cat "$TMP/profile" > "$TMP/profile.got" & reader=$!
$T "$BIN" run graphs/ssao.graph --size 16x12 --out "$TMP/special" -q \
    --profile-json "$TMP/profile" || fail "--profile-json into a FIFO failed"
wait $reader
grep -q '"nodes"' "$TMP/profile.got" || fail "--profile-json wrote nothing into the FIFO"

finish test_owned_fifo
