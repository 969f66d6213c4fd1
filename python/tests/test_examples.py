"""The tutorial's example (python/examples/radius_sweep.py) runs as docs/python.md shows,
small: its sweep, its table and its plot."""
import importlib.util
import subprocess
import sys


def load_example(repo):
    path = repo / "python/examples/radius_sweep.py"
    spec = importlib.util.spec_from_file_location("radius_sweep", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_radius_sweep_finds_the_error_low_near_the_truths_distance(repo):
    sweep = load_example(repo)
    rows, _ = sweep.sweep(repo / "graphs/ao_error.graph", "80x45", [0.1, 0.55, 1.5], 64)
    errors = [ssao for _, ssao, _ in rows]
    assert errors[1] < errors[0] and errors[1] < errors[2]


def test_radius_sweep_command_writes_its_plot(repo, tmp_path):
    plot = tmp_path / "sweep.png"
    out = subprocess.run([sys.executable, str(repo / "python/examples/radius_sweep.py"),
                          "--size", "64x36", "--count", "3", "--rays", "16", "--plot",
                          str(plot)], cwd=repo, capture_output=True, text=True, check=True)
    assert "lowest ssao error at radius" in out.stdout
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
