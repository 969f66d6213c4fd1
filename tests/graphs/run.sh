#!/usr/bin/env bash
# One graph end to end (a ctest case per graph file, registered in tests/CMakeLists.txt):
# `check` accepts it, `run` at 96x64 writes at least one EXR and one PNG and no temporary,
# and for a graph with a `compare` node the metrics of 1, 2 and 5 frames are the same bytes
# (sinks run in the last frame only; their prepare() must still run) - or, for a graph whose
# samples turn every frame, the same metrics, the same bytes on 1 thread as on all.
set -u
graph=${1:?usage: run.sh GRAPH}
name=$(echo "$graph" | tr '/' '_')
source "$(dirname "$0")/../lib.sh" "ssg_graph_$name"

expect_exit 0 "ok" "$BIN" check "$graph"
out="$TMP/f1"
expect_exit 0 "total" "$BIN" run "$graph" --size 96x64 --out "$out"
[ "$(ls "$out"/*.exr 2>/dev/null | wc -l)" -ge 1 ] || fail "$graph wrote no EXR into $out"
[ "$(ls "$out"/*.png 2>/dev/null | wc -l)" -ge 1 ] || fail "$graph wrote no PNG into $out"
ls -a "$out" | grep -q 'tmp' && fail "$graph left a temporary file in $out"

if grep -q 'compare(' "$graph"; then
    [ -f "$out/metrics.json" ] || fail "$graph has a compare node but wrote no metrics.json"
    # Nodes whose samples turn every frame (docs/time.md) make frame N-1 differ from frame 0;
    # the metrics of a sequence must then still be the same bytes on 1 thread as on all.
    per_frame=$("$BIN" dot "$graph" | grep -cE '\((halton|gtao|ssilvb)\)"')
    for frames in 2 5; do
        "$BIN" run "$graph" --size 96x64 --frames $frames --out "$TMP/f$frames" --quiet \
            > "$TMP/f$frames.log" 2>&1 || fail "$graph --frames $frames: $(tail -3 "$TMP/f$frames.log")"
        if [ "$per_frame" -eq 0 ]; then
            cmp -s "$out/metrics.json" "$TMP/f$frames/metrics.json" \
                || fail "$graph: metrics of $frames frames differ from one frame's: $(diff "$out/metrics.json" "$TMP/f$frames/metrics.json" | head -6)"
            continue
        fi
        [ "$(grep -o '"[a-z_]*":' "$out/metrics.json")" = "$(grep -o '"[a-z_]*":' "$TMP/f$frames/metrics.json")" ] \
            || fail "$graph: the metrics of $frames frames are not those of one frame"
        "$BIN" run "$graph" --size 96x64 --frames $frames --threads 1 --out "$TMP/t$frames" \
            --quiet > "$TMP/t$frames.log" 2>&1 || fail "$graph --frames $frames --threads 1"
        cmp -s "$TMP/t$frames/metrics.json" "$TMP/f$frames/metrics.json" \
            || fail "$graph: metrics of $frames frames differ between 1 thread and all"
    done
fi
finish "graph $graph"
