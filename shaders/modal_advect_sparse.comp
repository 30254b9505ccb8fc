#version 450
// The sparse Lie advection (ModalStepParams.h): per mode i, over the stored entries C[k][i][j]
// (k < j) of column i,
//
//     out_i = sum value (u_k x_j - u_j x_k),
//
// a gather (the columns' entries are kept apart from the rows modal_pair_sums_sparse.comp reads:
// engine/device/DeviceCoefficients). One invocation per i, grid-stride.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer ColumnStart { uint columnStart[]; };
layout(std430, set = 0, binding = 1) readonly buffer Entries { uvec4 entries[]; };  // k, j, value bits, 0
layout(std430, set = 0, binding = 2) readonly buffer VectorU { float u[]; };
layout(std430, set = 0, binding = 3) readonly buffer VectorX { float x[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Result { float result[]; };
layout(push_constant) uniform Push { CombineParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint i = gl_GlobalInvocationID.x; i < params.n; i += stride) {
        float sum = 0.0;
        for (uint t = columnStart[i]; t < columnStart[i + 1u]; ++t) {
            const uvec4 e = entries[t];
            sum += uintBitsToFloat(e.z) * (u[e.x] * x[e.y] - u[e.y] * x[e.x]);
        }
        result[i] = sum;
    }
}
