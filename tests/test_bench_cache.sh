#!/usr/bin/env bash
# test_bench_cache.sh - `bench --reference` scores each cell against a reference rendered
# once and cached (cli/bench_reference.c): the cached reference gives the very metrics the
# graph's own compare node gives; a second bench reuses it; a stale or corrupt cache file is
# rendered again; a reference parameter or a second scene is another entry.
set -u
. "$(dirname "$0")/lib.sh" test_bench_cache
export SSGRAPH_CACHE="$TMP/cache"
CACHE="$SSGRAPH_CACHE/references"
ARGS=(graphs/ao_error.graph --size 40x28 --frames 1 --sweep k.count=4,8
      --sweep ao.radius=0.25,0.5 --reference ref.out --image aob.out --mask g.depth -q)

"$BIN" bench "${ARGS[@]}" --out "$TMP/first" || fail "bench --reference failed"
[ "$(ls "$CACHE" | grep -c '\.exr$')" -eq 1 ] || fail "4 cells of one scene made $(ls "$CACHE") (want one reference)"
# the cache's reference and the graph's own give the same error, to the bit
"$BIN" run graphs/ao_error.graph --size 40x28 --set k.count=8 --set ao.radius=0.25 -q \
    --out "$TMP/run" || fail "run failed"
python3 - "$TMP" <<'PY' || fail "the cached reference's error is not the graph's own"
import csv, json, sys
t = sys.argv[1]
own = json.load(open(t + "/run/metrics.json"))["c_ssao_filtered"]
row = [r for r in csv.DictReader(open(t + "/first/bench.csv"))
       if r["k.count"] == "8" and r["ao.radius"] == "0.25"][0]
got = dict(kv.split("=") for kv in row["metrics"].split(";"))
for m in ("rmse", "mae", "bias", "ssim"):
    assert "%.6g" % own[m] == got["bench_reference." + m], (m, own, got)
PY
exr=$(ls "$CACHE"/*.exr); key=${exr%.exr}.key
stamp=$(stat -c %y "$exr")
"$BIN" bench "${ARGS[@]}" --out "$TMP/second" || fail "the second bench failed"
[ "$(stat -c %y "$exr")" = "$stamp" ] || fail "the second bench rendered the reference again"
cmp -s <(cut -d, -f1-5,14 "$TMP/first/bench.csv") <(cut -d, -f1-5,14 "$TMP/second/bench.csv") \
    || fail "the cached reference gave other metrics"

# corrupt pixels and a stale key are not trusted: rendered again, same metrics
printf 'garbage' | dd of="$exr" bs=1 seek=400 conv=notrunc status=none
"$BIN" bench "${ARGS[@]}" --out "$TMP/corrupt" || fail "bench over a corrupt cache failed"
[ "$(stat -c %y "$exr")" != "$stamp" ] || fail "a corrupt cached reference was used"
cmp -s <(cut -d, -f1-5,14 "$TMP/first/bench.csv") <(cut -d, -f1-5,14 "$TMP/corrupt/bench.csv") \
    || fail "a corrupt cache changed the metrics"
sed -i '1s/.*/ssgraph 0.0.0 bench reference/' "$key"
stamp=$(stat -c %y "$exr")
"$BIN" bench "${ARGS[@]}" --out "$TMP/stale" || fail "bench over a stale cache failed"
[ "$(stat -c %y "$exr")" != "$stamp" ] || fail "a stale cached reference was used"
head -1 "$key" | grep -q "^ssgraph [0-9.]* bench reference$" && ! grep -qF 0.0.0 "$key" \
    || fail "the stale key was not rewritten"

# what the reference reads makes another entry: its parameters, another scene
"$BIN" bench "${ARGS[@]}" --set ref.rays=64 --out "$TMP/rays" || fail "bench with ref.rays failed"
[ "$(ls "$CACHE" | grep -c '\.exr$')" -eq 2 ] || fail "ref.rays=64 did not make its own reference"
"$BIN" bench "${ARGS[@]}" --scene examples/cornell.scene --scene examples/gap.scene \
    --out "$TMP/scenes" || fail "bench over two scenes failed"
[ "$(ls "$CACHE" | grep -c '\.exr$')" -eq 3 ] || fail "the gap scene did not make its own reference"
[ "$(grep -c '^[0-9]*,"examples/gap.scene",.*,ok,' "$TMP/scenes/bench.csv")" -eq 4 ] \
    || fail "the scene sweep lacks the gap scene's 4 cells"
finish test_bench_cache
