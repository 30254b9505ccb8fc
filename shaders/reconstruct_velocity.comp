#version 450
// Velocity reconstruction (engine/README.md): the face field of sum_i v_i Psi_i,
//
//     field[face(d)] = sum_i v_i s_i Psi_i[d] / area(axis of face(d))
//
// over one chunk of modes (s_i the mode's scale factor, engine/device/ModeBuffer). With several
// chunks, all but the last leave their sums in a scratch buffer in DOF order (one 32-byte word a
// load and a store per unit), each adding to what the one before left (the sequence's barrier
// orders them), and only the last writes the faces (8 loads and 8 scattered stores a unit each
// time before). Faces that are not DOFs are never written.
//
// A GEMV over the tiled basis (ModeAccess.glsl), bandwidth-bound. Each invocation reads the
// chunk's v_i s_i once, then owns units of one 32-byte word (8 float32 or 16 float16 DOFs) and
// adds each mode's word times its coefficient, the chunk's modes unrolled (their count is a
// specialization constant). Why, measured on lavapipe (tools/bench/bench_runtime; each step's
// times: engine/README.md "Speed"), each step faster than the one before: one invocation per DOF
// reading a float of each mode and v, s per mode; 64-bit vectors, 8 DOFs per invocation, v by
// fours, mode-major modes; tiled; faces by fours. A unit's 32 bytes of a mode as one u64vec4 load
// instead of two u64vec2 loads. Lavapipe pays per lane and load, whatever the load brings. Then
// the precision and the chunk's place as specialization constants, the scratch sums, 16 units
// per invocation on a CPU device and v read once per invocation with the modes unrolled: faster
// at 64^3 N = 200 (five 40-mode chunks) in each of seven runs alternating with the previous
// version and at 48^3 N <= 100, one chunk of 200 modes (256^2) no faster (runs of 64 modes each,
// tried, were slower). Then the modes and face indices fetched as texels (TexelAccess.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "ReconstructVelocityParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
// Fixed per pipeline (engine/device/VelocityReconstruction): lavapipe runs both sides of a
// runtime branch.
layout(constant_id = 1) const uint HALF = 0u;          // 1: float16 modes, 0: float32
layout(constant_id = 2) const uint FROM_SCRATCH = 0u;  // 1: add to the sums earlier chunks left
layout(constant_id = 3) const uint TO_FIELD = 1u;      // 1: write the faces, 0: leave the sums
layout(constant_id = 4) const uint MODES = 4u;         // the chunk's modes
layout(constant_id = 5) const uint SKIP = 0u;          // the chunk's first mode % 4: its place in v's quads

layout(set = 0, binding = 0) uniform usamplerBuffer modeTexels;
// Both hold a multiple of 4 floats (engine/device/ModeBuffer), read four at a time.
layout(std430, set = 0, binding = 1) readonly buffer Scales { u64vec2 scales[]; };
layout(std430, set = 0, binding = 2) readonly buffer State { u64vec2 v[]; };
// Zero-padded to whole tiles (engine/device/VelocityReconstruction), four a texel.
layout(set = 0, binding = 3) uniform usamplerBuffer faceQuads;
layout(std430, set = 0, binding = 4) writeonly buffer FaceField { float field[]; };
// The sums over the chunks so far, DOF order, 8 floats a word (as long as the padded faces).
layout(std430, set = 0, binding = 5) buffer Scratch { u64vec4 scratch[]; };
layout(push_constant) uniform Push { ReconstructVelocityParams params; };

#include "FaceLocation.glsl"
#include "ModeAccess.glsl"

/* Four float32 values stored in 16 bytes. */
vec4 floatsOf(u64vec2 vector) {
    return vec4(uintBitsToFloat(unpack32(vector.x)), uintBitsToFloat(unpack32(vector.y)));
}

const uint OCTETS = HALF + 1u;                  // 8-DOF octets per unit
const uint QUADS = (SKIP + MODES + 3u) / 4u;    // quads of v the chunk's modes lie in

// Writes the sums of DOFs 4 quad ... 4 quad + 3 to their faces.
void store(uint quad, vec4 sum) {
    const uvec4 face = texelFetch(faceQuads, int(quad));
    [[unroll]] for (uint j = 0; j < 4; ++j) {
        if (4u * quad + j >= params.dofCount) break;  // padding
        const uint axis = faceAxis(face[j], params.faceStart1, params.faceStart2);
        field[face[j]] = sum[j] * (axis == 0u ? params.inverseArea[0] : axis == 1u ? params.inverseArea[1] : params.inverseArea[2]);
    }
}

u64vec2 wordsOf(vec4 values) {
    return u64vec2(pack64(floatBitsToUint(values.xy)), pack64(floatBitsToUint(values.zw)));
}

void main() {
    // v_i s_i of the chunk's modes: chunk mode j is component (SKIP + j) % 4 of c[(SKIP + j) / 4]
    // (the others, outside the chunk or past N, are never used).
    vec4 c[QUADS];
    [[unroll]] for (uint quad = 0; quad < QUADS; ++quad) {
        c[quad] = floatsOf(v[params.firstMode / 4u + quad]);
        if (HALF != 0u) c[quad] *= floatsOf(scales[params.firstMode / 4u + quad]);
    }
    uint begin, step, end;
    unitRange(gl_GlobalInvocationID.x, gl_NumWorkGroups.x * gl_WorkGroupSize.x, 0u, params.tileCount, begin, step, end);
    for (uint unit = begin; unit < end; unit += step) {
        const uint base = unitBase(unit, MODES);
        vec4 sum[4];  // the unit's DOFs, four per vec4 (float32: the first two)
        [[unroll]] for (uint h = 0; h < OCTETS; ++h) {
            const u64vec4 word = FROM_SCRATCH != 0u ? scratch[OCTETS * unit + h] : u64vec4(0u);
            sum[2 * h] = floatsOf(word.xy);
            sum[2 * h + 1] = floatsOf(word.zw);
        }
        [[unroll]] for (uint j = 0; j < MODES; ++j) {
            const float cj = c[(SKIP + j) / 4u][(SKIP + j) % 4u];
            const uint word = base + j * TILE_LANES;
            if (HALF != 0u) {
                vec4 h0, h1, h2, h3;
                modeHalves(word, h0, h1, h2, h3);
                sum[0] += cj * h0;
                sum[1] += cj * h1;
                sum[2] += cj * h2;
                sum[3] += cj * h3;
            } else {
                vec4 f0, f1;
                modeFloats(word, f0, f1);
                sum[0] += cj * f0;
                sum[1] += cj * f1;
            }
        }
        if (TO_FIELD != 0u) {
            [[unroll]] for (uint j = 0; j < 2 * OCTETS; ++j) store(2u * OCTETS * unit + j, sum[j]);
        } else {
            [[unroll]] for (uint h = 0; h < OCTETS; ++h)
                scratch[OCTETS * unit + h] = u64vec4(wordsOf(sum[2 * h]), wordsOf(sum[2 * h + 1]));
        }
    }
}
