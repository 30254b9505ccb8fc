/* ModalCombine.glsl: the body of modal_combine.comp and modal_combine_columns.comp.

   Second half of the structural-coefficient contraction (see modal_pair_sums.comp), whose pair
   sums stand in the strict upper triangle of an N x N matrix U, U[k][j] = sums(k, j) for k < j
   (rows of `rowTexels` texels; the rest zero):

       out_k = sum_{j>k} U[k][j] b_j - sum_{j<k} U[j][k] b_j,

   which is sum_ij C[k][i][j] a_i b_j by the antisymmetry C[k][i][j] = -C[j][i][k] (C[k][i][k] = 0).
   ROWS (modal_combine.comp, first): out = U b, one subgroup per output k, lanes over the
   texels of row k from the diagonal on. COLUMNS (modal_combine_columns.comp, then): out -= U^T b,
   one invocation per four outputs (a texel of each row), over the rows above them, b_j the same
   for every lane.
   Why U rather than the packed triangle, and two passes: with the packed triangle the j < k terms
   are one float from each earlier row, a scalar load per lane on lavapipe, where a texel is one
   vector gather for all lanes (TexelAccess.glsl); and writing U's mirror image from the pair sums
   makes those stores scattered (both measured slower on lavapipe: precompute/README.md
   "Closed-form bases"). The columns pass takes four rows a step, one fetch of b for them and no
   component picked by a run-time index (faster). Not one read of U for both products: every
   row's part then needs a sum across lanes in every tile of columns (a subgroup sum per row and
   tile, slower than the two passes), or each lane keeps the parts of a block of rows and texels,
   which on lavapipe (a value per lane is a SIMD register) spill.
   DENSE_ADD (modal_linear.comp): out += D b for a full N x N matrix D in the same rows of texels
   (a wind's linear term, engine/device/ModalStepper.h), the rows pass over every texel. */
#ifndef MODEFLOW_SHADERS_MODAL_COMBINE_GLSL
#define MODEFLOW_SHADERS_MODAL_COMBINE_GLSL

#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "ModalStepParams.h"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(set = 0, binding = 0) uniform usamplerBuffer sums;  // U, four floats a texel
layout(set = 0, binding = 1) uniform usamplerBuffer b;     // rowTexels texels (zero-padded)
layout(std430, set = 0, binding = 2) buffer Result { float result[]; };
layout(push_constant) uniform Push { CombineParams params; };

void main() {
    const uint rowTexels = params.rowTexels;
#ifdef COMBINE_COLUMNS
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint q = gl_GlobalInvocationID.x; q < rowTexels; q += stride) {
        vec4 sum = vec4(0.0);
        const uint rows = min(params.n, 4u * q + 3u);  // U[j][4q + c] = 0 for j >= 4q + c
        // Four rows a step, b's texel fetched once for them and no component picked by index.
        uint j = 0;
        for (; j + 4u <= rows; j += 4u) {
            const vec4 bj = floatTexel(b, j >> 2);
            const uint at = j * rowTexels + q;
            sum += floatTexel(sums, at) * bj.x;
            sum += floatTexel(sums, at + rowTexels) * bj.y;
            sum += floatTexel(sums, at + 2u * rowTexels) * bj.z;
            sum += floatTexel(sums, at + 3u * rowTexels) * bj.w;
        }
        for (; j < rows; ++j)
            sum += floatTexel(sums, j * rowTexels + q) * floatTexel(b, j >> 2)[j & 3u];
        for (uint c = 0; c < 4u && 4u * q + c < params.n; ++c) result[4u * q + c] -= sum[c];
    }
#else
    const uint stride = gl_NumWorkGroups.x * gl_NumSubgroups;
    for (uint k = gl_WorkGroupID.x * gl_NumSubgroups + gl_SubgroupID; k < params.n; k += stride) {
        float sum = 0.0;
#ifdef DENSE_ADD
        const uint firstTexel = 0u;
#else
        const uint firstTexel = k / 4u;  // U[k][j] = 0 for j <= k
#endif
        for (uint q = firstTexel + gl_SubgroupInvocationID; q < rowTexels; q += gl_SubgroupSize)
            sum += dot(floatTexel(sums, k * rowTexels + q), floatTexel(b, q));
        sum = subgroupAdd(sum);
#ifdef DENSE_ADD
        if (subgroupElect()) result[k] += sum;
#else
        if (subgroupElect()) result[k] = sum;
#endif
    }
#endif
}

#endif
