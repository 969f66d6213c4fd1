"""Every kind of bad input raises a Python exception that says what and where."""
import numpy as np
import pytest

import ssgraph
from conftest import plane_gbuffer


@pytest.fixture(scope="module")
def g(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=(32, 24)) as graph:
        graph.run()
        yield graph


def test_malformed_graph_has_file_line_column(tmp_path):
    bad = tmp_path / "bad.graph"
    bad.write_text("size 32 24\ng = gbuffer()\nao = ssao(g.position, g.normal, radius=)\n")
    with pytest.raises(ssgraph.Error) as e:
        ssgraph.load(bad)
    assert e.value.file.endswith("bad.graph") and e.value.line == 3 and e.value.column > 0
    assert e.value.code == "SSG_E_SYNTAX" and "bad.graph:3:" in str(e.value)


def test_missing_file():
    with pytest.raises(ssgraph.Error) as e:
        ssgraph.load("no/such.graph")
    assert e.value.code in ("SSG_E_IO", "SSG_E_INCLUDE")


def test_unknown_node_type(tmp_path):
    bad = tmp_path / "unknown.graph"
    bad.write_text("size 32 24\nx = ssaoo()\n")
    with pytest.raises(ssgraph.UnknownNameError) as e:
        ssgraph.load(bad)
    assert e.value.code == "SSG_E_UNKNOWN_NODE" and e.value.line == 2


def test_value_out_of_range_names_the_node(g, repo):
    with pytest.raises(ssgraph.ValueRangeError) as e:
        g.set("ao.radius", -3)
    assert e.value.code == "SSG_E_RANGE" and e.value.file.endswith("ssao.graph")
    assert e.value.line > 0 and isinstance(e.value, ValueError)
    assert g.get("ao.radius") == 0.5  # the graph is as it was


def test_unknown_parameter_and_node(g):
    with pytest.raises(ssgraph.UnknownNameError) as e:
        g.set("ao.radiu", 1)
    assert e.value.code == "SSG_E_UNKNOWN_PARAM" and isinstance(e.value, KeyError)
    with pytest.raises(ssgraph.UnknownNameError):
        g.set("nosuch.radius", 1)
    with pytest.raises(ssgraph.UnknownNameError):
        g.get("ao.radiu")


def test_wrong_type_of_value(g):
    with pytest.raises(ssgraph.Error):
        g.set("ao.radius", "far")
    with pytest.raises(TypeError):
        g.set("ao.radius", object())


def test_wrong_port(g):
    with pytest.raises(ssgraph.UnknownNameError):
        g.output("b.nothing")
    with pytest.raises(ssgraph.Error):
        g.output("nodot")


def test_bad_arrays():
    pos, normal = plane_gbuffer(16, 12)
    good = {"position": pos, "normal": normal}
    with pytest.raises(TypeError, match="float32"):
        ssgraph.run_node("ssao", {**good, "position": pos.astype(np.float64)})
    with pytest.raises(ValueError, match="C-contiguous"):
        ssgraph.run_node("ssao", {**good, "position": np.asfortranarray(pos)})
    with pytest.raises(ValueError, match="shape"):
        ssgraph.run_node("ssao", {**good, "position": pos[None]})
    with pytest.raises(TypeError, match="ndarray"):
        ssgraph.run_node("ssao", {**good, "position": pos.tolist()})
    with pytest.raises(ssgraph.Error) as e:  # 3 channels where depth has 1
        ssgraph.run_node("bilateral", {"in": pos, "depth": pos, "normal": normal})
    assert e.value.code in ("SSG_E_CHANNELS", "SSG_E_TYPE", "SSG_E_SIZE")
    with pytest.raises(ssgraph.Error):
        ssgraph.run_node("ssao", {**good, "normal": normal[:6].copy()})


def test_supply_wrong_shape(tmp_path):
    graph = tmp_path / "in.graph"
    graph.write_text("size 20 10\npos = input(type=vector)\nwrite(pos.out, \"pos\")\n")
    with ssgraph.load(graph) as g:
        with pytest.raises(ssgraph.ValueRangeError) as e:
            g.supply("pos", np.zeros((10, 20), np.float32))
        assert e.value.code in ("SSG_E_SIZE", "SSG_E_CHANNELS")
        with pytest.raises(ssgraph.Error):
            g.supply("nosuch", np.zeros((10, 20, 3), np.float32))
        with pytest.raises(ssgraph.Error) as e:  # run without supplying
            g.run()
        assert "supply" in str(e.value) or e.value.code == "SSG_E_RUN"


def test_unknown_node_type_alone():
    with pytest.raises(ssgraph.UnknownNameError):
        ssgraph.run_node("nosuchnode", {})
    with pytest.raises(ssgraph.UnknownNameError):
        ssgraph.node_params("nosuchnode")


def test_closed_graph(repo):
    g = ssgraph.load(repo / "graphs/ssao.graph", size=(16, 12))
    g.close()
    with pytest.raises(ValueError, match="closed"):
        g.run()


def test_bad_camera(g):
    cam = g.camera
    with pytest.raises(ssgraph.Error):
        g.camera = ssgraph.Camera(cam.position, cam.position, cam.up, cam.fov)
    with pytest.raises(ssgraph.Error):
        g.camera = ssgraph.Camera(cam.position, cam.target, cam.up, 200.0)
