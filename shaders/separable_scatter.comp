#version 450
// The reconstructed velocities of a closed-form basis (DOF order) written to their faces of the
// whole-grid face field (engine/device/SeparableTransform); other faces are never written.
#extension GL_GOOGLE_include_directive : require
#include "SeparableParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 1) readonly buffer Values { float values[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Field { float field[]; };
layout(push_constant) uniform Push { SeparableScatterParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint d = gl_GlobalInvocationID.x; d < params.count; d += stride) field[faces[d]] = values[d];
}
