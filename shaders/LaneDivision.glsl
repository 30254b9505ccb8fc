/* LaneDivision.glsl: integer quotients by a run-time divisor through float division, for kernels
   that must take an index apart (shaders/README.md: lavapipe divides integers lane by lane, a
   loop of scalar divisions per batch, where a float division is one vector instruction: a 64^3
   box's reconstruction passes ran faster, engine/README.md "Speed").

   Exact for any n and d > 0 whose quotient is below 2^21 (the callers' are positions along one
   grid axis or wave numbers of a band): float(n) and float(d) are within 2^-24 of n and d, and
   Vulkan's float division within 2.5 ulp, so the float quotient is within 2^-21 of n / d
   relatively, less than 1 for such quotients, which one step either way corrects. */
#ifndef MODEFLOW_SHADERS_LANE_DIVISION_GLSL
#define MODEFLOW_SHADERS_LANE_DIVISION_GLSL

/* n / d rounded down (d > 0, n / d < 2^21). */
uint quotientOf(uint n, uint d) {
    uint q = uint(float(n) / float(d));
    // q d <= n + d < 2^32 whenever n + d does not overflow: no wrap in either test.
    if (q * d > n) q -= 1u;
    else if (n - q * d >= d) q += 1u;
    return q;
}

#endif
