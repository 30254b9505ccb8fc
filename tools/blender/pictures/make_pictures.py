"""The add-on's pictures in README.md: the panel and a rendered bake. Needs a display (the panel is
a screenshot of Blender's window):

    MODEFLOW_BIN=build/tools/modeflow/modeflow xvfb-run -a -s "-screen 0 1400x900x24" \\
        blender --factory-startup --python tools/blender/pictures/make_pictures.py

A cube domain (48 cells, 300 modes), an icosphere emitter and a cube obstacle sliding and turning
through the plume, 48 frames at 24 fps, the last rendered with Cycles."""

import os
import sys

import bpy

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(here))
sys.path.insert(0, here)
import modeflow_blender  # noqa: E402
from plume_shot import plume_shot  # noqa: E402

modeflow_blender.register()

scene = bpy.context.scene
domain, emitter, obstacle = plume_shot(resolution=48, modes=300, frames=48, buoyancy=3.0,
                                      emitter_radius=0.3, obstacle_size=0.35, obstacle_turn=3.0)
emitter.modeflow.density = emitter.modeflow.temperature = 8.0


def render():
    assert bpy.ops.modeflow.bake() == {'FINISHED'}
    scene.frame_set(48)
    scene.render.engine = 'CYCLES'
    scene.cycles.samples = 64
    scene.cycles.use_denoising = False
    scene.render.resolution_x, scene.render.resolution_y = 480, 360
    scene.render.resolution_percentage = 100
    scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.8, 0.85, 0.9, 1.0)
    scene.camera.location = (3.4, -3.4, 1.6)
    scene.camera.rotation_euler = (1.35, 0.0, 0.785)
    emitter.hide_render = True
    scene.render.filepath = os.path.join(here, "bake.png")
    bpy.ops.render.render(write_still=True)


def show_panel():
    for area in bpy.context.window_manager.windows[0].screen.areas:
        if area.type == 'PROPERTIES':
            area.spaces[0].context = 'PHYSICS'
            area.tag_redraw()
    bpy.app.timers.register(shoot, first_interval=2.0)


def shoot():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'PROPERTIES')
    with bpy.context.temp_override(window=window, screen=window.screen, area=area):
        bpy.ops.screen.screenshot_area(filepath=os.path.join(here, "panel.png"))
    bpy.ops.wm.quit_blender()


def start():
    render()
    show_panel()


bpy.app.timers.register(start, first_interval=2.0)
