#!/usr/bin/env bash
# paired_graphs.sh - two graphs' median frames, their runs interleaved on one binary (so a
# load that comes and goes on the machine hits both alike): for a variant that renders at
# another size than the graph it replaces (gi_taau.graph at 640x360 shown at 1280x720
# against gi_temporal_half.graph at 1280x720, bench/results/issue47/README.md, "Fourth
# pass"). Each run is `ssgraph run GRAPH --size SIZE --scene SCENE --frames FRAMES
# --threads 2`; prints each pair's median frames, then each graph's median over the pairs
# and their ratio. Measures; asserts nothing.
#
#   bench/paired_graphs.sh [-n PAIRS] [-b BIN] GRAPH_A SIZE_A GRAPH_B SIZE_B
#
# Defaults: 7 pairs, build/ssgraph, examples/cornell_orbit.scene (the moving camera),
# 10 frames (SCENE, FRAMES in the environment override them).
set -u
pairs=7
bin=build/ssgraph
while [ $# -gt 0 ]; do
    case $1 in
    -n) pairs=$2; shift 2 ;;
    -b) bin=$2; shift 2 ;;
    *) break ;;
    esac
done
[ $# -eq 4 ] || { echo "usage: $0 [-n PAIRS] [-b BIN] GRAPH_A SIZE_A GRAPH_B SIZE_B" >&2; exit 2; }
scene=${SCENE:-examples/cornell_orbit.scene}
frames=${FRAMES:-10}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median_frame() { # graph size: the run's median frame in ms
    "$bin" run "$1" --size "$2" --scene "$scene" --frames "$frames" --threads 2 \
        --out "$work/out" 2>&1 | sed -n 's/.*median frame \([0-9.]*\) ms.*/\1/p'
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

: > "$work/a"
: > "$work/b"
for p in $(seq 1 "$pairs"); do
    a=$(median_frame "$1" "$2") || exit 1
    b=$(median_frame "$3" "$4") || exit 1
    [ -n "$a" ] && [ -n "$b" ] || { echo "$0: a run printed no median frame" >&2; exit 1; }
    echo "pair $p: $1 $a ms, $3 $b ms"
    echo "$a" >> "$work/a"
    echo "$b" >> "$work/b"
done
ma=$(median < "$work/a")
mb=$(median < "$work/b")
echo "median: $1 at $2 $ma ms, $3 at $4 $mb ms, ratio $(awk -v a="$ma" -v b="$mb" 'BEGIN {printf "%.2f", b / a}')"
