#version 450
// Velocity reconstruction (DESIGN section 4): the face field of sum_i v_i Psi_i,
//
//     field[face(d)] = sum_i v_i s_i Psi_i[d] / area(axis of face(d))
//
// over one chunk of modes (s_i the mode's scale factor, engine/kernels/ModeBuffer). One
// invocation per DOF: neighbouring invocations read neighbouring words of each mode, and each
// loops over the chunk's modes. Later chunks add to what the earlier ones wrote (the sequence's
// barrier orders them). Faces that are not DOFs are never written.
#extension GL_GOOGLE_include_directive : require
#include "ReconstructVelocityParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Modes { uint modeWords[]; };
// Read four at a time where whole aligned quads lie in the chunk (see main); both hold a multiple
// of 4 floats, so every vec4 lies inside its buffer.
layout(std430, set = 0, binding = 1) readonly buffer Scales { vec4 scales[]; };
layout(std430, set = 0, binding = 2) readonly buffer State { vec4 v[]; };
layout(std430, set = 0, binding = 3) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 4) buffer FaceField { float field[]; };
layout(push_constant) uniform Push { ReconstructVelocityParams params; };

#include "FaceLocation.glsl"
#include "ModeAccess.glsl"

float modeValue(uint mode, uint dof) { return modeValue(mode, dof, params.modeStride, params.halfPrecision != 0u); }

// v_i s_i for one mode (global index i).
float coefficient(uint i) { return v[i / 4u][i % 4u] * scales[i / 4u][i % 4u]; }

void main() {
    const uint invocations = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    // Global mode indices [first, last) of the chunk; the aligned quads inside it are read as
    // vec4s, the few modes around them one by one. Lavapipe makes every per-invocation load a
    // gather, uniform or not: one per four modes instead of two per mode cut this kernel's time
    // by a third there.
    const uint first = params.firstMode, last = params.firstMode + params.modeCount;
    const uint quadBegin = min((first + 3u) / 4u, last / 4u), quadEnd = last / 4u;
    for (uint d = gl_GlobalInvocationID.x; d < params.dofCount; d += invocations) {
        float sum = 0.0;
        for (uint i = first; i < min(4u * quadBegin, last); ++i) sum += coefficient(i) * modeValue(i - first, d);
        for (uint quad = quadBegin; quad < quadEnd; ++quad) {
            const vec4 c = v[quad] * scales[quad];
            const uint i = 4u * quad - first;
            if (params.halfPrecision != 0u) {
                sum += c.x * modeValue16(i, d, params.modeStride) + c.y * modeValue16(i + 1u, d, params.modeStride) +
                       c.z * modeValue16(i + 2u, d, params.modeStride) + c.w * modeValue16(i + 3u, d, params.modeStride);
            } else {
                sum += c.x * modeValue32(i, d, params.modeStride) + c.y * modeValue32(i + 1u, d, params.modeStride) +
                       c.z * modeValue32(i + 2u, d, params.modeStride) + c.w * modeValue32(i + 3u, d, params.modeStride);
            }
        }
        for (uint i = max(4u * quadEnd, first); i < last; ++i) sum += coefficient(i) * modeValue(i - first, d);
        const uint face = faces[d];
        const float value = sum * params.inverseArea[faceAxis(face, params.faceStart1, params.faceStart2)];
        field[face] = params.accumulate != 0u ? field[face] + value : value;
    }
}
