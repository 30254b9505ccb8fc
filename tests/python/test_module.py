"""The Python module against the command line and the files it writes."""

import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pyopenvdb
import pytest

import modeflow
from conftest import SCENE_DICT, SCENE_TOML, run_cli


def vdb_grid(path, name):
    return pyopenvdb.read(str(path), name)


def dense(grid, shape, components=1):
    """The grid's voxels from (0, 0, 0) (the first smoke cell; 2D: the one layer) as an array."""
    array = np.zeros(shape + ((components,) if components > 1 else ()), dtype=np.float32)
    grid.copyToArray(array, ijk=(0, 0, 0))
    return array


def test_from_dict_gives_the_cli_frames(modeflow_bin, cache_dir, tmp_path):
    # The TOML text and the dict describe one scene: the CLI runs the text, Python the dict.
    (tmp_path / "plume.toml").write_text(SCENE_TOML)
    out = tmp_path / "frames"
    run_cli(modeflow_bin, "run", tmp_path / "plume.toml", "--device", "cpu", "--out", out,
            "--cache-dir", cache_dir)
    sim = modeflow.Simulation(modeflow.Scene.from_dict(SCENE_DICT, name="plume"), device="cpu",
                              cache_dir=str(cache_dir))
    assert sim.steps_per_frame == 2
    for frame in (1, 2, 3):
        sim.step(sim.steps_per_frame)
        assert sim.frame == frame
        shape = sim.density.shape
        written = dense(vdb_grid(out / f"plume_{frame:04d}.vdb", "density"), shape + (1,))[..., 0]
        ours = sim.density.astype(np.float32)
        # Voxels below the activity threshold (1e-4) are left out of the file.
        ours[np.abs(ours) < 1e-4] = 0.0
        assert np.count_nonzero(written) > 10
        np.testing.assert_array_equal(ours, written)


@pytest.mark.parametrize("device", ["cpu", "vulkan"])
def test_fields_equal_the_vdb_written_at_the_same_step(cache_dir, tmp_path, device):
    sim = modeflow.Simulation(modeflow.Scene.from_toml(SCENE_TOML), device=device,
                              cache_dir=str(cache_dir))
    sim.step(5)
    sim.write_vdb(tmp_path / "now.vdb")
    density = sim.density
    assert density.shape == (16, 16) and density.max() > 0.1
    written = dense(vdb_grid(tmp_path / "now.vdb", "density"), (16, 16, 1))[..., 0]
    ours = density.astype(np.float32)
    ours[np.abs(ours) < 1e-4] = 0.0
    np.testing.assert_array_equal(ours, written)
    # The smoke rises from the box at the bottom: indexed [i, j], x first.
    assert density[8, 3] > density[3, 3] and density[8, 3] > density[8, 12]
    velocity = sim.velocity
    assert velocity.shape == (16, 16, 2)
    vel = dense(vdb_grid(tmp_path / "now.vdb", "vel"), (16, 16, 1), 3)[:, :, 0, :]
    ours = velocity.astype(np.float32)
    active = np.linalg.norm(ours, axis=-1) >= 1e-4
    np.testing.assert_array_equal(ours[active], vel[active][:, :2])
    assert sim.temperature.shape == (16, 16)
    assert sim.modal_velocity.shape == (12,)
    assert sim.energy == pytest.approx(0.5 * float(np.dot(sim.modal_velocity, sim.modal_velocity)))
    assert sim.time == pytest.approx(5 * 0.05)


@pytest.mark.parametrize("device", ["cpu", "vulkan"])
def test_a_fire_gives_fuel_and_flame_as_written(cache_dir, tmp_path, device):
    # The plume's source also feeds fuel that burns above 0.3: the flame is the fuel burned per
    # unit time; both arrays are the VDB's grids. Without [fire] they are None.
    plain = modeflow.Simulation(modeflow.Scene.from_toml(SCENE_TOML), device=device,
                                cache_dir=str(cache_dir))
    assert plain.fuel is None and plain.flame is None
    fiery = SCENE_TOML.replace("temperature = 4.0\n", "temperature = 4.0\nfuel = 3.0\n") + (
        "\n[fire]\nignition = 0.3\nburn_rate = 2.0\n")
    sim = modeflow.Simulation(modeflow.Scene.from_toml(fiery), device=device,
                              cache_dir=str(cache_dir))
    sim.step(5)
    sim.write_vdb(tmp_path / "fire.vdb")
    fuel, flame = sim.fuel, sim.flame
    assert fuel.shape == (16, 16) and flame.shape == (16, 16)
    assert flame.max() > 0.1 and fuel.min() >= 0.0 and flame.min() >= 0.0
    # Burning at 2 per unit time where it is hot: the flame is twice the fuel left, to first
    # order in dt (exactly 2 F e^{...} (1 - e^{-2 dt}) / (dt e^{-2 dt}) per cell).
    hot = flame > 0.0
    ratio = flame[hot] / fuel[hot]
    expected = np.expm1(2.0 * sim.dt) / sim.dt
    np.testing.assert_allclose(ratio, expected, rtol=1e-4)
    for name, ours in (("fuel", fuel), ("flame", flame)):
        written = dense(vdb_grid(tmp_path / "fire.vdb", name), (16, 16, 1))[..., 0]
        ours = ours.astype(np.float32)
        ours[np.abs(ours) < 1e-4] = 0.0
        np.testing.assert_array_equal(ours, written)


@pytest.mark.parametrize("device,tolerance", [("cpu", 1e-12), ("vulkan", 1e-6)])
def test_a_wind_blows_through_the_box(cache_dir, device, tolerance):
    # Still air in a wind of (1, 0): no disturbance arises, so the air moves at the wind's
    # velocity everywhere, walls along it included, on either backend.
    scene = modeflow.Scene.from_dict({
        "grid": {"resolution": [16, 8], "bounds_min": [0.0, 0.0], "bounds_max": [2.0, 1.0]},
        "basis": {"velocity_modes": 12, "scalar_modes": 0},
        "wind": {"velocity": [1.0, 0.0]},
    }, name="windy")
    sim = modeflow.Simulation(scene, device=device, cache_dir=str(cache_dir))
    sim.step(3)
    np.testing.assert_array_equal(sim.modal_velocity, np.zeros(12))
    np.testing.assert_allclose(sim.velocity[..., 0], 1.0, rtol=0, atol=tolerance)
    np.testing.assert_allclose(sim.velocity[..., 1], 0.0, rtol=0, atol=tolerance)


def test_open_sides_let_the_smoke_out_and_conservative_smoke_keeps_its_budget(cache_dir):
    # A box open at its bottom and top in the flow straight through it (its harmonic field):
    # conservative smoke leaves through an open side, on the device as on the CPU.
    scene = modeflow.Scene.from_dict({
        "grid": {"resolution": [8, 12], "bounds_min": [0.0, 0.0], "bounds_max": [0.8, 1.2],
                 "open": ["y_min", "y_max"]},
        "basis": {"velocity_modes": 6, "scalar_modes": 0},
        "initial": {"velocity": "modes", "amplitudes": [[1, 1.0]]},
        "simulation": {"dt": 0.02},
        "source": [{"shape": "box", "min": [0.0, 0.45], "max": [0.8, 0.75], "density": 10.0,
                    "end": 0.1}],
        "smoke": {"advection": "conservative"},
    }, name="chimney")
    sim, device = (modeflow.Simulation(scene, device=name, cache_dir=str(cache_dir))
                   for name in ("cpu", "vulkan"))
    sim.step(5)
    device.step(5)
    across = sim.velocity[..., 1]  # the same everywhere, up or down (the mode's sign)
    assert abs(across.mean()) > 0.5 and np.ptp(across) < 1e-9 * abs(across.mean())
    emitted = sim.density.sum()
    assert emitted > 0.0
    assert np.abs(device.density - sim.density).max() < 1e-4 * sim.density.max()
    sim.step(120)  # the air moves 2.4: the puff, within 0.75 of either side, has long left
    assert sim.density.sum() < 1e-6 * emitted, "the smoke left through an open side"


def test_an_inflow_lets_a_smoke_stream_in_on_either_device(cache_dir):
    # A rake upstream of a wind of (1, 0): the air coming in over rows 3 and 4 of the left side
    # carries density 1, elsewhere clean air; the wind does not mix rows, on either backend.
    scene = modeflow.Scene.from_dict({
        "grid": {"resolution": [16, 8], "bounds_min": [0.0, 0.0], "bounds_max": [2.0, 1.0]},
        "basis": {"velocity_modes": 12, "scalar_modes": 0},
        "simulation": {"dt": 0.02},
        "wind": {"velocity": [1.0, 0.0]},
        "inflow": [{"shape": "ball", "side": "x_min", "center": [0.0, 0.5], "radius": 0.13,
                    "density": 1.0}],
    }, name="rake")
    runs = [modeflow.Simulation(scene, device=device, cache_dir=str(cache_dir))
            for device in ("cpu", "vulkan")]
    for sim in runs:
        sim.step(60)  # the stream's front 1.2 in
    cpu, device = (sim.density for sim in runs)
    np.testing.assert_allclose(cpu[:6, 3:5], 1.0, rtol=0, atol=1e-3)
    assert np.abs(cpu[:, :3]).max() == 0.0 and np.abs(cpu[:, 5:]).max() == 0.0
    assert cpu[14:, 3:5].max() < 0.01, "the front has not reached the far side"
    assert np.abs(device - cpu).max() < 1e-4


def test_a_wind_goes_over_a_hill_on_either_device(cache_dir):
    # A hill of [[domain]] walls on the floor: the wind's held flow round it is the potential
    # flow the precompute solved, faster over the crest than far upstream, the same on both.
    scene = modeflow.Scene.from_dict({
        "grid": {"resolution": [32, 12], "bounds_min": [0.0, 0.0], "bounds_max": [2.0, 0.75]},
        "domain": [{"shape": "box", "min": [-1.0, -1.0], "max": [3.0, 2.0]},
                   {"shape": "ball", "op": "subtract", "center": [1.0, -0.3], "radius": 0.5}],
        "basis": {"velocity_modes": 8, "scalar_modes": 0},
        "simulation": {"dt": 0.02},
        "wind": {"velocity": [1.0, 0.0]},
    }, name="hill")
    runs = [modeflow.Simulation(scene, device=device, cache_dir=str(cache_dir))
            for device in ("cpu", "vulkan")]
    for sim in runs:
        sim.step(2)
    cpu, device = (sim.velocity for sim in runs)
    over_crest, upstream = cpu[16, 4, 0], cpu[0, 10, 0]
    assert over_crest > 1.3 * upstream and abs(upstream - 1.0) < 0.02
    assert np.abs(device - cpu).max() < 1e-4 * np.abs(cpu).max()


def test_errors_carry_the_cli_message(modeflow_bin, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(SCENE_TOML.replace("velocity_modes = 12", "velocity_mode = 12"))
    cli = run_cli(modeflow_bin, "run", bad, "--device", "cpu", "--out", tmp_path / "out", check=False)
    assert cli.returncode == 1
    message = cli.stderr.strip().splitlines()[-1]
    assert message.startswith("modeflow: error: ")
    with pytest.raises(modeflow.Error) as error:
        modeflow.Scene.load(bad)
    assert str(error.value) == message[len("modeflow: error: "):]
    assert "velocity_mode" in str(error.value)
    # The same check from a dict, naming the scene as given.
    schema = json.loads(json.dumps(SCENE_DICT))
    schema["basis"]["velocity_mode"] = schema["basis"].pop("velocity_modes")
    with pytest.raises(modeflow.Error, match="bad.toml: .*velocity_mode"):
        modeflow.Scene.from_dict(schema, name="bad")
    with pytest.raises(modeflow.Error, match=r"from_dict: smoke.buoyancy: TOML holds no NoneType"):
        modeflow.Scene.from_dict({**SCENE_DICT, "smoke": {"buoyancy": None}})
    with pytest.raises(modeflow.Error, match="--device|device"):
        modeflow.Simulation(modeflow.Scene.from_dict(SCENE_DICT), device="gpu7")


def test_splats_act_for_one_call_and_obstacles_follow_poses(cache_dir):
    still = {key: value for key, value in SCENE_DICT.items() if key not in ("source", "obstacle")}
    sim = modeflow.Simulation(modeflow.Scene.from_dict(still), device="cpu", cache_dir=str(cache_dir))
    sim.step(1)
    assert sim.energy == 0.0
    sim.add_splat(center=[0.5, 0.3], radius=0.15, force=[20.0, 0.0])
    sim.step(1)
    pushed = sim.energy
    assert pushed > 1e-4
    assert sim.velocity[8, 5, 0] > 0.0
    # No force acts any more: the midpoint rule keeps the energy (no viscosity).
    sim.step(3)
    assert sim.energy == pytest.approx(pushed, rel=1e-9)
    # The ball moves 0.05 along +x in one step: the air in it is pushed along.
    scene = dict(still, obstacle=SCENE_DICT["obstacle"])
    sim = modeflow.Simulation(modeflow.Scene.from_dict(scene), device="cpu", cache_dir=str(cache_dir))
    sim.set_obstacle_pose(0, [0.55, 0.6])
    sim.step(1)
    assert sim.energy > 1e-4
    assert sim.velocity[8, 9, 0] > 0.0
    with pytest.raises(modeflow.Error, match="no obstacle 1 .the scene has 1"):
        sim.set_obstacle_pose(1, [0.5, 0.5])
    with pytest.raises(modeflow.Error, match="not finite"):
        sim.set_obstacle_pose(0, [float("nan"), 0.5])


def test_inspect_is_the_cli_json(modeflow_bin, cache_dir, scene_file):
    ours = modeflow.inspect(modeflow.Scene.load(scene_file), cache_dir=str(cache_dir))
    cli = json.loads(run_cli(modeflow_bin, "inspect", scene_file, "--json", "--cache-dir", cache_dir).stdout)
    assert ours == cli
    assert ours["velocity"]["count"] == 12
    assert modeflow.inspect(str(scene_file), cache_dir=str(cache_dir)) == cli
    assert modeflow.inspect(ours["cache"]["path"]) == cli


def test_ctrl_c_stops_a_long_step(cache_dir):
    script = f"""
import modeflow, sys
sys.path.insert(0, {os.path.dirname(__file__)!r})
from conftest import SCENE_DICT
sim = modeflow.Simulation(modeflow.Scene.from_dict(SCENE_DICT), device="cpu", cache_dir={str(cache_dir)!r})
print("stepping", flush=True)
sim.step(10**9)
"""
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "stepping"
    time.sleep(1.0)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode != 0
    assert "KeyboardInterrupt" in stderr


def test_progress_reports_the_precompute_stages(tmp_path):
    lines = []
    modeflow.Simulation(modeflow.Scene.from_toml(SCENE_TOML), device="cpu",
                        cache_dir=str(tmp_path / "fresh"), progress=lines.append)
    assert any("velocity" in line for line in lines), lines
    assert all("\033" not in line and "\r" not in line for line in lines)


def test_the_wedge_writes_a_folder_per_value(source_dir, cache_dir, tmp_path):
    scene = tmp_path / "plume.toml"
    scene.write_text(SCENE_TOML)
    env = dict(os.environ)
    result = subprocess.run([sys.executable, str(source_dir / "tools/python/examples/wedge.py"),
                             str(scene), "--buoyancy", "0.5", "2", "--frames", "2", "--device", "cpu",
                             "--out", str(tmp_path / "wedge"), "--cache-dir", str(cache_dir)],
                            capture_output=True, text=True, env=env, timeout=600)
    assert result.returncode == 0, result.stderr
    velocities = []
    for value in ("0.5", "2"):
        folder = tmp_path / "wedge" / f"buoyancy_{value}"
        assert sorted(p.name for p in folder.iterdir()) == ["plume_0001.vdb", "plume_0002.vdb"]
        velocities.append(dense(vdb_grid(folder / "plume_0002.vdb", "vel"), (16, 16, 1), 3))
    # Warm air rises faster with more buoyancy.
    assert 0.0 < velocities[0][..., 1].max() < velocities[1][..., 1].max()


def test_sources_follow_poses(cache_dir):
    still = {key: value for key, value in SCENE_DICT.items() if key != "obstacle"}
    still["smoke"] = {"buoyancy": 0.0}
    sim = modeflow.Simulation(modeflow.Scene.from_dict(still), device="cpu", cache_dir=str(cache_dir))
    sim.step(2)
    assert sim.density[8, 2] > 0.0 and sim.density[2, 2] == 0.0
    # From the box's middle (0.5, 0.175) to the left: smoke appears there from the next step.
    sim.set_source_pose(0, [0.15, 0.175])
    sim.step(3)
    assert sim.density[2, 2] > 0.0
    assert sim.velocity.max() == 0.0  # a source without a velocity moves no air
    with pytest.raises(modeflow.Error, match="set_source_pose: no source 2 .the scene has 1"):
        sim.set_source_pose(2, [0.5, 0.5])
    with pytest.raises(modeflow.Error, match="rotation: expected .x, y, z, degrees., got 3"):
        sim.set_source_pose(0, [0.5, 0.5], rotation=[0.0, 0.0, 1.0])
