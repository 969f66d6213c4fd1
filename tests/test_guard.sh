#!/usr/bin/env bash
# The guard band (docs/guard_band.md): `guard G` renders G more pixels on every side with
# the same camera, and every file and metric stays frame-sized.
#  1. The frame's pixels are the same bits with and without a band (the band only adds
#     pixels around them), on the CPU and on GL.
#  2. compare counts the frame only, and edge=E only its border of E pixels.
#  3. On the scene with an occluder just below the frame (examples/offscreen.scene) the
#     border's error falls once the band holds that occluder.
#  4. A bad guard line or --guard gets file:line:column and exit 1 (2 for usage).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_guard"

cat > "$TMP/gb.graph" <<G
scene "$PWD/examples/offscreen.scene"
size 40 30
g = gbuffer()
c = compare(g.depth, g.depth)
out = write(g.direct, "gb", depth=g.depth, normal=g.normal, position=g.position,
            albedo=g.albedo, environment=g.environment)
G
for backend in cpu gl; do
    for guard in 0 7; do
        "$BIN" run "$TMP/gb.graph" --backend $backend --guard $guard --out "$TMP/$backend$guard" \
            --quiet > "$TMP/log" 2>&1 || fail "$backend guard $guard: $(tail -3 "$TMP/log")"
    done
    for layer in :depth :normal :position :albedo :environment ""; do
        expect_exit 0 '"rmse":0,' "$BIN" compare "$TMP/${backend}7/gb.exr$layer" \
            "$TMP/${backend}0/gb.exr$layer" --json
    done
    grep -q '"pixels": 1200' "$TMP/${backend}7/metrics.json" ||
        fail "$backend: compare with a band should count the 40x30 frame: $(cat "$TMP/${backend}7/metrics.json")"
done
oiiotool --info "$TMP/cpu7/gb.exr" 2>/dev/null | grep -q '40 x  *30' ||
    fail "the EXR of a guarded run is not 40x30: $(oiiotool --info "$TMP/cpu7/gb.exr" 2>&1)"

# 2: edge=3 of a 40x30 frame counts 40*30 - 34*24 pixels.
"$BIN" run "$TMP/gb.graph" --guard 5 --set c.edge=3 --out "$TMP/edge" --quiet > "$TMP/log" 2>&1 ||
    fail "edge run: $(tail -3 "$TMP/log")"
grep -q '"pixels": 384' "$TMP/edge/metrics.json" ||
    fail "compare edge=3 should count 384 pixels: $(cat "$TMP/edge/metrics.json")"

# 3: graphs/guard_band.graph at a quarter of its size, band scaled alike (160 -> 40).
rmse_edge() {
    "$BIN" run graphs/guard_band.graph --size 160x120 --guard "$1" --set c_edge.edge=6 \
        --set h.falloff=none --set h.steps=8 --out "$TMP/band$1" --quiet > "$TMP/log" 2>&1 ||
        fail "guard_band --guard $1: $(tail -3 "$TMP/log")"
    python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['c_edge']['rmse'])" \
        "$TMP/band$1/metrics.json"
}
without=$(rmse_edge 0)
with=$(rmse_edge 40)
python3 -c "import sys; a, b = map(float, sys.argv[1:]); sys.exit(0 if b < 0.6 * a else 1)" \
    "$without" "$with" || fail "the band should cut the border's rmse by 40 %: $without -> $with"
echo "border rmse without band $without, with band $with"

# 4: bad input.
bad() { printf 'size 8 8\n%s\n' "$1" > "$TMP/bad.graph"; }
bad "guard 2 3";    expect_exit 1 'bad.graph:2:9: error: .guard. expects one number' "$BIN" check "$TMP/bad.graph"
bad "guard -1";     expect_exit 1 'bad.graph:2:7: .*expected 0 to 1024' "$BIN" check "$TMP/bad.graph"
bad "guard 1.5";    expect_exit 1 'bad.graph:2:7: .*expects an integer' "$BIN" check "$TMP/bad.graph"
bad "guard";        expect_exit 1 'bad.graph:2:1: .*expects an integer' "$BIN" check "$TMP/bad.graph"
printf 'size 16384 64\nguard 8\ng = gbuffer()\n' > "$TMP/big.graph"
expect_exit 1 'big.graph:2:7: .*guard band of 8 pixels is out of range' "$BIN" check "$TMP/big.graph"
expect_exit 2 '--guard expects' "$BIN" run "$TMP/gb.graph" --guard 5000
finish test_guard
