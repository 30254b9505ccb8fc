#version 450
// The wind's held base flow B added to a reconstructed face field (engine/device/WindField.h;
// CPU reference windBaseFlow, engine/simulation/WindTransport.cpp): field[f] += B[f], the box's
// sides included (where the wind enters and leaves). A reconstruction writes the DOF faces alone
// and leaves the walled sides as they were, so those are set to B, not added to: what the CPU's
// fresh field (0 there) plus B gives. An open side's faces are DOFs: added to, as inside.
#extension GL_GOOGLE_include_directive : require
#include "FaceLocation.glsl"
#include "WindParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) buffer Field { float field[]; };
layout(set = 0, binding = 1) uniform usamplerBuffer base;  // B, one float a (R32UI) texel
layout(push_constant) uniform Push { WindParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint f = gl_GlobalInvocationID.x; f < params.faceTotal; f += stride) {
        const uint axis = faceAxis(f, params.faceStart1, params.faceStart2);
        const uint local = f - (axis == 2u ? params.faceStart2 : axis == 1u ? params.faceStart1 : 0u);
        const uvec3 p = facePosition(local, axis, uvec3(params.cells[0], params.cells[1], params.cells[2]),
                                     params.periodic);
        const bool side = (params.periodic & (1u << axis)) == 0u &&
                          ((p[axis] == 0u && (params.open & (1u << (2u * axis))) == 0u) ||
                           (p[axis] == params.cells[axis] &&
                            (params.open & (1u << (2u * axis + 1u))) == 0u));
        field[f] = (side ? 0.0 : field[f]) + uintBitsToFloat(texelFetch(base, int(f)).x);
    }
}
