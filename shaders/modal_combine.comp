#version 450
// Second half of the structural-coefficient contraction (see modal_pair_sums.comp):
//
//     out_k = sum_{j>k} sums(k,j) b_j - sum_{j<k} sums(j,k) b_j
//
// which is sum_ij C[k][i][j] a_i b_j by the antisymmetry C[k][i][j] = -C[j][i][k] (C[k][i][k] = 0).
// One subgroup per output k, lanes over j: the j > k terms are one contiguous run of sums.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Sums { float sums[]; };
layout(std430, set = 0, binding = 1) readonly buffer VectorB { float b[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Result { float result[]; };
layout(push_constant) uniform Push { CombineParams params; };

uint pairIndex(uint n, uint k, uint j) { return k * n - k * (k + 1) / 2 + (j - k - 1); }

void main() {
    const uint n = params.n;
    const uint stride = gl_NumWorkGroups.x * gl_NumSubgroups;
    for (uint k = gl_WorkGroupID.x * gl_NumSubgroups + gl_SubgroupID; k < n; k += stride) {
        float sum = 0.0;
        for (uint j = gl_SubgroupInvocationID; j < n; j += gl_SubgroupSize) {
            if (j > k) sum += sums[pairIndex(n, k, j)] * b[j];
            else if (j < k) sum -= sums[pairIndex(n, j, k)] * b[j];
        }
        sum = subgroupAdd(sum);
        if (subgroupElect()) result[k] = sum;
    }
}
