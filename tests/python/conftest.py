"""Fixtures of the Python module's tests (run by CTest: tests/CMakeLists.txt sets MODEFLOW_BIN,
MODEFLOW_SOURCE_DIR and PYTHONPATH=build/python)."""

import os
import pathlib
import subprocess

import pytest

import modeflow

# A small 2D plume with a ball obstacle: 16 x 16 cells, 12 velocity modes (seconds to
# precompute), warm smoke rising from a box.
SCENE_TOML = """\
[grid]
resolution = [16, 16]
bounds_min = [0.0, 0.0]
bounds_max = [1.0, 1.0]

[basis]
velocity_modes = 12
scalar_modes = 0

[simulation]
dt = 0.05
integrator = "midpoint"

[smoke]
buoyancy = 2.0

[[source]]
shape = "box"
min = [0.35, 0.1]
max = [0.65, 0.25]
density = 4.0
temperature = 4.0

[[obstacle]]
shape = "ball"
radius = 0.12
path = [[0.0, 0.5, 0.6]]

[output]
frames = 3
steps_per_frame = 2
"""

SCENE_DICT = {
    "grid": {"resolution": [16, 16], "bounds_min": [0.0, 0.0], "bounds_max": [1.0, 1.0]},
    "basis": {"velocity_modes": 12, "scalar_modes": 0},
    "simulation": {"dt": 0.05, "integrator": "midpoint"},
    "smoke": {"buoyancy": 2.0},
    "source": [{"shape": "box", "min": [0.35, 0.1], "max": [0.65, 0.25], "density": 4.0, "temperature": 4.0}],
    "obstacle": [{"shape": "ball", "radius": 0.12, "path": [[0.0, 0.5, 0.6]]}],
    "output": {"frames": 3, "steps_per_frame": 2},
}


@pytest.fixture(scope="session")
def modeflow_bin():
    return pathlib.Path(os.environ["MODEFLOW_BIN"])


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(os.environ["MODEFLOW_SOURCE_DIR"])


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("cache")


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "plume.toml"
    path.write_text(SCENE_TOML)
    return path


def run_cli(modeflow_bin, *args, check=True):
    result = subprocess.run([str(modeflow_bin), *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"modeflow {' '.join(map(str, args))} failed:\n{result.stderr}")
    return result
