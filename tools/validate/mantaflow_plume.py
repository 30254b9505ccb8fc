"""The outside check of `reduced_vs_full`'s 3D plume: Blender's Mantaflow on the same scene.

    blender -b --factory-startup --python mantaflow_plume.py -- \
        --out plume.json [--resolution 64] [--frames 60] [--cache DIR]

Builds, in an empty scene, a closed unit box [0, 1]³ holding a gas domain of RESOLUTION³ cells
and a hot ball (r = 0.08 at (0.5, 0.5, 0.1)) emitting smoke and heat; steps FRAMES frames of
0.02 s (one Mantaflow step each) and writes, per frame, the smoke density's centroid height and
the largest face velocity component to --out as JSON. `modeflow validate` runs it when Blender
is found (tools/validate/README.md, "The outside check").

How the scene is matched to `[[source]]` and `[smoke] buoyancy` of the study:
- Buoyancy. Mantaflow adds dt·(−g)·(β / L)·T to the vertical faces each step (Blender's
  smoke_script.h: buoyancy_heat = beta / domain_size, applied with the scene gravity g), L the
  domain's longest side in metres. Ours adds buoyancy·T. So the scene's gravity is set to
  (0, 0, −1) and β = buoyancy·L; the density term (α) is 0, as ours has none.
- Units. Blender steps in cells and a time unit of its own, 0.1 per frame at 25 fps (0.4 s):
  a frame rate of 50 makes a frame 0.02 s, one step with adaptive time steps off. Velocities
  read back are in cells per that unit: × (L / resolution) / 0.4 s gives metres per second
  (`speed_scale`). Checked: the first frames' peak speed is dt·Σ T times the full grid's
  projection of the ball's force (0.72 at 64³), as ours with every mode.
- The source. Ours adds `density` and `temperature` (1 each) per unit time to the cells inside
  the ball, after each step's advection. Mantaflow's flow object adds density when its
  "absolute density" is off: 0.1·dt per frame here (the smoke is passive, so its scale leaves
  the centroid unchanged, and a tenth keeps it clear of Blender's clamp at 1). Heat it only
  sets (to the flow's temperature where the cell is cooler), before the step: keyed to
  (frame − 1)·dt it equals ours in the fluid that stays in the ball, and the first step has no
  buoyancy in both. Fluid that enters the ball warm is set, not added to (a small difference
  while the plume leaves the ball).
- What cannot match: Mantaflow advects velocity semi-Lagrangian, second order (MacCormack), with
  numerical dissipation where ours conserves energy (the Galerkin-projected advection of the
  kept modes); it solves the pressure on its full grid (every mode). Vorticity confinement,
  dissolve and noise are off here.
"""
import argparse
import json
import math
import os
import sys
import tempfile

import bpy

FRAME_SECONDS = 0.02
FPS = 50  # 1 / FRAME_SECONDS
BALL_CENTRE = (0.5, 0.5, 0.1)
BALL_RADIUS = 0.08
BUOYANCY = 1.0
RATE = 1.0  # density and temperature added per unit time by ours
DENSITY_SCALE = 0.1  # Mantaflow's density per ours (see the file's comment)


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="mantaflow_plume.py")
    parser.add_argument("--out", required=True, help="the JSON file to write")
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--cache", help="Blender's cache folder (default: a temporary one)")
    return parser.parse_args(argv)


def empty_scene():
    for thing in list(bpy.data.objects):
        bpy.data.objects.remove(thing, do_unlink=True)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.render.fps_base = 1.0
    scene.use_gravity = True
    scene.gravity = (0.0, 0.0, -1.0)
    return scene


def keyed_linearly(settings, prop, frames):
    """`prop` of `settings` rising by RATE·FRAME_SECONDS per frame, 0 at frame 1."""
    for frame in (1, frames):
        setattr(settings, prop, RATE * FRAME_SECONDS * (frame - 1))
        settings.keyframe_insert(prop, frame=frame)
    action = settings.id_data.animation_data.action
    for curve in action.fcurves:
        curve.extrapolation = "LINEAR"
        for point in curve.keyframe_points:
            point.interpolation = "LINEAR"


def build(scene, resolution, frames, cache):
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.5, 0.5, 0.5))
    domain = bpy.context.active_object
    domain.name = "domain"
    fluid = domain.modifiers.new("Fluid", "FLUID")
    fluid.fluid_type = "DOMAIN"
    d = fluid.domain_settings
    d.domain_type = "GAS"
    d.resolution_max = resolution
    d.use_adaptive_domain = False
    d.use_adaptive_timesteps = False  # one step per frame: dt = 0.02 s, as ours
    d.timesteps_min = 1
    d.timesteps_max = 1
    d.time_scale = 1.0
    d.alpha = 0.0  # no density buoyancy: ours has none
    d.beta = BUOYANCY * 1.0  # × L = 1 (see the file's comment)
    d.vorticity = 0.0
    d.use_dissolve_smoke = False
    d.use_noise = False
    for side in ("front", "back", "right", "left", "top", "bottom"):
        setattr(d, "use_collision_border_" + side, True)  # a closed box
    d.cache_type = "REPLAY"
    d.cache_directory = cache
    d.cache_frame_start = 1
    d.cache_frame_end = frames

    bpy.ops.mesh.primitive_uv_sphere_add(radius=BALL_RADIUS, location=BALL_CENTRE, segments=64,
                                         ring_count=32)
    ball = bpy.context.active_object
    ball.name = "source"
    fluid = ball.modifiers.new("Fluid", "FLUID")
    fluid.fluid_type = "FLOW"
    f = fluid.flow_settings
    f.flow_type = "SMOKE"
    f.flow_behavior = "INFLOW"
    f.flow_source = "MESH"
    f.use_plane_init = False
    f.surface_distance = 0.0  # the cells inside the ball only, as ours
    f.volume_density = 1.0
    f.subframes = 0
    f.use_absolute = False  # density added each frame
    f.density = DENSITY_SCALE * RATE * FRAME_SECONDS
    keyed_linearly(f, "temperature", frames)
    scene.frame_start = 1
    scene.frame_end = frames
    return domain


def speed_scale(resolution):
    """Mantaflow's velocities (cells per its time unit, 0.1 per frame at 25 fps) in m/s."""
    unit_seconds = FRAME_SECONDS / (0.1 * 25.0 / FPS)
    return (1.0 / resolution) / unit_seconds


def measure(d, resolution):
    n = resolution
    density = d.density_grid[:]
    if len(density) != n * n * n:
        raise RuntimeError(f"mantaflow_plume.py: the density grid has {len(density)} values, "
                           f"not {n}³")
    layer = n * n
    mass = moment = 0.0
    for z in range(n):
        m = math.fsum(density[z * layer:(z + 1) * layer])
        mass += m
        moment += m * (z + 0.5) / n
    velocity = d.velocity_grid[:]
    peak = max(max(velocity), -min(velocity)) * speed_scale(resolution)
    smoke = mass / (n * n * n) / DENSITY_SCALE  # ∫ density over the unit box, in ours' units
    return (moment / mass if mass > 0.0 else float("nan")), peak, smoke


def main():
    args = arguments()
    scene = empty_scene()
    with tempfile.TemporaryDirectory(prefix="mantaflow_plume_") as scratch:
        domain = build(scene, args.resolution, args.frames, args.cache or scratch)
        frames = []
        for frame in range(1, args.frames + 1):
            scene.frame_set(frame)
            # The simulation lives in the evaluated copy of the domain's modifier.
            evaluated = domain.evaluated_get(bpy.context.evaluated_depsgraph_get())
            height, peak, smoke = measure(evaluated.modifiers["Fluid"].domain_settings,
                                                 args.resolution)
            frames.append({"frame": frame, "time": round(frame * FRAME_SECONDS, 10),
                           "centroid_height": height, "peak_speed": peak,
                           "smoke_mass": smoke})
            print(f"mantaflow_plume: frame {frame}: centroid {height:.4f}, peak speed {peak:.4f}",
                  flush=True)
    result = {
        "solver": f"Blender {bpy.app.version_string} Mantaflow",
        "resolution": args.resolution,
        "dt": FRAME_SECONDS,
        "scene": {"box": [[0, 0, 0], [1, 1, 1]], "closed": True, "ball_centre": BALL_CENTRE,
                  "ball_radius": BALL_RADIUS, "buoyancy_beta": BUOYANCY, "gravity": -1.0,
                  "source": "density added at 0.1 per unit time, temperature set to "
                            "(frame − 1)·dt inside the ball",
                  "vorticity": 0.0, "dissolve": False, "noise": False},
        "frames": frames,
    }
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as out:
        json.dump(result, out, indent=1)


main()
