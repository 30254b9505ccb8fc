#version 450
// Moving obstacles (seed section 6.3.5; CPU reference engine/simulation/MovingObstacle.cpp): on
// every velocity DOF face whose centre an obstacle covers (in its turned frame), the fluid's face
// velocity minus the velocity of the obstacle's material there (v + w x r, and a deforming mesh's
// own) along the face normal,
// written into a face field of the whole grid (other faces keep the 0 they were created with).
// project_force.comp then projects it on the basis (face-field weights: the exact inverse of the
// reconstruction) and modal_correct.comp subtracts the result from v. One invocation per DOF,
// grid-stride; the first covering obstacle decides. Along periodic axes an obstacle covers at the
// minimum-image offset (it reaches over the seam).
#extension GL_GOOGLE_include_directive : require
#include "FaceLocation.glsl"
#include "ObstacleParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Faces { uint faces[]; };
layout(std430, set = 0, binding = 1) readonly buffer Velocity { float velocity[]; };
layout(std430, set = 0, binding = 2) readonly buffer Obstacles { ObstacleRecord obstacles[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Mismatch { float mismatch[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lattices { float depth[]; };
layout(push_constant) uniform Push { ObstacleMismatchParams params; };
#include "ObstacleShape.glsl"

void main() {
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    const uvec3 cells = uvec3(params.cells[0], params.cells[1], params.cells[2]);
    for (uint dof = gl_GlobalInvocationID.x; dof < params.dofCount; dof += stride) {
        const uint face = faces[dof];
        const uint axis = faceAxis(face, params.faceStart1, params.faceStart2);
        const uint start = axis == 0u ? 0u : (axis == 1u ? params.faceStart1 : params.faceStart2);
        const uvec3 position = facePosition(face - start, axis, cells, params.periodic);
        vec3 centre = v3(params.origin) + (vec3(position) + vec3(0.5)) * v3(params.spacing);
        centre[axis] -= 0.5 * params.spacing[axis];
        if (params.dim == 2u) centre.z = 0.0;
        const vec3 box = vec3(cells) * v3(params.spacing);
        float value = 0.0;
        for (uint o = 0; o < params.obstacleCount; ++o) {
            const vec3 r = obstacleOffset(obstacles[o], centre, params.dim, box, params.periodic);
            if (!withinReach(obstacles[o], r)) continue;
            if (covers(obstacles[o], r)) {
                const vec3 solid = materialVelocity(obstacles[o], r);
                value = velocity[face] - solid[axis];
                break;
            }
        }
        mismatch[face] = value;
    }
}
