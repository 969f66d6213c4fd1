#!/usr/bin/env bash
# test_bench_shard.sh - `ssgraph bench --shard I/N` and `bench --merge` (docs/cluster.md):
# four shards of a 2x2x2 sweep, run one after another and merged, give the unsharded run's
# tables cell for cell (values, status, metrics; timings aside) and its plots; bad shard
# specs, missing, duplicated and foreign shards and an unreadable shard file are refused
# with a message naming the problem, exit 1, and nothing merged.
set -u
. "$(dirname "$0")/lib.sh" test_bench_shard
SWEEP=(graphs/ao_error.graph --size 40x28 --frames 1 --sweep k.count=4,8
       --sweep ao.radius=0.25,0.5 --sweep ao.bias=0.01,0.02)

"$BIN" bench "${SWEEP[@]}" -q --out "$TMP/full" || fail "the unsharded bench failed"
for i in 0 1 2 3; do
    expect_exit 0 "^bench: shard $i/4: 2 of the 8 cells, 0 failed" \
        "$BIN" bench "${SWEEP[@]}" --shard "$i/4" --out "$TMP/shard$i"
done
expect_exit 0 "bench: merged 4 shards: 8 cells, 0 failed" "$BIN" bench --merge \
    "$TMP/shard2" "$TMP/shard0" "$TMP/shard3" "$TMP/shard1" --plot --out "$TMP/merged"
python3 - "$TMP" <<'PY' || fail "the merged tables differ from the unsharded run's"
import csv, json, re, sys
t = sys.argv[1]
def rows(d):
    keep = ("cell", "k.count", "ao.radius", "ao.bias", "status", "frames", "metrics", "error")
    return [tuple(r[k] for k in keep) for r in csv.DictReader(open(d + "/bench.csv"))]
full, merged = rows(t + "/full"), rows(t + "/merged")
assert len(full) == 8 and full == merged, (full, merged)
assert all("c_ssao.rmse=" in r[6] for r in full)
timing = ("frame_median_ms", "frame_min_ms", "frame_max_ms", "frame_avg_ms", "node_median_ms",
          "node_min_ms", "node_max_ms", "node_ms")
def cells(d):
    j = json.load(open(d + "/bench.json"))
    return j, [{k: v for k, v in c.items() if k not in timing} for c in j["cells"]]
(jf, cf), (jm, cm) = cells(t + "/full"), cells(t + "/merged")
assert cf == cm
assert {k: v for k, v in jf.items() if k != "cells"} == {k: v for k, v in jm.items() if k != "cells"}
assert jm["shard"] == {"index": 0, "count": 1} and jm["cells_total"] == 8
strip = lambda p: re.sub(r"[0-9.]+ \[[0-9.]+-[0-9.]+\] ms", "ms", open(p).read())
assert strip(t + "/full/bench.md") == strip(t + "/merged/bench.md")
s = json.load(open(t + "/shard1/bench.json"))
assert s["shard"] == {"index": 1, "count": 4} and [c["cell"] for c in s["cells"]] == [1, 5]
assert s["definition_hash"] == jf["definition_hash"] and "sweep: ao.bias=0.01,0.02" in s["definition"]
PY
[ -s "$TMP/merged/bench_ms.png" ] && [ -s "$TMP/merged/bench_pareto.png" ] \
    || fail "the merge drew no plots"

# --- bad input: a message naming the problem, exit 1, --out untouched ---
for spec in 3/2 4/4 -1/2; do
    expect_exit 1 "--shard '$spec': I must be one of 0 to" "$BIN" bench "${SWEEP[@]}" \
        --shard "$spec" --out "$TMP/bad"
done
expect_exit 1 "--shard '0/0': N, the number of shards, must be 1" "$BIN" bench "${SWEEP[@]}" \
    --shard 0/0 --out "$TMP/bad"
expect_exit 1 "--shard expects I/N" "$BIN" bench "${SWEEP[@]}" --shard 1 --out "$TMP/bad"
# more shards than cells: refused before anything runs (one would hold no cell), both named
for spec in 8/9 0/9; do
    expect_exit 1 "--shard '$spec': 9 shards for 8 cells" "$BIN" bench "${SWEEP[@]}" \
        --shard "$spec" --out "$TMP/bad"
done
expect_exit 1 "cells missing: 3 \(shard 3/4\), 7 \(shard 3/4\)$" "$BIN" bench \
    --merge "$TMP/shard0" "$TMP/shard1" "$TMP/shard2" --out "$TMP/bad"
expect_exit 1 "^  run shard 3/4 \(--shard I/N\) and merge again" "$BIN" bench --merge \
    "$TMP/shard0" "$TMP/shard1" "$TMP/shard2" --out "$TMP/bad"
expect_exit 1 "shard1 and .*shard1 are both shard 1/4 \(overlapping" "$BIN" bench --merge \
    "$TMP/shard0" "$TMP/shard1" "$TMP/shard2" "$TMP/shard3" "$TMP/shard1" --out "$TMP/bad"
"$BIN" bench graphs/ao_error.graph --size 40x28 --frames 1 --sweep k.count=4,8 \
    --sweep ao.radius=0.25,0.5 --sweep ao.bias=0.01,0.03 --shard 3/4 -q --out "$TMP/foreign"
expect_exit 1 "foreign is a shard of another sweep than .*shard0" "$BIN" bench --merge \
    "$TMP/shard0" "$TMP/shard1" "$TMP/shard2" "$TMP/foreign" --out "$TMP/bad"
mkdir -p "$TMP/broken" && head -c 100 "$TMP/shard3/bench.json" > "$TMP/broken/bench.json"
expect_exit 1 "broken/bench.json: not JSON" "$BIN" bench --merge "$TMP/shard0" "$TMP/shard1" \
    "$TMP/shard2" "$TMP/broken" --out "$TMP/bad"
expect_exit 1 "nothing/bench.json: cannot open" "$BIN" bench --merge "$TMP/shard0" \
    "$TMP/nothing" --out "$TMP/bad"
[ ! -e "$TMP/bad" ] || fail "a refused bench or merge wrote $TMP/bad"
# a shard written before the median came (no frame_median_ms, node_median_ms, ...) still
# merges: its average stands for them
mkdir -p "$TMP/old3"
python3 - "$TMP" <<'PY' || fail "could not write an old-style shard"
import json, sys
j = json.load(open(sys.argv[1] + "/shard3/bench.json"))
for c in j["cells"]:
    for k in ("frame_median_ms", "node_median_ms", "node_min_ms", "node_max_ms"):
        del c[k]
json.dump(j, open(sys.argv[1] + "/old3/bench.json", "w"))
PY
expect_exit 0 "merged 4 shards: 8 cells, 0 failed" "$BIN" bench --merge "$TMP/shard0" \
    "$TMP/shard1" "$TMP/shard2" "$TMP/old3" --out "$TMP/oldmerged"
python3 - "$TMP" <<'PY' || fail "an old-style shard's times were not read back"
import json, sys
j = json.load(open(sys.argv[1] + "/oldmerged/bench.json"))
c = [c for c in j["cells"] if c["cell"] == 3][0]
assert c["frame_median_ms"] == c["frame_avg_ms"] and c["node_median_ms"] == c["node_ms"], c
PY
expect_exit 2 "it takes no --shard" "$BIN" bench --merge --shard 0/2 "$TMP/shard0"
finish test_bench_shard
