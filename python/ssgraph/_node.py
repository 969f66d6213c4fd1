"""Single nodes on arrays: the unit-test path (ssg_node_run), and the node registry."""
from typing import Dict, List, Mapping, Optional

import numpy as np

from . import _args
from ._errors import new_diags, raise_for
from ._graph import Param, Value, _param, _real, _text, set_strings
from ._images import from_library, to_library
from ._lock import locked
from ._ssgraph import ffi, lib


class NodeRun:
    """A node's outputs ({"out": array, ...} in its port order) and the metrics it
    reported ({"rmse": ...}: compare). Indexing reads an output: r["out"]."""

    def __init__(self, outputs: Dict[str, np.ndarray], metrics: Dict[str, float]):
        self.outputs, self.metrics = outputs, metrics

    def __getitem__(self, port: str) -> np.ndarray:
        return self.outputs[port]

    def __repr__(self) -> str:
        shapes = ", ".join("%s %s" % (k, v.shape) for k, v in self.outputs.items())
        return "<ssgraph.NodeRun %s>" % shapes


def run_node(node: str, inputs: Mapping[str, np.ndarray],
             params: Optional[Mapping[str, Value]] = None, *, width: Optional[int] = None,
             height: Optional[int] = None, fov: Optional[float] = None,
             near: Optional[float] = None, far: Optional[float] = None,
             seed: Optional[int] = None, frame: Optional[int] = None,
             backend: Optional[str] = None, planar: bool = False) -> NodeRun:
    """Runs one node of type `node` alone on arrays: inputs by port name (float32,
    H x W or H x W x C), parameters by name. The frame (size, lens, seed) defaults to the
    first input's size and the library's camera defaults (fov 45 degrees, near 0.05, far
    100); `frame` runs it as that frame of a sequence (per-frame samples), `backend` "gl"
    on the GL backend. Errors raise ssgraph.Error (an unknown node, port or parameter, a
    value out of range, images of different sizes)."""
    node_name = _args.c_text(node, "node")
    owners = [to_library(array, "%s input %r" % (node, port)) for port, array in inputs.items()]
    names = [ffi.new("char[]", _args.c_text(port, "input port")) for port in inputs]
    bindings = ffi.new("struct ssg_binding[]", max(1, len(owners)))
    for i, (name, image) in enumerate(zip(names, owners)):
        bindings[i].port, bindings[i].image = name, image
    sets = dict(params or {})
    if frame is not None:
        sets["frame"] = _args.integer(frame, "frame", 0, _args.INT_MAX)
    if backend is not None:
        sets["backend"] = backend
    texts, set_array = set_strings(sets.items(), "params")
    f = ffi.new("struct ssg_frame *")
    first = next(iter(inputs.values()), None)
    if width is not None:
        f.width = _args.integer(width, "width", 1, _args.SIZE_MAX)
    elif first is not None:
        f.width = first.shape[1]
    if height is not None:
        f.height = _args.integer(height, "height", 1, _args.SIZE_MAX)
    elif first is not None:
        f.height = first.shape[0]
    f.fov_y = 45.0 if fov is None else _real(fov, "fov")
    f.near_z = 0.05 if near is None else _real(near, "near")
    f.far_z = 100.0 if far is None else _real(far, "far")
    f.seed = 1 if seed is None else _args.integer(seed, "seed", 0, _args.SEED_MAX)
    outputs = ffi.new("struct ssg_outputs *")
    diags = new_diags()
    with locked():
        err = lib.ssg_node_run(node_name, bindings, len(owners), set_array, len(texts), f,
                               outputs, diags)
    try:
        raise_for(err, diags, "running node " + node)
        result = {}
        for i in range(outputs.count):
            image, outputs.images[i] = outputs.images[i], ffi.NULL
            if image != ffi.NULL:
                result[_text(outputs.names[i])] = from_library(image, planar)
        metrics = {_text(outputs.metric_names[i]): outputs.metric_values[i]
                   for i in range(outputs.metric_count)}
        return NodeRun(result, metrics)
    finally:
        lib.ssg_outputs_release(outputs)


def node_types() -> List[str]:
    """Every node type the library has ("ssao", "bilateral", ...)."""
    return [_text(lib.ssg_node_name(i)) for i in range(lib.ssg_node_count())]


def node_summary(node: str) -> str:
    """A node type's one-line summary."""
    for i in range(lib.ssg_node_count()):
        if _text(lib.ssg_node_name(i)) == node:
            return _text(lib.ssg_node_summary(i))
    raise_for(lib.SSG_E_UNKNOWN_NODE, new_diags(), "no node type '%s'" % node)
    return ""


def node_params(node: str) -> Dict[str, Param]:
    """A node type's parameters with their descriptors (values: the defaults are what the
    docs say; a loaded graph's Node.params carries current values)."""
    name = _args.c_text(node, "node")
    info = ffi.new("struct ssg_param_info *")
    if lib.ssg_node_param_info(name, 0, info) == lib.SSG_E_UNKNOWN_NODE:
        raise_for(lib.SSG_E_UNKNOWN_NODE, new_diags(), "no node type '%s'" % node)
    params, k = {}, 0
    while lib.ssg_node_param_info(name, k, info) == lib.SSG_OK:
        p = _param(node, k, "")
        params[p.name] = p
        k += 1
    return params
