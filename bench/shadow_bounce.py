#!/usr/bin/python3
"""shadow_bounce.py - how bright the tall box's shadows are on the Cornell box's red and back
walls against the truth (issue 44 item 1: the far bounce without visibility reached through
the box and lit them 3.7-5x too bright).

    bench/shadow_bounce.py [--graph graphs/gi.graph] [--size 640x360] [--paths 256]
                           [--set rsm.visibility=false ...] [--crops DIR]

Renders GRAPH (its write's main image and its far_bounce layer, E / pi of a white receiver)
and the truth (gbuffer + reference_gi with --paths paths a pixel, cached in --cache) of
examples/cornell.scene at one size. A shadow is the pixels on one wall (the G-buffer's world
position within 0.01 of the wall's plane, its normal within 25 degrees of the wall's) where
the truth's direct light is below 1 % of that wall's brightest direct light. Per shadow it
prints mean(image) / mean(truth) over R + G + B, and the same for the far bounce's share of
the image (albedo x far_bounce, the rsm term) against the truth's bounce (in a shadow the
truth is all bounce). 1.00 is right; issue 44's acceptance is within 0.75-1.25. Last, the
image over the truth on the short box's front face (lit: where the near and far bounce
meet, graphs/gi.graph's min_distance).

EXRs are read as bench/sequence.py reads them (python3-openimageio when importable, else
oiiotool's --dumpdata). --crops DIR writes PNG crops of both shadows, the graph's image
beside the truth (write's ACES tone curve), for looking at them.
"""
import argparse
import hashlib
import os
import struct
import subprocess
import sys
import tempfile
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import sequence  # noqa: E402 (its EXR readers)

SCENE = os.path.join(ROOT, "examples", "cornell.scene")
TRUTH = """size {w} {h}
seed 1
g   = gbuffer()
ref = reference_gi(g.position, g.normal, g.albedo, samples={paths})
out = write(ref.out, "truth", direct=ref.direct, bounce=ref.bounce, position=g.position,
            normal=g.normal, albedo=g.albedo)
"""
# wall: (axis, plane coordinate, inward normal sign)
WALLS = {"red wall (x = -1)": (0, -1.0, 1.0), "back wall (z = -1)": (2, -1.0, 1.0)}
RGB = ["R", "G", "B"]


def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode:
        sys.exit("shadow_bounce.py: %s failed:\n%s" % (" ".join(cmd), r.stderr))
    return r.stdout


def read(exr, layers, tmp):
    """{layer: H x W x 3} of the named layers ("" = the main image's R, G, B)."""
    chans = []
    for layer in layers:
        names = ["X", "Y", "Z"] if layer in ("position", "normal") else RGB
        chans += [(layer + "." if layer else "") + c for c in names]
    reader = sequence.read_sequence_oiio if sequence.oiio_importable() else None
    planes = (reader([exr], chans) if reader else
              sequence.read_sequence_oiiotool([exr], chans, tmp))[0]
    return {layer: np.stack(planes[3 * i:3 * i + 3], axis=-1) for i, layer in
            enumerate(layers)}


def truth(a, tmp):
    w, h = a.size.split("x")
    text = TRUTH.format(w=w, h=h, paths=a.paths)
    key = hashlib.sha256((text + open(SCENE).read() + run([a.binary, "--version"]))
                         .encode()).hexdigest()[:24]
    os.makedirs(a.cache, exist_ok=True)
    exr = os.path.join(a.cache, "shadow_truth_%s.exr" % key)
    if not os.path.exists(exr):
        graph = os.path.join(tmp, "truth.graph")
        with open(graph, "w") as f:
            f.write(text)
        run([a.binary, "run", graph, "--scene", SCENE, "--threads", str(a.threads), "-q",
             "-o", os.path.join(tmp, "truth.exr")])
        os.replace(os.path.join(tmp, "truth.exr"), exr)
    return read(exr, ["", "direct", "bounce", "position", "normal", "albedo"], tmp)


def pipeline(a, tmp):
    cmd = [a.binary, "run", a.graph, "--scene", SCENE, "--size", a.size, "--threads",
           str(a.threads), "-q", "-o", os.path.join(tmp, "image.exr")]
    for s in a.set or []:
        cmd += ["--set", s]
    run(cmd)
    return read(os.path.join(tmp, "image.exr"), ["", "far_bounce"], tmp)


def camera():
    """The scene's camera as (eye, rotation): world = eye + view @ rotation (node.h's
    conventions: the camera looks down -z, y up; rows of rotation are the view axes)."""
    for line in open(SCENE):
        if line.startswith("camera("):
            nums = line.replace("[", " ").replace("]", " ").replace(",", " ").split()
            vals = [float(v) for v in nums if v.lstrip("-").replace(".", "", 1).isdigit()]
            eye, target, up = (np.array(vals[0:3]), np.array(vals[3:6]),
                               np.array(vals[6:9]))
    back = (eye - target) / np.linalg.norm(eye - target)
    right = np.cross(up, back)
    right /= np.linalg.norm(right)
    return eye, np.stack([right, np.cross(back, right), back])


def shadows(t):
    """{wall: mask of its shadow}: on the wall, the truth's direct under 1 % of its top."""
    eye, rot = camera()
    pos, nrm = eye + t["position"] @ rot, t["normal"] @ rot
    direct = t["direct"].sum(-1)
    out = {}
    for name, (axis, at, sign) in WALLS.items():
        on = (np.abs(pos[..., axis] - at) < 0.01) & (sign * nrm[..., axis] > 0.9)
        lit = direct[on].max() if on.any() else 0
        out[name] = on & (direct < 0.01 * lit)
    return out


def short_front(t):
    """The short box's front face (its +z face turned -17 degrees about y, 0.3 before the
    centre (0.34, 0.3, 0.33)): where a near-field gap too wide or too narrow shows
    (graphs/gi.graph's min_distance comment)."""
    eye, rot = camera()
    pos, nrm = eye + t["position"] @ rot, t["normal"] @ rot
    a = np.radians(-17.0)
    n = np.array([np.sin(a), 0.0, np.cos(a)])
    c = np.array([0.34, 0.3, 0.33]) + 0.3 * n
    rel = pos - c
    return ((np.abs(rel @ n) < 0.01) & (nrm @ n > 0.95) &
            (np.linalg.norm(rel - np.outer(rel @ n, n).reshape(rel.shape), axis=-1) < 0.3))


def png(path, rgb8):
    h, w, _ = rgb8.shape
    raw = b"".join(b"\0" + rgb8[y].tobytes() for y in range(h))
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0,
                                                                     0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def aces_srgb(x):
    """write's PNG: the ACES fit of Narkowicz (2015), then sRGB encoding, in 8 bits."""
    x = np.maximum(x, 0)
    y = np.clip((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    s = np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1 / 2.4) - 0.055)
    return (s * 255 + 0.5).astype(np.uint8)


def crops(a, img, t, masks):
    os.makedirs(a.crops, exist_ok=True)
    for name, m in masks.items():
        ys, xs = np.nonzero(m)
        if not len(ys):
            continue
        pad = 12
        y0, y1 = max(ys.min() - pad, 0), min(ys.max() + pad, m.shape[0])
        x0, x1 = max(xs.min() - pad, 0), min(xs.max() + pad, m.shape[1])
        # exposure +2 stops: the shadows are dark
        pair = np.concatenate([img[y0:y1, x0:x1] * 4, np.ones((y1 - y0, 2, 3)),
                               t[""][y0:y1, x0:x1] * 4], axis=1)
        tag = name.split()[0]
        pair = pair.repeat(2, axis=0).repeat(2, axis=1)  # 2x, nearest: pixels visible
        png(os.path.join(a.crops, "%s%s.png" % (a.tag, tag)), aces_srgb(pair))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--graph", default=os.path.join(ROOT, "graphs", "gi.graph"))
    ap.add_argument("--binary", default=os.path.join(ROOT, "build-test", "ssgraph"))
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--paths", type=int, default=256)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--set", action="append", help="--set NODE.P=VALUE for the graph")
    ap.add_argument("--cache", default=os.path.join(tempfile.gettempdir(),
                                                    "ssgraph_shadow_bounce"))
    ap.add_argument("--crops", help="folder for PNG crops (image | truth)")
    ap.add_argument("--tag", default="", help="prefix of the crops' file names")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        t = truth(a, tmp)
        p = pipeline(a, tmp)
    masks = shadows(t)
    rsm = t["albedo"] * p["far_bounce"]
    print("%-20s %7s %9s %9s" % ("shadow", "pixels", "image", "rsm term"))
    for name, m in masks.items():
        img = p[""][m].sum(-1).mean() / t[""][m].sum(-1).mean()
        far = rsm[m].sum(-1).mean() / t["bounce"][m].sum(-1).mean()
        print("%-20s %7d %8.2fx %8.2fx" % (name, m.sum(), img, far))
    m = short_front(t)
    if m.any():
        print("%-20s %7d %8.2fx %9s" % ("short box front", m.sum(), p[""][m].sum(-1).mean() /
                                         t[""][m].sum(-1).mean(), "(lit)"))
    if a.crops:
        crops(a, p[""], t, masks)


if __name__ == "__main__":
    main()
