#version 450
// Force projection, pass 1 of 2 (DESIGN section 3; CPU reference engine/field/ForceProjection.h):
//
//     partial[k][b] = sum_{d in block b} Psi_k[d] w_d q_d
//
// for the modes of one chunk. Workgroup (mode group m, block b) takes 8 modes and one block of
// DOFs: its invocations stride over the block (neighbouring invocations read neighbouring words
// of each mode), read w_d q_d once for the 8 modes, and add their private sums with a
// shared-memory tree. Blocks spread one projection over many workgroups (a few hundred at least
// on a GPU); project_force_sum.comp adds the partial sums of each mode in a fixed order, so the
// result is deterministic (no atomics). On lavapipe 8 modes a group measured ~6% faster than 4.
#extension GL_GOOGLE_include_directive : require
#include "ProjectForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Modes { uint modeWords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Input { float q[]; };
layout(std430, set = 0, binding = 2) readonly buffer Weights { float w[]; };
layout(std430, set = 0, binding = 3) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Partials { float partials[]; };
layout(push_constant) uniform Push { ProjectForceParams params; };

#include "ModeAccess.glsl"

shared vec4 partial[gl_WorkGroupSize.x][2];

float modeValue(uint mode, uint dof) { return modeValue(mode, dof, params.modeStride, params.halfPrecision != 0u); }

void main() {
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    const uint block = gl_WorkGroupID.x % params.blockCount;
    const uint firstLocal = (gl_WorkGroupID.x / params.blockCount) * PROJECT_FORCE_MODES_PER_GROUP;
    // Modes past the chunk's end repeat its last mode; their sums are not written.
    const uint lastLocal = params.modeCount - 1u;
    const uvec4 modeA = min(uvec4(firstLocal) + uvec4(0u, 1u, 2u, 3u), uvec4(lastLocal));
    const uvec4 modeB = min(uvec4(firstLocal) + uvec4(4u, 5u, 6u, 7u), uvec4(lastLocal));
    const uint begin = block * params.blockSize;
    const uint end = min(begin + params.blockSize, params.dofCount);

    vec4 sumA = vec4(0.0), sumB = vec4(0.0);
    for (uint d = begin + lane; d < end; d += size) {
        const float x = w[d] * (params.gatherFaces != 0u ? q[faces[d]] : q[d]);
        sumA += x * vec4(modeValue(modeA.x, d), modeValue(modeA.y, d), modeValue(modeA.z, d), modeValue(modeA.w, d));
        sumB += x * vec4(modeValue(modeB.x, d), modeValue(modeB.y, d), modeValue(modeB.z, d), modeValue(modeB.w, d));
    }
    partial[lane][0] = sumA;
    partial[lane][1] = sumB;
    barrier();
    // Works for any workgroup size, not only powers of two.
    for (uint stride = 1u; stride < size; stride *= 2u) {
        if (lane % (2u * stride) == 0u && lane + stride < size) {
            partial[lane][0] += partial[lane + stride][0];
            partial[lane][1] += partial[lane + stride][1];
        }
        barrier();
    }
    // A loop, not `lane < 8`: workgroups may have fewer than 8 invocations.
    for (uint j = lane; j < PROJECT_FORCE_MODES_PER_GROUP && firstLocal + j < params.modeCount; j += size)
        partials[(params.firstMode + firstLocal + j) * params.blockCount + block] = partial[0][j / 4u][j % 4u];
}
