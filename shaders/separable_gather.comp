#version 450
// Indexed weighted sums for the closed-form basis transforms (engine/device/SeparableTransform):
// the modal coefficients into each component's tensor of slots (two modes at most share a
// slot: the two polarizations of a 3D wave vector), the tensors' slots back into modal forces
// (a term per component), and a face field read at the DOF faces.
#extension GL_GOOGLE_include_directive : require
#include "SeparableParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Index { uint index[]; };
layout(std430, set = 0, binding = 1) readonly buffer Weight { float weight[]; };
layout(std430, set = 0, binding = 2) readonly buffer In { float values[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Out { float result[]; };
layout(push_constant) uniform Push { SeparableGatherParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint e = gl_GlobalInvocationID.x; e < params.count; e += stride) {
        float sum = 0.0;
        for (uint t = 0; t < params.terms; ++t) {
            const uint i = index[e * params.terms + t];
            if (i != SEPARABLE_NONE) sum += weight[e * params.terms + t] * values[i];
        }
        result[params.outOffset + e] = sum;
    }
}
