#!/usr/bin/python3
"""sequence.py - how a pipeline behaves over a camera path (issue 32 item 7, docs/time.md).

    bench/sequence.py graphs/gtao_temporal.graph graphs/gtao.graph \
        --scene examples/cornell_path.scene --size 160x120 --frames 30 \
        --plot out/sequence.png --markdown bench/results/sequence_gtao.md
    bench/sequence.py --reference gi --paths 64 graphs/gi_temporal.graph graphs/gi.graph \
        --scene examples/cornell_orbit.scene --size 640x480 --frames 120

For each graph: `ssgraph run GRAPH --frames N --set out.sequence=true` writes one EXR a frame
(and, when the graph has a temporal node, its `length` output through a write of its own,
seq_length_NNNN.exr, at the node's size: a half-resolution history is scored on the frame
pixel by pixel, each frame pixel taking the history pixel it lies in). The
same frames of a reference sequence (gbuffer + reference_ao + write sequence=true, cached)
score each frame. Per frame: the RMSE of the pipeline's AO layer against the reference over
the pixels with a surface (reference depth > 0), the mean |p_f - p_{f-1}| of the pipeline
and of the reference, and the fraction of pixels whose history length is 1 (new to the
temporal node).

--reference gi scores a GI pipeline (graphs/gi.graph, gi_temporal.graph) instead: the
reference is gbuffer + reference_gi (samples=--paths, as graphs/gi_error.graph has it), the
pipeline's layer its write's main image (`image`: R,G,B, the colour reference_gi matches),
and the RMSE and changes are taken over the three channels of the surface pixels (as
`compare` does: over pixels x channels). Summary lines per graph:

    mean_rmse   the mean of the per-frame RMSEs over the path
    flicker     mean over frames f >= 1 of mean|p_f - p_{f-1}|, pipeline minus reference
                (the reference's own change is the camera's; what is left is the method's)
    ghosting    the frame after the largest disocclusion (largest length == 1 fraction,
                frame 0 excluded), the mean RMSE of the 8 frames from it divided by the
                steady-state RMSE (the median RMSE of the frames outside frame 0's and the
                disocclusion's first 8), and the frames until the RMSE is back within 10 %
                of steady state. Skipped for a graph without a temporal node.

EXRs are read through Debian's python3-openimageio when it is importable (--reader auto; a
640x480 gi.graph frame in 0.4 s), else through oiiotool (--dumpdata of the wanted channels,
printed to 9 decimals: the same values within 5e-10, 13 times slower). The reference
sequence is cached like bench --reference's images: $SSGRAPH_CACHE/sequences, else
$XDG_CACHE_HOME/ssgraph/sequences, else ~/.cache/ssgraph/sequences; <hash>.npz holds the
frames and <hash>.key the key text (in GI mode a line with the mode and the paths, then
ssgraph's version, the scene file's bytes' sha256, size, frames, seed and the reference
graph's text, then a sha256 of the frames). The key is written last and compared in full,
the frames' hash checked, so a stale, partial or corrupt file is rendered again.
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
import time
import zipfile

import numpy as np

GHOST_FRAMES = 8
RECOVERED = 1.10  # back to steady state: RMSE within 10 % of it

OPTIONS = [  # name, default, help
    ("scene", "examples/cornell_path.scene", "a scene with a camera path"),
    ("size", "160x120", "WxH"),
    ("render-size", None, "WxH the pipelines render at, when not --size: a taau graph's "
     "frame (graphs/gi_taau.graph: --size / 2), its write's image at --size"),
    ("frames", 30, "frames 0 .. N-1 of the path"),
    ("reference", "ao", "ao: reference_ao, the graph's AO layer; gi: reference_gi, its RGB image"),
    ("layer", None, "the pipeline's EXR layer to score (ao: ao, ao_raw before the filter; "
     "gi: image, the write's main R,G,B, or a colour layer such as near_bounce)"),
    ("rays", 256, "reference_ao rays"),
    ("paths", 64, "reference_gi samples (paths a pixel)"),
    ("max-distance", "0.5", "reference_ao max_distance"),
    ("seed", 1, "the seed of both runs"),
    ("threads", 2, "ssgraph --threads"),
    ("backend", "cpu", "ssgraph --backend"),
    ("ssgraph", "build/ssgraph", "the ssgraph executable"),
    ("reader", "auto", "how EXRs are read: oiio (python3-openimageio), oiiotool, auto (oiio "
     "when importable)"),
    ("plot", None, "write a PNG of RMSE over frames here"),
    ("markdown", None, "write the tables here too"),
]


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        sys.exit("sequence.py: %s failed (%d):\n%s%s" % (" ".join(cmd), p.returncode,
                                                          p.stdout, p.stderr))
    return p.stdout


def timed(a, what, cmd):
    """run(cmd), printing its wall time (the whole sequence, all frames) and per frame."""
    start = time.monotonic()
    run(cmd)
    wall = time.monotonic() - start
    print("wall: %s %.1f s (%.2f s a frame, %d threads)" % (what, wall, wall / a.frames,
                                                             a.threads), flush=True)


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


def read_sequence_oiiotool(files, channels, tmp):
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


def read_sequence_oiio(files, channels):
    """The same arrays through Debian's python3-openimageio: each file read whole as 32-bit
    floats (what write stores), the channels picked by name, widened to float64 as the
    oiiotool path's parse is. About 13 times faster than parsing --dumpdata's text at
    640x480."""
    import OpenImageIO as oiio
    out = []
    for exr in files:
        inp = oiio.ImageInput.open(exr)
        if inp is None:
            sys.exit("sequence.py: cannot read %s: %s" % (exr, oiio.geterror()))
        names = list(inp.spec().channelnames)
        pixels = inp.read_image(0, 0, 0, len(names), "float")
        inp.close()
        if pixels is None or any(c not in names for c in channels):
            sys.exit("sequence.py: %s: channels %s, wanted %s" % (exr, names, channels))
        out.append([np.asarray(pixels[:, :, names.index(c)], dtype=np.float64)
                    for c in channels])
    return out


def oiio_importable():
    try:
        import OpenImageIO  # noqa: F401 (only whether it is there)
        return True
    except ImportError:
        return False


def read_sequence(a, files, channels, tmp):
    """[file][channel] 2-D float64 arrays, through the reader --reader chose."""
    if a.reader == "oiio":
        return read_sequence_oiio(files, channels)
    return read_sequence_oiiotool(files, channels, tmp)


LENGTH_STEM = "seq_length"  # the history length's own write (pipeline_frames)


def sequence_files(folder, frames, stem=None):
    """NAME_0000.exr ... of the one sequence a run wrote into folder (besides the history
    length's), or of the sequence `stem`."""
    firsts = sorted(f for f in os.listdir(folder) if f.endswith("_0000.exr") and
                    (f.startswith(stem + "_") if stem else not f.startswith(LENGTH_STEM)))
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


def cache_dir(kind="sequences"):
    """The folder of one kind of cached reference, as bench --reference's cache is found:
    $SSGRAPH_CACHE/KIND, else $XDG_CACHE_HOME/ssgraph/KIND, else ~/.cache/ssgraph/KIND."""
    own, xdg, home = (os.environ.get(k) for k in ("SSGRAPH_CACHE", "XDG_CACHE_HOME", "HOME"))
    if own:
        return os.path.join(own, kind)
    if xdg:
        return os.path.join(xdg, "ssgraph", kind)
    return os.path.join(home, ".cache", "ssgraph", kind) if home else ""


def reference_graph(a):
    if a.reference == "gi":  # graphs/gi_error.graph's reference: one bounce, P paths a pixel
        return ('scene "%s"\nsize %d %d\nseed %d\n'
                "g   = gbuffer()\n"
                "ref = reference_gi(g.position, g.normal, g.albedo, samples=%d)\n"
                'out = write(ref.out, "reference", sequence=true, depth=g.depth)\n'
                % (os.path.realpath(a.scene), a.width, a.height, a.seed, a.paths))
    return ('scene "%s"\nsize %d %d\nseed %d\n'
            "g   = gbuffer()\n"
            "ref = reference_ao(g.position, g.normal, rays=%d, max_distance=%s)\n"
            'out = write(ref.out, "reference", tonemap=clamp, sequence=true, depth=g.depth)\n'
            % (os.path.realpath(a.scene), a.width, a.height, a.seed, a.rays, a.max_distance))


def pixels_hash(ao, depth):
    return hashlib.sha256(ao.astype("<f8").tobytes() + depth.astype("<f8").tobytes()).hexdigest()


def stack(frames, n):
    """(image, rest): the first n channels of every frame as one array, (frames, h, w) for
    one channel, (frames, h, w, n) for more; the channels after them one array each."""
    image = (np.array([f[0] for f in frames]) if n == 1 else
             np.array([np.stack(f[:n], axis=-1) for f in frames]))
    return image, [np.array([f[c] for f in frames]) for c in range(n, len(frames[0]))]


def reference_frames(a, tmp):
    """The reference's image (AO, or GI's RGB) and depth of every frame; cached."""
    text = reference_graph(a)
    version = " ".join(l for l in run([a.ssgraph, "--version"]).splitlines()
                       if l.startswith(("ssgraph", "embree")))
    scene_hash = hashlib.sha256(open(a.scene, "rb").read()).hexdigest()
    key = "ssgraph sequence reference\nversion %s\nscene %s\nframes %d backend %s\n%s" % (
        version, scene_hash, a.frames, a.backend, text)
    if a.reference == "gi":  # the mode and the paths are in the graph's text too
        key = "mode gi paths %d\n%s" % (a.paths, key)
    name, shape = a.reference, (a.frames, a.height, a.width) + ((3,) if a.reference == "gi"
                                                                 else ())
    base = os.path.join(cache_dir(), hashlib.sha256(key.encode()).hexdigest()[:32])
    folder = cache_dir()
    try:
        stored = open(base + ".key").read()
        if stored.startswith(key):
            with np.load(base + ".npz") as z:
                ao, depth = z[name], z["depth"]
            if (ao.shape == shape and depth.shape == shape[:3] and
                    stored[len(key):] == "pixels %s\n" % pixels_hash(ao, depth)):
                print("reference: cached %s.npz" % base)
                return ao, depth
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile):
        pass  # missing, stale, truncated or corrupt: render it again
    gpath, out = os.path.join(tmp, "reference.graph"), os.path.join(tmp, "reference")
    with open(gpath, "w") as f:
        f.write(text)
    print("reference: rendering %d frames (%s)" % (
        a.frames, "%d paths" % a.paths if a.reference == "gi" else "%d rays" % a.rays),
        flush=True)
    timed(a, "reference", [a.ssgraph, "run", gpath, "--frames", str(a.frames), "--threads",
                           str(a.threads), "--backend", a.backend, "--quiet", "--out", out])
    image = ["R", "G", "B"] if a.reference == "gi" else ["Y"]
    frames = read_sequence(a, sequence_files(out, a.frames), image + ["Z"], tmp)
    ao, (depth,) = stack(frames, len(image))
    if folder:  # image first, key last: a key names only a complete file
        try:
            os.makedirs(folder, exist_ok=True)
            with open(base + ".tmp.npz", "wb") as f:
                np.savez(f, **{name: ao, "depth": depth})
            os.replace(base + ".tmp.npz", base + ".npz")
            with open(base + ".key.tmp", "w") as f:
                f.write(key + "pixels %s\n" % pixels_hash(ao, depth))
            os.replace(base + ".key.tmp", base + ".key")
        except OSError:
            pass
    return ao, depth


def pipeline_frames(a, graph, tnode, tmp):
    """The pipeline's scored layer (AO, or an RGB image) and its temporal length, every frame."""
    out = os.path.join(tmp, "run_" + os.path.basename(graph))
    channels = layer_channels(a)
    n = len(channels)
    if tnode:  # the history length through a write of its own, at the temporal node's size
        wrapper = os.path.join(tmp, "length_" + os.path.basename(graph))
        with open(wrapper, "w") as f:
            f.write('include "%s"\nseqlength = write(%s.length, "%s", sequence=true, '
                    'png=false)\n' % (os.path.realpath(graph), tnode, LENGTH_STEM))
        graph = wrapper
    cmd = [a.ssgraph, "run", graph, "--scene", a.scene, "--size", a.render_size or a.size,
           "--frames", str(a.frames), "--threads", str(a.threads), "--backend", a.backend,
           "--quiet", "--out", out, "--set", "out.sequence=true"]
    timed(a, os.path.basename(graph), cmd)
    frames = read_sequence(a, sequence_files(out, a.frames), channels, tmp)
    ao, _ = stack(frames, n)
    if not tnode:
        return ao, None
    lengths = read_sequence(a, sequence_files(out, a.frames, LENGTH_STEM), ["Y"], tmp)
    return ao, np.array([to_frame(f[0], ao.shape[1], ao.shape[2]) for f in lengths])


def to_frame(img, h, w):
    """A lower-resolution image (a temporal node run at half size) on the frame's pixels:
    each frame pixel takes the low-resolution pixel it lies in."""
    if img.shape == (h, w):
        return img
    rows = (np.arange(h) * img.shape[0]) // h
    cols = (np.arange(w) * img.shape[1]) // w
    return img[np.ix_(rows, cols)]


def layer_channels(a):
    """The EXR channels of --layer: AO's scalar NAME.Y; GI's main R,G,B (`image`) or the
    colour layer NAME.R/G/B."""
    if a.reference == "ao":
        return [a.layer + ".Y"]
    return [c if a.layer == "image" else a.layer + "." + c for c in ("R", "G", "B")]


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
                "set output '%s'\nset title '%s error over the path: %s, %dx%d'\n"
                "set xlabel 'frame'\nset ylabel 'RMSE against reference_%s'\n"
                "set key bottom right\nset grid\nset yrange [0:*]\nset xtics %d\n%s"
                "plot for [i=0:%d] '%s' index i using 1:2 with linespoints title columnheader(1)\n"
                % (os.path.abspath(a.plot), a.reference.upper(), os.path.basename(a.scene),
                   a.width, a.height, a.reference,
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
    if a.reference not in ("ao", "gi") or a.reader not in ("auto", "oiio", "oiiotool"):
        sys.exit("sequence.py: --reference is ao or gi, --reader auto, oiio or oiiotool")
    if a.layer is None:
        a.layer = "ao" if a.reference == "ao" else "image"
    if a.reader == "auto":
        a.reader = "oiio" if oiio_importable() else "oiiotool"
    print("reader: %s" % ("python3-openimageio" if a.reader == "oiio" else "oiiotool --dumpdata"))
    tmp = tempfile.mkdtemp(prefix="ssg_sequence_")
    try:
        ref_ao, ref_depth = reference_frames(a, tmp)
        results = [measure(a, g, ref_ao, ref_depth, tmp) for g in a.graphs]
        lines = ["# Sequence: %s, %dx%d, %d frames, layer %s, %s" % (
            a.scene, a.width, a.height, a.frames, a.layer,
            "reference_gi %d paths" % a.paths if a.reference == "gi" else
            "reference_ao %d rays" % a.rays), ""]
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
