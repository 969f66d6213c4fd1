#!/usr/bin/env bash
# One graph's CPU/GL parity (a ctest case per graph file): the graph runs at 96x64 with
# --backend cpu and with --backend gl (every node that has a GL side on GL, the reference,
# compare and write nodes on the CPU, transfers between them), and every EXR it writes is
# compared channel by channel with oiiotool --diff (all but compare's diff_* layers, which
# repeat the AO layers' differences magnified): at most FAIL_PERCENT % of the values may
# differ by more than FAIL_ABS. Why not every value: the G-buffer is rasterised on GL and
# ray cast on the CPU, so silhouette pixels can see different surfaces, and everything
# downstream inherits them; the per-node tests (test_gl_*.c) bound the interiors tightly.
# Measured on llvmpipe (Mesa 22.3): ao_error 0.55 % of pixels over 0.05 (the hard range
# check of ssao's defaults flips whole samples at silhouettes), mean errors up to 0.0022.
set -u
graph=${1:?usage: parity.sh GRAPH}
name=$(echo "$graph" | tr '/' '_')
source "$(dirname "$0")/../lib.sh" "ssg_parity_$name"
FAIL_ABS=${FAIL_ABS:-0.05}
FAIL_PERCENT=${FAIL_PERCENT:-3}
MEAN_MAX=${MEAN_MAX:-0.005}
# A graph may widen the share for a reason it states beside it, in a line
# `# parity: percent N REASON` (the mean bound stays).
declared=$(sed -n 's/^# parity: percent \([0-9.]*\) .*/\1/p' "$graph" | head -1)
[ -n "$declared" ] && FAIL_PERCENT=$declared
command -v oiiotool > /dev/null || { fail "oiiotool not found (Debian: openimageio-tools)"; finish parity; }

for b in cpu gl; do
    "$BIN" run "$graph" --size 96x64 --backend $b --out "$TMP/$b" --quiet \
        > "$TMP/$b.log" 2>&1 || fail "$graph on $b: $(tail -5 "$TMP/$b.log")"
done
for exr in "$TMP/cpu"/*.exr; do
    other="$TMP/gl/$(basename "$exr")"
    # Difference-image layers (compare's diff_*) are left out: they show the AO layers'
    # differences again, 1/scale = 4x larger, so they would count each silhouette twice.
    chans=$(oiiotool --info -v "$exr" | sed -n 's/^ *channel list: //p' | tr -d ' ' |
            tr ',' '\n' | grep -v '^diff' | paste -sd, -)
    report=$(oiiotool "$other" --ch "$chans" "$exr" --ch "$chans" --fail "$FAIL_ABS" \
             --failpercent "$FAIL_PERCENT" --diff 2>&1)
    rc=$?
    stats=$(echo "$report" | grep -E "Mean error|Max error|exceed" | tr '\n' ' ')
    echo "$graph $(basename "$exr"): $stats"
    [ $rc -eq 0 ] || fail "$graph: $(basename "$exr") differs between cpu and gl: $report"
    mean=$(echo "$report" | sed -n 's/.*Mean error = //p')
    # oiiotool prints no statistics for images that are the same bits.
    [ -z "$mean" ] && [ $rc -eq 0 ] && ! echo "$report" | grep -q "error" && mean=0
    awk -v m="$mean" -v lim="$MEAN_MAX" 'BEGIN { exit !(m != "" && m + 0 <= lim + 0) }' \
        || fail "$graph: $(basename "$exr") mean cpu/gl difference '$mean' is over $MEAN_MAX"
done
finish "parity $graph"
