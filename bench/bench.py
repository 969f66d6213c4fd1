#!/usr/bin/env python3
"""Times every node of a graph over several runs and prints medians and peak memory.

    python3 bench/bench.py [--runs 7] [--bin build-bench/ssgraph] [--threads N]
                           [--graph graphs/ssao.graph ...] [--size 1280x720 ...] [--ao]
                           [--ssdo [--samples 12,24,36,64]] [--table1] [--backend]
                           [--hybrid] [--frame-budget]
                           [--accuracy [--part ao|gi] [--save docs/accuracy.md]]
                           [--gallery [--scenes a,b] [--lights own,sky] [--paths N]]

Each configuration runs `ssgraph run GRAPH --size WxH` RUNS times (after one warm-up run)
in a fresh process; the per-node milliseconds come from the timing table ssgraph prints,
the peak memory is the process's maximum resident set (getrusage of the child), which
includes the scene, Embree's BVH and the image pool. Without --bin it builds a Release
binary into build-bench/ first. Speed is compared by ratios of these medians, never by
timed assertions in tests.

--backend times each node on both backends (cpu, and gl: a GPU through EGL, else llvmpipe
through OSMesa), side by side, at 1280x720.

--hybrid times graphs/hybrid.graph (Knuth and Kohlhammer's hybrid AO) per frame for 128 and
512 lights and shadow maps of 256 and 1024 texels on both backends at 1280x720, with the
error of each image against reference_gi lit by the same probe (bench/hybrid_reference.graph),
next to the paper's 15 fps (128 lights) and 6 fps (512 lights).

--frame-budget measures the steady frame rates issue 17 set targets for: ssdo.graph at
1280x720 (30 fps), ssdo_realtime.graph at 1280x720 (60) and 1920x1080 (30), ssao.graph's
16-sample ssao node at 1920x1080 (8 ms) and hybrid.graph at 1280x720 (10 fps). Each run is
one process of --frames 10 whose median frame (or node run) is its steady time, so the
first frame's one-off page faults do not count; the table gives the median over runs.

--defaults-time times ssao.graph, hbao.graph and ssdo.graph at 1920x1080 with their shipped (tuned)
defaults and with the settings they replaced (medians, the ratio).

--accuracy scores every AO method of graphs/ao_error.graph against reference_ao on every
example scene (RMSE, bias = mean of method - reference, SSIM, with the frame time of the
shipped graph that runs it), and every GI pipeline of graphs/gi_error.graph and
graphs/hybrid_ssdo_error.graph against reference_gi on every example scene under its own
lights and each light of examples/lights/ (sun, sky, courtyard probe; a summary against
the SSAO baseline per light, and each bounce's energy against the reference's), as the
Markdown tables of docs/accuracy.md (--save it there).

--gallery writes docs/gallery.md: every shipped pipeline on every example scene with a still
camera beside converged truth (cached references), with error maps (FLIP) and crops of the
worst region (bench/gallery.py).

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


def run_once(binary, graph, size, threads, out_dir, extra=()):
    """One run in a child process: ({node: ms}, peak RSS in MiB of that child). GL nodes
    also give "<node> gpu": their timer-query milliseconds."""
    cmd = [binary, "run", graph, "--size", size, "--out", out_dir] + list(extra)
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
        if parts[:4] == ["node", "type", "on", "ms"]:
            table = "times"
        elif parts[:2] == ["metrics", "of"]:
            table = "metrics"
        elif parts and parts[0] == "PEAK_KB":
            peak = int(parts[1]) / 1024.0
        elif table == "times" and len(parts) >= 2:
            name = parts[0] if parts[0] == "total" else f"{parts[0]} ({parts[1]})"
            times[name] = float(parts[1] if parts[0] == "total" else parts[3])
            if parts[0] != "total" and len(parts) >= 5 and parts[4] != "-":
                times[name + " gpu"] = float(parts[4])
            if parts[0] == "total":  # the table ends here (a "GL: ..." line may follow)
                table = None
        elif table == "metrics" and len(parts) == 3:
            metrics[f"{parts[0]} {parts[1]}"] = float(parts[2])
    return times, metrics, peak


def bench(binary, graph, size, threads, runs, extra=()):
    with tempfile.TemporaryDirectory() as out_dir:
        # warm-up: page cache, first touch (and on GL the driver's shader cache)
        run_once(binary, graph, size, threads, out_dir, extra)
        samples = [run_once(binary, graph, size, threads, out_dir, extra) for _ in range(runs)]
    names = list(samples[0][0].keys())
    medians = {n: statistics.median(s[0][n] for s in samples) for n in names}
    spread = {n: (min(s[0][n] for s in samples), max(s[0][n] for s in samples)) for n in names}
    peak = statistics.median(s[2] for s in samples)
    return medians, spread, samples[0][1], peak


# issue 17's targets: (graph, size, node instance or None = the frame, target ms)
FRAME_BUDGET = [("ssdo.graph", "1280x720", None, 1000 / 30),
                ("ssdo_realtime.graph", "1280x720", None, 1000 / 60),
                ("ssdo_realtime.graph", "1920x1080", None, 1000 / 30),
                ("ssao.graph", "1920x1080", "ao", 8.0),
                ("hybrid.graph", "1280x720", None, 1000 / 10)]


def frame_budget_table(binary, threads, runs, frames=10):
    """Steady times against issue 17's targets: per run the median frame (or node run) of
    --frames FRAMES from --profile-json, then the median over runs."""
    print(f"{'graph':<22} {'size':<10} {'what':<10} {'median ms':>10} {'fps':>7} "
          f"{'min':>8} {'max':>8} {'target ms':>10} {'met':>4}")
    with tempfile.TemporaryDirectory() as tmp:
        for graph, size, node, target in FRAME_BUDGET:
            times = []
            for _ in range(runs):
                prof = os.path.join(tmp, "profile.json")
                cmd = [binary, "run", os.path.join(ROOT, "graphs", graph), "--size", size,
                       "--frames", str(frames), "--out", os.path.join(tmp, "out"),
                       "--profile-json", prof, "--quiet"]
                if threads:
                    cmd += ["--threads", str(threads)]
                run_cmd(cmd)
                p = json.load(open(prof))
                if node is None:
                    times.append(p["frame"]["median_ms"])
                else:
                    times.append(next(n["median_ms"] for n in p["nodes"] if n["name"] == node))
            ms = statistics.median(times)
            print(f"{graph:<22} {size:<10} {node or 'frame':<10} {ms:>10.2f} "
                  f"{1000 / ms:>7.1f} {min(times):>8.2f} {max(times):>8.2f} {target:>10.2f} "
                  f"{'yes' if ms <= target else 'no':>4}", flush=True)
    print(f"({runs} runs of {frames} frames each, medians; threads: "
          f"{threads or os.cpu_count()})")


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
          f"{'rmse':>8} {'flip':>7} {'ssim':>7}")
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
                          f"{err['flip']:>7.4f} {err['ssim']:>7.4f}")


PAPER_FPS = {128: 15, 512: 6}  # Knuth and Kohlhammer sec. 5, a GeForce 8 (2007)


def hybrid_table(binary, size, threads, runs):
    """Hybrid AO: median frame ms (every node but write; lightprobe's one-off conversion
    listed apart) for each light count, map resolution and backend, and the error against
    the ray-traced reference."""
    graph = os.path.join(ROOT, "graphs", "hybrid.graph")
    reference = os.path.join(ROOT, "bench", "hybrid_reference.graph")
    print(f"{'lights':>6} {'maps':>5} {'backend':<8} {'frame ms':>9} {'fps':>6} {'maps ms':>8} "
          f"{'global ms':>9} {'probe ms':>8} {'rmse':>8} {'flip':>7} {'ssim':>7} "
          f"{'paper fps':>9}")
    with tempfile.TemporaryDirectory() as tmp:
        ref_dir = os.path.join(tmp, "ref")
        run_cmd([binary, "run", reference, "--size", size, "--out", ref_dir, "--quiet"])
        ref = os.path.join(ref_dir, "reference.exr")
        for lights in (128, 512):
            for res in (256, 1024):
                for backend in ("cpu", "gl"):
                    out_dir = os.path.join(tmp, "hybrid")
                    rows = []
                    for i in range(runs + 1):
                        cmd = [binary, "run", graph, "--size", size, "--out", out_dir,
                               "--backend", backend, "--set", f"lp.count={lights}",
                               "--set", f"sm.resolution={res}"]
                        if threads:
                            cmd += ["--threads", str(threads)]
                        t = parse_times(run_cmd(cmd))
                        if i:  # the first run warms up (and compiles the shaders)
                            rows.append(t)
                    med = lambda key: statistics.median(r[key] for r in rows)
                    frames = [sum(ms for name, ms in r.items()
                                  if not name.endswith(("(write)", "(lightprobe)", " gpu")))
                              for r in rows]
                    frame = statistics.median(frames)
                    err = json.loads(run_cmd([binary, "compare",
                                              os.path.join(out_dir, "hybrid.exr"), ref,
                                              "--mask", ref + ":depth", "--json"]))
                    print(f"{lights:>6} {res:>5} {backend:<8} {frame:>9.1f} "
                          f"{1000 / frame:>6.2f} {med('sm (shadowmaps)'):>8.1f} "
                          f"{med('glob (probe_light)'):>9.1f} {med('lp (lightprobe)'):>8.1f} "
                          f"{err['rmse']:>8.4f} {err['flip']:>7.4f} {err['ssim']:>7.4f} "
                          f"{PAPER_FPS[lights]:>9}",
                          flush=True)
    print(f"({size}, {runs} runs each after a warm-up, medians; threads: "
          f"{threads or os.cpu_count()}; frame = every node but write and the one-off "
          f"lightprobe)")


TABLE1_ROWS = ["ssao_nosub_10", "ssdo_2step_10", "ssdo_nosub_10", "ssao_20", "ssdo_20",
               "ssdo_50", "ssdo_pre_20_50"]
TABLE1_SCENES = {"cornell": "cornell.scene", "pyramids": "pyramids.scene",
                 "bunny": "bunny.scene"}


def frame_ms(binary, graph, scene, size, threads, runs, out_dir):
    """Medians over runs after a warm-up: (ms of every node but write, ms of the
    screen-space passes alone: every node but gbuffer and write)."""
    frames, passes = [], []
    for i in range(runs + 1):
        cmd = [binary, "run", graph, "--scene", scene, "--size", size, "--out", out_dir]
        if threads:
            cmd += ["--threads", str(threads)]
        t = parse_times(run_cmd(cmd))
        if i:
            frame = sum(ms for name, ms in t.items() if not name.endswith("(write)"))
            frames.append(frame)
            passes.append(frame - sum(ms for name, ms in t.items()
                                      if name.endswith("(gbuffer)")))
    return statistics.median(frames), statistics.median(passes)


def table1(binary, size, threads, runs):
    """The rows of table 1 on its three scenes: ms per frame and error against truth."""
    reference = os.path.join(ROOT, "bench", "ssdo_reference.graph")
    print(f"{'scene':<9} {'graph':<16} {'frame ms':>9} {'passes':>7} {'rmse':>8} {'flip':>7} "
          f"{'ssim':>7} {'full passes':>12} {'speed-up':>9} {'full rmse':>10} {'error cost':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for label, scene_file in TABLE1_SCENES.items():
            scene = os.path.join(ROOT, "examples", scene_file)
            ref_dir = os.path.join(tmp, "ref_" + label)
            run_cmd([binary, "run", reference, "--scene", scene, "--size", size,
                     "--set", "ref.samples=64", "--out", ref_dir, "--quiet"])
            ref = os.path.join(ref_dir, "reference.exr")

            def score(out_dir):
                return json.loads(run_cmd([binary, "compare",
                                           os.path.join(out_dir, "table1.exr"), ref,
                                           "--mask", ref + ":depth", "--json"]))

            for row in TABLE1_ROWS:
                graph = os.path.join(ROOT, "graphs", "table1", row + ".graph")
                out_dir = os.path.join(tmp, "row")
                ms, passes = frame_ms(binary, graph, scene, size, threads, runs, out_dir)
                err = score(out_dir)
                line = (f"{label:<9} {row:<16} {ms:>9.1f} {passes:>7.1f} {err['rmse']:>8.4f} "
                        f"{err['flip']:>7.4f} {err['ssim']:>7.4f}")
                twin = os.path.join(ROOT, "bench", "table1_twins", row + "_full.graph")
                if os.path.exists(twin):
                    full_dir = os.path.join(tmp, "full")
                    _, full_passes = frame_ms(binary, twin, scene, size, threads, runs,
                                              full_dir)
                    full = score(full_dir)
                    cost = (err["rmse"] - full["rmse"]) / full["rmse"] * 100.0
                    line += (f" {full_passes:>12.1f} {full_passes / passes:>8.2f}x "
                             f"{full['rmse']:>10.4f} {cost:>+9.1f}%")
                print(line, flush=True)


def parse_times(stdout):
    times, table = {}, False
    for line in stdout.splitlines():
        parts = line.split()
        if parts[:4] == ["node", "type", "on", "ms"]:
            table = True
        elif table and len(parts) >= 4 and parts[0] != "total":
            times[f"{parts[0]} ({parts[1]})"] = float(parts[3])
        elif parts and parts[0] == "total":
            table = False
    return times


def backend_table(binary, graphs, size, threads, runs):
    """Each node's median ms on the CPU and on GL side by side (GL: wall clock until the
    GPU finished, and the timer query's GPU ms; llvmpipe through OSMesa without a GPU)."""
    print(f"{'graph':<22} {'node':<26} {'cpu ms':>9} {'gl ms':>9} {'gl gpu':>9} "
          f"{'cpu/gl':>7}")
    for graph in graphs:
        cpu, _, _, _ = bench(binary, graph, size, threads, runs, ["--backend", "cpu"])
        gl, _, _, _ = bench(binary, graph, size, threads, runs, ["--backend", "gl"])
        gname = os.path.relpath(graph, os.path.join(ROOT, "graphs"))
        for node, ms in cpu.items():
            if node.endswith(" gpu") or node not in gl:
                continue
            gpu = gl.get(node + " gpu")
            gpu_text = f"{gpu:>9.2f}" if gpu is not None else f"{'-':>9}"
            ratio = ms / gl[node] if gl[node] > 0 else float("inf")
            print(f"{gname:<22} {node:<26} {ms:>9.2f} {gl[node]:>9.2f} {gpu_text} "
                  f"{ratio:>7.2f}", flush=True)
    print(f"({size}, {runs} runs each after a warm-up; threads: {threads or os.cpu_count()})")


class Tee:
    """stdout that also goes, line by line, to a file (so a long run keeps its rows)."""

    def __init__(self, stream, path):
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        self.stream, self.file = stream, open(path, "w")

    def write(self, text):
        self.stream.write(text)
        self.file.write(text)
        self.file.flush()

    def flush(self):
        self.stream.flush()


# The settings the shipped defaults replaced, as --set lines on the shipped graphs: the
# papers' for ssao and hbao (issue 15, docs/occlusion.md, "How the defaults were chosen"),
# ssdo.graph's before issue 16 chose power 3 and strength 1 (docs/accuracy.md).
PAPER_SETTINGS = {
    "ssao.graph": ["k.falloff=2", "k.min_scale=0.1", "ao.bias=0.02", "ao.power=1",
                   "ao.range_check=smooth"],
    "hbao.graph": ["h.steps=4", "h.bias=0.1", "h.strength=1", "h.falloff=linear"],
    "ssdo.graph": ["do.power=1", "do.strength=4"],
}


def defaults_time_table(binary, size, threads, runs):
    """Frame time of each shipped AO graph with its tuned defaults against the same graph
    with the papers' settings: medians of whole frames (write excluded) and the ratio."""
    print(f"# Frame time of the tuned defaults against the settings they replaced, {size}\n")
    print(f"Medians of {runs} runs after a warm-up, {threads or os.cpu_count()} threads, write "
          "excluded; made by `python3 bench/bench.py --defaults-time`.\n")
    print("| graph | replaced settings ms | shipped defaults ms | ratio |")
    print("|---|---|---|---|")
    for graph, paper in PAPER_SETTINGS.items():
        path = os.path.join(ROOT, "graphs", graph)
        ms = []
        for extra in ([a for p in paper for a in ("--set", p)], []):
            medians, _, _, _ = bench(binary, path, size, threads, runs, extra)
            ms.append(sum(v for k, v in medians.items()
                          if k != "total" and not k.endswith("(write)") and
                          not k.endswith(" gpu")))
        print(f"| {graph} | {ms[0]:.1f} | {ms[1]:.1f} | {ms[1] / ms[0]:.2f} |")


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
    ap.add_argument("--table1", action="store_true",
                    help="table 1 of Szentandrasi: graphs/table1/ on three scenes, ms per "
                         "frame and error, subsampled rows against full-resolution twins")
    ap.add_argument("--backend", action="store_true",
                    help="each node's median ms on cpu and on gl side by side (default "
                         "graphs: ssao, hbao, ssdo at 1280x720)")
    ap.add_argument("--save", metavar="FILE",
                    help="also write what is printed to FILE (e.g. bench/results/table1.txt)")
    ap.add_argument("--accuracy", action="store_true",
                    help="every AO method's RMSE, bias and SSIM against reference_ao on every "
                         "example scene, with its graph's frame time (a Markdown table; "
                         "default 640x480; --save docs/accuracy.md)")
    ap.add_argument("--defaults-time", action="store_true",
                    help="frame time of ssao.graph and hbao.graph with their tuned defaults "
                         "against the papers' settings (default 1920x1080)")
    ap.add_argument("--frame-budget", action="store_true",
                    help="steady frame rates (median frame of 10) of the SSDO, SSAO and hybrid "
                         "pipelines against issue 17's targets")
    ap.add_argument("--part", choices=["ao", "gi"],
                    help="with --accuracy: only the AO table or only the GI tables")
    ap.add_argument("--hybrid", action="store_true",
                    help="hybrid AO: ms per frame for 128/512 lights and 256/1024 maps on "
                         "both backends, error against reference_gi, the paper's fps")
    ap.add_argument("--gallery", action="store_true",
                    help="every pipeline on every still example scene beside converged "
                         "truth, error maps and crops: docs/gallery.md (bench/gallery.py; "
                         "default 320x180)")
    ap.add_argument("--paths", type=int, default=4096,
                    help="with --gallery and --accuracy: reference_gi paths a pixel")
    ap.add_argument("--rays", type=int, default=4096,
                    help="with --gallery and --accuracy: reference_ao rays a pixel")
    ap.add_argument("--scenes", help="with --gallery and --accuracy: comma-separated scene "
                                     "names (default: every still example scene)")
    ap.add_argument("--lights", default="own,sky,courtyard",
                    help="with --gallery: lightings, of own, sky, courtyard, sun")
    ap.add_argument("--gallery-out", default=os.path.join(ROOT, "docs", "gallery.md"),
                    help="with --gallery: the Markdown file (its images go to "
                         "docs/images/gallery beside it unless --gallery-images)")
    ap.add_argument("--gallery-images", help="with --gallery: the folder of its pictures")
    ap.add_argument("--pipelines", help="with --gallery: comma-separated pipeline names "
                                        "(default: all)")
    ap.add_argument("--self-error", action="store_true",
                    help="with --gallery: a second reference per case with another seed, "
                         "to state the truth's own noise")
    args = ap.parse_args()
    if args.save:
        sys.stdout = Tee(sys.stdout, args.save)
    binary = args.bin or build()
    if args.gallery:
        from accuracy import still_scenes
        from gallery import gallery
        scenes = args.scenes.split(",") if args.scenes else [
            f[:-len(".scene")] for f in still_scenes()]
        images = args.gallery_images or os.path.join(
            os.path.dirname(os.path.abspath(args.gallery_out)), "images", "gallery")
        gallery(binary, (args.size or ["320x180"])[0], args.paths, args.rays, scenes,
                args.lights.split(","), images, args.gallery_out, args.self_error,
                args.pipelines.split(",") if args.pipelines else None)
        return
    if args.accuracy:
        from accuracy import accuracy_table, gi_accuracy_table  # the tables' own module
        size = (args.size or ["640x480"])[0]
        only = args.scenes.split(",") if args.scenes else None
        if args.part != "gi":
            accuracy_table(binary, size, args.threads, args.runs, args.rays, only)
        if args.part != "ao":
            gi_accuracy_table(binary, size, args.threads, args.runs, args.paths, only)
        return
    if args.frame_budget:
        frame_budget_table(binary, args.threads, args.runs)
        return
    if args.defaults_time:
        defaults_time_table(binary, (args.size or ["1920x1080"])[0], args.threads, args.runs)
        return
    if args.hybrid:
        hybrid_table(binary, (args.size or ["1280x720"])[0], args.threads, args.runs)
        return
    if args.backend:
        graphs = args.graph or [os.path.join(ROOT, "graphs", g) for g in
                                ("ssao.graph", "hbao.graph", "ssdo.graph")]
        backend_table(binary, graphs, (args.size or ["1280x720"])[0], args.threads, args.runs)
        return
    if args.table1:
        table1(binary, (args.size or ["1024x768"])[0], args.threads, args.runs)
        return
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
