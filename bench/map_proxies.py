#!/usr/bin/python3
"""map_proxies.py - what the map proxies (core/scene/proxy.h) save: gi.graph's first frame
with every lightmaps and shadowmaps node's proxy on and off, in the same build, alternating
the two so that a busy machine slows both alike. Prints a Markdown table of medians: the
map nodes' times (the first one that asks pays the simplification), the frame's total and
the peak resident memory, and whether the frame's EXR holds the same values with proxies
off (it does where no mesh is dense).

    /usr/bin/python3 bench/map_proxies.py --bin build/ssgraph --runs 3 \\
        --case million=bench/results/issue45/million.scene:examples/lights/sky.scene
A case is NAME=SCENE[:LIGHTS]."""
import argparse
import re
import statistics
import subprocess
import tempfile

import numpy
import OpenImageIO as oiio

MAP_NODES = ("lm", "sm", "lb")  # gi.graph's lightmaps, shadowmaps, environment lightmaps


def run_once(binary, scene, lights, proxy, out, threads, size):
    cmd = ["/usr/bin/time", "-f", "rss %M", binary, "run", "graphs/gi.graph", "--scene", scene,
           "--threads", str(threads), "--size", size, "--out", out]
    if lights:
        cmd += ["--lights", lights]
    for node in MAP_NODES:
        cmd += ["--set", f"{node}.proxy={proxy}"]
    done = subprocess.run(cmd, capture_output=True, text=True, check=True)
    text = done.stdout + done.stderr
    row = {}
    for node in MAP_NODES:
        m = re.search(rf"^{node}\s+\S+\s+cpu\s+([0-9.]+)", text, re.M)
        row[node] = float(m.group(1)) if m else 0.0
    row["total"] = float(re.search(r"^total\s+([0-9.]+)", text, re.M).group(1))
    row["rss"] = int(re.search(r"^rss (\d+)", text, re.M).group(1)) / 1024.0
    return row


def same_pixels(a, b):
    """1 when the two EXRs hold the same values in every channel (their headers differ:
    they record the command that made them)."""
    images = [oiio.ImageBuf(path) for path in (a, b)]
    pixels = [im.get_pixels(oiio.FLOAT) for im in images]
    return (images[0].spec().channelnames == images[1].spec().channelnames and
            numpy.array_equal(pixels[0], pixels[1], equal_nan=True))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default="build/ssgraph")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--case", action="append", required=True, help="NAME=SCENE[:LIGHTS]")
    args = ap.parse_args()
    print("| case | proxy | lm ms | sm ms | lb ms | frame ms | peak MB | same values |")
    print("|---|---|--:|--:|--:|--:|--:|---|")
    for case in args.case:
        name, spec = case.split("=", 1)
        scene, _, lights = spec.partition(":")
        rows = {"true": [], "false": []}
        with tempfile.TemporaryDirectory() as tmp:
            for _ in range(args.runs):
                for proxy in ("false", "true"):
                    rows[proxy].append(run_once(args.bin, scene, lights, proxy,
                                                f"{tmp}/{proxy}", args.threads, args.size))
            same = same_pixels(f"{tmp}/true/gi.exr", f"{tmp}/false/gi.exr")
        for proxy in ("false", "true"):
            med = {k: statistics.median(r[k] for r in rows[proxy]) for k in rows[proxy][0]}
            print(f"| {name} | {proxy} | {med['lm']:.0f} | {med['sm']:.0f} | {med['lb']:.0f} | "
                  f"{med['total']:.0f} | {med['rss']:.0f} | "
                  f"{'-' if proxy == 'false' else ('yes' if same else 'no')} |")


if __name__ == "__main__":
    main()
