#version 450
// Moving obstacles (seed section 6.3.5; CPU reference engine/simulation/MovingObstacle.cpp): on
// every velocity DOF face whose centre an obstacle covers (in its turned frame), the fluid's face
// velocity minus the velocity of the obstacle's material there (v + w x r, and a deforming mesh's
// own) along the face normal,
// written at the face's DOF (DOF order, filled with 0 before; faces that are not DOFs are
// skipped). The projection (project_force.comp or the separable passes, face-field weights: the
// exact inverse of the reconstruction) reads it as it is, with no gather over the whole grid,
// and modal_correct.comp subtracts the result from v. One invocation per line of faces
// along x, for each normal axis, of the box of cells around the regions (the host's
// ObstacleCorrection: no face beyond it is in any region's reach), each region tested on the part
// of the line it may cover (lineSpan), faces that are no DOF (walls) skipped; the first covering obstacle decides. Along periodic
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

// The centre of the normal-`axis` face at the low side of cell `p`.
vec3 faceCentre(ivec3 p, uint axis) {
    vec3 c = v3(params.origin) + (vec3(p) + vec3(0.5)) * v3(params.spacing);
    c[axis] -= 0.5 * params.spacing[axis];
    if (params.dim == 2u) c.z = 0.0;
    return c;
}

void main() {
    uint line = params.first + gl_GlobalInvocationID.x;
    uint axis = 0u;
    while (axis < 2u && line >= params.boxLines[axis]) line -= params.boxLines[axis++];
    if (line >= params.boxLines[axis]) return;
    const uint z = quotientOf(line, params.boxCount[3u * axis + 1u]);
    const uint y = line - z * params.boxCount[3u * axis + 1u];
    const int count = int(params.boxCount[3u * axis]);
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    // A side's faces are DOFs where it is open (a jet through it); walls are none.
    uvec3 extent = cells;
    if ((params.periodic & (1u << axis)) == 0u) extent[axis] += 1u;
    const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
    const vec3 box = vec3(cells) * v3(params.spacing);
    const ivec3 lineFirst = ivec3(params.boxFirst[0], params.boxFirst[1] + int(y), params.boxFirst[2] + int(z));
    // Along a periodic x the line may wrap: every face of it is tested.
    const bool periodicX = (params.periodic & 1u) != 0u;
    // Obstacle by obstacle, last first, over the faces it may cover (lineSpan): the first
    // covering obstacle's value is written last, and stands.
    for (uint o = params.obstacleCount; o-- > 0u;) {
        const ObstacleRecord record = obstacleAt(o);
        ivec2 span = ivec2(0, count - 1);
        if (!periodicX)
            span = lineSpan(record, obstacleOffset(record, faceCentre(lineFirst, axis), params.dim, box, params.periodic),
                            params.spacing[0], count);
        for (int x = span.x; x <= span.y; ++x) {
            ivec3 p = lineFirst + ivec3(x, 0, 0);
            // The box starts on the grid and is at most a grid long: one length back along
            // periodic axes at most (a select: lavapipe runs both sides of a branch).
            for (uint a = 0u; a < 3u; ++a)
                p[a] -= (params.periodic & (1u << a)) != 0u && p[a] >= int(cells[a]) ? int(cells[a]) : 0;
            const uint face = start + (uint(p.z) * extent.y + uint(p.y)) * extent.x + uint(p.x);
            const uint dof = texelFetch(dofOfFace, int(face)).x;
            if (dof == OBSTACLE_NO_DOF) continue;
            const vec3 r = obstacleOffset(record, faceCentre(p, axis), params.dim, box, params.periodic);
            if (dot(r, r) > record.reach * record.reach || !covers(record, r)) continue;
            const vec3 solid = materialVelocity(record, r);
            mismatch[dof] = uintBitsToFloat(texelFetch(velocity, int(face)).x) - solid[axis];
        }
    }
}
