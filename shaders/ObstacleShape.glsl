/* ObstacleShape.glsl: what an obstacle record covers (CPU reference MovingObstacle::covers in
   engine/simulation/MovingObstacle.cpp), for obstacle_mismatch.comp and smoke_displace.comp. The
   includer declares the mesh lattices' samples as `float depth[]` (a storage buffer) before
   including it, and includes ObstacleParams.h and FaceLocation.glsl. */
#ifndef MODEFLOW_SHADERS_OBSTACLE_SHAPE_GLSL
#define MODEFLOW_SHADERS_OBSTACLE_SHAPE_GLSL

vec3 v3(float a[3]) { return vec3(a[0], a[1], a[2]); }

// From the obstacle's centre to `point`, at the minimum-image offset along periodic axes of a
// grid `box` long (z dropped in 2D).
vec3 obstacleOffset(ObstacleRecord o, vec3 point, uint dim, vec3 box, uint periodic) {
    vec3 d = point - v3(o.centre);
    if (dim == 2u) d.z = 0.0;
    return minimumImage(d, box, periodic);
}

// Its shape's frame to the world.
mat3 orientationOf(ObstacleRecord o) {
    return mat3(o.orientation[0], o.orientation[1], o.orientation[2], o.orientation[4],
                o.orientation[5], o.orientation[6], o.orientation[8], o.orientation[9],
                o.orientation[10]);
}

// `r`, a world offset from the centre, in the obstacle's own frame (its shape's keys).
vec3 intoShapeFrame(ObstacleRecord o, vec3 r) { return transpose(orientationOf(o)) * r; }

uint latticeSample(ObstacleRecord o, uvec3 i) {
    return i.x + o.latticeSamples[0] * (i.y + o.latticeSamples[1] * i.z);
}

// Whether `p` (in the mesh's frame) lies on its lattice; then its first sample corner `i` and
// the fractions `f` of the trilinear weights (SolidLevelSet's trilinear).
bool onLattice(ObstacleRecord o, vec3 p, out uvec3 i, out vec3 f) {
    const uvec3 samples = uvec3(o.latticeSamples[0], o.latticeSamples[1], o.latticeSamples[2]);
    const vec3 x = (p - v3(o.latticeOrigin)) / o.latticeSpacing;
    i = uvec3(0u);
    f = vec3(0.0);
    if (any(lessThan(x, vec3(0.0))) || any(greaterThan(x, vec3(samples - uvec3(1))))) return false;
    i = min(uvec3(x), samples - uvec3(2));
    f = x - vec3(i);
    return true;
}

vec3 cornerWeights(vec3 f, uint corner, out uvec3 d) {
    d = uvec3(corner & 1u, (corner >> 1u) & 1u, (corner >> 2u) & 1u);
    return mix(vec3(1.0) - f, f, vec3(d));
}

// A mesh's depth (positive inside) at `p` in its own frame: trilinear between the lattice's
// samples, -spacing outside the lattice (SolidLevelSet::depthAt).
float meshDepth(ObstacleRecord o, vec3 p) {
    uvec3 i;
    vec3 f;
    if (!onLattice(o, p, i, f)) return -o.latticeSpacing;
    float sum = 0.0;
    for (uint corner = 0u; corner < 8u; ++corner) {
        uvec3 d;
        const vec3 w = cornerWeights(f, corner, d);
        sum += w.x * w.y * w.z * depth[o.latticeStart + latticeSample(o, i + d)];
    }
    return sum;
}

// A deforming mesh's material velocity at `p` in its own frame, mesh units per unit time
// (SolidLevelSet::velocityAt): trilinear, 0 outside the lattice.
vec3 meshVelocity(ObstacleRecord o, vec3 p) {
    uvec3 i;
    vec3 f;
    if (!onLattice(o, p, i, f)) return vec3(0.0);
    vec3 sum = vec3(0.0);
    for (uint corner = 0u; corner < 8u; ++corner) {
        uvec3 d;
        const vec3 w = cornerWeights(f, corner, d);
        const uint s = o.velocityStart + 3u * latticeSample(o, i + d);
        sum += w.x * w.y * w.z * vec3(depth[s], depth[s + 1u], depth[s + 2u]);
    }
    return sum;
}

// The velocity of the obstacle's material at `r` from its centre (MovingObstacle::velocityOf):
// v + w x r, plus a deforming mesh's own, turned and scaled into the world.
vec3 materialVelocity(ObstacleRecord o, vec3 r) {
    vec3 v = v3(o.velocity) + cross(v3(o.spin), r);
    if (o.velocityStart != OBSTACLE_RIGID)
        v += orientationOf(o) * (o.scale * meshVelocity(o, intoShapeFrame(o, r) / o.scale));
    return v;
}

// Whether the obstacle covers the point `r` from its centre (obstacleOffset).
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

// Whether `r` is within the obstacle's reach (most points are not: the shape's test is skipped).
bool withinReach(ObstacleRecord o, vec3 r) { return dot(r, r) <= o.reach * o.reach; }

#endif
