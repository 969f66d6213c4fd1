#!/usr/bin/env python3
"""artefact_crops.py - the crops that docs/gallery.md's artefact list (bench/gallery/
artefacts.md) shows: for each artefact a window of one pipeline's image on one scene under
one lighting, truth | before | after, enlarged, with the window's error beside the truth.

    python3 bench/artefact_crops.py --bin build/ssgraph \
        [--before OLD_SSGRAPH --before-graphs OLD_CHECKOUT/graphs] \
        [--size 640x360] [--paths 1024] [--only NAME,...] [--out docs/images/artefacts]

"before" is any other build of ssgraph with the graphs of its own checkout (for a change,
the commit before it); without --before the crops are truth | now. The truth is
bench/gallery/reference_gi.graph at --paths paths a pixel, cached as the gallery caches it
(bench/gallery.py). Each crop is <out>/<name>.jpg; the script prints one Markdown line per
artefact with the window's RMSE and its mean brightness over the truth's, before and after.
The windows are fractions of the frame, so they hold at any size.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gallery import (ROOT, aces_srgb, label, lights_file, read, reference,  # noqa: E402
                     save_jpeg)

# name, scene, lighting (gallery.LIGHTS), pipeline graph, window (x0, y0, x1, y1) as
# fractions of the frame, what a viewer sees there.
ARTEFACTS = [
    ("cornell_box_shadows", "cornell", "own", "gi.graph", (0.15, 0.3, 0.5, 0.8),
     "the tall box's shadows on the red and back walls"),
    ("cornell_short_box_shadow", "cornell", "own", "gi.graph", (0.45, 0.62, 0.85, 1.0),
     "the short box's shadow on the floor"),
    ("cornell_sky_back_wall", "cornell", "sky", "gi.graph", (0.3, 0.08, 0.7, 0.5),
     "the back wall under the sky"),
    ("bunny_courtyard_corner", "bunny", "courtyard", "gi.graph", (0.0, 0.35, 0.5, 0.85),
     "the walls and the wall-floor junction under the courtyard probe"),
    ("cornell_sun_crease", "cornell", "sun", "gi.graph", (0.1, 0.0, 0.5, 0.3),
     "the ceiling's concave edges under the sun"),
    ("table_sun_shadow", "table", "sun", "gi.graph", (0.25, 0.4, 0.75, 0.9),
     "the table's shadow under the sun"),
    ("cornell_realtime_edges", "cornell", "own", "ssdo_realtime.graph", (0.35, 0.55, 0.75, 0.95),
     "the boxes' silhouettes in the low-resolution SSDO"),
    ("cornell_sky_ssdo_streaks", "cornell", "sky", "ssdo.graph", (0.1, 0.1, 0.5, 0.6),
     "SSDO's kernel streaks on the walls"),
]


def scene_path(name):
    return os.path.join(ROOT, "examples", name + ".scene")


def render(binary, graphs, graph, scene, lights, size, out):
    cmd = [binary, "run", os.path.join(graphs, graph), "--scene", scene_path(scene),
           "--size", size, "--quiet", "-o", out]
    if lights_file(lights):
        cmd += ["--lights", lights_file(lights)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return out


def window(shape, frac):
    h, w = shape[:2]
    x0, y0, x1, y1 = frac
    return int(y0 * h), int(x0 * w), max(1, int((y1 - y0) * h)), max(1, int((x1 - x0) * w))


def enlarge(pixels, win, scale):
    y, x, h, w = win
    crop = pixels[y:y + h, x:x + w]
    return np.repeat(np.repeat(crop, scale, axis=0), scale, axis=1)


def window_scores(img, truth, surface, win):
    """RMSE over the window's surface pixels and the mean brightness over the truth's."""
    y, x, h, w = win
    m = surface[y:y + h, x:x + w]
    a, b = img[y:y + h, x:x + w][m], truth[y:y + h, x:x + w][m]
    rmse = float(np.sqrt(np.mean((a - b) ** 2))) if a.size else float("nan")
    return rmse, float(a.mean() / max(b.mean(), 1e-9)) if a.size else float("nan")


def one(a, art, tmp):
    name, scene, lights, graph, frac, what = art
    truth_exr = reference(a.bin, "gi", scene_path(scene), lights, a.size, a.paths, 1)
    truth = read(truth_exr)[..., :3]
    surface = read(truth_exr + ":depth")[..., 0] > 0
    win = window(truth.shape, frac)
    panels, notes = [("truth", truth)], []
    runs = [("before", a.before, a.before_graphs)] if a.before else []
    runs.append(("after" if a.before else "now", a.bin, os.path.join(ROOT, "graphs")))
    for tag, binary, graphs in runs:
        exr = render(binary, graphs, graph, scene, lights, a.size,
                     os.path.join(tmp, "%s_%s.exr" % (name, tag)))
        img = read(exr)[..., :3]
        panels.append((tag, img))
        rmse, ratio = window_scores(img, truth, surface, win)
        notes.append("%s rmse %.4f, %.2fx the truth's brightness" % (tag, rmse, ratio))
    tiles = [label(enlarge(aces_srgb(p), win, a.scale), t) for t, p in panels]
    path = os.path.join(a.out, name + ".jpg")
    save_jpeg(np.concatenate(tiles, axis=1), path)
    rel = os.path.relpath(path, os.path.join(ROOT, "docs"))
    print("- %s (%s, %s, %s): %s. ![%s](%s)" % (what, scene, lights, graph, "; ".join(notes),
                                              name, rel))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "ssgraph"))
    ap.add_argument("--before", help="another ssgraph binary: the 'before' column")
    ap.add_argument("--before-graphs", help="the graphs/ folder of the before binary's checkout")
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--paths", type=int, default=1024)
    ap.add_argument("--scale", type=int, default=2, help="enlargement, nearest neighbour")
    ap.add_argument("--only", help="comma-separated artefact names")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "images", "artefacts"))
    a = ap.parse_args()
    if a.before and not a.before_graphs:
        ap.error("--before needs --before-graphs (the graphs its checkout had)")
    os.makedirs(a.out, exist_ok=True)
    only = set(a.only.split(",")) if a.only else None
    with tempfile.TemporaryDirectory() as tmp:
        for art in ARTEFACTS:
            if only is None or art[0] in only:
                one(a, art, tmp)


if __name__ == "__main__":
    main()
