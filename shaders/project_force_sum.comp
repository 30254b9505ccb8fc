#version 450
// Force projection, pass 2 of 2: f_k = s_k * sum_b partial[k][b], one workgroup per mode k, the
// partial sums of project_force.comp added in a fixed order (strided private sums, then a
// shared-memory tree), s_k the mode's scale factor (engine/kernels/ModeBuffer).
#extension GL_GOOGLE_include_directive : require
#include "ProjectForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Partials { float partials[]; };
layout(std430, set = 0, binding = 1) readonly buffer Scales { float scales[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Force { float f[]; };
layout(push_constant) uniform Push { ProjectForceSumParams params; };

shared float partial[gl_WorkGroupSize.x];

void main() {
    const uint k = gl_WorkGroupID.x;
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    float sum = 0.0;
    if (k < params.modeCount)
        for (uint b = lane; b < params.blockCount; b += size) sum += partials[k * params.blockCount + b];
    partial[lane] = sum;
    barrier();
    for (uint stride = 1u; stride < size; stride *= 2u) {
        if (lane % (2u * stride) == 0u && lane + stride < size) partial[lane] += partial[lane + stride];
        barrier();
    }
    if (lane == 0u && k < params.modeCount) f[k] = scales[k] * partial[0];
}
