#version 450
// Force projection, pass 2 of 2: f_k = s_k * sum_b partial[k][b], one invocation per mode k adding
// the partial sums of project_force.comp in order (deterministic), s_k the mode's scale factor
// (engine/device/ModeBuffer). A loop per mode, not a workgroup per mode with a shared-memory
// tree: the blocks are few on a CPU device (about 16), where lavapipe ran each workgroup's tree
// invocation by invocation, and a few hundred on a GPU.
#extension GL_GOOGLE_include_directive : require
#include "ProjectForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Partials { float partials[]; };
layout(std430, set = 0, binding = 1) readonly buffer Scales { float scales[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Force { float f[]; };
layout(push_constant) uniform Push { ProjectForceSumParams params; };

void main() {
    const uint k = gl_GlobalInvocationID.x;
    if (k >= params.modeCount) return;
    float sum = 0.0;
    for (uint b = 0; b < params.blockCount; ++b) sum += partials[k * params.blockCount + b];
    f[k] = scales[k] * sum;
}
