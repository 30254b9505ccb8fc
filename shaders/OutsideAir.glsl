/* OutsideAir.glsl: where the ghosts of engine/simulation/OutsideAir lie, and what a pair of
   smoke fields reads in one, for the smoke kernels (SmokeAdvect.glsl, SmokeFlux.glsl). The
   includer binds the ghosts as an RGBA32UI texel buffer: (density, temperature, fuel, 0). */
#ifndef MODEFLOW_SHADERS_OUTSIDE_AIR_GLSL
#define MODEFLOW_SHADERS_OUTSIDE_AIR_GLSL

/* The ghost beyond smoke cell `at` of `side` (2 axis + 0 low, 1 high) on a grid of `cells`: the
   sides one after the other (x_min, x_max, y_min, ...), each along its other axes b < c. */
int ghostIndex(int side, ivec3 at, ivec3 cells) {
    const int axis = side / 2;
    const ivec2 along = ivec2(axis == 0 ? 1 : 0, axis == 2 ? 1 : 2);
    const int total = cells.x * cells.y * cells.z;
    int first = (side & 1) * (total / cells[axis]);
    for (int a = 0; a < axis; ++a) first += 2 * (total / cells[a]);
    return first + at[along.x] + cells[along.x] * at[along.y];
}

/* The pair's two fields in ghost `texel`: (density, temperature) for pair 0, (fuel, 0) for 1. */
vec2 ghostPairOf(uvec4 texel, uint pair) {
    return pair == 0u ? uintBitsToFloat(texel.xy) : vec2(uintBitsToFloat(texel.z), 0.0);
}

#endif
