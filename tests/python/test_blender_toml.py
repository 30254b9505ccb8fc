"""The Blender add-on's TOML writer (tools/blender/modeflow_blender/toml_text.py) against Python's
TOML reader, and the scene it writes against the modeflow loader; outside Blender, since the
writer needs no bpy."""

import importlib.util
import math
import tomllib

import pytest

import modeflow


@pytest.fixture(scope="module")
def toml_text(source_dir):
    spec = importlib.util.spec_from_file_location(
        "toml_text", source_dir / "tools/blender/modeflow_blender/toml_text.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


SCENE = {
    "grid": {"resolution": [16, 16, 16], "bounds_min": [-1.0, -1.0, -1.0], "bounds_max": [1.0, 1.0, 1.0]},
    "basis": {"velocity_modes": 16, "scalar_modes": 0},
    "simulation": {"dt": 1.0 / 48.0, "integrator": "midpoint"},
    "smoke": {"buoyancy": 4.0},
    "source": [{"shape": "box", "min": [-0.2, -0.2, -0.9], "max": [0.2, 0.2, -0.6], "density": 2.0},
               {"shape": "ball", "center": [0.5, 0.0, -0.5], "radius": 0.2, "temperature": 0.1 + 0.2}],
    "obstacle": [{"shape": "ball", "radius": 0.2, "path": [[0.0, -0.5, 0.0, 0.35], [0.5, 0.5, 0.0, 0.35]],
                  "rotation": [[0.0, 0.0, 0.0, 1.0, 0.0], [0.5, 0.0, 0.0, 1.0, 68.75493131758529]]}],
    "output": {"frames": 10, "steps_per_frame": 2},
}


def test_the_written_toml_reads_back_exactly(toml_text):
    text = toml_text.scene_toml(SCENE)
    assert tomllib.loads(text) == SCENE


def test_modeflow_reads_the_written_scene(toml_text):
    scene = modeflow.Scene.from_toml(toml_text.scene_toml(SCENE), name="written")
    assert scene.dim == 3 and scene.name == "written"


def test_strings_are_escaped_and_non_finite_numbers_refused(toml_text):
    text = toml_text.scene_toml({"domain": [{"shape": "mesh", "file": 'a "quoted" \\ name.obj'}]})
    assert tomllib.loads(text)["domain"][0]["file"] == 'a "quoted" \\ name.obj'
    with pytest.raises(ValueError, match="not a finite number"):
        toml_text.scene_toml({"smoke": {"buoyancy": math.nan}})
    with pytest.raises(TypeError, match="cannot write NoneType"):
        toml_text.scene_toml({"smoke": {"buoyancy": None}})
