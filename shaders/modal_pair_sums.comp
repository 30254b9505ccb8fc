#version 450
// First half of the dense structural-coefficient contraction (engine/README.md "Reduced dynamics", seed eq. 6.6),
// float32. For every stored pair p = (k, j), k < j, of one chunk of the packed coefficients:
//
//     sums(k, j) = sum_i C[k][i][j] a_i,   stored as U[k][j] (modal_combine.comp)
//
// modal_combine.comp then forms out_k = sum_{j>k} U[k][j] b_j - sum_{j<k} U[j][k] b_j, using
// C[j][i][k] = -C[k][i][j]. Each coefficient is read exactly once per contraction: the kernel is a
// GEMV over the (pairs x N) matrix of the chunk, and bandwidth-bound.
//
// Layout (engine/device/DeviceCoefficients): each row cut into rowOctets octets of 8 floats
// (zero-padded), the rows in tiles of PAIR_TILE_ROWS (the chunk zero-padded to whole tiles). A tile
// stores octet 0 of its rows, then octet 1 of them, and so on: octet q of row j of tile t is element
// (t rowOctets + q) PAIR_TILE_ROWS + j. Each batch of PAIR_TILE_LANES invocations sums one tile,
// each invocation ROWS of its rows (j = r PAIR_TILE_LANES + lane) front to back, one fetch of a's
// octet q serving all ROWS.
//
// Why, measured on lavapipe (tools/bench/bench_runtime, N = 200): lavapipe issues every lane's
// storage-buffer load as a loop over the lanes with a mask and bounds check per lane and per
// component, so the count of loads and components is what costs, not bytes. Each step faster
// than the one before (rates: engine/README.md "Speed"): floats; 64-bit words; four rows per
// a[q]. A subgroup per row with coalesced loads and subgroupAdd, or a[q] shared by
// subgroupBroadcast, were no faster. Tiles, which make what one 8-wide batch (lavapipe's SIMD
// width with AVX2) reads one contiguous stream instead of 32 (one per row); octets as one load of
// four 64-bit words and eight rows a lane. Then both inputs read as uniform texel buffers
// (TexelAccess.glsl), which lavapipe fetches with unmasked vector gathers. On a GPU each fetch of
// a warp covers whole, aligned segments (8 lanes x 32 bytes). Tiles are visited grid-stride, so any group count works.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "ModalStepParams.h"
#include "TexelAccess.glsl"

layout(local_size_x = 64, local_size_x_id = 0) in;

// Octets of 8 floats, two texels each; `a` holds rowOctets of them (zero-padded).
layout(set = 0, binding = 0) uniform usamplerBuffer coefficients;
layout(set = 0, binding = 1) uniform usamplerBuffer a;
layout(std430, set = 0, binding = 2) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { PairSumsParams params; };

const uint LANES = PAIR_TILE_LANES;

uint pairIndex(uint n, uint k, uint j) { return k * n - k * (k + 1u) / 2u + (j - k - 1u); }

// Pair p = (k, j) of the packed order (engine/core/PackedLayout.h) into U (modal_combine.comp):
// k from the quadratic formula in float, then corrected to the exact row.
void storePairSum(uint p, float value) {
    const uint n = params.n;
    const float b = float(2u * n - 1u);
    uint k = uint(max(0.0, floor(0.5 * (b - sqrt(max(0.0, b * b - 8.0 * float(p)))))));
    k = min(k, n - 2u);
    while (k > 0u && pairIndex(n, k, k + 1u) > p) --k;
    while (k + 2u < n && pairIndex(n, k + 1u, k + 2u) <= p) ++k;
    const uint j = p - pairIndex(n, k, k + 1u) + k + 1u;
    sums[k * 8u * params.rowOctets + j] = value;
}
const uint ROWS = PAIR_TILE_ROWS / PAIR_TILE_LANES;  // rows per invocation

void main() {
    const uint lane = gl_GlobalInvocationID.x % LANES;
    const uint tiles = (params.pairCount + PAIR_TILE_ROWS - 1u) / PAIR_TILE_ROWS;
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x / LANES;
    for (uint tile = gl_GlobalInvocationID.x / LANES; tile < tiles; tile += stride) {
        float sum[ROWS];
        [[unroll]] for (uint r = 0; r < ROWS; ++r) sum[r] = 0.0;
        uint index = tile * params.rowOctets * PAIR_TILE_ROWS + lane;
        for (uint q = 0; q < params.rowOctets; ++q, index += PAIR_TILE_ROWS) {
            const vec4 low = floatTexel(a, 2u * q), high = floatTexel(a, 2u * q + 1u);
            [[unroll]] for (uint r = 0; r < ROWS; ++r) {
                const uint octet = index + r * LANES;
                sum[r] += dot(floatTexel(coefficients, 2u * octet), low) +
                          dot(floatTexel(coefficients, 2u * octet + 1u), high);
            }
        }
        [[unroll]] for (uint r = 0; r < ROWS; ++r) {
            const uint row = tile * PAIR_TILE_ROWS + r * LANES + lane;
            if (row < params.pairCount) storePairSum(params.firstPair + row, sum[r]);
        }
    }
}
