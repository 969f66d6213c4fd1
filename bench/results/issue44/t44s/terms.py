"""terms.py - each term's share of gi.graph's structure (issue 44 item 2, t44s): from one
run of terms.graph (OUT holds terms.exr, truth.exr and structure.exr), d_T = G(m (T - T_ref))
/ G(m truth) over the pixels compare's structure measure kept for the whole image (its
nonzero map), G the same Gaussian (sigma = 0.01 x width, cut at 3 sigma, normalised):
  env  = the probe's far field (direct + environment) against reference_gi's direct
  near = SSDO's near bounce, far = the RSM far bounce, bounce = near + far, against the
         reference's bounce
    python3 bench/results/issue44/t44s/terms.py OUT"""
import os
import sys

import numpy as np
from scipy.ndimage import gaussian_filter

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", ".."))
import gallery  # noqa: E402


def main():
    out = sys.argv[1]
    grey = lambda p: gallery.read(os.path.join(out, p))[..., :3].mean(axis=2)
    truth, direct, bounce = grey("truth.exr"), grey("truth.exr:direct"), grey("truth.exr:bounce")
    env, near, far = grey("terms.exr"), grey("terms.exr:near"), grey("terms.exr:far")
    keep = gallery.read(os.path.join(out, "structure.exr"))[..., 0] != 0
    sigma = 0.01 * truth.shape[1]
    g = lambda x: gaussian_filter(x, sigma, mode="constant", truncate=3.0)
    base = g(truth)
    for name, term, ref in (("env", env, direct), ("near", near, bounce), ("far", far, bounce),
                            ("bounce", near + far, bounce), ("all", env + near + far, truth)):
        d = (g(term - ref) / base)[keep]
        print("%-7s pp %.3f rms %.3f" % (name, d.max() - d.min(), d.std()))


if __name__ == "__main__":
    main()
