#!/usr/bin/env python3
"""same_bytes.py - every graph's files from two builds, compared byte for byte.

    python3 bench/same_bytes.py --old OLD_BUILD/ssgraph [--new build-test/ssgraph]
        [--size 160x90] [--threads 1,2] [--frames 1] [--scene S.scene] [GRAPH ...]

Runs each graph (default: every graphs/*.graph and graphs/table1/*.graph) with both
executables, from this checkout's graph files, at each thread count, into separate
folders, and compares every file the two runs wrote (EXR, PNG, metrics) with `cmp`'s
rule: the same bytes or not. A speed-up that keeps a method must keep its bytes (issue
47); a graph whose method changed on purpose shows up here, to be named. The files record
the graph's path, not the build, so the same graph file gives comparable files. Prints
one line a graph and thread count, then a summary; exits 1 when anything differs or
failed in one build only.
"""
import argparse
import filecmp
import glob
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(binary, graph, out, size, threads, frames, scene):
    cmd = [binary, "run", graph, "--size", size, "--threads", str(threads), "--out", out,
           "--quiet"]
    if frames > 1:
        cmd += ["--frames", str(frames)]
    if scene:
        cmd += ["--scene", scene]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       cwd=ROOT)
    return p.returncode, p.stdout.strip().splitlines()[-1:] if p.stdout.strip() else []


def compare(a, b):
    """'same', or what differs between folders a and b."""
    fa = sorted(os.listdir(a)) if os.path.isdir(a) else []
    fb = sorted(os.listdir(b)) if os.path.isdir(b) else []
    if fa != fb:
        return "different files: %s / %s" % (fa, fb)
    bad = [f for f in fa if not filecmp.cmp(os.path.join(a, f), os.path.join(b, f),
                                            shallow=False)]
    return "same" if not bad else "differ: " + ", ".join(bad)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--old", required=True)
    ap.add_argument("--new", default=os.path.join(ROOT, "build-test", "ssgraph"))
    ap.add_argument("--size", default="160x90")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--frames", type=int, default=1)
    ap.add_argument("--scene")
    ap.add_argument("graphs", nargs="*")
    a = ap.parse_args()
    graphs = a.graphs or sorted(glob.glob(os.path.join(ROOT, "graphs", "*.graph")) +
                                glob.glob(os.path.join(ROOT, "graphs", "table1", "*.graph")))
    scene = os.path.abspath(a.scene) if a.scene else None
    counts = {"same": 0, "differ": 0, "failed": 0}
    with tempfile.TemporaryDirectory() as tmp:
        for graph in graphs:
            name = os.path.relpath(os.path.abspath(graph), ROOT)
            for threads in (int(t) for t in a.threads.split(",")):
                outs = []
                codes = []
                for side, binary in (("old", a.old), ("new", a.new)):
                    out = os.path.join(tmp, "%s_%s_%d" % (side, name.replace("/", "_"), threads))
                    code, last = run(binary, os.path.abspath(graph), out, a.size, threads,
                                     a.frames, scene)
                    outs.append(out)
                    codes.append((code, last))
                if codes[0][0] or codes[1][0]:
                    what = "failed (old %d, new %d): %s" % (codes[0][0], codes[1][0],
                                                          (codes[1][1] or codes[0][1]))
                    counts["failed" if codes[0][0] != codes[1][0] else "same"] += 1
                else:
                    what = compare(*outs)
                    counts["same" if what == "same" else "differ"] += 1
                print("%-40s threads %d: %s" % (name, threads, what), flush=True)
    print("\n%d same, %d differ, %d failed in one build only (%s, %d frame%s)" % (
        counts["same"], counts["differ"], counts["failed"], a.size, a.frames,
        "s" if a.frames > 1 else ""))
    sys.exit(1 if counts["differ"] or counts["failed"] else 0)


if __name__ == "__main__":
    main()
