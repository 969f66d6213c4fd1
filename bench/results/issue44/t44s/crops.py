"""crops.py - PNG crops for issue 44 item 2 (t44s): truth, gi.graph and compare's structure
map d of one run of terms.graph, tone mapped as bench/gallery.py shows them.
    python3 bench/results/issue44/t44s/crops.py OUT_DIR NAME X0 Y0 X1 Y1 [SCALE]"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", ".."))
import gallery  # noqa: E402


def main():
    out, name = sys.argv[1], sys.argv[2]
    x0, y0, x1, y1 = (int(v) for v in sys.argv[3:7])
    scale = int(sys.argv[7]) if len(sys.argv) > 7 else 3
    truth = gallery.display(gallery.read(os.path.join(out, "truth.exr")), "gi")
    gi = gallery.display(gallery.read(os.path.join(out, "gi.exr")), "gi")
    d = gallery.read(os.path.join(out, "structure.exr"))[..., 0]
    # d on a blue-white-red map, +-0.2 at full colour; grey where not measured
    t = np.clip(d / 0.2, -1, 1)[..., None]
    rgb = np.concatenate([np.where(t < 0, 1 + t, 1), 1 - np.abs(t), np.where(t > 0, 1 - t, 1)],
                         axis=2)
    rgb = np.where(d[..., None] == 0, 0.3, rgb)
    dmap = (rgb * 255 + 0.5).astype(np.uint8)
    tiles = [truth, gi, dmap]
    strip = gallery.crop_strip(tiles, (y0, x0, y1 - y0, x1 - x0), scale)
    from PIL import Image
    Image.fromarray(strip).save(name)
    print("wrote", name)


if __name__ == "__main__":
    main()
