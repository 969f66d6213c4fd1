#!/usr/bin/env bash
# test_bench_plot.sh - `ssgraph bench --plot` with hostile and long text (cli/plot.c): gnuplot
# runs what its script says (a double-quoted string runs its `backticks`, a quote ends it),
# so a graph file named with quotes and backticks, and a forged shard bench.json whose graph,
# sweep keys and values, --time and --error hold gnuplot and shell code, must draw their
# plots and run nothing; the script holds none of that text. Sweep values of 248 characters
# are cut in the plots' series names and labels, not written past their buffers.
set -u
. "$(dirname "$0")/lib.sh" test_bench_plot
ROOT=$PWD
HOSTILE='x`touch PWNED`$(touch PWNED)"; system "touch PWNED"; "'"'; system('touch PWNED'); '"

# no_pwned WHAT DIR: no payload ran (gnuplot runs in the output folder DIR, bench in the
# source root) and DIR's gnuplot scripts hold none of the outside text.
no_pwned() {
    local found
    found=$(find "$TMP" "$ROOT" -maxdepth 3 -name 'PWNED*' 2> /dev/null)
    [ -z "$found" ] || { fail "$1 ran a command: $found"; rm -f $found; }
    ! grep -l 'PWNED' "$2"/*.gp 2> /dev/null || fail "$1: a gnuplot script holds outside text"
}

# --- a graph file whose name is gnuplot and shell code ---
mkdir -p "$TMP/graphs"
G="$TMP/graphs/g\"\`touch PWNED\`\$(touch PWNED)'.graph"
printf 'include "%s/graphs/ssao.graph"\n' "$ROOT" > "$G"
expect_exit 0 "wrote .*/name/bench_ms.png" "$BIN" bench "$G" --size 24x16 --frames 1 \
    --sweep k.count=4,8 --sweep ao.radius=0.25,0.5 --plot --out "$TMP/name"
no_pwned "a graph named with quotes and backticks" "$TMP/name"

# --- a forged shard: every text a payload, a metric and a node named like one ---
# (without --error the Pareto plot's axis and bench.md name the metric shown: the first one
# reported, never "the first metric")
"$BIN" bench graphs/ao_error.graph --size 24x16 --frames 1 --sweep k.count=4,8 \
    --sweep ao.radius=0.25,0.5 --time ao --plot -q --out "$TMP/src" ||
    fail "the bench to forge from failed"
first=$(python3 -c 'import json, sys; m = json.load(open(sys.argv[1]))["cells"][0]["metrics"]
print(next(iter(m)))' "$TMP/src/bench.json")
[ "$(sed -n 4p "$TMP/src/bench_pareto.dat")" = "\"$first\"" ] ||
    fail "the Pareto plot's error axis is not named $first: $(head -4 "$TMP/src/bench_pareto.dat")"
grep -q "^ms of node ao (.*) and $first\.$" "$TMP/src/bench.md" ||
    fail "bench.md does not name the error metric $first: $(head -3 "$TMP/src/bench.md")"
mkdir -p "$TMP/forged"
python3 - "$TMP" "$HOSTILE" <<'PY' || fail "could not forge the shard"
import json, sys
t, bad = sys.argv[1], sys.argv[2]
j = json.load(open(t + "/src/bench.json"))
j["graph"] = "g`touch PWNED`" + bad + ".graph"
j["sweeps"][0]["key"] = "k\n`touch PWNED`\\" + bad   # its values stay numbers: the x axis
j["sweeps"][1]["key"] = 'system("touch PWNED")' + bad
j["sweeps"][1]["values"] = ["`touch PWNED`\n" + bad, "@x " + bad + "\\"]
metric = 'c`touch PWNED`.r"; system "touch PWNED"; "'   # node.metric, each part short
j["time_node"], j["error_metric"] = "ao`touch PWNED`" + bad, metric
for c in j["cells"]:
    c["metrics"] = {metric: c["metrics"]["c_ssao.rmse"]}
    for times in [k for k in c if k.startswith("node_") and k.endswith("_ms")]:
        c[times] = {j["time_node"] if k == "ao" else k: v for k, v in c[times].items()}
json.dump(j, open(t + "/forged/bench.json", "w"))
PY
expect_exit 0 "wrote .*/merged/bench_pareto.png" "$BIN" bench --merge "$TMP/forged" --plot \
    --out "$TMP/merged"
no_pwned "a forged bench.json" "$TMP/merged"
python3 - "$TMP/merged" <<'PY' || fail "the plot data lost a record or a name"
import sys
d = sys.argv[1]
for name in ("bench_ms", "bench_pareto"):
    lines = open(d + "/" + name + ".dat").read().split("\n")
    # every text one quoted field on its own record: no quote or newline of the names leaks
    assert all(l.count('"') % 2 == 0 for l in lines), lines
ms = open(d + "/bench_ms.dat").read().split("\n\n\n")
assert len(ms) == 3, ms                    # the texts, then the two series
assert all(s.strip("\n").count("\n") == 2 for s in ms[1:]), ms  # a name, two points
PY
[ -s "$TMP/merged/bench_ms.png" ] && [ -s "$TMP/merged/bench_pareto.png" ] ||
    fail "the forged merge drew no plots"

# --- four sweeps of one 248-character value: cut with "...", never past the buffers ---
long() { printf '%s%0*d' "$1" $((248 - ${#1})) 0; }
expect_exit 0 "wrote .*/long/bench_ms.png" "$BIN" bench graphs/ssao.graph --size 16x12 \
    --frames 1 --sweep "ao.radius=$(long 0.5)" --sweep "ao.bias=$(long 0.01)" \
    --sweep "k.falloff=$(long 1.5)" --sweep "k.min_scale=$(long 0.3)" --plot --out "$TMP/long"
grep -q '^"ao.bias=0.01000*.*\.\.\."$' "$TMP/long/bench_ms.dat" ||
    fail "the long series name is not cut with ...: $(cat "$TMP/long/bench_ms.dat")"
no_pwned "long values" "$TMP/long"
finish test_bench_plot
