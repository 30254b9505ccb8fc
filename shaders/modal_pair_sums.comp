#version 450
// First half of the dense structural-coefficient contraction (DESIGN section 3, seed eq. 6.6),
// float32. For every stored pair p = (k, j), k < j, of one chunk of the packed coefficients:
//
//     sums[p] = sum_i C[k][i][j] a_i
//
// modal_update.comp then forms out_k = sum_{j>k} sums(k,j) b_j - sum_{j<k} sums(j,k) b_j, using
// C[j][i][k] = -C[k][i][j]. Each coefficient is read exactly once per contraction, in memory
// order: the kernel is a GEMV over the packed (pairs x N) row-major matrix, and bandwidth-bound.
//
// Each invocation sums four rows (ROWS), front to back, four floats at a time (rows are
// zero-padded to a multiple of 4) read as two 64-bit words, and each load of a[q] serves all four.
// Why, measured on lavapipe (tools/bench/bench_runtime, N = 200): lavapipe issues every lane's
// load of every 32- or 64-bit component separately, whatever the access pattern, so load count
// is what costs. Floats: 1.5 GB/s; 64-bit words: 2.8; four rows per a[q]: 4.2 (eight: no better).
// A subgroup per row with coalesced loads and subgroupAdd, or a[q] shared by subgroupBroadcast,
// were no faster. On a GPU the 16-byte loads are native, and each invocation's next loads hit the
// cache lines its previous ones fetched. Rows are visited grid-stride, so any group count works.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Coefficients { u64vec2 coefficients[]; };  // 4 floats per element
layout(std430, set = 0, binding = 1) readonly buffer VectorA { vec4 a[]; };
layout(std430, set = 0, binding = 2) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { PairSumsParams params; };

const uint ROWS = 4;  // rows per invocation: each load of a[q] serves four rows

vec4 coefficientsAt(uint index) {
    const u64vec2 word = coefficients[index];
    return vec4(uintBitsToFloat(unpack32(word.x)), uintBitsToFloat(unpack32(word.y)));
}

void main() {
    const uint size = gl_WorkGroupSize.x;
    const uint stride = gl_NumWorkGroups.x * size * ROWS;
    const uint last = params.pairCount - 1;
    for (uint first = gl_WorkGroupID.x * size * ROWS + gl_LocalInvocationID.x; first < params.pairCount;
         first += stride) {
        uint base[ROWS];
        float sum[ROWS];
        [[unroll]] for (uint r = 0; r < ROWS; ++r) sum[r] = 0.0;
        [[unroll]] for (uint r = 0; r < ROWS; ++r) base[r] = min(first + r * size, last) * params.rowQuads;
        for (uint q = 0; q < params.rowQuads; ++q) {
            const vec4 aq = a[q];
            [[unroll]] for (uint r = 0; r < ROWS; ++r) sum[r] += dot(coefficientsAt(base[r] + q), aq);
        }
        [[unroll]] for (uint r = 0; r < ROWS; ++r)
            if (first + r * size < params.pairCount) sums[params.firstPair + first + r * size] = sum[r];
    }
}
