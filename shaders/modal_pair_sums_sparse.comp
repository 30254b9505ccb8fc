#version 450
// modal_pair_sums.comp for sparse coefficients (engine/dynamics/SparseCoefficients.h): rows are
// the pairs k < j with any non-zero, each a CSR run of (i, value) entries, and
//
//     sums[pairIndex(k, j)] = sum over the row's entries of value * a_i.
//
// Pairs without a row keep the zero their sum was initialized with. One invocation per row
// (rows hold few entries; a subgroup per row would leave most lanes idle), grid-stride.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer RowPair { uint rowPair[]; };
layout(std430, set = 0, binding = 1) readonly buffer RowStart { uint rowStart[]; };
layout(std430, set = 0, binding = 2) readonly buffer Columns { uint columns[]; };
layout(std430, set = 0, binding = 3) readonly buffer Values { float values[]; };
layout(std430, set = 0, binding = 4) readonly buffer VectorA { float a[]; };
layout(std430, set = 0, binding = 5) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { SparsePairSumsParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint row = gl_GlobalInvocationID.x; row < params.rowCount; row += stride) {
        float sum = 0.0;
        for (uint e = rowStart[row]; e < rowStart[row + 1]; ++e) sum += values[e] * a[columns[e]];
        sums[rowPair[row]] = sum;
    }
}
