#version 450
// display_dots.comp: particles drawn over the stir window's finished picture, one invocation a
// particle: its pixel and the four beside it set to the particle colour (every dot the same
// colour, so overlapping dots need no order). Wrapper: engine/display/DisplayKernels.cpp.
#extension GL_GOOGLE_include_directive : require
#include "DisplayParams.h"

layout(local_size_x = 64, local_size_x_id = 0) in;

layout(std430, set = 0, binding = 0) readonly buffer Dots { vec2 dots[]; };
layout(std430, set = 0, binding = 1) buffer Pixels { uint pixels[]; };
layout(push_constant) uniform Push { DisplayDotsParams params; };

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    const vec2 dot = dots[i];
    if (!(dot.x >= 0.0 && dot.y >= 0.0 && dot.x < float(params.width) && dot.y < float(params.height)))
        return;
    const ivec2 centre = ivec2(dot);
    const ivec2 offsets[5] = ivec2[5](ivec2(0, 0), ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int k = 0; k < 5; ++k) {
        const ivec2 p = centre + offsets[k];
        if (p.x < 0 || p.y < 0 || p.x >= int(params.width) || p.y >= int(params.height)) continue;
        pixels[uint(p.y) * params.width + uint(p.x)] = params.colour;
    }
}
