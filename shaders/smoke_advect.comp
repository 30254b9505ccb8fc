#version 450
// One smoke advection step of density and temperature together, float32 (DESIGN section 4; CPU
// reference engine/field/SmokeAdvection.cpp, whose comments give the reasons for each rule):
//
//   semi-Lagrangian:  out = SL(in) + emitters                                   (one dispatch)
//   MacCormack:       hat = SL(in);                                              (stage 1)
//                     out = clamp(hat + (in - SL_-dt(hat)) / 2, fluid stencil range of in)
//                           + emitters                                           (stage 2)
//
// SL: RK2 (midpoint) backtrace from the cell centre with the MAC-sampled velocity of the basis
// grid, in smoke-grid units; trilinear sample over the fluid cells of the stencil only, weights
// renormalized; no fluid weight left: the cell keeps its own value. Cells outside the fluid mask
// are written as exactly 0. One invocation per smoke cell, x fastest, so neighbouring lanes read
// neighbouring cells; stage 2 recomputes the forward backtrace rather than storing it.
#extension GL_GOOGLE_include_directive : require
#include "SmokeAdvectParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Velocity { float velocity[]; };
layout(std430, set = 0, binding = 1) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 2) readonly buffer Emitters { SmokeEmitterData emitters[]; };
layout(std430, set = 0, binding = 3) readonly buffer DensityIn { float densityIn[]; };
layout(std430, set = 0, binding = 4) readonly buffer TemperatureIn { float temperatureIn[]; };
layout(std430, set = 0, binding = 5) buffer DensityHat { float densityHat[]; };
layout(std430, set = 0, binding = 6) buffer TemperatureHat { float temperatureHat[]; };
layout(std430, set = 0, binding = 7) writeonly buffer DensityOut { float densityOut[]; };
layout(std430, set = 0, binding = 8) writeonly buffer TemperatureOut { float temperatureOut[]; };
layout(push_constant) uniform Push { SmokeAdvectParams params; };

float macFaceValue(uint face) { return velocity[face]; }
#include "MacSampling.glsl"

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

ivec3 smokeCells() { return ivec3(params.cellsX, params.cellsY, params.cellsZ); }

uint cellIndex(ivec3 p) { return uint((p.z * int(params.cellsY) + p.y) * int(params.cellsX) + p.x); }

// Velocity at a point in smoke-grid units (the basis grid is `scale` times coarser).
vec3 velocityAt(vec3 g) {
    vec3 basisPoint = g;
    for (int a = 0; a < int(params.dim); ++a) basisPoint[a] = g[a] / float(params.scale);
    return sampleVelocityGrid(basisPoint, ivec3(params.basisX, params.basisY, params.basisZ), int(params.dim),
                              uvec3(0u, params.faceOffsetY, params.faceOffsetZ));
}

// Where the RK2 trace from the centre of `cell` ends after -sign * dt * u, in smoke-grid units.
vec3 backtrace(ivec3 cell, float sign) {
    const vec3 step = sign * vec3(params.stepX, params.stepY, params.stepZ);
    const vec3 start = vec3(cell) + 0.5;
    const vec3 mid = start - 0.5 * (velocityAt(start) * step);
    return start - velocityAt(mid) * step;
}

// A masked trilinear sample of (density, temperature) from `in` or `hat`, and the range of
// the fluid cells of its stencil.
struct FluidSample {
    vec2 value;
    vec2 lo;
    vec2 hi;
    bool anyFluid;
};

vec2 fieldsAt(uint cell, bool fromHat) {
    return fromHat ? vec2(densityHat[cell], temperatureHat[cell]) : vec2(densityIn[cell], temperatureIn[cell]);
}

FluidSample sampleFluid(vec3 g, bool fromHat, vec2 fallback) {
    const ivec3 cells = smokeCells();
    AxisStencil s[3];
    for (int a = 0; a < 3; ++a) s[a] = axisStencil(g[a], 0.5, cells[a]);
    const float infinity = uintBitsToFloat(0x7f800000u);
    FluidSample taken = FluidSample(vec2(0.0), vec2(infinity), vec2(-infinity), false);
    vec2 sum = vec2(0.0);
    float weight = 0.0;
    for (int cz = 0; cz <= (s[2].hi != s[2].lo ? 1 : 0); ++cz)
        for (int cy = 0; cy <= (s[1].hi != s[1].lo ? 1 : 0); ++cy)
            for (int cx = 0; cx <= (s[0].hi != s[0].lo ? 1 : 0); ++cx) {
                const uint cell = cellIndex(ivec3(cx != 0 ? s[0].hi : s[0].lo, cy != 0 ? s[1].hi : s[1].lo,
                                                  cz != 0 ? s[2].hi : s[2].lo));
                if (!isFluid(cell)) continue;
                const float w = (cx != 0 ? s[0].f : 1.0 - s[0].f) * (cy != 0 ? s[1].f : 1.0 - s[1].f) *
                                (cz != 0 ? s[2].f : 1.0 - s[2].f);
                const vec2 v = fieldsAt(cell, fromHat);
                sum += w * v;
                weight += w;
                taken.lo = min(taken.lo, v);
                taken.hi = max(taken.hi, v);
                taken.anyFluid = true;
            }
    taken.value = weight > 0.0 ? sum / weight : fallback;
    return taken;
}

// (density, temperature) the emitters add to the cell in one step.
vec2 emitted(ivec3 cell) {
    const vec3 centre = vec3(params.originX, params.originY, params.originZ) +
                        (vec3(cell) + 0.5) * vec3(params.spacingX, params.spacingY, params.spacingZ);
    const int dim = int(params.dim);
    vec2 added = vec2(0.0);
    for (uint e = 0u; e < params.emitterCount; ++e) {
        const SmokeEmitterData emitter = emitters[e];
        bool inside = true;
        if (emitter.shape == SMOKE_EMITTER_BOX) {
            const vec3 lo = vec3(emitter.minX, emitter.minY, emitter.minZ);
            const vec3 hi = vec3(emitter.maxX, emitter.maxY, emitter.maxZ);
            for (int a = 0; a < dim; ++a) inside = inside && centre[a] >= lo[a] && centre[a] <= hi[a];
        } else {
            const vec3 d = centre - vec3(emitter.centreX, emitter.centreY, emitter.centreZ);
            float distance2 = 0.0;
            for (int a = 0; a < dim; ++a) distance2 += d[a] * d[a];
            inside = distance2 <= emitter.radius * emitter.radius;
        }
        if (inside) added += vec2(emitter.densityRate, emitter.temperatureRate) * params.dt;
    }
    return added;
}

void main() {
    const uint id = params.firstCell + gl_GlobalInvocationID.x;
    if (id >= params.cellCount) return;
    const ivec3 cell = ivec3(id % params.cellsX, (id / params.cellsX) % params.cellsY,
                             id / (params.cellsX * params.cellsY));
    const bool fluid = isFluid(id);
    const uint stage = params.stage;

    if (stage == SMOKE_STAGE_MACCORMACK_FORWARD) {
        const vec2 hat = fluid ? sampleFluid(backtrace(cell, 1.0), false, fieldsAt(id, false)).value : vec2(0.0);
        densityHat[id] = hat.x;
        temperatureHat[id] = hat.y;
        return;
    }
    vec2 result = vec2(0.0);
    if (fluid) {
        const vec2 old = fieldsAt(id, false);
        const FluidSample forward = sampleFluid(backtrace(cell, 1.0), false, old);
        if (stage == SMOKE_STAGE_SEMI_LAGRANGIAN) {
            result = forward.value;
        } else {
            const vec2 hat = fieldsAt(id, true);
            const vec2 backward = sampleFluid(backtrace(cell, -1.0), true, hat).value;
            result = forward.anyFluid ? clamp(hat + 0.5 * (old - backward), forward.lo, forward.hi) : hat;
        }
        result += emitted(cell);
    }
    densityOut[id] = result.x;
    temperatureOut[id] = result.y;
}
