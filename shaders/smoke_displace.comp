#version 450
// Smoke pushed out of solids, one substep's stage (rule and reasons: engine/simulation/
// SmokeDisplacement.h; CPU reference engine/reference/SmokeDisplacement.cpp; host side
// engine/device/SmokeDisplacement.cpp), the stage a specialization constant:
//   cover:  over the box around the solids (or a box each), one invocation a line of cells
//           along x, each solid tested on the part of the line it may reach: which solid (the
//           first) covers each fluid cell, cover word = stamp << 8 | solid; covered cells holding
//           anything go to a list, once each;
//   args:   one invocation: the indirect dispatch arguments of the lists' stages;
//   push:   over the covered cells' list: each picks the free fluid neighbour most nearly along
//           the solid's material velocity (outward where it is still), stashes its smoke and holds
//           0; the neighbours receiving smoke go to a second list, once each (their target word
//           marked with the stamp by an atomic exchange);
//   gather: over the receivers' list: each adds what its covered neighbours pushed to it, in
//           offset order (the sums do not depend on the lists' order).
//   stash:  over the covered cells' list, after a push: a second pair of fields (fire's fuel and
//           flame) stashed and held 0, bound for the targets the push chose; its gather follows.
// Words carrying another substep's stamp are stale: nothing clears them between substeps. The
// lists' stages loop grid-stride, so lists longer than one dispatch's groups are covered.
#extension GL_GOOGLE_include_directive : require
#include "FaceLocation.glsl"
#include "ObstacleParams.h"
#include "SmokeDisplaceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint stage = SMOKE_DISPLACE_COVER;
layout(constant_id = 2) const uint solidKinds = SOLID_KINDS_ALL;  // ObstacleShape.glsl

layout(set = 0, binding = 0) uniform usamplerBuffer obstacleTexels;  // ten texels a record
layout(set = 0, binding = 1) uniform usamplerBuffer latticeValues;   // one value a texel
layout(set = 0, binding = 2) uniform usamplerBuffer maskWords;  // 4 cells a (R32UI) texel
layout(std430, set = 0, binding = 3) buffer Cover { uint cover[]; };
layout(std430, set = 0, binding = 4) buffer Target { uint target[]; };
layout(std430, set = 0, binding = 5) buffer Fields { vec2 fields[]; };  // (density, temperature)
layout(std430, set = 0, binding = 6) writeonly buffer Temperature { float temperature[]; };
layout(std430, set = 0, binding = 7) buffer Stash { vec2 stash[]; };
// The push and gather dispatches' arguments (x, y, z), then the lists' lengths.
layout(std430, set = 0, binding = 8) buffer Work {
    uint pushGroups[3];
    uint coveredCount;
    uint gatherGroups[3];
    uint receiverCount;
};
layout(std430, set = 0, binding = 9) buffer Covered { uint covered[]; };
layout(std430, set = 0, binding = 10) buffer Receivers { uint receivers[]; };
// The other pair's fields (fire's fuel and flame beside the smoke), else the same pair again.
layout(std430, set = 0, binding = 11) readonly buffer Other { vec2 other[]; };
layout(push_constant) uniform Push { SmokeDisplaceParams params; };
#include "ObstacleShape.glsl"

bool isFluid(uint cell) {
    return ((texelFetch(maskWords, int(cell >> 2u)).x >> ((cell & 3u) * 8u)) & 0xffu) != 0u;
}
bool isCovered(uint cell) { return (cover[cell] >> 8u) == params.stamp; }

ivec3 gridCells() { return ivec3(params.cells[0], params.cells[1], params.cells[2]); }

// `p`, at most one grid length off it, moved onto the grid along periodic axes (MacGrid::wrap).
// Selects, not %: lavapipe runs both sides of a branch and divides lane by lane.
ivec3 wrapped(ivec3 p) {
    const ivec3 n = gridCells();
    for (int a = 0; a < 3; ++a) {
        const bool periodic = (params.periodic & (1u << uint(a))) != 0u;
        p[a] += periodic && p[a] < 0 ? n[a] : (periodic && p[a] >= n[a] ? -n[a] : 0);
    }
    return p;
}

// The cell at `p` (wrapped along periodic axes), or -1 off a walled side.
int cellAt(ivec3 p) {
    const ivec3 n = gridCells();
    p = wrapped(p);
    for (int a = 0; a < 3; ++a)
        if (p[a] < 0 || p[a] >= n[a]) return -1;
    return (p.z * n.y + p.y) * n.x + p.x;
}

// Offset i of pushOffsets(dim): z, then y, then x from -1 to 1, the centre left out.
uint offsetCount() { return params.dim == 3u ? 26u : 8u; }
ivec3 offsetAt(uint i) {
    const uint centre = params.dim == 3u ? 13u : 4u;
    const int j = int(i < centre ? i : i + 1u);
    return ivec3(j % 3 - 1, (j / 3) % 3 - 1, params.dim == 3u ? j / 9 - 1 : 0);
}

vec3 spacing() { return v3(params.spacing); }
vec3 centreOf(ivec3 p) {
    vec3 c = v3(params.origin) + (vec3(p) + 0.5) * spacing();
    if (params.dim == 2u) c.z = 0.0;
    return c;
}
vec3 gridBox() { return vec3(params.cells[0], params.cells[1], params.cells[2]) * spacing(); }

// The cover stage over the box's line of cells along x at box position (y, z): solid by solid,
// last first, over the cells it may cover (lineSpan), each covered fluid cell's word written with
// the solid's number: the first covering solid writes last, and decides, as in the CPU reference.
// A cell is listed when first stamped in the substep (boxes may overlap), if it holds something:
// most covered cells were emptied by earlier substeps, and pushing zeros adds nothing anywhere.
void coverStage(uint y, uint z) {
    const ivec3 lineFirst = ivec3(params.boxFirst[0], params.boxFirst[1] + int(y), params.boxFirst[2] + int(z));
    const int count = int(params.boxCount[0]);
    // Along a periodic x the line may wrap: every cell of it is tested.
    const bool periodicX = (params.periodic & 1u) != 0u;
    for (uint o = params.obstacleCount; o-- > 0u;) {
        const ObstacleRecord solid = obstacleAt(params.firstRecord + o);
        const vec3 r0 = obstacleOffset(solid, centreOf(wrapped(lineFirst)), params.dim, gridBox(), params.periodic);
        const ivec2 span = periodicX ? ivec2(0, count - 1) : lineSpan(solid, r0, params.spacing[0], count);
        const uint word = (params.stamp << 8u) | o;
        for (int x = span.x; x <= span.y; ++x) {
            const ivec3 p = wrapped(lineFirst + ivec3(x, 0, 0));
            const uint cell = uint(cellAt(p));  // the box lies on the grid once wrapped
            if (!isFluid(cell)) continue;
            const vec3 r = obstacleOffset(solid, centreOf(p), params.dim, gridBox(), params.periodic);
            if (dot(r, r) > solid.reach * solid.reach || !covers(solid, r)) continue;
            if ((atomicExchange(cover[cell], word) >> 8u) != params.stamp &&
                (fields[cell] != vec2(0.0) || other[cell] != vec2(0.0)))
                covered[atomicAdd(coveredCount, 1u)] = cell;
        }
    }
}

// A covered cell's values stashed for its target, and held 0.
void stashStage(uint cell) {
    stash[cell] = fields[cell];
    fields[cell] = vec2(0.0);
    temperature[cell] = 0.0;
}

void pushStage(uint cell, ivec3 p) {
    if (!isCovered(cell)) return;
    const ObstacleRecord solid = obstacleAt(params.firstRecord + (cover[cell] & 0xffu));
    const vec3 r = obstacleOffset(solid, centreOf(p), params.dim, gridBox(), params.periodic);
    // The solid's material velocity there in cells, else outward.
    vec3 d = materialVelocity(solid, r) / spacing();
    if (params.dim == 2u) d.z = 0.0;
    if (length(d) * params.dt < 1e-3) d = r / spacing();
    const float len = length(d);
    uint best = SMOKE_DISPLACE_NOWHERE;
    float bestScore = 0.0;
    for (uint i = 0u; i < offsetCount(); ++i) {
        const ivec3 off = offsetAt(i);
        const int n = cellAt(p + off);
        if (n < 0 || !isFluid(uint(n)) || isCovered(uint(n))) continue;
        const float score = len > 0.0 ? dot(vec3(off), d) / (len * length(vec3(off))) : 0.0;
        if (best == SMOKE_DISPLACE_NOWHERE || score > bestScore + 1e-4) {
            best = i;
            bestScore = score;
        }
    }
    target[cell] = (params.stamp << 8u) | best;
    if (best != SMOKE_DISPLACE_NOWHERE) {
        // A free cell's target word is unused (gather reads covered cells' alone): mark it.
        const uint to = uint(cellAt(p + offsetAt(best)));
        const uint mark = (params.stamp << 8u) | SMOKE_DISPLACE_RECEIVES;
        if (atomicExchange(target[to], mark) != mark) receivers[atomicAdd(receiverCount, 1u)] = to;
    }
    stashStage(cell);
}

void gatherStage(uint cell, ivec3 p) {
    if (!isFluid(cell) || isCovered(cell)) return;
    vec2 sum = fields[cell];
    bool received = false;
    for (uint i = 0u; i < offsetCount(); ++i) {
        const int from = cellAt(p - offsetAt(i));
        if (from < 0 || !isCovered(uint(from)) || target[from] != ((params.stamp << 8u) | i))
            continue;
        sum += stash[from];
        received = true;
    }
    if (received) {
        fields[cell] = sum;
        temperature[cell] = sum.y;
    }
}

// Quotients of at most an axis's positions (quotientOf's bound).
ivec3 positionOf(uint cell) {
    const uint plane = params.cells[0] * params.cells[1];
    const uint z = quotientOf(cell, plane), inPlane = cell - z * plane;
    const uint y = quotientOf(inPlane, params.cells[0]);
    return ivec3(int(inPlane - y * params.cells[0]), int(y), int(z));
}

uint groupsFor(uint count) {
    return min((count + gl_WorkGroupSize.x - 1u) / gl_WorkGroupSize.x, params.maxGroups);
}

void main() {
    if (stage == SMOKE_DISPLACE_ARGS) {
        if (gl_GlobalInvocationID.x != 0u) return;
        pushGroups = uint[3](groupsFor(coveredCount), 1u, 1u);
        gatherGroups = uint[3](groupsFor(receiverCount), 1u, 1u);
        return;
    }
    if (stage == SMOKE_DISPLACE_COVER) {
        const uint line = params.firstInvocation + gl_GlobalInvocationID.x;
        if (line >= params.boxLines) return;
        const uint z = quotientOf(line, params.boxCount[1]);
        coverStage(line - z * params.boxCount[1], z);
        return;
    }
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    if (stage == SMOKE_DISPLACE_PUSH) {
        for (uint i = gl_GlobalInvocationID.x; i < coveredCount; i += stride)
            pushStage(covered[i], positionOf(covered[i]));
    } else if (stage == SMOKE_DISPLACE_STASH) {
        for (uint i = gl_GlobalInvocationID.x; i < coveredCount; i += stride)
            stashStage(covered[i]);
    } else {
        for (uint i = gl_GlobalInvocationID.x; i < receiverCount; i += stride)
            gatherStage(receivers[i], positionOf(receivers[i]));
    }
}
