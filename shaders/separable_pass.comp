#version 450
// One pass of a closed-form basis transform along one axis (engine/basis/SeparableTransform.h;
// device side: engine/device/SeparableTransform): every line of the tensor along the axis (its
// fastest index) taken through the axis's table of trigonometric factors, a per-axis sum over
// the band of wave numbers in use (synthesis: slots -> positions; analysis: the transposed table,
// positions -> slots), written with the axes rotated so that three passes bring the tensor back
// to x fastest:
//
//     out[q outPlane + i2 outRow + i1] = sum_j table(q, j) in[(i2 d1 + i1) inLength + j]
//
// (outRow = d1, outPlane = d1 d2 for a packed tensor; a reconstruction's last pass writes the
// face field's rows and planes, which have the walls' faces between them), over the window of
// lines and inputs the host gives (all of them, or those of a box a projected field vanishes
// outside).
// One invocation per line and GROUP blocks of four consecutive outputs q (grid-stride),
// neighbouring lanes on neighbouring lines. The table is stored j-major, four outputs a texel
// (entry (q, j) at float j * 4 blocks + q, blocks = ceil(outLength / 4), zero-padded), so one
// texel fetch, the same for every lane of a batch, serves four outputs and each input value is
// loaded once for 4 GROUP of them (two blocks faster than one: engine/README.md "Speed"). Why
// texels: lavapipe makes every lane's storage load a scalar access and a texel fetch one gather
// for all lanes (TexelAccess.glsl); one output an invocation, two storage loads a term, was
// several times slower (precompute/README.md "Closed-form bases").
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "SeparableParams.h"
#include "LaneDivision.glsl"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(set = 0, binding = 0) uniform usamplerBuffer tables;  // texels; see above
// One value a texel (R32UI): lanes on different lines read different values, a gather where a
// storage load is a scalar access per lane (the last passes faster: engine/README.md "Speed").
layout(set = 0, binding = 1) uniform usamplerBuffer values;
layout(std430, set = 0, binding = 2) writeonly buffer Out { float result[]; };
layout(push_constant) uniform Push { SeparablePassParams params; };

#define GROUP SEPARABLE_BLOCKS_PER_INVOCATION

void main() {
    const uint lines = params.i1Count * params.i2Count;
    const uint blocks = (params.outLength + 3u) / 4u;
    // The groups of 4 GROUP outputs that hold the outputs asked for.
    const uint firstGroup = params.outFirst / (4u * GROUP);
    const uint groups =
        (params.outFirst + params.outCount + 4u * GROUP - 1u) / (4u * GROUP) - firstGroup;
    const uint total = lines * groups;
    const uint lastTexel = params.tableTexel + params.inLength * blocks - 1u;
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint e = gl_GlobalInvocationID.x; e < total; e += stride) {
        const uint inGroups = quotientOf(e, lines), inWindow = e - inGroups * lines;
        const uint group = firstGroup + inGroups;
        const uint i2Local = quotientOf(inWindow, params.i1Count);
        const uint i1 = params.i1First + inWindow - i2Local * params.i1Count;
        const uint i2 = params.i2First + i2Local;
        const uint first = params.inOffset + (i2 * params.d1 + i1) * params.inLength;
        uint texel = params.tableTexel + GROUP * group + params.jFirst * blocks;
        vec4 sum[GROUP];
        [[unroll]] for (uint g = 0; g < GROUP; ++g) sum[g] = vec4(0.0);
        const uint jEnd = params.jFirst + params.jCount;
        for (uint j = params.jFirst; j < jEnd; ++j, texel += blocks) {
            const float v = uintBitsToFloat(texelFetch(values, int(first + j)).x);
            [[unroll]] for (uint g = 0; g < GROUP; ++g)
                sum[g] += floatTexel(tables, min(texel + g, lastTexel)) * v;
        }
        const uint at = params.outOffset + i2 * params.outRow + i1;
        [[unroll]] for (uint g = 0; g < GROUP; ++g)
            [[unroll]] for (uint c = 0; c < 4u; ++c) {
                const uint q = 4u * (GROUP * group + g) + c;
                if (q < params.outLength) result[at + q * params.outPlane] = sum[g][c];
            }
    }
}
