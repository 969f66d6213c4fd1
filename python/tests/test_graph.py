"""Loading, looking, setting, running and reading graphs; bytes equal to the CLI's."""
import subprocess

import numpy as np
import pytest

import ssgraph
from conftest import plane_gbuffer

SIZE = (64, 48)


@pytest.fixture(scope="module")
def ssao(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE) as g:
        yield g


def test_acceptance_line(ssao):
    ssao.set("ao.radius", 0.25)
    a = ssao.run().output("b.out")
    assert a.shape == (48, 64) and a.dtype == np.float32
    assert 0.0 <= a.min() and a.max() <= 1.0 and a.mean() < 1.0  # a box has occlusion
    ssao.set("ao.radius", 0.5)


def test_nodes_params_ports(ssao):
    names = ssao.node_names
    assert {"g", "k", "ao", "b"} <= set(names)
    ao = ssao.node("ao")
    assert ao.type == "ssao" and ao.backend == "cpu"
    radius = ao.params["radius"]
    assert radius.type == "float" and radius.value == 0.5 and radius.unit
    assert radius.min is not None and radius.max is not None and radius.doc
    assert (radius.soft_min, radius.soft_max) == (0.05, 5)  # the useful range, the slider's
    assert [p.name for p in ao.inputs][:2] == ["position", "normal"]
    assert ao.inputs[0].source == "g.position"
    out = ao.outputs[0]
    assert (out.name, out.channels, out.width, out.height) == ("out", 1, 64, 48)
    assert ssao.get("ao.radius") == 0.5 and ssao.get("k.count") == 16
    assert ssao.size == SIZE and ssao.scene.endswith("cornell.scene")


def test_set_reruns_only_what_changed(ssao):
    ssao.run()
    again = ssao.run()
    assert "g" not in again.ran and "ao" not in again.ran
    ssao.set("b.size", 7)
    changed = ssao.run()
    assert "b" in changed.ran and "ao" not in changed.ran and "g" not in changed.ran
    ssao.set("b.size", 9)


def test_same_bytes_as_cli(repo, ssgraph_bin, tmp_path):
    subprocess.run([ssgraph_bin, "run", str(repo / "graphs/ssao.graph"), "--size", "64x48",
                    "--set", "ao.radius=0.3", "--threads", "2", "--quiet", "--out",
                    str(tmp_path)], check=True)
    cli = ssgraph.read_image(tmp_path / "ssao.exr", "ao")
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE) as g:
        g.set("ao.radius", 0.3)
        mine = g.run(threads=2).output("b.out")
    assert mine.dtype == cli.dtype and mine.shape == cli.shape
    assert mine.tobytes() == cli.tobytes()


def test_live_sets_equal_a_fresh_load(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE) as g:
        for radius in (0.1, 0.7, 0.3):
            g.set("ao.radius", radius).run()
        live = g.output("b.out")
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE, sets={"ao.radius": 0.3}) as g:
        fresh = g.run().output("b.out")
    assert live.tobytes() == fresh.tobytes()


def test_multi_channel_and_planar(ssao):
    ssao.run()
    normal = ssao.output("g.normal")
    assert normal.shape == (48, 64, 3) and normal.flags["C_CONTIGUOUS"]
    planar = ssao.output("g.normal", planar=True)
    assert planar.shape == (3, 48, 64)
    assert np.array_equal(planar.transpose(1, 2, 0), normal)
    lengths = np.linalg.norm(normal.reshape(-1, 3), axis=1)
    assert np.all((np.abs(lengths - 1) < 1e-3) | (lengths == 0))


def test_output_is_a_copy(ssao):
    first = ssao.run().output("b.out")
    kept = first.copy()
    ssao.set("ao.radius", 0.9).run()
    assert np.array_equal(first, kept)
    ssao.set("ao.radius", 0.5)


def test_stats_and_metrics(repo):
    with ssgraph.load(repo / "graphs/ao_error.graph", size=(32, 24),
                      sets={"ref.rays": 16}) as g:
        run = g.run(threads=1)
    assert run.stats["width"] == 32 and run.stats["frames"] == 1
    assert set(run.stats["nodes"]) >= {"g", "ref"}  # keyed by node name, in graph order
    assert all(n["ms"] >= 0 for n in run.stats["nodes"].values())
    assert run.stats["nodes"]["g"]["name"] == "g" and run.stats["nodes"]["g"]["calls"] >= 1
    rmse = [k for k in run.metrics if k.endswith(".rmse")]
    assert rmse and all(0 <= run.metrics[k] < 1 for k in rmse)


def test_why_each_node_ran(repo):
    """Run.why says why each node ran or was kept; set_lights relights, its readers alone
    running again, with a fresh load's bytes; a lights file that does not load is refused."""
    sets = {"lm.resolution": 64, "lb.resolution": 32, "sm.resolution": 64}
    with ssgraph.load(repo / "graphs/gi.graph", size=SIZE, sets=sets) as g:
        first = g.run().why
        assert first.pop("out") == "not run: no files"  # Python's runs write no files
        assert set(first.values()) == {"first run"}
        g.set("gdo.radius", 0.4)
        why = g.run().why
        assert why["gdo"] == "parameter changed" and why["gf"] == "input gdo ran"
        assert why["g"] == "kept" and why["lm"] == "kept"
        sky = repo / "examples/lights/sky.scene"
        relit = g.set_lights(sky).run()
        assert relit.why["lp"] == "lights changed" and relit.why["gk"] == "kept"
        with pytest.raises(ssgraph.Error):
            g.set_lights(repo / "examples/lights/no_such.scene")
        assert set(g.run().why.values()) == {"kept", "not run: no files"}
        image = g.run().output("gi.out")
    with ssgraph.load(repo / "graphs/gi.graph", size=SIZE, lights=sky,
                      sets=dict(sets, **{"gdo.radius": 0.4})) as fresh:
        assert np.array_equal(fresh.run().output("gi.out"), image)


def test_camera(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE) as g:
        before = g.run().output("b.out")
        cam = g.camera
        g.camera = ssgraph.Camera(cam.position, (0.0, 0.5, 0.0), cam.up, cam.fov)
        assert g.camera.target == (0.0, 0.5, 0.0)
        moved = g.run().output("b.out")
        assert not np.array_equal(before, moved)
        g.camera = cam
        assert np.array_equal(g.run().output("b.out"), before)


def test_camera_path_and_frames(repo):
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE,
                      scene=repo / "examples/cornell_orbit.scene") as g:
        assert g.camera_at(0) != g.camera_at(10)
        g.set_frame(10)
        run = g.run(frames=2)
        assert run.stats["frames"] == 2


def test_jitter_at(repo):
    # an engine asks for frame f's offset before rendering it (docs/time.md)
    with ssgraph.load(repo / "graphs/gi_taau.graph", size=SIZE) as g:
        assert g.jitter_at(0) == (0.0, pytest.approx(-1.0 / 6.0))
        assert g.jitter_at(1) == (-0.25, pytest.approx(1.0 / 6.0))
        assert g.jitter_at(8) == g.jitter_at(0)
    with ssgraph.load(repo / "graphs/ssao.graph", size=SIZE) as g:
        assert g.jitter_at(3) == (0.0, 0.0)


def test_supply_an_engine_gbuffer(tmp_path):
    graph = tmp_path / "engine.graph"
    graph.write_text("size 40 30\n"
                     "pos = input(type=vector)\n"
                     "nrm = input(type=vector)\n"
                     "k   = halton(count=8, bases=[2, 3])\n"
                     "ao  = ssao(pos.out, nrm.out, kernel=k.samples, rotation=k.rotation, "
                     "radius=0.5)\n"
                     "write(ao.out, \"ao\")\n")
    pos, normal = plane_gbuffer(40, 30)
    with ssgraph.load(graph) as g:
        g.supply("pos", pos).supply("nrm", normal)
        ao = g.run().output("ao.out")
        # a lone plane occludes nothing above it: AO 1 everywhere (docs/analytic.md)
        assert ao.shape == (30, 40) and np.allclose(ao, 1.0, atol=1e-6)
        assert np.array_equal(g.output("pos.out"), pos)


def test_write_files(repo, tmp_path):
    with ssgraph.load(repo / "graphs/ssao.graph", size=(32, 24)) as g:
        g.run(out_dir=str(tmp_path))
        assert not (tmp_path / "ssao.exr").exists()  # write nodes wait for write=True
        g.run(write=True, out_dir=str(tmp_path))
        assert (tmp_path / "ssao.exr").exists() and (tmp_path / "ssao.png").exists()


def test_image_round_trip(tmp_path):
    rng = np.random.default_rng(1)
    for shape in [(5, 7), (5, 7, 3), (5, 7, 4)]:
        a = rng.random(shape, dtype=np.float32)
        ssgraph.write_image(tmp_path / "a.exr", a)
        assert ssgraph.read_image(tmp_path / "a.exr").tobytes() == a.tobytes()


def test_help_and_types():
    assert "load" in ssgraph.__doc__ and ssgraph.load.__doc__
    assert ssgraph.Graph.run.__annotations__["return"] is ssgraph.Run
    assert ssgraph.__version__.count(".") == 2


def test_a_float_survives_set_and_get(repo):
    """Python writes a float so that the library reads the same number (repr, not "%g"'s
    6 digits) and reads it back exactly (not the library's "%g" text): the parameter is a
    C float, so what comes back is the float nearest the value."""
    with ssgraph.load(repo / "graphs/ssao.graph", size=(16, 12)) as g:
        for value in (0.123456789, 0.1, 1.0 / 3.0, 0.30000001192092896, 2.5e-6):
            g.set("ao.radius", value)
            want = float(np.float32(value))
            assert g.get("ao.radius") == want, value
            assert g.node("ao").params["radius"].value == want
        g.set("ao.radius", np.float32(0.123456789))
        assert g.get("ao.radius") == float(np.float32(0.123456789))
    with ssgraph.load(repo / "graphs/ssao.graph", size=(16, 12),
                      sets={"ao.radius": 0.123456789}) as g:
        assert g.get("ao.radius") == float(np.float32(0.123456789))


def test_a_bool_survives_set_and_get(repo):
    """"false" reads False and "true" True (bool("false") would be True)."""
    with ssgraph.load(repo / "graphs/ssao.graph", size=(16, 12)) as g:
        assert g.get("b.separable") is False  # the default
        for value in (True, False, np.bool_(True), np.bool_(False)):
            g.set("b.separable", value)
            assert g.get("b.separable") is bool(value)
            assert g.node("b").params["separable"].value is bool(value)
        assert ssgraph.node_params("bilateral")["separable"].value is None  # no graph


def test_compare_kept_when_its_inputs_did_not_change(repo):
    """A live graph's compare runs again only when an input ran or it was changed, and its
    metrics are still this run's (issue 46: every sweep step re-ran HDR-FLIP, 5.8 s of a
    step whose changed nodes took 0.12 s)."""
    with ssgraph.load(repo / "docs/tutorial/sweep.graph", size=SIZE,
                      sets={"ref.rays": 16}) as g:
        first = g.run()
        assert first.stats["nodes"]["c"]["calls"] == 1 and first.metrics["c.rmse"] > 0
        g.set("img.ambient", 0.3)  # after ao, not upstream of c
        kept = g.run()
        assert kept.stats["nodes"]["c"]["calls"] == 0 and kept.why["c"] == "kept"
        assert kept.stats["nodes"]["img"]["calls"] == 1
        assert kept.metrics == first.metrics  # reported again, the same values
        g.set("ao.radius", 0.3)  # upstream of c: it runs, with new numbers
        moved = g.run()
        assert moved.stats["nodes"]["c"]["calls"] == 1 and moved.why["c"] == "input ao ran"
        assert moved.metrics["c.rmse"] != first.metrics["c.rmse"]
        g.set("c.flip", "off")  # its own parameter
        own = g.run()
        assert own.stats["nodes"]["c"]["calls"] == 1 and "c.flip" not in own.metrics
