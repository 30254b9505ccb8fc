#version 450
// The dense Lie advection's partial sums (ModalStepParams.h): for one chunk of the packed tiles
// (modal_pair_sums.comp has the layout), group g of tiles and octet q of the modes,
//
//     partial[firstGroup + g][8 q + m] = sum over the rows p of g's tiles of C_p[8 q + m] w_p,
//
// the transposed product of modal_pair_sums.comp's. One invocation per (group, octet),
// grid-stride; modal_advect_sum.comp adds the groups.
#extension GL_GOOGLE_include_directive : require
#include "ModalStepParams.h"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(set = 0, binding = 0) uniform usamplerBuffer coefficients;
layout(std430, set = 0, binding = 1) readonly buffer Weights { float w[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Partial { vec4 partial[]; };
layout(push_constant) uniform Push { AdvectDenseParams params; };

void main() {
    const uint octets = params.rowOctets;
    const uint tiles = (params.pairCount + PAIR_TILE_ROWS - 1u) / PAIR_TILE_ROWS;
    const uint items = params.groupCount * octets;
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint item = gl_GlobalInvocationID.x; item < items; item += stride) {
        const uint group = item / octets, q = item % octets;
        vec4 low = vec4(0.0), high = vec4(0.0);
        const uint last = min(tiles, (group + 1u) * params.tilesPerGroup);
        for (uint tile = group * params.tilesPerGroup; tile < last; ++tile) {
            const uint rows = min(PAIR_TILE_ROWS, params.pairCount - tile * PAIR_TILE_ROWS);
            const uint base = (tile * octets + q) * PAIR_TILE_ROWS;
            for (uint j = 0u; j < rows; ++j) {
                const float weight = w[params.firstPair + tile * PAIR_TILE_ROWS + j];
                low += weight * floatTexel(coefficients, 2u * (base + j));
                high += weight * floatTexel(coefficients, 2u * (base + j) + 1u);
            }
        }
        const uint at = 2u * ((params.firstGroup + group) * octets + q);
        partial[at] = low;
        partial[at + 1u] = high;
    }
}
