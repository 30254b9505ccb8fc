#version 450
// Dense structural-coefficient contraction, float32 (DESIGN section 3, seed eq. 6.6):
//
//     out_k = sum_ij C[k][i][j] a_i b_j
//
// from the packed k < j half (engine/dynamics/PackedLayout.h): packed[pair(k,j) * N + i] holds
// C[k][i][j], and C[k][i][j] = -C[j][i][k] gives the rest (C[k][i][k] = 0).
//
// Reduction strategy: one workgroup per output k, so no atomics and a deterministic sum. The
// workgroup's invocations stride over the N*N terms (j, i) in i-fastest order, so neighbouring
// lanes read neighbouring coefficients; each keeps a private partial sum, then a shared-memory
// tree adds the partials. Rows j > k are one contiguous run of the packed array; rows j < k are
// N-float blocks spread through it (each read once per k). Correctness first: every coefficient
// is read twice over the whole dispatch (once for k, once for j), which a pair-major kernel
// with a second reduction pass would halve.
#extension GL_GOOGLE_include_directive : require
#include "ModalApplyParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Coefficients { float coefficients[]; };
layout(std430, set = 0, binding = 1) readonly buffer VectorA { float a[]; };
layout(std430, set = 0, binding = 2) readonly buffer VectorB { float b[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Result { float result[]; };
layout(push_constant) uniform Push { ModalApplyParams params; };

shared float partial[gl_WorkGroupSize.x];

uint pairIndex(uint n, uint k, uint j) { return k * n - k * (k + 1) / 2 + (j - k - 1); }

void main() {
    const uint n = params.n;
    const uint k = gl_WorkGroupID.x;
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;

    float sum = 0.0;
    if (k < n) {
        for (uint e = lane; e < n * n; e += size) {
            const uint j = e / n;
            const uint i = e - j * n;
            if (j == k) continue;
            const float c = j > k ? coefficients[pairIndex(n, k, j) * n + i]
                                  : -coefficients[pairIndex(n, j, k) * n + i];
            sum += c * a[i] * b[j];
        }
    }
    partial[lane] = sum;
    barrier();
    // Works for any workgroup size, not only powers of two.
    for (uint stride = 1; stride < size; stride *= 2) {
        if (lane % (2 * stride) == 0 && lane + stride < size) partial[lane] += partial[lane + stride];
        barrier();
    }
    if (lane == 0 && k < n) result[k] = partial[0];
}
