"""Run inside Blender (tests/CMakeLists.txt, CTest `BlenderAddon`):

    blender -b --factory-startup --python bake_and_render.py -- ADDON_FOLDER OUT_FOLDER DEVICE

The factory cube becomes the domain, an icosphere the emitter and an animated cube the obstacle;
the emitter also feeds fuel that burns; the add-on bakes 10 frames, which must come back as a
10-frame Volume sequence holding `density` and `flame`, and a Cycles render of the last frame must
show the smoke against the empty background, glowing flame-coloured where it burns."""

import os
import shutil
import subprocess
import sys

import bpy

addon_folder, out, device = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, addon_folder)
sys.path.insert(0, os.path.join(addon_folder, "pictures"))
import modeflow_blender  # noqa: E402
from plume_shot import plume_shot  # noqa: E402

modeflow_blender.register()
# A cache of this run's own: the first bake precomputes, the re-bake must not.
os.environ["MODEFLOW_CACHE_DIR"] = os.path.join(out, "cache")
shutil.rmtree(os.environ["MODEFLOW_CACHE_DIR"], ignore_errors=True)


def fail(message):
    print(f"FAILED: {message}", flush=True)
    sys.exit(1)


scene = bpy.context.scene
scene.render.fps = 8  # 10 frames: 1.25 s of rising smoke
domain, emitter, obstacle = plume_shot(resolution=16, modes=32, frames=10, buoyancy=4.0,
                                      emitter_radius=0.35, obstacle_size=0.4, obstacle_turn=1.2)
domain.modeflow.device = device
# Saved into this run's folder: the bake goes beside the .blend file (//modeflow_Cube).
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out, "shot.blend"))
emitter.modeflow.density = emitter.modeflow.temperature = 10.0
emitter.modeflow.fuel = 10.0
domain.modeflow.ignition = 0.5
if bpy.ops.modeflow.bake() != {'FINISHED'}:
    fail("the bake did not finish")

smoke = bpy.data.objects.get("Cube_smoke")
if smoke is None or smoke.type != 'VOLUME':
    fail("no Volume object Cube_smoke")
volume = smoke.data
if not volume.is_sequence or volume.frame_duration != 10 or volume.frame_start != 1:
    fail(f"sequence {volume.is_sequence}, {volume.frame_duration} frames from {volume.frame_start}")
frames = sorted(f for f in os.listdir(os.path.dirname(bpy.path.abspath(volume.filepath))) if f.endswith(".vdb"))
if len(frames) != 10:
    fail(f"{len(frames)} frame files: {frames}")
scene.frame_set(10)
volume.grids.load()
if not {"density", "fuel", "flame"} <= {grid.name for grid in volume.grids}:
    fail(f"grids {[grid.name for grid in volume.grids]}")

def bake_log():
    with open(os.path.join(os.path.dirname(os.path.dirname(bpy.path.abspath(volume.filepath))), "bake.log")) as log:
        return log.read()


if "write cache" not in bake_log():
    fail("the first bake did not precompute its basis")
emitter.location.x += 0.2
if bpy.ops.modeflow.bake() != {'FINISHED'}:
    fail("the re-bake did not finish")
if "write cache" in bake_log():
    fail("the re-bake after moving the emitter precomputed the basis again")

# A wind is written as [wind] for a box domain, and refused for a mesh domain.
def windy_scene():
    return modeflow_blender.scene_export.scene_of(domain, bpy.context, os.path.join(out, "windy"))[0]


def expect_refused(what, words):
    try:
        windy_scene()
        fail(f"{what} was written")
    except ValueError as error:
        if words not in str(error):
            fail(f"{what} was refused as: {error}")


domain.modeflow.wind = (1.5, 0.0, -0.25)
if windy_scene().get("wind") != {"velocity": [1.5, 0.0, -0.25]}:
    fail(f"the wind was written as {windy_scene().get('wind')}")
# Wind Layer adds a boundary layer over the floor, for a wind along it.
domain.modeflow.wind_layer = 0.5
expect_refused("a boundary layer under a rising wind", "boundary layer")
domain.modeflow.wind = (1.5, 0.0, 0.0)
if windy_scene().get("wind") != {"velocity": [1.5, 0.0, 0.0], "profile": "boundary-layer", "thickness": 0.5}:
    fail(f"the boundary layer was written as {windy_scene().get('wind')}")
domain.modeflow.wind_layer = 0.0
domain.modeflow.domain_shape = 'MESH'
expect_refused("a wind through a mesh domain", "wind")
domain.modeflow.domain_shape = 'BOX'
domain.modeflow.wind = (0.0, 0.0, 0.0)
if "wind" in windy_scene():
    fail("still air was written as a wind")
# Open Sides are written as [grid] open, in the box's order; with a wind, none along it.
if "open" in windy_scene()["grid"]:
    fail("a closed box was written with open sides")
domain.modeflow.open_sides = {'z_max', 'x_min'}
if windy_scene()["grid"].get("open") != ["x_min", "z_max"]:
    fail(f"the open sides were written as {windy_scene()['grid'].get('open')}")
domain.modeflow.wind = (1.0, 0.0, 0.0)
expect_refused("an open side along the wind", "Open Sides x_min")
domain.modeflow.open_sides = {'z_max'}
breezy = windy_scene()
if breezy["grid"].get("open") != ["z_max"] or breezy.get("wind") != {"velocity": [1.0, 0.0, 0.0]}:
    fail(f"a breeze under an open top was written as {breezy['grid'].get('open')}, "
         f"{breezy.get('wind')}")
domain.modeflow.wind = (0.0, 0.0, 0.0)
domain.modeflow.open_sides = set()
# Walls and Viscosity are written as [basis] wall and [simulation] viscosity.
domain.modeflow.wall = 'no-slip'
domain.modeflow.viscosity = 0.01
sticky = windy_scene()
if sticky["basis"].get("wall") != "no-slip" or abs(sticky["simulation"].get("viscosity", 0.0) - 0.01) > 1e-8:
    fail(f"the walls were written as {sticky['basis']}, {sticky['simulation']}")
domain.modeflow.wall = 'free-slip'
domain.modeflow.viscosity = 0.0

# An Inflow object is written as [[inflow]]: its bounding box, on the one side of the domain's
# box it crosses (a burner through an open floor), and modeflow reads the scene; through a wall
# modeflow refuses it by name, and a box across two sides the add-on refuses.
lo, hi, _ = modeflow_blender.scene_export.grid_of(domain)
centre = [0.5 * (lo[a] + hi[a]) for a in range(3)]
bpy.ops.mesh.primitive_cube_add(size=0.4, location=(centre[0], centre[1], lo[2]))
burner = bpy.context.active_object
burner.name = "Burner"
burner.modeflow.role = 'INFLOW'
burner.modeflow.density = 2.0
burner.modeflow.temperature = 3.0
burner.modeflow.fuel = 1.0
burner.modeflow.jet = (0.0, 0.0, 1.5)
domain.modeflow.open_sides = {'z_min', 'z_max'}
inflows = windy_scene().get("inflow", [])
expected = {"side": "z_min", "shape": "box", "density": 2.0, "temperature": 3.0, "fuel": 1.0,
            "velocity": [0.0, 0.0, 1.5]}
if len(inflows) != 1 or any(inflows[0].get(key) != value for key, value in expected.items()) \
        or abs(inflows[0]["min"][2] - (lo[2] - 0.2)) > 1e-6 or abs(inflows[0]["max"][0] - (centre[0] + 0.2)) > 1e-6:
    fail(f"the inflow was written as {inflows}")
if "fire" not in windy_scene():
    fail("an inflow's fuel was written without a [fire]")


def modeflow_reads(folder):
    path, _ = modeflow_blender.scene_export.write_scene(domain, bpy.context, os.path.join(out, folder))
    checked = subprocess.run([os.environ["MODEFLOW_BIN"], "precompute", path], capture_output=True, text=True)
    return checked.returncode, checked.stderr


status, errors = modeflow_reads("inflow")
if status != 0:
    fail(f"modeflow refused the inflow's scene: {errors}")
domain.modeflow.open_sides = {'z_max'}
status, errors = modeflow_reads("inflow_walled")
if status == 0 or "z_min is a wall" not in errors:
    fail(f"an inflow through a wall was not refused by name: {status}, {errors}")
burner.location = (lo[0], lo[1], lo[2])
expect_refused("an inflow across a corner", "crosses 3 sides")
bpy.data.objects.remove(burner)
domain.modeflow.open_sides = set()

# Cycles, white background: the smoke darkens what it covers.
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = 16
scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
scene.render.resolution_x = scene.render.resolution_y = 96
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = 'PNG'
world = scene.world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
camera = scene.camera
camera.location = (3.0, -3.0, 1.5)
camera.rotation_euler = (1.35, 0.0, 0.785)
for obj in scene.objects:
    if obj.type == 'MESH':
        obj.hide_render = True  # the emitter and obstacle would be seen too


def render(path):
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = list(image.pixels)
    return [tuple(pixels[i:i + 3]) for i in range(0, len(pixels), 4)]


def grey(pixels):
    return [sum(p) / 3.0 for p in pixels]


# The flame glows orange over the grey smoke: red above blue, which neither the smoke nor the
# white background has.
fiery = render(os.path.join(out, "with_smoke.png"))
warmest = max(r - b for r, g, b in fiery)
links = smoke.data.materials[0].node_tree.links
for link in [link for link in links if link.to_socket.name == "Emission Strength"]:
    links.remove(link)
plain = render(os.path.join(out, "without_flame.png"))
coolest = max(r - b for r, g, b in plain)
with_smoke = grey(plain)
print(f"red above blue: {warmest:.3f} with the flame's glow, {coolest:.3f} without")
if warmest < 0.15 or warmest < coolest + 0.1:
    fail("the render shows no flame")
smoke.hide_render = True
without = grey(render(os.path.join(out, "empty.png")))
background = sum(without) / len(without)
changed = sum(1 for a, b in zip(with_smoke, without) if abs(a - b) > 0.1)
darkest = min(with_smoke)
print(f"background {background:.3f}, darkest smoke pixel {darkest:.3f}, {changed} of {len(without)} pixels changed")
if changed < 0.01 * len(without) or background - darkest < 0.3:
    fail("the render shows no smoke")
print("PASSED", flush=True)
