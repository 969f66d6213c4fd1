#!/usr/bin/env bash
# `ssgraph tune`: a short tune of hbao's bias and strength on two example scenes at 48x36
# ends no worse than it started, is the same when run again, and its files agree (a row
# per evaluation, each mean the mean of its scenes); tuned.graph loads and, run on each
# scene, gives the error tune reported for it. Bad input exits 1 with the graph's or a
# named message before anything is written (a tune.csv already there survives); an
# evaluation that fails later keeps the rows before it.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_tune"

common=(graphs/ao_error.graph --reference ref.out --image h.out --mask g.depth
        --size 48x36 --threads 2)
scenes=(--scene examples/cornell.scene --scene examples/table.scene)
expect_exit 0 "best of 8 evaluations" "$BIN" tune "${common[@]}" "${scenes[@]}" \
    --param h.bias=0:0.5 --param h.strength=0.5:2 --evals 8 --out "$TMP/a"
expect_exit 0 "best of 8" "$BIN" tune "${common[@]}" "${scenes[@]}" \
    --param h.bias=0:0.5 --param h.strength=0.5:2 --evals 8 --out "$TMP/b"
cmp -s "$TMP/a/tune.csv" "$TMP/b/tune.csv" || fail "the same tune gave another tune.csv"

python3 - "$TMP/a" <<'PY' || fail "tune.csv and tune.json disagree or the tune got worse"
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/tune.csv")))
t = json.load(open(d + "/tune.json"))
assert len(rows) == len(t["evals"]) == 8, len(rows)
scenes = ["examples/cornell.scene", "examples/table.scene"]
assert t["scenes"] == scenes and t["mask"] == "g.depth"
for r, e in zip(rows, t["evals"]):
    errs = [float(r[s]) for s in scenes]
    assert abs(sum(errs) / 2 - float(r["mean"])) < 1e-8, r
    assert abs(e["mean"] - float(r["mean"])) < 1e-8 and r["status"] == "ok"
start, best = t["evals"][0], t["best"]
assert start["values"] == {"h.bias": 0.25, "h.strength": 1.25}, start  # the node's defaults
assert best["mean"] <= start["mean"] and best["mean"] == min(e["mean"] for e in t["evals"])
assert len({tuple(e["values"].values()) for e in t["evals"]}) == 8  # none evaluated twice
PY

# tuned.graph loads and reproduces each scene's error through the graph's own compare; it
# includes the graph by a path relative to itself, so the pair can move together.
expect_exit 0 "ok" "$BIN" check "$TMP/a/tuned.graph"
grep -q '^include "\.\./' "$TMP/a/tuned.graph" || fail "tuned.graph's include is not relative: \
$(grep '^include' "$TMP/a/tuned.graph")"
for scene in cornell table; do
    expect_exit 0 "c_hbao" "$BIN" run "$TMP/a/tuned.graph" --scene examples/$scene.scene \
        --out "$TMP/run_$scene"
    python3 - "$TMP" "$scene" <<'PY' || fail "tuned.graph does not reproduce the $scene error"
import json, sys
d, scene = sys.argv[1], sys.argv[2]
want = json.load(open(d + "/a/tune.json"))["best"]["errors"]["examples/%s.scene" % scene]
got = json.load(open(d + "/run_%s/metrics.json" % scene))["c_hbao"]["rmse"]
assert abs(got - want) < 1e-7, (got, want)
PY
done

# Bad input: exit 1 with the message, and the tune.csv of the tune before is untouched.
printf 'camera(position=[0, 1, 3], target=[0, 1, 0])\nbox(min=[-1, 0, -1], max=[1, 1 1])\n' \
    > "$TMP/bad.scene"
cp "$TMP/a/tune.csv" "$TMP/before.csv"
bad() { # PATTERN ARGS...: the tune into $TMP/a exits 1 and says PATTERN
    local pattern=$1; shift
    expect_exit 1 "$pattern" "$BIN" tune graphs/ao_error.graph --size 48x36 --evals 3 \
        --scene examples/cornell.scene --out "$TMP/a" "$@"
}
ports=(--reference ref.out --image h.out --mask g.depth)
bad "no node named 'hx' \(in 'hx.bias'" "${ports[@]}" --param hx.bias=0:1
bad "ao_error.graph:18:7: error: node 'h' \(hbao\) has no parameter 'bais' \(expected one of: " \
    "${ports[@]}" --param h.bais=0:1
bad "ao_error.graph:18:7: error: parameter 'falloff' .* is not a number" \
    "${ports[@]}" --param h.falloff=0:1
bad "empty or reversed range" "${ports[@]}" --param h.bias=0.5:0.5
bad "empty or reversed range" "${ports[@]}" --param h.bias=0.6:0.2
bad "a log range needs lo > 0" "${ports[@]}" --param h.bias=0:0.5:log
bad "expected a number lo" "${ports[@]}" --param h.bias=low:0.5
bad "expects a number in \[0, 1.5\] radians, got 5" "${ports[@]}" --param h.bias=0:5
bad "part of --reference ref.out" "${ports[@]}" --param ref.rays=16:64
bad "<output>:1:5: error: node 'ref' \(reference_ao\) has no output 'nope'" \
    --reference ref.nope --image h.out --param h.bias=0:0.5
bad "<output>:1:1: error: no node named 'hh'" --reference ref.out --image hh.out \
    --param h.bias=0:0.5
bad "bad.scene:2:[0-9]+: error: " "${ports[@]}" --scene "$TMP/bad.scene" --param h.bias=0:0.5
bad "missing.scene: error: cannot read" "${ports[@]}" --scene "$TMP/missing.scene" \
    --param h.bias=0:0.5
cmp -s "$TMP/a/tune.csv" "$TMP/before.csv" || fail "a refused tune changed tune.csv"
expect_exit 2 "tune needs --reference" "$BIN" tune graphs/ao_error.graph --image h.out \
    --param h.bias=0:1

# An evaluation that fails later (count 9 is no multiple of period 6) stops the tune; the
# files keep the one before it and record the failure.
expect_exit 1 "stopped at evaluation 2 of 6.*multiple of period 6" "$BIN" tune \
    "${common[@]}" --scene examples/cornell.scene --set k.period=6 --set k.count=12 \
    --param k.count=6:12 --evals 6 --out "$TMP/c"
python3 - "$TMP/c" <<'PY' || fail "a failed evaluation lost the rows before it"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/tune.csv")))
assert [r["status"] for r in rows] == ["ok", "error"], rows
assert "multiple of period" in rows[1]["error"]
assert json.load(open(sys.argv[1] + "/tune.json"))["best"]["eval"] == 1
PY

finish test_tune
