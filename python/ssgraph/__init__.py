"""ssgraph: screen-space global illumination graphs from Python, with numpy images.

    import ssgraph
    g = ssgraph.load("graphs/ssao.graph", size=(320, 240))
    g.set("ao.radius", 0.25)
    ao = g.run().output("b.out")          # float32, (240, 320)

Load a graph once (load), look at its nodes, parameters and ports (Graph.nodes), change
parameters and the camera (Graph.set, Graph.camera), run only what changed (Graph.run),
read any port as an array (Graph.output), feed `input` nodes from arrays (Graph.supply),
and run single nodes on arrays (run_node). Library errors raise ssgraph.Error with the
file, line and column of the problem. Reference and tutorial: docs/python.md.
"""
from ._errors import Diagnostic, Error, UnknownNameError, ValueRangeError
from ._graph import Camera, Graph, Node, Param, Port, Run, load
from ._images import read_image, write_image
from ._node import NodeRun, node_params, node_summary, node_types, run_node
from ._version import __version__

__all__ = ["load", "Graph", "Run", "Node", "Param", "Port", "Camera", "run_node", "NodeRun",
           "node_types", "node_summary", "node_params", "read_image", "write_image",
           "Error", "UnknownNameError", "ValueRangeError", "Diagnostic", "__version__"]
