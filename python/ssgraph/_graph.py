"""Graphs: load once, then set, run and read outputs (the live-graph C API, core/ssgraph.h).

A loaded Graph keeps its run state between runs (ssg_graph_keep): a run after `set` runs
only the nodes the change affects, and any sequence of sets and runs gives the bytes of a
fresh load with the final settings."""
import numbers
import os
from dataclasses import dataclass, field
from typing import Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _args
from ._errors import Error, new_diags, raise_for, warnings_of
from ._images import from_library, to_library
from ._lock import locked
from ._ssgraph import ffi, lib

Value = Union[bool, int, float, str, Sequence[float]]


def _text(chars) -> str:
    return ffi.string(chars).decode("utf-8", "replace") if chars != ffi.NULL else ""


def format_value(value: Value) -> str:
    """A Python value as a graph file writes it: True -> "true", 0.25 -> "0.25",
    [1, 2, 3] -> "[1, 2, 3]"; a string as it is ("smooth", or a quoted name). A float is
    written by repr, the shortest text that reads back as the same double (never "%g",
    which keeps 6 digits): the library rounds that double to its float once."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(format_value(v) for v in value) + "]"
    raise TypeError("cannot write a %s as a parameter value" % type(value).__name__)


def set_strings(items, what: str = "sets"):
    """("key", value) pairs as the C array of "key=value" strings the library's sets take:
    (the strings, which must outlive the call, and the array; NULL for none). A key must be
    a str without "=" (the library splits at the first one) and neither may hold a NUL."""
    texts = []
    for k, v in items:
        key = _args.c_text(k, what + " key")
        if b"=" in key:
            raise _args.refuse("SSG_E_VALUE", "%s key %r holds '=' (the value would begin "
                               "there)" % (what, k))
        value = _args.c_text(format_value(v), "%s[%r]" % (what, k))
        texts.append(ffi.new("char[]", key + b"=" + value))
    return texts, ffi.new("const char *[]", texts) if texts else ffi.NULL


def split_sets(sets, what: str = "sets"):
    """`sets` as ("key", value) pairs: a mapping's items, or "key=value" strings."""
    if isinstance(sets, Mapping):
        return list(sets.items())
    if isinstance(sets, (str, bytes)):
        raise TypeError("%s: expected a mapping or a list of \"node.param=value\" strings, "
                        "got one %s" % (what, type(sets).__name__))
    pairs = []
    for s in sets or []:
        if not isinstance(s, str) or "=" not in s:
            raise TypeError("%s: expected \"node.param=value\", got %r" % (what, s))
        pairs.append(tuple(s.split("=", 1)))
    return pairs


def parse_value(text: str, kind: str) -> Value:
    """A value as the library prints it, back in Python's terms by its parameter type
    (None for no value: a node type's descriptor without a graph)."""
    if text == "":
        return None
    if kind == "bool":
        return text == "true"
    if kind == "int":
        return int(text)
    if kind == "float":
        return float(text)
    if kind in ("vec3", "int list") and text.startswith("["):
        parts = [p.strip() for p in text.strip("[]").split(",") if p.strip()]
        return [int(p) if kind == "int list" else float(p) for p in parts]
    return text


@dataclass(frozen=True)
class Param:
    """A node's parameter: its current value and its descriptor (type, unit, range, useful
    range, choices, one line of doc), from the table that parses it."""
    name: str
    type: str
    value: Value
    doc: str
    unit: Optional[str] = None
    min: Optional[float] = None
    max: Optional[float] = None
    choices: Optional[Tuple[str, ...]] = None
    soft_min: Optional[float] = None  # a number's useful range, what the viewer's slider
    soft_max: Optional[float] = None  # spans (inside min .. max); None when it has none


@dataclass(frozen=True)
class Port:
    """A node's input or output. An output's size and channels are known once loaded;
    an input's `source` is its producer as written ("g.normal"), "" when unconnected."""
    name: str
    type: str
    doc: str
    output: bool
    optional: bool = False
    channels: int = 0
    width: int = 0
    height: int = 0
    source: str = ""


@dataclass(frozen=True)
class Node:
    """One node of a loaded graph."""
    name: str
    type: str
    backend: str
    params: Dict[str, Param] = field(default_factory=dict)
    ports: List[Port] = field(default_factory=list)

    @property
    def inputs(self) -> List[Port]:
        return [p for p in self.ports if not p.output]

    @property
    def outputs(self) -> List[Port]:
        return [p for p in self.ports if p.output]


@dataclass(frozen=True)
class Camera:
    """A camera: world position, the point looked at, an up hint, vertical fov (degrees)."""
    position: Tuple[float, float, float]
    target: Tuple[float, float, float]
    up: Tuple[float, float, float] = (0.0, 1.0, 0.0)
    fov: float = 45.0


class Run:
    """What one run measured, as the CLI prints it: `stats` (frame times, every node's
    time and whether it ran), `metrics` ({"cmp.rmse": 0.012, ...} from compare nodes) and
    `warnings`. `output(port)` is the graph's latest image of that port."""

    def __init__(self, graph: "Graph", stats: dict, metrics: Dict[str, float], warnings):
        self.graph, self.stats, self.metrics, self.warnings = graph, stats, metrics, warnings

    def output(self, port: str, planar: bool = False) -> np.ndarray:
        """The port's image ("node.port") as a new float32 array (Graph.output)."""
        return self.graph.output(port, planar)

    @property
    def ran(self) -> List[str]:
        """The nodes that ran (a live graph skips those whose inputs did not change)."""
        return [name for name, n in self.stats["nodes"].items() if n["calls"] > 0]

    @property
    def why(self) -> Dict[str, str]:
        """Why each node ran or was kept, by node name: "first run", "parameter changed",
        "camera moved", "lights changed", "input g ran", "kept" (docs/development.md)."""
        return {name: n["why"] for name, n in self.stats["nodes"].items()}

    def __repr__(self) -> str:
        return "<ssgraph.Run %d frame(s), %.2f ms a frame, %d node(s) ran>" % (
            self.stats["frames"], self.stats["frame_median_ms"], len(self.ran))


def _stats_dict(s) -> dict:
    # "nodes" is keyed by node name, in the graph's order (run.stats["nodes"]["ao"]["ms"]);
    # a list made every reader search it (issue 46). Each entry keeps its "name".
    nodes = [{"name": _text(n.name), "type": _text(n.type), "backend": _text(n.backend),
              "calls": n.calls, "ms": n.ms, "avg_ms": n.avg_ms, "min_ms": n.min_ms,
              "max_ms": n.max_ms, "median_ms": n.median_ms, "share": n.share,
              "gpu_ms": n.gpu_ms, "transfer_ms": n.transfer_ms, "prepare_ms": n.prepare_ms,
              "kept": n.kept, "why": _text(n.why)}
             for n in (s.nodes[i] for i in range(s.node_count))]
    return {"frames": s.frames, "frame_avg_ms": s.frame_avg_ms,
            "frame_min_ms": s.frame_min_ms, "frame_max_ms": s.frame_max_ms,
            "frame_median_ms": s.frame_median_ms, "total_ms": s.total_ms,
            "width": s.width, "height": s.height, "threads": s.threads,
            "peak_pool_bytes": int(s.peak_pool_bytes), "gl": _text(s.gl),
            "nodes": {n["name"]: n for n in nodes}}


def _metrics_dict(s) -> Dict[str, float]:
    return {"%s.%s" % (_text(m.node), _text(m.name)): m.value
            for m in (s.metrics[i] for i in range(s.metric_count))}


class Graph:
    """A loaded graph. Not for two threads at once on the same graph (calls take turns
    through the library's lock: docs/python.md, "Threads"). Close it with close(), a
    with-block, or let it be collected."""

    def __init__(self, path, *, scene=None, lights=None, size=None, sets=None, seed=None,
                 backend=None, guard=None, keep_bytes: int = 0):
        self._handle = None
        raw_path = _args.c_path(path, "path")
        self.path = os.fsdecode(raw_path)
        keep = []  # C strings that must outlive the load call
        o = ffi.new("struct ssg_overrides *")
        o.seed = -1 if seed is None else _args.integer(seed, "seed", 0, _args.SEED_MAX)
        if scene is not None:
            keep.append(ffi.new("char[]", _args.c_path(scene, "scene")))
            o.scene = keep[-1]
        if lights is not None:
            keep.append(ffi.new("char[]", _args.c_path(lights, "lights")))
            o.lights = keep[-1]
        if backend is not None:
            keep.append(ffi.new("char[]", _args.c_text(backend, "backend")))
            o.backend = keep[-1]
        if size is not None:
            o.width, o.height = _args.size(size)
        if guard is not None:
            o.guard_given, o.guard = 1, _args.integer(guard, "guard", 0, _args.GUARD_MAX)
        keep_bytes = _args.integer(keep_bytes, "keep_bytes", 0, 2 ** 63 - 1)
        texts, array = set_strings(split_sets(sets))
        o.sets, o.set_count = array, len(texts)
        out = ffi.new("struct ssg_graph **")
        diags = new_diags()
        with locked():
            err = lib.ssg_graph_load(raw_path, o, out, diags)
            if err == lib.SSG_OK:
                self._handle = out[0]
                err = lib.ssg_graph_keep(self._handle, keep_bytes, diags)
        self.warnings = warnings_of(diags)
        if err != lib.SSG_OK:
            self.close()
        raise_for(err, diags, "loading " + self.path)

    # ---- life
    def close(self) -> None:
        """Releases the graph (its scene, images and GL objects); later calls raise."""
        if self._handle is not None:
            holder = ffi.new("struct ssg_graph **", self._handle)
            with locked():
                lib.ssg_graph_destroy(holder)
            self._handle = None

    def __enter__(self) -> "Graph":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __del__(self):
        self.close()

    def _g(self):
        if self._handle is None:
            raise ValueError("the graph %s is closed" % self.path)
        return self._handle

    def _call(self, fn, *args, what=""):
        diags = new_diags()
        with locked():
            err = fn(self._g(), *args, diags)
        raise_for(err, diags, what)

    # ---- looking
    def _info(self):
        info = ffi.new("struct ssg_graph_info *")
        lib.ssg_graph_inspect(self._g(), info)
        return info

    @property
    def size(self) -> Tuple[int, int]:
        """(width, height) of the frame, pixels."""
        f = self._info().frame
        return f.width, f.height

    @property
    def scene(self) -> str:
        """The scene file the graph uses, resolved; "" for none."""
        return _text(self._info().scene)

    @property
    def node_names(self) -> List[str]:
        """Every node's instance name, in file order."""
        return [n.name for n in self.nodes]

    @property
    def nodes(self) -> List[Node]:
        """Every node in file order, with its parameters' current values and its ports."""
        with locked():
            return [self._node(i) for i in range(self._info().node_count)]

    def node(self, name: str) -> Node:
        """One node by instance name (KeyError-like UnknownNameError when there is none)."""
        for n in self.nodes:
            if n.name == name:
                return n
        raise _unknown("SSG_E_UNKNOWN_NAME", "%s: the graph has no node '%s' (it has: %s)"
                       % (self.path, name, ", ".join(self.node_names)))

    def _node(self, index: int) -> Node:
        info = ffi.new("struct ssg_node_info *")
        lib.ssg_graph_node_inspect(self._g(), index, info)
        kind = _text(info.type)
        params = {}
        value = ffi.new("char[]", 512)
        for k in range(info.param_count):
            name = _text(lib.ssg_graph_node_param(self._g(), index, k, value, 512))
            params[name] = _param(kind, k, _text(value),
                                  lambda: self._float("%s.%s" % (_text(info.name), name)))
        ports = []
        port = ffi.new("struct ssg_port_info *")
        for k in range(lib.ssg_graph_port_count(self._g(), index)):
            lib.ssg_graph_port_inspect(self._g(), index, k, port)
            ports.append(Port(_text(port.name), _text(port.type), _text(port.doc),
                              bool(port.output), bool(port.optional), port.channels,
                              port.width, port.height, _text(getattr(port, "from"))))
        return Node(_text(info.name), kind, _text(info.backend), params, ports)

    def _float(self, key: str) -> float:
        """A float parameter's value exactly (the library prints 6 digits: "%g")."""
        value = ffi.new("double *")
        self._call(lib.ssg_graph_param, _args.c_text(key, "key"), value, ffi.NULL,
                   what="reading " + key)
        return value[0]

    def get(self, key: str) -> Value:
        """A parameter's current value, key "node.param" ("ao.radius"). A float is the
        library's float exactly (0.1 set reads back as 0.10000000149011612, the float
        nearest 0.1), a bool True or False."""
        _args.c_text(key, "key")
        name, _, param = key.partition(".")
        node = self.node(name)
        if param not in node.params:
            raise _unknown("SSG_E_UNKNOWN_PARAM", "%s: node '%s' (%s) has no parameter '%s' "
                           "(it has: %s)" % (self.path, name, node.type, param,
                                             ", ".join(node.params)))
        return node.params[param].value

    # ---- changing
    def set(self, key: str, value: Value) -> "Graph":
        """Sets one parameter, key "node.param", as `--set` would (the same parsing and
        checks; errors name the node's place in its graph file). Returns the graph, so
        that calls chain: g.set("ao.radius", 0.25).run()."""
        self._call(lib.ssg_graph_set, _args.c_text(key, "key"),
                   _args.c_text(format_value(value), "value of " + repr(key)),
                   what="setting " + key)
        return self

    def update(self, values: Mapping[str, Value]) -> "Graph":
        """Sets several parameters, in order (stops at the first error)."""
        for key, value in values.items():
            self.set(key, value)
        return self

    @property
    def camera(self) -> Camera:
        """The camera of the graph's scene; assign a Camera to move it (every node that
        reads the camera runs again; those that never do keep their results)."""
        view = ffi.new("struct ssg_view *")
        self._call(lib.ssg_graph_view, view, what="the camera")
        return _camera(view)

    @camera.setter
    def camera(self, camera: Camera) -> None:
        view = ffi.new("struct ssg_view *")
        view.position, view.target, view.up = (_vec3(camera, n) for n in (
            "position", "target", "up"))
        view.fov_y = _real(camera.fov, "camera fov")
        self._call(lib.ssg_graph_set_view, view, what="setting the camera")

    def set_lights(self, lights=None) -> "Graph":
        """Lights the scene with the lights and environment of a lights file (as
        `--lights`: examples/lights/sun.scene, sky.scene, courtyard.scene), or with the
        scene's own with None. The nodes that read the lights run again; the rest are
        kept. Returns the graph."""
        path = ffi.NULL if lights is None else _args.c_path(lights, "lights")
        self._call(lib.ssg_graph_set_lights, path, what="setting the lights")
        return self

    def camera_at(self, frame: int) -> Camera:
        """Frame `frame`'s camera on the scene's camera path (the scene's camera without
        one)."""
        view = ffi.new("struct ssg_view *")
        self._call(lib.ssg_graph_camera_at, _args.integer(frame, "frame", 0, _args.INT_MAX),
                   view, what="the camera path")
        return _camera(view)

    def jitter_at(self, frame: int) -> tuple:
        """Frame `frame`'s sub-pixel jitter (x, y) in pixels under the graph's `jitter N`
        line, (0.0, 0.0) without one (docs/time.md)."""
        jitter = ffi.new("float[2]")
        self._call(lib.ssg_graph_jitter_at, _args.integer(frame, "frame", 0, _args.INT_MAX),
                   jitter, what="the jitter")
        return (jitter[0], jitter[1])

    def set_frame(self, frame: int) -> "Graph":
        """The frame the next run starts at (docs/time.md): the next frame after the last
        run follows on from it (history kept); any other is a cut."""
        self._call(lib.ssg_graph_set_frame, _args.integer(frame, "frame", 0, _args.INT_MAX),
                   what="setting the frame")
        return self

    def supply(self, node: str, image: np.ndarray) -> "Graph":
        """Gives an `input` node its image (float32, H x W or H x W x C, C-contiguous; the
        node's size and channels): the graph keeps a copy for every later run."""
        owner = to_library(image, "supply(%r)" % node)
        self._call(lib.ssg_graph_supply, _args.c_text(node, "node"), owner,
                   what="supplying " + node)
        return self

    # ---- running
    def run(self, frames: int = 1, threads: int = 0, write: bool = False,
            out_dir: Optional[str] = None) -> Run:
        """Runs the graph: the nodes whose parameters, inputs or camera changed since the
        last run, and what reads them. `write`: the graph's write nodes write their files
        into out_dir (default "out"), as `ssgraph run` does; by default they do not, and
        you read ports with output(). A compare node runs when an input ran or it was
        changed, else it is kept and its metrics reported again (Run.metrics). The GIL is
        released while it runs."""
        frames = _args.integer(frames, "frames", 1, _args.FRAMES_MAX)
        threads = _args.integer(threads, "threads", 0, _args.THREADS_MAX)
        folder = ffi.new("char[]", _args.c_path(out_dir, "out_dir")) if out_dir else ffi.NULL
        stats = ffi.new("struct ssg_run_stats *")
        options = ffi.new("struct ssg_run_options *")
        options.frames, options.threads, options.stats = frames, threads, stats
        options.no_files = 0 if write else 1
        options.out_dir = folder
        diags = new_diags()
        try:
            with locked():
                err = lib.ssg_graph_run(self._g(), options, diags)
            raise_for(err, diags, "running " + self.path)
            return Run(self, _stats_dict(stats), _metrics_dict(stats), warnings_of(diags))
        finally:
            lib.ssg_run_stats_free(stats)

    def output(self, port: str, planar: bool = False) -> np.ndarray:
        """The latest image of an output, port "node.port" ("b.out"), as a new float32
        array: H x W for one channel, H x W x C for more (planar: C x H x W). The graph
        must have run."""
        out = ffi.new("struct ssg_image **")
        self._call(lib.ssg_graph_output, _args.c_text(port, "port"), out,
                   what="output " + port)
        return from_library(out[0], planar)

    def __repr__(self) -> str:
        if self._handle is None:
            return "<ssgraph.Graph %s (closed)>" % self.path
        w, h = self.size
        return "<ssgraph.Graph %s %dx%d, %d nodes>" % (self.path, w, h,
                                                      self._info().node_count)


def _param(kind: str, k: int, value: str, exact=None) -> Param:
    """Parameter k of node type `kind`, its value from the library's text (a float's from
    exact() when given: the text has 6 digits)."""
    info = ffi.new("struct ssg_param_info *")
    if lib.ssg_node_param_info(kind.encode(), k, info) != lib.SSG_OK:
        return Param("?", "?", value, "")
    choices = None
    if info.choices != ffi.NULL:
        choices, i = [], 0
        while info.choices[i] != ffi.NULL:
            choices.append(_text(info.choices[i]))
            i += 1
        choices = tuple(choices)
    ptype = _text(info.type)
    parsed = exact() if exact is not None and ptype == "float" else parse_value(value, ptype)
    soft = info.soft_max > info.soft_min
    return Param(_text(info.name), ptype, parsed, _text(info.doc),
                 _text(info.unit) or None, info.min if info.bounded else None,
                 info.max if info.bounded else None, choices,
                 info.soft_min if soft else None, info.soft_max if soft else None)


def _real(value, name: str) -> float:
    """A real number as the library's float (NaN and infinities pass: the library refuses
    them with the camera's own message)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError("%s: expected a number, got %r" % (name, value))
    return float(value)


def _vec3(camera: Camera, field: str) -> List[float]:
    v = getattr(camera, field)
    if isinstance(v, (str, bytes)) or not hasattr(v, "__len__") or len(v) != 3:
        raise TypeError("camera %s: expected 3 numbers, got %r" % (field, v))
    return [_real(x, "camera %s" % field) for x in v]


def _camera(view) -> Camera:
    return Camera(tuple(view.position), tuple(view.target), tuple(view.up), view.fov_y)


def _unknown(code: str, message: str) -> Error:
    from ._errors import Diagnostic, UnknownNameError
    return UnknownNameError(code, [Diagnostic(code, "", 0, 0, message)])


def load(path, *, scene=None, lights=None, size=None, sets=None, seed=None, backend=None,
         guard=None, keep_bytes: int = 0) -> Graph:
    """Loads a graph file once: parses it, applies the overrides (as `ssgraph run`'s
    --scene, --lights, --size "WxH" or (W, H), --set {"ao.radius": 0.25}, --seed,
    --backend "cpu" | "gl", --guard), loads the scene and validates the whole graph.
    Errors raise ssgraph.Error with file, line, column and message. keep_bytes limits the
    images the graph keeps between runs (0: no limit)."""
    return Graph(path, scene=scene, lights=lights, size=size, sets=sets, seed=seed,
                 backend=backend, guard=guard, keep_bytes=keep_bytes)
