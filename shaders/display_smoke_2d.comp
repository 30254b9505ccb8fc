#version 450
// display_smoke_2d.comp: the stir window's picture of a 2D scene, one invocation per window
// pixel: the smoke sampled bilinearly between cell centres (the walls nearest-cell, so the
// domain's boundary shows as it is discretized), toned like the PNG previews, tinted where hot,
// with the text overlay on top. Wrapper: engine/display/DisplayKernels.cpp.
#extension GL_GOOGLE_include_directive : require
#include "DisplayParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Fields { vec2 fields[]; };  // (d, T) per cell
layout(std430, set = 0, binding = 1) readonly buffer Mask { uint maskWords[]; };  // 4 bytes a word
layout(std430, set = 0, binding = 2) readonly buffer Overlay { uint overlayWords[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Pixels { uint pixels[]; };
layout(push_constant) uniform Push { DisplayParams params; };

#include "Display.glsl"

bool isFluid(uint cell) { return ((maskWords[cell >> 2] >> ((cell & 3u) * 8u)) & 0xffu) != 0u; }

void main() {
    const uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    const uint x = pixel % params.width, y = pixel / params.width;
    vec3 colour = marginColour(x, y);
    vec2 p;
    if (sourcePoint(x, y, p)) {
        // Rows of the window run down, y of the grid up.
        p.y = float(params.sourceHeight) - p.y;
        const ivec2 n = ivec2(params.sourceWidth, params.sourceHeight);
        const ivec2 nearest = clamp(ivec2(floor(p)), ivec2(0), n - 1);
        if (!isFluid(uint(nearest.y * n.x + nearest.x))) {
            colour = vec3(DISPLAY_WALL_R, DISPLAY_WALL_G, DISPLAY_WALL_B);
        } else {
            const vec2 s = clamp(p - 0.5, vec2(0.0), vec2(n - 1));
            const ivec2 lo = min(ivec2(floor(s)), max(n - 2, ivec2(0)));
            const ivec2 hi = min(lo + 1, n - 1);
            const vec2 f = s - vec2(lo);
            // Wall cells hold 0: the smoke fades into the wall rather than past it.
            const vec2 v = mix(mix(fields[lo.y * n.x + lo.x], fields[lo.y * n.x + hi.x], f.x),
                               mix(fields[hi.y * n.x + lo.x], fields[hi.y * n.x + hi.x], f.x), f.y);
            const float tone = min(1.0, (1.0 - exp(-DISPLAY_TONE * max(v.x, 0.0) / params.densityScale)) /
                                            (1.0 - exp(-DISPLAY_TONE)));
            const float heat = params.hotScale > 0.0 ? clamp(v.y / params.hotScale, 0.0, 1.0) : 0.0;
            const vec3 smoke = mix(vec3(DISPLAY_SMOKE_R, DISPLAY_SMOKE_G, DISPLAY_SMOKE_B),
                                   vec3(DISPLAY_HOT_R, DISPLAY_HOT_G, DISPLAY_HOT_B), 0.6 * heat);
            colour = mix(vec3(DISPLAY_BACKGROUND_R, DISPLAY_BACKGROUND_G, DISPLAY_BACKGROUND_B),
                         smoke, tone);
        }
        colour = withPaddle(colour, p);
    }
    pixels[pixel] = packColour(withOverlay(colour, pixel));
}
