"""gi_terms.py - gi.graph's error split into its terms under one lighting (issue 44): per
example scene the RMSE of the frame, of its shadowed direct light against reference_gi's
direct light, and of its bounce against reference_gi's bounce (bench/gi_terms.graph), and
the means over the scenes, as a Markdown table.

  python3 bench/gi_terms.py [--lights sun|sky|courtyard|own] [--size 640x480] [--paths 256]
                            [--set NODE.P=VALUE ...]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from accuracy import still_scenes  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TERMS = [("frame", "c_gi"), ("direct", "c_direct"), ("bounce", "c_bounce")]


def scene_metrics(binary, scene, lights, size, paths, threads, out, sets=()):
    """The compare nodes' metrics of bench/gi_terms.graph on one scene (with --set sets)."""
    cmd = [binary, "run", os.path.join(ROOT, "bench", "gi_terms.graph"), "--scene",
           os.path.join(ROOT, "examples", scene), "--size", size, "--out", out, "--quiet",
           "--set", f"ref.samples={paths}", "--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    if lights != "own":
        cmd += ["--lights", os.path.join(ROOT, "examples", "lights", lights + ".scene")]
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build-test", "ssgraph"))
    ap.add_argument("--lights", default="sun")
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--paths", type=int, default=256)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--scenes", help="comma-separated scene files (default: every still one)")
    ap.add_argument("--set", action="append", default=[],
                    help="a parameter override for every run (gi.graph as it was: "
                         "--set lm.fit=scene --set dl.fit=scene)")
    a = ap.parse_args()
    scenes = a.scenes.split(",") if a.scenes else still_scenes()
    print(f"gi.graph under `{a.lights}` at {a.size}, reference_gi at {a.paths} paths: RMSE "
          "of the frame, of the direct light (dl.out against ref.direct) and of the bounce "
          "(M x near + M x albedo x far against ref.bounce). Made by `python3 "
          f"bench/gi_terms.py --lights {a.lights} --size {a.size} --paths {a.paths}"
          + "".join(f" --set {s}" for s in a.set) + "`.\n")
    print("| scene | frame rmse | direct rmse | bounce rmse |")
    print("|---|---|---|---|")
    sums = [0.0] * len(TERMS)
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            m = scene_metrics(a.bin, scene, a.lights, a.size, a.paths, a.threads,
                              os.path.join(tmp, scene), a.set)
            vals = [m[node]["rmse"] for _, node in TERMS]
            sums = [s + v for s, v in zip(sums, vals)]
            print(f"| {scene[:-6]} | " + " | ".join(f"{v:.4f}" for v in vals) + " |",
                  flush=True)
    print("| **mean** | " + " | ".join(f"**{s / len(scenes):.4f}**" for s in sums) + " |")


if __name__ == "__main__":
    main()
