#version 450
// display_picture.comp: the stir window's picture of a 3D scene: the ray-marched picture
// (render_volume.comp, packed RGBA8 with red in the low byte) scaled bilinearly into the
// viewport, with the text overlay on top.
// Wrapper: engine/display/DisplayKernels.cpp.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "DisplayParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Picture { uint picture[]; };
layout(std430, set = 0, binding = 1) readonly buffer Overlay { uint overlayWords[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Pixels { uint pixels[]; };
layout(push_constant) uniform Push { DisplayParams params; };

#include "DisplayView.glsl"

vec3 texel(ivec2 t) { return unpackUnorm4x8(picture[t.y * int(params.sourceWidth) + t.x]).rgb; }

vec3 pixelColour(uint x, uint y) {
    vec3 colour = marginColour(x, y);
    vec2 p;
    if (sourcePoint(x, y, p)) {
        const ivec2 n = ivec2(params.sourceWidth, params.sourceHeight);
        const vec2 s = clamp(p - 0.5, vec2(0.0), vec2(n - 1));
        const ivec2 lo = min(ivec2(floor(s)), max(n - 2, ivec2(0)));
        const ivec2 hi = min(lo + 1, n - 1);
        const vec2 f = s - vec2(lo);
        // sRGB values blended directly: a scaled picture, not a physical quantity.
        colour = mix(mix(texel(lo), texel(ivec2(hi.x, lo.y)), f.x),
                     mix(texel(ivec2(lo.x, hi.y)), texel(hi), f.x), f.y);
        colour = withPaddle(colour, p);
    }
    return colour;
}

#include "Display.glsl"
