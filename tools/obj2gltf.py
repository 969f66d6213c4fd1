#!/usr/bin/env python3
"""obj2gltf.py - converts a Wavefront OBJ or a 3D Studio (.3ds) triangle mesh into glTF 2.0
(a .gltf JSON file plus a binary .bin buffer next to it), using the Python standard library
only.

Only geometry is converted: positions, smooth per-vertex normals and triangle indices
(polygons are split into fans). Texture coordinates, OBJ normals, groups and materials are
ignored: normals are recomputed as the area-weighted average of the faces around each
position, so a vertex shared by several faces gets one smooth normal, as a scanned mesh
such as the Stanford bunny wants.

A .3ds file's objects (their triangle meshes: vertex list 0x4110 and face list 0x4120) are
merged into one mesh, coordinates as they are (3D Studio files differ in which axis is up: a
scene's mesh(rotate=...) turns the model upright); smoothing groups, materials and texture
coordinates are ignored as for OBJ.

Usage: tools/obj2gltf.py INPUT.obj|INPUT.3ds OUTPUT.gltf
The buffer is written as OUTPUT.bin and referenced by a relative URI.
"""

import json
import math
import os
import struct
import sys
from array import array


def parse_index(token, count, line_no):
    """One face corner 'v', 'v/t', 'v//n' or 'v/t/n' -> 0-based position index."""
    index = int(token.split("/")[0])
    if index < 0:
        index += count
    else:
        index -= 1
    if not 0 <= index < count:
        raise ValueError(f"line {line_no}: vertex index {token} out of range")
    return index


def read_obj(path):
    """Returns (positions as a flat list of floats, indices as a flat list of ints)."""
    positions, indices = [], []
    with open(path, encoding="ascii", errors="replace") as f:
        for line_no, line in enumerate(f, 1):
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                positions.extend(float(x) for x in parts[1:4])
            elif parts[0] == "f":
                count = len(positions) // 3
                corners = [parse_index(t, count, line_no) for t in parts[1:]]
                if len(corners) < 3:
                    raise ValueError(f"line {line_no}: face with fewer than 3 corners")
                for i in range(1, len(corners) - 1):
                    indices.extend((corners[0], corners[i], corners[i + 1]))
    if not indices:
        raise ValueError("no faces")
    return positions, indices


def read_chunks(data, start, end):
    """The 3DS chunks in data[start:end]: (id, body start, chunk end) each."""
    at = start
    while at + 6 <= end:
        cid, length = struct.unpack_from("<HI", data, at)
        if length < 6 or at + length > end:
            raise ValueError(f"chunk 0x{cid:04x} at byte {at} claims {length} bytes, "
                             f"past its parent's end {end}")
        yield cid, at + 6, at + length
        at += length


def read_trimesh(data, start, end, positions, indices):
    """Appends one 3DS triangle mesh (chunk 0x4100) to positions and indices."""
    base = len(positions) // 3
    count = 0
    for cid, body, stop in read_chunks(data, start, end):
        if cid == 0x4110:  # vertex list: u16 count, count x 3 float32
            (count,) = struct.unpack_from("<H", data, body)
            xyz = struct.unpack_from(f"<{3 * count}f", data, body + 2)
            for i in range(count):
                x, y, z = xyz[3 * i:3 * i + 3]
                positions.extend((x, y, z))
        elif cid == 0x4120:  # face list: u16 count, count x (a, b, c, flags) u16
            (faces,) = struct.unpack_from("<H", data, body)
            abcf = struct.unpack_from(f"<{4 * faces}H", data, body + 2)
            for i in range(faces):
                a, b, c = abcf[4 * i:4 * i + 3]
                if max(a, b, c) >= count:
                    raise ValueError(f"face {i} names vertex {max(a, b, c)} of {count}")
                indices.extend((base + a, base + b, base + c))


def read_3ds(path):
    """Returns (positions, indices) of every triangle mesh of a 3D Studio file, merged."""
    with open(path, "rb") as f:
        data = f.read()
    positions, indices = [], []
    for cid, body, stop in read_chunks(data, 0, len(data)):
        if cid != 0x4D4D:
            continue
        for eid, ebody, estop in read_chunks(data, body, stop):
            if eid != 0x3D3D:
                continue
            for oid, obody, ostop in read_chunks(data, ebody, estop):
                if oid != 0x4000:
                    continue
                name_end = data.index(b"\0", obody, ostop) + 1
                for mid, mbody, mstop in read_chunks(data, name_end, ostop):
                    if mid == 0x4100:
                        read_trimesh(data, mbody, mstop, positions, indices)
    if not indices:
        raise ValueError("no triangle mesh (chunk 0x4100) in the file")
    return positions, indices


def smooth_normals(positions, indices):
    """Area-weighted vertex normals: the unnormalised cross product of each face's edges
    has a length of twice its area, so summing them weights faces by area."""
    normals = [0.0] * len(positions)
    p = positions
    for t in range(0, len(indices), 3):
        a, b, c = (3 * i for i in indices[t:t + 3])
        e1 = (p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2])
        e2 = (p[c] - p[a], p[c + 1] - p[a + 1], p[c + 2] - p[a + 2])
        n = (e1[1] * e2[2] - e1[2] * e2[1],
             e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0])
        for v in (a, b, c):
            normals[v] += n[0]
            normals[v + 1] += n[1]
            normals[v + 2] += n[2]
    for v in range(0, len(normals), 3):
        length = math.sqrt(normals[v] ** 2 + normals[v + 1] ** 2 + normals[v + 2] ** 2)
        if length > 0.0:
            normals[v] /= length
            normals[v + 1] /= length
            normals[v + 2] /= length
        else:  # an unused or degenerate vertex still needs a unit normal
            normals[v:v + 3] = [0.0, 1.0, 0.0]
    return normals


def little_endian(values, typecode):
    data = array(typecode, values)
    if sys.byteorder != "little":
        data.byteswap()
    return data.tobytes()


def build_gltf(positions, normals, indices, bin_name, bin_size):
    count = len(positions) // 3
    lo = [min(positions[i::3]) for i in range(3)]
    hi = [max(positions[i::3]) for i in range(3)]
    vec_bytes = count * 12
    return {
        "asset": {"version": "2.0", "generator": "ssgraph tools/obj2gltf.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1},
            "indices": 2,
            "mode": 4,
        }]}],
        "buffers": [{"uri": bin_name, "byteLength": bin_size}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": vec_bytes, "target": 34962},
            {"buffer": 0, "byteOffset": vec_bytes, "byteLength": vec_bytes, "target": 34962},
            {"buffer": 0, "byteOffset": 2 * vec_bytes, "byteLength": len(indices) * 4,
             "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
        ],
    }


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    src, dst = argv[1], argv[2]
    try:
        read = read_3ds if src.lower().endswith(".3ds") else read_obj
        positions, indices = read(src)
    except (OSError, ValueError, struct.error) as err:
        sys.stderr.write(f"obj2gltf: {src}: {err}\n")
        return 1
    normals = smooth_normals(positions, indices)
    blob = (little_endian(positions, "f") + little_endian(normals, "f")
            + little_endian(indices, "I"))
    bin_path = os.path.splitext(dst)[0] + ".bin"
    gltf = build_gltf(positions, normals, indices, os.path.basename(bin_path), len(blob))
    with open(bin_path, "wb") as f:
        f.write(blob)
    with open(dst, "w", encoding="ascii") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")
    print(f"{dst}: {len(positions) // 3} vertices, {len(indices) // 3} triangles, "
          f"{len(blob)} bytes of buffer")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
