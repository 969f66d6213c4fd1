#!/usr/bin/env python3
"""readme_figure.py - the README's first picture (docs/images/cornell_gi.png): the Cornell box
under its own light, path-traced truth beside graphs/gi.graph and the seeds' ssdo.graph, with
gi.graph's error as a ratio on a diverging scale and crops where it is largest.

    python3 bench/readme_figure.py [--bin build/ssgraph] [--size 640x480] [--paths 1024]
                                   [--out docs/images/cornell_gi.png]

It runs graphs/gi_error.graph once (the reference's path count raised to --paths so that the
truth's own noise does not drown the ratio) and composes, from its EXR layers:

    row 1   truth | gi.graph
    row 2   ssdo.graph | gi.graph / truth
    row 3   the ratio's scale, labelled 1/5x ... 5x
    row 4   the window of a quarter of the frame where the ratio is furthest from 1:
            truth | gi.graph | ratio, enlarged
    row 5   the same for the next such window that overlaps the first by at most a quarter

The ratio is of luminances, both blurred by a Gaussian of deviation --blur px (the truth's
path noise would otherwise cover the picture) and each raised by a floor of 2 % of the
truth's median over the surfaces (a pixel in the dark shows no ratio from noise alone):
log2(gi / truth) mapped to red (gi brighter) and blue (gi darker), saturating at 5x either
way, so a shadow 5x too bright is full red. Colours show through write's tone map (ACES,
then sRGB), the same for every panel. Pixels without a surface are black.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gallery import aces_srgb, read, worst_window  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SATURATE = 5.0            # the ratio at full colour, either way
TICKS = [1 / 5, 1 / 3, 1 / 2, 1 / 1.5, 1, 1.5, 2, 3, 5]
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"


def luminance(rgb):
    return rgb[..., 0] * 0.2126 + rgb[..., 1] * 0.7152 + rgb[..., 2] * 0.0722


def gaussian(img, sigma):
    """Separable Gaussian blur of a 2-D array (edges clamped); sigma 0 returns it."""
    if sigma <= 0:
        return img
    r = max(1, int(3 * sigma + 0.5))
    k = np.exp(-0.5 * (np.arange(-r, r + 1) / sigma) ** 2)
    k /= k.sum()
    out = img
    for axis in (0, 1):
        pad = [(0, 0), (0, 0)]
        pad[axis] = (r, r)
        p = np.pad(out, pad, mode="edge")
        n = out.shape[axis]
        out = sum(k[i] * np.take(p, range(i, i + n), axis=axis) for i in range(2 * r + 1))
    return out


def log_ratio(method, truth, surface, blur):
    """log2 of the blurred luminance ratio method / truth, with the dark floor; 0 off surfaces.
    The blur is normalised over the surface pixels so the black background does not darken
    the edges of a surface."""
    w = surface.astype(np.float64)
    norm = np.maximum(gaussian(w, blur), 1e-6)
    lm = gaussian(luminance(method) * w, blur) / norm
    lt = gaussian(luminance(truth) * w, blur) / norm
    floor = 0.02 * float(np.median(luminance(truth)[surface]))
    r = np.log2((lm + floor) / (lt + floor))
    return np.where(surface, r, 0.0)


def diverging(r, surface):
    """log2 ratio -> RGB8: white at 1x, red towards 5x brighter, blue towards 5x darker."""
    t = np.clip(r / np.log2(SATURATE), -1, 1)[..., None]
    white = np.array([1.0, 1.0, 1.0])
    red, blue = np.array([0.70, 0.05, 0.10]), np.array([0.10, 0.20, 0.70])
    rgb = np.where(t >= 0, white + t * (red - white), white - t * (blue - white))
    rgb = np.where(surface[..., None], rgb, 0.0)
    return (rgb * 255 + 0.5).astype(np.uint8)


def font(size):
    from PIL import ImageFont
    try:
        return ImageFont.truetype(FONT, size)
    except OSError:
        return ImageFont.load_default()


def labelled(pixels, text, size=22):
    from PIL import Image, ImageDraw
    im = Image.fromarray(pixels)
    draw = ImageDraw.Draw(im)
    f = font(size)
    box = draw.textbbox((6, 4), text, font=f)
    draw.rectangle([0, 0, box[2] + 6, box[3] + 6], fill=(0, 0, 0))
    draw.text((6, 4), text, fill=(255, 255, 255), font=f)
    return np.asarray(im)


def scale_bar(width, height=64):
    """The ratio's colour bar with its ticks labelled, as RGB8."""
    from PIL import Image, ImageDraw
    margin = min(90, width // 6)
    bar = np.zeros((height, width, 3), np.uint8)
    xs = np.linspace(-1, 1, width - 2 * margin)
    row = diverging(xs[None, :] * np.log2(SATURATE), np.ones((1, xs.size), bool))
    bar[6:28, margin:width - margin] = row
    im = Image.fromarray(bar)
    draw = ImageDraw.Draw(im)
    f = font(16)
    for tick in TICKS:
        x = margin + (np.log2(tick) / np.log2(SATURATE) + 1) / 2 * (width - 2 * margin - 1)
        draw.line([(x, 28), (x, 34)], fill=(255, 255, 255))
        text = "1x" if tick == 1 else ("%gx" % tick if tick > 1 else "1/%gx" % (1 / tick))
        w = draw.textlength(text, font=f)
        draw.text((x - w / 2, 36), text, fill=(255, 255, 255), font=f)
    draw.text((4, 8), "darker", fill=(120, 150, 255), font=f)
    draw.text((width - margin + 4, 8), "brighter", fill=(255, 120, 120), font=f)
    return np.asarray(im)


def enlarge(pixels, y, x, h, w, width):
    """The window (y, x, h, w), scaled with nearest neighbour to `width` pixels wide."""
    from PIL import Image
    crop = Image.fromarray(np.ascontiguousarray(pixels[y:y + h, x:x + w]))
    height = int(round(h * width / w))
    return np.asarray(crop.resize((width, height), Image.NEAREST))


def overlap(a, b):
    """The fraction of window a's area that window b covers."""
    (ay, ax, h, w), (by, bx, _, _) = a, b
    oy = max(0, min(ay + h, by + h) - max(ay, by))
    ox = max(0, min(ax + w, bx + w) - max(ax, bx))
    return oy * ox / float(h * w)


def second_window(err, surface, first):
    """The worst window by err that overlaps `first` by at most a quarter."""
    masked = err.copy()
    for _ in range(8):
        win = worst_window(masked, surface)
        if overlap(win, first) <= 0.25:
            return win
        y, x, h, w = win
        masked[y:y + h, x:x + w] = 0
    return win


def crop_row(panels, window, width, captions):
    y, x, h, w = window
    cell = width // len(panels)
    tiles = [labelled(enlarge(p, y, x, h, w, cell), c, 18) for p, c in zip(panels, captions)]
    row = np.concatenate(tiles, axis=1)
    pad = width - row.shape[1]
    return np.pad(row, ((0, 0), (0, pad), (0, 0))) if pad > 0 else row


def render(binary, size, paths, out_dir):
    cmd = [binary, "run", os.path.join(ROOT, "graphs", "gi_error.graph"), "--size", size,
           "--set", "ref.samples=%d" % paths, "--threads", str(os.cpu_count() or 2),
           "--quiet", "--out", out_dir]
    subprocess.run(cmd, check=True)
    return os.path.join(out_dir, "gi_error.exr")


def surface_of(exr, *images):
    """The pixels with a surface: the EXR's depth where it has one, else where any image is
    not black (gi_error.graph writes no depth: its write node has no input to spare; a
    surface black in every image shows no ratio either way)."""
    depth = read(exr + ":depth")
    if depth.shape[2]:
        return depth[..., 0] > 0
    return np.any([np.any(img != 0, axis=2) for img in images], axis=0)


def compose(exr, blur):
    truth, gi, ssdo = read(exr)[..., :3], read(exr + ":gi"), read(exr + ":ssdo")
    surface = surface_of(exr, truth, gi, ssdo)
    r = log_ratio(gi, truth, surface, blur)
    first = worst_window(np.abs(r), surface)
    second = second_window(np.abs(r), surface, first)
    pics = {"truth": aces_srgb(truth), "gi": aces_srgb(gi), "ssdo": aces_srgb(ssdo),
            "ratio": diverging(r, surface)}
    height, width = truth.shape[:2]
    top = np.concatenate([labelled(pics["truth"], "truth (reference_gi, 1 bounce)"),
                          labelled(pics["gi"], "gi.graph")], axis=1)
    mid = np.concatenate([labelled(pics["ssdo"], "ssdo.graph (the seeds')"),
                          labelled(pics["ratio"], "gi.graph / truth")], axis=1)
    rows = [top, mid, scale_bar(2 * width)]
    for name, win in (("worst", first), ("next worst", second)):
        mean = float(np.exp2(r[win[0]:win[0] + win[2], win[1]:win[1] + win[3]][
            surface[win[0]:win[0] + win[2], win[1]:win[1] + win[3]]].mean()))
        rows.append(crop_row([pics["truth"], pics["gi"], pics["ratio"]], win, 2 * width,
                             ["%s: truth" % name, "gi.graph",
                              "ratio (geometric mean %.2fx)" % mean]))
    return np.concatenate(rows, axis=0), first, second


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "ssgraph"))
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--paths", type=int, default=1024, help="the truth's paths a pixel")
    ap.add_argument("--blur", type=float, default=1.5, help="the ratio's Gaussian, px")
    ap.add_argument("--exr", help="an existing gi_error.exr instead of running the graph")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "images", "cornell_gi.png"))
    a = ap.parse_args()
    from PIL import Image
    with tempfile.TemporaryDirectory() as tmp:
        exr = a.exr or render(a.bin, a.size, a.paths, tmp)
        figure, first, second = compose(exr, a.blur)
        part = a.out + ".part.png"
        Image.fromarray(figure).save(part, optimize=True)
        os.replace(part, a.out)
    print("wrote %s (%dx%d); crops at (y, x, h, w) %s and %s" %
          (a.out, figure.shape[1], figure.shape[0], first, second))


if __name__ == "__main__":
    main()
