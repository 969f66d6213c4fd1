"""What the tests share: the repository root (graphs and scenes are read from it), the
ssgraph command (SSG_BIN, as ctest sets it), and small hand-made G-buffers."""
import math
import os
import pathlib

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo() -> pathlib.Path:
    return REPO


@pytest.fixture(scope="session")
def ssgraph_bin() -> str:
    path = os.environ.get("SSG_BIN") or str(REPO / "build" / "ssgraph")
    if not os.access(path, os.X_OK):
        pytest.fail("no ssgraph command at %s: set SSG_BIN" % path)
    return path


def plane_gbuffer(width: int, height: int, depth: float = 2.0, fov: float = 45.0):
    """View-space position and normal of a plane facing the camera at `depth`, each pixel's
    position on its own view ray (camera down -z, y up, row 0 at the top), as the library's
    projection places it."""
    t = math.tan(math.radians(fov) / 2)
    aspect = width / height
    x = ((np.arange(width) + 0.5) / width * 2 - 1) * t * aspect
    y = (1 - (np.arange(height) + 0.5) / height * 2) * t
    pos = np.empty((height, width, 3), np.float32)
    pos[..., 0] = x[None, :] * depth
    pos[..., 1] = y[:, None] * depth
    pos[..., 2] = -depth
    normal = np.zeros((height, width, 3), np.float32)
    normal[..., 2] = 1
    return pos, normal
