#!/usr/bin/env bash
# `ssgraph bench`: the sweep runs exactly the cross product; bench.csv and bench.json
# parse and agree; a failed cell is reported and recorded while the others complete; an
# interrupted bench leaves the rows it finished on disk; bad sweeps and an unknown --time
# node are usage errors.
set -u
source "$(dirname "$0")/lib.sh" "/tmp/ssg_test_bench"

expect_exit 1 "6 cells, 2 failed" "$BIN" bench graphs/ssao.graph --size 48x32 --frames 2 \
    --sweep k.count=4,8 --sweep ao.radius=0.25,0.5,9x --time ao --out "$TMP/b"
python3 - "$TMP/b" <<'PY' || fail "bench files disagree with the cross product"
import csv, itertools, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/bench.csv")))
cells = json.load(open(d + "/bench.json"))["cells"]
want = list(itertools.product(["4", "8"], ["0.25", "0.5", "9x"]))
got = [(r["k.count"], r["ao.radius"]) for r in rows]
assert got == want, got
assert [(c["values"]["k.count"], c["values"]["ao.radius"]) for c in cells] == want
for r, c in zip(rows, cells):
    assert r["status"] == c["status"]
    ok = r["ao.radius"] != "9x"
    assert (r["status"] == "ok") == ok, r
    if ok:
        assert c["frames"] == 2 and abs(float(r["frame_avg_ms"]) - c["frame_avg_ms"]) < 1e-3
        assert abs(c["node_ms"]["ao"] - float(r["node_ms"].split("ao=")[1].split(";")[0])) < 1e-3
    else:
        assert "9x" in r["error"] or r["error"], r
md = open(d + "/bench.md").read()
assert "| k.count | ao.radius = 0.25 | ao.radius = 0.5 | ao.radius = 9x |" in md, md
assert md.count("failed") == 2, md
PY

# Interrupted: stop a slow bench (SIGTERM) once its first row is on disk.
"$BIN" bench graphs/reference_ao.graph --size 320x240 --frames 1 \
    --sweep ref.rays=256,512,768,1024,1280,1536,1792,2048 --out "$TMP/int" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 1 600); do
    [ -f "$TMP/int/bench.csv" ] && [ "$(wc -l < "$TMP/int/bench.csv")" -ge 2 ] && break
    sleep 0.1
done
kill -TERM $pid 2> /dev/null
wait $pid 2> /dev/null
python3 - "$TMP/int" <<'PY' || fail "an interrupted bench lost its finished rows"
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/bench.csv")))
assert 1 <= len(rows) < 8 and all(r["status"] == "ok" and r["error"] == "" for r in rows), rows
cells = json.load(open(d + "/bench.json"))["cells"]
assert len(cells) >= 1
PY

# --plot: ms against the first sweep and error against ms, as PNG through gnuplot.
expect_exit 0 "8 cells, 0 failed" "$BIN" bench graphs/ao_error.graph --size 48x32 --frames 1 \
    --sweep k.count=4,8,16,32 --sweep ao.radius=0.25,0.5 --time ao --error c_ssao.rmse --plot \
    --out "$TMP/plot"
for png in bench_ms bench_pareto; do
    oiiotool --info "$TMP/plot/$png.png" 2>&1 | grep -q "900 x  600" ||
        fail "$png.png is not a 900x600 image: $(oiiotool --info "$TMP/plot/$png.png" 2>&1)"
done
grep -q "Pareto front" "$TMP/plot/bench_pareto.dat" || fail "no Pareto front in the plot data"

# --reference/--image: every cell carries the error of its image against the truth (0
# against itself), and bench.md shows it.
expect_exit 0 "4 cells, 0 failed" "$BIN" bench graphs/ao_error.graph --size 48x32 --frames 1 \
    --sweep k.count=4,16 --sweep ao.radius=0.25,0.5 --reference ref.out --image aob.out \
    --out "$TMP/ref"
expect_exit 0 "2 cells, 0 failed" "$BIN" bench graphs/ao_error.graph --size 48x32 --frames 1 \
    --sweep k.count=4,16 --reference aob.out --image aob.out --out "$TMP/self"
python3 - "$TMP" <<'PY' || fail "--reference errors are missing or wrong"
import json, sys
ref = json.load(open(sys.argv[1] + "/ref/bench.json"))["cells"]
assert len(ref) == 4 and all(c["metrics"]["bench_reference.rmse"] > 0.01 for c in ref)
self = json.load(open(sys.argv[1] + "/self/bench.json"))["cells"]
assert all(c["metrics"]["bench_reference.rmse"] == 0 for c in self)
assert "bench_reference.rmse" in open(sys.argv[1] + "/ref/bench.md").read()
PY
expect_exit 2 "--reference NODE.PORT and --image NODE.PORT go together" "$BIN" bench \
    graphs/ao_error.graph --sweep k.count=4 --reference ref.out

# --stereo: each cell renders both eyes (own folders); its times are the pair's.
expect_exit 0 "2 cells, 0 failed" "$BIN" bench graphs/ssao.graph --stereo --size 40x44 \
    --frames 2 --sweep k.count=4,8 --time ao --out "$TMP/stereo"
for eye in left right; do
    [ -f "$TMP/stereo/cells/1/$eye/ssao.exr" ] || fail "bench --stereo wrote no $eye eye"
done

expect_exit 2 "--sweep expects node.param=v1,v2" "$BIN" bench graphs/ssao.graph --sweep radius=1
expect_exit 2 "--time 'nope' is not a node" "$BIN" bench graphs/ssao.graph --size 32x24 \
    --frames 1 --sweep k.count=4 --time nope --out "$TMP/t"
finish test_bench
