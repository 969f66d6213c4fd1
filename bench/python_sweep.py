#!/usr/bin/python3
"""python_sweep.py - a parameter sweep from Python on one loaded graph against the same
sweep as separate CLI runs (issue 33's acceptance: at least 3x faster).

    bench/python_sweep.py --ssgraph build/ssgraph --size 640x360 --repeats 3 \
        --markdown bench/results/python_sweep.md

Both sweep ao.radius over 20 values of graphs/ssao.graph and end with the filtered AO of
each value in hand: the CLI as `ssgraph run --set ao.radius=R --quiet` (each run loads the
scene, builds its ray-tracing structure, renders the G-buffer, runs every node and writes
the EXR and PNG; the script reads nothing back), Python as ssgraph.load once, then set,
run and output("b.out") per value (only the SSAO node, its filter and the shading run
again). Each sweep is timed whole, `--repeats` times, alternating; the medians are
compared. Needs the ssgraph package installed (docs/python.md).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import ssgraph

RADII = [0.1 + 0.9 * i / 19 for i in range(20)]


def cli_sweep(exe, graph, size, threads, out):
    for r in RADII:
        subprocess.run([exe, "run", graph, "--size", size, "--threads", str(threads),
                        "--set", "ao.radius=%r" % r, "--quiet", "--out", out], check=True)


def python_sweep(graph, size, threads):
    with ssgraph.load(graph, size=size) as g:
        for r in RADII:
            g.set("ao.radius", r).run(threads=threads).output("b.out")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--ssgraph", default="build/ssgraph")
    p.add_argument("--graph", default="graphs/ssao.graph")
    p.add_argument("--size", default="640x360")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--markdown", help="write the result table here too")
    a = p.parse_args()
    if not os.access(a.ssgraph, os.X_OK):
        sys.exit("python_sweep.py: no ssgraph command at %s (--ssgraph)" % a.ssgraph)
    cli, py = [], []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(a.repeats):
            t = time.perf_counter()
            cli_sweep(a.ssgraph, a.graph, a.size, a.threads, out)
            cli.append(time.perf_counter() - t)
            t = time.perf_counter()
            python_sweep(a.graph, a.size, a.threads)
            py.append(time.perf_counter() - t)
    c, q = statistics.median(cli), statistics.median(py)
    lines = ["| sweep of 20 radii, %s, %s, %d threads | median s | runs (s) |" % (
                 a.graph, a.size, a.threads),
             "|---|--:|---|",
             "| 20 CLI runs (`ssgraph run --set ao.radius=R`) | %.2f | %s |" % (
                 c, ", ".join("%.2f" % v for v in cli)),
             "| Python: one load, 20 x set + run + output | %.2f | %s |" % (
                 q, ", ".join("%.2f" % v for v in py)),
             "",
             "Python is **%.1fx** faster (median over median)." % (c / q)]
    print("\n".join(lines))
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("# A 20-value parameter sweep: Python on one loaded graph against 20 CLI "
                    "runs\n\nMeasured by bench/python_sweep.py (its docstring says what each "
                    "side does):\n\n    bench/python_sweep.py --ssgraph %s --size %s "
                    "--threads %d --repeats %d --markdown %s\n\n" % (
                        a.ssgraph, a.size, a.threads, a.repeats, a.markdown))
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
