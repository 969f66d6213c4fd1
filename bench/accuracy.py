"""accuracy.py - the tables of docs/accuracy.md for `bench.py --accuracy`: every AO method
of graphs/ao_error.graph against reference_ao, and every GI pipeline of graphs/gi_error.graph
and graphs/hybrid_ssdo_error.graph against reference_gi under each scene's own lights and
each light of examples/lights, with the bounce's energy against the reference's."""
import json
import os
import re
import tempfile

from bench import ROOT, frame_ms, run_cmd

ACCURACY_METHODS = [("ssao", "c_ssao", None), ("ssao + bilateral", "c_ssao_filtered", "ssao.graph"),
                    ("hbao", "c_hbao", None), ("hbao + bilateral", "c_hbao_filtered", "hbao.graph"),
                    ("gtao", "c_gtao", None), ("gtao + bilateral", "c_gtao_filtered", "gtao.graph")]



def still_scenes(only=None):
    """The example scenes with a still camera: the single-frame tables score frame 0 of one
    view; a scene whose camera moves (camera_key, orbit: docs/time.md) is a sequence's.
    only: scene names (without .scene) to keep, None = all."""
    folder = os.path.join(ROOT, "examples")
    moving = re.compile(r"^\s*(camera_key|orbit)\(", re.M)
    return sorted(f for f in os.listdir(folder) if f.endswith(".scene") and
                  not moving.search(open(os.path.join(folder, f)).read()) and
                  (only is None or f[:-len(".scene")] in only))

def accuracy_table(binary, size, threads, runs, rays=4096, only=None):
    """Every AO method of graphs/ao_error.graph against reference_ao on every example scene:
    RMSE, FLIP (compare's LDR-FLIP of the grey AO, mean over the surface pixels), bias (mean
    of method - reference: > 0 = too bright, missed occlusion) and SSIM, and the frame time
    (median, write excluded) of the shipped graph that runs the method."""
    ao_error = os.path.join(ROOT, "graphs", "ao_error.graph")
    scenes = still_scenes(only)
    print(f"# AO accuracy of the shipped graphs, {size}\n")
    print("Each AO method of `graphs/ao_error.graph` against `reference_ao` "
          f"({rays} cosine-weighted rays within the same 0.5 radius: converged, its own noise "
          f"about {0.01 * (1024 / rays) ** 0.5:.4f} RMSE, from 0.01 at 1024) on every "
          "example scene, surface pixels only. flip: mean LDR-FLIP (Andersson et al. 2020, the "
          "AO value as grey, 67 pixels per degree; 0 = identical, 1 = green against blue; "
          "docs/nodes.md#compare). bias = mean(method - reference): positive = "
          "too bright (missed occlusion). ms: median frame time of the shipped graph that "
          f"runs the method (`graphs/ssao.graph`, `graphs/hbao.graph`, `graphs/gtao.graph`; write excluded, "
          f"{runs} runs after a warm-up, {threads or os.cpu_count()} threads). Made by "
          f"`python3 bench/bench.py --accuracy --size {size}`.\n")
    print("| scene | method | rmse | flip | bias | ssim | ms |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            path = os.path.join(ROOT, "examples", scene)
            metrics = run_metrics(binary, ao_error, path, size, threads, os.path.join(tmp, scene),
                                  truth=("ref.rays", rays))
            print_rows(binary, scene, path, metrics, ACCURACY_METHODS, size, threads, runs, tmp)


# Each lighting of the GI tables: its name, the lights file that relights every scene
# (None: the scene's own lights and environment) and the graph that scores the pipelines.
GI_LIGHTS = [("own", None, "hybrid_ssdo_error.graph"), ("sun", "sun", "gi_error.graph"),
             ("sky", "sky", "hybrid_ssdo_error.graph"),
             ("courtyard", "courtyard", "hybrid_ssdo_error.graph")]
# Each pipeline: its row name, its compare node against reference_gi, what it is, and the
# compare node of its bounce term against reference_gi's bounce (None: it has no bounce).
GI_METHODS = [("none", "c_none", "no occlusion", None),
              ("ssao", "c_ssao", "SSAO-darkened ambient", None),
              ("ssdo", "c_ssdo", "ssdo.graph", "cb_ssdo"),
              ("hybrid", "c_hybrid", "hybrid.graph", None),
              ("hybrid_ssdo", "c_hybrid_ssdo", "hybrid_ssdo.graph", "cb_hybrid_ssdo"),
              ("gi", "c_gi", "gi.graph", "cb_gi")]


def bounce_ratio(metrics, node):
    """The mean of a pipeline's bounce term over the mean of reference_gi's bounce (the
    compare node `node` scores one against the other), or None."""
    m = metrics.get(node) if node else None
    if not m or not m.get("reference_mean"):
        return None
    return m["mean"] / m["reference_mean"]


def gi_accuracy_table(binary, size, threads, runs, paths=4096, only=None):
    """Every GI pipeline of graphs/gi_error.graph (and, where it runs, of
    graphs/hybrid_ssdo_error.graph) against reference_gi (direct light with true shadows
    plus one diffuse bounce) on every example scene under its own lights and each light of
    examples/lights: per scene RMSE, FLIP (HDR-FLIP of the linear images), bias, SSIM and
    the bounce energy (mean of the pipeline's bounce term over the reference's); per light
    the mean RMSE and FLIP, the mean and worst ratio to the SSAO baseline and how many
    scenes are worse than it; and the frame time of ssdo.graph and gi.graph (Cornell box)
    and hybrid_ssdo.graph (courtyard)."""
    scenes = still_scenes(only)
    print(f"\n# GI accuracy of the shipped graphs, {size}\n")
    print("Every example scene under its own lights (own: the point and directional lights "
          "and environment its file names) and relit by each file of `examples/lights/` "
          "(`--lights`: a sun alone, a uniform white sky, the courtyard probe), each "
          "pipeline's final image against `reference_gi` (direct light with ray-traced "
          f"shadows plus exactly one diffuse bounce, {paths} paths a pixel: converged, its own "
          "noise stated in docs/gallery.md), surface pixels only, "
          "linear radiance. flip: mean HDR-FLIP (Andersson et al. 2021: LDR-FLIP over the "
          "exposures the reference spans, the largest per pixel; 0 = identical). none: "
          "direct + environment light, no occlusion; ssao: direct + "
          "SSAO-darkened environment at the SSDO pipeline's radius, samples and filter (the "
          "baseline); ssdo: `graphs/ssdo.graph`; hybrid: `graphs/hybrid.graph`; hybrid_ssdo: "
          "`graphs/hybrid_ssdo.graph` (the hybrids need environment light: not under the "
          "sun); gi: `graphs/gi.graph`. bounce: the mean of the pipeline's bounce term over "
          "the mean of the reference's bounce (1 = the right energy; - where the pipeline "
          "has none). structure_pp: compare's structure measure, the peak to peak of the "
          "error's low-frequency part G(a - b) / G(b) where the truth is smooth and away "
          "from depth jumps (docs/nodes.md#compare; - where no pixel qualifies). Graphs: `graphs/gi_error.graph`, `graphs/hybrid_ssdo_error.graph`. "
          f"Made by `python3 bench/bench.py --accuracy --size {size}`.\n")
    rows, summary = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for light, lights_file, graph in GI_LIGHTS:
            lights = (os.path.join(ROOT, "examples", "lights", lights_file + ".scene")
                      if lights_file else None)
            per, energy, flips, structure = {}, {}, {}, {}
            for scene in scenes:
                path = os.path.join(ROOT, "examples", scene)
                metrics = run_metrics(binary, os.path.join(ROOT, "graphs", graph), path, size,
                                      threads, os.path.join(tmp, light + scene), lights,
                                      truth=("ref.samples", paths),
                                      sets=structure_sets(graph))
                for name, node, _, bounce_node in GI_METHODS:
                    if node not in metrics:
                        continue
                    m = metrics[node]
                    per.setdefault(name, {})[scene] = m["rmse"]
                    flips.setdefault(name, []).append(m["flip"])
                    ratio = bounce_ratio(metrics, bounce_node)
                    if ratio is not None:
                        energy.setdefault(name, []).append(ratio)
                    shown = f"{ratio:.3f}" if ratio is not None else "-"
                    structure.setdefault(name, []).append(m["structure_pp"])
                    rows.append(f"| {light} | {scene[:-6]} | {name} | {m['rmse']:.4f} | "
                                f"{m['flip']:.4f} | {cell(m['structure_pp'])} | "
                                f"{m['bias']:+.4f} | {m['ssim']:.3f} | {shown} |")
            base = per["ssao"]
            for name, _, what, _ in GI_METHODS:
                if name not in per:
                    continue
                r = [per[name][s] / base[s] for s in base]
                mean = sum(per[name].values()) / len(per[name])
                e = energy.get(name)
                shown = f"{sum(e) / len(e):.3f}" if e else "-"
                f = flips[name]
                st = [x for x in structure[name] if x is not None]
                summary.append(f"| {light} | {name} ({what}) | {mean:.4f} | "
                               f"{sum(f) / len(f):.4f} | "
                               f"{cell(sum(st) / len(st) if st else None)} | "
                               f"{sum(r) / len(r):.3f} | {max(r):.3f} | "
                               f"{sum(x > 1.0 for x in r)} of {len(r)} | {shown} |")
        ms = [frame_ms(binary, os.path.join(ROOT, "graphs", g),
                       os.path.join(ROOT, "examples", sc), size, threads, runs,
                       os.path.join(tmp, "t"))[0]
              for g, sc in (("ssdo.graph", "cornell.scene"), ("gi.graph", "cornell.scene"),
                            ("hybrid_ssdo.graph", "courtyard.scene"))]
    print("| light | method | mean rmse | mean flip | mean structure_pp | mean ratio to ssao | "
          "worst ratio | scenes worse than ssao | bounce |")
    print("|---|---|---|---|---|---|---|---|---|")
    print("\n".join(summary))
    print(f"\nFrame time at {size} (median of {runs} runs after a warm-up, "
          f"{threads or os.cpu_count()} threads, write excluded): ssdo.graph on the Cornell "
          f"box {ms[0]:.1f} ms, gi.graph on the Cornell box {ms[1]:.1f} ms, "
          f"hybrid_ssdo.graph on the courtyard {ms[2]:.1f} ms (lightprobe's one-off "
          "conversion included).\n")
    print("| light | scene | method | rmse | flip | structure_pp | bias | ssim | bounce |")
    print("|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


def structure_sets(graph):
    """--set values that turn on compare's structure measure in the c_* nodes of the graph
    and of the graphs it includes (those that score a whole pipeline; they take the depth
    it needs)."""
    text = open(os.path.join(ROOT, "graphs", graph)).read()
    names = re.findall(r"^(c_\w+)\s*=\s*compare\(", text, re.M)
    sets = ["%s.structure=true" % n for n in names]
    for included in re.findall(r'^include\s+"([^"]+)"', text, re.M):
        sets += structure_sets(included)
    return sets


def cell(value):
    """A table cell of 4 decimals, or - for a missing (null) value."""
    return f"{value:.4f}" if value is not None else "-"


def run_metrics(binary, graph, scene_path, size, threads, out, lights=None, truth=None,
                sets=()):
    """Runs graph on the scene (relit by the lights file, if one is given), its reference
    at truth = (its parameter, the count: issue 34's converged truth), with `sets` as
    --set values; its compare nodes' metrics."""
    cmd = [binary, "run", graph, "--scene", scene_path, "--size", size, "--out", out, "--quiet"]
    for value in sets:
        cmd += ["--set", value]
    if truth:
        cmd += ["--set", "%s=%d" % truth]
    if lights:
        cmd += ["--lights", lights]
    if threads:
        cmd += ["--threads", str(threads)]
    run_cmd(cmd)
    with open(os.path.join(out, "metrics.json")) as f:
        return json.load(f)


def print_rows(binary, scene, scene_path, metrics, methods, size, threads, runs, tmp):
    """One table row a method: its compare node's metrics and its shipped graph's time."""
    for label, node, graph in methods:
        m = metrics[node]
        ms = "-"
        if graph:
            frame, _ = frame_ms(binary, os.path.join(ROOT, "graphs", graph), scene_path, size,
                                threads, runs, os.path.join(tmp, "t"))
            ms = f"{frame:.1f}"
        print(f"| {scene[:-6]} | {label} | {m['rmse']:.3f} | {m['flip']:.4f} | "
              f"{m['bias']:+.3f} | {m['ssim']:.3f} | {ms} |")
