#!/usr/bin/env bash
# Models from any format, through the command line (core/scene/model.h): `check` of a scene
# around an OBJ, a PLY, an STL and a glTF 1.0 file prints each mesh line's triangles, the
# bounds, the camera and the lights; a model in millimetres gets the scale hint and one in
# metres does not; an unknown format, a broken OBJ, a missing model, .mtl or texture and a
# Draco glTF each give the scene's file:line:column and the file's name, exit 1, and a run
# writes nothing; graphs/ssao.graph renders examples/cup.scene (an OBJ).
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_models"

# --- fixtures: a box as PLY, two triangles as STL, a quad and a pentagon as OBJ, a
#     triangle as glTF 1.0 (named dictionaries, an embedded base64 buffer) ---
python3 - "$TMP" <<'PY'
import base64, json, struct, sys
d = sys.argv[1]
open(f"{d}/box.ply", "w").write(
    "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
    "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 2 0\n0 2 0\n0 0 3\n1 0 3\n1 2 3\n0 2 3\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n")
facet = "facet normal 0 1 0\nouter loop\n%sendloop\nendfacet\n"
vtx = lambda *p: "".join("vertex %g %g %g\n" % q for q in p)
open(f"{d}/two.stl", "w").write("solid two\n" + facet % vtx((-1, 0, -2), (1, 0, 2), (1, 0, -2))
                                + facet % vtx((-1, 0, -2), (-1, 0, 2), (1, 0, 2)) + "endsolid two\n")
open(f"{d}/two.obj", "w").write("mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "v 1 0 1\nv 2 0 1\nv 2 0.5 1\nv 1.5 1 1\nv 1 0.5 1\nusemtl blue\nf 1 2 3 4\nf 5 6 7 8 9\n")
open(f"{d}/two.mtl", "w").write("newmtl blue\nKd 0.2 0.4 0.6\n")
data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2)
uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
gltf1 = {
    "asset": {"version": "1.0"}, "scene": "s", "scenes": {"s": {"nodes": ["n"]}},
    "nodes": {"n": {"meshes": ["m"], "translation": [0, 0, -1]}},
    "meshes": {"m": {"primitives": [{"attributes": {"POSITION": "p"}, "indices": "i",
                                     "mode": 4, "material": "red"}]}},
    "materials": {"red": {"values": {"diffuse": [0.8, 0.1, 0.1, 1]}}},
    "accessors": {
        "p": {"bufferView": "vp", "byteOffset": 0, "byteStride": 12, "componentType": 5126,
              "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
        "i": {"bufferView": "vi", "byteOffset": 0, "byteStride": 0, "componentType": 5123,
              "count": 3, "type": "SCALAR"}},
    "bufferViews": {"vp": {"buffer": "b", "byteOffset": 0, "byteLength": 36, "target": 34962},
                    "vi": {"buffer": "b", "byteOffset": 36, "byteLength": 6, "target": 34963}},
    "buffers": {"b": {"uri": uri, "byteLength": len(data), "type": "arraybuffer"}},
}
json.dump(gltf1, open(f"{d}/tri1.gltf", "w"))
PY
scene() { # scene NAME MODEL [mesh arguments]: a camera, a floor-less scene of one mesh line
    printf 'camera(position=[0, 1, 9], target=[0, 0, 0])\npoint_light(position=[0, 5, 5])\nmesh("%s"%s)\n' \
        "$2" "${3:-}" > "$TMP/$1.scene"
}
scene obj two.obj
expect_exit 0 "mesh \"two.obj\": 5 triangles in 1 mesh" "$BIN" check "$TMP/obj.scene"
expect_exit 0 "bounds: min \(0, 0, 0\) max \(2, 1, 1\)" "$BIN" check "$TMP/obj.scene"
expect_exit 0 "obj.scene:3:6: mesh" "$BIN" check "$TMP/obj.scene"
expect_exit 0 "camera: position \(0, 1, 9\) target \(0, 0, 0\) fov 45 degrees" \
    "$BIN" check "$TMP/obj.scene"
expect_exit 0 "point_light position \(0, 5, 5\) color \(1, 1, 1\) intensity 1" \
    "$BIN" check "$TMP/obj.scene"
scene ply box.ply ", translate=[10, 0, 0]"
expect_exit 0 "triangles: 12" "$BIN" check "$TMP/ply.scene"
expect_exit 0 "bounds: min \(10, 0, 0\) max \(11, 2, 3\)" "$BIN" check "$TMP/ply.scene"
scene stl two.stl ", scale=2"
expect_exit 0 "triangles: 2" "$BIN" check "$TMP/stl.scene"
expect_exit 0 "bounds: min \(-2, 0, -4\) max \(2, 0, 4\)" "$BIN" check "$TMP/stl.scene"
scene gltf1 tri1.gltf
expect_exit 0 "mesh \"tri1.gltf\": 1 triangles" "$BIN" check "$TMP/gltf1.scene"
expect_exit 0 "bounds: min \(0, 0, -1\) max \(1, 1, -1\)" "$BIN" check "$TMP/gltf1.scene"

# --- the scale hint: millimetres (a 2 x 4 x 6 m box written in mm) get it, metres not ---
scene mm box.ply ", scale=1000"
expect_exit 0 "note: the models' bounding-box diagonal is .* times the AO radius 0.5.*scale=0.001.*mm.scene:3" \
    "$BIN" check "$TMP/mm.scene"
"$BIN" check "$TMP/ply.scene" | grep -q "note:" && fail "a scene in metres got the scale hint"
# the bundled scenes are in metres with floors many radii wide: none gets the hint
for f in examples/*.scene docs/tutorial/*.scene; do
    "$BIN" check "$f" | grep -q "note:" && fail "$f got the scale hint"
done

# --- bad models: file:line:column of the mesh line, the file named, exit 1, nothing written ---
printf 'solid\n' > "$TMP/model.xyz"
printf 'v 0 0 0\nv 1 0 0\nf 1 2 7\n' > "$TMP/broken.obj"
printf 'mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$TMP/nomtl.obj"
printf 'newmtl t\nKd 1 1 1\nmap_Kd gone.png\n' > "$TMP/tex.mtl"
printf 'mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl t\nf 1/1 2/2 3/3\n' \
    > "$TMP/tex.obj"
printf '{"asset":{"version":"2.0"},"extensionsRequired":["KHR_draco_mesh_compression"],"meshes":[]}' \
    > "$TMP/draco.gltf"
bad() { # bad MODEL PATTERN: check and run both refuse it at 3:6, and the run writes nothing
    scene bad "$1"
    expect_exit 1 "bad.scene:3:6: error: .*$1.*$2" "$BIN" check "$TMP/bad.scene"
    rm -rf "$TMP/out"
    expect_exit 1 "bad.scene:3:6: error: .*$1.*$2" \
        "$BIN" run graphs/ssao.graph --scene "$TMP/bad.scene" --size 32x24 --out "$TMP/out"
    [ -z "$(ls -A "$TMP/out" 2>/dev/null)" ] || fail "$1: the failed run wrote $(ls "$TMP/out")"
}
bad model.xyz "unsupported model format '.xyz'"
bad broken.obj "OBJ"
bad missing.obj "No such file"
bad nomtl.obj "gone.mtl"
bad tex.obj "texture 'gone.png'"
bad draco.gltf "Draco"

# --- the bundled OBJ example renders with the default AO graph ---
rm -rf "$TMP/cup"
"$BIN" run graphs/ssao.graph --scene examples/cup.scene --size 64x48 --out "$TMP/cup" --quiet \
    > "$TMP/cup.log" 2>&1 || fail "ssao.graph on examples/cup.scene: $(tail -3 "$TMP/cup.log")"
[ -s "$TMP/cup/ssao.exr" ] || fail "ssao.graph on examples/cup.scene wrote no ssao.exr"
finish test_models
