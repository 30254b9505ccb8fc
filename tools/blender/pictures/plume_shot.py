"""The add-on's demonstration shot, for its pictures (make_pictures.py) and its test
(tests/blender/bake_and_render.py): Blender's factory cube (2 x 2 x 2 about the origin) as the
domain, an icosphere emitter below its middle and a cube obstacle sliding along x through the
plume while it turns about z."""

import bpy


def plume_shot(resolution, modes, frames, buoyancy, emitter_radius, obstacle_size, obstacle_turn):
    """Sets the shot up in the current scene and returns (domain, emitter, obstacle)."""
    domain = bpy.data.objects["Cube"]
    settings = domain.modeflow
    settings.role = 'DOMAIN'
    settings.resolution = resolution
    settings.modes = modes
    settings.frame_start = 1
    settings.frame_end = frames
    settings.buoyancy = buoyancy
    bpy.ops.mesh.primitive_ico_sphere_add(radius=emitter_radius, location=(0.0, 0.0, -0.6))
    emitter = bpy.context.object
    emitter.modeflow.role = 'EMITTER'
    bpy.ops.mesh.primitive_cube_add(size=obstacle_size, location=(-0.5, 0.0, 0.3))
    obstacle = bpy.context.object
    obstacle.modeflow.role = 'OBSTACLE'
    for frame, x, turn in ((1, -0.5, 0.0), (frames, 0.5, obstacle_turn)):
        obstacle.location.x = x
        obstacle.rotation_euler.z = turn
        obstacle.keyframe_insert("location", frame=frame)
        obstacle.keyframe_insert("rotation_euler", frame=frame)
    bpy.context.view_layer.objects.active = domain
    domain.select_set(True)
    return domain, emitter, obstacle
