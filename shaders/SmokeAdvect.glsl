/* SmokeAdvect.glsl: one smoke advection step of density and temperature together, float32
   (engine/README.md; CPU reference engine/reference/SmokeAdvection.cpp, whose comments give the
   reasons for each rule), the body of the smoke_advect_<stage>_<dim>d.comp kernels, which define
   SMOKE_STAGE (SmokeAdvectParams.h) and SMOKE_DIM:

     semi-Lagrangian:  out = SL(in) + emitters                                  (one dispatch)
     MacCormack:       hat = SL(in)                                             (forward)
                       out = clamp(hat + (in - SL_-dt(hat)) / 2, fluid stencil range of in)
                             + emitters                                         (correction)

   SL: RK2 (midpoint) backtrace from the cell centre with the MAC-sampled velocity of the basis
   grid, in smoke-grid units; trilinear sample over the fluid cells of the stencil only, weights
   renormalized; no fluid weight left: the cell keeps its own value. Along periodic axes traces
   leave through one end and come in through the other: the stencils wrap (MacSampling.glsl).
   With a wind the sides it crosses are open (their faces carry its velocity) and the upstream
   ones bring in its air: ghost cells beyond them hold the outside air's values (OutsideAir: the
   wind's, or an [[inflow]]'s where it meets the side) in the sample and its clamp range. Open
   sides ([grid] open) are inflow sides of clean air. MacCormack's traces ahead
   read no ghosts: they leave the box only where the air leaves it.
   smoke_face_pairs.comp runs first each step. Cells outside the fluid mask are never written:
   SmokeState keeps them 0.

   Layout and work, chosen by measurement on lavapipe (Mesa 22.3; SmokeKernelTest's TimingPerStep,
   the times in engine/README.md "Speed"). There every lane's storage-buffer load or store of
   every 32- or 64-bit component is a separate scalar access whatever the pattern, so the count of
   components is the cost (shaders/modal_pair_sums.comp), while a texel fetch is one vector gather
   for all lanes (shaders/TexelAccess.glsl); and an `if` only masks lanes: its body runs, loads
   included, even when no lane takes it (gallivm's if_cond):
   - every read-only input fetched as texels (uniform texel buffers): the velocity pairs, the
     cell list, the stencil mask, the fields (in, and MacCormack's hat in the correction) and
     the record. Against 64-bit storage loads, steps ran faster, most where the stencil corners
     are gathered at random. The inputs read a 64-bit word at a time (pairs and fields) go through
     RG32UI views (DeviceBuffer::wordView), whose fetch gathers the two components in use, not
     the four of an RGBA32UI texel and a select of half (faster still); the stencil mask's 32-bit
     words likewise through an R32UI view (floatView);
   - results still stored as 64-bit words, one scalar access per lane, where a uvec2 takes two;
   - stage and dimension fixed at compile time, one pipeline each: with a run-time stage switch
     the correction cost nearly as much as the forward stage, split far less;
   - one invocation per entry of a list of the fluid cells (x fastest, so neighbouring lanes read
     neighbouring cells): no lane works outside the mask (most of the cells of the tests' disks
     and balls); an entry is one texel: the coordinates (no integer division) and the emitters'
     rates summed per fluid cell on the host (SmokeState::setEmitters), not a loop over emitter
     records in every lane;
   - density and temperature interleaved, one 64-bit word per cell: one fetch per stencil corner
     for both fields;
   - the fluid flags of a whole stencil in one byte (SmokeState's stencil mask): one fetch per
     stencil; a mask load per corner made steps slower (storage loads);
   - velocity faces read in x-neighbour pairs (MacSampling.glsl, smoke_face_pairs.comp): one
     fetch per two corners; reading the faces as floats made 3D steps much slower at scale 1
     (storage loads);
   - MacCormack's forward stage also traces backward (the centre velocity serves both traces) and
     records the clamp range and the backward end point, so the correction re-traces and
     re-samples nothing of the forward step: 3 velocity samples per cell instead of 6.
   On a GPU the same choices cut memory transactions and leave no lane idle, and texel fetches go
   through the texture cache. */
#ifndef MODEFLOW_SHADERS_SMOKE_ADVECT_GLSL
#define MODEFLOW_SHADERS_SMOKE_ADVECT_GLSL

#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "SmokeAdvectParams.h"
#include "OutsideAir.glsl"

layout(local_size_x = 128, local_size_x_id = 0) in;

// Read-only inputs as uniform texel buffers of RGBA32UI texels (why: the header).
layout(set = 0, binding = 0) uniform usamplerBuffer facePairs;   // one pair a word texel
layout(set = 0, binding = 1) uniform usamplerBuffer fluidCells;  // one entry a texel
layout(set = 0, binding = 2) uniform usamplerBuffer stencilMask; // 4 cells a (R32UI) texel
layout(set = 0, binding = 3) uniform usamplerBuffer fieldsIn;    // one cell a word texel
#if SMOKE_STAGE == SMOKE_STAGE_MACCORMACK_CORRECT
layout(set = 0, binding = 4) uniform usamplerBuffer hat;     // the forward stage's, one cell a word texel
layout(set = 0, binding = 5) uniform usamplerBuffer record;  // list order, two texels an entry
#else
// Stores of 64-bit words: one scalar access per lane each on lavapipe, where a uvec2 takes two.
layout(std430, set = 0, binding = 4) writeonly buffer Hat { uint64_t hat[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Record { uint64_t record[]; };  // list order
#endif
layout(std430, set = 0, binding = 6) writeonly buffer FieldsOut { uint64_t fieldsOut[]; };
layout(std430, set = 0, binding = 7) writeonly buffer TemperatureOut { float temperatureOut[]; };
layout(set = 0, binding = 8) uniform usamplerBuffer ghosts;  // OutsideAir's, one a texel
layout(push_constant) uniform Push { SmokeAdvectParams params; };

// The 64-bit word `index` of a word texel buffer (RG32UI) as two floats.
vec2 wordAt(usamplerBuffer words, uint index) { return uintBitsToFloat(texelFetch(words, int(index)).xy); }
uint64_t packPair(vec2 v) { return pack64(floatBitsToUint(v)); }

#define MAC_DIM SMOKE_DIM
vec2 macFacePair(uint face) { return wordAt(facePairs, face); }
#include "MacSampling.glsl"

uint stencilBits(uint cell) {
    const uint word = texelFetch(stencilMask, int(cell >> 2)).x;
    return (word >> ((cell & 3u) * 8u)) & 0xffu;
}

uint cellIndex(ivec3 p) { return uint((p.z * int(params.cellsY) + p.y) * int(params.cellsX) + p.x); }

// Velocity at a point in smoke-grid units (the basis grid is `scale` times coarser).
vec3 velocityAt(vec3 g) {
    vec3 basisPoint = g;
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) basisPoint[a] = g[a] / float(params.scale);
    return sampleVelocityGrid(basisPoint, ivec3(params.basisX, params.basisY, params.basisZ),
                              uvec3(0u, params.faceOffsetY, params.faceOffsetZ), params.boundary);
}

// With the smoke grid the basis grid (scale 1), a trace starts at a basis cell's centre, where
// the MAC sample of each component is the mean of the cell's two faces across it: 2 face reads a
// component where velocityAt reads 8, and no stencil arithmetic (the forward stage, which does
// it once for both traces, and the semi-Lagrangian step). The same sums to the bit: the
// general sample adds the other faces with weight 0 (MacSampling.glsl).
layout(constant_id = 1) const bool unitScale = false;

vec3 cellCentreVelocity(ivec3 cell) {
    const ivec3 cells = ivec3(params.basisX, params.basisY, params.basisZ);
    const uvec3 offsets = uvec3(0u, params.faceOffsetY, params.faceOffsetZ);
    vec3 u = vec3(0.0);
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) {
        const bool wraps = isPeriodic(params.boundary, a);
        ivec3 extent = cells;
        extent[a] += wraps ? 0 : 1;
        const uint face = offsets[a] + uint((cell.z * extent.y + cell.y) * extent.x + cell.x);
        vec2 faces = macFacePair(face);  // along x the pair is the two faces
        if (a > 0) {
            const int rowStride = a == 1 ? extent.x : extent.x * extent.y;
            const int across = wraps && cell[a] + 1 == cells[a] ? -(cells[a] - 1) * rowStride : rowStride;
            faces.y = macFacePair(face + uint(across)).x;  // negative across a seam: wraps
        }
        const bool walled = !wraps && !flowsThrough(params.boundary, a);
        const bool wallLo = walled && cell[a] == 0;
        const bool wallHi = walled && cell[a] + 1 == cells[a];
        u[a] = 0.5 * (wallLo ? 0.0 : faces.x) + 0.5 * (wallHi ? 0.0 : faces.y);
    }
    return u;
}

// Velocity at the centre of smoke cell `cell`.
vec3 velocityAtCentre(ivec3 cell) {
    return unitScale ? cellCentreVelocity(cell) : velocityAt(vec3(cell) + 0.5);
}

// Where the RK2 trace from `start` ends after -step * u, in smoke-grid units; u0 = velocityAt(start).
vec3 traceEnd(vec3 start, vec3 u0, vec3 step) {
    const vec3 mid = start - 0.5 * (u0 * step);
    return start - velocityAt(mid) * step;
}

// What the ghost cell a sample at `g` reaches beyond the inflow sides (`sides`, SMOKE_INFLOW_*
// bits) holds for this pair, as OutsideAir::ghostOf picks it: beyond the side it reaches
// farthest past (the first on a tie), at the cell its other coordinates fall in (clamped to the
// box, wrapped along periodic axes; a non-finite one at 0).
vec2 ghostAt(vec3 g, uint sides) {
    const ivec3 cells = ivec3(params.cellsX, params.cellsY, params.cellsZ);
    int side = 0;
    float least = 2.0;
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) {
        const float low = clamp(g[a] + 0.5, 0.0, 1.0);
        if ((sides & (1u << (SMOKE_INFLOW_LOW + uint(a)))) != 0u && low < least) {
            least = low;
            side = 2 * a;
        }
        const float high = clamp(float(cells[a]) + 0.5 - g[a], 0.0, 1.0);
        if ((sides & (1u << (SMOKE_INFLOW_HIGH + uint(a)))) != 0u && high < least) {
            least = high;
            side = 2 * a + 1;
        }
    }
    ivec3 at = ivec3(0);
    [[unroll]] for (int b = 0; b < SMOKE_DIM; ++b) {
        const int n = cells[b];
        const float x = isnan(g[b]) || isinf(g[b]) ? 0.0 : clamp(floor(g[b]), -float(n), 2.0 * float(n));
        at[b] = isPeriodic(params.boundary, b) ? ((int(x) % n) + n) % n : clamp(int(x), 0, n - 1);
    }
    return ghostPairOf(texelFetch(ghosts, ghostIndex(side, at, cells)), params.ghostPair);
}

// A masked trilinear sample of (density, temperature) from `fields` (in or hat), and the range of the
// fluid cells of its stencil (lo > hi: none).
struct FluidSample {
    vec2 value;
    vec2 lo;
    vec2 hi;
};

FluidSample sampleFluid(usamplerBuffer fields, vec3 g, vec2 fallback, bool ghosts) {
    const ivec3 cells = ivec3(params.cellsX, params.cellsY, params.cellsZ);
    AxisStencil s[3];
    s[2] = AxisStencil(0, 0, 0.0);
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a)
        s[a] = axisStencil(g[a], 0.5, cells[a], isPeriodic(params.boundary, a));
    const uint base = cellIndex(ivec3(s[0].lo, s[1].lo, s[2].lo));
    const uint fluid = stencilBits(base);
    // Offsets of the hi corners: 0 on a one-cell axis, whose hi corner is the lo one (its bit is 0);
    // negative across a periodic seam (uint arithmetic wraps them right).
    const uint dx = uint(s[0].hi - s[0].lo);
    const uint dy = uint(s[1].hi - s[1].lo) * params.cellsX;
    const uint dz = uint(s[2].hi - s[2].lo) * params.cellsX * params.cellsY;
    const float infinity = uintBitsToFloat(0x7f800000u);
    FluidSample taken = FluidSample(vec2(0.0), vec2(infinity), vec2(-infinity));
    vec2 sum = vec2(0.0);
    float weight = 0.0;
    [[unroll]] for (int cz = 0; cz < (SMOKE_DIM == 3 ? 2 : 1); ++cz)
        [[unroll]] for (int cy = 0; cy < 2; ++cy)
            [[unroll]] for (int cx = 0; cx < 2; ++cx) {
                const vec2 v = wordAt(fields, base + uint(cx) * dx + uint(cy) * dy + uint(cz) * dz);
                if ((fluid & (1u << (cx + 2 * cy + 4 * cz))) == 0u) continue;
                float w = (cx != 0 ? s[0].f : 1.0 - s[0].f) * (cy != 0 ? s[1].f : 1.0 - s[1].f);
#if SMOKE_DIM == 3
                w *= cz != 0 ? s[2].f : 1.0 - s[2].f;
#endif
                sum += w * v;
                weight += w;
                taken.lo = min(taken.lo, v);
                taken.hi = max(taken.hi, v);
            }
    taken.value = weight > 0.0 ? sum / weight : fallback;
    // Within a cell of an inflow side the trilinear weights reach the ghost cells beyond it,
    // which hold what the outside air brings: the in-box share of the sample, as on the CPU.
    float share = 1.0;
    const uint inflowSides = ghosts ? params.boundary : 0u;
    [[unroll]] for (int a = 0; a < SMOKE_DIM; ++a) {
        if ((inflowSides & (1u << (SMOKE_INFLOW_LOW + uint(a)))) != 0u)
            share *= clamp(g[a] + 0.5, 0.0, 1.0);
        if ((inflowSides & (1u << (SMOKE_INFLOW_HIGH + uint(a)))) != 0u)
            share *= clamp(float(cells[a]) + 0.5 - g[a], 0.0, 1.0);
    }
    if (share < 1.0) {
        const vec2 inflow = ghostAt(g, inflowSides);
        taken.value = share * taken.value + (1.0 - share) * inflow;
        if (weight > 0.0) {  // the clamp range takes the inflow's value in (none without fluid)
            taken.lo = min(taken.lo, inflow);
            taken.hi = max(taken.hi, inflow);
        }
    }
    return taken;
}

void main() {
    const uint entry = params.firstCell + gl_GlobalInvocationID.x;
    if (entry >= params.fluidCount) return;
    const uvec4 listed = texelFetch(fluidCells, int(entry));
    const ivec3 cell = ivec3(listed.x & 0xffffu, listed.x >> 16, listed.y);
    const uint id = cellIndex(cell);
    const vec3 start = vec3(cell) + 0.5;
    const vec3 step = vec3(params.stepX, params.stepY, params.stepZ);
    const vec2 old = wordAt(fieldsIn, id);

#if SMOKE_STAGE == SMOKE_STAGE_MACCORMACK_FORWARD
    const vec3 u0 = velocityAtCentre(cell);
    const FluidSample forward = sampleFluid(fieldsIn, traceEnd(start, u0, step), old, true);
    const vec3 ahead = traceEnd(start, u0, -step);
    const uint r = entry * SMOKE_RECORD_WORDS;
    hat[id] = packPair(forward.value);
    record[r] = packPair(forward.lo);
    record[r + 1u] = packPair(forward.hi);
    record[r + 2u] = packPair(ahead.xy);
#if SMOKE_DIM == 3
    record[r + 3u] = packPair(vec2(ahead.z, 0.0));
#endif
#else
#if SMOKE_STAGE == SMOKE_STAGE_SEMI_LAGRANGIAN
    vec2 result = sampleFluid(fieldsIn, traceEnd(start, velocityAtCentre(cell), step), old, true).value;
#else
    const vec4 range = uintBitsToFloat(texelFetch(record, int(2u * entry)));  // lo, hi
    const vec3 ahead = uintBitsToFloat(texelFetch(record, int(2u * entry + 1u)).xyz);  // z unused in 2D
    const vec2 forward = wordAt(hat, id);
    // The traces ahead read no ghosts: they leave the box where the air leaves it (as on the CPU).
    const vec2 backward = sampleFluid(hat, ahead, forward, false).value;
    vec2 result = range.x <= range.z ? clamp(forward + 0.5 * (old - backward), range.xy, range.zw) : forward;
#endif
    result += uintBitsToFloat(listed.zw) * params.dt;
    fieldsOut[id] = packPair(result);
    temperatureOut[id] = result.y;
#endif
}

#endif
