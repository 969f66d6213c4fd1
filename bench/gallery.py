"""gallery.py - docs/gallery.md for `bench.py --gallery`: every shipped pipeline on every
example scene with a still camera, beside converged truth, with its error map and crops of
its worst region.

    python3 bench/bench.py --gallery --bin build/ssgraph          # docs/gallery.md
    python3 bench/bench.py --gallery --scenes cornell,table --lights own,sky --size 320x180

GI pipelines (graphs/gi.graph, ssdo.graph, ssdo_realtime.graph, ssilvb.graph,
hybrid.graph, hybrid_ssdo.graph and gi_temporal.graph after 32 still frames) are scored
against bench/gallery/reference_gi.graph (`--paths` paths a pixel) under each scene's own
lights and each light of --lights (examples/lights/: sky, courtyard probe, sun); the AO
pipelines (ssao, hbao, gtao; their filtered `ao` layer) against bench/gallery/
reference_ao.graph (`--rays` rays). Every image is compared with `ssgraph compare` (RMSE,
SSIM, FLIP and the structure measure, structure_pp, with the truth's depth: blotches where
the truth is smooth) over the pixels with a surface, and its error map comes from
`ssgraph node compare` (the `flip` output, else `diff`).

The references are cached like bench --reference's: $SSGRAPH_CACHE/gallery, else
$XDG_CACHE_HOME/ssgraph/gallery, else ~/.cache/ssgraph/gallery; each <hash>.exr is keyed by
ssgraph's version, the reference graph's text, the scene's and the lights' files and the
files they name, the size, the path count and the seed (<hash>.key holds the key, written
last). --self-error renders two more references a case, with other seeds and a quarter of
the paths, and states the truth's own noise from their difference (own_noise).

Pictures: each case is one JPEG (top: truth, then every pipeline; bottom: each error map in
false colour, mean FLIP or RMSE in the label), written to --out (docs/images/gallery);
crops of the worst 1/4-frame window of the hybrid (and the worst pipeline) follow, 3x
enlarged. Display uses write's own tone map (ACES, Narkowicz 2015, then sRGB) for colour
and clamp for AO, the same for truth and pipeline. bench/gallery/artefacts.md (written by
people, looking) is appended: what a viewer would call an artefact, with its cause.
"""
import functools
import hashlib
import json
import math
import os
import re
import shutil
import tempfile

import numpy as np

from bench import run_cmd as run
from sequence import cache_dir as sequence_cache_dir

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HERE = os.path.join(ROOT, "bench", "gallery")

GI_PIPELINES = [("gi", "gi.graph", ()), ("ssdo", "ssdo.graph", ()),
                ("ssdo_realtime", "ssdo_realtime.graph", ()), ("ssilvb", "ssilvb.graph", ()),
                ("hybrid", "hybrid.graph", ()), ("hybrid_ssdo", "hybrid_ssdo.graph", ()),
                ("gi_temporal", "gi_temporal.graph", ("--frames", "32"))]
AO_PIPELINES = [("ssao", "ssao.graph"), ("hbao", "hbao.graph"), ("gtao", "gtao.graph")]
LIGHTS = {"own": None, "sky": "sky", "courtyard": "courtyard", "sun": "sun"}
CROPPED = "hybrid_ssdo"  # the pipeline whose worst region is always shown (issue 34)
# Lit by the environment alone: they refuse a lighting without one (shown as absent).
NEEDS_ENVIRONMENT = {"hybrid", "hybrid_ssdo"}


def has_environment(scene, lights):
    """Whether the lighting has an environment: the lights file's, else the scene's."""
    source = lights_file(lights) or scene
    return bool(re.search(r"^\s*environment\(", open(source).read(), re.M))


def cache_dir():
    path = sequence_cache_dir("gallery")
    os.makedirs(path, exist_ok=True)
    return path


@functools.lru_cache(maxsize=None)
def version(binary):
    """ssgraph's version line, asked once a binary (every reference's key holds it)."""
    return run([binary, "--version"]).splitlines()[0]


def named_files(scene_path, seen=None):
    """The scene (or lights) file and every file it names that exists, recursively."""
    seen = seen if seen is not None else []
    if not scene_path or scene_path in seen:
        return seen
    seen.append(scene_path)
    folder = os.path.dirname(scene_path)
    for name in re.findall(r'"([^"\n]+)"', open(scene_path, errors="replace").read()):
        path = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(path) and path not in seen:
            if path.endswith(".scene"):
                named_files(path, seen)
            else:
                seen.append(path)
    return seen


def lights_file(lights):
    return os.path.join(ROOT, "examples", "lights", LIGHTS[lights] + ".scene") \
        if LIGHTS[lights] else None


def reference(binary, kind, scene, lights, size, count, seed):
    """The cached reference EXR of one case (rendered when missing or stale)."""
    graph = os.path.join(HERE, "reference_%s.graph" % kind)
    parts = [version(binary), open(graph).read(), size, str(count), str(seed), kind]
    for path in named_files(scene) + named_files(lights_file(lights)):
        parts.append(os.path.relpath(path, ROOT))
        parts.append(hashlib.sha256(open(path, "rb").read()).hexdigest())
    text = "\n".join(parts) + "\n"
    name = hashlib.sha256(text.encode()).hexdigest()[:32]
    exr, keyfile = (os.path.join(cache_dir(), name + ext) for ext in (".exr", ".key"))
    if os.path.exists(exr) and os.path.exists(keyfile) and open(keyfile).read() == text:
        return exr
    param = "ref.samples" if kind == "gi" else "ref.rays"
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [binary, "run", graph, "--scene", scene, "--size", size, "--seed", str(seed),
               "--set", "%s=%d" % (param, count), "--quiet", "-o",
               os.path.join(tmp, "reference.exr")]
        if lights_file(lights):
            cmd += ["--lights", lights_file(lights)]
        run(cmd)
        shutil.move(os.path.join(tmp, "reference.exr"), exr + ".tmp")
    os.replace(exr + ".tmp", exr)
    with open(keyfile + ".tmp", "w") as f:
        f.write(text)
    os.replace(keyfile + ".tmp", keyfile)
    return exr


def own_noise(binary, scene, light, size, paths):
    """The reference's own noise at `paths`, from two references of paths / 4 with other
    seeds (2 and 3; the truth itself is seed 1): their RMSE / sqrt 2 is one quarter-path
    reference's noise, half of it the full reference's (noise falls as 1 / sqrt(paths)).
    Also the FLIP and the structure measure between the two quarter-path references, as
    measured."""
    quarter = max(1, paths // 4)
    a = reference(binary, "gi", scene, light, size, quarter, 2)
    b = reference(binary, "gi", scene, light, size, quarter, 3)
    m = json.loads(run([binary, "compare", a, b, "--mask", b + ":depth", "--depth",
                        b + ":depth", "--json"]))
    return (m["rmse"] / math.sqrt(2) * math.sqrt(quarter / paths), m.get("flip"),
            m.get("structure_pp"))


def render(binary, graph, extra, scene, lights, size, out):
    cmd = [binary, "run", os.path.join(ROOT, "graphs", graph), "--scene", scene, "--size",
           size, "--quiet", "-o", out] + list(extra)
    if lights_file(lights):
        cmd += ["--lights", lights_file(lights)]
    run(cmd)
    return out


def score(binary, image, ref, tmp, tag):
    """compare's metrics (a dict) and the error map (an EXR path) of image against ref."""
    mask = ref + ":depth"
    metrics = json.loads(run([binary, "compare", image, ref, "--mask", mask, "--depth", mask,
                              "--json"]))
    folder = os.path.join(tmp, "cmp_" + tag)
    out = run([binary, "node", "compare", "--in", "a=" + image, "--in", "b=" + ref,
               "--in", "mask=" + mask, "--out", folder])
    maps = {}
    for path in re.findall(r"wrote (\S+\.exr)", out):
        maps[os.path.splitext(os.path.basename(path))[0]] = path
    return metrics, maps.get("flip") or maps.get("diff")


# ---- pictures (numpy; OpenImageIO's Python module reads the EXRs; Pillow writes JPEG)

def read(path):
    """An EXR (FILE or FILE:LAYER) as float32 H x W x C."""
    import OpenImageIO as oiio
    file, layer = path, ""
    if not os.path.exists(path) and ":" in path:
        file, layer = path.rsplit(":", 1)
    buf = oiio.ImageBuf(file)
    spec = buf.spec()
    names = list(spec.channelnames)
    if layer:
        picks = [i for i, n in enumerate(names) if n.startswith(layer + ".")]
        if not picks and layer == "depth":  # written as the standard Z channel (docs/exr.md)
            picks = [names.index("Z")] if "Z" in names else []
    else:
        picks = [i for i, n in enumerate(names) if "." not in n] or list(range(len(names)))
    pixels = buf.get_pixels(oiio.FLOAT)
    return np.ascontiguousarray(pixels[:, :, picks])


def surface(ref):
    """The pixels with a surface: the reference's depth over 0."""
    return read(ref + ":depth")[..., 0] > 0


def aces_srgb(x):
    """write's PNG: the ACES fit of Narkowicz (2015), then sRGB encoding, in 8 bits."""
    x = np.maximum(x, 0)
    y = np.clip((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
    s = np.where(y <= 0.0031308, 12.92 * y, 1.055 * np.power(y, 1 / 2.4) - 0.055)
    return (s * 255 + 0.5).astype(np.uint8)


def grey(x):
    s = np.clip(x, 0, 1)
    s = np.where(s <= 0.0031308, 12.92 * s, 1.055 * np.power(s, 1 / 2.4) - 0.055)
    return (s * 255 + 0.5).astype(np.uint8)


def false_colour(err, top):
    """An error map in matplotlib's magma, 0 .. top."""
    from matplotlib import colormaps
    e = np.abs(err).mean(axis=2) if err.ndim == 3 else np.abs(err)  # a signed diff: |.|
    v = np.clip(e / top, 0, 1)
    return (colormaps["magma"](v)[..., :3] * 255 + 0.5).astype(np.uint8)


def display(img, kind):
    if kind == "ao" or img.shape[2] == 1:
        g = grey(img[..., :1])
        return np.repeat(g, 3, axis=2)
    return aces_srgb(img[..., :3])


def label(tile, text):
    from PIL import Image, ImageDraw
    im = Image.fromarray(tile)
    draw = ImageDraw.Draw(im)
    draw.rectangle([0, 0, 7 * len(text) + 6, 13], fill=(0, 0, 0))
    draw.text((3, 1), text, fill=(255, 255, 255))
    return np.asarray(im)


def save_jpeg(pixels, path):
    from PIL import Image
    Image.fromarray(pixels).save(path, quality=85)


def worst_window(err, mask):
    """(y, x, h, w) of the quarter-size window with the highest mean error."""
    e = np.abs(err).mean(axis=2) if err.ndim == 3 else np.abs(err)
    e = np.where(mask, e, 0)
    h, w = e.shape
    wh, ww = max(1, h // 4), max(1, w // 4)
    s = np.pad(np.cumsum(np.cumsum(e, 0), 1), ((1, 0), (1, 0)))
    sums = s[wh:, ww:] - s[:-wh, ww:] - s[wh:, :-ww] + s[:-wh, :-ww]
    y, x = np.unravel_index(np.argmax(sums), sums.shape)
    return int(y), int(x), wh, ww


def crop_strip(tiles, window, scale=3):
    y, x, h, w = window
    parts = [np.kron(t[y:y + h, x:x + w], np.ones((scale, scale, 1), np.uint8)) for t in tiles]
    gap = np.full((h * scale, 4, 3), 255, np.uint8)
    out = parts[0]
    for p in parts[1:]:
        out = np.concatenate([out, gap, p], axis=1)
    return out


# ---- the gallery

def case_picture(case, kind, ref_img, surface, rows, folder):
    """One JPEG: truth and the pipelines on top, their error maps below; crops of the
    worst window (over the surface pixels) of the hybrid and of the worst pipeline."""
    truth = display(ref_img, kind)
    top, bottom = [label(truth, "truth")], [np.zeros_like(truth)]
    metric = "flip" if all("flip" in r["metrics"] for r in rows) else "rmse"
    scale = 1.0 if metric == "flip" else 0.25
    for r in rows:
        top.append(label(display(r["image"], kind), r["name"]))
        err = r["map"] if r["map"] is not None else np.abs(r["image"] - ref_img)
        text = "%s %.3f" % (metric, r["metrics"][metric])
        if r["metrics"].get("structure_pp") is not None:
            text += " st %.2f" % r["metrics"]["structure_pp"]
        bottom.append(label(false_colour(err, scale), text))
    gap = np.full((truth.shape[0], 3, 3), 255, np.uint8)
    row = lambda ts: np.concatenate(sum([[t, gap] for t in ts], [])[:-1], axis=1)
    picture = np.concatenate([row(top), np.full((3, row(top).shape[1], 3), 255, np.uint8),
                              row(bottom)], axis=0)
    name = "%s_%s.jpg" % (case, kind)
    save_jpeg(picture, os.path.join(folder, name))
    crops = []
    chosen = [r for r in rows if r["name"] == CROPPED]
    worst = max(rows, key=lambda r: r["metrics"][metric])
    for r in chosen + ([worst] if worst not in chosen else []):
        err = r["map"] if r["map"] is not None else np.abs(r["image"] - ref_img)
        window = worst_window(err, surface)
        strip = crop_strip([truth, display(r["image"], kind), false_colour(err, scale)],
                           window)
        crop = "%s_%s_%s_crop.jpg" % (case, kind, r["name"])
        save_jpeg(strip, os.path.join(folder, crop))
        crops.append((r["name"], crop, window))
    return name, metric, crops


def gallery(binary, size, paths, rays, scenes, lights, folder, markdown, self_error,
            pipelines=None):
    """pipelines: the names to show (default all; an AO section only with an AO name)."""
    gi = [p for p in GI_PIPELINES if not pipelines or p[0] in pipelines]
    ao = [p for p in AO_PIPELINES if not pipelines or p[0] in pipelines]
    os.makedirs(folder, exist_ok=True)
    summary, sections, noise = {}, [], []
    with tempfile.TemporaryDirectory() as tmp:
        for scene_name in scenes:
            scene = os.path.join(ROOT, "examples", scene_name + ".scene")
            for light in lights:
                tag = "%s_%s" % (scene_name, light)
                ref = reference(binary, "gi", scene, light, size, paths, 1)
                if self_error:
                    noise.append((tag,) + own_noise(binary, scene, light, size, paths))
                rows = []
                for name, graph, extra in gi:
                    if name in NEEDS_ENVIRONMENT and not has_environment(scene, light):
                        continue
                    out = render(binary, graph, extra, scene, light, size,
                                 os.path.join(tmp, tag, name + ".exr"))
                    metrics, emap = score(binary, out, ref, tmp, tag + name)
                    rows.append({"name": name, "metrics": metrics, "image": read(out),
                                 "map": read(emap) if emap else None})
                    summary.setdefault((name, light), []).append(metrics)
                pic, metric, crops = case_picture(tag, "gi", read(ref), surface(ref), rows,
                                                  folder)
                sections.append((scene_name, light, pic, metric, rows, crops))
            if not ao:
                continue
            ref = reference(binary, "ao", scene, "own", size, rays, 1)
            rows = []
            for name, graph in ao:
                out = render(binary, graph, (), scene, "own", size,
                             os.path.join(tmp, scene_name, name + ".exr"))
                metrics, emap = score(binary, out + ":ao", ref, tmp, scene_name + name)
                rows.append({"name": name, "metrics": metrics, "image": read(out + ":ao"),
                             "map": read(emap) if emap else None})
                summary.setdefault((name, "ao"), []).append(metrics)
            pic, metric, crops = case_picture(scene_name, "ao", read(ref), surface(ref), rows,
                                              folder)
            sections.append((scene_name, "ao", pic, metric, rows, crops))
    write_markdown(markdown, folder, size, paths, rays, summary, sections, noise)


def fmt(value):
    """A table cell: 4 decimals, or - where the metric is missing (or null: no pixel)."""
    return "%.4f" % value if value is not None else "-"


def mean_of(metrics, key):
    """The mean of one metric over the cases that have it, else None."""
    values = [m[key] for m in metrics if m.get(key) is not None]
    return float(np.mean(values)) if values else None


def write_markdown(path, folder, size, paths, rays, summary, sections, noise):
    rel = os.path.relpath(folder, os.path.dirname(os.path.abspath(path)))
    lines = ["# Gallery: every pipeline beside converged truth", "",
             "Made by `python3 bench/bench.py --gallery --size %s --paths %d --rays %d` "
             "(bench/gallery.py says how). Truth: `reference_gi` with %d paths a pixel "
             "(one diffuse bounce, as the pipelines), `reference_ao` with %d rays for the "
             "AO pipelines. Each picture: truth and every pipeline on top, each one's error "
             "map below (FLIP, 0 = same, 1 = most different, in magma; where the build has "
             "no FLIP, |difference| with 0.25 at the top of the scale), the mean over the "
             "pixels with a surface in its label. Crops: the quarter-frame window where the "
             "error is highest, 3x: truth, pipeline, error." % (size, paths, rays, paths, rays),
             ""]
    if noise:
        lines += ["## The truth's own error", "",
                  "Two more references with other seeds at a quarter of the paths: their "
                  "RMSE / sqrt 2, halved (noise falls as 1 / sqrt(paths)), is the truth's own "
                  "noise at %d paths; the FLIP between the two quarter-path references is "
                  "shown as measured (an upper bound of what the truth's noise adds to a "
                  "pipeline's FLIP), and so is their structure measure (structure_pp: "
                  "blotches the truth's own noise leaves after the wide blur):" % paths, "",
                  "| case | noise rmse at %d paths | flip of two %d-path references | "
                  "structure_pp of them |" % (paths, max(1, paths // 4)),
                  "|---|--:|--:|--:|"]
        lines += ["| %s | %.4f | %s | %s |" % (t, r, fmt(f), fmt(st)) for t, r, f, st in noise]
        lines.append("")
    lines += ["## Summary", "", "Mean over the scenes of each pipeline's score, per lighting:",
              "(structure_pp: the peak to peak of the error's low-frequency part where "
              "the truth is smooth, `compare`'s structure measure, nodes/compare/README.md)",
              "", "| pipeline | lighting | scenes | mean flip | mean rmse | "
              "mean structure_pp |", "|---|---|--:|--:|--:|--:|"]
    for (name, light), ms in summary.items():
        lines.append("| %s | %s | %d | %s | %.4f | %s |" % (
            name, light, len(ms), fmt(mean_of(ms, "flip")), np.mean([m["rmse"] for m in ms]),
            fmt(mean_of(ms, "structure_pp"))))
    lines.append("")
    artefacts = os.path.join(HERE, "artefacts.md")
    if os.path.exists(artefacts):
        lines += [open(artefacts).read().rstrip(), ""]
    for scene, light, pic, metric, rows, crops in sections:
        title = "AO" if light == "ao" else "lights: " + light
        lines += ["## %s, %s" % (scene, title), "",
                  "![%s %s](%s/%s)" % (scene, light, rel, pic), "",
                  " | ".join("%s: %s" % (r["name"], ", ".join(
                      "%s %.4f" % (k, r["metrics"][k])
                      for k in ("flip", "rmse", "structure_pp", "ssim")
                      if r["metrics"].get(k) is not None)) for r in rows),
                  ""]
        for name, crop, (y, x, h, w) in crops:
            lines += ["%s, worst window at (%d, %d), %dx%d: truth | %s | error" % (
                name, x, y, w, h, name), "", "![%s crop](%s/%s)" % (name, rel, crop), ""]
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines))
    os.replace(path + ".tmp", path)
    print("wrote", path)
