"""Run inside Blender's interface with simulated events (tests/CMakeLists.txt, CTest
`BlenderAddonInterface`, under xvfb-run):

    blender --factory-startup --enable-event-simulate --python bake_in_the_interface.py -- \\
        ADDON_FOLDER OUT_FOLDER DEVICE

The Bake button's operator runs beside the interface: a long bake shows its frame in the status
bar and stops at Esc (no Volume object, the modeflow process gone); a short one then runs to the
end and loads its 10 frames."""

import os
import sys
import time

import bpy

addon_folder, out, device = sys.argv[sys.argv.index("--") + 1:]
sys.path.insert(0, addon_folder)
sys.path.insert(0, os.path.join(addon_folder, "pictures"))
import modeflow_blender  # noqa: E402
from plume_shot import plume_shot  # noqa: E402

modeflow_blender.register()
os.environ["MODEFLOW_CACHE_DIR"] = os.path.join(out, "cache")
domain, emitter, obstacle = plume_shot(resolution=16, modes=32, frames=400, buoyancy=4.0,
                                      emitter_radius=0.35, obstacle_size=0.4, obstacle_turn=1.2)
domain.modeflow.device = device
# Saved into this run's folder: the bake goes beside the .blend file (//modeflow_Cube).
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out, "shot.blend"))
log = os.path.join(modeflow_blender.bake.bake_folder(domain), "bake.log")
state = {"phase": "long", "since": time.monotonic()}


def finish(message):
    print(message, flush=True)
    bpy.ops.wm.quit_blender()


def invoke_bake():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == 'VIEW_3D')
    with bpy.context.temp_override(window=window, area=area):
        return bpy.ops.modeflow.bake('INVOKE_DEFAULT')


def frames_in_log():
    if not os.path.exists(log):
        return 0
    with open(log) as text:
        return text.read().count("frame ")


def tick():
    window = bpy.context.window_manager.windows[0]
    waited = time.monotonic() - state["since"]
    if waited > 300:
        finish(f"FAILED: phase {state['phase']} took over 300 s")
        return None
    if state["phase"] == "long":
        if invoke_bake() != {'RUNNING_MODAL'}:
            finish("FAILED: the bake did not run beside the interface")
            return None
        state.update(phase="running", since=time.monotonic())
    elif state["phase"] == "running":
        if frames_in_log() >= 2:
            window.event_simulate(type='ESC', value='PRESS')
            state.update(phase="cancelled", since=time.monotonic(), frames=frames_in_log())
    elif state["phase"] == "cancelled":
        # The interface handles the key at its next event loop turn (slow under xvfb): what the
        # log holds 2 s after Esc must stay as it is.
        if waited < 2.0:
            return 0.25
        state.update(phase="settled", since=time.monotonic(), frames=frames_in_log())
    elif state["phase"] == "settled":
        if waited < 2.0:
            return 0.25
        if "Cube_smoke" in bpy.data.objects:
            finish("FAILED: a cancelled bake loaded frames")
            return None
        if frames_in_log() != state["frames"] or state["frames"] >= 400:
            finish(f"FAILED: modeflow went on after Esc ({state['frames']} frames, then {frames_in_log()})")
            return None
        domain.modeflow.frame_end = 10
        if invoke_bake() != {'RUNNING_MODAL'}:
            finish("FAILED: the second bake did not start")
            return None
        state.update(phase="short", since=time.monotonic())
    elif state["phase"] == "short":
        smoke = bpy.data.objects.get("Cube_smoke")
        if smoke is not None:
            if smoke.data.frame_duration != 10:
                finish(f"FAILED: {smoke.data.frame_duration} frames loaded")
            else:
                finish("PASSED")
            return None
    return 0.25


bpy.app.timers.register(tick, first_interval=2.0)
