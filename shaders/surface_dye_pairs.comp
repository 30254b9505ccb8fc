#version 450
// The dye's advection operator on a surface at the step's mean velocity (seed eq. 6.2;
// engine/device/SurfaceDye.h): K = A(v) with v = (v0 + v1) / 2 the mean of the velocities before
// and after the modal step, one value per scalar pair i < j,
//
//     pairs[p] = sum_m A[p][m] (v0_m + v1_m) / 2.
//
// A is stored by columns, one per velocity mode, each of columnTexels texels (the pairs, zero-
// padded to a multiple of 4) and read as texels (TexelAccess.glsl has why): invocation t sums
// pairs 4t ... 4t + 3, so the lanes of a workgroup read consecutive texels. The velocity vectors
// are read to n only (their padding is not ours).
#extension GL_GOOGLE_include_directive : require
#include "SurfaceDyeParams.h"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(set = 0, binding = 0) uniform usamplerBuffer advection;
layout(std430, set = 0, binding = 1) readonly buffer Before { float before[]; };
layout(std430, set = 0, binding = 2) readonly buffer After { float after[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Pairs { float pairs[]; };
layout(push_constant) uniform Push { SurfaceDyePairsParams params; };

void main() {
    const uint t = gl_GlobalInvocationID.x;
    if (t >= params.columnTexels) return;
    vec4 sum = vec4(0.0);
    for (uint m = 0u; m < params.n; ++m)
        sum += floatTexel(advection, m * params.columnTexels + t) * (before[m] + after[m]);
    for (uint k = 0u; k < 4u; ++k)
        if (4u * t + k < params.pairCount) pairs[4u * t + k] = 0.5 * sum[k];
}
