#!/usr/bin/env bash
# test_sequence_bench.sh - bench/sequence.py (docs/time.md, "Measuring sequences") at a tiny
# size: for a temporal graph and a single-frame one over the camera path, one table row per
# frame with finite numbers (the first frame's change is "nan": it has no frame before), the
# temporal node's history length read back (every pixel new in frame 0), the summary lines
# (mean_rmse, flicker, ghosting; skipped without a temporal node) and the plot. A second run
# (of the temporal graph alone) takes the reference sequence from the cache and prints the
# same table; a third, over a cached file whose pixels were changed, renders it again.
# The two EXR readers (python3-openimageio, oiiotool's --dumpdata) give the same tables. GI
# mode (--reference gi): reference_gi's RGB against gi_temporal.graph's and gi.graph's main
# image, the same checks of rows and summary lines, a reference cached apart from AO's (a
# second run takes it from the cache; other --paths render another).
set -u
. "$(dirname "$0")/lib.sh" test_sequence_bench
export SSGRAPH_CACHE="$TMP/cache"
PY=/usr/bin/python3 # Debian's, with python3-numpy (tools/debian-packages-test.txt)
seq_run() {
    "$PY" bench/sequence.py --ssgraph "$BIN" --scene examples/cornell_path.scene \
        --size 32x24 --frames 4 --rays 32 "$@"
}

seq_run graphs/gtao_temporal.graph graphs/gtao.graph --markdown "$TMP/first.md" \
    --plot "$TMP/rmse.png" > "$TMP/first.log" 2>&1 ||
    fail "sequence.py failed: $(cat "$TMP/first.log")"
grep -q "^reference: rendering 4 frames" "$TMP/first.log" || fail "no reference was rendered"
[ -s "$TMP/rmse.png" ] || fail "no plot"

# check_tables FILE TEMPORAL SINGLE MAX: both graphs' rows 0-3 (finite, the rmse in (0, MAX)),
# the temporal one's frame 0 all new pixels, and the summary lines.
check_tables() {
    "$PY" - "$@" << 'EOF'
import math, re, sys
text = open(sys.argv[1]).read()
tgraph, top = sys.argv[2], float(sys.argv[4])
bad = []
for graph in sys.argv[2:4]:
    part = text.split("## %s\n" % graph)[1].split("\n## ")[0]
    rows = [r.strip("|").split("|") for r in part.splitlines() if re.match(r"^\| \d", r)]
    if [int(r[0]) for r in rows] != [0, 1, 2, 3]:
        bad.append("%s: rows %s" % (graph, [r[0] for r in rows]))
    for r in rows:
        vals = [float(v) for v in r[1:]]
        finite = [vals[0]] + (vals[1:3] if int(r[0]) > 0 else [])
        if graph == tgraph:
            finite.append(vals[3])
        if not all(math.isfinite(v) and v >= 0 for v in finite) or not 0 < vals[0] < top:
            bad.append("%s: row %s" % (graph, r))
    temporal = graph == tgraph
    if temporal and float(rows[0][4]) != 1.0:
        bad.append("%s: frame 0 is not all new pixels: %s" % (graph, rows[0]))
    for name in ("mean_rmse", "flicker"):
        m = re.search(r"^- %s %s (\S+)$" % (name, re.escape(graph)), part, re.M)
        if not m or not math.isfinite(float(m.group(1))):
            bad.append("%s: no finite %s line" % (graph, name))
    g = re.search(r"^- ghosting %s (.*)$" % re.escape(graph), part, re.M)
    want = (r"frame [1-3] ratio [0-9.]+ recovery (\d+|never) steady [0-9.]+$" if temporal
            else r"skipped \(no temporal node\)$")
    if not g or not re.match(want, g.group(1)):
        bad.append("%s: ghosting line %s" % (graph, g and g.group(0)))
print("\n".join(bad))
sys.exit(1 if bad else 0)
EOF
}
check_tables "$TMP/first.md" gtao_temporal.graph gtao.graph 1 || fail "the tables are wrong (above)"

seq_run graphs/gtao_temporal.graph --markdown "$TMP/second.md" > "$TMP/second.log" 2>&1 ||
    fail "the second run failed: $(cat "$TMP/second.log")"
grep -q "^reference: cached" "$TMP/second.log" || fail "the second run did not use the cache"
# the temporal graph's section, the same numbers from the cached reference
# (section FILE GRAPH: that graph's section; gtao_temporal.graph's without GRAPH)
section() { sed -n "/^## ${2:-gtao_temporal.graph}\$/,/^- ghosting/p" "$1"; }
one=$(section "$TMP/first.md")
[ -n "$one" ] && [ "$one" = "$(section "$TMP/second.md")" ] ||
    fail "the cached reference gave other numbers"

# a cached file whose frames no longer hash to its key is rendered again, with the same numbers
npz=$(ls "$SSGRAPH_CACHE"/sequences/*.npz)
"$PY" -c 'import numpy as np, sys
z = dict(np.load(sys.argv[1]))
z["ao"][0, 0, 0] += 0.5
np.savez(open(sys.argv[1], "wb"), **z)' "$npz"
seq_run graphs/gtao_temporal.graph --markdown "$TMP/third.md" > "$TMP/third.log" 2>&1 ||
    fail "the run over a corrupt cache failed: $(cat "$TMP/third.log")"
grep -q "^reference: rendering" "$TMP/third.log" || fail "a corrupt cached reference was used"
[ "$one" = "$(section "$TMP/third.md")" ] || fail "the reference rendered again differs"

# the other reader gives the same tables (AO mode, from the cached reference)
if "$PY" -c "import OpenImageIO" 2> /dev/null; then
    grep -q "^reader: python3-openimageio" "$TMP/second.log" ||
        fail "python3-openimageio is importable but was not used"
    seq_run graphs/gtao_temporal.graph --reader oiiotool --markdown "$TMP/oiiotool.md" \
        > "$TMP/oiiotool.log" 2>&1 || fail "the oiiotool reader failed: $(cat "$TMP/oiiotool.log")"
    grep -q "^reader: oiiotool" "$TMP/oiiotool.log" || fail "--reader oiiotool was not used"
    [ "$one" = "$(section "$TMP/oiiotool.md")" ] || fail "the two readers gave other numbers"
fi

# GI mode: reference_gi against the GI pipelines' RGB image
gi_run() {
    "$PY" bench/sequence.py --ssgraph "$BIN" --scene examples/cornell_path.scene \
        --size 32x24 --frames 4 --reference gi "$@"
}
gi_run --paths 8 graphs/gi_temporal.graph graphs/gi.graph --markdown "$TMP/gi.md" \
    --plot "$TMP/gi.png" > "$TMP/gi.log" 2>&1 || fail "GI mode failed: $(cat "$TMP/gi.log")"
grep -q "^reference: rendering 4 frames (8 paths)" "$TMP/gi.log" ||
    fail "GI mode did not render its own reference (the AO one is cached)"
grep -q "layer image, reference_gi 8 paths$" "$TMP/gi.md" || fail "GI mode's title is wrong"
[ -s "$TMP/gi.png" ] || fail "no GI plot"
check_tables "$TMP/gi.md" gi_temporal.graph gi.graph inf || fail "the GI tables are wrong (above)"
gi_run --paths 8 graphs/gi_temporal.graph --markdown "$TMP/gi2.md" > "$TMP/gi2.log" 2>&1 ||
    fail "the second GI run failed: $(cat "$TMP/gi2.log")"
grep -q "^reference: cached" "$TMP/gi2.log" || fail "the second GI run did not use the cache"
gisec=$(section "$TMP/gi.md" gi_temporal.graph)
[ -n "$gisec" ] && [ "$gisec" = "$(section "$TMP/gi2.md" gi_temporal.graph)" ] ||
    fail "the cached GI reference gave other numbers"
gi_run --paths 4 graphs/gi.graph > "$TMP/gi3.log" 2>&1 ||
    fail "the GI run at 4 paths failed: $(cat "$TMP/gi3.log")"
grep -q "^reference: rendering 4 frames (4 paths)" "$TMP/gi3.log" ||
    fail "other --paths took the cached reference"

finish test_sequence_bench
