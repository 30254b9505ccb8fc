/* ParticleStep.glsl: one step of every particle (the rule: engine/simulation/ParticleMotion.h;
   CPU reference engine/reference/ParticleAdvection.cpp; host side
   engine/device/ParticleAdvection.cpp), in stages (a specialization constant):
     move:   one invocation a particle: carried by the air; a particle then within reach of a
             solid is stored as it is, with its start, and listed as near; the others are
             finished (open sides, the box, sliding along walls);
     args:   one invocation: the next stage's indirect dispatch arguments;
     near:   over the near list: a particle some solid covers is listed as inside, the others
             finished;
     inside: over the inside list: pushed out of the solids, in order, then finished.
   lavapipe runs both sides of every branch: with the solids in the move stage every particle
   paid for the cover test and the mesh exit's Newton steps, which only the few near a solid,
   and fewer in one, need.
   The includer defines MAC_DIM (2 or 3). The velocity is the basis grid's face field as
   x-neighbour pairs (smoke_face_pairs.comp, written by the step's smoke advection from the same
   velocity). */
#include "FaceLocation.glsl"
#include "ObstacleParams.h"
#include "ParticleStepParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint solidKinds = SOLID_KINDS_ALL;  // ObstacleShape.glsl
layout(constant_id = 2) const uint stage = PARTICLE_STEP_MOVE;

layout(set = 0, binding = 0) uniform usamplerBuffer obstacleTexels;  // ten texels a record
layout(set = 0, binding = 1) uniform usamplerBuffer latticeValues;   // one value a texel
layout(set = 0, binding = 2) uniform usamplerBuffer maskWords;  // 4 cells a (R32UI) texel
layout(set = 0, binding = 3) uniform usamplerBuffer facePairs;  // one pair a word texel
layout(std430, set = 0, binding = 4) buffer Positions { vec4 positions[]; };  // xyz, w: set
layout(std430, set = 0, binding = 5) buffer Velocities { vec4 velocities[]; };
layout(std430, set = 0, binding = 6) readonly buffer Sets { ParticleSetRecord sets[]; };
// The near and inside stages' dispatch arguments (x, y, z), each followed by its list's length.
layout(std430, set = 0, binding = 7) buffer Work {
    uint nearGroups[3];
    uint nearCount;
    uint insideGroups[3];
    uint insideCount;
};
layout(std430, set = 0, binding = 8) buffer Near { uint near[]; };  // particles near a solid
layout(std430, set = 0, binding = 9) buffer Starts { vec4 starts[]; };  // their starting points
layout(std430, set = 0, binding = 10) buffer Inside { uint inside[]; };  // their near slots
layout(push_constant) uniform Push { ParticleStepParams params; };

vec2 macFacePair(uint face) { return uintBitsToFloat(texelFetch(facePairs, int(face)).xy); }
#include "MacSampling.glsl"
#include "ObstacleShape.glsl"

vec3 velocityAt(vec3 world) {
    vec3 g = (world - v3(params.origin)) / v3(params.spacing);
    if (MAC_DIM == 2) g.z = 0.5;
    const ivec3 cells = ivec3(params.cells[0], params.cells[1], params.cells[2]);
    const uvec3 offsets = uvec3(params.faceStart[0], params.faceStart[1], params.faceStart[2]);
    return sampleVelocityGrid(g, cells, offsets, params.boundary);
}

vec3 boxLength() {
    return vec3(params.cells[0], params.cells[1], params.cells[2]) * v3(params.spacing);
}

// inFluidCell (engine/simulation/ParticleEmission.cpp).
bool inFluid(vec3 p) {
    ivec3 c = ivec3(0);
    for (int a = 0; a < MAC_DIM; ++a) {
        const float x = (p[a] - params.origin[a]) / params.smokeSpacing[a];
        const float n = float(params.smokeCells[a]);
        const float cell = isPeriodic(params.boundary, a) ? x - n * floor(x / n) : clamp(x, 0.0, n - 1.0);
        c[a] = min(int(cell), int(params.smokeCells[a]) - 1);
    }
    const uint index = (uint(c.z) * params.smokeCells[1] + uint(c.y)) * params.smokeCells[0] + uint(c.x);
    return ((texelFetch(maskWords, int(index >> 2u)).x >> ((index & 3u) * 8u)) & 0xffu) != 0u;
}

// Beyond a side the air crosses (open, or a wind's) the particle leaves the run
// (engine/simulation/ParticleMotion.h).
bool beyondOpenSide(vec3 p) {
    const vec3 lo = v3(params.origin), hi = lo + boxLength();
    bool beyond = false;
    for (int a = 0; a < MAC_DIM; ++a) {
        beyond = beyond || (p[a] < lo[a] && (params.openSides & (1u << uint(2 * a))) != 0u);
        beyond = beyond || (p[a] > hi[a] && (params.openSides & (2u << uint(2 * a))) != 0u);
    }
    return beyond;
}

vec3 intoBox(vec3 p) {
    const vec3 lo = v3(params.origin), len = boxLength();
    for (int a = 0; a < MAC_DIM; ++a)
        p[a] = isPeriodic(params.boundary, a) ? lo[a] + (p[a] - lo[a]) - len[a] * floor((p[a] - lo[a]) / len[a])
                                              : clamp(p[a], lo[a], lo[a] + len[a]);
    return p;
}

// Whether `p` is within reach of any solid (two texels a solid).
bool nearSolid(vec3 p) {
    bool near = false;
    for (uint o = 0u; o < params.obstacleCount; ++o) {
        vec3 r;
        near = withinReachOf(o, p, uint(MAC_DIM), boxLength(), params.boundary, r) || near;
    }
    return near;
}

// Particle i, from x0, at x1 with velocity v1 after the air and the solids: beyond an open side
// it leaves the run; else it is kept in the box and, where it would end in a solid cell, slides
// along the walls from x0.
void finish(uint i, vec3 x0, vec3 x1, vec3 v1, ParticleSetRecord r, float setBits) {
    if (beyondOpenSide(x1)) {
        const float left = uintBitsToFloat(0x7fc00000u);  // a quiet NaN, kParticleLeft
        positions[i] = vec4(left, left, left, setBits);
        velocities[i] = vec4(0.0);
        return;
    }
    x1 = intoBox(x1);
    if (params.allFluid == 0u && !inFluid(x1)) {
        vec3 slid = x0;
        for (int a = 0; a < MAC_DIM; ++a) {
            const float held = slid[a];
            slid[a] = x1[a];
            if (!inFluid(slid)) {
                slid[a] = held;
                if (r.inertial != 0u) v1[a] = 0.0;
            }
        }
        x1 = slid;
    }
    positions[i] = vec4(x1, setBits);
    velocities[i] = vec4(v1, 0.0);
}

void moveStage(uint i) {
    const vec4 stored = positions[i];
    if (isnan(stored.x)) return;  // it left through an open side
    const vec3 x0 = stored.xyz;
    const vec3 v0 = velocities[i].xyz;
    const ParticleSetRecord r = sets[floatBitsToUint(stored.w)];
    const float dt = params.dt;
    // A tracer steps as an inertial particle that takes the air's velocity at once (decay = reach
    // = fall = 0) whose predictor is the air's velocity rather than its own: the two kinds share
    // their samples, since lavapipe runs both sides of a branch (two samples, not three).
    const bool tracer = r.inertial == 0u;
    const vec3 ahead = tracer ? velocityAt(x0) : v0;
    vec3 terminal = velocityAt(x0 + 0.5 * dt * ahead);
    terminal[params.up] -= tracer ? 0.0 : r.fall;
    const vec3 lag = v0 - terminal;
    const vec3 x1 = x0 + dt * terminal + lag * (tracer ? 0.0 : r.reach);
    const vec3 v1 = terminal + lag * (tracer ? 0.0 : r.decay);
    // Away from every solid no push happens (a push needs a solid that reaches the point).
    if (!nearSolid(x1)) {
        finish(i, x0, x1, v1, r, stored.w);
        return;
    }
    const uint slot = atomicAdd(nearCount, 1u);
    near[slot] = i;
    starts[slot] = vec4(x0, 0.0);
    positions[i] = vec4(x1, stored.w);
    velocities[i] = vec4(v1, 0.0);
}

// A near particle (its slot in the near list) some solid covers is listed as inside; the
// others are finished where the air took them.
void nearStage(uint slot) {
    const uint i = near[slot];
    const vec4 stored = positions[i];
    const vec3 x1 = stored.xyz;
    bool covered = false;
    for (uint o = 0u; o < params.obstacleCount; ++o) {
        vec3 r0;
        if (withinReachOf(o, x1, uint(MAC_DIM), boxLength(), params.boundary, r0))
            covered = covers(obstacleAt(o), r0) || covered;
    }
    // Covered by none, no solid pushes it (each push starts from a solid covering it).
    if (covered)
        inside[atomicAdd(insideCount, 1u)] = slot;
    else
        finish(i, starts[slot].xyz, x1, velocities[i].xyz, sets[floatBitsToUint(stored.w)], stored.w);
}

// A particle inside a solid (its slot in the near list) pushed out of each solid covering it,
// in order, then finished.
void insideStage(uint slot) {
    const uint i = near[slot];
    const vec4 stored = positions[i];
    vec3 x1 = stored.xyz;
    vec3 v1 = velocities[i].xyz;
    const ParticleSetRecord r = sets[floatBitsToUint(stored.w)];
    const uint dim = uint(MAC_DIM);
    for (uint o = 0u; o < params.obstacleCount; ++o) {
        vec3 r0;
        if (!withinReachOf(o, x1, dim, boxLength(), params.boundary, r0)) continue;
        const ObstacleRecord solid = obstacleAt(o);
        if (!covers(solid, r0)) continue;
        vec3 normal;
        x1 += solidExit(solid, r0, dim, params.margin, normal);
        if (dim == 2u) x1.z = 0.0;
        if (r.inertial == 0u) continue;
        const vec3 r1 = obstacleOffset(solid, x1, dim, boxLength(), params.boundary);
        const float into = dot(v1 - materialVelocity(solid, r1), normal);
        if (into < 0.0) v1 -= into * normal;
    }
    finish(i, starts[slot].xyz, x1, v1, r, stored.w);
}

uint groupsFor(uint count) {
    return min((count + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x, params.maxGroups);
}

void main() {
    if (stage == PARTICLE_STEP_ARGS) {
        if (gl_GlobalInvocationID.x == 0u) {
            nearGroups = uint[3](groupsFor(nearCount), 1u, 1u);
            insideGroups = uint[3](groupsFor(insideCount), 1u, 1u);
        }
        return;
    }
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    if (stage == PARTICLE_STEP_NEAR) {
        for (uint k = gl_GlobalInvocationID.x; k < nearCount; k += stride) nearStage(k);
        return;
    }
    if (stage == PARTICLE_STEP_INSIDE) {
        for (uint k = gl_GlobalInvocationID.x; k < insideCount; k += stride) insideStage(inside[k]);
        return;
    }
    const uint i = params.first + gl_GlobalInvocationID.x;
    if (i < params.count) moveStage(i);
}
