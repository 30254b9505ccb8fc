"""The modeflow scene of a Blender scene: the domain's box (or mesh), obstacles and emitters as
mesh obstacles and mesh sources with their animation sampled into key frames, inflows as boxes
on the domain's sides, and the OBJ files they name.

Time: Blender frame f is simulated time (f - frame_start + 1) / fps, so frame k of the bake
(NAME_000k.vdb) is shown at Blender frame frame_start + k - 1, and an object's pose at frame
frame_start - 1 is its pose at t = 0. Each Blender frame is `steps_per_frame` steps.
"""

import math
import os

import bpy

from .toml_text import scene_toml

STEPS_PER_FRAME = 2


def _bounds(obj):
    from mathutils import Vector

    corners = [obj.matrix_world @ Vector(corner) for corner in obj.bound_box]
    lo = [min(c[a] for c in corners) for a in range(3)]
    hi = [max(c[a] for c in corners) for a in range(3)]
    return lo, hi


def grid_of(domain):
    """bounds_min, bounds_max and cells per axis: `resolution` cells along the longest side."""
    lo, hi = _bounds(domain)
    extent = [hi[a] - lo[a] for a in range(3)]
    longest = max(extent)
    if longest <= 0.0:
        raise ValueError(f"modeflow: the domain {domain.name!r} has no extent")
    cells = [max(2, round(domain.modeflow.resolution * e / longest)) for e in extent]
    return lo, hi, cells


def _file_name(obj):
    safe = "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in obj.name)
    return f"{safe}.obj"


def write_obj(path, obj, depsgraph, in_world):
    """The evaluated mesh (modifiers applied) as triangles: in world coordinates, or in the object's
    own frame with its scale applied (its location and rotation are the key frames')."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        if in_world:
            matrix = obj.matrix_world
        else:
            from mathutils import Matrix

            scale = obj.matrix_world.to_scale()
            matrix = Matrix.Diagonal((scale[0], scale[1], scale[2], 1.0))
        flip = matrix.to_3x3().determinant() < 0.0  # a mirrored object: keep normals outward
        with open(path, "w") as out:
            out.write(f"# {obj.name}, written by the modeflow add-on\n")
            for vertex in mesh.vertices:
                p = matrix @ vertex.co
                out.write(f"v {p[0]!r} {p[1]!r} {p[2]!r}\n")
            for triangle in mesh.loop_triangles:
                a, b, c = (i + 1 for i in triangle.vertices)
                out.write(f"f {a} {c} {b}\n" if flip else f"f {a} {b} {c}\n")
    finally:
        evaluated.to_mesh_clear()


def sample_motion(obj, scene, first, last):
    """Key frames (path, rotation) of the object's world pose at Blender frames first - 1 … last,
    one key where it stands still."""
    fps = scene.render.fps / scene.render.fps_base
    kept = scene.frame_current
    path, rotation = [], []
    previous = None
    try:
        for frame in range(first - 1, last + 1):
            scene.frame_set(frame)
            t = (frame - first + 1) / fps
            location, quaternion, _ = obj.matrix_world.decompose()
            axis, angle = quaternion.to_axis_angle()
            degrees = math.degrees(angle)
            if axis.length >= 1e-12:
                axis = axis.normalized()
            else:
                axis = previous[0] if previous else axis.__class__((0.0, 0.0, 1.0))
                degrees = 0.0
            if previous is not None:
                # One axis: keep the angle continuous (350° then 10° is a 20° turn, not -340°).
                if axis.dot(previous[0]) < -0.999999:
                    axis, degrees = -axis, -degrees
                if axis.dot(previous[0]) > 0.999999:
                    axis = previous[0]
                    degrees += 360.0 * round((previous[1] - degrees) / 360.0)
            previous = (axis.copy(), degrees)
            path.append([t, *location])
            rotation.append([t, axis[0], axis[1], axis[2], degrees])
    finally:
        scene.frame_set(kept)
    if all(key[1:] == path[0][1:] for key in path):
        path = path[:1]
    if all(key[1:] == rotation[0][1:] for key in rotation):
        rotation = rotation[:1]
    return path, rotation


SIDES = ["x_min", "x_max", "y_min", "y_max", "z_min", "z_max"]


def inflow_of(obj, domain_lo, domain_hi):
    """The [[inflow]] of an Inflow object: its world bounding box (at the current frame: inflows
    stand still) and the one side of the domain's box whose plane it crosses."""
    lo, hi = _bounds(obj)
    crossed = [SIDES[2 * a + high] for a in range(3) for high in (0, 1)
               if lo[a] < (domain_hi if high else domain_lo)[a] < hi[a]]
    if len(crossed) != 1:
        where = "no side" if not crossed else f"{len(crossed)} sides ({', '.join(crossed)})"
        raise ValueError(f"modeflow: the inflow {obj.name!r} crosses {where} of the domain's box: "
                         "move it to reach across one side")
    settings = obj.modeflow
    entry = {"side": crossed[0], "shape": "box", "min": lo, "max": hi,
             "density": settings.density, "temperature": settings.temperature}
    if settings.fuel > 0.0:
        entry["fuel"] = settings.fuel
    if any(settings.jet):
        entry["velocity"] = [float(u) for u in settings.jet]
    return entry


def scene_of(domain, context, folder):
    """The scene (as dicts) of `domain` and the objects with a role, writing their meshes into
    `folder`/meshes; the frames to bake."""
    scene = context.scene
    settings = domain.modeflow
    first, last = settings.frame_start, settings.frame_end
    if last < first:
        raise ValueError(f"modeflow: frame_end {last} is before frame_start {first}")
    fps = scene.render.fps / scene.render.fps_base
    depsgraph = context.evaluated_depsgraph_get()
    meshes = os.path.join(folder, "meshes")
    os.makedirs(meshes, exist_ok=True)
    lo, hi, cells = grid_of(domain)
    description = {
        "grid": {"resolution": cells, "bounds_min": lo, "bounds_max": hi},
        "basis": {"velocity_modes": settings.modes, "scalar_modes": 0, "wall": settings.wall},
        "simulation": {"dt": 1.0 / (fps * STEPS_PER_FRAME), "integrator": settings.integrator.lower(),
                       "viscosity": settings.viscosity},
        "initial": {"velocity": "zero"},
        "smoke": {"buoyancy": settings.buoyancy},
    }
    if any(settings.wind):
        if settings.domain_shape == 'MESH':
            raise ValueError("modeflow: a wind blows through a box domain (Shape: Bounds), not "
                             "through a mesh domain's walls")
        description["wind"] = {"velocity": [float(u) for u in settings.wind]}
        if settings.wind_layer > 0.0:
            if settings.wind[2] != 0.0:
                raise ValueError("modeflow: a wind over a boundary layer blows along the floor: "
                                 "its Z must be 0")
            description["wind"].update(profile="boundary-layer", thickness=float(settings.wind_layer))
    if settings.open_sides:
        for axis, name in enumerate("xyz"):
            along = {f"{name}_min", f"{name}_max"} & set(settings.open_sides)
            if settings.wind[axis] != 0.0 and along:
                raise ValueError(f"modeflow: the wind blows along {name.upper()}, whose sides it "
                                 f"opens itself: clear Open Sides {', '.join(sorted(along))}, "
                                 "or the wind")
        if settings.wind_layer > 0.0 and any(settings.wind) and "z_min" in settings.open_sides:
            raise ValueError("modeflow: a boundary layer grows over the floor: clear Open Sides "
                             "z_min, or the Wind Layer")
        description["grid"]["open"] = [side for side in SIDES if side in settings.open_sides]
    if settings.domain_shape == 'MESH':
        name = _file_name(domain)
        write_obj(os.path.join(meshes, name), domain, depsgraph, in_world=True)
        description["domain"] = [{"shape": "mesh", "file": f"meshes/{name}"}]
    obstacles, sources, inflows = [], [], []
    for obj in scene.objects:
        role = obj.modeflow.role
        if obj.type != 'MESH' or role not in {'OBSTACLE', 'EMITTER', 'INFLOW'}:
            continue
        if role == 'INFLOW':
            inflows.append(inflow_of(obj, lo, hi))
            continue
        name = _file_name(obj)
        write_obj(os.path.join(meshes, name), obj, depsgraph, in_world=False)
        path, rotation = sample_motion(obj, scene, first, last)
        entry = {"shape": "mesh", "file": f"meshes/{name}", "path": path, "rotation": rotation}
        if role == 'OBSTACLE':
            obstacles.append(entry)
        else:
            entry["density"] = obj.modeflow.density
            entry["temperature"] = obj.modeflow.temperature
            if obj.modeflow.fuel > 0.0:
                entry["fuel"] = obj.modeflow.fuel
            sources.append(entry)
    if obstacles:
        description["obstacle"] = obstacles
    if sources:
        description["source"] = sources
    if inflows:
        description["inflow"] = inflows
    if any("fuel" in entry for entry in sources + inflows):
        description["fire"] = {"ignition": settings.ignition, "burn_rate": settings.burn_rate,
                               "heat": settings.heat, "smoke": settings.smoke}
    description["output"] = {"frames": last - first + 1, "steps_per_frame": STEPS_PER_FRAME}
    return description, last - first + 1


def write_scene(domain, context, folder):
    """Writes `folder`/NAME.toml (NAME: the domain's name, made file-safe) and its meshes;
    returns the scene file and the frame count."""
    description, frames = scene_of(domain, context, folder)
    path = os.path.join(folder, _file_name(domain)[:-4] + ".toml")
    with open(path, "w") as out:
        out.write(f"# {domain.name}: written by the modeflow Blender add-on\n\n")
        out.write(scene_toml(description))
    return path, frames
