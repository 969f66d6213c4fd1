#!/usr/bin/env bash
# tools/obj2gltf.py, the converter of the bundled meshes: a tiny OBJ and a tiny 3D Studio
# file (written here) convert to glTF with the right vertex and triangle counts and load in
# a scene; a 3DS chunk that claims more bytes than its parent holds, and a face naming a
# vertex the mesh lacks, are refused with a message and exit 1.
set -u
source "$(dirname "$0")/lib.sh" "ssg_test_obj2gltf"
conv=tools/obj2gltf.py

printf 'v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n' > "$TMP/quad.obj"
expect_exit 0 "4 vertices, 2 triangles" python3 "$conv" "$TMP/quad.obj" "$TMP/quad.gltf"

# A 3DS file: main 0x4D4D > editor 0x3D3D > object 0x4000 "tri" > trimesh 0x4100 >
# vertices 0x4110 (3) and faces 0x4120 (1); `bad` breaks one thing each.
make_3ds() {
    python3 - "$1" "$2" <<'PY'
import struct, sys
path, bad = sys.argv[1], sys.argv[2]
def chunk(cid, body, extra=0):
    return struct.pack("<HI", cid, 6 + len(body) + extra) + body
verts = chunk(0x4110, struct.pack("<H9f", 3, 0, 0, 0, 1, 0, 0, 0, 1, 0))
face = (0, 1, 5) if bad == "face" else (0, 1, 2)
faces = chunk(0x4120, struct.pack("<H4H", 1, *face, 0))
mesh = chunk(0x4100, verts + faces, 100 if bad == "length" else 0)
obj = chunk(0x4000, b"tri\0" + mesh)
open(path, "wb").write(chunk(0x4D4D, chunk(0x3D3D, obj)))
PY
}
make_3ds "$TMP/tri.3ds" none
expect_exit 0 "3 vertices, 1 triangles" python3 "$conv" "$TMP/tri.3ds" "$TMP/tri.gltf"
printf 'mesh("%s/tri.gltf")\nmesh("%s/quad.gltf", translate=[0, 0, -2])\n' "$TMP" "$TMP" > "$TMP/t.scene"
expect_exit 0 "ok" "$BIN" check "$TMP/t.scene"

make_3ds "$TMP/long.3ds" length
expect_exit 1 "claims .* bytes, past its parent's end" python3 "$conv" "$TMP/long.3ds" "$TMP/x.gltf"
make_3ds "$TMP/face.3ds" face
expect_exit 1 "face 0 names vertex 5 of 3" python3 "$conv" "$TMP/face.3ds" "$TMP/y.gltf"
finish test_obj2gltf
