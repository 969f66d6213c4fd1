#!/usr/bin/env python3
"""make_crops.py BEFORE_BUILD BEFORE_CHECKOUT: this folder's crops of issue 44's two walls
(seed 1, 320x180, against the gallery's cached 4096-path truth), before (another build and
its checkout's gi.graph) and now (this checkout's): rows truth | before | now, then the
structure measure's d (the blurred relative error where the truth is smooth) before | now,
red = too bright, blue = too dark, full red at +-0.05; 3x, nearest.

    /usr/bin/python3 bench/results/issue44/t44f/make_crops.py BEFORE_BUILD/ssgraph BEFORE_CHECKOUT
"""
import os
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import structure_seeds  # noqa: E402

NOW = os.path.join(ROOT, "build-test", "ssgraph")


def read(path):
    return oiio.ImageBuf(path).get_pixels(oiio.FLOAT)


def tone(rgb, exposure):
    x = np.clip(rgb[..., :3] * exposure, 0, None)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055).clip(0, 1)


def diverging(d, scale=0.05):
    r, b = np.clip(d / scale, 0, 1), np.clip(-d / scale, 0, 1)
    img = np.stack([r, np.zeros_like(r), b], -1)
    img[d == 0] = 0.15
    return img


def frame_and_d(binary, graph, case, tmp):
    """The frame at seed 1 and the structure measure's d (this build's compare)."""
    frame, cmp, _ = structure_seeds.run_and_compare(binary, graph, case, 1, [], tmp,
                                                    compare_bin=NOW)
    return read(frame), read(os.path.join(cmp, "structure.exr"))[..., 0]


def main():
    before_bin, before_root = sys.argv[1], sys.argv[2]
    for case, (x0, y0, x1, y1), exposure in (("bunny_courtyard", (80, 0, 320, 100), 2.5),
                                             ("cornell_sky", (100, 30, 220, 150), 1.5)):
        truth = structure_seeds.truth_of(NOW, case)
        with tempfile.TemporaryDirectory() as tmp:
            fb, db = frame_and_d(before_bin, os.path.join(before_root, "graphs", "gi.graph"),
                                 case, tmp)
            fn, dn = frame_and_d(NOW, os.path.join(ROOT, "graphs", "gi.graph"), case, tmp)
        t = read(truth)
        crop = np.s_[y0:y1, x0:x1]
        top = np.concatenate([tone(t[crop], exposure), tone(fb[crop], exposure),
                              tone(fn[crop], exposure)], 1)
        blank = np.full_like(tone(t[crop], exposure), 0.15)
        bottom = np.concatenate([blank, diverging(db[crop]), diverging(dn[crop])], 1)
        img = np.concatenate([top, bottom], 0)
        img = np.repeat(np.repeat(img, 3, 0), 3, 1).astype(np.float32)
        out = os.path.join(HERE, case + ".jpg")
        buf = oiio.ImageBuf(np.ascontiguousarray(img))
        buf.specmod().attribute("Compression", "jpeg:90")
        buf.write(out)
        print(out)


if __name__ == "__main__":
    main()
