"""obj.modeflow: an object's part in the simulation and, by part, its settings."""

import bpy
from bpy.props import EnumProperty, FloatProperty, FloatVectorProperty, IntProperty

# The most a smoke value (density, temperature, fuel, heat) may be in a scene: modeflow's loader
# refuses more (its smoke is held in 32-bit floats on the device).
SMOKE_LIMIT = 1e6


class ModeflowObjectSettings(bpy.types.PropertyGroup):
    role: EnumProperty(
        name="Role",
        items=[
            ('NONE', "None", "Not part of the simulation"),
            ('DOMAIN', "Domain", "The box (its bounds) or the mesh the fluid fills"),
            ('OBSTACLE', "Obstacle", "A solid the air flows around; moves and turns with its animation"),
            ('EMITTER', "Emitter", "Emits smoke and heat from its volume; moves with its animation"),
            ('INFLOW', "Inflow", "Lets smoke, heat and fuel in where its bounding box crosses a side of "
                                 "the domain's box (an open side, or the wind's upstream side)"),
        ],
        default='NONE',
    )
    # Domain
    domain_shape: EnumProperty(
        name="Shape",
        items=[('BOX', "Bounds", "The object's bounding box"),
               ('MESH', "Mesh", "The object's closed mesh (cut cells)")],
        default='BOX',
    )
    modes: IntProperty(name="Modes", description="Velocity modes of the basis", default=64, min=4, max=20000)
    resolution: IntProperty(name="Resolution", description="Cells on the longest axis", default=32, min=4, max=512)
    frame_start: IntProperty(name="Start", default=1)
    frame_end: IntProperty(name="End", default=50)
    buoyancy: FloatProperty(name="Buoyancy", description="Lift per unit of temperature", default=1.0)
    viscosity: FloatProperty(name="Viscosity", description="Kinematic viscosity of the air (scene units² "
                                                           "per second)", default=0.0, min=0.0, max=1e6)
    wall: EnumProperty(
        name="Walls",
        description="What the walls of a mesh domain do to the air along them (with a viscosity)",
        items=[('free-slip', "Free-slip", "The air slides along the walls"),
               ('no-slip', "No-slip", "The air sticks to the walls: a boundary layer grows as fast "
                                      "as the viscosity diffuses it")],
        default='free-slip',
    )
    integrator: EnumProperty(
        name="Integrator",
        items=[('MIDPOINT', "Midpoint", "Energy-preserving (the default)"),
               ('TRAPEZOIDAL', "Trapezoidal", ""),
               ('LINEARIZED', "Linearized", "Fastest energy-preserving step"),
               ('RK4', "RK4", ""),
               ('EXPLICIT', "Explicit", "")],
        default='MIDPOINT',
    )
    wind: FloatVectorProperty(name="Wind", size=3, subtype='VELOCITY', default=(0.0, 0.0, 0.0),
                              description="Velocity of the air blowing through the box (written as "
                                          "[wind] when not zero)")
    wind_layer: FloatProperty(name="Wind Layer", subtype='DISTANCE', default=0.0, min=0.0,
                              description="Thickness of the boundary layer over the domain's floor, "
                                          "where the wind slows towards the ground (0: the same "
                                          "wind at every height)")
    open_sides: EnumProperty(
        name="Open Sides",
        description="Sides of the domain's box the air may cross (written as [grid] open): an "
                    "open top over a fire lets its smoke out",
        items=[('x_min', "-X", "The box's low side along X"),
               ('x_max', "+X", "The box's high side along X"),
               ('y_min', "-Y", "The box's low side along Y"),
               ('y_max', "+Y", "The box's high side along Y"),
               ('z_min', "-Z", "The box's floor"),
               ('z_max', "+Z", "The box's top")],
        options={'ENUM_FLAG'},
        default=set(),
    )
    # Fire (written as [fire] when an emitter feeds fuel)
    ignition: FloatProperty(name="Ignition", description="Temperature above which fuel burns", default=1.0,
                            min=-SMOKE_LIMIT, max=SMOKE_LIMIT)
    burn_rate: FloatProperty(name="Burn Rate", description="Part of the fuel burnt per unit of time",
                             default=4.0, min=0.001)
    heat: FloatProperty(name="Heat", description="Temperature released per unit of fuel burnt", default=2.0,
                        min=0.0, max=SMOKE_LIMIT)
    smoke: FloatProperty(name="Smoke", description="Smoke released per unit of fuel burnt", default=0.5,
                         min=0.0, max=SMOKE_LIMIT)
    device: EnumProperty(
        name="Device",
        items=[('vulkan', "Vulkan", "The first suitable Vulkan device (a GPU, else lavapipe)"),
               ('cpu', "CPU", "The double-precision reference")],
        default='vulkan',
    )
    # Emitter
    density: FloatProperty(name="Density", description="Smoke emitted per unit of time", default=4.0, min=0.0,
                           max=SMOKE_LIMIT)
    temperature: FloatProperty(name="Temperature", description="Heat emitted per unit of time", default=4.0,
                               min=-SMOKE_LIMIT, max=SMOKE_LIMIT)
    fuel: FloatProperty(name="Fuel", description="Fuel emitted per unit of time (it burns where hot)",
                        default=0.0, min=0.0, max=SMOKE_LIMIT)
    # Inflow (its smoke values are the emitter's: density, temperature, fuel of the air let in)
    jet: FloatVectorProperty(name="Jet", size=3, subtype='VELOCITY', default=(0.0, 0.0, 0.0),
                             description="Velocity the inflow drives the air at inside its box, "
                                         "across the side (0: the air comes in at its own speed)")


def register():
    bpy.utils.register_class(ModeflowObjectSettings)
    bpy.types.Object.modeflow = bpy.props.PointerProperty(type=ModeflowObjectSettings)


def unregister():
    del bpy.types.Object.modeflow
    bpy.utils.unregister_class(ModeflowObjectSettings)
