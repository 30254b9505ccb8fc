#version 450
// Moving obstacles (seed section 6.3.5; CPU reference engine/simulation/MovingObstacle.cpp): on
// every velocity DOF face whose centre an obstacle covers (in its turned frame), the fluid's face
// velocity minus the velocity of the obstacle's material there (v + w x r, and a deforming mesh's
// own) along the face normal,
// written at the face's DOF (DOF order, filled with 0 before; faces that are not DOFs are
// skipped). The projection (project_force.comp or the separable passes, face-field weights: the
// exact inverse of the reconstruction) reads it as it is, with no gather over the whole grid,
// and modal_correct.comp subtracts the result from v. One invocation per face
// of the box of cells around the regions (the host's ObstacleCorrection: no face beyond it is in
// any region's reach), faces that are no DOF (walls) skipped; the first covering obstacle decides. Along periodic
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

void main() {
    uint local = params.first + gl_GlobalInvocationID.x;
    uint axis = 0u;
    while (axis < 2u && local >= params.boxFaces[axis]) local -= params.boxFaces[axis++];
    if (local >= params.boxFaces[axis]) return;
    const uvec3 count = uvec3(params.boxCount[3u * axis], params.boxCount[3u * axis + 1u],
                              params.boxCount[3u * axis + 2u]);
    const uint z = quotientOf(local, count.x * count.y), inPlane = local - z * count.x * count.y;
    const uint y = quotientOf(inPlane, count.x);
    ivec3 p = ivec3(params.boxFirst[0], params.boxFirst[1], params.boxFirst[2]) +
              ivec3(uvec3(inPlane - y * count.x, y, z));
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    // The box starts on the grid and is at most a grid long: one length back along periodic
    // axes at most (a select: lavapipe runs both sides of a branch and divides lane by lane).
    for (uint a = 0u; a < 3u; ++a)
        p[a] -= (params.periodic & (1u << a)) != 0u && p[a] >= int(cells[a]) ? int(cells[a]) : 0;
    // A side's faces are DOFs where it is open (a jet through it); walls are none.
    const bool periodicAxis = (params.periodic & (1u << axis)) != 0u;
    uvec3 extent = cells;
    if (!periodicAxis) extent[axis] += 1u;
    const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
    const uint face = start + (uint(p.z) * extent.y + uint(p.y)) * extent.x + uint(p.x);
    const uint dof = texelFetch(dofOfFace, int(face)).x;
    if (dof == OBSTACLE_NO_DOF) return;
    vec3 centre = v3(params.origin) + (vec3(p) + vec3(0.5)) * v3(params.spacing);
    centre[axis] -= 0.5 * params.spacing[axis];
    if (params.dim == 2u) centre.z = 0.0;
    const vec3 box = vec3(cells) * v3(params.spacing);
    float value = 0.0;
    for (uint o = 0; o < params.obstacleCount; ++o) {
        vec3 r;
        if (!withinReachOf(o, centre, params.dim, box, params.periodic, r)) continue;
        const ObstacleRecord record = obstacleAt(o);
        if (covers(record, r)) {
            const vec3 solid = materialVelocity(record, r);
            value = uintBitsToFloat(texelFetch(velocity, int(face)).x) - solid[axis];
            break;
        }
    }
    mismatch[dof] = value;
}
