#version 450
// Moving obstacles (seed section 6.3.5; CPU reference engine/simulation/MovingObstacle.cpp): on
// every velocity DOF face whose centre an obstacle covers (in its turned frame), the fluid's face
// velocity minus the velocity of the obstacle's material there (v + w x r, and a deforming mesh's
// own) along the face normal,
// written at the face's DOF (DOF order, filled with 0 before; faces that are not DOFs are
// skipped). The projection (project_force.comp or the separable passes, face-field weights: the
// exact inverse of the reconstruction) reads it as it is, with no gather over the whole grid,
// and modal_correct.comp subtracts the result from v. One invocation per run of
// OBSTACLE_MISMATCH_FACES_PER_INVOCATION faces along one normal axis of the box of cells around
// the regions (the host's ObstacleCorrection: no face beyond it is in any region's reach), faces
// that are no DOF (walls) skipped; the first covering obstacle decides. Along periodic
// axes an obstacle covers at the minimum-image offset (it reaches over the seam), and the box
// wraps.
#extension GL_GOOGLE_include_directive : require
#include "FaceLocation.glsl"
#include "ObstacleParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;
layout(constant_id = 1) const uint solidKinds = SOLID_KINDS_ALL;  // ObstacleShape.glsl

// Read-only inputs as texels (ObstacleShape.glsl says why).
layout(set = 0, binding = 0) uniform usamplerBuffer velocity;        // the face field, R32UI
layout(set = 0, binding = 1) uniform usamplerBuffer obstacleTexels;  // ten texels a record
layout(std430, set = 0, binding = 2) writeonly buffer Mismatch { float mismatch[]; };  // DOF order
layout(set = 0, binding = 3) uniform usamplerBuffer latticeValues;   // one value a texel
layout(set = 0, binding = 4) uniform usamplerBuffer dofOfFace;       // OBSTACLE_NO_DOF: none
layout(push_constant) uniform Push { ObstacleMismatchParams params; };
#include "ObstacleShape.glsl"

// The invocations' runs of faces along one normal axis's part of the box.
uint runsOf(uint axis) {
    return (params.boxFaces[axis] + OBSTACLE_MISMATCH_FACES_PER_INVOCATION - 1u) /
           OBSTACLE_MISMATCH_FACES_PER_INVOCATION;
}

void main() {
    uint run = params.first + gl_GlobalInvocationID.x;
    uint axis = 0u;
    while (axis < 2u && run >= runsOf(axis)) run -= runsOf(axis++);
    if (run >= runsOf(axis)) return;
    const uint first = OBSTACLE_MISMATCH_FACES_PER_INVOCATION * run;
    const uint count = min(OBSTACLE_MISMATCH_FACES_PER_INVOCATION, params.boxFaces[axis] - first);
    const uvec3 boxCount = uvec3(params.boxCount[3u * axis], params.boxCount[3u * axis + 1u],
                                 params.boxCount[3u * axis + 2u]);
    // The first face's place in the box, the next ones' by counting on (integer division is a
    // loop over the lanes on lavapipe).
    const uint z = quotientOf(first, boxCount.x * boxCount.y), inPlane = first - z * boxCount.x * boxCount.y;
    const uint y = quotientOf(inPlane, boxCount.x);
    uvec3 b = uvec3(inPlane - y * boxCount.x, y, z);
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    // A side's faces are DOFs where it is open (a jet through it); walls are none.
    uvec3 extent = cells;
    if ((params.periodic & (1u << axis)) == 0u) extent[axis] += 1u;
    const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
    const vec3 box = vec3(cells) * v3(params.spacing);
    uint face[OBSTACLE_MISMATCH_FACES_PER_INVOCATION];
    uint dof[OBSTACLE_MISMATCH_FACES_PER_INVOCATION];
    vec3 centre[OBSTACLE_MISMATCH_FACES_PER_INVOCATION];
    float value[OBSTACLE_MISMATCH_FACES_PER_INVOCATION];
    uint open = 0u;  // bit i: face i is a DOF no earlier obstacle covers
    for (uint i = 0u; i < OBSTACLE_MISMATCH_FACES_PER_INVOCATION; ++i) {
        ivec3 p = ivec3(params.boxFirst[0], params.boxFirst[1], params.boxFirst[2]) + ivec3(b);
        // The box starts on the grid and is at most a grid long: one length back along
        // periodic axes at most (a select: lavapipe runs both sides of a branch).
        for (uint a = 0u; a < 3u; ++a)
            p[a] -= (params.periodic & (1u << a)) != 0u && p[a] >= int(cells[a]) ? int(cells[a]) : 0;
        face[i] = start + (uint(p.z) * extent.y + uint(p.y)) * extent.x + uint(p.x);
        dof[i] = i < count ? texelFetch(dofOfFace, int(face[i])).x : OBSTACLE_NO_DOF;
        if (dof[i] != OBSTACLE_NO_DOF) open |= 1u << i;
        centre[i] = v3(params.origin) + (vec3(p) + vec3(0.5)) * v3(params.spacing);
        centre[i][axis] -= 0.5 * params.spacing[axis];
        if (params.dim == 2u) centre[i].z = 0.0;
        value[i] = 0.0;
        if (++b.x == boxCount.x) {
            b.x = 0u;
            if (++b.y == boxCount.y) {
                b.y = 0u;
                ++b.z;
            }
        }
    }
    // Obstacle by obstacle, its record read once for the run (every lane reads all of it
    // whichever branch it takes: per face it cost as much as the test); the first covering
    // obstacle decides.
    for (uint o = 0u; o < params.obstacleCount; ++o) {
        const ObstacleRecord record = obstacleAt(o);
        for (uint i = 0u; i < OBSTACLE_MISMATCH_FACES_PER_INVOCATION; ++i) {
            if ((open & (1u << i)) == 0u) continue;
            const vec3 r = obstacleOffset(record, centre[i], params.dim, box, params.periodic);
            if (dot(r, r) > record.reach * record.reach || !covers(record, r)) continue;
            open &= ~(1u << i);
            const vec3 solid = materialVelocity(record, r);
            value[i] = uintBitsToFloat(texelFetch(velocity, int(face[i])).x) - solid[axis];
        }
    }
    for (uint i = 0u; i < OBSTACLE_MISMATCH_FACES_PER_INVOCATION; ++i)
        if (dof[i] != OBSTACLE_NO_DOF) mismatch[dof[i]] = value[i];
}
