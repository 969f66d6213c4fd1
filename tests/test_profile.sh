#!/usr/bin/env bash
# The profile's roofline (issue 17, item 1): `peak` measures the machine's limits and
# caches them; `run --frames N` then prints each node's GB/s and GFLOP/s, which bound
# applies and its fraction of it, and --profile-json carries the same numbers. Without a
# cache (or with a broken one) the columns say '-', never a crash.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_profile"
PEAK="$(dirname "$BIN")/peak"
[ -x "$PEAK" ] || { fail "no peak binary next to $BIN"; finish test_profile; }

# The cache: written whole, numbers that make sense.
expect_exit 0 "memory GB/s" env SSGRAPH_PEAK="$TMP/peak.json" "$PEAK" --quick
python3 - "$TMP/peak.json" <<'PY' || fail "peak.json is wrong: $(cat "$TMP/peak.json")"
import json, sys
p = json.load(open(sys.argv[1]))
assert p["threads"] >= 1 and p["gflops"] > 0 and p["gbps"] > 0, p
PY

# With it: the declared flops are the node's formula times its pixels, the bytes every
# bound image once, a bound and a fraction for each CPU pass that declares flops.
expect_exit 0 "^bound: each image read or written once against .*peak.json" \
    env SSGRAPH_PEAK="$TMP/peak.json" "$BIN" run graphs/ssao.graph --size 64x48 --frames 2 \
    --out "$TMP/run" --profile-json "$TMP/run/profile.json"
grep -qE '^node +type .* +prepare ms +GB/s +GFLOP/s +bound +%bound  why$' <(
    env SSGRAPH_PEAK="$TMP/peak.json" "$BIN" run graphs/ssao.graph --size 64x48 --frames 2 \
    --out "$TMP/run2") || fail "the profile's header lacks the roofline columns"
python3 - "$TMP/run/profile.json" <<'PY' || fail "profile.json's roofline is wrong"
import json, sys
p = json.load(open(sys.argv[1]))
assert p["peak"]["gbps"] > 0 and p["peak"]["gflops"] > 0
n = {x["name"]: x for x in p["nodes"]}
px = 64 * 48
# ssao.graph: ssao with a 16-sample kernel; a 9x9 bilateral with normals (power 16)
assert n["ao"]["flops"] == (60 + 38 * 16) * px, n["ao"]["flops"]
assert n["b"]["flops"] == (10 + 1 + 81 * (17 + 6 + 2)) * px, n["b"]["flops"]
# bilateral reads in, depth and normal and writes out and out2 (all zeros): 7 planes
assert n["b"]["bytes"] == 7 * 4 * px, n["b"]["bytes"]
for name in ("g", "ao", "b", "img"):
    x = n[name]
    assert x["bound"] in ("memory", "compute") and x["fraction_of_bound"] > 0, x
    # both printed to 6 digits
    assert abs(x["gflops"] - x["flops"] / (x["avg_ms"] * 1e6)) <= 1e-4 * x["gflops"] + 1e-9
assert n["out"]["flops"] is None and n["out"]["bound"] is None  # write declares none
for x in n.values():  # 2 calls (a sink: 1): the median is the mean
    assert x["min_ms"] <= x["median_ms"] <= x["max_ms"], x
    assert abs(x["median_ms"] - x["avg_ms"]) <= 1e-4 * x["avg_ms"] + 1e-9, x
f = p["frame"]  # the median of 2 frames is their mean
assert f["min_ms"] <= f["median_ms"] <= f["max_ms"], f
assert abs(f["median_ms"] - f["avg_ms"]) <= 1e-4 * f["avg_ms"], f
PY

# Without a cache, and with a broken one: rates still, no bound.
printf 'not json' > "$TMP/broken.json"
for cache in "$TMP/none.json" "$TMP/broken.json"; do
    expect_exit 0 "^bound: no peaks measured" env SSGRAPH_PEAK="$cache" "$BIN" run \
        graphs/ssao.graph --size 64x48 --frames 2 --out "$TMP/nopeak"
    expect_exit 0 "^  ao +ssao +cpu +2 .* +- +-  first run, input k ran$" env SSGRAPH_PEAK="$cache" "$BIN" run \
        graphs/ssao.graph --size 64x48 --frames 2 --out "$TMP/nopeak"
done
finish test_profile
