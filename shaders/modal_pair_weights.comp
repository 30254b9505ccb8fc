#version 450
// The pair weights of the dense Lie advection (ModalStepParams.h, engine/device/DeviceCoefficients):
//
//     w[pairIndex(k, j)] = u_k x_j - u_j x_k   for every pair k < j,
//
// so that advect(u, x)_i = sum_pairs C[k][i][j] w(k, j) (C[j][i][k] = -C[k][i][j]). One invocation
// per k, grid-stride.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer VectorU { float u[]; };
layout(std430, set = 0, binding = 1) readonly buffer VectorX { float x[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Weights { float w[]; };
layout(push_constant) uniform Push { CombineParams params; };

void main() {
    const uint n = params.n;
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint k = gl_GlobalInvocationID.x; k < n; k += stride) {
        const uint first = k * n - k * (k + 1u) / 2u - k - 1u;  // pairIndex(n, k, j) - j
        for (uint j = k + 1u; j < n; ++j) w[first + j] = u[k] * x[j] - u[j] * x[k];
    }
}
