#!/usr/bin/env bash
# The command line's conventions (issue 18, item 3): both value forms of an option, help per
# command, options refused where they do not apply, -o for the main output, a `wrote PATH`
# line per file (none with --quiet), -v, bare strings in --set, `dot`, --version's features.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_cli_conventions"

# --- --size WxH and --size=WxH (every option with a value takes both) give the same run ---
"$BIN" run graphs/ssao.graph --size 48x32 --out "$TMP/sp" -q || fail "--size WxH"
"$BIN" run graphs/ssao.graph --size=48x32 --out="$TMP/eq" -q || fail "--size=WxH"
cmp -s "$TMP/sp/ssao.exr" "$TMP/eq/ssao.exr" || fail "--size=48x32 differs from --size 48x32"
expect_exit 2 "--size expects" "$BIN" run graphs/ssao.graph --size=48
expect_exit 2 "option '--quiet' takes no value" "$BIN" run graphs/ssao.graph --quiet=1
expect_exit 2 "option '--seed' needs a value" "$BIN" check graphs/ssao.graph --seed

# --- help: every command listed by `help`, and documented by `help CMD` and `CMD --help`
# alike, with only its own options ---
"$BIN" help > "$TMP/help.txt" || fail "help"
cmds=$(sed -n '/^commands:/,/^$/p' "$TMP/help.txt" | grep -oE '^  [a-z]+' | tr -d ' ')
[ "$(echo $cmds)" = "run check node bench compare tune dot view layers extract nodes describe docs help" ] \
    || fail "help lists: $(echo $cmds)"
for cmd in $cmds; do
    "$BIN" help "$cmd" > "$TMP/h_$cmd.txt" || fail "help $cmd"
    "$BIN" "$cmd" --help > "$TMP/c_$cmd.txt" || fail "$cmd --help"
    cmp -s "$TMP/h_$cmd.txt" "$TMP/c_$cmd.txt" || fail "help $cmd differs from $cmd --help"
    grep -q "^usage: ssgraph $cmd" "$TMP/h_$cmd.txt" || fail "help $cmd has no usage line"
    [ "$(wc -l < "$TMP/h_$cmd.txt")" -ge 5 ] || fail "help $cmd says too little"
done
grep -q -- "--sweep" "$TMP/h_run.txt" && fail "help run shows bench's --sweep"
grep -q -- "--size" "$TMP/h_compare.txt" && fail "help compare shows --size"
grep -q -- "--json" "$TMP/h_compare.txt" || fail "help compare lacks --json"
expect_exit 2 "unknown command 'frob'" "$BIN" help frob

# --- an option of another command: named with the command, exit 2, nothing written ---
expect_exit 2 "option '--size' does not apply to 'nodes'" "$BIN" nodes --size 64x64
expect_exit 2 "option '--frames' does not apply to 'compare'" "$BIN" compare a.exr b.exr --frames 3
expect_exit 2 "option '--out' does not apply to 'dot'" "$BIN" dot graphs/ssao.graph --out "$TMP/no"
expect_exit 2 "option '--threads' does not apply to 'check'" "$BIN" check graphs/ssao.graph \
    --threads=2
expect_exit 2 "both say where 'run' writes" "$BIN" run graphs/ssao.graph -o "$TMP/no/x.exr" \
    --out "$TMP/no"
[ -e "$TMP/no" ] && fail "a refused command line wrote $TMP/no"

# --- -o: run's first write node as DIR/NAME.exr with its PNG beside it; node's first
# output; a `wrote PATH` line per file, none with --quiet ---
"$BIN" run graphs/ssao.graph --size 48x32 -o "$TMP/o/main.exr" > "$TMP/o.txt" || fail "run -o"
[ "$(grep '^wrote ' "$TMP/o.txt")" = "wrote $TMP/o/main.exr
wrote $TMP/o/main.png" ] || fail "run -o wrote: $(grep '^wrote ' "$TMP/o.txt")"
oiiotool "$TMP/o/main.exr" "$TMP/sp/ssao.exr" --fail 0 --diff > /dev/null \
    || fail "run -o changed the image"
"$BIN" run graphs/ao_error.graph --size 32x24 --out "$TMP/m" > "$TMP/m.txt" || fail "metrics run"
for f in "$TMP"/m/*; do
    grep -qx "wrote $f" "$TMP/m.txt" || fail "run did not say it wrote $f"
done
[ "$(grep -c '^wrote ' "$TMP/m.txt")" -eq "$(ls "$TMP/m" | wc -l)" ] \
    || fail "run's wrote lines do not match its files"
"$BIN" run graphs/ssao.graph --size 48x32 -q -o "$TMP/q/x.exr" > "$TMP/q.txt" 2>&1 || fail "-q"
[ -s "$TMP/q.txt" ] && fail "run -q printed: $(head -3 "$TMP/q.txt")"
[ -f "$TMP/q/x.exr" ] || fail "run -q -o wrote no x.exr"
expect_exit 0 "^wrote $TMP/n/k.exr$" "$BIN" node halton --set count=8 -o "$TMP/n/k.exr"
[ -f "$TMP/n/k_rotation.exr" ] || fail "node -o did not put the second output beside the first"
expect_exit 0 "^wrote $TMP/n/v.exr \(8x1, 3 channels\)$" "$BIN" node halton --set count=8 -v \
    -o "$TMP/n/v.exr"
[ -z "$("$BIN" node halton --quiet --out "$TMP/nq")" ] || fail "node --quiet printed"
[ -z "$("$BIN" node halton -qvo "$TMP/nq/c.exr")" ] && [ -f "$TMP/nq/c.exr" ] \
    || fail "short options together (-qvo FILE) are not read as -q -v -o FILE"
expect_exit 2 "-o expects DIR/NAME.exr" "$BIN" run graphs/ssao.graph -o "$TMP/x.png"
printf 'scene "%s/examples/cornell.scene"\ng = gbuffer()\n' "$PWD" > "$TMP/nowrite.graph"
expect_exit 2 "has none" "$BIN" run "$TMP/nowrite.graph" -o "$TMP/nw/x.exr"

# --- -v: what the run resolved, every node's parameters ---
expect_exit 0 "^  ao +ssao +cpu +radius=0.5 " "$BIN" run graphs/ssao.graph --size 32x24 -v \
    --out "$TMP/v"

# --- bare strings in --set, for string parameters only; quoted ones as before ---
"$BIN" run graphs/ssao.graph --size 32x24 --set out.name=bare --out "$TMP/b" -q || fail "bare"
"$BIN" run graphs/ssao.graph --size 32x24 --set 'out.name="quoted"' --out "$TMP/b" -q \
    || fail "quoted"
[ -f "$TMP/b/bare.exr" ] && [ -f "$TMP/b/quoted.exr" ] || fail "--set out.name: $(ls "$TMP/b")"
expect_exit 1 "radius" "$BIN" check graphs/ssao.graph --set ao.radius=abc

# --- dot: a digraph with every node and its type, edges labelled with ports ---
"$BIN" dot graphs/ssao.graph > "$TMP/g.dot" || fail "dot"
grep -q '^digraph "ssao" {$' "$TMP/g.dot" && tail -1 "$TMP/g.dot" | grep -qx '}' \
    || fail "dot is not one digraph"
for n in "g:gbuffer" "k:halton" "ao:ssao" "b:bilateral" "img:combine" "out:write"; do
    grep -qF "\"${n%%:*}\" [label=\"${n%%:*}\\n(${n#*:})\"];" "$TMP/g.dot" || fail "dot lacks $n"
done
grep -qF '"g" -> "ao" [label="position -> position"];' "$TMP/g.dot" || fail "dot lacks g->ao"
[ "$(grep -c -- ' -> .*label=' "$TMP/g.dot")" -eq 18 ] || fail "dot has not 18 edges"
# Graphviz comes with the dependencies (tools/debian-packages.txt), so the README's
# `ssgraph dot | dot -Tsvg` works as written; in CI its absence is a failure.
if command -v dot > /dev/null; then
    "$BIN" dot graphs/ssao.graph | dot -Tsvg > "$TMP/g.svg" || fail "graphviz refuses the DOT"
    grep -q '<svg' "$TMP/g.svg" || fail "dot -Tsvg drew nothing"
elif [ -n "${CI:-}" ]; then
    fail "graphviz's dot is not installed (tools/debian-packages.txt lists graphviz)"
fi
expect_exit 0 "^wrote $TMP/d/g.dot$" "$BIN" dot graphs/ssao.graph -o "$TMP/d/g.dot"
cmp -s "$TMP/g.dot" "$TMP/d/g.dot" || fail "dot -o differs from stdout"
expect_exit 1 "cannot open" "$BIN" dot "$TMP/none.graph"

# --- --version: the build's features, found at run time ---
"$BIN" --version > "$TMP/version.txt" || fail "--version"
grep -qE '^ssgraph [0-9]+\.[0-9]+' "$TMP/version.txt" || fail "--version lacks the version"
grep -qx 'backends: cpu, gl.*' "$TMP/version.txt" || fail "--version lacks the backends"
grep -qE '^gl: (OSMesa|EGL|unavailable)' "$TMP/version.txt" || fail "--version lacks GL"
grep -qE '^embree: [0-9]+\.[0-9]+' "$TMP/version.txt" || fail "--version lacks Embree"
grep -qE '^openimageio: [0-9]+\.[0-9]+' "$TMP/version.txt" || fail "--version lacks OIIO"

# --- bench and tune: a wrote line per file, -q silences everything but errors ---
"$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4,8 --out "$TMP/b" \
    > "$TMP/bench.out" 2> "$TMP/bench.err" || fail "bench failed: $(cat "$TMP/bench.err")"
for f in bench.csv bench.json bench.md; do
    grep -qx "wrote $TMP/b/$f" "$TMP/bench.out" && [ -s "$TMP/b/$f" ] || fail "bench: no wrote line for $f"
done
grep -q "^bench: cell 2/2 k.count=8: " "$TMP/bench.err" || fail "bench shows no cell progress"
"$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4 -v --out "$TMP/bv" \
    2>&1 | grep -q "^bench: cell 1/1 k.count=4: .* ms (g [0-9.]*, k " || fail "bench -v lacks node times"
"$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep out.name=first,second -q \
    --out "$TMP/bs" || fail "bench: a bare string --sweep is refused"
[ -s "$TMP/bs/cells/0/first.exr" ] && [ -s "$TMP/bs/cells/1/second.exr" ] \
    || fail "bench: the bare string sweep did not name the cells' files"
out=$("$BIN" bench graphs/ssao.graph --size 32x24 --frames 1 --sweep k.count=4 -q --out "$TMP/bq" 2>&1)
[ -z "$out" ] && [ -s "$TMP/bq/bench.csv" ] || fail "bench -q printed '$out' or wrote nothing"
"$BIN" tune graphs/ao_error.graph --reference g.depth --image g.depth --size 24x16 \
    --param ao.radius=0.2:0.8 --evals 2 --out "$TMP/t" > "$TMP/tune.out" 2>&1 || fail "tune failed"
for f in tune.csv tune.json tuned.graph; do
    grep -qx "wrote $TMP/t/$f" "$TMP/tune.out" || fail "tune: no wrote line for $f"
done
out=$("$BIN" tune graphs/ao_error.graph --reference g.depth --image g.depth --size 24x16 \
      --param ao.radius=0.2:0.8 --evals 2 -q --out "$TMP/tq" 2>&1)
[ -z "$out" ] && [ -s "$TMP/tq/tune.csv" ] || fail "tune -q printed '$out' or wrote nothing"

finish test_cli_conventions
