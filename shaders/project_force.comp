#version 450
// Force projection, pass 1 of 2 (engine/README.md "Reduced dynamics"; CPU reference engine/reference/ForceProjection.h):
//
//     partial[k][b] = sum_{d in block b} Psi_k[d] w_d q_d
//
// for the modes of one chunk. Workgroup (mode group g, block b) takes MODES modes and one block of
// whole tiles of the tiled basis (ModeAccess.glsl). Each invocation sums, over its units of the
// block (one 32-byte word: 8 float32 or 16 float16 DOFs), x = w q formed once per unit dotted
// with the unit's word of each of the MODES modes; then each invocation of the first MODES / 4
// adds four modes' sums over the invocations in order. project_force_sum.comp adds the partial
// sums of each mode in a fixed order, so the result is deterministic (no atomics). Blocks spread
// one projection over many workgroups.
//
// Why, measured on lavapipe (tools/bench/bench_runtime; each step's times: engine/README.md
// "Speed"), each step faster than the one before: one invocation per DOF reading a float per mode,
// 8 modes a group; 64-bit vectors, 16 modes a group, mode-major modes; tiled; 64 modes a group,
// the slots past the chunk's modes skipped, each 8-wide batch on a run of consecutive tiles,
// larger blocks on a CPU device. Lavapipe pays per lane and load, whatever the load brings: x (w
// and q) shared by more modes pays, and so does running the tree (invocation by invocation there)
// over larger blocks (ForceProjection.cpp). A unit's word as one u64vec4 load instead of two
// u64vec2 loads. Then the precision, the input kind and the group's mode count as specialization
// constants (no unused path, few masked slots), w and density q read 8 floats a load, and the
// shared-memory tree replaced by one ordered pass over the invocations' sums: faster at 64^3
// N = 200 in each of seven runs alternating with the previous version, mostly faster at 256^2 and
// 48^3. Then the modes, w and density q fetched as texels (TexelAccess.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "ProjectForceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
// Fixed per pipeline (engine/device/ForceProjection): lavapipe runs both sides of a runtime
// branch, and a fixed count of mode slots unrolls.
layout(constant_id = 1) const uint HALF = 0u;    // 1: float16 modes, 0: float32
layout(constant_id = 2) const uint GATHER = 0u;  // 1: q is a whole-grid face field read at the DOF faces
layout(constant_id = 3) const uint MODES = 64u;  // mode slots of a workgroup, a multiple of 4

layout(set = 0, binding = 0) uniform usamplerBuffer modeTexels;
// The input's whole texels, for the units whose DOFs all lie in them (density q only).
layout(set = 0, binding = 1) uniform usamplerBuffer qTexels;
// Zero-padded to whole tiles of float16 modes (engine/device/ForceProjection).
layout(set = 0, binding = 2) uniform usamplerBuffer wTexels;
layout(std430, set = 0, binding = 3) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Partials { float partials[]; };
// The input again, one value at a time: the partial last unit, the padding, a face field.
layout(std430, set = 0, binding = 5) readonly buffer Input { float q[]; };
layout(push_constant) uniform Push { ProjectForceParams params; };

#include "ModeAccess.glsl"

const uint OCTETS = HALF + 1u;  // 8-DOF octets per unit

shared vec4 partial[gl_WorkGroupSize.x][MODES / 4u];

float sum[MODES];  // this invocation's sums
uint firstLocal;   // the group's first mode in the chunk
uint modes;        // the group's modes: slots past them are skipped and not written

// q at DOFs first ... first + 3 read one by one; past the last DOF at the last one (in bounds,
// the weight there is 0).
vec4 inputQuad(uint first) {
    const uvec4 d = min(uvec4(first) + uvec4(0u, 1u, 2u, 3u), uvec4(params.dofCount - 1u));
    if (GATHER != 0u) return vec4(q[faces[d.x]], q[faces[d.y]], q[faces[d.z]], q[faces[d.w]]);
    return vec4(q[d.x], q[d.y], q[d.z], q[d.w]);
}

// Adds the unit's word of each mode dotted with x = w q at its DOFs. `whole` (a constant at each
// call): the unit's DOFs all lie in density q's whole texels.
void accumulate(uint unit, const bool whole) {
    vec4 x[4];  // four DOFs per vec4 (float32: the first two)
    [[unroll]] for (uint h = 0; h < 2 * OCTETS; ++h) {
        const uint quad = 2u * OCTETS * unit + h;  // DOFs 4 quad ... 4 quad + 3
        x[h] = floatTexel(wTexels, quad) * (whole ? floatTexel(qTexels, quad) : inputQuad(4u * quad));
    }
    const uint base = unitBase(unit, params.modeCount);
    [[unroll]] for (uint m = 0; m < MODES; ++m) {
        if (m >= modes) break;
        const uint word = base + (firstLocal + m) * TILE_LANES;
        if (HALF != 0u) {
            vec4 h0, h1, h2, h3;
            modeHalves(word, h0, h1, h2, h3);
            sum[m] += dot(h0, x[0]) + dot(h1, x[1]) + dot(h2, x[2]) + dot(h3, x[3]);
        } else {
            vec4 f0, f1;
            modeFloats(word, f0, f1);
            sum[m] += dot(f0, x[0]) + dot(f1, x[1]);
        }
    }
}

void main() {
    const uint lane = gl_LocalInvocationID.x;
    const uint size = gl_WorkGroupSize.x;
    const uint block = gl_WorkGroupID.x % params.blockCount;
    firstLocal = (gl_WorkGroupID.x / params.blockCount) * MODES;
    modes = min(params.modeCount - firstLocal, MODES);

    // The block's units.
    const uint blockBegin = block * params.blockTiles;
    uint begin, step, end;
    unitRange(lane, size, blockBegin, min(blockBegin + params.blockTiles, params.tileCount), begin, step, end);

    [[unroll]] for (uint m = 0; m < MODES; ++m) sum[m] = 0.0;
    // Units wholly inside density q's whole texels first, then the rest (the partial last unit and
    // the padding; all units of a face-field input) one DOF a load: two loops, as a branch per
    // unit would run both sides on lavapipe.
    const uint wholeUnits = GATHER != 0u ? 0u : params.dofCount / (8u * OCTETS);
    uint unit = begin;
    for (; unit < min(end, wholeUnits); unit += step) accumulate(unit, true);
    for (; unit < end; unit += step) accumulate(unit, false);

    [[unroll]] for (uint j = 0; j < MODES / 4u; ++j)
        partial[lane][j] = vec4(sum[4 * j], sum[4 * j + 1], sum[4 * j + 2], sum[4 * j + 3]);
    barrier();
    // Invocation j adds the sums of modes 4j ... 4j + 3 over the invocations in order: one pass
    // over shared memory (a tree took log2(size) passes and barriers, run invocation by invocation
    // on lavapipe). A loop, not `lane < MODES / 4`: workgroups may have fewer invocations.
    for (uint j = lane; 4u * j < modes; j += size) {
        vec4 total = vec4(0.0);
        for (uint i = 0; i < size; ++i) total += partial[i][j];
        [[unroll]] for (uint k = 0; k < 4; ++k)
            if (4u * j + k < modes)
                partials[(params.firstMode + firstLocal + 4u * j + k) * params.blockCount + block] = total[k];
    }
}
