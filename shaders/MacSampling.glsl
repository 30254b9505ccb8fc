/* MacSampling.glsl: trilinear MAC (staggered) sampling of a face field, float32, the device twin
   of engine/core/MacSampling.cpp (same clamps, same corner order, same weight products). Points
   are in grid units of the sampled grid: cell (i, j, k) spans [i, i+1) x [j, j+1) x [k, k+1).

   The includer defines MAC_DIM (2 or 3: the axes sampled; a 2D grid has one cell along z) and
   `vec2 macFacePair(uint face)`: the values at MacGrid::faceIndex `face` and `face + 1`
   (smoke_face_pairs.comp). Every stencil row along x is two adjacent faces, so one read fetches
   it: half the reads of taking the faces apart (3D smoke steps ran faster on lavapipe with
   storage loads; shaders/SmokeAdvect.glsl, which now fetches the pairs as texels). Outside the box
   the stencils clamp to it: tangential components keep their nearest value, the normal component
   falls to 0 at the wall, because wall faces (position 0 or n along their normal) read as 0
   whatever the field holds. Where the reference skips a wall corner this adds weight x 0, and on
   an axis of one position (hi == lo) the second corner of a pair has weight 0: the same sums.

   Sides the air flows through (a wind: MacGrid::flowThrough, `boundary`'s flowsThrough) have no
   wall either: their faces read what the field holds, the wind's velocity.

   Periodic axes (bit a of `boundary`, MacGrid::periodic) clamp nothing: the stencil wraps (lo the
   last position, hi the first), their faces have no wall, and on a periodic x the includer's
   pair of the row's last face holds the row's first face as its second value (the x-neighbour
   across the seam). Corner offsets that wrap are negative; uint arithmetic takes them modulo
   2^32, so the addresses come out right. */
#ifndef MODEFLOW_SHADERS_MAC_SAMPLING_GLSL
#define MODEFLOW_SHADERS_MAC_SAMPLING_GLSL

#include "AxisStencil.glsl"

/* The normal-`axis` component at gridPoint on a grid of `cells`, whose normal-`axis` faces start
   at number `faceOffset`. */
float sampleFaceComponent(const int axis, vec3 gridPoint, ivec3 cells, uint faceOffset, uint boundary) {
    const bool wraps = isPeriodic(boundary, axis);
    const bool walled = !wraps && !flowsThrough(boundary, axis);
    ivec3 extent = cells;
    extent[axis] += wraps ? 0 : 1;
    AxisStencil s[3];
    s[2] = AxisStencil(0, 0, 0.0);
    [[unroll]] for (int a = 0; a < MAC_DIM; ++a)
        s[a] = axisStencil(gridPoint[a], a == axis ? 0.0 : 0.5, extent[a], isPeriodic(boundary, a));
    const uint row = faceOffset + uint((s[2].lo * extent.y + s[1].lo) * extent.x + s[0].lo);
    const uint rowY = uint((s[1].hi - s[1].lo) * extent.x);
    const uint rowZ = uint((s[2].hi - s[2].lo) * extent.y * extent.x);
    float value = 0.0;
    [[unroll]] for (int cz = 0; cz < (MAC_DIM == 3 ? 2 : 1); ++cz)
        [[unroll]] for (int cy = 0; cy < 2; ++cy) {
            const vec2 pair = macFacePair(row + uint(cy) * rowY + uint(cz) * rowZ);
            const ivec3 lo = ivec3(s[0].lo, cy != 0 ? s[1].hi : s[1].lo, cz != 0 ? s[2].hi : s[2].lo);
            const ivec3 hi = ivec3(s[0].hi, lo.yz);
            const bool wallLo = walled && (lo[axis] == 0 || lo[axis] == cells[axis]);
            const bool wallHi = walled && (hi[axis] == 0 || hi[axis] == cells[axis]);
            const float wy = cy != 0 ? s[1].f : 1.0 - s[1].f;
            float wz = 1.0;
#if MAC_DIM == 3
            wz = cz != 0 ? s[2].f : 1.0 - s[2].f;
#endif
            value += (1.0 - s[0].f) * wy * wz * (wallLo ? 0.0 : pair.x);
            value += s[0].f * wy * wz * (wallHi ? 0.0 : pair.y);
        }
    return value;
}

/* All components (0 beyond MAC_DIM), in world units per unit time. */
vec3 sampleVelocityGrid(vec3 gridPoint, ivec3 cells, uvec3 faceOffsets, uint boundary) {
    vec3 u = vec3(0.0);
    [[unroll]] for (int axis = 0; axis < MAC_DIM; ++axis)
        u[axis] = sampleFaceComponent(axis, gridPoint, cells, faceOffsets[axis], boundary);
    return u;
}

#endif
