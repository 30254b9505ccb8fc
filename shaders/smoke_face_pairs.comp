#version 450
// The basis grid's face velocity as x-neighbour pairs, the first dispatch of a smoke advection
// step (the smoke_advect_* kernels read it through MacSampling.glsl):
//
//     pairs[f] = (u[f], u[f + 1])
//
// Every trilinear MAC stencil, of any component, is two faces wide along x, and x is the fastest
// axis of MacGrid::faceIndex, so one 64-bit load of pairs[] fetches two of its corners. Why: on
// lavapipe the count of load components is what costs (shaders/modal_pair_sums.comp), and the
// advection samples the velocity two or three times per smoke cell. Invocation k writes pairs 2k
// and 2k + 1 from the 64-bit word of faces 2k, 2k + 1 and the float of face 2k + 2: a load per
// face instead of two (whole steps 5-10% faster than with two float loads per face here). f + 1
// past a row's end pairs with the next row's first face, which no stencil uses with a non-zero
// weight. The last face is a wall, which the sampling reads as 0: its pair (with an odd face
// count) and what lies past it hold finite stand-ins.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "SmokeAdvectParams.h"

layout(local_size_x = 128, local_size_x_id = 0) in;

// The velocity buffer twice: as 64-bit words (faces 2k, 2k + 1) and as floats.
layout(std430, set = 0, binding = 0) readonly buffer VelocityWords { uint64_t velocityWords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Velocity { float velocity[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Pairs { u64vec2 pairs[]; };
layout(push_constant) uniform Push { SmokeFacePairsParams params; };

void main() {
    const uint k = params.firstFace / 2u + gl_GlobalInvocationID.x;
    const uint faces = params.faceCount;  // at least 4
    if (2u * k >= faces) return;
    // With an odd face count the last word is partial: its first face is the last one, a wall.
    const uint64_t word = velocityWords[min(k, faces / 2u - 1u)];
    const float next = velocity[min(2u * k + 2u, faces - 1u)];
    pairs[k] = u64vec2(word, pack64(uvec2(unpack32(word).y, floatBitsToUint(next))));
}
