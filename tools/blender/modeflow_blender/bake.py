"""bpy.ops.modeflow.bake(): writes the domain's scene, runs `modeflow run` on it and loads the
frames as the Volume object "<domain>_smoke".

In the interface the bake runs beside Blender (progress in the status bar, Esc cancels); in
background mode (`blender -b`) the operator returns when the bake is done, as scripts and render
farms need. The basis cache is modeflow's own (~/.cache/modeflow): a re-bake that changes only
emitters or obstacles reuses it.
"""

import glob
import os
import shutil
import subprocess
import tempfile

import bpy

from .scene_export import write_scene


def modeflow_binary(context):
    """The add-on's preference, else $MODEFLOW_BIN, else `modeflow` on the PATH."""
    addon = context.preferences.addons.get(__package__)
    if addon is not None and addon.preferences.binary:
        return bpy.path.abspath(addon.preferences.binary)
    if os.environ.get("MODEFLOW_BIN"):
        return os.environ["MODEFLOW_BIN"]
    found = shutil.which("modeflow")
    if found is None:
        raise RuntimeError("modeflow: no binary (set the add-on's preference, $MODEFLOW_BIN or PATH)")
    return found


def bake_folder(domain):
    """Beside the .blend file (//modeflow_<domain>), or in the temporary folder for an unsaved one."""
    name = "modeflow_" + "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in domain.name)
    if bpy.data.filepath:
        return bpy.path.abspath("//" + name)
    return os.path.join(tempfile.gettempdir(), name)


def find_domain(context):
    if context.object is not None and context.object.modeflow.role == 'DOMAIN':
        return context.object
    for obj in context.scene.objects:
        if obj.modeflow.role == 'DOMAIN':
            return obj
    return None


FLAME_COLOUR = (1.0, 0.45, 0.08, 1.0)


def smoke_material():
    material = bpy.data.materials.get("modeflow smoke")
    if material is not None:
        return material
    material = bpy.data.materials.new("modeflow smoke")
    material.use_nodes = True
    nodes = material.node_tree.nodes
    nodes.clear()
    volume = nodes.new("ShaderNodeVolumePrincipled")
    volume.inputs["Density"].default_value = 5.0
    # It reads the grids by name: "density" and "temperature" are its defaults.
    volume.inputs["Density Attribute"].default_value = "density"
    # Flames glow: the `flame` grid (fuel burned per unit time; 0 without [fire]) drives the
    # emission, in a flame's colour.
    flame = nodes.new("ShaderNodeAttribute")
    flame.attribute_name = "flame"
    volume.inputs["Emission Color"].default_value = FLAME_COLOUR
    output = nodes.new("ShaderNodeOutputMaterial")
    links = material.node_tree.links
    links.new(flame.outputs["Fac"], volume.inputs["Emission Strength"])
    links.new(volume.outputs["Volume"], output.inputs["Volume"])
    return material


def load_frames(context, domain, frames_folder, frames, first_frame):
    """The Volume object <domain>_smoke showing NAME_0001.vdb … from Blender frame first_frame."""
    files = sorted(glob.glob(os.path.join(frames_folder, "*_[0-9][0-9][0-9][0-9].vdb")))
    if len(files) < frames:
        raise RuntimeError(f"modeflow: {len(files)} of {frames} frames in {frames_folder}")
    name = f"{domain.name}_smoke"
    obj = bpy.data.objects.get(name)
    if obj is None or obj.type != 'VOLUME':
        volume = bpy.data.volumes.new(name)
        obj = bpy.data.objects.new(name, volume)
        context.scene.collection.objects.link(obj)
    volume = obj.data
    volume.filepath = files[0]
    volume.is_sequence = True
    volume.frame_start = first_frame
    volume.frame_duration = frames
    volume.sequence_mode = 'CLIP'
    if not volume.materials:
        volume.materials.append(smoke_material())
    # The domain's box would hide the smoke.
    domain.display_type = 'BOUNDS'
    domain.hide_render = True
    return obj


class MODEFLOW_OT_bake(bpy.types.Operator):
    """Simulate the domain with modeflow and load the frames as a Volume object"""

    bl_idname = "modeflow.bake"
    bl_label = "Bake"

    @classmethod
    def poll(cls, context):
        return find_domain(context) is not None

    def _start(self, context):
        self.domain = find_domain(context)
        folder = bake_folder(self.domain)
        os.makedirs(folder, exist_ok=True)
        scene_file, self.frames = write_scene(self.domain, context, folder)
        self.out = os.path.join(folder, "frames")
        # Earlier frames would be shown if this bake wrote fewer.
        for old in glob.glob(os.path.join(self.out, "*.vdb")):
            os.remove(old)
        self.log = open(os.path.join(folder, "bake.log"), "w+")
        command = [modeflow_binary(context), "run", scene_file, "--out", self.out,
                   "--frames", str(self.frames), "--device", self.domain.modeflow.device]
        self.process = subprocess.Popen(command, stdout=self.log, stderr=subprocess.STDOUT)

    def _finish(self, context):
        self.log.seek(0)
        output = self.log.read().strip()
        self.log.close()
        if self.process.returncode != 0:
            errors = [line for line in output.splitlines() if "error" in line]
            self.report({'ERROR'}, errors[-1] if errors else output[-500:] or "modeflow failed")
            return {'CANCELLED'}
        load_frames(context, self.domain, self.out, self.frames, self.domain.modeflow.frame_start)
        self.report({'INFO'}, f"modeflow: baked {self.frames} frames into {self.out}")
        return {'FINISHED'}

    def execute(self, context):
        try:
            self._start(context)
        except (RuntimeError, ValueError, OSError) as error:
            self.report({'ERROR'}, str(error))
            return {'CANCELLED'}
        self.process.wait()
        return self._finish(context)

    def invoke(self, context, event):
        if bpy.app.background:
            return self.execute(context)
        try:
            self._start(context)
        except (RuntimeError, ValueError, OSError) as error:
            self.report({'ERROR'}, str(error))
            return {'CANCELLED'}
        self.timer = context.window_manager.event_timer_add(0.25, window=context.window)
        context.window_manager.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        if event.type == 'ESC':
            self.process.terminate()
            self.process.wait()
            self.log.close()
            self._end(context)
            self.report({'WARNING'}, "modeflow: bake cancelled")
            return {'CANCELLED'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        if self.process.poll() is None:
            done = len(glob.glob(os.path.join(self.out, "*_[0-9][0-9][0-9][0-9].vdb")))
            context.workspace.status_text_set(f"modeflow: frame {done}/{self.frames} (Esc cancels)")
            return {'PASS_THROUGH'}
        self._end(context)
        return self._finish(context)

    def _end(self, context):
        context.window_manager.event_timer_remove(self.timer)
        context.workspace.status_text_set(None)


def register():
    bpy.utils.register_class(MODEFLOW_OT_bake)


def unregister():
    bpy.utils.unregister_class(MODEFLOW_OT_bake)
