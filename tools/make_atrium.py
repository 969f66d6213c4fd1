#!/usr/bin/env python3
"""make_atrium.py - writes examples/atrium/: a courtyard under an open sky, made entirely by
this script (geometry, textures, lights), dedicated to the public domain (CC0 1.0).

    python3 tools/make_atrium.py [OUT_DIR]        (default: examples/atrium)

What it holds, each feature a screen-space method (and ssgraph's readers) must get right:
  - an arcade of 24 fluted columns with moulded bases and capitals, semicircular arches,
    a vaulted walk behind them and a wall above: deep concave corners and thin convex edges;
  - a paved floor with a tangent-space normal map (the paving's joints and worn stones);
  - four trees of alpha-masked leaf cards (glTF alphaMode MASK), in square planters;
  - six banners of cloth hung in the arches, draped, with a cut-out pattern and a fringe
    (alpha-masked, double-sided);
  - twelve lanterns whose glass emits (emissiveFactor x KHR_materials_emissive_strength);
  - four spot lights in the file (KHR_lights_punctual) aimed at the trees and the fountain;
  - a fountain turned on a lathe in the middle.
About 270,000 triangles. Same bytes on every run (no randomness without a fixed seed). The
sun and the sky are the scene file's (examples/atrium.scene), not the model's.
"""
import json
import math
import os
import struct
import sys

import numpy as np
from PIL import Image

RNG = np.random.default_rng(45)


# ---- meshes: (positions, normals, uvs, indices) as numpy arrays --------------------------

def grid(nu, nv, fn):
    """A (nu+1) x (nv+1) vertex grid: fn(u, v) -> (positions, normals) over u, v in [0, 1];
    uvs are (u, v); two triangles a cell, counter-clockwise seen from the normal."""
    u, v = np.meshgrid(np.linspace(0, 1, nu + 1), np.linspace(0, 1, nv + 1), indexing="xy")
    p, n = fn(u.ravel(), v.ravel())
    uv = np.stack([u.ravel(), v.ravel()], 1)
    i = np.arange((nu + 1) * (nv + 1)).reshape(nv + 1, nu + 1)
    a, b, c, d = i[:-1, :-1], i[:-1, 1:], i[1:, 1:], i[1:, :-1]
    tris = np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], 2).reshape(-1, 3)
    return [p, n, uv, tris]


def unit(v):
    return v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12)


def lathe(profile, segments, u_scale=1.0):
    """Turns a profile [(r, y), ...] (bottom to top) about +y: normals from the profile's
    tangent, uvs (angle, arc length)."""
    pr = np.asarray(profile, float)
    seg = np.diff(pr, axis=0)
    arc = np.concatenate([[0], np.cumsum(np.hypot(seg[:, 0], seg[:, 1]))])
    tang = np.gradient(pr, axis=0)
    prof_n = unit(np.stack([tang[:, 1], -tang[:, 0]], 1))  # outwards for a rising profile

    def fn(u, v):
        k = np.rint(v * (len(pr) - 1)).astype(int)
        a = u * 2 * math.pi
        r, y = pr[k, 0], pr[k, 1]
        p = np.stack([r * np.cos(a), y, -r * np.sin(a)], 1)
        n = np.stack([prof_n[k, 0] * np.cos(a), prof_n[k, 1], -prof_n[k, 0] * np.sin(a)], 1)
        return p, unit(n)
    m = grid(segments, len(pr) - 1, fn)
    m[2] = np.stack([m[2][:, 0] * u_scale, arc[np.rint(m[2][:, 1] * (len(pr) - 1)).astype(int)]], 1)
    return m


def box(lo, hi):
    """An axis-aligned box, 12 triangles, outward normals, uvs in metres."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    parts = []
    for axis in range(3):
        for side in (0, 1):
            a, b = (axis + 1) % 3, (axis + 2) % 3
            n = np.zeros(3)
            n[axis] = 1 if side else -1
            q = np.zeros((4, 3))
            q[:, axis] = hi[axis] if side else lo[axis]
            q[:, a] = [lo[a], hi[a], hi[a], lo[a]]
            q[:, b] = [lo[b], lo[b], hi[b], hi[b]]
            t = np.array([[0, 1, 2], [0, 2, 3]])
            if np.dot(np.cross(q[1] - q[0], q[2] - q[0]), n) < 0:
                t = t[:, ::-1]
            parts.append([q, np.tile(n, (4, 1)), np.stack([q[:, a], q[:, b]], 1), t])
    return merge(parts)


def merge(parts):
    p, n, uv, t, base = [], [], [], [], 0
    for q in parts:
        p.append(q[0]), n.append(q[1]), uv.append(q[2]), t.append(q[3] + base)
        base += len(q[0])
    return [np.concatenate(p), np.concatenate(n), np.concatenate(uv), np.concatenate(t)]


def moved(m, rot_y=0.0, at=(0, 0, 0), scale=1.0):
    c, s = math.cos(rot_y), math.sin(rot_y)
    r = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return [m[0] * scale @ r.T + np.asarray(at, float), m[1] @ r.T, m[2], m[3]]


# ---- the parts of the courtyard ----------------------------------------------------------

HALF = 6.0        # the columns stand on the square x, z = +-HALF
BAY = 2.0         # column spacing
SPRING = 3.0      # where the arches spring
WALK = 2.5        # depth of the walk behind the arcade
TOP = 4.6         # the arcade's roof line


def column():
    """A fluted shaft with a moulded base and capital, one lathe."""
    prof = [(0.32, 0.0), (0.32, 0.12), (0.28, 0.16), (0.27, 0.22), (0.24, 0.26)]
    prof += [(0.22, 0.3 + 2.4 * k / 40) for k in range(41)]
    prof += [(0.235, 2.74), (0.26, 2.8), (0.30, 2.86), (0.34, 2.9), (0.34, SPRING)]
    m = lathe(prof, 64, u_scale=3.0)
    # 16 flutes on the shaft: the radius dips where cos(16 a) is high
    a = np.arctan2(-m[0][:, 2], m[0][:, 0])
    on_shaft = (m[0][:, 1] > 0.32) & (m[0][:, 1] < 2.68)
    dip = 1 - 0.05 * np.clip(np.cos(16 * a), 0, None) ** 2 * on_shaft
    m[0][:, 0] *= dip
    m[0][:, 2] *= dip
    tilt = 0.05 * 2 * 16 * np.clip(np.cos(16 * a), 0, None) * np.sin(16 * a) * on_shaft
    tang = np.stack([-np.sin(a), np.zeros_like(a), -np.cos(a)], 1)
    m[1] = unit(m[1] + tilt[:, None] * tang)
    return m


def arch_band(span, depth, width, segments=48):
    """A semicircular arch's soffit and faces between two columns (local x across the bay,
    z across the arcade), springing at SPRING."""
    r0 = span / 2 - width / 2
    def soffit(u, v):
        a = math.pi * (1 - u)
        p = np.stack([r0 * np.cos(a), SPRING + r0 * np.sin(a), (v - 0.5) * depth], 1)
        n = -np.stack([np.cos(a), np.sin(a), 0 * a], 1)
        return p, n
    return grid(segments, 4, soffit)


def spandrel(span, z, facing, segments=48):
    """The wall above an arch, from its curve up to TOP, on the plane at z."""
    r0 = span / 2 - 0.125
    def fn(u, v):
        a = math.pi * (1 - u)
        x0, y0 = r0 * np.cos(a), SPRING + r0 * np.sin(a)
        x1 = np.clip(x0 * 1.12, -span / 2, span / 2)
        p = np.stack([x0 + (x1 - x0) * v, y0 + (TOP - y0) * v, np.full_like(u, z)], 1)
        return p, np.tile([0, 0, facing], (len(u), 1))
    m = grid(segments, 2, fn)
    if facing < 0:
        m[3] = m[3][:, ::-1]
    m[2] = m[0][:, :2].copy()
    return m


def side_of_arcade(rot):
    """One side: 6 bays of arches and spandrels, the walk's ceiling, floor and back wall,
    built along z = 0 (the courtyard towards +z), then moved out to z = -HALF and turned."""
    parts = []
    for k in range(6):
        x = -HALF + BAY * (k + 0.5)
        for m in (arch_band(BAY, 0.5, 0.25), spandrel(BAY, 0.25, 1), spandrel(BAY, -0.25, -1)):
            parts.append(moved(m, at=(x, 0, 0)))
    parts.append(box((-HALF, TOP, -0.25 - WALK), (HALF, TOP + 0.15, 0.25)))  # roof slab
    parts.append(box((-HALF - WALK, 0, -0.25 - WALK - 0.3), (HALF + WALK, 7.0, -0.25 - WALK)))
    parts.append(box((-HALF, TOP + 0.15, -0.2), (HALF, 7.0, 0.2)))           # upper wall
    parts.append(box((-HALF - WALK, -0.1, -0.25 - WALK), (HALF + WALK, 0.0, -0.25)))
    return moved(moved(merge(parts), at=(0, 0, -HALF)), rot_y=rot)


def fountain():
    prof = [(0.0, 0.0), (1.6, 0.0), (1.6, 0.45), (1.45, 0.5), (1.4, 0.2), (0.35, 0.2),
            (0.3, 0.9), (0.25, 1.2), (0.6, 1.3), (0.7, 1.4), (0.62, 1.45), (0.2, 1.5),
            (0.15, 2.0), (0.3, 2.1), (0.05, 2.3), (0.0, 2.31)]
    dense = []
    for a, b in zip(prof[:-1], prof[1:]):
        for t in np.linspace(0, 1, 8, endpoint=False):
            dense.append((a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t))
    dense.append(prof[-1])
    return lathe(dense, 128, u_scale=4.0)


def tree(seed):
    """A trunk and a crown of leaf cards (two triangles each, facing every way)."""
    rng = np.random.default_rng(seed)
    trunk = lathe([(0.16, 0.0), (0.12, 1.0), (0.09, 2.2), (0.04, 3.4)], 24)
    cards = 4000
    c = rng.normal(size=(cards, 3)) * [0.95, 0.5, 0.95] + [0, 3.3, 0]
    normal = unit(rng.normal(size=(cards, 3)) + [0, 0.6, 0])
    side = unit(np.cross(normal, rng.normal(size=(cards, 3))))
    up = np.cross(normal, side)
    s = 0.1
    corners = np.stack([c - s * side - s * up, c + s * side - s * up,
                        c + s * side + s * up, c - s * side + s * up], 1).reshape(-1, 3)
    uv = np.tile([[0, 1], [1, 1], [1, 0], [0, 0]], (cards, 1)).astype(float)
    t = (np.arange(cards)[:, None, None] * 4 + np.array([[0, 1, 2], [0, 2, 3]])).reshape(-1, 3)
    leaves = [corners, np.repeat(normal, 4, 0), uv, t]
    return trunk, leaves


def banner(width, height, seed):
    """A cloth hung from a rod: sags between its ends and ripples a little."""
    rng = np.random.default_rng(seed)
    phase = rng.uniform(0, 2 * math.pi)
    def fn(u, v):
        x = (u - 0.5) * width
        y = -v * height
        z = 0.06 * np.sin(6 * math.pi * u + phase) * (0.3 + v) + 0.1 * v * v
        p = np.stack([x, y, z], 1)
        du = np.stack([np.full_like(u, width), 0 * u,
                       0.06 * 6 * math.pi * np.cos(6 * math.pi * u + phase) * (0.3 + v)], 1)
        dv = np.stack([0 * u, np.full_like(u, -height),
                       0.06 * np.sin(6 * math.pi * u + phase) + 0.2 * v], 1)
        return p, unit(np.cross(du, dv))
    return grid(32, 64, fn)


def lantern():
    glass = lathe([(0.0, -0.18), (0.08, -0.16), (0.12, -0.05), (0.11, 0.08), (0.05, 0.16),
                   (0.0, 0.17)], 32)
    cap = lathe([(0.0, 0.16), (0.14, 0.18), (0.1, 0.24), (0.0, 0.26)], 32)
    chain = box((-0.01, 0.26, -0.01), (0.01, 0.9, 0.01))
    return glass, merge([cap, chain])


# ---- textures ------------------------------------------------------------------------------

def value_noise(size, cells, seed):
    rng = np.random.default_rng(seed)
    g = rng.random((cells + 1, cells + 1))
    g[-1, :], g[:, -1] = g[0, :], g[:, 0]
    t = np.linspace(0, cells, size, endpoint=False)
    i = t.astype(int)
    f = t - i
    f = f * f * (3 - 2 * f)
    a = g[i][:, i] * (1 - f)[None, :] + g[i][:, i + 1] * f[None, :]
    b = g[i + 1][:, i] * (1 - f)[None, :] + g[i + 1][:, i + 1] * f[None, :]
    return a * (1 - f)[:, None] + b * f[:, None]


def paving(size=512):
    """Albedo and tangent-space normal map of 4 x 4 stones a tile, with sunken joints."""
    n = sum(value_noise(size, c, 7 + c) / k for k, c in ((1, 8), (2, 16), (4, 32)))
    x = np.arange(size) / size * 4
    jx = np.minimum(x % 1, 1 - x % 1)
    joint = np.minimum(jx[None, :], jx[:, None])
    # joints sunk with a smoothstep: the normals tilt at most about 30 degrees there (a
    # steeper map sends a shading normal's rays under the floor, where no renderer agrees)
    t = np.clip(joint / 0.06, 0, 1)
    height = t * t * (3 - 2 * t) + 0.08 * n
    stone = ((np.floor(x)[None, :] * 5 + np.floor(x)[:, None] * 3) % 7) / 7
    base = np.array([0.62, 0.55, 0.45]) * (0.8 + 0.25 * stone[..., None]) * (0.85 + 0.2 * n[..., None])
    base = np.where((joint < 0.04)[..., None], [0.35, 0.32, 0.28], base)
    gy, gx = np.gradient(height * 3.0 / size * 4)
    nrm = unit(np.stack([-gx * size / 4, gy * size / 4, np.ones_like(gx)], -1))
    to8 = lambda a: (np.clip(a, 0, 1) * 255 + 0.5).astype(np.uint8)
    return to8(base ** (1 / 2.2)), to8(nrm * 0.5 + 0.5)


def leaf(size=128):
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    u, v = (x - 0.5) * 2, y
    inside = (np.abs(u) < 0.9 * np.sin(np.pi * np.clip(v, 0, 1)) ** 0.8) & (v > 0.04) & (v < 0.97)
    vein = np.exp(-(u / 0.04) ** 2) * 0.25
    col = np.stack([0.18 + 0.1 * v + vein, 0.38 + 0.15 * v + vein, 0.1 + vein * 0.5], -1)
    rgba = np.concatenate([col, inside[..., None].astype(float)], -1)
    return (np.clip(rgba, 0, 1) * 255 + 0.5).astype(np.uint8)


def cloth(size=256):
    """A red banner with a gold border, a cut-out pattern of rings and a fringe."""
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    col = np.where(((x < 0.08) | (x > 0.92) | (y < 0.05))[..., None], [0.75, 0.58, 0.18],
                   [0.55, 0.07, 0.06])
    ring = np.hypot((x * 4) % 1 - 0.5, (y * 6) % 1 - 0.5)
    holes = (np.abs(ring - 0.28) < 0.05) & (y > 0.15) & (y < 0.85) & (x > 0.12) & (x < 0.88)
    fringe = (y > 0.9) & (((x * 40) % 1) > 0.45)
    alpha = ~(holes | fringe)
    rgba = np.concatenate([col ** (1 / 2.2), alpha[..., None].astype(float)], -1)
    return (np.clip(rgba, 0, 1) * 255 + 0.5).astype(np.uint8)


# ---- glTF ----------------------------------------------------------------------------------

class Gltf:
    """Collects meshes, materials, textures, nodes and lights; writes .gltf + .bin."""

    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": "ssgraph tools/make_atrium.py",
                              "copyright": "CC0 1.0: dedicated to the public domain"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
                    "materials": [], "textures": [], "images": [], "samplers": [{}],
                    "accessors": [], "bufferViews": [], "buffers": [],
                    "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
                    "extensions": {"KHR_lights_punctual": {"lights": []}}}
        self.blob = bytearray()
        self.triangles = 0

    def texture(self, uri):
        self.doc["images"].append({"uri": uri})
        self.doc["textures"].append({"sampler": 0, "source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def material(self, name, **m):
        self.doc["materials"].append(dict(name=name, **m))
        return len(self.doc["materials"]) - 1

    def _view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob),
                                        "byteLength": len(data), "target": target})
        self.blob += data
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, a, kind, target):
        a = np.ascontiguousarray(a, np.float32 if kind != "SCALAR" else np.uint32)
        acc = {"bufferView": self._view(a.tobytes(), target), "count": len(a) if kind != "SCALAR"
               else a.size, "componentType": 5126 if kind != "SCALAR" else 5125, "type": kind}
        if kind == "VEC3" and target == 34962:
            acc["min"], acc["max"] = a.min(0).tolist(), a.max(0).tolist()
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, prims):
        """prims: [(mesh arrays, material)], one node at the origin."""
        out = []
        for m, mat in prims:
            attrs = {"POSITION": self._accessor(m[0], "VEC3", 34962),
                     "NORMAL": self._accessor(unit(m[1]), "VEC3", 34962),
                     "TEXCOORD_0": self._accessor(m[2], "VEC2", 34962)}
            out.append({"attributes": attrs, "material": mat,
                        "indices": self._accessor(m[3].ravel(), "SCALAR", 34963)})
            self.triangles += len(m[3])
        self.doc["meshes"].append({"name": name, "primitives": out})
        self.node({"name": name, "mesh": len(self.doc["meshes"]) - 1})

    def node(self, n):
        self.doc["nodes"].append(n)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def spot(self, name, at, target, inner, outer, intensity, color):
        lights = self.doc["extensions"]["KHR_lights_punctual"]["lights"]
        lights.append({"name": name, "type": "spot", "color": color, "intensity": intensity,
                       "spot": {"innerConeAngle": inner, "outerConeAngle": outer}})
        # the node's -z must point from at to target: the shortest rotation of -z onto it
        d = unit(np.asarray(target, float) - np.asarray(at, float))
        axis = np.cross([0, 0, -1], d)
        s, c = np.linalg.norm(axis), -d[2]
        angle = math.atan2(s, c)
        axis = axis / s if s > 1e-9 else np.array([1.0, 0, 0])
        q = [*(axis * math.sin(angle / 2)), math.cos(angle / 2)]
        self.node({"name": name, "translation": list(map(float, at)),
                   "rotation": [float(v) for v in q],
                   "extensions": {"KHR_lights_punctual": {"light": len(lights) - 1}}})

    def write(self, out_dir, name):
        self.doc["buffers"].append({"uri": name + ".bin", "byteLength": len(self.blob)})
        with open(os.path.join(out_dir, name + ".bin"), "wb") as f:
            f.write(self.blob)
        with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")


def save_png(out_dir, name, pixels):
    Image.fromarray(pixels).save(os.path.join(out_dir, name), optimize=True)


def build(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    albedo, normal = paving()
    save_png(out_dir, "paving.png", albedo)
    save_png(out_dir, "paving_normal.png", normal)
    save_png(out_dir, "leaf.png", leaf())
    save_png(out_dir, "cloth.png", cloth())
    g = Gltf()
    pbr = lambda rgb, **t: {"pbrMetallicRoughness": dict(baseColorFactor=[*rgb, 1.0],
                                                         metallicFactor=0.0, **t)}
    stone = g.material("stone", **pbr([0.72, 0.68, 0.60]))
    plaster = g.material("plaster", **pbr([0.78, 0.72, 0.62]))
    paving_mat = g.material("paving", normalTexture={"index": g.texture("paving_normal.png"),
                                                     "scale": 1.0},
                            **pbr([1, 1, 1], baseColorTexture={"index": g.texture("paving.png")}))
    leaves = g.material("leaves", alphaMode="MASK", alphaCutoff=0.5, doubleSided=True,
                        **pbr([1, 1, 1], baseColorTexture={"index": g.texture("leaf.png")}))
    bark = g.material("bark", **pbr([0.30, 0.22, 0.15]))
    banner_mat = g.material("banner", alphaMode="MASK", alphaCutoff=0.5, doubleSided=True,
                            **pbr([1, 1, 1], baseColorTexture={"index": g.texture("cloth.png")}))
    iron = g.material("iron", **pbr([0.08, 0.08, 0.08]))
    glass = g.material("lantern_glass", emissiveFactor=[1.0, 0.72, 0.38],
                       extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 6.0}},
                       **pbr([0.9, 0.85, 0.7]))
    terracotta = g.material("planter", **pbr([0.55, 0.30, 0.20]))

    floor = grid(24, 24, lambda u, v: (np.stack([(u - 0.5) * 2 * (HALF + 2.7), 0 * u,
                                                 (v - 0.5) * 2 * (HALF + 2.7)], 1),
                                       np.tile([0, 1, 0], (len(u), 1))))
    floor[3] = floor[3][:, ::-1]  # the grid's v runs along +z: face up
    floor[2] = floor[0][:, [0, 2]] / 2.0  # a paving tile (4 x 4 stones) every 2 m
    g.mesh("floor", [(floor, paving_mat)])
    cols = []
    for k in range(24):
        side, i = divmod(k, 6)
        t = -HALF + BAY * i
        x, z = [(t, HALF), (HALF, -t), (-t, -HALF), (-HALF, t)][side]
        cols.append(moved(column(), at=(x, 0, z)))
    g.mesh("columns", [(merge(cols), stone)])
    g.mesh("arcade", [(merge([side_of_arcade(r) for r in (0, math.pi / 2, math.pi,
                                                          -math.pi / 2)]),
                       plaster)])
    g.mesh("fountain", [(fountain(), stone)])
    trunks, crowns, planters = [], [], []
    for k, (x, z) in enumerate([(-3, -3), (3, -3), (-3, 3), (3, 3)]):
        trunk, crown = tree(100 + k)
        trunks.append(moved(trunk, at=(x, 0.5, z)))
        crowns.append(moved(crown, at=(x, 0.5, z)))
        planters.append(box((x - 0.6, 0, z - 0.6), (x + 0.6, 0.5, z + 0.6)))
    g.mesh("trees", [(merge(trunks), bark), (merge(crowns), leaves)])
    g.mesh("planters", [(merge(planters), terracotta)])
    banners = []
    for k in range(6):  # in the bays of the north side (z = -HALF), turned to face +z
        x = -HALF + BAY * (k + 0.5)
        banners.append(moved(banner(1.1, 1.8, 200 + k), at=(x, 3.35, -HALF - 0.2)))
    g.mesh("banners", [(merge(banners), banner_mat)])
    glass_parts, iron_parts = [], []
    for k in range(12):  # east and west arches
        side = 1 if k < 6 else -1
        t = -HALF + BAY * (k % 6 + 0.5)
        at = (side * HALF, 3.25, t)
        gl_, ir = lantern()
        glass_parts.append(moved(gl_, at=at))
        iron_parts.append(moved(ir, at=at))
    g.mesh("lanterns", [(merge(glass_parts), glass), (merge(iron_parts), iron)])
    for k, (x, z) in enumerate([(-3, -3), (3, -3), (-3, 3), (3, 3)]):
        g.spot("spot_tree_%d" % k, (x * 1.9, 4.4, z * 1.9), (x, 2.4, z), 0.25, 0.42, 40.0,
               [1.0, 0.92, 0.8])
    g.write(out_dir, "atrium")
    return g.triangles


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "examples", "atrium")
    tris = build(out)
    print("wrote %s/atrium.gltf: %d triangles" % (out, tris))


if __name__ == "__main__":
    main()
