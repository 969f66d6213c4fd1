#!/usr/bin/env bash
# Models from any format, through the command line (core/scene/model.h): `check` of a scene
# around an OBJ, a PLY, an STL and a glTF 1.0 file prints each mesh line's triangles, the
# bounds, the camera and the lights; a model in millimetres gets the scale hint and one in
# metres does not; an unknown format, a broken OBJ, a missing model, .mtl or texture and a
# Draco glTF each give the scene's file:line:column and the file's name, exit 1, and a run
# writes nothing; graphs/ssao.graph renders examples/cup.scene (an OBJ). Issue 28: a DAE
# nested 100,000 deep, a PLY header without end_header and one claiming 2e9 faces are
# refused at their line:column before Assimp sees them (no crash, no hang, no 15 GB);
# issue 42: a NaN or infinite vertex, normal or texture coordinate is refused;
# `check MODEL` prints the meshes, bounds, up axis and a scene that loads (a model without
# area too: a line, a point, says so and gets a floor of size 1 or more); a box standing
# Z-up as OBJ, FBX and 3DS gets the right up-axis advice for its reader (3DS arrives Y-up,
# and rotate=[-90, 0, 0] would lay it on its back), and `check FILE.scene` each mesh's box
# after its transform.
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

# --- hostile files (issue 28): refused at their line:column, never a crash or a hang ---
python3 - "$TMP" <<'PY'
import struct, sys
d = sys.argv[1]
n = 100000  # <COLLADA> is level 1, the 254th node level 257: line 5, column 253 * 6 + 1
open(f"{d}/deep.dae", "w").write('<?xml version="1.0"?>\n<COLLADA>\n<library_visual_scenes>\n'
    '<visual_scene id="s">\n' + "<node>" * n + "</node>" * n + "\n</visual_scene>\n"
    "</library_visual_scenes>\n</COLLADA>\n")
open(f"{d}/hang.ply", "w").write("ply\nformat ascii 1.0\n")
h = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
     b"property float y\nproperty float z\nelement face 2000000000\n"
     b"property list uchar int vertex_indices\nend_header\n")
open(f"{d}/bomb.ply", "wb").write(h + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + bytes([3])
                                  + struct.pack("<3i", 0, 1, 2))
# a box 1 x 2 x 3 standing on z = 0, Z-up, as OBJ, 3DS (3ds Max's own axes) and FBX
V = [(x, y, z) for z in (0, 3) for y in (0, 2) for x in (0, 1)]
Q = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
open(f"{d}/tall.obj", "w").write("".join("v %g %g %g\n" % v for v in V)
                                 + "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in Q))
def chunk(cid, body): return struct.pack("<HI", cid, 6 + len(body)) + body
F = [f for q in Q for f in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
mesh = chunk(0x4110, struct.pack("<H", 8) + b"".join(struct.pack("<3f", *v) for v in V))
mesh += chunk(0x4120, struct.pack("<H", 12) + b"".join(struct.pack("<4H", *f, 0) for f in F))
edit = chunk(0x3D3E, struct.pack("<I", 3)) + chunk(0x4000, b"tall\0" + chunk(0x4100, mesh))
open(f"{d}/tall.3ds", "wb").write(chunk(0x4D4D, chunk(0x0002, struct.pack("<I", 3))
                                        + chunk(0x3D3D, edit)))
idx = ",".join("%d,%d,%d,%d" % (a, b, c, -e - 1) for a, b, c, e in Q)
open(f"{d}/tall.fbx", "w").write(
    '; FBX 7.5.0 project file\nFBXHeaderExtension:  {\n FBXHeaderVersion: 1003\n FBXVersion: 7500\n}\n'
    'GlobalSettings:  {\n Version: 1000\n Properties70:  {\n  P: "UpAxis", "int", "Integer", "",2\n'
    '  P: "UpAxisSign", "int", "Integer", "",1\n }\n}\nObjects:  {\n Geometry: 1, "Geometry::box", "Mesh" {\n'
    '  Vertices: *24 {\n   a: ' + ",".join("%g" % c for v in V for c in v) + '\n  }\n'
    '  PolygonVertexIndex: *24 {\n   a: ' + idx + '\n  }\n  GeometryVersion: 124\n }\n'
    ' Model: 2, "Model::box", "Mesh" {\n  Version: 232\n }\n}\nConnections:  {\n C: "OO",2,0\n C: "OO",1,2\n}\n')
PY
expect_exit 1 "deep.dae:5:1519: error: " timeout 120 "$BIN" check "$TMP/deep.dae"
bad deep.dae "5:1519: XML"
expect_exit 1 "hang.ply: error: .*end_header" timeout 120 "$BIN" check "$TMP/hang.ply"
expect_exit 1 "bomb.ply:7:14: error: " timeout 120 "$BIN" check "$TMP/bomb.ply"

# --- check MODEL: meshes, bounds, the up axis, and a scene around it that loads ---
snippet() { # snippet MODEL NAME: check MODEL's scene, saved as NAME.scene beside it
    "$BIN" check "$TMP/$1" | sed -n '/^  a scene around it/,/^  and render/p' | grep '^    ' \
        | sed 's/^    //' > "$TMP/$2.scene"
}
expect_exit 0 "tall.3ds: ok" "$BIN" check "$TMP/tall.3ds"
expect_exit 0 "mesh 0: 12 triangles, bounds min \(0, 0, -2\) max \(1, 3, 0\)" \
    "$BIN" check "$TMP/tall.3ds"
# issue 46: a 3DS file does not record which way it was made (Debian's glmark2 cat.3ds,
# made Y-up, came out on its side while check called it "upright as loaded"): both ways are
# said, the other as commented lines that load, and a camera frames the model
expect_exit 0 "up: \+Y, from Assimp's 3DS reader.*upright as loaded if the file was made that way;" \
    "$BIN" check "$TMP/tall.3ds"
expect_exit 0 "but the file does not record which way it was made: .* comes out -Z up, lying on its side" \
    "$BIN" check "$TMP/tall.3ds"
expect_exit 0 "and rotate=\[90, 0, 0\] stands it up" "$BIN" check "$TMP/tall.3ds"
snippet tall.3ds pasted3ds
grep -q '^mesh("tall.3ds")$' "$TMP/pasted3ds.scene" || fail "3DS snippet: $(cat "$TMP/pasted3ds.scene")"
grep -q '^# mesh("tall.3ds", rotate=\[90, 0, 0\])$' "$TMP/pasted3ds.scene" \
    || fail "3DS snippet without the other way up: $(cat "$TMP/pasted3ds.scene")"
grep -Eq '^camera\(position=\[[-0-9.e]+, [-0-9.e]+, [-0-9.e]+\], target=\[0.5, 1.5, -1\], near=' \
    "$TMP/pasted3ds.scene" || fail "3DS snippet: no camera at the model's middle: $(cat "$TMP/pasted3ds.scene")"
expect_exit 0 "pasted3ds.scene: ok" "$BIN" check "$TMP/pasted3ds.scene"
# the commented lines in place of the first two
sed -e '1,2s/^/# /' -e '/^# lying/,+2s/^# \(mesh\|plane\)/\1/' "$TMP/pasted3ds.scene" > "$TMP/other3ds.scene"
grep -q '^mesh("tall.3ds", rotate=\[90, 0, 0\])$' "$TMP/other3ds.scene" \
    || fail "the other way up did not uncomment: $(cat "$TMP/other3ds.scene")"
expect_exit 0 "other3ds.scene: ok" "$BIN" check "$TMP/other3ds.scene"
expect_exit 0 "up: unknown \(nothing: OBJ files do not say.*1 x 2 x 3, largest along Z: looks Z-up, try rotate=\[-90, 0, 0\]" \
    "$BIN" check "$TMP/tall.obj"
snippet tall.obj pastedobj
grep -q '^mesh("tall.obj", rotate=\[-90, 0, 0\])$' "$TMP/pastedobj.scene" \
    || fail "OBJ snippet: $(cat "$TMP/pastedobj.scene")"
expect_exit 0 "plane\(center=\[0.5, 0, -1\], size=\[6, 0, 6\]\)" "cat" "$TMP/pastedobj.scene"
expect_exit 0 "largest along Y, the renderer's up" "$BIN" check "$TMP/pastedobj.scene"
expect_exit 0 "up: \+Z, from the file's UpAxis metadata.*FBX reader: rotate=\[-90, 0, 0\] on the mesh line stands it up" \
    "$BIN" check "$TMP/tall.fbx"

# --- a model without area (its triangles on a line, or all at one point; standing on end
#     after the suggested rotate, or far from the origin) is said to have none, and the
#     scene suggested around it still loads: the floor is sized from the largest extent,
#     at least 1 (size=[0, 0, 0] was refused by the scene reader) ---
printf 'v 0 0 0\nv 0 1 0\nv 0 2 0\nf 1 2 3\n' > "$TMP/line.obj"
printf 'v 0 0 0\nv 0 0 1\nv 0 0 2\nf 1 2 3\n' > "$TMP/zline.obj"
printf 'v 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\n' > "$TMP/point.obj"
printf 'v 3e7 0 -3e7\nv 3e7 0 -3e7\nv 3e7 0 -3e7\nf 1 2 3\n' > "$TMP/farpoint.obj"
for m in line zline point farpoint; do
    expect_exit 0 "no area: every triangle's corners lie on one line or at one point" \
        "$BIN" check "$TMP/$m.obj"
    snippet $m.obj pasted$m
    grep -q "^plane(center=" "$TMP/pasted$m.scene" \
        || fail "$m snippet: $(cat "$TMP/pasted$m.scene")"
    expect_exit 0 "pasted$m.scene: ok" "$BIN" check "$TMP/pasted$m.scene"
done
expect_exit 0 "plane\(center=\[0, 0, 0\], size=\[6, 0, 6\]\)" "cat" "$TMP/pastedline.scene"
expect_exit 0 "plane\(center=\[1, 2, 3\], size=\[1, 0, 1\]\)" "cat" "$TMP/pastedpoint.scene"
"$BIN" check "$TMP/tall.obj" | grep -q "no area" && fail "check of a box said it has no area"

# --- issue 42: NaN or infinity in a vertex (position, normal or texture coordinate) is
#     refused by check MODEL, naming the mesh and vertex, and no scene is suggested; a scene
#     and a run refuse it at the mesh line ---
printf 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n' > "$TMP/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn inf 0 1\nf 1//1 2//2 3//1\n' > "$TMP/infn.obj"
# (Assimp's OBJ reader reads `vt nan 0` as 0 0 itself; its PLY reader keeps the NaN)
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float s\nproperty float t\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 0 0\n1 0 0 nan 0\n0 1 0 0 1\n3 0 1 2\n' \
    > "$TMP/nanuv.ply"
expect_exit 1 "nan.obj: error: mesh 0.* vertex 1: its position is \(nan, 0, 0\) \(expected finite" \
    "$BIN" check "$TMP/nan.obj"
"$BIN" check "$TMP/nan.obj" 2>&1 | grep -Eq ": ok|scene around|mesh\(" \
    && fail "check of a NaN vertex said ok or suggested a scene: $("$BIN" check "$TMP/nan.obj" 2>&1)"
expect_exit 1 "infn.obj: error: mesh 0.* vertex 1: its normal is \(inf, 0, 1\)" \
    "$BIN" check "$TMP/infn.obj"
expect_exit 1 "nanuv.ply: error: mesh 0 vertex 1: its texture coordinate is \(nan, 0\)" \
    "$BIN" check "$TMP/nanuv.ply"
bad nan.obj "vertex 1: its position is \(nan, 0, 0\)"

# --- check FILE.scene: each mesh's box after its transform, the up axis per reader ---
z='(-?[0-9.]+e-0[6-9]|-?0)' # a quarter turn in floats leaves 0 as about 1e-7
scene zobj tall.obj ", rotate=[-90, 0, 0]"
expect_exit 0 "mesh 0: 12 triangles, bounds min \(0, $z, -2\) max \(1, 3, $z\)" \
    "$BIN" check "$TMP/zobj.scene"
expect_exit 0 "box is 1 x 3 x 2, largest along Y" "$BIN" check "$TMP/zobj.scene"
scene z3ds tall.3ds
expect_exit 0 "stands it up \(render it and look\); after the mesh line's transform, its box is .*largest along Y" \
    "$BIN" check "$TMP/z3ds.scene"
scene z3dsturned tall.3ds ", rotate=[-90, 0, 0]" # the old advice: on its back
expect_exit 0 "mesh 0: 12 triangles, bounds min \(0, -2, -3\) max \(1, $z, $z\)" \
    "$BIN" check "$TMP/z3dsturned.scene"
expect_exit 0 "stands it up \(render it and look\); .*its box is largest along Z" "$BIN" check "$TMP/z3dsturned.scene"
scene zfbx tall.fbx ", rotate=[-90, 0, 0]"
expect_exit 0 "bounds: min \(0, $z, -2\) max \(1, 3, $z\)" "$BIN" check "$TMP/zfbx.scene"

# --- the bundled OBJ example renders with the default AO graph ---
rm -rf "$TMP/cup"
"$BIN" run graphs/ssao.graph --scene examples/cup.scene --size 64x48 --out "$TMP/cup" --quiet \
    > "$TMP/cup.log" 2>&1 || fail "ssao.graph on examples/cup.scene: $(tail -3 "$TMP/cup.log")"
[ -s "$TMP/cup/ssao.exr" ] || fail "ssao.graph on examples/cup.scene wrote no ssao.exr"
finish test_models
