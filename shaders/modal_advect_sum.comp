#version 450
// out_i = sum over the rows g of modal_advect_dense.comp's partial sums of partial[g][i], in a fixed
// order (deterministic). One invocation per i.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Partial { float partial[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Result { float result[]; };
layout(push_constant) uniform Push { AdvectSumParams params; };

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint i = gl_GlobalInvocationID.x; i < params.n; i += stride) {
        float sum = 0.0;
        for (uint g = 0u; g < params.groupCount; ++g) sum += partial[g * params.rowStride + i];
        result[i] = sum;
    }
}
