#!/usr/bin/env python3
"""Times every node of a graph over several runs and prints medians and peak memory.

    python3 bench/bench.py [--runs 7] [--bin build-bench/ssgraph] [--threads N]
                           [--graph graphs/ssao.graph ...] [--size 1280x720 ...] [--ao]
                           [--ssdo [--samples 12,24,36,64]]

Each configuration runs `ssgraph run GRAPH --size WxH` RUNS times (after one warm-up run)
in a fresh process; the per-node milliseconds come from the timing table ssgraph prints,
the peak memory is the process's maximum resident set (getrusage of the child), which
includes the scene, Embree's BVH and the image pool. Without --bin it builds a Release
binary into build-bench/ first. Speed is compared by ratios of these medians, never by
timed assertions in tests.

--ssdo times graphs/ssdo.graph on the Cornell box for each kernel size K and with the
bounce on and off (the `do` node's median ms), and scores each final image against
reference_gi (bench/ssdo_reference.graph, made once per size) with `ssgraph compare`.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build():
    bdir = os.path.join(ROOT, "build-bench")
    subprocess.run(["cmake", "-S", ROOT, "-B", bdir, "-DCMAKE_BUILD_TYPE=Release"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", bdir, "-j", str(os.cpu_count() or 2)], check=True,
                   stdout=subprocess.DEVNULL)
    return os.path.join(bdir, "ssgraph")


def run_once(binary, graph, size, threads, out_dir):
    """One run in a child process: ({node: ms}, peak RSS in MiB of that child)."""
    cmd = [binary, "run", graph, "--size", size, "--out", out_dir]
    if threads:
        cmd += ["--threads", str(threads)]
    # ru_maxrss of RUSAGE_CHILDREN is the largest of all children so far, so each run is
    # measured through a fresh wrapper process that reports its own child's peak.
    wrapper = ("import resource,subprocess,sys;"
               "r=subprocess.run(sys.argv[1:],capture_output=True,text=True);"
               "sys.stdout.write(r.stdout);sys.stderr.write(r.stderr);"
               "print('PEAK_KB',resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss);"
               "sys.exit(r.returncode)")
    res = subprocess.run([sys.executable, "-c", wrapper] + cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f"bench: {' '.join(cmd)} failed:\n{res.stderr}")
    times, metrics, peak = {}, {}, 0.0
    table = None
    for line in res.stdout.splitlines():
        parts = line.split()
        if parts[:3] == ["node", "type", "ms"]:
            table = "times"
        elif parts[:2] == ["metrics", "of"]:
            table = "metrics"
        elif parts and parts[0] == "PEAK_KB":
            peak = int(parts[1]) / 1024.0
        elif table == "times" and len(parts) >= 2:
            name = parts[0] if parts[0] == "total" else f"{parts[0]} ({parts[1]})"
            times[name] = float(parts[1] if parts[0] == "total" else parts[2])
        elif table == "metrics" and len(parts) == 3:
            metrics[f"{parts[0]} {parts[1]}"] = float(parts[2])
    return times, metrics, peak


def bench(binary, graph, size, threads, runs):
    with tempfile.TemporaryDirectory() as out_dir:
        run_once(binary, graph, size, threads, out_dir)  # warm-up: page cache, first touch
        samples = [run_once(binary, graph, size, threads, out_dir) for _ in range(runs)]
    names = list(samples[0][0].keys())
    medians = {n: statistics.median(s[0][n] for s in samples) for n in names}
    spread = {n: (min(s[0][n] for s in samples), max(s[0][n] for s in samples)) for n in names}
    peak = statistics.median(s[2] for s in samples)
    return medians, spread, samples[0][1], peak


def run_cmd(cmd):
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f"bench: {' '.join(cmd)} failed:\n{res.stderr}")
    return res.stdout


def ssdo_table(binary, sizes, threads, runs, samples):
    """SSDO's median ms for each K and bounce setting, with its error against truth."""
    graph = os.path.join(ROOT, "graphs", "ssdo.graph")
    reference = os.path.join(ROOT, "bench", "ssdo_reference.graph")
    print(f"{'size':<10} {'K':>4} {'bounce':>7} {'ssdo ms':>9} {'min':>8} {'max':>8} "
          f"{'rmse':>8} {'ssim':>7}")
    with tempfile.TemporaryDirectory() as tmp:
        for size in sizes:
            ref_dir = os.path.join(tmp, "ref_" + size)
            run_cmd([binary, "run", reference, "--size", size, "--out", ref_dir, "--quiet"])
            ref = os.path.join(ref_dir, "reference.exr")
            for k in samples:
                for bounce in ("false", "true"):
                    sets = ["--set", f"k.count={k}", "--set", f"do.bounce={bounce}"]
                    out_dir = os.path.join(tmp, "ssdo")
                    cmd_graph = graph
                    times = []
                    for i in range(runs + 1):
                        cmd = [binary, "run", cmd_graph, "--size", size, "--out", out_dir] + sets
                        if threads:
                            cmd += ["--threads", str(threads)]
                        t = parse_times(run_cmd(cmd))
                        if i:  # the first run warms up
                            times.append(t["do (ssdo)"])
                    err = json.loads(run_cmd([binary, "compare",
                                              os.path.join(out_dir, "ssdo.exr"), ref,
                                              "--mask", ref + ":depth", "--json"]))
                    print(f"{size:<10} {k:>4} {bounce:>7} {statistics.median(times):>9.2f} "
                          f"{min(times):>8.2f} {max(times):>8.2f} {err['rmse']:>8.4f} "
                          f"{err['ssim']:>7.4f}")


def parse_times(stdout):
    times, table = {}, False
    for line in stdout.splitlines():
        parts = line.split()
        if parts[:3] == ["node", "type", "ms"]:
            table = True
        elif table and len(parts) >= 3 and parts[0] != "total":
            times[f"{parts[0]} ({parts[1]})"] = float(parts[2])
        elif parts and parts[0] == "total":
            table = False
    return times


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--bin")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--graph", action="append")
    ap.add_argument("--size", action="append")
    ap.add_argument("--ao", action="store_true",
                    help="the AO comparison: graphs/ao_error.graph (each AO method's time "
                         "and its error against the ray-traced reference)")
    ap.add_argument("--ssdo", action="store_true",
                    help="SSDO's time over kernel sizes, bounce on/off, and its error "
                         "against reference_gi on the Cornell box")
    ap.add_argument("--samples", default="12,24,36,64",
                    help="--ssdo: kernel sizes K, comma-separated")
    args = ap.parse_args()
    binary = args.bin or build()
    if args.ssdo:
        ssdo_table(binary, args.size or ["1280x720", "1920x1080"], args.threads, args.runs,
                   [int(k) for k in args.samples.split(",")])
        return
    if args.ao:
        graphs = [os.path.join(ROOT, "graphs", "ao_error.graph")]
    else:
        graphs = args.graph or [os.path.join(ROOT, "graphs", "ssao.graph"),
                                os.path.join(ROOT, "graphs", "ssao_bunny.graph")]
    sizes = args.size or ["1280x720", "1920x1080"]
    print(f"{'graph':<18} {'size':<10} {'node':<24} {'median ms':>10} {'min':>8} {'max':>8}")
    for graph in graphs:
        for size in sizes:
            medians, spread, metrics, peak = bench(binary, graph, size, args.threads, args.runs)
            gname = os.path.basename(graph)
            for node, ms in medians.items():
                lo, hi = spread[node]
                print(f"{gname:<18} {size:<10} {node:<24} {ms:>10.2f} {lo:>8.2f} {hi:>8.2f}")
            print(f"{gname:<18} {size:<10} {'peak memory (MiB)':<24} {peak:>10.1f}")
            # compare nodes' metrics (deterministic, so one run's values are the values)
            for name, value in metrics.items():
                print(f"{gname:<18} {size:<10} {name:<24} {value:>10.4f}   (metric)")
    print(f"({args.runs} runs each after a warm-up; threads: "
          f"{args.threads or os.cpu_count()})")


if __name__ == "__main__":
    main()
