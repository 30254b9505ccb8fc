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
// One invocation per row, reading it front to back four floats at a time (rows are zero-padded to
// a multiple of 4), as two 64-bit words. Measured on lavapipe, which issues every lane's load of
// every 32- or 64-bit component separately whatever the access pattern: 64-bit words stream twice
// as fast as floats (2.8 against 1.5 GB/s at N = 200); a subgroup per row with coalesced loads and
// subgroupAdd was no faster at N = 200 and 1.7x slower at N = 50, 100. On a GPU the 16-byte load
// is native and each invocation's next loads hit the cache lines its previous ones fetched. Rows
// are visited grid-stride, so any group count is correct.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Coefficients { u64vec2 coefficients[]; };  // 4 floats per element
layout(std430, set = 0, binding = 1) readonly buffer VectorA { vec4 a[]; };
layout(std430, set = 0, binding = 2) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { PairSumsParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint row = gl_GlobalInvocationID.x; row < params.pairCount; row += stride) {
        const uint base = row * params.rowQuads;
        float sum = 0.0;
        for (uint q = 0; q < params.rowQuads; ++q) {
            const u64vec2 word = coefficients[base + q];
            sum += dot(vec4(uintBitsToFloat(unpack32(word.x)), uintBitsToFloat(unpack32(word.y))), a[q]);
        }
        sums[params.firstPair + row] = sum;
    }
}
