#version 450
// Fuel burning for one step (the rule and its reasons: engine/simulation/Combustion.h, the CPU
// reference; host side engine/device/FireBurn.cpp): in every smoke cell hotter than the ignition
// temperature the fuel F loses burned = F (1 - e^{-r dt}) (the fraction from the host), each
// unit adding `heat` to the temperature and `smoke` to the density; the flame is burned / dt,
// written in every cell (the advection carried the last step's along; this replaces it). Cells
// outside the fluid hold 0 fuel and burn nothing: no mask needed.
#extension GL_GOOGLE_include_directive : require
#include "FireBurnParams.h"

layout(local_size_x = 128, local_size_x_id = 0) in;

// (density, temperature) and (fuel, flame) per cell, the temperature and the flame alone.
layout(std430, set = 0, binding = 0) buffer Smoke { vec2 smokeFields[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Temperature { float temperature[]; };
layout(std430, set = 0, binding = 2) buffer Fuel { vec2 fuelFields[]; };  // (fuel, flame)
layout(std430, set = 0, binding = 3) writeonly buffer Flame { float flame[]; };
layout(push_constant) uniform Push { FireBurnParams params; };

void main() {
    const uint cell = params.firstCell + gl_GlobalInvocationID.x;
    if (cell >= params.cellCount) return;
    const float fuel = fuelFields[cell].x;
    float burned = 0.0;
    if (fuel > 0.0) {
        const vec2 smoke = smokeFields[cell];
        if (smoke.y > params.ignition) {
            burned = fuel * params.burnFraction;
            const vec2 after = smoke + burned * vec2(params.smoke, params.heat);
            smokeFields[cell] = after;
            temperature[cell] = after.y;
        }
    }
    const float rate = burned * params.inverseDt;
    fuelFields[cell] = vec2(fuel - burned, rate);
    flame[cell] = rate;
}
