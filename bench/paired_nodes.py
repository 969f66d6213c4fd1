#!/usr/bin/env python3
"""paired_nodes.py - one graph's single-run cost, node by node, against another build:
runs OLD (a build of another commit, with the graphs of its own checkout) and NEW (this
checkout's) alternately, PAIRS times in one sitting (every other pair new first), and prints each node's median time
(ms, write excluded), the sum of those medians and its ratio, then the medians of the runs'
totals and their ratio. Only pairs mean anything on a machine whose speed drifts between
sittings; a single node's spike moves a total's median, not a node's.

    python3 bench/paired_nodes.py --old OLD_BUILD/ssgraph --old-graphs OLD_CHECKOUT/graphs
        [--bin build-test/ssgraph] [--graph gi.graph] [--size 1280x720] [--threads 2]
        [--pairs 9] [--scene S.scene] [--lights L.scene] [--set NODE.P=VALUE ...]
        [--frames N] [--new-graph G]
        (--set, --new-graph: the new run only; --scene, --lights, --frames: both runs)

--frames N runs N frames a run (a sequence: on a scene with a camera path the camera moves
every frame): a node's time is then its average over the calls it made, and a run's total
the median frame ssgraph printed (nodes kept from frame 0 cost nothing in the others).
--new-graph runs another graph for the new side (a successor of --graph).

bench/results/issue44/t44d/README.md ("The frame time") was made with it against b22328e.
Two copies of one build, one run through a wrapper that sets LD_LIBRARY_PATH, differed by
5 % (83.6 against 87.6 ms a frame, ssdo.graph, 8 pairs): read differences of that size as
noise (bench/results/issue47/README.md).
"""
import argparse
import collections
import os
import re
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROW = re.compile(r"^\s*(\S+)\s+(\S+)\s+(cpu|gl)\s+(?:(\d+)\s+)?([\d.]+)")
MEDIAN_FRAME = re.compile(r"median frame ([\d.]+) ms")


def node_times(binary, graph, size, threads, out, sets, scene_args=(), frames=1):
    """({node: ms}, median frame ms or None) of one run's node table, write excluded."""
    cmd = [binary, "run", graph, "--size", size, "--threads", str(threads), "--out", out]
    if frames > 1:
        cmd += ["--frames", str(frames)]
    cmd += list(scene_args)
    for s in sets:
        cmd += ["--set", s]
    text = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          check=True).stdout
    times, median = {}, None
    for line in text.splitlines():
        m = ROW.match(line)
        if m and m.group(2) != "write":
            times[m.group(1)] = float(m.group(5))
        f = MEDIAN_FRAME.search(line)
        if f:
            median = float(f.group(1))
    return times, median


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--old", required=True, help="the other build's ssgraph")
    ap.add_argument("--old-graphs", required=True, help="the graphs/ folder of its checkout")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build-test", "ssgraph"))
    ap.add_argument("--graph", default="gi.graph")
    ap.add_argument("--size", default="1280x720")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--pairs", type=int, default=9)
    ap.add_argument("--scene", help="a scene file for both runs (default: the graph's)")
    ap.add_argument("--lights", help="a lights file for both runs (examples/lights/)")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--frames", type=int, default=1)
    ap.add_argument("--new-graph", help="the new side's graph (default: --graph)")
    a = ap.parse_args()
    scene_args = (["--scene", os.path.abspath(a.scene)] if a.scene else []) + \
        (["--lights", os.path.abspath(a.lights)] if a.lights else [])
    old_runs, new_runs = collections.defaultdict(list), collections.defaultdict(list)
    old_totals, new_totals = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for pair in range(a.pairs):
            sides = [(a.old, os.path.join(a.old_graphs, a.graph), [], old_runs, old_totals),
                     (a.bin, os.path.join(ROOT, "graphs", a.new_graph or a.graph), a.set,
                      new_runs, new_totals)]
            # every other pair runs the new side first, so that an order effect cancels
            for binary, graph, sets, runs, totals in sides[::-1] if pair % 2 else sides:
                t, median = node_times(binary, graph, a.size, a.threads, tmp, sets,
                                       scene_args, a.frames)
                for node, ms in t.items():
                    if node != "frame":
                        runs[node].append(ms)
                totals.append(median if a.frames > 1 and median else
                              sum(v for k, v in t.items() if k != "frame"))
    med = lambda v: statistics.median(v) if v else 0.0
    where = "".join(f" {k} {os.path.relpath(v, ROOT)}" for k, v in
                    (("on", a.scene), ("under", a.lights)) if v)
    name = a.graph + (f" (new: {a.new_graph})" if a.new_graph else "")
    frames = f", {a.frames} frames a run (node: average a call)" if a.frames > 1 else ""
    print(f"{name}{where} at {a.size}, {a.threads} threads, {a.pairs} pairs{frames}; ms, "
          "medians\n")
    print("| node | old | new |")
    print("|---|--:|--:|")
    sum_old = sum_new = 0.0
    for node in dict.fromkeys(list(old_runs) + list(new_runs)):
        o, n = med(old_runs[node]), med(new_runs[node])
        sum_old, sum_new = sum_old + o, sum_new + n
        print(f"| {node} | {o:.1f} | {n:.1f} |")
    print(f"| **sum of medians** | **{sum_old:.1f}** | **{sum_new:.1f} "
          f"({sum_new / sum_old:.2f}x)** |")
    what = "median frames" if a.frames > 1 else "totals"
    print(f"\nmedians of the runs' {what}: old {med(old_totals):.1f}, new {med(new_totals):.1f} "
          f"({med(new_totals) / med(old_totals):.2f}x)")


if __name__ == "__main__":
    main()
