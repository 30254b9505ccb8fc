"""modeflow for Blender: a domain, obstacles and emitters set up in Properties ▸ Physics ▸
modeflow, baked by the modeflow binary into OpenVDB frames loaded as a Volume object
(tools/blender/README.md)."""

bl_info = {
    "name": "modeflow",
    "author": "modeflow",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Physics > modeflow",
    "description": "Model-reduced smoke: bake a domain with modeflow and load its VDB frames",
    "category": "Physics",
}

import bpy

from . import bake, panel, properties


class ModeflowPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    binary: bpy.props.StringProperty(
        name="modeflow binary",
        description="The modeflow program (else $MODEFLOW_BIN, else modeflow on the PATH)",
        subtype='FILE_PATH',
    )

    def draw(self, context):
        self.layout.prop(self, "binary")


def register():
    bpy.utils.register_class(ModeflowPreferences)
    properties.register()
    bake.register()
    panel.register()


def unregister():
    panel.unregister()
    bake.unregister()
    properties.unregister()
    bpy.utils.unregister_class(ModeflowPreferences)
