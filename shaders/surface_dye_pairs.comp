#version 450
// The dye's advection operator on a surface at the step's mean velocity (seed eq. 6.2;
// engine/device/SurfaceDye.h): K = A(v) with v = (v0 + v1) / 2 the mean of the velocities before
// and after the modal step, one value per scalar pair i < j,
//
//     pairs[p] = sum_m A[p][m] (v0_m + v1_m) / 2.
//
// One invocation per pair; the velocity vectors are read to n only (their padding is not ours).
#extension GL_GOOGLE_include_directive : require
#include "SurfaceDyeParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Advection { float advection[]; };
layout(std430, set = 0, binding = 1) readonly buffer Before { float before[]; };
layout(std430, set = 0, binding = 2) readonly buffer After { float after[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Pairs { float pairs[]; };
layout(push_constant) uniform Push { SurfaceDyePairsParams params; };

void main() {
    const uint p = gl_GlobalInvocationID.x;
    if (p >= params.pairCount) return;
    const uint row = p * params.rowFloats;
    float sum = 0.0;
    for (uint m = 0u; m < params.n; ++m) sum += advection[row + m] * (before[m] + after[m]);
    pairs[p] = 0.5 * sum;
}
