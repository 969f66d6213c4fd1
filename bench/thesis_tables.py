#!/usr/bin/env python3
"""The tables of sections 5.1.1 and 5.2 of the thesis (Belonogov, "Global Illumination methods in
simulated VR environments"): ms of SSAO, HBAO, SSDO and SSDO with one bounce over the
kernel size N = 12, 24, 36, 64 and the radius r at 800x600 and for both eyes of a
head-mounted display at 1080x1200 (--stereo), and figure 5.2 (ms against N
per method, averaged over r), measured with `ssgraph bench` on the Cornell box.

    python3 bench/thesis_tables.py [--bin build-bench/ssgraph] [--frames 5]
                                   [--out bench/results/thesis]

Each method is one `ssgraph bench` (its bench.csv, bench.md, bench.json and plots stay in
OUT/<method>/); OUT/README.md puts our tables next to the thesis's and OUT/fig52.png draws
the figure with gnuplot. Radii: the thesis's r = 2, 4, 8 are units of its city scene; the
Cornell box is 2 units wide, so r = 0.1, 0.2, 0.4 here (the same doubling). HBAO's N is
directions x steps: 4 steps and 3, 6, 9, 16 directions. The timed node is the method's own
pass (--time), as the thesis's profiler timed the method's shader calls."""
import argparse
import csv
import os
import platform
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench import build  # noqa: E402  (the one Release build of the benchmarks)
N = [12, 24, 36, 64]
R = ["0.1", "0.2", "0.4"]
# method: (graph, timed node, kernel sweep, radius key, extra --set)
METHODS = {
    "SSAO": ("ssao.graph", "ao", "k.count=12,24,36,64", "ao.radius", []),
    "HBAO": ("hbao.graph", "h", "h.directions=3,6,9,16", "h.radius", ["h.steps=4"]),
    "SSDO": ("ssdo.graph", "do", "k.count=12,24,36,64", "do.radius", ["do.bounce=false"]),
    "SSDO+": ("ssdo.graph", "do", "k.count=12,24,36,64", "do.radius", ["do.bounce=true"]),
}
# The thesis's section 5.2 values: both eyes of an HTC Vive, 1080x1200 each (GTX 1080 Ti).
THESIS_VR = {
    "SSAO": [[1.7, 1.8, 1.7], [3, 3.1, 3.2], [4.2, 4.3, 4.6], [6.6, 7.4, 7.8]],
    "HBAO": [[2.03, 2.3, 2.49], [3.13, 4.5, 4.92], [4.15, 6.4, 6.9], [7, 9.8, 10.8]],
    "SSDO": [[7, 7.36, 8], [11, 13.2, 14.1], [16.6, 17.7, 18.2], [31, 31.92, 32.71]],
    "SSDO+": [[8.2, 9.2, 9.4], [14.9, 17.9, 18.1], [21.4, 23.3, 23.7], [37.7, 41.1, 43.7]],
}
# The thesis's table values (ms, GeForce GTX 960, Halifaxstrasse scene), rows N, columns r.
THESIS = {
    "SSAO": [[0.78, 1.03, 1.2], [1.14, 1.61, 2], [1.36, 2, 2.4], [2.28, 3.46, 4.3]],
    "HBAO": [[1.2, 1.44, 1.54], [1.7, 2.16, 2.55], [2.14, 2.8, 3.35], [3.14, 4.3, 5.36]],
    "SSDO": [[1.6, 2.8, 2.5], [3.2, 4, 4.9], [4.5, 5.1, 6.52], [8.2, 10.4, 11.8]],
    "SSDO+": [[1.9, 2.5, 3.08], [3.8, 5, 5.9], [5.1, 6.7, 7.9], [10.2, 13.2, 15.6]],
}


def run_method(binary, name, out, frames, stereo=False):
    graph, node, kernel, radius, sets = METHODS[name]
    out = os.path.join(out, "vr") if stereo else out
    size = ["--stereo"] if stereo else ["--size", "800x600"]
    # The graph as a path relative to the repository (the command runs there): bench
    # records it as given, and committed results must not name this machine's folders.
    cmd = [binary, "bench", os.path.join("graphs", graph)] + size + [
           "--frames", str(frames), "--sweep", kernel, "--sweep", f"{radius}=" + ",".join(R),
           "--time", node, "--plot", "--out", os.path.join(out, name.replace("+", "_bounce"))]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, cwd=ROOT)
    method_dir = os.path.join(out, name.replace("+", "_bounce"))
    shutil.rmtree(os.path.join(method_dir, "cells"), ignore_errors=True)  # the images: MBs
    with open(os.path.join(method_dir, "bench.csv")) as f:
        rows = list(csv.DictReader(f))
    ms = {}
    for row in rows:
        # medians: robust against a busy machine's outliers, as bench's own tables
        times = dict(kv.split("=") for kv in row["node_median_ms"].split(";"))
        ms[(row[kernel.split("=")[0]], row[radius])] = float(times[node])
    kvals = kernel.split("=")[1].split(",")
    return [[ms[(k, r)] for r in R] for k in kvals]


def table(name, ours, thesis=THESIS):
    lines = [f"| {name} | " + " | ".join(f"r = {r} (thesis r = {t})" for r, t in
                                        zip(R, (2, 4, 8))) + " |",
             "|---|---|---|---|"]
    for i, n in enumerate(N):
        cells = [f"{ours[i][j]:.2f} ({thesis[name][i][j]})" for j in range(3)]
        lines.append(f"| N = {n} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def figure(out, results):
    dat = os.path.join(out, "fig52.dat")
    with open(dat, "w") as f:
        for name, ours in results.items():
            f.write(f'"{name} (ssgraph, CPU)"\n')
            for i, n in enumerate(N):
                f.write(f"{n} {sum(ours[i]) / 3:.4f}\n")
            f.write("\n\n")
        for name in results:
            f.write(f'"{name} (thesis, GTX 960)"\n')
            for i, n in enumerate(N):
                f.write(f"{n} {sum(THESIS[name][i]) / 3:.4f}\n")
            f.write("\n\n")
    gp = os.path.join(out, "fig52.gp")
    count = 2 * len(results)
    with open(gp, "w") as f:
        f.write("set terminal pngcairo size 900,600 enhanced font 'sans,11'\n"
                "set output 'fig52.png'\nset title 'ms against N, averaged over r "
                "(thesis figure 5.2), 800x600'\nset xlabel 'N'\nset ylabel 'ms'\n"
                "set grid\nset key outside right top noenhanced\nset logscale y\n")
        series = [f"'fig52.dat' index {i} using 1:2 with linespoints lw 2 "
                  f"dt {1 if i < count // 2 else 2} lc {i % (count // 2) + 1} "
                  "title columnheader(1)" for i in range(count)]
        f.write("plot " + ", ".join(series) + "\n")
    subprocess.run(["gnuplot", "fig52.gp"], cwd=out, check=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin")
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "thesis"))
    args = ap.parse_args()
    binary = os.path.abspath(args.bin) if args.bin else build()  # the bench runs in ROOT
    args.out = os.path.abspath(args.out)
    os.makedirs(args.out, exist_ok=True)
    results = {name: run_method(binary, name, args.out, args.frames) for name in METHODS}
    vr = {name: run_method(binary, name, args.out, args.frames, stereo=True)
          for name in METHODS}
    figure(args.out, results)
    cpu = platform.processor() or platform.machine()
    with open(os.path.join(args.out, "README.md"), "w") as f:
        f.write("# Thesis sections 5.1.1 and 5.2 on ssgraph\n\nms of each method's own pass at 800x600 "
                f"on the Cornell box, ssgraph's CPU backend, {os.cpu_count()} threads "
                f"({cpu}), median of {args.frames} frames per cell after the nodes were "
                "prepared; in brackets the thesis's ms (GeForce GTX 960, its city scene). "
                "Made by `python3 bench/thesis_tables.py`.\n\n")
        for name, ours in results.items():
            f.write(table(name, ours) + "\n\n")
        f.write("![ms against N](fig52.png)\n\n## Section 5.2: both eyes of a head-mounted "
                "display\n\n`--stereo`: each pass for both eyes, 1080x1200 each (the HTC "
                "Vive's panels), camera moved 0.032 left and right; in brackets the thesis's "
                "(GTX 1080 Ti).\n\n")
        for name, ours in vr.items():
            f.write(table(name, ours, THESIS_VR) + "\n\n")
    print(open(os.path.join(args.out, "README.md")).read())


if __name__ == "__main__":
    sys.exit(main())
