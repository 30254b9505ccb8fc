/* MacSampling.glsl: trilinear MAC (staggered) sampling of a face field, float32, the device twin
   of engine/field/MacSampling.cpp (same clamps, same loop order). Points are in grid units of
   the sampled grid: cell (i, j, k) spans [i, i+1) x [j, j+1) x [k, k+1).

   The includer defines `float macFaceValue(uint face)`, the face field's value at a
   MacGrid::faceIndex, before including this file. Outside the box the stencils clamp to it:
   tangential components keep their nearest value, the normal component falls to 0 at the wall
   (wall faces read as 0 whatever the field holds). */
#ifndef MODEFLOW_SHADERS_MAC_SAMPLING_GLSL
#define MODEFLOW_SHADERS_MAC_SAMPLING_GLSL

/* Linear interpolation along one axis between positions lo and hi = lo + 1, or a single position
   (hi == lo, f = 0) on a one-point axis. */
struct AxisStencil {
    int lo;
    int hi;
    float f;
};

/* Along an axis with n samples at grid coordinates offset + 0, 1, ..., n - 1, clamped to them. */
AxisStencil axisStencil(float coordinate, float offset, int n) {
    const float s = clamp(coordinate - offset, 0.0, float(n - 1));
    AxisStencil a;
    a.lo = min(int(floor(s)), max(n - 2, 0));
    a.hi = min(a.lo + 1, n - 1);
    a.f = s - float(a.lo);
    return a;
}

/* The normal-`axis` component at gridPoint on a grid of `cells`, whose normal-`axis` faces start
   at number `faceOffset`. */
float sampleFaceComponent(int axis, vec3 gridPoint, ivec3 cells, uint faceOffset) {
    ivec3 extent = cells;
    extent[axis] += 1;
    AxisStencil s[3];
    for (int a = 0; a < 3; ++a) s[a] = axisStencil(gridPoint[a], a == axis ? 0.0 : 0.5, extent[a]);
    float value = 0.0;
    for (int cz = 0; cz <= (s[2].hi != s[2].lo ? 1 : 0); ++cz)
        for (int cy = 0; cy <= (s[1].hi != s[1].lo ? 1 : 0); ++cy)
            for (int cx = 0; cx <= (s[0].hi != s[0].lo ? 1 : 0); ++cx) {
                const ivec3 p = ivec3(cx != 0 ? s[0].hi : s[0].lo, cy != 0 ? s[1].hi : s[1].lo,
                                      cz != 0 ? s[2].hi : s[2].lo);
                if (p[axis] == 0 || p[axis] == cells[axis]) continue; /* a wall of the box */
                const float w = (cx != 0 ? s[0].f : 1.0 - s[0].f) * (cy != 0 ? s[1].f : 1.0 - s[1].f) *
                                (cz != 0 ? s[2].f : 1.0 - s[2].f);
                value += w * macFaceValue(faceOffset + uint((p.z * extent.y + p.y) * extent.x + p.x));
            }
    return value;
}

/* All components (0 beyond `dim`), in world units per unit time. */
vec3 sampleVelocityGrid(vec3 gridPoint, ivec3 cells, int dim, uvec3 faceOffsets) {
    vec3 u = vec3(0.0);
    for (int axis = 0; axis < dim; ++axis) u[axis] = sampleFaceComponent(axis, gridPoint, cells, faceOffsets[axis]);
    return u;
}

#endif
