#version 450
// A surface's stirring force projected on its velocity basis (engine/device/SurfaceForce.h):
// f_k = sum_v g_v . u_k(x_v), u_k mode k's velocity at the vertices (a row of 3V floats), g from
// surface_splat_vertices.comp. One invocation per mode.
#extension GL_GOOGLE_include_directive : require
#include "SurfaceForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Modes { float modes[]; };
layout(std430, set = 0, binding = 1) readonly buffer Force { float g[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Modal { float f[]; };
layout(push_constant) uniform Push { SurfaceSplatParams params; };

void main() {
    const uint k = gl_GlobalInvocationID.x;
    if (k >= params.n) return;
    const uint row = k * params.rowFloats;
    float sum = 0.0;
    for (uint i = 0u; i < params.rowFloats; ++i) sum += modes[row + i] * g[i];
    f[k] = sum;
}
