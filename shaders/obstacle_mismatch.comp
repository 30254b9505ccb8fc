#version 450
// Moving obstacles (seed section 6.3.5; CPU reference engine/simulation/MovingObstacle.cpp): on
// every velocity DOF face whose centre an obstacle covers (in its turned frame), the fluid's face
// velocity minus the velocity of the obstacle's material there (v + w x r) along the face normal,
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

vec3 v3(float a[3]) { return vec3(a[0], a[1], a[2]); }

// From the obstacle's centre to `point`, at the minimum-image offset along periodic axes.
vec3 offset(ObstacleRecord o, vec3 point) {
    vec3 d = point - v3(o.centre);
    if (params.dim == 2u) d.z = 0.0;
    const vec3 box = vec3(params.cells[0], params.cells[1], params.cells[2]) * v3(params.spacing);
    return minimumImage(d, box, params.periodic);
}

// `r`, a world offset from the centre, in the obstacle's own frame (its shape's keys).
vec3 intoShapeFrame(ObstacleRecord o, vec3 r) {
    const mat3 orientation = mat3(o.orientation[0], o.orientation[1], o.orientation[2],
                                  o.orientation[4], o.orientation[5], o.orientation[6],
                                  o.orientation[8], o.orientation[9], o.orientation[10]);
    return transpose(orientation) * r;
}

float latticeDepth(ObstacleRecord o, uvec3 i) {
    return depth[o.latticeStart + i.x + o.latticeSamples[0] * (i.y + o.latticeSamples[1] * i.z)];
}

// A mesh's depth (positive inside) at `p` in its own frame: trilinear between the lattice's
// samples, -spacing outside the lattice (SolidLevelSet::depthAt).
float meshDepth(ObstacleRecord o, vec3 p) {
    const uvec3 samples = uvec3(o.latticeSamples[0], o.latticeSamples[1], o.latticeSamples[2]);
    const vec3 x = (p - v3(o.latticeOrigin)) / o.latticeSpacing;
    if (any(lessThan(x, vec3(0.0))) || any(greaterThan(x, vec3(samples - uvec3(1)))))
        return -o.latticeSpacing;
    const uvec3 i = min(uvec3(x), samples - uvec3(2));
    const vec3 f = x - vec3(i);
    float sum = 0.0;
    for (uint corner = 0u; corner < 8u; ++corner) {
        const uvec3 d = uvec3(corner & 1u, (corner >> 1u) & 1u, (corner >> 2u) & 1u);
        const vec3 w = mix(vec3(1.0) - f, f, vec3(d));
        sum += w.x * w.y * w.z * latticeDepth(o, i + d);
    }
    return sum;
}

bool covers(ObstacleRecord o, vec3 r) {
    vec3 d = intoShapeFrame(o, r);
    if (o.shape == OBSTACLE_MESH) return meshDepth(o, d / o.scale) >= 0.0;
    if (o.shape == OBSTACLE_BOX) return all(lessThanEqual(abs(d), v3(o.halfSize)));
    if (o.shape == OBSTACLE_CAPSULE) {
        const vec3 axis = v3(o.axis);
        const float length2 = dot(axis, axis);
        d -= (length2 > 0.0 ? clamp(dot(d, axis) / length2, -1.0, 1.0) : 0.0) * axis;
    }
    return dot(d, d) <= o.radius * o.radius;
}

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
        float value = 0.0;
        for (uint o = 0; o < params.obstacleCount; ++o) {
            const vec3 r = offset(obstacles[o], centre);
            // Most faces lie far from every obstacle: skip the shape's test there.
            if (dot(r, r) > obstacles[o].reach * obstacles[o].reach) continue;
            if (covers(obstacles[o], r)) {
                // The solid's material velocity there: v + ω × r.
                const vec3 solid = v3(obstacles[o].velocity) + cross(v3(obstacles[o].spin), r);
                value = velocity[face] - solid[axis];
                break;
            }
        }
        mismatch[face] = value;
    }
}
