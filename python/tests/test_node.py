"""Single nodes on hand-made arrays, with answers known in closed form."""
import numpy as np
import pytest

import ssgraph
from conftest import plane_gbuffer


def test_registry():
    types = ssgraph.node_types()
    assert {"ssao", "hbao", "bilateral", "halton", "gbuffer", "temporal"} <= set(types)
    assert ssgraph.node_summary("ssao")
    params = ssgraph.node_params("ssao")
    assert params["radius"].type == "float" and params["radius"].unit


def test_ssao_on_a_lone_plane_is_unoccluded():
    pos, normal = plane_gbuffer(24, 16)
    k = ssgraph.run_node("halton", {}, {"count": 8}, width=24, height=16)
    r = ssgraph.run_node("ssao", {"position": pos, "normal": normal,
                                  "kernel": k["samples"], "rotation": k["rotation"]},
                         {"radius": 0.5})
    assert r["out"].shape == (16, 24) and np.allclose(r["out"], 1.0, atol=1e-6)


def test_bilateral_keeps_a_constant_image():
    pos, normal = plane_gbuffer(20, 12)
    flat = np.full((12, 20), 0.375, np.float32)
    r = ssgraph.run_node("bilateral", {"in": flat, "depth": np.ascontiguousarray(-pos[..., 2]),
                                       "normal": normal}, {"size": 5})
    assert np.allclose(r["out"], 0.375, atol=1e-6)


def test_compare_reports_metrics():
    a = np.zeros((8, 8), np.float32)
    b = np.full((8, 8), 0.5, np.float32)
    r = ssgraph.run_node("compare", {"a": a, "b": b})
    assert r.metrics["rmse"] == pytest.approx(0.5)


def test_same_as_inside_a_graph(repo):
    """ssao run alone on a graph's own G-buffer gives the graph's bytes."""
    with ssgraph.load(repo / "graphs/ssao.graph", size=(48, 32)) as g:
        g.run()
        pos, normal = g.output("g.position"), g.output("g.normal")
        samples, rotation = g.output("k.samples"), g.output("k.rotation")
        inside = g.output("ao.out")
        cam = g.camera
    alone = ssgraph.run_node("ssao", {"position": pos, "normal": normal, "kernel": samples,
                                      "rotation": rotation}, {"radius": 0.5}, fov=cam.fov)
    assert np.array_equal(alone["out"], inside)
