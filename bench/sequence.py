#!/usr/bin/python3
"""sequence.py - how a pipeline behaves over a camera path (issue 32 item 7, docs/time.md).

    bench/sequence.py graphs/gtao_temporal.graph graphs/gtao.graph \
        --scene examples/cornell_path.scene --size 160x120 --frames 30 \
        --plot out/sequence.png --markdown bench/results/sequence_gtao.md

For each graph: `ssgraph run GRAPH --frames N --set out.sequence=true` writes one EXR a frame
(and, when the graph has a temporal node, its `length` output as the layer `length`). The
same frames of a reference sequence (gbuffer + reference_ao + write sequence=true, cached)
score each frame. Per frame: the RMSE of the pipeline's AO layer against the reference over
the pixels with a surface (reference depth > 0), the mean |p_f - p_{f-1}| of the pipeline
and of the reference, and the fraction of pixels whose history length is 1 (new to the
temporal node). Summary lines per graph:

    mean_rmse   the mean of the per-frame RMSEs over the path
    flicker     mean over frames f >= 1 of mean|p_f - p_{f-1}|, pipeline minus reference
                (the reference's own change is the camera's; what is left is the method's)
    ghosting    the frame after the largest disocclusion (largest length == 1 fraction,
                frame 0 excluded), the mean RMSE of the 8 frames from it divided by the
                steady-state RMSE (the median RMSE of the frames outside frame 0's and the
                disocclusion's first 8), and the frames until the RMSE is back within 10 %
                of steady state. Skipped for a graph without a temporal node.

EXRs are read through oiiotool (--dumpdata of the wanted channels). The reference sequence is
cached like bench --reference's images: $SSGRAPH_CACHE/sequences, else
$XDG_CACHE_HOME/ssgraph/sequences, else ~/.cache/ssgraph/sequences; <hash>.npz holds the
frames and <hash>.key the key text (ssgraph's version, the scene file's bytes' sha256, size,
frames, seed and the reference graph's text, then a sha256 of the frames). The key is
written last and compared in full, the frames' hash checked, so a stale, partial or corrupt
file is rendered again.
"""
import argparse
import hashlib
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile

import numpy as np

GHOST_FRAMES = 8
RECOVERED = 1.10  # back to steady state: RMSE within 10 % of it

OPTIONS = [  # name, default, help
    ("scene", "examples/cornell_path.scene", "a scene with a camera path"),
    ("size", "160x120", "WxH"),
    ("frames", 30, "frames 0 .. N-1 of the path"),
    ("layer", "ao", "the pipeline's EXR layer to score (ao_raw: before the filter)"),
    ("rays", 256, "reference_ao rays"),
    ("max-distance", "0.5", "reference_ao max_distance"),
    ("seed", 1, "the seed of both runs"),
    ("threads", 2, "ssgraph --threads"),
    ("backend", "cpu", "ssgraph --backend"),
    ("ssgraph", "build/ssgraph", "the ssgraph executable"),
    ("plot", None, "write a PNG of RMSE over frames here"),
    ("markdown", None, "write the tables here too"),
]


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        sys.exit("sequence.py: %s failed (%d):\n%s%s" % (" ".join(cmd), p.returncode,
                                                          p.stdout, p.stderr))
    return p.stdout


def parse_dump(text, exr, channels):
    """One file's part of `oiiotool --info -v --dumpdata`: its channels as 2-D arrays."""
    size = re.search(r":\s+(\d+) x\s+(\d+), (\d+) channel", text)
    listed = re.search(r"channel list: (.*)", text)
    if not size or not listed:
        sys.exit("sequence.py: cannot read %s through oiiotool" % exr)
    w, h, n = (int(v) for v in size.groups())
    names = [c.strip() for c in listed.group(1).split(",")]
    rows = re.findall(r"^\s*Pixel \((\d+), (\d+)\):([^\n]*)$", text, re.M)
    if len(rows) != w * h or sorted(names) != sorted(channels):
        sys.exit("sequence.py: %s: %d pixels of %dx%d, channels %s" % (exr, len(rows), w, h,
                                                                       names))
    img = np.zeros((h, w, n))
    for x, y, vals in rows:
        img[int(y), int(x)] = [float(v) for v in vals.split()]
    return [img[:, :, names.index(c)] for c in channels]  # EXR sorts its channels


def read_sequence(files, channels, tmp):
    """The named channels of every EXR, [file][channel] 2-D float arrays. Two oiiotool runs
    for the lot (each start costs about 0.3 s): one copies the channels of every file into a
    small EXR, one prints those files' pixels ("Pixel (x, y): v v ..." lines, 9 decimals)."""
    copy, parts = ["oiiotool"], []
    for i, exr in enumerate(files):
        parts.append(os.path.join(tmp, "part_%04d.exr" % i))
        copy += [exr, "--ch", ",".join(channels), "-d", "float", "-o", parts[-1]]
    run(copy)
    text = run(["oiiotool", "--info", "-v", "--dumpdata"] + parts)
    starts = [text.find("Reading %s\n" % part) for part in parts] + [len(text)]
    if any(s < 0 for s in starts) or starts != sorted(starts):
        sys.exit("sequence.py: oiiotool did not describe every file")
    return [parse_dump(text[starts[i]:starts[i + 1]], files[i], channels)
            for i in range(len(files))]


def sequence_files(folder, frames):
    """NAME_0000.exr ... of the one sequence a run wrote into folder."""
    firsts = sorted(f for f in os.listdir(folder) if f.endswith("_0000.exr"))
    if len(firsts) != 1:
        sys.exit("sequence.py: expected one sequence in %s, found %s" % (folder, firsts))
    stem = firsts[0][:-len("0000.exr")]
    files = [os.path.join(folder, "%s%04d.exr" % (stem, f)) for f in range(frames)]
    missing = [f for f in files if not os.path.exists(f)]
    if missing:
        sys.exit("sequence.py: missing frames: %s" % missing[:3])
    return files


def temporal_node(graph, seen=None):
    """The name of the graph's temporal node (following includes), or None."""
    seen = seen or set()
    graph = os.path.realpath(graph)
    if graph in seen:
        return None
    seen.add(graph)
    text = open(graph).read()
    m = re.search(r"^\s*(\w+)\s*=\s*temporal\s*\(", text, re.M)
    if m:
        return m.group(1)
    for inc in re.findall(r'^\s*include\s+"([^"]+)"', text, re.M):
        found = temporal_node(os.path.join(os.path.dirname(graph), inc), seen)
        if found:
            return found
    return None


def cache_dir():
    own, xdg, home = (os.environ.get(k) for k in ("SSGRAPH_CACHE", "XDG_CACHE_HOME", "HOME"))
    if own:
        return os.path.join(own, "sequences")
    if xdg:
        return os.path.join(xdg, "ssgraph", "sequences")
    return os.path.join(home, ".cache", "ssgraph", "sequences") if home else ""


def reference_graph(a):
    return ('scene "%s"\nsize %d %d\nseed %d\n'
            "g   = gbuffer()\n"
            "ref = reference_ao(g.position, g.normal, rays=%d, max_distance=%s)\n"
            'out = write(ref.out, "reference", tonemap=clamp, sequence=true, depth=g.depth)\n'
            % (os.path.realpath(a.scene), a.width, a.height, a.seed, a.rays, a.max_distance))


def pixels_hash(ao, depth):
    return hashlib.sha256(ao.astype("<f8").tobytes() + depth.astype("<f8").tobytes()).hexdigest()


def reference_frames(a, tmp):
    """The reference's AO and depth of every frame, (frames, h, w) each; cached."""
    text = reference_graph(a)
    version = " ".join(l for l in run([a.ssgraph, "--version"]).splitlines()
                       if l.startswith(("ssgraph", "embree")))
    scene_hash = hashlib.sha256(open(a.scene, "rb").read()).hexdigest()
    key = "ssgraph sequence reference\nversion %s\nscene %s\nframes %d backend %s\n%s" % (
        version, scene_hash, a.frames, a.backend, text)
    base = os.path.join(cache_dir(), hashlib.sha256(key.encode()).hexdigest()[:32])
    folder = cache_dir()
    try:
        stored = open(base + ".key").read()
        if stored.startswith(key):
            with np.load(base + ".npz") as z:
                ao, depth = z["ao"], z["depth"]
            if (ao.shape == (a.frames, a.height, a.width) == depth.shape and
                    stored[len(key):] == "pixels %s\n" % pixels_hash(ao, depth)):
                print("reference: cached %s.npz" % base)
                return ao, depth
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile):
        pass  # missing, stale, truncated or corrupt: render it again
    gpath, out = os.path.join(tmp, "reference.graph"), os.path.join(tmp, "reference")
    with open(gpath, "w") as f:
        f.write(text)
    print("reference: rendering %d frames (%d rays)" % (a.frames, a.rays), flush=True)
    run([a.ssgraph, "run", gpath, "--frames", str(a.frames), "--threads", str(a.threads),
         "--backend", a.backend, "--quiet", "--out", out])
    frames = read_sequence(sequence_files(out, a.frames), ["Y", "Z"], tmp)
    ao, depth = np.array([f[0] for f in frames]), np.array([f[1] for f in frames])
    if folder:  # image first, key last: a key names only a complete file
        try:
            os.makedirs(folder, exist_ok=True)
            with open(base + ".tmp.npz", "wb") as f:
                np.savez(f, ao=ao, depth=depth)
            os.replace(base + ".tmp.npz", base + ".npz")
            with open(base + ".key.tmp", "w") as f:
                f.write(key + "pixels %s\n" % pixels_hash(ao, depth))
            os.replace(base + ".key.tmp", base + ".key")
        except OSError:
            pass
    return ao, depth


def pipeline_frames(a, graph, tnode, tmp):
    """The pipeline's AO layer (and its temporal length) of every frame."""
    out = os.path.join(tmp, "run_" + os.path.basename(graph))
    channels = [a.layer + ".Y"]
    if tnode:  # the history length as one more layer of the graph's write
        wrapper = os.path.join(tmp, "length_" + os.path.basename(graph))
        with open(wrapper, "w") as f:
            f.write('include "%s"\nadd out.length = %s.length\n' % (os.path.realpath(graph),
                                                                     tnode))
        graph = wrapper
        channels.append("length.Y")
    cmd = [a.ssgraph, "run", graph, "--scene", a.scene, "--size", "%dx%d" % (a.width, a.height),
           "--frames", str(a.frames), "--threads", str(a.threads), "--backend", a.backend,
           "--quiet", "--out", out, "--set", "out.sequence=true"]
    run(cmd)
    frames = read_sequence(sequence_files(out, a.frames), channels, tmp)
    ao = np.array([f[0] for f in frames])
    return ao, (np.array([f[1] for f in frames]) if tnode else None)


def mean_change(images, masks):
    """Per frame f >= 1: mean |p_f - p_{f-1}| over pixels with a surface in both."""
    out = [float("nan")]
    for f in range(1, len(images)):
        m = masks[f] & masks[f - 1]
        out.append(float(np.abs(images[f] - images[f - 1])[m].mean()) if m.any() else 0.0)
    return out


def ghosting(rmse, new_fraction):
    """(frame, ratio, recovery frames, steady) of the largest disocclusion after frame 0."""
    n = len(rmse)
    if n < 2:
        return None
    d = 1 + int(np.argmax(new_fraction[1:]))
    window = range(d, min(n, d + GHOST_FRAMES))
    outside = [rmse[f] for f in range(n) if f >= GHOST_FRAMES and f not in window]
    steady = float(np.median(outside)) if outside else rmse[-1]
    ratio = float(np.mean([rmse[f] for f in window])) / steady if steady > 0 else float("inf")
    recovery = next((f - d for f in range(d, n) if rmse[f] <= RECOVERED * steady), None)
    return d, ratio, recovery, steady


def measure(a, graph, ref_ao, ref_depth, tmp):
    tnode = temporal_node(graph)
    ao, length = pipeline_frames(a, graph, tnode, tmp)
    masks = ref_depth > 0
    rmse = [float(math.sqrt(np.mean((ao[f] - ref_ao[f])[masks[f]] ** 2)))
            for f in range(a.frames)]
    change, ref_change = mean_change(ao, masks), mean_change(ref_ao, masks)
    new = [float((length[f][masks[f]] == 1).mean()) if tnode else float("nan")
           for f in range(a.frames)]
    r = {"graph": graph, "temporal": tnode, "rmse": rmse, "change": change,
         "ref_change": ref_change, "new": new, "mean_rmse": float(np.mean(rmse))}
    r["flicker"] = (float(np.mean(change[1:]) - np.mean(ref_change[1:]))
                    if a.frames > 1 else float("nan"))
    r["ghost"] = ghosting(rmse, new) if tnode else None
    return r


def report_lines(r):
    name = os.path.basename(r["graph"])
    lines = ["## %s" % name, "",
             "| frame | rmse | mean abs change | reference's change | new pixels |",
             "|------:|-----:|----------------:|-------------------:|-----------:|"]
    for f, e in enumerate(r["rmse"]):
        lines.append("| %d | %.5f | %.5f | %.5f | %.4f |" % (
            f, e, r["change"][f], r["ref_change"][f], r["new"][f]))
    lines += ["", "- mean_rmse %s %.5f" % (name, r["mean_rmse"]),
              "- flicker %s %.5f" % (name, r["flicker"])]
    g = r["ghost"]
    if g:
        d, ratio, recovery, steady = g
        lines.append("- ghosting %s frame %d ratio %.3f recovery %s steady %.5f" % (
            name, d, ratio, "never" if recovery is None else "%d" % recovery, steady))
    else:
        lines.append("- ghosting %s skipped (no temporal node)" % name)
    return lines + [""]


def plot(a, results, tmp):
    dat = os.path.join(tmp, "rmse.dat")
    with open(dat, "w") as f:
        for r in results:
            f.write('"%s"\n' % os.path.basename(r["graph"]))
            for i, e in enumerate(r["rmse"]):
                f.write("%d %.6g\n" % (i, e))
            f.write("\n\n")
    gp = os.path.join(tmp, "rmse.gp")
    ghost = next((r["ghost"][0] for r in results if r["ghost"]), None)
    marks = ("set arrow from first %d, graph 0 to first %d, graph 1 nohead dashtype 2\n"
             "set label 'disocclusion' at first %d, graph 0.95 offset 0.5, 0\n"
             % (ghost, ghost, ghost)) if ghost is not None else ""
    with open(gp, "w") as f:
        f.write("set terminal pngcairo size 900,500 noenhanced font 'sans,11'\n"
                "set output '%s'\nset title 'AO error over the path: %s, %dx%d'\n"
                "set xlabel 'frame'\nset ylabel 'RMSE against reference_ao'\n"
                "set key bottom right\nset grid\nset yrange [0:*]\nset xtics %d\n%s"
                "plot for [i=0:%d] '%s' index i using 1:2 with linespoints title columnheader(1)\n"
                % (os.path.abspath(a.plot), os.path.basename(a.scene), a.width, a.height,
                   max(1, a.frames // 15), marks, len(results) - 1, dat))
    run(["gnuplot", gp])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("graphs", nargs="+")
    for name, default, what in OPTIONS:
        p.add_argument("--" + name, default=default, type=type(default) if default else None,
                       help=what)
    a = p.parse_args()
    a.width, a.height = (int(v) for v in a.size.lower().split("x"))
    if a.frames < 1:
        sys.exit("sequence.py: --frames must be >= 1")
    tmp = tempfile.mkdtemp(prefix="ssg_sequence_")
    try:
        ref_ao, ref_depth = reference_frames(a, tmp)
        results = [measure(a, g, ref_ao, ref_depth, tmp) for g in a.graphs]
        lines = ["# Sequence: %s, %dx%d, %d frames, layer %s, reference_ao %d rays" % (
            a.scene, a.width, a.height, a.frames, a.layer, a.rays), ""]
        for r in results:
            lines += report_lines(r)
        text = "\n".join(lines)
        print(text)
        if a.markdown:
            with open(a.markdown, "w") as f:
                f.write(text)
        if a.plot:
            plot(a, results, tmp)
            print("plot: %s" % a.plot)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
