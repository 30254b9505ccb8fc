/* ObstacleShape.glsl: what an obstacle record covers (CPU reference MovingObstacle::covers in
   engine/simulation/MovingObstacle.cpp), for obstacle_mismatch.comp, smoke_displace.comp and
   ParticleStep.glsl. The includer binds the records as `usamplerBuffer obstacleTexels` (RGBA32UI
   texels, ten a record) and the mesh lattices' samples as `usamplerBuffer latticeValues` (R32UI,
   one a texel) and declares `solidKinds`, its last specialization constant (the kinds of solid
   its run holds, engine/device/SolidKernels.h: absent kinds' code folds away), before including
   it, and includes ObstacleParams.h and FaceLocation.glsl.

   Texels, not storage buffers: on lavapipe a storage-buffer read is a scalar load per lane and
   component, a texel fetch one vector gather (shaders/TexelAccess.glsl), and every lane reads a
   whole record and eight lattice samples per test whichever shape and branch it takes. */
#ifndef MODEFLOW_SHADERS_OBSTACLE_SHAPE_GLSL
#define MODEFLOW_SHADERS_OBSTACLE_SHAPE_GLSL

vec3 v3(float a[3]) { return vec3(a[0], a[1], a[2]); }

bool mayHold(uint kinds) { return (solidKinds & kinds) != 0u; }
bool mayHoldShape(uint shape) { return mayHold(1u << shape); }

vec4 obstacleTexel(uint index, int texel) {
    return uintBitsToFloat(texelFetch(obstacleTexels, 10 * int(index) + texel));
}

// The includer's record `index` (ObstacleRecord's std430 layout, ten vec4s).
ObstacleRecord obstacleAt(uint index) {
    vec4 t[10];
    for (int k = 0; k < 10; ++k) t[k] = obstacleTexel(index, k);
    ObstacleRecord o;
    o.centre = float[3](t[0].x, t[0].y, t[0].z);
    o.radius = t[0].w;
    o.halfSize = float[3](t[1].x, t[1].y, t[1].z);
    o.shape = floatBitsToUint(t[1].w);
    o.axis = float[3](t[2].x, t[2].y, t[2].z);
    o.scale = t[2].w;
    o.velocity = float[3](t[3].x, t[3].y, t[3].z);
    o.reach = t[3].w;
    o.spin = float[3](t[4].x, t[4].y, t[4].z);
    o.velocityStart = floatBitsToUint(t[4].w);
    for (int k = 0; k < 12; ++k) o.orientation[k] = t[5 + k / 4][k % 4];
    o.latticeOrigin = float[3](t[8].x, t[8].y, t[8].z);
    o.latticeSpacing = t[8].w;
    const uvec4 samples = floatBitsToUint(t[9]);
    o.latticeSamples = uint[3](samples.x, samples.y, samples.z);
    o.latticeStart = samples.w;
    return o;
}

// Value `index` of the lattices (SolidLevelSet's depth and velocity samples).
float latticeValue(uint index) { return uintBitsToFloat(texelFetch(latticeValues, int(index)).x); }

// From `centre` to `point`, at the minimum-image offset along periodic axes of a grid `box` long
// (z dropped in 2D).
vec3 offsetFrom(vec3 centre, vec3 point, uint dim, vec3 box, uint periodic) {
    vec3 d = point - centre;
    if (dim == 2u) d.z = 0.0;
    return minimumImage(d, box, periodic);
}

// From the obstacle's centre to `point` (offsetFrom).
vec3 obstacleOffset(ObstacleRecord o, vec3 point, uint dim, vec3 box, uint periodic) {
    return offsetFrom(v3(o.centre), point, dim, box, periodic);
}

// Whether `point` lies within reach of the includer's record `index`, with the offset from its
// centre: two texels read, where most points are beyond every obstacle's reach (read the whole
// record after this says yes).
bool withinReachOf(uint index, vec3 point, uint dim, vec3 box, uint periodic, out vec3 offset) {
    offset = offsetFrom(obstacleTexel(index, 0).xyz, point, dim, box, periodic);
    const float reach = obstacleTexel(index, 3).w;
    return dot(offset, offset) <= reach * reach;
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
// samples, -spacing outside the lattice (SolidLevelSet::depthAt); with its gradient, the
// trilinear interpolant's own from the same eight samples, 0 outside the lattice.
float meshDepth(ObstacleRecord o, vec3 p, out vec3 gradient) {
    gradient = vec3(0.0);
    uvec3 i;
    vec3 f;
    if (!onLattice(o, p, i, f)) return -o.latticeSpacing;
    float sum = 0.0;
    for (uint corner = 0u; corner < 8u; ++corner) {
        uvec3 d;
        const vec3 w = cornerWeights(f, corner, d);
        const vec3 slope = mix(vec3(-1.0), vec3(1.0), vec3(d)) / o.latticeSpacing;
        const float value = latticeValue(o.latticeStart + latticeSample(o, i + d));
        sum += w.x * w.y * w.z * value;
        gradient += vec3(slope.x * w.y * w.z, w.x * slope.y * w.z, w.x * w.y * slope.z) * value;
    }
    return sum;
}
// Without the gradient (its arithmetic folds away where it is not read).
float meshDepth(ObstacleRecord o, vec3 p) {
    vec3 unused;
    return meshDepth(o, p, unused);
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
        sum += w.x * w.y * w.z * vec3(latticeValue(s), latticeValue(s + 1u), latticeValue(s + 2u));
    }
    return sum;
}

// The velocity of the obstacle's material at `r` from its centre (MovingObstacle::velocityOf):
// v + w x r, plus a deforming mesh's own, turned and scaled into the world.
vec3 materialVelocity(ObstacleRecord o, vec3 r) {
    vec3 v = v3(o.velocity) + cross(v3(o.spin), r);
    if (mayHold(SOLID_KIND_DEFORMING) && o.velocityStart != OBSTACLE_RIGID)
        v += orientationOf(o) * (o.scale * meshVelocity(o, intoShapeFrame(o, r) / o.scale));
    return v;
}

// Whether the obstacle covers the point `r` from its centre (obstacleOffset).
bool covers(ObstacleRecord o, vec3 r) {
    vec3 d = intoShapeFrame(o, r);
    if (mayHoldShape(OBSTACLE_MESH) && o.shape == OBSTACLE_MESH) return meshDepth(o, d / o.scale) >= 0.0;
    if (mayHoldShape(OBSTACLE_BOX) && o.shape == OBSTACLE_BOX) return all(lessThanEqual(abs(d), v3(o.halfSize)));
    if (!mayHoldShape(OBSTACLE_BALL) && !mayHoldShape(OBSTACLE_CAPSULE)) return false;
    if (mayHoldShape(OBSTACLE_CAPSULE) && o.shape == OBSTACLE_CAPSULE) {
        const vec3 axis = v3(o.axis);
        const float length2 = dot(axis, axis);
        d -= (length2 > 0.0 ? clamp(dot(d, axis) / length2, -1.0, 1.0) : 0.0) * axis;
    }
    return dot(d, d) <= o.radius * o.radius;
}

// The least and greatest corners of the obstacle's shape box in its own frame, world units (a
// mesh's lattice scaled, a box's, a capsule's or a ball's): it covers no point beyond it.
void shapeBox(ObstacleRecord o, out vec3 lo, out vec3 hi) {
    hi = vec3(o.radius);
    if (mayHoldShape(OBSTACLE_CAPSULE) && o.shape == OBSTACLE_CAPSULE) hi = abs(v3(o.axis)) + o.radius;
    if (mayHoldShape(OBSTACLE_BOX) && o.shape == OBSTACLE_BOX) hi = v3(o.halfSize);
    lo = -hi;
    if (mayHoldShape(OBSTACLE_MESH) && o.shape == OBSTACLE_MESH) {
        const vec3 samples = vec3(o.latticeSamples[0], o.latticeSamples[1], o.latticeSamples[2]);
        lo = o.scale * v3(o.latticeOrigin);
        hi = lo + o.scale * o.latticeSpacing * (samples - 1.0);
    }
}

// The positions k in [0, count) of the points `start` + k `step` (a line of cell or face centres
// along x, k in cells; `start` at offset `r0` from the obstacle's centre, minimumImage) that the
// obstacle may cover: those within its reach and its turned shape box, with one position of slack
// on each side for rounding (the covers test decides each). Empty: x > y. A kernel that loops over
// these instead of the whole line runs, on lavapipe, as long as the longest line of its lanes.
ivec2 lineSpan(ObstacleRecord o, vec3 r0, float step, int count) {
    float t0 = 0.0, t1 = float(count - 1);
    // Within reach: |r0 + t step x| <= reach, a quadratic in t.
    const float mid = r0.x / step;
    const float disc = mid * mid - (dot(r0, r0) - o.reach * o.reach) / (step * step);
    if (disc < 0.0) return ivec2(1, 0);
    t0 = max(t0, -mid - sqrt(disc));
    t1 = min(t1, -mid + sqrt(disc));
    // Within the shape box: lo <= q0 + t dq <= hi, axis by axis of its own frame.
    vec3 lo, hi;
    shapeBox(o, lo, hi);
    const vec3 q0 = intoShapeFrame(o, r0), dq = intoShapeFrame(o, vec3(step, 0.0, 0.0));
    for (int k = 0; k < 3; ++k) {
        const bool across = abs(dq[k]) > 1e-6 * step;
        const float a = (lo[k] - step - q0[k]) / (across ? dq[k] : 1.0);
        const float b = (hi[k] + step - q0[k]) / (across ? dq[k] : 1.0);
        const bool outside = q0[k] < lo[k] - step || q0[k] > hi[k] + step;
        t0 = across ? max(t0, min(a, b)) : t0;
        t1 = across ? min(t1, max(a, b)) : (outside ? -1.0 : t1);
    }
    if (t1 < t0) return ivec2(1, 0);
    return ivec2(max(int(floor(t0)) - 1, 0), min(int(ceil(t1)) + 1, count - 1));
}

// Where `r` (from the centre, covered) leaves the solid, `margin` past its surface, and the
// outward normal there, both in the world frame (engine/simulation/SolidExit.cpp): the nearest
// surface point of a ball, box or capsule; Newton steps down a mesh's depth gradient (its
// lattice cell's own: eight texel fetches a step, where central differences took 56).
vec3 solidExit(ObstacleRecord o, vec3 r, uint dim, float margin, out vec3 normal) {
    vec3 d = intoShapeFrame(o, r);
    vec3 place = d;
    vec3 n = vec3(0.0, 0.0, 1.0);
    if (mayHoldShape(OBSTACLE_MESH) && o.shape == OBSTACLE_MESH) {
        vec3 p = d / o.scale;
        const float m = margin / o.scale;
        n = vec3(0.0, 0.0, 1.0);
        for (int step = 0; step < 4; ++step) {  // kMeshExitSteps
            vec3 gradient;
            const float depthHere = meshDepth(o, p, gradient);
            if (depthHere < 0.0) break;
            if (length(gradient) > 0.0) n = -normalize(gradient);
            p += n * (depthHere + m);
        }
        place = p * o.scale;
    } else if (mayHoldShape(OBSTACLE_BOX) && o.shape == OBSTACLE_BOX) {
        const vec3 extent = v3(o.halfSize);
        int nearest = 0;
        for (int a = 1; a < int(dim); ++a)
            if (extent[a] - abs(d[a]) < extent[nearest] - abs(d[nearest])) nearest = a;
        const float side = d[nearest] >= 0.0 ? 1.0 : -1.0;
        place = d;
        place[nearest] = side * (extent[nearest] + margin);
        n = vec3(0.0);
        n[nearest] = side;
    } else if (mayHoldShape(OBSTACLE_BALL) || mayHoldShape(OBSTACLE_CAPSULE)) {
        vec3 base = vec3(0.0);
        const vec3 axis = v3(o.axis);
        const float length2 = dot(axis, axis);
        if (mayHoldShape(OBSTACLE_CAPSULE) && o.shape == OBSTACLE_CAPSULE && length2 > 0.0)
            base = clamp(dot(d, axis) / length2, -1.0, 1.0) * axis;
        const vec3 q = d - base;
        const float len = length(q);
        n = vec3(1.0, 0.0, 0.0);
        if (len > 0.0) {
            n = q / len;
        } else if (mayHoldShape(OBSTACLE_CAPSULE) && o.shape == OBSTACLE_CAPSULE && length2 > 0.0) {
            if (dim == 2u) {
                n = normalize(vec3(-axis.y, axis.x, 0.0));
            } else {
                const vec3 helper = abs(axis.x) <= abs(axis.y) ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
                n = normalize(cross(axis, helper));
            }
        }
        place = base + n * (o.radius + margin);
    }
    normal = orientationOf(o) * n;
    return orientationOf(o) * (place - d);
}


#endif
