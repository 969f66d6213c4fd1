#!/usr/bin/env bash
# test_load_rules.sh - what loading a graph refuses or warns about, beyond syntax:
#  - `set` (a set line or --set) changes what a node's call defines and never adds to it
#    (`set out.in = x` on write used to add an EXR layer named `in`); `add` adds a layer;
#  - a node whose check failed is reported once: its readers add no follow-on errors;
#  - a scene with no light and no environment: an error where the graph reads gbuffer's
#    direct or environment light, a warning (exit 0) where it does not;
#  - a glTF camera whose yfov is out of range names the file when the scene is checked,
#    and one glTF forbids (yfov <= 0) is refused the same way, never dropped;
#  - `check` on an image or another binary file says what the file is and what check takes.
set -u
source "$(dirname "$0")/lib.sh" "test_load_rules"

# --- set never adds an input ---
cat > "$TMP/set_in.graph" <<EOF
include "$PWD/graphs/ssao.graph"
set out.in = ao.out
EOF
expect_exit 1 "set_in.graph:2:9: error: 'set' cannot add input 'in' to node 'out' \(write\).*expected an input: image.*ao, ao_raw" \
    "$BIN" check "$TMP/set_in.graph"
expect_exit 1 "<command line --set>.*'set' cannot add input 'nolayer'" \
    "$BIN" check graphs/ssao.graph --set out.nolayer=ao.out
# changing a layer the call defines is still a set
expect_exit 0 "ok" "$BIN" check graphs/ssao.graph --set out.ao_raw=b.out
# a new layer is an `add` line; adding a name that exists, or to a node without named
# inputs, is refused
cat > "$TMP/add.graph" <<EOF
include "$PWD/graphs/ssao.graph"
add out.extra = ao.out
EOF
expect_exit 0 "ok" "$BIN" check "$TMP/add.graph"
"$BIN" run "$TMP/add.graph" --size 16x12 --out "$TMP/add" --quiet || fail "add run failed"
oiiotool --info -v "$TMP/add/ssao.exr" 2> /dev/null | grep -q "extra\.Y" \
    || fail "the added layer is not in the EXR"
printf 'include "%s/graphs/ssao.graph"\nadd out.ao = ao.out\nadd ao.extra = g.depth\n' "$PWD" \
    > "$TMP/add_bad.graph"
out=$("$BIN" check "$TMP/add_bad.graph" 2>&1)
echo "$out" | grep -q "add_bad.graph:2:9: error: 'add' makes a new named input .*has that name already" \
    || fail "add of an existing layer: $out"
echo "$out" | grep -q "add_bad.graph:3:8: error: 'add' .*takes no named inputs" \
    || fail "add to a node without named inputs: $out"

# --- one mistake, one message ---
cat > "$TMP/cascade.graph" <<EOF
scene "$PWD/examples/cornell.scene"
size 32 24
g   = gbuffer()
k   = halton(count=8)
ao  = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)
b   = bilateral(k.samples, depth=g.depth, normal=g.normal)
img = combine(direct=g.direct, albedo=g.albedo, ambient_occlusion=b.out)
out = write(img.out, "c", ao=b.out)
EOF
out=$("$BIN" check "$TMP/cascade.graph" 2>&1)
[ $? -eq 1 ] || fail "a type mismatch did not fail check"
echo "$out" | grep -q "cascade.graph:6:17: error: input 'in' of node 'b' (bilateral) expects" \
    || fail "the type mismatch is not reported at its place: $out"
[ "$(echo "$out" | grep -c 'error:')" -eq 1 ] || fail "follow-on errors after the first: $out"

# --- a scene without light ---
cat > "$TMP/dark.scene" <<EOF
camera(position=[0, 1, 3.9], target=[0, 1, 0], up=[0, 1, 0], fov=40)
white = material(albedo=[0.73, 0.73, 0.73])
plane(material=white, center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])
box(material=white, center=[0, 0.3, 0], size=[0.6, 0.6, 0.6])
EOF
# ssao.graph reads g.direct (in combine and as a layer): black, so refused at the reference
expect_exit 1 "graphs/ssao.graph:[0-9]+:[0-9]+: error: 'g.direct' \(read by node '[a-z]+'\) is black: scene '.*dark.scene' has no light and no environment" \
    "$BIN" run graphs/ssao.graph --scene "$TMP/dark.scene" --size 32x24 --out "$TMP/dark"
[ -e "$TMP/dark/ssao.exr" ] && fail "a refused run wrote its output"
# the same scene with a sky is fine
expect_exit 0 "ok" "$BIN" check graphs/ssao.graph --scene "$TMP/dark.scene" \
    --lights examples/lights/sky.scene
# AO alone means something without light: a warning, exit 0, and the file
cat > "$TMP/ao_only.graph" <<EOF
scene "$TMP/dark.scene"
size 32 24
g  = gbuffer()
k  = halton(count=8)
ao = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)
out = write(ao.out, "ao")
EOF
expect_exit 0 "ao_only.graph:1:7: warning: scene '.*dark.scene' has no light and no environment" \
    "$BIN" run "$TMP/ao_only.graph" --out "$TMP/ao_only" --quiet
[ -s "$TMP/ao_only/ao.exr" ] || fail "a warned run wrote no output"
expect_exit 0 "warning: scene .* has no light" "$BIN" check "$TMP/ao_only.graph"

# --- a glTF camera with an absurd field of view names the file ---
sed 's/"yfov": 0.8/"yfov": 10/' tests/fixtures/gltf/triangle.gltf > "$TMP/wide.gltf"
cp tests/fixtures/gltf/*.bin "$TMP/" 2> /dev/null
cat > "$TMP/wide.scene" <<EOF
point_light(position=[0, 2, 2], color=[1, 1, 1], intensity=5)
mesh(file="wide.gltf")
EOF
expect_exit 1 "wide.gltf.*yfov 10.* rad .* is outside 1 to 179 degrees" "$BIN" check "$TMP/wide.scene"
sed 's/"yfov": 0.8/"yfov": 0/' tests/fixtures/gltf/triangle.gltf > "$TMP/wide.gltf"
expect_exit 1 "wide.scene:2:11: error: .*wide.gltf: camera 0: yfov 0 rad" "$BIN" check "$TMP/wide.scene"
expect_exit 1 "wide.gltf: error: camera 0: yfov 0 rad" "$BIN" check "$TMP/wide.gltf"

# --- check on an image or a binary file: what it is, and what check takes ---
expect_exit 1 "garbage.png: error: a PNG image, not a graph, a scene or a model: .*graph file.*\.scene file.*model \(\.gltf" \
    "$BIN" check tests/fixtures/garbage.png
expect_exit 1 "scanline.exr: error: an OpenEXR image, not a graph.*ssgraph layers FILE" \
    "$BIN" check tests/fixtures/images/scanline.exr
printf 'g = gbuffer()\0\n' > "$TMP/nul.graph"
expect_exit 1 "nul.graph: error: a binary file \(it holds NUL bytes\), not a graph" \
    "$BIN" check "$TMP/nul.graph"

finish test_load_rules
