#version 450
// One pass of a closed-form basis transform along one axis (engine/format/SeparableTransform.h;
// device side: engine/device/SeparableTransform): every line of the tensor along the axis (its
// fastest index) taken through the axis's table of trigonometric factors, a per-axis sum over
// the band of wave numbers in use (synthesis: slots -> positions; analysis: the transposed table,
// positions -> slots), written with the axes rotated so that three passes bring the tensor back
// to x fastest:
//
//     out[(q d2 + i2) d1 + i1] = sum_j table[q inLength + j] in[(i2 d1 + i1) inLength + j]
//
// One output value per invocation (grid-stride).
#extension GL_GOOGLE_include_directive : require
#include "SeparableParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Tables { float table[]; };
layout(std430, set = 0, binding = 1) readonly buffer In { float values[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Out { float result[]; };
layout(push_constant) uniform Push { SeparablePassParams params; };

void main() {
    const uint lines = params.d1 * params.d2;
    const uint total = lines * params.outLength;
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint e = gl_GlobalInvocationID.x; e < total; e += stride) {
        const uint line = e % lines, q = e / lines;  // line = i2 d1 + i1
        const uint row = params.tableOffset + q * params.inLength;
        const uint first = params.inOffset + line * params.inLength;
        float sum = 0.0;
        for (uint j = 0; j < params.inLength; ++j) sum += table[row + j] * values[first + j];
        result[params.outOffset + e] = sum;
    }
}
