#version 450
// A surface's stirring force at its vertices (engine/device/SurfaceForce.h; CPU reference
// engine/surface/SurfaceForce.cpp): the Gaussian splats' force density at each vertex, turned
// into the vertex's tangent plane and weighted by its area,
//
//     g_v = star0_v (F - (F . n_v) n_v),   F = sum_s force_s exp(-|x_v - c_s|^2 / r_s^2),
//
// three floats per vertex. One invocation per vertex.
#extension GL_GOOGLE_include_directive : require
#include "ForceFieldParams.h"
#include "SurfaceForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Vertices { vec4 vertices[]; };  // x, star0
layout(std430, set = 0, binding = 1) readonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = 2) readonly buffer Splats { ForceSplatRecord splats[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Force { float g[]; };
layout(push_constant) uniform Push { SurfaceSplatParams params; };

void main() {
    const uint v = gl_GlobalInvocationID.x;
    if (v >= params.vertexCount) return;
    const vec4 x = vertices[v];
    vec3 force = vec3(0.0);
    for (uint s = 0u; s < params.splatCount; ++s) {
        const vec3 d = x.xyz - vec3(splats[s].centre[0], splats[s].centre[1], splats[s].centre[2]);
        const float r = splats[s].radius;
        force += exp(-dot(d, d) / (r * r)) *
                 vec3(splats[s].force[0], splats[s].force[1], splats[s].force[2]);
    }
    const vec3 n = normals[v].xyz;
    const vec3 tangent = x.w * (force - dot(force, n) * n);
    g[3u * v] = tangent.x;
    g[3u * v + 1u] = tangent.y;
    g[3u * v + 2u] = tangent.z;
}
