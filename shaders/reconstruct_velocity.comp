#version 450
// Velocity reconstruction (DESIGN section 4): the face field of sum_i v_i Psi_i,
//
//     field[face(d)] = sum_i v_i s_i Psi_i[d] / area(axis of face(d))
//
// over one chunk of modes (s_i the mode's scale factor, engine/kernels/ModeBuffer). Later chunks
// add to what the earlier ones wrote (the sequence's barrier orders them). Faces that are not
// DOFs are never written.
//
// A GEMV over the tiled basis (ModeAccess.glsl), bandwidth-bound. Each invocation owns units of
// one 32-byte word (8 float32 or 16 float16 DOFs), grid-stride, and walks the chunk's modes four
// at a time: one 64-bit pair of v (and of the scales, float16) serves the four modes times all
// the unit's DOFs, and the unit's faces are read four at a time too. Why, measured on lavapipe
// (tools/bench/bench_runtime, 48^3 grid, N = 100, CPU ms of one lavapipe thread, float32 /
// float16): one invocation per DOF reading a float of each mode and v, s per mode: 146 / 131;
// 64-bit vectors, 8 DOFs per invocation, v by fours, mode-major modes: 113 / 91; tiled: 32 / 21;
// faces by fours: 29 / 20. A unit's 32 bytes of a mode as one u64vec4 load instead of two
// u64vec2 loads (64^3 grid, N = 200, GPU ms with two lavapipe threads): 224-296 / 100-124 ->
// 166-178 / 70-77. Lavapipe pays per lane and load, whatever the load brings.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "ReconstructVelocityParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Modes { u64vec4 modeWords[]; };
// Both hold a multiple of 4 floats (engine/kernels/ModeBuffer), read four at a time.
layout(std430, set = 0, binding = 1) readonly buffer Scales { u64vec2 scales[]; };
layout(std430, set = 0, binding = 2) readonly buffer State { u64vec2 v[]; };
// Zero-padded to whole tiles (engine/kernels/VelocityReconstruction), read four at a time.
layout(std430, set = 0, binding = 3) readonly buffer Faces { u64vec2 faceQuads[]; };
layout(std430, set = 0, binding = 4) buffer FaceField { float field[]; };
layout(push_constant) uniform Push { ReconstructVelocityParams params; };

#include "FaceLocation.glsl"
#include "ModeAccess.glsl"

// v_i s_i for the global modes 4 quad ... 4 quad + 3, 0 for those outside the chunk (its first
// and last quads may be partial), and `local`: their chunk-local indices, clamped into the chunk.
vec4 coefficients(uint quad, out uvec4 local) {
    const uint first = params.firstMode, last = params.firstMode + params.modeCount - 1u;
    const uvec4 mode = uvec4(4u * quad) + uvec4(0u, 1u, 2u, 3u);
    local = clamp(mode, uvec4(first), uvec4(last)) - uvec4(first);
    vec4 c = floatsOf(v[quad]);
    if (params.halfPrecision != 0u) c *= floatsOf(scales[quad]);
    return mix(vec4(0.0), c, equal(mode, local + uvec4(first)));  // a select: v past N may be anything
}

// Writes (or adds) the sums of DOFs 4 quad ... 4 quad + 3 to their faces.
void store(uint quad, vec4 sum) {
    const u64vec2 word = faceQuads[quad];
    const uvec4 face = uvec4(unpack32(word.x), unpack32(word.y));
    [[unroll]] for (uint j = 0; j < 4; ++j) {
        if (4u * quad + j >= params.dofCount) break;  // padding
        const uint axis = faceAxis(face[j], params.faceStart1, params.faceStart2);
        const float value = sum[j] * (axis == 0u ? params.inverseArea[0] : axis == 1u ? params.inverseArea[1] : params.inverseArea[2]);
        field[face[j]] = params.accumulate != 0u ? field[face[j]] + value : value;
    }
}

void main() {
    const uint quadBegin = params.firstMode / 4u, quadEnd = (params.firstMode + params.modeCount + 3u) / 4u;
    const uint units = params.tileCount * TILE_LANES;
    for (uint unit = gl_GlobalInvocationID.x; unit < units; unit += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {
        const uint base = unitBase(unit, params.modeCount);
        vec4 sum[2 * TILE_ROWS];  // the unit's 16-byte vector r in sum[r] (float32), or sum[2r], sum[2r + 1] (float16)
        [[unroll]] for (uint j = 0; j < 2 * TILE_ROWS; ++j) sum[j] = vec4(0.0);
        if (params.halfPrecision != 0u) {
            for (uint quad = quadBegin; quad < quadEnd; ++quad) {
                uvec4 local;
                const vec4 c = coefficients(quad, local);
                [[unroll]] for (uint k = 0; k < 4; ++k) {
                    const u64vec4 word = modeWords[base + local[k] * TILE_LANES];
                    vec4 low, high;
                    halvesOf(word.xy, low, high);
                    sum[0] += c[k] * low;
                    sum[1] += c[k] * high;
                    halvesOf(word.zw, low, high);
                    sum[2] += c[k] * low;
                    sum[3] += c[k] * high;
                }
            }
            [[unroll]] for (uint j = 0; j < 2 * TILE_ROWS; ++j) store(2u * TILE_ROWS * unit + j, sum[j]);
        } else {
            for (uint quad = quadBegin; quad < quadEnd; ++quad) {
                uvec4 local;
                const vec4 c = coefficients(quad, local);
                [[unroll]] for (uint k = 0; k < 4; ++k) {
                    const u64vec4 word = modeWords[base + local[k] * TILE_LANES];
                    sum[0] += c[k] * floatsOf(word.xy);
                    sum[1] += c[k] * floatsOf(word.zw);
                }
            }
            [[unroll]] for (uint r = 0; r < TILE_ROWS; ++r) store(TILE_ROWS * unit + r, sum[r]);
        }
    }
}
