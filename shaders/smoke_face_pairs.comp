#version 450
// The basis grid's face velocity as x-neighbour pairs, the first dispatch of a smoke advection
// step (the smoke_advect_* kernels read it through MacSampling.glsl):
//
//     pairs[f] = (u[f], u[f + 1])
//
// Every trilinear MAC stencil, of any component, is two faces wide along x, and x is the fastest
// axis of MacGrid::faceIndex, so one fetch of pairs[] (a word texel: SmokeAdvect.glsl) gives two
// of its corners. Why: the advection samples the velocity two or three times per smoke cell, and fewer
// reads cost less on lavapipe (shaders/SmokeAdvect.glsl). Invocation k writes pairs 4k ... 4k + 3
// from the velocity's texels k and k + 1, fetched (faster than a 64-bit and a float storage load
// per two faces: engine/README.md "Speed"), and stores 64-bit words: one scalar access per
// lane on lavapipe, where a uvec2 takes two. f + 1 past a row's end pairs with the next row's
// first face, which no stencil uses with a non-zero weight. The last face stands in for the faces
// past it. Along a periodic x (wrapX: the row
// length of every face group) the stencil of a row's last face reaches across the seam to the
// row's first face, which it pairs with instead.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "SmokeAdvectParams.h"

layout(local_size_x = 128, local_size_x_id = 0) in;
// x is periodic (params.wrapX > 0): a constant, so that a walled grid compiles the wrap out.
layout(constant_id = 1) const bool WRAP_X = false;

// The velocity buffer twice: its whole texels, and as floats for the faces past them.
layout(set = 0, binding = 0) uniform usamplerBuffer velocityTexels;
layout(std430, set = 0, binding = 1) readonly buffer Velocity { float velocity[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Pairs { u64vec2 pairs[]; };
layout(push_constant) uniform Push { SmokeFacePairsParams params; };

void main() {
    const uint k = params.firstFace / 4u + gl_GlobalInvocationID.x;
    const uint faces = params.faceCount;  // at least 4
    if (4u * k >= faces) return;
    uvec4 u = texelFetch(velocityTexels, int(k));           // faces 4k ... 4k + 3
    uint next = texelFetch(velocityTexels, int(k + 1u)).x;  // face 4k + 4
    // The last two invocations: the texel view holds whole texels only (a partial texel k + 1
    // would read as 0, and a side the air flows through reads it), and past the last face the
    // last one stands in (no stencil weighs it).
    if (4u * k + 8u > faces) {
        [[unroll]] for (uint c = 0u; c < 4u; ++c)
            u[c] = floatBitsToUint(velocity[min(4u * k + c, faces - 1u)]);
        next = floatBitsToUint(velocity[min(4u * k + 4u, faces - 1u)]);
    }
    uvec4 second = uvec4(u.yzw, next);
    if (WRAP_X) {
        // One integer division per lane (lavapipe divides lane by lane): the row position of
        // face 4k, then of the next three. Every face group has whole rows, so positions up to
        // the last face are exact; past it the pairs are never read.
        const uint row = params.wrapX;
        uint x = (4u * k) % row;
        [[unroll]] for (uint c = 0u; c < 4u; ++c) {
            const uint face = min(4u * k + c, faces - 1u);
            if (x == row - 1u) second[c] = floatBitsToUint(velocity[face - (row - 1u)]);
            x = x + 1u == row ? 0u : x + 1u;
        }
    }
    pairs[2u * k] = u64vec2(pack64(uvec2(u.x, second.x)), pack64(uvec2(u.y, second.y)));
    pairs[2u * k + 1u] = u64vec2(pack64(uvec2(u.z, second.z)), pack64(uvec2(u.w, second.w)));
}
