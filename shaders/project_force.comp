#version 450
// Force projection, pass 1 of 2 (DESIGN section 3; CPU reference engine/field/ForceProjection.h):
//
//     partial[k][b] = sum_{d in block b} Psi_k[d] w_d q_d
//
// for the modes of one chunk. Workgroup (mode group g, block b) takes MODES modes and one block of
// whole tiles of the tiled basis (ModeAccess.glsl). Each invocation sums, over its units of the
// block (one 32-byte word: 8 float32 or 16 float16 DOFs), x = w q formed once per unit dotted
// with the unit's word of each of the MODES modes; a shared-memory tree adds the invocations'
// sums. project_force_sum.comp adds the partial sums of each mode in a fixed order, so the result
// is deterministic (no atomics). Blocks spread one projection over many workgroups.
//
// Why, measured on lavapipe (tools/bench/bench_runtime, 48^3 grid, N = 100, CPU ms of one
// lavapipe thread, float32 / float16): one invocation per DOF reading a float per mode, 8 modes a
// group: 153 / 133. 64-bit vectors, 16 modes a group, mode-major modes: 126 / 97; tiled: 56 / 45.
// 64 modes a group, the slots past the chunk's modes skipped, each 8-wide batch on a run of
// consecutive tiles, larger blocks on a CPU device: 41 / 27. Lavapipe pays per lane and load,
// whatever the load brings: x (w and q, 10 loads a unit) shared by more modes pays, and so does
// running the tree (invocation by invocation there) over larger blocks (ForceProjection.cpp).
// A unit's word as one u64vec4 load instead of two u64vec2 loads (64^3 grid, N = 200, GPU ms with
// two lavapipe threads, float32 / float16): 198-220 / 156-166 -> 109-112 / 83-88.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "ProjectForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Modes { u64vec4 modeWords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Input { float q[]; };
// Zero-padded to whole tiles of float16 modes (engine/kernels/ForceProjection), read four at a time.
layout(std430, set = 0, binding = 2) readonly buffer Weights { u64vec2 w[]; };
layout(std430, set = 0, binding = 3) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Partials { float partials[]; };
layout(push_constant) uniform Push { ProjectForceParams params; };

#include "ModeAccess.glsl"

const uint MODES = PROJECT_FORCE_MODES_PER_GROUP;

shared vec4 partial[gl_WorkGroupSize.x][MODES / 4];

// w q at DOFs 4 quad ... 4 quad + 3; past the last DOF q is read at the last one (in bounds) and
// the weight is 0.
vec4 weightedInput(uint quad) {
    const uvec4 d = min(uvec4(4u * quad) + uvec4(0u, 1u, 2u, 3u), uvec4(params.dofCount - 1u));
    const vec4 x = params.gatherFaces != 0u ? vec4(q[faces[d.x]], q[faces[d.y]], q[faces[d.z]], q[faces[d.w]])
                                            : vec4(q[d.x], q[d.y], q[d.z], q[d.w]);
    return floatsOf(w[quad]) * x;
}

void main() {
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    const uint block = gl_WorkGroupID.x % params.blockCount;
    const uint firstLocal = (gl_WorkGroupID.x / params.blockCount) * MODES;
    // The group's modes in the chunk; the slots past them are skipped and not written.
    const uint modes = min(params.modeCount - firstLocal, MODES);
    uint mode[MODES];  // offsets of the modes in a tile
    [[unroll]] for (uint m = 0; m < MODES; ++m) mode[m] = min(firstLocal + m, params.modeCount - 1u) * TILE_LANES;

    // The block's units. With whole batches of TILE_LANES invocations each batch takes a run of
    // consecutive tiles: on lavapipe a batch is the SIMD width, and its loads then advance by a
    // fixed stride the prefetcher follows. Otherwise the invocations stride over the units.
    const uint blockBegin = block * params.blockTiles;
    const uint tiles = min(params.blockTiles, params.tileCount - blockBegin);
    uint begin = blockBegin * TILE_LANES + lane, step = size, end = (blockBegin + tiles) * TILE_LANES;
    if (size % TILE_LANES == 0u) {
        const uint batches = size / TILE_LANES, perBatch = (tiles + batches - 1u) / batches;
        const uint first = min((lane / TILE_LANES) * perBatch, tiles);
        begin = (blockBegin + first) * TILE_LANES + lane % TILE_LANES;
        step = TILE_LANES;
        end = (blockBegin + min(first + perBatch, tiles)) * TILE_LANES;
    }

    float sum[MODES];
    [[unroll]] for (uint m = 0; m < MODES; ++m) sum[m] = 0.0;
    if (params.halfPrecision != 0u) {
        for (uint unit = begin; unit < end; unit += step) {
            const uint base = unitBase(unit, params.modeCount);
            vec4 x[2 * TILE_ROWS];  // the unit's 16 DOFs, four per vec4
            [[unroll]] for (uint j = 0; j < 2 * TILE_ROWS; ++j) x[j] = weightedInput(2u * TILE_ROWS * unit + j);
            [[unroll]] for (uint m = 0; m < MODES; ++m) {
                if (m >= modes) break;
                const u64vec4 word = modeWords[base + mode[m]];
                vec4 low, high, low2, high2;
                halvesOf(word.xy, low, high);
                halvesOf(word.zw, low2, high2);
                sum[m] += dot(low, x[0]) + dot(high, x[1]) + dot(low2, x[2]) + dot(high2, x[3]);
            }
        }
    } else {
        for (uint unit = begin; unit < end; unit += step) {
            const uint base = unitBase(unit, params.modeCount);
            vec4 x[TILE_ROWS];  // the unit's 8 DOFs, four per vec4
            [[unroll]] for (uint r = 0; r < TILE_ROWS; ++r) x[r] = weightedInput(TILE_ROWS * unit + r);
            [[unroll]] for (uint m = 0; m < MODES; ++m) {
                if (m >= modes) break;
                const u64vec4 word = modeWords[base + mode[m]];
                sum[m] += dot(floatsOf(word.xy), x[0]) + dot(floatsOf(word.zw), x[1]);
            }
        }
    }

    [[unroll]] for (uint j = 0; j < MODES / 4; ++j)
        partial[lane][j] = vec4(sum[4 * j], sum[4 * j + 1], sum[4 * j + 2], sum[4 * j + 3]);
    barrier();
    // Works for any workgroup size, not only powers of two.
    for (uint stride = 1u; stride < size; stride *= 2u) {
        if (lane % (2u * stride) == 0u && lane + stride < size)
            [[unroll]] for (uint j = 0; j < MODES / 4; ++j) partial[lane][j] += partial[lane + stride][j];
        barrier();
    }
    // A loop, not `lane < modes`: workgroups may have fewer than MODES invocations.
    for (uint m = lane; m < modes; m += size)
        partials[(params.firstMode + firstLocal + m) * params.blockCount + block] = partial[0][m / 4u][m % 4u];
}
