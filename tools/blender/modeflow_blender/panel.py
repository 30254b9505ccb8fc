"""The modeflow panel of Properties ▸ Physics."""

import bpy


class MODEFLOW_PT_physics(bpy.types.Panel):
    bl_label = "modeflow"
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "physics"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.type == 'MESH'

    def draw(self, context):
        layout = self.layout
        settings = context.object.modeflow
        layout.prop(settings, "role")
        if settings.role == 'DOMAIN':
            layout.prop(settings, "domain_shape")
            column = layout.column(align=True)
            column.prop(settings, "resolution")
            column.prop(settings, "modes")
            row = layout.row(align=True)
            row.prop(settings, "frame_start")
            row.prop(settings, "frame_end")
            layout.prop(settings, "buoyancy")
            layout.prop(settings, "viscosity")
            layout.prop(settings, "wall")
            layout.prop(settings, "integrator")
            layout.prop(settings, "wind")
            layout.prop(settings, "wind_layer")
            layout.prop(settings, "open_sides")
            fire = layout.column(align=True)
            fire.label(text="Fire (with an emitter's fuel)")
            fire.prop(settings, "ignition")
            fire.prop(settings, "burn_rate")
            fire.prop(settings, "heat")
            fire.prop(settings, "smoke")
            layout.prop(settings, "device")
            layout.operator("modeflow.bake", icon='PHYSICS')
        elif settings.role in {'EMITTER', 'INFLOW'}:
            layout.prop(settings, "density")
            layout.prop(settings, "temperature")
            layout.prop(settings, "fuel")
            if settings.role == 'INFLOW':
                layout.prop(settings, "jet")


def register():
    bpy.utils.register_class(MODEFLOW_PT_physics)


def unregister():
    bpy.utils.unregister_class(MODEFLOW_PT_physics)
