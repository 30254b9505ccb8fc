#version 450
// Smoke pushed out of solids, one substep's stage (rule and reasons: engine/simulation/
// SmokeDisplacement.h; CPU reference engine/reference/SmokeDisplacement.cpp; host side
// engine/device/SmokeDisplacement.cpp). One invocation per cell of the box around the solids,
// the stage a specialization constant:
//   cover:  which solid (the first) covers each fluid cell: cover word = stamp << 8 | solid;
//   push:   each covered cell picks the free fluid neighbour most nearly along the solid's
//           material velocity (outward where it is still), stashes its smoke and holds 0;
//   gather: each free fluid cell adds what its covered neighbours pushed to it, in offset order.
// Words carrying another substep's stamp are stale: nothing clears them between substeps.
#extension GL_GOOGLE_include_directive : require
#include "FaceLocation.glsl"
#include "ObstacleParams.h"
#include "SmokeDisplaceParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint stage = SMOKE_DISPLACE_COVER;

layout(std430, set = 0, binding = 0) readonly buffer Obstacles { ObstacleRecord obstacles[]; };
layout(std430, set = 0, binding = 1) readonly buffer Lattices { float depth[]; };
layout(std430, set = 0, binding = 2) readonly buffer Mask { uint mask[]; };  // 4 cells a word
layout(std430, set = 0, binding = 3) buffer Cover { uint cover[]; };
layout(std430, set = 0, binding = 4) buffer Target { uint target[]; };
layout(std430, set = 0, binding = 5) buffer Fields { vec2 fields[]; };  // (density, temperature)
layout(std430, set = 0, binding = 6) writeonly buffer Temperature { float temperature[]; };
layout(std430, set = 0, binding = 7) buffer Stash { vec2 stash[]; };
layout(push_constant) uniform Push { SmokeDisplaceParams params; };
#include "ObstacleShape.glsl"

bool isFluid(uint cell) { return ((mask[cell >> 2u] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }
bool isCovered(uint cell) { return (cover[cell] >> 8u) == params.stamp; }

ivec3 gridCells() { return ivec3(params.cells[0], params.cells[1], params.cells[2]); }

// `p` moved onto the grid along periodic axes (MacGrid::wrap).
ivec3 wrapped(ivec3 p) {
    const ivec3 n = gridCells();
    for (int a = 0; a < 3; ++a)
        if ((params.periodic & (1u << uint(a))) != 0u) p[a] = ((p[a] % n[a]) + n[a]) % n[a];
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

void coverStage(uint cell, ivec3 p) {
    if (!isFluid(cell)) return;
    const vec3 centre = centreOf(p);
    for (uint o = 0u; o < params.obstacleCount; ++o) {
        const ObstacleRecord solid = obstacles[params.firstRecord + o];
        const vec3 r = obstacleOffset(solid, centre, params.dim, gridBox(), params.periodic);
        if (!withinReach(solid, r)) continue;
        if (covers(solid, r)) {
            cover[cell] = (params.stamp << 8u) | o;
            return;
        }
    }
}

void pushStage(uint cell, ivec3 p) {
    if (!isCovered(cell)) return;
    const ObstacleRecord solid = obstacles[params.firstRecord + (cover[cell] & 0xffu)];
    const vec3 r = obstacleOffset(solid, centreOf(p), params.dim, gridBox(), params.periodic);
    // The solid's material velocity there (v + w x r) in cells, else outward.
    vec3 d = (v3(solid.velocity) + cross(v3(solid.spin), r)) / spacing();
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
    stash[cell] = fields[cell];
    fields[cell] = vec2(0.0);
    temperature[cell] = 0.0;
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

void main() {
    const uint i = params.firstInvocation + gl_GlobalInvocationID.x;
    if (i >= params.boxCells) return;
    const uint x = i % params.boxCount[0], rest = i / params.boxCount[0];
    const uint y = rest % params.boxCount[1], z = rest / params.boxCount[1];
    const ivec3 p = wrapped(ivec3(params.boxFirst[0] + int(x), params.boxFirst[1] + int(y),
                                  params.boxFirst[2] + int(z)));
    const uint cell = uint(cellAt(p));  // the box lies on the grid once wrapped
    if (stage == SMOKE_DISPLACE_COVER)
        coverStage(cell, p);
    else if (stage == SMOKE_DISPLACE_PUSH)
        pushStage(cell, p);
    else
        gatherStage(cell, p);
}
